"""The sweep's plots drawn in a second process, so that they overlap the sweep's own work.

The command-line main job (README command 1) runs its chunks in one process on a 2-core
machine (``workers="auto"`` finds a pool not worth it), so the other core is idle. A
:class:`PlotProcess` is forked when the sweep starts: it imports matplotlib while the sweep
builds, verifies and solves, then draws what the parent sends it (the finished table, then the
worst angle's surface profile) while the parent writes the tables and the reports. The parent
never imports matplotlib.

Failure is contained: if the child fails, is killed or cannot start, the parent writes every
other file as before, leaves out the missing plots and warns in one line (``femcam plot DIR``
draws them again from ``sweep.npz``); each PNG is written atomically
(:func:`femcam.viz._mpl.save`), so a killed child leaves no half file. Where ``fork`` is not
available (Windows, macOS's default) the plots are drawn in the parent as before: a spawned
child would import numpy, scipy and femcam again, which costs about what it saves.
"""

from __future__ import annotations

import multiprocessing
import signal
import sys
import warnings

from ..viz._mpl import pyplot

__all__ = ["PlotProcess", "start_plot_process"]

#: longest wait for the child's plots once the parent has written everything else (s); a
#: child that is stuck longer is ended and its plots reported missing
WAIT_S = 600.0


def start_plot_process() -> PlotProcess | None:
    """A forked :class:`PlotProcess`, or None where ``fork`` is not the platform's way (the
    caller then draws in its own process).

    Returns
    -------
    PlotProcess or None
        The started child (importing matplotlib), or None.
    """
    if not sys.platform.startswith("linux"):
        return None
    try:
        return PlotProcess()
    except OSError:  # no process could be started (limits): draw in this process
        return None


class PlotProcess:
    """A child process that draws plots on request (module docstring).

    :meth:`submit` sends ``(function, args)``; the child calls ``function(*args)`` (each a
    plot function returning ``{name: path}``) in the order sent; :meth:`collect` returns the
    merged paths of the calls that succeeded and the first error line, if any.
    """

    def __init__(self):
        ctx = multiprocessing.get_context("fork")
        self._conn, child = ctx.Pipe()
        self._proc = ctx.Process(target=_serve, args=(child, self._conn), daemon=True,
                                 name="femcam-plots")
        self._proc.start()
        child.close()
        self._sent = 0

    def submit(self, function, *args) -> None:
        """Have the child call ``function(*args)`` (a module-level plot function).

        Parameters
        ----------
        function : callable
            Returns ``{name: path}`` of the PNGs it wrote.
        *args
            Its arguments (pickled).
        """
        try:
            self._conn.send((function, args))
            self._sent += 1
        except (OSError, ValueError):  # the child is gone: collect() says so
            pass

    def collect(self, timeout_s: float = WAIT_S) -> tuple[dict, str]:
        """Wait for the answers to every :meth:`submit` and end the child.

        Parameters
        ----------
        timeout_s : float
            Longest wait for all answers [s].

        Returns
        -------
        paths : dict[str, str]
            The plots written, in the order submitted.
        error : str
            ``""``, or one line saying which plots are missing and why.
        """
        paths, error = {}, ""
        for _ in range(self._sent):
            try:
                if not self._conn.poll(timeout_s):
                    error = f"the plot process did not answer within {timeout_s:g} s"
                    break
                ok, value = self._conn.recv()
            except (EOFError, OSError):
                self._proc.join(5.0)
                code = self._proc.exitcode
                error = ("the plot process ended early"
                         + (f" (exit code {code})" if code is not None else ""))
                break
            if ok:
                paths.update(value)
            elif not error:
                error = value
        self.close()
        return paths, error

    def close(self) -> None:
        """End the child (idempotent): close the pipe, which the child reads as the end."""
        self._conn.close()
        self._proc.join(2.0)
        if self._proc.is_alive():  # pragma: no cover - a stuck child
            self._proc.kill()
            self._proc.join()


def _serve(conn, parent_end) -> None:
    """The child: import matplotlib, then call each function received until the pipe closes."""
    parent_end.close()
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's: it ends this child
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    try:
        pyplot()  # while the parent computes: the import is off the critical path
    except ImportError:
        pass  # the plot call itself raises it, and its message goes back
    while True:
        try:
            function, args = conn.recv()
        except (EOFError, OSError):
            return
        try:
            answer = (True, function(*args))
        except Exception as exc:  # noqa: BLE001 - any failure becomes the parent's one line
            answer = (False, f"{getattr(function, '__name__', 'plot')}: {type(exc).__name__}: {exc}")
        try:
            conn.send(answer)
        except (OSError, ValueError):
            return


def warn_missing(error: str, out) -> None:
    """The one line of a plot process that failed (the other outputs are written).

    Parameters
    ----------
    error : str
        :meth:`PlotProcess.collect`'s error line.
    out : str or Path
        The output directory.
    """
    warnings.warn(f"some plots are missing: {error}; the tables, VTK files and reports are "
                  f"written; `femcam plot {out}` draws the plots again", RuntimeWarning, stacklevel=3)
