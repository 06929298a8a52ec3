"""The vectorised elasticity kernel and the contact-last order (femcam.fe.assembly) against
independent references: scikit-fem's generic form assembly (``asm(linear_elasticity)``, other
quadrature, other code), the closed-form strain energy of a uniform strain (patch test) and the
rigid-body modes; and the ordering's contract (a permutation with the given DOFs last).
"""

import numpy as np
import pytest
from skfem import Basis, ElementTriP1, ElementTriP2, ElementVector, MeshTri, asm
from skfem.models.elasticity import linear_elasticity

from femcam.fe.assembly import contact_last_order, elasticity_stiffness, triangle_edges
from femcam.fe.elasticity import assemble_body, contact_surface_dofs
from femcam.materials import STEEL
from femcam.mesh import MeshOptions, build_contact_mesh

LAM, MU = 1.21e11, 8.08e10  # Pa (steel, plane strain)


@pytest.fixture(scope="module")
def mesh():
    """A distorted unstructured triangle mesh (6 x 4 refined square, nodes moved)."""
    m = MeshTri.init_tensor(np.linspace(0, 2e-3, 7), np.linspace(0, 1e-3, 5))
    rng = np.random.default_rng(1)
    p = m.p.copy()
    inner = (p[0] > 0) & (p[0] < 2e-3) & (p[1] > 0) & (p[1] < 1e-3)
    p[:, inner] += rng.uniform(-6e-5, 6e-5, (2, int(inner.sum())))
    return MeshTri(p, m.t)


@pytest.mark.parametrize("element", [ElementTriP1, ElementTriP2])
def test_kernel_equals_scikit_fem(mesh, element):
    """Same matrix as scikit-fem's quadrature assembly to round-off (both exact for the
    polynomial integrand), for constant and element-wise Lamé parameters."""
    b = Basis(mesh, ElementVector(element()))
    ref = asm(linear_elasticity(LAM, MU), b).toarray()
    K = elasticity_stiffness(mesh.p, mesh.t, b.element_dofs, b.elem.elem, b.N, LAM, MU).toarray()
    np.testing.assert_allclose(K, ref, rtol=0, atol=1e-12 * np.abs(ref).max(),
                               err_msg="kernel vs skfem asm(linear_elasticity)")
    band = np.arange(mesh.t.shape[1]) % 3 == 0  # a second material on every third element
    lam_e, mu_e = np.where(band, 2 * LAM, LAM), np.where(band, 0.5 * MU, MU)
    bb = Basis(mesh, b.elem, elements=np.nonzero(band)[0])
    ref2 = ref + asm(linear_elasticity(LAM, -0.5 * MU), bb).toarray()
    K2 = elasticity_stiffness(mesh.p, mesh.t, b.element_dofs, b.elem.elem, b.N, lam_e, mu_e)
    np.testing.assert_allclose(K2.toarray(), ref2, rtol=0, atol=1e-12 * np.abs(ref2).max(),
                               err_msg="element-wise Lamé parameters")


def test_kernel_patch_test_and_rigid_modes(mesh):
    """Uniform strain eps: u^T K u = area (lam tr(eps)^2 + 2 mu eps:eps) exactly (the P2 space
    holds linear fields); rigid translations and rotation give K u = 0."""
    b = Basis(mesh, ElementVector(ElementTriP2()))
    K = elasticity_stiffness(mesh.p, mesh.t, b.element_dofs, b.elem.elem, b.N, LAM, MU)
    x, y = b.doflocs[0, ::2], b.doflocs[1, ::2]
    e = np.array([[2e-4, 5e-5], [5e-5, -1e-4]])
    u = np.empty(b.N)
    u[0::2] = e[0, 0] * x + e[0, 1] * y
    u[1::2] = e[1, 0] * x + e[1, 1] * y
    energy = 2e-3 * 1e-3 * (LAM * np.trace(e) ** 2 + 2 * MU * np.sum(e * e))
    assert u @ K @ u == pytest.approx(energy, rel=1e-12), "strain energy of a uniform strain"
    for ux, uy in ((np.ones_like(x), 0 * x), (0 * x, np.ones_like(x)), (-y, x)):
        r = np.empty(b.N)
        r[0::2], r[1::2] = ux, uy
        assert np.abs(K @ r).max() <= 1e-12 * abs(K).max() * np.abs(r).max(), "rigid-body mode"


def test_contact_last_order_is_a_permutation_with_contact_last():
    cm = build_contact_mesh(Rr=0.01, rho=0.02, a_ref=1.6e-4,
                            options=MeshOptions(a_over_h=2, growth=1.0, fine_depth=0.0))
    b = assemble_body(cm.cam, STEEL)
    last = contact_surface_dofs(b.mesh, b.basis, "P2", cm.cam.contact)
    order = contact_last_order(b.K, b.free, last, "MMD_AT_PLUS_A")
    assert np.array_equal(np.sort(order), np.arange(b.free.size))
    assert set(b.free[order[-last.size:]]) == set(last)


def test_triangle_edges_are_scikit_fems(mesh):
    """The edge table assemble_body hands scikit-fem is the one scikit-fem builds itself
    (``Mesh.build_entities``): same arrays, same dtypes (the P2 midside DOFs follow it)."""
    for m in (mesh, MeshTri.init_circle(3)):
        facets, t2f = triangle_edges(m.t, m.p.shape[1])
        ref_f, ref_t2f = MeshTri.build_entities(m.t, m.elem.refdom.facets)
        assert facets.dtype == ref_f.dtype and t2f.dtype == ref_t2f.dtype
        np.testing.assert_array_equal(facets, ref_f)
        np.testing.assert_array_equal(t2f, ref_t2f)


def test_body_dofs_are_scikit_fems():
    """A body's DOF numbering is scikit-fem's default Basis's: the edge table and the one-point
    quadrature change no DOF."""
    cm = build_contact_mesh(Rr=0.01, rho=0.02, a_ref=1.6e-4,
                            options=MeshOptions(a_over_h=2, growth=1.0, fine_depth=0.0))
    b = assemble_body(cm.cam, STEEL)
    ref = Basis(MeshTri(cm.cam.points, cm.cam.triangles, sort_t=False), ElementVector(ElementTriP2()))
    for name in ("element_dofs", "nodal_dofs", "facet_dofs", "doflocs"):
        np.testing.assert_array_equal(getattr(b.basis, name), getattr(ref, name), err_msg=name)


def test_an_unchecked_scikit_fem_builds_its_own_edge_table(monkeypatch):
    """Under a scikit-fem major version the edge table was not checked against, femcam leaves
    the private ``_facets``/``_t2f`` alone: scikit-fem builds them, and the body's DOFs are the
    ones of the default ``Basis`` (the reference, built by scikit-fem alone)."""
    import skfem

    cm = build_contact_mesh(Rr=0.01, rho=0.02, a_ref=1.6e-4,
                            options=MeshOptions(a_over_h=2, growth=1.0, fine_depth=0.0))
    monkeypatch.setattr(skfem, "__version__", "99.0.0")

    def not_called(*args):
        raise AssertionError("femcam's edge table used under an unchecked scikit-fem")

    monkeypatch.setattr("femcam.fe.elasticity.triangle_edges", not_called)
    b = assemble_body(cm.cam, STEEL)
    ref = Basis(MeshTri(cm.cam.points, cm.cam.triangles, sort_t=False), ElementVector(ElementTriP2()))
    np.testing.assert_array_equal(b.basis.element_dofs, ref.element_dofs)
    np.testing.assert_array_equal(b.mesh.facets, ref.mesh.facets)
