"""femcam.hertz.subsurface against independent references.

* Flamant (line-load) kernel integrated numerically over the Hertz pressure and traction
  (Johnson 1985 eq. 2.23) -- a different method from the closed form;
* the classic axis formulas for x = 0 (Johnson eq. 4.50);
* Johnson eqs. 7.20-7.21 typed naively here (the code uses a rearranged, cancellation-free form);
* interior equilibrium by finite differences; far-field point-load (Flamant) decay;
* seed 002 eqs. 5-7 at z = 0; principal stresses from numpy eigenvalues.
"""

import math
import warnings

import numpy as np
import pytest
from scipy.integrate import quad

from femcam.errors import InputError
from femcam.hertz import LineContact, stress_field, surface_stress, unit_stresses
from femcam.materials import STEEL, Material


def flamant(X, Z, which):
    """(sx, sz, txz)/p0 at (X, Z) > 0 by quadrature of the Flamant kernel (Johnson eq. 2.23).

    which = "p": pressure p = sqrt(1 - s^2); which = "q": traction q = sqrt(1 - s^2) in +x.
    """
    def dens(s):
        return math.sqrt(max(1.0 - s * s, 0.0))

    def integ(k):
        return quad(lambda s: dens(s) * k(X - s) / ((X - s) ** 2 + Z * Z) ** 2, -1, 1,
                    epsabs=1e-13, epsrel=1e-12, limit=200)[0]
    if which == "p":
        return (-2 * Z / math.pi * integ(lambda d: d * d),
                -2 * Z**3 / math.pi * integ(lambda d: 1.0),
                -2 * Z * Z / math.pi * integ(lambda d: d))
    return (-2 / math.pi * integ(lambda d: d**3),
            -2 * Z * Z / math.pi * integ(lambda d: d),
            -2 * Z / math.pi * integ(lambda d: d * d))


POINTS = [(0.0, 0.3), (0.0, 0.786), (0.5, 0.5), (-0.87, 0.5), (1.0, 0.05), (-1.0, 0.2),
          (1.5, 0.4), (-2.5, 1.0), (0.3, 2.0), (-0.95, 0.02)]


@pytest.mark.parametrize("X, Z", POINTS)
def test_normal_field_matches_flamant_quadrature(X, Z):
    got = unit_stresses(X, Z, mu=0.0)
    np.testing.assert_allclose(got, flamant(X, Z, "p"), atol=1e-8,
                               err_msg="Johnson 7.20 vs Flamant kernel quadrature (eq. 2.23)")


@pytest.mark.parametrize("X, Z", POINTS)
def test_tangential_field_matches_flamant_quadrature(X, Z):
    # tangential-only part: difference between mu = 1 and mu = 0 (the field is linear in mu)
    got = np.subtract(unit_stresses(X, Z, mu=1.0), unit_stresses(X, Z, mu=0.0))
    np.testing.assert_allclose(got, flamant(X, Z, "q"), atol=1e-8,
                               err_msg="Johnson 7.21 vs Flamant kernel quadrature (eq. 2.23)")


def johnson_printed(X, Z, mu):
    """Johnson eqs. 7.20-7.21 as printed (a = p0 = 1), with the naive m, n definitions."""
    A = 1 - X * X + Z * Z
    r = math.sqrt(A * A + 4 * X * X * Z * Z)
    m = math.sqrt(0.5 * (r + A))
    n = math.copysign(math.sqrt(max(0.5 * (r - A), 0.0)), X)
    D = m * m + n * n
    sx = -(m * (1 + (Z * Z + n * n) / D) - 2 * Z)
    sz = -m * (1 - (Z * Z + n * n) / D)
    txz = -n * (m * m - Z * Z) / D
    sxq = n * (2 - (Z * Z - m * m) / D) - 2 * X
    szq = -n * (m * m - Z * Z) / D
    txzq = -(m * (1 + (Z * Z + n * n) / D) - 2 * Z)
    return sx + mu * sxq, sz + mu * szq, txz + mu * txzq


@pytest.mark.parametrize("mu", [0.0, 0.3, 2.0])
def test_matches_johnson_7_20_7_21_as_printed(mu):
    rng = np.random.default_rng(11)
    for X, Z in zip(rng.uniform(-3, 3, 40), rng.uniform(0.01, 3, 40), strict=True):
        np.testing.assert_allclose(unit_stresses(X, Z, mu), johnson_printed(X, Z, mu),
                                   rtol=1e-10, atol=1e-12)


def test_axis_closed_forms():
    # x = 0: sx = -p0[(1 + 2z^2/a^2)/sqrt(1 + z^2/a^2) - 2z/a], sz = -p0/sqrt(1 + z^2/a^2), txz = 0
    a, p0 = 1.3e-4, 1.1e9
    z = a * np.array([0.0, 0.1, 0.5, 0.786, 1.0, 2.0, 5.0, 20.0])
    f = stress_field(0.0, z, a, p0)
    Z = z / a
    # the textbook form cancels at depth (z = 20a loses ~1e-10 relative): absolute tolerance
    np.testing.assert_allclose(f.sx, -p0 * ((1 + 2 * Z**2) / np.sqrt(1 + Z**2) - 2 * Z), rtol=1e-11,
                               atol=1e-13 * p0)
    np.testing.assert_allclose(f.sz, -p0 / np.sqrt(1 + Z**2), rtol=1e-13)
    np.testing.assert_allclose(f.txz, 0.0, atol=1e-6)
    np.testing.assert_allclose(f.sy, 0.3 * (f.sx + f.sz), rtol=1e-15)


@pytest.mark.parametrize("mu", [0.0, 0.25, 0.6])
def test_interior_equilibrium_by_finite_differences(mu):
    # d sx/dx + d txz/dz = 0 and d txz/dx + d sz/dz = 0 (no body force); central differences
    rng = np.random.default_rng(5)
    X = rng.uniform(-2.5, 2.5, 300)
    Z = rng.uniform(0.05, 2.5, 300)
    h = 1e-5

    def s(dx, dz):
        return unit_stresses(X + dx, Z + dz, mu)
    dsx_dx = (s(h, 0)[0] - s(-h, 0)[0]) / (2 * h)
    dtxz_dz = (s(0, h)[2] - s(0, -h)[2]) / (2 * h)
    dtxz_dx = (s(h, 0)[2] - s(-h, 0)[2]) / (2 * h)
    dsz_dz = (s(0, h)[1] - s(0, -h)[1]) / (2 * h)
    scale = np.abs(dsx_dx) + np.abs(dtxz_dz) + 1.0
    assert np.max(np.abs(dsx_dx + dtxz_dz) / scale) < 1e-6
    assert np.max(np.abs(dtxz_dx + dsz_dz) / scale) < 1e-6


def test_compatibility_by_finite_differences():
    # plane strain compatibility for a traction-loaded half plane: laplacian(sx + sz) = 0
    rng = np.random.default_rng(8)
    X = rng.uniform(-2, 2, 200)
    Z = rng.uniform(0.1, 2, 200)
    h = 1e-3

    def tr(dx, dz):
        sx, sz, _ = unit_stresses(X + dx, Z + dz, 0.4)
        return sx + sz
    lap = (tr(h, 0) + tr(-h, 0) + tr(0, h) + tr(0, -h) - 4 * tr(0, 0)) / h**2
    assert np.max(np.abs(lap)) < 1e-4 * np.max(np.abs(tr(0, 0)) / Z**2)


def test_far_field_is_a_flamant_point_load():
    # r >> a: the contact acts like a line load w (normal) and mu w (tangential) at the origin:
    # sx = -(2/pi)(w x^2 z + Q x^3)/r^4, sz = -(2/pi)(w z^3 + Q x z^2)/r^4,
    # txz = -(2/pi)(w x z^2 + Q x^2 z)/r^4   (Johnson eqs. 2.15 and 2.19)
    a, p0, mu = 1e-4, 1e9, 0.3
    w = math.pi * a * p0 / 2
    Q = mu * w
    r = 300 * a
    th = np.linspace(-1.4, 1.4, 15)
    x, z = r * np.sin(th), r * np.cos(th)
    f = stress_field(x, z, a, p0, mu)
    c = -2 / math.pi / r**4
    ref = (c * (w * x**2 * z + Q * x**3), c * (w * z**3 + Q * x * z**2), c * (w * x * z**2 + Q * x**2 * z))
    scale = 2 * w / (math.pi * r)
    for got, exp in zip((f.sx, f.sz, f.txz), ref, strict=True):
        np.testing.assert_allclose(got, exp, atol=1e-4 * scale)   # error ~ (a/r)^2


def test_z_zero_limit_equals_seed002_surface_field():
    a, p0, mu = 1e-4, 9e8, 0.35
    x = a * np.concatenate([[-1.0, 1.0], np.linspace(-3, 3, 601)])
    ref = surface_stress(x, a, p0, mu)
    with warnings.catch_warnings(), np.errstate(divide="raise", invalid="raise", over="raise"):
        warnings.simplefilter("error")
        f0 = stress_field(x, 0.0, a, p0, mu)
        f1 = stress_field(x, 1e-12 * a, a, p0, mu)
    for got in (f0, f1):
        for g, e in zip((got.sx, got.sz, got.txz), ref, strict=True):
            # the edge field varies like sqrt(r/a): 1e-6 p0 at r = 1e-12 a
            np.testing.assert_allclose(g, e, atol=1e-5 * p0, err_msg="z -> 0 limit vs seed 002 eqs. 5-7")
    for g, e in zip((f0.sx, f0.sz, f0.txz), ref, strict=True):
        np.testing.assert_allclose(g, e, rtol=1e-12, atol=1e-12 * p0)
    # independent seed 002 values at the edges: sx(-a) = +2 mu p0, sx(+a) = -2 mu p0, sz = txz = 0
    assert f0.sx[0] == pytest.approx(2 * mu * p0, rel=1e-14)
    assert f0.sx[1] == pytest.approx(-2 * mu * p0, rel=1e-14)
    assert f0.sz[0] == 0.0 and f0.txz[1] == 0.0


def test_no_warnings_near_edges_and_surface():
    X = np.array([-1.0, 1.0, -1.0 - 1e-15, 1.0 + 1e-12, 0.0, 1e-300, -1.0])
    Z = np.array([0.0, 0.0, 0.0, 1e-300, 0.0, 0.0, 1e-12])
    with warnings.catch_warnings(), np.errstate(divide="raise", invalid="raise", over="raise"):
        warnings.simplefilter("error")
        out = unit_stresses(X[:, None], Z[None, :], 0.7)
    assert all(np.all(np.isfinite(s)) for s in out)


def principal_by_eig(f, k):
    T = np.array([[f.sx.flat[k], 0.0, f.txz.flat[k]],
                  [0.0, f.sy.flat[k], 0.0],
                  [f.txz.flat[k], 0.0, f.sz.flat[k]]])
    return np.sort(np.linalg.eigvalsh(T))[::-1]


@pytest.mark.parametrize("plane", ["strain", "stress"])
def test_derived_measures_match_eigenvalues(plane):
    rng = np.random.default_rng(2)
    x = rng.uniform(-2, 2, 50) * 1e-4
    z = rng.uniform(0, 2, 50) * 1e-4
    f = stress_field(x, z, 1e-4, 1e9, 0.2, nu=0.28, plane=plane)
    if plane == "stress":
        assert np.all(f.sy == 0.0)
    else:
        np.testing.assert_allclose(f.sy, 0.28 * (f.sx + f.sz), rtol=1e-15)
    P = f.principal()
    for k in range(50):
        s1, s2, s3 = principal_by_eig(f, k)
        np.testing.assert_allclose(P[:, k], [s1, s2, s3], rtol=1e-10, atol=1e-3)
        vm = math.sqrt(0.5 * ((s1 - s2) ** 2 + (s2 - s3) ** 2 + (s3 - s1) ** 2))
        assert f.von_mises[k] == pytest.approx(vm, rel=1e-10)
        assert f.tresca[k] == pytest.approx(s1 - s3, rel=1e-10)
        T = np.array([[f.sx[k], f.txz[k]], [f.txz[k], f.sz[k]]])
        e = np.linalg.eigvalsh(T)
        assert f.tau1[k] == pytest.approx((e[1] - e[0]) / 2, rel=1e-10)


def test_line_contact_stress_shapes_body_and_bad_depth():
    roller = Material(E=200e9, nu=0.25)
    hc = LineContact(F=np.array([500.0, 1000.0, 2000.0]), length=0.01, R1=0.02, R2=0.01,
                     cam=STEEL, roller=roller, mu=0.1)
    xs = np.linspace(-2, 2, 9)[:, None] * hc.a
    f = hc.stress(xs, 0.5 * hc.a)
    assert f.sx.shape == (9, 3)
    # dimensionless field identical across load cases (self-similarity of Hertz)
    np.testing.assert_allclose(f.sz / hc.p0, np.repeat(f.sz[:, :1] / hc.p0[0], 3, axis=1), rtol=1e-12)
    fr = hc.stress(xs, 0.5 * hc.a, body="roller")
    np.testing.assert_allclose(fr.sy, 0.25 * (fr.sx + fr.sz), rtol=1e-15)
    with pytest.raises(InputError, match="z = -1e-06 m: must be >= 0"):
        hc.stress(0.0, -1e-6)
    with pytest.raises(InputError, match="body = 'cam2'"):
        hc.stress(0.0, 0.0, body="cam2")
