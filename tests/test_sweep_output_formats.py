"""Output formats a user reads back: text columns that numpy reads as text, integer NPZ columns,
and the resume refusal naming only what differs."""

from pathlib import Path

import numpy as np
import pytest

from femcam.errors import InputError
from femcam.sweep import SweepResult, sweep

SCENE = Path(__file__).resolve().parents[1] / "examples" / "seed002_study_model.toml"


@pytest.fixture(scope="module")
def hertz_sweep(tmp_path_factory):
    out = tmp_path_factory.mktemp("h") / "out"
    res = sweep(SCENE, angles=np.radians(np.arange(0.0, 360.0, 30.0)), method="hertz", out=out,
                vtk_every=0, plots=False, progress=False, workers=1)
    return out, res


def test_empty_text_columns_read_as_text_by_genfromtxt(hertz_sweep):
    out, res = hertz_sweep
    assert all(f == "" for f in res.table["flags"]), "the Hertz sweep of seed 002 has no flags"
    d = np.genfromtxt(out / "sweep.csv", delimiter=",", names=True, dtype=None, encoding="utf-8")
    for name in ("flags", "message", "status"):
        assert d[name].dtype.kind == "U", f"{name} read as {d[name].dtype} (bool before the fix)"
    assert set(d["status"]) == {"ok"}


def test_npz_counts_and_ids_are_integers_and_reload_as_nan(hertz_sweep):
    out, res = hertz_sweep
    with np.load(out / "sweep.npz") as z:
        for name in ("iterations", "n_dofs", "family"):
            assert z[name].dtype == np.int64, name
            assert np.all(z[name] == -1), "a Hertz sweep solves no FE: undefined, stored as -1"
    back = SweepResult.load(out)
    assert np.all(np.isnan(back.table["family"]))  # the table's own convention: NaN
    np.testing.assert_array_equal(back.table["p0_hertz"], res.table["p0_hertz"])


def test_resume_refusal_names_only_what_differs(hertz_sweep, tmp_path):
    out = tmp_path / "r"
    theta = np.radians(np.arange(0.0, 360.0, 30.0))
    sweep(SCENE, angles=theta, method="hertz", out=out, vtk_every=0, plots=False, progress=False,
          workers=1)
    with pytest.raises(InputError) as info:  # same angles and chunks, another tolerance
        sweep(SCENE, angles=theta, method="hertz", tolerance=5e-3, out=out, resume=True,
              vtk_every=0, plots=False, progress=False, workers=1)
    msg = str(info.value)
    assert "tolerance" in msg and "chunk bounds" not in msg, msg
