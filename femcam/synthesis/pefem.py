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
alpha           cam angle = polar angle of x, atan2(x_2, x_1)        rad      eq. 2 (energy)
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

The derivation, with the seed's typos corrected, is in :mod:`femcam.synthesis.energy`
(energy, residual, tangent); the globalised Newton solver in :mod:`femcam.synthesis.newton`.
The inputs and the result are in :mod:`femcam.synthesis.options`; this module holds the
driver :func:`synthesize_knife_edge`.

Orientation: the curve is the polar curve ``r(alpha) = R_b + s(alpha)`` at polar angle
``+alpha`` (a cam turning clockwise under a follower on the +x axis). The direct profile of a
counter-clockwise cam is the mirror image ``y -> -y``.
"""

from __future__ import annotations

import time

import numpy as np

from .. import _validate
from ..errors import ConvergenceError, InputError
from .energy import _Discretisation, _evaluate
from .newton import _condest, _factor, _newton
from .options import STABILIZATIONS, PressureAngleError, SynthesisOptions, SynthesisResult

__all__ = ["STABILIZATIONS", "PressureAngleError", "SynthesisOptions", "SynthesisResult", "as_law",
           "pressure_angle_exact", "synthesize_knife_edge"]


# --------------------------------------------------------------------------- law adapter
def as_law(program):
    """The lift law as a function ``f(alpha) -> (s, s1, s2)``.

    Parameters
    ----------
    program : CamProgram or callable
        An object with ``.derivatives(theta)`` giving ``s, s1, s2`` as attributes or keys
        (a :class:`femcam.kinematics.CamProgram`), or a callable already returning them.

    Returns
    -------
    callable
        ``f(alpha)`` with alpha in rad, returning ``(s, s1, s2)`` in m, m/rad, m/rad^2.

    Raises
    ------
    InputError
        ``program`` is neither.
    """
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


def pressure_angle_exact(Rb, s, s1):
    r"""In-line knife-edge pressure angle (rad).

    .. math:: \phi = \arctan\frac{s'(\theta)}{R_b + s(\theta)}

    (Norton, *Design of Machinery*, 2nd ed., eq. 8.31 with zero offset; seed 003 eq. 40 fixed).

    Parameters
    ----------
    Rb : float
        Base-circle radius (m).
    s, s1 : array_like
        Lift (m) and its derivative ds/dtheta (m/rad).

    Returns
    -------
    ndarray
        Pressure angle phi (rad), broadcast shape of ``s`` and ``s1``.

    >>> round(float(np.degrees(pressure_angle_exact(1.0, 0.0, 1.0))), 6)
    45.0
    """
    Rb = _validate.positive_array("Rb", Rb, "m")
    return np.arctan2(_validate.finite_array("s1", s1, "m/rad"), Rb + _validate.finite_array("s", s, "m"))


def synthesize_knife_edge(program, *, Rb, options: SynthesisOptions | None = None,
                          samples_per_element: int = 8) -> SynthesisResult:
    """Synthesise the in-line knife-edge cam curve for ``program`` on base radius ``Rb``.

    Starts from the base circle (seed 003 Table 1), minimises Pi with Newton-Raphson (k
    stages, see :class:`SynthesisOptions`) and samples the converged curve.

    Parameters
    ----------
    program : CamProgram or callable
        The lift law: a :class:`femcam.kinematics.CamProgram` (anything with
        ``.derivatives(theta)``) or a callable ``theta -> (s, s1, s2)`` in m, m/rad, m/rad^2.
    Rb : float
        Base-circle radius (m, > 0).
    options : SynthesisOptions, optional
        Discretisation and solver settings (default ``SynthesisOptions()``).
    samples_per_element : int
        Points per element at which the result is sampled (> 0).

    Returns
    -------
    SynthesisResult
        The curve, its errors and the solver diagnostics.

    Raises
    ------
    ConvergenceError
        Newton failed, or converged to a folded curve or a saddle of Pi (with the residual
        history).
    PressureAngleError
        The law needs a pressure angle above ``options.phi_limit`` on this base circle, or
        ``Rb + s <= 0``.
    InputError
        Bad ``Rb``, ``samples_per_element`` or ``program``.
    """
    opt = options or SynthesisOptions()
    Rb = _validate.positive("Rb", Rb, "m")
    _validate.integer("samples_per_element", samples_per_element, 1)
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
