"""``femcam wear``: seed 000's Archard/RMS table, and the Archard wear map of a scene.

* ``femcam wear seed000 [--csv FILE] [--all-laws]`` prints seed 000's Table 3 layout (v_rms in
  mm/s, ratio to SHM, S in mm), the wear list (W in mm^3), peak jerk and junction continuity,
  and the paper-vs-femcam differences.
* ``femcam wear map SCENE.toml --out DIR [--cycles N] [--source hertz|fe] [--laws a,b,c]``
  writes ``DIR/wear_<law>.csv`` (per cam angle), ``DIR/wear_<law>_surface.csv`` (cam arc
  length grid), ``DIR/wear_summary.csv`` and PNG plots.

Scene ``[wear]`` keys: ``K`` (dimensionless; with the cam's ``hardness_MPa``) or
``k_mm3_per_N_m``; ``roller_model = "srr"|"inertia"``, ``srr``, ``J_kg_m2``; ``cycles``.
"""

from __future__ import annotations

import csv
import math
import shlex
import sys
from pathlib import Path

import numpy as np

from ..errors import InputError


def register(subparsers) -> None:
    p = subparsers.add_parser("wear", help="Archard wear: seed 000's table, or a wear map of a scene",
                              description=__doc__.split("\n\n")[0])
    sub = p.add_subparsers(dest="wear_command", metavar="WHAT")
    s = sub.add_parser("seed000", help="seed 000's Table 3 and wear list, recomputed")
    s.add_argument("--csv", default=None, metavar="FILE", help="also write the table as CSV")
    s.add_argument("--all-laws", action="store_true", help="every femcam motion law, not only the paper's 3")
    s.set_defaults(func=_seed000)
    m = sub.add_parser("map", help="Archard wear depth on the cam of a scene")
    m.add_argument("scene", metavar="SCENE.toml")
    m.add_argument("--out", required=True, metavar="DIR")
    m.add_argument("--cycles", type=float, default=None, metavar="N",
                   help="number of cam revolutions (default: scene [wear] cycles or 1e6)")
    m.add_argument("--source", choices=("hertz", "fe"), default="hertz",
                   help="contact pressure from Hertz (default) or the FE sweep (slow)")
    m.add_argument("--laws", default=None, metavar="A,B,C",
                   help="compare motion laws (comma-separated; default: the scene's)")
    m.add_argument("--step-deg", type=float, default=0.5, metavar="DEG", help="cam angle step (default 0.5)")
    m.add_argument("--no-plots", action="store_true")
    m.set_defaults(func=_map)
    p.set_defaults(func=lambda args: (p.print_help(), 2)[1])


def _seed000(args) -> int:
    from ..wear.seed000 import PAPER_LAWS, format_table3, seed000_table, table_rows_for_csv

    laws = PAPER_LAWS
    if args.all_laws:
        from ..kinematics import LAW_NAMES

        laws = tuple(n for n in LAW_NAMES if n not in ("bezier", "polynomial"))
    t = seed000_table(laws)
    print(format_table3(t))
    if args.csv:
        header, rows = table_rows_for_csv(t)
        path = Path(args.csv)
        path.parent.mkdir(parents=True, exist_ok=True)
        with path.open("w", newline="") as fh:
            fh.write(f"# femcam wear seed000; command: {shlex.join(sys.argv)}\n")
            w = csv.writer(fh)
            w.writerow(header)
            w.writerows(rows)
        print(f"\nwrote {path}")
    return 0


def wear_coefficient(scene) -> float:
    """k (m^3/(N m)) from the scene's [wear] table: ``k_mm3_per_N_m``, or ``K`` with the cam
    hardness; default K = 1e-8 with H = 2000 N/mm^2 (seed 000)."""
    from ..wear.archard import dimensional_coefficient

    wr = scene.wear or {}
    if "k_mm3_per_N_m" in wr:
        from .. import _validate as vd

        return vd.nonnegative("[wear] k_mm3_per_N_m", wr["k_mm3_per_N_m"], "mm^3/(N m)") * 1e-9
    H = scene.cam.hardness or 2000e6
    return dimensional_coefficient(wr.get("K", 1e-8), H)


def scene_wear(scene, theta, *, source="hertz", cycles=1e6):
    """(WearMap, SceneState, SlipResult) of a scene at angles theta (one revolution)."""
    from ..wear.map import wear_map
    from ..wear.slip import follower_slip

    st = scene.analyse(theta)
    Fc = np.clip(st.Fc, 0.0, None)
    if source == "fe":
        from ..sweep import sweep

        res = sweep(scene, angles=theta, method="fe", progress=False)
        table = {"theta": res.theta, "a": res["a_fe"], "p0": res["p0_fe"], "Fc": res["Fc"]}
    else:
        from ..hertz import LineContact

        R2 = scene.follower.Rr if type(scene.follower).__name__ == "RollerFollower" else math.inf
        if type(scene.follower).__name__ == "KnifeEdgeFollower":
            raise InputError("follower type = knife-edge: a sharp tip has no Hertz contact width; "
                             "use a roller or flat-faced follower for the wear map")
        hc = LineContact(F=Fc, length=scene.length, R1=st.rho, R2=R2, cam=scene.cam, roller=scene.roller)
        table = {"theta": theta, "a": hc.a, "p0": hc.p0, "Fc": Fc}
    wr = scene.wear or {}
    slip = follower_slip(scene.follower, theta, st.s, st.s1, st.s2, omega=scene.omega, Fc=Fc,
                         roller_model=wr.get("roller_model", "srr"), srr=float(wr.get("srr", 0.02)),
                         mu=scene.mu or 0.1, J=wr.get("J_kg_m2"))
    wm = wear_map(table, slip, k=wear_coefficient(scene), length=scene.length, cycles=cycles)
    return wm, st, slip


def _map(args) -> int:
    from ..scene import load_scene

    scene = load_scene(args.scene)
    cycles = args.cycles if args.cycles is not None else float((scene.wear or {}).get("cycles", 1e6))
    step = float(args.step_deg)
    if not (0 < step <= 10):
        raise InputError(f"--step-deg = {step:g} deg: must be in (0, 10]")
    theta = np.radians(np.arange(0.0, 360.0, step))
    laws = [x.strip() for x in args.laws.split(",")] if args.laws else [None]
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    head = f"# femcam wear map; scene: {args.scene}; command: {shlex.join(sys.argv)}\n"
    results = {}
    for name in laws:
        sc = scene.with_law(name) if name else scene
        label = name or "scene"
        wm, st, slip = scene_wear(sc, theta, source=args.source, cycles=cycles)
        results[label] = (wm, st, slip)
        with (out / f"wear_{label}.csv").open("w", newline="") as fh:
            fh.write(head)
            w = csv.writer(fh)
            w.writerow(["theta_deg", "s_mm", "Fc_N", "v_slip_m_s", "V_cam_m_s", "arc_mm",
                        "depth_pass_closed_nm", "depth_per_rev_nm", f"depth_{cycles:g}_cycles_um"])
            for i in range(theta.size):
                w.writerow([f"{math.degrees(theta[i]):.4f}", f"{st.s[i] * 1e3:.6g}", f"{st.Fc[i]:.6g}",
                            f"{slip.v_slip[i]:.6g}", f"{slip.V_cam[i]:.6g}", f"{wm.xi_cam[i] * 1e3:.6g}",
                            f"{wm.depth_pass[i] * 1e9:.6g}", f"{wm.depth_at_theta[i] * 1e9:.6g}",
                            f"{wm.depth_at_theta[i] * cycles * 1e6:.6g}"])
        with (out / f"wear_{label}_surface.csv").open("w", newline="") as fh:
            fh.write(head)
            w = csv.writer(fh)
            w.writerow(["arc_mm", "depth_per_rev_nm", f"depth_{cycles:g}_cycles_um"])
            for x, h in zip(wm.x_cam, wm.depth_cam, strict=True):
                w.writerow([f"{x * 1e3:.6g}", f"{h * 1e9:.6g}", f"{h * cycles * 1e6:.6g}"])
    with (out / "wear_summary.csv").open("w", newline="") as fh:
        fh.write(head)
        w = csv.writer(fh)
        w.writerow(["law", "cycles", "max_depth_um", "theta_at_max_deg", "arc_at_max_mm", "volume_cam_mm3",
                    "volume_follower_mm3", "volume_archard_mm3", "conservation_error", "slip_model"])
        print(f"{'law':<20}{'max depth um':>14}{'at theta deg':>14}{'arc mm':>9}{'V cam mm^3':>13}"
              f"  (after {cycles:g} revolutions, k = {results[next(iter(results))][0].k:.3g} m^3/(N m))")
        for label, (wm, _st, slip) in results.items():
            w.writerow([label, f"{cycles:g}", f"{wm.max_depth * 1e6:.6g}",
                        f"{math.degrees(wm.theta_max):.3f}",
                        f"{wm.x_max * 1e3:.5g}", f"{wm.volume_cam * cycles * 1e9:.6g}",
                        f"{wm.volume_follower * cycles * 1e9:.6g}", f"{wm.volume_archard * cycles * 1e9:.6g}",
                        f"{wm.conservation_error:.2e}", slip.model])
            print(f"{label:<20}{wm.max_depth * 1e6:>14.4g}{math.degrees(wm.theta_max):>14.2f}"
                  f"{wm.x_max * 1e3:>9.3f}{wm.volume_cam * cycles * 1e9:>13.4g}")
    if not args.no_plots:
        from ..viz.wear import plot_wear_comparison, plot_wear_map, plot_wear_polar

        for label, (wm, st, _slip) in results.items():
            plot_wear_map(wm, out / f"wear_{label}.png", title=f"{scene.name} ({label})")
            plot_wear_polar(wm, st.profile.x, st.profile.y, out / f"wear_{label}_polar.png",
                            title=f"{scene.name} ({label})")
        if len(results) > 1:
            plot_wear_comparison({k: v[0] for k, v in results.items()}, out / "wear_laws.png",
                                 title=scene.name)
    print(f"wrote {out}/")
    return 0
