"""A part the scene asks for and the physics refuses at run time is said, and fails the run
(docs/sweep.md, "Refused parts and exit codes").

Each case is an example scene with one key changed so that its extra column provider
(femcam.sweep.extras) refuses: the console must name the part, the reason and the scene keys
to change (one line each, stderr), ``report.md`` must say it, ``femcam sweep`` must exit 1 with
everything computed still written, and ``SweepResult.refused`` must carry ``(part, reason)``.
Method hertz and two angles: the refusal does not depend on the contact model.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from femcam.cli import main
from femcam.io import read_csv
from femcam.sweep import RunOptions, SweepOptions, SweepResult, sweep

EX = Path("examples")


def _variant(tmp_path, example: str, changes) -> Path:
    text = (EX / example).read_text()
    for old, new in changes:
        assert old in text, f"{old!r} is not in {example}"
        text = text.replace(old, new)
    path = tmp_path / f"{Path(example).stem}_variant.toml"
    path.write_text(text)
    return path


#: (case id, example, ((text replaced, replacement), ...), refused part, words the reason must
#: hold, a scene key the line must name)
CASES = [
    # a ring solve that does not settle: ~2.7 s, so in the slow pass
    pytest.param(("three_needles_ring_does_not_converge", "seed002_needle_roller.toml",
                  (("needle_count = 18 ", "needle_count = 3 "),), "bodies", "did not settle", "needle_count"),
                 marks=pytest.mark.slow, id="three_needles_ring_does_not_converge"),
]

#: scenes whose part was refused only at run time before the scene ranges (docs/scene.md) and
#: is now refused at load, before any work: (case id, example, changes, the key the line names)
AT_LOAD = [
    ("pin_clearance_too_large", "seed002_needle_roller.toml",
     (('roller_support = "needles"', 'roller_support = "pin"'),
      ("pin_radius_mm = 4.99", "pin_radius_mm = 4.0"),
      ("pin_clearance_um = 10.0 ", "pin_clearance_um = 3000.0 "),
      ("needle_count = 18", "#"), ("needle_radius_mm = 1.0", "#")), "pin_clearance_um"),
    ("coating_thicker_than_a_coating", "seed002_coated.toml",
     (("thickness_um = 2.5 ", "thickness_um = 20000.0 "),), "thickness_um"),
    ("coating_of_1_nm", "seed002_coated.toml", (("thickness_um = 2.5 ", "thickness_um = 0.001 "),),
     "thickness_um"),
    ("case_deeper_than_the_cam", "seed002_coated.toml", (("depth_mm = 0.3 ", "depth_mm = 50.0 "),),
     "depth_mm"),
]


@pytest.mark.parametrize("case", AT_LOAD, ids=[c[0] for c in AT_LOAD])
def test_part_the_scene_cannot_have_is_refused_at_load(tmp_path, capsys, case):
    _, example, changes, key = case
    scene = _variant(tmp_path, example, changes)
    rc = main(["sweep", str(scene), "--out", str(tmp_path / "out"), "--angles-deg", "0:90:90",
               "--method", "hertz", "--no-plots", "--vtk-every", "0", "--workers", "1", "--progress", "off"])
    err = capsys.readouterr().err
    assert rc == 1 and "Traceback" not in err, err
    assert "1 problem" in err and key in err, err
    assert not (tmp_path / "out" / "sweep.csv").exists()            # refused before any work


@pytest.mark.parametrize("case", CASES)
def test_refused_part_is_said_and_fails_the_run(tmp_path, capsys, case):
    _, example, changes, part, words, key = case
    scene = _variant(tmp_path, example, changes)
    out = tmp_path / "out"
    rc = main(["sweep", str(scene), "--out", str(out), "--angles-deg", "0:90:90", "--method", "hertz",
               "--no-plots", "--vtk-every", "0", "--workers", "1", "--progress", "off"])
    err = capsys.readouterr().err
    assert rc == 1, err
    lines = [ln for ln in err.splitlines() if ln.startswith("femcam sweep: refused: ")]
    assert len(lines) == 1, err                                      # one line per refused part
    assert lines[0].startswith(f"femcam sweep: refused: {part} refused at 2 of 2 angle(s)")
    assert words in lines[0] and key in lines[0], lines[0]
    assert "femcam sweep: error: 1 part(s) the scene asks for were refused (exit 1)" in err
    assert "Traceback" not in err
    # everything computed is written: the contact columns are there, the part's are NaN
    cols, _ = read_csv(out / "sweep.csv")
    assert np.all(np.isfinite(cols["p0_hertz_MPa"])) and np.all(cols["status"] == "ok")
    report = (out / "report.md").read_text()
    assert "Not a complete answer: 1 part(s) the scene asks for were refused" in report
    assert f"- refused: {part} refused at 2 of 2 angle(s)" in report
    page = (out / "report.html").read_text()                         # first, above the title
    assert page.index("<div class=refused") < page.index("<h1>") and "Not a complete answer" in page
    assert f"{part} refused at 2 of 2 angle(s)" in page
    # the API: the reloaded result and a fresh in-memory sweep carry the refusal
    refused = SweepResult.load(out).refused
    assert [p for p, _ in refused] == [part] and words in refused[0][1]
    r = sweep(str(scene),
              SweepOptions(angles=np.radians([0.0]), method="hertz", plots=False),
              RunOptions(workers=1))
    assert [p for p, _ in r.refused] == [part]


def test_a_sweep_whose_parts_all_answer_refuses_nothing(tmp_path, capsys):
    rc = main(["sweep", str(EX / "seed002_assess.toml"), "--out", str(tmp_path / "out"), "--angles-deg",
               "0:90:90", "--method", "hertz", "--no-plots", "--vtk-every", "0", "--workers", "1",
               "--progress", "off"])
    err = capsys.readouterr().err
    assert rc == 0 and "refused" not in err
    assert SweepResult.load(tmp_path / "out").refused == ()


def test_every_provider_names_the_scene_keys_that_ask_for_it():
    # generated from the provider table, so a provider added later is covered: a refusal line
    # must name the part, count its rows, keep the first reason and say which scene keys to change
    from femcam.sweep.extras import ERROR_COLUMN, PROVIDERS
    from femcam.sweep.worst import refusals

    keys = {p.name: p.keys for p in PROVIDERS}
    for p in PROVIDERS:
        assert p.keys, f"provider {p.name} does not say which scene keys ask for it"
        table = {ERROR_COLUMN: np.array([f"{p.name}: InputError: x = 1 m: bad", "",
                                         f"{p.name}: InputError: x = 2 m: bad | other: E: y"])}
        got = refusals(table, keys)
        assert [r["part"] for r in got] == [p.name, "other"]
        r = got[0]
        assert r["angles"] == 2 and r["reason"].startswith("InputError: x = 1 m: bad")
        assert "1 other reason(s)" in r["reason"]
        assert r["line"] == (f"{p.name} refused at 2 of 3 angle(s), its columns are NaN there: "
                             f"{r['reason']}; change the scene keys {p.keys}")
