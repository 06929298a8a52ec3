r"""Wear map of a finite-length roller (crown, edge radius, tilt, unequal widths): the axial peak.

The 2D wear map spreads the contact force evenly over the face width, ``w = Fc / l``. A crowned,
tilted or narrower roller does not: the half-space strip (:mod:`femcam.halfspace`) gives the
load per unit length along the roller, and the deepest wear is where it is largest. Archard's
depth per pass depends on the pressure only through ``w = int p dx`` (:mod:`femcam.wear.map`),
so the map is laid down by the most loaded slice, as the sweep's wear column does:

=========  ===========================================================  =====
symbol     meaning                                                      unit
=========  ===========================================================  =====
w_max      most loaded slice's load per unit length (mean over ``2b``)   N/m
p_peak     axial peak pressure ``max p(x, y)``                           Pa
a          half-width with ``pi a p_peak / 2 = w_max``                   m
=========  ===========================================================  =====

.. math:: p_0 = p_{peak},\qquad a = \frac{2 w_{max}}{\pi p_{peak}}
          \quad\Rightarrow\quad \Delta h = k\,w_{max}\,v_{slip}/V

(``p0`` and ``a`` only shape the map over about ``a``; the depth per pass is exact in ``w_max``).
With an FE sweep (``--source fe``) the sweep's own half-space columns are used (the same solver,
chunk-wise warm-started), so both sources lay down the same ``w_max``.
"""

from __future__ import annotations

import math

import numpy as np

from .. import _validate
from ..halfspace.rows import finite_length_rows
from ..scene.case import ContactCase
from ..scene.finite_case import FiniteCase
from .coating import CoatingWear
from .map import WearMap, wear_map
from .options import slip_kwargs, wear_coefficient_info
from .scene import scene_wear, with_coating
from .slip import SlipResult, follower_slip


def axial_pressure(p_peak, w_max) -> tuple[np.ndarray, np.ndarray]:
    r"""``(a, p0)`` (m, Pa) of the most loaded slice: ``p0 = p_peak``, ``a = 2 w_max / (pi p_peak)``.

    NaN (no contact) where either is not finite or ``p_peak <= 0``.

    Parameters
    ----------
    p_peak : array_like
        Axial peak pressure ``max p(x, y)`` [Pa].
    w_max : array_like
        Most loaded slice's load per unit length [N/m].

    Returns
    -------
    a : ndarray
        Half-width ``2 w_max / (pi p_peak)`` [m], float, the broadcast shape of the inputs.
    p0 : ndarray
        Peak pressure ``p_peak`` [Pa], same shape.

    Examples
    --------
    >>> a, p0 = axial_pressure(np.array([1e9]), np.array([1e5]))
    >>> round(float(a[0]) * 1e6, 3), float(p0[0])
    (63.662, 1000000000.0)
    """
    p = np.asarray(p_peak, float)
    w = np.asarray(w_max, float)
    ok = np.isfinite(p) & np.isfinite(w) & (p > 0)
    a = np.where(ok, 2.0 * w / (math.pi * np.where(ok, p, 1.0)), np.nan)
    return a, np.where(ok, p, np.nan)


def axial_table(case: ContactCase, finite: FiniteCase | None = None, fe=None) -> dict:
    """Per-angle table for :func:`femcam.wear.map.wear_map` with ``pressure="axial_peak"``.

    Parameters
    ----------
    case : femcam.scene.case.ContactCase
        A roller scene's contact at cam angles ``theta`` (rad): ``contact_case(scene, theta)``.
    finite : femcam.scene.FiniteCase, optional
        The roller's finite-length contact (``finite_case(scene)``; m, rad): the strip solved at
        ``case.theta`` by :func:`femcam.halfspace.finite_length_rows`. Needed without ``fe``.
    fe : femcam.sweep.SweepResult, optional
        A sweep of the scene at ``case.theta``: its ``hs_p_axial_peak``/``hs_w_max`` columns are
        used instead.

    Returns
    -------
    dict
        ``theta`` (rad), ``a_axial`` (m), ``p0_axial`` (Pa), ``Fc`` (N), ``w_max`` (N/m).

    Raises
    ------
    InputError
        Neither ``finite`` nor ``fe`` given.
    """
    case = _validate.instance("case", case, ContactCase, "a femcam.scene.case.ContactCase "
                              "(femcam.scene.case.contact_case(scene, theta))")
    theta = np.asarray(case.theta, float)
    if fe is not None:
        tab = fe.table
        p, w, Fc = (np.asarray(tab[k], float) for k in ("hs_p_axial_peak", "hs_w_max", "Fc"))
    else:
        finite = _validate.instance("finite", finite, FiniteCase, "a femcam.scene.FiniteCase "
                                    "(femcam.scene.finite_case(scene)) when fe is not given")
        st = case.state
        r = finite_length_rows(finite.strip(), theta, st.Fc, st.rho, finite.Rr)
        p, w, Fc = r["p_axial_peak"], r["w_max"], r["Fc"]
    a, p0 = axial_pressure(p, w)
    return {"theta": theta, "a_axial": a, "p0_axial": p0, "Fc": np.clip(Fc, 0.0, None), "w_max": w}


def scene_wear_axial(case: ContactCase, finite: FiniteCase | None = None, *, cycles: float = 1e6, fe=None,
                     k_factor=None, regime=None, coating: CoatingWear | None = None
                     ) -> tuple[WearMap, object, SlipResult]:
    """Archard wear map of a finite-length roller from its most loaded slice.

    The same steps as :func:`femcam.wear.scene.scene_wear` (kinematics, slip, k, coating) with
    the pressure of :func:`axial_table`.

    Parameters
    ----------
    case : femcam.scene.case.ContactCase
        A roller scene's contact at cam angles ``theta`` [rad], uniform over one revolution,
        endpoint excluded: ``contact_case(scene, theta)``.
    finite : femcam.scene.FiniteCase, optional
        The roller's finite-length contact (``finite_case(scene)``); needed without ``fe``.
    cycles : float
        Number of cam revolutions [-].
    fe : femcam.sweep.SweepResult, optional
        A sweep of the scene at ``theta`` whose half-space columns are used (see
        :func:`axial_table`); default: solve the strip here.
    k_factor, regime : ndarray, shape (n,), optional
        The wear coefficient's factor k(lambda)/k [-] and the lubrication regime per angle;
        default: the dry k.
    coating : femcam.wear.coating.CoatingWear, optional
        The coated body's wear data (thickness [m], k [m^3/(N m)];
        :func:`femcam.wear.coating.coating_wear`); None: uncoated.

    Returns
    -------
    wear_map : femcam.wear.map.WearMap
        ``pressure = "axial_peak"``; its ``load_error`` is 0 (``pi a p0 / 2 = w_max`` exactly).
    state : femcam.scene.SceneState
        ``case.state``.
    slip : femcam.wear.slip.SlipResult
        Sliding and transport speeds [m/s] at ``theta``.
    """
    table = axial_table(case, finite, fe)
    theta, st = case.theta, case.state
    Fc = np.clip(st.Fc, 0.0, None)
    kw = slip_kwargs(case.wear, omega=case.omega, mu=case.pair.mu, follower=case.follower)
    slip = follower_slip(case.follower, theta, st.s, st.s1, st.s2, Fc=Fc, **kw)
    k, _where = wear_coefficient_info(case.wear, case.pair.cam.hardness)
    wm = wear_map(table, slip, k=k, length=case.pair.length, cycles=cycles, pressure="axial_peak",
                  k_factor=k_factor, regime=regime)
    return with_coating(wm, coating), st, slip


def scene_wear_map(case: ContactCase, finite: FiniteCase | None = None, *, cycles: float = 1e6, fe=None,
                   k_factor=None, regime=None, coating: CoatingWear | None = None
                   ) -> tuple[WearMap, object, SlipResult]:
    """Archard wear map of a scene's contact with the pressure its geometry asks for: the most
    loaded slice (:func:`scene_wear_axial`) for a crowned, tilted or narrower roller
    (``finite.applies``: :func:`femcam.halfspace.rows.has_finite_length`), the 2D contact
    (:func:`femcam.wear.scene.scene_wear`) otherwise.

    Parameters
    ----------
    case : femcam.scene.case.ContactCase
        The contact at cam angles ``theta`` [rad], uniform over one revolution, endpoint
        excluded (``contact_case(scene, theta, tip_radius=...)``; a knife edge's tip radius [m]
        for the 2D contact).
    finite : femcam.scene.FiniteCase or None, optional
        A roller's finite-length contact (``finite_case(scene)``); None: the 2D contact.
    cycles : float
        Number of cam revolutions [-].
    fe : femcam.sweep.SweepResult, optional
        A sweep of the scene at ``theta`` giving the pressure.
    k_factor, regime : ndarray, shape (n,), optional
        The wear coefficient's factor k(lambda)/k [-] and the lubrication regime per angle.
    coating : femcam.wear.coating.CoatingWear, optional
        The coated body's wear data (thickness [m], k [m^3/(N m)]); None: uncoated.

    Returns
    -------
    wear_map : femcam.wear.map.WearMap
        The map (the most loaded slice's when ``finite.applies``).
    state : femcam.scene.SceneState
        ``case.state``.
    slip : femcam.wear.slip.SlipResult
        Sliding and transport speeds [m/s] at ``theta``.
    """
    if finite is not None and _validate.instance("finite", finite, FiniteCase, "a femcam.scene.FiniteCase "
                                                 "or None").applies:
        return scene_wear_axial(case, finite, cycles=cycles, fe=fe, k_factor=k_factor, regime=regime,
                                coating=coating)
    return scene_wear(case, cycles=cycles, fe=fe, k_factor=k_factor, regime=regime, coating=coating)
