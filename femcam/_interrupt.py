"""Ctrl-C (SIGINT) and SIGTERM on the command line: one line on stderr and exit 130 / 143,
from the first instruction of ``femcam`` (also while numpy/scipy are still being imported).

Two phases, because what an interruption may leave behind differs:

* **starting** (imports, building the parser, reading the flags): nothing has been written,
  so the handler :func:`_exit_now` prints ``femcam: interrupted`` and ends the process at once
  with ``os._exit`` (a ``KeyboardInterrupt`` raised inside an import would print a traceback
  from wherever the import happened to be). ``femcam/__init__.py`` installs it (its first
  import) when the process is the command line (:func:`is_command_line`), so the 0.5-1 s of
  ``import femcam`` are covered too: the console script and ``python -m femcam`` both import
  the package before any code of :mod:`femcam.cli` can run.
* **working** (the subcommand's function): SIGINT raises ``KeyboardInterrupt`` (Python's own
  handler) and SIGTERM raises :class:`Terminated`, a ``KeyboardInterrupt``, so the cleanups
  written for Ctrl-C run for both (the sweep's saved chunks and ``--resume`` message, lock
  release). :func:`femcam.cli.main` turns either into one line and the exit code
  :data:`EXIT_CODES` gives: 128 + the signal number, the shell's convention (130 for SIGINT,
  143 for SIGTERM).

Built on the C module ``_signal`` (and ``os``/``sys``, loaded with the interpreter): importing
``signal`` would first import ``enum`` and ``functools``, tens of milliseconds in which a
Ctrl-C would still be a traceback. What remains uncovered is the interpreter's own start-up
before the first statement of ``femcam/__init__.py``, where Python's default applies.
"""

from __future__ import annotations

import _signal as signal  # the C module: no Python imports before the handler is in place
import os
import sys

#: exit code per signal: 128 + signal number (what a shell reports for a process it killed)
EXIT_CODES = {signal.SIGINT: 130, signal.SIGTERM: 143}

#: the last signal handled while working (None: none); read by femcam.cli.main for the exit code
last_signal = None


class Terminated(KeyboardInterrupt):
    """SIGTERM while a subcommand works: handled like Ctrl-C (cleanups, one line), exit 143."""


def is_command_line() -> bool:
    """Whether this process is the ``femcam`` command line (not a program importing femcam).

    Returns
    -------
    bool
        True for ``python [options] -m femcam ...`` / ``-m femcam.cli`` (read from
        ``sys.orig_argv``, which keeps the interpreter's own options) and for the console
        script, whose ``sys.argv[0]`` is the script ``.../femcam``.
    """
    argv = list(getattr(sys, "orig_argv", ()))
    for i, a in enumerate(argv[:-1]):
        if a == "-m":
            return argv[i + 1] in ("femcam", "femcam.cli")
    return os.path.basename(sys.argv[0] if sys.argv else "") == "femcam"


def _exit_now(signum, frame) -> None:  # noqa: ARG001 - the signal handler signature
    """Starting phase: one line and exit at once (nothing was written yet)."""
    os.write(2, b"femcam: interrupted\n")
    os._exit(EXIT_CODES.get(signum, 1))


def _raise_terminated(signum, frame) -> None:  # noqa: ARG001 - the signal handler signature
    global last_signal
    last_signal = signum
    raise Terminated("terminated (SIGTERM)")


def _raise_interrupt(signum, frame) -> None:  # noqa: ARG001 - the signal handler signature
    global last_signal
    last_signal = signum
    raise KeyboardInterrupt


def _set(handlers: dict) -> dict:
    """Install ``{signum: handler}`` and return the previous ones ({} off the main thread,
    where Python allows no signal handler: an in-process ``main()`` from a worker thread)."""
    try:
        return {s: signal.signal(s, h) for s, h in handlers.items()}
    except ValueError:  # "signal only works in main thread of the main interpreter"
        return {}


def starting() -> dict:
    """Install the starting-phase handler (:func:`_exit_now`) for SIGINT and SIGTERM.

    Returns
    -------
    dict
        The previous handlers, for :func:`restore`.
    """
    return _set({s: _exit_now for s in EXIT_CODES})


def working() -> dict:
    """Install the working-phase handlers (``KeyboardInterrupt`` / :class:`Terminated`).

    Returns
    -------
    dict
        The previous handlers, for :func:`restore`.
    """
    global last_signal
    last_signal = None
    return _set({signal.SIGINT: _raise_interrupt, signal.SIGTERM: _raise_terminated})


def restore(previous: dict) -> None:
    """Put back the handlers :func:`starting` or :func:`working` replaced.

    Parameters
    ----------
    previous : dict
        ``{signum: handler}`` as returned by them.
    """
    _set(previous)


def exit_code(exc: BaseException) -> int:
    """The exit code of an interruption: 143 for SIGTERM, else 130.

    Parameters
    ----------
    exc : BaseException
        The ``KeyboardInterrupt`` (or subclass) that ended the work.

    Returns
    -------
    int
        ``EXIT_CODES`` of the signal.
    """
    term = isinstance(exc, Terminated) or last_signal == signal.SIGTERM
    return EXIT_CODES[signal.SIGTERM if term else signal.SIGINT]


def install_if_command_line() -> None:
    """The starting-phase handler, only when this process is the command line
    (:func:`is_command_line`); a program that imports femcam keeps its own handlers. Run on
    import of this module, the first import of ``femcam/__init__.py``."""
    if is_command_line():
        starting()


install_if_command_line()
