"""Constraint margins of a study's variants: positive = satisfied, normalised by the limit so
that the smallest margin names the constraint that binds.

=============== ==================================================== ===========================
constraint      margin (dimensionless)                               applies
=============== ==================================================== ===========================
``phi``         ``1 - phi_max / phi_limit``                          always
``undercut``    ``+1`` (no undercut) or ``-1``                       always
``rho``         ``rho_min / rho_limit - 1``                          ``rho_limit > 0``
``liftoff``     ``Fc_min / Fc_max`` (< 0: lift-off)                  ``liftoff`` (default)
``sf``          ``sf_min / sf_limit - 1``                            scenes with assessment data
``lambda``      ``lambda_min / lambda_limit - 1``                    ``lambda_limit`` given
``p0``          ``1 - p0_max / p0_limit``                            ``p0_limit`` given
``jump``        ``rpm_jump / (jump_factor * rpm) - 1`` (no jump up   scenes with an elastic train
                to the search's end: that end is used, a lower bound)
=============== ==================================================== ===========================

A margin that does not apply is NaN and does not constrain; a failed variant is infeasible.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate

#: constraint names, in table order
NAMES = ("phi", "undercut", "rho", "liftoff", "sf", "lambda", "p0", "jump")


@dataclass(frozen=True, kw_only=True)
class Constraints:
    """The limits a feasible variant respects (SI).

    Parameters
    ----------
    phi_limit : float
        Largest pressure angle (rad), in (0, pi/2). Default 30 deg.
    rho_limit : float
        Smallest convex cam radius of curvature (m), >= 0 (0: not constrained beyond undercut).
    liftoff : bool
        Forbid lift-off (contact force <= 0 anywhere).
    sf_limit : float
        Smallest safety factor of the assessment (> 0), where the scene has the data.
    lambda_limit : float or None
        Smallest film parameter lambda (> 0), or None.
    p0_limit : float or None
        Largest Hertz peak pressure (Pa, > 0), or None.
    jump_factor : float
        The train's jump speed must exceed this multiple of the operating speed (> 0).
    """

    phi_limit: float = math.radians(30.0)
    rho_limit: float = 0.0
    liftoff: bool = True
    sf_limit: float = 1.0
    lambda_limit: float | None = None
    p0_limit: float | None = None
    jump_factor: float = 1.0

    def __post_init__(self):
        _validate.number("phi_limit", self.phi_limit, "rad")
        if not 0.0 < self.phi_limit < math.pi / 2:  # no cam meets phi <= 0; phi < 90 deg always
            raise _validate.fail("phi_limit", self.phi_limit, "rad", "must be in (0, pi/2)")
        _validate.nonnegative("rho_limit", self.rho_limit, "m")
        _validate.positive("sf_limit", self.sf_limit, "")
        _validate.positive("jump_factor", self.jump_factor, "x operating speed")
        if self.lambda_limit is not None:
            _validate.positive("lambda_limit", self.lambda_limit, "")
        if self.p0_limit is not None:
            _validate.positive("p0_limit", self.p0_limit, "Pa")

    def as_dict(self) -> dict:
        """The limits, JSON-able (for the provenance).

        Returns
        -------
        dict
            Field name -> value (SI).
        """
        return {k: getattr(self, k) for k in self.__dataclass_fields__}


def margins(rec: dict, c: Constraints, jump_factor_hi: float) -> dict:
    """The margin of every constraint for one variant's record (module docstring).

    Parameters
    ----------
    rec : dict
        A record of :func:`femcam.study.evaluate.evaluate` (SI).
    c : Constraints
        The limits.
    jump_factor_hi : float
        The end of the jump-speed search (x operating speed).

    Returns
    -------
    dict
        ``{name: margin}`` for :data:`NAMES` (NaN: does not apply or not computed).
    """
    nan = math.nan
    m = dict.fromkeys(NAMES, nan)
    if rec.get("status") != "ok":
        return m
    m["phi"] = 1.0 - rec["phi_max"] / c.phi_limit
    m["undercut"] = -1.0 if rec["undercut"] else 1.0
    if c.rho_limit > 0:
        m["rho"] = rec["rho_min"] / c.rho_limit - 1.0
    if c.liftoff and rec["Fc_max"] > 0:
        m["liftoff"] = rec["Fc_min"] / rec["Fc_max"]
    if math.isfinite(rec["sf_min"]):
        m["sf"] = rec["sf_min"] / c.sf_limit - 1.0
    if c.lambda_limit is not None and math.isfinite(rec["lambda_min"]):
        m["lambda"] = rec["lambda_min"] / c.lambda_limit - 1.0
    if c.p0_limit is not None:
        m["p0"] = 1.0 - rec["p0_max"] / c.p0_limit
    if rec.get("has_train"):
        jump = rec["rpm_jump"] if math.isfinite(rec["rpm_jump"]) else jump_factor_hi * rec["rpm"]
        if "jump speed not computed" not in rec.get("reason", ""):
            m["jump"] = jump / (c.jump_factor * rec["rpm"]) - 1.0
    return m


def feasibility(margin_table: dict, ok) -> tuple:
    """Feasible flags and the binding (smallest-margin) constraint of every variant.

    Parameters
    ----------
    margin_table : dict
        ``{name: ndarray (n,)}`` margins.
    ok : ndarray of bool, shape (n,)
        Variants evaluated without failure.

    Returns
    -------
    feasible : ndarray of bool, shape (n,)
    binding : ndarray of str, shape (n,)
        Name of the smallest margin ("" for a failed variant).
    """
    M = np.column_stack([np.asarray(margin_table[k], float) for k in NAMES])
    F = np.where(np.isfinite(M), M, np.inf)
    feasible = np.asarray(ok, bool) & np.all(F >= 0.0, axis=1)
    idx = np.argmin(F, axis=1)
    ok = np.asarray(ok, bool)
    binding = np.array([NAMES[i] if ok[r] and np.isfinite(F[r, i]) else "" for r, i in enumerate(idx)],
                       dtype=object)
    return feasible, binding.astype(str)


def infeasible_reason(margin_table: dict, ok) -> str:
    """Why no variant is feasible: the constraint(s) that every evaluated variant violates, and
    how many variants dropping each constraint would make feasible.

    Parameters
    ----------
    margin_table : dict
        ``{name: ndarray (n,)}`` margins.
    ok : ndarray of bool, shape (n,)
        Variants evaluated without failure.

    Returns
    -------
    str
        "" when some variant is feasible; else a one-line explanation.
    """
    ok = np.asarray(ok, bool)
    if not np.any(ok):
        return "no variant was evaluated (every variant failed or was refused; see the reason column)"
    feasible, _ = feasibility(margin_table, ok)
    if np.any(feasible):
        return ""
    parts = []
    for k in NAMES:
        v = np.asarray(margin_table[k], float)[ok]
        bad = int(np.sum(np.isfinite(v) & (v < 0)))
        if bad == 0:
            continue
        rest = {j: margin_table[j] for j in NAMES if j != k}
        rest[k] = np.full(ok.shape, np.nan)
        freed = int(np.sum(feasibility(rest, ok)[0]))
        parts.append(f"{k} violated by {bad} of {int(ok.sum())} variants"
                     + (f" (without it {freed} would be feasible)" if freed else ""))
    worst = [k for k in NAMES if np.all(np.asarray(margin_table[k], float)[ok] < 0)]
    head = (f"no feasible variant: the {', '.join(worst)} constraint{'s' if len(worst) > 1 else ''} "
            "fails in every variant" if worst else "no feasible variant: the constraints exclude each other")
    return head + "; " + "; ".join(parts)
