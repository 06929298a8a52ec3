"""FE on the candidates that matter: the ``top`` best feasible variants by the objective (or
the Pareto set), each swept with :func:`femcam.sweep.sweep` (``method="fe"``) on a few angles
around its Hertz worst angle. The FE peak pressure answers ``p0_fe``; the Hertz columns stay.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..errors import FemcamError, InputError
from ..sweep import RunOptions, SweepOptions, sweep
from .spec import MAX_VARIANTS, whole

#: what chooses the FE candidates
SELECT = ("objective", "pareto")


@dataclass(frozen=True, kw_only=True)
class FEOptions:
    """Which variants get an FE check and how.

    Parameters
    ----------
    top : int
        Number of candidates (>= 0; 0: no FE). With ``select="pareto"``: at most this many of
        the Pareto set, lowest objective first.
    select : str
        ``"objective"`` (the best feasible by the objective) or ``"pareto"``.
    offsets : tuple of float
        Cam angles around each candidate's Hertz worst angle (rad).
    a_over_h : float
        FE element size in the contact zone, ``h = a / a_over_h``.
    tolerance : float
        The sweep's model-reuse tolerance (relative p0).
    """

    top: int = 0
    select: str = "objective"
    offsets: tuple = tuple(math.radians(d) for d in (-2.0, -1.0, 0.0, 1.0, 2.0))
    a_over_h: float = 10.0
    tolerance: float = 2e-3

    def __post_init__(self):
        whole("top", self.top, 0, MAX_VARIANTS, "variants")
        if self.select not in SELECT:
            raise InputError(f"fe_select = {self.select!r}: must be one of {', '.join(SELECT)}")
        off = None if isinstance(self.offsets, str | bytes) else \
            _validate.finite_array("offsets", self.offsets, "rad")
        if off is None or off.ndim != 1 or not off.size:
            raise _validate.fail("offsets", self.offsets, "rad", "give finite angle offsets")
        _validate.positive("a_over_h", self.a_over_h, "(contact half-width / element size)")
        _validate.positive("tolerance", self.tolerance, "(relative p0)")

    def as_dict(self) -> dict:
        """JSON-able options (the FE records' content key).

        Returns
        -------
        dict
            ``top``, ``select``, ``offsets_deg``, ``a_over_h``, ``tolerance``.
        """
        return {"top": int(self.top), "select": self.select,
                "offsets_deg": [round(math.degrees(o), 9) for o in self.offsets],
                "a_over_h": float(self.a_over_h), "tolerance": float(self.tolerance)}


def candidates(table: dict, opts: FEOptions, objective: str) -> list:
    """Rows that get an FE check.

    Parameters
    ----------
    table : dict
        The study table (``feasible``, ``pareto`` and the objective column).
    opts : FEOptions
        ``top`` and ``select``.
    objective : str
        SI column minimised (``p0_max``, ...).

    Returns
    -------
    list of int
        Row indices, best first; one per content hash (duplicates are skipped).
    """
    if opts.top == 0:
        return []
    mask = (table["feasible"] > 0) & (table["duplicate_of"] < 0)
    if opts.select == "pareto":
        mask &= table["pareto"] > 0
    rows = np.flatnonzero(mask)
    order = rows[np.argsort(np.asarray(table[objective], float)[rows], kind="stable")]
    return [int(i) for i in order[: opts.top]]


def fe_check(task: tuple) -> dict:
    """The FE sweep of one candidate (module-level: runs on a worker; writes nothing).

    Parameters
    ----------
    task : tuple
        ``(scene, theta_worst in rad, FEOptions)``.

    Returns
    -------
    dict
        ``p0_fe`` (Pa, the largest solved peak pressure of the angles), ``theta_fe`` (rad),
        ``status`` and ``reason``.
    """
    scene, theta0, opts = task
    angles = np.mod(theta0 + np.asarray(opts.offsets, float), 2.0 * math.pi)
    try:
        r = sweep(scene,
                  SweepOptions(angles=angles,  method="fe",  a_over_h=opts.a_over_h,
                               tolerance=opts.tolerance,  plots=False),
                  RunOptions(workers=1, progress=False))
    except FemcamError as exc:
        return {"p0_fe": math.nan, "theta_fe": math.nan, "status": "failed",
                "reason": f"FE: {type(exc).__name__}: {exc}".replace("\n", " ")}
    p0 = np.asarray(r.table["p0_fe"], float)
    if not np.any(np.isfinite(p0)):
        msg = "; ".join(sorted({str(m) for m in r.table.get("message", []) if str(m)})) or "no solved angle"
        return {"p0_fe": math.nan, "theta_fe": math.nan, "status": "failed", "reason": f"FE: {msg}"}
    i = int(np.nanargmax(p0))
    return {"p0_fe": float(p0[i]), "theta_fe": float(r.table["theta"][i]), "status": "ok", "reason": ""}
