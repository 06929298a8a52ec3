"""Plots of the sweep's extra columns (:mod:`femcam.sweep.extras`): one PNG per provider, one
panel per quantity against cam angle (matplotlib, imported inside the function).

They draw columns the sweep computed; they never call a solver. The panels come from the
caller as plain data, so this module knows no sweep."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ._mpl import pyplot, save


def plot_extra_panels(theta, panels, path, *, title: str = "") -> Path:
    """Stacked panels of per-angle series against cam angle.

    Parameters
    ----------
    theta : ndarray, shape (n,)
        Cam angles (rad).
    panels : sequence of (ylabel, series, log)
        ``series``: sequence of ``(label, values)`` with ``values`` of shape (n,) already in the
        unit of ``ylabel``; ``log``: logarithmic y axis. NaN values leave gaps.
    path : str or Path
        Output PNG.
    title : str
        Figure title.

    Returns
    -------
    Path
        ``path``.
    """
    plt = pyplot()
    panels = list(panels)
    fig, axes = plt.subplots(len(panels), 1, figsize=(7.0, 2.4 * len(panels) + 0.6), sharex=True,
                             squeeze=False)
    deg = np.degrees(np.asarray(theta, float))
    for ax, (ylabel, series, log) in zip(axes[:, 0], panels, strict=True):
        for label, y in series:
            y = np.asarray(y, float)
            ax.plot(deg, np.where(y > 0, y, np.nan) if log else y, ".-", ms=3, lw=1, label=label)
        if log:
            ax.set_yscale("log")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
        if len(series) > 1:
            ax.legend(fontsize=8)
    axes[-1, 0].set_xlabel("cam angle (deg)")
    if title:
        fig.suptitle(title, fontsize=10)
    return save(fig, path, dpi=90, tight=True)
