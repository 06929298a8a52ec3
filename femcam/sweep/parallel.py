"""Where the chunks run: in this process, in local worker processes, or on a Dask cluster.

All three take the same picklable tasks (a scene, a few hundred angles and the options -- no
big arrays) and the same module-level function, and yield ``(task_id, rows)`` as chunks finish.
Each worker process keeps its own cache of FE models (see
:class:`femcam.sweep.cache.ModelCache`), so a family's mesh and factorisation are built once
per process, not once per chunk.

* ``workers <= 1`` and no Dask: serial, in this process.
* ``workers = N``: :class:`concurrent.futures.ProcessPoolExecutor`. On Linux the ``fork``
  start method (no re-import, works from scripts without a ``__main__`` guard; the parent has
  not touched gmsh at that point: it only ran the analytic chain); elsewhere ``spawn``.
* ``scheduler = "tcp://host:8786"`` or ``client = Client(...)`` / a ``LocalCluster``: Dask
  distributed; femcam must be importable on the workers.

``workers="auto"`` (:func:`auto_workers`) decides between serial and a process pool from the
expected work.
"""

from __future__ import annotations

import dataclasses
import multiprocessing
import os
import signal
import sys
import tempfile
import threading
import time
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from pathlib import Path

from .. import _validate
from .._threads import limit_blas_threads
from ..errors import InputError, WorkerLostError
from ..io import TEMP_SUFFIX, atomic_write_bytes
from .diskcache import read_only

#: ``workers="auto"``: use processes only if they are expected to save at least this fraction
AUTO_MIN_SAVING = 0.25
#: ``workers="auto"``: fixed cost of starting a process pool and collecting its results (s)
AUTO_POOL_OVERHEAD_S = 0.4


def _cpu_count() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):  # pragma: no cover - not Linux
        return os.cpu_count() or 1


#: ``workers="auto"``: estimated time to write one FE ``.vtu`` at a_over_h = 10 (s; full-field
#: back-solves of both bodies with the cached stress operator, ~10 ms, and an uncompressed
#: ~1.7 MB file, ~4 ms), scaled with (a_over_h/10)^2
AUTO_VTU_S = 0.015


def auto_workers(n_tasks: int, n_solves: int, t_solve: float, n_families: int, t_build: float,
                 *, t_other: float = 0.0, cpus: int | None = None,
                 fork: bool | None = None) -> tuple[int, str]:
    """``workers="auto"``: how many local processes, and why (a one-line reason).

    The chunks' work is ``n_solves`` contact solves of ``t_solve`` each, plus ``t_other`` s of
    other work (writing the ``.vtu`` files): the family models are
    built and verified before the chunks run, in this process, and the verification already
    solves up to :data:`~femcam.sweep.verify.MAX_SCAN` load cases per family (cached; forked
    workers inherit models and results, spawned ones rebuild the ``n_families`` models at
    ``t_build`` each). Processes are used only when they are expected to save at least
    :data:`AUTO_MIN_SAVING` of that time after the pool's fixed cost
    :data:`AUTO_POOL_OVERHEAD_S`. For the seed 002 study model (360 angles, 200 of them solved
    during the verification) serial wins, also with the CLI's default 36 ``.vtu`` files
    (docs/performance.md). Processes pay for long angle lists, fine meshes (slower
    solves), many VTU files and resumed sweeps, which solve everything in the chunks.

    Parameters
    ----------
    n_tasks : int
        Chunks to compute.
    n_solves : int
        Contact solves the chunks still have to do.
    t_solve : float
        Time per solve (s).
    n_families : int
        Model families (rebuilt by spawned workers).
    t_build : float
        Time per model build (s).
    t_other : float
        Other work of the chunks (s), e.g. writing ``.vtu`` files.
    cpus : int, optional
        Usable cores (default: this process's affinity).
    fork : bool, optional
        Whether workers are forked (default: on Linux).

    Returns
    -------
    workers : int
        1 (serial) or the number of processes.
    reason : str
        One line saying why.
    """
    n_tasks = _validate.integer("n_tasks", n_tasks, 0, "chunks")
    _validate.integer("n_solves", n_solves, 0, "solves")
    _validate.nonnegative("t_solve", t_solve, "s")
    _validate.integer("n_families", n_families, 0, "families")
    _validate.nonnegative("t_build", t_build, "s")
    _validate.nonnegative("t_other", t_other, "s")
    cpus = _cpu_count() if cpus is None else _validate.integer("cpus", cpus, 1, "cores")
    if fork is None:
        fork = sys.platform.startswith("linux")
    serial = n_solves * t_solve + t_other
    w = max(1, min(cpus, n_tasks))
    if w < 2:
        return 1, f"serial: {cpus} core(s), {n_tasks} chunk(s)"
    par = serial / w + AUTO_POOL_OVERHEAD_S + (0.0 if fork else n_families * t_build)
    what = "solves" + (" and VTU files" if t_other > 0 else "")
    if par <= (1.0 - AUTO_MIN_SAVING) * serial:
        return w, f"{w} processes: ~{serial:.2f} s of {what} serially, ~{par:.2f} s expected in parallel"
    return 1, (f"serial: ~{serial:.2f} s of {what}; {w} processes would not be faster (~{par:.2f} s "
               "with the pool start-up" + ("" if fork else " and the rebuilt models") + ")")



def run_tasks(fn: Callable, tasks: Iterable, *, workers: int = 1, scheduler=None,
              client=None) -> Iterator[tuple[int, object]]:
    """Run ``fn(task)`` for every task, serially, in a process pool or on Dask.

    Parameters
    ----------
    fn : callable
        A module-level (picklable) function of one task.
    tasks : iterable
        The tasks.
    workers : int
        Local processes, >= 1 (1: serial in this process).
    scheduler : str, optional
        Dask scheduler address.
    client : dask.distributed.Client or cluster, optional

    Yields
    ------
    tuple[int, object]
        ``(index in tasks, fn(task))`` in completion order.

    Raises
    ------
    femcam.errors.WorkerLostError
        A process of the pool ended without its result (killed: out of memory, a signal);
        the pool's other workers are stopped.
    """
    if not callable(fn):
        raise _validate.fail("fn", fn, "", "must be a module-level function of one task")
    tasks = list(tasks)
    if not tasks:
        return
    if client is not None or scheduler is not None:
        yield from _run_dask(fn, tasks, scheduler=scheduler, client=client)
    elif _validate.optional(_validate.integer, "workers", workers, 1, "processes") in (None, 1) \
            or len(tasks) == 1:
        for i, t in enumerate(tasks):
            yield i, fn(t)
    else:
        yield from _run_pool(fn, tasks, workers)


def _worker_init(parent_pid: int | None = None):
    limit_blas_threads(1)
    # Ctrl-C is the parent's to handle (one line, exit 130); the parent stops the pool
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    # a forked worker inherits the command line's SIGTERM handler (femcam._interrupt); the pool
    # ends its workers with SIGTERM, which must end them at once
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
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
        except BrokenProcessPool:  # a worker died: the pool has failed every future already
            raise WorkerLostError("a worker process ended without its result (killed by the "
                                  "system, e.g. out of memory, or by a signal)") from None
        except BaseException:
            for f in futs:
                f.cancel()
            # (chunks in flight finish, bounded by one chunk per worker; terminating the workers
            # instead breaks the executor's pipes mid-shutdown)
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
        futs = [client.submit(_files_back, fn, t, pure=False,
                              key=f"femcam-chunk-{i}-{time.time_ns()}")
                for i, t in enumerate(tasks)]
        index = {f.key: i for i, f in enumerate(futs)}
        for f in dask_completed(futs):
            rows, files = f.result()
            _write_back(tasks[index[f.key]], files)
            yield index[f.key], rows
    finally:
        if own is not None:
            own.close()


def _files_back(fn, task):
    """Run ``fn(task)`` on a Dask worker with its files written to a private temporary directory,
    and return ``(rows, {file name: bytes})``: the client writes them (:func:`_write_back`).

    A worker's working directory and disk are not the client's (another directory for a
    relative ``--out``, another machine on a cluster), so a worker writes nothing into the
    output directory itself; nor into the model cache: it reads what the client stored
    (:func:`femcam.sweep.diskcache.read_only`, a cache directory it can reach)."""
    if getattr(task, "disk", None) is not None:
        task = dataclasses.replace(task, disk=read_only(task.disk))
    vtk_dir = getattr(task, "vtk_dir", None)
    if vtk_dir is None:
        return fn(task), {}
    with tempfile.TemporaryDirectory(prefix="femcam-chunk-") as tmp:
        rows = fn(dataclasses.replace(task, vtk_dir=tmp))
        files = {p.name: p.read_bytes() for p in sorted(Path(tmp).iterdir())
                 if not p.name.endswith(TEMP_SUFFIX)}
    return rows, files


def _write_back(task, files: dict) -> None:
    """Write the files a Dask worker returned into the task's ``vtk_dir`` (atomically)."""
    if not files:
        return
    root = Path(task.vtk_dir)
    root.mkdir(parents=True, exist_ok=True)
    for name, data in files.items():
        atomic_write_bytes(root / name, lambda f, d=data: f.write(d))
