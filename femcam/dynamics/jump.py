r"""Jump speed and rpm sweeps of a follower train.

The *jump speed* is the lowest cam speed at which the contact is lost. Below it the train
never leaves the cam, so its response is the linear (always-in-contact) periodic solution and
the smallest trial contact force

.. math:: F_{\min}(\omega) = \min_\theta \bigl(-k_t e_1 - c_t \dot e_1\bigr)

is a continuous function of the speed; the jump speed is its first zero, bracketed on a scan
and found by Brent's method (``scipy.optimize.brentq``). The rigid model's lift-off speed
(eq. 11: :math:`\min_\theta (m \omega^2 s'' + c \omega s' + k s + F_{pl}) = 0`) is found the same
way and reported beside it.

Symbols
-------
=========  ===========================================  =====  =========================
symbol     meaning                                      unit   source
=========  ===========================================  =====  =========================
omega      cam speed (rpm at the interface)             rad/s  [operating] rpm
F_min      least trial contact force over a cycle       N      linear periodic solution
rpm_jump   lowest speed with F_min = 0 (jump speed)     rpm    Norton 2009 ch. 10
rpm_rigid  same for the rigid eq. 11 force              rpm    seed 002 eq. 11
=========  ===========================================  =====  =========================
"""

from __future__ import annotations

import math
import signal
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field

import numpy as np

from .. import _validate
from .._repr import compact_repr, dataframe, span
from ..errors import InputError
from ..kinematics import CamProgram
from .model import TrainModel
from .periodic import (
    _check_follows,
    _setup,
    _steps_per_rev,
    _whole,
    choose_steps,
    linear_periodic,
    periodic_response,
)

RPM = 30.0 / math.pi  # rad/s -> rpm


@dataclass(frozen=True)
class JumpResult:
    """Jump speed ``rpm_jump`` (rpm; nan if none in the range), the rigid eq. 11 lift-off
    speed ``rpm_rigid`` (rpm; nan if none), the scan (``rpm_scan``, ``Fc_min_scan`` in N),
    Brent ``iterations`` and the bracket width ``xtol_rpm``.

    Attributes
    ----------
    rpm_jump : float
        Jump speed [rpm]: first zero of the least trial force on the scan, refined by Brent
        (``rpm_lo`` if the contact is already lost there); NaN if none in the range.
    rpm_rigid : float
        Lift-off speed of the rigid eq. 11 force [rpm]; NaN if none in the range.
    rpm_scan : ndarray, shape (n_scan,)
        Scanned speeds [rpm], uniform from ``rpm_lo`` to ``rpm_hi``.
    Fc_min_scan : ndarray, shape (n_scan,)
        Least trial contact force over a cycle at each scanned speed [N] (negative once the
        contact is lost).
    iterations : int
        Brent iterations on the jump speed (0 if no root or contact lost at ``rpm_lo``).
    xtol_rpm : float
        Absolute tolerance of the Brent search [rpm].
    steps_per_rev : int
        Time steps per revolution used for every speed.
    message : str
        Where the contact is lost, or that it is not lost in the range.
    """

    rpm_jump: float
    rpm_rigid: float
    rpm_scan: np.ndarray
    Fc_min_scan: np.ndarray
    iterations: int
    xtol_rpm: float
    steps_per_rev: int
    message: str = ""

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)



def _first_root(fun, x, y, xtol):
    """First sign change of y = fun(x) on the scan refined by brentq: (root, iterations)."""
    neg = np.flatnonzero(y <= 0.0)
    if neg.size == 0:
        return math.nan, 0
    i = int(neg[0])
    if i == 0:
        return float(x[0]), 0
    from scipy.optimize import brentq  # lazy: scipy.optimize, ~0.15 s to import

    root, info = brentq(fun, x[i - 1], x[i], xtol=xtol, full_output=True)
    return float(root), int(info.iterations)


def jump_speed(train: TrainModel, program: CamProgram, rpm_lo: float, rpm_hi: float, *,
               n_scan: int = 40, steps_per_rev=None, xtol_rpm: float = 1e-3) -> JumpResult:
    """Lowest speed in ``[rpm_lo, rpm_hi]`` (rpm) at which ``train`` loses the cam.

    One fixed number of steps per revolution (resolving the train at ``rpm_lo``) is used for
    the whole search so that the minimum force is a continuous function of the speed.

    Parameters
    ----------
    train : TrainModel
        Elastic follower train and its return spring.
    program : CamProgram
        Cam program (lift [m] against cam angle [rad]).
    rpm_lo, rpm_hi : float
        Speed range [rpm], ``0 < rpm_lo < rpm_hi``.
    n_scan : int, optional
        Number of scanned speeds before the Brent refinement, a whole number >= 1 (at least 2
        used). Default 40.
    steps_per_rev : int or None, optional
        Time steps per revolution (``>= 16``); None (default) picks enough for ``rpm_lo``.
    xtol_rpm : float, optional
        Absolute tolerance of the jump speed [rpm]. Default 1e-3.

    Returns
    -------
    JumpResult
        Jump speed and rigid lift-off speed [rpm] with the scan and diagnostics.

    Raises
    ------
    InputError
        Invalid speeds or counts, a train whose lowest natural frequency is at or below the cam
        frequency at ``rpm_hi``, or a time step that cannot resolve the train.
    """
    lo = _validate.positive("rpm_lo", rpm_lo, "rpm")
    hi = _validate.positive("rpm_hi", rpm_hi, "rpm")
    if hi <= lo:
        raise _validate.fail("rpm_hi", rpm_hi, "rpm", f"must be > rpm_lo = {lo:g} rpm")
    n_scan = _whole("n_scan", n_scan, 1)
    xtol_rpm = _validate.positive("xtol_rpm", xtol_rpm, "rpm")
    _check_follows(train, hi / RPM)
    N = choose_steps(train, lo / RPM, steps_per_rev)

    def fmin(rpm):
        _, _, _, _, _, U, modes = _setup(train, program, rpm / RPM, N)
        return float(np.min(train.trial_force(linear_periodic(train, modes, U, rpm / RPM))))

    theta = np.linspace(0.0, 2.0 * math.pi, N, endpoint=False)
    d = program.derivatives(theta)
    f = train.follower

    def fmin_rigid(rpm):
        w = rpm / RPM
        return float(np.min(train.total_mass * w**2 * d.s2 + f.c * w * d.s1 + f.k * d.s + f.Fpl))

    x = np.linspace(lo, hi, max(n_scan, 2))
    y = np.array([fmin(r) for r in x])
    root, it = _first_root(fmin, x, y, xtol_rpm)
    yr = np.array([fmin_rigid(r) for r in x])
    rigid, _ = _first_root(fmin_rigid, x, yr, xtol_rpm)
    msg = (f"contact lost from {root:.6g} rpm" if math.isfinite(root)
           else f"no contact loss between {lo:g} and {hi:g} rpm")
    return JumpResult(rpm_jump=root, rpm_rigid=rigid, rpm_scan=x, Fc_min_scan=y, iterations=it,
                      xtol_rpm=xtol_rpm, steps_per_rev=N, message=msg)


@dataclass(frozen=True)
class RpmSweep:
    """Per speed (rpm): peak and least axial contact force (N) of the periodic response and
    of the rigid eq. 11, lift-off, convergence, cycles, residual, largest displacement error
    (m) and dwell vibration (m); ``message`` per speed (why a speed has no answer).

    Every array has shape ``(n,)``, one entry per speed; a speed refused with an
    :class:`~femcam.errors.InputError` has NaN values, ``converged = False`` and the error text
    in ``messages``.

    Attributes
    ----------
    rpm : ndarray, shape (n,)
        Cam speeds [rpm].
    Fc_max, Fc_min : ndarray, shape (n,)
        Peak and least axial contact force of the periodic response [N].
    Fc_rigid_max, Fc_rigid_min : ndarray, shape (n,)
        Peak and least axial force of the rigid eq. 11 [N].
    liftoff : ndarray of bool, shape (n,)
        Contact lost somewhere in the cycle.
    converged : ndarray of bool, shape (n,)
        Periodic steady state found.
    cycles : ndarray of int, shape (n,)
        Cycles integrated.
    residual : ndarray, shape (n,)
        Scaled state change over the last cycle [-].
    max_error : ndarray, shape (n,)
        Largest displacement error ``|x - s|`` of the last mass [m].
    dwell_vibration : ndarray, shape (n,)
        Largest half peak-to-peak error of the last mass within a dwell [m].
    messages : list of str
        One per speed: how the answer was obtained, or why there is none.
    """

    rpm: np.ndarray
    Fc_max: np.ndarray
    Fc_min: np.ndarray
    Fc_rigid_max: np.ndarray
    Fc_rigid_min: np.ndarray
    liftoff: np.ndarray
    converged: np.ndarray
    cycles: np.ndarray
    residual: np.ndarray
    max_error: np.ndarray
    dwell_vibration: np.ndarray
    messages: list = field(default_factory=list)

    def csv_columns(self) -> dict:
        """One row per speed, as the columns of ``rpm_sweep.csv`` (forces in N, ``max_error_um``
        and ``dwell_vibration_um`` in um, flags as bool, the solver's message as text).

        Returns
        -------
        dict[str, ndarray]
            Column name (unit in the name) -> values, shape (n_speeds,).
        """
        return {"rpm": np.asarray(self.rpm, float), "Fc_max_N": self.Fc_max, "Fc_min_N": self.Fc_min,
                "Fc_rigid_max_N": self.Fc_rigid_max, "Fc_rigid_min_N": self.Fc_rigid_min,
                "liftoff": np.asarray(self.liftoff, bool), "converged": np.asarray(self.converged, bool),
                "cycles": np.asarray(self.cycles, int), "residual": np.asarray(self.residual, float),
                "max_error_um": np.asarray(self.max_error) * 1e6,
                "dwell_vibration_um": np.asarray(self.dwell_vibration) * 1e6,
                "message": np.asarray(self.messages, dtype=str)}

    def to_dataframe(self):
        """:meth:`csv_columns` as a ``pandas.DataFrame`` (one row per speed).

        Returns
        -------
        pandas.DataFrame

        Raises
        ------
        ImportError
            pandas is not installed (femcam does not require it).
        """
        return dataframe(self.csv_columns(), "RpmSweep.to_dataframe")

    def __repr__(self) -> str:
        """The speeds and the lift-off count (a compact line)."""
        return compact_repr(self, [
            f"{np.size(self.rpm)} speeds {span(self.rpm, 1.0, 'rpm')}",
            f"Fc {span(self.Fc_min, 1.0, 'N')} (min)",
            f"lift-off at {int(np.count_nonzero(self.liftoff))} speeds",
            f"converged {int(np.count_nonzero(self.converged))}/{np.size(self.rpm)}",
        ])



_KEYS = ("Fc_max", "Fc_min", "Fc_rigid_max", "Fc_rigid_min", "liftoff", "converged", "cycles",
         "residual", "max_error", "dwell_vibration")


def _one(args):
    train, program, rpm, steps, max_cycles = args
    try:
        r = periodic_response(train, program, rpm / RPM, steps_per_rev=steps, max_cycles=max_cycles)
    except InputError as exc:
        return (math.nan,) * 4 + (False, False, 0, math.nan, math.nan, math.nan, str(exc))
    return (r.Fc_max, r.Fc_min, float(r.Fc_rigid_axial.max()), float(r.Fc_rigid_axial.min()),
            r.any_liftoff, r.converged, r.cycles, r.residual, r.max_error, r.dwell_vibration,
            r.message)


#: most speeds of one rpm sweep: ~10 ms each at 3,600 steps per revolution (101 speeds of
#: seed 002's one_dof train in ~1 s on one core), so the cap is a few minutes; more steps per
#: revolution at high speed take longer
MAX_SPEEDS = 20_000
#: measured seconds per speed of an rpm sweep, for the refusal's time estimate
SECONDS_PER_SPEED = 0.01


def speeds_problem(n: int) -> str:
    """Why an rpm sweep of ``n`` speeds is refused (the estimate, the cap, what to change).

    Parameters
    ----------
    n : int
        Number of speeds (-).

    Returns
    -------
    str
        The condition, for an error message.
    """
    return (f"{n:,} speeds would take ~{n * SECONDS_PER_SPEED / 3600:.3g} h at ~"
            f"{SECONDS_PER_SPEED * 1e3:g} ms per speed, above the cap of {MAX_SPEEDS:,} speeds "
            "(femcam.dynamics.jump.MAX_SPEEDS); use a larger STEP or a narrower range")


def _worker_init() -> None:
    """A pool worker leaves Ctrl-C to the parent (one line, exit 130) and ends at once on the
    SIGTERM with which the pool stops it (a forked worker inherits the command line's handlers)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


def rpm_sweep(train: TrainModel, program: CamProgram, rpm, *, steps_per_rev=None,
              max_cycles: int = 400, workers: int = 1) -> RpmSweep:
    """Periodic response at each speed of ``rpm`` (rpm); ``workers`` > 1 runs the speeds in
    that many processes (the results are small and pickle).

    Parameters
    ----------
    train : TrainModel
        Elastic follower train and its return spring.
    program : CamProgram
        Cam program (lift [m] against cam angle [rad]).
    rpm : float or array_like, shape (n,)
        Cam speeds [rpm], each ``> 0``.
    steps_per_rev : int or None, optional
        Time steps per revolution (``>= 16``); None (default) picks enough per speed.
    max_cycles : int, optional
        Most cycles integrated per speed when the contact is lost. Default 400.
    workers : int, optional
        Number of processes, ``>= 1``. Default 1 (in-process).

    Returns
    -------
    RpmSweep
        Forces [N], errors [m] and diagnostics per speed.

    Raises
    ------
    InputError
        Non-finite or non-positive speeds, more than :data:`MAX_SPEEDS`, or ``workers`` or
        ``max_cycles`` not a whole number >= 1.
    """
    n = np.size(rpm)
    if n > MAX_SPEEDS:  # before any work (or any copy of the array)
        raise _validate.fail("rpm", f"<{n} speeds>", "", speeds_problem(n))
    rpm = np.atleast_1d(_validate.finite_array("rpm", rpm, "rpm"))
    _validate.instance("train", train, TrainModel)
    _validate.record("program", program, "a femcam.kinematics.CamProgram", "derivatives")
    if np.any(rpm <= 0):
        raise _validate.fail("rpm", float(rpm[rpm <= 0][0]), "rpm", "every speed must be > 0")
    workers = _whole("workers", workers, 1)
    max_cycles = _whole("max_cycles", max_cycles, 1)
    if steps_per_rev is not None:
        _steps_per_rev(steps_per_rev)  # refused here, not per speed in the rows
    jobs = [(train, program, float(r), steps_per_rev, max_cycles) for r in rpm]
    if workers == 1:
        rows = [_one(j) for j in jobs]
    else:
        with ProcessPoolExecutor(max_workers=workers, initializer=_worker_init) as ex:
            rows = list(ex.map(_one, jobs, chunksize=max(1, len(jobs) // (4 * workers))))
    cols = list(zip(*rows, strict=True))
    out = {k: np.array(c) for k, c in zip(_KEYS, cols[:-1], strict=True)}
    return RpmSweep(rpm=rpm, messages=list(cols[-1]), **out)
