"""Tests of femcam.fe.elasticity and the contact load operators (independent analytic references)."""

import numpy as np
import pytest

from femcam.fe.contact import load_matrix, solve_lcp, trapezoid_weights
from femcam.fe.elasticity import assemble_body, scalar_node_coordinates, stress_operator
from femcam.materials import Material, lame_parameters
from femcam.mesh import MeshOptions, build_contact_mesh

MAT = Material(E=200e9, nu=0.25)


@pytest.fixture(scope="module", params=["P1", "P2"])
def body(request):
    cm = build_contact_mesh(Rr=0.01, rho=0.02, a_ref=1e-4, options=MeshOptions(a_over_h=5))
    return assemble_body(cm.cam, MAT, element=request.param)


def mesh_area(b):
    p = b.mesh.p[:, b.mesh.t]
    return 0.5 * np.sum((p[0, 1] - p[0, 0]) * (p[1, 2] - p[1, 0]) - (p[0, 2] - p[0, 0]) * (p[1, 1] - p[1, 0]))


def test_strain_energy_of_uniform_strain(body):
    """u = (eps x, 0): U = 1/2 (lambda + 2 mu) eps^2 * area (plane strain, Lame from E, nu)."""
    eps = 1e-3
    X = body.basis.doflocs
    u = np.zeros(body.n_dofs)
    u[0::2] = eps * X[0, 0::2]
    lam, mu = lame_parameters(MAT.E, MAT.nu, "strain")
    U = 0.5 * u @ (body.K @ u)
    assert U == pytest.approx(0.5 * (lam + 2 * mu) * eps**2 * mesh_area(body), rel=1e-10)


def test_rigid_modes_have_no_energy(body):
    X = body.basis.doflocs
    for u in (np.tile([1.0, 0.0], body.n_dofs // 2), np.tile([0.0, 1.0], body.n_dofs // 2)):
        assert np.abs(body.K @ u).max() < 1e-6 * np.abs(body.K).max()
    rot = np.zeros(body.n_dofs)
    rot[0::2], rot[1::2] = -X[1, 1::2], X[0, 0::2]
    assert np.abs(body.K @ rot).max() < 1e-8 * np.abs(body.K).max() * 0.01


def test_stress_operator_reproduces_linear_stress(body):
    """Hooke's law for u = (e x^2, e x y) (P2) or a linear field (P1): exact at every node."""
    e = 1e-3
    X = scalar_node_coordinates(body)
    x, y = X
    lam, mu = body.lam, body.mu_L
    u = np.zeros(body.n_dofs)
    if body.element == "P2":
        u[0::2], u[1::2] = e * x**2 / 0.01, e * x * y / 0.01
        exx, eyy, exy2 = 2 * e * x / 0.01, e * x / 0.01, e * y / 0.01
    else:
        u[0::2], u[1::2] = e * x, 2 * e * x + 0.5 * e * y
        exx, eyy, exy2 = e * np.ones_like(x), 0.5 * e * np.ones_like(x), 2 * e * np.ones_like(x)
    s = stress_operator(body) @ u
    n = x.size
    np.testing.assert_allclose(s[:n], (lam + 2 * mu) * exx + lam * eyy, atol=1e-6 * mu * e)
    np.testing.assert_allclose(s[n:2 * n], lam * exx + (lam + 2 * mu) * eyy, atol=1e-6 * mu * e)
    np.testing.assert_allclose(s[2 * n:], mu * exy2, atol=1e-6 * mu * e)


def test_consistent_nodal_forces(body):
    """B sums to int L_k ds; a uniform pressure gives Simpson weights h/3 (vertex), 2h/3 (midside)."""
    g = body.geometry
    B = load_matrix(body, g.contact, g.contact_x, 1)
    np.testing.assert_allclose(B.sum(axis=0), trapezoid_weights(g.contact_x), rtol=1e-12)
    f = B.sum(axis=1)
    h = g.contact_x[1] - g.contact_x[0]
    fv = f[body.basis.nodal_dofs[1, g.contact[1:-1]]]
    expect = h / 3 if body.element == "P2" else h
    np.testing.assert_allclose(fv, expect, rtol=1e-9)
    assert np.abs(B[body.basis.nodal_dofs[0]]).max() == 0.0  # no x-force from a y-load


def test_lcp_two_springs():
    """Two independent springs k, gaps h0 = (0, d): load W shared only once spring 1 closes d."""
    k, d = 2.0, 1.0
    A = np.diag([1 / k, 1 / k])
    w = np.ones(2)
    s = solve_lcp(A, np.array([0.0, d]), w, 1.0, active0=np.array([True, True]))  # W < k d
    np.testing.assert_allclose(s.p, [1.0, 0.0], atol=1e-14)
    s = solve_lcp(A, np.array([0.0, d]), w, 6.0, active0=np.array([True, False]))  # W > k d
    np.testing.assert_allclose(s.p, [(6 + k * d) / 2, (6 - k * d) / 2], rtol=1e-14)
    assert s.converged and s.delta == pytest.approx(4.0 / k)


def test_lcp_reports_failure_with_history():
    """Wrong start (spring 2 active although its gap stays open) and one iteration allowed."""
    from femcam.errors import ConvergenceError

    A = np.diag([0.5, 0.5])
    with pytest.raises(ConvergenceError) as exc:
        solve_lcp(A, np.array([0.0, 1.0]), np.ones(2), 1.0, active0=np.array([True, True]), max_iter=1)
    assert len(exc.value.history) == 1 and exc.value.history[0] > 0
