"""Off-screen pyvista rendering of an FE contact solution (von Mises near the contact)."""

from __future__ import annotations

from pathlib import Path

from ..fe.export import scene_arrays


def plot_von_mises(result, path, *, window: float = 3.0, size=(760, 640), scalar: str = "von_mises",
                   show_edges: bool = False):
    """Render ``scalar`` (default von Mises, shown in MPa) over ``|x|, |y| <= window * a`` to a PNG.

    ``result`` is a :class:`femcam.fe.ContactResult`; the x and y axes are drawn with their
    ticks in mm. Returns the path.

    Parameters
    ----------
    result : femcam.fe.ContactResult
        The FE solution with its full fields (Pa, m).
    path : str or os.PathLike
        Output PNG.
    window : float
        Half-size of the view in contact half-widths a (-).
    size : (int, int)
        Image size (pixels).
    scalar : str
        Point field to draw (Pa fields shown in MPa).
    show_edges : bool
        Draw the mesh edges.

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    import pyvista as pv  # lazy: pyvista/VTK is heavy and only this rendering needs it

    points, cells, cell_type, data, body = scene_arrays(result)
    ctype = pv.CellType.QUADRATIC_TRIANGLE if cell_type == "triangle6" else pv.CellType.TRIANGLE
    grid = pv.UnstructuredGrid({ctype: cells}, points * 1e3)  # mm
    grid.point_data[f"{scalar} (MPa)"] = data[scalar] / 1e6
    a = (result.a if result.a > 0 else result.model.a_ref) * 1e3
    L = window * a
    clip = grid.clip_box([-L, L, -L, L, -1.0, 1.0], invert=False)
    pl = pv.Plotter(off_screen=True, window_size=list(size))
    pl.add_mesh(clip, scalars=f"{scalar} (MPa)", cmap="viridis", show_edges=False,
                scalar_bar_args={"title": f"{scalar.replace('_', ' ')} (MPa)", "vertical": True,
                                   "position_x": 0.86, "position_y": 0.2, "height": 0.6, "width": 0.08})
    if show_edges:
        pl.add_mesh(clip.extract_all_edges(), color="white", opacity=0.08, line_width=0.5)
    pl.add_text(f"F = {result.F:g} N, rho = {result.rho * 1e3:g} mm, mu = {result.mu:g}, "
                f"a = {result.a * 1e3:.4f} mm, p0 = {result.p0 / 1e6:.0f} MPa",
                font_size=9, position="upper_left")
    pl.show_bounds(mesh=clip, xtitle="x (mm)", ytitle="y (mm)", ztitle="z", show_zaxis=False,
                   show_zlabels=False, location="outer", ticks="outside", font_size=10, fmt="%.2f")
    pl.view_xy()
    pl.camera.zoom(0.95)  # room for the axis labels
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    pl.screenshot(str(path))
    pl.close()
    return path


