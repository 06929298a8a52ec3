r"""Sliding speed at the cam-follower contact, per follower type.

Every function takes the follower lift and its cam-angle derivatives (``s, s1 = ds/dtheta,
s2 = d^2 s/dtheta^2`` in m, m/rad, m/rad^2) at constant cam speed ``omega`` and returns a
:class:`SlipResult` with three speeds per angle:

* ``v_slip``: magnitude of the relative velocity of the two material points in contact (m/s),
  the speed that enters Archard's law;
* ``V_cam``: speed at which the contact point travels over the cam surface (m/s);
* ``V_follower``: speed at which it travels over the follower surface (m/s).

Conventions: the cam turns counter-clockwise at ``omega > 0``; a translating follower moves
along the line ``x = e`` (offset ``e``); the base circle has radius ``Rb``. Turning the cam the
other way is the same as passing ``-e``. Contact is maintained (normal velocities equal), so the
relative velocity is tangential.

Derivations (cam-fixed origin, ``d = sqrt(Rb^2 - e^2)``):

* **Knife-edge** (tip at ``(e, d + s)``). The cam material under the tip moves at
  ``omega x r = omega(-(d+s), e)``, the tip at ``(0, omega s1)``. Relative speed
  :math:`v_{slip} = \omega\sqrt{(d+s)^2 + (s_1-e)^2}`; this is also ``omega |dP/dtheta|`` of the
  cam profile (the tip path in the cam frame): every point of the profile slides under the tip,
  ``V_cam = v_slip``, ``V_follower = 0`` (the tip is one point).
* **Knife-edge with a tip radius** ``r`` (:func:`radiused_tip`): a sharp tip has no contact
  width, so a wear depth needs a tip radius. The tip is a roller of radius ``r`` that does not
  turn (``Omega = 0``): the cam is the one cut for it (same base circle and lift law; its
  pitch curve has base radius ``Rb + r``), ``v_slip = r |Omega_req| = |V_p - omega r|``, and
  the contact runs over the tip at ``r dphi/dt = V_cam + r Omega_req`` as the pressure angle
  swings. ``r -> 0`` gives the sharp knife-edge.
* **Flat-faced** (face ``y = Rb + s`` normal to the axis). The contact lies at distance ``s1``
  from the axis (the classic ``x = ds/dtheta`` result), cam material there moves at
  ``omega(-(Rb+s), s1)``, the face at ``(0, omega s1)``: relative velocity ``(omega(Rb+s), 0)``, so
  :math:`v_{slip} = \omega (R_b + s)` whatever the offset. Check: the contact moves over the
  cam at ``V_cam = omega rho`` (``rho = Rb + s + s2``, radius of curvature of the cam) and over
  the face at ``V_follower = omega s2``; ``V_cam - V_follower = omega(Rb + s)``.
* **Roller** (radius ``Rr``). In the cam frame the roller centre runs along the pitch curve at
  ``V_p = omega sqrt((d_p+s)^2 + (s1-e)^2)``, ``d_p = sqrt((Rb+Rr)^2 - e^2)``; rolling without
  slip makes the contact point the instantaneous centre, so the roller turns (absolute rate)
  :math:`\Omega_{req} = \omega - V_p/R_r` and the contact travels over cam and roller at
  ``V_cam = V_p rho/(rho + Rr)`` (parallel curves). On the base circle ``Omega_req =
  -omega Rb/Rr``. A roller turning at ``Omega`` slides at ``v_slip = Rr |Omega - Omega_req|``.
  Two slip models:

  - :func:`roller_srr`: a prescribed slide-to-roll ratio ``SRR = (u1 - u2)/U``,
    ``U = (u1 + u2)/2`` (Johnson's definition with the factor 2), ``u1 = V_cam``:
    ``v_slip = |SRR| U = 2 |SRR| V_cam/(2 + SRR)``.
  - :func:`roller_inertia`: the roller of polar inertia ``J`` can be accelerated only by the
    friction torque ``mu Fc Rr`` (minus a bearing drag ``T_drag``); where the required angular
    acceleration ``omega dOmega_req/dtheta`` exceeds ``(mu Fc Rr - T_drag)/J`` the roller lags
    and slides. Integrated as a rate-limited tracking of ``Omega_req`` over revolutions until
    periodic.

References: Norton, *Cam Design and Manufacturing Handbook* (2009), ch. 7 (pressure angle,
radius of curvature, flat-faced contact at ``x = ds/dtheta``); Johnson, *Contact Mechanics*
(1985) §8.1 (rolling, slide-to-roll ratio).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from .. import _validate
from .._repr import compact_repr
from ..errors import ConvergenceError, UndercutError
from ..profile import OscillatingPadFollower, OscillatingRollerFollower, arm_geometry, pressure_angle


@dataclass(frozen=True)
class SlipResult:
    """Sliding and transport speeds at the contact, per cam angle (all in m/s, rad/s).

    ``Omega``/``Omega_req``/``slipping`` are set for the roller inertia model (None otherwise);
    ``iterations`` counts revolutions integrated, ``converged`` whether Omega became periodic.

    Parameters
    ----------
    theta : ndarray, shape (n,)
        Cam angles [rad].
    v_slip : ndarray, shape (n,)
        Sliding speed, magnitude of the relative velocity at the contact [m/s].
    V_cam : ndarray, shape (n,)
        Speed of the contact point over the cam surface [m/s].
    V_follower : ndarray, shape (n,)
        Speed of the contact point over the follower surface (signed) [m/s].
    omega : float
        Cam speed [rad/s].
    model : str
        Description of the slip model.
    Omega : ndarray, shape (n,), or None
        Roller (or tip) angular speed [rad/s].
    Omega_req : ndarray, shape (n,), or None
        Roller angular speed for rolling without slip [rad/s].
    slipping : ndarray of bool, shape (n,), or None
        Where the inertia-limited roller slides.
    iterations : int
        Revolutions integrated (inertia model).
    converged : bool
        Whether ``Omega`` became periodic.
    message : str
        Convergence summary.
    follower_period : float or None
        Perimeter of the roller surface ``2 pi Rr`` [m]; None for an open coordinate.
    follower_origin : float
        Position of the contact on the follower surface at ``theta[0]`` [m].
    """

    theta: np.ndarray
    v_slip: np.ndarray
    V_cam: np.ndarray
    V_follower: np.ndarray
    omega: float
    model: str
    Omega: np.ndarray | None = None
    Omega_req: np.ndarray | None = None
    slipping: np.ndarray | None = None
    iterations: int = 0
    converged: bool = True
    message: str = ""
    #: perimeter of the follower surface for a roller (2 pi Rr, m); None: open coordinate
    follower_period: float | None = None
    #: position of the contact on the follower surface at ``theta[0]`` (m): flat face, distance
    #: from the follower axis (``s1 - e``); radiused knife-edge tip, arc ``r_tip phi`` from the
    #: tip's axis point; roller 0 (the roller coordinate starts at the point in contact at theta[0])
    follower_origin: float = 0.0

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)

    @property
    def slip_per_rolled_length(self) -> np.ndarray:
        """``v_slip / V_cam``: metres slid per metre the contact advances over the cam."""
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(self.V_cam > 0, self.v_slip / np.where(self.V_cam > 0, self.V_cam, 1.0),
                            0.0)


def _common(theta, s, s1, omega):
    theta = _validate.finite_array("theta", theta, "rad")
    s = _validate.finite_array("s", s, "m")
    s1 = _validate.finite_array("s1", s1, "m/rad")
    omega = _validate.positive("omega", omega, "rad/s")
    theta, s, s1 = np.broadcast_arrays(theta, s, s1)
    return theta.astype(float), s.astype(float), s1.astype(float), omega


def _offset_distance(R, e, name):
    e = _validate.number("e", e, "m")
    if abs(e) >= R:
        raise _validate.fail("e", e, "m", f"must satisfy |e| < {name} = {R:g} m")
    return e, float(np.sqrt(R * R - e * e))


def knife_edge(theta, s, s1, *, Rb, omega, e=0.0) -> SlipResult:
    r"""Knife-edge follower: full sliding, :math:`v_{slip} = \omega\sqrt{(d+s)^2 + (s_1-e)^2}`.

    Parameters
    ----------
    theta : array_like, shape (n,)
        Cam angles [rad].
    s : array_like, shape (n,)
        Follower lift [m].
    s1 : array_like, shape (n,)
        ``ds/dtheta`` [m/rad].
    Rb : float
        Base-circle radius [m].
    omega : float
        Cam speed, ``> 0`` [rad/s].
    e : float
        Follower offset, ``|e| <`` the (pitch) base radius [m].

    Returns
    -------
    SlipResult
        Speeds per angle, shape (n,) [m/s].

    Examples
    --------
    >>> r = knife_edge([0.0], [0.0], [0.0], Rb=0.02, omega=10.0)   # base circle: omega Rb
    >>> float(r.v_slip[0])
    0.2
    """
    theta, s, s1, omega = _common(theta, s, s1, omega)
    Rb = _validate.positive("Rb", Rb, "m")
    e, d = _offset_distance(Rb, e, "Rb")
    v = omega * np.hypot(d + s, s1 - e)
    return SlipResult(theta=theta, v_slip=v, V_cam=v.copy(), V_follower=np.zeros_like(v),
                      omega=omega, model="knife-edge: full sliding")


def flat_faced(theta, s, s1, s2, *, Rb, omega) -> SlipResult:
    r"""Flat-faced translating follower: :math:`v_{slip} = \omega (R_b + s)`.

    ``V_cam = omega (Rb + s + s2)`` (must stay > 0, else the cam is cusped),
    ``V_follower = omega s2`` (signed: the contact runs back and forth along the face).

    Parameters
    ----------
    theta : array_like, shape (n,)
        Cam angles [rad].
    s : array_like, shape (n,)
        Follower lift [m].
    s1 : array_like, shape (n,)
        ``ds/dtheta`` [m/rad].
    s2 : array_like, shape (n,)
        ``d^2s/dtheta^2`` [m/rad^2].
    Rb : float
        Base-circle radius [m].
    omega : float
        Cam speed, ``> 0`` [rad/s].

    Returns
    -------
    SlipResult
        Speeds per angle, shape (n,) [m/s].

    Raises
    ------
    UndercutError
        ``Rb + s + s2 <= 0`` (cusped cam).

    Examples
    --------
    >>> round(float(flat_faced([0.0], [0.001], [0.0], [0.0], Rb=0.02, omega=10.0).v_slip[0]), 12)
    0.21
    """
    theta, s, s1, omega = _common(theta, s, s1, omega)
    s2 = np.broadcast_to(_validate.finite_array("s2", s2, "m/rad^2"), s.shape).astype(float)
    Rb = _validate.positive("Rb", Rb, "m")
    rho = Rb + s + s2
    if np.any(rho <= 0):
        i = int(np.argmin(rho))
        raise UndercutError(f"flat-faced follower: cam radius of curvature Rb + s + s'' = {rho[i]:g} m "
                            f"<= 0 at theta = {theta[i]:g} rad (cusp); increase Rb")
    return SlipResult(theta=theta, v_slip=omega * (Rb + s), V_cam=omega * rho, V_follower=omega * s2,
                      omega=omega, model="flat-faced: full sliding", follower_origin=float(s1.flat[0]))


def pitch_speed(s, s1, s2, *, Rb, Rr, e=0.0):
    r"""Pitch-curve arc rate ``dsp/dtheta`` (m/rad) and its radius of curvature ``rho_p`` (m).

    For ``P(theta) = R(-theta)(e, d_p + s)``:

    .. math:: \frac{ds_p}{d\theta} = \sqrt{(d_p+s)^2 + (s_1-e)^2},\qquad
              \rho_p = \frac{[(d_p+s)^2 + (s_1-e)^2]^{3/2}}{(d_p+s)^2 + (s_1-e)(2s_1-e) - (d_p+s)s_2}

    (curvature of a plane parametric curve, Norton 2009 eq. 7.14 with offset). The cam
    surface's radius of curvature is ``rho = rho_p - Rr``.

    Parameters
    ----------
    s : array_like, shape (n,)
        Follower lift [m].
    s1 : array_like, shape (n,)
        ``ds/dtheta`` [m/rad].
    s2 : array_like, shape (n,)
        ``d^2s/dtheta^2`` [m/rad^2].
    Rb : float
        Base-circle radius [m].
    Rr : float
        Roller radius [m].
    e : float
        Follower offset, ``|e| < Rb + Rr`` [m].

    Returns
    -------
    dsp_dtheta : ndarray, shape (n,)
        Pitch-curve arc rate [m/rad].
    rho_p : ndarray, shape (n,)
        Pitch-curve radius of curvature (``inf`` where straight) [m].
    """
    R = _validate.positive("Rb", Rb, "m") + _validate.positive("Rr", Rr, "m")
    e, dp = _offset_distance(R, e, "Rb + Rr")
    y = dp + np.asarray(s, dtype=float)
    q = np.asarray(s1, dtype=float) - e
    num = (y * y + q * q) ** 1.5
    den = y * y + q * (2.0 * np.asarray(s1, dtype=float) - e) - y * np.asarray(s2, dtype=float)
    with np.errstate(divide="ignore"):
        rho_p = np.where(den != 0, num / np.where(den != 0, den, 1.0), np.inf)
    return np.sqrt(y * y + q * q), rho_p


def _roller_kinematics(theta, s, s1, s2, Rb, Rr, e, omega):
    theta, s, s1, omega = _common(theta, s, s1, omega)
    s2 = np.broadcast_to(_validate.finite_array("s2", s2, "m/rad^2"), s.shape).astype(float)
    Rr = _validate.positive("Rr", Rr, "m")
    sp, rho_p = pitch_speed(s, s1, s2, Rb=Rb, Rr=Rr, e=e)
    rho = rho_p - Rr
    if np.any((rho <= 0) & (rho_p > 0)):
        i = int(np.argmin(np.where(rho_p > 0, rho, np.inf)))
        raise UndercutError(f"roller follower: cam radius of curvature {rho[i]:g} m <= 0 at theta = "
                            f"{theta[i]:g} rad (roller larger than the pitch-curve curvature)")
    V_p = omega * sp
    V_cam = V_p * np.where(np.isfinite(rho_p), rho / rho_p, 1.0)
    Omega_req = omega - V_p / Rr
    return theta, s, omega, Rr, V_p, V_cam, Omega_req


def _srr_result(theta, V_cam, omega, srr, Rr, Omega_req, kind) -> SlipResult:
    """Roller surface speeds for a prescribed slide-to-roll ratio: ``U = 2 V_cam / (2 + srr)``,
    ``v_slip = |srr| U``, ``V_follower = V_cam (2 - srr) / (2 + srr)`` (one copy for the
    translating and the oscillating roller)."""
    U = 2.0 * V_cam / (2.0 + srr)
    return SlipResult(theta=theta, v_slip=abs(srr) * U, V_cam=V_cam, V_follower=V_cam * (2 - srr) / (2 + srr),
                      omega=omega, model=f"{kind}: slide-to-roll ratio {srr:g}", Omega_req=Omega_req,
                      follower_period=2 * np.pi * Rr)


def oscillating_roller_srr(theta, psi, psi1, psi2, *, follower, omega, srr=0.0) -> SlipResult:
    r"""Roller on an oscillating arm with a prescribed slide-to-roll ratio (``srr = 0``: rolling).

    .. math:: V_{cam} = \omega\,|T|\,(1 - R_r \kappa), \quad U = \frac{2 V_{cam}}{2 + SRR}, \quad
              v_{slip} = |SRR|\,U

    ``|T|`` and ``kappa`` from :func:`femcam.profile.arm_geometry`: the contact point moves over
    the cam surface at ``V_cam`` (the envelope's arc-length rate, docs/oscillating.md); the roller
    surface speeds follow as in :func:`roller_srr`. ``Omega_req = V_cam / Rr`` is the roller's
    rolling speed relative to the arm.

    Parameters
    ----------
    theta : array_like, shape (n,)
        Cam angles [rad].
    psi, psi1, psi2 : array_like, shape (n,)
        Arm angle [rad] and its theta-derivatives.
    follower : OscillatingRollerFollower
        The follower.
    omega : float
        Cam speed, ``> 0`` [rad/s].
    srr : float, optional
        Slide-to-roll ratio, ``-2 < srr < 2`` [-]. Default 0.

    Returns
    -------
    SlipResult
        Speeds per angle, shape (n,) [m/s].

    Raises
    ------
    UndercutError
        Cam radius of curvature ``<= 0`` (``Rr kappa >= 1``) somewhere.
    """
    srr = _validate.in_range("srr", srr, -2.0, 2.0, "", lo_open=True, hi_open=True)
    f = _validate.instance("follower", follower, OscillatingRollerFollower)
    omega = _validate.positive("omega", omega, "rad/s")
    theta = np.ravel(_validate.finite_array("theta", theta, "rad"))
    g = arm_geometry(f, np.ravel(psi), np.ravel(psi1), np.ravel(psi2))
    fac = 1.0 - f.Rr * g.kappa
    if np.any(fac <= 0.0):
        raise UndercutError("oscillating roller: cam radius of curvature <= 0 (undercut) at theta = "
                            f"{np.degrees(theta[fac <= 0.0][0]):.2f} deg")
    V_cam = omega * g.pitch_speed * fac
    return _srr_result(theta, V_cam, omega, srr, f.Rr, V_cam / f.Rr, "oscillating roller")


def oscillating_pad(theta, s, s1, s2, *, follower, omega) -> SlipResult:
    r"""Curved pad on an oscillating arm: full sliding (:mod:`femcam.profile.pad`).

    .. math:: v_{slip} = |u_{cam} - u_{pad}| = \omega\left|\,|T| - R_r(1 + \sigma\psi')\right|

    ``V_cam = u_cam``, ``V_follower = u_pad`` (the pad surface's speed relative to the contact,
    signed), an open pad coordinate starting at the contact's arc position on the pad at
    ``theta[0]`` (:meth:`femcam.profile.OscillatingPadFollower.speeds`).

    Parameters
    ----------
    theta : array_like, shape (n,)
        Cam angles [rad].
    s, s1, s2 : array_like, shape (n,)
        Arc travel of the pad centre ``L psi`` [m] and its theta-derivatives [m/rad, m/rad^2].
    follower : OscillatingPadFollower
        The follower.
    omega : float
        Cam speed, ``> 0`` [rad/s].

    Returns
    -------
    SlipResult
        Speeds per angle, shape (n,) [m/s].

    Raises
    ------
    UndercutError
        Cam radius of curvature ``<= 0`` (``Rr kappa >= 1``) somewhere.
    """
    f = _validate.instance("follower", follower, OscillatingPadFollower)
    theta = np.ravel(_validate.finite_array("theta", theta, "rad"))
    sp = f.program_speeds(np.ravel(s), np.ravel(s1), np.ravel(s2), omega=omega)
    if np.any(sp.u_cam <= 0.0):
        raise UndercutError("oscillating pad: cam radius of curvature <= 0 (undercut) at theta = "
                            f"{np.degrees(theta[sp.u_cam <= 0.0][0]):.2f} deg")
    return SlipResult(theta=theta, v_slip=np.abs(sp.v_slide), V_cam=sp.u_cam, V_follower=sp.u_pad,
                      omega=float(omega), model=f"curved pad R = {f.Rr * 1e3:g} mm on an arm: full sliding",
                      follower_origin=float(sp.xi_pad.flat[0]) if sp.xi_pad.size else 0.0)


def roller_srr(theta, s, s1, s2, *, Rb, Rr, omega, srr, e=0.0) -> SlipResult:
    r"""Roller follower with a prescribed slide-to-roll ratio ``srr`` (-2 < srr < 2).

    .. math:: v_{slip} = |SRR|\,U,\quad U = \frac{2 V_{cam}}{2 + SRR},\quad
              V_{follower} = V_{cam}\frac{2 - SRR}{2 + SRR}

    ``srr = 0`` is pure rolling (zero wear).

    Parameters
    ----------
    theta : array_like, shape (n,)
        Cam angles [rad].
    s : array_like, shape (n,)
        Follower lift [m].
    s1 : array_like, shape (n,)
        ``ds/dtheta`` [m/rad].
    s2 : array_like, shape (n,)
        ``d^2s/dtheta^2`` [m/rad^2].
    Rb : float
        Base-circle radius [m].
    Rr : float
        Roller radius [m].
    omega : float
        Cam speed, ``> 0`` [rad/s].
    srr : float
        Slide-to-roll ratio, ``-2 < srr < 2`` [-].
    e : float
        Follower offset, ``|e| <`` the (pitch) base radius [m].

    Returns
    -------
    SlipResult
        Speeds per angle, shape (n,) [m/s].

    Raises
    ------
    UndercutError
        Cam radius of curvature ``<= 0`` somewhere.
    """
    srr = _validate.in_range("srr", srr, -2.0, 2.0, "", lo_open=True, hi_open=True)
    theta, s, omega, Rr, V_p, V_cam, Omega_req = _roller_kinematics(theta, s, s1, s2, Rb, Rr, e, omega)
    return _srr_result(theta, V_cam, omega, srr, Rr, Omega_req, "roller")


def roller_inertia(theta, s, s1, s2, Fc, *, Rb, Rr, omega, mu, J, T_drag=0.0, e=0.0,
                   max_revolutions: int = 200, tol: float = 1e-9) -> SlipResult:
    r"""Roller follower that slides when friction cannot accelerate its inertia.

    The roller obeys :math:`J\dot\Omega = T_f - T_{drag}\,\mathrm{sign}\,\Omega` with
    :math:`|T_f| \le \mu F_c R_r`. It rolls (``Omega = Omega_req``) while the torque needed,
    ``J omega dOmega_req/dtheta + T_drag``, is available; otherwise it lags with the friction
    torque saturated and slides at ``v_slip = Rr |Omega - Omega_req|``. ``theta`` must span one
    revolution on a uniform grid (periodic, endpoint excluded); the integration is repeated over
    revolutions until ``Omega`` is periodic to ``tol`` (relative), at most ``max_revolutions``.
    The march over angles is a short sequential loop (the state carries from step to step).

    Parameters
    ----------
    theta : array_like, shape (n,)
        Cam angles [rad].
    s : array_like, shape (n,)
        Follower lift [m].
    s1 : array_like, shape (n,)
        ``ds/dtheta`` [m/rad].
    s2 : array_like, shape (n,)
        ``d^2s/dtheta^2`` [m/rad^2].
    Fc : array_like, shape (n,)
        Contact force [N].
    Rb : float
        Base-circle radius [m].
    Rr : float
        Roller radius [m].
    omega : float
        Cam speed, ``> 0`` [rad/s].
    mu : float
        Friction coefficient, ``>= 0`` [-].
    J : float
        Roller polar moment of inertia, ``> 0`` [kg m^2].
    T_drag : float
        Roller bearing drag torque, ``>= 0`` [N m].
    e : float
        Follower offset, ``|e| <`` the (pitch) base radius [m].
    max_revolutions : int
        Largest number of revolutions integrated.
    tol : float
        Periodicity tolerance on ``Omega``, relative to ``max |Omega_req|`` [-].

    Returns
    -------
    SlipResult
        Speeds per angle, shape (n,) [m/s].

    Raises
    ------
    ConvergenceError
        ``Omega`` not periodic after ``max_revolutions``.
    InputError
        ``theta`` not one uniform revolution of at least 4 angles, or a bad parameter.
    """
    max_revolutions = _validate.integer("max_revolutions", max_revolutions, 1, "revolutions")
    tol = _validate.positive("tol", tol, "")
    mu = _validate.nonnegative("mu", mu, "")
    J = _validate.positive("J", J, "kg m^2")
    T_drag = _validate.nonnegative("T_drag", T_drag, "N m")
    theta, s, omega, Rr, V_p, V_cam, Omega_req = _roller_kinematics(theta, s, s1, s2, Rb, Rr, e, omega)
    Fc = np.broadcast_to(_validate.finite_array("Fc", Fc, "N"), theta.shape).astype(float)
    n = theta.size
    if n < 4:
        raise _validate.fail("theta", n, "points", "need >= 4 angles over one revolution")
    dtheta = np.diff(theta)
    span = theta[-1] - theta[0] + float(np.mean(dtheta))
    if np.any(dtheta <= 0) or abs(span - 2 * np.pi) > 1e-6 * 2 * np.pi:
        raise _validate.fail("theta", f"[{theta[0]:g} .. {theta[-1]:g}] ({n} points)", "rad",
                     "must be increasing and cover one revolution (endpoint excluded)")
    dt = np.append(dtheta, 2 * np.pi - (theta[-1] - theta[0])) / omega
    dOmega_max = (mu * np.clip(Fc, 0.0, None) * Rr / J) * dt      # friction authority per step
    drag = T_drag / J * dt
    req = np.roll(Omega_req, -1)                                  # target at the end of each step
    Om = float(Omega_req[0])
    prev = None
    history = []
    Omega = np.empty(n)
    it = 0
    for it in range(1, max_revolutions + 1):  # noqa: B007 - it is reported
        for i in range(n):
            Omega[i] = Om
            free = Om - drag[i] * np.sign(Om)
            Om = free + min(max(req[i] - free, -dOmega_max[i]), dOmega_max[i])
        if prev is not None:
            change = float(np.max(np.abs(Omega - prev))) / max(float(np.max(np.abs(Omega_req))), 1e-300)
            history.append(change)
            if change <= tol:
                break
        prev = Omega.copy()
    else:
        raise ConvergenceError(f"roller spin did not become periodic in {max_revolutions} revolutions",
                               history)
    v_slip = Rr * np.abs(Omega - Omega_req)
    slipping = v_slip > 1e-9 * np.max(np.abs(V_cam))
    # contact speed over the roller surface: V_cam when rolling, less by the lag Rr (Omega - Omega_req)
    # (the contact direction on the roller turns at V_p/rho_p: V_cam = Rr|Omega_req - omega| - Rr V_p/rho_p)
    V_roll = V_cam - Rr * (Omega - Omega_req)
    return SlipResult(theta=theta, v_slip=v_slip, V_cam=V_cam, V_follower=V_roll, omega=omega,
                      model=f"roller: inertia-limited (mu = {mu:g}, J = {J:g} kg m^2)", Omega=Omega.copy(),
                      Omega_req=Omega_req, slipping=slipping, iterations=it, converged=True,
                      message=f"periodic after {it} revolutions; slipping at {int(slipping.sum())} "
                              f"of {n} angles",
                      follower_period=2 * np.pi * Rr)


def radiused_tip(theta, s, s1, s2, *, Rb, r_tip, omega, e=0.0) -> SlipResult:
    r"""Knife-edge follower with a tip of radius ``r_tip``: a roller of radius ``r_tip`` that
    does not turn (``Omega = 0``), so it slides fully.

    The tip centre follows the lift law on the pitch curve of base radius ``Rb + r_tip`` (the
    cam is cut for the radiused tip: same base circle ``Rb``, same lift law; it tends to the
    knife-edge cam as ``r_tip -> 0``). With the roller relations of this module at
    ``Omega = 0``:

    .. math:: v_{slip} = r_{tip}|\Omega_{req}| = |V_p - \omega r_{tip}|,\qquad
              V_{cam} = V_p\,\frac{\rho}{\rho + r_{tip}},\qquad
              V_{follower} = V_{cam} + r_{tip}\,\Omega_{req}

    ``V_follower`` (signed) is the speed of the contact over the tip surface, ``r_tip dphi/dt``
    (``phi`` the pressure angle of the pitch curve): the contact runs back and forth over the
    tip as the pressure angle swings. ``r_tip -> 0`` gives :func:`knife_edge`.

    Parameters
    ----------
    theta : array_like, shape (n,)
        Cam angles [rad].
    s : array_like, shape (n,)
        Follower lift [m].
    s1 : array_like, shape (n,)
        ``ds/dtheta`` [m/rad].
    s2 : array_like, shape (n,)
        ``d^2s/dtheta^2`` [m/rad^2].
    Rb : float
        Base-circle radius [m].
    r_tip : float
        Tip radius, ``> 0`` [m].
    omega : float
        Cam speed, ``> 0`` [rad/s].
    e : float
        Follower offset, ``|e| <`` the (pitch) base radius [m].

    Returns
    -------
    SlipResult
        Speeds per angle, shape (n,) [m/s].

    Examples
    --------
    >>> r = radiused_tip([0.0], [0.0], [0.0], [0.0], Rb=0.02, r_tip=0.001, omega=10.0)
    >>> round(float(r.v_slip[0]), 12)          # base circle: omega (Rb + r) - omega r = omega Rb
    0.2
    """
    r_tip = _validate.positive("r_tip", r_tip, "m")
    theta, s, omega, Rr, V_p, V_cam, Omega_req = _roller_kinematics(theta, s, s1, s2, Rb, r_tip, e, omega)
    phi0 = float(pressure_angle(s.flat[0], np.asarray(s1, dtype=float).flat[0], Rb + r_tip, float(e)))
    return SlipResult(theta=theta, v_slip=r_tip * np.abs(Omega_req), V_cam=V_cam,
                      V_follower=V_cam + r_tip * Omega_req, omega=omega,
                      model=f"knife-edge with tip radius {r_tip * 1e3:g} mm: full sliding",
                      Omega=np.zeros_like(Omega_req), Omega_req=Omega_req,
                      follower_origin=r_tip * phi0)


ROLLER_MODELS = ("srr", "inertia")


def _says(follower, flag: str) -> bool:
    """A flag of the follower protocol (:class:`femcam.profile.geometry.FollowerBehaviour`);
    False for an object that is not a follower."""
    return bool(getattr(follower, flag, False))


def follower_slip(follower, theta, s, s1, s2, *, omega, Fc=None, roller_model: str = "srr",
                  srr: float = 0.02, mu: float = 0.1, J: float | None = None,
                  T_drag: float = 0.0, tip_radius: float | None = None) -> SlipResult:
    """Dispatch on a :mod:`femcam.profile` follower (roller, knife-edge, flat-faced; on an arm:
    roller, :func:`oscillating_roller_srr`, or curved pad, :func:`oscillating_pad`).

    Roller: ``roller_model="srr"`` (slide-to-roll ratio ``srr``, default 2 %) or ``"inertia"``
    (needs ``Fc`` in N, friction ``mu`` and polar inertia ``J`` in kg m^2; ``J=None`` takes a
    solid steel disc of the roller radius and a 10 mm width, ``J = pi rho l Rr^4/2``).
    Knife-edge: ``tip_radius`` (m, optional) selects :func:`radiused_tip` instead of the sharp
    tip of :func:`knife_edge`. Flat-faced: ``follower_origin`` is the contact's distance from
    the follower axis at ``theta[0]`` (``s1 - e``).

    Parameters
    ----------
    follower : RollerFollower, KnifeEdgeFollower or FlatFacedFollower
        The follower (:mod:`femcam.profile`; ``Rb``, ``Rr``, ``e`` in m).
    theta : array_like, shape (n,)
        Cam angles [rad].
    s : array_like, shape (n,)
        Follower lift [m].
    s1 : array_like, shape (n,)
        ``ds/dtheta`` [m/rad].
    s2 : array_like, shape (n,)
        ``d^2s/dtheta^2`` [m/rad^2].
    omega : float
        Cam speed, ``> 0`` [rad/s].
    Fc : array_like, shape (n,), optional
        Contact force [N] (inertia model only).
    roller_model : {"srr", "inertia"}
        Roller slip model.
    srr : float
        Slide-to-roll ratio [-] (``"srr"`` model).
    mu : float
        Friction coefficient [-] (``"inertia"`` model).
    J : float, optional
        Roller polar moment of inertia [kg m^2] (``"inertia"`` model).
    T_drag : float
        Roller bearing drag torque [N m] (``"inertia"`` model).
    tip_radius : float, optional
        Knife-edge tip radius [m].

    Returns
    -------
    SlipResult
        Speeds per angle, shape (n,) [m/s].

    Raises
    ------
    InputError
        An unknown follower or roller model, a ``tip_radius`` on another follower, or ``Fc``
        missing for the inertia model.
    """
    srr = _validate.in_range("srr", srr, -2.0, 2.0, "", lo_open=True, hi_open=True)
    mu = _validate.nonnegative("mu", mu, "")
    kind = type(follower).__name__
    e = float(getattr(follower, "e", 0.0))
    if _says(follower, "needs_tip"):
        if tip_radius is not None:
            return radiused_tip(theta, s, s1, s2, Rb=follower.Rb, r_tip=tip_radius, omega=omega, e=e)
        return knife_edge(theta, s, s1, Rb=follower.Rb, omega=omega, e=e)
    if tip_radius is not None:
        raise _validate.fail("tip_radius", tip_radius, "m",
                             f"applies to knife-edge followers only (got a {kind})")
    if _says(follower, "flat_face"):
        r = flat_faced(theta, s, s1, s2, Rb=follower.Rb, omega=omega)
        return dataclasses.replace(r, follower_origin=r.follower_origin - e)
    if _says(follower, "oscillating") and not _says(follower, "rolls"):  # the pad on an arm
        return oscillating_pad(theta, s, s1, s2, follower=follower, omega=omega)
    if _says(follower, "oscillating"):  # the roller on an arm
        if roller_model != "srr":
            raise _validate.fail("roller_model", roller_model, "", "an oscillating roller has the "
                                 "slide-to-roll ratio model only ('srr'; srr = 0: pure rolling)")
        L = follower.L  # a scene's s is the roller centre's arc travel L psi (m)
        return oscillating_roller_srr(theta, np.asarray(s, float) / L, np.asarray(s1, float) / L,
                                      np.asarray(s2, float) / L, follower=follower, omega=omega, srr=srr)
    if not _says(follower, "translating_roller"):
        raise _validate.fail("follower", kind, "",
                      "must be a RollerFollower, KnifeEdgeFollower, FlatFacedFollower, "
                      "OscillatingRollerFollower or OscillatingPadFollower")
    _validate.choice("roller_model", roller_model, ROLLER_MODELS)
    if roller_model == "srr":
        return roller_srr(theta, s, s1, s2, Rb=follower.Rb, Rr=follower.Rr, omega=omega, srr=srr, e=e)
    if Fc is None:
        raise _validate.fail("Fc", None, "N", "is needed by the inertia-limited roller model")
    if J is None:
        J = 0.5 * np.pi * 7850.0 * 0.010 * follower.Rr**4
    return roller_inertia(theta, s, s1, s2, Fc, Rb=follower.Rb, Rr=follower.Rr, omega=omega, mu=mu, J=J,
                          T_drag=T_drag, e=e)
