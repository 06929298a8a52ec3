"""Every CSV femcam writes opens in ``pandas.read_csv`` as it is, with a sidecar JSON holding the
provenance (femcam.io: one writer, one layout).

Each CLI subcommand that writes CSVs runs once on a small case (Hertz method, few angles, no
plots); the output folders are globbed, so a CSV added later is covered, and it must have an entry
in ``EXPECTED`` (its leading columns and row count, known from the command line, not from the
file itself). ``femcam optimise`` (seconds) is checked the same way in tests/test_optimise.py.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from femcam.cli import main
from femcam.io import csv_text, meta_path, read_csv, read_meta

pd = pytest.importorskip("pandas", reason="pandas is in femcam's [test] extra; the CSV check needs it")

EX = Path(__file__).resolve().parents[1] / "examples"

#: provenance keys every sidecar holds (femcam.io.provenance)
PROV_KEYS = ("versions", "date", "machine", "command")

#: file name -> (leading columns, row count); rows follow from the commands in ``outputs``
EXPECTED = {
    "analytic.csv": (["theta_deg", "s_mm", "v_m_s"], 12),                  # 0:360:30
    "sweep.csv": (["theta_deg"], 4),                                         # 40:70:10
    "assessment.csv": (["theta_deg"], 12),                                   # 0:360:30
    "dynamics.csv": (["theta_deg", "s_mm", "Fc_rigid_N", "Fc_N", "liftoff"], None),
    "rpm_sweep.csv": (["rpm", "Fc_max_N", "Fc_min_N"], 2),                   # 600:700:100
    "wear_scene.csv": (["theta_deg", "s_mm", "Fc_N"], 36),                   # --step-deg 10
    "wear_scene_surface.csv": (["arc_mm", "depth_per_rev_nm"], None),
    "wear_scene_follower.csv": (["roller_arc_mm", "depth_per_rev_nm"], None),
    "wear_scene_evolution.csv": (["blocks", "block_revolutions", "max_depth_um"], 2),  # 1, 2
    "wear_summary.csv": (["law", "cycles", "max_depth_um"], 1),
    "seed000.csv": (["law", "int_v2_du"], 3),                                # the paper's 3 laws
    "synth_curve.csv": (["theta_deg", "r_mm", "x_mm", "y_mm"], None),
    "study.csv": (["variant", "follower.base_radius_mm"], 2),              # --vary ...=10,12
}


@pytest.fixture(scope="module")
def outputs(tmp_path_factory):
    """Run every CSV-writing subcommand once; returns the output folders."""
    d = tmp_path_factory.mktemp("outputs")
    study, dyn = str(EX / "seed002_study_model.toml"), str(EX / "seed002_dynamic.toml")
    cmds = {
        "run": ["run", study, "--angles-deg", "0:360:30", "--no-plots"],
        "sweep": ["sweep", study, "--method", "hertz", "--angles-deg", "40:70:10", "--no-plots",
                  "--vtk-every", "0", "--workers", "1", "--progress", "off"],
        "assess": ["assess", str(EX / "seed002_assess.toml"), "--angles-deg", "0:360:30",
                   "--no-plots"],
        "dynamics": ["dynamics", dyn, "--rpm-sweep", "600:700:100", "--no-plots"],
        "wear": ["wear", "map", study, "--step-deg", "10", "--cycles", "1000", "--no-plots",
                 "--evolve-blocks", "2"],
        "synth": ["synth", "--case", "seed003", "--elements", "12"],
        "study": ["study", study, "--vary", "follower.base_radius_mm=10,12", "--no-plots"],
    }
    for name, argv in cmds.items():
        assert main([*argv, "--out", str(d / name)]) == 0, name
    d.joinpath("seed000").mkdir()
    assert main(["wear", "seed000", "--csv", str(d / "seed000" / "seed000.csv")]) == 0
    return d


def test_every_csv_opens_in_pandas_with_its_sidecar(outputs):
    csvs = sorted(outputs.rglob("*.csv"))
    names = {p.name for p in csvs}
    assert names >= set(EXPECTED), f"expected CSVs not written: {set(EXPECTED) - names}"
    for p in csvs:
        assert p.name in EXPECTED, f"{p}: a CSV without an entry in EXPECTED (add its columns and rows)"
        lead, n = EXPECTED[p.name]
        df = pd.read_csv(p)                      # as it is: no comment=, no skiprows=
        assert list(df.columns[:len(lead)]) == lead, p.name
        if n is not None:
            assert len(df) == n, p.name
        assert len(df) > 0 and not any(str(c).startswith("#") for c in df.columns), p.name
        assert not p.read_text().count("#"), f"{p.name}: a comment line or '#' in a field"
        # the sidecar: CSVW name rule, provenance keys, columns and row count of the file
        side = meta_path(p)
        assert side.name == p.name + "-metadata.json" and side.is_file(), p.name
        meta = json.loads(side.read_text())
        assert meta["url"] == p.name and meta["rows"] == len(df), p.name
        assert [c["name"] for c in meta["tableSchema"]["columns"]] == list(df.columns), p.name
        for key in PROV_KEYS:
            assert key in meta["provenance"], (p.name, key)
        assert meta["provenance"]["versions"]["femcam"], p.name
        # numeric columns are numbers in pandas, as the sidecar says
        for c in meta["tableSchema"]["columns"]:
            if c["datatype"] == "number":
                assert np.issubdtype(df[c["name"]].dtype, np.number), (p.name, c["name"])


def test_sweep_sidecar_holds_the_scene_and_options(outputs):
    meta = read_meta(outputs / "sweep" / "sweep.csv")
    prov = meta["provenance"]
    scene = EX / "seed002_study_model.toml"
    assert prov["scene"] == str(scene) and len(prov["scene_sha256"]) == 64
    import hashlib

    assert prov["scene_file_sha256"] == hashlib.sha256(scene.read_bytes()).hexdigest()
    assert prov["options"]["method"] == "hertz"
    # the same record as the NPZ's
    with np.load(outputs / "sweep" / "sweep.npz") as z:
        assert json.loads(str(z["provenance_json"]))["date"] == prov["date"]
    # read_csv gives the provenance as text lines, as it did from the old '#' header
    cols, header = read_csv(outputs / "sweep" / "sweep.csv")
    assert header["command"] == prov["command"] and json.loads(header["options"])["method"] == "hertz"
    assert cols["theta_deg"].tolist() == [40.0, 50.0, 60.0, 70.0]


def test_rows_match_the_run_they_came_from(outputs):
    """Independent checks of a few values: angles from the command line, 0/1 flags, text."""
    a = pd.read_csv(outputs / "run" / "analytic.csv")
    assert np.allclose(a["theta_deg"], np.arange(0, 360, 30))
    assert set(a["liftoff"]) <= {0, 1}
    r = pd.read_csv(outputs / "dynamics" / "rpm_sweep.csv")
    assert r["rpm"].tolist() == [600, 700] and set(r["converged"]) <= {0, 1}
    w = pd.read_csv(outputs / "wear" / "wear_scene.csv")
    assert np.allclose(w["theta_deg"], np.arange(0, 360, 10))
    s = pd.read_csv(outputs / "seed000" / "seed000.csv")
    assert s["law"].tolist() == ["uniform_velocity", "shm", "cycloidal"]
    c = pd.read_csv(outputs / "synth" / "synth_curve.csv")
    assert np.allclose(np.hypot(c["x_mm"], c["y_mm"]), c["r_mm"], rtol=1e-9)   # polar radius


def test_text_fields_with_commas_quotes_newlines_stay_one_field(tmp_path):
    from femcam.io import provenance, write_table

    text = ['a, "b"\nc', "", "# d"]
    p = write_table(tmp_path / "t.csv", {"x_mm": np.array([1.0, math.nan, 3.0]),
                                          "n": np.array([1, 2, 3]), "msg": text},
                    provenance(command="t"), title="t")
    df = pd.read_csv(p, keep_default_na=False)
    assert df.shape == (3, 3) and df["n"].tolist() == [1, 2, 3]
    assert df["msg"].tolist() == [csv_text(t) for t in text] == ["a; 'b' c", "-", "No. d"]
    cols, _ = read_csv(p)
    assert cols["msg"].tolist() == ["a; 'b' c", "", "No. d"] and math.isnan(cols["x_mm"][1])
    g = np.genfromtxt(p, delimiter=",", names=True, dtype=None, encoding="utf-8")
    assert g.shape == (3,) and g["n"].tolist() == [1, 2, 3]


def test_read_csv_keeps_reading_an_old_results_folder(tmp_path):
    """A CSV written before the sidecar: '#' provenance lines after the header, no JSON."""
    p = tmp_path / "sweep.csv"
    p.write_text("theta_deg,status\n# versions: femcam 0.0\n# command: femcam sweep x\n"
                 "0,ok\n10,-\n")
    cols, header = read_csv(p)
    assert cols["theta_deg"].tolist() == [0.0, 10.0] and cols["status"].tolist() == ["ok", ""]
    assert header["command"] == "femcam sweep x"
    from femcam.errors import InputError

    with pytest.raises(InputError, match="no sidecar sweep.csv-metadata.json"):
        read_meta(p)


def test_study_result_dataframe_and_repr_match_study_csv(outputs):
    """The study's result object gives the CSV's table (same names and units) and a short repr."""
    from femcam.study import StudySpec, run_study

    res = run_study(EX / "seed002_study_model.toml", StudySpec.parse(["follower.base_radius_mm=10,12"]))
    df, csv = res.to_dataframe(), pd.read_csv(outputs / "study" / "study.csv")
    assert list(df.columns) == list(csv.columns) and len(df) == 2
    np.testing.assert_allclose(df["p0_max_MPa"], csv["p0_max_MPa"], rtol=1e-9)
    assert df["follower.base_radius_mm"].tolist() == [10.0, 12.0]
    r = repr(res)
    assert len(r) <= 1000 and r.startswith("StudyResult(2 variants") and "MPa" in r
