"""BLAS thread control without extra dependencies (used by ``femcam.fe`` and ``femcam.sweep``),
and :class:`Background`, jobs run ahead in background threads and taken back by key (the sweep's
family phase builds its independent FE models on a second core with it).

OpenBLAS reads ``OPENBLAS_NUM_THREADS`` only when it loads, so the running libraries are told
directly through ``ctypes`` (the ``openblas_set_num_threads`` calls that threadpoolctl makes;
threadpoolctl itself is not needed). Only OpenBLAS builds are handled (the NumPy and SciPy
wheels ship ``scipy_openblas``); with another BLAS, or off Linux, these are no-ops.

Why one thread: SuperLU's multi-right-hand-side triangular solves (the FE condensation) and the
worker processes of a sweep call BLAS on small blocks; several BLAS threads per process on a
shared 2-core machine busy-wait against each other and against other processes (the
measurement is in docs/performance.md). A threaded BLAS may also sum in a different order, so results
would depend on the executor in the last bits.

>>> from femcam._threads import single_threaded_blas
>>> with single_threaded_blas():
...     pass
"""

from __future__ import annotations

import ctypes
import sys
import threading
from concurrent.futures import Future, ThreadPoolExecutor

_BLAS_PREFIXES = ("openblas_", "scipy_openblas_")
_BLAS_SUFFIXES = ("", "64_")


_found: tuple = (-1, [])  # (len(sys.modules) at the last scan, its libraries)


def _blas_libs():
    """ctypes handles ``(get, set)`` of the OpenBLAS builds loaded in this process (Linux only).

    The scan of ``/proc/self/maps`` is redone only when a module was imported since the last
    one (a new OpenBLAS comes with a new extension module), because every ``Body.solve`` enters
    :class:`single_threaded_blas`.
    """
    global _found
    if _found[0] != len(sys.modules):
        _found = (len(sys.modules), _scan_blas_libs())
    return _found[1]


def _scan_blas_libs():
    """:func:`_blas_libs` read from ``/proc/self/maps``."""
    try:
        with open("/proc/self/maps") as f:
            paths = {line.split()[-1] for line in f if ".so" in line and "openblas" in line.lower()}
    except OSError:  # not Linux
        return []
    out = []
    for p in sorted(paths):
        try:
            dll = ctypes.CDLL(p)
        except OSError:
            continue
        for pre in _BLAS_PREFIXES:
            for suf in _BLAS_SUFFIXES:
                get = getattr(dll, f"{pre}get_num_threads{suf}", None)
                put = getattr(dll, f"{pre}set_num_threads{suf}", None)
                if get is not None and put is not None:
                    out.append((get, put))
                    break
            else:
                continue
            break
    return out


def blas_threads() -> list[int]:
    """Current thread count of every loaded OpenBLAS (empty list if none is found)."""
    out = []
    for get, _ in _blas_libs():
        try:
            out.append(int(get()))
        except Exception:  # pragma: no cover - exotic builds
            out.append(-1)
    return out


def _set_threads(n: int) -> list[tuple]:
    """Set every loaded OpenBLAS to ``n`` threads; ``[(set function, previous count), ...]``."""

    changed = []
    for get, put in _blas_libs():
        try:
            prev = int(get())
            put(ctypes.c_int(int(n)))
        except Exception:  # pragma: no cover - exotic builds
            prev = -1
        changed.append((put, prev))
    return changed


def limit_blas_threads(n: int = 1) -> list[int]:
    """Best effort: set the thread count of every loaded OpenBLAS; returns the previous counts.

    Why: (1) worker processes forked from a parent inherit its BLAS thread pool (one thread per
    core), and N workers x N BLAS threads on N cores busy-wait against each other; (2) a
    threaded BLAS may sum in a different order, so results would
    depend on the executor in the last bits. Environment variables are read only when the
    library loads, so the running library is told directly (the calls threadpoolctl makes).
    """
    return [prev for _, prev in _set_threads(n)]


_lock = threading.Lock()
_depth = 0
_saved: list = []  # (set function, previous count) of each library changed by the outermost enter


class single_threaded_blas:  # noqa: N801 - used like a function
    """Context manager: one BLAS thread inside, the previous counts restored after.

    Re-entrant and shared between threads: the counts are saved by the first ``__enter__`` and
    restored by the last ``__exit__``, so nested uses (a sweep worker around an FE build) and
    concurrent Dask worker threads never restore a multi-threaded pool while another one is
    still inside.
    """

    def __enter__(self):
        global _depth, _saved
        with _lock:
            if _depth == 0:
                _saved = _set_threads(1)
            _depth += 1
        return self

    def __exit__(self, *exc):
        global _depth, _saved
        with _lock:
            _depth -= 1
            if _depth == 0:
                for put, n in _saved:
                    if n > 0:
                        put(ctypes.c_int(n))
                _saved = []
        return False


class Background:
    """Jobs run in background threads while the caller works, and taken back by key.

    :meth:`submit` queues ``fn()`` under a key (nothing when there are no threads, or when the
    key is queued already); :meth:`take` returns the result: the job's, or ``fn()`` computed in
    the calling thread when the job was never queued or has not started (it is then cancelled:
    the caller never waits for work it can do itself). While the job it takes is running, the
    caller runs the oldest queued jobs itself (their results kept for their own :meth:`take`),
    so neither thread idles while work is queued. A job's exception is raised by :meth:`take`,
    as if ``fn()`` had run there; a job nobody takes is dropped. :meth:`defer` queues work done
    for its effect (a cache file written) that is never dropped. A context manager: on exit the
    queued jobs are cancelled, the running ones and the deferred work waited for (a job is one
    model build, a fraction of a second at the default mesh).

    Why threads and not processes: the jobs are FE model builds, whose results (factorised
    bodies) cannot be pickled to another process; their SuperLU solves and numpy kernels
    release the GIL and overlap, their meshing (one gmsh at a time), factorisations (scipy
    runs one at a time) and sparse conversions do not, which bounds the gain
    (docs/performance.md).

    Parameters
    ----------
    threads : int
        Background threads (0: none; every :meth:`take` computes in the caller).

    >>> with Background(1) as bg:
    ...     bg.submit("x", lambda: 2 + 2)
    ...     bg.take("x", lambda: 4)
    4
    """

    def __init__(self, threads: int = 1):
        self.threads = max(0, int(threads))
        self._jobs: dict = {}   # key -> (Future, fn), in the order submitted
        self._lock = threading.Lock()
        self._pool = (ThreadPoolExecutor(self.threads, thread_name_prefix="femcam-background")
                      if self.threads else None)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def close(self) -> None:
        """Cancel the queued jobs, wait for the running ones; later submits do nothing."""
        with self._lock:
            pool, self._pool = self._pool, None
            jobs, self._jobs = self._jobs, {}
        for f, _ in jobs.values():
            f.cancel()
        if pool is not None:
            pool.shutdown(wait=True)

    def submit(self, key, fn) -> None:
        """Queue ``fn()`` under ``key`` (hashable) unless it is queued already or there are no
        threads."""
        with self._lock:
            if self._pool is not None and key not in self._jobs:
                self._jobs[key] = (self._pool.submit(fn), fn)

    def defer(self, fn) -> None:
        """Run ``fn()`` in the background, for its effect (e.g. a file written): never
        cancelled, waited for on exit (its exceptions dropped); run here at once when there
        are no threads."""
        with self._lock:
            pool = self._pool
            if pool is not None:
                pool.submit(fn)
                return
        fn()

    def take(self, key, fn):
        """The result of the job ``key``, or ``fn()`` here if it was never queued or has not
        started (see the class docstring)."""
        with self._lock:
            fut, _ = self._jobs.pop(key, (None, None))
        if fut is None or fut.cancel():
            return fn()
        while not fut.done() and self._help():
            pass
        return fut.result()

    def _help(self) -> bool:
        """Run the oldest queued job in this thread (its result kept under its key); False when
        none is queued."""
        with self._lock:
            for key, (f, fn) in self._jobs.items():
                if f.cancel():
                    mine = Future()
                    self._jobs[key] = (mine, fn)
                    break
            else:
                return False
        try:
            mine.set_result(fn())
        except Exception as exc:  # noqa: BLE001 - raised by the take of its own key
            mine.set_exception(exc)
        return True
