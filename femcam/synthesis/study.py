"""Seed 003 case study, parameter studies (Figs. 6-9) and the comparison with direct synthesis.

The case (seed 003 section 5): in-line knife-edge follower, rise 120 deg to 3 mm, dwell 90 deg,
fall 90 deg, dwell 60 deg, 3-4-5 polynomial (eq. 39 with zero velocity and acceleration at the
segment ends), base circle 5 mm.

* :func:`seed003_program` builds the cam program with :mod:`femcam.kinematics`.
* :func:`direct_profile` is the direct analytic synthesis (:func:`femcam.profile.cam_profile`,
  knife edge: polar radius ``Rb + s(theta)``, ``phi = atan(s'/(Rb + s))``).
* :func:`compare_direct` measures the FE curve against it at the same polar angles.
* :func:`study_k` and :func:`study_k_over_mu` sweep k and k/mu (seed 003 Figs. 6-9);
  :func:`format_table` (Markdown) and :func:`study_columns` (CSV columns, units in the column
  names) write them.

Only numpy/scipy (and femcam's analytic chain) are imported.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, replace

import numpy as np

from .. import _validate
from ..errors import ConvergenceError
from ..kinematics import CamProgram, dwell, fall, rise
from ..profile import KnifeEdgeFollower, cam_profile
from .pefem import SynthesisOptions, SynthesisResult, synthesize_knife_edge

#: seed 003's base circle (m) and printed results (section 5)
SEED003_RB = 5.0e-3
SEED003_PHI_MAX_DEG = 29.3619
SEED003_MAX_ERROR = 5.4363e-5          # printed without a unit; the paper's lengths are in mm


def seed003_program(h: float = 3.0e-3, law: str = "poly345"):
    """Rise 120 deg to ``h`` (m), dwell 90, fall 90, dwell 60 deg (seed 003 section 5).

    Parameters
    ----------
    h : float
        Lift (m).
    law : str
        Motion law of the rise and the fall.

    Returns
    -------
    femcam.kinematics.CamProgram
    """
    h = _validate.positive("h", h, "m")
    r = math.radians
    return CamProgram([rise(r(120.0), h, law), dwell(r(90.0)), fall(r(90.0), h, law),
                       dwell(r(60.0))])


def derivatives(program, theta):
    """Lift and its first two derivatives of ``program``.

    Parameters
    ----------
    program : femcam.kinematics.CamProgram
        The cam program.
    theta : array_like
        Cam angles (rad).

    Returns
    -------
    (ndarray, ndarray, ndarray)
        ``(s, s1, s2)`` at ``theta`` (m, m/rad, m/rad^2).
    """
    d = program.derivatives(theta)
    return tuple(np.asarray(getattr(d, n), float) for n in ("s", "s1", "s2"))


def direct_profile(program, Rb: float, theta):
    """Direct analytic knife-edge synthesis at cam angles ``theta``.

    Parameters
    ----------
    program : femcam.kinematics.CamProgram
        The cam program.
    Rb : float
        Base-circle radius (m).
    theta : array_like
        Cam angles (rad).

    Returns
    -------
    r : ndarray
        Polar radius of the cam point in contact at ``theta``, ``|(x, y)| = Rb + s`` (m).
    phi : ndarray
        Pressure angle (rad), from :func:`femcam.profile.cam_profile` (Norton eq. 8.31).
    """
    _validate.record("program", program, "a femcam.kinematics.CamProgram", "derivatives")
    s, s1, s2 = derivatives(program, theta)
    p = cam_profile(KnifeEdgeFollower(Rb=Rb), theta, s, s1, s2, allow_undercut=True)
    return np.hypot(p.x, p.y), p.phi


@dataclass(frozen=True)
class Comparison:
    """FE curve vs direct synthesis at the FE sample angles.

    Parameters
    ----------
    max_radius_deviation, rms_radius_deviation : float
        max and rms of ``|r_FE - r_direct|`` (m).
    phi_max_fe : float
        max ``|phi|`` of the FE curve (rad).
    phi_max_direct : float
        max ``|phi|`` of the direct profile on a dense grid (rad).
    max_phi_deviation : float
        max ``|phi_FE - phi_direct|`` at the same angles (rad).
    time_fe : float
        FE Newton solve (s).
    time_direct : float
        Direct profile at the same number of angles (s).
    """

    max_radius_deviation: float      # max |r_FE - r_direct| (m)
    rms_radius_deviation: float      # rms of the same (m)
    phi_max_fe: float                # max |phi| of the FE curve (rad)
    phi_max_direct: float            # max |phi| of the direct profile, dense grid (rad)
    max_phi_deviation: float         # max |phi_FE - phi_direct| at the same angles (rad)
    time_fe: float                   # FE Newton solve (s)
    time_direct: float               # direct profile at the same number of angles (s)


def compare_direct(result: SynthesisResult, program, *, n_dense: int = 72001) -> Comparison:
    """Compare a converged FE curve with :func:`direct_profile` of the same program.

    Parameters
    ----------
    result : SynthesisResult
        The FE curve.
    program : femcam.kinematics.CamProgram
        The program it was synthesised for.
    n_dense : int
        Grid points over one revolution for the direct max ``|phi|``.

    Returns
    -------
    Comparison
        Deviations (m, rad) and times (s).
    """
    n_dense = _validate.integer("n_dense", n_dense, 2, "points")
    _validate.instance("result", result, SynthesisResult, "a SynthesisResult (synthesize_knife_edge)")
    _validate.record("program", program, "a femcam.kinematics.CamProgram", "derivatives")
    t0 = time.perf_counter()
    r_d, phi_d = direct_profile(program, result.Rb, result.theta)
    t_direct = time.perf_counter() - t0
    th = np.linspace(0.0, 2 * np.pi, n_dense)
    phi_dense = direct_profile(program, result.Rb, th)[1]
    dev = result.r - r_d
    return Comparison(
        max_radius_deviation=float(np.max(np.abs(dev))),
        rms_radius_deviation=float(np.sqrt(np.mean(dev**2))),
        phi_max_fe=result.phi_max, phi_max_direct=float(np.max(np.abs(phi_dense))),
        max_phi_deviation=float(np.max(np.abs(result.phi - phi_d))),
        time_fe=result.solve_time, time_direct=t_direct)


@dataclass(frozen=True)
class StudyRow:
    """One point of a parameter study.

    Parameters
    ----------
    k, mu : float
        Penalty constant and stabilisation parameter (-).
    n_elements : int
        Quadratic elements.
    max_error : float
        max ``|y - y_o|`` over the sampled curve (m; NaN if not converged).
    node_error : float
        max ``|y - y_o|`` at the nodes (m; NaN if not converged).
    phi_max : float
        max ``|phi|`` of the FE curve (rad).
    iterations : int
        Newton iterations (those done before the failure if not converged).
    condition : float
        1-norm condition estimate of the final tangent (-).
    time : float
        Newton solve time (s).
    converged : bool
        False when the solve raised :class:`~femcam.errors.ConvergenceError`.
    message : str
        The solver's message or the error text.
    """

    k: float
    mu: float
    n_elements: int
    max_error: float
    node_error: float
    phi_max: float
    iterations: int
    condition: float
    time: float
    converged: bool
    message: str = ""

    @property
    def k_over_mu(self) -> float:
        """k / mu (-)."""
        return self.k / self.mu


def _row(program, Rb, opt) -> StudyRow:
    try:
        r = synthesize_knife_edge(program, Rb=Rb, options=opt)
    except ConvergenceError as exc:
        return StudyRow(k=opt.k, mu=opt.mu, n_elements=opt.n_elements, max_error=math.nan,
                        node_error=math.nan, phi_max=math.nan, iterations=len(exc.history) - 1,
                        condition=math.nan, time=math.nan, converged=False, message=str(exc))
    return StudyRow(k=opt.k, mu=opt.mu, n_elements=opt.n_elements, max_error=r.max_error,
                    node_error=float(np.max(np.abs(r.node_error))), phi_max=r.phi_max,
                    iterations=r.iterations, condition=r.condition_estimate, time=r.solve_time,
                    converged=True, message=r.message)


def study_k(program, *, Rb: float, ks, mu: float = 1.0,
            options: SynthesisOptions | None = None) -> list[StudyRow]:
    """Error and pressure angle against k at fixed mu (seed 003 Figs. 6 and 7).

    Parameters
    ----------
    program : CamProgram or callable
        The lift law (see :func:`~femcam.synthesis.synthesize_knife_edge`).
    Rb : float
        Base-circle radius (m).
    ks : iterable of float
        Penalty constants (-).
    mu : float
        Stabilisation parameter (-).
    options : SynthesisOptions, optional
        Other settings (k and mu replaced).

    Returns
    -------
    list of StudyRow
        One per k; a failed solve is a row with ``converged = False``.
    """
    base = options or SynthesisOptions()
    ks = _validate.positive_array("ks", ks, "")
    mu = _validate.positive("mu", mu, "")
    return [_row(program, Rb, replace(base, k=float(k), mu=mu)) for k in np.ravel(ks)]


def study_k_over_mu(program, *, Rb: float, ratios, k: float = 1.0e6,
                    options: SynthesisOptions | None = None) -> list[StudyRow]:
    """Error and pressure angle against k/mu at fixed k (seed 003 Figs. 8 and 9).

    Continuation starts at ``k_start mu``, so it is lowered with mu to keep the first stage
    at k/mu = 1e4 or less.

    Parameters
    ----------
    program : CamProgram or callable
        The lift law (see :func:`~femcam.synthesis.synthesize_knife_edge`).
    Rb : float
        Base-circle radius (m).
    ratios : iterable of float
        Values of k/mu (-).
    k : float
        Penalty constant (-).
    options : SynthesisOptions, optional
        Other settings (k and mu replaced).

    Returns
    -------
    list of StudyRow
        One per ratio; a failed solve is a row with ``converged = False``.
    """
    base = options or SynthesisOptions()
    ratios = _validate.positive_array("ratios", ratios, "")
    k = _validate.positive("k", k, "")
    return [_row(program, Rb, replace(base, k=k, mu=k / float(q))) for q in np.ravel(ratios)]


def format_table(rows, *, key: str = "k") -> str:
    """Markdown table of a study (errors in mm, angles in deg).

    Parameters
    ----------
    rows : iterable of StudyRow
        The study.
    key : str
        Unused (no caller passes it): the table always shows k, mu and k/mu.

    Returns
    -------
    str
        The table, one line per row.
    """
    head = ("| k | mu | k/mu | elements | max error (mm) | max node error (mm) | phi max (deg) "
            "| iterations | cond. est. | time (s) |")
    lines = [head, "|" + "---|" * 10]
    for r in rows:
        if r.converged:
            lines.append(f"| {r.k:.0e} | {r.mu:.3g} | {r.k_over_mu:.0e} | {r.n_elements} | "
                         f"{r.max_error * 1e3:.3e} | {r.node_error * 1e3:.3e} | "
                         f"{math.degrees(r.phi_max):.4f} | {r.iterations} | {r.condition:.1e} | "
                         f"{r.time:.3f} |")
        else:
            lines.append(f"| {r.k:.0e} | {r.mu:.3g} | {r.k_over_mu:.0e} | {r.n_elements} | "
                         f"ConvergenceError | | | {r.iterations} | | |")
    return "\n".join(lines)


#: columns of :func:`study_columns` (unit after the last underscore; ``nondim``: dimensionless)
STUDY_CSV_COLUMNS = ("k_nondim", "mu_nondim", "k_over_mu_nondim", "n_elements", "max_error_mm",
                     "max_node_error_mm", "phi_max_deg", "newton_iterations", "cond_est_nondim",
                     "solve_time_s", "converged", "message")


def study_columns(rows) -> dict:
    """A study as table columns :data:`STUDY_CSV_COLUMNS` (errors in mm, angles in deg), for
    :func:`femcam.io.write_table` (``femcam synth --study`` writes them as CSV).

    A row whose solve raised :class:`ConvergenceError` has ``converged = False``, ``nan``
    results and the error message.

    Parameters
    ----------
    rows : iterable of StudyRow
        The study.

    Returns
    -------
    dict[str, ndarray]
        Column name -> values, in :data:`STUDY_CSV_COLUMNS` order.

    >>> row = StudyRow(k=1e3, mu=1.0, n_elements=30, max_error=5e-6, node_error=4e-6,
    ...                phi_max=0.5, iterations=10, condition=1e5, time=0.02, converged=True)
    >>> c = study_columns([row])
    >>> float(c["max_error_mm"][0]), round(float(c["phi_max_deg"][0]), 6), bool(c["converged"][0])
    (0.005, 28.64789, True)
    """
    rows = list(rows)
    nan = float("nan")

    def col(f, ok_only=True):
        return np.array([f(r) if (r.converged or not ok_only) else nan for r in rows], dtype=float)

    vals = (col(lambda r: r.k, False), col(lambda r: r.mu, False), col(lambda r: r.k_over_mu, False),
            np.array([r.n_elements for r in rows], dtype=int), col(lambda r: r.max_error * 1e3),
            col(lambda r: r.node_error * 1e3), col(lambda r: math.degrees(r.phi_max)),
            np.array([r.iterations for r in rows], dtype=int), col(lambda r: r.condition),
            col(lambda r: r.time), np.array([bool(r.converged) for r in rows], dtype=bool),
            np.array(["" if r.converged else str(r.message) for r in rows], dtype=str))
    return dict(zip(STUDY_CSV_COLUMNS, vals, strict=True))
