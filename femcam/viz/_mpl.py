"""matplotlib with the Agg backend, imported on first use (one place for every plot module)."""

from __future__ import annotations


def pyplot():
    """``matplotlib.pyplot`` on the Agg backend (headless; PNG output)."""
    import matplotlib  # lazy: matplotlib is heavy and only the plots need it

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return plt


def legend_outside(ax, fontsize: float = 8, **kw):
    """The legend of ``ax`` to the right of the axes, never over the data (``tight_layout``
    makes room for it)."""
    return ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, frameon=False,
                     fontsize=fontsize, **kw)
