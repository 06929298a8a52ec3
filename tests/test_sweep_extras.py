"""Wiring of the extra column providers (femcam.sweep.extras) into the sweep.

These are wiring tests: the sweep CSV must hold each provider's columns with the values of the
provider's own function called directly at the same angles (the physics of each provider is
validated in its package's tests: test_assess, test_halfspace, test_bodies_*, test_layers). The
CSV writes 10 significant digits, hence ``rtol = 1e-9`` against the direct call. The wear column
of a finite-length scene is checked against Archard's per-pass closed form written here.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from femcam.assess import COLUMNS as ASSESS_COLUMNS
from femcam.assess import assess_rows, worst_angles
from femcam.bodies.rows import CSV_COLUMNS as RING_COLUMNS
from femcam.bodies.rows import build_for, ring_rows
from femcam.errors import InputError
from femcam.halfspace.rows import COLUMNS as HS_COLUMNS
from femcam.halfspace.rows import anchor_angles, finite_length_rows
from femcam.io import read_csv
from femcam.layers import scene_layer_rows
from femcam.scene import contact_case, finite_case, load_scene
from femcam.sweep import RunOptions, SweepOptions, extras, providers, sweep
from femcam.sweep.chunk import ChunkRows
from femcam.wear.options import wear_coefficient_info

EX = "examples/"
TH8 = np.radians(np.arange(0.0, 360.0, 45.0))   # coarse: 0, 45, ..., 315 deg
RTOL = 1e-9                                        # CSV: 10 significant digits


def _sweep_csv(scene, theta, tmp_path, **kw):
    kw = {"method": "hertz", "plots": False, "vtk_every": 0, **kw}
    r = sweep(scene, SweepOptions(angles=theta, **kw), RunOptions(out=tmp_path, workers=1))
    cols, _ = read_csv(r.paths["csv"])
    return r, cols


def _close(csv_values, direct, factor=1.0):
    np.testing.assert_allclose(csv_values, np.asarray(direct, float) * factor, rtol=RTOL, atol=0.0,
                               equal_nan=True)


# ---------------------------------------------------------------------------------------------
def test_which_providers_apply_to_the_examples():
    names = {f: [p.name for p in extras.providers_for(load_scene(EX + f + ".toml"))]
             for f in ("seed002_study_model", "seed002_assess", "seed002_crowned",
                       "seed002_needle_roller", "seed002_coated")}
    assert names == {"seed002_study_model": [], "seed002_assess": ["assess"],
                     "seed002_crowned": ["halfspace"], "seed002_needle_roller": ["bodies"],
                     "seed002_coated": ["layers"]}


def test_plain_scene_has_no_extra_columns(tmp_path):
    scene = load_scene(EX + "seed002_study_model.toml")
    r, cols = _sweep_csv(scene, TH8, tmp_path)
    assert extras.extra_columns(scene) == ((), ())
    assert "extras_error" not in cols and "lambda" not in cols
    assert r.provenance["extras"] == {"providers": []}


def test_assess_columns_equal_direct_call(tmp_path):
    scene = load_scene(EX + "seed002_assess.toml")
    r, cols = _sweep_csv(scene, TH8, tmp_path, chunk_size=3)
    direct = assess_rows(contact_case(scene, TH8))    # method hertz: no FE a/p0, Hertz as the direct call
    for si, csv, f in ((c.si, c.csv, c.factor) for c in ASSESS_COLUMNS):
        if si in ("theta", "Fc"):
            continue
        name = csv if csv not in ("a_um", "p0_MPa") else "assess_" + csv
        _close(cols[name], direct[si], f)
    assert list(cols["assess_regime"]) == [str(v) for v in direct["regime"]]
    assert list(cols["assess_flags"]) == [str(v) for v in direct["flags"]]
    assert set(cols["assess_source"]) == {"hertz"}
    # the worst-angle summary in the provenance and the summary is assess's own
    worst = worst_angles(direct)
    prov = r.provenance["extras"]["assess"]
    assert set(prov) == set(worst)
    for crit, (v, t, _) in worst.items():
        assert prov[crit]["value"] == pytest.approx(v, rel=1e-12)
        assert prov[crit]["theta_deg"] == pytest.approx(math.degrees(t), abs=1e-9)
    assert r.summary()["extras"]["providers"] == ["assess"]
    _, header = read_csv(r.paths["csv"])
    assert '"providers": ["assess"]' in header["extras"]      # the CSV header says which ran
    report = open(r.paths["report"]).read()                    # and report.md, with the worst angles
    lam = worst["film (lambda)"]
    assert "Extra columns from: assess." in report
    assert f"| film (lambda) | {lam[0]:.4g} | {math.degrees(lam[1]):.1f} |" in report


@pytest.mark.slow
def test_assess_uses_fe_contact_of_the_sweep(tmp_path):
    scene = load_scene(EX + "seed002_assess.toml")
    th = np.radians([0.0, 130.0])
    r, cols = _sweep_csv(scene, th, tmp_path, method="fe")
    direct = assess_rows(contact_case(scene, th), table=r.table)
    _close(cols["assess_p0_MPa"], direct["p0"], 1e-6)
    _close(cols["assess_p0_MPa"], cols["p0_fe_MPa"])        # FE p0 replaces Hertz where finite
    _close(cols["sf_yield"], direct["sf_yield"])
    assert set(cols["assess_source"]) == {"fe"}


# ---------------------------------------------------------------------------------------------
@pytest.mark.slow  # ~1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_halfspace_columns_and_axial_peak_wear(tmp_path):
    scene = load_scene(EX + "seed002_crowned.toml")
    r, cols = _sweep_csv(scene, TH8, tmp_path)
    # every angle warm-started from its anchor angle, as the direct call with start="anchor"
    st, an = scene.analyse(TH8), scene.analyse(anchor_angles(TH8))
    direct = finite_length_rows(finite_case(scene).strip(), TH8, st.Fc, st.rho, scene.follower.Rr,
                                start="anchor", anchor_Fc=an.Fc, anchor_rho=an.rho)
    for k, c in HS_COLUMNS.items():
        _close(cols[c.csv], direct[k], c.factor)
    assert list(cols["hs_flags"]) == [";".join(f) for f in direct["flags"]]
    # Archard per pass at the most loaded slice: h = k w_max v_slip / V_cam (independent form)
    k = wear_coefficient_info(scene.wear, scene.cam.hardness)[0]
    ok = cols["status"] == "ok"
    h_ref = k * direct["w_max"] * cols["v_slip_m_s"] / cols["V_cam_m_s"]
    np.testing.assert_allclose(cols["wear_depth_per_rev_nm"][ok], h_ref[ok] * 1e9, rtol=1e-8)
    assert set(cols["wear_source"][ok]) == {"axial_peak"}
    assert "halfspace" in r.provenance["extras"]["providers"]


def test_assessment_of_a_finite_length_scene_uses_the_axial_peak(tmp_path):
    lub = load_scene(EX + "seed002_assess.toml")
    crowned = load_scene(EX + "seed002_crowned.toml")
    scene = dataclasses.replace(lub, finite_length=crowned.finite_length)
    th = TH8[:4]
    _, cols = _sweep_csv(scene, th, tmp_path)
    ok = cols["status"] == "ok"
    np.testing.assert_allclose(cols["assess_p0_MPa"][ok], cols["p_axial_peak_MPa"][ok], rtol=RTOL)
    # a from w_max: pi a p0 / 2 = w_max (N/mm = 1e3 N/m; a in um, p0 in MPa)
    w = math.pi * cols["assess_a_um"] * 1e-6 * cols["assess_p0_MPa"] * 1e6 / 2.0
    np.testing.assert_allclose(w[ok], cols["w_max_N_per_mm"][ok] * 1e3, rtol=1e-8)
    assert set(cols["assess_source"][ok]) == {"axial_peak"}


# ---------------------------------------------------------------------------------------------
@pytest.mark.slow
def test_needle_roller_sweep_writes_ring_results(tmp_path):
    scene = load_scene(EX + "seed002_needle_roller.toml")
    th = np.radians([0.0, 130.0, 230.0])
    r, cols = _sweep_csv(scene, th, tmp_path)
    grid = np.linspace(0.0, 2.0 * math.pi, 720, endpoint=False)
    g = scene.analyse(grid)
    model = build_for(scene.bodies.roller, scene.pair, np.where(g.Fc > 0, g.Fc, np.nan),
                      g.rho)   # graded as the provider says
    st = scene.analyse(th)
    direct = ring_rows(scene.bodies.roller, scene.pair, th, st.Fc, st.rho, model=model)
    side = {c.csv for c in providers.RING}
    for k, c in RING_COLUMNS.items():
        csv = c.csv
        if csv in side:
            _close(cols[csv], direct[k], c.factor)
        elif k != "theta":   # the ring's cam contact is no side column: it answers the headline
            assert csv not in cols, csv
    # the headline: the peak of the ring's solved pressure, the fitted ellipse, model ...+ring
    _close(cols["p0_fe_MPa"], direct["p0_peak"], 1e-6)
    _close(cols["p0_fit_MPa"], direct["p0"], 1e-6)
    _close(cols["a_fe_um"], direct["a"], 1e6)
    assert all(m.endswith("+ring") for m in cols["model"][cols["status"] == "ok"])
    assert np.all(np.isfinite(cols["bore_hoop_max_MPa"])) and np.all(cols["needle_Qmax_on_N"] > 0)
    assert r.provenance["extras"]["bodies"]["bore_hoop_max_MPa"] == pytest.approx(
        np.nanmax(direct["hoop_max"]) * 1e-6, rel=1e-12)


def test_ring_model_is_built_once_per_process():
    scene = load_scene(EX + "seed002_needle_roller.toml")
    calls = []
    providers._CACHE.pop(("ring", repr(scene)), None)
    orig = providers.build_for
    try:
        providers.build_for = lambda *a, **k: calls.append(1) or object()
        m1, m2 = providers.ring_model(scene), providers.ring_model(scene)
    finally:
        providers.build_for = orig
        providers._CACHE.pop(("ring", repr(scene)), None)
    assert m1 is m2 and calls == [1]


# ---------------------------------------------------------------------------------------------
@pytest.mark.slow
def test_layer_columns_equal_direct_call(tmp_path):
    scene = load_scene(EX + "seed002_coated.toml")
    th = np.radians([0.0, 130.0])
    r, cols = _sweep_csv(scene, th, tmp_path)
    st = scene.analyse(th)
    direct = scene_layer_rows(scene.layers, scene.pair, scene.follower, th, st.Fc, st.rho, a_over_h=10.0)
    # method hertz: no FE solve answered the rows, so the layer columns come from the layered
    # model of each angle (method fe takes them from the headline solve: tests/test_sweep_coated.py)
    assert set(cols["layer_source"]) == {"layer_model"}
    for csv in (c.csv for c in providers.LAYERS):
        _close(cols[csv], direct[csv])
    assert r.provenance["extras"]["layers"]["case_margin_min"] == pytest.approx(
        np.nanmin(direct["case_margin"]), rel=1e-12)


# ---------------------------------------------------------------------------------------------
def test_refused_provider_gives_nan_columns_and_the_reason(tmp_path, monkeypatch):
    def refuse(task, rows):
        raise InputError("viscosity = -1 Pa s: must be > 0")

    p = extras.PROVIDERS[1]
    assert p.name == "assess"
    monkeypatch.setattr(extras, "PROVIDERS", (dataclasses.replace(p, compute=refuse),))
    scene = load_scene(EX + "seed002_assess.toml")
    r, cols = _sweep_csv(scene, TH8[:3], tmp_path)
    assert np.all(np.isnan(cols["lambda"]))
    assert set(cols["extras_error"]) == {"assess: InputError: viscosity = -1 Pa s: must be > 0"}
    assert np.all(cols["status"] == "ok")           # the contact sweep went on
    assert r.provenance["extras"]["errors"] == ["assess: InputError: viscosity = -1 Pa s: must be > 0"]


def test_resume_keeps_the_extra_columns(tmp_path):
    scene = load_scene(EX + "seed002_assess.toml")
    opts = SweepOptions(angles=TH8, method="hertz", chunk_size=3, plots=False, vtk_every=0)
    r1 = sweep(scene, opts, RunOptions(workers=1, out=tmp_path))
    r2 = sweep(scene, opts, RunOptions(workers=1, out=tmp_path, resume=True))
    assert r2.n_chunks_resumed == 3 and r2.n_chunks_computed == 0
    for name in ("assess_lam", "assess_sf_yield", "assess_regime", "extras_error"):
        assert name in r2.table
        if r1.table[name].dtype.kind == "f":
            np.testing.assert_array_equal(r2.table[name], r1.table[name])
        else:
            assert list(r2.table[name]) == list(r1.table[name])
    with np.load(r2.paths["npz"]) as z:
        np.testing.assert_array_equal(z["assess_lam"], r1.table["assess_lam"])
    from femcam.sweep.result import SweepResult
    r3 = SweepResult.load(tmp_path)           # the extra columns come back with the table
    np.testing.assert_array_equal(r3.table["assess_lam"], r1.table["assess_lam"])
    assert list(r3.table["assess_regime"]) == list(r1.table["assess_regime"])


@pytest.mark.slow
def test_fe_answers_at_the_most_loaded_slice(tmp_path):
    """method fe on a crowned roller: the 2D FE is solved again at F = w_max * length; its p0 is
    the 2D Hertz p0 at that load per unit length (Johnson 1985 eq. 4.45) within 1 % (the sweep's
    mean-load FE p0 is within 0.2 % of Hertz at a_over_h = 10 in this run; 1 % bounds the FE
    discretisation error at the larger load, where the family model may be rebuilt)."""
    scene = load_scene(EX + "seed002_crowned.toml")
    th = np.radians([0.0, 230.0])
    _, cols = _sweep_csv(scene, th, tmp_path, method="fe")
    w = cols["w_max_N_per_mm"] * 1e3
    np.testing.assert_allclose(cols["F_peak_slice_N"], w * scene.length, rtol=RTOL)
    R = 1.0 / (1.0 / (cols["rho_mm"] * 1e-3) + 1.0 / scene.follower.Rr)
    E_star = 1.0 / (2.0 * (1.0 - 0.3**2) / 210e9)             # plane strain, steel on steel
    p0_ref = np.sqrt(w * E_star / (math.pi * R))
    np.testing.assert_allclose(cols["p0_peak_slice_MPa"] * 1e6, p0_ref, rtol=1e-2)
    assert list(cols["fe_load_basis"]) == ["w_max*length"] * 2
    # the mean-load FE columns are untouched: still the Hertz load Fc / length
    p0_mean = np.sqrt(cols["Fc_N"] / scene.length * E_star / (math.pi * R))
    np.testing.assert_allclose(cols["p0_fe_MPa"] * 1e6, p0_mean, rtol=1e-2)


# ---------------------------------------------------------------------------------------------
# coating wear coefficient (femcam.wear.coating)
# ---------------------------------------------------------------------------------------------
COAT = """
[materials.{body}.coating]
thickness_um = {t}
E_GPa = 170.0
nu = 0.22
{wear}
"""


def _coated_scene(tmp_path, body="cam", t=2.0, wear="wear_k_mm3_per_N_m = 1e-8"):
    text = open(EX + "seed002_study_model.toml").read() + COAT.format(body=body, t=t, wear=wear)
    p = tmp_path / f"coated_{body}.toml"
    p.write_text(text)
    return load_scene(p)


@pytest.mark.parametrize("wear, msg", [
    ("wear_K = 1e-8", "materials.cam.coating.wear_K"),
    ("wear_K = 1e-8\nwear_k_mm3_per_N_m = 1e-8\nhardness_MPa = 9000.0", "not both"),
    ("wear_k_mm3_per_N_m = -1e-8", "materials.cam.coating.wear_k_mm3_per_N_m"),
])
def test_coating_wear_keys_bad_input(tmp_path, wear, msg):
    from femcam.errors import SceneError
    with pytest.raises(SceneError, match=msg):
        _coated_scene(tmp_path, wear=wear)


def _layered(d_c, d_s, t, N):
    """Hand form: N d_c until N d_c = t, then the substrate rate (written out per point)."""
    out = []
    for dc, ds in zip(d_c, d_s, strict=True):
        out.append(N * dc if N * dc <= t else t + (N - t / dc) * ds)
    return np.array(out)


def _coating(scene):
    """The scene's coating wear data (its layers, [wear] settings and cam hardness)."""
    from femcam.wear.coating import coating_wear

    return coating_wear(scene.layers, scene.wear, scene.cam.hardness)


def test_wear_map_uses_the_coating_k_until_worn_through(tmp_path):
    from femcam.wear.scene import scene_wear
    bare = load_scene(EX + "seed002_study_model.toml")
    scene = _coated_scene(tmp_path, t=2.0, wear="wear_K = 1e-9\nhardness_MPa = 18000.0")
    k_s = wear_coefficient_info(bare.wear, bare.cam.hardness)[0]
    k_c = 1e-9 / 18000e6                      # K / H, m^3/(N m)
    th = np.radians(np.arange(0.0, 360.0, 1.0))
    ref, _, _ = scene_wear(contact_case(bare, th), cycles=1.0, coating=_coating(bare))
    d_s = ref.depth_cam                       # m per revolution with the substrate k
    d_c = d_s * k_c / k_s
    N_t = 2e-6 / d_c.max()                    # revolutions to wear through at the deepest point
    N = 2e-6 / np.median(d_c)                 # half the points worn through, half not
    wm, _, _ = scene_wear(contact_case(scene, th), cycles=N, coating=_coating(scene))
    h_ref = _layered(d_c, d_s, 2e-6, N)
    np.testing.assert_allclose(wm.depth_cam_total, h_ref, rtol=1e-12, atol=1e-18)
    assert wm.max_depth == pytest.approx(2e-6 + (N - N_t) * d_s.max(), rel=1e-12)
    assert wm.coating["revolutions_through"] == pytest.approx(N_t, rel=1e-12)
    assert np.any(h_ref < 2e-6)               # the hard case: both branches are exercised
    # the roller keeps the substrate k (the coating is on the cam)
    ref_n, _, _ = scene_wear(contact_case(bare, th), cycles=N, coating=_coating(bare))
    np.testing.assert_allclose(wm.depth_follower_total, ref_n.depth_follower_total, rtol=1e-12)


def test_wear_map_coated_roller_uses_the_drift_averaged_rate(tmp_path):
    from femcam.wear.scene import scene_wear
    bare = load_scene(EX + "seed002_study_model.toml")
    scene = _coated_scene(tmp_path, body="roller", t=1.0, wear="wear_k_mm3_per_N_m = 1e-8")
    k_s = wear_coefficient_info(bare.wear, bare.cam.hardness)[0]
    th = np.radians(np.arange(0.0, 360.0, 1.0))
    N = 1e9
    ref, _, _ = scene_wear(contact_case(bare, th), cycles=N, coating=_coating(bare))
    d_s = ref.depth_follower_total / N
    d_c = d_s * 1e-17 / k_s
    wm, _, _ = scene_wear(contact_case(scene, th), cycles=N, coating=_coating(scene))
    np.testing.assert_allclose(wm.depth_follower_total, _layered(d_c, d_s, 1e-6, N), rtol=1e-12,
                               atol=1e-18)
    assert wm.coating["revolutions_through"] == pytest.approx(1e-6 / d_c.max(), rel=1e-12)
    np.testing.assert_allclose(wm.depth_cam_total, ref.depth_cam_total, rtol=1e-12)


def test_sweep_wear_column_uses_the_coating_k(tmp_path, monkeypatch):
    # only the coating-wear provider (the layers provider's FE checks are tested above, slow)
    monkeypatch.setattr(extras, "PROVIDERS", tuple(p for p in extras.PROVIDERS if p.name == "coating_wear"))
    bare = load_scene(EX + "seed002_study_model.toml")
    scene = _coated_scene(tmp_path, t=2.0, wear="wear_k_mm3_per_N_m = 1e-8")
    ratio = 1e-17 / wear_coefficient_info(bare.wear, bare.cam.hardness)[0]
    r0 = sweep(bare, SweepOptions(angles=TH8, method="hertz"), RunOptions(workers=1))
    r, cols = _sweep_csv(scene, TH8, tmp_path / "out")
    ok = cols["status"] == "ok"
    np.testing.assert_allclose(cols["wear_depth_per_rev_nm"][ok], r0.table["wear_depth"][ok] * ratio * 1e9,
                               rtol=RTOL)
    assert set(cols["wear_source"][ok]) == {"hertz;coating"}
    rec = r.provenance["extras"]["coating_wear"]
    assert rec["revolutions_through"] == pytest.approx(2e-6 / (r0.table["wear_depth"][ok].max() * ratio),
                                                       rel=1e-12)


@pytest.mark.slow  # over 1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_plots_of_the_extra_columns(tmp_path):
    scene = load_scene(EX + "seed002_assess.toml")
    r = sweep(scene,
              SweepOptions(angles=TH8, method="hertz", plots=True, vtk_every=0),
              RunOptions(workers=1, out=tmp_path))
    p = r.paths["plot_extras_assess"]
    assert p.endswith("extras_assess.png")
    with open(p, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"


@pytest.mark.slow
def test_extra_columns_parallel_equal_serial():
    """Worker processes compute the providers in their own process (models per process): the
    table equals the serial one."""
    scene = dataclasses.replace(load_scene(EX + "seed002_assess.toml"),
                                finite_length=load_scene(EX + "seed002_crowned.toml").finite_length)
    th = TH8
    r1 = sweep(scene, SweepOptions(angles=th, method="hertz", chunk_size=2), RunOptions(workers=1))
    r2 = sweep(scene, SweepOptions(angles=th, method="hertz", chunk_size=2), RunOptions(workers=2))
    cols, text = extras.extra_columns(scene)
    for c in cols:   # the same arithmetic in another process: equal to rounding
        np.testing.assert_allclose(r2.table[c.si], r1.table[c.si], rtol=1e-12, equal_nan=True)
    for t in text:
        assert list(r2.table[t]) == list(r1.table[t])


def test_undercut_rows_are_left_out_of_the_providers():
    """An undercut row (the roller does not fit the concave cam) has no contact solution: the
    assessment is NaN there and the other rows equal the direct call at their angles."""
    import types
    scene = load_scene(EX + "seed002_assess.toml")
    r = sweep(scene, SweepOptions(angles=TH8[:4], method="hertz"), RunOptions(workers=1))
    rows = ChunkRows.from_arrays({k: np.array(v, dtype=object if v.dtype.kind in "US" else float)
                                  for k, v in r.table.items()})
    rows.status[1] = "undercut"
    task = types.SimpleNamespace(scene=scene, theta=TH8[:4])
    out = providers.assess_chunk(task, rows)
    keep = np.array([0, 2, 3])
    direct = assess_rows(contact_case(scene, TH8[:4][keep]))
    assert np.isnan(out["assess_lam"][1]) and out["assess_regime"][1] == ""
    np.testing.assert_allclose(out["assess_lam"][keep], direct["lam"], rtol=1e-12)
