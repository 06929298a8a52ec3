"""``femcam check SCENE.toml``: load and validate a scene without running it.

Every key, unit and stated range of the file, then the whole cam: undercut, the largest
pressure angle, the smallest radius of curvature and, with a follower train, lift-off. No FE.
Exit 0 when the scene is fine, 1 with the problems (one per line) otherwise.
"""

from __future__ import annotations

import sys

from ..start import check_scene
from ._common import plain


def register(subparsers) -> None:
    """Add the ``check`` sub-parser and set its ``func``.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        Where ``femcam``'s parser (:func:`femcam.cli.build_parser`) collects its subcommands.
    """
    p = subparsers.add_parser("check", help="validate a scene file without running it (no FE)",
                              description=plain(__doc__, 2))
    p.add_argument("scene", metavar="SCENE.toml", help="scene file")
    p.set_defaults(func=_run)


def _run(args) -> int:
    res = check_scene(args.scene)
    print("\n".join(res.lines()))
    if not res.ok:
        print(f"femcam check: error: {args.scene}: " + ("undercut" if res.undercut else "lift-off")
              + " (see above)", file=sys.stderr)
        return 1
    print(f"femcam check: {args.scene}: OK")
    return 0
