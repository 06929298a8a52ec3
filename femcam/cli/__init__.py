"""Command-line interface: ``femcam <subcommand> ...``.

Each subcommand lives in its own module in this package and exposes
``register(subparsers) -> None``, which adds an argparse sub-parser and sets
``func=<callable(args) -> int>`` as its default. :func:`main` imports only the module of the
subcommand given: ``femcam --version`` reads the versions from the package metadata and
``femcam --help`` lists the subcommands from :data:`SUBCOMMANDS`, so neither imports numpy's
solvers, the scene machinery, gmsh, scikit-fem, pyvista, matplotlib or dask.

Console conventions (every subcommand): ``-q/--quiet`` prints nothing but errors and warnings
(stderr; the exit code says the rest); ``-v/--verbose`` logs every phase, however short;
progress of the long phases goes to stderr (:mod:`femcam._progress`: a bar on a terminal,
plain lines elsewhere).
"""

from __future__ import annotations

import argparse
import atexit
import contextlib
import importlib
import os
import sys
from importlib import metadata

from .. import __version__, _interrupt, _progress
from .._files import os_error_line
from ..errors import FemcamError
from ._flags import FlagError

#: subcommand -> its one-line help, in the order of ``femcam --help`` (the module
#: ``femcam.cli.<name>`` registers it; ``tests/test_cli_front.py`` checks the texts agree)
SUBCOMMANDS = {
    "run": "kinematics, profile and load tables of a scene, with PNG plots",
    "sweep": "FE contact sweep over cam angle (CSV/NPZ, VTK series, plots)",
    "wear": "Archard wear: seed 000's table, or a wear map of a scene",
    "synth": "knife-edge cam curve by potential-energy FE (seed 003)",
    "dynamics": "follower-train dynamics: contact force, jump speed",
    "assess": "will it fail? film, flash temperature, fatigue, safety factors",
    "optimise": "minimise peak p0 (or size, wear, ...) over the cam design",
    "study": "design study over scene keys (grid or Latin hypercube)",
    "check": "validate a scene file without running it (no FE)",
    "init": "write a commented scene template",
    "examples": "copy the example scenes into a directory",
    "info": "what a results folder holds (scene, angles, worst values, files)",
    "plot": "redraw the plots of a sweep's results folder",
}

#: packages whose versions ``--version`` prints: (distribution, shown as)
VERSIONED = (("scikit-fem", "scikit-fem"), ("gmsh", "gmsh"), ("numpy", "numpy"))


def _versions() -> str:
    """``femcam X, scikit-fem Y, gmsh Z, numpy W`` from the installed package metadata (no
    import of those packages)."""
    parts = [f"femcam {__version__}"]
    for dist, shown in VERSIONED:
        try:
            parts.append(f"{shown} {metadata.version(dist)}")
        except metadata.PackageNotFoundError:  # pragma: no cover - a missing dependency
            parts.append(f"{shown} (not installed)")
    return ", ".join(parts)


class _VersionAction(argparse.Action):
    def __init__(self, option_strings, dest, **kw):
        super().__init__(option_strings, dest, nargs=0,
                         help="print the versions of femcam, scikit-fem, gmsh and numpy")

    def __call__(self, parser, namespace, values, option_string=None):
        print(_versions())
        parser.exit()


def add_verbosity(p, default=None) -> None:
    """Add ``-q/--quiet`` and ``-v/--verbose`` (``args.verbosity``: -1, 0 or 1).

    Parameters
    ----------
    p : argparse.ArgumentParser
        The top-level parser (``default=0``) or a subcommand's (``argparse.SUPPRESS``, so
        ``femcam -q sweep`` and ``femcam sweep -q`` both work).
    default : object
        The default of ``args.verbosity``.
    """
    g = p.add_mutually_exclusive_group()
    g.add_argument("-q", "--quiet", dest="verbosity", action="store_const", const=-1,
                   default=default, help="print nothing but errors and warnings (stderr), no progress")
    g.add_argument("-v", "--verbose", dest="verbosity", action="store_const", const=1,
                   default=default, help="log every phase on stderr, however short")


def build_parser(only: str | None = "") -> argparse.ArgumentParser:
    """The ``femcam`` parser with one sub-parser per entry of :data:`SUBCOMMANDS`.

    Parameters
    ----------
    only : str or None
        ``""`` (default): every subcommand, each module imported; a name: only that
        subcommand is built (the others are listed by name and help); None: none is built
        (``femcam --help``).

    Returns
    -------
    argparse.ArgumentParser
        The parser.
    """
    parser = argparse.ArgumentParser(
        prog="femcam",
        description="Finite-element contact-stress analysis of cam-follower mechanisms.",
    )
    parser.add_argument("--version", action=_VersionAction)
    add_verbosity(parser, default=0)
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name, text in SUBCOMMANDS.items():
        if only is None or (only and name != only):
            sub.add_parser(name, help=text)  # listed in --help, not built
            continue
        importlib.import_module(f".{name}", __name__).register(sub)
        _add_verbosity_below(sub.choices[name])
    return parser


def _add_verbosity_below(p) -> None:
    """:func:`add_verbosity` on ``p`` and on its own sub-parsers (``femcam wear map -q``)."""
    add_verbosity(p, default=argparse.SUPPRESS)
    for a in p._actions:
        if isinstance(a, argparse._SubParsersAction):
            for q in a.choices.values():
                _add_verbosity_below(q)


def _command(argv: list) -> str | None:
    """The subcommand named in ``argv`` (the first word that is not a flag), or None."""
    for a in argv:
        if a in ("--version", "-h", "--help"):
            return None  # a top-level flag before any subcommand
        if not a.startswith("-"):
            return a if a in SUBCOMMANDS else None
    return None


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
        command quietly with 1 (no message). Run as the ``femcam`` command (``argv`` None
        and :func:`femcam._interrupt.is_command_line`), the process ends here with that code
        once stdout and stderr are flushed (no interpreter teardown: :func:`_exit_process`).
    """
    previous = _interrupt.starting()  # imports of the subcommands: one line, exit at once
    try:
        code = _main(argv)
    finally:
        _interrupt.restore(previous)
    if argv is None and _interrupt.is_command_line():
        _exit_process(code)  # the command line only: never a program that imports femcam
    return code


def _exit_process(code: int) -> None:
    """End the ``femcam`` process with ``code`` once its output is out, skipping the
    interpreter's teardown of the modules and of the large arrays of a sweep (0.25-0.5 s).

    Every file femcam writes is complete and closed when its writer returns
    (:mod:`femcam.io.atomic`); stdout and stderr are flushed and the ``atexit`` functions run
    (logging, a process pool's workers, temporary directories) before ``os._exit``.
    """
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    except (BrokenPipeError, ValueError):  # a reader that closed early, or a closed stream
        _quiet_broken_pipe()
    atexit._run_exitfuncs()
    os._exit(code)


def _main(argv) -> int:
    """:func:`main` inside the interruption handlers (:mod:`femcam._interrupt`)."""
    argv = _join_negative(sys.argv[1:] if argv is None else list(argv))
    parser = build_parser(_command(argv))
    try:  # a numeric flag out of its range is refused while parsing (femcam.cli._flags)
        args = parser.parse_args(argv)
    except FlagError as exc:
        print(f"{exc.prog}: error: {exc}", file=sys.stderr)
        return 1
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    _interrupt.working()  # from here Ctrl-C / SIGTERM raise, so the cleanups of the work run
    _progress.set_level(args.verbosity)
    sink = open(os.devnull, "w") if args.verbosity < 0 else None  # noqa: SIM115 - closed below
    quiet = contextlib.redirect_stdout(sink) if sink else contextlib.nullcontext()
    try:
        with quiet:  # --quiet: errors and warnings only (stderr), no summary, no progress
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
    finally:
        _progress.set_level(None)
        if sink is not None:
            sink.close()


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
