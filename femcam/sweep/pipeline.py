r"""The per-angle chain and the grouping of angles into model families.

At every cam angle :math:`\theta`:

1. kinematics, profile and loads from the scene (``Scene.analyse``): s, v, a, j, phi, rho, Fc;
2. Hertz (:class:`femcam.hertz.LineContact`) with ``R1 = rho`` (cam), ``R2 = Rr`` (roller);
3. ``method="fe"``: the FE contact solve (:mod:`femcam.fe`) with the same F, rho and mu;
   ``method="hertz"``: the analytic maxima instead (a fast, legitimate analytic sweep).

Families (``method="fe"``)
--------------------------
2D linear elasticity is invariant under a uniform scaling of the geometry: the stiffness of a
body meshed in units of ``a`` is the same matrix for every ``a``. From angle to angle only the
gap shape ``x^2 / 2R`` and the load change. So one mesh + factorisation serves every angle whose
``a`` (and ``Rr / rho``) stays close to the model's reference. The parent process plans the
families and verifies the reuse error against ``tolerance`` with fresh models, splitting
families until it holds (:func:`femcam.sweep.verify.verify_families`); each worker process
then builds a family's model once (:class:`~femcam.sweep.cache.ModelCache`, one per
process; forked workers inherit the parent's) and checks it with ``model.covers(F, rho)``; an
angle it does not cover gets its own model (flag ``rebuilt``). Because the plan depends only on
the set of angles (and is stored with the chunks for ``resume``), results do not depend on
chunking, the number of workers, the executor, or resuming.
"""

from __future__ import annotations

import multiprocessing
import os
import threading
import time
import traceback
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .._threads import single_threaded_blas
from ..errors import FemcamError
from ..fe import ContactResult
from ..hertz import HertzValidityWarning, LineContact
from ..hertz.conformity import (
    NEARLY_CONFORMAL_GAP,
    gap_nonparabolicity,
    roller_does_not_fit,
    undercut_message,
)
from ..io import vtu_name, write_fe_vtu, write_hertz_vtu
from ..wear.slip import SlipResult
from .cache import ModelCache, default_cache
from .chunk import ChunkRows
from .diskcache import attach, store_fields
from .estimate import fill_row_estimate
from .extras import fill_extras
from .headline import COATED, omitted_physics
from .options import ContactParams, ResolvedOptions, contact_params
from .plan import hertz_half_width
from .realcam import Traction, arc_error_estimate, contact_scene, hertz_within_tolerance, traction_args
from .realrows import (
    exact_solve,
    fe_fill,
    fill_choice,
    flat_edge_rows,
    flat_rows,
    hertz_answer,
    hertz_row_traction,
    hertz_stress,
)
from .ringhead import ring_headline
from .table import TEXT_COLUMNS
from .wear import fill_wear

#: result columns that are 0 (not NaN) at lift-off: no contact has zero width and zero pressure
ZERO_AT_LIFTOFF = ("a_hertz", "p0_hertz", "a_fe", "p0_fe", "p0_fit", "vm_max", "tau1_max",
                   "txz_range_max", "surf_sx_min", "surf_sx_max", "surf_sz_min", "surf_txz_absmax")


def line_contact(cp: ContactParams, F, rho) -> LineContact:
    """The Hertz line contact of load cases ``F`` (N) at cam radii ``rho`` (m), without the
    large-``a`` warning (the sweep flags those rows ``hertz_large_a`` instead).

    Parameters
    ----------
    cp : ContactParams
    F, rho : float or ndarray
        Contact force (N) and cam radius of curvature (m).

    Returns
    -------
    femcam.hertz.LineContact
    """
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", HertzValidityWarning)
        return LineContact(F=F, length=cp.length, R1=rho, R2=cp.Rr, cam=cp.cam, roller=cp.roller,
                           mu=cp.mu, plane=cp.plane, direction=cp.sliding)


def _hertz_rows(rows, flags, idx, cp: ContactParams, F, rho, method: str):
    """Fill Hertz a/p0 (and, for method hertz, the stress maxima) of rows ``idx``."""
    if idx.size == 0:
        return
    hc = line_contact(cp, F[idx], rho[idx])
    for i in idx[~np.atleast_1d(hc.valid)]:
        flags[i].append("hertz_large_a")
    a_h = np.atleast_1d(np.asarray(hc.a, float))
    eps = gap_nonparabolicity(a_h, rho[idx], cp.Rr)
    for i in idx[(rho[idx] < 0) & (eps > NEARLY_CONFORMAL_GAP)]:
        flags[i].append("nearly_conformal")
    rows.a_hertz[idx] = hc.a
    rows.p0_hertz[idx] = hc.p0
    if method == "hertz":
        hertz_stress(rows, idx, cp, hc.p0, hc.a)
        rows.model[idx] = "hertz"


# ---------------------------------------------------------------------------------------------
# one chunk
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ChunkTask:
    """Everything a worker needs for one chunk (small: a scene and a few hundred angles).

    Parameters
    ----------
    index : int
        Chunk number.
    scene : femcam.scene.Scene
    theta : ndarray, shape (n,)
        Cam angles (rad).
    options : ResolvedOptions
    family : ndarray of int, shape (n,)
        Family id per angle (-1: none).
    refs : dict[int, tuple[float, float]]
        ``(rho_ref, a_ref)`` (m) of the families used here.
    a_over_h : dict[int, float]
        Each family's own ``a_over_h`` [-] (missing: ``options.a_over_h``;
        :meth:`family_options`).
    vtk_dir : str, optional
        Where to write the ``.vtu`` files.
    vtk_mask : ndarray of bool, shape (n,), optional
        Angles that get a ``.vtu``.
    slip : femcam.wear.slip.SlipResult, optional
        Slip at these angles (None: no wear columns).
    wear_k : float
        Archard k (m^3/(N m)).
    delay_s : float
        Seconds to sleep after the chunk (>= 0; tests use it to kill a sweep between chunks).
    jump : ndarray of bool, shape (n,), optional
        Rows in a curvature jump's straddle span (:func:`femcam.sweep.realcam.jump_angles`).
    traction : femcam.sweep.realcam.Traction, optional
        Per-angle traction (None: full sliding in the scene's direction).
    hertz : ndarray of bool, shape (n,), optional
        Method ``auto``: rows Hertz answers (:func:`femcam.sweep.realcam.auto_hertz_rows`).
    estimates : dict[int, femcam.sweep.estimate.FamilyEstimate]
        The families' two-level error estimates (empty: the rows get NaN estimates).
    disk : tuple, optional
        The sweep's persistent model cache (:meth:`femcam.sweep.diskcache.DiskCache.spec`; read
        only on Dask workers); None: the process's as it is.
    """

    index: int
    scene: object
    theta: np.ndarray
    options: ResolvedOptions
    family: np.ndarray = field(default_factory=lambda: np.zeros(0, int))
    refs: dict = field(default_factory=dict)
    a_over_h: dict = field(default_factory=dict)
    vtk_dir: str | None = None
    vtk_mask: np.ndarray | None = None
    slip: SlipResult | None = None
    wear_k: float = float("nan")
    delay_s: float = 0.0
    jump: np.ndarray | None = None
    traction: Traction | None = None
    hertz: np.ndarray | None = None
    estimates: dict = field(default_factory=dict)
    disk: tuple | None = None

    def family_options(self, fid: int) -> ResolvedOptions:
        """The options family ``fid``'s model was built with (its own ``a_over_h``).

        Parameters
        ----------
        fid : int
            Family id (-1 or unknown: the sweep's options).

        Returns
        -------
        ResolvedOptions
        """
        return self.options.for_family(self.a_over_h.get(int(fid)))


def analytic_rows(scene, theta) -> tuple[ChunkRows, object]:
    """Rows with the kinematics/profile/load columns filled, and the scene state.

    Parameters
    ----------
    scene : femcam.scene.Scene
    theta : ndarray, shape (n,)
        Cam angles (rad).

    Returns
    -------
    rows : ChunkRows
        The chunk's table (:class:`~femcam.sweep.chunk.ChunkRows`) with ``theta, s, v, a, j, phi, rho,
        Fc`` (SI) filled (knife-edge: of the cam cut for the tip radius).
    state : femcam.scene.SceneState
    """
    theta = np.asarray(theta, dtype=float)
    st = contact_scene(scene).analyse(theta)  # knife-edge: the cam cut for the radiused tip
    rows = ChunkRows(theta.size)
    rows.theta[:] = theta
    for name in ("s", "v", "a", "j", "phi", "rho", "Fc"):
        getattr(rows, name)[:] = np.asarray(getattr(st, name), dtype=float)
    return rows, st


def contact_mask(st) -> np.ndarray:
    """Angles in contact: no lift-off and ``Fc > 0``.

    Parameters
    ----------
    st : femcam.scene.SceneState
        With ``liftoff`` (bool, shape (n,)) and ``Fc`` (N, shape (n,)).

    Returns
    -------
    ndarray of bool, shape (n,)
    """
    return ~np.asarray(st.liftoff, dtype=bool) & (np.asarray(st.Fc, dtype=float) > 0.0)


def run_chunk(task: ChunkTask) -> ChunkRows:
    """Compute the rows of one chunk (runs in a worker process).

    In worker processes and Dask worker threads BLAS runs single-threaded (the parallelism is
    over chunks; BLAS threads on top only oversubscribe the cores). The caller's process is left
    alone in the serial case.

    Parameters
    ----------
    task : ChunkTask

    Returns
    -------
    ChunkRows
        The chunk's rows (SI, see :mod:`femcam.sweep.table`).
    """
    if multiprocessing.parent_process() is None and threading.current_thread() is threading.main_thread():
        return _run_chunk(task)
    with single_threaded_blas():
        return _run_chunk(task)


def _run_chunk(task: ChunkTask) -> ChunkRows:
    opts = task.options
    attach(default_cache(), task.disk)
    cp = contact_params(task.scene)
    rows, st = analytic_rows(task.scene, task.theta)
    n = rows.theta.size
    contact = contact_mask(st)
    flags = [[] for _ in range(n)]

    # lift-off: no contact -- zero width, zero pressure, zero stress
    lift = np.flatnonzero(~contact)
    rows.status[lift] = "liftoff"
    for name in ZERO_AT_LIFTOFF:
        getattr(rows, name)[lift] = 0.0
    # the roller does not fit the concave cam: no contact solution at all
    nofit = contact & roller_does_not_fit(rows.rho, cp.Rr)
    for i in np.flatnonzero(nofit):
        rows.status[i] = "undercut"
        rows.message[i] = undercut_message(float(rows.rho[i]), cp.Rr)
    good = np.flatnonzero(contact & ~nofit)
    if task.jump is not None:
        rows.curvature_jump[:] = task.jump
    rows.fe_time[:] = 0.0
    rows.build_time[:] = 0.0
    _hertz_rows(rows, flags, good, cp, rows.Fc, rows.rho, opts.method)
    if task.scene.follower.flat_face:  # past the face end: an edge contact, never Hertz
        good = flat_edge_rows(task.scene, cp, rows, good)
    vtk_fe, solved = {}, {}
    if opts.method == "hertz":
        rows.a_fe[:] = np.nan
        rows.p0_fe[:] = np.nan
        rows.status[good] = "ok"
    else:
        fe = _choose_models(task, cp, rows, flags, good)
        if task.scene.follower.flat_face:
            vtk_fe = flat_rows(task, cp, rows, fe, default_cache(), flags)
        else:
            solved = _fe_rows(task, cp, rows, flags, fe, default_cache())
            vtk_fe = {i: r for i, r in solved.items()
                      if task.vtk_dir is not None and task.vtk_mask is not None and task.vtk_mask[i]}
    ring = ring_headline(task, rows)  # a roller on a pin or needles: the ring answers
    fill_wear(rows, task.slip, task.wear_k, "fe" if ring.any() else opts.method)
    rows.wear_source = np.where(ring & (rows.wear_source == "fe"), "ring", rows.wear_source)
    # extra column providers (femcam.sweep.extras), after contact and wear; the layers take
    # their columns from the solves that answered the headline
    fill_extras(task, rows, solved)
    solved = None
    _write_vtus(task, cp, rows, vtk_fe)  # last: not part of any timing column
    omitted = [flag for flag, _ in omitted_physics(task.scene, opts.method)]
    for i in np.flatnonzero(rows.status == "ok"):   # never silently (femcam.sweep.extras)
        flags[i].extend(omitted)
    for i in range(n):
        rows.flags[i] = ";".join(flags[i])
    for name in TEXT_COLUMNS:
        setattr(rows, name, np.asarray(getattr(rows, name)).astype(str))
    if task.delay_s > 0:
        time.sleep(task.delay_s)
    return rows


def _choose_models(task: ChunkTask, cp: ContactParams, rows, flags, good) -> np.ndarray:
    """The error estimates of rows ``good``; method ``auto``: Hertz answers the rows within the
    tolerance (not in a curvature jump's span). Returns the rows the FE answers."""
    e_arc, e_h = arc_error_estimate(task.scene, rows.theta[good], rows.a_hertz[good], cp.Rr)
    rows.est_err_arc[good] = e_arc / 100.0
    rows.est_err_hertz[good] = e_h / 100.0
    if task.options.method != "auto" or (cp.coat_body is not None and not task.scene.follower.flat_face):
        return good   # a coated body: Hertz (homogeneous) is not the scene's model
    hz = (task.hertz[good] if task.hertz is not None else
          hertz_within_tolerance(e_h, task.jump[good] if task.jump is not None else None,
                                 task.options.tolerance))
    hertz_answer(rows, good[hz], cp, task.traction, flags)
    return good[~hz]


def _fe_rows(task: ChunkTask, cp: ContactParams, rows, flags, good, cache: ModelCache) -> dict:
    """FE solve of rows ``good``; returns ``{row: ContactResult}`` of the rows solved (the
    VTUs and the layer columns are taken from them)."""
    solved = {}
    for i in good:
        b0 = cache.stats["build_time"]
        try:
            solved[int(i)] = _fe_angle(task, cp, rows, flags, int(i), cache)
        except (FemcamError, ValueError, ArithmeticError, RuntimeError, MemoryError) as exc:
            rows.status[i] = "failed"
            msg = f"{type(exc).__name__}: {exc}"
            if os.environ.get("FEMCAM_DEBUG"):
                msg += " | " + traceback.format_exc().replace("\n", " | ")
            rows.message[i] = msg
        rows.build_time[i] = cache.stats["build_time"] - b0
    ok = rows.status == "ok"
    with np.errstate(invalid="ignore", divide="ignore"):
        rows.err_a[:] = np.where(ok, rows.a_fe / rows.a_hertz - 1.0, np.nan)
        rows.err_p0[:] = np.where(ok, rows.p0_fe / rows.p0_hertz - 1.0, np.nan)
    return solved


def _fe_angle(task: ChunkTask, cp: ContactParams, rows, flags, i: int,
              cache: ModelCache) -> ContactResult:
    """Solve row ``i`` with its family's model (or a model of its own) and fill the row."""
    F, rho = float(rows.Fc[i]), float(rows.rho[i])
    fid = int(task.family[i])
    opts = task.family_options(fid)
    model = cache.model_for(cp, *task.refs[fid], opts)
    own = not model.covers(F, rho)
    if own:  # outside the family's range (e.g. nearly conformal): its own model
        a_i = float(hertz_half_width(np.array([F]), np.array([rho]), cp)[0])
        model = cache.model_for(cp, rho, a_i, opts)
        flags[i].append("rebuilt")
    sl, Q, roll = traction_args(task.traction, i, cp.sliding)
    jump = bool(task.jump[i]) if task.jump is not None else False
    tol_pct = 100.0 * task.options.tolerance
    res = None
    if jump or 100.0 * rows.est_err_arc[i] > tol_pct:  # the exact gap where the choice needs it
        res = exact_solve(task.scene, cp, model, float(rows.theta[i]), F, Q=Q, jump=jump,
                          tol_pct=tol_pct)
    if res is not None:
        r = res.result
        fill_choice(rows, i, res)
    else:
        r = cache.solve(model, F, rho, cp.mu, sl, check=not own, Q=Q, rolling=roll)
        rows.model[i] = "fe_arc"
    if cp.coat_body is not None:   # the coating band is in this model (sweep.cache.build_model)
        rows.model[i] = rows.model[i] + COATED
    rows.fe_time[i] = r.timings["contact"] + r.timings.get("recovery", 0.0)
    flags[i].extend(fe_fill(rows, i, r))
    rows.Q_over_muFc[i] = r.Q / (cp.mu * F) if cp.mu > 0 else np.nan
    rows.family[i] = fid
    fill_row_estimate(rows, i, task.estimates.get(fid), float(rows.a_hertz[i]), model.a_ref,
                      opts.a_over_h)
    if task.options.rtol is not None and _rtol_missed(rows, i, task.estimates.get(fid), task.options):
        flags[i].append("rtol_not_met")
    if r.outside_hertz and "hertz_large_a" not in flags[i]:
        flags[i].append("hertz_large_a")
    if r.converged:
        rows.status[i] = "ok"
    else:
        rows.status[i] = "failed"
        rows.message[i] = (f"FE contact solve did not converge ({r.iterations} iterations, "
                              f"residual {r.residual:.3g})")
    return r


def _write_vtus(task: ChunkTask, cp: ContactParams, rows, vtk_fe: dict) -> None:
    """The chunk's ``.vtu`` files: FE results, or the analytic field for the rows Hertz
    answered (method hertz, and method auto's Hertz rows), so the series is complete."""
    if task.vtk_dir is None or task.vtk_mask is None:
        return
    disk = default_cache().disk
    for i, r in vtk_fe.items():
        if r.model is not None:  # the back-solves of the fields: stored, or read back (warm)
            store_fields(r.model, disk)
        write_fe_vtu(Path(task.vtk_dir) / vtu_name(task.theta[i]), r, wear=_vtu_wear(task, rows, i))
    analytic = (rows.status == "ok") & np.isin(rows.model, ("hertz", "hertz+ring"))
    if task.options.method == "hertz":
        analytic = rows.status == "ok"
    for i in np.flatnonzero(task.vtk_mask & analytic):
        if int(i) not in vtk_fe:
            # method auto: the traction the row carries (|Q|/Fc), as its stress columns
            mu, d = (cp.mu, cp.sliding) if task.options.method == "hertz" else hertz_row_traction(rows, i, cp)
            hc = LineContact(F=rows.Fc[i], length=cp.length, R1=rows.rho[i], R2=cp.Rr,
                             cam=cp.cam, roller=cp.roller, mu=mu, plane=cp.plane, direction=d)
            write_hertz_vtu(Path(task.vtk_dir) / vtu_name(task.theta[i]), hc,
                            wear=_vtu_wear(task, rows, i))


def _vtu_wear(task: ChunkTask, rows, i) -> dict | None:
    """Wear data for the VTU of row ``i``: k, v_slip, V_cam, depth per revolution, angle."""
    if task.slip is None or not np.isfinite(task.wear_k):
        return None
    return {"k": float(task.wear_k), "v_slip": float(rows.v_slip[i]),
            "V_cam": float(rows.V_cam[i]), "wear_depth_per_rev": float(rows.wear_depth[i]),
            "theta_deg": float(np.degrees(rows.theta[i])), "Fc": float(rows.Fc[i])}


def _rtol_missed(rows, i: int, est, options) -> bool:
    """Row ``i``'s estimate of a quantity ``rtol`` controls (``options.rtol_on``) is above
    ``rtol``: the table's ``err_est_<q>``, or for the interface stresses (a provider's columns,
    filled later) the family estimate carried to the row."""
    for q in options.rtol_on:
        col = rows.get(f"err_est_{q}")
        e = col[i] if col is not None else (est.carried(q, float(rows.a_over_h_row[i]))
                                             if est is not None else np.nan)
        if e > options.rtol:
            return True
    return False
