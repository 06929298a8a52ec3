"""Web-thickness study of the cam disk on its shaft: how the bore changes the cam-roller contact,
the bore hoop stress and the shaft contact (README figure, benchmarks/figures_cam_disk.py).

For each bore radius the fully refined model (:mod:`femcam.bodies.cam_model`) is solved at one
cam angle (default: the angle of the largest contact force) against today's local cam body,
and the global model (:mod:`femcam.bodies.cam_global`) over the whole revolution.
"""

from __future__ import annotations

import math
import time

import numpy as np

from .. import _validate
from ..errors import InputError
from ..hertz.contact import effective_radius, half_width
from ..materials import effective_modulus
from ..mesh import surface_height
from ..scene.case import CamDiskCase
from ..scene.state import SceneState
from .cam_geometry import contact_frame, require_roller
from .cam_global import CamGlobalModel
from .cam_model import CamDiskModel
from .cam_rows import disk_from_case, solve_global
from .cam_solve import _local, solve_cam_disk

KEYS = ("Rb", "web", "p0", "a", "p0_local", "a_local", "dp0", "da", "delta", "delta_local",
        "hoop_refined", "hoop_angle_refined", "shaft_p0", "shaft_arc", "hoop_max_rev", "theta_hoop_max_rev",
        "hoop_global_at_theta",
        "t_refined", "t_global", "t_rev", "n_dofs_refined", "n_dofs_global")


def peak_angle(state: SceneState) -> float:
    """Cam angle of the largest contact force of an analysed state (a revolution: the peak).

    Parameters
    ----------
    state : femcam.scene.SceneState
        The analytic chain at cam angles (rad; e.g. :attr:`CamDiskCase.revolution
        <femcam.scene.case.CamDiskCase.revolution>`, 720 uniform angles).

    Returns
    -------
    float
        The cam angle [rad].
    """
    _validate.instance("state", state, SceneState, "a femcam.scene.SceneState")
    return float(state.theta[int(np.nanargmax(state.Fc))])


def _one_angle(state) -> SceneState:
    """``state`` if it is a :class:`SceneState` at exactly one cam angle, else an InputError."""
    _validate.instance("state", state, SceneState, "a femcam.scene.SceneState")
    if state.theta.size != 1:
        raise InputError(f"state: {state.theta.size} cam angles: must be the analytic chain at one "
                         "cam angle (Scene.analyse([theta]))")
    return state


def refined_at(case: CamDiskCase, disk, state: SceneState, **kw):
    """The fully refined model of ``disk`` at one cam angle, solved for the scene's force there.

    Parameters
    ----------
    case : femcam.scene.case.CamDiskCase
        The scene's cam on its shaft (a roller follower).
    disk : CamDisk
        The cam disk.
    state : femcam.scene.SceneState
        The analytic chain at the one cam angle (``Scene.analyse([theta])``, rad).
    **kw
        Passed to :meth:`~femcam.bodies.cam_model.CamDiskModel.build` (``mesh``, ``cam_mesh``,
        ``element``, ``local``).

    Returns
    -------
    model : CamDiskModel
        The built model (``a_ref``: the Hertz half-width at ``theta``).
    result : CamDiskResult
        Its solution.
    """
    _validate.instance("case", case, CamDiskCase, "a femcam.scene.case.CamDiskCase")
    state = _one_angle(state)
    require_roller(case.follower)
    pair = case.pair
    C, n, rho, F = contact_frame(state)
    a_ref = float(half_width(F / pair.length, effective_radius(case.follower.Rr, rho),
                             effective_modulus(pair.cam, pair.roller, pair.plane)))
    m = CamDiskModel.build(disk=disk, C=C, n=n, rho=rho, Rr=case.follower.Rr, roller=pair.roller,
                           a_ref=a_ref, length=pair.length, plane=pair.plane, **kw)
    return m, solve_cam_disk(m, F=F)


def check_local_body(case: CamDiskCase, state: SceneState, *, tolerance: float, disk=None) -> dict:
    """Verify, at one cam angle, that today's local cam body gives the contact's p0 and a: one
    fully refined model of the whole disk on its shaft (:func:`refined_at`) against the local
    body at the same contact vertices, with the same roller (frictionless both).

    The drive torque twists the hub and moves the disk's contact by ``x0`` (a rigid tilt of the
    gap; the local body carries no torque). In the continuum a tilt moves a Hertz contact without
    changing a or p0, but on the fixed fine-zone nodes the fitted a changes with the move (seed
    002, 2 mm bore, x0 = -2.4 um: da -0.43 % at h = a/10, -0.27 % at a/20, +0.003 % at a/40).
    The local body is therefore solved again with its gap tilted by ``-x0 / R`` (``1/R = 1/Rr +
    1/rho``), which centres its contact at the same ``x0``; the "moved" changes are the disk's own
    effect on p0 and a, and they decide the flag. Both are recorded.

    Parameters
    ----------
    case : femcam.scene.case.CamDiskCase
        The scene's cam on its shaft (``[cam] bore_mm``).
    state : femcam.scene.SceneState
        The analytic chain at the one cam angle checked (``Scene.analyse([theta])``, rad); the
        sweep uses the angle of its largest contact force.
    tolerance : float
        The sweep's tolerance (relative): a larger ``|dp0_moved|`` or ``|da_moved|`` is flagged.
    disk : CamDisk, optional
        Default :func:`~femcam.bodies.cam_rows.disk_from_case`.

    Returns
    -------
    dict
        JSON-able: ``theta_deg``, ``Fc_N``, ``p0_disk_MPa``, ``p0_local_MPa``, ``dp0`` (disk /
        local - 1), ``a_disk_um``, ``a_local_um``, ``da``, ``x0_um`` (the disk's contact centre),
        ``dp0_moved``, ``da_moved`` (against the local body with the same move), ``tolerance``,
        ``exceeds`` (bool), ``converged``, ``n_dofs``, ``time_s``, ``line`` (one sentence with
        the numbers) and ``flag`` (the sentence when it exceeds the tolerance, else "").
    """
    t0 = time.perf_counter()
    theta = float(_one_angle(state).theta[0])
    disk = disk_from_case(case) if disk is None else disk
    m, r = refined_at(case, disk, state)
    inv_R = 1 / m.Rr + (0.0 if math.isinf(m.rho) else 1 / m.rho)
    h0 = surface_height(m.x, m.Rr) + surface_height(m.x, m.rho) - (r.x0 * inv_R) * m.x
    a_m, p0_m, _ = _local(m, h0, r.F / m.length, np.abs(m.x - r.x0) < r.a)
    out = {"theta_deg": math.degrees(theta), "Fc_N": r.F, "p0_disk_MPa": r.p0 / 1e6,
           "p0_local_MPa": r.p0_local / 1e6, "dp0": r.dp0, "a_disk_um": r.a * 1e6,
           "a_local_um": r.a_local * 1e6, "da": r.da, "x0_um": r.x0 * 1e6, "dp0_moved": r.p0 / p0_m - 1,
           "da_moved": r.a / a_m - 1, "tolerance": float(tolerance), "converged": bool(r.converged),
           "n_dofs": int(m.n_dofs)}
    line, exceeds = check_sentence(out)
    return out | {"exceeds": exceeds, "time_s": time.perf_counter() - t0, "line": line,
                  "flag": line if exceeds else ""}


def check_sentence(c: dict) -> tuple[str, bool]:
    """The sentence of a :func:`check_local_body` dict and whether it exceeds the tolerance.

    Parameters
    ----------
    c : dict
        ``theta_deg``, ``Fc_N``, ``p0_disk_MPa``, ``p0_local_MPa``, ``dp0``, ``a_disk_um``,
        ``a_local_um``, ``da``, ``x0_um``, ``dp0_moved``, ``da_moved``, ``tolerance``.

    Returns
    -------
    (str, bool)
        The sentence (both p0 and both a, their changes, the contact move, the verdict) and
        ``max(|dp0_moved|, |da_moved|) > tolerance``.

    Examples
    --------
    >>> c = dict(theta_deg=44.0, Fc_N=1646.4, p0_disk_MPa=977.0, p0_local_MPa=976.0, dp0=1.0e-3,
    ...          a_disk_um=107.0, a_local_um=107.5, da=-4.7e-3, x0_um=-2.4, dp0_moved=1.0e-3,
    ...          da_moved=-3.0e-3, tolerance=2e-3)
    >>> line, exceeds = check_sentence(c)
    >>> exceeds
    True
    >>> print(line.split("; ")[-1].replace(": ", ":\\n"))
    EXCEEDS the sweep tolerance 0.2 %:
    the disk changes p0 by +0.100 %, a by -0.300 % against the sweep's local body
    """
    worst = max(abs(c["dp0_moved"]), abs(c["da_moved"]))
    exceeds = bool(worst > c["tolerance"])
    tol = f"the sweep tolerance {100 * c['tolerance']:g} %"
    moved = f"p0 by {100 * c['dp0_moved']:+.3f} %, a by {100 * c['da_moved']:+.3f} %"
    line = (f"cam disk check at {c['theta_deg']:.1f} deg (Fc = {c['Fc_N']:.1f} N; one fully refined model "
            f"of the disk on its shaft vs today's local cam body on the same nodes): "
            f"p0 {c['p0_disk_MPa']:.2f} vs {c['p0_local_MPa']:.2f} MPa ({100 * c['dp0']:+.3f} %), "
            f"a {c['a_disk_um']:.2f} vs {c['a_local_um']:.2f} um ({100 * c['da']:+.3f} %); "
            f"the drive torque moves the contact centre {c['x0_um']:+.2f} um (hub twist); "
            + (f"EXCEEDS {tol}: the disk changes {moved} against the sweep's local body" if exceeds else
               f"with that move on the local body too: {moved}, within {tol}"))
    return line, exceeds


def _contact_at(state: SceneState):
    """Contact point and normal of a one-angle state as (2, 1) columns (:func:`solve_global`)."""
    C, n, _, _ = contact_frame(_one_angle(state))
    return C[:, None], n[:, None]


def web_study(case: CamDiskCase, bores, *, state: SceneState, revolution: SceneState) -> dict:
    """The refined model at one angle and the global model over a revolution, per bore radius.

    Parameters
    ----------
    case : femcam.scene.case.CamDiskCase
        The scene's cam on its shaft (a roller follower).
    bores : sequence of float
        Bore radii ``Rb`` [m].
    state : femcam.scene.SceneState
        The analytic chain at the refined model's cam angle (``Scene.analyse([theta])``, rad;
        e.g. :func:`peak_angle` of ``case.revolution``).
    revolution : femcam.scene.SceneState
        The analytic chain at the global model's cam angles (``Scene.analyse`` at uniform angles
        over one revolution, rad).

    Returns
    -------
    dict
        Float arrays over ``bores`` under :data:`KEYS`, SI: lengths [m], stresses and pressures
        [Pa], angles [rad], ``dp0``/``da`` relative [-], times ``t_*`` [s], ``n_dofs_*``
        counts; ``*_rev``: the global model over the angles of ``revolution``; plus ``theta``
        [rad].
    """
    theta = float(_one_angle(state).theta[0])
    st = _validate.instance("revolution", revolution, SceneState, "a femcam.scene.SceneState")
    th = st.theta
    on = st.Fc > 0
    C = np.stack([st.profile.x, st.profile.y])[:, on]
    nn = np.stack([st.profile.pitch_x, st.profile.pitch_y])[:, on] - C
    nn = nn / np.hypot(*nn)
    out = {k: [] for k in KEYS}
    for Rb in bores:
        disk = disk_from_case(case, Rb=float(Rb))
        t0 = time.perf_counter()
        m, r = refined_at(case, disk, state)
        t1 = time.perf_counter()
        g = CamGlobalModel.build(disk=disk, length=case.pair.length, plane=case.pair.plane)
        t2 = time.perf_counter()
        rg = solve_global(g, C, nn, st.Fc[on])
        t3 = time.perf_counter()
        k = int(np.argmax(rg["hoop_max"]))
        r1 = solve_global(g, *_contact_at(state), np.array([r.F]))
        vals = dict(Rb=Rb, web=disk.web, p0=r.p0, a=r.a, p0_local=r.p0_local, a_local=r.a_local, dp0=r.dp0,
                    da=r.da, delta=r.delta, delta_local=r.delta_local, hoop_refined=r.hoop_max,
                    hoop_angle_refined=r.hoop_theta, shaft_p0=r.shaft_p0, shaft_arc=r.shaft_arc,
                    hoop_max_rev=rg["hoop_max"][k], hoop_global_at_theta=r1["hoop_max"][0],
                    theta_hoop_max_rev=th[on][k], t_refined=t1 - t0,
                    t_global=t2 - t1, t_rev=t3 - t2, n_dofs_refined=m.n_dofs, n_dofs_global=g.n_dofs)
        for key in KEYS:
            out[key].append(vals[key])
    res = {k: np.asarray(v, dtype=float) for k, v in out.items()}
    res["theta"] = theta
    return res
