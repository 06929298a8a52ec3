r"""Model families, verification: the reuse error of every family checked against the tolerance.

The **reuse error** of an angle is the relative difference of its FE peak pressure solved with
its family's model and solved with a model built fresh for that angle (mesh graded to the
angle's own Hertz half-width ``a`` and cam radius ``rho``: the naive path)::

    reuse_error = p0(family model) / p0(fresh model) - 1

:func:`verify_families` builds each family's model, solves it at (up to :data:`MAX_SCAN` of)
its load cases, and checks the angles where the reuse error is largest
(:func:`check_angles`) with fresh models (built with ``stress_operators="per_solve"``: only
their p0 is needed). A family whose ``max |reuse_error| > tolerance`` is split in two and
checked again, down to single load cases (whose family model *is* the fresh model).

One fresh model per family, not two, where Hertz applies
-----------------------------------------------------------
A model built for the angle itself has a nearly constant ``c = p0 / p0_Hertz - 1`` (its contact
edge sits on a node; measured -0.046 .. -0.055 % over the study model at a_over_h = 10), so
the reuse error at an angle whose family-model error is ``e`` is close to
``(1 + e) / (1 + c) - 1``. The first check (the family's largest ``e``) gives ``c`` of its fresh
model; a further candidate whose estimate plus :data:`ESTIMATE_MARGIN` stays within the tolerance
(or below the largest checked error) is recorded as *estimated* (``FamilyRecord.estimated``)
without a fresh model; any other candidate is checked fresh. The recorded ``reuse_error`` is the
largest of the fresh-checked and the estimated errors.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from types import SimpleNamespace

import numpy as np

from .. import _validate
from ..errors import FemcamError
from .cache import ModelCache, default_cache
from .options import ContactParams, ResolvedOptions
from .plan import contact_rows, curvature_ratio, family_reference, hertz_half_width, initial_groups
from .realcam import traction_args

__all__ = ["ESTIMATE_MARGIN", "MAX_SCAN", "N_CHECKS", "FamilyRecord", "check_angles",
           "verify_families"]
#: largest number of distinct load cases per family solved with the family model during the
#: verification to find its worst angles (more are sampled evenly in a)
MAX_SCAN = 128
#: default number of check candidates per family: the largest and smallest ``p0/p0_Hertz - 1``
#: of the family model (or, without Hertz, the worst edge offset and the extreme corner in
#: (a, Rr/rho)); each fresh check costs one model build (~0.3 s at a_over_h = 10)
N_CHECKS = 2
#: a candidate's reuse error is estimated instead of checked fresh when its estimate plus this
#: margin is within the tolerance (or below the largest checked error): 5.5 x the measured spread
#: of a fresh model's own p0/p0_Hertz - 1 (0.009 %, study model, a_over_h = 10)
ESTIMATE_MARGIN = 5e-4


@dataclass
class FamilyRecord:
    """One verified family (JSON-able through :meth:`to_dict`).

    Attributes
    ----------
    id : int
        Family id (-1 until numbered by :func:`verify_families`).
    rho_ref : float
        Cam radius of curvature the family model is built for [m] (``inf``: flat cam).
    a_ref : float
        Hertz half-width the family model's mesh is graded to [m].
    n_angles : int
        Angles in the family.
    a_ratio : tuple of (float, float)
        ``(min, max)`` of ``a / a_ref`` over the family [-].
    kappa : tuple of (float, float)
        ``(min, max)`` of ``Rr / rho`` over the family [-].
    checks : list of tuple
        ``[(theta_deg, a/a_ref, Rr/rho, reuse_error), ...]`` at the angles checked with fresh
        models (angle in degrees, the rest dimensionless).
    reuse_error : float
        The largest ``|reuse_error|`` of the checks and the estimates [-] (0 for a family of
        one load case: its model is the fresh model; ``inf`` when a scan solve failed).
    build_time : float
        Time to build the family model [s] (this process, during the verification; 0 if cached).
    check_time : float
        Time of the fresh check models and solves [s].
    solve_time : float
        Time per solve with the family model [s] (median, the solve's own timing).
    p0_vs_hertz : tuple of (float, float)
        Range of the family model's ``p0 / p0_Hertz - 1`` over the scanned load cases [-]
        (where Hertz applies; NaN otherwise).
    n_scanned : int
        Load cases solved with the family model during the verification.
    n_rebuilt : int
        Angles the model does not cover (solved with models of their own).
    estimated : list of tuple
        As ``checks``, for candidates whose reuse error was only estimated (module docstring:
        well below the checked worst).
    a_over_h : float
        Elements per ``a_ref`` of the family model's mesh [-] (the sweep's ``a_over_h``, or the
        family's own when ``rtol`` chose it: :mod:`femcam.sweep.rtol`; NaN: not recorded).
    """

    id: int
    rho_ref: float
    a_ref: float
    n_angles: int
    a_ratio: tuple[float, float]
    kappa: tuple[float, float]
    checks: list = field(default_factory=list)
    reuse_error: float = 0.0
    build_time: float = 0.0
    check_time: float = 0.0
    solve_time: float = float("nan")
    p0_vs_hertz: tuple = (float("nan"), float("nan"))
    n_scanned: int = 0
    n_rebuilt: int = 0
    estimated: list = field(default_factory=list)
    a_over_h: float = float("nan")

    def to_dict(self) -> dict:
        """The record as JSON-able lists and numbers (``plan.json``, provenance).

        Returns
        -------
        dict
            Field name -> value (tuples as lists; the fields' units).
        """
        return {"id": self.id, "rho_ref": self.rho_ref, "a_ref": self.a_ref,
                "n_angles": self.n_angles, "a_ratio": list(self.a_ratio),
                "kappa": list(self.kappa), "checks": [list(c) for c in self.checks],
                "reuse_error": self.reuse_error, "build_time": self.build_time,
                "check_time": self.check_time, "solve_time": self.solve_time,
                "p0_vs_hertz": list(self.p0_vs_hertz), "n_scanned": self.n_scanned,
                "n_rebuilt": self.n_rebuilt, "estimated": [list(c) for c in self.estimated],
                "a_over_h": self.a_over_h}

    @classmethod
    def from_dict(cls, d: dict) -> FamilyRecord:
        """The record of :meth:`to_dict` (``plan.json`` of a resumed sweep; files written
        before ``estimated`` existed load with none).

        Parameters
        ----------
        d : dict
            A dict written by :meth:`to_dict`.

        Returns
        -------
        FamilyRecord
            The record.
        """
        return cls(**{**d, "a_ratio": tuple(d["a_ratio"]), "kappa": tuple(d["kappa"]),
                      "p0_vs_hertz": tuple(d.get("p0_vs_hertz", (math.nan, math.nan))),
                      "checks": [tuple(c) for c in d["checks"]],
                      "estimated": [tuple(c) for c in d.get("estimated", ())]})


def _edge_offset(x_nodes: np.ndarray, a: np.ndarray) -> np.ndarray:
    """Distance of the contact edge ``x = a`` from the nearest mesh node, in units of the local
    node spacing (0 on a node, 0.5 mid-element)."""
    x = np.asarray(x_nodes, float)
    x = x[x > 0]
    if x.size < 2:
        return np.zeros_like(a)
    j = np.clip(np.searchsorted(x, a), 1, x.size - 1)
    lo, hi = x[j - 1], x[j]
    d = np.minimum(np.abs(a - lo), np.abs(hi - a)) / (hi - lo)
    return np.where((a > x[-1]) | (a < x[0]), 0.5, d)


def check_angles(a, kappa, a_ref, k_ref, x_nodes, n_checks: int = N_CHECKS,
                 e_hertz=None) -> list[int]:
    """Indices (into ``a``/``kappa``) of the angles to check with a fresh model, worst first.

    With ``e_hertz`` (the family model's ``p0 / p0_Hertz - 1`` at every angle, cheap: one small
    solve each): its largest and its smallest value. A model built for the angle itself has a
    nearly constant ``p0 / p0_Hertz - 1`` (its edge sits on a node; measured -0.046 .. -0.055 %
    over the study model at a_over_h = 10), so the reuse error is largest at these two angles,
    whatever the cause (edge between nodes, mesh coarser or finer than ``a/h``, body shape).
    Then, or without ``e_hertz`` (Hertz does not apply): the largest edge offset from a mesh node
    and the family's extreme corner in the normalised (``ln(a/a_ref)``, ``kappa - k_ref``) plane,
    then the extremes of ``a`` and ``kappa``. Load cases equal to one already chosen are skipped.

    Parameters
    ----------
    a, kappa : ndarray, shape (m,)
        Hertz half-width (m) and ``Rr/rho`` of the family's covered angles.
    a_ref, k_ref : float
        The family model's reference half-width (m) and ``Rr/rho_ref``.
    x_nodes : ndarray
        Contact-surface node abscissae of the family mesh (m).
    n_checks : int
        How many angles to return at most.
    e_hertz : ndarray, shape (m,), optional
        ``p0 / p0_Hertz - 1`` of the family model (NaN where not solved).

    Returns
    -------
    list of int
    """
    if a.size == 0:
        return []
    la = np.log(a / a_ref)
    dk = kappa - k_ref
    sa, sk = float(np.max(np.abs(la))), float(np.max(np.abs(dk)))
    dn = np.hypot(la / sa if sa > 0 else 0.0 * la, dk / sk if sk > 0 else 0.0 * dk)
    cands = []
    if e_hertz is not None:
        e = np.asarray(e_hertz, float)
        if np.any(np.isfinite(e)):
            cands += [int(np.nanargmax(e)), int(np.nanargmin(e))]
    cands += [int(np.argmax(_edge_offset(x_nodes, a) + 1e-6 * np.abs(la))),
              int(np.argmax(dn)),
              int(np.argmax(np.abs(la))), int(np.argmax(np.abs(dk))),
              int(np.argmin(la)), int(np.argmax(la)),
              int(np.argmin(kappa)), int(np.argmax(kappa))]
    out, seen = [], set()
    for i in cands:
        key = (float(a[i]), float(kappa[i]))
        if key in seen:
            continue
        seen.add(key)
        out.append(i)
        if len(out) >= n_checks:
            break
    return out


def _same_case(rho, a, rho_ref, a_ref) -> bool:
    same_rho = (rho == rho_ref) or (math.isfinite(rho) and math.isfinite(rho_ref)
                                    and abs(rho / rho_ref - 1.0) <= 1e-12)
    return same_rho and abs(a / a_ref - 1.0) <= 1e-12


def verify_families(F, rho, theta, cp: ContactParams, options: ResolvedOptions,
                    contact: np.ndarray, n_checks: int = N_CHECKS, *,
                    cache: ModelCache | None = None, traction=None, prefetch=None):
    """Plan the families and verify the reuse error against ``options.tolerance``.

    Runs in the calling process (deterministically: the result depends only on the angles and
    options). Family models built here stay in ``cache`` (default: this process's
    :func:`default_cache`; forked workers inherit it). The groups are verified in waves (the
    initial groups, then the halves of those that failed): each wave's models are built, scanned
    and their first candidates' fresh checks started before any verdict, so that with the
    cache's background thread on (:meth:`ModelCache.building_in_background`) the builds of
    one wave run on both cores; the records do not depend on it.

    Parameters
    ----------
    F, rho, theta : ndarray, shape (n,)
        Contact force (N), cam radius of curvature (m) and cam angle (rad) of every angle.
    cp : ContactParams
        The scene's contact parameters.
    options : ResolvedOptions
        ``tolerance`` and ``a_over_h``.
    contact : ndarray of bool, shape (n,)
        Angles with contact (and a roller that fits).
    n_checks : int
        Fresh-model checks per family.
    cache : ModelCache, optional
        Where the family models are kept.
    traction : femcam.sweep.realcam.Traction, optional
        Per-angle traction of the load cases (default: full sliding in ``cp.sliding``); the
        chunks solve the same load cases, so they reuse the scanned results.
    prefetch : callable, optional
        ``prefetch(rho_ref, a_ref)`` (m) is called for each group before its model is built,
        e.g. to start the family's error estimate in the background
        (:func:`femcam.sweep.estimate.prefetch_estimate`).

    Returns
    -------
    family, refs
        As :func:`plan_families`, for the verified families.
    records : list of FamilyRecord
        One per family, ids in order.
    """
    cache = default_cache() if cache is None else cache
    F, rho = contact_rows(F, rho, contact)
    theta = _validate.finite_array("theta", theta, "rad")
    n_checks = _validate.integer("n_checks", n_checks, 1, "checks")
    fam = np.full(F.shape, -1, dtype=int)
    idx = np.flatnonzero(contact)
    if idx.size == 0:
        return fam, {}, []
    a_all = hertz_half_width(F[idx], rho[idx], cp)
    k_all = curvature_ratio(rho[idx], cp.Rr)
    queue = initial_groups(a_all, k_all, float(options.tolerance))
    done: list[tuple[np.ndarray, FamilyRecord]] = []
    case = _Case(cache, cp, options, F, rho, theta, traction)
    while queue:  # in waves: a wave's models, scans and first checks, then its verdicts
        wave, queue = queue, []
        refs = [family_reference(a_all[g], k_all[g], rho[idx[g]], cp.Rr) for g in wave]
        for ref in refs[1:]:  # the first is built here now; the others meanwhile, if a
            cache.prefetch_model(cp, *ref, options)  # background thread is on (else nothing)
        for ref in refs if prefetch is not None else ():
            prefetch(*ref)
        staged = [_scan_group(case, n_checks, idx[g], a_all[g], k_all[g]) for g in wave]
        for g, st in zip(wave, staged, strict=True):
            rec = _finish_group(case, st)
            if rec.reuse_error <= float(options.tolerance):
                done.append((g, rec))
                continue
            cache.forget(cp, rec.rho_ref, rec.a_ref, options)  # replaced by the two halves
            queue += _split(g, a_all[g], k_all[g])
    # deterministic ids: by reference half-width, then curvature
    done.sort(key=lambda t: (t[1].a_ref, t[1].kappa[0], t[1].kappa[1]))
    refs, records = {}, []
    for n, (g, rec) in enumerate(done):
        rec.id, rec.a_over_h = n, float(options.a_over_h)
        refs[n] = (rec.rho_ref, rec.a_ref)
        fam[idx[g]] = n
        records.append(rec)
    return fam, refs, records


@dataclass(frozen=True)
class _Case:
    """What every family of one verification shares."""

    cache: ModelCache
    cp: ContactParams
    options: ResolvedOptions
    F: np.ndarray
    rho: np.ndarray
    theta: np.ndarray
    traction: object


def _scan_group(case: _Case, n_checks, rows, a, kap) -> SimpleNamespace:
    """Build (or take) one group's model, scan its load cases, pick the check candidates and
    start the first one's fresh check in the background (:meth:`ModelCache.prefetch_fresh`;
    nothing without a background thread); :func:`_finish_group` checks them."""
    cache, cp, F, rho = case.cache, case.cp, case.F, case.rho
    rho_ref, a_ref = family_reference(a, kap, rho[rows], cp.Rr)
    rec = FamilyRecord(id=-1, rho_ref=rho_ref, a_ref=a_ref, n_angles=int(rows.size),
                       a_ratio=(float(a.min() / a_ref), float(a.max() / a_ref)),
                       kappa=(float(kap.min()), float(kap.max())))
    built_before, time_before = cache.stats["built"], cache.stats["build_time"]
    model = cache.model_for(cp, rho_ref, a_ref, case.options)
    # the build's own time (it may have run in the background while this thread worked)
    rec.build_time = cache.stats["build_time"] - time_before if cache.stats["built"] > built_before else 0.0
    covered = np.array([model.covers(F[i], rho[i]) for i in rows])
    rec.n_rebuilt = int(np.count_nonzero(~covered))  # solved with models of their own
    cov = np.flatnonzero(covered)
    n_distinct = len({(float(x), float(y)) for x, y in zip(a, kap, strict=True)})
    rows, a, kap = rows[cov], a[cov], kap[cov]
    e_h, failed = _scan_family(cache, model, cp, rec, rows, a, kap, F, rho, case.traction)
    picks = []
    if not failed:
        k_ref = cp.Rr / rho_ref if math.isfinite(rho_ref) else 0.0
        picks = check_angles(a, kap, a_ref, k_ref, model.x, n_checks, e_hertz=e_h)
    if picks:  # the first candidate is always checked fresh (_check)
        i, j = int(rows[picks[0]]), picks[0]
        if not _same_case(float(rho[i]), float(a[j]), rho_ref, a_ref):
            cache.prefetch_fresh(cp, float(rho[i]), float(a[j]), case.options, float(F[i]),
                                 traction_args(case.traction, i, cp.sliding))
    return SimpleNamespace(rec=rec, model=model, rows=rows, a=a, kap=kap, e_h=e_h,
                           failed=failed, picks=picks, n_distinct=n_distinct)


def _finish_group(case: _Case, st: SimpleNamespace) -> FamilyRecord:
    """Check the worst candidates of a scanned group (:func:`_scan_group`) with fresh models;
    its record."""
    rec = st.rec
    t1 = time.perf_counter()
    worst = math.inf if st.failed else _check(case, rec, st.model, st.rows, st.a, st.kap, st.e_h,
                                              st.picks)
    if np.any(np.isfinite(st.e_h)):
        rec.p0_vs_hertz = (float(np.nanmin(st.e_h)), float(np.nanmax(st.e_h)))
    rec.check_time = time.perf_counter() - t1
    # one load case: the family model is its fresh model
    rec.reuse_error = 0.0 if st.n_distinct == 1 else worst
    return rec


def _check(case: _Case, rec: FamilyRecord, model, rows, a, kap, e_h, picks) -> float:
    """Fresh-model checks of the candidates ``picks`` (worst first), or estimates where the
    estimate is safely within the tolerance (module docstring); the largest ``|reuse_error|``
    checked or estimated."""
    worst, c_fresh = 0.0, math.nan  # c_fresh: the first fresh model's p0 / p0_Hertz - 1
    tol = float(case.options.tolerance)
    for j in picks:
        i = int(rows[j])
        row = (float(np.degrees(case.theta[i])), float(a[j] / rec.a_ref), float(kap[j]))
        if worst > tol:  # the family is split anyway
            break
        est = (1.0 + e_h[j]) / (1.0 + c_fresh) - 1.0
        if math.isfinite(est) and abs(est) + ESTIMATE_MARGIN <= max(worst, tol):
            rec.estimated.append((*row, float(est)))
            worst = max(worst, abs(est))
            continue
        err = _reuse_error(case.cache, model, case.cp, case.options, float(case.F[i]),
                           float(case.rho[i]), float(a[j]),
                           _same_case(float(case.rho[i]), float(a[j]), rec.rho_ref, rec.a_ref),
                           traction_args(case.traction, i, case.cp.sliding))
        rec.checks.append((*row, err))
        if math.isnan(err):
            continue
        worst = max(worst, abs(err))
        if math.isnan(c_fresh) and math.isfinite(err) and math.isfinite(e_h[j]):
            c_fresh = (1.0 + e_h[j]) / (1.0 + err) - 1.0
    return worst


def _scan_family(cache, model, cp, rec, rows, a, kap, F, rho, traction=None) -> tuple[np.ndarray, bool]:
    """Solve the family model at (up to MAX_SCAN of) its covered load cases: ``p0 / p0_Hertz - 1``
    per case (NaN where not scanned) and whether a solve failed. The results stay in ``cache``,
    so the chunks computed in this process or in forked workers reuse them."""
    e_h = np.full(rows.size, np.nan)
    t_solves = []
    failed = False
    for j in _scan_subset(a, kap, F[rows], rho[rows]):
        i = int(rows[j])
        try:
            sl, Q, roll = traction_args(traction, i, cp.sliding)
            r = cache.solve(model, float(F[i]), float(rho[i]), cp.mu, sl, Q=Q, rolling=roll)
        except (FemcamError, ValueError, ArithmeticError):
            failed = True
            break
        t_solves.append(r.timings.get("contact", np.nan) + r.timings.get("recovery", 0.0))
        rec.n_scanned += 1
        if np.isfinite(r.hertz_p0) and r.hertz_p0 > 0:
            e_h[j] = r.p0_nodal / r.hertz_p0 - 1.0
    rec.solve_time = float(np.nanmedian(t_solves)) if t_solves else float("nan")
    return e_h, failed


def _scan_subset(a, kappa, F, rho, max_scan: int | None = None) -> np.ndarray:
    """Indices of the distinct load cases to solve with the family model (all of them, or
    ``max_scan`` spread evenly over the sorted half-widths plus the curvature extremes)."""
    max_scan = MAX_SCAN if max_scan is None else max_scan
    _, first = np.unique(np.column_stack([F, rho]), axis=0, return_index=True)
    first = np.sort(first)
    if first.size <= max_scan:
        return first
    order = first[np.argsort(a[first], kind="stable")]
    pick = order[np.unique(np.round(np.linspace(0, order.size - 1, max_scan - 2)).astype(int))]
    extra = [first[int(np.argmin(kappa[first]))], first[int(np.argmax(kappa[first]))]]
    return np.unique(np.concatenate([pick, extra]))


def _split(g, a, kap) -> list[np.ndarray]:
    """Two halves of a group: in ln a at its geometric centre, or in kappa if a is constant."""
    la = np.log(a)
    if la.max() - la.min() > 1e-12:
        cut = 0.5 * (la.min() + la.max())
        lo = la <= cut
    else:
        cut = 0.5 * (kap.min() + kap.max())
        lo = kap <= cut
    return [g[lo], g[~lo]]


def _reuse_error(cache, model, cp, options, F, rho, a, same: bool, load=(None, None, 0)) -> float:
    """``p0(family model)/p0(fresh model) - 1`` at one load case (``load``: sliding, Q, rolling);
    ``inf`` if the family model cannot solve it (the family must be split), NaN if the fresh
    model cannot."""
    sl, Q, roll = load
    try:
        r = cache.solve(model, F, rho, cp.mu, cp.sliding if sl is None else sl, Q=Q, rolling=roll)
    except (FemcamError, ValueError, ArithmeticError):
        return math.inf
    if same:
        return 0.0
    p0_fresh = cache.fresh_p0(cp, rho, a, options, F, load)
    return float(r.p0_nodal / p0_fresh - 1.0) if math.isfinite(p0_fresh) else math.nan
