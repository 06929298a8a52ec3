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

from .. import _validate
from .._repr import compact_repr, span
from ..errors import InputError, UndercutError

FOLLOWER_KINDS = ("roller", "knife_edge", "flat_faced")


# --------------------------------------------------------------------------------------------
# followers
# --------------------------------------------------------------------------------------------
def _set_checked(follower, **checks) -> None:
    """Set each length field (m) of the frozen ``follower`` to its checked value, in the order
    given: ``name=check`` with ``check(name, value, "m")`` a :mod:`femcam._validate` helper."""
    for name, check in checks.items():
        object.__setattr__(follower, name, check(name, getattr(follower, name), "m"))


class FollowerBehaviour:
    """The follower protocol: what a follower does at the contact, so that callers read these
    attributes instead of dispatching on the class or on ``kind`` (docs/architecture.md,
    "Follower protocol"). Each follower class sets the flags that differ from these defaults.
    """

    #: the follower surface turns with the contact (a roller; a knife edge, a flat face or a pad slides)
    rolls = False
    #: the contact surface is a circle of radius ``Rr`` (a roller, on a slide or an arm, or a pad)
    draws_circle = False
    #: the contact surface is a flat face (second radius ``inf``; the cam is the curved body)
    flat_face = False
    #: a knife edge: contact stresses need a tip radius (a sharp tip has no contact width)
    needs_tip = False
    #: the follower sits on a pivoted arm (femcam.profile.oscillating)
    oscillating = False

    @property
    def translating_roller(self) -> bool:
        """A roller on a slide (not on an arm): the roller slip models and the pitch curve."""
        return self.rolls and not self.oscillating

    def describe(self) -> str:
        """One line of the geometry in mm (``femcam run`` prints it); the arm's classes say more.

        Returns
        -------
        str
            Base radius, the roller radius of a roller, and the offset.

        Examples
        --------
        >>> RollerFollower(Rb=0.02, Rr=0.01).describe()
        'Rb = 20 mm, Rr = 10 mm, e = 0 mm'
        """
        roller = f", Rr = {self.Rr * 1e3:g} mm" if self.translating_roller else ""
        return f"Rb = {self.Rb * 1e3:g} mm{roller}, e = {self.e * 1e3:g} mm"

    def contact_radius(self, tip_radius: float | None = None) -> float:
        """Radius of the follower body at the contact, the second Hertz radius (m).

        Parameters
        ----------
        tip_radius : float, optional
            Knife-edge tip radius [m] (required for a knife edge, ignored otherwise).

        Returns
        -------
        float
            ``Rr`` for a follower circle, ``tip_radius`` for a knife edge, ``inf`` for a flat face.

        Raises
        ------
        InputError
            A knife edge without ``tip_radius`` (naming ``tip_radius_mm``), or a tip radius not
            positive.

        Examples
        --------
        >>> FlatFacedFollower(Rb=0.02).contact_radius()
        inf
        """
        if self.flat_face:
            return math.inf
        if self.needs_tip:
            if tip_radius is None:
                raise _validate.fail("tip_radius_mm", None, "mm", "a knife-edge follower needs a tip radius "
                                     "for contact stresses (a sharp tip has no contact width): add "
                                     "tip_radius_mm = ... to the [follower] table")
            return _validate.positive("tip_radius", tip_radius, "m")
        return float(self.Rr)


@dataclass(frozen=True, kw_only=True)
class RollerFollower(FollowerBehaviour):
    """Translating roller follower: base radius ``Rb``, roller radius ``Rr``, offset ``e`` (m).

    Parameters
    ----------
    Rb : float
        Base-circle radius of the cam [m], ``> 0``.
    Rr : float
        Roller radius [m], ``> 0``.
    e : float, optional
        Follower offset [m], positive to +x, ``|e| < Rb + Rr``. Default 0.

    Raises
    ------
    InputError
        ``Rb`` or ``Rr`` not positive, ``e`` not finite or ``|e| >= Rb + Rr``.

    Examples
    --------
    >>> RollerFollower(Rb=0.01, Rr=0.01).Rp
    0.02
    """

    Rb: float
    Rr: float
    e: float = 0.0
    kind = "roller"
    rolls = True
    draws_circle = True

    def __post_init__(self):
        _set_checked(self, Rb=_validate.positive, Rr=_validate.positive, e=_validate.number)
        if abs(self.e) >= self.Rp:
            raise _validate.fail("e", self.e, "m", f"offset must satisfy |e| < Rb + Rr = {self.Rp:g} m")

    @property
    def Rp(self) -> float:
        """Prime-circle radius ``Rb + Rr`` (m)."""
        return self.Rb + self.Rr


@dataclass(frozen=True, kw_only=True)
class KnifeEdgeFollower(FollowerBehaviour):
    """Translating knife-edge follower: base radius ``Rb`` and offset ``e`` (m).

    Parameters
    ----------
    Rb : float
        Base-circle radius of the cam [m], ``> 0``.
    e : float, optional
        Follower offset [m], positive to +x, ``|e| < Rb``. Default 0.

    Raises
    ------
    InputError
        ``Rb`` not positive, ``e`` not finite or ``|e| >= Rb``.
    """

    Rb: float
    e: float = 0.0
    kind = "knife_edge"
    needs_tip = True

    def __post_init__(self):
        _set_checked(self, Rb=_validate.positive, e=_validate.number)
        if abs(self.e) >= self.Rb:
            raise _validate.fail("e", self.e, "m", f"offset must satisfy |e| < Rb = {self.Rb:g} m")

    @property
    def Rr(self) -> float:
        """Roller radius (m): 0 for a knife edge."""
        return 0.0

    @property
    def Rp(self) -> float:
        """Prime-circle radius (m): ``Rb`` for a knife edge."""
        return self.Rb


@dataclass(frozen=True, kw_only=True)
class FlatFacedFollower(FollowerBehaviour):
    """Translating flat-faced follower (face perpendicular to its axis), base radius ``Rb`` (m).

    The axis offset ``e`` does not change the cam shape; it only moves the contact point
    along the face (the contact sits ``s1 - e`` from the axis).

    Parameters
    ----------
    Rb : float
        Base-circle radius of the cam [m], ``> 0``.
    e : float, optional
        Offset of the follower axis [m], positive to +x, any finite value. Default 0.

    Raises
    ------
    InputError
        ``Rb`` not positive or ``e`` not finite.
    """

    Rb: float
    e: float = 0.0
    kind = "flat_faced"
    flat_face = True

    def __post_init__(self):
        _set_checked(self, Rb=_validate.positive, e=_validate.number)

    @property
    def Rr(self) -> float:
        """Roller radius (m): 0 for a flat face."""
        return 0.0


Follower = RollerFollower | KnifeEdgeFollower | FlatFacedFollower


def make_follower(kind: str, *, Rb: float, Rr: float = 0.0, e: float = 0.0) -> Follower:
    """Build a follower from its kind name (``"roller"``, ``"knife_edge"``, ``"flat_faced"``).

    Parameters
    ----------
    kind : {"roller", "knife_edge", "flat_faced"}
        Follower type.
    Rb : float
        Base-circle radius of the cam [m], ``> 0``.
    Rr : float, optional
        Roller radius [m]: ``> 0`` for a roller, must be 0 (default) otherwise.
    e : float, optional
        Follower offset [m]. Default 0.

    Returns
    -------
    RollerFollower or KnifeEdgeFollower or FlatFacedFollower
        The validated follower.

    Raises
    ------
    InputError
        Unknown ``kind``, ``Rr != 0`` for a non-roller, or an invalid radius or offset.
    """
    _validate.choice("follower kind", kind, FOLLOWER_KINDS)
    if kind == "roller":
        return RollerFollower(Rb=Rb, Rr=Rr, e=e)
    if _validate.number("Rr", Rr, "m") != 0.0:
        raise _validate.fail("Rr", Rr, "m", f"only a roller follower has a roller radius; a {kind} "
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

    Attributes
    ----------
    follower : RollerFollower or KnifeEdgeFollower or FlatFacedFollower
        The follower the profile was generated for.
    theta : ndarray
        Cam angles [rad], float; every array below has this (broadcast) shape.
    s : ndarray
        Follower lift [m].
    phi : ndarray
        Signed pressure angle [rad] (0 for a flat face).
    rho : ndarray
        Cam-surface radius of curvature [m]: ``> 0`` convex, ``< 0`` concave, ``inf`` flat.
    rho_pitch : ndarray
        Pitch-curve radius of curvature [m] (equal to ``rho`` for knife-edge and flat-faced).
    x, y : ndarray
        Cam-surface contact point in the cam frame [m].
    pitch_x, pitch_y : ndarray
        Pitch-curve point in the cam frame [m].
    contact_x, contact_y : ndarray
        Contact point in the fixed frame [m].
    undercut : ndarray of bool
        True where the generated surface is not realisable.
    face_offset : ndarray
        Contact position along a flat face from the follower axis, ``s1 - e`` [m]; zeros
        for other followers.
    face_width_min : float
        Width of a face centred on the axis that keeps the contact on it [m]; 0 for other
        followers.
    undercut_intervals : list of tuple of float
        ``(theta_start, theta_end)`` [rad] of each run of undercut samples, in grid order.
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

    def __repr__(self) -> str:
        """The follower kind, angles, rho range and undercut count (a compact line)."""
        return compact_repr(self, [
            type(self.follower).__name__,
            f"{self.theta.size} angles",
            f"rho {span(self.rho, 1e3, 'mm')}",
            f"undercut {int(np.count_nonzero(self.undercut))}",
        ])

    @property
    def cusp(self) -> bool:
        """True when any sample is undercut (the envelope folds over itself)."""
        return bool(np.any(self.undercut))

    @property
    def phi_max(self) -> float:
        """Largest ``|phi|`` (rad)."""
        return float(np.max(np.abs(self.phi))) if self.phi.size else 0.0

    @property
    def rho_min(self) -> float:
        """Smallest ``|rho|`` over the samples (m); concave and convex alike."""
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

    Parameters
    ----------
    s : float or array_like
        Follower lift [m].
    s1 : float or array_like
        ``ds/dtheta`` [m/rad]; broadcasts against ``s``.
    Rp : float
        Prime-circle radius [m] (``Rb + Rr`` for a roller, ``Rb`` for a knife edge).
    e : float, optional
        Follower offset [m], ``|e| < Rp``. Default 0.

    Returns
    -------
    ndarray
        Signed pressure angle ``phi`` [rad], float, the broadcast shape of ``s, s1``.

    Examples
    --------
    >>> round(math.degrees(float(pressure_angle(0.0, 0.02, 0.02))), 6)
    45.0
    """
    s, s1 = _validate.finite_array("s", s, "m"), _validate.finite_array("s1", s1, "m/rad")
    d = _prime_offset(Rp, e)
    return np.arctan2(s1 - e, d + s)


def _prime_offset(Rp, e) -> float:
    """``d = sqrt(Rp^2 - e^2)`` of a checked prime radius ``Rp > 0`` and offset ``|e| < Rp``."""
    Rp = _validate.positive("Rp", Rp, "m")
    e = _validate.number("e", e, "m")
    if abs(e) >= Rp:
        raise _validate.fail("e", e, "m", f"must satisfy |e| < Rp = {Rp:g} m")
    return math.sqrt(Rp * Rp - e * e)


def pitch_curvature(s, s1, s2, Rp, e=0.0):
    r"""Signed curvature of the pitch curve (1/m, > 0 convex).

    .. math:: \kappa_p = \frac{(d+s)^2 + (s'-e)(2s'-e) - s''(d+s)}
                             {\left[(d+s)^2 + (s'-e)^2\right]^{3/2}}, \quad d = \sqrt{R_p^2-e^2}

    The curvature of the parametric curve ``p(theta) = R(-theta) (e, d + s)`` (Chen 1982 ch. 4;
    Norton ch. 8). For ``e = 0`` it is the polar formula ``(r^2 + 2r'^2 - r r'')/(r^2 + r'^2)^{3/2}``
    with ``r = Rp + s``.

    Parameters
    ----------
    s : float or array_like
        Follower lift [m].
    s1 : float or array_like
        ``ds/dtheta`` [m/rad].
    s2 : float or array_like
        ``d2s/dtheta2`` [m/rad^2]; ``s, s1, s2`` broadcast.
    Rp : float
        Prime-circle radius [m].
    e : float, optional
        Follower offset [m], ``|e| < Rp``. Default 0.

    Returns
    -------
    ndarray
        Signed pitch-curve curvature ``kappa_p`` [1/m] (``> 0`` convex), the broadcast shape.

    Examples
    --------
    >>> round(float(pitch_curvature(0.0, 0.0, 0.0, 0.02)), 6)   # base circle: 1/Rp
    50.0
    """
    s, s1 = _validate.finite_array("s", s, "m"), _validate.finite_array("s1", s1, "m/rad")
    s2 = _validate.finite_array("s2", s2, "m/rad^2")
    d = _prime_offset(Rp, e)
    r = d + s
    q = s1 - e
    num = r * r + q * (2.0 * s1 - e) - s2 * r
    return num / (r * r + q * q) ** 1.5


def flat_face_radius(s, s2, Rb):
    r"""Cam radius of curvature under a flat-faced translating follower (m).

    .. math:: \rho = R_b + s + s''

    Norton eq. 8.25 (envelope of the face lines ``n(theta) . P = Rb + s``).

    Parameters
    ----------
    s : float or array_like
        Follower lift [m].
    s2 : float or array_like
        ``d2s/dtheta2`` [m/rad^2]; broadcasts against ``s``.
    Rb : float or array_like
        Base-circle radius [m].

    Returns
    -------
    ndarray
        Cam radius of curvature ``rho`` [m] (``<= 0`` means undercut), the broadcast shape.

    Examples
    --------
    >>> float(flat_face_radius(0.001, -0.002, 0.01))
    0.009
    """
    Rb, s, s2 = _validate.broadcast(Rb=_validate.positive_array("Rb", Rb, "m"),
                                    s=_validate.finite_array("s", s, "m"),
                                    s2=_validate.finite_array("s2", s2, "m/rad^2"))
    return Rb + s + s2


def _rot(theta, x, y):
    """Fixed-frame (x, y) at cam angle theta -> cam-frame coordinates, i.e. R(-theta) (x, y)."""
    c, sn = np.cos(theta), np.sin(theta)
    return c * x + sn * y, -sn * x + c * y


def bool_intervals(theta, mask):
    """Contiguous runs of True in ``mask`` as ``[(theta_start, theta_end), ...]`` (grid order).

    Parameters
    ----------
    theta : array_like
        Cam angles [rad], flattened in grid order.
    mask : array_like of bool
        Flag per angle, the same number of elements as ``theta``.

    Returns
    -------
    list of tuple of float
        ``(theta_start, theta_end)`` [rad] of each run: the first and last flagged sample
        (inclusive); empty if no flag is set.
    """
    theta = np.ravel(_validate.finite_array("theta", theta, "rad"))
    m = np.ravel(np.asarray(mask, bool))
    if m.size != theta.size:
        raise _validate.fail("mask", f"{m.size} flags", "", f"must have one flag per angle ({theta.size})")
    if not m.any():
        return []
    edges = np.diff(np.concatenate(([0], m.astype(np.int8), [0])))
    starts = np.flatnonzero(edges == 1)
    ends = np.flatnonzero(edges == -1) - 1
    return [(float(theta[a]), float(theta[b])) for a, b in zip(starts, ends, strict=True)]


def _fmt_intervals_deg(intervals, most: int = 20) -> str:
    """The first ``most`` intervals in degrees, then ``... and N more`` (a message stays short);
    two decimals, four for an interval narrower than 0.05 deg (a short segment's undercut would
    print as ``[0.01, 0.01]``)."""
    def one(a, b):
        d = 2 if math.degrees(b - a) >= 0.05 else 4
        return f"[{math.degrees(a):.{d}f}, {math.degrees(b):.{d}f}] deg"

    text = ", ".join(one(a, b) for a, b in intervals[:most])
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

    Parameters
    ----------
    f : RollerFollower or KnifeEdgeFollower or FlatFacedFollower
        The follower.
    theta : float or array_like
        Cam angles [rad].
    s : float or array_like
        Follower lift [m].
    s1 : float or array_like
        ``ds/dtheta`` [m/rad].
    s2 : float or array_like
        ``d2s/dtheta2`` [m/rad^2]; ``theta, s, s1, s2`` broadcast together.
    allow_undercut : bool, optional
        Return an undercut profile with its flags instead of raising. Default False.

    Returns
    -------
    CamProfile
        Surface, pitch curve, contact point, ``phi`` and ``rho``, all of the broadcast shape.

    Raises
    ------
    UndercutError
        The profile is undercut and ``allow_undercut`` is False.
    InputError
        Not a follower, non-finite or non-broadcasting inputs, or a pitch point through the
        cam centre (``s <= -sqrt(Rp^2 - e^2)``).
    """
    own = getattr(type(f), "cam_profile", None)
    if own is not None:  # a follower that owns its profile (femcam.profile.oscillating)
        return own(f, theta, s, s1, s2, allow_undercut=allow_undercut)
    if not isinstance(f, RollerFollower | KnifeEdgeFollower | FlatFacedFollower):
        raise InputError(f"follower = {f!r}: must be a RollerFollower, KnifeEdgeFollower, "
                         "FlatFacedFollower or OscillatingRollerFollower")
    theta = _validate.finite_array("theta", theta, "rad")
    s = _validate.finite_array("s", s, "m")
    s1 = _validate.finite_array("s1", s1, "m/rad")
    s2 = _validate.finite_array("s2", s2, "m/rad^2")
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
            raise _validate.fail("s", bad, "m", f"pitch point passes the cam centre: need s > -{d:g} m")
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
