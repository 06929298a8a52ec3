"""Design studies: a grid or Latin hypercube over scene keys, one Hertz-chain evaluation per
variant, FE on the candidates that matter, constraint margins, the Pareto set (docs/study.md).

Modules: ``spec`` (``KEY=VALUES``, :class:`StudySpec`), ``variants`` (a variant's scene through
the public loader, content hash), ``evaluate`` (the worker's Hertz record), ``constraints``
(margins, feasibility, why a study is infeasible), ``store`` (records by content hash: resume,
dedup), ``fe`` (FE candidates through :func:`femcam.sweep.sweep`), ``result``
(:class:`StudyResult`, the columns, the Pareto set), ``outputs`` (CSV/NPZ/plots through
:mod:`femcam.io`) and ``run`` (:func:`run_study`).
"""

from .constraints import NAMES as CONSTRAINTS
from .constraints import Constraints
from .evaluate import EvalOptions, evaluate
from .fe import FEOptions
from .result import StudyResult, pareto_mask
from .run import OBJECTIVES, run_study
from .spec import StudySpec, Variable, parse_vary

__all__ = ["CONSTRAINTS", "OBJECTIVES", "Constraints", "EvalOptions", "FEOptions", "StudyResult",
           "StudySpec", "Variable", "evaluate", "parse_vary", "pareto_mask", "run_study"]
