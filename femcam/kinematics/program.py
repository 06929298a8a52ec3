r"""Cam programs: rise / dwell / fall segments closing to one revolution, SVAJ and junctions.

A segment spans ``beta`` rad of cam angle. With ``u = (theta - theta_0)/beta`` and the lift
``h_0`` at the segment start (Norton 2009 ch. 3; architecture.md "Kinematics contract"):

.. math::
    \text{rise: } s = h_0 + h\,L(u), \quad \text{fall: } s = h_0 - h\,L(u),
    \quad \text{dwell: } s = h_0 \\
    \frac{d^k s}{d\theta^k} = \pm \frac{h}{\beta^k} \frac{d^k L}{du^k}, \qquad
    v = \omega s', \ a = \omega^2 s'', \ j = \omega^3 s''' \ (\omega \text{ constant})

Symbols
-------
=============  =====================================  ===========  =========================
symbol         meaning                                 unit         source
=============  =====================================  ===========  =========================
theta          cam angle (taken modulo 2 pi)           rad          seed 002 (u = theta/beta)
beta           segment angle                           rad          seed 002 / Norton ch. 3
h              segment lift                            m            seed 002 (L)
s1, s2, s3     d^k s/d theta^k                         m/rad^k
s, v, a, j     lift and its time derivatives           m, m/s, ...  Norton "SVAJ"
omega          cam angular speed (constant)            rad/s
=============  =====================================  ===========  =========================

Junctions
---------
At every join (including the wrap-around at 2 pi) :meth:`CamProgram.junctions` compares the
left limit (end of one segment) with the right limit (start of the next): per radian always
(``jump_s1, jump_s2, jump_s3``), and in SI when the cam speed is given,
``junctions(omega)``: ``jump_v = omega jump_s1`` (m/s), ``jump_a = omega^2 jump_s2`` (m/s^2),
``jump_j = omega^3 jump_s3`` (m/s^3). A step in s' (a
velocity step) makes the acceleration a delta function: *infinite acceleration*, and its
derivative, the jerk, is infinite too. A step in s'' (an acceleration step, e.g. SHM next to
a dwell) makes the jerk a delta: *infinite jerk*. A step in s''' is a finite jerk jump.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from math import degrees, pi

import numpy as np

from .. import _validate
from .._repr import compact_repr
from ..errors import InputError
from .laws import MotionLaw, law

__all__ = ["Segment", "rise", "dwell", "fall", "CamProgram", "Derivatives", "SVAJ", "Junction",
           "junction_report"]

TWO_PI = 2.0 * pi
_CLOSE_RTOL = 1e-9  # closure tolerance on sum(beta) relative to 2 pi
_JUMP_RTOL = 1e-9  # a jump smaller than this times the adjacent segments' scale is round-off
_KINDS = ("rise", "dwell", "fall")


@dataclass(frozen=True, kw_only=True)
class Segment:
    """One segment of a cam program (build with :func:`rise`, :func:`dwell`, :func:`fall`).

    Parameters
    ----------
    kind : {"rise", "dwell", "fall"}
        Segment type.
    beta : float
        Segment angle [rad], ``> 0``.
    h : float, optional
        Segment lift [m], ``> 0`` for a rise or fall; forced to 0 for a dwell.
    law : str or MotionLaw or None, optional
        Normalised motion law (a name or a :class:`~femcam.kinematics.laws.MotionLaw`; stored
        as a MotionLaw, ``"cycloidal"`` if None); forced to None for a dwell.

    Raises
    ------
    InputError
        Unknown ``kind``, non-positive ``beta`` or ``h``, or an invalid law.
    """

    kind: str
    beta: float
    h: float = 0.0
    law: MotionLaw | None = None

    def __post_init__(self):
        _validate.choice("kind", self.kind, _KINDS)
        object.__setattr__(self, "beta", _validate.positive("beta", self.beta, "rad"))
        _validate.nonnegative("h", self.h, "m")  # a dwell ignores h, but not a bad one
        if self.kind == "dwell":
            object.__setattr__(self, "h", 0.0)
            object.__setattr__(self, "law", None)
        else:
            object.__setattr__(self, "h", _validate.positive("h", self.h, "m"))
            lw = self.law if self.law is not None else "cycloidal"
            object.__setattr__(self, "law", law(lw))

    @property
    def sign(self) -> float:
        """+1 for a rise, -1 for a fall, 0 for a dwell."""
        return {"rise": 1.0, "fall": -1.0, "dwell": 0.0}[self.kind]

    @property
    def name(self) -> str:
        """``'rise(poly345)'``, ``'dwell'``, ..."""
        return self.kind if self.law is None else f"{self.kind}({self.law.name})"

    def end_derivatives(self, end: int) -> np.ndarray:
        """(s1, s2, s3) in m/rad^k at the segment start (end=0) or end (end=1).

        Parameters
        ----------
        end : {0, 1}
            0 for the segment start, 1 for its end (any other value is taken as the end).

        Returns
        -------
        ndarray, shape (3,)
            ``ds/dtheta`` [m/rad], ``d2s/dtheta2`` [m/rad^2], ``d3s/dtheta3`` [m/rad^3];
            zeros for a dwell.
        """
        if self.law is None:
            return np.zeros(3)
        e = self.law.ends
        vaj = (e.v0, e.a0, e.j0) if end == 0 else (e.v1, e.a1, e.j1)
        return np.array([self.sign * self.h / self.beta ** (k + 1) * vaj[k] for k in range(3)])

    def scale(self) -> np.ndarray:
        """Characteristic size of (s1, s2, s3) in m/rad^k, for round-off tolerances.

        Returns
        -------
        ndarray, shape (3,)
            ``h/beta^k max(C_k, 1)`` for k = 1, 2, 3 [m/rad^k]; zeros for a dwell.
        """
        if self.law is None:
            return np.zeros(3)
        return np.array([self.h / self.beta**k * max(C, 1.0)
                         for k, C in ((1, self.law.Cv), (2, self.law.Ca), (3, self.law.Cj))])


def rise(beta: float, h: float, law: str | MotionLaw = "cycloidal") -> Segment:
    """A rise of ``h`` m over ``beta`` rad following ``law`` (a name or a MotionLaw).

    Parameters
    ----------
    beta : float
        Segment angle [rad], ``> 0``.
    h : float
        Segment lift [m], ``> 0``.
    law : str or MotionLaw, optional
        Normalised motion law: a name from :data:`~femcam.kinematics.laws.LAW_NAMES` or a
        :class:`~femcam.kinematics.laws.MotionLaw`. Default ``"cycloidal"``.

    Returns
    -------
    Segment
        The validated rise segment.
    """
    return Segment(kind="rise", beta=beta, h=h, law=law)


def fall(beta: float, h: float, law: str | MotionLaw = "cycloidal") -> Segment:
    """A fall of ``h`` m over ``beta`` rad: the rise law mirrored, ``s = h_0 - h L(u)``.

    Parameters
    ----------
    beta : float
        Segment angle [rad], ``> 0``.
    h : float
        Segment lift [m], ``> 0``.
    law : str or MotionLaw, optional
        Normalised motion law: a name from :data:`~femcam.kinematics.laws.LAW_NAMES` or a
        :class:`~femcam.kinematics.laws.MotionLaw`. Default ``"cycloidal"``.

    Returns
    -------
    Segment
        The validated fall segment.
    """
    return Segment(kind="fall", beta=beta, h=h, law=law)


def dwell(beta: float) -> Segment:
    """A dwell (constant lift) over ``beta`` rad.

    Parameters
    ----------
    beta : float
        Segment angle [rad], ``> 0``.

    Returns
    -------
    Segment
        The validated dwell segment (``h = 0``, ``law = None``).
    """
    return Segment(kind="dwell", beta=beta)


@dataclass(frozen=True)
class Derivatives:
    """Lift and its cam-angle derivatives: s (m), s1 (m/rad), s2 (m/rad^2), s3 (m/rad^3).

    Items can also be read by name, ``d["s1"]``.

    Attributes
    ----------
    theta : ndarray
        Cam angles [rad] as given (not reduced mod 2 pi), float, any shape.
    s : ndarray
        Lift [m], the shape of ``theta``.
    s1, s2, s3 : ndarray
        ``d^k s/dtheta^k`` [m/rad^k], k = 1, 2, 3, the shape of ``theta``.
    """

    theta: np.ndarray
    s: np.ndarray
    s1: np.ndarray
    s2: np.ndarray
    s3: np.ndarray

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)

    def __getitem__(self, key):
        return getattr(self, key)


@dataclass(frozen=True)
class SVAJ:
    """Follower lift s (m), velocity v (m/s), acceleration a (m/s^2), jerk j (m/s^3) vs theta (rad).

    Items can also be read by name, ``r["v"]``.

    Attributes
    ----------
    theta : ndarray
        Cam angles [rad] as given, float, any shape.
    s : ndarray
        Lift [m], the shape of ``theta``.
    v : ndarray
        Velocity [m/s].
    a : ndarray
        Acceleration [m/s^2].
    j : ndarray
        Jerk [m/s^3].
    omega : float
        Constant cam speed [rad/s] (NaN if unknown).
    """

    theta: np.ndarray
    s: np.ndarray
    v: np.ndarray
    a: np.ndarray
    j: np.ndarray
    omega: float = float("nan")

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)

    def __getitem__(self, key):
        return getattr(self, key)


@dataclass(frozen=True)
class Junction:
    """A join between two segments; jumps are right limit minus left limit.

    ``jump_s1``, ``jump_s2``, ``jump_s3`` are the per-radian jumps of ds/dtheta (m/rad),
    d2s/dtheta2 (m/rad^2) and d3s/dtheta3 (m/rad^3); they do not depend on the speed.
    With the cam speed ``omega`` (rad/s; from ``CamProgram.junctions(omega)``) the physical
    jumps are ``jump_v = omega jump_s1`` (m/s), ``jump_a = omega^2 jump_s2`` (m/s^2) and
    ``jump_j = omega^3 jump_s3`` (m/s^3); without it they are ``None``.

    Attributes
    ----------
    theta : float
        Junction angle [rad], in [0, 2 pi).
    left, right : str
        Names of the segments ending and starting there, e.g. ``"rise(shm)"``.
    jump_s1 : float
        Jump of ``ds/dtheta`` [m/rad] (velocity step / omega).
    jump_s2 : float
        Jump of ``d2s/dtheta2`` [m/rad^2] (acceleration step / omega^2).
    jump_s3 : float
        Jump of ``d3s/dtheta3`` [m/rad^3] (jerk step / omega^3).
    infinite_acceleration : bool
        Velocity step: the acceleration (and jerk) is a delta function.
    infinite_jerk : bool
        Acceleration or velocity step: the jerk is infinite.
    index : int
        Junction ``k`` joins segment ``k`` and segment ``(k + 1) mod n``.
    omega : float or None
        Cam speed [rad/s]; None if only the per-radian jumps are known.
    """

    theta: float  # rad, in [0, 2 pi)
    left: str
    right: str
    jump_s1: float  # m/rad (velocity step / omega)
    jump_s2: float  # m/rad^2 (acceleration step / omega^2)
    jump_s3: float  # m/rad^3 (jerk step / omega^3)
    infinite_acceleration: bool
    infinite_jerk: bool
    index: int = 0  # junction k joins segment k and segment (k+1) mod n
    omega: float | None = None  # rad/s; None: only the per-radian jumps are known

    # SI jumps at speed omega (None without omega)
    @property
    def jump_v(self) -> float | None:
        """Velocity jump omega * jump_s1 (m/s), or None without omega."""
        return None if self.omega is None else self.omega * self.jump_s1

    @property
    def jump_a(self) -> float | None:
        """Acceleration jump omega^2 * jump_s2 (m/s^2), or None without omega."""
        return None if self.omega is None else self.omega**2 * self.jump_s2

    @property
    def jump_j(self) -> float | None:
        """Jerk jump omega^3 * jump_s3 (m/s^3), or None without omega."""
        return None if self.omega is None else self.omega**3 * self.jump_s3

    @property
    def kind(self) -> str:
        """'infinite acceleration', 'infinite jerk', 'finite jerk step' or 'smooth'."""
        if self.infinite_acceleration:
            return "infinite acceleration"
        if self.infinite_jerk:
            return "infinite jerk"
        return "finite jerk step" if self.jump_s3 != 0.0 else "smooth"

    def describe(self) -> str:
        """One line for humans, e.g. ``theta = 90 deg: rise(shm) -> dwell: ... infinite jerk``.

        With ``omega`` the jumps are in m/s, m/s^2, m/s^3; without it, per radian.

        Returns
        -------
        str
            One line: angle [deg], segment names, jumps and the junction kind.
        """
        msg = {
            "infinite acceleration": "INFINITE ACCELERATION (velocity step; jerk infinite too)",
            "infinite jerk": "INFINITE JERK (acceleration step)",
            "finite jerk step": "finite jerk step",
            "smooth": "smooth (s, v, a, j continuous)",
        }[self.kind]
        if self.omega is None:  # + 0.0 turns -0.0 into 0.0 (no "-0" in the report)
            jumps = (f"jump s' = {self.jump_s1 + 0.0:+.4g} m/rad, s'' = {self.jump_s2 + 0.0:+.4g} "
                     f"m/rad^2, s''' = {self.jump_s3 + 0.0:+.4g} m/rad^3")
        else:
            jumps = (f"jump v = {self.jump_v + 0.0:+.4g} m/s, a = {self.jump_a + 0.0:+.4g} m/s^2, "
                     f"j = {self.jump_j + 0.0:+.4g} m/s^3")
        return f"theta = {degrees(self.theta):8.3f} deg: {self.left} -> {self.right}: {jumps}; {msg}"

    def __str__(self):
        return self.describe()


def junction_report(junctions) -> str:
    """Text report of a junction list (for the CLI). Jumps are in m/s, m/s^2, m/s^3 when the
    junctions carry the cam speed (``CamProgram.junctions(omega)``), else per radian (the
    velocity/acceleration/jerk jumps are then omega, omega^2, omega^3 times these).

    Parameters
    ----------
    junctions : iterable of Junction
        Junctions as returned by :meth:`CamProgram.junctions`.

    Returns
    -------
    str
        A header line, one line per junction, and a count of the singular ones.
    """
    junctions = list(junctions)
    omegas = {jn.omega for jn in junctions}
    if junctions and None not in omegas and len(omegas) == 1:
        head = f"Junctions (jumps = right - left, at omega = {omegas.pop():.6g} rad/s):"
    else:
        head = "Junctions (jumps = right - left, per-rad units):"
    lines = [head]
    lines += [f"  {k + 1:2d}. {jn.describe()}" for k, jn in enumerate(junctions)]
    n_a = sum(jn.infinite_acceleration for jn in junctions)
    n_j = sum(jn.infinite_jerk and not jn.infinite_acceleration for jn in junctions)
    lines.append(f"  {len(junctions)} junctions: {n_a} with infinite acceleration, "
                 f"{n_j} more with infinite jerk")
    return "\n".join(lines)


@dataclass(frozen=True)
class CamProgram:
    """A sequence of segments spanning exactly one revolution and returning to the start lift.

    Parameters
    ----------
    segments : sequence of Segment
        Segments in cam-angle order from ``theta = 0``; their ``beta`` must sum to 2 pi rad
        (relative tolerance 1e-9), the rises and falls [m] must cancel, and the lift must stay
        ``>= 0``.

    Raises
    ------
    InputError
        Empty or non-segment input, angles not closing to 2 pi, net lift not zero, or a lift
        below the start lift.

    Examples
    --------
    >>> from math import pi
    >>> p = CamProgram([rise(pi/2, 0.01, "poly345"), dwell(pi/2), fall(pi/2, 0.01), dwell(pi/2)])
    >>> p.h_max
    0.01
    """

    segments: tuple = field(default=())

    def __post_init__(self):
        try:
            segs = tuple(self.segments)
        except TypeError:
            raise _validate.fail("segments", self.segments, "", "must be a sequence of segments") from None
        if not segs:
            raise InputError("segments = (): a cam program needs at least one segment")
        for i, sg in enumerate(segs):
            if not isinstance(sg, Segment):
                raise InputError(f"segments[{i}] = {sg!r}: must be a Segment from rise(), dwell() "
                                 "or fall()")
        object.__setattr__(self, "segments", segs)
        beta = np.array([sg.beta for sg in segs])
        total = float(beta.sum())
        if abs(total - TWO_PI) > _CLOSE_RTOL * TWO_PI:
            raise InputError(
                f"sum(beta) = {total:.12g} rad ({degrees(total):.9g} deg): the segments must close "
                f"to 2*pi = {TWO_PI:.12g} rad (360 deg); off by {degrees(total - TWO_PI):+.6g} deg")
        # lift at each segment start (h_0); rises add, falls subtract
        dh = np.array([sg.sign * sg.h for sg in segs])
        h0 = np.concatenate([[0.0], np.cumsum(dh)])
        scale = max(float(np.abs(dh).max()), 1e-300)
        if abs(h0[-1]) > 1e-9 * scale:
            rises = sum(sg.h for sg in segs if sg.kind == "rise")
            falls = sum(sg.h for sg in segs if sg.kind == "fall")
            raise InputError(
                f"net lift = {h0[-1]:.6g} m ({h0[-1] * 1e3:.6g} mm): the program must return to "
                f"the start lift (sum of rises {rises:.6g} m != sum of falls {falls:.6g} m)")
        if h0.min() < -1e-9 * scale:
            k = int(np.argmin(h0))
            raise InputError(
                f"lift = {h0[k]:.6g} m after segment {k - 1} ({segs[k - 1].name}): the lift is "
                "measured from the start (base circle) and must stay >= 0; start with a rise")
        starts = np.concatenate([[0.0], np.cumsum(beta)[:-1]])
        object.__setattr__(self, "_beta", beta)
        object.__setattr__(self, "_starts", starts)
        object.__setattr__(self, "_h0", h0[:-1])

    # --- geometry ----------------------------------------------------------------------
    @property
    def theta_starts(self) -> np.ndarray:
        """Start angle of each segment (rad); segment k spans [start_k, start_k + beta_k)."""
        return self._starts.copy()

    @property
    def h_max(self) -> float:
        """Maximum lift (m) over the revolution (includes Bezier overshoot, if any)."""
        best = 0.0
        for sg, h0 in zip(self.segments, self._h0, strict=True):
            if sg.law is None:
                best = max(best, h0)
            else:
                lo, hi = sg.law.s_range
                best = max(best, h0 + sg.h * (hi if sg.kind == "rise" else -lo))
        return float(best)

    # --- evaluation --------------------------------------------------------------------
    def derivatives(self, theta) -> Derivatives:
        """s and d^k s/d theta^k (k = 1..3) at cam angles ``theta`` (rad, any shape, mod 2 pi).

        At a junction the value of the segment that *starts* there is returned.

        Parameters
        ----------
        theta : float or array_like
            Cam angles [rad], any shape, taken modulo 2 pi.

        Returns
        -------
        Derivatives
            ``s`` [m] and ``s1, s2, s3`` [m/rad^k], each of the shape of ``theta``.

        Raises
        ------
        InputError
            ``theta`` not finite.
        """
        th = _validate.finite_array("theta", theta, "rad")
        t = np.mod(th, TWO_PI)
        idx = np.clip(np.searchsorted(self._starts, t, side="right") - 1, 0, len(self.segments) - 1)
        u = np.clip((t - self._starts[idx]) / self._beta[idx], 0.0, 1.0)
        out = [np.broadcast_to(self._h0[idx], t.shape).astype(float)] + [np.zeros(t.shape)
                                                                         for _ in range(3)]
        for k_seg, sg in enumerate(self.segments):  # loop over segments, vectorised over angles
            if sg.law is None:
                continue
            m = idx == k_seg
            if not np.any(m):
                continue
            um = u[m]
            out[0][m] += sg.sign * sg.h * sg.law.s(um)
            out[1][m] = sg.sign * sg.h / sg.beta * sg.law.v(um)
            out[2][m] = sg.sign * sg.h / sg.beta**2 * sg.law.a(um)
            out[3][m] = sg.sign * sg.h / sg.beta**3 * sg.law.j(um)
        return Derivatives(th, *out)

    def svaj(self, theta, omega: float) -> SVAJ:
        """s (m), v (m/s), a (m/s^2), j (m/s^3) at constant cam speed ``omega`` (rad/s).

        .. math:: v = \\omega s', \\quad a = \\omega^2 s'', \\quad j = \\omega^3 s'''

        Parameters
        ----------
        theta : float or array_like
            Cam angles [rad], any shape, taken modulo 2 pi.
        omega : float
            Constant cam speed [rad/s], ``> 0``.

        Returns
        -------
        SVAJ
            ``s`` [m], ``v`` [m/s], ``a`` [m/s^2], ``j`` [m/s^3], each of the shape of ``theta``.

        Raises
        ------
        InputError
            ``theta`` not finite or ``omega <= 0``.
        """
        w = _validate.positive("omega", omega, "rad/s")
        d = self.derivatives(theta)
        return SVAJ(d.theta, d.s, w * d.s1, w**2 * d.s2, w**3 * d.s3, w)

    # --- junctions ---------------------------------------------------------------------
    def junctions(self, omega: float | None = None) -> list[Junction]:
        """One :class:`Junction` per join, in order, the last one being the wrap at 2 pi.

        Each carries the per-radian jumps ``jump_s1, jump_s2, jump_s3``; with the cam speed
        ``omega`` (rad/s) also the SI jumps ``jump_v = omega jump_s1`` (m/s),
        ``jump_a = omega^2 jump_s2`` (m/s^2) and ``jump_j = omega^3 jump_s3`` (m/s^3).

        Parameters
        ----------
        omega : float or None, optional
            Cam speed [rad/s], ``> 0``; None (default) for the per-radian jumps only.

        Returns
        -------
        list of Junction
            One per segment, junction ``k`` at the end of segment ``k``.
        """
        w = None if omega is None else _validate.positive("omega", omega, "rad/s")
        segs = self.segments
        n = len(segs)
        out = []
        for k in range(n):
            L, R = segs[k], segs[(k + 1) % n]
            jump = R.end_derivatives(0) - L.end_derivatives(1)
            tol = _JUMP_RTOL * np.maximum(L.scale(), R.scale())
            jump = np.where(np.abs(jump) <= tol, 0.0, jump)  # round-off, e.g. sin(2 pi)
            inf_a = bool(jump[0] != 0.0)
            th = (self._starts[k] + L.beta) % TWO_PI
            if TWO_PI - th <= 1e-9 * TWO_PI:  # segment sum a hair under 2 pi: the wrap join is 0
                th = 0.0
            out.append(Junction(theta=float(th),
                                left=L.name, right=R.name, jump_s1=float(jump[0]),
                                jump_s2=float(jump[1]), jump_s3=float(jump[2]),
                                infinite_acceleration=inf_a,
                                infinite_jerk=inf_a or bool(jump[1] != 0.0), index=k, omega=w))
        return out

    def table(self, omega: float | None = None) -> str:
        """Readable report: the segments, then the junctions (in SI at ``omega`` rad/s if given,
        else per radian).

        Parameters
        ----------
        omega : float or None, optional
            Cam speed [rad/s], ``> 0``; None (default) reports the jumps per radian.

        Returns
        -------
        str
            Segments (angles in deg, lift in mm) followed by :func:`junction_report`.
        """
        lines = ["Cam program (theta in deg, lift in mm):"]
        for k, (sg, th0, h0) in enumerate(zip(self.segments, self._starts, self._h0, strict=True)):
            end = h0 + sg.sign * sg.h
            lines.append(f"  {k + 1:2d}. {sg.name:28s} {degrees(th0):8.3f} -> "
                         f"{degrees(th0 + sg.beta):8.3f} deg, lift {h0 * 1e3:.4g} -> {end * 1e3:.4g} mm")
        lines.append(junction_report(self.junctions(omega)))
        return "\n".join(lines)

    def __str__(self):
        return self.table()
