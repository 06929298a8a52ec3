"""Plots of the real bodies: ring hoop stress picture (pyvista, off-screen) and the bore stress
and contact change against the ring wall (matplotlib). They draw computed results only."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ._mpl import pyplot, save


def plot_hoop(vtu_path, path, *, size=(760, 700), body: int = 1, clim=None):
    """Render the hoop stress (MPa) of the ring (``body`` id 1) from a VTU written by
    :func:`femcam.io.write_ring_vtu` to a PNG; returns the path.

    Parameters
    ----------
    vtu_path : str or os.PathLike
        The ring's ``.vtu`` (stresses in Pa).
    path : str or os.PathLike
        Output PNG.
    size : (int, int)
        Image size (pixels).
    body : int
        ``body`` id of the cells drawn (1: the ring).
    clim : (float, float), optional
        Colour range (MPa; default: the data range).

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    import pyvista as pv  # heavy optional dependency: only for rendering

    grid = pv.read(str(vtu_path))
    grid.points = grid.points * 1e3  # mm
    part = grid.extract_cells(np.nonzero(grid.cell_data["body"] == body)[0])
    part.point_data["hoop (MPa)"] = part.point_data["hoop"] / 1e6
    pl = pv.Plotter(off_screen=True, window_size=list(size))
    pl.add_mesh(part, scalars="hoop (MPa)", cmap="coolwarm", clim=clim,
                scalar_bar_args={"title": "ring hoop stress (MPa)", "vertical": False,
                                 "position_x": 0.2, "position_y": 0.02, "width": 0.6})
    pl.view_xy()
    pl.add_text("ring hoop stress; cam contact at the bottom", font_size=10)
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    pl.screenshot(str(path))
    pl.close()
    return path


def plot_wall_study(studies: dict, path, *, title: str = ""):
    """Bore hoop stress (MPa) and the cam-contact change (p0, a vs the solid roller, %) against
    the ring wall (mm). ``studies``: ``{label: femcam.bodies.study.wall_study(...) dict}``.

    Parameters
    ----------
    studies : dict
        ``{label: femcam.bodies.study.wall_study(...) dict}`` (SI).
    path : str or os.PathLike
        Output PNG.
    title : str
        Figure title.

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    plt = pyplot()
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    for label, s in studies.items():
        w = s["wall"] * 1e3
        ax1.plot(w, s["hoop_max"] / 1e6, "o-", label=label)
        ax2.plot(w, 100 * (s["p0"] / s["p0_solid"] - 1), "o-", label=f"p0, {label}")
        ax2.plot(w, 100 * (s["a"] / s["a_solid"] - 1), "s--", label=f"a, {label}")
    ax1.set_xlabel("ring wall Ro - Ri (mm)")
    ax1.set_ylabel("max tensile bore hoop stress (MPa)")
    ax1.grid(True, alpha=0.3)
    ax1.legend()
    ax2.set_xlabel("ring wall Ro - Ri (mm)")
    ax2.set_ylabel("cam contact vs solid roller (%)")
    ax2.axhline(0.0, color="k", lw=0.5)
    ax2.grid(True, alpha=0.3)
    ax2.legend(fontsize=8)
    if title:
        fig.suptitle(title)
    return save(fig, path, dpi=110, tight=True)
