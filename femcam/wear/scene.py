"""The Archard wear map of a scene's contact: kinematics, contact pressure and slip put together.

The contact comes as a :class:`femcam.scene.case.ContactCase` (``contact_case(scene, theta)``),
the coated body's wear data as a :class:`femcam.wear.coating.CoatingWear` from the caller.
Knife-edge followers need a tip radius (the case's ``tip_radius``: ``[follower]
tip_radius_mm`` or ``contact_case(..., tip_radius=...)``): the kinematics, pressure angle,
contact force and cam curvature are then those of the cam cut for the radiused tip (a roller of
that radius that does not turn), the pressure is Hertz of the cam against the tip radius
(Johnson 1985 §4.3), and the slip is :func:`femcam.wear.slip.radiused_tip`.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from .. import _validate
from ..errors import InputError
from ..hertz import LineContact
from ..scene.case import ContactCase
from .coating import CoatingWear
from .map import WearMap, wear_map
from .options import slip_kwargs, wear_coefficient_info
from .slip import SlipResult, follower_slip


def scene_wear(case: ContactCase, *, cycles: float = 1e6, fe=None, k_factor=None, regime=None,
               coating: CoatingWear | None = None) -> tuple[WearMap, object, SlipResult]:
    """Archard wear map of a scene's contact over one revolution.

    Parameters
    ----------
    case : femcam.scene.case.ContactCase
        The contact at cam angles ``theta`` (rad, uniform over one revolution, endpoint
        excluded): ``contact_case(scene, theta)``.
    cycles : float
        Number of cam revolutions.
    fe : femcam.sweep.SweepResult, optional
        An FE sweep of the scene at ``theta`` (a knife edge: ``femcam.scene.case.tip_scene(scene, tip)``): its
        ``a_fe``/``p0_fe`` are the pressure (angles whose FE solve failed are skipped with a
        warning). Default: Hertz.
    k_factor, regime : ndarray, shape (n,), optional
        The wear coefficient's factor k(lambda)/k and the lubrication regime per angle (from
        :func:`femcam.assess.wear_factor` for a lubricated scene); default: the dry k.
    coating : femcam.wear.coating.CoatingWear, optional
        The coated body's wear data (:func:`femcam.wear.coating.coating_wear`); None: uncoated.

    Returns
    -------
    wear_map : femcam.wear.map.WearMap
    state : femcam.scene.SceneState
        ``case.state`` (of the cam cut for the tip, for a knife edge).
    slip : femcam.wear.slip.SlipResult

    Raises
    ------
    InputError
        A knife edge without a tip radius.
    """
    case = _validate.instance("case", case, ContactCase, "a femcam.scene.case.ContactCase "
                              "(femcam.scene.case.contact_case(scene, theta))")
    f = case.follower
    if f.needs_tip and case.tip_radius is None:
        raise InputError("follower type = knife_edge: a sharp tip has no contact width, so the contact "
                         "pressure and the wear depth are undefined; give the tip radius: scene [follower] "
                         "tip_radius_mm (mm) or --tip-radius-mm (mm)")
    theta, st = case.theta, case.state
    Fc = np.clip(st.Fc, 0.0, None)
    if fe is not None:
        table, pressure = fe, "fe"
    else:
        # a roller, the tip's roller, or the roller or pad on an arm: the follower circle's radius
        R2 = case.tip_radius if f.needs_tip else (f.Rr if f.draws_circle else math.inf)
        pr = case.pair
        hc = LineContact(F=Fc, length=pr.length, R1=st.rho, R2=R2, cam=pr.cam, roller=pr.roller)
        table, pressure = {"theta": theta, "a": hc.a, "p0": hc.p0, "Fc": Fc}, "hertz"
    kw = slip_kwargs(case.wear, omega=case.omega, mu=case.pair.mu, follower=f)
    slip = follower_slip(f, theta, st.s, st.s1, st.s2, Fc=Fc, **kw, tip_radius=case.tip_radius)
    k, _where = wear_coefficient_info(case.wear, case.pair.cam.hardness)
    wm = wear_map(table, slip, k=k, length=case.pair.length, cycles=cycles, pressure=pressure,
                  k_factor=k_factor, regime=regime)
    return with_coating(wm, coating), st, slip


def with_coating(wm: WearMap, coating: CoatingWear | None) -> WearMap:
    """``wm`` with the coated body's depth after ``wm.cycles`` revolutions worn at the
    coating's k until the coating is worn through (:mod:`femcam.wear.coating`); ``wm`` itself
    for an uncoated scene or a coating without a wear coefficient (``coating`` None).

    The roller's pattern drifts from revolution to revolution; its per-revolution rate at a point
    is taken as the drift-averaged ``depth_follower_total / cycles`` (exact for a phase-locked
    roller and for a drift that has spread the wear evenly).

    Parameters
    ----------
    wm : femcam.wear.map.WearMap
        The uncoated wear map (depths [m], ``cycles`` in revolutions).
    coating : femcam.wear.coating.CoatingWear or None
        The coated body's wear data (thickness [m], k [m^3/(N m)]).

    Returns
    -------
    femcam.wear.map.WearMap
        ``wm`` with ``coating`` (``thickness_m`` [m], ``k_coating``, ``k_substrate``
        [m^3/(N m)], ``revolutions_through`` [-]) and ``depth_cam_cycles`` or
        ``depth_follower_cycles`` [m] set.
    """
    cw = coating
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
