"""femcam.assess and `femcam assess`: the seed 002 assessment against hand calculations written in
the test, the flat-faced film collapse, knife-edge, huge loads, FE input and bad input."""

import json
import math
import re

import numpy as np
import pytest

from femcam.assess import assess, assess_rows
from femcam.cli import main
from femcam.errors import InputError, SceneError
from femcam.io import read_meta
from femcam.scene import contact_case, load_scene
from femcam.scene.digest import physics_parts
from femcam.viz.html import png_data_uri

EXAMPLE = "examples/seed002_assess.toml"
OMEGA = 20 * math.pi                         # 600 rpm


def _scene(tmp_path, edit=None, name="s.toml"):
    text = open(EXAMPLE).read()
    if edit:
        text = edit(text)
    p = tmp_path / name
    p.write_text(text)
    return load_scene(p)


def _astm_d341_eta(T_C, nu40=46.0, nu100=6.8, rho=861.0):
    """Walther / ASTM D341 written out: loglog(nu + 0.7) linear in log T (nu in mm^2/s, T in K)."""
    y = [math.log10(math.log10(v + 0.7)) for v in (nu40, nu100)]
    x = [math.log10(T) for T in (313.15, 373.15)]
    yT = y[0] + (y[1] - y[0]) * (math.log10(T_C + 273.15) - x[0]) / (x[1] - x[0])
    return rho * (10 ** 10**yT - 0.7) * 1e-6


def test_seed002_base_circle_by_hand(tmp_path):
    """On the base-circle dwell (300 deg): Fc = preload 1500 N, R = Rb Rr/(Rb + Rr) = 5 mm,
    u_cam = omega Rb, the roller at SRR 0.02, entrainment U = (u1 + u2)/2 (the mean, as in the speed
    parameter of Stolarski 1990 §6.7); film by the Pan-Hamrock 1989 formula typed here with
    ASTM D341 viscosity at 70 C; flash temperature by AGMA 925's form (K = 0.80, 2 %); surface
    fatigue by ISO 6336 (sigma_Hlim / p0, Z_NT slope 13.2)."""
    sc = load_scene(EXAMPLE)
    r = assess_rows(contact_case(sc, np.radians([300.0])))
    E_star = 210e9 / (2 * (1 - 0.3**2))
    w, R = 1500.0 / 0.01, 0.005
    a = math.sqrt(4 * w * R / (math.pi * E_star))
    p0 = 2 * w / (math.pi * a)
    u1 = OMEGA * 0.010
    u2 = u1 * (2 - 0.02) / (2 + 0.02)
    U = 0.5 * (u1 + u2)
    eta = _astm_d341_eta(70.0)
    Ep = 2 * E_star
    h_min = R * 1.714 * (w / (Ep * R)) ** -0.128 * (eta * U / (Ep * R)) ** 0.694 * (2e-8 * Ep) ** 0.568
    sigma = math.sqrt(math.pi / 2) * math.hypot(0.2e-6, 0.1e-6)
    np.testing.assert_allclose([r["Fc"][0], r["R"][0], r["p0"][0]], [1500.0, R, p0], rtol=1e-9)
    np.testing.assert_allclose([r["u_cam"][0], r["U"][0]], [u1, U], rtol=1e-9)
    np.testing.assert_allclose(r["eta0"][0], eta, rtol=1e-9)
    np.testing.assert_allclose(r["h_min"][0], h_min, rtol=1e-9)
    np.testing.assert_allclose(r["lam"][0], h_min / sigma, rtol=1e-9)
    assert r["regime"][0] == "boundary"                      # lambda ~ 0.2 < 1
    beta = math.sqrt(46.6 * 7810.0 * 475.0)
    agma = 0.80 * 0.1 * w * (u1 - u2) / (math.sqrt(a) * beta * (math.sqrt(u1) + math.sqrt(u2)))
    assert abs(r["dT_flash"][0] / agma - 1) < 0.02
    np.testing.assert_allclose(r["T_contact"][0], 70.0 + r["dT_flash"][0], rtol=1e-12)
    np.testing.assert_allclose(r["sf_surface_fatigue"][0], 1500e6 / p0, rtol=1e-9)
    np.testing.assert_allclose(r["N_pitting"][0], 5e7 * (1500e6 / p0) ** (math.log(500) / math.log(1.6)),
                               rtol=1e-9)
    np.testing.assert_allclose(r["p0_over_k"][0], p0 / 850e6, rtol=1e-9)   # Tresca k = Y/2


def test_seed002_assessment_summary():
    res = assess(contact_case(load_scene(EXAMPLE)))
    assert set(res.worst) >= {"film (lambda)", "contact temperature", "shakedown", "surface fatigue"}
    assert res.notes == ()
    lam = res.rows["lam"]
    assert res.worst["film (lambda)"][0] == pytest.approx(float(np.min(lam)))
    # the Pe < 5 angles are flagged, never silent
    pe = np.minimum(res.rows["Pe_cam"], res.rows["Pe_follower"])
    flagged = np.array(["low_peclet" in f for f in res.rows["flags"]])
    np.testing.assert_array_equal(flagged, pe < 5.0)


FLAT = """
[follower]
type = "flat_faced"
base_radius_mm = 20.0
face_width_mm = 10.0
"""


def _flat(text):
    text = re.sub(r"\[follower\].*?face_width_mm = 10.0\n", FLAT, text, flags=re.S)
    return text.replace('law = "bezier5"', 'law = "cycloidal"')


def test_flat_faced_entrainment_reverses_and_film_collapses(tmp_path):
    """Flat face: u_cam = omega (Rb + s + s''), u_face = omega s'' (Norton 2009 ch. 7), so
    U = omega (Rb + s + 2 s'')/2 changes sign near the nose of this cam: there h = 0, lambda = 0,
    flagged no_entrainment."""
    sc = _scene(tmp_path, _flat)
    theta = np.radians(np.arange(0, 360, 1.0))
    r = assess_rows(contact_case(sc, theta))
    d = sc.program.derivatives(theta)
    U = 0.5 * OMEGA * (0.020 + d.s + 2 * d.s2)
    np.testing.assert_allclose(r["U"], U, rtol=1e-9, atol=1e-12)
    neg = U <= 0
    assert neg.any() and (~neg).any()
    np.testing.assert_array_equal(r["h_min"][neg], 0.0)
    np.testing.assert_array_equal(r["lam"][neg], 0.0)
    assert all("no_entrainment" in f for f in r["flags"][neg])
    assert all(g == "boundary" for g in r["regime"][neg])
    assert np.all(r["h_min"][~neg] > 0)
    np.testing.assert_allclose(r["v_slide"], OMEGA * (0.020 + d.s), rtol=1e-9)   # omega (Rb + s)


KNIFE = """
[follower]
type = "knife_edge"
base_radius_mm = 20.0
face_width_mm = 10.0
"""


def test_knife_edge_needs_tip_radius_and_slides_fully(tmp_path):
    def knife(text):
        return re.sub(r"\[follower\].*?face_width_mm = 10.0\n", KNIFE, text, flags=re.S)

    with pytest.raises(InputError, match="tip_radius_mm"):
        assess_rows(contact_case(_scene(tmp_path, knife), np.radians([300.0])))
    sc = _scene(tmp_path, lambda t: knife(t).replace("face_width_mm = 10.0\n",
                                                     "face_width_mm = 10.0\ntip_radius_mm = 2.0\n"),
                "k.toml")
    r = assess_rows(contact_case(sc, np.radians([300.0])))             # base circle: v_slip = omega Rb
    np.testing.assert_allclose(r["v_slide"][0], OMEGA * 0.020, rtol=1e-9)
    np.testing.assert_allclose(r["R"][0], 0.020 * 0.002 / 0.022, rtol=1e-9)
    assert r["dT_flash"][0] > 0


def test_huge_load_is_computed_and_flagged(tmp_path):
    sc = _scene(tmp_path, lambda t: t.replace("preload_N = 1500.0", "preload_N = 3.0e6"))
    r = assess_rows(contact_case(sc, np.radians([300.0])))
    assert np.isfinite(r["h_min"][0]) and r["h_min"][0] > 0
    assert "W_range" in r["flags"][0] and "hertz_validity" in r["flags"][0]
    assert r["sf_yield"][0] < 1                              # and it yields, of course


def test_fe_table_replaces_hertz(tmp_path):
    sc = load_scene(EXAMPLE)
    theta = np.radians([0.0, 50.0, 300.0])
    h = assess_rows(contact_case(sc, theta))
    p_fe = np.array([h["p0"][0] / 1.1, np.nan, h["p0"][2] / 1.1])
    table = {"theta": theta, "a_fe": h["a"] * 1.1, "p0_fe": p_fe}
    table["a_fe"][1] = np.nan                                 # a failed FE angle keeps Hertz
    r = assess_rows(contact_case(sc, theta), table)
    assert list(r["source"]) == ["fe", "hertz", "fe"]
    p_used = np.where(np.isfinite(p_fe), p_fe, h["p0"])
    np.testing.assert_allclose(r["sf_surface_fatigue"], 1500e6 / p_used, rtol=1e-12)
    # FE stress maxima: first yield k / tau1_max (Tresca k = Y/2); the orthogonal shear range over
    # one pass is the FE subsurface txz_range_max, utilisation (dtau/2)/tau_e
    table.update(tau1_max=np.full(3, 500e6), txz_range_max=np.full(3, 400e6))
    r = assess_rows(contact_case(sc, theta), table)
    np.testing.assert_allclose(r["sf_yield"][[0, 2]], 850e6 / 500e6, rtol=1e-12)
    np.testing.assert_allclose(r["sf_subsurface"][[0, 2]], 350e6 / 200e6, rtol=1e-12)
    np.testing.assert_allclose(r["sf_yield"][1], h["sf_yield"][1], rtol=1e-12)   # Hertz where FE failed


def test_missing_lubricant_data_is_one_clear_error(tmp_path):
    def strip(text):
        text = text.split("\n[lubricant]")[0]
        return text.replace("oil_temperature_C = 70.0", "")

    with pytest.raises(SceneError) as e:
        assess_rows(contact_case(_scene(tmp_path, strip), np.radians([0.0])))
    msg = str(e.value)
    for key in ("[lubricant]", "[surface]", "oil_temperature_C", "pressure_viscosity_per_GPa"):
        assert key in msg, (key, msg)

    def partial(text):
        return text.replace('name = "ISO VG 46 mineral"', "viscosity_Pa_s = 0.02")

    with pytest.raises(SceneError) as e:
        assess_rows(contact_case(_scene(tmp_path, partial, "p.toml"), np.radians([0.0])))
    msg = str(e.value)
    for key in ("temperature_C (degC)", "viscosity_temperature_coefficient_per_K (1/K)",
                "lubricant.pressure_viscosity_per_GPa", "lubricant.density_kg_per_m3"):
        assert key in msg, (key, msg)
    # below absolute zero, and below any oil's pour point: refused at load (femcam.scene.ranges)
    with pytest.raises(SceneError, match=r"oil_temperature_C = -300 degC: must be in \[-60, 350\] degC"):
        _scene(tmp_path, lambda t: t.replace("oil_temperature_C = 70.0", "oil_temperature_C = -300"),
               "t.toml")
    with pytest.raises(SceneError, match="not a table oil"):
        assess_rows(contact_case(_scene(tmp_path, lambda t: t.replace("ISO VG 46 mineral", "SAE 5W-30"),
                                        "n.toml"), np.radians([0.0])))


def test_scene_keys_checked_with_units(tmp_path):
    with pytest.raises(SceneError, match=r"lubricant.viscosity = 0.02: unknown key; did you mean "
                                         r"'viscosity_Pa_s' in Pa s\? \(units go in the key name\)"):
        _scene(tmp_path, lambda t: t.replace('name = "ISO VG 46 mineral"',
                                             'name = "ISO VG 46 mineral"\nviscosity = 0.02'))
    with pytest.raises(SceneError, match=r"surface.cam_Ra_um = -0.2 um: must be >= 0"):
        _scene(tmp_path, lambda t: t.replace("cam_Ra_um = 0.2", "cam_Ra_um = -0.2"), "r.toml")
    with pytest.raises(SceneError, match=r"materials.cam.yield_strength_MPa = 0 MPa: must be > 0"):
        _scene(tmp_path, lambda t: t.replace("yield_strength_MPa = 1700.0", "yield_strength_MPa = 0", 1),
               "y.toml")


def test_missing_material_data_skips_criteria_and_says_so(tmp_path):
    sc = _scene(tmp_path, lambda t: t.replace("shear_fatigue_limit_MPa = 350.0", ""))
    res = assess(contact_case(sc, np.radians(np.arange(0, 360, 10.0))))
    need = "subsurface fatigue: skipped, needs [materials.cam] shear_fatigue_limit_MPa"
    assert any(need in n for n in res.notes), res.notes
    assert np.all(np.isnan(res.rows["sf_subsurface"]))
    assert "subsurface fatigue" not in res.worst


def test_cli_assess_writes_csv_summary_report(tmp_path):
    out = tmp_path / "a"
    assert main(["assess", EXAMPLE, "--out", str(out), "--angles-deg", "0:360:5", "--no-plots"]) == 0
    head = (out / "assessment.csv").read_text().splitlines()
    names = head[0].split(",")
    for col in ("theta_deg", "h_min_um", "lambda", "dT_flash_K", "T_contact_C", "sf_shakedown", "regime",
                "flags"):
        assert col in names
    assert read_meta(out / "assessment.csv")["dc:title"].startswith("femcam assess")
    data = np.genfromtxt(out / "assessment.csv", delimiter=",", names=True, dtype=None,
                         encoding="utf-8")
    assert data.size == 72
    assert "Worst angle per criterion" in (out / "report.md").read_text()
    page = (out / "report.html").read_text()               # the same report as one page
    assert "<h2>Worst angle per criterion</h2>" in page and "<img" not in page


@pytest.mark.slow
def test_cli_assess_plots(tmp_path):
    out = tmp_path / "a"
    assert main(["assess", EXAMPLE, "--out", str(out), "--angles-deg", "0:360:5"]) == 0
    assert "plots/assess_lambda.png" in (out / "report.md").read_text()
    page = (out / "report.html").read_text()               # every plot embedded in the page
    for png in (out / "plots").glob("*.png"):
        assert png_data_uri(png) in page, png.name
    for png in ("assess_lambda", "assess_temperature", "assess_safety", "assess_outline"):
        assert (out / "plots" / f"{png}.png").stat().st_size > 1000


def test_cli_assess_bad_input_exit_code(tmp_path, capsys):
    assert main(["assess", "examples/seed002_study_model.toml", "--out", str(tmp_path / "b")]) == 1
    assert "[lubricant]: missing table" in capsys.readouterr().err


def test_wear_map_uses_k_of_lambda_and_says_the_regime(tmp_path):
    """The lubricated wear map scales k angle by angle by F_5/2(lambda)/F_5/2(0) (Greenwood & Tripp
    1970, by quadrature here); the same scene without [lubricant] keeps the dry k."""
    from scipy.integrate import quad

    from femcam.assess import wear_factor
    from femcam.wear.scene import scene_wear

    theta = np.radians(np.arange(0, 360, 2.0))
    wet = load_scene(EXAMPLE)
    dry = _scene(tmp_path, lambda t: t.split("\n[lubricant]")[0])
    k_factor, regime = wear_factor(contact_case(wet, theta))
    assert wear_factor(contact_case(dry, theta)) == (None, None)
    wm_wet, _, _ = scene_wear(contact_case(wet, theta), cycles=1.0, k_factor=k_factor, regime=regime)
    wm_dry, _, _ = scene_wear(contact_case(dry, theta), cycles=1.0)
    assert wm_dry.regime is None and wm_dry.k_factor is None
    lam = assess_rows(contact_case(wet, theta))["lam"]

    def F(x):
        return quad(lambda s: (s - x) ** 2.5 * math.exp(-s * s / 2), x, np.inf)[0]

    ratio = np.array([F(x) / F(0.0) for x in lam])
    np.testing.assert_allclose(wm_wet.depth_pass, wm_dry.depth_pass * ratio, rtol=1e-7)
    assert wm_wet.summary()["regime_angles"] == {"boundary": 180}


def test_cli_assess_from_a_sweep_npz_and_bad_angles(tmp_path, capsys):
    """--sweep takes the angles and FE a/p0 of a sweep's sweep.npz (written here by hand)."""
    sc = load_scene(EXAMPLE)
    theta = np.radians(np.arange(0.0, 360.0, 30.0))
    h = assess_rows(contact_case(sc, theta))
    sw = tmp_path / "sw"
    sw.mkdir()
    prov = {"scene_physics_parts": physics_parts(sc)}   # the scene the sweep records (its check)
    np.savez(sw / "sweep.npz", theta=theta, a_fe=h["a"] * 1.01, p0_fe=h["p0"] / 1.01,
             provenance_json=np.array(json.dumps(prov)))
    out = tmp_path / "o"
    assert main(["assess", EXAMPLE, "--out", str(out), "--sweep", str(sw), "--no-plots"]) == 0
    data = np.genfromtxt(out / "assessment.csv", delimiter=",", names=True, comments="#", dtype=None,
                         encoding="utf-8")
    np.testing.assert_allclose(data["p0_MPa"], h["p0"] / 1.01 * 1e-6, rtol=1e-7)
    assert set(data["source"]) == {"fe"}
    assert main(["assess", EXAMPLE, "--out", str(out), "--angles-deg", "0:360"]) == 1
    assert "start:stop:step" in capsys.readouterr().err
    assert main(["assess", EXAMPLE, "--out", str(out), "--sweep", str(tmp_path / "none")]) == 1
    assert "no sweep.npz" in capsys.readouterr().err


def test_inertia_roller_model_on_a_sweep_chunk(tmp_path):
    """The inertia-limited roller needs a whole revolution; on a chunk of angles the speeds are
    those of the whole-revolution solution (interpolated, exact at its 0.5 deg grid points)."""
    sc = _scene(tmp_path, lambda t: t + '\n[wear]\nroller_model = "inertia"\n')
    full = assess_rows(contact_case(sc, np.radians(np.arange(0.0, 360.0, 0.5))))
    chunk = assess_rows(contact_case(sc, np.radians([10.0, 74.0, 200.5])))
    idx = [20, 148, 401]
    np.testing.assert_allclose(chunk["u_follower"], full["u_follower"][idx], rtol=1e-12)
    np.testing.assert_allclose(chunk["lam"], full["lam"][idx], rtol=1e-12)
    # seed 002 at 600 rpm: friction always accelerates the roller (no slip), so zero sliding and
    # exactly zero flash temperature (Blok: dT ~ |u1 - u2|)
    np.testing.assert_allclose(full["v_slide"], 0.0, atol=1e-12)
    np.testing.assert_array_equal(full["dT_flash"], 0.0)


def test_dry_assessment_of_a_scene_without_tribology_data():
    """lubricated=False on seed 002's study model (no lubricant, no material extras): no film,
    every criterion skipped with the keys that would enable it, dry k everywhere."""
    res = assess(contact_case(load_scene("examples/seed002_study_model.toml"),
                              np.radians(np.arange(0, 360, 30.0))), lubricated=False)
    r = res.rows
    assert set(r["regime"]) == {"dry"} and np.all(np.isnan(r["lam"]))
    assert np.all(np.isnan(r["sf_shakedown"])) and np.all(np.isnan(r["dT_flash"]))
    assert len(res.notes) == 5 and any("yield_strength_MPa" in n for n in res.notes)
    np.testing.assert_allclose(r["k_wear"], 1e-8 / 2000e6)          # seed 000's K / H (m^3/(N m))
    assert set(res.worst) == set()
