"""A forked helper process that builds FE models while the sweep's own process works: the family
phase on the second core (:class:`ForkLane`).

The family phase of a sweep builds independent FE models (the families' models, the fresh check
models, the coarse models of the error estimates) and solves the family models at their load
cases. In threads of one process these overlap only in part: meshing (one gmsh at a time),
SuperLU factorisations (scipy runs one at a time) and most of the Python do not
(docs/performance.md). A :class:`ForkLane` is one child forked when the phase starts (it then
has the parent's imports and state for free); the parent sends it jobs, one at a time, and it
sends back their results: a fresh check's p0 (a float), a coarse model's quantities (a dict), or
a family model without its factorised bodies (:func:`femcam.sweep.diskcache.strip_model`, which
the parent restores with bodies refactorised on first use, as a model from the persistent
cache). A job is a picklable callable (a :func:`functools.partial` of a module-level function),
or an object whose ``in_child()`` returns what is sent and whose ``in_parent(value, defer)``
returns what the parent keeps (``defer``: :meth:`ForkLane.defer`, for work such as a cache file
written in the parent: the child writes nothing, so one process writes the persistent cache and
says once when it cannot).

The interface is that of :class:`femcam._threads.Background` (``submit``, ``take``, ``defer``,
``close``), with the same rule: a job not yet sent to the child when its result is wanted is
computed by the caller (the caller never waits for work it can do itself), and while the caller
waits for the job in the child it runs the other queued jobs itself. Every result is the one the
caller would have computed (the jobs are deterministic functions of their arguments): the rows
do not depend on which process built what.

Faults: a child that cannot be started, dies (killed, out of memory) or fails a job costs only
time: the jobs it had are computed again in the parent, and the lane takes no more. The child
ignores Ctrl-C (the parent's to handle: it ends the child), ends when the parent's pipe closes
or the parent is gone (:func:`_exit_with_parent`), and is ended and reaped
by :meth:`ForkLane.close`: no orphan, no zombie. Where ``fork`` is not available, there is no
lane (:func:`fork_available`) and the sweep builds in a background thread instead.
"""

from __future__ import annotations

import multiprocessing
import os
import pickle
import signal
import sys
import threading
import time
from concurrent.futures import Future, ThreadPoolExecutor

from .._threads import limit_blas_threads

__all__ = ["ForkLane", "fork_available"]

#: longest wait for the child to end after its job pipe is closed, before it is killed (s)
END_WAIT_S = 5.0


def fork_available() -> bool:
    """Whether a :class:`ForkLane` can be started here and now: Linux with the ``fork`` start
    method, called from the main thread of a process that may have children.

    Returns
    -------
    bool
        False elsewhere: macOS's and Windows' default ``spawn`` would import everything again;
        a sweep run in a worker thread (Dask, a threaded study) might fork while another thread
        holds a lock the child needs (gmsh's, BLAS's); a daemonic process (a
        :mod:`multiprocessing` pool's worker) may not start one.
    """
    return (sys.platform.startswith("linux") and "fork" in multiprocessing.get_all_start_methods()
            and threading.current_thread() is threading.main_thread()
            and not multiprocessing.current_process().daemon)


class _LostError(Exception):
    """The lane could not compute a job (child gone, a job or result that does not pickle, a
    job that failed there): the caller computes it."""


class ForkLane:
    """One forked child computing queued jobs (module docstring), taken back by key.

    Use as a context manager, in the main thread with no other thread building (the child
    keeps only the forking thread). The child is forked when the first job is submitted (a run
    whose models all come from the persistent cache forks none).

    Parameters
    ----------
    prepare : callable, optional
        Called once before the fork (e.g. the imports the jobs need: done once, here).

    Attributes
    ----------
    threads : int
        1 while the child serves jobs or can be started (the "background capacity"
        :class:`ModelCache` reads), 0 once it is gone or could not be started.
    pid : int or None
        The child's process id (None before the first job).

    >>> import functools, operator
    >>> with ForkLane() as lane:                       # doctest: +SKIP
    ...     lane.submit("x", functools.partial(operator.add, 2, 2))
    ...     lane.take("x", lambda: 4)
    4
    """

    def __init__(self, prepare=None):
        self._prepare = prepare
        self._proc = None          # forked on the first job submitted (a warm run forks none)
        self.pid = None
        self.threads = 1
        self._cond = threading.Condition()
        self._queue: dict = {}     # key -> [fn, Future, state, priority]; state "queued",
        self._closed = False       # "sent" (to the child) or "local" (computed here)
        self._deferred = None

    def _start(self) -> bool:
        """Fork the child (once; ``prepare()`` first, e.g. imports the jobs need, so that the
        child does not repeat them); False when it cannot be started."""
        if self._proc is not None:
            return True
        if self._prepare is not None:
            self._prepare()
        ctx = multiprocessing.get_context("fork")
        try:
            jobs_r, self._jobs_w = ctx.Pipe(duplex=False)
            self._results_r, results_w = ctx.Pipe(duplex=False)
            self._proc = ctx.Process(target=_serve, args=(jobs_r, results_w, self._jobs_w,
                                                          self._results_r, os.getpid()),
                                     daemon=True, name="femcam-lane")
            self._proc.start()
        except OSError:  # no process could be started (limits): the caller computes everything
            self._proc, self.threads = None, 0
            return False
        jobs_r.close()
        results_w.close()
        self.pid = self._proc.pid
        self._dispatcher = threading.Thread(target=self._dispatch, daemon=True,
                                            name="femcam-lane-dispatch")
        self._dispatcher.start()
        return True

    def __enter__(self):
        return self

    def __exit__(self, exc_type, *exc):
        self.close(kill=exc_type is not None)
        return False

    def submit(self, key, fn, priority: int = 0) -> None:
        """Queue ``fn()`` under ``key`` for the child (nothing when it is queued already, the
        lane is closed or gone, or ``fn`` does not pickle: the caller then computes it).

        Parameters
        ----------
        key : hashable
            What :meth:`take` asks for.
        fn : callable
            A picklable job (module docstring).
        priority : int
            Queued jobs of a lower value are started first (then in the order submitted).
        """
        try:
            pickle.dumps(fn, protocol=5)
        except Exception:  # noqa: BLE001 - a closure: computed where it is taken
            return
        if not self.threads or self._closed or not self._start():
            return
        with self._cond:
            if self.threads and not self._closed and key not in self._queue:
                self._queue[key] = [fn, Future(), "queued", int(priority)]
                self._cond.notify_all()

    def _next(self):
        """The queued job to start next (lowest priority, then oldest), or None; hold the lock."""
        queued = [e for e in self._queue.values() if e[2] == "queued"]
        return min(queued, key=lambda e: e[3]) if queued else None

    def defer(self, fn) -> None:
        """Run ``fn()`` for its effect (a file written) in a thread of this process; waited for
        by :meth:`close`, its exceptions dropped.

        Parameters
        ----------
        fn : callable
            The work.
        """
        with self._cond:
            if not self._closed:
                if self._deferred is None:
                    self._deferred = ThreadPoolExecutor(1, thread_name_prefix="femcam-lane-defer")
                self._deferred.submit(fn)
                return
        fn()

    def take(self, key, fn):
        """The result of the job ``key``: the child's, or ``fn()`` computed here when the job
        was never queued, not yet sent, or lost (class docstring).

        Parameters
        ----------
        key : hashable
            The job's key.
        fn : callable
            Computes the same result here.

        Returns
        -------
        object
            The result.
        """
        with self._cond:
            entry = self._queue.pop(key, None)
        if entry is None or entry[2] == "queued":
            return fn()
        job, fut = entry[0], entry[1]
        while not fut.done() and self._help():
            pass
        try:
            value = fut.result()
        except _LostError:
            return fn()
        if entry[2] == "local":
            return value
        in_parent = getattr(job, "in_parent", None)
        return value if in_parent is None else in_parent(value, self.defer)

    def _help(self) -> bool:
        """Compute the oldest queued job here (its result kept for its own :meth:`take`); False
        when none is queued."""
        with self._cond:
            entry = self._next()
            if entry is None:
                return False
            entry[2] = "local"
        try:
            entry[1].set_result(entry[0]())
        except Exception as exc:  # noqa: BLE001 - raised by the take of its own key
            entry[1].set_exception(exc)
        return True

    def _dispatch(self) -> None:
        """Send the oldest queued job to the child, wait for its answer, repeat (a thread of
        this process, blocked in pipe reads and writes: it releases the GIL)."""
        while True:
            with self._cond:
                while not self._closed and self._next() is None:
                    self._cond.wait()
                if self._closed:
                    return
                entry = self._next()
                entry[2] = "sent"
            try:
                self._jobs_w.send_bytes(pickle.dumps(entry[0], protocol=5))
                ok, value = pickle.loads(self._results_r.recv_bytes())
            except Exception:  # noqa: BLE001 - the child is gone (EOF, broken pipe) or closed
                entry[1].set_exception(_LostError())
                self._lost()
                return
            if ok:
                entry[1].set_result(value)
            else:
                entry[1].set_exception(_LostError())

    def _lost(self) -> None:
        """The child is gone: no more jobs for it; queued ones stay for their takers."""
        with self._cond:
            self.threads = 0

    def close(self, kill: bool = False) -> None:
        """End the lane (idempotent): drop the queued jobs, end the child and reap it, and
        wait for the deferred work. A job still in the child is one nobody took: the child is
        killed rather than waited for (a model file it was writing is left incomplete, which the
        persistent cache ignores); an idle child ends when its job pipe closes (killed after
        :data:`END_WAIT_S`).

        Parameters
        ----------
        kill : bool
            End the child at once in any case (an exception or Ctrl-C in the parent).
        """
        with self._cond:
            if self._closed:
                return
            self._closed = True
            self.threads = 0
            for entry in self._queue.values():
                if entry[2] == "queued":
                    entry[1].set_exception(_LostError())
                kill = kill or entry[2] == "sent"
            self._queue = {}
            self._cond.notify_all()
        if self._proc is not None:
            if kill:
                self._proc.kill()
            self._jobs_w.close()   # the child reads the end of its jobs
            self._proc.join(END_WAIT_S)
            if self._proc.is_alive():  # pragma: no cover - a job far longer than expected
                self._proc.kill()
                self._proc.join()
            self._dispatcher.join()
            self._results_r.close()
        if self._deferred is not None:
            self._deferred.shutdown(wait=True)


def _exit_with_parent(parent_pid: int, period: float = 0.5) -> None:
    """End this process (a pool worker, or a :class:`ForkLane`'s child) when the sweep process
    that started it is gone.

    A pool worker blocks on its task queue, whose pipe it holds open itself, so it never sees
    an EOF when the parent is killed (SIGKILL, OOM killer, a closed terminal): without this
    watch it would stay orphaned for ever, holding memory and the parent's stdout. The chunks it
    finished are already on disk (atomic writes), and ``--resume`` recomputes the rest."""
    while True:
        time.sleep(period)
        if os.getppid() != parent_pid:
            os._exit(1)


def _serve(jobs, results, parent_jobs, parent_results, parent_pid: int) -> None:
    """The child: compute each job received and send back ``(ok, value)``, until the job pipe
    closes or the parent is gone."""
    parent_jobs.close()
    parent_results.close()
    signal.signal(signal.SIGINT, signal.SIG_IGN)   # Ctrl-C is the parent's: it ends the child
    signal.signal(signal.SIGTERM, signal.SIG_DFL)  # the command line's handler is the parent's
    limit_blas_threads(1)   # two processes on two cores: no BLAS threads busy-waiting
    threading.Thread(target=_exit_with_parent, args=(parent_pid,), daemon=True,
                     name="femcam-parent-watch").start()
    while True:
        try:
            job = pickle.loads(jobs.recv_bytes())
        except (EOFError, OSError):
            break
        try:
            value = job.in_child() if hasattr(job, "in_child") else job()
            data = pickle.dumps((True, value), protocol=5)
        except Exception:  # noqa: BLE001 - the parent computes it again (and raises there)
            data = pickle.dumps((False, None))
        try:
            results.send_bytes(data)
        except OSError:
            break
    os._exit(0)  # no cleanups of the parent's state (its atexit functions are the parent's)
