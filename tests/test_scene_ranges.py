"""Stated ranges of the scene keys, the cross-key limits, the whole-cam pressure-angle check and
the scene reference page (issue 29: item 7 and the scene-key faults of the independent campaign).

References: each "silently accepted" case of the campaign is typed in below with the key its
refusal must name; the pressure angle of a short cycloidal rise is the closed form of seed 002
eq. 24 (Norton 2009 eq. 8.31 with e = 0), ``tan phi = s' / (Ro + s)``, evaluated here.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from femcam.cli import main
from femcam.errors import InputError, SceneError, UndercutError
from femcam.mesh.build import build_contact_mesh
from femcam.scene import load_scene
from femcam.scene.ranges import reference_table
from femcam.scene.schema import _CHOICES, TABLES

ROOT = Path(__file__).resolve().parents[1]
EX = ROOT / "examples"


def _edit(tmp_path, example: str, old: str, new: str, name: str = "s.toml") -> Path:
    text = (EX / example).read_text(encoding="utf-8")
    assert old in text, (example, old)
    p = tmp_path / name
    p.write_text(text.replace(old, new, 1), encoding="utf-8")
    return p


# the campaign's silently accepted scene cases: (example, old text, new text, key the refusal names)
CAMPAIGN = [
    ("seed002_assess.toml", "oil_temperature_C = 70.0", "oil_temperature_C = 1e30",
     "operating.oil_temperature_C"),
    ("seed002_assess.toml", "oil_temperature_C = 70.0", "oil_temperature_C = 5000.0",
     "operating.oil_temperature_C"),
    ("flat_faced.toml", "face_length_mm = 30.0", "face_length_mm = 1e30", "follower.face_length_mm"),
    ("seed002_crowned.toml", "roller_width_mm = 10.0", "roller_width_mm = 1e30", "follower.roller_width_mm"),
    ("seed002_crowned.toml", 'crown = "logarithmic"', 'crown = "circular"\ncrown_drop_um = 1e30',
     "follower.crown_drop_um"),
    ("seed002_crowned.toml", 'crown = "logarithmic"', 'crown = "circular"\ncrown_drop_um = 1e6',  # 1 m
     "follower.crown_drop_um"),
    ("seed002_crowned.toml", 'crown = "logarithmic"', 'crown = "circular"\ncrown_drop_um = 600.0',  # > 5 % Rr
     "follower.crown_drop_um"),
    ("seed002_crowned.toml", 'crown = "logarithmic"', 'crown = "circular"\ncrown_radius_mm = 1e30',
     "follower.crown_radius_mm"),
    ("seed002_crowned.toml", "[cam]\nface_width_mm = 12.0", "[cam]\nface_width_mm = 1e30",
     "cam.face_width_mm"),
    ("seed002_assess.toml", "hardness_MPa = 7000.0", "hardness_MPa = 1e30", "materials.cam.hardness_MPa"),
    ("seed002_assess.toml", "yield_strength_MPa = 1700.0", "yield_strength_MPa = 1e30",
     "materials.cam.yield_strength_MPa"),
    ("seed002_assess.toml", "thermal_conductivity_W_per_m_K = 46.6", "thermal_conductivity_W_per_m_K = 1e30",
     "materials.cam.thermal_conductivity_W_per_m_K"),
    ("seed002_assess.toml", "density_kg_per_m3 = 7810.0", "density_kg_per_m3 = 1e-9",
     "materials.cam.density_kg_per_m3"),
    ("seed002_assess.toml", "contact_fatigue_strength_MPa = 1500.0", "contact_fatigue_strength_MPa = 1e30",
     "materials.cam.contact_fatigue_strength_MPa"),
    ("seed002_assess.toml", "contact_fatigue_strength_MPa = 1500.0",
     "contact_fatigue_strength_MPa = 1500.0\ncontact_fatigue_cycles = 0.5",
     "materials.cam.contact_fatigue_cycles"),
    ("seed002_assess.toml", "contact_fatigue_strength_MPa = 1500.0",
     "contact_fatigue_strength_MPa = 1500.0\ncontact_fatigue_exponent = 1e30",
     "materials.cam.contact_fatigue_exponent"),
    ("seed002_assess.toml", "scuffing_temperature_C = 150.0", "scuffing_temperature_C = 1e30",
     "materials.cam.scuffing_temperature_C"),
    ("seed002_assess.toml", "scuffing_temperature_C = 150.0", "scuffing_temperature_C = -300.0",
     "materials.cam.scuffing_temperature_C"),
    ("seed002_assess.toml", "cam_Ra_um = 0.2", "cam_Ra_um = 1e6", "surface.cam_Ra_um"),  # 1 m
    ("seed002_coated.toml", "thickness_um = 2.5", "thickness_um = 1e30",
     "materials.roller.coating.thickness_um"),
    ("seed002_coated.toml", "thickness_um = 2.5", "thickness_um = 10000.0",  # = the roller radius
     "materials.roller.coating.thickness_um"),
    ("seed002_coated.toml", "thickness_um = 2.5",
     "thickness_um = 900.0",  # < 1000 um but 9 % of Rr... accepted
     None),
    ("seed002_coated.toml", "E_GPa = 170.0", "E_GPa = 1e-6", "materials.roller.coating.E_GPa"),
    ("seed002_coated.toml", "E_GPa = 170.0", "E_GPa = 1e6", "materials.roller.coating.E_GPa"),
    ("seed002_coated.toml", "interface_shear_strength_MPa = 250.0", "interface_shear_strength_MPa = 1e30",
     "materials.roller.coating.interface_shear_strength_MPa"),
    ("seed002_coated.toml", "depth_mm = 0.3", "depth_mm = 1e30", "materials.cam.case.depth_mm"),
    ("seed002_coated.toml", "depth_mm = 0.3", "depth_mm = 15.0", "materials.cam.case.depth_mm"),  # Rb = 10 mm
    ("seed002_coated.toml", "surface_hardness_HV = 700.0", "surface_hardness_HV = 320.0",  # core 300 HV
     "materials.cam.case.surface_hardness_HV"),
    ("seed002_dynamic.toml", "train_stiffness_N_per_m = 2.0e6", "train_stiffness_N_per_m = 1e30",
     "dynamics.train_stiffness_N_per_m"),
    ("seed002_study_model.toml", "spring_N_per_m = 800.0", "spring_N_per_m = 1e30",
     "dynamics.spring_N_per_m"),
    ("seed002_study_model.toml", "preload_N = 1500.0", "preload_N = 1e30", "dynamics.preload_N"),
    ("seed002_needle_roller.toml", "pin_clearance_um = 10.0", "pin_clearance_um = 400.0",  # > 0.05 x 7 mm
     "follower.pin_clearance_um"),
    ("seed002_study_model.toml", "friction = 0.1", "friction = 5.0", "contact.friction"),
    ("seed002_study_model.toml", "lift_mm = 10.0", "lift_mm = 10000.0", "program.segment[0].lift_mm"),
    ("seed003_knife_edge.toml", "tip_radius_mm = 2.0", 'tip_radius_mm = 2.0\nroller_support = "pin"',
     "follower.roller_support"),
    ("seed002_crowned.toml", "misalignment_deg = 0.02", "misalignment_deg = 5.0",
     "follower.misalignment_deg"),
]


@pytest.mark.parametrize("example, old, new, key", CAMPAIGN,
                         ids=[f"{c[3]}={c[2].split('= ')[-1]}" for c in CAMPAIGN])
def test_campaign_nonsense_is_refused_naming_the_key(tmp_path, example, old, new, key):
    p = _edit(tmp_path, example, old, new)
    if key is None:  # inside every range and cross-key limit: accepted
        load_scene(p)
        return
    with pytest.raises(SceneError) as ei:
        load_scene(p)
    assert key in str(ei.value), str(ei.value)


def test_case_step_is_the_layers_criterion():
    from femcam.layers.case import DELTA_H, HV
    from femcam.scene.cross import CASE_STEP_HV
    assert CASE_STEP_HV * HV == DELTA_H


def test_misalignment_bound_is_in_degrees(tmp_path):
    # 5 deg = 0.087 rad passed the old [-0.1, 0.1] bound that was in radians
    p = _edit(tmp_path, "seed002_crowned.toml", "misalignment_deg = 0.02", "misalignment_deg = 5.0")
    with pytest.raises(SceneError, match=r"follower.misalignment_deg = 5.0 deg: must be in \[-1, 1\] deg"):
        load_scene(p)


def test_steps_per_rev_cap_states_the_memory(tmp_path):
    p = _edit(tmp_path, "seed002_dynamic.toml", 'model = "one_dof"', 'model = "one_dof"\nsteps_per_rev = 1e9')
    with pytest.raises(SceneError) as ei:
        load_scene(p)
    msg = str(ei.value)
    # 1e9 steps at ~400 bytes a step (femcam.scene.ranges.STEP_BYTES, measured) = 4e11 bytes
    assert "dynamics.steps_per_rev = 1000000000.0" in msg and "about 400 GB of memory" in msg, msg


def test_damping_in_n_s_per_m_is_checked_against_critical(tmp_path):
    # c_c = 2 sqrt(k_t m) = 2 sqrt(2e6 N/m * 0.2 kg) = 1265 N s/m; 1e6 N s/m is 791 x that
    p = _edit(tmp_path, "seed002_dynamic.toml", "train_damping_ratio = 0.05", "train_damping_N_s_per_m = 1e6")
    with pytest.raises(SceneError, match=r"dynamics.train_damping_N_s_per_m = 1000000.0 N s/m: must be "
                       r"<= 10 x the critical damping .* = 1265 N s/m"):
        load_scene(p)


@pytest.mark.parametrize("example, old, new, key", [
    ("seed002_study_model.toml", "base_radius_mm = 10.0", "base_radius_mm = 1e30", "follower.base_radius_mm"),
    ("seed002_study_model.toml", "face_width_mm = 10.0", "face_width_mm = 1e30", "follower.face_width_mm"),
    ("seed003_knife_edge.toml", "tip_radius_mm = 2.0", "tip_radius_mm = 1e30", "follower.tip_radius_mm"),
    ("seed002_dynamic.toml", 'model = "one_dof"', 'model = "one_dof"\nsteps_per_rev = 1e30',
     "dynamics.steps_per_rev"),
    ("seed002_dynamic.toml", "train_damping_ratio = 0.05", "train_damping_N_s_per_m = 1e30",
     "dynamics.train_damping_N_s_per_m"),
    ("seed002_dynamic.toml", "train_damping_ratio = 0.05",
     'train_damping_ratio = 0.05\nsecond_mass_kg = 0.1\nsecond_stiffness_N_per_m = 1e6\n'
     'second_damping_ratio = 1e30',
     "dynamics.second_damping_ratio"),
    ("seed002_dynamic.toml", "train_damping_ratio = 0.05",
     'train_damping_ratio = 0.05\nsecond_mass_kg = 0.1\nsecond_stiffness_N_per_m = 1e6\n'
     'second_damping_N_s_per_m = 1e30', "dynamics.second_damping_N_s_per_m"),
])
def test_former_tracebacks_are_one_scene_error_on_the_cli(tmp_path, capsys, example, old, new, key):
    # gmsh messages and Python tracebacks before: now the scene check answers first
    text = (EX / example).read_text(encoding="utf-8").replace(old, new, 1)
    text = text.replace('model = "one_dof"', 'model = "two_dof"') if "second_" in new else text
    p = tmp_path / "s.toml"
    p.write_text(text, encoding="utf-8")
    assert main(["run", str(p), "--out", str(tmp_path / "o")]) == 1
    err = capsys.readouterr().err
    assert "Traceback" not in err and key in err and "1e+30" in err, err


def test_lubricant_temperature_overflow_is_a_range_error(tmp_path):
    p = _edit(tmp_path, "seed002_assess.toml", 'name = "ISO VG 46 mineral"',
              "viscosity_Pa_s = 0.02\ntemperature_C = 1e30\nviscosity_temperature_coefficient_per_K = 0.03\n"
              "pressure_viscosity_per_GPa = 20.0\ndensity_kg_per_m3 = 861.0")
    with pytest.raises(SceneError, match=r"lubricant.temperature_C = 1e\+30 degC: must be in "
                       r"\[-60, 350\] degC"):
        load_scene(p)


# ---- item 7: the undercut / pressure-angle check sees every segment -------------------------
SHORT = {"beta_deg": 0.01, "lift_mm": 10.0}


def _short_rise(tmp_path) -> Path:
    text = (EX / "seed002_study_model.toml").read_text(encoding="utf-8")
    # program: rise 10 mm over 0.01 deg, dwell, fall over 180 deg, no final dwell
    prog = ('[program]\nlaw = "cycloidal"\n[[program.segment]]\nkind = "rise"\nbeta_deg = 0.01\n'
            'lift_mm = 10.0\n[[program.segment]]\nkind = "dwell"\nbeta_deg = 179.99\n'
            '[[program.segment]]\nkind = "fall"\nbeta_deg = 180.0\nlift_mm = 10.0\n\n')
    text = re.sub(r"\[program\].*?(?=\[follower\])", prog, text, flags=re.S)
    p = tmp_path / "short.toml"
    p.write_text(text, encoding="utf-8")
    return p


def test_short_rise_is_undercut_and_refused(tmp_path):
    sc = load_scene(_short_rise(tmp_path))
    with pytest.raises(UndercutError, match=r"theta in \[0\.00\d\d, 0\.0100\] deg.*257 in each segment"):
        sc.analyse(np.radians(np.arange(0.0, 360.0, 1.0)))  # inside the 0.01 deg rise, 4 decimals


def test_max_pressure_angle_of_a_short_rise_is_the_closed_form(tmp_path):
    sc = load_scene(_short_rise(tmp_path))
    Ro = sc.follower.Rb + sc.follower.Rr            # prime circle, 20 mm (e = 0)
    h, beta = 10e-3, math.radians(SHORT["beta_deg"])
    u = np.linspace(0.0, 1.0, 2_000_001)
    s = h * (u - np.sin(2 * np.pi * u) / (2 * np.pi))   # cycloidal rise
    s1 = h / beta * (1.0 - np.cos(2 * np.pi * u))
    phi_ref = np.max(np.arctan2(s1, Ro + s))           # seed 002 eq. 24
    phi, theta = sc.max_pressure_angle
    # both are the maximum of the same smooth function; the reference samples u every 5e-7
    # (error ~ phi'' du^2 / 8 < 1e-9 rad), femcam refines to xatol 1e-12 rad in theta
    assert phi == pytest.approx(phi_ref, abs=1e-8), (math.degrees(phi), math.degrees(phi_ref))
    assert math.degrees(phi) > 89.98                  # the old grid reported 14.5 deg at the analysed angles
    assert 0.0 <= theta <= beta


def test_max_pressure_angle_matches_seed003(tmp_path):
    # seed 003's exact 3-4-5 curve: max phi = 29.44 deg (examples/seed003_knife_edge.toml);
    # the grid-only value is within 0.01 deg of it, the refined one closer
    phi, _ = load_scene(EX / "seed003_knife_edge.toml").max_pressure_angle
    assert math.degrees(phi) == pytest.approx(29.44, abs=0.005)


def test_run_summary_prints_the_whole_cam_max_not_the_analysed_angles():
    from femcam.cli.run import summary_lines
    sc = load_scene(EX / "seed003_knife_edge.toml")
    st = sc.analyse(np.radians([0.0, 90.0, 180.0, 270.0]))  # coarse: miss the 29.44 deg peak
    line = next(ln for ln in summary_lines(sc, st) if ln.startswith("max |phi|"))
    assert np.degrees(np.max(np.abs(st.phi))) < 29.0 and "29.437 deg" in line and "whole cam" in line, line


def test_contact_too_wide_names_the_scene_keys():
    with pytest.raises(InputError) as ei:
        build_contact_mesh(Rr=0.01, rho=0.02, a_ref=0.005)
    msg = str(ei.value)
    for key in ("a_ref", "E_GPa", "roller_radius_mm", "face_width_mm", "preload_N"):
        assert key in msg, msg


# ---- the scene reference page ------------------------------------------------------------------
def test_scene_doc_holds_the_generated_key_table():
    doc = (ROOT / "docs" / "scene.md").read_text(encoding="utf-8")
    table = doc.split("<!-- scene-keys:start -->\n", 1)[1].split("<!-- scene-keys:end -->", 1)[0]
    assert table == reference_table(TABLES, _CHOICES), \
        "docs/scene.md's key table is not the one the schema generates; regenerate it (see docs/scene.md)"


def test_readme_points_to_the_scene_reference():
    assert "docs/scene.md" in (ROOT / "README.md").read_text(encoding="utf-8")


def test_rtol_on_accepts_the_err_est_stems_and_refuses_others(tmp_path):
    """``[fe] rtol_on``: a list of the err_est_* stems (femcam.scene.schema.RTOL_ON) loads as it
    is; a name outside it, a bare string and an empty list are refused naming the key and the
    accepted names."""
    text = (EX / "seed002_study_model.toml").read_text(encoding="utf-8")
    ok = tmp_path / "ok.toml"
    ok.write_text(text + '\n[fe]\nrtol_pct = 0.5\nrtol_on = ["p0", "tau1"]\n', encoding="utf-8")
    assert load_scene(ok).study.rtol_on == ("p0", "tau1")
    for bad in ('["p0", "tau2"]', '"p0"', "[]"):
        p = tmp_path / "bad.toml"
        p.write_text(text + f"\n[fe]\nrtol_on = {bad}\n", encoding="utf-8")
        with pytest.raises(SceneError) as ei:
            load_scene(p)
        assert "fe.rtol_on" in str(ei.value) and "'interface_tau'" in str(ei.value), str(ei.value)
