"""Plot layout: no legend over the data (every legend lies outside its axes), no label cut off
(every axis label and title inside the figure), the rho clip value stated, and the von Mises
render draws the mm axes it names. The reference is geometry: the rendered bounding boxes."""

from pathlib import Path

import numpy as np
import pytest

import femcam.viz.analytic as va
import femcam.viz.wear as vw
from femcam.scene import load_scene
from femcam.wear.scene import scene_wear

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.fixture(scope="module")
def case():
    sc = load_scene(EXAMPLES / "seed002_study_model.toml")
    theta = np.radians(np.arange(0.0, 360.0, 2.0))
    wm, st, _ = scene_wear(sc, theta, cycles=1e6)
    return sc, st, wm


@pytest.fixture
def figures(monkeypatch):
    """Every figure the plot functions save (still drawable after pyplot closes it)."""
    figs = []
    for mod in (va, vw):
        real = mod._save

        def keep(fig, path, *a, _real=real, **k):
            figs.append(fig)
            return _real(fig, path, *a, **k)

        monkeypatch.setattr(mod, "_save", keep)
    return figs


def _check_layout(fig):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    canvas = FigureCanvasAgg(fig)  # pyplot has closed the figure: draw it on a fresh canvas
    canvas.draw()
    r = canvas.get_renderer()
    W, H = fig.bbox.width, fig.bbox.height
    legends = [ax.get_legend() for ax in fig.axes if ax.get_legend()] + list(fig.legends)
    assert legends, "each checked plot has a legend"
    for lg in legends:
        lb = lg.get_window_extent(r)
        for other in fig.axes:  # over no axes at all (so over no data)
            assert not lb.overlaps(other.get_window_extent(r)), (lg.texts[0].get_text(), other)
        assert lb.x0 >= -1 and lb.x1 <= W + 1 and lb.y0 >= -1 and lb.y1 <= H + 1
    for ax in fig.axes:
        for t in (ax.xaxis.label, ax.yaxis.label, ax.title):
            if t.get_text():
                b = t.get_window_extent(r)
                assert b.x0 >= -1 and b.x1 <= W + 1 and b.y0 >= -1 and b.y1 <= H + 1, t.get_text()


def test_wear_plots_layout(case, figures, tmp_path):
    sc, st, wm = case
    vw.plot_wear_map(wm, tmp_path / "w.png", title="seed002 (bezier5)", follower_label="roller arc")
    vw.plot_wear_polar(wm, st.profile.x, st.profile.y, tmp_path / "p.png", title="seed002")
    vw.plot_wear_comparison({"a": wm, "b": wm}, tmp_path / "c.png", title="seed002")
    assert len(figures) == 3
    for fig in figures:
        _check_layout(fig)


def test_analytic_plots_layout(case, figures, tmp_path):
    sc, st, _ = case
    va.plot_rho(st, tmp_path / "rho.png", Rr=sc.follower.Rr)
    va.plot_cam(st, tmp_path / "cam.png")
    va.plot_laws(tmp_path / "laws.png", n=51)
    for fig in figures:
        _check_layout(fig)


def test_rho_clip_is_stated(case, figures, tmp_path):
    _, st, _ = case
    va.plot_rho(st, tmp_path / "rho.png")
    rho_mm = np.asarray(st.rho) * 1e3
    clip = 4.0 * np.median(rho_mm[rho_mm > 0])  # the documented rule, computed here
    ax = figures[0].axes[0]
    shown = ax.lines[0].get_ydata()
    assert np.max(np.abs(shown)) == pytest.approx(clip, rel=1e-12)
    assert any(f"|rho| > {clip:.3g} mm clipped" in t.get_text() for t in ax.get_legend().texts)


@pytest.mark.slow
def test_von_mises_png_draws_mm_axes(tmp_path, monkeypatch):
    pv = pytest.importorskip("pyvista")
    from femcam.fe import MeshOptions, solve_contact
    from femcam.materials import STEEL
    from femcam.viz.fe import plot_von_mises

    seen = {}
    real = pv.Plotter.show_bounds

    def spy(self, *a, **k):
        seen.update(k)
        return real(self, *a, **k)

    monkeypatch.setattr(pv.Plotter, "show_bounds", spy)
    r = solve_contact(1500.0, 0.02, 0.01, STEEL, STEEL, 0.01, mesh=MeshOptions(a_over_h=6))
    plot_von_mises(r, tmp_path / "vm.png", size=(400, 300))
    assert seen["xtitle"] == "x (mm)" and seen["ytitle"] == "y (mm)"
