"""Model families: which angles share one FE model, and the per-process model cache.

2D linear elasticity is invariant under a uniform scaling of the geometry; from angle to angle
only the gap shape and the load change. So angles are grouped into families that share one
:class:`femcam.fe.ContactModel` (mesh + factorisation + condensation), planned deterministically
from the analytic chain (:func:`plan_families`), and every worker process keeps the models it
built (:func:`model_for`). The reuse error this causes is measured in ``docs/sweep.md``.
"""

from __future__ import annotations

import time
from collections import OrderedDict
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:  # pragma: no cover
    from .pipeline import ContactParams, SweepOptions


def hertz_half_width_any(F, rho, cp: ContactParams) -> np.ndarray:
    """Hertz-like half-width estimate for sizing meshes, also where Hertz is invalid (uses |R|)."""
    from ..materials import effective_modulus

    E_star = effective_modulus(cp.cam, cp.roller, cp.plane)
    with np.errstate(divide="ignore"):
        R = np.abs(1.0 / (1.0 / np.asarray(rho, float) + 1.0 / cp.Rr))
    R = np.minimum(R, 1e3 * cp.Rr)  # nearly conformal: cap, FE decides the real width
    return np.sqrt(4.0 * np.maximum(F, 0.0) / cp.length * R / (np.pi * E_star))


def family_spans(tolerance: float) -> tuple[float, float]:
    """``(a_span, kappa_span)`` of one family for a reuse tolerance on p0.

    A family holds angles with ``max(a)/min(a) <= a_span`` and
    ``max(kappa) - min(kappa) <= kappa_span``, ``kappa = Rr/rho``. Calibrated on the reuse study
    in ``docs/sweep.md`` (a_over_h = 10): changing the cam curvature by 0.4 Rr/rho moves p0 by
    < 0.01 %; moving a away from a_ref moves p0 by up to ~0.2 % (the contact edge falls between
    nodes), independently of the distance within +-12 %. So the default tolerance 2e-3 gives
    ``a_span = 1.25``, ``kappa_span = 0.8``; ``tolerance -> 0`` gives one model per distinct
    angle (the naive path).
    """
    return 1.0 + 125.0 * tolerance, min(400.0 * tolerance, 0.95)


def _clusters(v: np.ndarray, span, ratio: bool) -> np.ndarray:
    """Greedy 1D clustering of sorted values: a new cluster when v exceeds start * span
    (``ratio``) or start + span."""
    order = np.argsort(v, kind="stable")
    lab = np.empty(v.size, dtype=int)
    k, start = -1, None
    for j in order:
        x = v[j]
        if start is None or (x > start * span if ratio else x > start + span):
            k += 1
            start = x
        lab[j] = k
    return lab


def plan_families(F, rho, cp: ContactParams, tolerance: float, contact: np.ndarray):
    """Deterministic family id per angle (``-1`` where there is no contact) and references.

    Greedy clustering of the contact angles, first in the Hertz half-width ``a`` (ratio
    ``a_span``), then in the curvature ratio ``kappa = Rr/rho`` (width ``kappa_span``), see
    :func:`family_spans`. The reference of a family is the geometric centre of its ``a`` range
    and the centre of its ``kappa`` range. The plan depends only on the set of angles, so chunking,
    worker count and resuming do not change any result. Returns ``(family, refs)`` with
    ``refs[fid] = (rho_ref, a_ref)``.
    """
    F = np.asarray(F, float)
    rho = np.asarray(rho, float)
    fam = np.full(F.shape, -1, dtype=int)
    refs: dict[int, tuple[float, float]] = {}
    idx = np.flatnonzero(contact)
    if idx.size == 0:
        return fam, refs
    a_span, k_span = family_spans(tolerance)
    a = hertz_half_width_any(F[idx], rho[idx], cp)
    with np.errstate(divide="ignore"):
        kappa = np.where(np.isfinite(rho[idx]), cp.Rr / rho[idx], 0.0)
    la = _clusters(a, a_span, ratio=True)
    n = 0
    for ca in range(la.max() + 1):
        sel = np.flatnonzero(la == ca)
        lk = _clusters(kappa[sel], k_span, ratio=False)
        a_ref = float(np.sqrt(a[sel].min() * a[sel].max()))
        for ck in range(lk.max() + 1):
            sub = sel[lk == ck]
            k_ref = 0.5 * float(kappa[sub].min() + kappa[sub].max())
            rho_ref = cp.Rr / k_ref if k_ref != 0.0 else float("inf")
            refs[n] = (rho_ref, a_ref)
            fam[idx[sub]] = n
            n += 1
    return fam, refs


# ---------------------------------------------------------------------------------------------
# FE models: one per family per process
# ---------------------------------------------------------------------------------------------
_MODELS: OrderedDict = OrderedDict()
_MAX_MODELS = 24
#: models built by this process (diagnostics for benchmarks)
STATS = {"built": 0, "build_time": 0.0}


def model_for(cp: ContactParams, rho_ref: float, a_ref: float, options: SweepOptions):
    """The FE model of a family, from this process's cache or built now."""
    key = (cp.Rr, cp.length, repr(cp.cam), repr(cp.roller), cp.plane, float(rho_ref),
           float(a_ref), options.a_over_h, options.tolerance)
    m = _MODELS.get(key)
    if m is not None:
        _MODELS.move_to_end(key)
        return m
    t0 = time.perf_counter()
    m = build_model(cp, rho_ref, a_ref, options)
    STATS["built"] += 1
    STATS["build_time"] += time.perf_counter() - t0
    _MODELS[key] = m
    while len(_MODELS) > _MAX_MODELS:
        _MODELS.popitem(last=False)
    return m


def clear_model_cache() -> None:
    _MODELS.clear()


def build_model(cp: ContactParams, rho_ref: float, a_ref: float, options: SweepOptions,
                _threaded: bool = False):
    """A fresh :class:`femcam.fe.ContactModel` (mesh + factorisation)."""
    import threading

    from ..fe import ContactModel, SolverOptions
    from ..mesh import MeshOptions

    if not _threaded and threading.current_thread() is not threading.main_thread():
        # Dask runs tasks in worker threads; gmsh.initialize() installs a SIGINT handler, which
        # Python allows only in the main thread. Initialise gmsh here without it (same
        # arguments as femcam.mesh otherwise) so that femcam.mesh finds it initialised.
        import gmsh

        if not gmsh.isInitialized():
            gmsh.initialize(["-nopopup"], readConfigFiles=False, interruptible=False)
            try:
                return build_model(cp, rho_ref, a_ref, options, _threaded=True)
            finally:
                gmsh.finalize()
    return ContactModel.build(Rr=cp.Rr, rho_ref=rho_ref, cam=cp.cam, roller=cp.roller,
                              length=cp.length, a_ref=a_ref,
                              mesh=MeshOptions(a_over_h=options.a_over_h),
                              solver=SolverOptions(), plane=cp.plane)
