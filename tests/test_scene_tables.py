"""Every scene table is checked at load ([fe], [sweep], [wear]), and `femcam sweep` honours the
scene's [fe]/[sweep] settings with command-line flags overriding them.

References: the bad values are typed in the tests; the expected ranges are the ones the sweep
options refuse (``femcam.sweep.options.SweepOptions``, checked here independently by
constructing it at and beyond each bound).
"""

import os
from pathlib import Path

import numpy as np
import pytest

import femcam.cli.sweep as cli_sweep
from femcam.cli import main
from femcam.errors import InputError, SceneError
from femcam.scene import StudySettings, load_scene
from femcam.sweep.options import TOLERANCE_FLOOR, SweepOptions
from femcam.sweep.settings import resolve_settings

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
STUDY = (EXAMPLES / "seed002_study_model.toml").read_text()


def _scene(tmp_path, extra: str, base: str = STUDY) -> Path:
    p = tmp_path / "scene.toml"
    p.write_text(base + "\n" + extra)
    return p


def _problems(tmp_path, extra: str, base: str = STUDY) -> str:
    with pytest.raises(SceneError) as ei:
        load_scene(_scene(tmp_path, extra, base))
    return str(ei.value)


@pytest.mark.parametrize("extra, msg", [
    ("[fe]\na_over_h = -5", "fe.a_over_h = -5 (elements per contact half-width): must be > 0"),
    ("[fe]\na_over_h = 1", "fe.a_over_h = 1 (elements per contact half-width): must be in [2, 400]"),
    ("[fe]\ntolerance = 1e-5", "fe.tolerance = 1e-05 (relative p0 reuse error): must be >= 0.0001"),
    ("[fe]\nmesh_size = 20", "fe.mesh_size = 20: unknown key; valid keys: a_over_h, tolerance"),
    ("[fe]\na_over = 20", "fe.a_over = 20: unknown key; did you mean 'a_over_h'"),
    ("[sweep]\nmethod = \"fem\"", "sweep.method = 'fem': must be one of 'fe', 'hertz'"),
    ("[sweep]\nangles_deg = \"0:360\"", "sweep.angles_deg = '0:360'"),
    ("[sweep]\nchunk_size = 2.5", "sweep.chunk_size = 2.5 angles: must be a whole number >= 1"),
    ("[sweep]\nchunk_size = 0", "sweep.chunk_size = 0 angles: must be a whole number >= 1"),
    ("[sweep]\nvtk_every = -1", "sweep.vtk_every = -1 angles: must be a whole number >= 0"),
    ("[sweep]\nplots = \"yes\"", "sweep.plots = 'yes': must be true or false"),
    ("[sweeps]\nplots = true", "sweeps: unknown table [sweeps]; did you mean [sweep]?"),
    ("[fe]\nfoo = 1\n[sweep]\nbar = 2", "2 problems"),
])
def test_fe_and_sweep_tables_are_checked(tmp_path, extra, msg):
    assert msg in _problems(tmp_path, extra)


def test_scene_ranges_are_the_sweep_options_ranges():
    # the same bounds SweepOptions enforces: accepted at the bound, refused beyond it
    for kw in ({"a_over_h": 2.0}, {"a_over_h": 400.0}, {"tolerance": TOLERANCE_FLOOR}, {"tolerance": 0.5}):
        SweepOptions(**kw)
    for kw in ({"a_over_h": 1.99}, {"a_over_h": 400.1}, {"tolerance": 0.99 * TOLERANCE_FLOOR},
               {"tolerance": 0.51}):
        with pytest.raises(InputError):
            SweepOptions(**kw)
    from femcam.scene.schema import _RANGES
    assert _RANGES == {"a_over_h": (2.0, 400.0), "tolerance": (TOLERANCE_FLOOR, 0.5)}


@pytest.mark.parametrize("extra, msg", [
    ("[wear]\nk_mm3_per_Nm = 1e-9", "wear.k_mm3_per_Nm = 1e-09: unknown key; did you mean 'k_mm3_per_N_m'"),
    ("[wear]\nk = 1e-17", "did you mean 'k_mm3_per_N_m' in mm^3/(N m)? (units go in the key name)"),
    ("[wear]\nsrr = 3", "wear.srr = 3 (dimensionless): must be in (-2, 2)"),
    ("[wear]\nroller_model = \"slip\"", "wear.roller_model = 'slip': must be one of 'srr', 'inertia'"),
    ("[wear]\nK = 1e-8", "wear.K = 1e-08 (dimensionless): needs the cam hardness"),
    ("[wear]\nK = 1e-8\nk_mm3_per_N_m = 1e-9", "give either K"),
    ("wear = 3", "wear = 3: must be a table [wear]"),
])
def test_wear_table_is_checked_at_load(tmp_path, extra, msg):
    if extra.startswith("wear ="):  # a top-level key must come before the first table
        assert msg in _problems(tmp_path, "", base=extra + "\n" + STUDY)
    else:
        assert msg in _problems(tmp_path, extra)


def test_valid_tables_are_kept(tmp_path):
    text = ("[fe]\na_over_h = 20\ntolerance = 1e-3\n[sweep]\nmethod = \"hertz\"\nangles_deg = \"-90:90:5\"\n"
            "chunk_size = 6\nvtk_every = 0\nplots = false\n[wear]\nk_mm3_per_N_m = 1e-9\nsrr = 0.05\n")
    sc = load_scene(_scene(tmp_path, text))
    assert sc.study == StudySettings(a_over_h=20.0, tolerance=1e-3, method="hertz",
                                     angles_deg="-90:90:5", chunk_size=6, vtk_every=0, plots=False)
    assert sc.study.given() == {"a_over_h": 20.0, "tolerance": 1e-3, "method": "hertz",
                                "angles_deg": "-90:90:5", "chunk_size": 6, "vtk_every": 0, "plots": False}
    assert isinstance(sc.study.chunk_size, int) and sc.study.rtol is None
    # the scene's percent is the record's fraction (SI inside): 0.5 % -> 0.005
    (tmp_path / "pct").mkdir()
    pct = load_scene(_scene(tmp_path / "pct", "[fe]\nrtol_pct = 0.5\nrtol_on = [\"p0\", \"tau1\"]\n"))
    assert pct.study.rtol == pytest.approx(0.005, rel=1e-15) and pct.study.rtol_on == ("p0", "tau1")
    assert StudySettings().given() == {}
    assert sc.wear.k == pytest.approx(1e-18) and sc.wear.srr == pytest.approx(0.05)  # mm^3 = 1e-9 m^3
    assert sc.wear.K is None and sc.wear.J is None and sc.wear.cycles is None   # not given


@pytest.fixture
def captured(monkeypatch):
    """Replace the sweep the CLI calls by one that records its run options and resolved settings."""
    calls = []

    class _R:  # just enough of a SweepResult for the CLI's printout
        n_angles, n_chunks_resumed, n_chunks_computed, method, paths = 0, 0, 0, "hertz", {}
        timings, provenance = {"total": 0.0}, {}

        def summary(self):
            return dict.fromkeys(("n_liftoff", "n_undercut", "n_failed", "Fc_max", "p0_hertz_max",
                                  "vm_max", "tau1_max"), 0)

    def fake(scene, options, run):
        # the CLI hands its flags over as given; the library resolves them (scene, default)
        st = resolve_settings(scene, options.given())
        calls.append({**vars(run), "angles": st.angles, "a_over_h": st.a_over_h, "tolerance": st.tolerance,
                      "method": st.method, "chunk_size": st.chunk_size, "vtk_every": st.vtk_every,
                      "plots": st.plots})
        return _R()

    monkeypatch.setattr(cli_sweep, "sweep", fake)
    return calls


SETTINGS = ("[fe]\na_over_h = 20\ntolerance = 1e-3\n[sweep]\nmethod = \"hertz\"\nangles_deg = \"0:30:10\"\n"
            "chunk_size = 2\nvtk_every = 0\nplots = false\n")


def test_sweep_takes_settings_from_the_scene(tmp_path, captured, capsys):
    assert main(["sweep", str(_scene(tmp_path, SETTINGS)), "--out", str(tmp_path / "o")]) == 0
    kw = captured[-1]
    assert np.degrees(kw["angles"]) == pytest.approx([0, 10, 20, 30])
    assert (kw["a_over_h"], kw["tolerance"], kw["method"], kw["chunk_size"], kw["vtk_every"], kw["plots"]) \
        == (20.0, 1e-3, "hertz", 2, 0, False)
    out = capsys.readouterr().out
    assert "settings from the scene file: [sweep] angles_deg = \"0:30:10\", [fe] a_over_h = 20" in out


def test_flags_override_the_scene(tmp_path, captured):
    args = ["sweep", str(_scene(tmp_path, SETTINGS)), "--out", str(tmp_path / "o"), "--angles-deg", "0:10:10",
            "--a-over-h", "8", "--tolerance", "0.01", "--method", "fe", "--chunk-size", "5",
            "--vtk-every", "3", "--plots"]
    assert main(args) == 0
    kw = captured[-1]
    assert np.degrees(kw["angles"]) == pytest.approx([0, 10])
    assert (kw["a_over_h"], kw["tolerance"], kw["method"], kw["chunk_size"], kw["vtk_every"], kw["plots"]) \
        == (8.0, 0.01, "fe", 5, 3, True)
    assert "--angles-deg 0:10:10" in kw["command"] and "--no-plots" not in kw["command"]


def test_defaults_without_scene_settings(tmp_path, captured):
    assert main(["sweep", str(_scene(tmp_path, "")), "--out", str(tmp_path / "o")]) == 0
    kw = captured[-1]
    assert kw["angles"].size == 360 and np.degrees(kw["angles"][1]) == pytest.approx(1.0)
    assert (kw["a_over_h"], kw["tolerance"], kw["method"], kw["chunk_size"], kw["vtk_every"], kw["plots"]) \
        == (10.0, 2e-3, "fe", 30, 10, True)


def test_negative_angle_range_is_accepted(tmp_path, captured):
    for flag in (["--angles-deg", "-360:0:30"], ["--angles-deg=-360:0:30"]):
        assert main(["sweep", str(_scene(tmp_path, "")), "--out", str(tmp_path / "o"), *flag]) == 0
        assert np.degrees(captured[-1]["angles"]) == pytest.approx(np.arange(-360.0, 0.0, 30.0))


def test_workers_capped_at_the_useful_number(tmp_path, captured, capsys, monkeypatch):
    monkeypatch.setattr(os, "cpu_count", lambda: 2)  # read by femcam.cli._common.cap_workers
    # 12 angles in chunks of 30: 1 chunk, so 1 process is all that can work
    assert main(["sweep", str(_scene(tmp_path, "")), "--out", str(tmp_path / "o"), "--angles-deg", "0:360:30",
                 "--workers", "999"]) == 0
    assert captured[-1]["workers"] == 1
    assert "--workers 999 capped at 1 (the useful number: 2 CPU cores, 1 chunks" in capsys.readouterr().err
    # 360 angles: 12 chunks, 2 cores -> 2
    assert main(["sweep", str(_scene(tmp_path, "")), "--out", str(tmp_path / "o"), "--workers", "999"]) == 0
    assert captured[-1]["workers"] == 2
    capsys.readouterr()
    assert main(["sweep", str(_scene(tmp_path, "")), "--out", str(tmp_path / "o"), "--workers", "2"]) == 0
    assert captured[-1]["workers"] == 2 and "capped" not in capsys.readouterr().err


def test_scene_settings_drive_a_real_hertz_sweep(tmp_path, capsys):
    out = tmp_path / "o"
    assert main(["sweep", str(_scene(tmp_path, SETTINGS)), "--out", str(out), "--progress", "off"]) == 0
    with np.load(out / "sweep.npz") as z:
        assert np.degrees(z["theta"]) == pytest.approx([0, 10, 20, 30])
    assert not (out / "plots").exists() and not (out / "sweep.pvd").exists()
