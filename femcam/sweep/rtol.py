r"""Accuracy on demand: the mesh of each model family chosen for a requested p0 error (``rtol``).

The estimated p0 error of an FE row (:mod:`femcam.sweep.estimate`) has two parts: the
discretisation error of its family's mesh carried to the row, and the family's verified reuse
error (bounded by ``tolerance``). ``rtol`` splits the budget in half:

1. ``tolerance = rtol / 2`` (``min(tolerance, rtol / 2)`` when a tolerance is given): the family
   verification keeps the reuse error within half the budget;
2. the families are planned (:func:`femcam.sweep.plan.plan_families`) and **each** gets a
   **pilot** p0 estimate at ``a_over_h = 8``: 2D elasticity is scale invariant, so the relative
   error at a given ``a/h`` changes only with the shape of the gap (``Rr / rho``); the two-level
   estimate is solved on the families with the smallest and the largest ``Rr / rho`` and
   interpolated linearly in ``Rr / rho`` for the others (a pilot solve for each of 11 families
   cost 5 s more at rtol 0.1 % on the study model, which its choices did not win back). The
   family's pilot carried to its smallest row half-width ``a_min`` predicts the family's own
   ``a_over_h`` whose discretisation error is ``rtol / 2`` on every row:
   ``n_f = 8 (e_8 (a_ref / a_min)^p / (rtol / 2))^{1/p}``, rounded up to an even whole number
   >= 6 (an even ``a_over_h`` keeps the contact centre and the Hertz edge on nodes of both
   estimate levels, where the two-level estimate was validated). A flat or mildly curved family
   stays coarse while a sharply curved one is refined: the least elements that meet ``rtol``
   family by family, instead of the worst family's mesh everywhere;
3. each planned family's rows are verified (:func:`femcam.sweep.verify.verify_families`, split
   until the reuse error is within ``tolerance``) and estimated at its ``n_f``; a family whose
   worst row estimate still exceeds ``rtol`` is refined once more by the same rule from that
   row (:func:`refine`), verified and estimated again (rows still above are flagged
   ``rtol_not_met``).

The families are then numbered as :func:`~femcam.sweep.verify.verify_families` numbers them
(reference half-width, then curvature); each :class:`~femcam.sweep.verify.FamilyRecord` keeps
its ``a_over_h`` (the model cache and the persistent cache key on it through
:func:`femcam.sweep.cache.model_args`), each row its ``a_over_h_row``, and the provenance's
``rtol_choice`` the pilot of every planned family and every level tried. The sweep's
``a_over_h`` (``ResolvedOptions.a_over_h``, used by models outside the families: the layer and ring
side columns) is the largest family's.

**Which quantities** (``rtol_on``, ``--rtol-on``, ``[fe] rtol_on``; default ``p0``): any of
the ``err_est_*`` stems of :data:`femcam.sweep.options.RTOL_ON` (``p0``, ``a``, ``vm``, ``tau1``
and, on a coated scene, ``interface_tau``, ``interface_sn``). Each family's ``a_over_h`` is the
largest any chosen quantity needs: p0's target is ``rtol / 2`` (the reuse error takes the other
half), the others' ``rtol`` (their row estimate holds no reuse part); the pilot interpolates
each chosen quantity, and the refinement step checks them all. The ring model's estimates
(:mod:`femcam.sweep.ringhead`) are reported, not controlled: the ring's mesh is not a family's.
"""

from __future__ import annotations

import math

import numpy as np

from .. import _validate
from ..mesh import MeshOptions
from ..mesh.estimate import check_contact_elements
from .estimate import (
    LAYER_QUANTITIES,
    RATES,
    FamilyEstimate,
    family_estimate,
    predict_a_over_h,
    prefetch_estimate,
    row_estimate,
)
from .options import RTOL_RANGE, ContactParams, contact_params
from .plan import hertz_half_width, plan_families
from .verify import verify_families

__all__ = ["PILOT_A_OVER_H", "choose_mesh", "even_ceil", "family_need", "refine", "rows_p0_estimate",
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


def family_need(est: FamilyEstimate, a_rows, target: float, quantity: str = "p0") -> float:
    r"""The ``a_over_h`` at which a family's p0 discretisation estimate meets ``target`` on all of
    its rows (the row with the smallest half-width has the largest estimate).

    .. math:: n = n_0 \left(\frac{e_0 (a_{ref} / a_{min})^p}{target}\right)^{1/p}

    Parameters
    ----------
    est : FamilyEstimate
        The family's estimate at ``est.a_over_h``.
    a_rows : array_like, shape (m,)
        Hertz half-widths of the family's rows [m].
    target : float
        Relative error to reach [-].
    quantity : str
        The estimated quantity (a key of :data:`femcam.sweep.estimate.RATES`).

    Returns
    -------
    float
        Even whole number >= 6 [-]; ``2 * PILOT_A_OVER_H`` when the estimate failed (NaN).
    """
    target = _validate.positive("target", target, "(relative error)")
    a_rows = np.asarray(a_rows, dtype=float)
    a_rows = a_rows[np.isfinite(a_rows) & (a_rows > 0)]
    scale = float(np.max(est.a_ref / a_rows)) ** RATES[quantity] if a_rows.size else 1.0
    n = predict_a_over_h(est, target / scale, quantity) if quantity in est.err else np.nan
    return even_ceil(n if np.isfinite(n) else 2 * PILOT_A_OVER_H)


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


def refine(a_over_h: float, worst: float, rtol: float, quantity: str = "p0") -> float:
    """The next ``a_over_h`` when the worst row's estimate ``worst`` of ``quantity`` exceeds ``rtol``.

    Parameters
    ----------
    a_over_h : float
        Current elements per half-width [-].
    worst, rtol : float
        Worst row estimate and the requested bound (relative) [-].
    quantity : str
        The estimated quantity (its rate, :data:`femcam.sweep.estimate.RATES`).

    Returns
    -------
    float
        ``even_ceil(a_over_h (worst / rtol)^(1/p))`` and at least ``a_over_h + 2`` [-].
    """
    return even_ceil(max(a_over_h + 2.0, a_over_h * (worst / rtol) ** (1.0 / RATES[quantity])))


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
        ``rtol`` (a looser reuse bound means fewer families; the cost of each tolerance is in
        docs/performance.md).

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
        raise _validate.fail("rtol (--rtol-pct / 100)", rtol, "(relative p0 error)",
                             "needs an FE method (fe or auto)")
    rtol = _validate.in_range("rtol (--rtol-pct / 100)", rtol, *RTOL_RANGE, "(relative p0 error)")
    if tolerance is None:
        return PILOT_A_OVER_H, rtol / 2.0, rtol
    return PILOT_A_OVER_H, min(_validate.positive("tolerance", tolerance, ""), rtol / 2.0), rtol


def choose_mesh(run, fit_rows, cache) -> None:
    """``rtol``: each planned family's own ``a_over_h`` from its pilot estimate, its rows verified
    and estimated there, refined once more where a row's p0 estimate still exceeds ``rtol``.

    Parameters
    ----------
    run : femcam.sweep.outputs.SweepRun
        The sweep's state after the analytic phase; ``opts`` (``a_over_h``: the largest family's),
        ``family``, ``records``, ``estimates``, ``preplanned`` and ``rtol_info`` are set in place.
    fit_rows : callable
        ``fit_rows(run) -> ndarray of bool``: the rows the family models answer (sets
        ``run.hertz`` for method auto).
    cache : ModelCache
        The process's model cache.

    Raises
    ------
    InputError
        A flat-faced follower (binned models, no families), or a chosen mesh too large.
    """
    cp = contact_params(run.scene)
    rtol = run.opts.rtol
    if run.scene.follower.flat_face:
        raise _validate.fail("rtol_pct (--rtol-pct)", 100 * rtol, "%", "needs model families; a "
                             "flat-faced follower's binned real-cam models carry no estimate; give "
                             "[fe] a_over_h or --a-over-h instead")
    on = run.opts.rtol_on
    if cp.coat_body is None and any(q in LAYER_QUANTITIES for q in on):
        raise _validate.fail("rtol_on (--rtol-on)", ",".join(on), "", "names an interface stress "
                             f"({', '.join(LAYER_QUANTITIES)}) but the scene has no coating "
                             "([materials.<body>.coating]); choose from p0, a, vm, tau1")
    F, rho = run.rows0["Fc"], run.rows0["rho"]
    fit = fit_rows(run)
    fam0, refs = plan_families(F, rho, cp, run.opts.tolerance, fit)
    pilots, groups, tried = [], [], []
    for f, est in _pilot_estimates(cp, refs, run.opts, cache, on).items():
        rows = fit & (fam0 == f)
        a_rows = hertz_half_width(F[rows], rho[rows], cp)
        n = max(family_need(est, a_rows, rtol / 2.0 if q == "p0" else rtol, q) for q in on)
        pilots.append({"rho_ref": refs[f][0], "a_ref": refs[f][1], "n_angles": int(rows.sum()),
                       "err_p0": est.err["p0"], "err": {q: est.err.get(q, math.nan) for q in on},
                       "solved": bool(est.a_over_h_coarse > 0), "a_over_h": n})
        groups += _verified(run, cp, rows, n, cache)
    final = []
    for idx, rec, est in groups:
        worst = _worst_on(F[idx], rho[idx], est, cp, on)
        tried.append({"rho_ref": rec.rho_ref, "a_ref": rec.a_ref, "a_over_h": rec.a_over_h,
                      "worst_err_est_p0": _worst(F[idx], rho[idx], est, cp), "worst": worst})
        over = {q: w for q, w in worst.items() if w > rtol}
        if not over:
            final.append((idx, rec, est))
            continue
        mask = np.zeros(fit.shape, bool)
        mask[idx] = True
        n_next = max(refine(rec.a_over_h, w, rtol, q) for q, w in over.items())
        for g in _verified(run, cp, mask, n_next, cache):
            tried.append({"rho_ref": g[1].rho_ref, "a_ref": g[1].a_ref, "a_over_h": g[1].a_over_h,
                          "worst_err_est_p0": _worst(F[g[0]], rho[g[0]], g[2], cp),
                          "worst": _worst_on(F[g[0]], rho[g[0]], g[2], cp, on)})
            final.append(g)
    _number(run, final)
    n_all = [rec.a_over_h for rec in run.records]
    run.opts = run.opts.for_family(max(n_all) if n_all else PILOT_A_OVER_H)
    run.preplanned = True
    run.rtol_info = {"rtol": rtol, "rtol_on": list(on), "a_over_h": run.opts.a_over_h,
                     "tolerance": run.opts.tolerance,
                     "per_family": True, "family_a_over_h": n_all, "pilots": pilots, "levels": tried}


def _pilot_estimates(cp: ContactParams, refs: dict, options, cache, on=("p0",)) -> dict:
    """The pilot estimate (p0 and the quantities ``on``) at ``a/h = 8`` of every planned family:
    solved on the families with the smallest and the largest ``Rr / rho`` (two fine and two
    coarse builds, whatever the number of families), interpolated linearly in ``Rr / rho``
    between them for the others (marked ``a_over_h_coarse = 0``); the per-family refinement
    catches an interpolation that falls short."""
    kap = {f: (0.0 if math.isinf(r[0]) else cp.Rr / r[0]) for f, r in refs.items()}
    if not kap:
        return {}
    picks = sorted({min(kap, key=kap.get), max(kap, key=kap.get)}, key=kap.get)
    pilot_opts = options.for_family(PILOT_A_OVER_H)
    # the builds the first estimate does not wait for: in the background thread, if the caller
    # started one (ModelCache.building_in_background; else nothing)
    for i, f in enumerate(picks if cache is not None else ()):
        if i:
            cache.prefetch_model(cp, *refs[f], pilot_opts)
        prefetch_estimate(cp, *refs[f], pilot_opts, cache)
    solved = {f: family_estimate(cp, *refs[f], pilot_opts, cache) for f in picks}
    k = [kap[f] for f in picks]
    keys = dict.fromkeys(("p0", "a", "vm", "tau1", *on))
    out = {}
    for f in refs:
        if f in solved:
            out[f] = solved[f]
            continue
        err = {q: (float(np.interp(kap[f], k, [solved[g].err.get(q, math.nan) for g in picks]))
                   if q == "p0" or q in on else math.nan) for q in keys}
        out[f] = FamilyEstimate(refs[f][1], PILOT_A_OVER_H, 0.0, err)
    return out


def _verified(run, cp: ContactParams, rows, n: float, cache) -> list:
    """Rows ``rows`` verified at ``a_over_h = n`` (split as needed), each family estimated:
    ``[(row indices, FamilyRecord, FamilyEstimate), ...]``."""
    opts = run.opts.for_family(n)
    check_contact_elements(MeshOptions(a_over_h=n), "a_over_h (chosen for rtol)")
    fam, _, recs = verify_families(run.rows0["Fc"], run.rows0["rho"], run.angles, cp, opts, rows,
                                   cache=cache, traction=run.traction,
                                   prefetch=lambda r, a: prefetch_estimate(cp, r, a, opts, cache))
    out = []
    for rec in recs:
        reuse = rec.reuse_error if np.isfinite(rec.reuse_error) else math.nan
        out.append((np.flatnonzero(fam == rec.id), rec,
                    family_estimate(cp, rec.rho_ref, rec.a_ref, opts, cache, reuse)))
    return out


def _worst(F, rho, est: FamilyEstimate, cp: ContactParams) -> float:
    """The largest row p0 estimate of a family (NaN when none is finite)."""
    e = rows_p0_estimate(F, rho, np.zeros(np.shape(F), int), {0: est}, cp)
    return float(np.nanmax(e)) if np.any(np.isfinite(e)) else math.nan


def _worst_on(F, rho, est: FamilyEstimate, cp: ContactParams, on) -> dict:
    """The largest row estimate of each quantity ``on`` over a family's rows: p0 with the reuse
    error (:func:`_worst`), the others carried to the smallest row half-width."""
    a = hertz_half_width(np.asarray(F), np.asarray(rho), cp)
    a = a[np.isfinite(a) & (a > 0)]
    out = {}
    for q in on:
        if q == "p0":
            out[q] = _worst(F, rho, est, cp)
        else:
            e = est.err.get(q, math.nan)
            out[q] = float(e * np.max(est.a_ref / a) ** RATES[q]) if a.size else math.nan
    return out


def _number(run, groups: list) -> None:
    """Families numbered as :func:`~femcam.sweep.verify.verify_families` numbers them (reference
    half-width, then curvature, then ``a_over_h``): ``run.family``, ``run.records``,
    ``run.estimates``."""
    groups = sorted(groups, key=lambda g: (g[1].a_ref, g[1].kappa[0], g[1].kappa[1], g[1].a_over_h))
    run.family = np.full(run.angles.size, -1)
    run.records, run.estimates = [], {}
    for k, (idx, rec, est) in enumerate(groups):
        rec.id = k
        run.family[idx] = k
        run.records.append(rec)
        run.estimates[k] = est
