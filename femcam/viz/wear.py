"""Wear plots (matplotlib, imported inside the functions): depth against cam angle and arc
length, the follower (roller) depth, a polar view of the cam with the wear magnified, a
motion-law comparison, and the evolved vs linear depth of a profile evolution.

Each function documents its parameters and return value (numpydoc, with units).
"""

from __future__ import annotations

import numpy as np

from ._mpl import legend_outside, pyplot, save


def _save(fig, path, dpi: int = 90):
    """Lay out, write and close a figure; returns ``path``."""
    save(fig, path, dpi=dpi, tight=True)
    return path


def plot_wear_map(wm, path, *, title: str = "", follower_label: str | None = None):
    """Three panels: cam depth after ``wm.cycles`` revolutions vs cam angle (deg) and vs arc
    length (mm), and the follower (roller, face or tip) depth vs its surface coordinate (mm).

    On a roller the follower panel shows the depth after ``cycles`` with the contact's drift
    from one revolution to the next (``wm.depth_follower_cycles``) and the phase-locked bound
    ``cycles x`` one revolution's depth (dashed).

    Parameters
    ----------
    wm : femcam.wear.map.WearMap
        The wear map (depths in m per revolution, ``cycles``).
    path : str or os.PathLike
        Output PNG.
    title : str
        Figure title.
    follower_label : str, optional
        Label of the follower surface coordinate (default from the map).

    Returns
    -------
    str or pathlib.Path
        ``path`` as given.
    """
    plt = pyplot()
    fig, (ax1, ax2, ax3) = plt.subplots(3, 1, figsize=(8.4, 7.6))
    c = wm.cycles
    ax1.plot(np.degrees(wm.theta), wm.depth_at_theta * c * 1e6, label="map (moving Hertz ellipse)")
    ax1.plot(np.degrees(wm.theta), wm.depth_pass * c * 1e6, "--", label="closed form k w v_slip / V_cam")
    ax1.set_xlabel("cam angle theta (deg)")
    ax1.set_ylabel("cam depth (um)")
    ax1.set_title(f"cam wear depth after {c:g} revolutions", fontsize=9)
    legend_outside(ax1)
    ax2.plot(wm.x_cam * 1e3, wm.depth_cam * c * 1e6)
    ax2.axvline(wm.x_max * 1e3, color="r", lw=0.8)
    ax2.set_xlabel("cam arc length from the contact at theta = 0 (mm)")
    ax2.set_ylabel("cam depth (um)")
    ax2.set_title(f"cam: max {wm.max_depth * 1e6:.3g} um at arc {wm.x_max * 1e3:.2f} mm", fontsize=9)
    total = wm.depth_follower_total
    if wm.follower_period is not None:
        ax3.plot(wm.x_follower * 1e3, total * 1e6,
                 label=f"with drift {wm.follower_drift * 1e3:.3g} mm/rev")
        ax3.plot(wm.x_follower * 1e3, c * wm.depth_follower * 1e6, "--", lw=0.8,
                 label=f"{c:g} x one revolution (phase-locked bound)")
        legend_outside(ax3)
    else:
        ax3.plot(wm.x_follower * 1e3, total * 1e6)
    ax3.axvline(wm.x_max_follower * 1e3, color="r", lw=0.8)
    ax3.set_xlabel(f"follower: {follower_label or 'surface coordinate'} (mm)", fontsize=8)
    ax3.set_ylabel("follower depth (um)")
    ax3.set_title(f"follower: max {wm.max_depth_follower * 1e6:.3g} um at {wm.x_max_follower * 1e3:.2f} mm",
                  fontsize=9)
    if title:
        fig.suptitle(title, fontsize=10)
    return _save(fig, path)


def worn_profile(wm, x, y, magnify: float, floor: float = 0.0):
    """Cam-frame points of the profile moved inward by ``magnify x (depth - floor)`` (m).

    Parameters
    ----------
    wm : femcam.wear.map.WearMap
        The wear map (depths in m per revolution, ``cycles``).
    x, y : array_like
        Cam profile points in the cam frame (m), ordered along the profile.
    magnify : float
        Wear magnification factor (-).
    floor : float, optional
        Depth subtracted before magnifying (m; e.g. the smallest depth, so that the variation
        of the depth along the profile is drawn instead of a nearly uniform offset).

    Returns
    -------
    (ndarray, ndarray)
        The worn profile's x and y (m).
    """
    x = np.asarray(x, float)
    y = np.asarray(y, float)
    seg = np.hypot(np.diff(x, append=x[0]), np.diff(y, append=y[0]))
    arc = np.concatenate(([0.0], np.cumsum(seg)[:-1]))
    # the profile's own arc length is rescaled to the map's perimeter (same curve, same origin)
    arc = arc * wm.perimeter / seg.sum()
    h = np.interp(arc, wm.x_cam, wm.depth_cam * wm.cycles, period=wm.perimeter) - floor
    tx = np.gradient(x)
    ty = np.gradient(y)
    nrm = np.hypot(tx, ty)
    # inward normal of a counter-clockwise-ordered closed curve is (-ty, tx); orient by the centroid
    nx, ny = -ty / nrm, tx / nrm
    if np.mean(nx * (x - x.mean()) + ny * (y - y.mean())) > 0:
        nx, ny = -nx, -ny
    return x + magnify * h * nx, y + magnify * h * ny


def plot_wear_polar(wm, x, y, path, *, magnify: float | None = None, title: str = ""):
    """The cam profile (cam frame) and the worn profile with the depth above its smallest value
    magnified (a linear depth scale starting at the minimum, so the deepest region stands out);
    the deepest point is marked.

    Parameters
    ----------
    wm : femcam.wear.map.WearMap
        The wear map (depths in m per revolution, ``cycles``).
    x, y : array_like
        Cam profile points in the cam frame (m), ordered along the profile.
    path : str or os.PathLike
        Output PNG.
    magnify : float, optional
        Magnification of the depth above its minimum (-; default: the depth range drawn as
        5 % of the profile's x extent).
    title : str
        Figure title.

    Returns
    -------
    str or pathlib.Path
        ``path`` as given.
    """
    plt = pyplot()
    hmax = wm.max_depth
    h = np.asarray(wm.depth_cam, float) * wm.cycles
    hmin = float(h.min()) if h.size else 0.0
    if magnify is None:
        size = np.ptp(np.asarray(x))
        magnify = 0.05 * size / (h.max() - hmin) if h.size and h.max() > hmin else 1.0
    xw, yw = worn_profile(wm, x, y, magnify, floor=hmin)
    x, y = np.asarray(x, float), np.asarray(y, float)
    k = int(np.argmax(np.hypot(xw - x, yw - y)))
    fig, ax = plt.subplots(figsize=(7.0, 5))
    ax.plot(x * 1e3, y * 1e3, "k-", lw=0.8, label="new profile")
    ax.plot(xw * 1e3, yw * 1e3, "r-", lw=1.0,
            label=f"worn: (depth - {hmin * 1e6:.3g} um)\n x {magnify:.3g}")
    ax.plot(xw[k] * 1e3, yw[k] * 1e3, "rv", ms=6, label=f"deepest, {hmax * 1e6:.3g} um")
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    legend_outside(ax)
    ax.set_title((title + "\n" if title else "") + f"{wm.cycles:g} rev, depth {hmin * 1e6:.3g} to "
                 f"{hmax * 1e6:.3g} um; drawn: depth above the minimum x {magnify:.3g}",
                 fontsize=9)
    return _save(fig, path)


def plot_wear_comparison(maps: dict, path, *, title: str = ""):
    """Depth vs cam angle for several motion laws (``{label: WearMap}``).

    Parameters
    ----------
    maps : dict of str to femcam.wear.map.WearMap
        Motion-law label -> wear map (m per revolution).
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
    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    for label, wm in maps.items():
        ax.plot(np.degrees(wm.theta), wm.depth_at_theta * wm.cycles * 1e6,
                label=f"{label}: max {wm.max_depth * 1e6:.3g} um")
    ax.set_xlabel("cam angle theta (deg)")
    c = next(iter(maps.values())).cycles
    ax.set_ylabel("cam wear depth (um)")
    legend_outside(ax)
    ax.set_title((f"{title}: " if title else "") + f"after {c:g} revolutions", fontsize=10)
    return _save(fig, path)


def plot_evolution(res, path, *, title: str = ""):
    """Two panels of a :class:`~femcam.wear.evolution.EvolutionResult`: the evolved and the linear
    cam depth after ``res.cycles`` revolutions vs arc length (um), and their difference (nm).

    Parameters
    ----------
    res : femcam.wear.evolution.EvolutionResult
        Evolved and linear depths (m) along the cam arc (m).
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
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(8.0, 6.0), sharex=True)
    x = res.x_cam * 1e3
    a1.plot(x, res.depth_linear * 1e6, label="linear (unworn geometry) x N")
    a1.plot(x, res.depth_cam * 1e6, "--", label=f"evolved, {res.blocks} blocks")
    a1.set_ylabel("cam wear depth (um)")
    legend_outside(a1)
    a1.set_title(f"{title + ': ' if title else ''}{res.cycles:g} revolutions")
    a2.plot(x, (res.depth_cam - res.depth_linear) * 1e9)
    a2.set_ylabel("evolved - linear (nm)")
    a2.set_xlabel("cam arc length (mm)")
    return _save(fig, path, dpi=110)
