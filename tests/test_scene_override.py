"""femcam.scene.override: the command line's overrides written into the scene text (comments
kept) load back as the overridden scene."""

from pathlib import Path

import pytest

from femcam.scene import load_scene
from femcam.scene.override import with_overrides

EX = Path(__file__).resolve().parents[1] / "examples"


@pytest.mark.parametrize("law", ["cycloidal", "poly345"])
def test_law_override_loads_as_with_law(tmp_path, law):
    src = EX / "seed002_study_model.toml"
    p = tmp_path / "s.toml"
    p.write_text(with_overrides(src.read_text(), {}, law=law))
    assert repr(load_scene(p).program) == repr(load_scene(src).with_law(law).program)
    assert "# the file has" not in p.read_text() and "(the file had: \"bezier5\")" in p.read_text()


def test_segment_laws_and_multiline_control_points_are_replaced(tmp_path):
    text = ('name = "x"\n[operating]\nrpm = 100.0\n[program]\ncontrol_points = [0.0, 0.0,\n'
            '  1.0, 1.0]   # a Bezier rise\n'
            '[[program.segment]]\nkind = "rise"\nbeta_deg = 180.0\nlift_mm = 5.0\nlaw = "shm"  # own\n'
            '[[program.segment]]\nkind = "fall"\nbeta_deg = 180.0\nlift_mm = 5.0\n'
            '[follower]\ntype = "roller"\nbase_radius_mm = 20.0\nroller_radius_mm = 5.0\n'
            'face_width_mm = 10.0\n[dynamics]\nmass_kg = 0.1\nspring_N_per_m = 1000.0\n'
            'preload_N = 100.0\ndamping_ratio = 0.05\n'
            '[materials.cam]\nE_GPa = 210.0\nnu = 0.3\n'
            '[materials.roller]\nE_GPa = 210.0\nnu = 0.3\n')
    p = tmp_path / "s.toml"
    p.write_text(text)
    q = tmp_path / "q.toml"
    q.write_text(with_overrides(text, {("sweep", "method"): "hertz"}, law="cycloidal"))
    sc = load_scene(q)
    assert repr(sc.program) == repr(load_scene(p).with_law("cycloidal").program)
    assert sc.study.method == "hertz"
    assert "# control_points = [0.0, 0.0," in q.read_text()   # kept, as a comment
