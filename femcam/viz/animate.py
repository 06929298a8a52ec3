"""Animated GIF of a field over cam angle from a sweep's ``sweep.pvd`` (pyvista off-screen).

One frame per ``.vtu`` of the series (the cam angles of ``--vtk-every``), drawn around the
contact with one colour scale for all frames (0 to the largest value of the series), so the
frames compare. Written with matplotlib's Pillow writer: no video codec needed.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import InputError
from ._mpl import pyplot


def _frames(pvd: Path, scalar: str):
    """``[(theta_deg, mesh)]`` of the series, in angle order."""
    import pyvista as pv  # lazy: pyvista/VTK is heavy and only the rendering needs it

    reader = pv.get_reader(str(pvd))
    out = []
    for t in reader.time_values:
        reader.set_active_time_value(t)
        m = reader.read()
        m = m.combine() if isinstance(m, pv.MultiBlock) else m
        if scalar not in m.point_data:
            raise InputError(f"scalar = {scalar!r}: not a point array of {pvd} (has "
                             f"{', '.join(sorted(m.point_data.keys()))})")
        out.append((float(t), m))
    return out


def animate_pvd(pvd, path, *, scalar: str = "von_mises_Pa", window: float = 3.0,
                size=(640, 480), frame_s: float = 0.25) -> str:
    """Render ``scalar`` at every angle of ``pvd`` to an animated GIF.

    Parameters
    ----------
    pvd : str or Path
        A sweep's ``sweep.pvd``.
    path : str or Path
        Output ``.gif``.
    scalar : str
        Point array to colour by (Pa arrays are shown in MPa).
    window : float
        Half-size of the view in units of the largest contact half-width of the series
        (where ``contact_pressure_Pa > 0``; the whole mesh if there is none).
    size : (int, int)
        Frame size in pixels.
    frame_s : float
        Seconds per frame.

    Returns
    -------
    str
        The path written.
    """
    import pyvista as pv  # lazy: pyvista/VTK is heavy and only the rendering needs it
    from matplotlib.animation import PillowWriter  # lazy: matplotlib is heavy; writes the GIF

    frames = _frames(Path(pvd), scalar)
    if not frames:
        raise InputError(f"pvd = {pvd}: the series has no .vtu files (use --vtk-every > 0)")
    mpa = scalar.endswith("_Pa")
    vmax = max(float(np.max(np.abs(m.point_data[scalar]))) for _, m in frames) * (1e-6 if mpa else 1)
    half = [np.max(np.abs(m.points[m.point_data["contact_pressure_Pa"] > 0, 0]), initial=0.0)
            for _, m in frames if "contact_pressure_Pa" in m.point_data]
    L = window * max(half, default=0.0)
    label = scalar.removesuffix("_Pa") + (" (MPa)" if mpa else "")
    images = []
    for t, m in frames:
        m = m.copy()
        m.point_data[label] = np.asarray(m.point_data[scalar]) * (1e-6 if mpa else 1.0)
        if L > 0:
            m = m.clip_box([-L, L, -L, L, -1.0, 1.0], invert=False)
        pl = pv.Plotter(off_screen=True, window_size=list(size))
        pl.add_mesh(m, scalars=label, cmap="viridis", clim=[0.0, vmax],
                    scalar_bar_args={"title": label, "vertical": False})
        pl.add_text(f"cam angle {t:.1f} deg", font_size=10, position="upper_left")
        pl.view_xy()
        images.append(pl.screenshot(return_img=True))
        pl.close()
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    plt = pyplot()
    h, w = images[0].shape[:2]
    fig = plt.figure(figsize=(w / 100, h / 100), dpi=100)
    ax = fig.add_axes([0, 0, 1, 1])
    ax.set_axis_off()
    shown = ax.imshow(images[0])
    writer = PillowWriter(fps=1.0 / frame_s)
    with writer.saving(fig, str(path), dpi=100):
        for img in images:
            shown.set_data(img)
            writer.grab_frame()
    plt.close(fig)
    return str(path)
