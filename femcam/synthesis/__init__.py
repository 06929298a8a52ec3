"""Cam-curve synthesis by potential-energy finite elements (seed 003, Nguyen 2023).

>>> from femcam.synthesis import seed003_program, synthesize_knife_edge, SynthesisOptions
>>> res = synthesize_knife_edge(seed003_program(), Rb=5e-3,
...                             options=SynthesisOptions(n_elements=60, k=1e6))
>>> res.converged, round(res.phi_max * 180 / 3.141592653589793, 1)
(True, 29.6)

Modules: :mod:`~femcam.synthesis.pefem` (the driver, symbol table),
:mod:`~femcam.synthesis.options` (inputs, result), :mod:`~femcam.synthesis.energy` (quadratic
elements, energy, residual, consistent tangent), :mod:`~femcam.synthesis.newton` (globalised
Newton-Raphson) and :mod:`~femcam.synthesis.study` (the seed-003 case, parameter
studies as Markdown and CSV tables, comparison with the direct analytic profile). Only
numpy/scipy are imported.
"""

from .pefem import (
    PressureAngleError,
    SynthesisOptions,
    SynthesisResult,
    pressure_angle_exact,
    synthesize_knife_edge,
)
from .study import (
    SEED003_RB,
    Comparison,
    StudyRow,
    compare_direct,
    direct_profile,
    seed003_program,
    study_columns,
    study_k,
    study_k_over_mu,
)

__all__ = [
    "PressureAngleError",
    "SynthesisOptions",
    "SynthesisResult",
    "pressure_angle_exact",
    "synthesize_knife_edge",
    "SEED003_RB",
    "Comparison",
    "StudyRow",
    "compare_direct",
    "direct_profile",
    "seed003_program",
    "study_k",
    "study_k_over_mu",
    "study_columns",
]
