"""Finite-length contact plots (matplotlib, imported inside the functions): the pressure map
p(x, y) of one angle, the peak pressure along the length against cam angle for several crowns,
and the crown comparison (pressure along the length, and peak against misalignment).

They draw what :mod:`femcam.halfspace` computed (a ``StripResult`` or the dict of
:func:`~femcam.halfspace.rows.finite_length_rows`); they never call the solver."""

from __future__ import annotations

import numpy as np

from ._mpl import pyplot, save


def plot_pressure_map(res, path, *, title: str = ""):
    """Contour map of ``res.p`` (MPa) over rolling ``x`` and axial ``y`` (mm) of a
    :class:`~femcam.halfspace.strip.StripResult`, with the pressure along the length below.

    Parameters
    ----------
    res : femcam.halfspace.strip.StripResult
        Pressure ``p`` (Pa) on the ``x``, ``y`` grid (m).
    path : str or os.PathLike
        Output PNG.
    title : str
        Figure title.

    Returns
    -------
    str or pathlib.Path
        ``path`` as given.
    """
    plt = pyplot()
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(6.8, 6.0), height_ratios=[2, 1], sharex=True)
    Y, X = np.meshgrid(res.y * 1e3, res.x * 1e3)
    cs = ax1.contourf(Y, X, res.p * 1e-6, levels=24, cmap="inferno")
    fig.colorbar(cs, ax=ax1, label="p (MPa)")
    loaded = np.any(res.p > 0, axis=1)
    if loaded.any():
        xm = np.abs(res.x[loaded]).max() * 1e3
        ax1.set_ylim(-1.3 * xm, 1.3 * xm)
    ax1.set_ylabel("rolling x (mm)")
    ax1.set_title(title or f"peak {res.p_max * 1e-6:.0f} MPa at y = {res.y_peak * 1e3:.2f} mm", fontsize=9)
    ax2.plot(res.y * 1e3, res.p_line * 1e-6, label="peak pressure of each slice")
    ax2b = ax2.twinx()
    ax2b.plot(res.y * 1e3, res.w * 1e-3, "C1--", label="slice load")
    ax2.set_xlabel("axial y (mm)")
    ax2.set_ylabel("p_max(y) (MPa)")
    ax2b.set_ylabel("w(y) (N/mm)", color="C1")
    h1, l1 = ax2.get_legend_handles_labels()
    h2, l2 = ax2b.get_legend_handles_labels()
    ax2.legend(h1 + h2, l1 + l2, fontsize=8, loc="lower center")
    save(fig, path, dpi=90, tight=True)
    return path


def plot_peak_along_length(rows_by_crown: dict, path, *, p0_2d=None, title: str = ""):
    """Top: the peak pressure along the length ``p_line`` (MPa) as a map over cam angle and
    axial position, one panel per crown; bottom: the axial peak against cam angle for every crown
    (and the 2D Hertz ``p0_2d`` (Pa), if given). ``rows_by_crown``: label -> rows dict.

    Parameters
    ----------
    rows_by_crown : dict of str to dict
        Crown label -> :func:`~femcam.halfspace.rows.finite_length_rows` dict (SI).
    path : str or os.PathLike
        Output PNG.
    p0_2d : array_like, optional
        2D Hertz peak pressure per angle (Pa).
    title : str
        Figure title.

    Returns
    -------
    str or pathlib.Path
        ``path`` as given.
    """
    plt = pyplot()
    n = len(rows_by_crown)
    fig = plt.figure(figsize=(3.0 * n + 1.0, 6.4))
    gs = fig.add_gridspec(2, n, height_ratios=[1.2, 1])
    vmax = max(np.nanmax(r["p_line"]) for r in rows_by_crown.values()) * 1e-6
    ax_b = fig.add_subplot(gs[1, :])
    for k, (name, r) in enumerate(rows_by_crown.items()):
        ax = fig.add_subplot(gs[0, k])
        th = np.degrees(r["theta"])
        im = ax.pcolormesh(r["y"] * 1e3, th, r["p_line"] * 1e-6, vmin=0, vmax=vmax, cmap="inferno",
                           shading="nearest")
        ax.set_title(name, fontsize=9)
        ax.set_xlabel("axial y (mm)")
        if k == 0:
            ax.set_ylabel("cam angle (deg)")
        ax_b.plot(th, r["p_axial_peak"] * 1e-6, label=name)
    fig.colorbar(im, ax=fig.axes[1:], label="peak pressure along the length (MPa)", shrink=0.8)
    if p0_2d is not None:
        th = np.degrees(next(iter(rows_by_crown.values()))["theta"])
        ax_b.plot(th, np.asarray(p0_2d) * 1e-6, "k:", label="2D Hertz p0 (w = Fc / L)")
    ax_b.set_xlabel("cam angle (deg)")
    ax_b.set_ylabel("axial peak p (MPa)")
    ax_b.legend(fontsize=8, ncol=4)
    if title:
        fig.suptitle(title, fontsize=10)
    save(fig, path, dpi=90)
    return path


def plot_crown_comparison(y, p_line_by_crown: dict, tilt_deg, peak_by_crown: dict, path, *,
                          p0_2d=None, title: str = ""):
    """Left: pressure along the length (MPa) at one angle for each crown; right: the axial peak
    (MPa) against misalignment (deg) for each crown. ``y`` in m, pressures in Pa.

    Parameters
    ----------
    y : array_like
        Axial positions (m).
    p_line_by_crown : dict of str to array_like
        Crown label -> pressure along the length at one angle (Pa).
    tilt_deg : array_like
        Misalignment angles (deg).
    peak_by_crown : dict of str to array_like
        Crown label -> axial peak pressure per misalignment (Pa).
    path : str or os.PathLike
        Output PNG.
    p0_2d : float, optional
        2D Hertz peak pressure (Pa), drawn as a reference.
    title : str
        Figure title.

    Returns
    -------
    str or pathlib.Path
        ``path`` as given.
    """
    plt = pyplot()
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10.0, 4.0))
    for name, pl in p_line_by_crown.items():
        ax1.plot(np.asarray(y) * 1e3, np.asarray(pl) * 1e-6, label=name)
    for name, pk in peak_by_crown.items():
        ax2.plot(tilt_deg, np.asarray(pk) * 1e-6, "o-", label=name)
    if p0_2d is not None:
        for ax in (ax1, ax2):
            ax.axhline(p0_2d * 1e-6, color="k", ls=":", lw=1, label="2D Hertz p0")
    ax1.set_xlabel("axial y (mm)")
    ax1.set_ylabel("peak pressure of the slice (MPa)")
    ax1.set_title("aligned roller, worst angle", fontsize=9)
    ax2.set_xlabel("misalignment (deg)")
    ax2.set_ylabel("axial peak pressure (MPa)")
    ax2.set_title("peak vs roller tilt, worst angle", fontsize=9)
    for ax in (ax1, ax2):
        ax.legend(fontsize=8)
    if title:
        fig.suptitle(title, fontsize=10)
    save(fig, path, dpi=90, tight=True)
    return path
