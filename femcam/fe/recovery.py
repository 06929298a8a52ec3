r"""Stress recovery near the contact, half-width fit, stress maxima.

Stresses are reported in Johnson's frame of each body: ``x`` along the surface, ``z >= 0`` depth
into the body, tension positive (``sx, sz, txz``; ``sy`` is the out-of-plane stress,
``nu (sx + sz)`` in plane strain). The cam occupies ``y < 0`` in the FE frame, so there
``z = y_s(x) - y`` and ``txz = -s_xy``; the roller occupies ``y > 0``: ``z = y - y_s(x)``,
``txz = s_xy``.

Derived quantities (Johnson 1985 §4.2, §7.1):

.. math:: \tau_1 = \sqrt{\left(\tfrac{\sigma_x - \sigma_z}{2}\right)^2 + \tau_{xz}^2},\qquad
          \sigma_{vM} = \sqrt{\tfrac12[(\sigma_x-\sigma_z)^2 + (\sigma_z-\sigma_y)^2
          + (\sigma_y-\sigma_x)^2] + 3\tau_{xz}^2}

The range of the orthogonal shear over one pass is in :mod:`femcam.fe.passrange`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp

from ..mesh import surface_height
from .contact import edge_midside_dofs
from .elasticity import Body, scalar_node_coordinates, stress_operator


@dataclass(frozen=True, eq=False)
class EvalSet:
    """Stress recovery on the scalar nodes of one body near the contact.

    Parameters
    ----------
    body : str
        Body name, ``"cam"`` or ``"roller"``.
    nodes : ndarray of int, shape (n_eval,)
        Scalar node indices of the window.
    x, z : ndarray of float, shape (n_eval,)
        Abscissa and depth (``z >= 0``) of each window node [m].
    Sn, St : ndarray of float, shape (3, n_eval, n_c), or None
        ``(sx, sz, txz)`` [Pa] per unit nodal pressure / unit friction traction [Pa], i.e. [-]
        (already with this body's sign: pressure into the body, friction in the model's sliding
        sense), for ``SolverOptions.stress_operators = "precompute"``; None for ``"per_solve"``
        (:meth:`stresses` then back-solves the body for each load case with ``S``, ``Bn``,
        ``Bt`` and ``solver``).
    surface : ndarray of int
        Indices into ``nodes`` of the nodes on the contact surface, sorted by x.
    S : scipy.sparse.csr_matrix, shape (3 n_eval, n_dofs), optional
        ``"per_solve"``: displacements [m] -> ``(sx, sz, txz)`` [Pa] in the Johnson frame.
    Bn, Bt : scipy.sparse.csc_matrix, shape (n_dofs, n_c), optional
        ``"per_solve"``: consistent nodal forces of unit pressure / traction hats [m].
    solver : Body, optional
        ``"per_solve"``: the factorised body.
    pass_P, pass_x, pass_z, pass_ok : optional
        The rows of equal depth for the range of ``txz`` over one pass
        (:func:`femcam.fe.passrange.pass_grid`, attached by the model build; None: not computed):
        interpolation (n_ok, n_eval) [-] at the grid points inside the window, abscissae
        (n_x,) [m], depths (n_z,) [m], and the grid points inside the window (n_z, n_x).
    """

    body: str
    nodes: np.ndarray
    x: np.ndarray
    z: np.ndarray
    Sn: np.ndarray | None
    St: np.ndarray | None
    surface: np.ndarray
    S: sp.csr_matrix | None = None
    Bn: sp.csc_matrix | None = None
    Bt: sp.csc_matrix | None = None
    solver: Body | None = field(default=None, repr=False)
    pass_P: sp.csr_matrix | None = field(default=None, repr=False)
    pass_x: np.ndarray | None = None
    pass_z: np.ndarray | None = None
    pass_ok: np.ndarray | None = None

    def stresses(self, p: np.ndarray, q: np.ndarray | None = None) -> np.ndarray:
        """Stresses at the window nodes for one load case.

        Parameters
        ----------
        p : ndarray of float, shape (n_c,)
            Nodal contact pressures [Pa].
        q : ndarray of float, shape (n_c,), optional
            Tangential tractions [Pa] in the model's sliding sense (``mu p`` in full sliding, the
            solved partial-slip traction otherwise); None = frictionless.

        Returns
        -------
        ndarray of float, shape (3, n_eval)
            ``(sx, sz, txz)`` in the body's Johnson frame [Pa].
        """
        friction = q is not None and np.any(q)
        if self.Sn is not None:
            # einsum, not `@`: OpenBLAS's threaded gemv busy-waits on a loaded 2-core machine
            # (Sn and St of one body at a/20 with two busy processes: 43 ms vs 6 ms einsum)
            s = np.einsum("cij,j->ci", self.Sn, p)
            if friction:
                s += np.einsum("cij,j->ci", self.St, q)
            return s
        f = self.Bn @ p
        if friction:
            f = f + self.Bt @ q
        return (self.S @ self.solver.solve(f)).reshape(3, -1)


def johnson_frame(body: Body, sxx, syy, sxy):
    """Stresses of a body in its own Johnson frame from FE-frame stresses.

    Parameters
    ----------
    body : Body
        The body (its ``name`` sets the sign of ``txz``).
    sxx, syy, sxy : float or ndarray
        FE-frame stresses [Pa].

    Returns
    -------
    tuple of (float or ndarray)
        ``(sx, sz, txz)`` [Pa]: ``txz = -sxy`` on the cam, ``+sxy`` on the roller.
    """
    sign = -1.0 if body.name == "cam" else 1.0
    return sxx, syy, sign * sxy


def depth(body: Body, xy: np.ndarray) -> np.ndarray:
    """Depth below the body's contact surface of FE-frame points.

    Parameters
    ----------
    body : Body
        The body.
    xy : ndarray of float, shape (2, n)
        Points in the FE frame [m].

    Returns
    -------
    ndarray of float, shape (n,)
        Depth ``z`` [m], >= 0 inside the body.
    """
    ys = surface_height(xy[0], body.geometry.R)
    return (-ys - xy[1]) if body.name == "cam" else (xy[1] - ys)


def surface_nodes(body: Body) -> np.ndarray:
    """Scalar nodes on the fine-zone contact curve: its vertices and, for P2, the midside nodes
    of its edges (these sit on the chords, a sagitta h^2 / (8 |R|) below the arc).

    Parameters
    ----------
    body : Body
        The body.

    Returns
    -------
    ndarray of int
        Scalar node indices: the vertices in order along the curve, then the midside nodes.
    """
    v = np.asarray(body.geometry.contact)  # vertices come first in the scalar numbering
    md = edge_midside_dofs(body, v)
    return v if md is None else np.concatenate([v, md[0] // 2])


def eval_operator(body: Body, half_width: float, max_depth: float):
    """The stress window of one body: ``(nodes, x, z, surface, S)``.

    ``nodes``: the scalar nodes with ``|x| <= half_width`` and ``z <= max_depth``, and every node
    of the fine-zone contact curve (:func:`surface_nodes`); ``x``, ``z`` (m, ``z >= 0``) their
    abscissae and depths; ``surface`` indexes the ones on the contact curve, sorted by x; ``S``
    the sparse operator (3 n_eval, n_dofs) from displacements to (sx, sz, txz) in the body's
    Johnson frame (the sign of ``txz`` folded in, see :func:`johnson_frame`).

    Parameters
    ----------
    body : Body
        The body.
    half_width : float
        Half-width of the window in x [m].
    max_depth : float
        Depth of the window [m].

    Returns
    -------
    nodes : ndarray of int, shape (n_eval,)
        Scalar node indices.
    x, z : ndarray of float, shape (n_eval,)
        Abscissae and depths (clipped to >= 0) [m].
    surface : ndarray of int
        Indices into ``nodes`` of the contact-curve nodes, sorted by x.
    S : scipy.sparse.csr_matrix, shape (3 n_eval, n_dofs)
        Displacements [m] -> ``(sx, sz, txz)`` [Pa] (stacked by component) [Pa/m].
    """
    xy = scalar_node_coordinates(body)
    z = depth(body, xy)
    tol = 1e-9 * half_width
    on_surface = np.zeros(xy.shape[1], dtype=bool)
    on_surface[surface_nodes(body)] = True
    sel = np.nonzero(((np.abs(xy[0]) <= half_width + tol) & (z <= max_depth + tol)) | on_surface)[0]
    S = stress_operator(body, sel)
    ne = sel.size
    sign = np.ones(3 * ne)
    sign[2 * ne:] = johnson_frame(body, 1.0, 1.0, 1.0)[2]
    S = sp.diags(sign) @ S
    surf = np.nonzero(on_surface[sel])[0]
    surf = surf[np.argsort(xy[0, sel][surf])]
    return sel, xy[0, sel], np.maximum(z[sel], 0.0), surf, S.tocsr()


def build_eval_set(body: Body, Bn, Bt, S_y, half_width: float, max_depth: float,
                   precompute: bool = True):
    """Condense one body: ``(EvalSet, Yn, Yt)`` with ``Yn = S_y K^-1 Bn``, ``Yt = S_y K^-1 Bt``.

    ``Bn``, ``Bt``: sparse consistent nodal forces (n_dofs, n_c) of unit nodal pressure /
    friction traction with this body's signs; ``S_y``: sparse selection (m, n_dofs) of the
    contact-vertex displacements to condense onto (the normal ones, then the tangential ones).

    ``precompute=True``: the stress operators of the window (:func:`eval_operator`) and ``Y``
    come out of one pass of 2 n_c block solves (:meth:`Body.solve_apply`), without holding
    ``K^-1 B``. ``precompute=False``: only ``Y``, from n_c solves: ``K`` is symmetric, so
    ``Y^T = B^T K^-1 S_y^T`` (unit loads at the contact vertices, Maxwell-Betti reciprocity);
    the stresses are then back-solved per load case (:meth:`EvalSet.stresses`).

    Parameters
    ----------
    body : Body
        The factorised body.
    Bn, Bt : scipy.sparse.csc_matrix, shape (n_dofs, n_c)
        Consistent nodal forces of unit pressure / traction hats, with this body's signs [m].
    S_y : scipy.sparse.csr_matrix, shape (m, n_dofs)
        0/1 selection of the contact-vertex DOFs to condense onto.
    half_width : float
        Half-width of the stress window in x [m].
    max_depth : float
        Depth of the stress window [m].
    precompute : bool, optional
        Precompute the stress operators (see above).

    Returns
    -------
    ev : EvalSet
        The stress window of the body.
    Yn, Yt : ndarray of float, shape (m, n_c)
        Selected displacements per unit nodal pressure / traction [m/Pa].
    """
    sel, x, z, surf, S = eval_operator(body, half_width, max_depth)
    ne = sel.size
    if not precompute:
        nc = Bn.shape[1]
        ev = EvalSet(body=body.name, nodes=sel, x=x, z=z, Sn=None, St=None, surface=surf, S=S,
                     Bn=Bn, Bt=Bt, solver=body)
        B = sp.hstack([Bn, Bt]).tocsr()
        if body.last is not None:  # S_y and B live on the contact surface: Schur complement
            C = body.last
            Y = S_y[:, C] @ body.schur_solve(B[C].toarray())
            return ev, Y[:, :nc], Y[:, nc:]
        R = body.solve_apply(S_y.T, B.T)
        return ev, R[:nc].T.copy(), R[nc:].T.copy()
    P = sp.vstack([S, S_y]).tocsr()
    out = []
    for B in (Bn, Bt):
        R = body.solve_apply(B, P)
        out.append((R[:3 * ne].reshape(3, ne, -1), R[3 * ne:]))
    (Sn, Yn), (St, Yt) = out
    ev = EvalSet(body=body.name, nodes=sel, x=x, z=z, Sn=Sn, St=St, surface=surf)
    return ev, Yn, Yt


def derived(sx, sz, txz, sy):
    """Maximum in-plane shear and von Mises stress (module docstring).

    Parameters
    ----------
    sx, sz, txz, sy : float or ndarray
        Stress components in the Johnson frame [Pa] (``sy`` out of plane).

    Returns
    -------
    tau1 : float or ndarray
        Maximum in-plane shear stress [Pa].
    von_mises : float or ndarray
        Von Mises equivalent stress [Pa].
    """
    tau1 = np.sqrt((0.5 * (sx - sz)) ** 2 + txz**2)
    vm = np.sqrt(0.5 * ((sx - sz) ** 2 + (sz - sy) ** 2 + (sy - sx) ** 2) + 3.0 * txz**2)
    return tau1, vm


def fit_half_width(x: np.ndarray, p: np.ndarray, threshold: float = 0.2):
    r"""Least-squares fit of the Hertz ellipse to the nodal pressure.

    .. math:: p^2 = c\,(a^2 - (x - x_0)^2) = \alpha + \beta x + \gamma x^2

    over the nodes with ``p > threshold * max(p)``; returns ``(a, x0, p0_fit)`` with
    ``p0_fit = sqrt(c) a``. Robust against the discrete edge of the loaded zone (the last loaded
    node would be a grid quantity, not the half-width).

    Parameters
    ----------
    x : ndarray of float, shape (n,)
        Node abscissae [m].
    p : ndarray of float, shape (n,)
        Nodal pressures [Pa].
    threshold : float, optional
        Fraction of ``max(p)`` above which nodes enter the fit [-].

    Returns
    -------
    a : float
        Fitted half-width [m]; 0 when no cap can be fitted (fewer than 3 nodes or no maximum).
    x0 : float
        Fitted centre [m] (the node of ``max(p)`` when no cap is fitted).
    p0_fit : float
        Fitted peak pressure [Pa] (``max(p)`` when no cap is fitted).
    """
    pm = float(np.max(p)) if p.size else 0.0
    if pm <= 0.0:
        return 0.0, 0.0, 0.0
    sel = p > threshold * pm
    if np.count_nonzero(sel) < 3:
        i = int(np.argmax(p))
        return 0.0, float(x[i]), pm
    xs = x[sel]
    xc = np.mean(xs)
    sc = np.ptp(xs) or 1.0
    t = (xs - xc) / sc
    V = np.stack([np.ones_like(t), t, t**2], axis=1)
    al, be, ga = np.linalg.lstsq(V, p[sel] ** 2, rcond=None)[0]
    if ga >= 0.0:  # not a cap: fall back to the nodal maximum
        i = int(np.argmax(p))
        return 0.0, float(x[i]), pm
    c = -ga
    t0 = be / (2 * c)
    a2 = (al + c * t0**2) / c
    a = float(np.sqrt(max(a2, 0.0)) * sc)
    return a, float(xc + t0 * sc), float(np.sqrt(c * max(a2, 0.0)))
