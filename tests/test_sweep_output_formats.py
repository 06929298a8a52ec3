"""Output formats a user reads back: text columns that numpy reads as text, integer NPZ columns,
and the resume refusal naming only what differs."""

from pathlib import Path

import numpy as np
import pytest

from femcam.errors import InputError
from femcam.scene import load_scene
from femcam.sweep import RunOptions, SweepOptions, SweepResult, sweep

SCENE = Path(__file__).resolve().parents[1] / "examples" / "seed002_study_model.toml"


@pytest.fixture(scope="module")
def hertz_sweep(tmp_path_factory):
    out = tmp_path_factory.mktemp("h") / "out"
    res = sweep(SCENE,
                SweepOptions(angles=np.radians(np.arange(0.0, 360.0, 30.0)),  method="hertz",  vtk_every=0,
                             plots=False),
                RunOptions(out=out, progress=False, workers=1))
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
    sweep(SCENE,
          SweepOptions(angles=theta, method="hertz", vtk_every=0, plots=False),
          RunOptions(out=out, progress=False, workers=1))
    with pytest.raises(InputError) as info:  # same angles and chunks, another tolerance
        sweep(SCENE,
              SweepOptions(angles=theta, method="hertz", tolerance=5e-3, vtk_every=0, plots=False),
              RunOptions(out=out, resume=True, progress=False, workers=1))
    msg = str(info.value)
    assert "tolerance" in msg and "chunk bounds" not in msg, msg


def test_report_wear_depth_has_significant_digits(hertz_sweep):
    """seed 002's wear depth per revolution is ~1.6e-5 nm: the report shows 3 significant digits
    (it read "0.000" with a fixed 3-decimal format); the number itself is validated against
    Archard's closed form in test_sweep.py::test_wear_column_is_archard_per_pass_closed_form."""
    out, res = hertz_sweep
    lines = (out / "report.md").read_text().splitlines()
    line = next(ln for ln in lines if "wear depth per revolution" in ln)
    shown = float(line.split("|")[2])
    want = float(np.nanmax(res.table["wear_depth"])) * 1e9
    assert 0 < want < 1e-3
    assert shown == pytest.approx(want, rel=5e-3)  # 3 significant digits: rounding <= 0.5e-2


def test_families_text_singular_and_no_nan():
    from femcam.sweep.result import families_text

    assert families_text(1, 1.2e-4).startswith("1 model family, reuse error <= 0.012 %")
    assert families_text(3, 1.2e-4).startswith("3 model families,")
    for n, err in ((0, float("nan")), (0, 0.0)):
        t = families_text(n, err)
        assert "nan" not in t and "no verified model families" in t


def test_legend_only_with_labelled_artists_and_wear_plot_of_axial_peak_rows(hertz_sweep, tmp_path):
    """No matplotlib 'No artists with labels' warning; the crowned (finite-length) sweep's wear
    rows (wear_source axial_peak) are drawn and labelled."""
    import warnings

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from femcam.viz._mpl import legend_outside
    from femcam.viz.sweep import plot_wear

    fig, ax = plt.subplots()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert legend_outside(ax) is None
    plt.close(fig)
    import dataclasses

    _, hs = hertz_sweep
    res = dataclasses.replace(hs, table={**hs.table, "wear_source": np.full(hs.n_angles, "axial_peak")})
    seen = {}
    real_legend = matplotlib.axes.Axes.legend

    def spy(self, *a, **kw):
        seen.setdefault("labels", []).extend(self.get_legend_handles_labels()[1])
        return real_legend(self, *a, **kw)

    matplotlib.axes.Axes.legend = spy
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", UserWarning)
            plot_wear(res, tmp_path / "w.png")
    finally:
        matplotlib.axes.Axes.legend = real_legend
    assert any("axial peak" in s for s in seen["labels"])


@pytest.mark.slow  # ~1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_long_sweep_table_stays_on_disk_and_writes_the_same_files(tmp_path, monkeypatch):
    """With at least STREAM_ANGLES angles and an output directory the table is read from the
    chunk files (memory bounded, benchmarks/bench_sweep_memory.py); lowered here to 1 so that a
    small sweep takes that path (and the analytic phase runs in blocks of 5 angles, as it does
    from ANALYTIC_BLOCK angles on). Reference: the closed-form Hertz p0 (Johnson 1985 eq. 4.45,
    written out below) at the requested angles, and the in-memory path's files."""
    from femcam.sweep import run
    from femcam.sweep.store import StoredTable

    th = np.radians(np.arange(0.0, 360.0, 7.0))
    opts = SweepOptions(angles=th, method="hertz", chunk_size=11, vtk_every=0, plots=False)
    mem = sweep(SCENE, opts, RunOptions(out=tmp_path / "mem", progress=False, workers=1))
    monkeypatch.setattr(run, "STREAM_ANGLES", 1)
    monkeypatch.setattr(run, "ANALYTIC_BLOCK", 5)  # the analytic phase in blocks, as from 20 000
    disk = sweep(SCENE, opts, RunOptions(out=tmp_path / "disk", progress=False, workers=1))
    assert isinstance(disk.table, StoredTable) and isinstance(mem.table, dict)
    sc = load_scene(SCENE)
    w = disk["Fc"] / sc.length
    R = 1.0 / (1.0 / disk["rho"] + 1.0 / sc.follower.Rr)
    E = 1.0 / ((1 - sc.cam.nu ** 2) / sc.cam.E + (1 - sc.roller.nu ** 2) / sc.roller.E)
    if sc.plane == "stress":
        E = 1.0 / (1.0 / sc.cam.E + 1.0 / sc.roller.E)
    p0 = 2 * w / (np.pi * np.sqrt(4 * w * R / (np.pi * E)))
    np.testing.assert_allclose(disk["theta"], th, rtol=0, atol=1e-15)
    np.testing.assert_allclose(disk["p0_hertz"], p0, rtol=1e-12)
    body = [[line for line in (tmp_path / d / "sweep.csv").read_text().splitlines()
             if not line.startswith("#")] for d in ("mem", "disk")]
    assert body[0] == body[1] and len(body[1]) == th.size + 1
    with np.load(tmp_path / "mem" / "sweep.npz") as a, np.load(tmp_path / "disk" / "sweep.npz") as b:
        cols = [k for k in a.files if k not in ("provenance_json",)]
        assert set(a.files) == set(b.files)
        for k in cols:
            np.testing.assert_array_equal(a[k], b[k], err_msg=k)


def test_analytic_phase_in_blocks_is_exact_with_follower_dynamics(monkeypatch):
    """The blocked analytic phase of long sweeps against one ``Scene.analyse`` call of all the
    angles, on a scene with a one-degree-of-freedom follower train (its periodic response is a
    whole-cycle computation, done once per scene and interpolated): identical arrays."""
    from femcam.sweep import run
    from femcam.sweep.realcam import contact_scene

    sc = contact_scene(load_scene(Path(SCENE).parent / "seed002_dynamic.toml"))
    assert sc.train is not None
    th = np.radians(np.arange(0.0, 360.0, 4.5))
    whole = sc.analyse(th)
    monkeypatch.setattr(run, "ANALYTIC_BLOCK", 7)
    blocks = run._analyse_in_blocks(sc, th)
    for k in ("theta", "s", "s1", "s2", "Fc", "rho", "liftoff"):
        np.testing.assert_array_equal(getattr(blocks, k), getattr(whole, k), err_msg=k)
