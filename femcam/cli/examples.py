"""``femcam examples DIR``: copy the example scenes shipped with femcam into DIR.

``--list`` prints their names and descriptions instead. A non-empty DIR is refused unless
``--overwrite``.
"""

from __future__ import annotations

from ..start import copy_examples, example_scenes
from ._common import plain


def register(subparsers) -> None:
    """Add the ``examples`` sub-parser and set its ``func``.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        Where ``femcam``'s parser (:func:`femcam.cli.build_parser`) collects its subcommands.
    """
    p = subparsers.add_parser("examples", help="copy the example scenes into a directory",
                              description=plain(__doc__, 2))
    p.add_argument("dir", nargs="?", default=None, metavar="DIR", help="where to copy them")
    p.add_argument("--list", action="store_true", help="print the names and descriptions only")
    p.add_argument("--overwrite", action="store_true",
                   help="write into a non-empty DIR, replacing its files (refused otherwise)")
    p.set_defaults(func=_run)


def _run(args) -> int:
    if args.list or args.dir is None:
        for name, desc in example_scenes().items():
            print(f"{name}: {desc}")
        return 0
    written = copy_examples(args.dir, overwrite=args.overwrite)
    print(f"wrote {len(written)} example scenes to {args.dir}")
    return 0
