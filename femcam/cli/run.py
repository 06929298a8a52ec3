"""``femcam run SCENE.toml``: the analytic chain of a scene (kinematics -> profile -> loads).

Prints the cam program with its junction report, a table of s, v, a, j, phi, rho and Fc
against cam angle, and a summary (max phi, min rho, max Fc, lift-off intervals). Writes
``DIR/analytic.csv`` (every angle; units in the column names; provenance in
``DIR/analytic.csv-metadata.json``),
``DIR/summary.txt`` and, unless ``--no-plots``, PNG plots ``DIR/{svaj,phi,rho,fc,cam}.png``.
"""

from __future__ import annotations

import math
import shlex
import sys
from pathlib import Path

import numpy as np

from .. import _validate
from .._columns import Column
from ..dynamics import arm_follower, rigid_jump_speed
from ..io import atomic_write_text, provenance, write_table
from ..scene import load_scene
from ..sweep.table import COLUMNS as SWEEP_COLUMNS
from ..viz.analytic import plot_all
from ._common import (
    add_law_override,
    add_no_plots,
    add_overwrite,
    add_scene_out,
    check_law,
    out_dir,
    plain,
    refuse_non_empty,
)
from ._flags import RANGE_RULE, Range, add_number

#: the analytic chain's columns, named and scaled as in the sweep table (one copy of each
#: column's unit: :data:`femcam.sweep.table.COLUMNS`)
_ANALYTIC = ("theta", "s", "v", "a", "j", "phi", "rho", "Fc")
_SWEEP_COLUMNS = {c.si: c for c in SWEEP_COLUMNS}

#: CSV columns (:class:`femcam._columns.Column`; ``si`` is the SceneState attribute); the first
#: eight are the printed table
COLUMNS = (*(_SWEEP_COLUMNS[a] for a in _ANALYTIC),
           Column("contact_x", "contact_x_mm", 1e3), Column("contact_y", "contact_y_mm", 1e3),
           Column("liftoff", "liftoff", 1.0), Column("undercut", "undercut", 1.0))


#: ranges of the numeric flags (femcam.cli._flags)
PRINT_STEP = Range("deg", 1e-3, 360.0, why="a step below 0.001 deg prints every computed angle anyway")
PHI_LIMIT = Range("deg", 0.0, 90.0, lo_open=True, hi_open=True,
                  why="a pressure angle of 90 deg or more transmits no lift")


def register(subparsers) -> None:
    """Add the ``run`` sub-parser (the analytic chain of a scene) and set its ``func``.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        Where ``femcam``'s parser (:func:`femcam.cli.build_parser`) collects its subcommands.
    """
    p = subparsers.add_parser(
        "run", help="kinematics, profile and load tables of a scene, with PNG plots",
        description=plain(__doc__))
    add_scene_out(p, "scene file (see examples/)", out_required=False,
                  out_help="output directory (default: femcam-out/<scene name>)")
    p.add_argument("--angles-deg", default="0:360:0.5", metavar="START:STOP:STEP",
                   help=f"cam angles in degrees, {RANGE_RULE}: 0:360:1 is 0 to 359, 0:90:30 is 0 to 90 "
                        "(default 0:360:0.5)")
    add_number(p, "--print-every-deg", PRINT_STEP, default=10.0, metavar="STEP",
               help="angle step of the printed table in degrees (default 10); the CSV has all")
    add_law_override(p)
    add_number(p, "--phi-limit-deg", PHI_LIMIT, default=30.0, metavar="DEG",
               help="pressure-angle limit drawn and checked in the summary (default 30)")
    p.add_argument("--allow-undercut", action="store_true",
                   help="report an undercut profile as a warning instead of an error")
    add_no_plots(p)
    add_overwrite(p)
    p.set_defaults(func=_run)


def _intervals_deg(iv, most: int = 20) -> str:
    """The first ``most`` intervals, then ``... and N more``."""
    text = ", ".join(f"{math.degrees(a):.2f}-{math.degrees(b):.2f} deg" for a, b in iv[:most]) or "none"
    return text + (f", ... and {len(iv) - most} more" if len(iv) > most else "")


def _undercut_intervals(st):
    """Undercut intervals of the whole cam (dense check of Scene.analyse) or, for a SceneState
    built elsewhere, of the analysed angles."""
    return st.undercut_intervals or st.profile.undercut_intervals


def summary_lines(scene, st, phi_limit_deg: float = 30.0) -> list[str]:
    """Summary of the analytic chain: max |phi|, min |rho|, Fc range, lift-off and undercut.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene (its follower kind).
    st : femcam.scene.SceneState
        The chain at the scene's angles (SI, rad).
    phi_limit_deg : float
        Pressure-angle limit the maximum is checked against (deg).

    Returns
    -------
    list of str
        One line per quantity, angles in deg, lengths in mm, forces in N.
    """
    # the whole cam's max |phi| (every segment at its own points), not the analysed angles'
    phi_max, th_phi = (math.degrees(x) for x in scene.max_pressure_angle)
    rho = np.asarray(st.rho, float)
    i_rho = int(np.argmin(np.abs(rho)))
    conv = rho > 0
    i_max, i_min = int(np.argmax(st.Fc)), int(np.argmin(st.Fc))
    deg = lambda i: math.degrees(st.theta[i])  # noqa: E731
    concave = (f"yes, tightest rho {np.max(rho[~conv]) * 1e3:.4g} mm" if (~conv).any() else "no")
    lines = [
        f"max |phi|      = {phi_max:.3f} deg at theta = {th_phi:.4g} deg (whole cam; "
        f"{'OK' if phi_max <= phi_limit_deg else 'EXCEEDS'} limit {phi_limit_deg:g} deg)",
        f"min |rho|      = {abs(rho[i_rho]) * 1e3:.4g} mm at theta = {deg(i_rho):.2f} deg"
        f" ({'convex' if rho[i_rho] > 0 else 'concave'})",
        f"min convex rho = {np.min(rho[conv]) * 1e3:.4g} mm" if conv.any() else "min convex rho = none",
        f"concave        = {concave}",
        f"max Fc         = {st.Fc[i_max]:.2f} N at theta = {deg(i_max):.2f} deg",
        f"min Fc         = {st.Fc[i_min]:.2f} N at theta = {deg(i_min):.2f} deg",
        f"lift-off       = {_intervals_deg(st.loads.liftoff_intervals)}",
        f"undercut       = {_intervals_deg(_undercut_intervals(st))} (whole revolution: 0.05 deg grid and "
        "every segment)",
    ]
    if scene.follower.oscillating:  # the arm's rigid lift-off (jump) speed
        j = rigid_jump_speed(arm_follower(scene.dynamics, scene.follower.L), scene.program,
                             0.01 * scene.rpm, 10.0 * scene.rpm)
        lines.append(f"jump speed     = {j:.6g} rpm (rigid arm)" if math.isfinite(j) else
                     f"jump speed     = none up to {10 * scene.rpm:.6g} rpm (rigid arm)")
    if scene.follower.flat_face:
        lines.append(f"min face width = {st.profile.face_width_min * 1e3:.3f} mm (face centred on the axis)")
    return lines


def _table(st, every_deg: float) -> str:
    th = np.degrees(st.theta)
    if every_deg > 0:
        k = np.round((th - th[0]) / every_deg)
        pick = np.flatnonzero(np.isclose(th - th[0], k * every_deg, atol=1e-6))
    else:
        pick = np.arange(th.size)
    cols = COLUMNS[:8]
    head = "".join(f"{c.csv:>12s}" for c in cols)
    rows = []
    for i in pick:
        vals = [float(np.asarray(getattr(st, c.si))[i]) * c.factor for c in cols]
        # + 0.0 turns -0.0 into 0.0, so the table never shows "-0"
        rows.append("".join(f"{v + 0.0:12.5g}" for v in vals) + ("  LIFT-OFF" if st.liftoff[i] else ""))
    return "\n".join([head, *rows])


def write_csv(path, scene, st, command: str) -> Path:
    """Write the analytic chain at all angles as CSV (:data:`COLUMNS`, units in the names) and
    its sidecar JSON (:func:`femcam.io.write_table`).

    Parameters
    ----------
    path : str or os.PathLike
        Output file.
    scene : femcam.scene.Scene
        The scene (provenance: file, name, rpm, follower).
    st : femcam.scene.SceneState
        The chain (SI, rad; converted to the column units).
    command : str
        The command line, written in the sidecar JSON's provenance.

    Returns
    -------
    pathlib.Path
        The path written.
    """
    cols = {c.csv: np.asarray(getattr(st, c.si), float) * c.factor for c in COLUMNS}
    cols["liftoff"] = cols["liftoff"].astype(int)
    cols["undercut"] = cols["undercut"].astype(int)
    prov = provenance(scene_path=scene.source_path, command=command, scene_name=scene.name,
                      omega_rad_s=float(scene.omega), rpm=float(scene.rpm),
                      follower=repr(scene.follower))
    return write_table(path, cols, prov, title="femcam run: the analytic chain, one row per cam angle")


def _run(args) -> int:
    if args.out is not None:
        out_dir(args.out, create=False)  # checked before any work (same words as the others)
    if args.law is not None:
        check_law("--law", args.law)
    theta = _validate.angles_deg("--angles-deg", args.angles_deg)
    _validate.angle_count("--angles-deg", args.angles_deg, theta.size, 800.0, "femcam run")
    if hint := _validate.radians_hint("--angles-deg", args.angles_deg):
        print(f"femcam run: note: {hint}", file=sys.stderr)
    scene = load_scene(args.scene)
    if args.law is not None:
        scene = scene.with_law(args.law)
    out = args.out if args.out is not None else Path("femcam-out") / scene.name
    out_dir(out, create=False)
    refuse_non_empty(out, args.overwrite)  # before any work (the rule of every subcommand)
    st = scene.analyse(theta, allow_undercut=args.allow_undercut)
    out = out_dir(out)
    # rebuilt from the parsed options (sys.argv is not ours when main() is called in-process)
    opts = ["--out", str(out), "--angles-deg", args.angles_deg]
    opts += ["--law", args.law] if args.law else []
    opts += ["--allow-undercut"] if args.allow_undercut else []
    command = shlex.join(["femcam", "run", str(args.scene), *opts])

    fo, dy = scene.follower, scene.dynamics
    geo = fo.describe()  # the follower's geometry in mm (femcam.profile)
    # a dynamics record that describes itself (the oscillating arm) says so
    dyn = dy.describe() if hasattr(dy, "describe") else (
        f"m = {dy.m:g} kg, k = {dy.k:g} N/m, Fpl = {dy.Fpl:g} N, c = {dy.c:.4g} N s/m")
    print(f"femcam run: {scene.name}  ({scene.source_path})")
    if scene.description:
        print(f"  {scene.description}")
    print(f"  {fo.kind} follower, {geo}; omega = {scene.omega:.6g} rad/s ({scene.rpm:.6g} rpm); {dyn}")
    print()
    print(scene.program.table(omega=scene.omega))  # junction jumps in m/s, m/s^2, m/s^3
    print()
    print(f"Kinematics, profile and loads (every {args.print_every_deg:g} deg; all angles in the CSV):")
    print(_table(st, args.print_every_deg))
    print()
    summ = summary_lines(scene, st, args.phi_limit_deg)
    print("Summary:")
    for ln in summ:
        print("  " + ln)
    if _undercut_intervals(st):  # includes the analysed angles' own flags
        print("WARNING: the profile is undercut (see 'undercut' above); rho there is not realisable",
              file=sys.stderr)

    files = [write_csv(out / "analytic.csv", scene, st, command)]
    atomic_write_text(out / "summary.txt", "\n".join([f"scene: {scene.source_path}",
                                                      scene.program.table(omega=scene.omega),
                                                      "Summary:", *summ]) + "\n")
    files.append(out / "summary.txt")
    if not args.no_plots:
        files += plot_all(st, out, "", Rr=fo.Rr if fo.draws_circle else 0.0,
                          limit_deg=args.phi_limit_deg, title=scene.name)
    print()
    print("Wrote: " + ", ".join(str(f) for f in files))
    return 0
