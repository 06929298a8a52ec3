"""An assessment refuses the sweep folder of another scene (femcam.assess.sweep_dir, docs/assess.md
"A sweep folder as the table").

Reference: the scene file itself. The same physics written differently (comments, layout, key
order, free text, the study settings of [fe]/[sweep]) must be accepted; another roller radius or
another program must be refused with one line naming both scenes; a damaged folder with one line.
The sweep is method hertz over two angles: the check does not depend on the contact model.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from femcam.assess import sweep_table
from femcam.cli import main
from femcam.errors import InputError
from femcam.scene import load_scene
from femcam.scene.digest import physics_hash, scene_digest
from femcam.sweep import RunOptions, SweepOptions, sweep

EXAMPLE = Path("examples/seed002_assess.toml")


def _write(tmp_path, name: str, changes=()) -> Path:
    text = EXAMPLE.read_text()
    for old, new in changes:
        assert old in text, old
        text = text.replace(old, new)
    path = tmp_path / name
    path.write_text(text)
    return path


@pytest.fixture(scope="module")
def swept(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("sweep_dir")
    out = tmp / "sw"
    sweep(str(EXAMPLE),
          SweepOptions(angles=np.radians([0.0, 90.0]), method="hertz", plots=False, vtk_every=0),
          RunOptions(workers=1, out=out))
    return out


def _assess(scene: Path, sw: Path, out: Path, capsys) -> tuple[int, str]:
    rc = main(["assess", str(scene), "--out", str(out), "--sweep", str(sw), "--no-plots"])
    return rc, capsys.readouterr().err


def test_the_same_physics_written_differently_is_accepted(tmp_path, swept, capsys):
    text = EXAMPLE.read_text()
    lines = [ln.split("#")[0].rstrip() for ln in text.splitlines()]   # comments gone
    first = next(i for i, ln in enumerate(lines) if ln.startswith("["))
    body = "\n".join(lines[first:]).replace(" = ", "   =   ")             # layout changed
    same = tmp_path / "same.toml"
    head = 'name = "renamed"\ndescription = "other words"\n\n[fe]\na_over_h = 14.0\n\n'   # free text, study
    same.write_text(head + body + "\n")
    assert physics_hash(load_scene(same)) == physics_hash(load_scene(EXAMPLE))
    assert scene_digest(load_scene(same)).sha256 == physics_hash(load_scene(EXAMPLE))
    t = sweep_table(swept, scene_digest(load_scene(same)))
    np.testing.assert_array_equal(t["theta"], np.radians([0.0, 90.0]))
    rc, err = _assess(same, swept, tmp_path / "o", capsys)
    assert rc == 0, err


@pytest.mark.parametrize("changes, part", [
    ((("roller_radius_mm = 10.0", "roller_radius_mm = 12.0"),), "follower"),
    ((("lift_mm = 10.0", "lift_mm = 8.0"),), "program"),
], ids=["other_roller_radius", "other_program"])
def test_a_sweep_of_another_scene_is_refused(tmp_path, swept, capsys, changes, part):
    other = _write(tmp_path, "other.toml", changes)
    with pytest.raises(InputError, match=f"they differ in {part}"):
        sweep_table(swept, scene_digest(load_scene(other)))
    rc, err = _assess(other, swept, tmp_path / "o", capsys)
    assert rc == 1
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err
    assert "it was swept from scene 'seed002_assess'" in lines[0]          # the folder's scene
    assert f"({other})" in lines[0]                                       # the scene given
    assert f"femcam sweep {other} --out NEW_DIR" in lines[0]              # how to fix it
    assert str(swept / "scene.toml") in lines[0]
    assert not (tmp_path / "o" / "assessment.csv").exists()


def test_a_sweep_recorded_before_the_hash_is_checked_against_its_scene_copy(tmp_path, swept, capsys):
    old = tmp_path / "old"
    old.mkdir()
    with np.load(swept / "sweep.npz") as z:
        arrays = {k: z[k] for k in z.files}
    prov = json.loads(str(arrays["provenance_json"]))
    prov.pop("scene_physics_parts"), prov.pop("scene_physics_sha256")
    arrays["provenance_json"] = np.array(json.dumps(prov))
    np.savez(old / "sweep.npz", **arrays)
    (old / "scene.toml").write_text((swept / "scene.toml").read_text())
    assert sweep_table(old, scene_digest(load_scene(EXAMPLE)))["theta"].size == 2
    other = _write(tmp_path, "other.toml", (("roller_radius_mm = 10.0", "roller_radius_mm = 12.0"),))
    with pytest.raises(InputError, match="they differ in follower"):
        sweep_table(old, scene_digest(load_scene(other)))
    (old / "scene.toml").unlink()
    with pytest.raises(InputError, match="records no scene"):
        sweep_table(old, scene_digest(load_scene(EXAMPLE)))
    with pytest.raises(InputError, match="digest = "):
        sweep_table(swept, load_scene(EXAMPLE))                 # the digest record, not the scene


@pytest.mark.parametrize("damage", ["truncated", "not_a_zip", "no_provenance"])
def test_a_corrupted_sweep_folder_gives_one_line(tmp_path, swept, capsys, damage):
    bad = tmp_path / "bad"
    bad.mkdir()
    data = (swept / "sweep.npz").read_bytes()
    if damage == "truncated":
        (bad / "sweep.npz").write_bytes(data[: len(data) // 2])
    elif damage == "not_a_zip":
        (bad / "sweep.npz").write_text("theta,p0\n1,2\n")
    else:
        np.savez(bad / "sweep.npz", theta=np.zeros(2))
    rc, err = _assess(EXAMPLE, bad, tmp_path / "o", capsys)
    assert rc == 1
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    assert "sweep.npz cannot be read" in lines[0] and "corrupted or partial" in lines[0]
