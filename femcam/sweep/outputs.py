"""The state of one sweep call and the files it writes: ``scene.toml``, ``sweep.csv``,
``sweep.npz``, ``sweep.pvd``, the plots, ``report.md``, ``report.html`` (:func:`write_outputs`, called by
:func:`femcam.sweep.sweep` with an output directory).
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from ..errors import FemcamError, InputError
from ..hertz.conformity import roller_does_not_fit, shape_factors
from ..io import atomic_write_text, vtu_name, write_csv, write_npz, write_pvd
from ..scene import Scene
from ..scene.origin import thaw
from ..scene.override import with_overrides
from ..viz.animate import animate_pvd
from ..viz.process import PlotProcess, warn_missing
from ..viz.sweep import named_plot, plot_surface_sweep, plot_svaj_loads, plot_sweep, sweep_plot_calls
from .cache import default_cache
from .extras import extra_columns, extras_files, plot_extras, providers_for
from .options import ResolvedOptions, contact_params
from .pipeline import analytic_rows, contact_mask, line_contact
from .profile import worst_surface_profile
from .report import report_html
from .result import SweepResult, plot_data_arrays, report_markdown
from .store import STREAM_ANGLES, ChunkStore, DirLock
from .table import COLUMNS, INTEGER_COLUMNS, NUMERIC, TEXT_COLUMNS
from .wear import WearSetup

__all__ = ["SweepRun", "check_vtus", "early_plots", "scene_hash", "scene_source", "with_plot_data",
           "write_outputs"]


def scene_hash(scene, scene_path) -> str:
    """SHA-256 of the scene file and the parsed scene (the resume key).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The parsed scene (its ``repr`` is hashed).
    scene_path : str or Path or None
        The scene file (its bytes are hashed too, if it exists).

    Returns
    -------
    str
        Hex digest.
    """
    if scene_path is not None and Path(scene_path).is_file():
        h = hashlib.sha256(Path(scene_path).read_bytes())
        h.update(repr(scene).encode())  # also catches in-code changes such as --law
        return h.hexdigest()
    return hashlib.sha256(repr(scene).encode()).hexdigest()


def scene_source(scene, scene_path):
    """The scene file and its text, for the copy in the output directory.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene (``scene.source_path`` is the fallback).
    scene_path : str or Path or None
        The scene file given to the sweep.

    Returns
    -------
    path : Path or None
        The scene file (None: the scene was built in code).
    text : str
        Its text ("" when there is none or it is unreadable).
    """
    for p in (scene_path, scene.source_path):
        if p and Path(p).is_file():
            try:
                text = Path(p).read_text(encoding="utf-8")
            except (OSError, UnicodeDecodeError):
                return Path(p), ""
            ov = thaw(dict(scene.overrides))  # e.g. --law: the copy must reproduce the run
            if ov.get("law"):
                text = with_overrides(text, {}, law=ov.pop("law"), control_points=ov.get("control_points"))
            return Path(p), text
    return None, ""



@dataclass
class SweepRun:
    """The state of one :func:`femcam.sweep.sweep` call, filled phase by phase
    (:mod:`femcam.sweep.run`), read by the output writers.

    Attributes
    ----------
    scene : femcam.scene.Scene
        The scene swept.
    scene_path : str or Path or None
        Its file, if any.
    angles : ndarray, shape (n,)
        Cam angles [rad] (curvature jumps resolved).
    opts : ResolvedOptions
        Numerical options.
    workers : int or str
        Worker processes, or ``"auto"``.
    out : Path or None
        Output directory (None: nothing written).
    resume : bool
        Continue the sweep stored in ``out``.
    bounds : list of (int, int)
        Chunk row ranges ``(start, stop)``.
    delay_s : float
        Pause after each chunk [s] (for testing interruptions).
    shash : str
        Scene hash (:func:`scene_hash`).
    contact : ndarray of bool, shape (n,), optional
        Angles with contact.
    rows0 : dict[str, ndarray], optional
        ``Fc`` [N] and ``rho`` [m] of every angle, shape (n,).
    wear : WearSetup, optional
        Archard k and slip of every angle.
    store : ChunkStore, optional
        On-disk chunk store (with ``out``).
    done : frozenset of int
        Chunks already finished (resume).
    vtk_mask : ndarray of bool, shape (n,), optional
        Angles that get a ``.vtu``.
    family : ndarray of int, shape (n,), optional
        Model family id per angle (-1: none).
    records : list of FamilyRecord, optional
        The verified families.
    verified_here : bool
        The families were verified in this process (their solves are cached).
    overwrite : bool
        Replace the results in a non-empty ``out``.
    animate : bool
        Write ``animation.gif`` from the VTK series.
    lock : DirLock, optional
        The lock held on ``out``.
    jump : ndarray of bool, shape (n,), optional
        Rows inside a curvature jump's straddle span.
    traction : femcam.sweep.realcam.Traction, optional
        Tangential load and directions per angle (FE methods).
    hertz : ndarray of bool, shape (n,), optional
        Rows answered by Hertz under method ``auto``.
    estimates : dict[int, FamilyEstimate]
        The families' two-level error estimates (:mod:`femcam.sweep.estimate`).
    preplanned : bool
        The families were planned and verified while choosing the mesh for ``rtol``.
    rtol_info : dict
        The ``rtol`` mesh choice (pilots, levels tried), recorded in the provenance.
    disk : femcam.sweep.diskcache.DiskCache, optional
        The persistent model cache of this call (``model_cache``, ``cache_dir``).
    settings : femcam.sweep.settings.SweepSettings, optional
        The resolved settings and the source of each (argument, scene, default).
    plotter : femcam.viz.process.PlotProcess, optional
        The process drawing the plots (started with the sweep; None: drawn here).
    early : dict
        Plots sent to ``plotter`` before the chunk solves (:func:`early_plots`): name -> (the
        columns drawn, the lane).
    """

    scene: Scene
    scene_path: object
    angles: np.ndarray
    opts: ResolvedOptions
    workers: int | str
    out: Path | None
    resume: bool
    bounds: list
    delay_s: float = 0.0
    shash: str = ""
    contact: np.ndarray | None = None
    rows0: dict | None = None
    wear: WearSetup | None = None
    store: ChunkStore | None = None
    done: frozenset = frozenset()
    vtk_mask: np.ndarray | None = None
    family: np.ndarray | None = None
    records: list | None = None
    verified_here: bool = False
    overwrite: bool = False
    animate: bool = False
    lock: DirLock | None = None
    jump: np.ndarray | None = None
    traction: object = None
    hertz: np.ndarray | None = None
    estimates: dict = field(default_factory=dict)
    preplanned: bool = False
    rtol_info: dict = field(default_factory=dict)
    disk: object = None
    settings: object = None
    plotter: object = None
    early: dict = field(default_factory=dict)



#: CPU seconds of each sweep plot (the study model, AMD EPYC, median of 3): the weights that
#: share the plots between the plot process's two lanes (:class:`PlotProcess`)
PLOT_CPU_S = {"plot_p0": 0.17, "plot_maxima": 0.15, "plot_svaj": 0.38, "plot_wear": 0.20,
              "plot_junction": 0.20, "plot_surface": 0.23}


#: the order of the sweep's plots in ``SweepResult.paths`` and the report (that of
#: :func:`femcam.viz.sweep.plot_sweep`); the extra providers' plots follow
PLOT_ORDER = ("plot_p0", "plot_maxima", "plot_svaj", "plot_wear", "plot_junction", "plot_surface")
#: the table columns ``svaj_loads.png`` draws (all known after the analytic chain)
SVAJ_COLUMNS = ("theta", "s", "v", "a", "j", "phi", "rho", "Fc", "p0_hertz")


def svaj_columns(scene, theta) -> dict:
    """The columns of ``svaj_loads.png`` for the angles ``theta`` (rad), as the chunks fill them
    (:func:`femcam.sweep.pipeline.analytic_rows`; Hertz ``p0`` of the rows in contact where the
    roller fits, 0 at lift-off, NaN otherwise).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene swept.
    theta : ndarray of float, shape (n,)
        Cam angles [rad].

    Returns
    -------
    dict of str to ndarray, shape (n,)
        :data:`SVAJ_COLUMNS` (SI).
    """
    rows, st = analytic_rows(scene, theta)
    cp = contact_params(scene)
    contact = contact_mask(st)
    good = np.flatnonzero(contact & ~roller_does_not_fit(rows.rho, cp.Rr))
    if good.size:
        rows.p0_hertz[good] = line_contact(cp, rows.Fc[good], rows.rho[good]).p0
    rows.p0_hertz[~contact] = 0.0
    return {c: np.array(getattr(rows, c), dtype=float) for c in SVAJ_COLUMNS}


def early_plots(run: SweepRun) -> None:
    """Send ``svaj_loads.png`` (kinematics, geometry, load and Hertz p0: the analytic chain's
    columns) to the plot process before the chunk solves, so that the plot process, otherwise
    idle until the table is complete, draws it on the core the serial solves leave free.
    :func:`with_plot_data` checks the finished table's columns against those drawn and has the
    plot drawn again from the table when any value differs (e.g. a follower whose rows the
    chunks fill otherwise).

    Parameters
    ----------
    run : SweepRun
        The sweep (``plotter`` and ``out`` set, fewer than
        :data:`~femcam.sweep.store.STREAM_ANGLES` angles; else nothing is sent).
    """
    if (run.plotter is None or run.out is None or run.scene.follower.flat_face
            or run.angles.size >= STREAM_ANGLES):  # a long sweep's analytic chain is computed in
        return                                       # blocks (memory): drawn from its table
    cols = svaj_columns(run.scene, run.angles)
    # weight 0: drawn long before the table is complete, it must not steer the later plots
    # away from its lane
    lane = run.plotter.submit(named_plot, "plot_svaj", plot_svaj_loads, _Columns(cols),
                              run.out / "plots" / "svaj_loads.png", weight=0.0)
    run.early["plot_svaj"] = (cols, lane)


@dataclass(frozen=True)
class _Columns:
    """What a plot function of :mod:`femcam.viz.sweep` reads of a result drawn early: its table."""

    table: dict


def _drawn_early(run: SweepRun, name: str, table):
    """The lane of plot ``name`` sent by :func:`early_plots` and whether the columns it drew equal
    ``table``'s (bit for bit, NaN in the same places); ``(None, False)`` if not sent early."""
    if name not in run.early:
        return None, False
    cols, lane = run.early[name]
    same = all(np.array_equal(np.asarray(table[c], dtype=float), v, equal_nan=True)
               for c, v in cols.items())
    return lane, same


def write_outputs(result: SweepResult, run: SweepRun, plots: bool, src_path=None,
                   src_text: str = "") -> SweepResult:
    """``scene.toml``, ``sweep.csv``, ``sweep.npz``, ``sweep.pvd`` and the plots in ``run.out``.

    Parameters
    ----------
    result : SweepResult
        The computed sweep.
    run : SweepRun
        Its state (``run.out`` must be set).
    plots : bool
        Also compute the plot data and write the plots.
    src_path : Path, optional
        The scene file (:func:`scene_source`), copied as ``scene.toml``.
    src_text : str
        Its text ("": no copy).

    Returns
    -------
    SweepResult
        ``result`` with the provenance, paths (and plot data) of the files written.
    """
    out = run.out
    paths = {}
    prov = dict(result.provenance)
    if src_path is not None and src_text:
        copy = out / "scene.toml"
        if not (copy.exists() and copy.resolve() == Path(src_path).resolve()):
            atomic_write_text(copy, src_text)
        paths["scene"] = str(copy)
        prov["scene_copy"] = (f"{copy.name} (copy of {src_path} with the overrides of the run, e.g. "
                              "--law, written into it: sweeping it again reproduces the run)")
    result = replace(result, provenance=prov)
    child = run.plotter if plots else None
    if plots:
        result = with_plot_data(result, run, child)
    xcols, xtext = extra_columns(run.scene)  # extra column providers (femcam.sweep.extras)
    paths.update(csv=str(write_csv(out / "sweep.csv", result.table, prov, columns=COLUMNS + xcols,
                                   text_columns=TEXT_COLUMNS + xtext,
                                   title="femcam sweep: one row per cam angle")),
                 npz=str(write_npz(out / "sweep.npz", result.table, prov,
                                   numeric=NUMERIC + tuple(c.si for c in xcols),
                                   text_columns=TEXT_COLUMNS + xtext, integer_columns=INTEGER_COLUMNS,
                                   scene_toml=src_text,
                                   scene_repr=repr(run.scene), extra=plot_data_arrays(result))))
    theta = result.table["theta"]
    entries = [(float(np.degrees(theta[i])), out / "vtk" / vtu_name(theta[i]))
               for i in np.flatnonzero(run.vtk_mask)]
    check_vtus(result, run)
    entries = [(t, p) for t, p in entries if p.exists()]
    if entries:
        paths["pvd"] = str(write_pvd(out / "sweep.pvd", entries))
    paths.update(extras_files(run.scene, result.table, out, run.vtk_mask))  # e.g. camdisk.pvd
    result = replace(result, paths=paths)
    if child is not None:  # drawn in the plot process meanwhile (femcam.viz.process)
        drawn, error = child.collect()
        if ": ImportError: " in error:  # pragma: no cover - matplotlib missing
            raise InputError(f"plots = True: {error.split(': ', 2)[-1]}")
        # in the order plot_sweep draws them (the report lists them so), whatever was sent first
        paths.update(sorted(drawn.items(), key=lambda kv: PLOT_ORDER.index(kv[0])
                            if kv[0] in PLOT_ORDER else len(PLOT_ORDER)))
        if error:
            warn_missing(error, out)
    elif plots:
        try:
            paths.update(plot_sweep(result, out))
            paths.update(plot_extras(run.scene, result.table, out))
        except ImportError as exc:  # pragma: no cover - matplotlib missing
            raise InputError(f"plots = True: {exc}") from None
    if run.animate and "pvd" in paths:
        paths["animation"] = animate_pvd(paths["pvd"], out / "animation.gif")
    atomic_write_text(out / "report.md", report_markdown(result))
    paths["report"] = str(out / "report.md")
    drawn = [v for k, v in paths.items() if k.startswith("plot_")]   # not an earlier run's PNGs
    atomic_write_text(out / "report.html", report_html(result, out, plots=drawn))  # one file to send
    paths["report_html"] = str(out / "report.html")
    return result


def check_vtus(result: SweepResult, run: SweepRun) -> None:
    """Every ``ok`` angle of the VTK series has its ``.vtu`` in ``DIR/vtk``, or the sweep fails
    loudly (never a silent exit 0 with files missing, e.g. written on another machine).

    Parameters
    ----------
    result : SweepResult
        The computed sweep.
    run : SweepRun
        Its state (``out``, ``vtk_mask``).

    Raises
    ------
    FemcamError
        Some ``.vtu`` files are missing.
    """
    # one read of each column: a long sweep's table is read from its chunk files per access
    theta, status = result.table["theta"], result.table["status"]
    want = np.flatnonzero(run.vtk_mask & (status == "ok"))
    missing = [name for name in (vtu_name(theta[i]) for i in want)
               if not (run.out / "vtk" / name).exists()]
    if missing:
        raise FemcamError(f"{len(missing)} of {want.size} .vtu files are missing from "
                          f"{run.out / 'vtk'} (first: {missing[0]}); the table is saved in "
                          f"{run.out / 'chunks'}")


def with_plot_data(result: SweepResult, run: SweepRun, child: PlotProcess | None = None) -> SweepResult:
    """The Hertz shape factors and the worst angle's surface profile, for the plots.

    Parameters
    ----------
    result : SweepResult
        The computed sweep.
    run : SweepRun
        Its state (scene, options).
    child : PlotProcess, optional
        A plot process: it is sent the plots that need no surface profile before the profile
        is solved, then the profile's plot, the extra providers' plots last (the order of
        :func:`femcam.viz.sweep.plot_sweep`, then :func:`femcam.sweep.extras.plot_extras`).

    Returns
    -------
    SweepResult
        ``result`` with ``surface_profile`` (None without an ``ok`` angle) and ``hertz_factors``.
    """
    cp = contact_params(run.scene)
    result = replace(result, hertz_factors=shape_factors(cp.mu, cp.cam.nu, cp.plane))
    if child is not None:
        for function, args in sweep_plot_calls(replace(result, surface_profile=None), run.out):
            lane, same = _drawn_early(run, args[0], result.table)
            if not same:  # not drawn early, or from other numbers: (again) from the table
                child.submit(function, *args, weight=PLOT_CPU_S.get(str(args[0]), 0.2), lane=lane)
    profile = None
    if np.any(result.ok):
        fe = "hertz" if (result.method == "hertz" or run.scene.follower.flat_face) else "fe"
        profile = worst_surface_profile(result.table, fe, cp, result.families, run.opts,
                                        default_cache(), scene=run.scene)
    result = replace(result, surface_profile=profile)
    if child is not None:
        if profile is not None and "x_hertz" in profile:
            child.submit(plot_surface_sweep, profile, run.out, weight=PLOT_CPU_S["plot_surface"])
        if any(p.panels for p in providers_for(run.scene)):
            child.submit(plot_extras, run.scene, result.table, run.out, weight=0.2)
    return result
