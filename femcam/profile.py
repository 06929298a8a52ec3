r"""Follower geometry: cam surface, pressure angle and radius of curvature.

Pure vectorised functions of the cam angle ``theta`` and the follower motion ``s(theta)`` with
its theta-derivatives ``s1 = ds/dtheta`` and ``s2 = d2s/dtheta2`` (from
:meth:`femcam.kinematics.CamProgram.derivatives`). Nothing here depends on the cam speed.

Frames and sign conventions
---------------------------
The cam turns **counter-clockwise** about the origin; ``theta`` is its rotation angle. The
*fixed frame* has the follower translating along +y; its axis is the line ``x = e``
(offset ``e``, positive to +x, which lowers the pressure angle on the rise: Norton's
convention). The *cam frame* turns with the cam and coincides with the fixed frame at
``theta = 0``; a fixed-frame point ``P`` has cam-frame coordinates ``R(-theta) P``.

The pitch point (roller centre, or knife tip) is at ``(e, d + s)`` in the fixed frame with
``d = sqrt(Rp^2 - e^2)`` and ``Rp`` the prime-circle radius (``Rb + Rr`` for a roller, ``Rb``
for a knife edge). Its cam-frame trace is the pitch curve, traversed clockwise as theta grows.

Symbols
-------
=========  ==================================================  =======  ===========================
symbol     meaning                                              unit     source
=========  ==================================================  =======  ===========================
theta      cam angle                                            rad
s          follower lift above the base circle                  m
s1, s2     ds/dtheta, d2s/dtheta2                               m/rad^k
Rb         base-circle radius (smallest cam radius)             m        Norton ch. 8
Rr         roller radius                                        m
Rp         prime-circle radius, Rb + Rr (roller)                m        Norton ch. 8; seed 002 "Ro"
e          follower offset (eccentricity)                       m        Norton eq. 8.31
d          sqrt(Rp^2 - e^2), pitch height at s = 0              m
phi        pressure angle (signed; > 0 on an in-line rise)      rad      Norton eq. 8.31; seed 002 eq. 24
rho        cam SURFACE radius of curvature at the contact       m        > 0 convex, < 0 concave,
                                                                         +inf flat
rho_pitch  radius of curvature of the pitch curve               m        Chen (1982) ch. 4
=========  ==================================================  =======  ===========================

References
----------
* R. L. Norton, *Design of Machinery*, ch. 8 (pressure angle eq. 8.31, radius of curvature
  and undercutting, flat-faced follower eq. 8.24-8.27: ``rho = Rb + s + s''``).
* F. Y. Chen, *Mechanics and Design of Cam Mechanisms*, Pergamon, 1982, ch. 4.
* Seed 002 eq. 24, ``phi = atan(s'/(s + Ro))``: the in-line (e = 0) case of Norton 8.31 with
  the prime-circle radius ``Ro``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from . import _validate as V  # noqa: N812
from .errors import InputError, UndercutError

FOLLOWER_KINDS = ("roller", "knife_edge", "flat_faced")


# --------------------------------------------------------------------------------------------
# followers
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True, kw_only=True)
class RollerFollower:
    """Translating roller follower: base radius ``Rb``, roller radius ``Rr``, offset ``e`` (m).

    >>> RollerFollower(Rb=0.01, Rr=0.01).Rp
    0.02
    """

    Rb: float
    Rr: float
    e: float = 0.0
    kind = "roller"

    def __post_init__(self):
        object.__setattr__(self, "Rb", V.positive("Rb", self.Rb, "m"))
        object.__setattr__(self, "Rr", V.positive("Rr", self.Rr, "m"))
        object.__setattr__(self, "e", V.number("e", self.e, "m"))
        if abs(self.e) >= self.Rp:
            raise V.fail("e", self.e, "m", f"offset must satisfy |e| < Rb + Rr = {self.Rp:g} m")

    @property
    def Rp(self) -> float:
        """Prime-circle radius ``Rb + Rr`` (m)."""
        return self.Rb + self.Rr


@dataclass(frozen=True, kw_only=True)
class KnifeEdgeFollower:
    """Translating knife-edge follower: base radius ``Rb`` and offset ``e`` (m)."""

    Rb: float
    e: float = 0.0
    kind = "knife_edge"

    def __post_init__(self):
        object.__setattr__(self, "Rb", V.positive("Rb", self.Rb, "m"))
        object.__setattr__(self, "e", V.number("e", self.e, "m"))
        if abs(self.e) >= self.Rb:
            raise V.fail("e", self.e, "m", f"offset must satisfy |e| < Rb = {self.Rb:g} m")

    @property
    def Rr(self) -> float:
        return 0.0

    @property
    def Rp(self) -> float:
        return self.Rb


@dataclass(frozen=True, kw_only=True)
class FlatFacedFollower:
    """Translating flat-faced follower (face perpendicular to its axis), base radius ``Rb`` (m).

    The axis offset ``e`` does not change the cam shape; it only moves the contact point
    along the face (the contact sits ``s1 - e`` from the axis).
    """

    Rb: float
    e: float = 0.0
    kind = "flat_faced"

    def __post_init__(self):
        object.__setattr__(self, "Rb", V.positive("Rb", self.Rb, "m"))
        object.__setattr__(self, "e", V.number("e", self.e, "m"))

    @property
    def Rr(self) -> float:
        return 0.0


Follower = RollerFollower | KnifeEdgeFollower | FlatFacedFollower


def make_follower(kind: str, *, Rb: float, Rr: float = 0.0, e: float = 0.0) -> Follower:
    """Build a follower from its kind name (``"roller"``, ``"knife_edge"``, ``"flat_faced"``)."""
    V.choice("follower kind", kind, FOLLOWER_KINDS)
    if kind == "roller":
        return RollerFollower(Rb=Rb, Rr=Rr, e=e)
    if V.number("Rr", Rr, "m") != 0.0:
        raise V.fail("Rr", Rr, "m", f"only a roller follower has a roller radius; a {kind} "
                     "follower needs Rr = 0 (the default)")
    if kind == "knife_edge":
        return KnifeEdgeFollower(Rb=Rb, e=e)
    return FlatFacedFollower(Rb=Rb, e=e)


# --------------------------------------------------------------------------------------------
# result
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class CamProfile:
    """Cam geometry sampled at ``theta`` (all arrays share theta's shape; SI units).

    ``x, y`` are cam-surface points in the cam frame; ``contact_x, contact_y`` the contact point
    in the fixed frame; ``pitch_x, pitch_y`` the pitch curve in the cam frame (equal to the
    surface for knife-edge; for flat-faced it is the contact point too). ``undercut`` flags
    samples where the generated surface is not realisable (roller: ``0 < rho_pitch <= Rr``;
    flat-faced: ``Rb + s + s2 <= 0``); ``cusp`` is True when any sample is undercut (the
    generated envelope then folds over itself and has cusps). ``face_offset`` is the contact
    position along a flat face measured from the follower axis (``s1 - e``; zero otherwise) and
    ``face_width_min`` the width of a face centred on the axis that keeps the contact on it.
    """

    follower: Follower
    theta: np.ndarray
    s: np.ndarray
    phi: np.ndarray
    rho: np.ndarray
    rho_pitch: np.ndarray
    x: np.ndarray
    y: np.ndarray
    pitch_x: np.ndarray
    pitch_y: np.ndarray
    contact_x: np.ndarray
    contact_y: np.ndarray
    undercut: np.ndarray
    face_offset: np.ndarray
    face_width_min: float
    undercut_intervals: list = field(default_factory=list)

    @property
    def cusp(self) -> bool:
        return bool(np.any(self.undercut))

    @property
    def phi_max(self) -> float:
        """Largest |phi| (rad)."""
        return float(np.max(np.abs(self.phi))) if self.phi.size else 0.0

    @property
    def rho_min(self) -> float:
        """Smallest |rho| over the samples (m); concave and convex alike."""
        return float(np.min(np.abs(self.rho))) if self.rho.size else math.inf


# --------------------------------------------------------------------------------------------
# formulas
# --------------------------------------------------------------------------------------------
def pressure_angle(s, s1, Rp, e=0.0):
    r"""Pressure angle of a translating roller or knife-edge follower (rad, signed).

    .. math:: \varphi = \arctan\frac{s' - e}{s + \sqrt{R_p^2 - e^2}}

    Norton, *Design of Machinery*, eq. 8.31; seed 002 eq. 24 is the case ``e = 0``,
    ``Rp = Ro``. Derivation: the pitch-curve tangent, written in the fixed frame at angle
    theta, is ``(d + s, s1 - e)``; the contact normal is perpendicular to it.

    >>> round(math.degrees(float(pressure_angle(0.0, 0.02, 0.02))), 6)
    45.0
    """
    d = math.sqrt(Rp * Rp - e * e)
    return np.arctan2(np.asarray(s1, float) - e, d + np.asarray(s, float))


def pitch_curvature(s, s1, s2, Rp, e=0.0):
    r"""Signed curvature of the pitch curve (1/m, > 0 convex).

    .. math:: \kappa_p = \frac{(d+s)^2 + (s'-e)(2s'-e) - s''(d+s)}
                             {\left[(d+s)^2 + (s'-e)^2\right]^{3/2}}, \quad d = \sqrt{R_p^2-e^2}

    The curvature of the parametric curve ``p(theta) = R(-theta) (e, d + s)`` (Chen 1982 ch. 4;
    Norton ch. 8). For ``e = 0`` it is the polar formula ``(r^2 + 2r'^2 - r r'')/(r^2 + r'^2)^{3/2}``
    with ``r = Rp + s``.

    >>> round(float(pitch_curvature(0.0, 0.0, 0.0, 0.02)), 6)   # base circle: 1/Rp
    50.0
    """
    d = math.sqrt(Rp * Rp - e * e)
    r = d + np.asarray(s, float)
    q = np.asarray(s1, float) - e
    num = r * r + q * (2.0 * np.asarray(s1, float) - e) - np.asarray(s2, float) * r
    return num / (r * r + q * q) ** 1.5


def flat_face_radius(s, s2, Rb):
    r"""Cam radius of curvature under a flat-faced translating follower (m).

    .. math:: \rho = R_b + s + s''

    Norton eq. 8.25 (envelope of the face lines ``n(theta) . P = Rb + s``).

    >>> float(flat_face_radius(0.001, -0.002, 0.01))
    0.009
    """
    return Rb + np.asarray(s, float) + np.asarray(s2, float)


def _rot(theta, x, y):
    """Fixed-frame (x, y) at cam angle theta -> cam-frame coordinates, i.e. R(-theta) (x, y)."""
    c, sn = np.cos(theta), np.sin(theta)
    return c * x + sn * y, -sn * x + c * y


def bool_intervals(theta, mask):
    """Contiguous runs of True in ``mask`` as ``[(theta_start, theta_end), ...]`` (grid order)."""
    theta = np.ravel(theta)
    m = np.ravel(np.asarray(mask, bool))
    if not m.any():
        return []
    edges = np.diff(np.concatenate(([0], m.astype(np.int8), [0])))
    starts = np.flatnonzero(edges == 1)
    ends = np.flatnonzero(edges == -1) - 1
    return [(float(theta[a]), float(theta[b])) for a, b in zip(starts, ends, strict=True)]


def _fmt_intervals_deg(intervals, most: int = 20) -> str:
    """The first ``most`` intervals in degrees, then ``... and N more`` (a message stays short)."""
    text = ", ".join(f"[{math.degrees(a):.2f}, {math.degrees(b):.2f}] deg" for a, b in intervals[:most])
    return text + (f", ... and {len(intervals) - most} more" if len(intervals) > most else "")


def cam_profile(f: Follower, theta, s, s1, s2, *, allow_undercut: bool = False) -> CamProfile:
    """Cam surface, pressure angle and radius of curvature for follower ``f``.

    ``theta`` (rad) and ``s, s1, s2`` (m, m/rad, m/rad^2) broadcast together. Raises
    :class:`~femcam.errors.UndercutError` (with the angle ranges in degrees and the smallest
    radius) if the profile is undercut or cusped, unless ``allow_undercut=True``, which returns
    the result with ``undercut`` flags set.

    Roller: ``rho_cam = rho_pitch - Rr`` (inner offset of the pitch curve; Norton ch. 8),
    computed as ``kappa/(1 - Rr kappa)`` so that an inflection of the pitch curve gives
    ``rho = inf`` without a division warning. Knife edge: ``rho = rho_pitch``. Flat-faced:
    ``phi = 0``, ``rho = Rb + s + s2``, contact at ``x = s1`` in the fixed frame.
    """
    if not isinstance(f, RollerFollower | KnifeEdgeFollower | FlatFacedFollower):
        raise InputError(f"follower = {f!r}: must be a RollerFollower, KnifeEdgeFollower or "
                         "FlatFacedFollower")
    theta = V.finite_array("theta", theta, "rad")
    s = V.finite_array("s", s, "m")
    s1 = V.finite_array("s1", s1, "m/rad")
    s2 = V.finite_array("s2", s2, "m/rad^2")
    try:
        theta, s, s1, s2 = np.broadcast_arrays(theta, s, s1, s2)
    except ValueError:
        raise InputError(f"theta, s, s1, s2 have shapes {theta.shape}, {s.shape}, {s1.shape}, "
                         f"{s2.shape}: must broadcast together") from None
    theta, s, s1, s2 = (np.array(a, dtype=float) for a in (theta, s, s1, s2))

    if isinstance(f, FlatFacedFollower):
        rho = flat_face_radius(s, s2, f.Rb)
        rho_pitch = rho
        phi = np.zeros_like(s)
        cx, cy = s1.copy(), f.Rb + s
        x, y = _rot(theta, cx, cy)
        px, py = x, y
        undercut = rho <= 0.0
        face_offset = s1 - f.e
        face_width = 2.0 * float(np.max(np.abs(face_offset))) if face_offset.size else 0.0
        detail = "radius of curvature Rb + s + s'' <= 0"
        worst = float(np.min(rho)) if rho.size else 0.0
    else:
        Rp, e, Rr = f.Rp, f.e, f.Rr
        d = math.sqrt(Rp * Rp - e * e)
        if np.any(d + s <= 0.0):
            bad = float(s[d + s <= 0.0].flat[0])
            raise V.fail("s", bad, "m", f"pitch point passes the cam centre: need s > -{d:g} m")
        phi = pressure_angle(s, s1, Rp, e)
        kappa = pitch_curvature(s, s1, s2, Rp, e)
        with np.errstate(divide="ignore"):
            rho_pitch = np.where(kappa == 0.0, np.inf, 1.0 / np.where(kappa == 0.0, 1.0, kappa))
            denom = 1.0 - Rr * kappa
            k_cam = np.where(denom == 0.0, np.inf, kappa / np.where(denom == 0.0, 1.0, denom))
            rho = np.where(k_cam == 0.0, np.inf, 1.0 / np.where(k_cam == 0.0, 1.0, k_cam))
        pxf, pyf = e + 0.0 * s, d + s
        # contact = pitch point - Rr * n_hat, n_hat = (-sin phi, cos phi) outward normal
        cx, cy = pxf + Rr * np.sin(phi), pyf - Rr * np.cos(phi)
        px, py = _rot(theta, pxf, pyf)
        x, y = _rot(theta, cx, cy)
        undercut = (Rr * kappa >= 1.0) if Rr > 0 else np.zeros(s.shape, bool)
        face_offset = np.zeros_like(s)
        face_width = 0.0
        detail = f"pitch-curve radius of curvature <= roller radius Rr = {Rr * 1e3:g} mm"
        worst = float(np.min(rho_pitch[undercut])) if np.any(undercut) else math.inf

    intervals = bool_intervals(theta, undercut)
    if intervals and not allow_undercut:
        raise UndercutError(
            f"{f.kind} cam profile is undercut (cusped) for theta in {_fmt_intervals_deg(intervals)}: "
            f"{detail}; smallest radius there {worst * 1e3:.4g} mm. Increase the base radius Rb "
            f"(now {f.Rb * 1e3:g} mm), use a smaller roller or a longer segment angle beta, "
            "or pass allow_undercut=True to get the flagged profile.")
    return CamProfile(follower=f, theta=theta, s=s, phi=phi, rho=rho, rho_pitch=rho_pitch, x=x, y=y,
                      pitch_x=px, pitch_y=py, contact_x=cx, contact_y=cy, undercut=undercut,
                      face_offset=face_offset, face_width_min=face_width, undercut_intervals=intervals)


# --------------------------------------------------------------------------------------------
# smallest base circle
# --------------------------------------------------------------------------------------------
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
    from scipy.optimize import minimize_scalar

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
    """
    from scipy.optimize import brentq

    V.choice("kind", kind, FOLLOWER_KINDS)
    phi_lim = V.in_range("phi_max", phi_max, 0.0, math.pi / 2, "rad", lo_open=True, hi_open=True)
    Rr = V.nonnegative("Rr", Rr, "m")
    e = V.number("e", e, "m")
    rho_min = V.nonnegative("rho_min", rho_min, "m")
    if kind == "roller" and Rr <= 0.0:
        raise V.fail("Rr", Rr, "m", "must be > 0 for a roller follower")
    if kind != "roller" and Rr != 0.0:
        raise V.fail("Rr", Rr, "m", f"only a roller follower has a roller radius; a {kind} "
                     "follower needs Rr = 0 (the default)")
    n = V.integer("n_theta", n_theta, 16)
    theta = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    dtheta = 2.0 * math.pi / n
    s, s1, s2 = _derivs(program, theta)

    if kind == "flat_faced":
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
        hi = max(2.0 * Rb, reach, float(np.max(np.abs(s))) + 1e-6)
        while margin(hi) <= 0.0:
            hi *= 2.0
            iterations += 1
            if hi > 1e3:  # pragma: no cover - pathological program
                raise UndercutError("no base radius below 1 km avoids undercutting")
        Rb, r = brentq(margin, Rb, hi, xtol=1e-12, rtol=1e-12, full_output=True)
        Rb *= 1.0 + RB_MARGIN  # step just onto the safe side of the root
        iterations += r.iterations
        binding = "undercut"
    deg = math.degrees(phi_lim)
    if binding == "none":
        # the limit Rb -> 0: prime radius Rr
        phi0, rho0, _ = at_prime_radius(Rr) if Rr > abs(e) else (math.pi / 2, 0.0, None)
        if kind == "roller":
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
