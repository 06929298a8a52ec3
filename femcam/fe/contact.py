r"""Contact operators (consistent nodal forces, condensed compliances) and the contact LCP.

Discretisation
--------------
* Contact unknowns: the pressure ``p_k`` at the evenly spaced VERTEX nodes ``x_k`` of the
  fine zone, interpolated linearly between them (P1 pressure along the contact curve). Using
  every P2 node (corner and midside alternately) gives a checkerboard pressure (docs/fe.md).
* Consistent nodal forces ``B[i, k] = \int N_i L_k ds`` (``N_i`` the P2 -- or P1 -- trace shape
  functions on a contact edge, ``L_k`` the P1 pressure hats). On an edge of length ``h`` the
  exact integrals are ``h/6`` (end node of the same hat), ``0`` (other end) and ``h/3`` (midside)
  for P2, and ``h/3``, ``h/6`` for P1.
* Condensation: ``U = K^{-1} B`` (one factorisation, ``n_c`` right-hand sides per load
  direction); the normal displacement of the contact vertices is ``A = S_y U``.
* Frame: ``y`` from cam to roller. The pressure pushes the cam in ``-y`` and the roller in
  ``+y``; the friction traction ``q = mu p`` acts on the cam in ``+sliding x`` and on the roller in
  ``-sliding x`` (``femcam.hertz`` convention: ``sliding = +1`` is hertz ``direction = +1`` for the
  cam). Friction between dissimilar bodies moves the surfaces normally (Johnson 1985 §5.4 /
  §7.1 coupling, ``beta`` of Dundurs): that enters through ``A_t = S_y K^{-1} B_x``.

Complementarity problem (per unit face width, ``W = F / length`` in N/m)
------------------------------------------------------------------------
.. math:: g = h_0(x) + (A_n + s\,\mu\,A_t)\,p - \delta \ge 0,\quad p \ge 0,\quad p^T g = 0,
          \quad w^T p = W

with ``h_0(x) = d_{Rr}(x) + d_{\rho}(x)`` the exact initial separation of the two arcs
(:func:`femcam.mesh.surface_height`; concave cams give ``d_rho < 0``), ``delta`` the rigid
approach (unknown) and ``w_k = \int L_k ds`` the trapezoid weights. Solved by a primal-dual
active-set method (semismooth Newton on ``p = max(0, p - c g)``), which terminates when the
active set repeats (Hintermüller, Ito & Kunisch, SIAM J. Optim. 13, 2002).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from .. import _validate
from ..errors import ConvergenceError


def edge_midside_dofs(body, contact: np.ndarray) -> np.ndarray | None:
    """Vector DOF pairs of the midside nodes of consecutive contact vertices.

    Parameters
    ----------
    body : femcam.fe.elasticity.Body
        The assembled body.
    contact : ndarray of int, shape (n_c,)
        Mesh vertex indices of the contact nodes, in order along the surface.

    Returns
    -------
    ndarray of int, shape (2, n_c - 1), or None
        ``(u_x, u_y)`` DOFs of the midside node of each contact edge; None for P1 elements.

    Raises
    ------
    InputError
        Two consecutive contact vertices are not joined by a mesh edge (named).
    """
    if body.element != "P2":
        return None
    facets = body.mesh.facets  # (2, nf), sorted so facets[0] < facets[1]
    a = np.minimum(contact[:-1], contact[1:])
    b = np.maximum(contact[:-1], contact[1:])
    n = body.mesh.p.shape[1]
    key_f = facets[0].astype(np.int64) * n + facets[1]
    order = np.argsort(key_f)
    key = a.astype(np.int64) * n + b
    pos = np.searchsorted(key_f, key, sorter=order)
    f = order[np.clip(pos, 0, key_f.size - 1)]
    if not np.array_equal(key_f[f], key):
        k = int(np.flatnonzero(key_f[f] != key)[0])
        raise _validate.fail("contact", f"vertices {int(contact[k])}, {int(contact[k + 1])}", "",
                             "consecutive contact vertices must be joined by a mesh edge (the "
                             "contact nodes are not in order along the surface)")
    return body.basis.facet_dofs[:, f]


def load_operator(body, contact: np.ndarray, x: np.ndarray, component: int) -> sp.csc_matrix:
    """Sparse ``B``: consistent nodal forces of unit pressure hats (a hat loads its vertex and
    the midside nodes of its two edges; sparse, because the dense ``(n_dofs, n_c)`` array is
    ~100 MB per body and direction at a/h = 40).

    Parameters
    ----------
    body : femcam.fe.elasticity.Body
        The assembled body.
    contact : ndarray of int, shape (n_c,)
        Mesh vertex indices of the contact nodes, in order along the surface.
    x : ndarray of float, shape (n_c,)
        Abscissae of the contact nodes [m] (edge lengths are projected on x).
    component : int
        Load direction: 0 = x, 1 = y.

    Returns
    -------
    scipy.sparse.csc_matrix, shape (n_dofs, n_c)
        ``B[i, k] = int N_i L_k ds`` [m]: nodal force per unit thickness [N/m] per unit nodal
        pressure [Pa].
    """
    nc = contact.size
    # edge lengths projected on x: small-slope theory, as in Hertz (docs/fe.md, "Limits of the
    # model"). The arc slope is x/R, so the true edge is longer by ~ (x/R)^2 / 2: 3e-4 h at the
    # end of the fine zone of the seed 002 case (2.5 a / Rr = 2.6 %), but 1.7 % h at x = a
    # for the nearly conformal rho = -1.005 Rr (a = 0.18 Rr) and more under huge loads
    hs = np.diff(x)
    vd = body.basis.nodal_dofs[component, contact]
    md = edge_midside_dofs(body, contact)
    k = np.arange(nc - 1)
    if md is None:  # P1: int L_a L_a = h/3, int L_a L_b = h/6
        rows = (vd[k], vd[k + 1], vd[k + 1], vd[k])
        vals = (hs / 3, hs / 3, hs / 6, hs / 6)
    else:  # P2 trace x P1 hats: ends h/6 (own hat), 0 (other hat); midside h/3 each
        rows = (vd[k], vd[k + 1], md[component], md[component])
        vals = (hs / 6, hs / 6, hs / 3, hs / 3)
    cols = (k, k + 1, k, k + 1)
    # duplicates (a vertex shared by two edges) are summed, as np.add.at did
    return sp.csc_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                         shape=(body.n_dofs, nc))


def load_matrix(body, contact: np.ndarray, x: np.ndarray, component: int) -> np.ndarray:
    """Dense ``B`` of :func:`load_operator`.

    Parameters
    ----------
    body : femcam.fe.elasticity.Body
        The assembled body.
    contact : ndarray of int, shape (n_c,)
        Mesh vertex indices of the contact nodes.
    x : ndarray of float, shape (n_c,)
        Abscissae of the contact nodes [m].
    component : int
        Load direction: 0 = x, 1 = y.

    Returns
    -------
    ndarray of float, shape (n_dofs, n_c)
        ``B`` [m] (nodal force per unit thickness [N/m] per unit nodal pressure [Pa]).
    """
    return load_operator(body, contact, x, component).toarray()


def trapezoid_weights(x: np.ndarray) -> np.ndarray:
    """Trapezoid weights ``w_k = int L_k dx`` of P1 hats.

    Parameters
    ----------
    x : ndarray of float, shape (n,)
        Increasing node abscissae [m].

    Returns
    -------
    ndarray of float, shape (n,)
        ``w_k`` [m]; ``w @ p`` is the load per unit face width [N/m] for ``p`` in Pa.
    """
    hs = np.diff(x)
    w = np.zeros(x.size)
    w[:-1] += hs / 2
    w[1:] += hs / 2
    return w


@dataclass(frozen=True)
class LCPSolution:
    """Solution of :func:`solve_lcp`.

    Attributes
    ----------
    p : ndarray
        Nodal pressures (Pa) at the contact vertices.
    g : ndarray
        Gap (m) after loading at the vertices.
    delta : float
        Rigid approach (m).
    active : ndarray of bool
        Nodes in contact.
    iterations : int
        Active-set iterations.
    residual : float
        Complementarity residual ``||min(p, c g)||_inf / max(p)`` (-).
    history : tuple of float
        Residual per iteration.
    converged : bool
        True when the active set repeated with ``residual <= tol``.
    message : str
        Why it did not converge (empty when it did).
    """

    p: np.ndarray
    g: np.ndarray
    delta: float
    active: np.ndarray
    iterations: int
    residual: float
    history: tuple
    converged: bool
    message: str = ""


def solve_lcp(A: np.ndarray, h0: np.ndarray, w: np.ndarray, W: float, *, active0: np.ndarray,
              max_iter: int = 50, tol: float = 1e-10) -> LCPSolution:
    """Primal-dual active set for ``g = h0 + A p - delta >= 0, p >= 0, p.g = 0, w.p = W``.

    Parameters
    ----------
    A : ndarray (n, n)
        Compliance (m/Pa): gap change at node i per unit pressure hat k.
    h0 : ndarray (n,)
        Initial gap (m).
    w : ndarray (n,)
        Quadrature weights (m): ``w.p`` is the load per unit length.
    W : float
        Load per unit length (N/m).
    active0 : ndarray of bool
        Initial guess of the contact set.
    max_iter : int
        Iteration limit.
    tol : float
        Complementarity tolerance on ``residual`` (-), used as given.

    Returns
    -------
    LCPSolution
        ``converged`` is True when the active set repeats and ``residual <= tol``. A fixed point
        whose residual stays above ``tol`` (round-off in an ill-conditioned ``A``) or an active
        set that cycles returns ``converged = False`` with the reason in ``message``. Raises
        :class:`ConvergenceError` with the residual history if the active set is still changing
        after ``max_iter`` iterations.
    """
    n = h0.size
    c = 1.0 / np.mean(np.diag(A))
    active = active0.copy()
    history = []
    seen = set()
    p = np.zeros(n)
    delta = 0.0
    for it in range(1, max_iter + 1):
        I = np.nonzero(active)[0]
        if I.size == 0:
            I = np.array([int(np.argmin(h0))])
            active[I] = True
        m = I.size
        M = np.zeros((m + 1, m + 1))
        M[:m, :m] = A[np.ix_(I, I)]
        M[:m, m] = -1.0
        M[m, :m] = w[I]
        rhs = np.concatenate([-h0[I], [W]])
        sol = np.linalg.solve(M, rhs)
        p = np.zeros(n)
        p[I] = sol[:m]
        delta = float(sol[m])
        g = h0 + A @ p - delta
        pmax = max(float(p.max()), 1e-300)
        res = float(np.max(np.abs(np.minimum(p, c * g)))) / pmax
        history.append(res)
        new = (p - c * g) > 0.0
        key = new.tobytes()
        if np.array_equal(new, active):
            ok = res <= tol
            msg = "" if ok else (f"active set settled but the complementarity residual {res:.3g} "
                                 f"exceeds tol = {tol:.3g}")
            return LCPSolution(p, g, delta, active, it, res, tuple(history), ok, msg)
        if key in seen:
            return LCPSolution(p, g, delta, active, it, res, tuple(history), False,
                               f"active set cycles (residual {res:.3g}, tol = {tol:.3g})")
        seen.add(key)
        active = new
    raise ConvergenceError(f"contact active set did not settle in {max_iter} iterations "
                           f"(last residual {history[-1]:.3g})", history)
