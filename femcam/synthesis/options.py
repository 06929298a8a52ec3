"""Inputs and result of the seed-003 synthesis: :class:`SynthesisOptions`,
:class:`SynthesisResult`, :class:`PressureAngleError` (symbols in :mod:`femcam.synthesis.pefem`)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .. import _validate
from .._repr import compact_repr
from ..errors import PhysicsError

STABILIZATIONS = ("sauer", "eq12")


class PressureAngleError(PhysicsError):
    """The requested lift law needs a pressure angle too close to 90 deg on this base circle."""


#: most quadratic elements around the cam: the Newton solve is sparse; seed 003 with 4,000
#: elements took ~4 s and with 20,000 ~22 s and 0.23 GB (one core); 1e9 was killed for memory
MAX_ELEMENTS = 20_000


@dataclass(frozen=True, kw_only=True)
class SynthesisOptions:
    """Discretisation and Newton-Raphson settings (all keyword-only, validated).

    Parameters
    ----------
    n_elements : int
        Quadratic elements around the cam (2 n_elements nodes; >= 3).
    k, mu : float
        Penalty constant and stabilisation parameter (dimensionless, lengths scaled by R_b;
        see the module docstring; > 0).
    quad_points : int
        Gauss points per element (2 to 5).
    stabilization : {"sauer", "eq12"}
        ``"sauer"`` (eq. 18 form, default) or ``"eq12"`` (the printed square).
    rtol : float
        Stop when ||R|| <= rtol ||R_0|| (-, in (0, 1]).
    xtol : float
        Or when ||dx||_inf <= xtol R_b (-, >= 0), after a full exact Newton step.
    max_iter : int
        Newton iterations per k stage before :class:`ConvergenceError` (>= 1).
    line_search : bool
        Globalised Newton (default): the exact Newton step where the tangent is positive
        definite and the full step passes the Armijo test; otherwise a shifted or Gauss-Newton
        step (tangent without the indefinite ``k e E`` term and the compressive stabilisation)
        with Armijo backtracking. Near the solution every step is exact Newton (quadratic
        convergence). False: the paper's plain Newton-Raphson (full steps, Table 1).
    k_factor, k_start : float
        k-continuation (only with line_search): stages k_start mu, k_start mu k_factor, ...,
        k (-); ``k_factor = 1`` switches it off.
    phi_limit : float
        Refuse (:class:`PressureAngleError`) laws whose exact pressure angle exceeds it
        (rad, in (0, pi/2)).
    estimate_condition : bool
        1-norm condition estimate of the final tangent (a few extra solves).

    Raises
    ------
    InputError
        A value out of range (names parameter, value and unit).
    """

    n_elements: int = 180
    k: float = 1.0e6
    mu: float = 1.0
    quad_points: int = 3
    stabilization: str = "sauer"
    rtol: float = 1e-10
    xtol: float = 1e-13
    max_iter: int = 50
    line_search: bool = True
    k_factor: float = 10.0
    k_start: float = 1.0e4
    phi_limit: float = np.radians(80.0)
    estimate_condition: bool = True

    def __post_init__(self):
        _validate.integer("n_elements", self.n_elements, 3)
        if self.n_elements > MAX_ELEMENTS:  # refused before any array is allocated
            raise _validate.fail("n_elements", self.n_elements, "", f"must be <= {MAX_ELEMENTS:,} "
                                 "(femcam.synthesis.options.MAX_ELEMENTS): 20,000 take ~22 s "
                                 "and the curve converges long before (seed 003 uses 180)")
        q = self.quad_points
        if isinstance(q, bool) or not isinstance(q, (int, np.integer)) or not 2 <= q <= 5:
            raise _validate.fail("quad_points", q, "", "must be an integer in [2, 5]")
        _validate.integer("max_iter", self.max_iter, 1)
        object.__setattr__(self, "k", _validate.positive("k", self.k, ""))
        object.__setattr__(self, "mu", _validate.positive("mu", self.mu, ""))
        object.__setattr__(self, "rtol", _validate.in_range("rtol", self.rtol, 0.0, 1.0, "", lo_open=True))
        object.__setattr__(self, "xtol", _validate.nonnegative("xtol", self.xtol, ""))
        object.__setattr__(self, "phi_limit", _validate.in_range("phi_limit", self.phi_limit, 0.0, np.pi / 2,
                                                                 "rad", lo_open=True, hi_open=True))
        _validate.choice("stabilization", self.stabilization, STABILIZATIONS)
        object.__setattr__(self, "k_factor", _validate.number("k_factor", self.k_factor, ""))
        if self.k_factor < 1.0:
            raise _validate.fail("k_factor", self.k_factor, "", "must be >= 1 (1: no k-continuation)")
        object.__setattr__(self, "k_start", _validate.positive("k_start", self.k_start, ""))


@dataclass(frozen=True)
class SynthesisResult:
    """Converged cam curve and diagnostics (SI units, radians).

    Parameters
    ----------
    Rb : float
        Base-circle radius (m).
    options : SynthesisOptions
        The options used.
    nodes : ndarray, shape (2N, 2)
        Nodal coordinates (m), N = n_elements.
    theta, r, x, y : ndarray, shape (n_elements * samples_per_element,)
        The curve sampled at ``samples_per_element`` points per element, sorted by theta:
        polar angle (rad), radius (m), Cartesian coordinates (m).
    error : ndarray
        Transfer-function error ``r - R_b - s(theta)`` at the samples (m).
    phi, phi_exact : ndarray
        FE pressure angle and ``atan(s'/(R_b + s))`` at the same angles (rad).
    node_error : ndarray, shape (2N,)
        ``r - R_b - s(theta)`` at the nodes (m).
    stretch : ndarray
        ``sqrt(a11 / A11)`` at the Gauss points (-).
    converged : bool
        True (a failed solve raises :class:`ConvergenceError` instead of returning).
    iterations : int
        Newton iterations over all k stages.
    residual_history, energy_history : tuple of float
        ||R|| and Pi per iterate (scaled, dimensionless).
    message : str
        The stopping criterion met.
    condition_estimate : float
        1-norm condition estimate of the final tangent (-; NaN if not estimated).
    solve_time : float
        Wall time of the Newton stages (s).
    extras : dict
        ``modes`` (direction per iteration), ``k_stages``, ``stage_starts``,
        ``phi_max_exact`` (rad), ``n_dof``.
    """

    Rb: float
    options: SynthesisOptions
    nodes: np.ndarray
    theta: np.ndarray
    r: np.ndarray
    x: np.ndarray
    y: np.ndarray
    error: np.ndarray
    phi: np.ndarray
    phi_exact: np.ndarray
    node_error: np.ndarray
    stretch: np.ndarray
    converged: bool
    iterations: int
    residual_history: tuple
    energy_history: tuple
    message: str
    condition_estimate: float
    solve_time: float
    extras: dict = field(default_factory=dict)

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)

    @property
    def max_error(self) -> float:
        """max ``|y - y_o|`` over the sampled curve (m)."""
        return float(np.max(np.abs(self.error)))

    @property
    def phi_max(self) -> float:
        """max ``|phi|`` of the FE curve over the samples (rad)."""
        return float(np.max(np.abs(self.phi)))
