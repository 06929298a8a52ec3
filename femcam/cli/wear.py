"""``femcam wear``: seed 000's Archard/RMS table, and the Archard wear map of a scene.

* ``femcam wear seed000 [--csv FILE] [--all-laws]`` prints seed 000's Table 3 layout (v_rms in
  mm/s, ratio to SHM, S in mm), the wear list (W in mm^3), interior and with-dwell peak jerk and
  junction continuity, and the paper-vs-femcam differences.
* ``femcam wear map SCENE.toml --out DIR [--cycles N] [--source hertz|fe] [--laws a,b,c]
  [--tip-radius-mm R] [--evolve-blocks K]`` writes ``DIR/wear_<law>.csv`` (per cam angle),
  ``DIR/wear_<law>_surface.csv`` (cam arc length grid), ``DIR/wear_<law>_follower.csv``
  (follower surface grid), ``DIR/wear_summary.csv`` and PNG plots. With ``--evolve-blocks K``
  (roller followers) the profile is also evolved in blocks (:mod:`femcam.wear.evolution`) with
  1, 2, 4, ... K blocks: ``DIR/wear_<law>_evolution.csv`` (convergence table) and
  ``DIR/wear_<law>_evolution.png`` (evolved vs linear depth). A finite-length roller (crown,
  edge radius, tilt or roller/cam widths, :mod:`femcam.halfspace`) wears at its most loaded
  slice (:mod:`femcam.wear.axial`): ``pressure = axial_peak`` in the summary.

Scene ``[wear]`` keys (checked; see :mod:`femcam.wear.options`): ``K`` (dimensionless; with the
cam's ``hardness_MPa``) or ``k_mm3_per_N_m``; ``roller_model = "srr"|"inertia"``, ``srr``,
``J_kg_m2``, ``T_drag_N_m``; ``cycles`` (a knife edge's tip radius: ``[follower] tip_radius_mm``).
"""

from __future__ import annotations

import dataclasses
import math
import shlex
import sys
from pathlib import Path

import numpy as np

from .. import _validate
from .._progress import phase
from ..assess import wear_factor
from ..errors import InputError
from ..halfspace.rows import has_finite_length
from ..io import provenance, write_rows, write_table
from ..kinematics import LAW_NAMES
from ..scene import load_scene
from ..scene.case import contact_case, tip_scene
from ..scene.finite_case import finite_case
from ..sweep import SweepOptions, sweep
from ..viz.wear import plot_evolution, plot_wear_comparison, plot_wear_map, plot_wear_polar
from ..wear.axial import scene_wear_map
from ..wear.coating import coating_wear
from ..wear.evolution import convergence_table, evolution_case, evolution_problem
from ..wear.options import describe_k, wear_coefficient_info
from ..wear.seed000 import PAPER_LAWS, format_table3, seed000_table, table_rows_for_csv
from ._common import NAMED_LAWS, add_overwrite, add_scene_out, check_law, out_dir, plain, refuse_non_empty
from ._flags import Range, add_number

#: ranges of the numeric flags of ``wear map`` (femcam.cli._flags)
CYCLES = Range("revolutions", 0.0, 1e12, lo_open=True,
               why="1e12 revolutions is 3,000 years at 600 rpm")
STEP = Range("deg", 0.01, 10.0, why="36,000 angles at most (~2 min of wear map); above 10 deg the "
             "contact path is not resolved")
TIP = Range("mm", 0.0, 100.0, lo_open=True, why="a tip radius above 100 mm is a flat face")
BLOCKS = Range("(number of blocks)", 1, 4096, whole=True,
               why="with the angle step also capped at MAX_ANGLE_SOLVES of femcam.wear.evolution")


def register(subparsers) -> None:
    """Add the ``wear`` sub-parser (``seed000`` and ``map``) and set its ``func``.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        Where ``femcam``'s parser (:func:`femcam.cli.build_parser`) collects its subcommands.
    """
    p = subparsers.add_parser("wear", help="Archard wear: seed 000's table, or a wear map of a scene",
                              description=plain(__doc__))
    sub = p.add_subparsers(dest="wear_command", metavar="WHAT")
    s = sub.add_parser("seed000", help="seed 000's Table 3 and wear list, recomputed",
                       description="Seed 000's Table 3 recomputed: v_rms (mm/s), its ratio to SHM, "
                       "sliding distance S (mm), the Archard wear list W (mm^3), interior and "
                       "with-dwell peak jerk, junction continuity, and where femcam differs "
                       "from the paper.")
    s.add_argument("--csv", default=None, metavar="FILE", help="also write the table as CSV")
    s.add_argument("--all-laws", action="store_true",
                   help="every femcam motion law a name alone defines (" + ", ".join(NAMED_LAWS)
                        + "), not only the paper's " + ", ".join(PAPER_LAWS))
    s.set_defaults(func=_seed000)
    m = sub.add_parser("map", help="Archard wear depth on the cam and the follower of a scene",
                       description="Archard wear depth per cam angle, along the cam surface and "
                       "on the follower; writes DIR/wear_<law>.csv, wear_<law>_surface.csv, "
                       "wear_<law>_follower.csv, wear_summary.csv and PNG plots. Scene [wear] "
                       "keys: K (with [materials.cam] hardness_MPa) or k_mm3_per_N_m, "
                       "roller_model = srr|inertia, srr, J_kg_m2, T_drag_N_m, cycles.")
    add_scene_out(m, "scene file (see examples/)")
    add_number(m, "--cycles", CYCLES, default=None, metavar="N",
               help="number of cam revolutions (default: scene [wear] cycles or 1e6)")
    m.add_argument("--source", choices=("hertz", "fe"), default="hertz",
                   help="contact pressure from Hertz (default) or the FE sweep (slow)")
    m.add_argument("--laws", default=None, metavar="A,B,C",
                   help="compare motion laws (comma-separated; default: the scene's): "
                        + ", ".join(LAW_NAMES))
    add_number(m, "--step-deg", STEP, default=0.5, metavar="DEG", help="cam angle step (default 0.5)")
    add_number(m, "--tip-radius-mm", TIP, default=None, metavar="R",
               help="knife-edge followers: tip radius in mm (default: scene [follower] tip_radius_mm); "
                    "a sharp tip has no contact width, so the wear map needs one")
    add_number(m, "--evolve-blocks", BLOCKS, default=None, metavar="K",
               help="roller followers: also evolve the profile (wear -> geometry -> pressure -> wear) "
                    "in 1, 2, 4, ... K blocks of cycles and write the convergence table")
    m.add_argument("--no-plots", action="store_true", help="skip the PNG plots")
    add_overwrite(m)
    m.set_defaults(func=_map)
    p.set_defaults(func=lambda args: (p.print_help(), 2)[1])


def _csv_path(value) -> Path:
    """The ``--csv`` file, checked before any work: not empty, not a directory, in a directory
    that can be written (one line naming the flag each)."""
    if not str(value).strip():
        raise InputError(f"--csv = {value!r}: must name a file (it is empty), e.g. --csv table3.csv")
    path = Path(value)
    if path.is_dir() or str(value).endswith(("/", "\\")):
        raise InputError(f"--csv = {value!r}: is a directory, not a file; give a file path, e.g. "
                         f"--csv {path / 'table3.csv'}")
    out_dir(path.parent, "--csv (its directory)", create=False)
    return path


def _seed000(args) -> int:
    csv = _csv_path(args.csv) if args.csv is not None else None   # before the work
    laws = PAPER_LAWS
    if args.all_laws:
        laws = NAMED_LAWS
    t = seed000_table(laws)
    print(format_table3(t))
    if csv is not None:
        header, rows = table_rows_for_csv(t)
        path = csv
        out_dir(path.parent, "--csv (its directory)")
        write_rows(path, header, rows, provenance(command=shlex.join(sys.argv)),
                   title="femcam wear seed000: seed 000's Table 3 recomputed, one row per law")
        print(f"\nwrote {path}")
    return 0


def _follower_coordinate(scene) -> tuple[str, str, str]:
    """(CSV column name, plain-words description, plot label) of the follower surface coordinate."""
    if scene.follower.translating_roller:
        return "roller_arc_mm", ("arc along the roller circumference (0 .. 2 pi Rr) from the roller point "
                                 "in contact at the first cam angle of the first revolution"), "roller arc"
    if scene.follower.flat_face:
        return "face_x_mm", "distance along the flat face from the follower axis", "face position from axis"
    return ("tip_arc_mm", "arc along the tip from the tip's axis point (r_tip x pressure angle)",
            "tip arc r_tip phi")


def _check_map_args(args) -> tuple[float, float | None]:
    """``(step (deg), tip radius (m) or None)`` from the flags, checked."""
    step = STEP.parse("--step-deg", args.step_deg)  # the flags' ranges (also for main(...) values)
    tip = None
    if args.tip_radius_mm is not None:
        tip = TIP.parse("--tip-radius-mm", args.tip_radius_mm) * 1e-3
    if args.cycles is not None:
        CYCLES.parse("--cycles", args.cycles)
    if args.evolve_blocks is not None:
        why = evolution_problem(round(360.0 / step), BLOCKS.parse("--evolve-blocks", args.evolve_blocks))
        if why:
            raise _validate.fail("--evolve-blocks", args.evolve_blocks, "(number of blocks)",
                                 why.replace("coarser angle step", "coarser angle step (--step-deg)"))
    if args.evolve_blocks is not None and args.source != "hertz":
        raise InputError(f"--source = {args.source}: --evolve-blocks uses Hertz pressure (--source hertz)")
    return step, tip


def _map(args) -> int:
    out_dir(args.out, create=False)  # checked before any work, created below
    step, tip = _check_map_args(args)
    laws = [check_law("--laws", x.strip()) for x in args.laws.split(",")] \
        if args.laws is not None else [None]
    refuse_non_empty(args.out, args.overwrite)  # the rule of femcam sweep
    scene = load_scene(args.scene)
    cycles = args.cycles if args.cycles is not None else (scene.wear.cycles if scene.wear.cycles is not None
                                                           else 1e6)
    theta = np.radians(np.arange(0.0, 360.0, step))
    k, k_where = wear_coefficient_info(scene.wear, scene.cam.hardness)
    print(describe_k(k, k_where))
    out = out_dir(args.out)
    head = provenance(scene_path=args.scene, command=shlex.join(sys.argv), cycles=cycles,
                      source=args.source, wear_coefficient=describe_k(k, k_where),
                      k_m3_per_N_m=float(k))
    results = {}
    for name in laws:
        sc = scene.with_law(name) if name else scene
        label = name or "scene"
        fe = None
        if args.source == "fe":  # the FE pressure: a sweep of the scene (a knife edge as itself)
            # the scene's [fe] settings apply as in femcam sweep; progress on a terminal
            fe = sweep(_fe_scene(sc, tip), SweepOptions(angles=theta, method="fe"))
        case = contact_case(sc, theta, tip_radius=tip)
        k_factor, regime = wear_factor(case, fe.table if fe is not None else None)
        with phase(f"wear map: {label}"):
            finite = finite_case(sc) if has_finite_length(sc.finite_length, sc.length) else None
            coating = coating_wear(sc.layers, sc.wear, sc.cam.hardness)
            wm, st, slip = scene_wear_map(case, finite, cycles=cycles, fe=fe, k_factor=k_factor,
                                          regime=regime, coating=coating)  # axial peak if crowned
        results[label] = (wm, st, slip)
        _write_angle_csv(out / f"wear_{label}.csv", head, theta, cycles, wm, st, slip)
        _write_surface_csv(out / f"wear_{label}_surface.csv", head, cycles, wm)
        _write_follower_csv(out / f"wear_{label}_follower.csv", head, cycles, wm, slip, sc)
    source = "axial_peak" if has_finite_length(scene.finite_length, scene.length) else args.source
    _write_summary(out / "wear_summary.csv", head, cycles, k, k_where, results, source,
                   scene_law_label(scene))
    if not args.no_plots:
        _plots(scene, results, out)
    if args.evolve_blocks is not None:
        for name in laws:
            sc = scene.with_law(name) if name else scene
            _evolution(sc, name or "scene", theta, cycles, args, out, head)
    print(f"wrote {out}/")
    return 0


def _fe_scene(scene, tip):
    """The scene the FE sweep of ``--source fe`` solves: a knife edge stays a knife edge (the
    sweep cuts the cam for its radiused tip and lets the tip slide) with ``--tip-radius-mm`` as
    its tip radius; any other follower as it is."""
    if scene.follower.needs_tip:
        return dataclasses.replace(scene, tip_radius=tip if tip is not None else scene.tip_radius)
    return tip_scene(scene, tip)   # itself; refuses a tip radius on another follower, naming it


def _write_angle_csv(path, head, theta, cycles, wm, st, slip) -> None:
    """Per cam angle: lift, force, slip, arc, depth per pass / revolution / ``cycles``."""
    # depth after ``cycles`` at the contact point of each angle (coating included)
    total = np.interp(wm.xi_cam, wm.x_cam, wm.depth_cam_total, period=wm.perimeter)
    cols = {"theta_deg": np.degrees(theta), "s_mm": np.asarray(st.s) * 1e3, "Fc_N": st.Fc,
            "v_slip_m_s": slip.v_slip, "V_cam_m_s": slip.V_cam, "arc_mm": wm.xi_cam * 1e3,
            "depth_pass_closed_nm": wm.depth_pass * 1e9, "depth_per_rev_nm": wm.depth_at_theta * 1e9,
            f"depth_{cycles:g}_cycles_um": total * 1e6}
    write_table(path, cols, head, title="femcam wear map: one row per cam angle")


def _write_surface_csv(path, head, cycles, wm) -> None:
    """Depth on the cam arc-length grid."""
    cols = {"arc_mm": wm.x_cam * 1e3, "depth_per_rev_nm": wm.depth_cam * 1e9,
            f"depth_{cycles:g}_cycles_um": wm.depth_cam_total * 1e6}
    write_table(path, cols, head, title="femcam wear map: depth along the cam surface")


def _write_follower_csv(path, head, cycles, wm, slip, scene) -> None:
    """Depth on the follower surface grid (with the roller's drift per revolution)."""
    col, words, _short = _follower_coordinate(scene)
    note = f"{col}: {words}; {slip.model}"
    if wm.follower_period is not None:
        note += (f"; the contact advances {wm.follower_drift * 1e3:.6g} mm of the "
                 f"{wm.follower_period * 1e3:.6g} mm roller circumference per cam revolution: "
                 f"depth_{cycles:g}_cycles sums the revolutions with that drift, "
                 f"depth_{cycles:g}_cycles_no_drift is {cycles:g} x depth_per_rev "
                 "(phase-locked bound)")
    cols = {col: wm.x_follower * 1e3, "depth_per_rev_nm": wm.depth_follower * 1e9,
            f"depth_{cycles:g}_cycles_um": wm.depth_follower_total * 1e6,
            f"depth_{cycles:g}_cycles_no_drift_um": wm.depth_follower * cycles * 1e6}
    write_table(path, cols, dict(head, columns_note=note),
                title="femcam wear map: depth on the follower surface")


def scene_law_label(scene) -> str:
    """The motion law(s) of a scene's rise/fall segments, ``"bezier5"`` or ``"cycloidal+shm"``
    (the row label of ``femcam wear map`` without ``--laws``).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene.

    Returns
    -------
    str
        The distinct law names in segment order, joined by ``+``.
    """
    names = [seg.law.name for seg in scene.program.segments if seg.law is not None]
    return "+".join(dict.fromkeys(names)) or "scene"


def _write_summary(path, head, cycles, k, k_where, results, source, scene_law="scene") -> None:
    """One row per law (CSV) and the printed table; the scene's own law (file label ``scene``)
    is shown as ``scene_law``."""
    rows = []
    header = ["law", "cycles", "max_depth_um", "theta_at_max_deg", "arc_at_max_mm", "volume_cam_mm3",
                "volume_follower_mm3", "volume_archard_mm3", "conservation_error",
                "max_depth_follower_um", "follower_x_at_max_mm", "max_depth_follower_no_drift_um",
                "follower_drift_mm_per_rev", "load_error", "skipped_angles_deg", "k_m3_per_N_m",
                "pressure", "slip_model"]
    print(f"{'law':<20}{'max depth um':>14}{'at theta deg':>14}{'arc mm':>9}{'V cam mm^3':>13}"
          f"{'follower um':>13}{'at mm':>9}  (after {cycles:g} revolutions)")
    for key, (wm, _st, slip) in results.items():
        label = scene_law if key == "scene" else key
        skipped = " ".join(f"{math.degrees(wm.theta[i]):g}" for i in wm.skipped)
        rows.append([label, f"{cycles:g}", f"{wm.max_depth * 1e6:.6g}",
                    f"{math.degrees(wm.theta_max):.3f}",
                    f"{wm.x_max * 1e3:.5g}", f"{wm.volume_cam_total * 1e9:.6g}",
                    f"{wm.volume_follower_total * 1e9:.6g}", f"{wm.volume_archard * cycles * 1e9:.6g}",
                    f"{wm.conservation_error:.2e}", f"{wm.max_depth_follower * 1e6:.6g}",
                    f"{wm.x_max_follower * 1e3:.5g}", f"{wm.max_depth_follower_locked * 1e6:.6g}",
                    f"{wm.follower_drift * 1e3:.6g}", f"{wm.load_error:.2e}", skipped, f"{wm.k:.6g}",
                    source, slip.model])
        print(f"{label:<20}{wm.max_depth * 1e6:>14.4g}{math.degrees(wm.theta_max):>14.2f}"
              f"{wm.x_max * 1e3:>9.3f}{wm.volume_cam_total * 1e9:>13.4g}"
              f"{wm.max_depth_follower * 1e6:>13.4g}{wm.x_max_follower * 1e3:>9.3f}")
        if wm.skipped:
            print(f"  {label}: skipped {len(wm.skipped)} angle(s) with a failed FE solve: {skipped} deg")
    write_rows(path, header, rows, head, title="femcam wear map: one row per motion law",
               text=("law", "skipped_angles_deg", "pressure", "slip_model"))


def _plots(scene, results, out) -> None:
    """Wear map and polar plot per law; the comparison of the laws."""
    for label, (wm, st, _slip) in results.items():
        plot_wear_map(wm, out / f"wear_{label}.png", title=f"{scene.name} ({label})",
                      follower_label=_follower_coordinate(scene)[2])
        plot_wear_polar(wm, st.profile.x, st.profile.y, out / f"wear_{label}_polar.png",
                        title=f"{scene.name} ({label})")
    if len(results) > 1:
        plot_wear_comparison({k: v[0] for k, v in results.items()}, out / "wear_laws.png",
                             title=scene.name)


def _evolution(scene, label, theta, cycles, args, out, head) -> None:
    """``--evolve-blocks K``: convergence table CSV and evolved-vs-linear PNG of one law."""
    with phase("wear map: profile evolution"):
        ct = convergence_table(evolution_case(contact_case(scene, theta)), cycles, args.evolve_blocks)
    header, rows = ct.rows()
    fin = ct.finest
    write_rows(out / f"wear_{label}_evolution.csv", header, rows,
               dict(head, evolution="profile evolution in blocks (explicit Euler)",
                    linear_max_depth_um=ct.linear_max_depth * 1e6, a_over_R_max=fin.a_over_R_max),
               title="femcam wear map --evolve-blocks: convergence, one row per block count")
    print(f"{label}: profile evolution over {cycles:g} revolutions (max cam depth, um; difference to "
          f"{ct.blocks[-1]} blocks, nm; observed order)")
    for r in rows:
        print(f"  {r[0]:>6} blocks of {r[1]:>10} rev: {float(r[2]):.8g} um  {r[3]:>10} nm  order {r[5]}")
    if not args.no_plots:
        plot_evolution(fin, out / f"wear_{label}_evolution.png", title=f"{scene.name} ({label})")
