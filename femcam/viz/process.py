"""The sweep's plots drawn in a second process, so that they overlap the sweep's own work.

The command-line main job (README command 1) runs its chunks in one process on a 2-core
machine (``workers="auto"`` finds a pool not worth it), so the other core is idle. A
:class:`PlotProcess` is forked when the sweep starts: it imports matplotlib while the sweep
builds, verifies and solves, then forks itself into a second lane (matplotlib imported once),
and the two lanes draw what the parent sends them (the finished table, then the worst angle's
surface profile) on the two cores while the parent writes the tables and waits. The parent
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
import os
import queue
import signal
import sys
import threading
import time
import warnings
from multiprocessing.reduction import ForkingPickler

from ._mpl import pyplot

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
    """Two lanes of plot drawing (module docstring): a forked child, and its own fork once it
    has imported matplotlib (so the import is paid once), each answering on its own pipe.

    :meth:`submit` sends ``(function, args)`` to the lane with less work queued (``weight``);
    a lane calls ``function(*args)`` (a plot function returning ``{name: path}``) in the order
    sent; :meth:`collect` returns the merged paths of the calls that succeeded, in the order
    submitted, and the first error line, if any.

    Parameters
    ----------
    lanes : int
        1 or 2 drawing processes (2: the 2 cores of the machine the main job is tuned for;
        the sweep's own process only waits while they draw).
    """

    def __init__(self, lanes: int = 2):
        ctx = multiprocessing.get_context("fork")
        pipes = [ctx.Pipe() for _ in range(lanes)]
        self._conns = [mine for mine, _ in pipes]
        self._proc = ctx.Process(target=_serve, args=([theirs for _, theirs in pipes], self._conns),
                                 daemon=True, name="femcam-plots")
        self._proc.start()
        for _, theirs in pipes:
            theirs.close()
        self._jobs = []   # lane of each call, in the order submitted
        self._load = [0.0] * lanes
        # one sender thread per lane: a call's arguments (the sweep table, ~0.3 MB pickled) do
        # not fit in a pipe's buffer, so a send waits until the lane has drawn its earlier
        # calls; the threads wait instead, and the sweep writes its tables meanwhile
        self._queues = [queue.SimpleQueue() for _ in range(lanes)]
        self._senders = [threading.Thread(target=_feed, args=(conn, q), daemon=True,
                                          name="femcam-plots-send")
                         for conn, q in zip(self._conns, self._queues, strict=True)]
        for t in self._senders:
            t.start()

    def submit(self, function, *args, weight: float = 1.0, lane: int | None = None) -> int:
        """Have a lane call ``function(*args)`` (a module-level plot function); returns at once
        (the arguments are pickled here and sent by the lane's sender thread).

        Parameters
        ----------
        function : callable
            Returns ``{name: path}`` of the PNGs it wrote.
        *args
            Its arguments (pickled).
        weight : float
            Its expected cost relative to the others (e.g. its number of axes): the call goes
            to the lane with the least queued weight.
        lane : int, optional
            The lane instead (e.g. the one that drew an earlier version of the same file: a
            lane calls in the order sent, so the later version is written last).

        Returns
        -------
        int
            The lane that draws it.
        """
        if lane is None:
            lane = min(range(len(self._load)), key=self._load.__getitem__)
        self._load[lane] += weight
        self._jobs.append(lane)
        self._queues[lane].put(ForkingPickler.dumps((function, args)))
        return lane

    def collect(self, timeout_s: float = WAIT_S) -> tuple[dict, str]:
        """Wait for the answers to every :meth:`submit` and end the lanes.

        Parameters
        ----------
        timeout_s : float
            Longest wait for each answer [s].

        Returns
        -------
        paths : dict[str, str]
            The plots written, in the order submitted.
        error : str
            ``""``, or one line saying why plots are missing (the first failure).
        """
        paths, error, dead = {}, "", set()
        for lane in self._jobs:
            if lane in dead:
                continue
            conn = self._conns[lane]
            try:
                if not conn.poll(timeout_s):
                    error = error or f"a plot process did not answer within {timeout_s:g} s"
                    dead.add(lane)
                    continue
                ok, value = conn.recv()
            except (EOFError, OSError):
                dead.add(lane)
                code = self._exit_code() if lane == 0 else None  # the second lane is not our child
                error = error or ("a plot process ended early"
                                  + (f" (exit code {code})" if code is not None else ""))
                continue
            if ok:
                paths.update(value)
            elif not error:
                error = value
        self.close()
        return paths, error

    def _exit_code(self, wait_s: float = 2.0):
        """The first lane's exit code once it has ended (None if it has not within ``wait_s``).
        Polled (``waitpid``), not joined: the second lane inherited the first's sentinel."""
        end = time.monotonic() + wait_s
        while self._proc.exitcode is None and time.monotonic() < end:
            time.sleep(0.01)
        return self._proc.exitcode

    def close(self) -> None:
        """End the lanes (idempotent): stop the sender threads, close the pipes, which the
        lanes read as the end."""
        for q in self._queues:
            q.put(None)
        for t in self._senders:
            t.join(2.0)
        for conn in self._conns:
            conn.close()
        self._proc.join(2.0)
        if self._proc.is_alive():  # pragma: no cover - a stuck child
            self._proc.kill()
            self._proc.join()


def _feed(conn, q) -> None:
    """A lane's sender thread: send each pickled call of ``q`` until the None that ends it; a
    lane that is gone ends the sending (its :meth:`PlotProcess.collect` says so)."""
    while True:
        data = q.get()
        if data is None:
            return
        try:
            conn.send_bytes(data)
        except (OSError, ValueError):  # the lane ended (or the pipe was closed)
            return


def _serve(conns, parent_ends) -> None:
    """The first lane: import matplotlib, fork the second lane, then serve ``conns[0]``."""
    for c in parent_ends:
        c.close()
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's: it ends the lanes
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    try:
        pyplot()  # while the parent computes: the import is off the critical path
    except ImportError:
        pass  # the plot call itself raises it, and its message goes back
    second = 0
    if len(conns) > 1:
        try:
            second = os.fork()
        except OSError:  # no second lane: its calls are reported missing
            conns[1].close()
        else:
            if second == 0:  # the second lane: serve its pipe, then end without cleanups
                conns[0].close()
                try:
                    _answer(conns[1])
                finally:
                    os._exit(0)
            conns[1].close()
    _answer(conns[0])
    if second:
        os.waitpid(second, 0)


def _answer(conn) -> None:
    """Call each function received on ``conn`` and send its answer, until the pipe closes."""
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
