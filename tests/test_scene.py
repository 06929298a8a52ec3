"""femcam.scene: the shipped example scenes against the seed papers' closed forms, and clear
errors for bad scene files."""

import math
from pathlib import Path

import numpy as np
import pytest

from femcam.errors import SceneError, UndercutError
from femcam.scene import load_scene

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
SEED002 = EXAMPLES / "seed002_study_model.toml"

# Seed 002 eqs. 12-14: b(u)/L as power-series coefficients (u^0 ... u^9), typed from the paper
BEZIER = {
    "bezier5": [0, 0, 0, 10, -15, 6],
    "bezier7": [0, 0, 0, 0, 35, -84, 70, -20],
    "bezier9": [0, 0, 0, 0, 0, 126, -420, 540, -315, 70],
}


def seed002_phi_max_deg(law, beta_deg, L=0.010, Ro=0.020):
    """Seed 002 eq. 24, phi = atan(s'/(s + Ro)), on the rise (the fall mirrors it), with numpy's
    polynomial class on eqs. 12-14; independent of femcam.kinematics and femcam.profile."""
    P = np.polynomial.Polynomial(BEZIER[law])
    u = np.linspace(0.0, 1.0, 200001)
    beta = math.radians(beta_deg)
    s, s1 = L * P(u), L * P.deriv()(u) / beta
    return math.degrees(np.max(np.arctan(s1 / (s + Ro))))


def test_seed002_scene_matches_table1():
    sc = load_scene(SEED002)
    assert sc.omega == pytest.approx(20 * math.pi, rel=1e-12)  # 600 rpm
    assert sc.follower.Rb + sc.follower.Rr == pytest.approx(0.020)  # prime circle Ro
    assert sc.follower.Rr == pytest.approx(0.010) and sc.length == pytest.approx(0.010)
    assert sc.dynamics.c == pytest.approx(0.06 * 2 * math.sqrt(800 * 0.2))
    assert sc.program.h_max == pytest.approx(0.010)
    betas = [math.degrees(s.beta) for s in sc.program.segments]
    assert sum(betas) == pytest.approx(360.0) and betas[0] == betas[2]


def test_seed002_beta_is_smallest_whole_degree_with_phi_le_30():
    sc = load_scene(SEED002)
    beta = round(math.degrees(sc.program.segments[0].beta))
    worst = max(seed002_phi_max_deg(n, beta) for n in BEZIER)
    worst_minus_1 = max(seed002_phi_max_deg(n, beta - 1) for n in BEZIER)
    assert worst <= 30.0 < worst_minus_1, (beta, worst, worst_minus_1)
    th = np.radians(np.arange(0.0, 360.0, 0.01))
    for n in BEZIER:  # femcam's chain agrees with eq. 24 evaluated independently
        st = sc.with_law(n).analyse(th)
        assert math.degrees(np.max(np.abs(st.phi))) == pytest.approx(seed002_phi_max_deg(n, beta),
                                                                       abs=2e-3)


def test_seed002_contact_force_eq11_by_hand():
    sc = load_scene(SEED002)
    # at the start of the rise: s = v = 0; bezier5 (3-4-5) has a = 0 there too -> Fc = Fpl
    st = sc.analyse(np.array([0.0, math.radians(50.0)]))
    assert st.Fc[0] == pytest.approx(1500.0, rel=1e-12)
    # mid-rise, u = 1/2: s = L/2, s' = 1.875 L/beta, s'' = 0 (3-4-5)
    beta, L, w = math.radians(100), 0.01, 20 * math.pi
    s, v = L / 2, 1.875 * L / beta * w
    phi = math.atan(1.875 * L / beta / (s + 0.02))
    c = 0.06 * 2 * math.sqrt(800 * 0.2)
    assert st.Fc[1] == pytest.approx((c * v + 800 * s + 1500) / math.cos(phi), rel=1e-9)
    assert not st.liftoff.any()


def seed003_exact_phi_max_deg(Rb=0.005, h=0.003):
    """tan phi = |s'|/(Rb + s) on seed 003's 3-4-5 rise (120 deg) and fall (90 deg; s = h - h L),
    maximised over u with scipy's bounded Brent search; independent of femcam."""
    from scipy.optimize import minimize_scalar

    P = np.polynomial.Polynomial([0, 0, 0, 10, -15, 6])
    best = 0.0
    for beta_deg, falling in ((120.0, False), (90.0, True)):
        beta = math.radians(beta_deg)

        def neg(u, beta=beta, falling=falling):
            s = h - h * P(u) if falling else h * P(u)
            return -math.atan(h * P.deriv()(u) / beta / (Rb + s))

        r = minimize_scalar(neg, bounds=(0, 1), method="bounded", options={"xatol": 1e-12})
        best = max(best, -r.fun)
    return math.degrees(best)


def test_seed003_scene_pressure_angle():
    sc = load_scene(EXAMPLES / "seed003_knife_edge.toml")
    st = sc.analyse(np.radians(np.arange(0, 360, 0.01)))
    femcam_deg = math.degrees(np.max(np.abs(st.phi)))
    exact = seed003_exact_phi_max_deg()  # 29.4366 deg, on the fall
    assert exact == pytest.approx(29.4366, abs=1e-4)
    assert femcam_deg == pytest.approx(exact, abs=1e-3)
    assert femcam_deg < 30.0
    # documented discrepancy (docs/profile.md): seed 003 reports 29.3619 deg from its
    # FE-approximated curve; femcam's exact profile is 0.0747 deg higher (exact - paper, by hand)
    assert femcam_deg - 29.3619 == pytest.approx(0.0747, abs=5e-4)


def test_seed000_scene_rise():
    sc = load_scene(EXAMPLES / "seed000_rise.toml")
    th = np.radians(np.linspace(0, 180, 181))
    st = sc.analyse(th)
    u = th / math.pi
    # seed 000 cycloidal: y = h (u - sin(2 pi u)/(2 pi)), v = h w / beta (1 - cos 2 pi u)
    np.testing.assert_allclose(st.s, 0.01 * (u - np.sin(2 * np.pi * u) / (2 * np.pi)), atol=1e-15)
    np.testing.assert_allclose(st.v, 0.01 / np.pi * (1 - np.cos(2 * np.pi * u)), atol=1e-15)
    # constant load L = 500 N (preload), seen through the pressure angle
    np.testing.assert_allclose(st.Fc * np.cos(st.phi), 500.0, rtol=1e-5)
    assert sc.cam.hardness == pytest.approx(2000e6) and sc.wear.K == pytest.approx(1e-8)


def test_liftoff_weak_spring_high_speed(tmp_path):
    text = SEED002.read_text().replace("rpm = 600.0", "rpm = 3000.0").replace(
        "preload_N = 1500.0", "preload_N = 10.0")
    p = tmp_path / "fast.toml"
    p.write_text(text)
    sc = load_scene(p)
    th = np.radians(np.arange(0, 360, 0.1))
    st = sc.analyse(th)
    # independent: axial force m a + c v + k s + Fpl from the 3-4-5 polynomial by hand
    beta, L, w = math.radians(100), 0.01, 100 * math.pi
    u = th[th < beta] / beta
    a = L * (60 * u - 180 * u**2 + 120 * u**3) * w**2 / beta**2
    v = L * (30 * u**2 - 60 * u**3 + 30 * u**4) * w / beta
    s = L * (10 * u**3 - 15 * u**4 + 6 * u**5)
    F = 0.2 * a + sc.dynamics.c * v + 800 * s + 10.0
    np.testing.assert_array_equal(st.liftoff[th < beta], F <= 0)
    assert st.liftoff.any() and st.loads.liftoff_intervals


def test_undercut_reported_when_analysed(tmp_path):
    text = SEED002.read_text().replace("roller_radius_mm = 10.0", "roller_radius_mm = 30.0")
    text = text.replace("beta_deg = 100.0", "beta_deg = 40.0").replace("beta_deg = 80.0", "beta_deg = 140.0")
    p = tmp_path / "undercut.toml"
    p.write_text(text)
    sc = load_scene(p)  # loads fine: undercut is a property of the analysed profile
    with pytest.raises(UndercutError, match="deg"):
        sc.analyse(np.radians(np.arange(0, 360, 0.5)))
    st = sc.analyse(np.radians(np.arange(0, 360, 0.5)), allow_undercut=True)
    assert st.undercut.any()


def _bad(tmp_path, old, new):
    text = SEED002.read_text()
    assert old in text
    p = tmp_path / "bad.toml"
    p.write_text(text.replace(old, new, 1))
    with pytest.raises(SceneError) as info:
        load_scene(p)
    return str(info.value)


@pytest.mark.parametrize("old,new,expect", [
    ("beta_deg = 80.0", "beta = 80.0",
     ["program.segment[1].beta", "80.0", "unknown key", "beta_deg", "deg"]),
    ("beta_deg = 100.0", "beta_deg = -100.0", ["program.segment[0].beta_deg", "-100.0 deg", "> 0"]),
    ("mass_kg = 0.2", "mass_kg = -0.2", ["dynamics.mass_kg", "-0.2 kg", ">= 0"]),
    ("nu = 0.3", "nu = 0.7", ["materials.cam.nu", "0.7", "(-1, 0.5)"]),
    ("base_radius_mm = 10.0", "base_radius_mm = 0.0", ["follower.base_radius_mm", "0.0 mm", "> 0"]),
    ("rpm = 600.0", 'rpm = "600"', ["operating.rpm", "'600'", "number", "rpm"]),
    ('law = "bezier5"', 'law = "bezier11"', ["program.law", "bezier11", "unknown motion law"]),
    ('type = "roller"', 'type = "rollr"', ["follower.type", "rollr", "'roller'"]),
    ("lift_mm = 10.0", "lift_mm = 12.0", ["program.segment", "start lift"]),
    ("beta_deg = 80.0", "beta_deg = 81.0", ["program.segment", "360"]),
    ("face_width_mm = 10.0", "face_width = 10.0",
     ["follower.face_width = 10.0: unknown", "face_width_mm", "mm", "follower.face_width_mm: missing"]),
    ("damping_ratio = 0.06", "damping_ratio = 0.06\ndamping_N_s_per_m = 1.0", ["exactly one"]),
    ("offset_mm = 0.0", "offset_mm = 25.0", ["follower.offset_mm", "25", "20 mm"]),
])
def test_scene_errors_name_key_value_unit(tmp_path, old, new, expect):
    msg = _bad(tmp_path, old, new)
    for e in expect:
        assert e in msg, f"{e!r} not in {msg!r}"


def test_scene_errors_are_collected_and_file_errors(tmp_path):
    msg = _bad(tmp_path, "mass_kg = 0.2", "mass_kg = -0.2\nspring = 3")
    assert "2 problems" in msg and "dynamics.spring = 3" in msg
    with pytest.raises(SceneError, match="not found"):
        load_scene(tmp_path / "nope.toml")
    p = tmp_path / "broken.toml"
    p.write_text("name = \n")
    with pytest.raises(SceneError, match="not valid TOML"):
        load_scene(p)


# --- unknown tables, closure errors next to other problems, damping ratio ---------------------
def test_unknown_table_is_named_with_nearest_table(tmp_path):
    msg = _bad(tmp_path, "[contact]", "[contactt]")
    assert "unknown table [contactt]" in msg and "did you mean [contact]?" in msg
    assert "valid keys: name, description, source" not in msg
    msg = _bad(tmp_path, "[contact]", "[zzz]")
    assert "unknown table [zzz]" in msg and "[operating]" in msg  # lists the valid tables


def test_closure_error_reported_with_other_problems(tmp_path):
    # sum of beta = 361 deg AND a negative mass AND an unknown law: all three are listed
    text = SEED002.read_text()
    text = text.replace("beta_deg = 80.0", "beta_deg = 81.0", 1).replace("mass_kg = 0.2", "mass_kg = -0.2")
    text = text.replace('law = "bezier5"', 'law = "bezier11"')
    p = tmp_path / "bad.toml"
    p.write_text(text)
    with pytest.raises(SceneError) as info:
        load_scene(p)
    msg = str(info.value)
    assert "3 problems" in msg
    assert "dynamics.mass_kg = -0.2 kg" in msg and "bezier11" in msg
    assert "program.segment: sum(beta)" in msg and "off by +1 deg" in msg


@pytest.mark.parametrize("old,new,what", [("spring_N_per_m = 800.0", "spring_N_per_m = 0.0", "0 N/m"),
                                          ("mass_kg = 0.2", "mass_kg = 0.0", "0 kg")])
def test_damping_ratio_needs_critical_damping(tmp_path, old, new, what):
    msg = _bad(tmp_path, old, new)
    assert "dynamics.damping_ratio = 0.06" in msg and "c_c = 2 sqrt(k m)" in msg
    assert what in msg and "= 0 N s/m" in msg and "damping_N_s_per_m (N s/m)" in msg


# --- undercut in a band narrower than the analysis step -------------------------------------
def narrow_undercut_scene(tmp_path):
    """Seed 002's cam (3-4-5 = bezier5, L = 10 mm, beta = 100 deg) with Rb = 2.5 mm under a 20 mm
    roller: the pitch curve's tightest radius is just below Rr near 76 deg and 204 deg."""
    text = SEED002.read_text().replace("roller_radius_mm = 10.0", "roller_radius_mm = 20.0")
    text = text.replace("base_radius_mm = 10.0", "base_radius_mm = 2.5")
    p = tmp_path / "narrow.toml"
    p.write_text(text)
    return p


def undercut_band_deg(Rb=0.0025, Rr=0.020, L=0.010, beta_deg=100.0):
    """Undercut band of the rise by hand: 3-4-5 rise, in-line roller, polar curvature of the pitch
    curve r = Rb + Rr + s; undercut where Rr kappa_p >= 1 (a 0.001-deg grid)."""
    P = np.polynomial.Polynomial([0, 0, 0, 10, -15, 6])
    beta = math.radians(beta_deg)
    th = np.radians(np.arange(0.0, beta_deg, 0.001))
    u = th / beta
    r, r1, r2 = Rb + Rr + L * P(u), L * P.deriv()(u) / beta, L * P.deriv(2)(u) / beta**2
    kappa = (r**2 + 2 * r1**2 - r * r2) / (r**2 + r1**2) ** 1.5
    bad = np.degrees(th[Rr * kappa >= 1.0])
    return float(bad.min()), float(bad.max())


def test_narrow_undercut_found_between_coarse_angles(tmp_path):
    a, b = undercut_band_deg()
    assert 0.5 < b - a < 5.0 and math.floor(b / 10) * 10 < a  # band lies strictly between 70 and 80
    sc = load_scene(narrow_undercut_scene(tmp_path))
    coarse = np.radians(np.arange(0.0, 360.0, 10.0))
    with pytest.raises(UndercutError, match="dense check") as info:
        sc.analyse(coarse)
    assert "deg" in str(info.value)
    st = sc.analyse(coarse, allow_undercut=True)
    assert not st.undercut.any()  # the 10-deg grid itself sees nothing
    iv = [(math.degrees(p), math.degrees(q)) for p, q in st.undercut_intervals]
    assert len(iv) == 2  # one band on the rise, one on the fall
    # endpoints agree with the hand band to the 0.05-deg dense step
    assert iv[0][0] == pytest.approx(a, abs=0.06) and iv[0][1] == pytest.approx(b, abs=0.06)
    # the fall (180 -> 280 deg) is the rise (0 -> 100 deg) mirrored: theta -> 280 - theta
    assert iv[1][0] == pytest.approx(280.0 - b, abs=0.06) and iv[1][1] == pytest.approx(280.0 - a, abs=0.06)


def test_unphysical_modulus_in_scene_is_one_scene_error(tmp_path):
    msg = _bad(tmp_path, "E_GPa = 210.0", "E_GPa = 1e30")
    assert "materials.cam.E_GPa = 1e+30 GPa: must be in [0.0001, 2000] GPa" in msg, msg


def test_python_m_femcam_import_runs_nothing():
    import importlib
    import sys

    sys.modules.pop("femcam.__main__", None)
    mod = importlib.import_module("femcam.__main__")  # used to call sys.exit(main()) on import
    assert callable(mod.main)
