"""Newton-Raphson on the seed-003 potential energy (seed 003 Table 1), globalised: exact
Newton where the tangent is positive definite, a shifted or Gauss-Newton direction where it is
not, Armijo backtracking (Nocedal & Wright 2006 §3.1, §3.4); sparse LU with inertia and a
condition estimate."""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ..errors import ConvergenceError
from .energy import _evaluate


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
