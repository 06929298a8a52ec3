"""femcam.hertz.contact and femcam.hertz.surface against hand formulas, seed 002 and quadrature.

Expected values are typed here independently of the code (Johnson 1985 eqs. 4.44-4.46, seed 002
eqs. 5-10 transcribed literally), or computed by a different numerical method (scipy quad,
Cauchy principal values).
"""

import math
import warnings

import numpy as np
import pytest
from scipy.integrate import quad

from femcam.errors import HertzValidityError, InputError
from femcam.hertz import (
    VALIDITY_RATIO,
    HertzValidityWarning,
    LineContact,
    hertz_pressure,
    surface_stress,
)
from femcam.materials import STEEL, Material

ALU = Material(E=70e9, nu=0.33, name="aluminium")
BRONZE = Material(E=110e9, nu=0.34, name="bronze")


def steel_pair(**kw):
    args = dict(F=1500.0, length=0.01, R1=0.01, R2=0.01, cam=STEEL, roller=STEEL)
    args.update(kw)
    return LineContact(**args)


# -- half-width, peak pressure, E*, R -------------------------------------------------------------

def test_steel_pair_hand_calculation():
    hc = steel_pair(mu=0.1)
    E_star = 210e9 / (2 * (1 - 0.3**2))            # Johnson eq. 4.22: 115.3846 GPa
    R = 0.005                                       # 1/R = 2/0.01
    w = 1500.0 / 0.01
    a = math.sqrt(4 * w * R / (math.pi * E_star))  # Johnson eq. 4.45
    assert hc.E_star == pytest.approx(E_star, rel=1e-14)
    assert hc.R == pytest.approx(R, rel=1e-14)
    assert hc.w == pytest.approx(w, rel=1e-14)
    assert hc.a == pytest.approx(a, rel=1e-14)
    assert hc.a == pytest.approx(90.97e-6, rel=1e-4)   # hand value 90.97 um
    # two independent forms of p0: 2F/(pi a l) (seed 002 eq. 9) and sqrt(w E*/(pi R))
    assert hc.p0 == pytest.approx(2 * 1500.0 / (math.pi * a * 0.01), rel=1e-13)
    assert hc.p0 == pytest.approx(math.sqrt(w * E_star / (math.pi * R)), rel=1e-13)
    assert hc.fmax == pytest.approx(0.1 * hc.p0, rel=1e-15)   # seed 002 eq. 8
    assert hc.valid and hc.a_over_R == pytest.approx(a / R, rel=1e-14)


def test_seed002_eq10_literal_dissimilar_materials():
    # seed 002 eq. 10 as printed: alpha = sqrt(4Fc/(pi l) * ((1-g1^2)/E1 + (1-g2^2)/E2) / (1/R1 + 1/R2))
    # (alpha is the half-width a, gamma the Poisson ratio; the formula is the plane-strain one)
    Fc, l, R1, R2 = 2300.0, 0.012, 0.021, 0.0125
    alpha = math.sqrt(4 * Fc / (math.pi * l) * ((1 - 0.3**2) / 210e9 + (1 - 0.34**2) / 110e9)
                      / (1 / R1 + 1 / R2))
    hc = LineContact(F=Fc, length=l, R1=R1, R2=R2, cam=STEEL, roller=BRONZE)
    assert hc.a == pytest.approx(alpha, rel=1e-14)
    assert hc.p0 == pytest.approx(2 * Fc / (math.pi * alpha * l), rel=1e-14)   # eq. 9


def test_plane_stress_modulus():
    # plane stress: 1/E* = 1/E1 + 1/E2 (replace E by E(1+2nu)/(1+nu)^2, nu by nu/(1+nu))
    hc = LineContact(F=800.0, length=0.005, R1=0.02, R2=0.01, cam=STEEL, roller=ALU,
                     plane="stress")
    E_star = 1 / (1 / 210e9 + 1 / 70e9)
    nu1p = 0.3 / 1.3
    E1p = 210e9 * (1 + 0.6) / 1.3**2
    assert E1p / (1 - nu1p**2) == pytest.approx(210e9, rel=1e-14)   # the substitution rule
    assert hc.E_star == pytest.approx(E_star, rel=1e-14)
    R = 1 / (1 / 0.02 + 1 / 0.01)
    assert hc.a == pytest.approx(math.sqrt(4 * 800 / 0.005 * R / (math.pi * E_star)), rel=1e-14)


def test_equilibrium_integral_of_pressure_times_length_is_F():
    hc = LineContact(F=np.array([10.0, 1500.0, 4.2e4]), length=0.008, R1=np.array([0.03, -0.05, np.inf]),
                     R2=0.012, cam=STEEL, roller=BRONZE)
    for i in range(3):
        a = hc.a[i]
        integral, _ = quad(lambda x, i=i: float(hc.pressure(x)[i]), -1.5 * a, 1.5 * a,
                           points=[-a, a], epsabs=0, epsrel=1e-12)
        assert integral * 0.008 == pytest.approx(hc.F[i], rel=1e-9), "int p dx * l = F"


@pytest.mark.parametrize("k", [0.25, 2.0, 9.0])
def test_load_scaling_sqrt_k(k):
    h1 = steel_pair(R1=-0.04)
    hk = steel_pair(R1=-0.04, F=1500.0 * k)
    assert hk.a / h1.a == pytest.approx(math.sqrt(k), rel=1e-14)
    assert hk.p0 / h1.p0 == pytest.approx(math.sqrt(k), rel=1e-14)


def test_symmetric_in_bodies():
    h12 = LineContact(F=900.0, length=0.01, R1=0.03, R2=0.007, cam=STEEL, roller=ALU)
    h21 = LineContact(F=900.0, length=0.01, R1=0.007, R2=0.03, cam=ALU, roller=STEEL)
    for name in ("R", "E_star", "a", "p0"):
        assert getattr(h12, name) == pytest.approx(getattr(h21, name), rel=1e-15)


def test_concave_and_flat_cam():
    hc = steel_pair(R1=-0.03)
    assert hc.R == pytest.approx(1 / (1 / 0.01 - 1 / 0.03), rel=1e-14)     # 15 mm
    flat = steel_pair(R1=np.inf)
    assert flat.R == pytest.approx(0.01, rel=1e-15)


# -- validity -------------------------------------------------------------------------------------

@pytest.mark.parametrize("R1, R2, text", [
    (-0.01, 0.01, "R1 = -10 mm, R2 = 10 mm"),            # conformal: 1/R = 0
    (-0.008, 0.01, "R1 = -8 mm, R2 = 10 mm"),            # concave tighter than the roller
    (np.inf, np.inf, "R1 = inf mm, R2 = inf mm"),        # flat on flat
])
def test_non_hertzian_geometry_is_refused(R1, R2, text):
    with pytest.raises(HertzValidityError, match=text):
        steel_pair(R1=R1, R2=R2)


def test_non_hertzian_entry_in_array_names_index():
    with pytest.raises(HertzValidityError, match=r"R1 = -5 mm.*index \(2,\)"):
        steel_pair(R1=np.array([0.02, -0.05, -0.005, 0.01]))


def test_zero_load_gives_exact_zeros():
    hc = steel_pair(F=np.array([0.0, 1500.0]), mu=0.3)
    assert hc.a[0] == 0.0 and hc.p0[0] == 0.0 and hc.fmax[0] == 0.0
    x = np.array([[-1e-4], [0.0], [1e-4]])
    for s in (*hc.surface_stress(x), hc.pressure(x)):
        assert np.all(s[:, 0] == 0.0)
        assert np.all(np.isfinite(s))
    f = hc.stress(x, np.array([[0.0], [2e-5], [0.0]]))
    for s in (f.sx, f.sz, f.txz, f.sy, f.tau1, f.von_mises, f.tresca):
        assert np.all(s[:, 0] == 0.0)


@pytest.mark.parametrize("kw, text", [
    (dict(F=-1.0), "F = -1 N: must be >= 0"),
    (dict(F=np.array([1.0, np.nan])), "F = nan N"),
    (dict(length=0.0), "length = 0 m: must be > 0"),
    (dict(R1=0.0), "R1 = 0 m: must be nonzero"),
    (dict(R2=np.nan), "R2 = nan m"),
    (dict(R1=["big"]), "R1 = \\['big'\\] m"),
    (dict(mu=-0.1), "mu = -0.1: must be >= 0"),
    (dict(plane="axisymmetric"), "plane = 'axisymmetric'"),
    (dict(cam="steel"), "cam = 'steel'"),
    (dict(direction=2), "direction = 2"),
])
def test_bad_input_is_input_error(kw, text):
    with pytest.raises(InputError, match=text.replace("(", r"\(").replace(")", r"\)")):
        steel_pair(**kw)


def test_bad_material_is_input_error():
    with pytest.raises(InputError, match="nu = 0.6"):
        steel_pair(roller=Material(E=1e9, nu=0.6))
    with pytest.raises(InputError, match="E = 0 Pa"):
        steel_pair(cam=Material(E=0.0, nu=0.3))


def test_large_half_width_is_flagged():
    # a/R = sqrt(4 w/(pi E* R)) > 0.1  <=>  w > 0.01 pi E* R / 4 = 4.53e6 N/m for R = 5 mm
    w_lim = VALIDITY_RATIO**2 * math.pi * 210e9 / (2 * 0.91) * 0.005 / 4
    with pytest.warns(HertzValidityWarning, match="a / min"):
        hc = steel_pair(F=np.array([0.5, 2.0]) * w_lim * 0.01)
    assert list(hc.valid) == [True, False]
    # concave cam: R = 15 mm but the roller (10 mm) is the radius a must be small against
    with pytest.warns(HertzValidityWarning):
        # a/R = 0.08 (w = 0.08^2 pi E* R / 4) -> a/R2 = 0.08 * 15/10 = 0.12
        hc = steel_pair(R1=-0.03, F=0.08**2 * math.pi * 115.38e9 * 0.015 / 4 * 0.01)
    assert hc.a_over_rmin == pytest.approx(0.12, rel=1e-4)
    assert not hc.valid and hc.a_over_R < VALIDITY_RATIO < hc.a_over_rmin
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert steel_pair().valid


def test_vectorised_over_angles_and_broadcasting():
    rng = np.random.default_rng(3)
    n = 100_000
    F = rng.uniform(0.0, 5e3, n)
    R1 = rng.uniform(0.005, 0.1, n) * rng.choice([-1, 1], n)
    R1 = np.where(np.abs(R1) <= 0.012, 0.05, R1)                # keep concave radii > roller
    hc = LineContact(F=F, length=0.01, R1=R1, R2=0.01, cam=STEEL, roller=BRONZE, mu=0.05)
    assert hc.a.shape == hc.p0.shape == hc.R.shape == (n,)
    E_star = 1 / ((1 - 0.09) / 210e9 + (1 - 0.34**2) / 110e9)
    for i in rng.integers(0, n, 5):
        R = 1 / (1 / R1[i] + 1 / 0.01)
        assert hc.a[i] == pytest.approx(math.sqrt(4 * F[i] / 0.01 * R / (math.pi * E_star)), rel=1e-13)
    # grid broadcasting: loads x radii, and x against the contact shape
    g = LineContact(F=np.array([100.0, 200.0, 400.0])[:, None], length=0.01,
                    R1=np.array([0.01, 0.02]), R2=0.01, cam=STEEL, roller=STEEL)
    assert g.a.shape == (3, 2)
    sx, sz, txz = steel_pair(F=F[:7]).surface_stress(np.linspace(-2e-4, 2e-4, 11)[:, None])
    assert sx.shape == sz.shape == txz.shape == (11, 7)
    assert np.isscalar(steel_pair().a)


# -- surface field: seed 002 eqs. 5-7 typed independently -------------------------------------------

def seed002_surface(x, a, pmax, fmax):
    """Seed 002 eqs. 2-7 transcribed literally (scalar Python, one x)."""
    if abs(x) <= a:
        sxn = -pmax * math.sqrt(1 - x**2 / a**2)                       # eq. 5
        szn = sxn
        sxt = -2 * fmax * x / a                                        # eq. 6a
        txzt = -fmax * math.sqrt(1 - x**2 / a**2)                      # eq. 6b
    else:
        sxn = szn = 0.0
        txzt = 0.0
        if x > a:
            sxt = -2 * fmax * (x / a - math.sqrt(x**2 / a**2 - 1))     # eq. 6c
        else:
            sxt = -2 * fmax * (x / a + math.sqrt(x**2 / a**2 - 1))     # eq. 7
    return sxn + sxt, szn + 0.0, 0.0 + txzt                            # eqs. 2-4


@pytest.mark.parametrize("mu", [0.0, 0.1, 0.45])
def test_surface_stress_equals_seed002_eqs_5_to_7(mu):
    hc = steel_pair(mu=mu)
    x = hc.a * np.array([-3.0, -1.2, -1.0, -0.999, -0.4, 0.0, 0.3, 0.999, 1.0, 1.0001, 2.5, 40.0])
    sx, sz, txz = hc.surface_stress(x)
    for k, xk in enumerate(x):
        ref = seed002_surface(xk, hc.a, hc.p0, mu * hc.p0)
        np.testing.assert_allclose([sx[k], sz[k], txz[k]], ref, rtol=1e-12, atol=1e-9 * hc.p0,
                                   err_msg=f"seed 002 eqs. 5-7 at x/a = {xk / hc.a}")


def test_trailing_edge_tensile_peak_and_direction():
    hc = steel_pair(mu=0.2)
    sx, _, _ = hc.surface_stress(np.array([-hc.a, hc.a]))
    assert sx[0] == pytest.approx(2 * 0.2 * hc.p0, rel=1e-14)   # +2 mu p0 at x = -a
    assert sx[1] == pytest.approx(-2 * 0.2 * hc.p0, rel=1e-14)
    x = np.linspace(-3, 3, 601) * hc.a
    assert np.argmax(hc.surface_stress(x)[0]) == 200           # the tensile peak is at x = -a
    rev = steel_pair(mu=0.2, direction=-1)
    np.testing.assert_allclose(rev.surface_stress(x)[0], hc.surface_stress(-x)[0], rtol=1e-14)
    # mirror x -> -x: normal stresses even, shear odd (tau_xz = -q = +mu p for traction in -x)
    np.testing.assert_allclose(rev.surface_stress(x)[2], -hc.surface_stress(-x)[2], rtol=1e-14)
    assert rev.surface_stress(0.0)[2] == pytest.approx(0.2 * hc.p0, rel=1e-14)


@pytest.mark.parametrize("X", [-3.0, -1.3, -0.7, 0.2, 0.95, 1.6, 5.0])
def test_tangential_surface_sx_is_hilbert_transform_of_traction(X):
    # Johnson eq. 2.25b: sx(x, 0) = -(2/pi) PV int q(s)/(x - s) ds, q = sqrt(1 - s^2) (a = q0 = 1)
    def q(s):
        return math.sqrt(max(1 - s * s, 0.0))
    if abs(X) < 1:
        pv, _ = quad(q, -1, 1, weight="cauchy", wvar=X, epsabs=1e-13)   # PV int q/(s - X)
    else:
        pv, _ = quad(lambda s: q(s) / (s - X), -1, 1, epsabs=1e-13)
    expected = 2 / math.pi * pv
    sx_mu1 = surface_stress(X, 1.0, 1.0, mu=1.0)[0] - surface_stress(X, 1.0, 1.0, mu=0.0)[0]
    assert sx_mu1 == pytest.approx(expected, abs=1e-9)


def test_surface_has_no_warnings_at_edges_and_is_continuous():
    a, p0 = 2e-4, 1.2e9
    x = np.concatenate([[-a, a, 0.0], a * np.linspace(-4, 4, 8001)])
    with warnings.catch_warnings(), np.errstate(all="raise"):
        warnings.simplefilter("error")
        sx, sz, txz = surface_stress(x, a, p0, mu=0.3)
        p = hertz_pressure(x, a, p0)
    assert np.all(np.isfinite(sx)) and np.all(p >= 0)
    for edge in (-a, a):
        lo, hi = surface_stress(np.array([edge * (1 - 1e-12), edge * (1 + 1e-12)]), a, p0, mu=0.3)[0]
        assert lo == pytest.approx(hi, abs=1e-4 * p0), "sx continuous at |x| = a"
    assert np.all(p[np.abs(x) >= a] == 0.0)


@pytest.mark.parametrize("kw, text", [
    (dict(F=None), r"^F = None N: must be a number"),          # numpy would read None as NaN
    (dict(F="1500"), r"^F = '1500' N: must be a number"),      # ... and "1500" as 1500.0
    (dict(F=True), r"^F = True N: must be a number"),
    (dict(R1=None), r"^R1 = None m: must be a number"),
    (dict(F=np.ones(3), R1=np.full(2, 0.02)),
     r"^F, R1, R2 = 'arrays of shapes \(3,\), \(2,\), \(\)': must broadcast"),
])
def test_non_numeric_or_mismatched_input_is_named(kw, text):
    with pytest.raises(InputError, match=text):
        steel_pair(**kw)


def test_field_shape_mismatch_is_named():
    hc = steel_pair(F=np.array([1000.0, 1500.0, 2000.0]))
    shapes = r"'arrays of shapes \(2,\), \(\), \(3,\)'"
    with pytest.raises(InputError, match=r"^x, z and the load cases = " + shapes):
        hc.stress(np.zeros(2), 1e-5)
    with pytest.raises(InputError, match=r"^x and the load cases"):
        hc.surface_stress(np.zeros(4))
    with pytest.raises(InputError, match=r"^x = 'a' m: must be a number"):
        hc.pressure("a")
