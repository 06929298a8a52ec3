"""matplotlib with the Agg backend, imported on first use (one place for every plot module)."""

from __future__ import annotations


def pyplot():
    """``matplotlib.pyplot`` on the Agg backend (headless; PNG output)."""
    import matplotlib  # lazy: matplotlib is heavy and only the plots need it

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return plt
