"""``sweep(scene, options, run) -> SweepResult``: the main job of femcam.

Orchestration only: the analytic chain for all angles (vectorised, in this process), family
planning, chunking, the executor and the on-disk store; the output files are written by
:mod:`femcam.sweep.outputs`. The per-angle work is :func:`femcam.sweep.pipeline.run_chunk`.
"""

from __future__ import annotations

import os
import time
from pathlib import Path
from types import SimpleNamespace

import numpy as np

from .. import _validate
from .._progress import Progress
from ..errors import WorkerLostError
from ..hertz.conformity import roller_does_not_fit
from ..io import provenance
from ..mesh import MeshOptions
from ..mesh.estimate import check_contact_elements
from ..scene import load_scene
from ..scene.digest import physics_hash, physics_parts
from ..viz.process import start_plot_process
from .cache import default_cache
from .diskcache import DiskCache, usage
from .estimate import estimate_run, prefetch_estimate
from .extras import extras_provenance
from .options import ResolvedOptions, RunOptions, SweepOptions, contact_params
from .outputs import SweepRun, early_plots, scene_hash, scene_source, write_outputs
from .parallel import AUTO_VTU_S, _cpu_count, auto_workers, run_tasks
from .pipeline import ChunkTask, contact_mask, run_chunk
from .realcam import auto_hertz_rows, contact_scene, jump_angles, real_cam_summary, scene_traction
from .result import SweepResult
from .rtol import choose_mesh
from .settings import resolve_settings
from .store import LOCK, STREAM_ANGLES, ChunkStore, DirLock, array_hash
from .table import TableBuilder
from .verify import FamilyRecord, verify_families
from .wear import wear_setup

ANALYTIC_BLOCK = 20_000  # angles per Scene.analyse call in the analytic phase (memory)


def parse_angles_deg(spec: str) -> np.ndarray:
    """``"start:stop:step"`` in degrees -> radians: the stop included when it falls on the
    grid, dropped for a range of whole turns (:func:`femcam._validate.angles_deg` for the flag
    ``--angles-deg``).

    Parameters
    ----------
    spec : str
        ``start:stop:step`` in degrees.

    Returns
    -------
    ndarray
        Cam angles (rad).

    >>> np.degrees(parse_angles_deg("0:90:30")).round(6).tolist()
    [0.0, 30.0, 60.0, 90.0]
    """
    return _validate.angles_deg("--angles-deg", spec)


def sweep(scene, options: SweepOptions | None = None, run: RunOptions | None = None) -> SweepResult:
    """Sweep a scene over cam angles: kinematics, loads, Hertz and FE contact at every angle.

    What is computed is ``options``; each option left at None takes the scene's ``[fe]`` /
    ``[sweep]`` value (:attr:`femcam.scene.Scene.study`), else femcam's default, as each flag of
    ``femcam sweep`` does (one resolution for both, :func:`femcam.sweep.settings.resolve_settings`:
    ``sweep(path)`` and ``femcam sweep path`` compute the same rows). How it runs (output
    directory, workers, cache, progress) is ``run``. The settings and their sources are in
    ``provenance["options"]["settings"]``.

    Parameters
    ----------
    scene : femcam.scene.Scene or str or Path
        A scene, or the path of a scene TOML file.
    options : SweepOptions, optional
        Angles [rad], method, ``a_over_h``, ``tolerance``, ``rtol``, ``rtol_on``, chunk size,
        VTK stride, plots, animation (:class:`femcam.sweep.options.SweepOptions`); default all
        from the scene, else femcam's defaults.
    run : RunOptions, optional
        Output directory, resume / overwrite, workers or Dask, progress, model cache, the
        recorded command line and scene path (:class:`femcam.sweep.options.RunOptions`);
        default in memory, ``workers="auto"``.

    Returns
    -------
    SweepResult

    Raises
    ------
    InputError
        ``options`` or ``run`` of another type, or settings that cannot go together (``rtol``
        with ``a_over_h``, ``animate`` without VTK output).
    SweepInterrupted
        On Ctrl-C (a ``KeyboardInterrupt`` saying what was saved and how to resume).
    WorkerLostError
        A worker process ended without its result (killed by the system or a signal); the
        message says what was saved and how to resume, as for Ctrl-C.

    Examples
    --------
    >>> from femcam import RunOptions, SweepOptions, sweep        # doctest: +SKIP
    >>> r = sweep("examples/seed002_study_model.toml", SweepOptions(method="hertz"),
    ...           RunOptions(out="out", workers=2))               # doctest: +SKIP
    """
    t_start = time.perf_counter()
    options = SweepOptions() if options is None else _validate.instance("options", options, SweepOptions)
    ro = RunOptions() if run is None else _validate.instance("run", run, RunOptions)
    run = _prepare(scene, options, ro)
    run.overwrite = ro.overwrite
    run.animate = bool(options.animate)
    run.disk = DiskCache(ro.cache_dir, enabled=ro.model_cache)
    if run.animate and not run.opts.vtk_every:
        raise _validate.fail("animate", True, "", "needs the VTK series: an output directory "
                             "(out) and vtk_every > 0 (--vtk-every)")
    plots = run.out is not None and run.settings.plots
    run.plotter = start_plot_process() if plots else None  # imports matplotlib meanwhile
    try:
        return _sweep(run, ro.scheduler, ro.client, ro.progress, plots, ro.command, t_start)
    except KeyboardInterrupt:
        raise SweepInterrupted(_interrupt_message(run)) from None
    except WorkerLostError as exc:  # what was saved, as for Ctrl-C
        raise WorkerLostError(f"{exc}; {_saved_message(run)}") from None
    finally:
        if run.plotter is not None:
            run.plotter.close()
        if run.lock is not None:
            run.lock.release()


class SweepInterrupted(KeyboardInterrupt):
    """Ctrl-C during a sweep; the message says what was saved and how to resume."""


def _interrupt_message(run: SweepRun) -> str:
    return "interrupted; " + _saved_message(run)


def _saved_message(run: SweepRun) -> str:
    """How many chunks are saved and how to go on (a run without an output directory: none)."""
    if run.store is None or run.out is None:
        return "nothing was saved" + ("" if run.out is None else
                                      f" in {run.out} (rerun the same command)")
    saved = sum(1 for i in range(len(run.bounds)) if run.store.path(i).exists())
    return (f"{saved} of {len(run.bounds)} chunks saved in {run.out / 'chunks'}; "
            "rerun the same command with --resume to compute the rest")


def _sweep(run: SweepRun, scheduler, client, progress, plots, command, t_start) -> SweepResult:
    talk = Progress(0, enabled=progress)
    with talk.phase(f"analytic chain ({run.angles.size} angles)"):
        _analytic(run)
    t_analytic = time.perf_counter() - t_start
    t0 = time.perf_counter()
    cache = default_cache()
    cache.disk = run.disk
    before = dict(cache.stats)
    if run.opts.rtol is not None:
        with talk.phase(f"mesh for rtol {100 * run.opts.rtol:g} %: a pilot estimate and a mesh per family"):
            with cache.building_in_background(_background_threads(run)):  # as _plan's builds
                choose_mesh(run, _fit_rows, cache)
    _open_store(run)
    with talk.phase("model families: build, verify, estimate the error (a coarse model each)"):
        _plan(run)
        estimate_run(run, default_cache())
    t_verify = time.perf_counter() - t0
    # svaj_loads.png: drawn by the plot process during the chunk solves (after the family
    # phase, whose background builds use the second core on a cold run)
    early_plots(run)
    tasks, task_chunk = _tasks(run)
    workers, workers_note = _choose_workers(run, tasks, task_chunk, scheduler, client)
    t0 = time.perf_counter()
    table = _compute(run, tasks, task_chunk, workers, scheduler, client, progress)
    t_compute = time.perf_counter() - t0
    src_path, src_text = scene_source(run.scene, run.scene_path)
    options = {**run.opts.to_dict(), "workers": workers,
               "scheduler": str(scheduler) if scheduler else None,
               "n_angles": int(run.angles.size), "n_families": len(run.records)}
    if run.workers == "auto":
        options.update(workers_requested="auto", workers_reason=workers_note)
    options.update(real_cam_summary(table, run.traction), rtol_choice=run.rtol_info or None,
                   settings=run.settings.to_dict())  # each setting's source (femcam.sweep.settings)
    fe = run.opts.method != "hertz"
    if fe:  # this process's builds and loads (a process pool's workers count their own)
        options["model_cache"] = usage(cache.stats, before, run.disk)
    prov = provenance(scene_path=run.scene_path if run.scene_path is not None else src_path,
                      scene_hash=run.shash, command=command, options=options,
                      families=[r.to_dict() for r in run.records] if fe else None,
                      wear=run.wear.to_dict())
    prov["estimates"] = {str(k): e.to_dict() for k, e in run.estimates.items()}
    prov["extras"] = extras_provenance(run.scene, table, tolerance=run.opts.tolerance,
                                        method=run.opts.method)
    # what an assessment of this folder checks its scene against (femcam.assess.sweep_table)
    prov["scene_physics_parts"] = physics_parts(run.scene)
    prov["scene_physics_sha256"] = physics_hash(run.scene)
    timings = {"analytic": t_analytic, "verify": t_verify, "compute": t_compute}
    result = SweepResult(table=table, method=run.opts.method, provenance=prov, paths={},
                         timings=timings, n_chunks_computed=len(tasks),
                         n_chunks_resumed=len(run.done))
    if run.out is not None:
        with talk.phase(f"writing {run.out}" + (" (tables, plots)" if plots else "")):
            result = write_outputs(result, run, plots, src_path, src_text)
    result.timings["total"] = time.perf_counter() - t_start
    return result


def _prepare(scene, options: SweepOptions, ro: RunOptions) -> SweepRun:
    """Load the scene file; resolve the settings (given > scene > default,
    :func:`femcam.sweep.settings.resolve_settings`, as the CLI does); check the inputs."""
    scene_path, out = ro.scene_path, ro.out
    if isinstance(scene, (str, Path)):
        scene_path = scene if scene_path is None else scene_path
        scene = load_scene(scene)
    st = resolve_settings(scene, options.given())
    angles, a_over_h, tolerance, rtol = st.angles, st.a_over_h, st.tolerance, st.rtol
    opts = ResolvedOptions(method=st.method, **({} if a_over_h is None else {"a_over_h": a_over_h}),
                        tolerance=tolerance, chunk_size=st.chunk_size,
                        vtk_every=st.vtk_every if out is not None else 0, rtol=rtol, rtol_on=st.rtol_on)
    if opts.method != "hertz":  # refused before any work: a mesh too large for time and memory
        check_contact_elements(MeshOptions(a_over_h=opts.a_over_h))
    angles, jump = jump_angles(scene, angles)  # curvature jumps resolved (femcam.sweep.realcam)
    n = angles.size
    bounds = [(i, min(i + opts.chunk_size, n)) for i in range(0, n, opts.chunk_size)]
    return SweepRun(scene=scene, scene_path=scene_path, angles=angles, opts=opts, workers=ro.workers,
                    out=out, resume=ro.resume, bounds=bounds, delay_s=ro.chunk_delay_s, jump=jump,
                    settings=st)


def _analytic(run: SweepRun) -> None:
    """The analytic chain for all angles (cheap, vectorised): contact mask and slip."""
    # only what the planning needs (no table of all angles: memory; the chunks fill theirs)
    st0 = _analyse_in_blocks(contact_scene(run.scene), run.angles)
    run.rows0 = {k: np.asarray(getattr(st0, k), dtype=float) for k in ("Fc", "rho")}
    run.contact = contact_mask(st0)
    if run.opts.method != "hertz":
        run.traction = scene_traction(run.scene, run.angles)
    run.wear = wear_setup(run.scene, run.angles, st0)


def _analyse_in_blocks(scene, theta):
    """``scene.analyse(theta)``, ANALYTIC_BLOCK angles at a time above that size, reduced to the
    arrays the planning and the wear slip read (``theta, s, s1, s2, Fc, rho, liftoff``).

    Exact: each angle's state depends on that angle alone; a follower train's periodic response
    is computed once per scene (a cached property) on its own grid and interpolated to each
    block. The transient of one call (~300 B per angle) stays that of one block.
    """
    if theta.size <= ANALYTIC_BLOCK:
        return scene.analyse(theta)
    keys = ("theta", "s", "s1", "s2", "Fc", "rho", "liftoff")
    parts = {k: [] for k in keys}
    for i in range(0, theta.size, ANALYTIC_BLOCK):
        st = scene.analyse(theta[i:i + ANALYTIC_BLOCK])
        for k in keys:
            parts[k].append(np.asarray(getattr(st, k)))
    return SimpleNamespace(**{k: np.concatenate(v) for k, v in parts.items()})


def _open_store(run: SweepRun) -> None:
    """The scene hash; the on-disk chunk store (with ``out``): finished chunks on resume, stale
    files removed."""
    n = run.angles.size
    run.shash = scene_hash(run.scene, run.scene_path)
    run.vtk_mask = np.zeros(n, bool)
    if run.out is None:
        return
    key = {"scene_sha256": run.shash, "angles_sha256": array_hash(run.angles), "n_angles": int(n),
           **run.opts.to_dict()}
    run.out.mkdir(parents=True, exist_ok=True)
    run.lock = DirLock(run.out).acquire()
    if not run.resume and not run.overwrite and any(p.name != LOCK for p in run.out.iterdir()):
        raise _validate.fail("out", str(run.out), "", "the directory is not empty; pass resume=True "
                             "to continue the sweep in it, overwrite=True to replace its results, "
                             "or choose another out")  # the API's words; the CLI's: refuse_non_empty
    run.store = ChunkStore(run.out / "chunks", key, run.bounds)
    run.done = frozenset(run.store.open(run.resume))
    if not run.done:  # fresh sweep: no stale series from an earlier run in the same DIR
        for p in (run.out / "vtk").glob("angle_*.vtu"):
            p.unlink()
        (run.out / "sweep.pvd").unlink(missing_ok=True)
    if run.opts.vtk_every:
        run.vtk_mask[:: run.opts.vtk_every] = True


def _plan(run: SweepRun) -> None:
    """Model families verified against the tolerance (FE only); a resume reuses the stored plan;
    families chosen for an rtol (:func:`femcam.sweep.rtol.choose_mesh`) are only stored."""
    n = run.angles.size
    if run.opts.method == "hertz" or not run.preplanned:
        run.family, run.records = np.full(n, -1), []
    if run.opts.method == "hertz":
        return
    cp = contact_params(run.scene)
    fit = _fit_rows(run)
    plan = run.store.load_plan() if (run.store is not None and run.resume) else None
    if plan is not None and len(plan.get("family", ())) == n and not run.preplanned:
        run.family = np.asarray(plan["family"], dtype=int)
        run.records = [FamilyRecord.from_dict(r) for r in plan["records"]]
        return
    if run.scene.follower.flat_face:  # binned real-cam models (femcam.sweep.realrows), no families
        return
    if not run.preplanned:
        cache = default_cache()
        # the models of the families, their fresh checks and their coarse estimate models are
        # independent builds: a background thread builds ahead on a second core (--workers 1:
        # none, everything in this thread), same rows (docs/performance.md)
        with cache.building_in_background(_background_threads(run)):
            run.family, _, run.records = verify_families(
                run.rows0["Fc"], run.rows0["rho"], run.angles, cp, run.opts, fit, cache=cache,
                traction=run.traction, prefetch=lambda r, a: prefetch_estimate(cp, r, a, run.opts, cache))
            estimate_run(run, cache)
    run.verified_here = True
    if run.store is not None:
        run.store.save_plan({"family": run.family.tolist(),
                             "records": [r.to_dict() for r in run.records]})


def _background_threads(run: SweepRun) -> int:
    """Background build threads of the family phase: 1 with two or more usable cores, unless
    the sweep was asked to stay in one process and thread (``workers=1``); with ``"auto"`` only
    while a core is idle (1-minute load average below cores - 0.5): on busy cores the two
    threads only take turns, at ~5-10 % more CPU (docs/performance.md)."""
    cores = _cpu_count()
    if run.workers == 1 or cores < 2:
        return 0
    if run.workers == "auto":
        try:
            if os.getloadavg()[0] > cores - 0.5:
                return 0
        except OSError:  # no load average on this platform: use the core
            pass
    return 1


def _fit_rows(run: SweepRun) -> np.ndarray:
    """The rows the family models answer (contact, a roller that fits, not Hertz's in method
    auto); sets ``run.hertz``."""
    cp = contact_params(run.scene)
    run.hertz = auto_hertz_rows(run.scene, cp, run.opts, run.angles, run.rows0["Fc"], run.rows0["rho"],
                                run.contact, run.jump)
    return run.contact & ~roller_does_not_fit(run.rows0["rho"], cp.Rr) & ~run.hertz


def _tasks(run: SweepRun) -> tuple[list[ChunkTask], list[int]]:
    """One task per chunk still to compute, and its chunk number."""
    refs = {r.id: (r.rho_ref, r.a_ref) for r in run.records}
    own = {r.id: r.a_over_h for r in run.records}   # each family's a/h (rtol chooses it per family)
    vtk_dir = str(run.out / "vtk") if (run.out is not None and run.opts.vtk_every) else None
    tasks, task_chunk = [], []
    for c, (a, b) in enumerate(run.bounds):
        if c in run.done:
            continue
        fam = run.family[a:b]
        sub = {int(f): refs[int(f)] for f in np.unique(fam) if f >= 0}
        tasks.append(ChunkTask(index=c, scene=run.scene, theta=run.angles[a:b], options=run.opts,
                               family=fam, refs=sub, a_over_h={f: own[f] for f in sub},
                               vtk_dir=vtk_dir, vtk_mask=run.vtk_mask[a:b],
                               slip=run.wear.chunk(a, b), wear_k=run.wear.k, delay_s=run.delay_s,
                               jump=run.jump[a:b], hertz=None if run.hertz is None else run.hertz[a:b],
                               traction=run.traction.chunk(a, b) if run.traction is not None else None,
                               estimates={f: run.estimates[f] for f in sub if f in run.estimates},
                               disk=run.disk.spec()))
        task_chunk.append(c)
    return tasks, task_chunk


def _choose_workers(run: SweepRun, tasks, task_chunk, scheduler, client) -> tuple[int, str | None]:
    """``workers="auto"``: the expected work of the chunks decides (:func:`auto_workers`)."""
    if run.workers != "auto":
        return run.workers, None
    if scheduler is not None or client is not None:
        return 1, "Dask: the cluster's workers"
    opts, records = run.opts, run.records
    todo = np.zeros(run.angles.size, bool)
    for c in task_chunk:
        todo[run.bounds[c][0]:run.bounds[c][1]] = True
    n_solves = int(np.count_nonzero(run.contact & todo))
    if run.verified_here:  # load cases solved during the verification are cached (forks inherit)
        n_solves = max(0, n_solves - sum(r.n_scanned for r in records))
    ts = [r.solve_time for r in records if np.isfinite(r.solve_time)]
    tb = [r.build_time for r in records if r.build_time > 0]
    t_solve = float(np.mean(ts)) if ts else (0.0 if opts.method == "hertz"
                                              else 2e-3 * (opts.a_over_h / 10.0) ** 2)
    t_build = float(np.mean(tb)) if tb else 0.5 * (opts.a_over_h / 10.0) ** 2
    n_vtu = int(np.count_nonzero(todo & run.vtk_mask & run.contact))
    t_vtu = n_vtu * AUTO_VTU_S * ((opts.a_over_h / 10.0) ** 2 if opts.method != "hertz" else 0.1)
    return auto_workers(len(tasks), n_solves, t_solve, len(records), t_build, t_other=t_vtu)


def _compute(run: SweepRun, tasks, task_chunk, workers, scheduler, client, progress):
    """Run the chunks (stored as they finish), load the resumed ones, return the whole table:
    a dict of arrays, or with an output directory and at least :data:`STREAM_ANGLES` angles a
    :class:`~femcam.sweep.store.StoredTable` read from the chunk files (memory bounded)."""
    stream = run.store is not None and run.angles.size >= STREAM_ANGLES
    # filled as chunks finish: no second copy of the rows
    table = None if stream else TableBuilder(run.bounds)
    bar = Progress(sum(b - a for c, (a, b) in enumerate(run.bounds) if c not in run.done),
                   label="solves" + (" and VTU files" if run.opts.vtk_every else ""),
                   enabled=progress)
    try:
        for k, rows in run_tasks(run_chunk, tasks, workers=workers, scheduler=scheduler,
                                 client=client):
            c = task_chunk[k]
            if run.store is not None:
                run.store.write(c, rows)
            if table is not None:
                table.put(c, rows)
            del rows
            bar.update(run.bounds[c][1] - run.bounds[c][0])
    finally:
        bar.close()
    if table is None:
        return run.store.table()
    for c in run.done:
        table.put(c, run.store.load(c))
    return table.table()
