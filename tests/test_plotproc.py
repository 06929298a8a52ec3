"""The sweep's plot process (femcam.sweep.plotproc): the plots it draws are those the sweep
drew in its own process, and a plot process that fails or is killed loses no other output and
says so in one warning.

References are independent of the plot process: the plots drawn in-process by
:func:`femcam.viz.sweep.plot_sweep` (same bytes: same matplotlib, same data), and the files a
sweep without plots writes.
"""

from __future__ import annotations

import os
import sys

import pytest

import femcam.viz.sweep as vs
from femcam.scene import load_scene
from femcam.sweep import sweep
from femcam.sweep.plotproc import PlotProcess, start_plot_process
from femcam.viz.sweep import plot_sweep

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="fork: Linux only")

SCENE = "examples/seed002_study_model.toml"
HERTZ = dict(angles=[0.0, 0.5, 1.0, 1.5], method="hertz", vtk_every=0, progress=False)


def _boom(*_):
    raise ValueError("no ink")


def _die(*_):
    os._exit(3)


def test_answers_errors_and_a_killed_child_in_order():
    """Each call's paths come back in the order sent; a failing call is one line; a child that
    dies mid-way is reported with its exit code and the answers before it are kept."""
    p = PlotProcess()
    p.submit(dict, {"a": "1"})
    p.submit(_boom)
    p.submit(dict, {"b": "2"})
    paths, error = p.collect()
    assert paths == {"a": "1", "b": "2"}
    assert error == "_boom: ValueError: no ink"
    p = start_plot_process()
    p.submit(dict, {"a": "1"})
    p.submit(_die)
    p.submit(dict, {"b": "2"})
    paths, error = p.collect()
    assert paths == {"a": "1"} and "ended early (exit code 3)" in error


def test_plots_equal_those_drawn_in_process(tmp_path):
    """The PNGs of a sweep (drawn by the plot process) equal, byte for byte, those
    plot_sweep draws in this process from the same result."""
    r = sweep(load_scene(SCENE), out=tmp_path / "a", **HERTZ)
    assert r.surface_profile is not None
    again = plot_sweep(r, tmp_path / "b")
    assert {k: os.path.basename(v) for k, v in again.items()} == {
        k: os.path.basename(v) for k, v in r.paths.items() if k.startswith("plot_")}
    for k, v in again.items():
        assert open(v, "rb").read() == open(r.paths[k], "rb").read(), k


def test_killed_plot_process_loses_no_other_output(tmp_path, monkeypatch):
    """The child dies while drawing (its plot function ends the process): the tables and the
    reports are written as without plots, the plots drawn before it are kept, one warning
    names the missing plots and the command that redraws them."""
    monkeypatch.setattr(vs, "plot_maxima", _die)  # the forked child inherits the patch
    with pytest.warns(RuntimeWarning, match=r"some plots are missing: .*exit code 3.*femcam plot"):
        r = sweep(load_scene(SCENE), out=tmp_path / "o", **HERTZ)
    bare = sweep(load_scene(SCENE), out=tmp_path / "bare", plots=False, **HERTZ)
    for f in ("sweep.csv", "sweep.npz", "report.md", "report.html"):
        assert (tmp_path / "o" / f).stat().st_size > 0
    assert {k for k in r.paths if not k.startswith("plot_")} == set(bare.paths)
    assert sorted(p.name for p in (tmp_path / "o" / "plots").iterdir()) == ["p0_vs_angle.png"]
    assert "p0_vs_angle.png" in (tmp_path / "o" / "report.html").read_text()
