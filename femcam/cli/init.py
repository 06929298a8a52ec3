"""``femcam init [PATH]``: write a commented scene template (default ``scene.toml``).

Every key carries its unit, whether it is required, its accepted range and the range's source,
generated from the scene schema, so the comments say what ``femcam check`` accepts. An
existing file is refused unless ``--overwrite``.
"""

from __future__ import annotations

from pathlib import Path

from .. import _validate
from ..io import atomic_write_text
from ..start import scene_template
from ._common import plain


def register(subparsers) -> None:
    """Add the ``init`` sub-parser and set its ``func``.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        Where ``femcam``'s parser (:func:`femcam.cli.build_parser`) collects its subcommands.
    """
    p = subparsers.add_parser("init", help="write a commented scene template",
                              description=plain(__doc__, 2))
    p.add_argument("path", nargs="?", default="scene.toml", metavar="PATH",
                   help="the file to write (default: scene.toml)")
    p.add_argument("--overwrite", action="store_true", help="replace an existing PATH")
    p.set_defaults(func=_run)


def _run(args) -> int:
    path = Path(args.path)
    if path.is_dir():
        raise _validate.fail("PATH", str(path), "", "is a directory; name the scene file to write")
    if path.exists() and not args.overwrite:
        raise _validate.fail("PATH", str(path), "", "exists; pass --overwrite to replace it, or "
                             "choose another PATH")
    atomic_write_text(path, scene_template())
    print(f"wrote {path} (edit it, then: femcam check {path})")
    return 0
