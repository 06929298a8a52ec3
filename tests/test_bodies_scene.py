"""Scene keys of the real bodies and the sweep-facing ring_rows (femcam.bodies.rows)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from femcam.bodies import RingMeshOptions
from femcam.bodies.rows import CSV_COLUMNS, build_for, ring_rows, to_csv_columns
from femcam.errors import SceneError
from femcam.mesh import MeshOptions
from femcam.scene import load_scene

EXAMPLE = Path(__file__).resolve().parent.parent / "examples" / "seed002_needle_roller.toml"


def _write(tmp_path, old, new):
    text = EXAMPLE.read_text()
    assert old in text
    p = tmp_path / "s.toml"
    p.write_text(text.replace(old, new, 1))
    return p


def test_example_scene_states_a_fitting_needle_roller():
    sc = load_scene(EXAMPLE)
    g = sc.bodies.roller
    assert g.support == "needles" and g.Z == 18 and sc.bodies.cam is None
    # the stated geometry: Ri = Rp + 2 r_n + c, and 18 needles fit on the pitch circle
    assert math.isclose(g.Rp + 2 * g.r_n + g.c, g.Ri, rel_tol=1e-12)
    assert 2 * (g.Ri - g.r_n) * math.sin(math.pi / 18) > 2 * g.r_n
    assert g.pin.name == "100Cr6"


def test_solid_roller_default_has_no_bodies():
    sc = load_scene(EXAMPLE.parent / "seed002_study_model.toml")
    assert sc.bodies.roller is None and sc.bodies.cam is None


def test_all_bad_body_keys_are_reported_in_one_scene_error(tmp_path):
    p = _write(tmp_path, "needle_count = 18 ", "needle_count = 40 ")
    text = p.read_text().replace('pin_radius_mm = 4.99 ', 'pin_radius_mm = 4.5 ')
    text = text.replace("[contact]", "[cam]\nbore_mm = 12.0\n\n[contact]")
    p.write_text(text)
    with pytest.raises(SceneError) as e:
        load_scene(p)
    msg = str(e.value)
    assert "3 problems" in msg
    assert "needle_count = 40 needles of radius 1 mm do not fit" in msg and "at most 18 fit" in msg
    assert "= 6.51 mm: must equal roller_bore_mm = 7 mm" in msg
    assert "cam.bore_mm = 12.0 mm: the shaft bore radius must be < base_radius_mm = 10 mm" in msg


@pytest.mark.parametrize("old, new, expect", [
    ('roller_support = "needles"', 'roller_support = "balls"',
     "follower.roller_support = 'balls': must be one of 'solid', 'pin', 'needles'"),
    ("roller_bore_mm = 7.0 ", "roller_bore_mm = 12.0 ",
     "roller_bore_mm = 12 mm: must be in (0, roller_radius_mm = 10 mm)"),
    ("pin_clearance_um = 10.0 ", "pin_clearance_um = -1.0 ",
     "follower.pin_clearance_um = -1.0 um: must be >= 0"),
    ("needle_radius_mm = 1.0 ", "",
     "follower.needle_radius_mm: missing: required with roller_support = 'needles'"),
    ('roller_support = "needles"', 'roller_support = "solid"',
     "follower.roller_bore_mm = 7.0: not used with roller_support = 'solid'"),
    ("needle_count = 18 ", "needle_count = 2.5 ", "needle_count = 2.5: must be a whole number >= 3"),
])
def test_bad_body_keys_name_key_value_unit(tmp_path, old, new, expect):
    with pytest.raises(SceneError, match=None) as e:
        load_scene(_write(tmp_path, old, new))
    assert expect in str(e.value)


def test_ring_rows_columns_units_and_liftoff():
    """Coarse model, three angles (one lift-off). The solid-roller columns are Hertz (Johnson 1985
    eq. 4.45) written here; the 3 mm wall keeps the cam contact within 2 % of the solid roller
    (the ring effect on p0 is measured at -0.07 %, docs/bodies.md)."""
    sc = load_scene(EXAMPLE)
    theta = np.radians([0.0, 60.0, 200.0])
    st = sc.analyse(theta)
    Fc = st.Fc.copy()
    Fc[2] = 0.0
    m = build_for(sc.bodies.roller, sc.pair, Fc, st.rho, mesh=MeshOptions(a_over_h=8),
                  ring_mesh=RingMeshOptions(n_bore=72))
    rows = ring_rows(sc.bodies.roller, sc.pair, theta, Fc, st.rho, model=m)
    assert set(rows) == set(CSV_COLUMNS) | {"needle_loads_on", "needle_loads_between"}
    assert np.all(np.isnan([rows[k][2] for k in CSV_COLUMNS if k != "theta"]))
    # the distributions balance the cam force along the load line (statics, Stribeck geometry)
    Z = 18
    for key, cage in (("needle_loads_on", 0.0), ("needle_loads_between", math.pi / Z)):
        psi = cage + 2 * math.pi * np.arange(Z) / Z
        np.testing.assert_allclose(rows[key][:2] @ np.cos(psi), Fc[:2], rtol=1e-9)
    E_star = 1 / (2 * (1 - 0.3**2) / 210e9)
    for i in (0, 1):
        R = 1 / (1 / 0.01 + 1 / st.rho[i])
        a = math.sqrt(4 * Fc[i] / 0.01 * R / (math.pi * E_star))
        np.testing.assert_allclose(rows["a_solid"][i], a, rtol=1e-9, err_msg="Hertz a (solid roller)")
        np.testing.assert_allclose(rows["p0"][i], 2 * Fc[i] / 0.01 / (math.pi * a), rtol=0.02)
        assert rows["needle_Q_on"][i] > rows["needle_Q_between"][i] > Fc[i] / 18
    csv = to_csv_columns(rows)
    assert "bore_hoop_max_MPa" in csv and "needle_Qmax_on_N" in csv and "theta_deg" in csv
    np.testing.assert_allclose(csv["theta_deg"], [0.0, 60.0, 200.0])
