r"""The elastic train of an oscillating (pivoted-arm) follower, referred to the roller's path,
and the rigid lift-off (jump) speed.

An arm turns about its pivot by one angle, so the **arc travel of the roller centre**
``s = L psi`` is an exact coordinate of its motion (no small-angle step): dividing the moment
balance about the pivot by ``L`` gives the translating follower's equation in ``s`` with

.. math::
    m = \frac{I}{L^2},\quad k_s = \frac{k_\psi}{L^2},\quad F_{pl} = \frac{M_{pl}}{L},\quad
    c_s = \frac{c_\psi}{L^2},\quad k_t = \frac{K_t}{L^2},\quad c_t = \frac{C_t}{L^2}

(a torsional stiffness ``K`` in N m/rad acts on ``s`` as ``K / L^2`` in N/m: the moment
``K psi = (K/L^2) s L``). The force these give is the force at the roller centre along its
path, ``F_axial = M / L``, and the normal contact force is ``F_axial / cos(phi)`` as for a
translating follower (``phi`` the angle between the contact normal and the roller path;
:func:`femcam.loads.arm_contact_force`). A scene's program of an oscillating follower already
holds ``s = L psi`` (m), so :func:`femcam.dynamics.periodic_response` and
:func:`femcam.dynamics.jump_speed` run on the referred train unchanged. Damping ratios are the
same in both coordinates (``c / (2 sqrt(k m))`` scales by ``L^-2 / L^-2``).

A sliding pad's friction force also has a moment about the pivot: the train's contact moment
``M_c = F_axial L`` then gives ``Fc = M_c / (L cos phi + s_f mu d_t)``
(:func:`femcam.loads.arm_lever`; :meth:`femcam.scene.Scene.analyse` applies it). The lever
``D`` is positive (a self-locking arm is refused), so the sign of ``Fc``, lift-off and the jump
speed are the train's.

The brief's equivalent mass ``I / (L cos phi)^2`` is the inertia referred along the contact
*normal*; along the roller *path*, where the train acts, it is ``I / L^2`` exactly and the
``cos phi`` enters once, in the normal force.

Symbols
-------
=========  ===========================================  =========  =========================
symbol     meaning                                      unit       source
=========  ===========================================  =========  =========================
I          arm inertia about the pivot                  kg m^2     [dynamics] arm_inertia_kg_m2
k_psi      torsional return spring                      N m/rad    spring_rate_N_m_per_rad
M_pl       preload moment at psi = 0                    N m        preload_N_m
c_psi      torsional damping to ground                  N m s/rad  damping_N_m_s_per_rad
K_t, C_t   torsional train stiffness, damping           N m/rad    train_stiffness_N_m_per_rad
I2, K2     second inertia (valve), its coupling         kg m^2     second_inertia_kg_m2
L          pivot to roller centre                       m          arm_length_mm
k, l, F    linear spring rate, its lever, preload       N/m, m, N  spring_N_per_m, spring_lever_mm
=========  ===========================================  =========  =========================

References
----------
* R. L. Norton, *Cam Design and Manufacturing Handbook*, 2nd ed., 2009, ch. 10 (lumped models,
  effective mass and stiffness referred through a rocker arm).
"""

from __future__ import annotations

import math

import numpy as np

from .. import _validate
from ..kinematics import CamProgram
from ..loads import ArmDynamics, FollowerDynamics
from .jump import RPM, _first_root
from .model import TrainModel


def _opt(name, x, unit):
    return None if x is None else _validate.nonnegative(name, x, unit)


def arm_follower(arm: ArmDynamics, L: float) -> FollowerDynamics:
    r"""The rigid arm referred to the roller centre's arc travel ``s = L psi``.

    .. math:: m = I/L^2,\ k = k_\psi/L^2,\ F_{pl} = M_{pl}/L,\ c = c_\psi/L^2

    Parameters
    ----------
    arm : ArmDynamics
        Inertia [kg m^2], torsional spring [N m/rad], preload moment [N m], damping
        [N m s/rad] about the pivot.
    L : float
        Arm length, pivot to roller centre [m], ``> 0``.

    Returns
    -------
    FollowerDynamics
        Mass [kg], spring [N/m], preload [N] and damping [N s/m] along the roller path.

    Examples
    --------
    >>> f = arm_follower(ArmDynamics(I=2.5e-4, k_t=100.0, M_pl=12.5), 0.035)
    >>> round(f.m, 6), round(f.k, 3), round(f.Fpl, 3)
    (0.204082, 81632.653, 357.143)
    """
    _validate.instance("arm", arm, ArmDynamics)
    L = _validate.positive("L", L, "m")
    return FollowerDynamics(m=arm.I / L**2, k=arm.k_t / L**2, Fpl=arm.M_pl / L, c=arm.c_t / L**2)


def arm_train(arm: ArmDynamics, L: float, *, K_t: float, C_t: float | None = None,
              zeta_t: float | None = None, I2: float | None = None, K2: float | None = None,
              C2: float | None = None, zeta2: float | None = None) -> TrainModel:
    r"""The elastic train of an arm (one_dof, or two_dof with ``I2``) in the arc travel ``s = L psi``.

    .. math:: k_t = K_t / L^2,\quad c_t = C_t / L^2,\quad m_2 = I_2 / L^2,\quad
              k_2 = K_2 / L^2,\quad c_2 = C_2 / L^2

    one_dof: the cam turns the train end by the rigid ``psi(theta)``; the torsional train
    ``K_t, C_t`` (roller, contact and finger compliance) drives the arm inertia ``I`` on its
    return spring. two_dof: a second inertia ``I2`` (the valve, referred to the pivot) hangs on
    the arm by ``K2, C2`` and carries the return spring. The train's axial force is ``M / L``.

    Parameters
    ----------
    arm : ArmDynamics
        Arm inertia [kg m^2] (``> 0``), return spring [N m/rad], preload [N m], damping
        [N m s/rad] to ground.
    L : float
        Arm length [m], ``> 0``.
    K_t : float
        Torsional train stiffness [N m/rad], ``> 0``.
    C_t : float or None, optional
        Torsional train damping [N m s/rad]; exactly one of ``C_t`` and ``zeta_t``.
    zeta_t : float or None, optional
        Train damping ratio [-].
    I2 : float or None, optional
        Second inertia about the pivot [kg m^2], ``> 0``; None (default): one_dof.
    K2 : float or None, optional
        Torsional stiffness between the arm and ``I2`` [N m/rad] (two_dof).
    C2 : float or None, optional
        Torsional damping between the arm and ``I2`` [N m s/rad]; exactly one of ``C2``, ``zeta2``.
    zeta2 : float or None, optional
        Damping ratio between the arm and ``I2`` [-].

    Returns
    -------
    TrainModel
        The referred train (masses [kg], stiffnesses [N/m], dampings [N s/m] along the path).

    Examples
    --------
    >>> tm = arm_train(ArmDynamics(I=2.5e-4, k_t=100.0, M_pl=12.5), 0.035, K_t=2450.0, zeta_t=0.05)
    >>> round(tm.k_t, 1)                        # 2450 N m/rad / (0.035 m)^2
    2000000.0
    """
    f = arm_follower(arm, L)
    L2 = _validate.positive("L", L, "m") ** 2
    K_t = _validate.positive("K_t", K_t, "N m/rad")
    C_t = _opt("C_t", C_t, "N m s/rad")
    sec = {}
    if I2 is not None or K2 is not None or C2 is not None or zeta2 is not None:
        I2 = _validate.positive("I2", I2, "kg m^2")
        K2 = _validate.positive("K2", K2, "N m/rad")
        C2 = _opt("C2", C2, "N m s/rad")
        sec = {"m2": I2 / L2, "k2": K2 / L2, "c2": None if C2 is None else C2 / L2, "zeta2": zeta2}
    return TrainModel(follower=f, k_t=K_t / L2, c_t=None if C_t is None else C_t / L2,
                      zeta_t=zeta_t, **sec)


def lever_spring(k: float, lever: float, Fpl: float) -> tuple:
    r"""A linear spring acting at ``lever`` from the pivot, perpendicular to the arm at
    ``psi = 0``, as the torsional spring of the arm (linearised in ``psi``).

    .. math:: k_\psi = k\,l^2,\qquad M_{pl} = F_{pl}\,l

    The exact moment of a spring whose end moves along a fixed line perpendicular to the arm
    at ``psi = 0`` is ``(F_pl + k l sin psi) l cos psi``; the linear form is its first-order
    Taylor term, off by ``F_pl l (1 - cos psi) ~ F_pl l psi^2/2`` and
    ``k l^2 (psi - sin psi cos psi) ~ (2/3) k l^2 psi^3`` (0.54 N m, 1.8 % of the moment, at the
    full 10 deg swing of examples/rff_valve_train.toml). femcam's arm is linear
    (:class:`~femcam.loads.ArmDynamics`), so this is what it models.

    Parameters
    ----------
    k : float
        Spring rate [N/m], ``>= 0``.
    lever : float
        Pivot to the spring's line of action [m], ``> 0``.
    Fpl : float
        Spring force at ``psi = 0`` [N], ``>= 0``.

    Returns
    -------
    (float, float)
        ``(k_psi, M_pl)``: torsional rate [N m/rad] and preload moment [N m].

    Examples
    --------
    >>> lever_spring(40e3, 0.05, 250.0)
    (100.00000000000001, 12.5)
    """
    k = _validate.nonnegative("k", k, "N/m")
    lever = _validate.positive("lever", lever, "m")
    Fpl = _validate.nonnegative("Fpl", Fpl, "N")
    return k * lever**2, Fpl * lever


def rigid_jump_speed(follower: FollowerDynamics, program: CamProgram, rpm_lo: float,
                     rpm_hi: float, *, n: int = 3600, n_scan: int = 40,
                     xtol_rpm: float = 1e-3) -> float:
    r"""Lowest speed in ``[rpm_lo, rpm_hi]`` (rpm) at which the rigid follower's axial force
    reaches zero somewhere (lift-off of eq. 11; NaN if none in the range).

    .. math:: \min_\theta \bigl(m \omega^2 s'' + c\,\omega s' + k s + F_{pl}\bigr) = 0

    For an arm pass :func:`arm_follower`: the axial force is the moment about the pivot over
    ``L`` and ``cos phi > 0``, so it vanishes where the contact force does.

    Parameters
    ----------
    follower : FollowerDynamics
        Mass [kg], spring [N/m], preload [N], damping [N s/m].
    program : CamProgram
        Cam program (lift [m] against cam angle [rad]).
    rpm_lo, rpm_hi : float
        Speed range [rpm], ``0 < rpm_lo < rpm_hi``.
    n : int, optional
        Cam angles over a revolution on which the minimum is taken. Default 3600.
    n_scan : int, optional
        Speeds scanned before the Brent refinement. Default 40.
    xtol_rpm : float, optional
        Absolute tolerance [rpm]. Default 1e-3.

    Returns
    -------
    float
        Lift-off speed [rpm], or NaN.

    Examples
    --------
    >>> from femcam.kinematics import CamProgram, dwell, fall, rise
    >>> q = math.pi / 2
    >>> prog = CamProgram([rise(q, 0.01), dwell(q), fall(q, 0.01), dwell(q)])
    >>> round(rigid_jump_speed(FollowerDynamics(m=0.2, k=800.0, Fpl=50.0, c=0.0), prog, 100, 3000), 1)
    1012.5
    """
    _validate.instance("follower", follower, FollowerDynamics)
    _validate.instance("program", program, CamProgram)
    lo = _validate.positive("rpm_lo", rpm_lo, "rpm")
    hi = _validate.positive("rpm_hi", rpm_hi, "rpm")
    if hi <= lo:
        raise _validate.fail("rpm_hi", rpm_hi, "rpm", f"must be > rpm_lo = {lo:g} rpm")
    n = _validate.integer("n", n, 16, "angles")
    n_scan = _validate.integer("n_scan", n_scan, 2, "speeds")
    xtol_rpm = _validate.positive("xtol_rpm", xtol_rpm, "rpm")
    d = program.derivatives(np.linspace(0.0, 2.0 * math.pi, n, endpoint=False))
    f = follower

    def fmin(rpm):
        w = rpm / RPM
        return float(np.min(f.m * w**2 * d.s2 + f.c * w * d.s1 + f.k * d.s + f.Fpl))

    x = np.linspace(lo, hi, n_scan)
    return _first_root(fmin, x, np.array([fmin(r) for r in x]), xtol_rpm)[0]
