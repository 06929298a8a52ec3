r"""Follower dynamics and the cam-follower contact force (seed 002 eq. 11).

A single-degree-of-freedom follower train: mass ``m`` held on the cam by a spring of rate
``k`` with preload ``Fpl`` and a viscous damper ``c``. With the follower rigidly following the
cam (s, v, a are the kinematic values at cam speed omega), the force along the follower axis
is ``m a + c v + k s + Fpl``; the cam pushes along the contact normal, which is tilted by the
pressure angle ``phi`` from the axis, so the normal contact force is that divided by cos phi.

Symbols
-------
======  =================================================  =============  =======================
symbol  meaning                                            unit           source
======  =================================================  =============  =======================
m       effective mass of the follower train               kg             seed 002 Table 1 (tracker)
k       spring rate ("equivalent rigidity")                N/m            seed 002 Table 1
Fpl     spring preload at s = 0                            N              seed 002 Table 1
c       viscous damping coefficient                        N s/m          seed 002 Table 1
zeta    damping ratio, c = zeta c_c, c_c = 2 sqrt(k m)     -              seed 002 Table 1 ("0.06 c_c")
s,v,a   follower lift, velocity, acceleration              m, m/s, m/s^2  femcam.kinematics
phi     pressure angle                                     rad            femcam.profile
Fc      normal contact force (> 0 pushes)                  N              seed 002 eq. 11
======  =================================================  =============  =======================

This is the rigid follower (scene ``[dynamics] model = "rigid"``, the default). An elastic
follower train (one_dof / two_dof, with contact loss and re-impact) is in
:mod:`femcam.dynamics`; its stiff-train limit is this eq. 11.

Seed 002 writes eq. 11 with theta-derivatives, ``(a m w^2 + v c w + s k + Fpl)/cos phi``;
with ``a = s'' w^2`` and ``v = s' w`` in time units it is the same expression as here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from . import _validate
from ._repr import compact_repr, span
from .errors import InputError, LiftOffError
from .profile import bool_intervals


@dataclass(frozen=True, kw_only=True)
class FollowerDynamics:
    """Mass ``m`` (kg), spring ``k`` (N/m), preload ``Fpl`` (N), damping ``c`` (N s/m) **or**
    damping ratio ``zeta`` (exactly one of them).

    ``zeta > 0`` needs ``k > 0`` and ``m > 0``: with ``c_c = 2 sqrt(k m) = 0`` a ratio cannot
    set ``c`` and :class:`~femcam.errors.InputError` asks for ``c`` instead (``zeta = 0`` is
    accepted and gives ``c = 0``).

    Parameters
    ----------
    m : float
        Effective mass of the follower train [kg], >= 0.
    k : float
        Spring rate [N/m], >= 0.
    Fpl : float
        Spring preload at s = 0 [N], >= 0.
    c : float or None, optional
        Viscous damping coefficient [N s/m], >= 0; set from ``zeta`` when None.
    zeta : float or None, optional
        Damping ratio c / c_c [-], >= 0; set from ``c`` when None (inf for ``c > 0`` with
        ``c_c = 0``).

    Raises
    ------
    InputError
        A negative value, both or neither of ``c`` and ``zeta``, or ``zeta > 0`` with ``c_c = 0``.

    >>> round(FollowerDynamics(m=0.2, k=800.0, Fpl=1500.0, zeta=0.06).c, 6)
    1.517893
    """

    m: float
    k: float
    Fpl: float
    c: float | None = None
    zeta: float | None = None

    def __post_init__(self):
        object.__setattr__(self, "m", _validate.nonnegative("m", self.m, "kg"))
        object.__setattr__(self, "k", _validate.nonnegative("k", self.k, "N/m"))
        object.__setattr__(self, "Fpl", _validate.nonnegative("Fpl", self.Fpl, "N"))
        if (self.c is None) == (self.zeta is None):
            raise InputError(f"c = {self.c!r} N s/m, zeta = {self.zeta!r}: give exactly one of the "
                             "damping coefficient c or the damping ratio zeta")
        if self.zeta is not None:
            zeta = _validate.nonnegative("zeta", self.zeta, "")
            if zeta > 0.0 and self.c_critical == 0.0:
                raise InputError(
                    f"zeta (damping_ratio) = {zeta:g}: the critical damping c_c = 2 sqrt(k m) = "
                    f"2 sqrt({self.k:g} N/m * {self.m:g} kg) = 0 N s/m, so a damping ratio cannot set "
                    "the damping; give the damping coefficient c in N s/m instead "
                    "(scene key damping_N_s_per_m)")
            object.__setattr__(self, "zeta", zeta)
            object.__setattr__(self, "c", zeta * self.c_critical)
        else:
            c = _validate.nonnegative("c", self.c, "N s/m")
            object.__setattr__(self, "c", c)
            cc = self.c_critical
            object.__setattr__(self, "zeta", c / cc if cc > 0 else math.inf if c > 0 else 0.0)

    @property
    def c_critical(self) -> float:
        r"""Critical damping :math:`c_c = 2\sqrt{k m}` (N s/m)."""
        return 2.0 * math.sqrt(self.k * self.m)

    @property
    def natural_frequency(self) -> float:
        r""":math:`\omega_n = \sqrt{k/m}` (rad/s); inf for a massless follower."""
        return math.sqrt(self.k / self.m) if self.m > 0 else math.inf


@dataclass(frozen=True)
class LoadResult:
    """Contact force along the cam cycle.

    ``F_axial`` is the force along the follower axis ``m a + c v + k s + Fpl`` (N), ``Fc`` the
    normal contact force (N); ``liftoff`` flags ``Fc <= 0`` (the spring cannot keep the
    follower on the cam); ``liftoff_angles`` are the flagged theta (rad) and
    ``liftoff_intervals`` their contiguous runs ``[(start, end), ...]`` (rad, grid order).

    Parameters
    ----------
    theta : ndarray, shape (n,)
        Cam angles [rad] (the broadcast shape of the inputs; shape (n,) for a cam-angle grid).
    Fc : ndarray, shape (n,)
        Normal contact force [N].
    F_axial : ndarray, shape (n,)
        Force along the follower axis, ``m a + c v + k s + Fpl`` [N].
    F_inertia : ndarray, shape (n,)
        Inertia term ``m a`` [N].
    F_damping : ndarray, shape (n,)
        Damping term ``c v`` [N].
    F_spring : ndarray, shape (n,)
        Spring term ``k s + Fpl`` [N].
    liftoff : ndarray of bool, shape (n,)
        True where ``Fc <= 0``.
    liftoff_angles : ndarray, shape (m,)
        The flagged ``theta`` [rad].
    liftoff_intervals : list of (float, float)
        Contiguous lift-off runs ``(start, end)`` [rad], in grid order.
    """

    theta: np.ndarray
    Fc: np.ndarray
    F_axial: np.ndarray
    F_inertia: np.ndarray
    F_damping: np.ndarray
    F_spring: np.ndarray
    liftoff: np.ndarray
    liftoff_angles: np.ndarray
    liftoff_intervals: list = field(default_factory=list)

    def __repr__(self) -> str:
        """The angles, the Fc range and the lift-off count (a compact line)."""
        return compact_repr(self, [
            f"{self.theta.size} angles",
            f"Fc {span(self.Fc, 1.0, 'N')}",
            f"lift-off {int(np.count_nonzero(self.liftoff))}",
        ])

    @property
    def any_liftoff(self) -> bool:
        """True if the follower lifts off at any angle (``Fc <= 0`` somewhere)."""
        return bool(np.any(self.liftoff))

    @property
    def Fc_max(self) -> float:
        """Largest contact force over the cycle [N] (0 for an empty result)."""
        return float(np.max(self.Fc)) if self.Fc.size else 0.0

    @property
    def Fc_min(self) -> float:
        """Smallest contact force over the cycle [N] (0 for an empty result)."""
        return float(np.min(self.Fc)) if self.Fc.size else 0.0


_LIFTOFF_MODES = ("flag", "raise")


def contact_force(dyn: FollowerDynamics, theta, s, v, a, phi, *,
                  on_liftoff: str = "flag") -> LoadResult:
    r"""Normal cam-follower contact force (N), seed 002 eq. 11.

    .. math:: F_c = \frac{m a + c v + k s + F_{pl}}{\cos\varphi}

    ``theta`` (rad), ``s`` (m), ``v`` (m/s), ``a`` (m/s^2) and ``phi`` (rad, ``|phi|`` < 90 deg)
    broadcast together. Lift-off (``Fc <= 0``) is flagged in the result
    (``on_liftoff="flag"``, the default) or, with ``on_liftoff="raise"``, raises
    :class:`~femcam.errors.LiftOffError` listing the lift-off intervals in degrees and the
    smallest ``Fc``.

    Parameters
    ----------
    dyn : FollowerDynamics
        Mass, spring, preload and damping of the follower train.
    theta : float or ndarray
        Cam angle [rad].
    s : float or ndarray
        Follower lift [m].
    v : float or ndarray
        Follower velocity [m/s].
    a : float or ndarray
        Follower acceleration [m/s^2].
    phi : float or ndarray
        Pressure angle [rad], ``|phi|`` < pi/2.
    on_liftoff : {"flag", "raise"}, optional
        Flag lift-off in the result (default) or raise :class:`~femcam.errors.LiftOffError`.

    Returns
    -------
    LoadResult
        Contact force and its terms [N], float arrays of the broadcast shape of the inputs.

    Raises
    ------
    InputError
        Non-finite input, ``|phi|`` >= 90 deg, or shapes that do not broadcast.
    LiftOffError
        ``Fc <= 0`` somewhere with ``on_liftoff="raise"``.

    >>> r = contact_force(FollowerDynamics(m=0.2, k=800.0, Fpl=1500.0, c=0.0),
    ...                   0.0, 0.01, 0.0, 100.0, 0.0)
    >>> float(r.Fc)    # 0.2*100 + 800*0.01 + 1500
    1528.0
    """
    if not isinstance(dyn, FollowerDynamics):
        raise InputError(f"dyn = {dyn!r}: must be a FollowerDynamics")
    _validate.choice("on_liftoff", on_liftoff, _LIFTOFF_MODES)
    theta = _validate.finite_array("theta", theta, "rad")
    s = _validate.finite_array("s", s, "m")
    v = _validate.finite_array("v", v, "m/s")
    a = _validate.finite_array("a", a, "m/s^2")
    phi = _validate.finite_array("phi", phi, "rad")
    if np.any(np.abs(phi) >= 0.5 * math.pi):
        bad = float(phi[np.abs(phi) >= 0.5 * math.pi].flat[0])
        raise _validate.fail("phi", bad, "rad", f"pressure angle ({math.degrees(bad):.4g} deg) must satisfy "
                             "|phi| < 90 deg")
    try:
        theta, s, v, a, phi = (np.array(x, dtype=float) for x in np.broadcast_arrays(theta, s, v, a, phi))
    except ValueError:
        raise InputError("theta, s, v, a, phi: shapes must broadcast together") from None
    F_in = dyn.m * a
    F_d = dyn.c * v
    F_s = dyn.k * s + dyn.Fpl
    F_ax = F_in + F_d + F_s
    Fc = F_ax / np.cos(phi)
    lift = Fc <= 0.0
    intervals = bool_intervals(theta, lift)
    if intervals and on_liftoff == "raise":
        iv = ", ".join(f"[{math.degrees(p):.2f}, {math.degrees(q):.2f}] deg" for p, q in intervals)
        i = int(np.argmin(Fc))
        raise LiftOffError(
            f"the follower lifts off the cam (Fc <= 0) for theta in {iv}; smallest Fc = "
            f"{float(Fc.flat[i]):.4g} N at theta = {math.degrees(float(theta.flat[i])):.2f} deg. "
            f"Raise the spring rate k (now {dyn.k:g} N/m) or preload Fpl (now {dyn.Fpl:g} N), or "
            "lower the speed; on_liftoff='flag' returns the flagged result")
    return LoadResult(theta=theta, Fc=Fc, F_axial=F_ax, F_inertia=F_in, F_damping=F_d, F_spring=F_s,
                      liftoff=lift, liftoff_angles=theta[lift], liftoff_intervals=intervals)


# --------------------------------------------------------------------------------------------
# oscillating arm (femcam.profile.oscillating): moment balance about the pivot
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True, kw_only=True)
class ArmDynamics:
    """Rigid oscillating arm: inertia ``I`` about the pivot (kg m^2), torsional spring ``k_t``
    (N m/rad), preload moment ``M_pl`` at psi = 0 (N m), torsional damping ``c_t`` (N m s/rad).

    Parameters
    ----------
    I : float
        Arm (and roller, valve referred to the pivot) inertia about the pivot [kg m^2], >= 0.
    k_t : float
        Torsional spring rate [N m/rad], >= 0.
    M_pl : float
        Spring preload moment at psi = 0 [N m], >= 0.
    c_t : float, optional
        Torsional viscous damping [N m s/rad], >= 0. Default 0.

    Raises
    ------
    InputError
        A negative or non-finite value.

    >>> ArmDynamics(I=1e-5, k_t=20.0, M_pl=5.0).c_t
    0.0
    """

    I: float
    k_t: float
    M_pl: float
    c_t: float = 0.0

    def describe(self) -> str:
        """One line of the arm dynamics (``femcam run`` prints it).

        Returns
        -------
        str
            Inertia, spring rate, preload moment and damping with their units.
        """
        return (f"I = {self.I:g} kg m^2, k_t = {self.k_t:g} N m/rad, M_pl = {self.M_pl:g} N m, "
                f"c_t = {self.c_t:g} N m s/rad")

    def __post_init__(self):
        for name, unit in (("I", "kg m^2"), ("k_t", "N m/rad"), ("M_pl", "N m"), ("c_t", "N m s/rad")):
            object.__setattr__(self, name, _validate.nonnegative(name, getattr(self, name), unit))


def arm_lever(L, phi, *, mu=0.0, friction_lever=0.0, theta=0.0) -> np.ndarray:
    r"""Moment about the pivot of a unit normal contact force with its friction (m).

    .. math:: D = L\cos\varphi + \mu\, s_f d_t

    ``s_f d_t`` is the follower's signed friction lever
    (:meth:`femcam.profile.OscillatingPadFollower.friction_lever`; 0 for a roller, whose
    rolling traction is left out), so the moment balance reads ``Fc D = I psi'' + c psi' +
    k psi + M_pl``. Where ``D <= 0`` the friction moment beats the normal force's: no contact
    force can drive the arm (self-locking), and the geometry is refused.

    Parameters
    ----------
    L : float
        Arm length, pivot to roller or pad centre [m], ``> 0``.
    phi : float or ndarray
        Pressure angle [rad], ``|phi| < 90 deg``.
    mu : float, optional
        Friction coefficient [-], ``>= 0`` (scene key ``[contact] friction``). Default 0.
    friction_lever : float or ndarray, optional
        ``s_f d_t`` [m], signed. Default 0.
    theta : float or ndarray, optional
        Cam angle [rad], only to name the self-locking angle in the message. Default 0.

    Returns
    -------
    ndarray
        ``D`` [m], ``> 0``, the broadcast shape.

    Raises
    ------
    InputError
        Non-finite input, ``L <= 0``, ``mu < 0``, or ``D <= 0`` (self-locking; the message names
        ``mu``, the scene key ``[contact] friction``, the angle and the levers).

    >>> float(arm_lever(0.04, 0.0, mu=0.1, friction_lever=-0.02))   # 0.04 - 0.1 * 0.02
    0.038
    """
    L = _validate.positive("L", L, "m")
    mu = _validate.nonnegative("mu", mu, "")
    arrs = [_validate.finite_array(n, x, u) for n, x, u in (
        ("phi", phi, "rad"), ("friction_lever", friction_lever, "m"), ("theta", theta, "rad"))]
    try:
        phi, lev, theta = (np.array(x, float) for x in np.broadcast_arrays(*arrs))
    except ValueError:
        raise InputError("phi, friction_lever, theta: shapes must broadcast together") from None
    D = L * np.cos(phi) + mu * lev
    if np.any(D <= 0.0):
        i = int(np.argmin(D))
        raise _validate.fail(
            "mu", mu, "(dimensionless)", "self-locking arm (scene key [contact] friction) at theta = "
            f"{math.degrees(float(theta.flat[i])):.2f} deg: the friction moment per N of Fc, mu * "
            f"friction_lever (s_f d_t) = {mu:g} * {float(lev.flat[i]) * 1e3:.4g} mm, cancels the normal "
            f"force's L cos(phi) = {L * math.cos(float(phi.flat[i])) * 1e3:.4g} mm, so no contact force "
            "can drive the arm; lower the friction coefficient or change the pivot, arm length or pad radius")
    return D


def arm_contact_force(dyn: ArmDynamics, theta, psi, psi_dot, psi_ddot, L, phi, *, mu=0.0,
                      friction_lever=0.0) -> LoadResult:
    r"""Normal contact force on an oscillating arm from the moment balance about the pivot.

    .. math:: F_c\,\left(L \cos\varphi + \mu\,s_f d_t\right) = I \ddot\psi + c_t \dot\psi + k_t \psi + M_{pl}

    The contact force acts along the cam normal through the roller (or pad) centre; its moment
    about the pivot in the sense of ``psi`` is ``Fc L cos(phi)`` (virtual work: the roller centre
    moves ``L dpsi`` along ``u``, and ``u . n = cos phi``; Norton, *Cam Design and Manufacturing
    Handbook* (2009) ch. 8). A sliding pad adds the friction force's moment ``mu Fc s_f d_t``
    (:func:`arm_lever`; ``friction_lever = s_f d_t`` from the follower's ``friction_lever``; 0,
    the default, is the frictionless balance). ``F_axial`` etc. of the result are the moments
    divided by ``L`` (the force at the roller centre along its path, N), so
    ``Fc = F_axial L / D``. Lift-off: ``Fc <= 0`` (``D > 0``, so where the moment is).

    Parameters
    ----------
    dyn : ArmDynamics
        Inertia, spring, preload and damping of the arm.
    theta : float or ndarray
        Cam angle [rad].
    psi, psi_dot, psi_ddot : float or ndarray
        Arm angle [rad], angular velocity [rad/s] and acceleration [rad/s^2].
    L : float
        Arm length, pivot to roller centre [m], > 0.
    phi : float or ndarray
        Pressure angle [rad], ``|phi| < 90 deg``.
    mu : float, optional
        Friction coefficient [-], ``>= 0``. Default 0.
    friction_lever : float or ndarray, optional
        Signed friction lever ``s_f d_t`` [m]. Default 0.

    Returns
    -------
    LoadResult
        Contact force [N] and its terms, the broadcast shape of the inputs.

    Raises
    ------
    InputError
        Non-finite input, ``L <= 0``, ``|phi| >= 90 deg``, ``mu < 0`` or a self-locking arm
        (:func:`arm_lever`).

    >>> r = arm_contact_force(ArmDynamics(I=1e-5, k_t=20.0, M_pl=5.0), 0.0, 0.1, 0.0, 1e4, 0.04, 0.0)
    >>> round(float(r.Fc), 9)    # (1e-5 * 1e4 + 20 * 0.1 + 5) / 0.04
    177.5
    """
    if not isinstance(dyn, ArmDynamics):
        raise InputError(f"dyn = {dyn!r}: must be an ArmDynamics")
    L = _validate.positive("L", L, "m")
    arrs = [_validate.finite_array(n, x, u) for n, x, u in (
        ("theta", theta, "rad"), ("psi", psi, "rad"), ("psi_dot", psi_dot, "rad/s"),
        ("psi_ddot", psi_ddot, "rad/s^2"), ("phi", phi, "rad"))]
    theta, psi, psi_dot, psi_ddot, phi = (np.array(x, float) for x in np.broadcast_arrays(*arrs))
    if np.any(np.abs(phi) >= 0.5 * math.pi):
        bad = float(phi[np.abs(phi) >= 0.5 * math.pi].flat[0])
        raise _validate.fail("phi", bad, "rad", "pressure angle must satisfy |phi| < 90 deg")
    arm_lever(L, phi, mu=mu, friction_lever=friction_lever, theta=theta)   # refuses self-locking
    F_in, F_d = dyn.I * psi_ddot / L, dyn.c_t * psi_dot / L
    F_s = (dyn.k_t * psi + dyn.M_pl) / L
    F_ax = F_in + F_d + F_s
    # D / L written so that mu = 0 divides by cos(phi) itself (the frictionless Fc to the bit)
    Fc = F_ax / (np.cos(phi) + float(mu) * np.asarray(friction_lever, float) / L)
    theta = np.broadcast_to(theta, Fc.shape)
    lift = Fc <= 0.0
    return LoadResult(theta=theta, Fc=Fc, F_axial=F_ax, F_inertia=F_in, F_damping=F_d, F_spring=F_s,
                      liftoff=lift, liftoff_angles=theta[lift], liftoff_intervals=bool_intervals(theta, lift))
