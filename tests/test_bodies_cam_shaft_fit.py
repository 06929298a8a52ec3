"""Scene keys of the cam's shaft fit: ``[cam] shaft_fit``, ``shaft_clearance_um`` (femcam.scene.bodies).

The references are the key values typed into the scenes here (Rs = bore - clearance in SI) and the
stated limits (clearance <= 0.05 x bore: the linearised shaft-bore gap; a bonded fit has no
clearance), each message naming the key, the value and the unit.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from femcam.bodies.cam_rows import disk_from_case
from femcam.errors import SceneError
from femcam.scene import cam_disk_case, load_scene

EXAMPLE = Path(__file__).resolve().parent.parent / "examples" / "seed002_cam_on_shaft.toml"
BORE = "bore_mm = 6.0 "


def _scene(tmp_path, cam_lines: str, bore: str = BORE):
    text = EXAMPLE.read_text()
    assert BORE in text
    p = tmp_path / "s.toml"
    p.write_text(text.replace(BORE, bore + "\n" + cam_lines + "\n", 1))
    return p


def test_default_fit_is_unilateral_contact_line_to_line(tmp_path):
    sc = load_scene(EXAMPLE)
    assert sc.bodies.cam.fit == "contact" and sc.bodies.cam.clearance == 0.0
    d = disk_from_case(cam_disk_case(sc))
    assert d.fit == "contact" and d.Rs == d.Rb == pytest.approx(6e-3, rel=1e-12)


def test_fit_and_clearance_reach_the_disk(tmp_path):
    d = disk_from_case(cam_disk_case(load_scene(_scene(tmp_path, "shaft_clearance_um = 20.0"))))
    assert d.fit == "contact"
    assert d.Rs == pytest.approx(6e-3 - 20e-6, rel=1e-12)   # shaft radius = bore - clearance
    assert d.c == pytest.approx(20e-6, rel=1e-9)
    d = disk_from_case(cam_disk_case(load_scene(_scene(tmp_path, 'shaft_fit = "bonded"\n'
                                                       'shaft_clearance_um = 0.0'))))
    assert d.fit == "bonded" and d.Rs == d.Rb


def test_all_bad_shaft_fit_keys_are_reported_in_one_scene_error(tmp_path):
    """A clearance above 0.05 x 6 mm = 300 um on a bonded fit: two problems, one error."""
    with pytest.raises(SceneError) as e:
        load_scene(_scene(tmp_path, 'shaft_fit = "bonded"\nshaft_clearance_um = 400.0'))
    msg = str(e.value)
    assert "2 problems" in msg
    assert "cam.shaft_clearance_um = 400 um: must be <= 0.05 x bore_mm (6 mm) = 300 um" in msg
    assert ("cam.shaft_fit = 'bonded' with shaft_clearance_um = 400 um: a bonded fit has no clearance"
            in msg)


@pytest.mark.parametrize("lines, bore, expect", [
    ('shaft_fit = "press"', BORE, "cam.shaft_fit = 'press': must be one of 'contact', 'bonded'"),
    ("shaft_clearance_um = -3.0", BORE, "cam.shaft_clearance_um = -3.0 um: must be >= 0"),
    ('shaft_clearance_mm = 0.01', BORE, "cam.shaft_clearance_mm = 0.01: unknown key; did you mean "
                                        "'shaft_clearance_um' in um?"),
    ('shaft_fit = "bonded"\nshaft_clearance_um = 5.0', BORE,
     "cam.shaft_fit = 'bonded' with shaft_clearance_um = 5 um: a bonded fit has no clearance"),
    ("shaft_clearance_um = 5.0", "", "cam.shaft_clearance_um = 5.0 um: needs cam.bore_mm"),
])
def test_bad_shaft_fit_keys_name_key_value_unit(tmp_path, lines, bore, expect):
    with pytest.raises(SceneError) as e:
        load_scene(_scene(tmp_path, lines, bore))
    assert expect in str(e.value)
