r"""Knife-edge cam curve synthesis by potential-energy finite elements (seed 003).

The cam curve :math:`\mathbf x(\xi)` is a "deformation" of the base circle
:math:`\mathbf X(\xi) = R_b(\cos\xi, \sin\xi)`, discretised with periodic quadratic 1-D
elements along the curvilinear coordinate :math:`\xi \in [0, 2\pi)` (seed 003 eqs. 3, 19-23).
The nodes are found by minimising the total potential energy (seed 003 eq. 13)

.. math:: \Pi = \frac{k}{2}\int (y - y_o)^2\,d\xi
                + \mu \int \psi(a_{11})\,d\xi

with Newton-Raphson (seed 003 section 4, Table 1).

Symbols
-------
==============  ===================================================  =======  ================
symbol          meaning                                              unit     source
==============  ===================================================  =======  ================
xi              curvilinear (reference) coordinate = base-circle     rad      eq. 3
                angle; the integration measure d(alpha) of eqs.
                11-12 is read as d(xi) on the reference curve
x               current cam-curve point (cam frame)                  m        eq. 19
a1, A1          covariant tangent dx/dxi on current / initial curve  m        eq. 4, 21
a11, A11        a1.a1, A1.A1 ; a^11 = 1/a11, A^11 = 1/A11            m^2      eqs. 6-7
d               follower direction x/|x| (in-line knife edge)        -        eq. 9
t               (-d_2, d_1): unit vector normal to d, d(alpha)/dx    -        (this module)
                = t/|x|
alpha           cam angle = polar angle of x, atan2(x_2, x_1)        rad      eq. 2 (see below)
y, y_o          current / given follower lift; y = |x| - R_b         m        eqs. 1, 8
e               transfer-function error y - y_o(alpha)               m        eq. 11
k, mu           penalty constant and stabilisation parameter         -        eqs. 11-12
phi             pressure angle, angle between d and curve normal     rad      eq. 40 (fixed)
==============  ===================================================  =======  ================

Lengths are scaled by R_b inside the energy, so ``k`` and ``mu`` are dimensionless and
only ``k/mu`` and the mesh set the accuracy (seed 003 Figs. 6-9). In the paper's eq. 13 the
penalty carries a length^2 and the stabilisation none, so a k/mu computed with lengths in a
unit l is ``(k/mu)_femcam / (R_b/l)^2`` (l = 1 mm, R_b = 5 mm: a factor 25; see
docs/synthesis.md). While the penalty dominates, the error is
``e ~ -R_b (lam^2 - 1) (R_b kappa) cos(phi) mu/k`` (uniform stretch lam = perimeter /
(2 pi R_b), kappa the curvature of the exact curve).

Derivation and the seed's typos (checked against a finite-difference Jacobian in the tests)
-----------------------------------------------------------------------------------------
* **alpha.** Eq. 2, ``alpha = acos(d . x1)``, only covers [0, pi]: it folds the lower half
  plane onto the upper one, so ``y_o(alpha)`` is mirror-symmetric about x and a 360 deg
  program (120 deg rise, ...) cannot be represented; its derivative produces the
  ``1/sqrt(1 - cos^2 alpha) = 1/|sin alpha|`` factor of ``c1`` (eq. 17), singular at
  alpha = 0, pi. We use the polar angle ``alpha = atan2(x_2, x_1)`` with
  ``grad alpha = t/|x|``, regular everywhere.
* **b (eqs. 15-17).** ``grad e = b = d - y_o'(alpha) t/|x|``. The paper's ``d + B r`` is the
  gradient of the folded-acos error; it equals ours only for sin(alpha) > 0 (``B x = 0``, so
  the ``x`` in ``r`` contributes nothing).
* **E (eqs. 27-29).** Exact Hessian of e:
  ``E = t(x)t/|x| - y_o'' t(x)t/|x|^2 + y_o' (d(x)t + t(x)d)/|x|^2``. The paper's middle
  term ``B(r(x)d - d(x)r)B`` is identically zero (``B d = 0``), the ``d(x)t`` coupling is
  missing, and ``c2`` carries a spurious ``1/|sin alpha|`` and the wrong sign on ``y_o''``.
* **Stabilisation (eqs. 12, 18, 32, 34).** Eq. 18 is the variation of Sauer's (2016) energy
  ``psi = 1/2 (A^11 a11 - 1 - ln(a11/A11))`` (no square), and its ``(A^11 - a_11)`` must read
  ``(A^11 - a^11)`` with the *contravariant* ``a^11 = 1/a11`` (dimensionally required). Eq. 32
  /34 are then the exact linearisation. Eq. 12 as printed (squared) is available as
  ``stabilization="eq12"``; we differentiate it exactly too.
* **Pressure angle (eqs. 10, 40).** ``a1/|a1|`` is the unit *tangent*, not the normal, so eq.
  40 as printed gives 90 deg - phi. We use ``phi = atan2(d . a1, t . a1)``, i.e.
  ``tan phi = r'/r`` for the polar curve (Norton, *Design of Machinery*, ch. 8).

Orientation: the curve is the polar curve ``r(alpha) = R_b + s(alpha)`` at polar angle
``+alpha`` (a cam turning clockwise under a follower on the +x axis). The direct profile of a
counter-clockwise cam is the mirror image ``y -> -y``.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from .. import _validate
from ..errors import ConvergenceError, InputError, PhysicsError

STABILIZATIONS = ("sauer", "eq12")


class PressureAngleError(PhysicsError):
    """The requested lift law needs a pressure angle too close to 90 deg on this base circle."""


@dataclass(frozen=True, kw_only=True)
class SynthesisOptions:
    """Discretisation and Newton-Raphson settings (all keyword-only, validated).

    n_elements : number of quadratic elements around the cam (2 n_elements nodes).
    k, mu      : penalty constant and stabilisation parameter (dimensionless, see module doc).
    quad_points: Gauss points per element (2-5).
    stabilization : ``"sauer"`` (eq. 18 form, default) or ``"eq12"`` (the printed square).
    rtol       : stop when ||R|| <= rtol ||R_0||; ``xtol``: or when ||dx||_inf <= xtol R_b.
    max_iter   : Newton iterations (per k stage) before :class:`ConvergenceError`.
    line_search: globalised Newton (default): the exact Newton step is taken when it is a
                 descent direction of Pi and its full step passes the Armijo test; otherwise a
                 Gauss-Newton step (tangent without the indefinite ``k e E`` term and without
                 compressive stabilisation) with Armijo backtracking. Near the solution every
                 step is exact Newton, so convergence is quadratic. False: the paper's plain
                 Newton-Raphson (exact tangent, full steps from the base circle, Table 1).
    k_factor, k_start : k-continuation (only with line_search): stages k_start mu,
                 k_start mu k_factor, ..., k; ``k_factor = 1`` switches it off.
    phi_limit  : refuse (``PressureAngleError``) laws whose exact pressure angle exceeds it (rad).
    estimate_condition : 1-norm condition estimate of the final tangent (a few extra solves).
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

    ``nodes`` (2N, 2) nodal coordinates; ``theta, r, x, y`` the curve sampled at
    ``samples_per_element`` points per element (polar angle, radius, Cartesian);
    ``error = r - R_b - s(theta)`` the transfer-function error there (m); ``phi`` the FE
    pressure angle and ``phi_exact = atan(s'/(R_b + s))`` at the same angles (rad).
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

    @property
    def max_error(self) -> float:
        """max |y - y_o| over the sampled curve (m)."""
        return float(np.max(np.abs(self.error)))

    @property
    def phi_max(self) -> float:
        """max |phi| of the FE curve over the samples (rad)."""
        return float(np.max(np.abs(self.phi)))


# --------------------------------------------------------------------------- law adapter
def as_law(program):
    """Return ``f(alpha) -> (s, s1, s2)`` (m, m/rad, m/rad^2) from a CamProgram-like object
    (``.derivatives(theta)`` giving ``s, s1, s2`` as attributes or keys) or a callable."""
    if hasattr(program, "derivatives"):
        def f(alpha):
            d = program.derivatives(alpha)
            get = (lambda n: d[n]) if isinstance(d, dict) else (lambda n: getattr(d, n))
            return (np.asarray(get("s"), float), np.asarray(get("s1"), float),
                    np.asarray(get("s2"), float))
        return f
    if callable(program):
        return program
    raise InputError(f"program = {program!r}: must have .derivatives(theta) or be callable")


# --------------------------------------------------------------------------- element kernel
def _shape(nq):
    """Quadratic Lagrange shape functions on eta in [-1, 1] and Gauss rule (nq points)."""
    eta, w = np.polynomial.legendre.leggauss(nq)
    N = np.stack([eta * (eta - 1) / 2, 1 - eta**2, eta * (eta + 1) / 2], axis=1)
    dN = np.stack([eta - 0.5, -2 * eta, eta + 0.5], axis=1)
    return N, dN, w


class _Discretisation:
    """Periodic quadratic mesh of the unit base circle (lengths scaled by R_b)."""

    def __init__(self, ne, nq):
        self.ne, self.nn = ne, 2 * ne
        self.xi_nodes = 2 * np.pi * np.arange(self.nn) / self.nn
        self.X = np.stack([np.cos(self.xi_nodes), np.sin(self.xi_nodes)], axis=1)
        self.conn = (2 * np.arange(ne)[:, None] + np.arange(3)[None, :]) % self.nn
        N, dN, w = _shape(nq)
        J = np.pi / ne                      # dxi/deta, element length in xi is 2 pi / ne
        self.N, self.dN, self.w = N, dN / J, w * J
        Xe = self.X[self.conn]
        self.A11 = np.einsum("qa,eai->eqi", self.dN, Xe)
        self.A11 = np.einsum("eqi,eqi->eq", self.A11, self.A11)
        dofs = (2 * self.conn[:, :, None] + np.arange(2)[None, None, :]).reshape(ne, 6)
        self.dofs = dofs
        self.rows = np.repeat(dofs, 6, axis=1).ravel()
        self.cols = np.tile(dofs, (1, 6)).ravel()


def _stab(a11, A11, mu, kind):
    """psi(a11) and its first two derivatives in a11 (per unit dxi)."""
    if kind == "sauer":        # Sauer (2016): mu/2 (A^11 a11 - 1 - ln(a11/A11)); eq. 18 form
        psi = 0.5 * mu * (a11 / A11 - 1.0 - np.log(a11 / A11))
        d1 = 0.5 * mu * (1.0 / A11 - 1.0 / a11)
        d2 = 0.5 * mu / a11**2
    else:                      # eq. 12 as printed: mu/2 (A^11 a11 - ln(a11/A11))^2
        g = a11 / A11 - np.log(a11 / A11)
        g1 = 1.0 / A11 - 1.0 / a11
        psi = 0.5 * mu * g**2
        d1 = mu * g * g1
        d2 = mu * (g1**2 + g / a11**2)
    return psi, d1, d2


def _evaluate(u, D, law, k, mu, kind, want_tangent=True):
    """Energy, residual R = dPi/du and tangent K = d2Pi/du2 (u: (nn, 2), scaled)."""
    xe = u[D.conn]
    x = np.einsum("qa,eai->eqi", D.N, xe)
    a1 = np.einsum("qa,eai->eqi", D.dN, xe)
    rho = np.hypot(x[..., 0], x[..., 1])
    if np.any(rho <= 1e-12):
        raise ConvergenceError("the cam curve passed through the cam centre", [])
    d = x / rho[..., None]
    t = np.stack([-d[..., 1], d[..., 0]], axis=-1)
    alpha = np.mod(np.arctan2(x[..., 1], x[..., 0]), 2 * np.pi)
    s, s1, s2 = law(alpha)
    e = rho - 1.0 - s                                  # eq. 8 minus eq. 1 (scaled)
    b = d - (s1 / rho)[..., None] * t                  # grad e (corrects eqs. 16-17)
    a11 = np.einsum("eqi,eqi->eq", a1, a1)
    if np.any(a11 <= 0):
        raise ConvergenceError("an element collapsed (a11 <= 0)", [])
    psi, p1, p2 = _stab(a11, D.A11, mu, kind)
    w = D.w[None, :]
    energy = float(np.sum(w * (0.5 * k * e**2 + psi)))
    gx = (k * e)[..., None] * b                        # dPi_p/dx   (eq. 15)
    ga = (2 * p1)[..., None] * a1                      # dPi_s/da1  (eq. 18 with a^11)
    Re = (np.einsum("q,qa,eqi->eai", D.w, D.N, gx) + np.einsum("q,qa,eqi->eai", D.w, D.dN, ga))
    R = np.zeros((D.nn, 2))
    np.add.at(R, D.conn, Re)
    if not want_tangent:
        return energy, R.ravel(), None
    # Hessian of e: E = t t/rho - s2 t t/rho^2 + s1 (d t + t d)/rho^2   (corrects eq. 28)
    tt = np.einsum("eqi,eqj->eqij", t, t)
    dt = np.einsum("eqi,eqj->eqij", d, t)
    E = ((1.0 / rho - s2 / rho**2)[..., None, None] * tt
         + (s1 / rho**2)[..., None, None] * (dt + np.swapaxes(dt, -1, -2)))
    Hx = k * (np.einsum("eqi,eqj->eqij", b, b) + e[..., None, None] * E)        # eq. 31
    Ha = ((4 * p2)[..., None, None] * np.einsum("eqi,eqj->eqij", a1, a1)
          + (2 * p1)[..., None, None] * np.eye(2))                             # eq. 34 (fixed)
    Ke = (np.einsum("q,qa,qb,eqij->eaibj", D.w, D.N, D.N, Hx)
          + np.einsum("q,qa,qb,eqij->eaibj", D.w, D.dN, D.dN, Ha)).reshape(D.ne, 36)
    n = 2 * D.nn
    K = sp.csc_matrix((Ke.ravel(), (D.rows, D.cols)), shape=(n, n))
    # positive semi-definite "Gauss-Newton" tangent for the globalisation phase: drop the
    # k e E curvature term and the compressive part of the stabilisation (psi' < 0)
    Hx_gn = k * np.einsum("eqi,eqj->eqij", b, b)
    Ha_gn = Ha - (2 * np.minimum(p1, 0.0))[..., None, None] * np.eye(2)
    Kg = (np.einsum("q,qa,qb,eqij->eaibj", D.w, D.N, D.N, Hx_gn)
          + np.einsum("q,qa,qb,eqij->eaibj", D.w, D.dN, D.dN, Ha_gn)).reshape(D.ne, 36)
    Kgn = sp.csc_matrix((Kg.ravel(), (D.rows, D.cols)), shape=(n, n))
    return energy, R.ravel(), (K, Kgn)


def _solve(K, rhs):
    """Sparse direct solve; None if the matrix is singular or the result not finite."""
    try:
        x = spla.spsolve(K, rhs)
    except RuntimeError:
        return None
    return x if np.all(np.isfinite(x)) else None


def _expand(v, free):
    """Scatter the free-DOF vector v into a (nn, 2) displacement with zeros at fixed DOFs."""
    out = np.zeros(free.size)
    out[free] = v
    return out.reshape(-1, 2)


def _factor(K):
    """Symmetric-mode sparse LU (diagonal pivots, symmetric permutation) of symmetric K and
    the number of negative pivots, which by Sylvester's law of inertia is the number of
    negative eigenvalues. (None, -1) if the factorisation breaks down."""
    try:
        lu = spla.splu(K, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0,
                       options=dict(SymmetricMode=True))
    except RuntimeError:
        return None, -1
    piv = lu.U.diagonal()
    if not np.all(np.isfinite(piv)) or np.any(piv == 0):
        return None, -1
    return lu, int(np.sum(piv < 0))


def _condest(K):
    """1-norm condition-number estimate of sparse K (Hager/Higham via onenormest)."""
    try:
        lu = spla.splu(K)
        inv = spla.LinearOperator(K.shape, matvec=lu.solve, rmatvec=lambda v: lu.solve(v, "T"),
                                  dtype=float)
        return float(spla.onenormest(K) * spla.onenormest(inv))
    except RuntimeError:   # exactly singular
        return float("inf")


def pressure_angle_exact(Rb, s, s1):
    r"""In-line knife-edge pressure angle (rad).

    .. math:: \phi = \arctan\frac{s'(\theta)}{R_b + s(\theta)}

    (Norton, *Design of Machinery*, 2nd ed., eq. 8.31 with zero offset; seed 003 eq. 40 fixed).

    >>> round(float(np.degrees(pressure_angle_exact(1.0, 0.0, 1.0))), 6)
    45.0
    """
    return np.arctan2(s1, Rb + s)


def _direction(Kf, Rf, Kgn, free, opt, tau: float, it: int, hist):
    """Newton direction ``(du, mode, tau)``; with the line search, a shifted or Gauss-Newton
    direction where the exact tangent is indefinite (None: singular, no line search)."""
    lu, n_neg = _factor(Kf)
    if lu is not None and (n_neg == 0 or not opt.line_search):
        return lu.solve(-Rf), "newton", tau
    if not opt.line_search:
        return None, "newton", tau
    # the exact tangent is indefinite here (the k e E term, far from the solution or right
    # after k was raised): smallest shift K + tau diag(K_GN) that is positive definite
    # (inertia from the symmetric LU; Nocedal & Wright 2006 §3.4)
    Dg = sp.diags(Kgn.diagonal()[free])
    tau = max(tau / 100.0, 1e-8)
    while tau <= 1e-2:
        lu, n_neg = _factor((Kf + tau * Dg).tocsc())
        if lu is not None and n_neg == 0:
            return lu.solve(-Rf), "shifted-newton", tau
        tau *= 10.0
    # far from the solution: Gauss-Newton (positive semi-definite tangent)
    du = _solve(Kgn[free][:, free].tocsc(), -Rf)
    if du is None:
        raise ConvergenceError(f"singular Gauss-Newton tangent at iteration {it}", hist)
    return du, "gauss-newton", 1e-8


def _line_search(trial, Pi: float, rn: float, slope: float, k: float, it: int, hist) -> float:
    """Backtracking step: Armijo on Pi; at the round-off level of Pi the residual norm must
    drop instead (Nocedal & Wright 2006 §3.1)."""
    step = 1.0
    while True:
        Pn, rn_trial = trial(step)
        if Pn <= Pi + 1e-4 * step * slope and Pn < Pi:
            return step
        if abs(Pn - Pi) <= 1e-14 * abs(Pi) and 0 <= rn_trial < rn:
            return step
        step *= 0.5
        if step < 1e-10:
            raise ConvergenceError(f"line search failed at iteration {it} (k = {k:g})", hist)


def _newton(u, D, law, k, mu, kind, opt, free, r_ref, rtol, hist, ehist, modes, max_iter):
    """Newton-Raphson on Pi for one value of k (seed 003 Table 1, globalised).

    Appends to ``hist``/``ehist``/``modes``; returns ``(u, K_free, iterations, message)`` or
    raises :class:`ConvergenceError`."""
    Pi, R, (K, Kgn) = _evaluate(u, D, law, k, mu, kind)
    rn = float(np.linalg.norm(R[free]))
    hist.append(rn), ehist.append(Pi)
    tau = 1e-8
    for it in range(1, max_iter + 1):
        Kf, Rf = K[free][:, free].tocsc(), R[free]
        du, mode, tau = _direction(Kf, Rf, Kgn, free, opt, tau, it, hist)
        if du is None:
            raise ConvergenceError(f"singular tangent at iteration {it}", hist)
        step = 1.0
        if opt.line_search:
            def trial(step, du=du, u=u):
                try:
                    Pn, Rn, _ = _evaluate(u + step * _expand(du, free), D, law, k, mu, kind, False)
                except ConvergenceError:
                    return np.inf, np.inf
                return Pn, float(np.linalg.norm(Rn[free]))

            step = _line_search(trial, Pi, rn, float(Rf @ du), k, it, hist)
        u = u + step * _expand(du, free)
        modes.append(mode)
        Pi, R, (K, Kgn) = _evaluate(u, D, law, k, mu, kind)
        rn = float(np.linalg.norm(R[free]))
        hist.append(rn), ehist.append(Pi)
        if not np.isfinite(rn):
            raise ConvergenceError(f"non-finite residual at iteration {it}", hist)
        if rn <= rtol * r_ref:
            return u, K[free][:, free].tocsc(), it, f"||R|| <= {rtol:g} ||R(base circle)||"
        if mode == "newton" and step == 1.0 and np.max(np.abs(du)) <= opt.xtol:
            return u, K[free][:, free].tocsc(), it, f"||dx||_inf <= {opt.xtol:g} R_b"
    raise ConvergenceError(
        f"Newton-Raphson did not converge in {max_iter} iterations at k = {k:g} "
        f"(||R|| = {hist[-1]:.3e}, target {rtol * r_ref:.3e})", hist)


def synthesize_knife_edge(program, *, Rb, options: SynthesisOptions | None = None,
                          samples_per_element: int = 8) -> SynthesisResult:
    """Synthesise the in-line knife-edge cam curve for ``program`` on base radius ``Rb`` (m).

    ``program``: a :class:`femcam.kinematics.CamProgram` (or anything with
    ``.derivatives(theta)`` / a callable ``theta -> (s, s1, s2)`` in m, m/rad, m/rad^2).
    Starts from the base circle (seed 003 Table 1), minimises Pi with Newton-Raphson and
    returns a :class:`SynthesisResult`. Raises :class:`ConvergenceError` (with the residual
    history) if Newton fails and :class:`PressureAngleError` if the law needs a pressure
    angle above ``options.phi_limit`` on this base circle.
    """
    opt = options or SynthesisOptions()
    Rb = _validate.positive("Rb", Rb, "m")
    _validate.positive("samples_per_element", samples_per_element, "")
    law_m = as_law(program)
    # refuse hopeless geometry before any iteration: exact phi on a fine grid
    th = np.linspace(0.0, 2 * np.pi, 20001)
    s_, s1_, _ = law_m(th)
    if np.any(Rb + s_ <= 0):
        raise PressureAngleError(f"Rb = {Rb * 1e3:g} mm: Rb + s(theta) <= 0, the cam curve would "
                                 "pass through the cam centre")
    phx = np.max(np.abs(pressure_angle_exact(Rb, s_, s1_)))
    if phx > opt.phi_limit:
        raise PressureAngleError(
            f"Rb = {Rb * 1e3:g} mm: the lift law needs a pressure angle of {np.degrees(phx):.2f} deg "
            f"> phi_limit = {np.degrees(opt.phi_limit):.2f} deg; the knife-edge follower would jam "
            "(increase the base circle)")

    def law(alpha):                      # lengths scaled by Rb
        s, s1, s2 = law_m(alpha)
        return s / Rb, s1 / Rb, s2 / Rb

    D = _Discretisation(opt.n_elements, opt.quad_points)
    u = D.X.copy()
    mu, kind = opt.mu, opt.stabilization
    # Gauge: Pi is (almost) invariant under sliding all nodes along the converged curve (a
    # zero-energy re-parametrisation mode the seed does not mention; it makes K nearly singular
    # and Newton crawl). Node 0 is held on the x axis (its y DOF is removed).
    free = np.ones(2 * D.nn, bool)
    free[1] = False
    # k-continuation: a penalty Newton solve gets harder as k/mu grows (steps along the curve
    # leave the curved constraint manifold by O(step^2), costing O(k step^2)), so k is raised
    # by opt.k_factor per stage from k_start, each stage starting from the previous curve.
    ks = [opt.k]
    if opt.line_search and opt.k_factor > 1:
        while ks[0] / opt.k_factor >= opt.k_start * mu:
            ks.insert(0, ks[0] / opt.k_factor)
    hist, ehist, modes, stages = [], [], [], []
    t0 = time.perf_counter()
    its = 0
    try:
        for j, k in enumerate(ks):
            r_ref = float(np.linalg.norm(_evaluate(D.X, D, law, k, mu, kind, False)[1][free]))
            last = j == len(ks) - 1
            stages.append(len(hist))
            u, Kf, it, msg = _newton(u, D, law, k, mu, kind, opt, free, r_ref,
                                     opt.rtol if last else max(opt.rtol, 1e-6), hist, ehist, modes,
                                     opt.max_iter)
            its += it
    except ConvergenceError as exc:
        raise ConvergenceError(f"seed-003 synthesis: {exc}", exc.history) from None
    solve_time = time.perf_counter() - t0
    _check_solution(u, D, Kf, hist)
    cond = _condest(Kf) if opt.estimate_condition else float("nan")
    res = _postprocess(u, D, Rb, law_m, opt, samples_per_element, True, its, hist, ehist,
                       f"converged: {msg} after {its} iterations ({len(ks)} k stage(s))", cond,
                       solve_time)
    res.extras.update(modes=tuple(modes), k_stages=tuple(ks), stage_starts=tuple(stages),
                      phi_max_exact=float(phx), n_dof=int(free.sum()))
    return res


def _check_solution(u, D, Kf, hist):
    """Never return a silent wrong curve: a converged Newton iterate must be a minimum of Pi
    (tangent positive definite) and a simple star-shaped curve (polar angle increasing along
    xi, i.e. t . a1 > 0 at every Gauss point). Plain Newton from the base circle can converge
    to a folded curve (a saddle of Pi) - seen with ``line_search=False``."""
    xe = u[D.conn]
    x = np.einsum("qa,eai->eqi", D.N, xe)
    a1 = np.einsum("qa,eai->eqi", D.dN, xe)
    t_a1 = -x[..., 1] * a1[..., 0] + x[..., 0] * a1[..., 1]     # |x| t . a1
    if np.any(t_a1 <= 0):
        bad = np.degrees(np.mod(np.arctan2(x[..., 1], x[..., 0])[t_a1 <= 0], 2 * np.pi))
        raise ConvergenceError(
            f"seed-003 synthesis: Newton converged to a folded curve (the polar angle runs "
            f"backwards near theta = {bad.min():.1f}..{bad.max():.1f} deg): a spurious stationary "
            "point, not the cam; use the globalised solver (line_search=True)", hist)
    _, n_neg = _factor(Kf)
    if n_neg != 0:
        raise ConvergenceError(
            f"seed-003 synthesis: Newton converged to a stationary point of Pi that is not a "
            f"minimum ({n_neg} negative tangent eigenvalue(s))", hist)


def _postprocess(u, D, Rb, law_m, opt, m, converged, it, hist, ehist, msg, cond, solve_time):
    """Sample the converged curve: error and pressure angle at m points per element."""
    _validate.positive("samples_per_element", m, "")
    eta = -1.0 + 2.0 * np.arange(m) / m                # half-open, so no duplicates
    N = np.stack([eta * (eta - 1) / 2, 1 - eta**2, eta * (eta + 1) / 2], axis=1)
    dN = np.stack([eta - 0.5, -2 * eta, eta + 0.5], axis=1)
    xe = u[D.conn] * Rb
    x = np.einsum("qa,eai->eqi", N, xe).reshape(-1, 2)
    a1 = np.einsum("qa,eai->eqi", dN, xe).reshape(-1, 2)
    r = np.hypot(x[:, 0], x[:, 1])
    theta = np.mod(np.arctan2(x[:, 1], x[:, 0]), 2 * np.pi)
    d = x / r[:, None]
    t = np.stack([-d[:, 1], d[:, 0]], axis=1)
    phi = np.arctan2(np.sum(d * a1, 1), np.sum(t * a1, 1))
    s, s1, _ = law_m(theta)
    order = np.argsort(theta)
    nodes = u * Rb
    rn = np.hypot(nodes[:, 0], nodes[:, 1])
    sn = law_m(np.mod(np.arctan2(nodes[:, 1], nodes[:, 0]), 2 * np.pi))[0]
    a1q = np.einsum("qa,eai->eqi", D.dN, u[D.conn])
    stretch = np.sqrt(np.einsum("eqi,eqi->eq", a1q, a1q) / D.A11)
    return SynthesisResult(
        Rb=Rb, options=opt, nodes=nodes, theta=theta[order], r=r[order], x=x[order, 0],
        y=x[order, 1], error=(r - Rb - s)[order], phi=phi[order],
        phi_exact=pressure_angle_exact(Rb, s, s1)[order], node_error=rn - Rb - sn,
        stretch=stretch.ravel(), converged=converged, iterations=it,
        residual_history=tuple(hist), energy_history=tuple(ehist), message=msg,
        condition_estimate=cond, solve_time=solve_time)
