r"""Vectorised plane-elasticity stiffness of straight-sided triangles, and the contact-last order.

Symbols: ``K`` stiffness (N/m per unit thickness), ``lam, mu_L`` Lamé parameters (Pa, per element
for a coated body), ``phi_j`` the scalar shape functions (P1 or P2) of a triangle, ``g_j`` their
physical gradients (1/m), ``J`` the affine map's Jacobian (m), ``c, d`` displacement components.

Local stiffness of the vector shape functions ``phi_j e_c`` and ``phi_l e_d`` (weak form of
:mod:`femcam.fe.elasticity`; Zienkiewicz & Taylor 2000 §4.2):

.. math:: K^e_{(j c),(l d)} = \int_T \lambda\, g_{j,c}\, g_{l,d}
          + \mu \left(\delta_{cd}\, g_j \cdot g_l + g_{j,d}\, g_{l,c}\right) dA

On a straight-sided triangle ``g`` is constant (P1) or linear (P2), so the integrand is at most
quadratic and the three-point edge-midpoint rule (weights ``|T| / 3``) integrates it exactly
(Strang & Fix 1973 §4.3): the matrix equals scikit-fem's ``asm(linear_elasticity(...))`` to
round-off (``tests/test_fe_assembly.py``), at a fraction of the time of its generic form
assembly (docs/performance.md).

The contact-last order (:func:`contact_last_order`) serves
``SolverOptions(stress_operators="per_solve")``: the minimum-degree order of the node graph of
the body WITHOUT the contact-surface nodes, each node's two DOFs kept together, then the
contact-surface DOFs; the trailing factor blocks are then the Schur complement on the contact
surface (:meth:`femcam.fe.elasticity.Body.schur_solve`).
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

#: edge midpoints of the reference triangle (exact for quadratic integrands), weight 1/6 each
_QUAD_X = np.array([[0.5, 0.5, 0.0], [0.0, 0.5, 0.5]])
_QUAD_W = np.full(3, 1.0 / 6.0)


def elasticity_stiffness(points: np.ndarray, triangles: np.ndarray, element_dofs: np.ndarray,
                         scalar_element, n_dofs: int, lam, mu_L) -> sp.csr_matrix:
    """Global stiffness ``K`` (csr, ``n_dofs`` square) of plane linear elasticity.

    Parameters
    ----------
    points : ndarray (2, n_nodes)
        Vertex coordinates (m).
    triangles : ndarray (3, n_el)
        Vertex indices of each triangle.
    element_dofs : ndarray (2 n_loc, n_el)
        Global vector DOFs of each element, interleaved ``(u_x, u_y)`` per local scalar node in
        the order of ``scalar_element.lbasis`` (scikit-fem's ``ElementVector`` numbering).
    scalar_element : skfem element
        The scalar P1 or P2 triangle (its ``lbasis`` gives the reference gradients).
    n_dofs : int
        Number of global DOFs.
    lam, mu_L : float or ndarray (n_el,)
        Lamé parameters (Pa).

    Returns
    -------
    scipy.sparse.csr_matrix
        ``K`` (N/m per unit thickness).
    """
    nloc = element_dofs.shape[0] // 2
    # reference gradients at the quadrature points: (nloc, 2[k], nq)
    G = np.stack([scalar_element.lbasis(_QUAD_X, j)[1] for j in range(nloc)])
    p, t = points, triangles
    x0 = p[:, t[0]]
    J = np.stack([p[:, t[1]] - x0, p[:, t[2]] - x0], axis=2)  # (2[i], nel, 2[k]) dx_i/dxi_k
    det = J[0, :, 0] * J[1, :, 1] - J[0, :, 1] * J[1, :, 0]
    inv = np.empty_like(J)  # dxi_k/dx_i as (k, nel, i)
    inv[0, :, 0] = J[1, :, 1] / det
    inv[0, :, 1] = -J[0, :, 1] / det
    inv[1, :, 0] = -J[1, :, 0] / det
    inv[1, :, 1] = J[0, :, 0] / det
    g = np.einsum("jkq,kei->ejiq", G, inv).reshape(det.size, 2 * nloc, -1)  # (nel, (j c), nq)
    wq = np.abs(det)[:, None] * _QUAD_W  # (nel, nq)
    # M[e, (j c), (l d)] = sum_q w_q g_jc g_ld: one batched product gives all three terms
    M = np.matmul(g * wq[:, None, :], g.transpose(0, 2, 1)).reshape(det.size, nloc, 2, nloc, 2)
    lam = np.asarray(lam, dtype=float).reshape(-1, 1, 1, 1, 1)
    mu = np.asarray(mu_L, dtype=float).reshape(-1, 1, 1)
    Kloc = lam * M + mu[..., None, None] * M.transpose(0, 1, 4, 3, 2)  # lam g_jc g_ld + mu g_jd g_lc
    gg = mu * (M[:, :, 0, :, 0] + M[:, :, 1, :, 1])  # mu g_j . g_l on the diagonal c = d
    Kloc[:, :, 0, :, 0] += gg
    Kloc[:, :, 1, :, 1] += gg
    n = 2 * nloc
    dofs = element_dofs.T  # (nel, n) in the local order (j, c) -> 2 j + c
    rows = np.broadcast_to(dofs[:, :, None], (dofs.shape[0], n, n))
    cols = np.broadcast_to(dofs[:, None, :], (dofs.shape[0], n, n))
    K = sp.coo_matrix((Kloc.reshape(-1), (rows.reshape(-1), cols.reshape(-1))),
                      shape=(n_dofs, n_dofs))
    return K.tocsr()


def triangle_edges(triangles: np.ndarray, n_nodes: int) -> tuple[np.ndarray, np.ndarray]:
    """The edges of a triangle mesh as scikit-fem numbers them (``Mesh.facets``, ``Mesh.t2f``).

    scikit-fem builds its edge table with ``np.unique`` over the columns of the sorted vertex
    pairs (``Mesh.build_entities``); with each pair packed in one integer key
    ``lo * n_nodes + hi`` a one-dimensional ``np.unique`` gives the same lexicographic order and
    the same arrays (``tests/test_fe_assembly.py``) in far less time (docs/performance.md). The
    edge numbering sets the P2 midside DOFs, so the arrays must match exactly.

    Parameters
    ----------
    triangles : ndarray of int, shape (3, n_el)
        Vertex indices of each triangle (scikit-fem's ``mesh.t``).
    n_nodes : int
        Number of vertices.

    Returns
    -------
    facets : ndarray of int, shape (2, n_edges)
        Vertex pairs ``(lo, hi)`` of the edges, sorted lexicographically (dtype of ``triangles``).
    t2f : ndarray of int, shape (3, n_el)
        Edges of each triangle: local edges (0, 1), (1, 2), (0, 2).
    """
    t = triangles
    a = np.concatenate([t[0], t[1], t[0]]).astype(np.int64)
    b = np.concatenate([t[1], t[2], t[2]]).astype(np.int64)
    keys, t2f = np.unique(np.minimum(a, b) * n_nodes + np.maximum(a, b), return_inverse=True)
    facets = np.ascontiguousarray(np.stack([keys // n_nodes, keys % n_nodes]).astype(t.dtype))
    return facets, t2f.reshape(3, t.shape[1])


def contact_last_order(K: sp.csr_matrix, free: np.ndarray, last: np.ndarray,
                       ordering: str) -> np.ndarray:
    """Factor order (positions in ``free``) with the DOFs ``last`` (global indices) at the end.

    The rest is ordered on the node graph (DOFs ``2 n`` and ``2 n + 1`` are the two components
    of node ``n``) of the nodes without a ``last`` DOF, by SuperLU's column ordering
    ``ordering`` (taken from an incomplete factorisation with everything dropped: ``spilu``
    returns the same ``perm_c`` as ``splu`` at a fraction of the cost). Ordering the reduced
    graph, not the whole one with the ``last`` DOFs moved afterwards, is what keeps the fill of
    the constrained order low (docs/performance.md).

    Parameters
    ----------
    K : scipy.sparse.csr_matrix, shape (n_dofs, n_dofs)
        Global stiffness [N/m per unit thickness]; only its sparsity pattern is used.
    free : ndarray of int, shape (n_free,)
        Global indices of the unconstrained DOFs (the factorised ones).
    last : ndarray of int
        Global indices of the DOFs to order last (the contact-surface DOFs).
    ordering : str
        SuperLU ``permc_spec`` (e.g. ``"MMD_AT_PLUS_A"``).

    Returns
    -------
    ndarray of int, shape (n_free,)
        Positions in ``free``, in factor order, the ``last`` DOFs (those in ``free``) at the end.
    """
    n_nodes = K.shape[0] // 2
    pos = np.full(K.shape[0], -1)
    pos[free] = np.arange(free.size)
    keep = np.zeros(n_nodes, dtype=bool)
    keep[free // 2] = True
    keep[np.asarray(last) // 2] = False
    nodes = np.nonzero(keep)[0]
    Kn = K[2 * nodes][:, 2 * nodes].tocsc()  # node graph: the x-x block has its pattern
    ilu = spla.spilu(Kn, drop_tol=1e300, fill_factor=1.0, permc_spec=ordering,
                     diag_pivot_thresh=0.0, options={"SymmetricMode": True})
    first = nodes[np.argsort(ilu.perm_c)]  # perm_c[j] is the position of column j
    dofs = np.stack([2 * first, 2 * first + 1], axis=1).ravel()
    order = np.concatenate([pos[dofs], pos[np.asarray(last)]])
    return order[order >= 0]

