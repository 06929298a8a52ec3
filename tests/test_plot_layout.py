"""Plot layout: no legend over the data (every legend lies outside its axes), no label cut off
(every axis label and title inside the figure), the rho clip value stated, and the von Mises
render draws the mm axes it names. The reference is geometry: the rendered bounding boxes."""

from pathlib import Path

import numpy as np
import pytest

import femcam.viz.analytic as va
import femcam.viz.wear as vw
from femcam.scene import contact_case, load_scene
from femcam.wear.scene import scene_wear

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.fixture(scope="module")
def case():
    sc = load_scene(EXAMPLES / "seed002_study_model.toml")
    theta = np.radians(np.arange(0.0, 360.0, 2.0))
    wm, st, _ = scene_wear(contact_case(sc, theta), cycles=1e6)
    return sc, st, wm


@pytest.fixture
def figures(monkeypatch):
    """Every figure the plot functions save (still drawable after pyplot closes it)."""
    figs = []
    for mod in (va, vw):
        name = "_save" if hasattr(mod, "_save") else "save"  # the module's own saving function
        real = getattr(mod, name)

        def keep(fig, path, *a, _real=real, **k):
            figs.append(fig)
            return _real(fig, path, *a, **k)

        monkeypatch.setattr(mod, name, keep)
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


@pytest.mark.slow  # ~1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_wear_plots_layout(case, figures, tmp_path):
    sc, st, wm = case
    vw.plot_wear_map(wm, tmp_path / "w.png", title="seed002 (bezier5)", follower_label="roller arc")
    vw.plot_wear_polar(wm, st.profile.x, st.profile.y, tmp_path / "p.png", title="seed002")
    vw.plot_wear_comparison({"a": wm, "b": wm}, tmp_path / "c.png", title="seed002")
    assert len(figures) == 3
    for fig in figures:
        _check_layout(fig)


@pytest.mark.slow  # ~1 s; the default suite keeps its budget (CI runs it in the slow pass)
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


def test_worn_profile_draws_the_depth_above_the_floor():
    """On a circle of radius R (counter-clockwise) with depth h(s) = h0 + A (1 + cos(s / R)), the
    worn curve at magnification m and floor h0 has radius R - m A (1 + cos(s / R)) (closed form):
    the least-worn point lies on the profile, the deepest is moved by m (h_max - h0)."""
    from types import SimpleNamespace
    R, h0, A, n = 10e-3, 1e-6, 0.2e-6, 720
    t = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    s = R * t
    wm = SimpleNamespace(x_cam=s, depth_cam=h0 + A * (1 + np.cos(t)), cycles=1.0, perimeter=2 * np.pi * R)
    m = 0.05 * 2 * R / (2 * A)
    xw, yw = vw.worn_profile(wm, R * np.cos(t), R * np.sin(t), m, floor=h0)
    ref = R - m * A * (1 + np.cos(t))
    # the normal from central differences of a regular polygon is radial (exact to rounding);
    # one-sided at the two ends, tilted by half a step (pi / n): a radial error below that
    # tilt times the offset there
    r = np.hypot(xw, yw)
    np.testing.assert_allclose(r[1:-1], ref[1:-1], rtol=0, atol=1e-9 * m * 2 * A)
    np.testing.assert_allclose(r[[0, -1]], ref[[0, -1]], rtol=0, atol=np.pi / n * m * 2 * A)
    assert r[1:-1].max() == pytest.approx(R, abs=1e-9 * m * 2 * A), "least worn on the profile"


def test_halfspace_extras_plot_says_what_it_shows(tmp_path, monkeypatch):
    """The finite-length extras plot: a title naming what it shows, every y axis a quantity with
    its unit in parentheses, the x axis the cam angle in degrees."""
    import femcam.viz.extras as ve
    from femcam.sweep.extras import plot_extras

    figs = []
    real = ve.save

    def keep(fig, path, *a, **k):
        figs.append(fig)
        return real(fig, path, *a, **k)

    monkeypatch.setattr(ve, "save", keep)
    sc = load_scene(EXAMPLES / "seed002_crowned.toml")
    theta = np.radians(np.arange(0.0, 360.0, 30.0))
    one = np.ones_like(theta)
    table = {"theta": theta, "status": np.array(["ok"] * theta.size), "hs_p_axial_peak": 2e9 * one,
             "p0_hertz": 1e9 * one, "p0_peak_slice": 1.1e9 * one, "hs_w_max": 3e5 * one}
    paths = plot_extras(sc, table, tmp_path)
    assert "plot_extras_halfspace" in paths and len(figs) == 1
    fig = figs[0]
    assert "finite-length contact along the roller" in fig._suptitle.get_text()
    labels = [ax.get_ylabel() for ax in fig.axes]
    assert labels == ["peak pressure (MPa)", "most loaded slice\nw_max (N/mm)"]
    assert fig.axes[-1].get_xlabel() == "cam angle (deg)"
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    FigureCanvasAgg(fig).draw()
    r = fig.canvas.get_renderer()
    W, H = fig.bbox.width, fig.bbox.height
    for t in [fig._suptitle] + [ax.yaxis.label for ax in fig.axes]:  # nothing cut off
        b = t.get_window_extent(r)
        assert b.x0 >= -1 and b.x1 <= W + 1 and b.y0 >= -1 and b.y1 <= H + 1, t.get_text()
