r"""The FE sweep on the real cam: curvature-jump angles, traction from the mechanism, the model
that answers each angle, and the three followers (:mod:`femcam.fe.choice`, docs/fe_real_cam.md).

* **Curvature jumps** (:func:`jump_angles`): every junction of the cam program with a step in
  ``s''`` inside the requested angle range is inserted with ``n_refine`` angles per side over the
  span in which the contact zone (Hertz half-width ``a`` at the junction) straddles it
  (:func:`femcam.fe.angles.refine_angles`); those rows are flagged ``curvature_jump`` and solved
  with both the exact and the osculating-arc gap.
* **Traction** (:func:`scene_traction`): rollers roll, the tangential force on the cam is what
  the roller's angular acceleration and bearing drag need (:func:`femcam.wear.slip.roller_inertia`
  on a uniform revolution, :func:`femcam.fe.choice.mechanism_Q`), solved as Coulomb partial slip;
  knife-edge, flat-faced and curved-pad (on an arm, :mod:`femcam.profile.pad`) followers slide
  fully in the direction of the sliding velocity (:func:`femcam.fe.followers.sliding_sign`).
  The scene's ``[contact] sliding`` is an explicit override: full sliding in that fixed
  direction.
* **Model per angle** (:func:`arc_error_estimate`): the error of the osculating-arc gap is
  estimated without building the exact gap from the curvature gradient along the cam surface,
  ``kappa_1 = d kappa / d s``: the cam surface departs from its osculating circle by
  ``kappa_1 x^3 / 6``, so with ``g_arc(a) = a^2 / (2 R_eff)``

  .. math:: \epsilon_{arc} \approx \tfrac12\,\frac{|\kappa_1| a^3/6}{a^2/(2R_{eff})}
            = \frac{|\kappa_1|\,a\,R_{eff}}{6},\qquad
            \epsilon_{Hertz} \approx \epsilon_{arc} + (a/R_{min})^2

  (Johnson 1985 §4.1; the same bound :mod:`femcam.fe.choice` takes from the exact gap). Rows
  whose estimate exceeds the sweep tolerance, and the ``curvature_jump`` rows, are solved with
  the exact gap (:func:`femcam.fe.choice.solve_angle`); the others keep the family model's
  arc-gap answer (``model = fe_arc``).
* **Method** ``fe`` answers every contact angle with the FE (arc or exact gap); ``auto`` lets
  Hertz answer the angles whose Hertz estimate is within the tolerance
  (:func:`hertz_within_tolerance`, :func:`auto_hertz_rows`) and builds no model for them.
* **Knife-edge**: the kinematics and the contact are those of the cam cut for the radiused tip
  (``[follower] tip_radius_mm``; :func:`femcam.scene.case.tip_scene`). **Flat-faced**: the
  per-angle :func:`femcam.fe.choice.solve_angle` on models binned by half-width and cam radius
  (:mod:`femcam.sweep.realrows`); a contact past the face end is the row status
  ``edge_contact`` (never Hertz).

References: K. L. Johnson, *Contact Mechanics*, CUP 1985, §4.1, §7.1, §8.2; F. W. Carter,
Proc. R. Soc. Lond. A 112 (1926) 151-157.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..fe.angles import curvature_jumps, refine_angles
from ..fe.choice import MODELS, mechanism_Q
from ..fe.followers import rolling_direction, sliding_sign
from ..fe.gap import contact_geometry
from ..materials import effective_modulus
from ..profile import (
    cam_profile,
)
from ..scene.case import tip_scene
from ..wear.options import slip_kwargs
from ..wear.slip import roller_inertia

#: angles inserted per side of a curvature jump (over the straddle span)
N_REFINE = 8
#: uniform revolution grid of the roller inertia model (deg step)
TRACTION_STEP_DEG = 0.5
#: row statuses added by the real-cam sweep
REAL_CAM_STATUSES = ("edge_contact", "refused")


def contact_scene(scene):
    """The scene whose kinematics and contact the sweep solves: a knife-edge scene becomes the
    cam cut for its radiused tip (``[follower] tip_radius_mm``, refused naming the key when
    missing); other scenes are returned as they are.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene swept.

    Returns
    -------
    femcam.scene.Scene
        ``scene``, or its tip-cam scene for a knife-edge follower.

    Raises
    ------
    InputError
        A knife-edge follower without ``[follower] tip_radius_mm``.
    """
    if not scene.follower.needs_tip:
        return scene
    tip = scene.tip_radius
    if tip is None:
        raise InputError("follower.type = knife_edge: a sharp tip has no contact width, so the contact "
                         "stresses are undefined; add the tip radius to the scene: [follower] "
                         "tip_radius_mm = ... (mm)")
    return tip_scene(scene, tip)


def _tip(scene):
    return scene.tip_radius if scene.follower.needs_tip else None


def _a_at(scene, jump, F) -> float:
    """Hertz half-width (m) at a junction: the larger of the two sides."""
    _, R = contact_geometry(scene.follower, _tip(scene))
    E = effective_modulus(scene.cam, scene.roller, scene.plane)
    a = 0.0
    for rho in (jump.rho_left, jump.rho_right):
        inv = (0.0 if math.isinf(R) else 1 / R) + 1 / rho
        if inv > 0:
            a = max(a, math.sqrt(4 * F / scene.length / inv / (math.pi * E)))
    return a


def jump_angles(scene, angles) -> tuple[np.ndarray, np.ndarray]:
    """The sweep angles with the curvature jumps resolved.

    Parameters
    ----------
    scene : femcam.scene.Scene
    angles : ndarray, shape (n,)
        Requested cam angles (rad).

    Returns
    -------
    angles : ndarray, shape (m,)
        ``angles`` unchanged when no jump lies inside their range (a full revolution when they
        span >= 359 deg), else sorted (mod 2 pi) with the refinement of each jump inside it.
    curvature_jump : ndarray of bool, shape (m,)
        Rows inside a straddle span.
    """
    angles = np.asarray(angles, float)
    flag = np.zeros(angles.size, bool)
    jumps = curvature_jumps(scene.program, scene.follower, tip_radius=_tip(scene))
    if not jumps:
        return angles, flag
    lo, hi = float(angles.min()), float(angles.max())
    full = hi - lo >= math.radians(359.0)
    inside = [j for j in jumps if full or lo <= j.theta <= hi
              or lo <= j.theta + 2 * math.pi <= hi]
    st = contact_scene(scene).analyse(np.array([j.theta for j in inside])) if inside else None
    keep = [(j, float(F)) for j, F in zip(inside, st.Fc if st is not None else [], strict=True) if F > 0]
    if not keep:
        return angles, flag
    a = [_a_at(scene, j, F) for j, F in keep]
    return refine_angles(angles, [j for j, _ in keep], a, n_refine=N_REFINE)


@dataclass(frozen=True)
class Traction:
    """Per-angle traction of the sweep rows.

    Parameters
    ----------
    Q : ndarray of float, shape (n,)
        Tangential force on the cam along local x [N]; NaN: full sliding.
    direction : ndarray of int, shape (n,)
        Rolling direction (+1/-1) where ``Q`` is given, else the sliding sign.
    source : str
        Where the traction came from (recorded in the provenance).
    """

    Q: np.ndarray
    direction: np.ndarray
    source: str

    def at(self, i: int) -> tuple[float | None, int]:
        """The traction of one row.

        Parameters
        ----------
        i : int
            Row index.

        Returns
        -------
        Q : float or None
            Tangential force [N]; None: full sliding.
        direction : int
            Rolling direction or sliding sign (+1/-1).
        """
        q = float(self.Q[i])
        return (None if math.isnan(q) else q), int(self.direction[i])

    def chunk(self, a: int, b: int) -> Traction:
        """Rows ``a:b`` (a chunk).

        Parameters
        ----------
        a, b : int
            Row range.

        Returns
        -------
        Traction
            The rows' traction, same ``source``.
        """
        return Traction(Q=self.Q[a:b], direction=self.direction[a:b], source=self.source)


def _roller_J(scene, J):
    """Polar inertia (kg m^2): the scene's ``[wear] J_kg_m2`` or, as
    :func:`femcam.wear.slip.follower_slip`, a solid steel disc of the roller radius, 10 mm wide."""
    return J if J is not None else 0.5 * math.pi * 7850.0 * 0.010 * scene.follower.Rr ** 4


def scene_traction(scene, theta) -> Traction:
    """Traction of every sweep angle from the mechanism (module docstring).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene (follower, ``mu``, ``[contact] sliding``, ``[wear]`` roller inertia and drag).
    theta : ndarray, shape (n,)
        Cam angles [rad].

    Returns
    -------
    Traction
        ``Q`` [N] and direction per angle.

    Raises
    ------
    InputError
        A knife-edge without ``[follower] tip_radius_mm``.
    """
    theta = np.asarray(theta, float)
    n = theta.size
    if scene.sliding:  # explicit override: full sliding in a fixed direction
        s = -1 if str(scene.sliding).strip() == "-x" else 1
        return Traction(np.full(n, np.nan), np.full(n, s, int), f"[contact] sliding = {scene.sliding}")
    f = scene.follower
    if f.oscillating and f.rolls:  # the roller slip models are translating only
        return Traction(np.zeros(n), np.ones(n, int), "oscillating roller: pure rolling, no traction "
                        "(the roller inertia slip model is not built for an arm)")
    if not f.rolls:  # knife-edge, flat face, the pad on an arm: full sliding
        sg = sliding_sign(scene.program, f, theta, tip_radius=_tip(scene))
        return Traction(np.full(n, np.nan), sg.astype(int), "full sliding, sign of the sliding velocity")
    roll = rolling_direction(scene.program, f, theta)
    if not scene.mu > 0:
        return Traction(np.zeros(n), roll.astype(int), "mu = 0: no traction")
    kw = slip_kwargs(scene.wear, omega=scene.omega, mu=scene.mu, follower=scene.follower)
    J, T_drag = _roller_J(scene, kw["J"]), float(kw["T_drag"])
    grid = np.radians(np.arange(0.0, 360.0, TRACTION_STEP_DEG))
    g = scene.analyse(grid)
    Fc = np.clip(g.Fc, 0.0, None)
    slip = roller_inertia(grid, g.s, g.s1, g.s2, Fc, Rb=f.Rb, Rr=f.Rr, omega=scene.omega,
                          mu=scene.mu, J=J, T_drag=T_drag, e=f.e)
    Qg = mechanism_Q(slip.Omega, grid, scene.omega, J=J, T_drag=T_drag, Rr=f.Rr)
    Q = np.interp(np.mod(theta, 2 * math.pi), grid, Qg, period=2 * math.pi)
    return Traction(Q, roll.astype(int), f"roller inertia J = {J:.3g} kg m^2, drag {T_drag:g} N m")


def arc_error_estimate(scene, theta, a, R: float) -> tuple[np.ndarray, np.ndarray]:
    """Estimated relative p0 error of the osculating-arc FE and of Hertz (module docstring).
    Vectorised: two profile evaluations ``1e-5`` rad on each side of every angle.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene (cam program, follower).
    theta : ndarray, shape (n,)
        Cam angles [rad].
    a : ndarray, shape (n,)
        Hertz half-widths [m].
    R : float
        Follower radius at the contact [m] (``inf``: flat face).

    Returns
    -------
    e_arc : ndarray, shape (n,)
        Estimated p0 error of the arc-gap FE [%].
    e_hertz : ndarray, shape (n,)
        Estimated p0 error of Hertz [%].
    """
    theta = np.asarray(theta, float)
    a = np.asarray(a, float)
    d = 1e-5
    both = np.concatenate([theta - d, theta + d])
    gen, _ = contact_geometry(scene.follower, _tip(scene))
    dd = scene.program.derivatives(both)
    pr = cam_profile(gen, both, dd.s, dd.s1, dd.s2, allow_undercut=True)
    n = theta.size
    ds = np.hypot(pr.x[n:] - pr.x[:n], pr.y[n:] - pr.y[:n])
    with np.errstate(divide="ignore", invalid="ignore"):
        k = 1.0 / pr.rho
        k1 = np.abs(k[n:] - k[:n]) / ds
        kc = 0.5 * (k[n:] + k[:n])
        inv = (0.0 if math.isinf(R) else 1 / R) + kc
        R_eff = 1.0 / inv
        e_arc = 100.0 * k1 * a * np.abs(R_eff) / 6.0
        R_min = np.minimum(R, np.abs(1.0 / kc))
        e_h = e_arc + 100.0 * (a / R_min) ** 2
    return e_arc, e_h


def hertz_within_tolerance(e_hertz_pct, jump, tolerance: float) -> np.ndarray:
    """Method ``auto``: the rows Hertz answers (estimate within the tolerance, not in a
    curvature jump's span).

    Parameters
    ----------
    e_hertz_pct : ndarray, shape (n,)
        Estimated p0 error of Hertz [%] (:func:`arc_error_estimate`).
    jump : ndarray of bool, shape (n,), or None
        Rows inside a curvature jump's straddle span.
    tolerance : float
        Sweep tolerance [-] (relative, not %).

    Returns
    -------
    ndarray of bool, shape (n,)
        Rows Hertz answers.
    """
    ok = np.asarray(e_hertz_pct, float) <= 100.0 * tolerance
    return ok & ~np.asarray(jump, bool) if jump is not None else ok


def auto_hertz_rows(scene, cp, options, theta, F, rho, contact, jump) -> np.ndarray:
    """Method ``auto``: the rows (bool, shape (n,)) Hertz answers, decided once in the parent
    process from the Hertz half-width (Johnson 1985 eq. 4.43) so that the family plan and the
    chunks agree; all False for other methods.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene.
    cp : ContactParams
        Its contact parameters (``Rr``, ``length``, ``E_star``).
    options : ResolvedOptions
        ``method`` and ``tolerance``.
    theta : ndarray, shape (n,)
        Cam angles [rad].
    F : ndarray, shape (n,)
        Contact forces [N].
    rho : ndarray, shape (n,)
        Cam radii of curvature [m].
    contact : ndarray of bool, shape (n,)
        Angles with contact.
    jump : ndarray of bool, shape (n,), or None
        Rows inside a curvature jump's straddle span.

    Returns
    -------
    ndarray of bool, shape (n,)
        Rows Hertz answers (none for a coated roller or knife-edge scene: its Hertz error
        estimate knows no coating, the coated FE answers).
    """
    n = np.asarray(theta).size
    if options.method != "auto" or (cp.coat_body is not None and not scene.follower.flat_face):
        return np.zeros(n, bool)   # a coated body: Hertz (homogeneous) is not the scene's model
    F = np.clip(np.asarray(F, float), 0.0, None)
    rho = np.asarray(rho, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / rho + (0.0 if math.isinf(cp.Rr) else 1.0 / cp.Rr)
        a = np.sqrt(4 * F / (cp.length * inv * math.pi * cp.E_star))
    ok = np.asarray(contact, bool) & np.isfinite(a) & (a > 0)
    out = np.zeros(n, bool)
    idx = np.flatnonzero(ok)
    if idx.size:
        _, e_h = arc_error_estimate(scene, np.asarray(theta)[idx], a[idx], cp.Rr)
        out[idx] = hertz_within_tolerance(e_h, None if jump is None else np.asarray(jump)[idx],
                                          options.tolerance)
    return out


def traction_args(traction: Traction | None, i: int, sliding: int) -> tuple[int, float | None, int]:
    """``(sliding, Q, rolling)`` of :meth:`femcam.fe.ContactModel.solve` for row ``i``: full
    sliding in ``sliding`` without a traction table.

    Parameters
    ----------
    traction : Traction or None
        The sweep's traction (None: method hertz or no table).
    i : int
        Row index into ``traction``.
    sliding : int
        Default sliding direction (+1/-1).

    Returns
    -------
    sliding : int
        Sliding direction (+1/-1; 1 when ``Q`` is given).
    Q : float or None
        Tangential force on the cam [N]; None: full sliding.
    rolling : int
        Rolling direction (+1/-1; 0 under full sliding).
    """
    if traction is None:
        return sliding, None, 0
    Q, d = traction.at(i)
    return (d, None, 0) if Q is None else (1, Q, d)


def follower_radius(scene) -> float:
    """Radius of the follower surface at the contact.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene.

    Returns
    -------
    float
        ``Rr``, the knife-edge tip radius, or ``inf`` (flat face) [m].
    """
    return scene.follower.contact_radius(_tip(scene))


def real_cam_summary(table, traction: Traction | None) -> dict:
    """Provenance counts: rows per answering model, curvature-jump rows, edge contacts, and the
    traction's source.

    Parameters
    ----------
    table : Mapping[str, ndarray]
        The sweep table (``model``, ``curvature_jump``, ``status`` columns).
    traction : Traction or None
        The sweep's traction.

    Returns
    -------
    dict
        ``{"models": {model: count}, "n_curvature_jump", "n_edge_contact", "traction"}``
        (``<model>+coating``, ``<model>+ring`` counted apart where the coated or the ring model
        answered).
    """
    names = np.array([str(m) for m in table["model"]], dtype=str)
    models = {m: int(np.count_nonzero(names == m)) for m in MODELS}
    for v in sorted(set(names.tolist()) - set(MODELS)):   # fe_arc+coating, fe_exact+ring, ...
        if "+" in v:   # the richer model that answered these rows, counted apart
            models[v] = int(np.count_nonzero(names == v))
    return {"models": models, "n_curvature_jump": int(np.nansum(table["curvature_jump"] == 1)),
            "n_edge_contact": int(np.count_nonzero(table["status"] == "edge_contact")),
            "traction": traction.source if traction is not None else "none (method hertz)"}
