"""Where the chunks run: in this process, in local worker processes, or on a Dask cluster.

All three take the same picklable tasks (a scene, a few hundred angles and the options -- no
big arrays) and the same module-level function, and yield ``(task_id, rows)`` as chunks finish.
Each worker process keeps its own cache of FE models (see
:func:`femcam.sweep.pipeline.model_for`), so a family's mesh and factorisation are built once
per process, not once per chunk.

* ``workers <= 1`` and no Dask: serial, in this process.
* ``workers = N``: :class:`concurrent.futures.ProcessPoolExecutor`. On Linux the ``fork``
  start method (no re-import, works from scripts without a ``__main__`` guard; the parent has
  not touched gmsh at that point: it only ran the analytic chain); elsewhere ``spawn``.
* ``scheduler = "tcp://host:8786"`` or ``client = Client(...)`` / a ``LocalCluster``: Dask
  distributed; femcam must be importable on the workers.
"""

from __future__ import annotations

import multiprocessing
import os
import sys
import threading
import time
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import ProcessPoolExecutor, as_completed

from .._threads import limit_blas_threads
from ..errors import InputError


def run_tasks(fn: Callable, tasks: Iterable, *, workers: int = 1, scheduler=None,
              client=None) -> Iterator[tuple[int, object]]:
    """Run ``fn(task)`` for every task; yield ``(index in tasks, result)`` in completion order."""
    tasks = list(tasks)
    if not tasks:
        return
    if client is not None or scheduler is not None:
        yield from _run_dask(fn, tasks, scheduler=scheduler, client=client)
    elif workers is None or workers <= 1 or len(tasks) == 1:
        for i, t in enumerate(tasks):
            yield i, fn(t)
    else:
        yield from _run_pool(fn, tasks, workers)


def _worker_init(parent_pid: int | None = None):
    limit_blas_threads(1)
    if parent_pid is not None:
        threading.Thread(target=_exit_with_parent, args=(parent_pid,), daemon=True,
                         name="femcam-parent-watch").start()


def _exit_with_parent(parent_pid: int, period: float = 0.5) -> None:
    """End this worker when the sweep process that started it is gone.

    A pool worker blocks on its task queue, whose pipe it holds open itself, so it never sees
    an EOF when the parent is killed (SIGKILL, OOM killer, a closed terminal): without this
    watch it would stay orphaned for ever, holding memory and the parent's stdout. The chunks it
    finished are already on disk (atomic writes), and ``--resume`` recomputes the rest."""
    while True:
        time.sleep(period)
        if os.getppid() != parent_pid:
            os._exit(1)


def _run_pool(fn, tasks, workers):
    methods = multiprocessing.get_all_start_methods()
    ctx = multiprocessing.get_context("fork" if sys.platform.startswith("linux") and "fork" in methods
                                      else "spawn")
    with ProcessPoolExecutor(max_workers=min(workers, len(tasks)), mp_context=ctx,
                             initializer=_worker_init, initargs=(os.getpid(),)) as ex:
        futs = {ex.submit(fn, t): i for i, t in enumerate(tasks)}
        try:
            for f in as_completed(futs):
                yield futs[f], f.result()
        except BaseException:
            for f in futs:
                f.cancel()
            raise


def _run_dask(fn, tasks, *, scheduler=None, client=None):
    try:
        from dask.distributed import Client  # lazy: dask is an optional extra (femcam[dask])
        from dask.distributed import as_completed as dask_completed
    except ImportError:  # pragma: no cover - optional dependency
        raise InputError("scheduler = "
                         f"{scheduler!r}: Dask is not installed (pip install 'femcam[dask]')") from None
    own = None
    if client is None:
        try:
            own = client = Client(scheduler, timeout="20s")
        except (OSError, TimeoutError, ValueError) as exc:
            raise InputError(f"scheduler = {scheduler!r}: cannot connect to the Dask scheduler "
                             f"({exc})") from None
    elif not isinstance(client, Client):  # a LocalCluster / cluster object
        own = client = Client(client)
    try:
        futs = [client.submit(fn, t, pure=False, key=f"femcam-chunk-{i}-{time.time_ns()}")
                for i, t in enumerate(tasks)]
        index = {f.key: i for i, f in enumerate(futs)}
        for f in dask_completed(futs):
            yield index[f.key], f.result()
    finally:
        if own is not None:
            own.close()


class Progress:
    """A one-line progress bar on stderr, shown only when stderr is a TTY (no tqdm needed)."""

    def __init__(self, total: int, label: str = "sweep", enabled: bool | None = None,
                 stream=None):
        self.stream = stream or sys.stderr
        if enabled is None:
            enabled = bool(getattr(self.stream, "isatty", lambda: False)())
        self.enabled = enabled and total > 0
        self.total, self.done, self.label = total, 0, label
        self.t0 = time.perf_counter()

    def update(self, n: int) -> None:
        self.done += n
        if not self.enabled:
            return
        frac = min(1.0, self.done / self.total)
        width = 30
        bar = "#" * int(round(frac * width))
        el = time.perf_counter() - self.t0
        eta = el / frac - el if frac > 0 else float("nan")
        self.stream.write(f"\r{self.label} [{bar:<{width}}] {self.done}/{self.total} angles "
                          f"{el:5.1f} s, eta {eta:5.1f} s")
        self.stream.flush()

    def close(self) -> None:
        if self.enabled:
            self.stream.write("\n")
            self.stream.flush()
