r"""Contact operators on curved boundaries and the multi-contact complementarity problem.

Unknowns: nodal pressures ``lambda_k >= 0`` (P1 hats in arc length) on every contact of the
floating ring (cam, bore) or the needle forces, plus rigid unknowns ``r`` (ring translation,
cam approach). With ``g`` the gaps (m), ``A`` the condensed compliance (m per Pa),
``G`` the rigid-motion columns and ``C lambda = d`` the equilibrium rows:

.. math:: g = h_0 + A\,\lambda + G\,r \ge 0,\quad \lambda \ge 0,\quad \lambda^T g = 0,
          \quad C\,\lambda = d

solved by the primal-dual active-set method of :func:`femcam.fe.contact.solve_lcp`
(Hintermüller, Ito & Kunisch 2002), generalised to several rigid unknowns and constraints.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ConvergenceError
from ..fe.contact import edge_midside_dofs


def arc_load_matrix(body, nodes: np.ndarray, centre: tuple, closed: bool,
                    direction: float = 1.0, scale: float = 1.0, tangential: bool = False) -> np.ndarray:
    """Dense ``B`` (n_dofs, n): nodal forces of unit radial pressure hats on a circle.

    ``nodes`` are vertices on a circle about ``centre`` (ordered by angle; ``closed`` joins the
    last to the first). The hat ``L_k`` (P1 in arc length) times ``direction * e_r`` (outward
    radial unit vector at each node) is integrated against the P2 (or P1) trace: ``h/6`` at the
    own vertex, ``h/3`` at the midside nodes, ``h/3, h/6`` for P1 (as
    :func:`femcam.fe.contact.load_matrix`, with the chord length ``h`` of each edge).
    ``tangential``: the hats act along ``direction * e_theta`` (counter-clockwise) instead (a
    shear traction, e.g. the drive torque on the cam's bore).

    Parameters
    ----------
    body : femcam.fe.elasticity.Body
        The assembled body (P1 or P2).
    nodes : ndarray of int, shape (n,)
        Vertex nodes on the circle, ordered by angle.
    centre : (float, float)
        Circle centre [m].
    closed : bool
        Join the last node to the first (a full circle).
    direction : float, optional
        +1 outward radial (or counter-clockwise), -1 inward.
    scale : float, optional
        Factor on every force [-] (e.g. ``Rb / Rs`` to carry a bore pressure onto the shaft).
    tangential : bool, optional
        Shear along ``e_theta`` instead of pressure along ``e_r``.

    Returns
    -------
    ndarray, shape (n_dofs, n)
        Nodal forces of each unit hat [N/m per Pa] (DOFs interleaved x, y).
    """
    n = nodes.size
    a = nodes
    b = np.roll(nodes, -1) if closed else nodes[1:]
    a = a if closed else nodes[:-1]
    k = np.arange(a.size)
    k1 = (k + 1) % n
    p = body.mesh.p
    hs = np.hypot(*(p[:, b] - p[:, a]))
    B = np.zeros((body.n_dofs, n))
    cx, cy = centre

    def er(xy):
        d = xy - np.array([[cx], [cy]])
        if tangential:
            d = np.array([-d[1], d[0]])
        return direction * d / np.hypot(*d)

    md = edge_midside_dofs(body, np.concatenate([a, b[-1:]])) if body.element == "P2" else None
    ea, eb = er(p[:, a]), er(p[:, b])
    for c in (0, 1):
        va = body.basis.nodal_dofs[c, a]
        vb = body.basis.nodal_dofs[c, b]
        if md is None:
            np.add.at(B, (va, k), scale * ea[c] * hs / 3)
            np.add.at(B, (vb, k1), scale * eb[c] * hs / 3)
            np.add.at(B, (vb, k), scale * eb[c] * hs / 6)
            np.add.at(B, (va, k1), scale * ea[c] * hs / 6)
        else:
            xm = body.basis.doflocs[:, md[0]]
            em = er(xm)
            np.add.at(B, (va, k), scale * ea[c] * hs / 6)
            np.add.at(B, (vb, k1), scale * eb[c] * hs / 6)
            np.add.at(B, (md[c], k), scale * em[c] * hs / 3)
            np.add.at(B, (md[c], k1), scale * em[c] * hs / 3)
    return B


def radial_measure(body, nodes: np.ndarray, centre: tuple, direction: float = 1.0):
    """The radial displacement ``u . (direction e_r)`` at ``nodes`` as ``ex u[dof_x] + ey u[dof_y]``.

    Parameters
    ----------
    body : femcam.fe.elasticity.Body
        The assembled body.
    nodes : ndarray of int, shape (n,)
        Vertex nodes.
    centre : (float, float)
        Centre of the radial direction [m].
    direction : float, optional
        +1 outward, -1 inward.

    Returns
    -------
    dof_x, dof_y : ndarray of int, shape (n,)
        The x and y DOFs of ``nodes``.
    ex, ey : ndarray, shape (n,)
        Components of ``direction e_r`` [-].
    """
    p = body.mesh.p[:, nodes]
    d = p - np.array([[centre[0]], [centre[1]]])
    e = direction * d / np.hypot(*d)
    return body.basis.nodal_dofs[0, nodes], body.basis.nodal_dofs[1, nodes], e[0], e[1]


def arc_weights(n: int, spacing: float, closed: bool) -> np.ndarray:
    """``w_k = int L_k ds`` of P1 hats with uniform ``spacing``.

    Parameters
    ----------
    n : int
        Number of hats.
    spacing : float
        Node spacing (arc length) [m].
    closed : bool
        A closed curve (else the end hats are halved).

    Returns
    -------
    ndarray, shape (n,)
        Hat weights [m].
    """
    w = np.full(n, spacing)
    if not closed:
        w[[0, -1]] *= 0.5
    return w


@dataclass(frozen=True)
class MultiLCPSolution:
    """Solution of :func:`solve_multi_lcp` (symbols of the module docstring).

    Attributes
    ----------
    lam : ndarray, shape (n,)
        Contact unknowns: nodal pressures [Pa] (or needle loads [N/m]).
    g : ndarray, shape (n,)
        Gaps [m].
    r : ndarray, shape (m,)
        Rigid unknowns (translations, approaches) [m].
    active : ndarray of bool, shape (n,)
        The final active set.
    iterations : int
        Active-set iterations.
    residual : float
        Relative complementarity residual ``max|min(lam, c g)| / max|lam|`` [-].
    history : tuple of float
        Residual of every iteration [-].
    converged : bool
        Always True (a solve that does not settle raises).
    """

    lam: np.ndarray
    g: np.ndarray
    r: np.ndarray
    active: np.ndarray
    iterations: int
    residual: float
    history: tuple
    converged: bool


def solve_multi_lcp(A, h0, G, C, d, *, active0, max_iter: int = 80, tol: float = 1e-10,
                    bilateral=None):
    """Active-set solve of the problem in the module docstring (see there for the symbols).

    ``bilateral`` (bool mask, optional): unknowns that are always active, of either sign, with
    ``g = 0`` (a bonded, frictionless tie).

    Parameters
    ----------
    A : ndarray, shape (n, n)
        Condensed compliance [m/Pa].
    h0 : ndarray, shape (n,)
        Initial gaps [m].
    G : ndarray, shape (n, m)
        Rigid-motion columns [-].
    C : ndarray, shape (m, n)
        Equilibrium rows (weights) [m].
    d : ndarray, shape (m,)
        Equilibrium right-hand sides (loads per unit width) [N/m].
    active0 : ndarray of bool, shape (n,)
        Initial active set.
    max_iter : int, optional
        Most active-set iterations.
    tol : float, optional
        Residual that ends the iterations once the active set repeats [-].
    bilateral : ndarray of bool, shape (n,), optional
        Unknowns that are always active, of either sign, with ``g = 0``.

    Returns
    -------
    MultiLCPSolution
        Pressures, gaps, rigid unknowns and diagnostics.

    Raises
    ------
    ConvergenceError
        The active set cycles; carries the residual history.
    """
    n = h0.size
    m = d.size
    c = 1.0 / np.mean(np.diag(A))
    bil = np.zeros(n, dtype=bool) if bilateral is None else np.asarray(bilateral, dtype=bool)
    active = active0.copy() | bil
    history, seen = [], set()
    for it in range(1, max_iter + 1):
        I = np.nonzero(active)[0]
        k = I.size
        M = np.zeros((k + m, k + m))
        M[:k, :k] = A[np.ix_(I, I)]
        M[:k, k:] = G[I]
        M[k:, :k] = C[:, I]
        rhs = np.concatenate([-h0[I], d])
        try:
            sol = np.linalg.solve(M, rhs)
        except np.linalg.LinAlgError:
            sol = np.linalg.lstsq(M, rhs, rcond=None)[0]
        lam = np.zeros(n)
        lam[I] = sol[:k]
        r = sol[k:]
        g = h0 + A @ lam + G @ r
        uni = ~bil
        res = (float(np.max(np.abs(np.minimum(lam[uni], c * g[uni])), initial=0.0))
               / max(float(np.abs(lam).max()), 1e-300))
        history.append(res)
        new = ((lam - c * g) > 0.0) | bil
        key = new.tobytes()
        if np.array_equal(new, active) and res <= max(tol, 1e-9):
            return MultiLCPSolution(lam, g, r, active, it, res, tuple(history), True)
        if (np.array_equal(new, active) or key in seen) and res < 1e-6:
            return MultiLCPSolution(lam, g, r, active, it, res, tuple(history), True)
        seen.add(key)
        active = new
    raise ConvergenceError(f"ring contact active set did not settle in {max_iter} iterations "
                           f"(last residual {history[-1]:.3g})", history)
