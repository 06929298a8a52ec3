"""FE sweep over cam angle: per-angle pipeline, chunked/resumable store, parallel executors.

>>> from femcam import sweep            # doctest: +SKIP
>>> from femcam import RunOptions                                        # doctest: +SKIP
>>> r = sweep("examples/seed002_study_model.toml", run=RunOptions(out="out", workers=2))  # doctest: +SKIP

``femcam.sweep`` is the function (:func:`femcam.sweep.run.sweep`); this package is imported by
name: ``from femcam.sweep import SweepResult`` or ``from femcam.sweep.table import COLUMNS``.

Modules: :mod:`~femcam.sweep.options` (:class:`SweepOptions`, :class:`RunOptions`, the scene
adapter),
:mod:`~femcam.sweep.pipeline` (per-angle chain, one chunk), model families
(:mod:`~femcam.sweep.plan`, the first guess, and :mod:`~femcam.sweep.verify`, the reuse error
checked against ``tolerance``), :mod:`~femcam.sweep.cache` (:class:`ModelCache`: the process's
FE models), :mod:`~femcam.sweep.profile` (the worst angle's surface stresses for the plot),
:mod:`~femcam.sweep.wear` (Archard wear columns), :mod:`~femcam.sweep.store` (chunked atomic
store, resume, the on-disk table of long sweeps), :mod:`~femcam.sweep.parallel` (serial /
process pool / Dask), :mod:`~femcam.sweep.table` (columns, :class:`TableBuilder`),
:mod:`~femcam.sweep.result` (:class:`SweepResult`, report), :mod:`~femcam.sweep.run`
(:func:`sweep`, ``workers="auto"``), :mod:`~femcam.sweep.outputs` (the files of ``out``).

The names below load with their module on first use (PEP 562), so ``import femcam`` (which
imports this package to bind ``femcam.sweep`` to the function) stays numpy/scipy only.
"""

import importlib

#: public name -> the module that defines it
_WHERE = {"COLUMNS": ".table", "ModelCache": ".cache", "Progress": "femcam._progress",
          "RunOptions": ".options", "SweepOptions": ".options", "SweepResult": ".result",
          "auto_workers": ".parallel",
          "default_cache": ".cache", "parse_angles_deg": ".run", "plan_families": ".plan",
          "run_chunk": ".pipeline", "run_tasks": ".parallel", "sweep": ".run",
          "verify_families": ".verify"}

__all__ = sorted(_WHERE)


def __getattr__(name):
    """A public name, imported from its module on first use (PEP 562)."""
    if name not in _WHERE:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(_WHERE[name], __name__), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(_WHERE))
