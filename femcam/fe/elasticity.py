"""Plane linear elasticity of one body: assembly, supports, factorisation.

Symbols: ``K`` stiffness matrix (N/m per unit thickness), ``u`` nodal displacements (m),
``lam, mu_L`` Lamé parameters (Pa; :func:`femcam.materials.lame_parameters`, the plane-stress
``lambda*`` when ``plane="stress"``). Weak form (scikit-fem's ``linear_elasticity``, assembled
by the vectorised kernel of :mod:`femcam.fe.assembly` on scikit-fem's DOF numbering):

.. math:: \\int_\\Omega \\sigma(u) : \\varepsilon(v)\\,d\\Omega, \\qquad
          \\sigma = \\lambda\\,\\mathrm{tr}(\\varepsilon) I + 2\\mu\\,\\varepsilon

Rigid-body modes are removed by clamping every DOF on the body's fixed support (far from the
contact). The free block ``K_ff`` is factorised once with SuperLU (``scipy.sparse.linalg.splu``)
using an explicit column ordering: ``MMD_AT_PLUS_A`` is the ordering for symmetric matrices,
the SciPy default ``COLAMD`` is meant for unsymmetric ones and fills in far more
(``benchmarks/bench_fe.py``).
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from types import SimpleNamespace

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from scipy.linalg import solve_triangular

from .. import _validate
from .._threads import single_threaded_blas
from ..errors import FemcamError
from ..materials import Material, lame_parameters
from ..mesh import BodyMesh
from .assembly import contact_last_order, elasticity_stiffness, triangle_edges
from .contact import edge_midside_dofs

ELEMENTS = ("P1", "P2")
ORDERINGS = ("MMD_AT_PLUS_A", "MMD_ATA", "COLAMD", "NATURAL")
#: right-hand sides per SuperLU triangular solve (see Body.solve)
CHUNK = 20
#: the quadrature of ``Body.basis``: one point. The basis carries the DOF numbering and the node
#: locations; ``K`` is assembled by :mod:`femcam.fe.assembly`, which never integrates with it
#: (scikit-fem's default rule would evaluate every basis function at 6 points per element)
_DOF_QUADRATURE = (np.array([[1.0 / 3.0], [1.0 / 3.0]]), np.array([0.5]))

#: the scikit-fem major versions whose cached edge table (the private ``Mesh._facets``,
#: ``Mesh._t2f``) :func:`~femcam.fe.assembly.triangle_edges` was checked to reproduce
#: (tests/test_fe_assembly.py); under any other, scikit-fem builds its own (slower, never wrong)
EDGE_TABLE_SKFEM_MAJORS = (10, 11, 12)


def _edge_table_checked(version: str) -> bool:
    """Whether scikit-fem ``version`` is one :data:`EDGE_TABLE_SKFEM_MAJORS` names.

    >>> _edge_table_checked("12.0.2"), _edge_table_checked("13.0"), _edge_table_checked("dev")
    (True, False, False)
    """
    head = str(version).split(".")[0]
    return head.isdigit() and int(head) in EDGE_TABLE_SKFEM_MAJORS


@dataclass(frozen=True, eq=False)
class Body:
    """One assembled, supported and factorised elastic body (built by :func:`assemble_body`).

    Parameters
    ----------
    name : str
        Body name (``geometry.name``).
    geometry : femcam.mesh.BodyMesh
        The meshed body.
    material : femcam.materials.Material
        Its material (a :class:`femcam.layers.CoatedMaterial` for a coated body).
    plane : {"strain", "stress"}
        Plane-elasticity assumption.
    element : {"P1", "P2"}
        Triangle element.
    mesh : skfem.MeshTri
        The scikit-fem mesh [m].
    basis : skfem.Basis
        The vector basis (DOFs interleaved ``(u_x, u_y)`` per node): its DOF numbering and node
        locations. Built with a one-point quadrature, so not for integration
        (``skfem.Basis(body.mesh, body.basis.elem)`` is).
    K : scipy.sparse.csr_matrix, shape (n_dofs, n_dofs)
        Full stiffness [N/m per unit thickness].
    free : ndarray of int, shape (n_free,)
        Free (unsupported) DOF indices.
    lu : scipy.sparse.linalg.SuperLU
        Factor of ``K[free][:, free]`` (in the order ``perm`` if set).
    lam, mu_L : float
        Lamé parameters [Pa] (plane-stress ``lambda*`` when ``plane="stress"``).
    t_assembly, t_factor : float
        Wall time of the assembly and of the factorisation [s].
    lam_e, mu_e : ndarray of float, shape (n_el,), or None
        Element-wise Lamé parameters [Pa] of a layered body; None when homogeneous.
    perm : ndarray of int, shape (n_free,), or None
        Factor order of the free DOFs (``lu`` factorises ``K_ff[perm][:, perm]``), or None.
    last : ndarray of int, or None
        Global DOF indices ordered last in the factor (the contact surface), or None.
    """

    name: str
    geometry: BodyMesh
    material: Material
    plane: str
    element: str
    mesh: object
    basis: object
    K: sp.csr_matrix
    free: np.ndarray
    lu: object
    lam: float
    mu_L: float
    t_assembly: float
    t_factor: float
    #: element-wise Lamé parameters (Pa) of a layered body (None: homogeneous lam, mu_L)
    lam_e: np.ndarray | None = None
    mu_e: np.ndarray | None = None
    #: factor order of the free DOFs (``lu`` factorises ``K_ff[perm][:, perm]``), or None
    perm: np.ndarray | None = None
    #: global DOF indices ordered last in the factor (the contact surface), or None
    last: np.ndarray | None = None

    @property
    def n_dofs(self) -> int:
        """Number of global DOFs (two per node)."""
        return int(self.basis.N)

    def _lu_solve(self, rhs_free: np.ndarray) -> np.ndarray:
        if self.perm is None:
            return self.lu.solve(rhs_free)
        out = np.empty_like(rhs_free)
        out[self.perm] = self.lu.solve(np.asfortranarray(rhs_free[self.perm]))
        return out

    def schur_solve(self, G: np.ndarray) -> np.ndarray:
        """``(K^-1)[last][:, last] @ G`` from the trailing blocks of the factor (see
        :meth:`schur_inverse`); needs a body assembled with ``contact_last=True``.

        Parameters
        ----------
        G : ndarray of float, shape (len(last), k)
            Nodal forces on the ``last`` DOFs [N per unit thickness].

        Returns
        -------
        ndarray of float, shape (len(last), k)
            Displacements of the ``last`` DOFs [m].

        Raises
        ------
        InputError
            The body was assembled without ``contact_last=True``.
        """
        self._check_contact_last("schur_solve")
        m = self.free.size
        k = self.last.size
        if not np.array_equal(self.lu.perm_r[m - k:], np.arange(m - k, m)):
            return self._schur_by_solves() @ G
        with single_threaded_blas():  # see solve()
            Lb = self.lu.L[m - k:, m - k:].toarray()
            Ub = self.lu.U[m - k:, m - k:].toarray()
            y = solve_triangular(Lb, G, lower=True, unit_diagonal=True, check_finite=False)
            return solve_triangular(Ub, y, lower=False, check_finite=False)

    def schur_inverse(self) -> np.ndarray:
        """Dense ``(K^-1)[last][:, last]`` (m/N) from the trailing blocks of the factor.

        With the ``last`` DOFs ordered last, ``K_ff = L U`` has the Schur complement
        ``S = K_ll - K_lr K_rr^-1 K_rl = L_ll U_ll`` in its trailing blocks, and
        ``(K^-1)_ll = S^-1``: the contact compliance from one factorisation, without a solve
        per contact unknown. If SuperLU pivoted rows (never seen with
        ``diag_pivot_thresh = 0`` on this SPD matrix) the trailing block is not ``S``: the
        columns are then solved for (:meth:`_schur_by_solves`).

        Returns
        -------
        ndarray of float, shape (len(last), len(last))
            Contact compliance ``(K^-1)[last][:, last]`` [m/N per unit thickness].

        Raises
        ------
        InputError
            The body was assembled without ``contact_last=True``.
        """
        self._check_contact_last("schur_inverse")
        return self.schur_solve(np.eye(self.last.size))

    def _check_contact_last(self, method: str) -> None:
        """Refuse the Schur methods on a body whose factor does not order the contact last."""
        if self.last is None or self.perm is None:
            raise _validate.fail("contact_last", False, "",
                                 f"Body.{method} of body {self.name} needs the body assembled with "
                                 "assemble_body(..., contact_last=True) (the contact DOFs ordered "
                                 "last in the factor)")

    def _schur_by_solves(self) -> np.ndarray:
        """``(K^-1)[last][:, last]`` from ``len(last)`` unit-load solves (reference path)."""
        k = self.last.size
        E = sp.csc_matrix((np.ones(k), (self.last, np.arange(k))), shape=(self.n_dofs, k))
        return self.solve_apply(E, E.T)

    def solve(self, f: np.ndarray) -> np.ndarray:
        """Displacements for nodal forces ``f``; zero on the supports.

        Parameters
        ----------
        f : ndarray of float, shape (n_dofs,) or (n_dofs, k)
            Nodal forces [N per unit thickness].

        Returns
        -------
        ndarray of float, same shape as ``f``
            Nodal displacements [m].
        """
        f = np.asarray(f, dtype=float)
        u = np.zeros_like(f)
        # one BLAS thread: SuperLU's triangular solves call BLAS on small blocks, and OpenBLAS
        # threads busy-wait against each other and other processes on a shared 2-core machine
        # (condensation at a/h = 20: 5-8 s with the default threads, 0.9-1.9 s with one, load
        # average ~2; docs/fe.md)
        with single_threaded_blas():
            if f.ndim == 1:
                u[self.free] = self._lu_solve(f[self.free])
                return u
            # blocks of CHUNK columns: SuperLU's multi-RHS solve was measured fastest in blocks
            # of ~20 (0.18 s vs 0.25 s for all 101 at once and 0.46 s one by one, 21k DOFs)
            ff = f[self.free]
            uf = np.empty_like(ff)
            for j in range(0, ff.shape[1], CHUNK):
                uf[:, j:j + CHUNK] = self._lu_solve(np.asfortranarray(ff[:, j:j + CHUNK]))
        u[self.free] = uf
        return u

    def solve_apply(self, F, P) -> np.ndarray:
        """``P @ K^-1 F`` (dense, (P.shape[0], F.shape[1])) for sparse nodal forces ``F`` (N) and
        a sparse output operator ``P`` (e.g. stresses at a few nodes, or a DOF selection).

        The displacements ``K^-1 F`` are never held for all columns at once: blocks of
        :data:`CHUNK` right-hand sides are solved and projected in turn, so the memory is that of
        the result (at a/h = 40 the full ``K^-1 F`` of one body would be ~200 MB, plus the dense
        ``F``). Same factor and block size as :meth:`solve`.

        Parameters
        ----------
        F : sparse matrix or ndarray, shape (n_dofs, k)
            Nodal forces [N per unit thickness].
        P : sparse matrix or ndarray, shape (m, n_dofs)
            Output operator applied to the displacements [m] (e.g. :func:`stress_operator`).

        Returns
        -------
        ndarray of float, shape (m, k)
            ``P @ K^-1 F``, in the units of ``P`` times m.
        """
        idx = self.free if self.perm is None else self.free[self.perm]  # in factor order
        Ff = sp.csr_matrix(F)[idx].tocsc()
        Pf = sp.csr_matrix(P)[:, idx].tocsr()
        out = np.empty((Pf.shape[0], Ff.shape[1]))
        with single_threaded_blas():  # see solve()
            for j in range(0, Ff.shape[1], CHUNK):
                rhs = np.asfortranarray(Ff[:, j:j + CHUNK].toarray())
                out[:, j:j + CHUNK] = Pf @ self.lu.solve(rhs)
        return out


def _element(element: str):
    from skfem import (  # skfem: kept out of ``import femcam`` (tests/test_imports.py)
        ElementTriP1,
        ElementTriP2,
        ElementVector,
    )

    _validate.choice("element", element, ELEMENTS)   # never a silent P1 for "p2" or "P3"
    return ElementVector(ElementTriP2() if element == "P2" else ElementTriP1())


def contact_surface_dofs(mesh, basis, element: str, contact: np.ndarray) -> np.ndarray:
    """Vector DOFs (x and y) of the contact vertices and of the midside nodes between them.

    Parameters
    ----------
    mesh : skfem.MeshTri
        The body mesh.
    basis : skfem.Basis
        Its vector basis.
    element : {"P1", "P2"}
        Triangle element of ``basis``.
    contact : array_like of int, shape (n_c,)
        Mesh vertex indices of the contact nodes, in order along the surface.

    Returns
    -------
    ndarray of int
        Sorted unique global DOF indices.
    """

    md = edge_midside_dofs(SimpleNamespace(element=element, mesh=mesh, basis=basis),
                           np.asarray(contact))
    d = basis.nodal_dofs[:, np.asarray(contact)].ravel()
    return np.unique(d if md is None else np.concatenate([d, md.ravel()]))


def assemble_body(geometry: BodyMesh, material: Material, *, plane: str = "strain",
                  element: str = "P2", ordering: str = "MMD_AT_PLUS_A",
                  supports: tuple | None = None, contact_last: bool = False) -> Body:
    """Assemble ``K`` of one body, clamp its fixed support and factorise the free block.

    ``supports``: optional ``((node, component), ...)`` point supports (component 0 x, 1 y)
    used INSTEAD of the clamped ``geometry.fixed`` curve, e.g. a statically determinate
    3-DOF support of a floating body loaded by self-equilibrated contact forces
    (:mod:`femcam.bodies`): its reactions are then zero.

    ``contact_last``: order the contact-surface DOFs (:func:`contact_surface_dofs`) last in the
    factor (:func:`femcam.fe.assembly.contact_last_order`), so that :meth:`Body.schur_inverse`
    gives the contact compliance (a little more fill than ``ordering`` alone: 13.0 M vs 10.4 M
    nonzeros in L + U for the cam at a/h = 40).

    Parameters
    ----------
    geometry : femcam.mesh.BodyMesh
        The meshed body [m] (its ``fixed`` nodes are clamped unless ``supports`` is given).
    material : femcam.materials.Material
        Its material (a :class:`femcam.layers.CoatedMaterial` gives the coating band its own).
    plane : {"strain", "stress"}, optional
        Plane-elasticity assumption.
    element : {"P1", "P2"}, optional
        Triangle element.
    ordering : str, optional
        SuperLU column ordering, one of :data:`ORDERINGS`.
    supports : tuple of (int, int), optional
        ``((node, component), ...)`` point supports replacing the clamped curve.
    contact_last : bool, optional
        Order the contact-surface DOFs last in the factor.

    Returns
    -------
    Body
        The assembled, supported and factorised body.

    Raises
    ------
    FemcamError
        The stiffness of the free block is singular (support missing).
    """
    t0 = time.perf_counter()
    mesh, basis, lam, mu_L, lam_e, mu_e = _discretise(geometry, material, plane, element)
    K = elasticity_stiffness(mesh.p, mesh.t, basis.element_dofs, basis.elem.elem, basis.N,
                             float(lam) if lam_e is None else lam_e,
                             float(mu_L) if mu_e is None else mu_e)
    fixed_nodes = np.zeros(mesh.p.shape[1], dtype=bool)
    fixed_nodes[geometry.fixed] = True
    fac = np.nonzero(fixed_nodes[mesh.facets].all(axis=0))[0]
    fixed = basis.get_dofs(fac).all()
    if supports is not None:
        fixed = np.array([basis.nodal_dofs[c, n] for n, c in supports], dtype=np.int64)
    is_free = np.ones(basis.N, dtype=bool)
    is_free[fixed] = False
    free = np.flatnonzero(is_free)     # sorted, as np.setdiff1d(np.arange(N), fixed)
    t1 = time.perf_counter()
    perm = last = None
    try:
        if contact_last:
            last = contact_surface_dofs(mesh, basis, element, geometry.contact)
            perm = contact_last_order(K, free, last, ordering)
            last = free[perm[free.size - last.size:]]  # in factor order
            Kff = K[free[perm]][:, free[perm]].tocsc()
        else:
            Kff = K[free][:, free].tocsc()
        lu = spla.splu(Kff, permc_spec="NATURAL" if contact_last else ordering,
                       diag_pivot_thresh=0.0, options={"SymmetricMode": True})
    except RuntimeError as exc:  # singular: support missing
        raise FemcamError(f"stiffness of body {geometry.name} is singular ({exc}); "
                          "is its fixed support meshed?") from None
    t2 = time.perf_counter()
    return Body(name=geometry.name, geometry=geometry, material=material, plane=plane,
                element=element, mesh=mesh, basis=basis, K=K, free=free, lu=lu, lam=float(lam),
                mu_L=float(mu_L), t_assembly=t1 - t0, t_factor=t2 - t1, lam_e=lam_e, mu_e=mu_e,
                perm=perm, last=last)


def _discretise(geometry: BodyMesh, material: Material, plane: str, element: str) -> tuple:
    """``(mesh, basis, lam, mu_L, lam_e, mu_e)`` of one body (no stiffness, no factor)."""
    import skfem  # kept out of ``import femcam`` (tests/test_imports.py)
    from skfem import Basis, MeshTri

    mesh = MeshTri(geometry.points, geometry.triangles, validate=False, sort_t=False)
    # scikit-fem's own edge table (its cached ``facets``, ``t2f``), built faster, same arrays;
    # only under the scikit-fem versions it was checked against (private attributes)
    if _edge_table_checked(skfem.__version__):
        mesh._facets, mesh._t2f = triangle_edges(mesh.t, mesh.p.shape[1])
    basis = Basis(mesh, _element(element), quadrature=_DOF_QUADRATURE)
    lam, mu_L = lame_parameters(material.E, material.nu, plane)
    lam_e, mu_e = _coating_lame(geometry, material, plane, lam, mu_L)
    return mesh, basis, lam, mu_L, lam_e, mu_e


def mesh_body(geometry: BodyMesh, material: Material, *, plane: str = "strain",
              element: str = "P2") -> Body:
    """A body's mesh, basis and Lamé parameters without its stiffness and factor.

    What the full-field recovery needs (:func:`stress_operator`, :func:`element_gradients`,
    :func:`scalar_node_coordinates`, :func:`probe_matrix`) for displacements obtained
    elsewhere (stored by :mod:`femcam.sweep.diskcache`), at a few per cent of the cost of
    :func:`assemble_body`: the same mesh, basis and parameters as the body :func:`assemble_body`
    builds from the same arguments, with ``K``, ``free`` and ``lu`` None (no :meth:`Body.solve`).

    Parameters
    ----------
    geometry : femcam.mesh.BodyMesh
        The meshed body [m].
    material : femcam.materials.Material
        Its material (a :class:`femcam.layers.CoatedMaterial` gives the coating band its own).
    plane : {"strain", "stress"}, optional
        Plane-elasticity assumption.
    element : {"P1", "P2"}, optional
        Triangle element.

    Returns
    -------
    Body
        The body without ``K``, ``free``, ``lu``, ``perm`` and ``last``.
    """
    mesh, basis, lam, mu_L, lam_e, mu_e = _discretise(geometry, material, plane, element)
    return Body(name=geometry.name, geometry=geometry, material=material, plane=plane,
                element=element, mesh=mesh, basis=basis, K=None, free=None, lu=None,
                lam=float(lam), mu_L=float(mu_L), t_assembly=0.0, t_factor=0.0, lam_e=lam_e,
                mu_e=mu_e)


def _coating_lame(geometry: BodyMesh, material: Material, plane, lam, mu_L):
    """Layered body: a ``material`` with a ``coating`` Material (``femcam.layers.CoatedMaterial``)
    on a mesh with a coating band (``geometry.coating``) gets the coating's Lamé parameters in
    the band. Returns element-wise (lam_e, mu_e) in Pa, or (None, None) for a homogeneous body."""
    coat = getattr(material, "coating", None)
    if coat is None or geometry.coating is None:
        return None, None
    lc, mc = lame_parameters(coat.E, coat.nu, plane)
    lam_e = np.where(geometry.coating, float(lc), float(lam))
    mu_e = np.where(geometry.coating, float(mc), float(mu_L))
    return lam_e, mu_e


def probe_matrix(body: Body, xy: np.ndarray) -> sp.csr_matrix:
    """Sparse ``P`` with ``P @ f`` = the scalar nodal field ``f`` of ``body`` interpolated at
    points.

    Parameters
    ----------
    body : Body
        The assembled body.
    xy : ndarray of float, shape (2, n)
        Points in the body frame [m].

    Returns
    -------
    scipy.sparse.csr_matrix, shape (n, n_dofs // 2)
        Interpolation weights [-] on the scalar nodes.

    Raises
    ------
    InputError
        ``xy`` is not a (2, n) array of finite numbers, or a point lies outside the mesh.
    """
    from skfem import Basis  # skfem: kept out of ``import femcam`` (tests/test_imports.py)

    xy = _validate.finite_array("xy", xy, "m")
    if xy.ndim != 2 or xy.shape[0] != 2:
        raise _validate.fail("xy", f"shape {xy.shape}", "m", "must have the shape (2, n)")
    try:
        return Basis(body.mesh, body.basis.elem.elem).probes(xy)
    except ValueError:  # scikit-fem: a point not found in any element
        raise _validate.fail("xy", xy.T.tolist(), "m",
                             f"must lie inside the mesh of body {body.name}") from None


def element_gradients(body: Body, nodes: np.ndarray | None = None) -> tuple:
    """Physical shape-function gradients of every element at its own nodes (no averaging).

    Parameters
    ----------
    body : Body
        The assembled body.
    nodes : ndarray of int, shape (n,), optional
        Only the elements around these scalar nodes; default all elements.

    Returns
    -------
    dphi : ndarray, shape (nloc, 2, nel, nloc)
        ``d phi_j / d x_i`` of local function ``j`` at local node ``k`` of each element [1/m].
    sdofs : ndarray of int, shape (nloc, nel)
        Scalar node of each local node.
    edofs : ndarray of int, shape (2 nloc, nel)
        Vector DOFs ``(ux, uy)`` of each local node.
    lam, mu : float or ndarray, shape (nel,)
        Lame constants of the elements [Pa].
    cnt : ndarray, shape (n_dofs // 2,)
        Elements around each scalar node (all elements counted).
    """
    b = body.basis
    mesh = body.mesh
    elem = b.elem.elem  # scalar element
    # local node coordinates on the reference triangle (vertices, then edges for P2)
    ref = np.asarray(elem.doflocs, dtype=float).T
    nloc = ref.shape[1]
    # reference gradients dphi_j/dxi at node k: (nloc_j, 2, nloc_k)
    G = np.zeros((nloc, 2, nloc))
    for j in range(nloc):
        G[j] = elem.lbasis(ref, j)[1]
    nscal = b.N // 2
    sdofs = b.element_dofs[::2] // 2  # scalar dofs (vector dofs interleaved (ux, uy) per node)
    cnt = np.bincount(sdofs.ravel(), minlength=nscal).astype(float)  # elements per node
    lam, mu = (body.lam, body.mu_L) if body.lam_e is None else (body.lam_e, body.mu_e)
    edofs = b.element_dofs
    t = mesh.t
    if nodes is not None:  # only the elements around the selected nodes (the stress window)
        on = np.zeros(nscal, dtype=bool)
        on[np.asarray(nodes)] = True
        els = np.nonzero(on[sdofs].any(axis=0))[0]
        t, sdofs, edofs = t[:, els], sdofs[:, els], edofs[:, els]
        if body.lam_e is not None:
            lam, mu = lam[els], mu[els]
    p = mesh.p
    x0 = p[:, t[0]]
    J = np.stack([p[:, t[1]] - x0, p[:, t[2]] - x0], axis=2)  # (2, nel, 2): dx_i/dxi_k
    detJ = J[0, :, 0] * J[1, :, 1] - J[0, :, 1] * J[1, :, 0]
    invJ = np.empty_like(J)  # dxi_k/dx_i stored as (k, nel, i)
    invJ[0, :, 0] = J[1, :, 1] / detJ
    invJ[0, :, 1] = -J[0, :, 1] / detJ
    invJ[1, :, 0] = -J[1, :, 0] / detJ
    invJ[1, :, 1] = J[0, :, 0] / detJ
    # physical gradients: (nloc_j, 2[i], nel, nloc_k)
    return np.einsum("jkn,kei->jien", G, invJ), sdofs, edofs, lam, mu, cnt


def stress_operator(body: Body, nodes: np.ndarray | None = None) -> sp.csr_matrix:
    """Sparse operator ``S`` with ``S @ u = [sxx; syy; sxy]`` at scalar-DOF nodes (stacked).

    ``nodes`` selects scalar nodes (indices into the scalar DOF numbering of ``body.basis``,
    vertices first then edge midpoints for P2); default all. Built from the reference-element
    shape-function gradients at the element nodes, then averaged over neighbouring elements.

    Parameters
    ----------
    body : Body
        The assembled body.
    nodes : ndarray of int, shape (n,), optional
        Scalar node indices; default all ``n_dofs // 2`` nodes.

    Returns
    -------
    scipy.sparse.csr_matrix, shape (3 n, n_dofs)
        Stress per unit nodal displacement [Pa/m]; rows ``sxx`` of every node, then ``syy``,
        then ``sxy``.
    """
    dphi, sdofs, edofs, lam, mu, cnt = element_gradients(body, nodes)
    b, nscal, nloc = body.basis, body.basis.N // 2, dphi.shape[0]
    rows, cols, vals = [], [], []
    for k in range(nloc):  # node at which stress is evaluated
        node = sdofs[k]
        w = 1.0 / cnt[node]
        for j in range(nloc):
            dx = dphi[j, 0, :, k]
            dy = dphi[j, 1, :, k]
            ux = edofs[2 * j]
            uy = edofs[2 * j + 1]
            # sxx = (lam+2mu) du/dx + lam dv/dy ; syy = lam du/dx + (lam+2mu) dv/dy ; sxy = mu(du/dy+dv/dx)
            for comp, cu, cv in ((0, (lam + 2 * mu) * dx, lam * dy),
                                 (1, lam * dx, (lam + 2 * mu) * dy),
                                 (2, mu * dy, mu * dx)):
                r = comp * nscal + node
                rows += [r, r]
                cols += [ux, uy]
                vals += [w * cu, w * cv]
    S = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                      shape=(3 * nscal, b.N))
    if nodes is not None:
        nodes = np.asarray(nodes)
        S = S[np.concatenate([nodes, nodes + nscal, nodes + 2 * nscal])]
    return S


def scalar_node_coordinates(body: Body) -> np.ndarray:
    """Coordinates of the scalar nodes (vertices, then edge midpoints for P2).

    Parameters
    ----------
    body : Body
        The assembled body.

    Returns
    -------
    ndarray of float, shape (2, n_dofs // 2)
        ``(x, y)`` of each scalar node in the body frame [m].
    """
    return body.basis.doflocs[:, ::2]
