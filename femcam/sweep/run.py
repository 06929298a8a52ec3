"""``sweep(scene, *, angles=..., ...) -> SweepResult``: the main job of femcam.

Orchestration only: the analytic chain for all angles (vectorised, in this process), family
planning, chunking, the executor, the on-disk store and the output files. The per-angle work is
:func:`femcam.sweep.pipeline.run_chunk`.
"""

from __future__ import annotations

import hashlib
import time
from pathlib import Path

import numpy as np

from .. import _validate as V  # noqa: N812
from ..errors import InputError
from .parallel import Progress, run_tasks
from .pipeline import (
    ChunkTask,
    SweepOptions,
    analytic_rows,
    contact_mask,
    contact_params,
    plan_families,
    run_chunk,
    vtu_name,
)
from .result import SweepResult, concat_rows
from .store import ChunkStore, array_hash

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


def sweep(scene, *, angles=None, method: str = "fe", a_over_h: float = 10.0,
          tolerance: float = 2e-3, chunk_size: int = 30, out=None, resume: bool = False,
          workers: int = 1, scheduler=None, client=None, vtk_every: int = 0,
          progress: bool | None = None, plots: bool = False, command: str | None = None,
          scene_path=None) -> SweepResult:
    """Sweep a scene over cam angles: kinematics, loads, Hertz and FE contact at every angle.

    Parameters
    ----------
    scene : a :class:`femcam.scene.Scene`, or the path of a scene TOML file.
    angles : cam angles (rad); default 0, 1, ..., 359 degrees.
    method : ``"fe"`` (FE contact solve, default) or ``"hertz"`` (analytic only, fast).
    a_over_h : FE element size in the contact zone ``h = a / a_over_h``.
    tolerance : relative p0 error allowed from reusing a model across angles.
    chunk_size : angles per chunk (unit of parallel work and of the on-disk store).
    out : output directory; ``None`` keeps everything in memory.
    resume : continue a killed sweep in ``out`` (loads finished chunks, computes the rest).
    workers : local worker processes (``1`` = serial in this process).
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
    workers = int(V.positive("workers", workers, "processes"))
    opts = SweepOptions(method=method, a_over_h=a_over_h, tolerance=tolerance,
                        chunk_size=chunk_size, vtk_every=vtk_every if out is not None else 0)
    if resume and out is None:
        raise V.fail("resume", resume, "", "needs an output directory (out)")

    # analytic chain for all angles (cheap, vectorised): contact mask and families
    cp = contact_params(scene)
    rows0, st0 = analytic_rows(scene, angles)
    contact = contact_mask(rows0, st0)
    if opts.method == "fe":
        family, refs = plan_families(rows0["Fc"], rows0["rho"], cp, opts.tolerance, contact)
    else:
        family, refs = np.full(angles.size, -1), {}
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

    tasks, task_chunk = [], []
    for c, (a, b) in enumerate(bounds):
        if c in done:
            continue
        fam = family[a:b]
        sub = {int(f): refs[int(f)] for f in np.unique(fam) if f >= 0}
        tasks.append(ChunkTask(index=c, scene=scene, theta=angles[a:b], options=opts,
                               family=fam, refs=sub,
                               vtk_dir=str(vtk_dir) if vtk_dir is not None else None,
                               vtk_mask=vtk_mask[a:b]))
        task_chunk.append(c)

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

    prov = provenance(scene_path=scene_path, scene_hash=shash, command=command,
                      options={**opts.to_dict(), "workers": workers,
                               "scheduler": str(scheduler) if scheduler else None,
                               "n_angles": int(n), "n_families": len(refs)})
    timings = {"analytic": t_analytic, "compute": t_compute}
    result = SweepResult(table=table, method=opts.method, provenance=prov, paths={},
                         timings=timings, n_chunks_computed=len(tasks), n_chunks_resumed=len(done))
    if out is not None:
        result = _write_outputs(result, scene, out, vtk_mask, plots)
    result.timings["total"] = time.perf_counter() - t_start
    return result


def _write_outputs(result: SweepResult, scene, out: Path, vtk_mask, plots: bool) -> SweepResult:
    from ..io import write_csv, write_npz, write_pvd

    paths = {"csv": str(write_csv(out / "sweep.csv", result.table, result.provenance)),
             "npz": str(write_npz(out / "sweep.npz", result.table, result.provenance))}
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
