"""Tribology formulas (femcam.tribology) against published values, closed forms and independent
numerics written in the tests."""

import ast
import math
import pathlib
import subprocess
import sys

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import gamma

from femcam.errors import InputError
from femcam.tribology import (
    film_thickness,
    first_yield_limit,
    flash_temperature,
    greenwood_tripp,
    lubricant,
    lubrication_regime,
    orthogonal_shear_range,
    shakedown_limit,
    sn_cycles,
    wear_coefficient,
)
from femcam.tribology.film import RQ_PER_RA
from femcam.tribology.lubricants import Lubricant

# a cam-like line contact: steel on steel, R = 5 mm, 150 kN/m, U = 1 m/s, 10 mPa s, 20 1/GPa
CASE = dict(U=1.0, w=1.5e5, R=0.005, E_star=210e9 / (2 * (1 - 0.3**2)), eta0=0.010, alpha=2e-8)


def test_film_exponents_pan_hamrock_1989():
    """lambda scales with the exponents typed from Pan & Hamrock 1989: h_min ~ Ud^0.694 W^-0.128
    (speed and viscosity enter through Ud, the load through W)."""
    base = film_thickness(**CASE, sigma=0.25e-6)
    for key, factor, exponent in (("U", 2.0, 0.694), ("eta0", 3.0, 0.694), ("w", 2.0, -0.128)):
        r = film_thickness(**{**CASE, key: CASE[key] * factor}, sigma=0.25e-6)
        np.testing.assert_allclose(r["lam"] / base["lam"], factor**exponent, rtol=1e-12,
                                   err_msg=f"lambda ~ {key}^{exponent} (Pan & Hamrock 1989)")
    r = film_thickness(**{**CASE, "alpha": CASE["alpha"] * 2}, sigma=0.25e-6)
    np.testing.assert_allclose(r["lam"] / base["lam"], 2.0**0.568, rtol=1e-12)   # G^0.568


def test_film_against_typed_formulas():
    """Pan-Hamrock minimum and central film typed in the test (Hamrock's E' = 2 E*), and the
    Dowson & Higginson 1977 minimum film: the two published fits of numerical EHL solutions agree
    within 10 % for cam-like contacts (U 0.1-10 m/s, w 20-500 kN/m; this run: 5-8 %, the two fits'
    own difference, so the bound cannot be much tighter)."""
    Ep = 2 * CASE["E_star"]
    G = CASE["alpha"] * Ep
    for U in (0.1, 1.0, 10.0):
        for w in (2e4, 1.5e5, 5e5):
            Ud = CASE["eta0"] * U / (Ep * CASE["R"])
            W = w / (Ep * CASE["R"])
            r = film_thickness(**{**CASE, "U": U, "w": w})
            np.testing.assert_allclose(r["h_min"], CASE["R"] * 1.714 * W**-0.128 * Ud**0.694 * G**0.568,
                                       rtol=1e-12)
            np.testing.assert_allclose(r["h_c"], CASE["R"] * 2.922 * W**-0.166 * Ud**0.692 * G**0.470,
                                       rtol=1e-12)
            h_dh = CASE["R"] * 2.65 * Ud**0.70 * G**0.54 * W**-0.13
            assert abs(r["h_min"] / h_dh - 1) < 0.10, (U, w, r["h_min"], h_dh)
            assert r["h_c"] > r["h_min"]               # the outlet constriction is the minimum
            assert not any(bool(np.any(m)) for _, m in r["flags"])   # inside the fitted range


def test_film_zero_and_reversed_entrainment_collapse():
    """U <= 0 (flat-faced follower at the nose): no EHL film, flagged; never NaN."""
    r = film_thickness(**{**CASE, "U": np.array([-0.5, 0.0, 1e-9, 1.0])}, sigma=0.25e-6)
    np.testing.assert_array_equal(r["h_min"][:2], 0.0)
    np.testing.assert_array_equal(r["lam"][:2], 0.0)
    assert np.all(r["h_min"][2:] > 0)
    flags = dict(r["flags"])
    np.testing.assert_array_equal(flags["no_entrainment"], [True, True, False, False])
    assert flags["U_range"][2] and not flags["U_range"][3]   # U = 1e-9 m/s: below the fitted range


def test_film_huge_load_flagged_not_refused():
    r = film_thickness(**{**CASE, "w": 1e9})
    assert np.isfinite(r["h_min"]) and r["h_min"] > 0
    assert dict(r["flags"])["W_range"], "W far above the fitted range must be flagged"


def test_film_bad_input_names_parameter():
    with pytest.raises(InputError, match=r"eta0 = -0.01 Pa s: must be > 0"):
        film_thickness(**{**CASE, "eta0": -0.01})


def test_regime_limits_and_gaussian_rq_over_ra():
    """Regime limits 1 and 3 (Hamrock, Schmid & Jacobson 2004); Rq/Ra = sqrt(pi/2) for Gaussian heights
    (E|z| = sigma sqrt(2/pi)), checked by quadrature of the normal density."""
    assert lubrication_regime([0.99, 1.0, 2.99, 3.0]).tolist() == [0, 1, 1, 2]
    mean_abs = quad(lambda z: abs(z) * math.exp(-z * z / 2) / math.sqrt(2 * math.pi), -40, 40)[0]
    assert abs(RQ_PER_RA - 1.0 / mean_abs) < 1e-9


def _duhamel_peak(n=4000):
    """Independent numerics: peak surface temperature of a half-space swept by a semi-elliptical
    flux of unit peak over a time 2 (1-D conduction, Carslaw & Jaeger 1959 eq. 2.9(6)), with the
    1/sqrt kernel integrated exactly per cell: returns I_max of the Blok constant."""
    s = np.linspace(0, 2, n + 1)
    mid = 0.5 * (s[1:] + s[:-1])
    f = np.sqrt(np.clip(1 - (mid - 1) ** 2, 0, None))
    best = 0.0
    for j in range(n // 2, n + 1):
        t = s[j]
        w = 2 * (np.sqrt(np.clip(t - s[:j], 0, None)) - np.sqrt(np.clip(t - s[1:j + 1], 0, None)))
        best = max(best, float(np.sum(f[:j] * w)))
    return best


def test_flash_temperature_blok_constant_by_duhamel_integral():
    """Equal bodies: dT = C mu w |du| / (sqrt(a) beta (sqrt(u1) + sqrt(u2))) with
    C = 2 I_max / pi^1.5 from an independent Duhamel integral (Blok 1937) (0.2 % tolerance: the n = 4000 cell
    discretisation of the peak)."""
    C = 2 * _duhamel_peak() / math.pi**1.5
    mu, w, a, beta = 0.1, 2e5, 1e-4, 13000.0
    u1, u2 = 4.0, 2.0
    got = flash_temperature(mu, w, a, u1, u2, beta, beta)
    ref = C * mu * w * abs(u1 - u2) / (math.sqrt(a) * beta * (math.sqrt(u1) + math.sqrt(u2)))
    assert abs(got / ref - 1) < 2e-3, (got, ref, C)


def test_flash_temperature_agma925_form():
    """AGMA 925-A03 flash temperature in its own units: 31.62 K mu X w_Nr |v1 - v2| /
    ((B_M1 sqrt(v1) + B_M2 sqrt(v2)) sqrt(b_H)), K = 0.80 (semi-elliptic), X = 1, w in N/mm, b_H in mm,
    B_M in N/(mm s^0.5 K). femcam's exact constant 0.786 is 1.8 % below AGMA's rounded 0.80."""
    mu, w, a, u1, u2 = 0.08, 3.0e5, 2.0e-4, 10.0, 6.0
    beta1, beta2 = 13_000.0, 11_000.0                       # W s^0.5/(m^2 K)
    agma = (31.62 * 0.80 * mu * (w * 1e-3) * abs(u1 - u2)
            / ((beta1 * 1e-3 * math.sqrt(u1) + beta2 * 1e-3 * math.sqrt(u2)) * math.sqrt(a * 1e3)))
    got = flash_temperature(mu, w, a, u1, u2, beta1, beta2)
    assert abs(got / agma - 1) < 0.02, (got, agma)


def test_flash_temperature_zero_sliding_is_zero():
    np.testing.assert_array_equal(flash_temperature(0.1, 2e5, 1e-4, [1.0, 0.0], [1.0, 0.0], 1e4, 1e4), 0.0)
    assert flash_temperature(0.0, 2e5, 1e-4, 2.0, 1.0, 1e4, 1e4) == 0.0


def test_first_yield_and_shakedown_johnson_1985():
    """Johnson 1985 §4.2 / §9.2 (Fig. 9.11): first yield p0/k = 3.3 (tau1 = 0.300 p0), elastic
    shakedown (perfectly plastic) p0/k = 4.0 without friction, decreasing with mu, and for
    mu > 0.367 the surface limit p0/k = 1/mu."""
    assert abs(first_yield_limit(0.0) - 1 / 0.300) < 0.01
    assert abs(shakedown_limit(0.0) - 4.0) < 0.01
    mus = [0.0, 0.1, 0.2, 0.3, 0.367]
    vals = [shakedown_limit(m) for m in mus]
    assert all(x > y for x, y in zip(vals, vals[1:], strict=False)), vals
    for mu in (0.367, 0.4, 0.5):
        assert abs(shakedown_limit(mu) * mu - 1.0) < 0.005, mu
    assert shakedown_limit(0.3) < 1 / 0.3          # below 0.367 the subsurface governs
    for mu in (0.0, 0.3):
        assert shakedown_limit(mu) >= first_yield_limit(mu) - 1e-3   # shakedown never below yield


def test_orthogonal_shear_range_frictionless():
    """Johnson 1985 §9.2: |txz| max = p0/4 at z = a/2, x = +-0.87 a, so the range over one pass is
    2 x 0.25 p0 = 0.5 p0 at z = 0.5 a (grid: z and x steps a/100)."""
    rng, z = orthogonal_shear_range(0.0)
    assert abs(rng - 0.5) < 1e-4 and abs(z - 0.5) < 0.01


def test_sn_law_iso6336_life_factor():
    """ISO 6336-2 Z_NT (case-hardened steel): 1.6 at 1e5 cycles, 1.0 at 5e7 cycles."""
    assert abs(sn_cycles(1.6e9, 1e9) / 1e5 - 1) < 1e-9
    assert abs(sn_cycles(1.0e9, 1e9) / 5e7 - 1) < 1e-12
    assert sn_cycles(0.0, 1e9) == np.inf


def test_greenwood_tripp_closed_form_quadrature_and_fit():
    """F_5/2(0) = 2^(3/4) Gamma(7/4)/sqrt(2 pi); F_n by direct quadrature; the fit
    4.4086e-5 (4 - lam)^6.804 of Arcoumanis et al. 1997 on 1..2 within 11 % (a curve fit: this run
    found 3.5 % at 1 and 10.1 % at 2, the fit's own error, so the bound cannot be tighter)."""
    assert abs(greenwood_tripp(2.5, 0.0) - 2**0.75 * gamma(1.75) / math.sqrt(2 * math.pi)) < 1e-12
    for lam in (0.5, 1.0, 2.0, 3.0):
        ref = quad(lambda s, lam=lam: (s - lam) ** 2.5 * math.exp(-s * s / 2), lam, np.inf)[0]
        ref /= math.sqrt(2 * math.pi)
        assert abs(greenwood_tripp(2.5, lam) / ref - 1) < 1e-8
    for lam in (1.0, 1.5, 2.0):
        assert abs(greenwood_tripp(2.5, lam) / (4.4086e-5 * (4 - lam) ** 6.804) - 1) < 0.11


def test_wear_coefficient_by_regime():
    k = wear_coefficient(1e-17, [0.0, 0.5, 1.0, 3.0, 5.0])
    assert k[0] == 1e-17 and np.all(np.diff(k) < 0)
    assert k[3] < 1e-3 * k[0]                       # full film: wear all but stops


def test_lubricant_laws():
    """ASTM D341 through both grade points; exponential law: eta_ref at T_ref, eta_ref/e one
    1/beta_T later; bad data named."""
    oil = lubricant("ISO VG 46 mineral")
    np.testing.assert_allclose(oil.viscosity([40.0, 100.0]) / oil.rho, [46e-6, 6.8e-6], rtol=1e-9)
    assert oil.viscosity(70.0) < oil.viscosity(40.0)
    ex = Lubricant(eta_ref=0.02, T_ref_C=60.0, beta_T=0.03, alpha=2e-8, rho=860.0)
    np.testing.assert_allclose(ex.viscosity([60.0, 60.0 + 1 / 0.03]), [0.02, 0.02 / math.e], rtol=1e-12)
    with pytest.raises(InputError, match="unknown; valid names"):
        lubricant("SAE 90 unicorn")
    with pytest.raises(InputError, match="nu100"):
        Lubricant(nu40=46e-6, nu100=60e-6, alpha=2e-8, rho=860.0)


def test_layers_and_headless_imports():
    """femcam.tribology imports only numpy/scipy and femcam._validate/errors/materials/hertz; neither
    it nor femcam.assess pulls in matplotlib/gmsh/pyvista."""
    allowed = {"_validate", "errors", "materials", "hertz"}
    for f in pathlib.Path("femcam/tribology").glob("*.py"):
        for node in ast.walk(ast.parse(f.read_text())):
            if isinstance(node, ast.ImportFrom) and node.level == 2:
                assert (node.module or node.names[0].name).split(".")[0] in allowed, (f, node.module)
            elif isinstance(node, ast.Import) or (isinstance(node, ast.ImportFrom) and node.level == 0):
                mod = node.module if isinstance(node, ast.ImportFrom) else node.names[0].name
                assert mod.split(".")[0] in {"numpy", "scipy", "math", "random", "dataclasses", "functools",
                                             "__future__"}, (f, mod)
    code = ("import sys, femcam.tribology, femcam.assess\n"
            "print(','.join(m for m in ('matplotlib', 'gmsh', 'pyvista', 'skfem') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""


def test_kinematic_hardening_shakedown():
    """Kinematic hardening (Johnson 1985 §9.2, Johnson 1989): 4.0 without friction like the
    perfectly plastic limit; never below it; and 1/mu where the surface governs: at z = 0 the path
    ((sx - sz)/2, txz) = (-mu p0 x/a, -mu p0 sqrt(1 - x^2/a^2)) is a half circle of radius mu p0,
    whose smallest enclosing circle has radius mu p0 (its diameter joins x = -a and x = a)."""
    assert abs(shakedown_limit(0.0, "kinematic") - 4.0) < 0.01
    assert shakedown_limit(0.1, "kinematic") >= shakedown_limit(0.1) - 1e-6
    assert abs(shakedown_limit(0.3, "kinematic") * 0.3 - 1.0) < 1e-6
    with pytest.raises(InputError, match="hardening"):
        shakedown_limit(0.1, "isotropic")


def test_enclosing_radius_against_minimax_search():
    """Welzl's smallest enclosing circle against a direct minimax search of the centre
    (scipy Nelder-Mead on max |p - c|, tolerance 1e-6 of the radius)."""
    from scipy.optimize import minimize

    from femcam.tribology.fatigue import enclosing_radius

    rng = np.random.default_rng(1)
    for n in (3, 10, 200):
        P = rng.normal(size=(n, 2)) * [1.0, 0.3]
        res = minimize(lambda c, P=P: np.max(np.hypot(*(P - c).T)), P.mean(axis=0), method="Nelder-Mead",
                       options={"xatol": 1e-10, "fatol": 1e-12, "maxiter": 20000})
        assert abs(enclosing_radius(P) / res.fun - 1) < 1e-6


def test_flash_temperature_stolarski_1990_blok_factors():
    """Stolarski 1990, *Tribology in Machine Design*, §2 p. 76: Blok's maximum flash temperature of
    two bodies of the same material under a semi-elliptical (Hertzian) frictional heat source over
    the contact width w, printed with the numerical factors 1.11, 0.62 and 2.45 (three forms "in
    commonly available variables", p_H the Hertzian maximum pressure). The three equations are
    images in the copy consulted; the forms below are the only ones of Blok's three classical forms
    that those factors fit (E' = 2 E*, w = 2a, and the Hertz relations written in the test):

        1.11 mu w' |sqrt(u1) - sqrt(u2)| / (beta sqrt(w))
        0.62 mu w'^(3/4) (E'/R)^(1/4) |sqrt(u1) - sqrt(u2)| / beta
        2.45 mu p_H^(3/2) (R/E')^(1/2) |sqrt(u1) - sqrt(u2)| / beta

    femcam's exact constant 0.78598 (checked by the Duhamel integral above) gives 1.1115, 0.6222
    and 2.4692. Tolerances: the printed rounding of 1.11 (0.45 %) and 0.62 (0.81 %); 2.45 differs by
    0.78 %, more than its own rounding (0.2 %): 2.45 = pi x 0.78, i.e. the book multiplied a
    two-figure Blok constant 0.78 (0.77 % below 0.786), so its tolerance is 1 %."""
    mu, wl, R, u1, u2 = 0.1, 2.0e5, 0.010, 4.0, 2.0          # N/m, m, m/s
    E_star = 210e9 / (2 * (1 - 0.3**2))
    Ep = 2 * E_star
    beta = math.sqrt(46.0 * 7850.0 * 470.0)                   # steel, W s^0.5/(m^2 K)
    a = math.sqrt(4 * wl * R / (math.pi * E_star))            # Johnson 1985 eq. 4.45
    pH = 2 * wl / (math.pi * a)
    ds = abs(math.sqrt(u1) - math.sqrt(u2))
    got = float(flash_temperature(mu, wl, a, u1, u2, beta, beta))
    forms = {"1.11": (1.11 * mu * wl * ds / (beta * math.sqrt(2 * a)), 0.005),
             "0.62": (0.62 * mu * wl**0.75 * (Ep / R) ** 0.25 * ds / beta, 0.009),
             "2.45": (2.45 * mu * pH**1.5 * math.sqrt(R / Ep) * ds / beta, 0.010)}
    for name, (ref, tol) in forms.items():
        assert abs(got / ref - 1) < tol, (name, got, ref)


def test_kinematic_shakedown_friction_enters_at_second_order():
    """Kinematic hardening (the yield circle may translate in both (sx - sz)/2 and txz) against the
    perfectly plastic limit (Melan's residual rho_x(z) shifts only (sx - sz)/2). The tangential
    traction adds to txz a part that is even in x (the Flamant kernels: txz of a tangential line
    load = sx of a normal one; Johnson 1985 ch. 2), i.e. the same shift at the two orthogonal
    shear peaks x = -+0.87a: the translating circle absorbs it, so the limit leaves 4.0 only at
    second order in mu, while the perfectly plastic limit falls at first order: consistent with the
    reading "4.0 up to mu ~ 0.25, then 1/mu" quoted for kinematic hardening, whose printed
    intermediate values were not available to type in (see docs/assess.md, Validation sources).
    Bounds: first order zero means (4/K - 1)/mu -> 0 linearly; this run gives (4/K - 1)/mu^2 =
    0.32-0.36 for mu = 0.05-0.25 (0.33 at 0.1, 0.36 at 0.25 checked here), bounded by 0.5; the
    perfectly plastic (4/K - 1)/mu is 1.2 at mu = 0.1 (first order)."""
    for mu in (0.1, 0.25):
        K = shakedown_limit(mu, "kinematic")
        assert 0.0 < 4.0 / K - 1.0 < 0.5 * mu**2, (mu, K)
    assert (4.0 / shakedown_limit(0.1) - 1.0) / 0.1 > 1.0          # perfectly plastic: first order
    # the kinematic limit meets the surface limit 1/mu just above mu = 0.25 (4.0 = 1/0.25)
    assert shakedown_limit(0.25, "kinematic") < 1 / 0.25
    assert abs(shakedown_limit(0.27, "kinematic") * 0.27 - 1) < 1e-6
