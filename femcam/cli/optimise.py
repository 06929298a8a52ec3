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

from ..io import provenance
from ..optimise import OBJECTIVES, BezierRise, compare_laws, optimise
from ..optimise.outputs import parse_vary, write_outputs
from ..scene import load_scene
from ._common import add_scene_out, out_dir, plain


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
    p.add_argument("--phi-max-deg", type=float, default=30.0, help="pressure-angle limit (deg, default 30)")
    p.add_argument("--rho-min-mm", type=float, default=0.0,
                   help="smallest convex cam radius (mm; default 0 = no undercut)")
    p.add_argument("--liftoff-rpm", type=float, default=None, help="no lift-off up to this speed (rpm)")
    p.add_argument("--safety-min", type=float, default=None,
                   help="smallest safety factor of every assessment criterion (needs the scene's data)")
    p.add_argument("--lambda-min", type=float, default=None, help="smallest film ratio lambda (assessment)")
    p.add_argument("--degree", type=int, default=9, help="Bezier degree when control points vary (default 9)")
    p.add_argument("--zero-derivatives", type=int, default=2,
                   help="derivatives that vanish at each end of the Bezier rise (default 2: v, a)")
    p.add_argument("--starts", type=int, default=3, help="SLSQP starts (default 3)")
    p.add_argument("--no-fe", action="store_true", help="skip the FE check of the optimum")
    p.set_defaults(func=_run)


def _run(args) -> int:
    out_dir(args.out, create=False)  # checked before any work, created below
    scene = load_scene(args.scene)
    bez = BezierRise(degree=args.degree, zero_derivatives=args.zero_derivatives)
    variables = [v for spec in args.vary for v in parse_vary(spec, bez.free)]
    cons = {"phi_max": math.radians(args.phi_max_deg), "rho_min": args.rho_min_mm * 1e-3}
    for key in ("safety_min", "lambda_min"):
        if getattr(args, key) is not None:
            cons[key] = getattr(args, key)
    if args.liftoff_rpm is not None:
        cons["liftoff_omega"] = args.liftoff_rpm * math.pi / 30.0
    res = optimise(scene, objective=args.objective, variables=variables, constraints=cons, starts=args.starts,
                   bezier=bez, verify_fe=not args.no_fe)
    table = compare_laws(scene, optimum=res, constraints=cons)
    out = out_dir(args.out)
    prov = provenance(scene_path=args.scene, command=shlex.join(["femcam", "optimise", *sys.argv[2:]]))
    files = write_outputs(out, res, table, prov)
    print(f"{res.objective}: {res.value:.6g} {res.unit} (start {res.start_value:.6g}); "
          f"converged {res.converged}")
    print(res.message)
    for n, v in res.design().items():
        print(f"  {n} = {v:.6g}")
    if res.fe is not None:
        print(res.fe.message)
    print("wrote " + ", ".join(str(f) for f in files))
    return 0
