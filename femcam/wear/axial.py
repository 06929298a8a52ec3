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

from ..halfspace.rows import finite_length_rows, has_finite_length
from ..scene.case import contact_case
from .coating import coating_wear
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


def axial_table(scene, theta, fe=None) -> dict:
    """Per-angle table for :func:`femcam.wear.map.wear_map` with ``pressure="axial_peak"``.

    Parameters
    ----------
    scene : femcam.scene.Scene
        A roller scene with finite-length keys.
    theta : ndarray, shape (n,)
        Cam angles (rad).
    fe : femcam.sweep.SweepResult, optional
        A sweep of ``scene`` at ``theta``: its ``hs_p_axial_peak``/``hs_w_max`` columns are used.
        Default: :func:`femcam.halfspace.rows.finite_length_rows` at ``theta``.

    Returns
    -------
    dict
        ``theta`` (rad), ``a_axial`` (m), ``p0_axial`` (Pa), ``Fc`` (N), ``w_max`` (N/m).
    """
    theta = np.asarray(theta, float)
    if fe is not None:
        tab = fe.table
        p, w, Fc = (np.asarray(tab[k], float) for k in ("hs_p_axial_peak", "hs_w_max", "Fc"))
    else:
        r = finite_length_rows(scene, theta)
        p, w, Fc = r["p_axial_peak"], r["w_max"], r["Fc"]
    a, p0 = axial_pressure(p, w)
    return {"theta": theta, "a_axial": a, "p0_axial": p0, "Fc": np.clip(Fc, 0.0, None), "w_max": w}


def scene_wear_axial(scene, theta, *, cycles: float = 1e6, fe=None, k_factor=None,
                     regime=None) -> tuple[WearMap, object, SlipResult]:
    """Archard wear map of a finite-length roller scene from its most loaded slice.

    The same steps as :func:`femcam.wear.scene.scene_wear` (kinematics, slip, k, coating) with
    the pressure of :func:`axial_table`.

    Parameters
    ----------
    scene : femcam.scene.Scene
        A roller scene with finite-length keys.
    theta : ndarray, shape (n,)
        Cam angles [rad], uniform over one revolution, endpoint excluded.
    cycles : float
        Number of cam revolutions [-].
    fe : femcam.sweep.SweepResult, optional
        A sweep of ``scene`` at ``theta`` whose half-space columns are used (see
        :func:`axial_table`); default: solve the strip here.
    k_factor, regime : ndarray, shape (n,), optional
        The wear coefficient's factor k(lambda)/k [-] and the lubrication regime per angle;
        default: the dry k.

    Returns
    -------
    wear_map : femcam.wear.map.WearMap
        ``pressure = "axial_peak"``; its ``load_error`` is 0 (``pi a p0 / 2 = w_max`` exactly).
    state : femcam.scene.SceneState
        ``scene.analyse(theta)``.
    slip : femcam.wear.slip.SlipResult
        Sliding and transport speeds [m/s] at ``theta``.
    """
    st = scene.analyse(theta)
    Fc = np.clip(st.Fc, 0.0, None)
    table = axial_table(scene, theta, fe)
    kw = slip_kwargs(scene.wear, omega=scene.omega, mu=scene.mu, follower=scene.follower)
    slip = follower_slip(scene.follower, theta, st.s, st.s1, st.s2, Fc=Fc, **kw)
    k, _where = wear_coefficient_info(scene.wear, scene.cam.hardness)
    wm = wear_map(table, slip, k=k, length=scene.length, cycles=cycles, pressure="axial_peak",
                  k_factor=k_factor, regime=regime)
    return with_coating(wm, coating_wear(scene.layers, scene.wear, scene.cam.hardness)), st, slip


def scene_wear_map(scene, theta, *, cycles: float = 1e6, tip_radius: float | None = None, fe=None,
                   k_factor=None, regime=None) -> tuple[WearMap, object, SlipResult]:
    """Archard wear map of a scene with the pressure its geometry asks for: the most loaded
    slice (:func:`scene_wear_axial`) for a crowned, tilted or narrower roller
    (:func:`femcam.halfspace.rows.has_finite_length`), the 2D contact
    (:func:`femcam.wear.scene.scene_wear`) otherwise.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene.
    theta : ndarray, shape (n,)
        Cam angles [rad], uniform over one revolution, endpoint excluded.
    cycles : float
        Number of cam revolutions [-].
    tip_radius : float or None, optional
        Knife-edge tip radius [m] (2D contact only).
    fe : femcam.sweep.SweepResult, optional
        A sweep of ``scene`` at ``theta`` giving the pressure.
    k_factor, regime : ndarray, shape (n,), optional
        The wear coefficient's factor k(lambda)/k [-] and the lubrication regime per angle.

    Returns
    -------
    wear_map : femcam.wear.map.WearMap
        The map (the most loaded slice's when ``has_finite_length(scene.finite_length, scene.length)``).
    state : femcam.scene.SceneState
        ``scene.analyse(theta)``.
    slip : femcam.wear.slip.SlipResult
        Sliding and transport speeds [m/s] at ``theta``.
    """
    if has_finite_length(scene.finite_length, scene.length):
        return scene_wear_axial(scene, theta, cycles=cycles, fe=fe, k_factor=k_factor, regime=regime)
    return scene_wear(contact_case(scene, theta, tip_radius=tip_radius), cycles=cycles, fe=fe,
                      k_factor=k_factor, regime=regime,
                      coating=coating_wear(scene.layers, scene.wear, scene.cam.hardness))
