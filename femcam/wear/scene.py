"""The Archard wear map of a scene: kinematics, contact pressure and slip put together.

Knife-edge followers need a tip radius (``tip_radius`` in m, or the scene's ``[follower]
tip_radius_mm``): the kinematics, pressure
angle, contact force and cam curvature are then those of the cam cut for the radiused tip (a
roller of that radius that does not turn), the pressure is Hertz of the cam against the tip
radius (Johnson 1985 §4.3), and the slip is :func:`femcam.wear.slip.radiused_tip`.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from .. import _validate
from ..errors import InputError
from ..hertz import LineContact
from ..profile import RollerFollower
from .coating import coating_wear
from .map import WearMap, wear_map
from .options import follower_tip_radius, slip_kwargs, wear_coefficient_info
from .slip import SlipResult, follower_slip


def tip_scene(scene, tip_radius: float | None):
    """The scene whose cam is cut for a radiused knife-edge tip.

    Parameters
    ----------
    scene : femcam.scene.Scene
    tip_radius : float or None
        Tip radius (m); knife-edge followers only.

    Returns
    -------
    femcam.scene.Scene
        A knife-edge scene with a roller of radius ``tip_radius`` (which the slip model keeps
        from turning); any other follower: the scene itself.

    Raises
    ------
    InputError
        A tip radius for a follower that is not a knife edge, or none for a knife edge.
    """
    if not scene.follower.needs_tip:
        if tip_radius is not None:
            raise InputError(f"tip radius = {tip_radius * 1e3:g} mm: applies to knife-edge followers only "
                             f"(this scene's follower is a {scene.follower.kind} follower)")
        return scene
    if tip_radius is None:
        raise InputError("follower type = knife_edge: a sharp tip has no contact width, so the contact "
                         "pressure and the wear depth are undefined; give the tip radius: scene [follower] "
                         "tip_radius_mm (mm) or --tip-radius-mm (mm)")
    f = scene.follower
    return dataclasses.replace(scene, follower=RollerFollower(Rb=f.Rb, Rr=tip_radius, e=f.e))


def scene_tip_radius(scene, tip_radius: float | None = None) -> float | None:
    """The tip radius to use.

    Parameters
    ----------
    scene : femcam.scene.Scene
    tip_radius : float, optional
        Tip radius (m), checked > 0 for a knife edge; default the scene's ``[follower]
        tip_radius_mm`` (:func:`femcam.wear.options.follower_tip_radius`).

    Returns
    -------
    float or None
        m.
    """
    if tip_radius is None:
        return follower_tip_radius(scene)
    if scene.follower.needs_tip:
        return _validate.positive("tip radius", tip_radius, "m")
    return tip_radius


def scene_wear(scene, theta, *, cycles: float = 1e6, tip_radius: float | None = None,
               fe=None, k_factor=None, regime=None) -> tuple[WearMap, object, SlipResult]:
    """Archard wear map of a scene over one revolution.

    Parameters
    ----------
    scene : femcam.scene.Scene
    theta : ndarray, shape (n,)
        Cam angles (rad), uniform over one revolution, endpoint excluded.
    cycles : float
        Number of cam revolutions.
    tip_radius : float, optional
        Knife-edge tip radius (m); default the scene's ``[follower] tip_radius_mm``.
    fe : femcam.sweep.SweepResult, optional
        An FE sweep of ``tip_scene(scene, tip)`` at ``theta``: its ``a_fe``/``p0_fe`` are the
        pressure (angles whose FE solve failed are skipped with a warning). Default: Hertz.
    k_factor, regime : ndarray, shape (n,), optional
        The wear coefficient's factor k(lambda)/k and the lubrication regime per angle (from
        :func:`femcam.assess.assess_rows` for a lubricated scene); default: the dry k.

    Returns
    -------
    wear_map : femcam.wear.map.WearMap
    state : femcam.scene.SceneState
        ``scene.analyse(theta)`` of the (tip) scene.
    slip : femcam.wear.slip.SlipResult
    """
    tip_radius = scene_tip_radius(scene, tip_radius)
    sc = tip_scene(scene, tip_radius)
    st = sc.analyse(theta)
    Fc = np.clip(st.Fc, 0.0, None)
    if fe is not None:
        table, pressure = fe, "fe"
    else:
        # a roller, the tip's roller, or the roller or pad on an arm: the follower circle's radius
        R2 = sc.follower.Rr if sc.follower.draws_circle else math.inf
        hc = LineContact(F=Fc, length=sc.length, R1=st.rho, R2=R2, cam=sc.cam, roller=sc.roller)
        table, pressure = {"theta": theta, "a": hc.a, "p0": hc.p0, "Fc": Fc}, "hertz"
    kw = slip_kwargs(scene.wear, omega=scene.omega, mu=scene.mu, follower=scene.follower)
    slip = follower_slip(scene.follower, theta, st.s, st.s1, st.s2, Fc=Fc, **kw,
                         tip_radius=tip_radius if sc is not scene else None)
    k, _where = wear_coefficient_info(scene.wear, scene.cam.hardness)
    wm = wear_map(table, slip, k=k, length=scene.length, cycles=cycles, pressure=pressure,
                  k_factor=k_factor, regime=regime)
    return with_coating(scene, wm), st, slip


def with_coating(scene, wm: WearMap) -> WearMap:
    """``wm`` with the coated body's depth after ``wm.cycles`` revolutions worn at the
    coating's k until the coating is worn through (:mod:`femcam.wear.coating`); ``wm`` itself
    for an uncoated scene or a coating without a wear coefficient.

    The roller's pattern drifts from revolution to revolution; its per-revolution rate at a point
    is taken as the drift-averaged ``depth_follower_total / cycles`` (exact for a phase-locked
    roller and for a drift that has spread the wear evenly).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene (its coating, from ``scene.layers``).
    wm : femcam.wear.map.WearMap
        The uncoated wear map (depths [m], ``cycles`` in revolutions).

    Returns
    -------
    femcam.wear.map.WearMap
        ``wm`` with ``coating`` (``thickness_m`` [m], ``k_coating``, ``k_substrate``
        [m^3/(N m)], ``revolutions_through`` [-]) and ``depth_cam_cycles`` or
        ``depth_follower_cycles`` [m] set.
    """
    cw = coating_wear(scene)
    if cw is None:
        return wm
    if cw.body == "cam":
        rate = wm.depth_cam
        new = {"depth_cam_cycles": cw.depth_after(rate, wm.cycles)}
    else:
        rate = wm.depth_follower_total / wm.cycles if wm.cycles > 0 else wm.depth_follower
        new = {"depth_follower_cycles": cw.depth_after(rate, wm.cycles)}
    rec = {"body": cw.body, "thickness_m": cw.thickness, "k_coating": cw.k_coating,
           "k_substrate": cw.k_substrate, "revolutions_through": cw.revolutions_through(rate),
           "source": cw.source}
    return dataclasses.replace(wm, coating=rec, **new)
