"""``femcam assess --sweep DIR`` on a damaged sweep.npz (issue 29 review, item 2): a per-angle
column missing or of the wrong length is refused with one line naming it; FE data present but
rows without it fall back to Hertz and the count is said (console, report.md).

Reference: the folder's own table (a Hertz-method sweep of two angles, FE columns NaN, and the
same table with FE values written into one row).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from femcam.assess import assess, sweep_table
from femcam.cli import main
from femcam.errors import InputError
from femcam.scene import contact_case, load_scene
from femcam.scene.digest import scene_digest
from femcam.sweep import RunOptions, SweepOptions, sweep

EXAMPLE = Path("examples/seed002_assess.toml")


@pytest.fixture(scope="module")
def swept(tmp_path_factory):
    out = tmp_path_factory.mktemp("sweep_damage") / "sw"
    sweep(str(EXAMPLE),
          SweepOptions(angles=np.radians([60.0, 90.0]), method="hertz", plots=False, vtk_every=0),
          RunOptions(workers=1, out=out))
    return out


def _damaged(tmp_path, swept, edit) -> Path:
    bad = tmp_path / "bad"
    bad.mkdir()
    with np.load(swept / "sweep.npz") as z:
        arrays = {k: z[k] for k in z.files}
    edit(arrays)
    np.savez(bad / "sweep.npz", **arrays)
    return bad


@pytest.mark.parametrize("column, edit", [
    ("p0_fe", lambda a: a.pop("p0_fe")),
    ("p0_fe", lambda a: a.update(p0_fe=a["p0_fe"][:1])),
    ("txz_range_max", lambda a: a.update(txz_range_max=a["txz_range_max"][:1])),
], ids=["p0_fe_removed", "p0_fe_cut", "txz_range_cut"])
def test_a_damaged_column_is_refused_with_one_line(tmp_path, swept, capsys, column, edit):
    bad = _damaged(tmp_path, swept, edit)
    with pytest.raises(InputError, match=f"column {column}"):
        sweep_table(bad, scene_digest(load_scene(EXAMPLE)))
    rc = main(["assess", str(EXAMPLE), "--sweep", str(bad), "--out", str(tmp_path / "o"), "--no-plots"])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 1 and len(err) == 1 and column in err[0], err


def test_rows_that_fall_back_to_hertz_are_counted(tmp_path, swept, capsys):
    scene = load_scene(EXAMPLE)
    hertz = assess(contact_case(scene, np.radians([60.0, 90.0])))

    def one_fe_row(a):   # the FE answered the first row only (its Hertz values, as if FE)
        a["a_fe"][0], a["p0_fe"][0] = hertz.rows["a"][0], hertz.rows["p0"][0]

    part = _damaged(tmp_path, swept, one_fe_row)
    res = assess(contact_case(scene, np.radians([60.0, 90.0])),
                 table=sweep_table(part, scene_digest(scene)))
    assert list(res.rows["source"]) == ["fe", "hertz"]
    assert any(n.startswith("contact: 1 of 2 angles fall back to Hertz") for n in res.notes)
    out = tmp_path / "o"
    rc = main(["assess", str(EXAMPLE), "--sweep", str(swept), "--out", str(out), "--no-plots"])
    assert rc == 0
    assert "contact: 2 of 2 angles fall back to Hertz" in capsys.readouterr().out   # all NaN
    md = (out / "report.md").read_text()
    assert "contact: 2 of 2 angles fall back to Hertz" in md and "hertz at 2 angles" in md
