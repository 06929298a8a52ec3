"""``femcam sweep SCENE.toml --out DIR``: the FE (or Hertz) sweep over cam angle.

Writes DIR/sweep.csv (units in the column names; provenance in DIR/sweep.csv-metadata.json),
DIR/sweep.npz (SI, plus the scene file's text), DIR/scene.toml (a copy of the scene file with
--law written into it), DIR/chunks/ (the resumable store), DIR/sweep.pvd + DIR/vtk/*.vtu
(every 10th angle by default; --vtk-every K) and PNG plots in DIR/plots/ (unless --no-plots).

Settings: a flag given on the command line wins; else the scene's [fe] a_over_h, tolerance,
rtol_pct and [sweep] method, angles_deg, chunk_size, vtk_every, plots; else the defaults shown
below. --rtol-pct chooses the mesh: it is refused together with --a-over-h (and [fe] rtol_pct
together with [fe] a_over_h); a flag of one beats the scene's other.
"""

from __future__ import annotations

import argparse
import math
import shlex
import sys

from .. import _validate
from ..mesh import MeshOptions
from ..mesh.estimate import check_contact_elements
from ..scene import load_scene, study_problem
from ..scene.schema import STUDY_RANGES, STUDY_UNITS, STUDY_WHOLE
from ..sweep import sweep
from ..sweep.estimate import estimate_text
from ..sweep.options import RTOL_ON, RTOL_RANGE, TOLERANCE_FLOOR, RunOptions, SweepOptions
from ..sweep.result import families_text, hertz_check_text
from ..sweep.settings import SETTINGS as LIBRARY_SETTINGS
from ..sweep.settings import resolve_settings
from ..sweep.worst import assess_line
from ._common import (
    add_law_override,
    add_scene_out,
    cap_workers,
    check_law,
    out_dir,
    plain,
    refuse_non_empty,
)
from ._flags import RANGE_RULE, Range, add_number


def register(subparsers) -> None:
    """Add the ``sweep`` sub-parser (the FE or Hertz sweep over cam angle) and set its ``func``.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        Where ``femcam``'s parser (:func:`femcam.cli.build_parser`) collects its subcommands.
    """
    p = subparsers.add_parser(
        "sweep", help="FE contact sweep over cam angle (CSV/NPZ, VTK series, plots)",
        description=plain(__doc__, 3),
        formatter_class=argparse.RawDescriptionHelpFormatter)
    add_scene_out(p)
    p.add_argument("--angles-deg", default=None, metavar="START:STOP:STEP",
                   help=f"cam angles in degrees, {RANGE_RULE}: 0:360:1 is 0 to 359, 0:90:30 is 0 to 90 "
                   + _default_text("angles_deg")
                   + "; a negative start is accepted (--angles-deg -360:0:30)")
    add_number(p, "--workers", Range("processes", 1, 1024, whole=True, words=("auto",)),
               default="auto", metavar="N|auto",
               help="local worker processes; 1 = serial in this process; auto (default) = "
                    "processes only when the expected saving beats the pool start-up: the "
                    "model families are built and verified before the chunks run, so the "
                    "chunks are only short contact solves per angle: a sweep without VTK "
                    "usually runs serially, while writing many VTU files pays on 2 "
                    "processes; capped at the useful number (CPU cores, chunks); auto and "
                    "N >= 2 also build the family phase's models in a second thread (auto: "
                    "while a core is idle)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="Dask scheduler address, e.g. tcp://host:8786 (needs femcam[dask])")
    p.add_argument("--resume", action="store_true",
                   help="continue an interrupted sweep in DIR (computes only missing chunks)")
    p.add_argument("--overwrite", action="store_true",
                   help="replace the results in a non-empty DIR (refused otherwise)")
    p.add_argument("--no-cache", dest="model_cache", action="store_false",
                   help="build every FE model, neither loading nor storing the persistent model cache")
    p.add_argument("--cache-dir", default=None, metavar="DIR",
                   help="the persistent model cache (default $FEMCAM_CACHE_DIR, else "
                        "$XDG_CACHE_HOME/femcam, else ~/.cache/femcam; docs/sweep.md)")
    p.add_argument("--animate", action="store_true",
                   help="also write DIR/animation.gif: von Mises over cam angle (the VTK series)")
    for flag, rng, metavar, text, extra in _SCENE_FLAGS:
        dest = flag[2:].replace("-", "_")
        add_number(p, flag, rng, default=None, metavar=metavar,
                   help=f"{text} {_default_text(dest, extra)}")
    add_number(p, "--rtol-pct", Range("percent", RTOL_RANGE[0] * 100, RTOL_RANGE[1] * 100), default=None,
               metavar="PCT",
               help="requested bound on the estimated p0 error of every FE row, in percent "
                    "(0.5 means 0.5 %%): the sweep chooses the mesh (a/h) and a reuse tolerance "
                    "<= PCT/2 from a two-level error estimate; each row reports err_est_p0_pct "
                    "(default: [fe] rtol_pct, else none: --a-over-h decides)")
    p.add_argument("--rtol-on", default=None, metavar="Q[,Q...]",
                   help="the quantities --rtol-pct bounds, stems of the err_est_*_pct columns: "
                        + ", ".join(RTOL_ON) + " (the interface ones on coated scenes); each "
                        "family's mesh meets all of them (default: [fe] rtol_on, else p0)")
    p.add_argument("--method", choices=("fe", "hertz", "auto"), default=None,
                   help="fe: FE contact solve; hertz: analytic only; auto: the cheapest of Hertz, "
                        "FE arc gap, FE exact gap within --tolerance per angle "
                        + _default_text("method"))
    add_law_override(p)
    p.add_argument("--plots", dest="plots", action="store_true", default=None,
                   help="write the PNG plots " + _default_text("plots"))
    p.add_argument("--no-plots", dest="plots", action="store_false", help="skip the PNG plots")
    p.add_argument("--progress", choices=("auto", "on", "off"), default="auto",
                   help="progress on stderr: a bar on a terminal, plain lines elsewhere (auto: on unless "
                        "-q; off: none)")
    # a test aid (not shown in --help): sleep after each chunk, so that a test can kill the
    # sweep between chunks deterministically
    add_number(p, "--chunk-delay-s", Range("s", 0.0, 60.0), default=0.0, help=argparse.SUPPRESS)
    p.set_defaults(func=_run)


#: flag dest -> the library's parameter (:data:`femcam.sweep.settings.SETTINGS`: scene table,
#: key and default, written once there; the --help text is made from it)
_PARAMS = {"angles_deg": "angles", "a_over_h": "a_over_h", "tolerance": "tolerance",
           "chunk_size": "chunk_size", "vtk_every": "vtk_every", "method": "method", "plots": "plots"}
#: flag dest -> (scene table, key, default)
SETTINGS = {dest: LIBRARY_SETTINGS[p] for dest, p in _PARAMS.items()}
#: the flags' names in the library's messages about given values
_NAMES = {"rtol": ("--rtol-pct", 100, "%"), "rtol_on": ("--rtol-on", 1, ""),
          "a_over_h": ("--a-over-h", 1, ""), "angles_deg": ("--angles-deg", 1, "deg")}

def _study(key: str, whole: bool = False, hi: float | None = None) -> Range:
    """The flag's range: the scene's (femcam.scene.schema.study_problem, one copy, with the
    hint of :data:`_FLAG_CHECKS`), capped at ``hi`` where the scene has no upper bound."""
    lo, top = STUDY_RANGES.get(key, (STUDY_WHOLE.get(key, 0), hi))
    dest = {v[1]: k for k, v in SETTINGS.items()}[key]
    return Range(STUDY_UNITS[key], lo, top, whole=whole, check=lambda x: _study_problem(dest, x))


def _study_problem(dest: str, x: float) -> str | None:
    """:func:`study_problem` of a flag's setting in the flag's words, with its hint."""
    problem = study_problem(SETTINGS[dest][1], x)
    if not problem:
        return None
    hint = _FLAG_CHECKS[dest][1]
    problem = problem.replace("a_over_h", "--a-over-h")
    return f"{problem}; {hint}" if hint else problem


#: the numeric flags a scene can set: (flag, range, metavar, help, note after the default);
#: chunk_size and vtk_every are capped at 1e6 angles (a revolution at 0.001 deg is 360,000)
_SCENE_FLAGS = (
    ("--a-over-h", _study("a_over_h"), "A_OVER_H",
     "FE element size in the contact zone, h = a / A_OVER_H", ""),
    ("--tolerance", _study("tolerance"), "TOL",
     "bound on the relative p0 difference between an angle solved with its family's shared model "
     "and with a model built for it alone; checked with fresh models at each family's worst "
     "angles, families are split until it holds", f">= {TOLERANCE_FLOOR:g}"),
    ("--chunk-size", _study("chunk_size", True, 1e6), "N",
     "angles per chunk on disk / per parallel task", ""),
    ("--vtk-every", _study("vtk_every", True, 1e6), "K",
     "write a .vtu (both bodies, ~1 MB) every K angles plus sweep.pvd",
     "1 = every angle; 0 = none"),
)


def _default_text(dest: str, note: str = "") -> str:
    """``"(default: [table] key, else VALUE; note)"`` for ``--help``, from :data:`SETTINGS`."""
    table, key, default = SETTINGS[dest]
    if isinstance(default, bool):
        shown = "yes" if default else "no"
    else:
        shown = f"{default:g}" if isinstance(default, int | float) else str(default)
    return f"(default: [{table}] {key}, else {shown}" + (f"; {note}" if note else "") + ")"


def resolve_args(args, scene) -> list[str]:
    """Fill the settings not given as flags, by the library's rule (flag > scene [fe]/[sweep]
    table > default, :func:`femcam.sweep.settings.resolve_settings`, which ``sweep()`` applies
    to the same flags again).

    Parameters
    ----------
    args : argparse.Namespace
        The parsed flags; the :data:`SETTINGS` and ``rtol_pct`` are set in place to the
        resolved values (scene units: deg spec, a/h, relative tolerance, percent).
    scene : femcam.scene.Scene
        The scene (its ``study``: the [fe] and [sweep] settings).

    Returns
    -------
    list of str
        ``[table] key = value`` of each setting taken from the scene.

    Raises
    ------
    InputError
        ``--rtol-pct`` with ``--a-over-h``, or ``[fe] rtol_pct`` with ``[fe] a_over_h``.
    """
    st = resolve_settings(scene, _given(args), names=_NAMES)
    args.angles_deg, args.method, args.tolerance = st.angles_deg, st.method, st.tolerance
    args.a_over_h, args.chunk_size, args.vtk_every, args.plots = (st.a_over_h, st.chunk_size,
                                                                   st.vtk_every, st.plots)
    args.rtol_pct = None if st.rtol is None else 100.0 * st.rtol
    args.rtol_on = ",".join(st.rtol_on)
    args.angles = st.angles
    return list(st.from_scene)


def _given(args) -> dict:
    """The settings as given on the command line (None where no flag was given)."""
    given = {p: getattr(args, dest) for dest, p in _PARAMS.items()}
    given["angles_deg"] = given.pop("angles")
    given["rtol"] = None if args.rtol_pct is None else args.rtol_pct / 100.0
    given["rtol_on"] = args.rtol_on
    return given


def useful_workers(requested, n_angles: int, chunk_size: int) -> tuple:
    """Cap a worker count at the CPU cores and the number of chunks (more only wait).

    Parameters
    ----------
    requested : int or str
        ``--workers`` after validation (an int, or ``"auto"``, passed through).
    n_angles : int
        Number of cam angles.
    chunk_size : int
        Angles per chunk.

    Returns
    -------
    (int or str, str)
        ``(workers, note)``; ``note`` says why it was capped ("" when not).
    """
    if not isinstance(requested, int):
        return requested, ""
    chunks = max(1, math.ceil(n_angles / chunk_size))
    return cap_workers(requested, chunks, f"{chunks} chunks of {chunk_size} angles")


#: flag dest -> (unit shown in the message, CLI hint appended to the condition); the ranges
#: themselves are femcam.scene.schema.study_problem (one copy; each flag's scene key is in SETTINGS)
_FLAG_CHECKS = {
    "a_over_h": (STUDY_UNITS["a_over_h"], "10 (default) keeps p0 within 0.3 % of Hertz"),
    "tolerance": (STUDY_UNITS["tolerance"], ""),
    "chunk_size": (STUDY_UNITS["chunk_size"], ""),
    "vtk_every": (STUDY_UNITS["vtk_every"], "0 = no VTK"),
}


def _check_args(args) -> None:
    """Validate the options with the flags' own names (before the API sees them).

    The condition is :func:`femcam.scene.schema.study_problem`'s, with the scene key
    ``a_over_h`` it may mention written as its flag ``--a-over-h``.
    """
    for dest, (unit, _hint) in _FLAG_CHECKS.items():
        flag, value = "--" + dest.replace("_", "-"), getattr(args, dest)
        problem = _study_problem(dest, _validate.number(flag, value, unit))
        if problem:
            raise _validate.fail(flag, value, unit, problem)
    if args.method != "hertz":  # the FE mesh's size, estimated before any work (the library's cap)
        check_contact_elements(MeshOptions(a_over_h=args.a_over_h), "--a-over-h")
    args.workers = _validate.workers("--workers", args.workers)
    if args.cache_dir is not None and not args.cache_dir.strip():
        raise _validate.fail("--cache-dir", args.cache_dir, "", "must name a directory")


def _command_line(args) -> str:
    """The command, rebuilt from the parsed arguments (also right for ``main([...])`` calls)."""
    parts = ["femcam", "sweep", args.scene, "--out", args.out, "--angles-deg", args.angles_deg,
             "--workers", str(args.workers),
             *(["--rtol-pct", f"{args.rtol_pct:g}", "--rtol-on", args.rtol_on]
               if args.rtol_pct is not None else ["--a-over-h", f"{args.a_over_h:g}"]),
             "--tolerance", f"{args.tolerance:g}", "--chunk-size", str(args.chunk_size),
             "--vtk-every", str(args.vtk_every), "--method", args.method]
    if args.scheduler:
        parts += ["--scheduler", args.scheduler]
    if args.law:
        parts += ["--law", args.law]
    if args.resume:
        parts.append("--resume")
    if not args.plots:
        parts.append("--no-plots")
    if args.overwrite:
        parts.append("--overwrite")
    if args.animate:
        parts.append("--animate")
    if not args.model_cache:
        parts.append("--no-cache")
    if args.cache_dir is not None:
        parts += ["--cache-dir", args.cache_dir]
    return shlex.join(parts)


def _run(args) -> int:
    out_dir(args.out, create=False)
    if args.law is not None:
        check_law("--law", args.law)
    scene = load_scene(args.scene)
    given = _given(args)   # handed to sweep() as given: it resolves them as resolve_args did
    from_scene = resolve_args(args, scene)
    _check_args(args)
    args.workers, note = useful_workers(args.workers, args.angles.size, args.chunk_size)
    refuse_non_empty(args.out, args.overwrite, resume=args.resume)  # the flags' words, not the API's
    if from_scene:
        print("femcam sweep: settings from the scene file: " + ", ".join(from_scene))
    if note:
        print(f"femcam sweep: note: {note}", file=sys.stderr)
    if hint := _validate.radians_hint("--angles-deg" if given["angles_deg"] is not None
                                      else "[sweep] angles_deg", args.angles_deg):
        print(f"femcam sweep: note: {hint}", file=sys.stderr)
    if args.law is not None:
        scene = scene.with_law(args.law)
    progress = {"auto": None, "on": True, "off": False}[args.progress]
    try:
        res = sweep(scene, SweepOptions(
            angles=None if given["angles_deg"] is None else args.angles, method=given["method"],
            a_over_h=given["a_over_h"], rtol=given["rtol"], rtol_on=given["rtol_on"],
            tolerance=given["tolerance"], chunk_size=given["chunk_size"],
            vtk_every=given["vtk_every"], plots=given["plots"], animate=args.animate),
            RunOptions(out=args.out, resume=args.resume, workers=args.workers,
                       scheduler=args.scheduler, progress=progress, command=_command_line(args),
                       scene_path=args.scene, chunk_delay_s=args.chunk_delay_s,
                       overwrite=args.overwrite, model_cache=args.model_cache,
                       cache_dir=args.cache_dir))
    except KeyboardInterrupt as exc:  # Ctrl-C: one line (what was saved, how to resume)
        nl = "\n" if sys.stderr.isatty() else ""  # end a progress bar's line
        print(f"{nl}femcam sweep: {exc or 'interrupted'}", file=sys.stderr)
        return 130
    _print_summary(res)
    return _refusal_code(res)


def _refusal_code(res) -> int:
    """1 (one line per refused part on stderr) when a part the scene asks for was refused at
    run time (``SweepResult.refused``), else 0; everything computed is written either way."""
    refused = res.summary().get("extras", {}).get("refused", ())
    for r in refused:
        print(f"femcam sweep: refused: {r['line']}", file=sys.stderr)
    if refused:
        where = f" to {res.paths['csv']}" if res.paths.get("csv") else ""
        print(f"femcam sweep: error: {len(refused)} part(s) the scene asks for were refused (exit 1); "
              f"everything computed is written{where}", file=sys.stderr)
        return 1
    return 0


def _p0_fe_text(res, s: dict) -> str:
    """``, p0 FE ... MPa (peak of the solved pressure, ...)`` where the FE (or a ring) answered."""
    if not (res.method == "fe" or math.isfinite(s.get("p0_fe_max", math.nan))):   # a ring: any method
        return ""
    return (f", p0 FE {s['p0_fe_max'] / 1e6:.1f} MPa (peak of the solved pressure"
            + (", 2D at the mean load Fc / length"
               if "halfspace" in s.get("extras", {}).get("providers", ()) else "")
            + (", coated model" if s.get("n_coated") else "") + ")")


def _print_families(s: dict, o: dict) -> None:
    """The model families' line (reuse error, workers) and the model cache's line."""
    print(f"  {families_text(s['n_families'], s['reuse_error_max'], s['n_binned'])} "
          f"(reuse tolerance {100 * o['tolerance']:g} %); workers "
          f"{o.get('workers')}" + (f" ({o['workers_reason']})" if o.get("workers_reason") else ""))
    if o.get("model_cache"):
        print(f"  {o['model_cache']['line']}")


def _print_summary(res) -> None:
    """The sweep's summary on stdout (warnings on stderr): counts, models, the 2D headline and
    one line per extra provider's worst values (:mod:`femcam.sweep.worst`)."""
    s = res.summary()
    o = res.provenance.get("options", {})
    print(f"femcam sweep: {res.n_angles} angles ({res.n_chunks_resumed} chunks resumed, "
          f"{res.n_chunks_computed} computed) in {res.timings['total']:.2f} s; "
          f"liftoff {s['n_liftoff']}, undercut {s['n_undercut']}, failed {s['n_failed']}")
    if o.get("models"):
        print(f"  models: {o['models']} (reuse tolerance {100 * o['tolerance']:g} %); curvature-jump rows "
              f"{o.get('n_curvature_jump', 0)}, edge contacts {o.get('n_edge_contact', 0)}; traction: "
              f"{o.get('traction')}")
    if res.method != "hertz":
        _print_families(s, o)
    print(f"  peak Fc {s['Fc_max']:.1f} N, p0 Hertz {s['p0_hertz_max'] / 1e6:.1f} MPa"
          + _p0_fe_text(res, s)
          + f", von Mises {s['vm_max'] / 1e6:.1f} MPa, tau1 {s['tau1_max'] / 1e6:.1f} MPa")
    if res.method == "fe":
        print(f"  p0 FE vs Hertz: {hertz_check_text(s)}")
    if res.method != "hertz" and estimate_text(res):
        print(f"  {estimate_text(res)}")
    for line in s.get("extras", {}).get("headline", ()):   # what the headline model omits
        print(f"  {line}")
    for line in s.get("extras", {}).get("worst", ()):   # each provider's worst values (sweep.worst)
        print(f"  {line}")
    line = assess_line(s.get("extras", {}))              # report.md has it as a table
    if line:
        print(f"  {line}")
    for note in s.get("extras", {}).get("notes", ()):   # e.g. the cam disk check (femcam.sweep.extras)
        print(f"  {note}")
    for k, v in res.paths.items():
        print(f"  {k}: {v}")
    for flag in s.get("extras", {}).get("flags", ()):
        print(f"femcam sweep: warning: {flag}", file=sys.stderr)
    if s["n_failed"]:
        print(f"femcam sweep: warning: {s['n_failed']} angle(s) failed; see the status and "
              "message columns", file=sys.stderr)
