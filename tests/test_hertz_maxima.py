"""femcam.hertz.maxima against textbook values, 1-D closed-form maximisations and dense sampling.

References: Johnson, *Contact Mechanics* (1985) §4.2.3 / Fig. 4.6 (tau1 = 0.300 p0 at z = 0.786 a,
|txz| = p0/4 at (+-0.87 a, 0.5 a)) and the von Mises maximum ~0.557 p0 at ~0.70 a for nu = 0.3.
"""

import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from femcam.errors import InputError
from femcam.hertz import (
    LineContact,
    max_orthogonal_shear,
    max_shear,
    max_von_mises,
    unit_stresses,
)
from femcam.materials import STEEL


def axis(Z, nu=0.3):
    """Classic closed forms on x = 0 (frictionless): sx, sz / p0 and sy = nu (sx + sz)."""
    sx = -((1 + 2 * Z * Z) / math.sqrt(1 + Z * Z) - 2 * Z)
    sz = -1 / math.sqrt(1 + Z * Z)
    return sx, sz, nu * (sx + sz)


def test_frictionless_tau1_max_textbook_and_axis_closed_form():
    m = max_shear(0.0)
    assert m.converged and m.value >= m.grid_value
    assert m.value == pytest.approx(0.300, abs=5e-4), "Johnson: tau1max = 0.300 p0"
    assert m.z == pytest.approx(0.786, abs=1e-3), "Johnson: at z = 0.786 a"
    assert m.x == pytest.approx(0.0, abs=1e-6)
    r = minimize_scalar(lambda Z: -0.5 * abs(axis(Z)[0] - axis(Z)[1]), bounds=(0.1, 2),
                        method="bounded", options=dict(xatol=1e-10))
    assert m.value == pytest.approx(-r.fun, rel=1e-9)
    assert m.z == pytest.approx(r.x, abs=1e-5)


def test_frictionless_von_mises_max_textbook_and_axis_closed_form():
    m = max_von_mises(0.0, 0.3)
    assert m.value == pytest.approx(0.557, abs=1e-3), "von Mises max ~ 0.557 p0 (nu = 0.3)"
    assert m.z == pytest.approx(0.70, abs=0.01), "at z ~ 0.70 a"
    assert m.x == pytest.approx(0.0, abs=1e-6)

    def vm(Z):
        sx, sz, sy = axis(Z)
        return math.sqrt(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2))
    r = minimize_scalar(lambda Z: -vm(Z), bounds=(0.1, 2), method="bounded", options=dict(xatol=1e-10))
    assert m.value == pytest.approx(-r.fun, rel=1e-9)
    assert m.z == pytest.approx(r.x, abs=1e-5)


def test_frictionless_orthogonal_shear_is_quarter_p0_at_sqrt3_half():
    m = max_orthogonal_shear()
    assert m.value == pytest.approx(0.25, abs=1e-9)
    assert abs(m.x) == pytest.approx(math.sqrt(3) / 2, abs=1e-5)   # 0.866 a
    assert m.z == pytest.approx(0.5, abs=1e-5)


def measure(q, X, Z, mu, nu=0.3):
    sx, sz, txz = unit_stresses(X, Z, mu)
    if q == "tau1":
        return np.hypot((sx - sz) / 2, txz)
    if q == "txz":
        return np.abs(txz)
    sy = nu * (sx + sz)
    return np.sqrt(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2) + 3 * txz**2)


FUNCS = {"tau1": max_shear, "von_mises": max_von_mises, "txz": max_orthogonal_shear}


@pytest.mark.parametrize("q", list(FUNCS))
@pytest.mark.parametrize("mu", [0.05, 0.2, 0.3, 0.37, 0.6, 1.5])
def test_maximum_is_not_beaten_by_dense_random_sampling(q, mu):
    m = FUNCS[q](mu)
    rng = np.random.default_rng(17)
    X = np.concatenate([rng.uniform(-3, 3, 60_000), rng.uniform(-1.05, 1.05, 20_000)])
    Z = np.concatenate([rng.uniform(0, 3, 60_000) ** 2 / 3, np.zeros(20_000)])  # dense near z = 0
    sampled = measure(q, X, Z, mu).max()
    assert m.value >= sampled - 1e-12, f"{q} at mu = {mu}: sampled {sampled} > {m.value}"
    assert m.value == pytest.approx(float(measure(q, m.x, m.z, mu)), rel=1e-12)


def test_surface_maxima_for_large_friction():
    # surface, |x| <= a: (sx - sz)/2 = -mu p0 x/a, txz = -mu p sqrt(1 - x^2/a^2)  =>  tau1 = mu p0
    m = max_shear(0.5)
    assert m.value == pytest.approx(0.5, rel=1e-12) and m.z == 0.0 and "plateau" in m.message
    t = max_orthogonal_shear(0.5)                     # |txz| = mu p0 at the centre of the contact
    assert t.value == pytest.approx(0.5, rel=1e-12) and t.z == 0.0 and t.x == pytest.approx(0, abs=1e-6)
    # von Mises on the surface from seed 002 eqs. 5-7 typed here, maximised over x in 1-D
    mu, nu = 1.0, 0.3

    def vm_surface(X):
        p = math.sqrt(max(1 - X * X, 0.0))
        out = math.sqrt(max(X * X - 1, 0.0))
        sx = -p - 2 * mu * (X - math.copysign(out, X))
        sz, txz = -p, -mu * p
        sy = nu * (sx + sz)
        return math.sqrt(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2) + 3 * txz**2)
    Xs = np.linspace(-2, 2, 40001)
    best = max(vm_surface(X) for X in Xs)
    v = max_von_mises(mu, nu)
    assert v.z == 0.0
    assert v.value == pytest.approx(best, rel=1e-7)
    assert v.value >= 2 * mu * math.sqrt(1 - nu + nu * nu)   # >= the trailing-edge value at x = -a


def test_tau1_maximum_reaches_surface_for_larger_friction():
    # Johnson §7.2: with friction the maximum approaches the surface and reaches it at larger mu
    zs = [max_shear(mu).z for mu in (0.0, 0.1, 0.2, 0.3, 0.36)]
    assert all(z1 > z2 > 0 for z1, z2 in zip(zs, zs[1:], strict=False))
    assert max_shear(0.45).z == 0.0
    assert max_von_mises(0.35).z == 0.0
    vals = [max_shear(mu).value for mu in np.linspace(0, 1, 11)]
    assert np.all(np.diff(vals) > 0)


def test_line_contact_scales_maxima_per_load_case():
    hc = LineContact(F=np.array([300.0, 1200.0, 4800.0]), length=0.01, R1=0.015, R2=0.01,
                     cam=STEEL, roller=STEEL, mu=0.15)
    unit = max_shear(0.15)
    m = hc.max_shear()
    np.testing.assert_allclose(m.value, unit.value * hc.p0, rtol=1e-15)
    np.testing.assert_allclose(m.z, unit.z * hc.a, rtol=1e-15)
    # the maximum of the dimensional field at the scaled point equals the scaled maximum
    f = hc.stress(m.x, m.z)
    np.testing.assert_allclose(f.tau1, m.value, rtol=1e-12)
    vm = hc.max_von_mises()
    np.testing.assert_allclose(hc.stress(vm.x, vm.z).von_mises, vm.value, rtol=1e-12)
    rev = LineContact(F=1200.0, length=0.01, R1=0.015, R2=0.01, cam=STEEL, roller=STEEL,
                      mu=0.15, direction=-1)
    assert rev.max_shear().x == pytest.approx(-m.x[1], rel=1e-12)
    t = hc.max_orthogonal_shear()
    np.testing.assert_allclose(np.abs(hc.stress(t.x, t.z).txz), t.value, rtol=1e-12)


def test_bad_arguments():
    with pytest.raises(InputError, match="mu = -0.2"):
        max_shear(-0.2)
    with pytest.raises(InputError, match="nu = 0.5"):
        max_von_mises(0.1, 0.5)
    with pytest.raises(InputError, match="plane = 'x'"):
        max_von_mises(0.1, 0.3, "x")
