"""Progress of the long phases on stderr: one policy for every command.

* On a terminal: a bar per counted phase (angles, speeds, cycles) drawn by ``rich`` and a
  ``label ... 3.2 s`` timer for a phase without a count, once it has lasted ``delay_s`` (1 s).
* Off a terminal (CI, a notebook, a pipe): plain log lines, one when a phase has lasted
  ``delay_s`` and one when it ends, and for a counted phase one line per 10 % with the
  elapsed time, e.g. ``femcam: solves 40/120 (33 %) 4.1 s``.

What is shown follows :data:`LEVEL`, set once by the command line (``femcam -q`` / ``-v``):

* ``None`` (a program that imports femcam): progress only when stderr is a terminal;
* ``-1`` (``--quiet``): none;
* ``0`` (the command line's default): on a terminal a bar, elsewhere plain lines;
* ``1`` (``--verbose``): as 0, and every phase is logged however short.

A caller may still force it per call (``enabled=True/False``, the sweep's ``progress``).
Standard library only at import; ``rich`` is imported when a bar is drawn on a terminal.
"""

from __future__ import annotations

import contextlib
import sys
import threading
import time

from . import _validate

#: the command line's verbosity (-1 quiet, 0 default, 1 verbose); None: not set (a library call)
LEVEL: int | None = None

#: a plain-line progress report is written every this fraction of the total
STEP_FRACTION = 0.1


def set_level(level: int | None) -> None:
    """Set :data:`LEVEL` (the command line calls it with ``args.verbosity``).

    Parameters
    ----------
    level : int or None
        -1 quiet, 0 default, 1 verbose; None: a library call (progress on a terminal only).
    """
    global LEVEL
    LEVEL = level


def _is_tty(stream) -> bool:
    return bool(getattr(stream, "isatty", lambda: False)())


class Progress:
    """Progress of one counted phase (:meth:`update`) and of uncounted phases (:meth:`phase`).

    Parameters
    ----------
    total : int
        Number of steps of the counted phase (0: no count).
    label : str
        Name of the counted phase.
    enabled : bool, optional
        Show progress; default from :data:`LEVEL` (see the module docstring).
    stream : file-like, optional
        Where to write (default ``sys.stderr``).
    delay_s : float
        How long an uncounted phase lasts before it is shown [s] (0 when verbose).
    unit : str
        What is counted (``"angles"``).
    """

    def __init__(self, total: int, label: str = "sweep", enabled: bool | None = None,
                 stream=None, delay_s: float = 1.0, unit: str = "angles"):
        total = _validate.integer("total", total, 0, "steps")
        delay_s = _validate.nonnegative("delay_s", delay_s, "s")
        self.stream = stream or sys.stderr
        self.tty = _is_tty(self.stream)
        if enabled is None:
            enabled = self.tty if LEVEL is None else LEVEL >= 0
        self.on = bool(enabled)
        self.delay_s = 0.0 if LEVEL is not None and LEVEL > 0 else float(delay_s)
        self.enabled = self.on and total > 0
        self.total, self.done, self.label, self.unit = total, 0, label, unit
        self.t0 = time.perf_counter()
        self._next = STEP_FRACTION
        self._bar = None

    def _line(self, text: str) -> None:
        self.stream.write(f"femcam: {text}\n")
        self.stream.flush()

    def update(self, n: int) -> None:
        """``n`` more steps are done: redraw the bar, or write a line at each 10 %.

        Parameters
        ----------
        n : int
            Steps finished since the last update.
        """
        self.done += n
        if not self.enabled:
            return
        frac = min(1.0, self.done / self.total)
        if self.tty:
            self._draw()
            return
        if frac + 1e-12 >= self._next or self.done >= self.total:
            el = time.perf_counter() - self.t0
            self._line(f"{self.label} {self.done}/{self.total} {self.unit} ({100 * frac:.0f} %) "
                       f"{el:.1f} s")
            while self._next <= frac + 1e-12:
                self._next += STEP_FRACTION

    def _draw(self) -> None:
        """The terminal bar (rich: a maintained progress bar with elapsed and remaining time)."""
        if self._bar is None:
            from rich.console import Console  # only on a terminal: not needed off one
            from rich.progress import (
                BarColumn,
                MofNCompleteColumn,
                TextColumn,
                TimeElapsedColumn,
                TimeRemainingColumn,
            )
            from rich.progress import Progress as Bar

            self._bar = Bar(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                            TextColumn(self.unit), TimeElapsedColumn(), TimeRemainingColumn(),
                            console=Console(file=self.stream))
            self._bar.start()
            self._task = self._bar.add_task(self.label, total=self.total)
        self._bar.update(self._task, completed=self.done)

    def close(self) -> None:
        """End the bar (on a terminal)."""
        if self._bar is not None:
            self._bar.stop()
            self._bar = None

    @contextlib.contextmanager
    def phase(self, label: str, period_s: float = 0.25):
        """Context manager: show a phase without a count once it has lasted ``delay_s``.

        On a terminal ``label ... 3.2 s`` is redrawn every ``period_s``, then ``label: 4.1 s``
        stays on its own line; off a terminal ``femcam: label ...`` and ``femcam: label: 4.1 s``
        are two plain lines. Nothing for a phase shorter than ``delay_s``.

        Parameters
        ----------
        label : str
            Name of the phase.
        period_s : float
            Redraw period on a terminal [s].

        Yields
        ------
        None
            The body of the ``with`` block runs while the timer is shown.
        """
        if not self.on:
            yield
            return
        stop, shown, t0 = threading.Event(), [False], time.perf_counter()

        def tick():
            if self.delay_s and stop.wait(self.delay_s):
                return
            shown[0] = True
            if not self.tty:
                self._line(f"{label} ...")
                return
            while True:
                self.stream.write(f"\r{label} ... {time.perf_counter() - t0:5.1f} s")
                self.stream.flush()
                if stop.wait(period_s):
                    return

        th = threading.Thread(target=tick, daemon=True, name="femcam-progress")
        th.start()
        try:
            yield
        finally:
            stop.set()
            th.join()
            if shown[0]:
                el = time.perf_counter() - t0
                if self.tty:
                    self.stream.write(f"\r{label}: {el:5.1f} s\n")
                    self.stream.flush()
                else:
                    self._line(f"{label}: {el:.1f} s")


def phase(label: str):
    """``with phase("dynamics: rpm sweep"): ...``: :meth:`Progress.phase` with the defaults.

    Parameters
    ----------
    label : str
        Name of the phase.

    Returns
    -------
    contextlib.AbstractContextManager
        Shows the phase while the ``with`` block runs.
    """
    return Progress(0).phase(label)
