"""matplotlib with the Agg backend, imported on first use (one place for every plot module)."""

from __future__ import annotations

from pathlib import Path

from ..io.atomic import atomic_write_bytes


def pyplot():
    """``matplotlib.pyplot`` on the Agg backend (headless; PNG output).

    Returns
    -------
    module
        ``matplotlib.pyplot``.
    """
    import matplotlib  # lazy: matplotlib is heavy and only the plots need it

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return plt


def legend_outside(ax, fontsize: float = 8, **kw):
    """The legend of ``ax`` to the right of the axes, never over the data (``tight_layout``
    makes room for it); None (no legend, no matplotlib warning) when no artist has a label.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes.
    fontsize : float
        Legend font size (pt).
    **kw
        Passed to ``ax.legend``.

    Returns
    -------
    matplotlib.legend.Legend or None
        The legend, None when nothing is labelled.
    """
    if not ax.get_legend_handles_labels()[0]:
        return None
    return ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, frameon=False,
                     fontsize=fontsize, **kw)


def save(fig, path, *, dpi: int = 100, tight: bool = False) -> Path:
    """Write ``fig`` to the PNG ``path`` (parent folders made; laid out first when ``tight``)
    and close it; returns the path as a :class:`~pathlib.Path`.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure (closed afterwards).
    path : str or os.PathLike
        Output PNG.
    dpi : int
        Resolution (dots per inch).
    tight : bool
        ``fig.tight_layout()`` first.

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    if tight:
        fig.tight_layout()
    if tight and path.suffix.lower() == ".png":
        # the Agg canvas directly: savefig would lay the figure out once more (a draw with
        # rendering off, for the placeholder layout engine tight_layout leaves), ~40 % of a plot;
        # atomic, so that a plot process ended mid-write (femcam.viz.process) leaves no half PNG
        fig.dpi = dpi
        atomic_write_bytes(path, fig.canvas.print_png)
    else:
        fig.savefig(path, dpi=dpi)
    pyplot().close(fig)
    return path
