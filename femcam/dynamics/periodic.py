r"""Periodic steady state of a follower train driven by a cam program at constant speed.

Without contact loss the train is linear, and the periodic solution is found directly: one
pass from rest gives the particular end state ``z_N``, the transition matrix over the cycle
``Phi^N`` (monodromy) gives the free part, and the periodic start is

.. math:: z_0 = (I - \Phi^N)^{-1} z_N^{\text{rest}}

(exact up to round-off; ``cycles = 1``). If that solution's trial contact force turns
negative, the contact is unilateral and the problem nonlinear: whole cycles are integrated
with free flight and re-impact (:func:`femcam.dynamics.model.march`) from that start until
the state changes by less than ``tol`` over a cycle (scaled by the lift and the peak rigid
velocity); ``cycles`` and ``residual`` are reported, and ``converged`` is False (with the
reason) when ``max_cycles`` pass first (e.g. an undamped train that keeps bouncing, or a
period-doubled motion).

Symbols
-------
======  ==============================================  =======  ======================
symbol  meaning                                         unit     source
======  ==============================================  =======  ======================
z       state (e, e') of the train, e = x - s           m, m/s   femcam.dynamics.model
Phi     one-step transition of the contact mode         -        exact (modal)
N       time steps per revolution                       -        choose_steps
P(z)    state after one cycle from z (cycle map)        m, m/s   shooting (Norton 2009 ch. 10)
tol     periodicity tolerance, scaled by lift, max |v|  -
======  ==============================================  =======  ======================
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .. import _validate
from .._repr import compact_repr, dataframe, span
from ..errors import InputError
from ..kinematics import CamProgram
from ..loads import LoadResult
from ..profile import bool_intervals
from .model import Mode, TrainModel, check_resolution, march

#: default (and least) number of time steps per revolution
DEFAULT_STEPS = 3600
#: most steps per revolution, chosen automatically or given, before the problem is refused
MAX_STEPS = 400_000
#: memory of a periodic response per time step (bytes): peak 138 MB at 100,000 and 197 MB at
#: 400,000 steps per revolution (one_dof, seed 002), ~200 B per step; MAX_STEPS is ~80 MB
BYTES_PER_STEP = 200


@dataclass(frozen=True)
class DynamicsResult:
    """Periodic response on ``theta`` (N+1 angles, rad, 0..2 pi; last = first).

    ``e`` and ``ed`` (N+1, ndof) are the displacement (m) and velocity (m/s) errors ``x - s``
    of each mass; ``Fc_axial`` the axial contact force (N, 0 in free flight), ``contact``
    the contact flags, ``Fc_rigid_axial`` eq. 11's axial force with the total train mass.
    Diagnostics: ``cycles`` integrated, ``residual`` (scaled state change over the last
    cycle), ``converged``, ``n_events`` (lift-offs + re-impacts in the last cycle),
    ``message``.

    Attributes
    ----------
    model : {"one_dof", "two_dof"}
        Train model.
    omega : float
        Cam speed [rad/s].
    theta : ndarray, shape (N+1,)
        Cam angles [rad], uniform on ``[0, 2 pi]``.
    s : ndarray, shape (N+1,)
        Rigid lift [m].
    v : ndarray, shape (N+1,)
        Rigid follower velocity [m/s].
    a : ndarray, shape (N+1,)
        Rigid follower acceleration [m/s^2].
    e : ndarray, shape (N+1, ndof)
        Displacement error ``x - s`` of each mass [m].
    ed : ndarray, shape (N+1, ndof)
        Velocity error of each mass [m/s].
    Fc_axial : ndarray, shape (N+1,)
        Axial contact force [N], ``>= 0`` (0 in free flight).
    contact : ndarray of bool, shape (N+1,)
        In contact at each angle.
    Fc_rigid_axial : ndarray, shape (N+1,)
        Axial force of the rigid eq. 11 with the total train mass [N] (may be negative).
    natural_frequencies : ndarray, shape (ndof,)
        Undamped natural frequencies in contact [rad/s], ascending.
    steps_per_rev : int
        Time steps per revolution ``N``.
    cycles : int
        Cycles integrated (1 for the linear periodic solution).
    residual : float
        Scaled state change over the last cycle [-].
    converged : bool
        A stable periodic steady state was found.
    n_events : int
        Lift-offs plus re-impacts in the last cycle.
    message : str
        How the answer was obtained, or why it did not converge.
    params : dict
        ``k_s`` [N/m], ``c_s`` [N s/m], ``Fpl`` [N], ``k_t`` [N/m], ``c_t`` [N s/m].
    """

    model: str
    omega: float
    theta: np.ndarray
    s: np.ndarray
    v: np.ndarray
    a: np.ndarray
    e: np.ndarray
    ed: np.ndarray
    Fc_axial: np.ndarray
    contact: np.ndarray
    Fc_rigid_axial: np.ndarray
    natural_frequencies: np.ndarray
    steps_per_rev: int
    cycles: int
    residual: float
    converged: bool
    n_events: int
    message: str = ""
    params: dict = field(default_factory=dict)

    def csv_columns(self) -> dict:
        """The response per time step of one revolution as the columns of ``dynamics.csv``:
        ``theta_deg``, ``s_mm``, ``Fc_rigid_N``, ``Fc_N`` (axial), ``liftoff`` (bool) and
        ``error_mass<i>_um`` (``x_i - s``) per mass; the closing step (theta = 2 pi) is left out.

        Returns
        -------
        dict[str, ndarray]
            Column name (unit in the name) -> values, shape (steps_per_rev,).
        """
        n = self.theta.size - 1
        cols = {"theta_deg": np.degrees(self.theta[:n]), "s_mm": self.s[:n] * 1e3,
                "Fc_rigid_N": self.Fc_rigid_axial[:n], "Fc_N": self.Fc_axial[:n],
                "liftoff": ~np.asarray(self.contact[:n], bool)}
        cols.update({f"error_mass{i + 1}_um": self.e[:n, i] * 1e6 for i in range(self.e.shape[1])})
        return cols

    def to_dataframe(self):
        """:meth:`csv_columns` as a ``pandas.DataFrame`` (one row per time step).

        Returns
        -------
        pandas.DataFrame

        Raises
        ------
        ImportError
            pandas is not installed (femcam does not require it).
        """
        return dataframe(self.csv_columns(), "DynamicsResult.to_dataframe")

    def __repr__(self) -> str:
        """Model, speed, convergence and the Fc range (a compact line)."""
        return compact_repr(self, [
            self.model,
            f"{self.omega * 30 / np.pi:.6g} rpm",
            f"{self.steps_per_rev} steps/rev",
            f"Fc {span(self.Fc_axial, 1.0, 'N')}",
            f"converged {self.converged}",
            f"lift-off {int(np.count_nonzero(~np.asarray(self.contact, bool)))} steps",
        ])

    @property
    def rpm(self) -> float:
        """Cam speed (rpm)."""
        return self.omega * 30.0 / math.pi

    @property
    def t(self) -> np.ndarray:
        """Time (s) of each grid angle."""
        return self.theta / self.omega

    @property
    def liftoff(self) -> np.ndarray:
        """True where the train is off the cam (free flight), shape (N+1,)."""
        return ~self.contact

    @property
    def any_liftoff(self) -> bool:
        """True if the contact is lost anywhere in the cycle."""
        return bool(np.any(~self.contact))

    @property
    def Fc_max(self) -> float:
        """Peak axial contact force (N)."""
        return float(np.max(self.Fc_axial))

    @property
    def Fc_min(self) -> float:
        """Least axial contact force (N); 0 with lift-off."""
        return float(np.min(self.Fc_axial))

    @property
    def max_error(self) -> float:
        """Largest ``|x - s|`` of the last mass (m): the displacement error against the rigid lift."""
        return float(np.max(np.abs(self.e[:, -1])))

    @property
    def dwell_vibration(self) -> float:
        """Largest half peak-to-peak of the last mass's error ``e`` (m) within one dwell: the
        residual vibration (0 without dwells)."""
        dw = (self.v == 0.0) & (self.a == 0.0)
        best, i, n = 0.0, 0, dw.size
        while i < n:
            if not dw[i]:
                i += 1
                continue
            j = i
            while j < n and dw[j]:
                j += 1
            seg = self.e[i:j, -1]
            best = max(best, 0.5 * float(seg.max() - seg.min()))
            i = j
        return best

    def at(self, theta):
        """Axial contact force (N) interpolated to cam angles ``theta`` (rad, mod 2 pi).

        Parameters
        ----------
        theta : float or array_like
            Cam angles [rad], any shape, taken modulo 2 pi.

        Returns
        -------
        ndarray
            Axial contact force [N] (linear interpolation), the shape of ``theta``.
        """
        th = np.mod(np.asarray(theta, float), 2.0 * math.pi)
        return np.interp(th, self.theta, self.Fc_axial)

    def load_result(self, theta, phi) -> LoadResult:
        """A :class:`~femcam.loads.LoadResult` at ``theta`` (rad) with pressure angles ``phi``
        (rad): ``Fc = Fc_axial / cos phi``, ``liftoff`` where ``Fc <= 0`` (free flight).

        Parameters
        ----------
        theta : array_like, shape (m,)
            Cam angles [rad], taken modulo 2 pi for the interpolation.
        phi : float or array_like, shape (m,)
            Pressure angles [rad] at ``theta``.

        Returns
        -------
        LoadResult
            Normal force ``Fc`` and the axial, spring, damping and inertia forces [N] of the
            last mass at ``theta``, with the lift-off flags and intervals.
        """
        theta = np.asarray(theta, float)
        th = np.mod(theta, 2.0 * math.pi)
        F_ax = np.interp(th, self.theta, self.Fc_axial)
        p = self.params
        x = np.interp(th, self.theta, self.s + self.e[:, -1])
        xd = np.interp(th, self.theta, self.v + self.ed[:, -1])
        F_s = p["k_s"] * x + p["Fpl"]
        F_d = p["c_s"] * xd
        Fc = F_ax / np.cos(np.asarray(phi, float))
        lift = Fc <= 0.0
        return LoadResult(theta=theta, Fc=Fc, F_axial=F_ax, F_inertia=F_ax - F_s - F_d, F_damping=F_d,
                          F_spring=F_s, liftoff=lift, liftoff_angles=theta[lift],
                          liftoff_intervals=bool_intervals(theta, lift))


def _steps_per_rev(steps_per_rev) -> int:
    """A requested step count: a whole number >= 16 (``720.0`` is accepted as 720)."""
    N = int(_validate.positive("steps_per_rev", steps_per_rev, ""))
    if N != steps_per_rev or N < 16:
        raise _validate.fail("steps_per_rev", steps_per_rev, "", "must be a whole number >= 16")
    return N


def choose_steps(train: TrainModel, omega: float, steps_per_rev=None) -> int:
    """Steps per revolution: the given number if it resolves the train (else InputError with
    the numbers), or ``DEFAULT_STEPS`` raised to the resolving count when that is larger.

    Parameters
    ----------
    train : TrainModel
        The follower train.
    omega : float
        Cam speed [rad/s], ``> 0``.
    steps_per_rev : int or None, optional
        Requested steps per revolution (a whole number ``>= 16``); None (default) chooses.

    Returns
    -------
    int
        Time steps per revolution.

    Raises
    ------
    InputError
        The requested count is not a whole number ``>= 16``, exceeds ``MAX_STEPS`` (the
        message gives the memory it would need) or does not resolve the train, or more than
        ``MAX_STEPS`` would be needed.
    """
    if steps_per_rev is not None:
        N = _steps_per_rev(steps_per_rev)
        if N > MAX_STEPS:  # refused before any array is allocated
            raise _validate.fail("steps_per_rev", steps_per_rev, "(time steps per revolution)",
                                 f"needs ~{N * BYTES_PER_STEP / 1e9:.3g} GB of per-step arrays "
                                 f"(~{BYTES_PER_STEP} B per step), above the cap of {MAX_STEPS:,} "
                                 f"steps (~{MAX_STEPS * BYTES_PER_STEP / 1e6:.0f} MB, "
                                 "femcam.dynamics.periodic.MAX_STEPS); give fewer steps "
                                 "([dynamics] steps_per_rev) or leave it unset")
        why = check_resolution(train, omega, N)
        if why:
            raise InputError(why + "; give more steps or leave steps_per_rev unset")
        return N
    N = DEFAULT_STEPS
    for _ in range(3):
        why = check_resolution(train, omega, N)
        if why is None:
            return N
        N = int(why.rsplit(">= ", 1)[1].rstrip(")"))
        if N > MAX_STEPS:
            raise InputError(f"{why}: more than {MAX_STEPS} steps per revolution. The train is so "
                             "stiff and lightly damped that it rings far above the cam harmonics; "
                             "use model = 'rigid' (its stiff-train limit is eq. 11) or give the "
                             "train some damping")
    return N  # pragma: no cover - the resolving count always passes the check


def _check_follows(train: TrainModel, omega: float) -> None:
    w1 = float(train.natural_frequencies[0])
    if w1 <= omega:
        raise InputError(
            f"k_t ([dynamics] train_stiffness_N_per_m) = {train.k_t:g} N/m: the lowest natural "
            "frequency of the train in contact, "
            f"{w1 / (2 * math.pi):.4g} Hz ({w1:.4g} rad/s), is at or below the camshaft frequency "
            f"{omega / (2 * math.pi):.4g} Hz ({omega * 30 / math.pi:.6g} rpm): every cam harmonic "
            "drives the train above resonance and the follower cannot follow the lift. Stiffen "
            "the train (train_stiffness_N_per_m) or lighten the masses (mass_kg, second_mass_kg)")


def _setup(train, program, omega, N):
    """Grid, rigid kinematics, inputs ``U = (a, g)`` and the two modes at N steps/rev."""
    h = 2.0 * math.pi / (omega * N)
    theta = np.linspace(0.0, 2.0 * math.pi, N + 1)
    d = program.derivatives(theta)
    s, v, a = d.s, omega * d.s1, omega**2 * d.s2
    f = train.follower
    g = f.k * s + f.c * v + f.Fpl
    modes = {c: Mode(*train.state_space(c), h) for c in (True, False)}
    return theta, s, v, a, g, np.column_stack([a, g]), modes


def linear_periodic(train, modes, U, omega):
    """States of the always-in-contact periodic solution on the grid of ``U`` (exact).

    Parameters
    ----------
    train : TrainModel
        The follower train.
    modes : dict of bool to Mode
        ``{True: contact mode, False: free-flight mode}``; only the contact mode is used.
    U : ndarray, shape (N+1, 2)
        Inputs ``(a [m/s^2], g [N])`` over one revolution.
    omega : float
        Cam speed [rad/s] (for the error message).

    Returns
    -------
    ndarray, shape (N+1, 2n)
        Periodic states ``(e [m], e' [m/s])``.

    Raises
    ------
    InputError
        An undamped train in exact resonance with a cam harmonic.
    """
    N, n2 = U.shape[0] - 1, 2 * train.ndof
    rest = modes[True].run(np.zeros(n2), U)[-1]
    IM = np.eye(n2) - modes[True].power(N)
    if np.linalg.cond(IM) > 1e12:
        raise InputError(
            f"omega = {omega:g} rad/s: the undamped train (natural frequencies "
            f"{np.array2string(train.natural_frequencies, precision=6)} rad/s) is in exact "
            "resonance with a cam harmonic, so no periodic response exists; add train damping")
    return modes[True].run(np.linalg.solve(IM, rest), U)


#: fixed-point cycles before the Newton (shooting) iterations start
SETTLE_CYCLES = 3
#: Newton steps after which a motion that still does not repeat is reported as not periodic
MAX_NEWTON = 20


def _iterate_cycles(train, modes, U, z0, scale, tol, max_cycles):
    """Periodic start of the unilateral problem: a few whole cycles (fixed point of the cycle
    map P), then Newton shooting on ``P(z) - z = 0`` with a finite-difference Jacobian,
    falling back to a fixed-point cycle whenever a Newton step does not lower the residual.
    A periodic motion whose Floquet multipliers (eigenvalues of dP/dz) exceed 1 is unstable,
    never observed, and reported as not converged. Counts every integrated cycle."""
    cycles = 0

    def P(z):
        nonlocal cycles
        cycles += 1
        return march(train, modes, U, z, bool(train.trial_force(z) > 0.0))

    n2 = z0.size
    Z, C, events = P(z0)
    residual = float(np.max(np.abs(Z[-1] - z0) / scale))
    z, J, newton = z0, None, 0
    while residual >= tol and cycles < max_cycles and newton < MAX_NEWTON:
        if cycles <= SETTLE_CYCLES:
            cand = Z[-1]
        else:
            J = np.column_stack([(P(z + 1e-7 * scale[i] * np.eye(n2)[i])[0][-1] - Z[-1])
                                 / (1e-7 * scale[i]) for i in range(n2)])
            cand, newton = z - np.linalg.lstsq(J - np.eye(n2), Z[-1] - z, rcond=None)[0], newton + 1
        Zc, Cc, ec = P(cand)
        rc = float(np.max(np.abs(Zc[-1] - cand) / scale))
        if rc >= residual and cycles > SETTLE_CYCLES + 1:  # Newton did not help: one plain cycle
            cand = Z[-1]
            Zc, Cc, ec = P(cand)
            rc = float(np.max(np.abs(Zc[-1] - cand) / scale))
        z, Z, C, events, residual = cand, Zc, Cc, ec, rc
    converged = residual < tol
    how = f"{cycles} cycles integrated, {newton} Newton (shooting) steps"
    msg = (f"contact lost: periodic ({how}, residual {residual:.2g})" if converged
           else f"not periodic within max_cycles = {max_cycles} or {MAX_NEWTON} Newton steps ({how}): "
           f"residual {residual:.3g} "
           f"> tol {tol:g} (a bouncing, lightly damped or period-multiplied motion); add damping")
    if converged and J is not None:
        mult = float(np.max(np.abs(np.linalg.eigvals(J))))
        if mult > 1.0 + 1e-6:
            converged = False
            msg = (f"the periodic motion found ({how}) is unstable: largest Floquet multiplier "
                   f"{mult:.4g} > 1, so the steady motion is not one-periodic (period doubling or "
                   "chaotic bouncing); add damping or stiffen the return spring")
    return Z, C, cycles, events, residual, converged, msg


def _whole(name: str, value, lo: int) -> int:
    """A count given as a whole number ``>= lo`` (an int, or a float without fraction).

    Parameters
    ----------
    name : str
        Parameter name for the message.
    value : int or float
        The count.
    lo : int
        Smallest accepted value.

    Returns
    -------
    int
        The count.

    Raises
    ------
    InputError
        Not a finite number, a fraction (``2.5``: never truncated) or below ``lo``.

    Examples
    --------
    >>> _whole("cycles", 3.0, 1)
    3
    """
    x = _validate.number(name, value, "")
    if x != int(x) or x < lo:
        raise _validate.fail(name, value, "", f"must be a whole number >= {lo}")
    return int(x)


def _check_types(train, program) -> None:
    """InputError unless ``train`` is a TrainModel and ``program`` a CamProgram."""
    if not isinstance(train, TrainModel):
        raise InputError(f"train = {train!r}: must be a TrainModel")
    if not isinstance(program, CamProgram):
        raise InputError(f"program = {program!r}: must be a CamProgram")


def periodic_response(train: TrainModel, program: CamProgram, omega: float, *,
                      steps_per_rev=None, tol: float = 1e-9, max_cycles: int = 400,
                      ) -> DynamicsResult:
    """Periodic steady state of ``train`` on ``program`` at cam speed ``omega`` (rad/s).

    Raises :class:`~femcam.errors.InputError` (with the numbers) for an unresolved time step,
    a train that cannot follow the cam (lowest natural frequency <= cam frequency), or an
    undamped train in exact resonance with a cam harmonic.

    Parameters
    ----------
    train : TrainModel
        The follower train.
    program : CamProgram
        Cam program (lift [m] against cam angle [rad]).
    omega : float
        Constant cam speed [rad/s], ``> 0``.
    steps_per_rev : int or None, optional
        Time steps per revolution (``>= 16``); None (default) chooses (:func:`choose_steps`).
    tol : float, optional
        Periodicity tolerance [-] on the state change over a cycle, scaled by the lift and the
        peak rigid velocity. Default 1e-9.
    max_cycles : int, optional
        Most cycles integrated when the contact is lost. Default 400.

    Returns
    -------
    DynamicsResult
        Periodic response on ``N + 1`` angles with forces [N], errors [m, m/s] and diagnostics.

    Raises
    ------
    InputError
        Wrong argument types or values, or the physical refusals above.

    Examples
    --------
    >>> from femcam.kinematics import CamProgram, dwell, fall, rise
    >>> from femcam.loads import FollowerDynamics
    >>> q = math.pi / 2
    >>> prog = CamProgram([rise(q, 0.01), dwell(q), fall(q, 0.01), dwell(q)])
    >>> tm = TrainModel(follower=FollowerDynamics(m=0.2, k=800.0, Fpl=500.0, c=0.0),
    ...                 k_t=1e6, zeta_t=0.1)
    >>> r = periodic_response(tm, prog, 20 * math.pi)     # 600 rpm
    >>> r.converged, r.cycles, r.any_liftoff, r.steps_per_rev
    (True, 1, False, 3600)
    """
    _check_types(train, program)
    omega = _validate.positive("omega", omega, "rad/s")
    tol = _validate.positive("tol", tol, "")
    max_cycles = _whole("max_cycles", max_cycles, 1)
    f = train.follower
    _check_follows(train, omega)
    N = choose_steps(train, omega, steps_per_rev)
    theta, s, v, a, g, U, modes = _setup(train, program, omega, N)
    n = train.ndof
    scale = np.r_[np.full(n, max(program.h_max, 1e-12)),
                  np.full(n, max(float(np.max(np.abs(v))), omega * program.h_max, 1e-12))]
    Z = linear_periodic(train, modes, U, omega)
    C = np.ones(N + 1, bool)
    cycles, events = 1, 0
    residual = float(np.max(np.abs(Z[-1] - Z[0]) / scale))
    converged, msg = True, "linear periodic solution (contact never lost)"
    if np.min(train.trial_force(Z)) <= 0.0:  # contact is lost: the unilateral problem
        Z, C, cycles, events, residual, converged, msg = _iterate_cycles(
            train, modes, U, Z[0], scale, tol, max_cycles)
    F = np.where(C, np.maximum(train.trial_force(Z), 0.0), 0.0)
    F_rigid = train.total_mass * a + g
    return DynamicsResult(
        model=train.model, omega=omega, theta=theta, s=s, v=v, a=a, e=Z[:, :n], ed=Z[:, n:],
        Fc_axial=F, contact=C, Fc_rigid_axial=F_rigid,
        natural_frequencies=train.natural_frequencies, steps_per_rev=N, cycles=cycles,
        residual=residual, converged=converged, n_events=events, message=msg,
        params={"k_s": f.k, "c_s": f.c, "Fpl": f.Fpl, "k_t": train.k_t, "c_t": train.c_t})


def simulate(train: TrainModel, program: CamProgram, omega: float, *, z0=None,
             steps_per_rev=None, cycles: int = 1):
    """Transient response from state ``z0`` (default: rest, ``e = e' = 0``) over ``cycles``
    revolutions. Returns ``(theta, Z, contact, Fc_axial)`` with ``Z = (e, e')`` per angle.

    Parameters
    ----------
    train : TrainModel
        The follower train.
    program : CamProgram
        Cam program (lift [m] against cam angle [rad]).
    omega : float
        Constant cam speed [rad/s], ``> 0``.
    z0 : array_like, shape (2n,), optional
        Start state ``(e [m], e' [m/s])``; default rest.
    steps_per_rev : int or None, optional
        Time steps per revolution (``>= 16``); None (default) chooses.
    cycles : int, optional
        Number of revolutions, ``>= 1``. Default 1.

    Returns
    -------
    theta : ndarray, shape (M+1,)
        Cam angles [rad] from 0 to ``2 pi cycles``, ``M = N cycles``.
    Z : ndarray, shape (M+1, 2n)
        States ``(e [m], e' [m/s])``.
    contact : ndarray of bool, shape (M+1,)
        Contact flags.
    Fc_axial : ndarray, shape (M+1,)
        Axial contact force [N], 0 in free flight.

    Raises
    ------
    InputError
        Wrong argument types, a ``z0`` of the wrong shape, a ``cycles`` that is not a whole
        number >= 1, or the refusals of :func:`choose_steps`.
    """
    _check_types(train, program)
    omega = _validate.positive("omega", omega, "rad/s")
    N = choose_steps(train, omega, steps_per_rev)
    ncyc = _whole("cycles", cycles, 1)
    n2 = 2 * train.ndof
    z = np.zeros(n2) if z0 is None else _validate.finite_array("z0", z0, "(m, m/s)")
    if z.shape != (n2,):
        raise _validate.fail("z0", z0, "(m, m/s)", f"must have shape ({n2},): the {train.ndof} "
                             f"errors e [m] then their rates e' [m/s]; got shape {z.shape}")
    _, _, _, _, _, U1, modes = _setup(train, program, omega, N)
    theta = np.linspace(0.0, 2.0 * math.pi * ncyc, N * ncyc + 1)
    U = np.vstack([U1[:-1]] * ncyc + [U1[-1:]])
    Z, C, _ = march(train, modes, U, z, bool(train.trial_force(z) > 0.0))
    F = np.where(C, np.maximum(train.trial_force(Z), 0.0), 0.0)
    return theta, Z, C, F
