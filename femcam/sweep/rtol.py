r"""Accuracy on demand: the mesh of a sweep chosen for a requested p0 error (``rtol``).

The estimated p0 error of an FE row (:mod:`femcam.sweep.estimate`) has two parts: the
discretisation error of its family's mesh carried to the row, and the family's verified reuse
error (bounded by ``tolerance``). ``rtol`` splits the budget in half:

1. ``tolerance = rtol / 2`` (``min(tolerance, rtol / 2)`` when a tolerance is given): the family
   verification keeps the reuse error within half the budget;
2. a **pilot** two-level estimate at ``a_over_h = 8`` on the planned families with the smallest
   and the largest curvature ratio ``Rr / rho`` (2D elasticity is scale invariant, so the
   relative error at a given ``a/h`` changes only with the shape of the gap) predicts the
   ``a_over_h`` whose discretisation error is ``rtol / 2``:
   ``n = 8 (e_8 / (rtol / 2))^{1/p}``, rounded up to an even whole number >= 6 (an even
   ``a_over_h`` keeps the contact centre and the Hertz edge on nodes of both estimate levels,
   where the two-level estimate was validated);
3. the families are planned, verified and estimated at that ``a_over_h``; if a row's estimate
   still exceeds ``rtol``, ``a_over_h`` is raised once more by the same rule from the worst row
   (rows still above are flagged ``rtol_not_met``).

Only p0 is controlled (the estimates of a, von Mises and tau1 are reported, not targeted).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from .. import _validate
from ..hertz.conformity import roller_does_not_fit
from ..mesh import MeshOptions
from ..mesh.estimate import check_contact_elements
from .estimate import RATES, FamilyEstimate, family_estimate, predict_a_over_h, row_estimate
from .options import RTOL_RANGE, ContactParams, SweepOptions, contact_params
from .plan import hertz_half_width, plan_families

__all__ = ["PILOT_A_OVER_H", "choose_mesh", "even_ceil", "pilot_a_over_h", "refine", "rows_p0_estimate",
           "rtol_settings"]

#: ``a_over_h`` of the pilot estimate (coarse level 4)
PILOT_A_OVER_H = 8.0
#: reuse tolerance of a sweep without ``rtol`` when none is given (relative p0 error)
DEFAULT_TOLERANCE = 2e-3
#: smallest ``a_over_h`` chosen for an rtol (the two-level estimate is validated from 6 on)
MIN_A_OVER_H = 6.0


def even_ceil(x: float, lo: float = MIN_A_OVER_H, hi: float = 400.0) -> float:
    """The smallest even whole number >= ``x``, within ``[lo, hi]``.

    Parameters
    ----------
    x : float
        Elements per half-width [-].
    lo, hi : float
        Bounds [-].

    Returns
    -------
    float
        An even whole number [-].

    >>> even_ceil(6.1), even_ceil(3.0), even_ceil(8.0)
    (8.0, 6.0, 8.0)
    """
    x = _validate.positive("x", x, "(elements per half-width)")
    return float(min(hi, max(lo, 2 * math.ceil(x / 2 - 1e-9))))


def pilot_a_over_h(F, rho, contact, cp: ContactParams, options: SweepOptions, cache=None) -> tuple:
    """The ``a_over_h`` predicted for ``options.rtol`` from a pilot two-level estimate.

    Parameters
    ----------
    F, rho : ndarray, shape (n,)
        Contact force [N] and cam radius of curvature [m] per angle.
    contact : ndarray of bool, shape (n,)
        Angles the FE answers.
    cp : ContactParams
        Contact parameters.
    options : SweepOptions
        With ``rtol`` (relative p0 error) and the effective ``tolerance``.
    cache : ModelCache, optional
        Where the pilot family models go.

    Returns
    -------
    a_over_h : float
        Even whole number >= 6 [-].
    pilots : list of dict
        ``{"rho_ref" (m), "a_ref" (m), "err_p0" (relative, at a/h 8), "a_over_h" (predicted)}``.
    """
    rtol = _validate.positive("rtol", options.rtol, "(relative p0 error)")
    fam, refs = plan_families(F, rho, cp, options.tolerance, contact)
    if not refs:
        return MIN_A_OVER_H, []
    kap = {f: (0.0 if math.isinf(r[0]) else cp.Rr / r[0]) for f, r in refs.items()}
    picks = sorted({min(kap, key=kap.get), max(kap, key=kap.get)})
    pilot = replace(options, a_over_h=PILOT_A_OVER_H)
    out, need = [], MIN_A_OVER_H
    for f in picks:
        est = family_estimate(cp, *refs[f], pilot, cache)
        n = predict_a_over_h(est, rtol / 2.0) if np.isfinite(est.err["p0"]) else 2 * PILOT_A_OVER_H
        need = max(need, n)
        out.append({"rho_ref": refs[f][0], "a_ref": refs[f][1], "err_p0": est.err["p0"], "a_over_h": n})
    return even_ceil(need), out


def rows_p0_estimate(F, rho, family, estimates: dict, cp: ContactParams) -> np.ndarray:
    """The p0 estimate of each row from its family's estimate (before the rows are solved).

    Parameters
    ----------
    F, rho : ndarray, shape (n,)
        Contact force [N] and cam radius [m] per angle.
    family : ndarray of int, shape (n,)
        Family id per angle (-1: none).
    estimates : dict[int, FamilyEstimate]
        The families' estimates.
    cp : ContactParams
        Contact parameters.

    Returns
    -------
    ndarray, shape (n,)
        Relative p0 error estimate [-] (NaN outside the families).
    """
    out = np.full(np.shape(F), np.nan)
    for f, est in estimates.items():
        idx = np.flatnonzero(np.asarray(family) == f)
        if idx.size == 0 or not isinstance(est, FamilyEstimate):
            continue
        a = hertz_half_width(np.asarray(F)[idx], np.asarray(rho)[idx], cp)
        out[idx] = [row_estimate(est, float(ai))["p0"] for ai in a]
    return out


def refine(a_over_h: float, worst: float, rtol: float) -> float:
    """The next ``a_over_h`` when the worst row's p0 estimate ``worst`` exceeds ``rtol``.

    Parameters
    ----------
    a_over_h : float
        Current elements per half-width [-].
    worst, rtol : float
        Worst row estimate and the requested bound (relative) [-].

    Returns
    -------
    float
        ``even_ceil(a_over_h (worst / rtol)^(1/p))`` and at least ``a_over_h + 2`` [-].
    """
    return even_ceil(max(a_over_h + 2.0, a_over_h * (worst / rtol) ** (1.0 / RATES["p0"])))


def rtol_settings(a_over_h, rtol, method: str, tolerance: float) -> tuple:
    """``(a_over_h, tolerance, rtol)`` of a sweep call: with ``rtol``, the pilot's ``a_over_h``
    and ``tolerance <= rtol / 2``.

    Parameters
    ----------
    a_over_h : float or None
        Elements per half-width as given [-] (refused together with ``rtol``).
    rtol : float or None
        Requested relative p0 error [-], in :data:`femcam.sweep.options.RTOL_RANGE`.
    method : str
        The sweep method (``"hertz"`` is refused with ``rtol``).
    tolerance : float or None
        The reuse tolerance as given [-]; None: :data:`DEFAULT_TOLERANCE`, or ``rtol / 2`` with
        ``rtol`` (measured on the seed 002 study model at rtol 1 %: 2 families and 2.9 s instead
        of 6 families and 13.5 s with 0.2 %, load 3.9).

    Returns
    -------
    tuple
        ``(a_over_h or None, tolerance, rtol or None)``; with ``rtol`` the tolerance is at most
        ``rtol / 2``.

    Raises
    ------
    InputError
        ``rtol`` with ``a_over_h``, with method ``hertz``, or out of range.
    """
    if rtol is None:
        return a_over_h, DEFAULT_TOLERANCE if tolerance is None else tolerance, None
    if a_over_h is not None:
        raise _validate.fail("a_over_h", a_over_h, "(elements per contact half-width)",
                             f"cannot be given with rtol = {rtol}: rtol chooses the mesh; give one")
    if method == "hertz":
        raise _validate.fail("rtol", rtol, "(relative p0 error)", "needs an FE method (fe or auto)")
    rtol = _validate.in_range("rtol", rtol, *RTOL_RANGE, "(relative p0 error)")
    if tolerance is None:
        return PILOT_A_OVER_H, rtol / 2.0, rtol
    return PILOT_A_OVER_H, min(_validate.positive("tolerance", tolerance, ""), rtol / 2.0), rtol


def choose_mesh(run, plan, estimate, cache) -> None:
    """``rtol``: the pilot's ``a_over_h``, then the families planned, verified and estimated
    there; one refinement when a row's p0 estimate still exceeds ``rtol``.

    Parameters
    ----------
    run : femcam.sweep.outputs.SweepRun
        The sweep's state after the analytic phase; ``opts``, ``family``, ``records``,
        ``estimates``, ``preplanned`` and ``rtol_info`` are set in place.
    plan, estimate : callable
        ``plan(run)`` and ``estimate(run, cache)``: the sweep's family and estimate phases.
    cache : ModelCache
        The process's model cache.

    Raises
    ------
    InputError
        A flat-faced follower (binned models, no families), or a chosen mesh too large.
    """
    cp = contact_params(run.scene)
    if run.scene.follower.flat_face:
        raise _validate.fail("rtol", run.opts.rtol, "(relative p0 error)", "needs model families; a "
                             "flat-faced follower's binned real-cam models carry no estimate; give a_over_h")
    F, rho = run.rows0["Fc"], run.rows0["rho"]
    fit = run.contact & ~roller_does_not_fit(rho, cp.Rr)
    n, pilots = pilot_a_over_h(F, rho, fit, cp, run.opts, cache)
    tried = []
    for attempt in range(2):
        run.opts = replace(run.opts, a_over_h=n)
        check_contact_elements(MeshOptions(a_over_h=n), "a_over_h (chosen for rtol)")
        run.preplanned, run.estimates = False, {}
        plan(run)
        estimate(run, cache)
        est = rows_p0_estimate(F, rho, run.family, run.estimates, cp)
        worst = float(np.nanmax(est)) if np.any(np.isfinite(est)) else float("nan")
        tried.append({"a_over_h": n, "worst_err_est_p0": worst})
        if not worst > run.opts.rtol or attempt == 1:
            break
        n = refine(n, worst, run.opts.rtol)
    run.preplanned = True
    run.rtol_info = {"rtol": run.opts.rtol, "a_over_h": run.opts.a_over_h,
                     "tolerance": run.opts.tolerance, "pilots": pilots, "levels": tried}
