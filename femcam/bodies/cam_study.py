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

from ..materials import effective_modulus
from .cam_geometry import contact_frame
from .cam_global import CamGlobalModel
from .cam_model import CamDiskModel
from .cam_rows import disk_from_scene, solve_global
from .cam_solve import solve_cam_disk

KEYS = ("Rb", "web", "p0", "a", "p0_local", "a_local", "dp0", "da", "delta", "delta_local",
        "hoop_refined", "hoop_angle_refined", "shaft_p0", "shaft_arc", "hoop_max_rev", "theta_hoop_max_rev",
        "hoop_global_at_theta",
        "t_refined", "t_global", "t_rev", "n_dofs_refined", "n_dofs_global")


def peak_angle(scene, n: int = 720) -> float:
    """Cam angle of the largest contact force over one revolution.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene.
    n : int, optional
        Equally spaced cam angles over [0, 2 pi).

    Returns
    -------
    float
        The cam angle [rad].
    """
    th = np.linspace(0.0, 2 * math.pi, n, endpoint=False)
    return float(th[int(np.nanargmax(scene.analyse(th).Fc))])


def refined_at(scene, disk, theta: float, **kw):
    """The fully refined model of ``disk`` at one cam angle, solved for the scene's force there.

    Parameters
    ----------
    scene : femcam.scene.Scene
        A roller-follower scene.
    disk : CamDisk
        The cam disk.
    theta : float
        Cam angle [rad].
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
    C, n, rho, F = contact_frame(scene, theta)
    inv_R = 1 / scene.follower.Rr + (0.0 if math.isinf(rho) else 1 / rho)
    a_ref = math.sqrt(4 * F / scene.length / (inv_R * math.pi * effective_modulus(scene.cam, scene.roller,
                                                                                 scene.plane)))
    m = CamDiskModel.build(disk=disk, C=C, n=n, rho=rho, Rr=scene.follower.Rr, roller=scene.roller,
                           a_ref=a_ref, length=scene.length, plane=scene.plane, **kw)
    return m, solve_cam_disk(m, F=F)


def _contact_at(scene, theta):
    C, n, _, _ = contact_frame(scene, theta)
    return C[:, None], n[:, None]


def web_study(scene, bores, *, theta: float | None = None, n_rev: int = 360) -> dict:
    """The refined model at one angle and the global model over a revolution, per bore radius.

    Parameters
    ----------
    scene : femcam.scene.Scene
        A roller-follower scene.
    bores : sequence of float
        Bore radii ``Rb`` [m].
    theta : float or None, optional
        Cam angle of the refined model [rad]; None: :func:`peak_angle`.
    n_rev : int, optional
        Equally spaced cam angles of the global model over one revolution.

    Returns
    -------
    dict
        Float arrays over ``bores`` under :data:`KEYS`, SI: lengths [m], stresses and pressures
        [Pa], angles [rad], ``dp0``/``da`` relative [-], times ``t_*`` [s], ``n_dofs_*``
        counts; ``*_rev``: the global model over ``n_rev`` angles; plus ``theta`` [rad].
    """
    theta = peak_angle(scene) if theta is None else float(theta)
    th = np.linspace(0.0, 2 * math.pi, n_rev, endpoint=False)
    st = scene.analyse(th)
    on = st.Fc > 0
    C = np.stack([st.profile.x, st.profile.y])[:, on]
    nn = np.stack([st.profile.pitch_x, st.profile.pitch_y])[:, on] - C
    nn = nn / np.hypot(*nn)
    out = {k: [] for k in KEYS}
    for Rb in bores:
        disk = disk_from_scene(scene, Rb=float(Rb))
        t0 = time.perf_counter()
        m, r = refined_at(scene, disk, theta)
        t1 = time.perf_counter()
        g = CamGlobalModel.build(disk=disk, length=scene.length, plane=scene.plane)
        t2 = time.perf_counter()
        rg = solve_global(g, C, nn, st.Fc[on])
        t3 = time.perf_counter()
        k = int(np.argmax(rg["hoop_max"]))
        r1 = solve_global(g, *_contact_at(scene, theta), np.array([r.F]))
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
