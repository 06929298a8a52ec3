"""FE sweep over cam angle: per-angle pipeline, chunked/resumable store, parallel executors.

>>> from femcam.sweep import sweep            # doctest: +SKIP
>>> r = sweep("examples/seed002_study_model.toml", out="out", workers=2)  # doctest: +SKIP

Modules: :mod:`~femcam.sweep.options` (:class:`SweepOptions`, the scene adapter),
:mod:`~femcam.sweep.pipeline` (per-angle chain, one chunk), :mod:`~femcam.sweep.families` (model
families: :mod:`~femcam.sweep.plan`, the first guess, and :mod:`~femcam.sweep.verify`, the
reuse error checked against ``tolerance``), :mod:`~femcam.sweep.cache`
(:class:`ModelCache`: the process's FE models),
:mod:`~femcam.sweep.profile` (the worst angle's surface stresses for the plot),
:mod:`~femcam.sweep.wear` (Archard wear columns), :mod:`~femcam.sweep.store` (chunked atomic
store, resume, the on-disk table of long sweeps), :mod:`~femcam.sweep.parallel` (serial /
process pool / Dask), :mod:`~femcam.sweep.table` (columns, :class:`TableBuilder`),
:mod:`~femcam.sweep.result` (:class:`SweepResult`, report), :mod:`~femcam.sweep.run`
(:func:`sweep`, ``workers="auto"``), :mod:`~femcam.sweep.outputs` (the files of ``out``).
"""

import sys
import types

from .cache import ModelCache, default_cache
from .families import plan_families, verify_families
from .options import SweepOptions
from .parallel import Progress, auto_workers, run_tasks
from .pipeline import run_chunk
from .result import COLUMNS, SweepResult
from .run import parse_angles_deg, sweep

__all__ = ["COLUMNS", "ModelCache", "Progress", "SweepOptions", "SweepResult", "auto_workers",
           "default_cache", "parse_angles_deg", "plan_families", "run_chunk", "run_tasks", "sweep",
           "verify_families"]


# ``femcam.sweep`` is both this package and the entry point: ``femcam.sweep(scene, ...)`` calls
# :func:`sweep`. A callable module keeps ``import femcam.sweep.pipeline`` and
# ``femcam.sweep(...)`` both working, where re-exporting the function under the package's own
# name would shadow the package.
def _install_callable_module():
    class _SweepModule(types.ModuleType):
        def __call__(self, scene, **kwargs):
            return sweep(scene, **kwargs)

    sys.modules[__name__].__class__ = _SweepModule


_install_callable_module()
