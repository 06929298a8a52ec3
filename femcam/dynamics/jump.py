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
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field

import numpy as np

from .. import _validate
from ..errors import InputError
from ..kinematics import CamProgram
from .model import TrainModel
from .periodic import _check_follows, _setup, choose_steps, linear_periodic, periodic_response

RPM = 30.0 / math.pi  # rad/s -> rpm


@dataclass(frozen=True)
class JumpResult:
    """Jump speed ``rpm_jump`` (rpm; nan if none in the range), the rigid eq. 11 lift-off
    speed ``rpm_rigid`` (rpm; nan if none), the scan (``rpm_scan``, ``Fc_min_scan`` in N),
    Brent ``iterations`` and the bracket width ``xtol_rpm``."""

    rpm_jump: float
    rpm_rigid: float
    rpm_scan: np.ndarray
    Fc_min_scan: np.ndarray
    iterations: int
    xtol_rpm: float
    steps_per_rev: int
    message: str = ""


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
    """
    lo = _validate.positive("rpm_lo", rpm_lo, "rpm")
    hi = _validate.positive("rpm_hi", rpm_hi, "rpm")
    if hi <= lo:
        raise _validate.fail("rpm_hi", rpm_hi, "rpm", f"must be > rpm_lo = {lo:g} rpm")
    n_scan = int(_validate.positive("n_scan", n_scan, ""))
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
    (m) and dwell vibration (m); ``message`` per speed (why a speed has no answer)."""

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


def rpm_sweep(train: TrainModel, program: CamProgram, rpm, *, steps_per_rev=None,
              max_cycles: int = 400, workers: int = 1) -> RpmSweep:
    """Periodic response at each speed of ``rpm`` (rpm); ``workers`` > 1 runs the speeds in
    that many processes (the results are small and pickle)."""
    rpm = np.atleast_1d(_validate.finite_array("rpm", rpm, "rpm"))
    if np.any(rpm <= 0):
        raise _validate.fail("rpm", float(rpm[rpm <= 0][0]), "rpm", "every speed must be > 0")
    workers = int(_validate.positive("workers", workers, ""))
    jobs = [(train, program, float(r), steps_per_rev, max_cycles) for r in rpm]
    if workers == 1:
        rows = [_one(j) for j in jobs]
    else:
        with ProcessPoolExecutor(max_workers=workers) as ex:
            rows = list(ex.map(_one, jobs, chunksize=max(1, len(jobs) // (4 * workers))))
    cols = list(zip(*rows, strict=True))
    out = {k: np.array(c) for k, c in zip(_KEYS, cols[:-1], strict=True)}
    return RpmSweep(rpm=rpm, messages=list(cols[-1]), **out)
