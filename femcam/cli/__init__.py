"""Command-line interface: ``femcam <subcommand> ...``.

Each subcommand lives in its own module in this package and exposes
``register(subparsers) -> None``, which adds an argparse sub-parser and sets
``func=<callable(args) -> int>`` as its default. Nothing heavy is imported at import time;
the subcommand modules import the library at module level (``import femcam`` is numpy/scipy
only; gmsh, pyvista, matplotlib and dask stay lazy inside the library).
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys

from .. import __version__, _interrupt
from ..errors import FemcamError
from ._common import os_error_line
from ._flags import FlagError

#: subcommand modules, in the order they appear in ``femcam --help``
SUBCOMMANDS = ("run", "sweep", "wear", "synth", "dynamics", "assess", "optimise", "study")


def _versions() -> str:
    parts = [f"femcam {__version__}"]
    for mod, attr in (("skfem", "__version__"), ("gmsh", "__version__"), ("numpy", "__version__")):
        try:
            m = importlib.import_module(mod)
            parts.append(f"{'scikit-fem' if mod == 'skfem' else mod} {getattr(m, attr, '?')}")
        except Exception:  # pragma: no cover - a missing optional dependency
            parts.append(f"{mod} (not installed)")
    return ", ".join(parts)


class _VersionAction(argparse.Action):
    def __init__(self, option_strings, dest, **kw):
        super().__init__(option_strings, dest, nargs=0, help="print femcam, scikit-fem and gmsh versions")

    def __call__(self, parser, namespace, values, option_string=None):
        print(_versions())
        parser.exit()


def build_parser() -> argparse.ArgumentParser:
    """The ``femcam`` parser with one sub-parser per module of :data:`SUBCOMMANDS`.

    Returns
    -------
    argparse.ArgumentParser
        The parser; a subcommand module that does not exist yet is skipped.
    """
    parser = argparse.ArgumentParser(
        prog="femcam",
        description="Finite-element contact-stress analysis of cam-follower mechanisms.",
    )
    parser.add_argument("--version", action=_VersionAction)
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name in SUBCOMMANDS:
        try:
            mod = importlib.import_module(f".{name}", __name__)
        except ModuleNotFoundError as exc:
            if exc.name == f"{__name__}.{name}":
                continue  # subcommand not implemented yet
            raise
        mod.register(sub)
    return parser


def main(argv=None) -> int:
    """Entry point of the ``femcam`` console script.

    Parameters
    ----------
    argv : list of str, optional
        Arguments (default ``sys.argv[1:]``).

    Returns
    -------
    int
        Exit code: 0 success; 130 Ctrl-C (SIGINT), 143 SIGTERM, with one line on stderr,
        from the first instruction (:mod:`femcam._interrupt`); 1 a
        :class:`~femcam.errors.FemcamError` or an ``OSError`` (a file that cannot be read or
        written, a full disk), printed as one line
        ``femcam <command>: error: ...`` naming the path, never a traceback; 2 usage. A reader
        that closes the pipe early (``femcam wear seed000 --all-laws | head -2``) ends the
        command quietly with 1 (no message).
    """
    previous = _interrupt.starting()  # imports of the subcommands: one line, exit at once
    try:
        return _main(argv)
    finally:
        _interrupt.restore(previous)


def _main(argv) -> int:
    """:func:`main` inside the interruption handlers (:mod:`femcam._interrupt`)."""
    parser = build_parser()
    try:  # a numeric flag out of its range is refused while parsing (femcam.cli._flags)
        args = parser.parse_args(_join_negative(sys.argv[1:] if argv is None else list(argv)))
    except FlagError as exc:
        print(f"{exc.prog}: error: {exc}", file=sys.stderr)
        return 1
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    _interrupt.working()  # from here Ctrl-C / SIGTERM raise, so the cleanups of the work run
    try:
        code = int(args.func(args) or 0)
        sys.stdout.flush()  # a closed pipe shows here, not in the interpreter's final flush
        if code == 130 and _interrupt.last_signal is not None:  # the sweep's own Ctrl-C line
            code = _interrupt.EXIT_CODES[_interrupt.last_signal]
        return code
    except KeyboardInterrupt as exc:  # Ctrl-C or SIGTERM (femcam._interrupt.Terminated)
        nl = "\n" if sys.stderr.isatty() else ""  # end a progress bar's line
        print(f"{nl}femcam {args.command}: {str(exc) or 'interrupted'}", file=sys.stderr)
        return _interrupt.exit_code(exc)
    except BrokenPipeError:  # the reader closed early (femcam ... | head): quiet, as cat would be
        return _quiet_broken_pipe()
    except FemcamError as exc:
        print(f"femcam {args.command}: error: {_capped(str(exc))}", file=sys.stderr)
        return 1
    except OSError as exc:  # the disk, not femcam: say which file and why
        print(f"femcam {args.command}: error: {os_error_line(exc)}", file=sys.stderr)
        return 1


def _quiet_broken_pipe() -> int:
    """Point stdout at ``os.devnull`` (the interpreter's final flush must not fail again) and
    return 1, Python's exit code on EPIPE (the recipe of the Python documentation, "Note on
    SIGPIPE", module ``signal``)."""
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, sys.stdout.fileno())
    return 1


#: flags whose value is a range START:STOP:STEP that may start with a minus sign
RANGE_FLAGS = ("--angles-deg", "--rpm-sweep")


def _join_negative(argv: list) -> list:
    """``--angles-deg -360:0:30`` -> ``--angles-deg=-360:0:30``: argparse reads a value that
    starts with ``-`` (and is not a plain number) as an option; the ``=`` form it takes."""
    out, i = [], 0
    while i < len(argv):
        a = argv[i]
        if a in RANGE_FLAGS and i + 1 < len(argv) and str(argv[i + 1]).startswith("-") \
                and ":" in str(argv[i + 1]):
            out.append(f"{a}={argv[i + 1]}")
            i += 2
            continue
        out.append(a)
        i += 1
    return out


#: most problem lines one error message shows (a scene with 1800 bad segments lists 1800)
MAX_LINES = 20


def _capped(text: str) -> str:
    """``text`` with at most :data:`MAX_LINES` lines after the first, then ``... and N more``."""
    lines = text.split("\n")
    if len(lines) <= MAX_LINES + 1:
        return text
    more = len(lines) - 1 - MAX_LINES
    return "\n".join(lines[:MAX_LINES + 1] + [f"  ... and {more} more"])


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
