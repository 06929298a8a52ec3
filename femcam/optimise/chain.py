r"""The analytic chain of a design at sample angles: objective and constraint margins per angle.

Every quantity is a smooth function of the design at a fixed *normalised* angle ``u`` of each
segment (the grid moves with ``rise_angle``), so its finite differences are smooth too. A
maximum over angles is handled as one constraint per sample angle (the epigraph form, see
:mod:`femcam.optimise.solve`); margins are dimensionless and >= 0 when the limit holds.

Symbols
-------
=========  ===============================================  =====  ================================
symbol     meaning                                          unit   source
=========  ===============================================  =====  ================================
phi        pressure angle                                   rad    Norton, *Design of Machinery*
                                                                   eq. 8.31
kappa_p    pitch-curve curvature (> 0 convex)               1/m    Norton ch. 8
rho        cam radius of curvature at the contact           m      ``1/kappa_p - Rr``
Fc         contact force at the operating speed             N      seed 002 eq. 11
p0         Hertz peak pressure                              Pa     Johnson (1985) eq. 4.45
k_vm       von Mises / p0 (and tau1 / p0), with friction    -      Johnson (1985) §7.1, McEwen 1949
g_phi      ``1 - (phi/phi_max)^2``                          -      this module
g_rho      ``1 - kappa_p (Rr + rho_min)``                   -      roller fits / no undercut
g_lift     ``(m a + c v + k s + Fpl)/Fpl`` at ``omega_L``   -      seed 002 eq. 11 numerator
=========  ===============================================  =====  ================================

``g_rho >= 0`` is the undercut condition in a form that stays smooth through a flat pitch curve:
a convex pitch radius ``1/kappa_p`` must exceed ``Rr + rho_min`` (cam radius ``rho >= rho_min``);
a concave pitch curve (``kappa_p < 0``) always fits the roller (``|rho| = |1/kappa_p| + Rr``).
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from ..assess import assess
from ..dynamics import periodic_response
from ..errors import InputError, PhysicsError
from ..hertz import LineContact
from ..hertz.conformity import shape_factors
from ..hertz.contact import HertzValidityWarning
from ..layers.from_scene import scene_coatings
from ..profile import cam_profile, pitch_curvature
from ..scene.case import contact_case
from ..wear.map import wear_depth_per_angle
from ..wear.options import slip_kwargs, wear_coefficient_info
from ..wear.slip import follower_slip

__all__ = ["OBJECTIVES", "OBJECTIVE_UNITS", "CONSTRAINT_UNITS", "angle_grid", "evaluate"]

#: per-angle objectives (the maximum over the revolution is minimised) and their SI units;
#: ``"wear"``: the Archard cam wear depth per revolution at the contact (femcam.wear)
OBJECTIVE_UNITS = {"p0": "Pa", "von_mises": "Pa", "tau1": "Pa", "acceleration": "m/s^2", "size": "m",
                   "wear": "m", "utilisation": "-", "lambda": "-", "residual_vibration": "m"}
#: objectives that are one number per design, not one per angle (no exchange over angles)
SCALAR_OBJECTIVES = ("residual_vibration",)
OBJECTIVES = tuple(OBJECTIVE_UNITS)
#: constraint names and the unit of their limit
CONSTRAINT_UNITS = {"phi_max": "rad", "rho_min": "m", "liftoff_omega": "rad/s", "safety_min": "-",
                    "lambda_min": "-"}
#: the assessment's safety-factor columns (femcam.assess): every one is a row of the margins
SF_COLUMNS = ("sf_yield", "sf_shakedown", "sf_subsurface", "sf_surface_fatigue", "sf_scuffing")
_SF_NONE = 1e6  # a criterion the scene cannot assess, or an angle without contact: no limit

_RHO_FLOOR = 1e-7  # m: an undercut trial design gets a tiny convex radius (huge p0), not an error


def angle_grid(program, n_motion: int, extra_u=()) -> tuple[np.ndarray, np.ndarray]:
    """Sample angles: ``n_motion`` uniform ``u`` per rise/fall (plus ``extra_u``), one per dwell.

    Parameters
    ----------
    program : femcam.kinematics.CamProgram
        The cam program of the design.
    n_motion : int
        Samples per rise/fall segment, ends included.
    extra_u : sequence of (int, float)
        Extra ``(segment index, u)`` samples (the exchange points of the refinement).

    Returns
    -------
    theta : ndarray, shape (m,)
        Cam angles (rad).
    seg_u : ndarray, shape (m, 2)
        ``(segment index, u)`` of each angle.
    """
    rows = []
    for k, sg in enumerate(program.segments):
        us = np.linspace(0.0, 1.0, n_motion) if sg.law is not None else np.array([0.5])
        rows.extend((k, float(u)) for u in us)
    rows.extend((int(k), float(u)) for k, u in extra_u)
    seg_u = np.array(rows, float)
    starts = program.theta_starts
    beta = np.array([sg.beta for sg in program.segments])
    k = seg_u[:, 0].astype(int)
    # u = 1 of segment k is u = 0 of segment k+1; keep it inside segment k by a round-off step back
    theta = starts[k] + np.minimum(seg_u[:, 1], 1.0 - 1e-12) * beta[k]
    return theta, seg_u


def evaluate(scene, theta, objective: str, *, phi_max: float | None, rho_min: float | None,
             liftoff_omega: float | None, safety_min: float | None = None,
             lambda_min: float | None = None) -> dict:
    """Objective and constraint margins of a scene variant at ``theta``.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The variant (roller or knife-edge follower).
    theta : ndarray, shape (m,)
        Cam angles (rad).
    objective : str
        One of :data:`OBJECTIVES`.
    phi_max : float or None
        Pressure-angle limit (rad); None: not constrained.
    rho_min : float or None
        Smallest convex cam radius (m, >= 0; 0 = no undercut); None: not constrained.
    liftoff_omega : float or None
        Speed (rad/s) up to which the follower must not lift off; None: not constrained.
    safety_min, lambda_min : float or None
        Smallest safety factor of every assessment criterion (:data:`SF_COLUMNS`) and smallest
        film ratio lambda (femcam.assess; the scene needs its data); None: not constrained.

    Returns
    -------
    dict
        ``"objective"``: ndarray (m,) in the unit of :data:`OBJECTIVE_UNITS`; one margin array
        (m,) per given constraint (``safety_min`` and the ``"utilisation"`` objective, 1/sf:
        shape (5, m), one row per criterion), dimensionless, >= 0 where it holds; ``"phi"`` (rad),
        ``"rho"`` (m), ``"p0"`` (Pa), ``"Fc"`` (N), ``"a"`` (m/s^2) for reports.

    Examples
    --------
    >>> from femcam.scene import load_scene
    >>> sc = load_scene("examples/seed002_study_model.toml")
    >>> r = evaluate(sc, np.array([0.5]), "p0", phi_max=0.5, rho_min=None, liftoff_omega=None)
    >>> sorted(r)[:3]
    ['Fc', 'a', 'objective']
    """
    f, w, dyn = scene.follower, scene.omega, scene.dynamics
    d = scene.program.derivatives(theta)
    Rr = float(f.Rr)
    p = cam_profile(f, d.theta, d.s, d.s1, d.s2, allow_undercut=True)
    kappa = pitch_curvature(d.s, d.s1, d.s2, f.Rp, f.e)
    a = w * w * d.s2
    Fc = (dyn.m * a + dyn.c * w * d.s1 + dyn.k * d.s + dyn.Fpl) / np.cos(p.phi)
    out = {"phi": p.phi, "rho": p.rho, "Fc": Fc, "a": a}
    if objective in ("p0", "von_mises", "tau1", "wear"):
        if not f.translating_roller:
            raise InputError(f"objective = {objective!r}: needs a roller follower (Hertz contact); "
                             f"this scene's follower is a {f.kind} follower")
        rho = np.where(kappa * (Rr + _RHO_FLOOR) >= 1.0, _RHO_FLOOR, p.rho)
        with warnings.catch_warnings():  # a trial design may strain Hertz; the optimum is reported
            warnings.simplefilter("ignore", HertzValidityWarning)
            hc = LineContact(F=np.clip(Fc, 0.0, None), length=scene.length, R1=rho, R2=Rr, cam=scene.cam,
                             roller=scene.roller, plane=scene.plane)
            p0 = np.asarray(hc.p0, float)
        out["p0"] = p0
        if objective == "wear":
            out["objective"] = _wear(scene, d, np.clip(Fc, 0.0, None), np.asarray(hc.a, float), p0)
        else:
            factors = shape_factors(scene.mu, scene.cam.nu, scene.plane)
            out["objective"] = (1.0 if objective == "p0" else factors[objective][0]) * p0
    elif objective == "acceleration":
        out["objective"] = np.abs(a)
    elif objective == "size":
        out["objective"] = np.hypot(p.x, p.y)
    elif objective == "residual_vibration":
        out["objective"], out["theta_worst"] = residual_vibration(scene)
    if objective in ("utilisation", "lambda") or safety_min is not None or lambda_min is not None:
        out.update(_assessment(scene, d.theta, objective, safety_min, lambda_min))
    if phi_max is not None:
        out["phi_max"] = 1.0 - (p.phi / phi_max) ** 2
    if rho_min is not None:
        out["rho_min"] = 1.0 - kappa * (Rr + rho_min)
    if liftoff_omega is not None:
        wl = liftoff_omega
        out["liftoff_omega"] = (dyn.m * wl * wl * d.s2 + dyn.c * wl * d.s1 + dyn.k * d.s + dyn.Fpl) / dyn.Fpl
    return out


def _wear(scene, d, Fc, a, p0) -> np.ndarray:
    """Archard cam wear depth per revolution at each angle's contact (m): femcam.wear's closed
    form ``k w v_slip / V_cam`` with the scene's k and slip model (pointwise models only: the
    inertia-limited roller integrates over the revolution, which a design grid is not)."""
    kw = slip_kwargs(scene.wear, omega=scene.omega, mu=scene.mu, follower=scene.follower)
    if kw["roller_model"] != "srr":
        raise InputError(f"[wear] roller_model = {kw['roller_model']!r}: the wear objective needs the "
                         "pointwise slide-to-roll model ('srr')")
    f = scene.follower
    # an undercut trial design (cam rho <= 0 somewhere) has no slip kinematics: continue it with
    # the s'' that gives rho = _RHO_FLOOR there (the pitch curvature is linear in s'')
    r = math.sqrt(f.Rp**2 - f.e**2) + d.s
    q = d.s1 - f.e
    s2_floor = (r * r + q * (2.0 * d.s1 - f.e) - (r * r + q * q) ** 1.5 / (f.Rr + _RHO_FLOOR)) / r
    slip = follower_slip(f, d.theta, d.s, d.s1, np.maximum(d.s2, s2_floor), Fc=Fc, **kw)
    k, _where = wear_coefficient_info(scene.wear, scene.cam.hardness)
    return wear_depth_per_angle(d.theta, a, p0, Fc, slip, k)


def check_objective(scene, objective: str) -> None:
    """Refuse an objective the scene has no data for (before any work).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The base scene.
    objective : str
        One of :data:`OBJECTIVES`.

    Raises
    ------
    InputError
        ``"lambda"`` without ``[lubricant]`` data; ``"residual_vibration"`` with a rigid train.
    """
    if objective == "lambda" and scene.tribology.lubricant is None:
        raise InputError("objective = 'lambda': the film parameter needs the scene's lubricant data "
                         "([lubricant], [surface] roughness and oil_temperature_C, femcam.assess); "
                         "this scene has no [lubricant] table")
    if objective == "residual_vibration" and scene.train is None:
        raise InputError("objective = 'residual_vibration': needs an elastic follower train "
                         "([dynamics] model = 'one_dof' or 'two_dof' with train_stiffness_N_per_m); "
                         "this scene's [dynamics] model is 'rigid' (no vibration to minimise)")


def residual_vibration(scene) -> tuple[np.ndarray, float]:
    r"""Residual vibration of the follower in the dwell after each rise (m) and where it peaks.

    .. math:: r = \max_{\theta \in \text{dwell after a rise}} |e(\theta) - e_{st}|,
       \quad e = x - s,\quad e_{st} = -K^{-1} g\,(k\,s_{dwell} + F_{pl})

    ``e`` is the last mass's error of the periodic steady state (femcam.dynamics) at the scene's
    speed and its own step count; ``e_st`` is the static compression of the train under the
    spring and preload at the dwell lift (the level ``e`` decays to). Subtracting it keeps the
    measure a vibration amplitude: the static compression (``(F_pl + k h)/k_t`` ~ 0.75 mm for
    seed002_dynamic) is the same for every law of the same lift and would swamp the ~1 um ringing.

    Parameters
    ----------
    scene : femcam.scene.Scene
        A scene with an elastic train (``scene.train``).

    Returns
    -------
    value : ndarray, shape (1,)
        The residual vibration (m).
    theta_worst : float
        Cam angle of its maximum (rad).

    Examples
    --------
    >>> from femcam.scene import load_scene
    >>> r, th = residual_vibration(load_scene("examples/seed002_dynamic.toml"))
    >>> 1e-7 < float(r[0]) < 1e-5
    True
    """
    tr, prog = scene.train, scene.program
    d = periodic_response(tr, prog, scene.omega, steps_per_rev=scene.steps_per_rev)
    _M, _C, K, g = tr.mck(True)
    f = tr.follower
    starts, best, where = prog.theta_starts, 0.0, 0.0
    segs = prog.segments
    for k, sg in enumerate(segs):
        nxt = segs[(k + 1) % len(segs)]
        if sg.kind != "rise" or nxt.law is not None:
            continue
        t0 = starts[(k + 1) % len(segs)]
        sel = (d.theta >= t0) & (d.theta <= t0 + nxt.beta)
        s_dw = float(np.mean(d.s[sel]))
        e_st = -np.linalg.solve(K, g)[-1] * (f.k * s_dw + f.Fpl)
        dev = np.abs(d.e[sel, -1] - e_st)
        i = int(np.argmax(dev))
        if dev[i] > best:
            best, where = float(dev[i]), float(d.theta[sel][i])
    return np.array([best]), where


def _assessment(scene, theta, objective, safety_min, lambda_min) -> dict:
    """Safety factors ``"sf"`` (5, m) and film ratio ``"lam"`` (m,) of femcam.assess at
    ``theta``, the ``utilisation`` objective 1/sf and the margins; an undercut trial design (the
    assessment refuses it) gets sf = lambda = 0: every margin -1."""
    try:
        rows = assess(contact_case(scene, theta), coatings=scene_coatings(scene.layers)).rows
        sf = np.array([np.asarray(rows[c], float) if c in rows else np.full(theta.size, np.nan)
                       for c in SF_COLUMNS])
        lam = np.asarray(rows.get("lam", np.full(theta.size, np.nan)), float)
        sf, lam = np.where(np.isfinite(sf), sf, _SF_NONE), np.where(np.isfinite(lam), lam, _SF_NONE)
    except PhysicsError:
        sf, lam = np.zeros((len(SF_COLUMNS), theta.size)), np.zeros(theta.size)
    out = {"sf": sf, "lam": lam}
    if objective == "utilisation":
        out["objective"] = 1.0 / np.maximum(sf, 1e-3)
    elif objective == "lambda":  # minimise 1/lambda: maximises the smallest film ratio
        out["objective"] = 1.0 / np.maximum(lam, 1e-6)
    if safety_min is not None:
        out["safety_min"] = sf / safety_min - 1.0
    if lambda_min is not None:
        out["lambda_min"] = lam / lambda_min - 1.0
    return out


def constraint_value(name: str, r: dict, limit: float) -> float:
    """The physical worst value of a constraint from :func:`evaluate`'s output (SI).

    Parameters
    ----------
    name : str
        A name of :data:`CONSTRAINT_UNITS`.
    r : dict
        Output of :func:`evaluate`.
    limit : float
        The constraint's limit (SI).

    Returns
    -------
    float
        Largest ``|phi|`` (rad), smallest convex cam radius (m; inf if none), or the smallest
        contact force ratio ``Fc/Fpl`` at the lift-off speed (-), smallest safety factor or
        film ratio lambda (-).
    """
    if name == "phi_max":
        return float(np.max(np.abs(r["phi"])))
    if name == "rho_min":
        rho = r["rho"][np.isfinite(r["rho"]) & (r["rho"] > 0)]
        return float(rho.min()) if rho.size else math.inf
    if name == "safety_min":
        return float(np.min(r["sf"]))
    if name == "lambda_min":
        return float(np.min(r["lam"]))
    return float(np.min(r["liftoff_omega"]))
