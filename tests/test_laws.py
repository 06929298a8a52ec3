"""Tests of femcam.kinematics.laws against closed forms, textbook tables and seed 002.

References: Norton, *Cam Design and Manufacturing Handbook* (2nd ed., 2009), table 3-2
(peak coefficients); seed 002 eqs. 1 and 12-23 (Bezier laws, typed in here independently).
"""

from math import comb, pi, sqrt

import numpy as np
import pytest
from scipy.integrate import quad

from femcam.errors import InputError
from femcam.kinematics import LAW_NAMES, bernstein, law

FIXED = [n for n in LAW_NAMES if n not in ("bezier", "polynomial")]
RNG_POINTS = np.concatenate([[0.0], np.random.default_rng(7).uniform(-0.3, 1.3, 7), [1.0]])


def all_laws():
    out = [law(n) for n in FIXED]
    out.append(law("bezier", control_points=RNG_POINTS))
    out.append(law("polynomial", coefficients=[0, 0, 0, 10, -15, 6]))
    return out


@pytest.mark.parametrize("L", all_laws(), ids=lambda L: L.name)
def test_unit_lift_boundary_values(L):
    np.testing.assert_allclose(L.s(0.0), 0.0, atol=1e-14)
    np.testing.assert_allclose(L.s(1.0), 1.0, atol=1e-13)


# v, a, j at u = 0 and u = 1 as each law defines them (Norton 2009 ch. 3; seed 002 eqs. 15-23)
ENDS = {
    "uniform_velocity": (1, 0, 0, 1, 0, 0),
    "shm": (0, pi**2 / 2, 0, 0, -pi**2 / 2, 0),
    "cycloidal": (0, 0, 4 * pi**2, 0, 0, 4 * pi**2),
    "poly345": (0, 0, 60, 0, 0, 60),
    "poly4567": (0, 0, 0, 0, 0, 0),
    "bezier5": (0, 0, 60, 0, 0, 60),  # eq. 17 at u = 0, 1: 60, 60
    "bezier7": (0, 0, 0, 0, 0, 0),
    "bezier9": (0, 0, 0, 0, 0, 0),
}


@pytest.mark.parametrize("name", list(ENDS))
def test_end_derivatives(name):
    L = law(name)
    e = np.array([0.0, 1.0])
    got = np.array([L.v(e)[0], L.a(e)[0], L.j(e)[0], L.v(e)[1], L.a(e)[1], L.j(e)[1]])
    np.testing.assert_allclose(got, ENDS[name], atol=1e-12 * 100, rtol=1e-12)
    e2 = L.ends
    np.testing.assert_allclose([e2.v0, e2.a0, e2.j0, e2.v1, e2.a1, e2.j1], ENDS[name], atol=1e-9)


@pytest.mark.parametrize("name", ["modified_sine", "modified_trapezoid"])
def test_modified_laws_start_and_end_with_zero_v_and_a_and_jerk_4pi_Ca(name):
    # the first piece is a = Ca sin(4 pi u), so j(0) = 4 pi Ca (Norton 2009 sec. 3.9-3.10)
    L = law(name)
    e = np.array([0.0, 1.0])
    np.testing.assert_allclose(L.v(e), 0.0, atol=1e-12)
    np.testing.assert_allclose(L.a(e), 0.0, atol=1e-12)
    np.testing.assert_allclose(L.j(e), 4 * pi * L.Ca, rtol=1e-12)


@pytest.mark.parametrize("L", all_laws(), ids=lambda L: L.name)
def test_central_differences_match_exact_derivatives(L):
    h = 1e-5
    u = np.linspace(0.013, 0.987, 151)
    for bp in getattr(L, "breakpoints", ()):
        u = u[np.abs(u - bp) > 3 * h]  # one-sided pieces: do not difference across a kink in j
    pairs = [(L.s, L.v, L.Cv), (L.v, L.a, L.Ca), (L.a, L.j, L.Cj)]
    for f, df, C in pairs:
        fd = (f(u + h) - f(u - h)) / (2 * h)
        np.testing.assert_allclose(fd, df(u), rtol=0, atol=1e-6 * max(C, 1.0),
                                   err_msg=f"{L.name}: central difference vs exact derivative")


@pytest.mark.parametrize("name", ["modified_sine", "modified_trapezoid"])
def test_piecewise_laws_are_continuous_at_breakpoints(name):
    L = law(name)
    bp = np.array(L.breakpoints)
    assert bp.size >= 2
    eps = 1e-11
    for f, C in ((L.s, 1.0), (L.v, L.Cv), (L.a, L.Ca), (L.j, L.Cj)):
        np.testing.assert_allclose(f(bp - eps), f(bp + eps), atol=1e-8 * C,
                                   err_msg=f"{name}: jump at a piece boundary")


def _quad_law(pieces):
    """Independent reference: integrate an unscaled acceleration profile twice with quad.

    Returns (Cv, Ca) of the unit-lift law: s(1) = int_0^1 (1 - u) a(u) du, Ca = 1/s(1),
    Cv = max v / s(1) with v at u = 1/2 (antisymmetric a, peak velocity at mid-rise).
    """
    def a(u):
        for (lo, hi), f in pieces:
            if lo <= u <= hi:
                return f(u)
        raise AssertionError(u)

    br = sorted({x for (lo, hi), _ in pieces for x in (lo, hi)})
    s1 = sum(quad(lambda u: (1 - u) * a(u), lo, hi, epsabs=1e-14)[0]
             for lo, hi in zip(br[:-1], br[1:], strict=True))
    bh = sorted({min(x, 0.5) for x in br})
    vmid = sum(quad(a, lo, hi, epsabs=1e-14)[0] for lo, hi in zip(bh[:-1], bh[1:], strict=True))
    return vmid / s1, 1.0 / s1


MOD_TRAP = [((0, 1 / 8), lambda u: np.sin(4 * pi * u)), ((1 / 8, 3 / 8), lambda u: 1.0),
            ((3 / 8, 5 / 8), lambda u: np.cos(4 * pi * (u - 3 / 8))), ((5 / 8, 7 / 8), lambda u: -1.0),
            ((7 / 8, 1), lambda u: -np.cos(4 * pi * (u - 7 / 8)))]
MOD_SINE = [((0, 1 / 8), lambda u: np.sin(4 * pi * u)),
            ((1 / 8, 7 / 8), lambda u: np.cos(4 * pi / 3 * (u - 1 / 8))),
            ((7 / 8, 1), lambda u: -np.cos(4 * pi * (u - 7 / 8)))]


def _poly_peak(c, k):
    """max |d^k p/du^k| on [0, 1] from the real roots of d^(k+1) p (numpy.roots), plus the ends."""
    P = np.polynomial.polynomial
    dk = P.polyder(c, k)
    r = np.roots(P.polyder(dk, 1)[::-1])
    r = r[np.abs(r.imag) < 1e-9].real
    cand = np.concatenate([[0.0, 1.0], r[(r >= 0) & (r <= 1)]])
    return np.max(np.abs(P.polyval(cand, dk)))


# (name, Cv, Ca, Cj, rtol) with independent closed forms; textbook values in the comments
def _peak_table():
    c4567 = [0, 0, 0, 0, 35, -84, 70, -20]
    c9 = [0, 0, 0, 0, 0, 126, -420, 540, -315, 70]
    trap_cv, trap_ca = _quad_law(MOD_TRAP)
    sine_cv, sine_ca = _quad_law(MOD_SINE)
    return [
        ("uniform_velocity", 1.0, 0.0, 0.0),
        ("shm", pi / 2, pi**2 / 2, pi**3 / 2),  # Norton: 1.5708, 4.9348, 15.5031
        ("cycloidal", 2.0, 2 * pi, 4 * pi**2),  # 2, 6.2832, 39.4784
        ("poly345", 15 / 8, 10 / sqrt(3), 60.0),  # 1.875, 5.7735, 60
        ("poly4567", 35 / 16, _poly_peak(c4567, 2), 52.5),  # 2.1875, 7.5132, 52.5
        ("bezier5", 15 / 8, 10 / sqrt(3), 60.0),
        ("bezier7", 35 / 16, _poly_peak(c4567, 2), 52.5),
        ("bezier9", 630 / 256, _poly_peak(c9, 2), _poly_peak(c9, 3)),
        ("modified_trapezoid", trap_cv, trap_ca, 4 * pi * trap_ca),  # 2.0000, 4.8881, 61.426
        ("modified_sine", sine_cv, sine_ca, 4 * pi * sine_ca),  # 1.7596, 5.5280, 69.466
    ]


@pytest.mark.parametrize("name,Cv,Ca,Cj", _peak_table(), ids=lambda x: x if isinstance(x, str) else "")
def test_peak_coefficients_closed_form(name, Cv, Ca, Cj):
    L = law(name)
    np.testing.assert_allclose([L.Cv, L.Ca, L.Cj], [Cv, Ca, Cj], rtol=1e-8, atol=1e-12,
                               err_msg=f"{name}: peak coefficients vs closed form")


# Norton (2009) table 3-2, as printed (4-5 significant figures)
TEXTBOOK = {
    "poly345": (1.875, 5.7735, 60.0),
    "poly4567": (2.1875, 7.5132, 52.5),
    "cycloidal": (2.0, 6.2832, 39.478),
    "shm": (1.5708, 4.9348, 15.503),
    "modified_sine": (1.7596, 5.5280, 69.466),
    "modified_trapezoid": (2.0000, 4.8881, 61.426),
}


@pytest.mark.parametrize("name", list(TEXTBOOK))
def test_peak_coefficients_textbook_table(name):
    L = law(name)
    np.testing.assert_allclose([L.Cv, L.Ca, L.Cj], TEXTBOOK[name], rtol=5e-5,
                               err_msg=f"{name}: Norton (2009) table 3-2")


def test_modified_trapezoid_peak_velocity_is_exactly_two():
    # closed form: v(1/2) = Ca (1/4 + 1/(2 pi)) and Ca = 4.8881... give Cv = 2 (Norton 2009)
    L = law("modified_trapezoid")
    np.testing.assert_allclose(L.Cv, L.Ca * (0.25 + 1 / (2 * pi)), rtol=1e-10)
    np.testing.assert_allclose(L.Cv, 2.0, rtol=1e-10)


# seed 002 eqs. 12-23, typed in from the paper (with L = 1, beta = 1)
SEED002 = {
    "bezier5": ([0, 0, 0, 10, -15, 6], [0, 0, 30, -60, 30], [0, 60, -180, 120], [60, -360, 360]),
    "bezier7": ([0, 0, 0, 0, 35, -84, 70, -20], [0, 0, 0, 140, -420, 420, -140],
                [0, 0, 420, -1680, 2100, -840], [0, 840, -5040, 8400, -4200]),
    "bezier9": ([0, 0, 0, 0, 0, 126, -420, 540, -315, 70], [0, 0, 0, 0, 630, -2520, 3780, -2520, 630],
                [0, 0, 0, 2520, -12600, 22680, -17640, 5040],
                [0, 0, 7560, -50400, 113400, -105840, 35280]),
}


@pytest.mark.parametrize("name", list(SEED002))
def test_bezier_presets_equal_seed002_polynomials(name):
    L = law(name)
    u = np.linspace(0, 1, 101)
    pv = np.polynomial.polynomial.polyval
    for f, c in zip((L.s, L.v, L.a, L.j), SEED002[name], strict=True):
        np.testing.assert_allclose(f(u), pv(u, c), atol=1e-10, err_msg=f"{name}: seed 002 eqs. 12-23")


def test_bezier_from_control_points_equals_bezier5_and_eq12():
    L = law("bezier", control_points=[0, 0, 0, 1, 1, 1])
    u = np.linspace(0, 1, 51)
    np.testing.assert_allclose(L.s(u), 10 * u**3 - 15 * u**4 + 6 * u**5, atol=1e-14)


def test_seed002_eq1_exponent_typo():
    """Seed 002 eq. 1 prints (1-u)^(n-1); the Bernstein basis needs (1-u)^(n-i)."""
    u = np.linspace(0, 1, 41)
    n = 5
    P = [0, 0, 0, 1, 1, 1]
    correct = sum(comb(n, i) * u**i * (1 - u) ** (n - i) for i in range(n + 1))
    printed = sum(comb(n, i) * u**i * (1 - u) ** (n - 1) for i in range(n + 1))
    np.testing.assert_allclose(correct, 1.0, atol=1e-14)  # partition of unity
    assert np.max(np.abs(printed - 1.0)) > 0.5  # the printed form is not
    eq12 = 10 * u**3 - 15 * u**4 + 6 * u**5
    printed_curve = sum(Pi * comb(n, i) * u**i * (1 - u) ** (n - 1) for i, Pi in enumerate(P))
    assert np.max(np.abs(printed_curve - eq12)) > 0.1  # printed eq. 1 does not give eq. 12
    got = sum(Pi * bernstein(n, i, u) for i, Pi in enumerate(P))
    np.testing.assert_allclose(got, eq12, atol=1e-14)


def test_random_bezier_matches_power_basis_expansion():
    # independent method: expand sum P_i C(n,i) u^i (1-u)^(n-i) into the power basis
    P = RNG_POINTS
    n = P.size - 1
    Pm = np.polynomial.polynomial
    c = np.zeros(1)
    for i, Pi in enumerate(P):
        c = Pm.polyadd(c, Pi * comb(n, i) * Pm.polymul(Pm.polypow([0, 1], i), Pm.polypow([1, -1], n - i)))
    L = law("bezier", control_points=P)
    u = np.linspace(0, 1, 77)
    for k, f in enumerate((L.s, L.v, L.a, L.j)):
        ref = Pm.polyval(u, Pm.polyder(c, k))
        np.testing.assert_allclose(f(u), ref, atol=1e-9 * max(1, np.abs(ref).max()))
    lo, hi = L.s_range
    assert lo <= Pm.polyval(u, c).min() + 1e-12 and hi >= Pm.polyval(u, c).max() - 1e-12


def test_vectorised_shapes():
    L = law("modified_sine")
    u = np.linspace(0, 1, 12).reshape(3, 4)
    for f in (L.s, L.v, L.a, L.j):
        assert f(u).shape == (3, 4)
    assert np.ndim(L.s(0.5)) == 0
    B = law("bezier7")
    assert B.j(u).shape == (3, 4)


def test_polynomial_law_equals_poly345():
    u = np.linspace(0, 1, 33)
    a, b = law("polynomial", coefficients=[0, 0, 0, 10, -15, 6]), law("poly345")
    for k in range(4):
        np.testing.assert_allclose(a.derivative(u, k), b.derivative(u, k), atol=1e-12)


def test_unknown_law_lists_valid_names():
    with pytest.raises(InputError) as e:
        law("sinusoid")
    msg = str(e.value)
    assert "sinusoid" in msg and "cycloidal" in msg and "modified_trapezoid" in msg
    assert isinstance(e.value, ValueError)


@pytest.mark.parametrize("kwargs,word", [
    ({"control_points": [0.1, 0.5, 1]}, "control_points[0]"),
    ({"control_points": [0, 0.5, 0.9]}, "control_points[-1]"),
    ({"control_points": [0]}, "control_points"),
    ({"control_points": [0, np.nan, 1]}, "control_points"),
    ({}, "control_points"),
])
def test_bad_bezier(kwargs, word):
    with pytest.raises(InputError, match=word.replace("[", r"\[").replace("]", r"\]")):
        law("bezier", **kwargs)


def test_bad_params_and_u():
    with pytest.raises(InputError, match="takes no parameters"):
        law("cycloidal", h=1)
    with pytest.raises(InputError, match="sum"):
        law("polynomial", coefficients=[0, 1, 1])
    with pytest.raises(InputError, match=r"u = 1\.5"):
        law("shm").s(1.5)
    with pytest.raises(InputError, match="u"):
        law("shm").s([0.2, np.inf])


def test_junction_flags_from_end_values():
    assert law("uniform_velocity").v_end_nonzero
    assert not law("shm").v_end_nonzero and law("shm").a_end_nonzero
    assert not law("cycloidal").v_end_nonzero and not law("cycloidal").a_end_nonzero


def test_plot_laws_writes_png(tmp_path):
    pytest.importorskip("matplotlib")
    from femcam.viz.analytic import LAWS_FIGURE, plot_laws

    path = plot_laws(tmp_path / "laws.png")
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and path.stat().st_size > 10_000
    assert set(LAWS_FIGURE) <= set(LAW_NAMES)
