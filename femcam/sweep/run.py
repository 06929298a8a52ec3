"""``sweep(scene, *, angles=..., ...) -> SweepResult``: the main job of femcam.

Orchestration only: the analytic chain for all angles (vectorised, in this process), family
planning, chunking, the executor, the on-disk store and the output files. The per-angle work is
:func:`femcam.sweep.pipeline.run_chunk`.
"""

from __future__ import annotations

import hashlib
import os
import sys
import time
from pathlib import Path

import numpy as np

from .. import _validate as V  # noqa: N812
from ..errors import InputError
from .families import FamilyRecord, verify_families
from .parallel import Progress, run_tasks
from .pipeline import (
    ChunkTask,
    SweepOptions,
    analytic_rows,
    contact_mask,
    contact_params,
    roller_does_not_fit,
    run_chunk,
    vtu_name,
)
from .result import SweepResult, concat_rows
from .store import ChunkStore, array_hash
from .wear import wear_setup

DEFAULT_STEP_DEG = 1.0


def parse_angles_deg(spec: str) -> np.ndarray:
    """``"start:stop:step"`` in degrees (stop exclusive, like ``numpy.arange``) -> radians.

    >>> np.degrees(parse_angles_deg("0:90:30")).round(6).tolist()
    [0.0, 30.0, 60.0]
    """
    parts = str(spec).split(":")
    if len(parts) != 3:
        raise V.fail("--angles-deg", spec, "deg", "must be start:stop:step, e.g. 0:360:1")
    try:
        start, stop, step = (float(p) for p in parts)
    except ValueError:
        raise V.fail("--angles-deg", spec, "deg", "must be three numbers start:stop:step") from None
    if not all(np.isfinite([start, stop, step])):
        raise V.fail("--angles-deg", spec, "deg", "must be finite numbers")
    if step <= 0:
        raise V.fail("--angles-deg", spec, "deg", "step must be > 0")
    if stop <= start:
        raise V.fail("--angles-deg", spec, "deg", "stop must be > start")
    n = int(np.ceil((stop - start) / step - 1e-9))
    if n > 10_000_000:
        raise V.fail("--angles-deg", spec, "deg", "gives more than 1e7 angles")
    return np.radians(start + step * np.arange(n))


def _scene_hash(scene, scene_path) -> str:
    if scene_path is not None and Path(scene_path).is_file():
        h = hashlib.sha256(Path(scene_path).read_bytes())
        h.update(repr(scene).encode())  # also catches in-code changes such as --law
        return h.hexdigest()
    return hashlib.sha256(repr(scene).encode()).hexdigest()


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
#: back-solves of both bodies and a ~1 MB file; measured ~0.09 s), scaled with (a_over_h/10)^2
AUTO_VTU_S = 0.09


def auto_workers(n_tasks: int, n_solves: int, t_solve: float, n_families: int, t_build: float,
                 *, t_other: float = 0.0, cpus: int | None = None,
                 fork: bool | None = None) -> tuple[int, str]:
    """``workers="auto"``: how many local processes, and why (a one-line reason).

    The chunks' work is ``n_solves`` contact solves of ``t_solve`` each, plus ``t_other`` s of
    other work (writing the ``.vtu`` files): the family models are
    built and verified before the chunks run, in this process, and the verification already
    solves up to :data:`~femcam.sweep.families.MAX_SCAN` load cases per family (cached; forked
    workers inherit models and results, spawned ones rebuild the ``n_families`` models at
    ``t_build`` each). Processes are used only when they are expected to save at least
    :data:`AUTO_MIN_SAVING` of that time after the pool's fixed cost
    :data:`AUTO_POOL_OVERHEAD_S`. For the seed 002 study model (360 angles, ~1 ms per solve,
    200 of them solved during the verification) serial wins when no VTK is written; writing
    the CLI's default 36 ``.vtu`` files (~3 s) makes 2 processes pay (measured 5.6 s -> 4.4 s on
    2 cores). Processes also pay for long angle lists, fine meshes (slower solves) and resumed
    sweeps, which solve everything in the chunks.
    """
    cpus = _cpu_count() if cpus is None else int(cpus)
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
    return 1, (f"serial: ~{serial:.2f} s of {what} would take ~{par:.2f} s with {w} processes "
               "(pool start-up" + ("" if fork else ", rebuilt models") + ")")


def _scene_source(scene, scene_path):
    """(path of the scene file or None, its text or "")."""
    for p in (scene_path, getattr(scene, "source_path", None)):
        if p and Path(p).is_file():
            try:
                return Path(p), Path(p).read_text(encoding="utf-8")
            except (OSError, UnicodeDecodeError):
                return Path(p), ""
    return None, ""


def sweep(scene, *, angles=None, method: str = "fe", a_over_h: float = 10.0,
          tolerance: float = 2e-3, chunk_size: int = 30, out=None, resume: bool = False,
          workers: int | str = "auto", scheduler=None, client=None, vtk_every: int = 0,
          progress: bool | None = None, plots: bool = False, command: str | None = None,
          scene_path=None) -> SweepResult:
    """Sweep a scene over cam angles: kinematics, loads, Hertz and FE contact at every angle.

    Parameters
    ----------
    scene : a :class:`femcam.scene.Scene`, or the path of a scene TOML file.
    angles : cam angles (rad); default 0, 1, ..., 359 degrees.
    method : ``"fe"`` (FE contact solve, default) or ``"hertz"`` (analytic only, fast).
    a_over_h : FE element size in the contact zone ``h = a / a_over_h``.
    tolerance : bound on the relative p0 difference between an angle solved with its family's
        model and with a model built fresh for it (the reuse error); verified with fresh models
        at each family's worst-covered angles, families split until it holds
        (:mod:`femcam.sweep.families`). >= 1e-4.
    chunk_size : angles per chunk (unit of parallel work and of the on-disk store).
    out : output directory; ``None`` keeps everything in memory.
    resume : continue a killed sweep in ``out`` (loads finished chunks, computes the rest).
    workers : local worker processes (``1`` = serial in this process), or ``"auto"`` (default):
        processes only when the expected saving is worth it (:func:`auto_workers`); ignored
        with ``scheduler``/``client``.
    scheduler, client : Dask scheduler address, or a ``Client``/``LocalCluster``.
    vtk_every : with ``out``, write one ``.vtu`` every k angles and ``sweep.pvd`` (0 = none).
    progress : stderr progress bar (default: only when stderr is a TTY).
    plots : with ``out``, write the PNG plots (:mod:`femcam.viz.sweep`).

    Returns
    -------
    SweepResult
    """
    t_start = time.perf_counter()
    if isinstance(scene, (str, Path)):
        from ..scene import load_scene

        scene_path = scene
        scene = load_scene(scene)
    if angles is None:
        angles = np.radians(np.arange(0.0, 360.0, DEFAULT_STEP_DEG))
    angles = V.finite_array("angles", angles, "rad").ravel()
    if angles.size == 0:
        raise V.fail("angles", "[]", "rad", "must contain at least one angle")
    auto = isinstance(workers, str)
    if auto and workers != "auto":
        raise V.fail("workers", workers, "processes", "must be an integer >= 1 or 'auto'")
    if not auto:
        w = V.positive("workers", workers, "processes")
        if w != int(w):
            raise V.fail("workers", workers, "processes", "must be an integer >= 1 or 'auto'")
        workers = int(w)
    opts = SweepOptions(method=method, a_over_h=a_over_h, tolerance=tolerance,
                        chunk_size=chunk_size, vtk_every=vtk_every if out is not None else 0)
    if resume and out is None:
        raise V.fail("resume", resume, "", "needs an output directory (out)")

    # analytic chain for all angles (cheap, vectorised): contact mask, slip
    cp = contact_params(scene)
    rows0, st0 = analytic_rows(scene, angles)
    contact = contact_mask(rows0, st0)
    wear = wear_setup(scene, angles, st0)
    t_analytic = time.perf_counter() - t_start

    n = angles.size
    bounds = [(i, min(i + opts.chunk_size, n)) for i in range(0, n, opts.chunk_size)]
    shash = _scene_hash(scene, scene_path)
    key = {"scene_sha256": shash, "angles_sha256": array_hash(angles), "n_angles": int(n),
           **opts.to_dict()}

    store = None
    done: set[int] = set()
    vtk_dir = None
    vtk_mask = np.zeros(n, bool)
    if out is not None:
        out = Path(out)
        out.mkdir(parents=True, exist_ok=True)
        store = ChunkStore(out / "chunks", key, bounds)
        done = store.open(resume)
        if not done:  # fresh sweep: no stale series from an earlier run in the same DIR
            for p in (out / "vtk").glob("angle_*.vtu"):
                p.unlink()
            (out / "sweep.pvd").unlink(missing_ok=True)
        if opts.vtk_every:
            vtk_dir = out / "vtk"
            vtk_mask[:: opts.vtk_every] = True

    # model families, verified against the tolerance (FE only); a resume reuses the stored plan
    t0 = time.perf_counter()
    family, records = np.full(n, -1), []
    verified_here = False
    if opts.method == "fe":
        plan = store.load_plan() if (store is not None and resume) else None
        if plan is not None and len(plan.get("family", ())) == n:
            family = np.asarray(plan["family"], dtype=int)
            records = [FamilyRecord(**{**r, "a_ratio": tuple(r["a_ratio"]), "kappa": tuple(r["kappa"]),
                                       "checks": [tuple(c) for c in r["checks"]]})
                       for r in plan["records"]]
        else:
            fit = contact & ~roller_does_not_fit(rows0["rho"], cp.Rr)
            family, _, records = verify_families(rows0["Fc"], rows0["rho"], angles, cp, opts, fit)
            verified_here = True
            if store is not None:
                store.save_plan({"family": family.tolist(),
                                 "records": [r.to_dict() for r in records]})
    refs = {r.id: (r.rho_ref, r.a_ref) for r in records}
    t_verify = time.perf_counter() - t0

    tasks, task_chunk = [], []
    for c, (a, b) in enumerate(bounds):
        if c in done:
            continue
        fam = family[a:b]
        sub = {int(f): refs[int(f)] for f in np.unique(fam) if f >= 0}
        tasks.append(ChunkTask(index=c, scene=scene, theta=angles[a:b], options=opts,
                               family=fam, refs=sub,
                               vtk_dir=str(vtk_dir) if vtk_dir is not None else None,
                               vtk_mask=vtk_mask[a:b], slip=wear.chunk(a, b), wear_k=wear.k))
        task_chunk.append(c)

    workers_note = None
    if auto and (scheduler is not None or client is not None):
        workers, workers_note = 1, "Dask: the cluster's workers"
    elif auto:
        n_solves = sum(int(np.count_nonzero(contact[bounds[c][0]:bounds[c][1]])) for c in task_chunk)
        if verified_here:  # load cases solved during the verification are cached (forks inherit)
            n_solves = max(0, n_solves - sum(r.n_scanned for r in records))
        ts = [r.solve_time for r in records if np.isfinite(r.solve_time)]
        tb = [r.build_time for r in records if r.build_time > 0]
        t_solve = float(np.mean(ts)) if ts else (0.0 if opts.method == "hertz"
                                                  else 2e-3 * (opts.a_over_h / 10.0) ** 2)
        t_build = float(np.mean(tb)) if tb else 0.5 * (opts.a_over_h / 10.0) ** 2
        todo = np.zeros(n, bool)
        for c in task_chunk:
            todo[bounds[c][0]:bounds[c][1]] = True
        n_vtu = int(np.count_nonzero(todo & vtk_mask & contact))
        t_vtu = n_vtu * AUTO_VTU_S * ((opts.a_over_h / 10.0) ** 2 if opts.method == "fe" else 0.1)
        workers, workers_note = auto_workers(len(tasks), n_solves, t_solve, len(records), t_build,
                                             t_other=t_vtu)

    parts: dict[int, dict] = {}
    bar = Progress(sum(b - a for c, (a, b) in enumerate(bounds) if c not in done),
                   enabled=progress)
    t0 = time.perf_counter()
    try:
        for k, rows in run_tasks(run_chunk, tasks, workers=workers, scheduler=scheduler,
                                 client=client):
            c = task_chunk[k]
            if store is not None:
                store.write(c, rows)
            parts[c] = rows
            bar.update(bounds[c][1] - bounds[c][0])
    finally:
        bar.close()
    t_compute = time.perf_counter() - t0
    for c in done:
        parts[c] = store.load(c)
    table = concat_rows([parts[c] for c in range(len(bounds))])

    from ..io import provenance

    src_path, src_text = _scene_source(scene, scene_path)
    options = {**opts.to_dict(), "workers": workers,
               "scheduler": str(scheduler) if scheduler else None,
               "n_angles": int(n), "n_families": len(records)}
    if auto:
        options.update(workers_requested="auto", workers_reason=workers_note)
    prov = provenance(scene_path=scene_path if scene_path is not None else src_path,
                      scene_hash=shash, command=command, options=options,
                      families=[r.to_dict() for r in records] if opts.method == "fe" else None,
                      wear=wear.to_dict())
    timings = {"analytic": t_analytic, "verify": t_verify, "compute": t_compute}
    result = SweepResult(table=table, method=opts.method, provenance=prov, paths={},
                         timings=timings, n_chunks_computed=len(tasks), n_chunks_resumed=len(done))
    if out is not None:
        result = _write_outputs(result, scene, out, vtk_mask, plots, src_path, src_text)
    result.timings["total"] = time.perf_counter() - t_start
    return result


def _write_outputs(result: SweepResult, scene, out: Path, vtk_mask, plots: bool,
                   src_path=None, src_text: str = "") -> SweepResult:
    from ..io import write_csv, write_npz, write_pvd
    from .store import atomic_write_text

    paths = {}
    prov = dict(result.provenance)
    if src_path is not None and src_text:
        copy = out / "scene.toml"
        if not (copy.exists() and copy.resolve() == Path(src_path).resolve()):
            atomic_write_text(copy, src_text)
        paths["scene"] = str(copy)
        prov["scene_copy"] = (f"{copy.name} (copy of {src_path}; the sweep used the parsed scene "
                              "recorded as scene_repr in sweep.npz, which differs from the file "
                              "only if it was changed in code, e.g. --law)")
    result = SweepResult(**{**result.__dict__, "provenance": prov})
    paths.update(csv=str(write_csv(out / "sweep.csv", result.table, prov)),
                 npz=str(write_npz(out / "sweep.npz", result.table, prov, scene_toml=src_text,
                                   scene_repr=repr(scene))))
    if np.any(vtk_mask):
        theta = result.table["theta"]
        entries = []
        for i in np.flatnonzero(vtk_mask):
            p = out / "vtk" / vtu_name(theta[i])
            if p.exists():
                entries.append((float(np.degrees(theta[i])), p))
        if entries:
            paths["pvd"] = str(write_pvd(out / "sweep.pvd", entries))
    result = SweepResult(**{**result.__dict__, "paths": paths})
    if plots:
        from ..viz.sweep import plot_sweep

        try:
            paths.update(plot_sweep(result, scene, out))
        except ImportError as exc:  # pragma: no cover - matplotlib missing
            raise InputError(f"plots = True: {exc}") from None
    return result
