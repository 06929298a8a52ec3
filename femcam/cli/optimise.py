"""``femcam optimise SCENE.toml --objective p0 --vary NAME=LO:HI ... --out DIR``: minimise the
worst-angle objective of a cam over base radius, roller radius, rise angle and the free interior
ordinates of a Bezier rise, subject to the pressure-angle, undercut/curvature and lift-off
limits; the optimum is checked by the FE and compared with seed 002's Bezier degrees and the
classical laws.

Writes ``DIR/optimum.json`` (the optimum, how it was obtained, every start, the FE check) and
``DIR/compare.csv`` (one row per law: peak p0, max phi, min rho, peak acceleration, margins).
"""

from __future__ import annotations

import math
import shlex
import sys

from .._progress import phase
from ..io import provenance
from ..optimise import OBJECTIVES, BezierRise, compare_laws, optimise
from ..optimise.outputs import EDGE_UNITS, parse_vary, write_outputs
from ..scene import load_scene
from ._common import add_overwrite, add_scene_out, out_dir, plain, refuse_non_empty
from ._flags import Range, add_number


def register(subparsers) -> None:
    """Add the ``optimise`` sub-parser and set its ``func``.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        Where ``femcam``'s parser (:func:`femcam.cli.build_parser`) collects its subcommands.
    """
    p = subparsers.add_parser("optimise", help="minimise peak p0 (or size, wear, ...) over the cam design",
                              description=plain(__doc__))
    add_scene_out(p, "scene file (roller follower)")
    p.add_argument("--objective", default="p0", choices=OBJECTIVES, help="quantity to minimise (default p0)")
    p.add_argument("--vary", action="append", required=True, metavar="NAME=LO:HI",
                   help="design variable and bounds: base_radius_mm, roller_radius_mm, rise_angle_deg, "
                        "control_point_<i> or control_points (every free Bezier ordinate); repeatable")
    add_number(p, "--phi-max-deg", Range("deg", 0.0, 90.0, lo_open=True, hi_open=True,
                                         why="a pressure angle of 90 deg jams the follower"),
               default=30.0, help="pressure-angle limit (default 30)")
    add_number(p, "--rho-min-mm", Range("mm", 0.0, 1000.0, why="the scene's radius range"), default=0.0,
               help="smallest convex cam radius (default 0 = no undercut)")
    add_number(p, "--liftoff-rpm", Range("rpm", 0.0, 1e5, lo_open=True, why="the scene's speed range"),
               default=None, help="no lift-off up to this speed")
    add_number(p, "--safety-min", Range("", 0.0, 100.0, lo_open=True, why="a safety factor > 0"),
               default=None, help="smallest safety factor of every assessment criterion (needs the "
                                  "scene's data)")
    add_number(p, "--lambda-min", Range("", 0.0, 100.0, lo_open=True, why="a film ratio > 0"),
               default=None, help="smallest film ratio lambda (assessment)")
    add_number(p, "--degree", Range("(Bezier degree)", 3, 30, whole=True,
                                    why="the rise's continuity needs >= 3; above 30 the basis is "
                                        "ill-conditioned"),
               default=9, help="Bezier degree when control points vary (default 9)")
    add_number(p, "--zero-derivatives", Range("(derivatives)", 0, 4, whole=True, why="v, a, j, snap at most"),
               default=2, help="derivatives that vanish at each end of the Bezier rise (default 2: v, a)")
    add_number(p, "--starts", Range("(starts)", 1, 50, whole=True, why="each start costs one SLSQP run"),
               default=3, help="SLSQP starts (default 3)")
    p.add_argument("--no-fe", action="store_true", help="skip the FE check of the optimum")
    add_overwrite(p)
    p.set_defaults(func=_run)


def _run(args) -> int:
    out_dir(args.out, create=False)  # checked before any work, created below
    refuse_non_empty(args.out, args.overwrite)  # the rule of every subcommand, before the work
    scene = load_scene(args.scene)
    bez = BezierRise(degree=args.degree, zero_derivatives=args.zero_derivatives)
    variables = [v for spec in args.vary for v in parse_vary(spec, bez.free)]
    cons = {"phi_max": math.radians(args.phi_max_deg), "rho_min": args.rho_min_mm * 1e-3}
    for key in ("safety_min", "lambda_min"):
        if getattr(args, key) is not None:
            cons[key] = getattr(args, key)
    if args.liftoff_rpm is not None:
        cons["liftoff_omega"] = args.liftoff_rpm * math.pi / 30.0
    with phase("optimise: starts"):
        res = optimise(scene, objective=args.objective, variables=variables, constraints=cons,
                       starts=args.starts, bezier=bez, verify_fe=not args.no_fe)
    table = compare_laws(scene, optimum=res, constraints=cons)
    out = out_dir(args.out)
    prov = provenance(scene_path=args.scene, command=shlex.join(["femcam", "optimise", *sys.argv[2:]]))
    files = write_outputs(out, res, table, prov)
    print(f"{res.objective}: {res.value:.6g} {res.unit} (start {res.start_value:.6g}); "
          f"converged {res.converged}")
    if res.objective == "lambda":                     # the objective minimised is 1/lambda_min
        print(f"smallest film parameter lambda_min = {1.0 / res.value:.6g} "
              f"(start {1.0 / res.start_value:.6g})")
    print(res.message)
    edge = {si: (flag, f) for flag, (si, f) in EDGE_UNITS.items()}
    for n, v in res.design().items():
        flag, f = edge.get(n, (n, 1.0))               # as --vary takes it: mm, deg
        print(f"  {flag} = {v / f:.6g}")
    print("wrote " + ", ".join(str(f) for f in files))
    if res.fe is not None and not res.fe.ok:           # asked for and not delivered: not a success
        print(f"femcam optimise: error: {res.fe.message} (the optimum is written; rerun with --no-fe "
              "to skip the check)", file=sys.stderr)
        return 1
    if res.fe is not None:
        print(res.fe.message)
    return 0
