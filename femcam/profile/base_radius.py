r"""Smallest base-circle radius of a cam: the pressure-angle limit, undercutting (roller and
knife edge) and the flat-faced curvature condition, as closed forms polished by bounded Brent
searches (:func:`min_base_radius`).

References
----------
* R. L. Norton, *Design of Machinery*, ch. 8 (pressure angle eq. 8.31, undercutting,
  flat-faced follower eq. 8.24-8.27).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..errors import UndercutError
from .geometry import (
    FOLLOWER_KINDS,
    FlatFacedFollower,
    KnifeEdgeFollower,
    RollerFollower,
    pitch_curvature,
    pressure_angle,
)

#: the follower class of each kind: its protocol says what bounds Rb (a circle, a flat face)
_CLASS = {c.kind: c for c in (RollerFollower, KnifeEdgeFollower, FlatFacedFollower)}


@dataclass(frozen=True)
class BaseRadiusResult:
    """Result of :func:`min_base_radius` (SI). ``float(result)`` is ``Rb``.

    ``binding`` says which requirement set ``Rb``: ``"pressure_angle"``, ``"undercut"``
    (roller/knife: convex radius of curvature > ``rho_min``), ``"curvature"`` (flat-faced
    ``rho > rho_min``) or ``"none"``: no requirement bounds ``Rb`` away from zero (e.g. a roller
    larger than the prime radius the pressure-angle limit needs), so any ``Rb > 0`` works and
    ``Rb`` is reported as 0; ``message`` then says why and what else should set it.
    ``phi_max`` and ``rho_min`` are the values reached at ``Rb`` (in the limit ``Rb -> 0`` for
    ``"none"``); ``theta_critical`` is the angle of the binding requirement.

    Attributes
    ----------
    Rb : float
        Smallest base-circle radius [m] (0 when ``binding == "none"``).
    kind : {"roller", "knife_edge", "flat_faced"}
        Follower type.
    binding : {"pressure_angle", "undercut", "curvature", "none"}
        The requirement that sets ``Rb``.
    phi_max : float
        Largest ``|phi|`` [rad] reached at ``Rb`` (0 for a flat face).
    rho_min : float
        Smallest convex cam radius of curvature [m] reached at ``Rb`` (flat face:
        ``Rb + min(s + s'')``).
    theta_critical : float
        Cam angle [rad] of the binding requirement, in [0, 2 pi).
    n_theta : int
        Number of samples over one revolution.
    iterations : int
        Bracketing steps plus ``brentq`` iterations of the undercut search (0 if not needed).
    message : str
        What set ``Rb``, or why nothing bounds it.
    """

    Rb: float
    kind: str
    binding: str
    phi_max: float
    rho_min: float
    theta_critical: float
    n_theta: int
    iterations: int = 0
    message: str = ""

    def __float__(self) -> float:
        return self.Rb


#: relative step of the returned Rb above the exact infimum (strict inequalities hold on any grid)
RB_MARGIN = 1e-9


def _derivs(program, theta):
    d = program.derivatives(theta)
    get = (lambda k: d[k]) if isinstance(d, dict) else (lambda k: getattr(d, k))
    return (np.asarray(get("s"), float), np.asarray(get("s1"), float), np.asarray(get("s2"), float))


def _polish_min(fun, theta, vals, dtheta, n_max: int = 8):
    """Smallest value of the scalar function ``fun(theta)`` whose samples on the uniform grid
    ``theta`` are ``vals``: every grid local minimum within a small band of the grid minimum
    (at most ``n_max`` of them) is polished by a bounded Brent search over +-1 grid step.
    Returns ``(value, theta)``; never worse than the grid minimum."""
    from scipy.optimize import minimize_scalar  # lazy: scipy.optimize, ~0.15 s to import

    i0 = int(np.argmin(vals))
    best, best_t = float(vals[i0]), float(theta[i0])
    span = float(np.max(vals)) - best
    local = (vals <= np.roll(vals, 1)) & (vals <= np.roll(vals, -1)) & (vals <= best + 1e-4 * span)
    cand = np.flatnonzero(local)
    cand = cand[np.argsort(vals[cand], kind="stable")][:n_max]
    for i in dict.fromkeys([i0, *cand.tolist()]):
        res = minimize_scalar(fun, bounds=(theta[i] - dtheta, theta[i] + dtheta), method="bounded",
                              options={"xatol": 1e-12})
        if float(res.fun) < best:
            best, best_t = float(res.fun), float(res.x) % (2.0 * math.pi)
    return best, best_t


def min_base_radius(kind: str, program, *, phi_max: float = math.radians(30.0), Rr: float = 0.0,
                    e: float = 0.0, rho_min: float = 0.0, n_theta: int = 7200) -> BaseRadiusResult:
    r"""Smallest base-circle radius for which ``max |phi| <= phi_max`` and the cam is not undercut.

    ``kind`` is ``"roller"``, ``"knife_edge"`` or ``"flat_faced"``; ``program`` anything with
    ``derivatives(theta)`` giving ``s, s1, s2`` (a :class:`femcam.kinematics.CamProgram`).
    ``Rr`` (m) is required (> 0) for a roller and must be 0 for the other kinds; ``n_theta``
    (an integer >= 16) is the number of samples over one revolution.

    Roller/knife edge: :math:`|\tan\varphi| \le \tan\varphi_{max}` at every theta is
    equivalent to

    .. math:: d \ge d^* = \max_\theta \left(\frac{|s' - e|}{\tan\varphi_{max}} - s\right),
              \qquad R_b = \sqrt{d^{*2} + e^2} - R_r,

    evaluated on ``n_theta`` samples and polished with a bounded Brent search around the
    worst samples (closed form, so no bisection on phi is needed). If the cam is then undercut
    (convex pitch radius ``<= Rr + rho_min``), ``Rb`` is raised by ``brentq`` on
    ``1 - (Rr + rho_min) max kappa_p(Rb) = 0``. If the roller alone is larger than the prime
    radius the pressure-angle limit needs (``Rr >= sqrt(d*^2 + e^2)``) and no ``Rb > 0``
    undercuts, nothing bounds ``Rb`` away from 0: the result has ``Rb = 0``,
    ``binding = "none"`` and a message (any ``Rb > 0`` works; the cam's radius of curvature on
    the base circle is ``Rb`` itself, so pass ``rho_min`` to bound it).

    Flat-faced: ``phi = 0``, and ``rho = Rb + s + s'' > rho_min`` everywhere (a strict
    inequality: ``rho = 0`` is a cusp) holds for ``Rb > rho_min - min(s + s'')`` (Norton eq.
    8.27). The minimum of ``s + s''`` is polished with a bounded Brent search and the returned
    ``Rb`` is that infimum times ``1 + RB_MARGIN`` (1e-9), so :func:`cam_profile` accepts it on
    any grid.

    Parameters
    ----------
    kind : {"roller", "knife_edge", "flat_faced"}
        Follower type.
    program : CamProgram
        Anything with ``derivatives(theta)`` giving ``s`` [m], ``s1`` [m/rad], ``s2`` [m/rad^2].
    phi_max : float, optional
        Pressure-angle limit [rad], in (0, pi/2). Default 30 deg (0.5236 rad). Unused for a
        flat face.
    Rr : float, optional
        Roller radius [m]: ``> 0`` for a roller, 0 (default) otherwise.
    e : float, optional
        Follower offset [m]. Default 0.
    rho_min : float, optional
        Smallest allowed convex cam radius of curvature [m], ``>= 0``. Default 0.
    n_theta : int, optional
        Number of samples over one revolution, ``>= 16``. Default 7200.

    Returns
    -------
    BaseRadiusResult
        ``Rb`` [m] with the binding requirement, the values reached there and diagnostics.

    Raises
    ------
    InputError
        Invalid ``kind``, ``phi_max``, ``Rr``, ``e``, ``rho_min`` or ``n_theta``.
    UndercutError
        No base radius below 1 km avoids undercutting.
    """
    phi_lim, Rr, e, rho_min, n = _checked(kind, phi_max, Rr, e, rho_min, n_theta)
    _validate.record("program", program, "a femcam.kinematics.CamProgram", "derivatives")
    theta = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    dtheta = 2.0 * math.pi / n
    s, s1, s2 = _derivs(program, theta)
    if _CLASS[kind].flat_face:
        return _flat_faced(program, theta, s, s2, dtheta, rho_min, n)

    tan_lim = math.tan(phi_lim)

    def neg_need(t):
        ss, ss1, _ = _derivs(program, np.array([t]))
        return -(abs(ss1[0] - e) / tan_lim - ss[0])

    neg_d_star, theta_c = _polish_min(neg_need, theta, -(np.abs(s1 - e) / tan_lim - s), dtheta)
    d_star = -neg_d_star
    Rp_phi = math.sqrt(max(d_star, 0.0) ** 2 + e * e)  # prime radius the phi limit needs
    Rb = Rp_phi - Rr
    binding = "pressure_angle"
    if Rb <= 0.0 or d_star <= 0.0:  # phi <= phi_max for every Rb > 0
        Rb, binding = max(Rb, 0.0), "none"

    reach = Rr + rho_min

    def margin(Rb_):
        Rp = Rb_ + Rr
        if Rp <= abs(e):
            return -1.0
        return 1.0 - reach * float(np.max(pitch_curvature(s, s1, s2, Rp, e)))

    def at_prime_radius(Rp):
        """max |phi| (rad), smallest convex cam radius of curvature (m) and kappa_p at Rp."""
        kap = pitch_curvature(s, s1, s2, Rp, e)
        conv = kap > 0
        rho_c = float(np.min(1.0 / kap[conv] - Rr)) if np.any(conv) else math.inf
        return float(np.max(np.abs(pressure_angle(s, s1, Rp, e)))), rho_c, kap

    iterations = 0
    # margin(0) of a program with a base-circle point (s = s1 = s2 = 0) is 1 - Reach/Rr, i.e. 0 up
    # to round-off when rho_min = 0: that is "no constraint", not a root to polish
    m_lo = margin(Rb) if reach > 0.0 else 1.0
    if m_lo <= 0.0 and not (binding == "none" and m_lo > -1e-12):
        Rb, iterations = _raise_to_undercut_limit(margin, Rb, reach, s)
        binding = "undercut"
    deg = math.degrees(phi_lim)
    if binding == "none":
        # the limit Rb -> 0: prime radius Rr
        phi0, rho0, _ = at_prime_radius(Rr) if Rr > abs(e) else (math.pi / 2, 0.0, None)
        return _unbounded(kind, Rr, Rp_phi, deg, phi0, rho0, theta_c, n, iterations)
    phi_c, rho_c, kap = at_prime_radius(Rb + Rr)
    if binding == "undercut":
        theta_c = float(theta[int(np.argmax(kap))])
        msg = (f"undercut sets Rb: the convex cam radius of curvature must exceed rho_min = "
               f"{rho_min * 1e3:g} mm (the pressure angle alone would allow "
               f"Rb = {max(Rp_phi - Rr, 0.0) * 1e3:.6g} mm)")
    else:
        msg = f"pressure angle sets Rb: max |phi| = {deg:g} deg at theta = {math.degrees(theta_c):.3f} deg"
    return BaseRadiusResult(Rb=float(Rb), kind=kind, binding=binding,
                            phi_max=phi_c, rho_min=rho_c,
                            theta_critical=theta_c, n_theta=n, iterations=iterations, message=msg)


def _checked(kind, phi_max, Rr, e, rho_min, n_theta):
    """Checked ``(phi_max (rad), Rr (m), e (m), rho_min (m), n_theta)`` of :func:`min_base_radius`."""
    _validate.choice("kind", kind, FOLLOWER_KINDS)
    phi_lim = _validate.in_range("phi_max", phi_max, 0.0, math.pi / 2, "rad", lo_open=True, hi_open=True)
    Rr = _validate.nonnegative("Rr", Rr, "m")
    e = _validate.number("e", e, "m")
    rho_min = _validate.nonnegative("rho_min", rho_min, "m")
    if _CLASS[kind].draws_circle and Rr <= 0.0:
        raise _validate.fail("Rr", Rr, "m", "must be > 0 for a roller follower")
    if not _CLASS[kind].draws_circle and Rr != 0.0:
        raise _validate.fail("Rr", Rr, "m", f"only a roller follower has a roller radius; a {kind} "
                             "follower needs Rr = 0 (the default)")
    return phi_lim, Rr, e, rho_min, _validate.integer("n_theta", n_theta, 16)


def _flat_faced(program, theta, s, s2, dtheta, rho_min, n) -> BaseRadiusResult:
    """Flat-faced follower: ``Rb > rho_min - min(s + s'')`` (Norton eq. 8.27)."""
    kind = "flat_faced"

    def g_at(t):
        ss, _, ss2 = _derivs(program, np.array([t]))
        return float(ss[0] + ss2[0])

    g_min, theta_c = _polish_min(g_at, theta, s + s2, dtheta)
    Rb_inf = rho_min - g_min
    if Rb_inf <= 1e-12 * float(np.max(np.abs(s + s2))):  # <= 0 up to round-off
        return BaseRadiusResult(
            Rb=0.0, kind=kind, binding="none", phi_max=0.0, rho_min=g_min, theta_critical=theta_c,
            n_theta=n, message=f"min(s + s'') = {g_min * 1e3:.6g} mm >= rho_min = "
            f"{rho_min * 1e3:g} mm: rho = Rb + s + s'' > rho_min for every Rb > 0; the base "
            "radius is set by other requirements (shaft, face width, contact stress)")
    Rb = Rb_inf * (1.0 + RB_MARGIN)
    return BaseRadiusResult(
        Rb=Rb, kind=kind, binding="curvature", phi_max=0.0, rho_min=Rb + g_min,
        theta_critical=theta_c, n_theta=n,
        message=f"rho = Rb + s + s'' > rho_min = {rho_min * 1e3:g} mm sets Rb "
        f"(min(s + s'') = {g_min * 1e3:.6g} mm at theta = {math.degrees(theta_c):.3f} deg; Rb is "
        f"the infimum {Rb_inf * 1e3:.9g} mm times 1 + {RB_MARGIN:g})")


def _raise_to_undercut_limit(margin, Rb, reach, s):
    """``(Rb, iterations)``: the root of ``margin`` above ``Rb`` (bracketed by doubling, then
    ``brentq``), stepped by ``RB_MARGIN`` onto the safe side."""
    from scipy.optimize import brentq  # lazy: scipy.optimize, ~0.15 s to import

    iterations = 0
    hi = max(2.0 * Rb, reach, float(np.max(np.abs(s))) + 1e-6)
    while margin(hi) <= 0.0:
        hi *= 2.0
        iterations += 1
        if hi > 1e3:  # pragma: no cover - pathological program
            raise UndercutError("no base radius below 1 km avoids undercutting")
    Rb, r = brentq(margin, Rb, hi, xtol=1e-12, rtol=1e-12, full_output=True)
    Rb *= 1.0 + RB_MARGIN  # step just onto the safe side of the root
    return Rb, iterations + r.iterations


def _unbounded(kind, Rr, Rp_phi, deg, phi0, rho0, theta_c, n, iterations) -> BaseRadiusResult:
    """``binding = "none"``: nothing bounds ``Rb`` away from 0 (the values in the limit Rb -> 0)."""
    if _CLASS[kind].draws_circle:
        why = (f"the roller radius Rr = {Rr * 1e3:g} mm alone is at least the prime radius "
               f"{Rp_phi * 1e3:.6g} mm that phi <= {deg:g} deg needs, and no Rb > 0 undercuts "
               "the cam")
    else:
        why = f"phi <= {deg:g} deg for every Rb > 0"
    return BaseRadiusResult(
        Rb=0.0, kind=kind, binding="none", phi_max=phi0, rho_min=rho0, theta_critical=theta_c,
        n_theta=n, iterations=iterations,
        message=f"no lower bound on Rb: {why}. Any Rb > 0 works; choose it for the shaft/hub "
        "and the contact stress (the cam's radius of curvature on the base circle equals Rb; "
        "pass rho_min to require a minimum)")
