"""``femcam optimise``: --vary bounds inside the scene key's range, the optimum printed in the
flags' units, and a failed FE check said in one line with a non-zero exit (issue 29 review,
item 4). Reference: femcam.scene.ranges (``[follower] base_radius_mm`` in [0.1, 1000] mm,
``[program.segment] beta_deg`` in (0, 360] deg).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import femcam.optimise.solve as solve
from femcam.cli import main
from femcam.errors import ConvergenceError, InputError
from femcam.optimise import Variable, optimise
from femcam.scene import load_scene

SCENE = Path("examples/seed002_study_model.toml")


@pytest.mark.parametrize("spec, says", [
    ("base_radius_mm=1e-9:1e30", "--vary base_radius_mm LO = 1e-09 mm"),
    ("base_radius_mm=5:5000", "--vary base_radius_mm HI = 5000 mm"),
    ("roller_radius_mm=5:2000", "--vary roller_radius_mm HI = 2000 mm"),
    ("rise_angle_deg=50:400", "--vary rise_angle_deg HI = 400 deg"),
])
def test_bounds_outside_the_scene_range_are_refused(tmp_path, capsys, spec, says):
    rc = main(["optimise", str(SCENE), "--vary", spec, "--no-fe", "--out", str(tmp_path / "o")])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 1 and len(err) == 1, err
    assert says in err[0] and "must be in" in err[0], err[0]


def test_the_api_refuses_too():
    with pytest.raises(InputError, match=r"base_radius_mm HI = 5000 mm.*\[0\.1, 1000\] mm"):
        optimise(load_scene(SCENE), variables=[Variable(name="base_radius", lower=5e-3, upper=5.0)],
                 verify_fe=False)


def test_a_failed_fe_check_is_one_line_and_not_a_success(tmp_path, capsys, monkeypatch):
    def broken(*args, **kwargs):
        raise ConvergenceError("Circle or ellipse arc 1 greater than Pi\n(gmsh)")

    monkeypatch.setattr(solve, "sweep", broken)
    out = tmp_path / "o"
    rc = main(["optimise", str(SCENE), "--vary", "base_radius_mm=10:30", "--starts", "1", "--out", str(out)])
    cap = capsys.readouterr()
    err = cap.err.strip().splitlines()
    assert rc == 1 and len(err) == 1, err
    assert err[0].startswith("femcam optimise: error: the FE check of the optimum failed: ")
    assert "Circle or ellipse arc 1 greater than Pi (gmsh)" in err[0]          # wrapped, one line
    assert "  base_radius_mm = " in cap.out                                     # in the flag's unit
    rb = float(cap.out.split("  base_radius_mm = ")[1].split()[0])
    assert 10.0 <= rb <= 30.0
    assert json.loads((out / "optimum.json").read_text())                       # still written


def test_a_failed_fe_row_is_said_in_one_line(tmp_path, capsys, monkeypatch):
    import numpy as np

    class Failed:   # a sweep whose middle row the mesher refused (as a sweep reports it)
        table = {"p0_hertz": np.array([1e9, 1e9, 1e9]), "p0_fe": np.array([1e9, np.nan, 1e9]),
                 "status": np.array(["ok", "failed", "ok"]),
                 "message": np.array(["", "MeshError: Circle or ellipse arc 1\ngreater than Pi", ""])}

    monkeypatch.setattr(solve, "sweep", lambda *a, **k: Failed())
    out = tmp_path / "o"
    rc = main(["optimise", str(SCENE), "--vary", "base_radius_mm=10:30", "--starts", "1", "--out", str(out)])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 1 and len(err) == 1, err
    assert "the FE check of the optimum failed at 1 of 3 angles" in err[0]
    assert "Circle or ellipse arc 1 greater than Pi" in err[0]
    assert (out / "optimum.json").is_file()
