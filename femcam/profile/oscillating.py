r"""Oscillating roller follower: the arm geometry, the cam profile by the envelope of the roller,
pressure angle, radius of curvature, undercut and the smallest base circle.

The motion laws are reused unchanged: the arm angle is ``psi(theta) = lift * s_normalised`` (rad),
with ``psi1 = dpsi/dtheta`` and ``psi2 = d2psi/dtheta2``. The functions here take ``psi``; a
scene's cam program holds the roller centre's arc travel ``L psi`` (m), so that every lift,
velocity and acceleration column keeps its unit (:meth:`OscillatingRollerFollower.cam_profile`).

Frames and sign conventions
---------------------------
The cam turns **counter-clockwise** about the origin ``O``. In the *fixed frame* the pivot is at
``A = (a, 0)``. ``beta`` is the angle at the pivot between ``A -> O`` and ``A -> B`` (``B`` the
roller centre); ``|B|^2 = a^2 + L^2 - 2 a L cos(beta)`` grows with ``beta``, so a positive lift
``psi`` raises ``beta = beta0 + psi`` (the roller moves away from the cam). ``beta0`` follows from
the roller on the base circle, ``|B| = Rp = Rb + Rr`` (cosine rule). ``sigma = +1``
(``direction = "away_from_pivot"``): the roller sits on the side ``y > 0``, where the cam surface at
the contact moves away from the pivot; ``sigma = -1`` (``"toward_pivot"``): the mirror side ``y < 0``.

.. math:: B = \left(a - L\cos\beta,\ \sigma L \sin\beta\right), \quad
          \cos\beta_0 = \frac{a^2 + L^2 - R_p^2}{2 a L}

The *cam frame* is ``R(-theta)`` times the fixed frame (as in :mod:`femcam.profile.geometry`);
the pitch curve ``P = R(-theta) B`` is traversed clockwise, its outward normal is ``n = J t``
(``J`` the +90 deg rotation, ``t`` the unit tangent) and the cam surface is ``P - Rr n``.

Symbols
-------
=========  ==================================================  =======  ===========================
symbol     meaning                                              unit     source
=========  ==================================================  =======  ===========================
theta      cam angle                                            rad
psi        arm angle above its base-circle position             rad      Norton ch. 8 (oscillating)
psi1,psi2  dpsi/dtheta, d2psi/dtheta2                           rad/rad^k
a          cam centre to pivot distance                         m        scene pivot_distance_mm
L          pivot to roller centre (arm length)                  m        scene arm_length_mm
Rb, Rr     base-circle and roller radii                         m
Rp         prime-circle radius Rb + Rr                          m
beta       angle at the pivot, A->O to A->B                     rad      cosine rule
sigma      side of the roller (+1 away_from_pivot, -1 toward)   -
T, U       dP/dtheta, d2P/dtheta2 written in the fixed frame    m        Chen (1982) ch. 4
u          unit velocity direction of B, dB/dbeta / L           -
n          outward unit normal of the cam at the contact        -
phi        pressure angle, signed angle from u to n            rad      Norton ch. 8
kappa      pitch-curve curvature (> 0 convex)                   1/m
rho        cam surface radius of curvature 1/kappa - Rr         m        > 0 convex, < 0 concave
=========  ==================================================  =======  ===========================

References
----------
* R. L. Norton, *Cam Design and Manufacturing Handbook*, 2nd ed., 2009, ch. 7-8 (oscillating
  roller followers, pressure angle to the path of the roller centre).
* F. Y. Chen, *Mechanics and Design of Cam Mechanisms*, Pergamon, 1982, ch. 4 (envelope).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..errors import InputError, UndercutError
from .geometry import CamProfile, _fmt_intervals_deg, _rot, _set_checked, bool_intervals

#: scene values of ``[follower] direction`` and their ``sigma``
DIRECTIONS = {"away_from_pivot": 1, "toward_pivot": -1}


@dataclass(frozen=True, kw_only=True)
class OscillatingRollerFollower:
    """Roller on an arm pivoted at distance ``a`` from the cam centre (m; module docstring).

    Parameters
    ----------
    Rb : float
        Base-circle radius of the cam [m], ``> 0``.
    Rr : float
        Roller radius [m], ``> 0``.
    a : float
        Cam centre to pivot [m], ``> Rb`` (a pivot inside the base circle is refused).
    L : float
        Pivot to roller centre [m], ``|a - L| < Rb + Rr < a + L`` (the roller reaches the cam).
    sigma : int, optional
        +1 (``"away_from_pivot"``, default) or -1 (``"toward_pivot"``).

    Raises
    ------
    InputError
        A radius not positive, the pivot inside the base circle, or an arm that cannot reach.

    Examples
    --------
    >>> f = OscillatingRollerFollower(Rb=0.018, Rr=0.009, a=0.045, L=0.036)
    >>> round(math.degrees(f.beta0), 4)
    36.8699
    """

    Rb: float
    Rr: float
    a: float
    L: float
    sigma: int = 1
    kind = "oscillating_roller"
    #: the roller turns on the arm (rolls); a pad (femcam.profile.pad) does not
    rolls = True
    #: the follower surface named in messages
    face = "roller"

    def __post_init__(self):
        _set_checked(self, Rb=_validate.positive, Rr=_validate.positive, a=_validate.positive,
                     L=_validate.positive)
        if isinstance(self.sigma, bool) or self.sigma not in (1, -1):
            raise _validate.fail("sigma", self.sigma, "", "must be +1 or -1")
        if self.a <= self.Rb:
            raise _validate.fail("a", self.a, "m", f"the pivot lies inside the base circle: need a > Rb = "
                                 f"{self.Rb:g} m")
        if not abs(self.a - self.L) < self.Rp < self.a + self.L:
            raise _validate.fail("L", self.L, "m", f"the arm cannot put the roller on the base circle: need "
                                 f"|a - L| < Rb + Rr = {self.Rp:g} m < a + L (a = {self.a:g} m)")

    @property
    def Rp(self) -> float:
        """Prime-circle radius ``Rb + Rr`` (m)."""
        return self.Rb + self.Rr

    @property
    def beta0(self) -> float:
        """Arm angle at the pivot on the base circle (rad, cosine rule; module docstring)."""
        return math.acos((self.a**2 + self.L**2 - self.Rp**2) / (2.0 * self.a * self.L))

    @property
    def psi_fold(self) -> float:
        """Largest arm lift before the arm folds past the line pivot-cam centre (rad): pi - beta0."""
        return math.pi - self.beta0

    def describe(self) -> str:
        """One line of the geometry in mm and deg (``femcam run`` prints it).

        Returns
        -------
        str
            Radii, pivot distance, arm length, direction, base-circle arm angle.
        """
        side = "away_from_pivot" if self.sigma == 1 else "toward_pivot"
        return (f"Rb = {self.Rb * 1e3:g} mm, Rr = {self.Rr * 1e3:g} mm, pivot {self.a * 1e3:g} mm, arm "
                f"{self.L * 1e3:g} mm, {side}, base-circle arm angle {math.degrees(self.beta0):.4g} deg")

    def friction_lever(self, psi, psi1, psi2) -> np.ndarray:
        """Lever of the contact friction about the pivot per unit ``mu``: 0 for a roller (m).

        A roller rolls: the tangential force at its contact is the small traction its inertia
        and bearing drag need, not ``mu Fc``, and the moment balance leaves it out. The sliding
        pad (:class:`femcam.profile.OscillatingPadFollower`) overrides this.

        Parameters
        ----------
        psi, psi1, psi2 : float or array_like
            Arm angle [rad] and its theta-derivatives [rad/rad, rad/rad^2]; broadcast together.

        Returns
        -------
        ndarray
            Zeros of the broadcast shape [m].
        """
        return np.zeros(arm_geometry(self, psi, psi1, psi2).phi.shape)

    def cam_profile(self, theta, s, s1, s2, *, allow_undercut: bool = False) -> CamProfile:
        """:func:`oscillating_profile` at the roller-centre arc travel ``s = L psi`` (m) of a scene
        program; :func:`femcam.profile.cam_profile` hands an oscillating follower here, so the
        scene's profile, undercut and pressure-angle checks need no dispatch. (A scene program of
        an oscillating follower holds ``L psi`` in m, so ``s_mm``, ``v``, ``a`` of every table are
        the roller centre's travel along its arc, in their stated units.)

        Parameters
        ----------
        theta : float or array_like
            Cam angle [rad].
        s, s1, s2 : float or array_like
            Arc travel of the roller centre ``L psi`` [m] and its theta-derivatives [m/rad^k].
        allow_undercut : bool, optional
            Return an undercut profile with its flags instead of raising. Default False.

        Returns
        -------
        CamProfile
            The profile at ``theta`` (``CamProfile.s``: psi in rad).
        """
        L = self.L
        return oscillating_profile(self, theta, np.asarray(s, float) / L, np.asarray(s1, float) / L,
                                   np.asarray(s2, float) / L, allow_undercut=allow_undercut)


@dataclass(frozen=True)
class ArmGeometry:
    """The arm state at cam angles (fixed frame, SI; built by :func:`arm_geometry`).

    Attributes
    ----------
    Bx, By : ndarray
        Roller centre (m).
    ux, uy : ndarray
        Unit velocity direction of the roller centre (positive psi).
    nx, ny : ndarray
        Outward unit cam normal at the contact.
    kappa : ndarray
        Pitch-curve curvature (1/m, > 0 convex).
    phi : ndarray
        Pressure angle (rad).
    lever : ndarray
        Moment arm of a unit contact force about the pivot in the psi sense, ``L cos(phi)`` (m).
    pitch_speed : ndarray
        ``|T|``: speed of the roller centre over the cam (cam frame) per unit cam angle (m/rad);
        the contact point moves over the cam surface at ``omega |T| (1 - Rr kappa)``.
    """

    Bx: np.ndarray
    By: np.ndarray
    ux: np.ndarray
    uy: np.ndarray
    nx: np.ndarray
    ny: np.ndarray
    kappa: np.ndarray
    phi: np.ndarray
    lever: np.ndarray
    pitch_speed: np.ndarray


def arm_geometry(f: OscillatingRollerFollower, psi, psi1, psi2) -> ArmGeometry:
    r"""Roller centre, contact normal, pitch curvature and pressure angle of an oscillating roller.

    .. math:: T = \psi' L u - J B, \quad U = \psi'' L u + \psi'^2 L u_\beta - 2 \psi' L J u - B,
              \quad \kappa = -\frac{T \times U}{|T|^3}, \quad n = \frac{J T}{|T|}

    ``T, U`` are the first two theta-derivatives of the pitch curve ``R(-theta) B`` rotated back to
    the fixed frame (the cross product is rotation-invariant); ``u_beta = (cos beta, -sigma sin
    beta)``. Chen (1982) ch. 4 for the parametric curvature; Norton (2009) ch. 8 for the pressure
    angle of an oscillating follower (normal against the path of the roller centre).

    Parameters
    ----------
    f : OscillatingRollerFollower
        The follower.
    psi, psi1, psi2 : float or array_like
        Arm angle (rad) and its theta-derivatives (rad/rad, rad/rad^2); broadcast together.

    Returns
    -------
    ArmGeometry
        Arrays of the broadcast shape.

    Raises
    ------
    InputError
        Non-finite input or an arm folded past the cam centre (``beta0 + psi >= pi``).

    Examples
    --------
    >>> f = OscillatingRollerFollower(Rb=0.018, Rr=0.009, a=0.045, L=0.036)
    >>> g = arm_geometry(f, 0.0, 0.0, 0.0)   # dwell on the base circle: kappa = 1/Rp
    >>> round(float(g.kappa), 9), round(float(np.hypot(g.Bx, g.By)), 12)
    (37.037037037, 0.027)
    """
    _validate.instance("f", f, OscillatingRollerFollower)
    psi = _validate.finite_array("psi", psi, "rad")
    psi1 = _validate.finite_array("psi1", psi1, "rad/rad")
    psi2 = _validate.finite_array("psi2", psi2, "rad/rad^2")
    psi, psi1, psi2 = (np.array(x, float) for x in np.broadcast_arrays(psi, psi1, psi2))
    beta = f.beta0 + psi
    if np.any(beta >= math.pi) or np.any(beta <= 0.0):
        bad = float(psi[(beta >= math.pi) | (beta <= 0.0)].flat[0])
        raise _validate.fail("psi", bad, "rad", f"({math.degrees(bad):.4g} deg) folds the arm past the line "
                             f"pivot-cam centre: need -{math.degrees(f.beta0):.4g} deg < psi < "
                             f"{math.degrees(f.psi_fold):.4g} deg")
    L, sg = f.L, f.sigma
    cb, sb = np.cos(beta), np.sin(beta)
    Bx, By = f.a - L * cb, sg * L * sb
    ux, uy = sb, sg * cb
    # T = psi1 L u - J B, J (x, y) = (-y, x)
    Tx, Ty = psi1 * L * ux + By, psi1 * L * uy - Bx
    # U = psi2 L u + psi1^2 L u_beta - 2 psi1 L J u - B
    Ux = psi2 * L * ux + psi1**2 * L * cb + 2.0 * psi1 * L * uy - Bx
    Uy = psi2 * L * uy - psi1**2 * L * sg * sb - 2.0 * psi1 * L * ux - By
    nT = np.hypot(Tx, Ty)
    kappa = -(Tx * Uy - Ty * Ux) / nT**3
    nx, ny = -Ty / nT, Tx / nT
    # no sigma factor: a rise turns the normal the same way on both sides (as s' - e does for a
    # translating roller); the side shows in the base-circle value, like an offset
    phi = np.arctan2(ux * ny - uy * nx, ux * nx + uy * ny)
    lever = L * (ux * nx + uy * ny)
    return ArmGeometry(Bx=Bx, By=By, ux=ux, uy=uy, nx=nx, ny=ny, kappa=kappa, phi=phi, lever=lever,
                       pitch_speed=nT)


def oscillating_profile(f: OscillatingRollerFollower, theta, psi, psi1, psi2, *,
                        allow_undercut: bool = False) -> CamProfile:
    r"""Cam surface, pressure angle and radius of curvature under an oscillating roller.

    .. math:: \rho = \frac{1}{\kappa} - R_r, \qquad x_{cam} = R(-\theta)\,(B - R_r n)

    The envelope of the roller circles (inner offset of the pitch curve by ``Rr``; Norton ch. 8),
    ``rho`` computed as ``1/(kappa/(1 - Rr kappa))`` so an inflection gives ``inf``.
    ``CamProfile.s`` holds ``psi`` (rad); ``contact_x, contact_y`` are in the fixed frame of this
    module (pivot on +x).

    Parameters
    ----------
    f : OscillatingRollerFollower
        The follower.
    theta : float or array_like
        Cam angles [rad].
    psi, psi1, psi2 : float or array_like
        Arm angle [rad] and its theta-derivatives; broadcast with ``theta``.
    allow_undercut : bool, optional
        Return an undercut profile with its flags instead of raising. Default False.

    Returns
    -------
    CamProfile
        The profile at ``theta``.

    Raises
    ------
    UndercutError
        ``Rr kappa >= 1`` somewhere and ``allow_undercut`` is False.
    InputError
        Not an oscillating follower, non-finite input or an arm folded past the cam centre.

    Examples
    --------
    >>> f = OscillatingRollerFollower(Rb=0.018, Rr=0.009, a=0.045, L=0.036)
    >>> p = oscillating_profile(f, 0.3, 0.0, 0.0, 0.0)   # dwell: the base circle
    >>> round(float(p.rho), 12), round(float(np.hypot(p.x, p.y)), 12)
    (0.018, 0.018)
    """
    if not isinstance(f, OscillatingRollerFollower):
        raise InputError(f"follower = {f!r}: must be an OscillatingRollerFollower")
    theta = _validate.finite_array("theta", theta, "rad")
    g = arm_geometry(f, psi, psi1, psi2)
    try:
        bc = np.broadcast_arrays(theta, np.asarray(psi, float), g.Bx)
    except ValueError:
        raise InputError(f"theta {np.shape(theta)} and psi {np.shape(psi)}: must broadcast together") \
            from None
    theta, psi = np.array(bc[0], float), np.array(bc[1], float)
    kappa, Rr = np.broadcast_to(g.kappa, theta.shape), f.Rr
    with np.errstate(divide="ignore"):
        rho_pitch = np.where(kappa == 0.0, np.inf, 1.0 / np.where(kappa == 0.0, 1.0, kappa))
        denom = 1.0 - Rr * kappa
        k_cam = np.where(denom == 0.0, np.inf, kappa / np.where(denom == 0.0, 1.0, denom))
        rho = np.where(k_cam == 0.0, np.inf, 1.0 / np.where(k_cam == 0.0, 1.0, k_cam))
    cx, cy = g.Bx - Rr * g.nx, g.By - Rr * g.ny
    px, py = _rot(theta, g.Bx, g.By)
    x, y = _rot(theta, cx, cy)
    undercut = Rr * kappa >= 1.0
    intervals = bool_intervals(theta, undercut)
    if intervals and not allow_undercut:
        worst = float(np.min(rho_pitch[undercut]))
        raise UndercutError(
            f"{f.kind} cam profile is undercut (cusped) for theta in "
            f"{_fmt_intervals_deg(intervals)}: "
            f"pitch-curve radius of curvature <= {f.face} radius Rr = {Rr * 1e3:g} mm; smallest radius "
            f"there {worst * 1e3:.4g} mm. Increase the base radius Rb (now {f.Rb * 1e3:g} mm), use a "
            f"smaller {f.face} or a smaller angular lift, or pass allow_undercut=True.")
    z = np.zeros(theta.shape)
    return CamProfile(follower=f, theta=theta, s=psi, phi=np.broadcast_to(g.phi, theta.shape).copy(),
                      rho=rho, rho_pitch=rho_pitch, x=x, y=y, pitch_x=px, pitch_y=py,
                      contact_x=np.broadcast_to(cx, theta.shape).copy(),
                      contact_y=np.broadcast_to(cy, theta.shape).copy(), undercut=undercut,
                      face_offset=z, face_width_min=0.0, undercut_intervals=intervals)


def min_base_radius_oscillating(program, *, Rr: float, a: float, L: float, sigma: int = 1,
                                phi_max: float = math.radians(30.0), n_theta: int = 2048) -> float:
    r"""Smallest base radius whose largest ``|phi|`` is ``phi_max`` (m), pivot and arm fixed.

    .. math:: \max_\theta |\varphi(\theta; R_b)| = \varphi_{max}

    Scans ``Rb`` between the reach limits of the arm (``|a - L| < Rb + Rr < a + L``, ``Rb < a``)
    and polishes the first admissible crossing with Brent's method (as
    :func:`femcam.profile.min_base_radius` does for the translating followers).

    Parameters
    ----------
    program : femcam.kinematics.CamProgram
        The arm motion (lift in rad).
    Rr, a, L : float
        Roller radius, pivot distance, arm length [m].
    sigma : int, optional
        +1 or -1 (module docstring). Default +1.
    phi_max : float, optional
        Pressure-angle limit [rad], in (0, pi/2). Default 30 deg.
    n_theta : int, optional
        Angles of the pressure-angle scan. Default 2048.

    Returns
    -------
    float
        The smallest base radius [m] with ``max |phi| <= phi_max`` (to 1e-12 m in Rb).

    Raises
    ------
    InputError
        No base radius in the reachable range meets the limit.

    Examples
    --------
    >>> from femcam.kinematics import CamProgram, rise, dwell, fall
    >>> prog = CamProgram([rise(1.5, 0.2), dwell(1.0), fall(1.5, 0.2), dwell(2 * math.pi - 4.0)])
    >>> Rb = min_base_radius_oscillating(prog, Rr=0.009, a=0.045, L=0.036, phi_max=math.radians(25))
    >>> 0.0 < Rb < 0.045
    True
    """
    from scipy.optimize import brentq  # scipy.optimize: ~0.1 s, only this root find needs it

    phi_max = _validate.in_range("phi_max", phi_max, 0.0, 0.5 * math.pi, "rad", lo_open=True, hi_open=True)
    Rr, a, L = (_validate.positive(n, x, "m") for n, x in (("Rr", Rr), ("a", a), ("L", L)))
    n_theta = _validate.integer("n_theta", n_theta, 2)
    _validate.record("program", program, "a CamProgram", "derivatives")
    th = np.linspace(0.0, 2.0 * math.pi, n_theta, endpoint=False)
    d = program.derivatives(th)

    def excess(Rb):
        f = OscillatingRollerFollower(Rb=Rb, Rr=Rr, a=a, L=L, sigma=sigma)
        if float(np.max(d.s)) >= f.psi_fold:
            return math.inf
        return float(np.max(np.abs(arm_geometry(f, d.s, d.s1, d.s2).phi))) - phi_max

    lo = max(abs(a - L) - Rr, 0.0) * (1 + 1e-9) + 1e-9
    hi = min(a + L - Rr, a) * (1 - 1e-9)
    grid = np.linspace(lo, hi, 200)
    vals = [excess(r) for r in grid]
    for r0, r1, v0, v1 in zip(grid[:-1], grid[1:], vals[:-1], vals[1:], strict=True):
        if v0 <= 0.0:
            return float(r0)
        if v1 <= 0.0 and math.isfinite(v0):
            return float(brentq(excess, r0, r1, xtol=1e-12))
    raise _validate.fail("phi_max", phi_max, "rad", f"({math.degrees(phi_max):.4g} deg) is not met by any "
                         f"base radius the arm reaches (a = {a:g} m, L = {L:g} m, Rr = {Rr:g} m)")
