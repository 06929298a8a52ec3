"""The sweep's plot process (femcam.viz.process): the plots it draws are those the sweep
drew in its own process, and a plot process that fails or is killed loses no other output and
says so in one warning.

References are independent of the plot process: the plots drawn in-process by
:func:`femcam.viz.sweep.plot_sweep` (same bytes: same matplotlib, same data), and the files a
sweep without plots writes.
"""

from __future__ import annotations

import dataclasses
import os
import sys

import pytest

import femcam.viz.sweep as vs
from femcam.scene import load_scene
from femcam.sweep import RunOptions, SweepOptions, sweep
from femcam.viz._mpl import pyplot
from femcam.viz.process import PlotProcess, start_plot_process
from femcam.viz.sweep import plot_sweep

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="fork: Linux only")

SCENE = "examples/seed002_study_model.toml"
pyplot()  # imported here once: every forked lane inherits it (the tests stay short)
HERTZ = SweepOptions(angles=[0.0, 0.5, 1.0, 1.5], method="hertz", vtk_every=0)


def _boom(*_):
    raise ValueError("no ink")


def _die(*_):
    os._exit(3)


def test_answers_errors_and_a_killed_child_in_order():
    """One lane: each call's paths come back in the order sent; a failing call is one line; a
    child that dies mid-way is reported with its exit code and the answers before it are kept."""
    p = PlotProcess(lanes=1)
    p.submit(dict, {"a": "1"})
    p.submit(_boom)
    p.submit(dict, {"b": "2"})
    paths, error = p.collect()
    assert list(paths.items()) == [("a", "1"), ("b", "2")]
    assert error == "_boom: ValueError: no ink"
    p = PlotProcess(lanes=1)
    p.submit(dict, {"a": "1"})
    p.submit(_die)
    p.submit(dict, {"b": "2"})
    paths, error = p.collect()
    assert paths == {"a": "1"} and error == "a plot process ended early (exit code 3)"


def test_two_lanes_keep_the_order_and_survive_each_other():
    """Two lanes: calls go to the less loaded lane, answers come back in the order submitted,
    and a lane that dies loses only its own calls."""
    p = start_plot_process()
    for k, w in (("a", 1.0), ("b", 3.0), ("c", 1.0), ("d", 1.0)):  # lanes 0, 1, 0, 0
        p.submit(dict, {k: k}, weight=w)
    paths, error = p.collect()
    assert list(paths) == ["a", "b", "c", "d"] and error == ""
    for lane_die in (0, 1):
        p = PlotProcess()
        p.submit(dict, {"a": "1"}) if lane_die else p.submit(_die)   # lane 0
        p.submit(_die) if lane_die else p.submit(dict, {"a": "1"})   # lane 1
        p.submit(dict, {"b": "2"}, weight=0.5)                      # lane 0 or 1: the lighter
        paths, error = p.collect()
        assert "a" in paths and "ended early" in error, (lane_die, paths, error)


@pytest.mark.slow
def test_plots_equal_those_drawn_in_process(tmp_path):
    """The PNGs of a sweep (drawn by the plot process) equal, byte for byte, those
    plot_sweep draws in this process from the same result."""
    r = sweep(load_scene(SCENE), HERTZ, RunOptions(out=tmp_path / "a", progress=False))
    assert r.surface_profile is not None
    again = plot_sweep(r, tmp_path / "b")
    assert {k: os.path.basename(v) for k, v in again.items()} == {
        k: os.path.basename(v) for k, v in r.paths.items() if k.startswith("plot_")}
    for k, v in again.items():
        assert open(v, "rb").read() == open(r.paths[k], "rb").read(), k


def test_killed_plot_process_loses_no_other_output(tmp_path, monkeypatch):
    """A lane dies while drawing (its plot function ends the process): the tables and the
    reports are written as without plots, the other lane's plots are kept (and only they are
    in the report), one warning names the missing plots and the command that redraws them."""
    monkeypatch.setattr(vs, "plot_maxima", _die)  # the forked child inherits the patch
    with pytest.warns(RuntimeWarning, match=r"some plots are missing: .*ended early.*femcam plot"):
        r = sweep(load_scene(SCENE), HERTZ, RunOptions(out=tmp_path / "o", progress=False))
    bare = sweep(load_scene(SCENE), dataclasses.replace(HERTZ, plots=False),
                 RunOptions(out=tmp_path / "bare", progress=False))
    for f in ("sweep.csv", "sweep.npz", "report.md", "report.html"):
        assert (tmp_path / "o" / f).stat().st_size > 0
    assert {k for k in r.paths if not k.startswith("plot_")} == set(bare.paths)
    kept = sorted(p.name for p in (tmp_path / "o" / "plots").iterdir())
    assert "p0_vs_angle.png" in kept and "maxima_vs_angle.png" not in kept
    assert kept == sorted(os.path.basename(v) for k, v in r.paths.items() if k.startswith("plot_"))
    html = (tmp_path / "o" / "report.html").read_text()
    assert all(name in html for name in kept) and "maxima_vs_angle.png" not in html


def test_early_svaj_plot_is_drawn_again_when_the_table_differs(tmp_path, monkeypatch):
    """svaj_loads.png is sent to the plot process before the solves (from the analytic chain's
    columns); if the finished table's columns differ, it is drawn again from the table: the
    PNG equals the one plot_sweep draws in this process from the result."""
    import numpy as np

    from femcam.sweep import outputs

    real = outputs.svaj_columns

    def off(scene, theta):   # columns unlike the table's: the early plot must not stand
        cols = real(scene, theta)
        return {**cols, "s": 2.0 * cols["s"] + 1e-3}

    monkeypatch.setattr(outputs, "svaj_columns", off)
    r = sweep(load_scene(SCENE), HERTZ, RunOptions(out=tmp_path / "a", progress=False))
    again = plot_sweep(r, tmp_path / "b")
    got = open(r.paths["plot_svaj"], "rb").read()
    assert got == open(again["plot_svaj"], "rb").read()
    assert list(k for k in r.paths if k.startswith("plot_")) == list(again)   # the report's order
    assert np.array_equal(real(load_scene(SCENE), r.table["theta"])["s"], r.table["s"])


def test_long_sweep_sends_no_early_svaj_plot(tmp_path):
    """From STREAM_ANGLES angles on the analytic chain is computed in blocks (memory bound):
    early_plots computes no whole-sweep columns and sends nothing; below it, the plot is sent."""
    from types import SimpleNamespace

    import numpy as np

    from femcam.sweep import outputs
    from femcam.sweep.store import STREAM_ANGLES

    sent = []
    plotter = SimpleNamespace(submit=lambda *a, **k: sent.append(a[1]) or 0)
    scene = load_scene(SCENE)
    long_run = SimpleNamespace(plotter=plotter, out=tmp_path, scene=scene, early={},
                               angles=np.linspace(0.0, 2 * np.pi, STREAM_ANGLES, endpoint=False))
    outputs.early_plots(long_run)
    assert sent == [] and long_run.early == {}
    short_run = SimpleNamespace(**{**vars(long_run), "angles": np.linspace(0.0, 1.0, 4), "early": {}})
    outputs.early_plots(short_run)
    assert sent == ["plot_svaj"] and set(short_run.early) == {"plot_svaj"}
