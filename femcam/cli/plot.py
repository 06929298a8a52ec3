"""``femcam plot DIR``: redraw the plots of a sweep's results folder into DIR/plots.

From the saved data (``DIR/sweep.npz``, which keeps the worst angle's surface profile); no
solve. Plots are derived data: existing PNGs of the same names are replaced (no
``--overwrite`` needed).
"""

from __future__ import annotations

from ..folder import replot
from ._common import plain


def register(subparsers) -> None:
    """Add the ``plot`` sub-parser and set its ``func``.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        Where ``femcam``'s parser (:func:`femcam.cli.build_parser`) collects its subcommands.
    """
    p = subparsers.add_parser("plot", help="redraw the plots of a sweep's results folder",
                              description=plain(__doc__, 2))
    p.add_argument("dir", metavar="DIR", help="a sweep's results folder")
    p.set_defaults(func=_run)


def _run(args) -> int:
    paths = replot(args.dir)
    for path in paths.values():
        print(f"wrote {path}")
    return 0
