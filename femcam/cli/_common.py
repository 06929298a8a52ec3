"""Shared pieces of the subcommands: the argparse blocks every subcommand repeats
(:func:`add_scene_out`, :func:`add_law_override`, :func:`add_no_plots`), the output directory
and the one-line error text.

A subcommand calls :func:`out_dir` before any work, so that ``--out`` naming an existing
file, a path under a file or a directory it cannot create is one line naming the flag and the
path, not a traceback after minutes of computing. :func:`os_error_line` is the text
``femcam.cli.main`` prints for an ``OSError`` that still escapes (a full disk, say).
"""

from __future__ import annotations

import difflib
import os
import re
from pathlib import Path

from .. import _validate
from .._files import os_error_line
from ..errors import InputError
from ..kinematics import LAW_NAMES
from ..sweep.store import LOCK

#: motion laws a flag can name alone (``bezier`` and ``polynomial`` need control points)
NAMED_LAWS = tuple(n for n in LAW_NAMES if n not in ("bezier", "polynomial"))


def add_scene_out(p, scene_help: str = "scene file", *, out_help: str = "output directory",
                  out_required: bool = True) -> None:
    """Add the positional ``SCENE.toml`` and the ``--out DIR`` flag.

    Parameters
    ----------
    p : argparse.ArgumentParser
        The subcommand's parser.
    scene_help : str
        Help text of the scene argument.
    out_help : str
        Help text of ``--out``.
    out_required : bool
        ``--out`` must be given (False: default None, the subcommand picks the directory).
    """
    p.add_argument("scene", metavar="SCENE.toml", help=scene_help)
    p.add_argument("--out", required=out_required, default=None, metavar="DIR", help=out_help)


def add_overwrite(p) -> None:
    """Add ``--overwrite`` (``args.overwrite``): every subcommand refuses a non-empty ``--out``
    without it (:func:`refuse_non_empty`), so a second run never mixes or silently replaces
    the files of the first.

    Parameters
    ----------
    p : argparse.ArgumentParser
        The subcommand's parser.
    """
    p.add_argument("--overwrite", action="store_true",
                   help="write into a non-empty DIR, replacing its files (refused otherwise)")


def add_law_override(p) -> None:
    """Add ``--law NAME``, overriding the scene's rise/fall motion law (:data:`NAMED_LAWS`).

    Parameters
    ----------
    p : argparse.ArgumentParser
        The subcommand's parser; the value is checked with :func:`check_law` before any work.
    """
    p.add_argument("--law", default=None, metavar="NAME",
                   help="override the rise/fall motion law of the scene: " + ", ".join(NAMED_LAWS))


def add_no_plots(p) -> None:
    """Add ``--no-plots`` (``args.no_plots``, default False).

    Parameters
    ----------
    p : argparse.ArgumentParser
        The subcommand's parser.
    """
    p.add_argument("--no-plots", action="store_true", help="skip the PNG plots")


def out_dir(path, flag: str = "--out", *, create: bool = True) -> Path:
    """Create the output directory ``path`` (with parents) and check it is writable.

    Parameters
    ----------
    path : str or os.PathLike
        The directory.
    flag : str
        The flag named in the error (``--out``, ``--csv (its directory)``, ...).
    create : bool
        False: only check (the first existing component of the path must be a writable
        directory).

    Returns
    -------
    pathlib.Path
        ``path``.

    Raises
    ------
    InputError
        Naming ``flag`` and the path when ``path`` is an existing file, lies under a file, or
        cannot be created or written.
    """
    if not str(path).strip():  # Path("") is the current directory: never meant
        raise _validate.fail(flag, str(path), "", "must name a directory (it is empty)")
    p = Path(path)
    for q in (p, *p.parents):  # the first existing component must be a directory
        if q.exists() or q.is_symlink():
            if not q.is_dir():
                where = "is an existing file" if q == p else f"is under the file {q}"
                raise _validate.fail(flag, str(p), "", f"{where}, not a directory")
            break
    if not create:
        if not os.access(q, os.W_OK | os.X_OK):
            raise _validate.fail(flag, str(p), "", f"directory {q} is not writable")
        return p
    try:
        p.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        why = f"cannot create the directory ({os_error_line(exc)})"
        raise _validate.fail(flag, str(p), "", why) from None
    if not os.access(p, os.W_OK | os.X_OK):
        raise _validate.fail(flag, str(p), "", "directory is not writable")
    return p


def cap_workers(requested: int, n_tasks: int, tasks: str) -> tuple:
    """Cap ``--workers`` at the CPU cores and the number of tasks (more processes only wait).

    Parameters
    ----------
    requested : int
        ``--workers`` after validation, ``>= 1``.
    n_tasks : int
        Number of independent tasks (chunks, speeds).
    tasks : str
        The tasks as the note names them, e.g. ``"12 chunks of 30 angles"``.

    Returns
    -------
    (int, str)
        ``(workers, note)``; ``note`` says why it was capped ("" when not).
    """
    cores = os.cpu_count() or 1
    cap = max(1, min(cores, n_tasks))
    if requested <= cap:
        return requested, ""
    return cap, f"--workers {requested} capped at {cap} (the useful number: {cores} CPU cores, {tasks})"


def refuse_non_empty(path, overwrite: bool, *, resume: bool | None = None, what: str = "sweep") -> None:
    """Refuse a non-empty output directory unless ``--overwrite`` (or ``--resume``) is given:
    the rule of ``femcam sweep``, worded with the flags.

    Parameters
    ----------
    path : str or os.PathLike
        The ``--out`` directory (need not exist).
    overwrite : bool
        ``--overwrite`` given.
    resume : bool or None, optional
        ``--resume`` given; None: the command has no ``--resume`` (not offered in the message).
    what : str
        What ``--resume`` continues, as the message names it (``"sweep"``, ``"study"``).

    Raises
    ------
    InputError
        ``--out = DIR: the directory is not empty; pass ...``.
    """
    p = Path(path)  # the sweep's lock file (femcam.sweep.store.LOCK) is not content
    if overwrite or resume or not p.is_dir() or not any(q.name != LOCK for q in p.iterdir()):
        return
    hint = f"--resume to continue the {what} in it, --overwrite to replace its results" \
        if resume is not None else "--overwrite to replace its files"
    raise _validate.fail("--out", str(p), "", f"the directory is not empty; pass {hint}, or choose "
                         "another --out")


def plain(doc: str, paragraphs: int = 1) -> str:
    """The first paragraphs of a module docstring for ``--help``, without RST markup.

    Parameters
    ----------
    doc : str
        The docstring.
    paragraphs : int
        How many blank-line separated paragraphs to keep.

    Returns
    -------
    str
        The text, ````x```` -> ``x`` and ``:func:`~a.b``` -> ``b``.
    """
    text = "\n\n".join(doc.strip().split("\n\n")[:paragraphs])
    text = re.sub(r":[a-z]+:`~?([^`]+)`", lambda m: m.group(1).split(".")[-1]
                  if m.group(0).count("~") else m.group(1), text)
    return text.replace("``", "")


def check_law(flag: str, name: str) -> str:
    """Check a motion-law name given on the command line, before any work.

    Parameters
    ----------
    flag : str
        The flag (``--law``, ``--laws``), named in the error.
    name : str
        The value given.

    Returns
    -------
    str
        ``name``, one of :data:`~femcam.kinematics.LAW_NAMES`.

    Raises
    ------
    InputError
        Naming the flag, the value and a did-you-mean.
    """
    if name not in LAW_NAMES:
        near = difflib.get_close_matches(name, list(LAW_NAMES), n=1, cutoff=0.6)
        hint = f" (did you mean {near[0]!r}?)" if near else ""
        raise InputError(f"{flag} = {name!r}: unknown motion law{hint}; valid names: "
                         f"{', '.join(LAW_NAMES)}")
    return name
