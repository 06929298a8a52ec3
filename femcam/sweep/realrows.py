"""The real-cam columns of a chunk's rows: the model that answered, the exact-gap solve where
the choice needs it, the traction, and the flat-faced sweep (:mod:`femcam.sweep.realcam`).

The roller and knife-edge rows keep the family models of :mod:`femcam.sweep.plan` (arc gap,
traction from the mechanism); a row whose arc-gap error estimate exceeds the tolerance, or that
lies in a curvature jump's straddle span, is solved again with the exact gap by
:func:`femcam.fe.choice.solve_angle` on the same model. Flat-faced rows are answered by
:func:`femcam.fe.choice.solve_angle` (the cheapest model within the tolerance) on models binned
by half-width and cam radius.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import PhysicsError
from ..fe import ContactResult, SolverOptions
from ..fe.choice import RealCam, build_real_cam, solve_angle
from ..fe.followers import check_face
from ..hertz.conformity import shape_factors
from ..mesh import MeshOptions
from .headline import edge_flags
from .realcam import traction_args

#: geometric bin ratio (half-width and cam radius) of the flat-faced models
FLAT_BIN_RATIO = 1.25
#: a Hertz row's traction ratio |Q|/Fc is taken on the grid mu k / RATIO_STEPS (k = 0 ..
#: RATIO_STEPS; exact at 0 and at full sliding): at most RATIO_STEPS + 1 shape-factor
#: maximisations per process instead of one per row, the ratio off by <= mu / (2 RATIO_STEPS)
RATIO_STEPS = 100


def fe_fill(rows, i, r: ContactResult) -> list[str]:
    """Copy one :class:`femcam.fe.ContactResult` into row ``i``.

    ``p0_fe`` is the peak of the solved pressure (its largest nodal value), ``p0_fit`` and
    ``a_fe`` the Hertz ellipse fitted to it (:mod:`femcam.sweep.table`). Maxima are over both
    bodies (``StressMax.value``, depth ``z`` below that body's surface), and so is the range of
    ``txz`` over one pass (the larger body's; NaN where the stress window cuts the pass,
    ``ShearRange.inside`` False); the ``surf_*`` extremes are on the cam surface of the FE
    model's stress window.

    Parameters
    ----------
    rows : ChunkRows
        The chunk's table (SI columns, modified in place).
    i : int
        Row index.
    r : femcam.fe.ContactResult
        The solved load case (a, depths in m; p0, stresses in Pa; Q in N).

    Returns
    -------
    list of str
        The row's flags from this solve (:func:`edge_flags`).
    """
    rows.a_fe[i] = r.a
    rows.p0_fe[i] = r.p0_nodal   # the peak of the solved pressure, not the fit
    rows.p0_fit[i] = r.p0
    rows.vm_max[i] = r.von_mises_max.value
    rows.vm_depth[i] = r.von_mises_max.z
    rows.tau1_max[i] = r.tau1_max.value
    rows.tau1_depth[i] = r.tau1_max.z
    tr = r.txz_range
    rows.txz_range_max[i] = tr.value if tr.inside else np.nan
    rows.txz_range_depth[i] = tr.z if tr.inside else np.nan
    if r.sx.size:
        rows.surf_sx_min[i] = r.sx.min()
        rows.surf_sx_max[i] = r.sx.max()
        rows.surf_sz_min[i] = r.sz.min()
        rows.surf_txz_absmax[i] = np.abs(r.txz).max()
    rows.iterations[i] = r.iterations
    rows.residual[i] = r.residual
    rows.n_dofs[i] = r.n_dofs
    rows.Q[i] = r.Q
    rows.stick_width[i] = r.stick_width
    rows.slip_state[i] = r.slip_state
    return edge_flags(r)


def hertz_stress(rows, idx, cp, p0, a, ratio=None) -> None:
    """Stress maxima of rows ``idx`` from the Hertz shape factors, with the tangential traction
    ``q = (|Q|/Fc) p`` (Johnson 1985 §7.1; full sliding: ``|Q|/Fc = mu``).

    Parameters
    ----------
    rows : ChunkRows
        The chunk's table (SI columns, modified in place).
    idx : array_like of int, shape (m,)
        Row indices.
    cp : ContactParams
        Contact parameters (``mu``, cam material, plane).
    p0 : float or ndarray, shape (m,)
        Peak Hertz pressure [Pa].
    a : float or ndarray, shape (m,)
        Hertz half-width [m].
    ratio : float or ndarray, shape (m,), optional
        Traction ratio ``|Q|/Fc`` of each row [-], in ``[0, mu]``; default ``mu`` (full
        sliding). Taken on the grid of :data:`RATIO_STEPS`.
    """
    idx = np.atleast_1d(np.asarray(idx, int))
    p0 = np.broadcast_to(np.asarray(p0, float), idx.shape)
    a = np.broadcast_to(np.asarray(a, float), idx.shape)
    if ratio is None or cp.mu <= 0:
        steps = np.full(idx.shape, RATIO_STEPS if cp.mu > 0 else 0)
    else:
        steps = np.rint(np.clip(np.asarray(ratio, float) / cp.mu, 0.0, 1.0) * RATIO_STEPS).astype(int)
        steps = np.broadcast_to(steps, idx.shape)
    for k_step in np.unique(steps):
        sel = steps == k_step
        j, p, b = idx[sel], p0[sel], a[sel]
        # the ratio on the grid mu k_step / RATIO_STEPS: at most RATIO_STEPS + 1 cached maximisations
        k = shape_factors(float(cp.mu) * (int(k_step) / RATIO_STEPS), float(cp.cam.nu), cp.plane)
        rows.vm_max[j] = k["von_mises"][0] * p
        rows.vm_depth[j] = k["von_mises"][1] * b
        rows.tau1_max[j] = k["tau1"][0] * p
        rows.tau1_depth[j] = k["tau1"][1] * b
        rows.txz_range_max[j] = k["txz_range"][0] * p
        rows.txz_range_depth[j] = k["txz_range"][1] * b
        for name in ("surf_sx_min", "surf_sx_max", "surf_sz_min", "surf_txz_absmax"):
            getattr(rows, name)[j] = k[name] * p


def hertz_row_traction(rows, i: int, cp) -> tuple[float, int]:
    """The traction a Hertz-answered row carries, for its analytic field (VTU).

    Parameters
    ----------
    rows : ChunkRows
        The chunk's table (``Q`` [N], ``Fc`` [N]).
    i : int
        Row index.
    cp : ContactParams
        Contact parameters (``mu``, ``sliding``).

    Returns
    -------
    ratio : float
        ``|Q|/Fc`` [-] (``mu`` when the row has no ``Q``, 0 at ``Fc = 0``).
    direction : int
        Sign of ``Q`` on the cam along x (``cp.sliding`` when ``Q`` is 0 or missing).
    """
    Q, F = float(rows.Q[i]), float(rows.Fc[i])
    if not math.isfinite(Q):
        return cp.mu, cp.sliding
    ratio = abs(Q) / F if F > 0 else 0.0
    return ratio, (int(math.copysign(1, Q)) if Q else cp.sliding)


def fill_choice(rows, i, res) -> None:
    """The model-choice columns of row ``i``.

    Parameters
    ----------
    rows : ChunkRows
        The chunk's table (SI columns, modified in place).
    i : int
        Row index.
    res : femcam.fe.choice.AngleResult
        The per-angle answer (errors in %, stored as fractions; Q in N; stick width in m).
    """
    rows.model[i] = res.model
    rows.est_err_arc[i] = res.est_err_arc_pct / 100.0
    rows.est_err_hertz[i] = res.est_err_hertz_pct / 100.0
    rows.exact_vs_arc_p0[i] = res.exact_vs_arc_p0_pct / 100.0
    rows.Q[i] = res.Q
    rows.Q_over_muFc[i] = res.Q_over_muFc
    rows.stick_width[i] = res.stick_width
    rows.slip_state[i] = res.slip_state


def family_real_cam(scene, cp, model) -> RealCam:
    """A :class:`femcam.fe.choice.RealCam` around a family model (roller or knife-edge: the
    family's ``Rr`` is the roller or the tip radius).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene (cam program, follower).
    cp : ContactParams
        Contact parameters (``Rr`` [m], ``E_star`` [Pa]).
    model : femcam.fe.ContactModel
        The family model.

    Returns
    -------
    femcam.fe.choice.RealCam
        The real cam on that model.
    """
    tip = cp.Rr if scene.follower.needs_tip else None
    return RealCam(program=scene.program, follower=scene.follower, model=model, tip_radius=tip,
                   face_length=None, swapped=False, E_star=cp.E_star)


def exact_solve(scene, cp, model, theta, F, *, Q, jump: bool, tol_pct: float):
    """The exact-gap answer of one roller or knife-edge row on its family model, or None when
    the exact-gap estimate of :func:`femcam.fe.choice.solve_angle` finds the arc gap within
    ``tol_pct`` after all (the caller then solves the arc gap). Curvature-jump rows solve both
    gaps (``exact_vs_arc_p0_pct``).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene (cam program, follower).
    cp : ContactParams
        Contact parameters.
    model : femcam.fe.ContactModel
        The row's family model.
    theta : float
        Cam angle [rad].
    F : float
        Contact force [N].
    Q : float or None
        The roller's tangential force on the cam [N], or None for full sliding (knife-edge:
        direction from the sliding velocity).
    jump : bool
        The row lies in a curvature jump's straddle span (both gaps are solved).
    tol_pct : float
        Sweep tolerance [%].

    Returns
    -------
    femcam.fe.choice.AngleResult or None
        The exact-gap answer, or None when the arc gap is within the tolerance.
    """
    if scene.follower.translating_roller and Q is None:  # [contact] sliding override
        Q = cp.sliding * cp.mu * F
    res = solve_angle(family_real_cam(scene, cp, model), theta, F, mu=cp.mu, Q=Q,
                      curvature_jump=jump, tol_pct=tol_pct, force_exact=jump)
    return res if res.model == "fe_exact" else None


def hertz_answer(rows, idx, cp, traction, flags) -> None:
    """Rows ``idx`` answered by Hertz (method ``auto``, estimate within the tolerance): traction
    from the closed forms (Carter / Cattaneo stick width ``2 a sqrt(1 - |Q|/(mu F))``, Johnson
    1985 §7.1, §8.2; full sliding: ``Q = s mu F``), stress maxima from the shape factors with
    the traction the row carries, ``q = (|Q|/F) p`` (:func:`hertz_stress`). A nonzero ``Q``
    with ``mu = 0`` cannot be carried: ``Q`` is set to 0 and the row flagged
    ``Q_without_friction``.

    Parameters
    ----------
    rows : ChunkRows
        The chunk's table (SI columns, modified in place).
    idx : array_like of int
        Rows Hertz answers.
    cp : ContactParams
        Contact parameters (``mu``, ``sliding``, shape factors).
    traction : femcam.sweep.realcam.Traction or None
        Per-angle traction of the chunk (None: full sliding in ``cp.sliding``).
    flags : list of list of str
        Per-row flags (appended to).
    """
    idx = np.asarray(idx, int)
    if idx.size == 0:
        return
    ratio = np.full(idx.size, cp.mu)
    for n, i in enumerate(idx):
        F, a = float(rows.Fc[i]), float(rows.a_hertz[i])
        sl, Q, _ = traction_args(traction, int(i), cp.sliding)
        if Q is None:
            Q, f = sl * cp.mu * F, 1.0
        else:
            f = abs(Q) / (cp.mu * F) if cp.mu > 0 else (math.inf if Q else 0.0)
            if cp.mu <= 0 and Q:
                flags[i].append("Q_without_friction")
            Q = math.copysign(min(abs(Q), cp.mu * F), Q)
            if f < 1:
                ratio[n] = abs(Q) / F if F > 0 else 0.0
        rows.Q[i] = Q
        rows.Q_over_muFc[i] = Q / (cp.mu * F) if cp.mu > 0 else np.nan
        rows.stick_width[i] = 2 * a * math.sqrt(1 - f) if f < 1 else 0.0
        rows.slip_state[i] = "none" if Q == 0 else ("sliding" if f >= 1 else "partial slip")
        rows.model[i] = "hertz"
        rows.p0_fit[i] = np.nan
        rows.status[i] = "ok"
    hertz_stress(rows, idx, cp, rows.p0_hertz[idx], rows.a_hertz[idx], ratio)


def flat_edge_rows(scene, cp, rows, good) -> np.ndarray:
    """Flat-faced rows of ``good`` whose contact runs past the face end: status
    ``edge_contact`` with the angle ranges of this chunk (never Hertz).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene (cam program, flat-faced follower with offset ``e`` [m]).
    cp : ContactParams
        Contact parameters (``face_length`` [m], None: unlimited).
    rows : ChunkRows
        The chunk's table (SI columns, modified in place).
    good : array_like of int
        Contact rows to check.

    Returns
    -------
    ndarray of int
        The rows of ``good`` whose contact stays on the face.
    """
    good = np.asarray(good, int)
    if cp.face_length is None or good.size == 0:
        return good
    th, a = rows.theta[good], rows.a_hertz[good]
    off = np.abs(scene.program.derivatives(th).s1 - scene.follower.e) + a
    edge = off > 0.5 * cp.face_length
    if np.any(edge):
        try:
            check_face(scene.program, scene.follower, cp.face_length, th, a)
        except PhysicsError as exc:
            rows.message[good[edge]] = str(exc)
        rows.status[good[edge]] = "edge_contact"
        for name in ("a_hertz", "p0_hertz"):
            getattr(rows, name)[good[edge]] = np.nan
    return good[~edge]


def _flat_model(cache, scene, cp, options, a: float, rho: float) -> RealCam:
    """The flat-faced model of the bin of ``(a, rho)``: references at the bin's geometric centre
    (so the model depends on the angle only, not on the chunking)."""
    la = math.floor(math.log(a) / math.log(FLAT_BIN_RATIO))
    lr = math.floor(math.log(rho) / math.log(FLAT_BIN_RATIO))
    a_ref, rho_ref = FLAT_BIN_RATIO ** (la + 0.5), FLAT_BIN_RATIO ** (lr + 0.5)
    F_ref = a_ref ** 2 * math.pi * cp.E_star * cp.length / (4 * rho_ref)
    key = ("real_cam", "flat_faced", repr(cp.cam), repr(cp.roller), cp.length, cp.plane, la, lr,
           options.a_over_h)
    # face_length None: the edge check is done before (flat_edge_rows) and the FE answers
    return cache.real_cam(key, lambda: build_real_cam(
        program=scene.program, follower=scene.follower, cam=cp.cam, roller=cp.roller,
        length=cp.length, plane=cp.plane, F_ref=F_ref, rho_ref=rho_ref,
        face_length=None, mesh=MeshOptions(a_over_h=options.a_over_h),
        solver=SolverOptions()))


def flat_rows(task, cp, rows, good, cache, flags=None) -> dict:
    """Flat-faced rows ``good``: :func:`femcam.fe.choice.solve_angle` per angle.

    Parameters
    ----------
    task : ChunkTask
        The chunk (scene, options, ``jump``, ``vtk_mask``).
    cp : ContactParams
        Contact parameters.
    rows : ChunkRows
        The chunk's table (SI columns, modified in place).
    good : array_like of int
        Rows the FE answers.
    cache : ModelCache
        Where the binned models are kept.
    flags : list of list of str, optional
        Per-row flags (appended to).

    Returns
    -------
    dict[int, femcam.fe.ContactResult]
        The FE-answered rows that get a VTU.
    """
    vtk = {}
    tol_pct = 100.0 * task.options.tolerance
    jump = task.jump if task.jump is not None else np.zeros(rows.theta.size, bool)
    for i in good:
        F, rho, th = float(rows.Fc[i]), float(rows.rho[i]), float(rows.theta[i])
        a = math.sqrt(4 * F * rho / (cp.length * math.pi * cp.E_star))
        b0 = cache.stats["build_time"]
        try:
            rc = _flat_model(cache, task.scene, cp, task.options, a, rho)
            res = solve_angle(rc, th, F, mu=cp.mu, curvature_jump=bool(jump[i]), tol_pct=tol_pct)
        except PhysicsError as exc:  # a cusp or undercut inside the contact zone, with the angle
            rows.status[i] = "undercut"
            rows.message[i] = str(exc)
            continue
        finally:
            rows.build_time[i] = cache.stats["build_time"] - b0
        r = res.result
        if r is None:
            hertz_stress(rows, [i], cp, res.p0_hertz, rows.a_hertz[i])
            rows.fe_time[i] = 0.0
        else:
            row_flags = fe_fill(rows, i, r)
            if flags is not None:
                flags[i].extend(row_flags)
            rows.fe_time[i] = r.timings.get("contact", 0.0) + r.timings.get("recovery", 0.0)
            if task.vtk_mask is not None and task.vtk_mask[i]:
                vtk[int(i)] = r
        fill_choice(rows, i, res)
        rows.status[i] = "ok" if (r is None or r.converged) else "failed"
        if r is not None and not r.converged:
            rows.message[i] = r.message or "FE contact solve did not converge"
    ok = (rows.status == "ok") & np.isfinite(rows.p0_fe)
    with np.errstate(invalid="ignore", divide="ignore"):
        rows.err_a[:] = np.where(ok, rows.a_fe / rows.a_hertz - 1.0, np.nan)
        rows.err_p0[:] = np.where(ok, rows.p0_fe / rows.p0_hertz - 1.0, np.nan)
    return vtk
