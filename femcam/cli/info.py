"""``femcam info DIR``: what a results folder holds.

The command that wrote it; for a sweep, the scene and its physics hash, the angles (count,
range, step), the worst value of each quantity with its unit and cam angle, and the refused
parts; then the files with their sizes. A folder no femcam command wrote: one line, exit 1.
"""

from __future__ import annotations

from ..folder import folder_info
from ._common import plain


def register(subparsers) -> None:
    """Add the ``info`` sub-parser and set its ``func``.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        Where ``femcam``'s parser (:func:`femcam.cli.build_parser`) collects its subcommands.
    """
    p = subparsers.add_parser("info", help="what a results folder holds (scene, angles, worst values, files)",
                              description=plain(__doc__, 2))
    p.add_argument("dir", metavar="DIR", help="a results folder (a command's --out)")
    p.set_defaults(func=_run)


def _run(args) -> int:
    print("\n".join(folder_info(args.dir).lines()))
    return 0
