"""``femcam study SCENE.toml --vary KEY=VALUES ... --out DIR``: a design study over scene keys.

Each variant (a grid over the --vary values, or --lhs N Latin-hypercube samples over LO:HI
ranges) is the scene with those keys set, checked by the scene loader, evaluated by the
Hertz chain over a full revolution (worst p0, von Mises, tau1, max |phi|, min rho, undercut,
lift-off, assessment safety factors and lambda, jump speed) and given one margin per
constraint; --fe-top K adds an FE sweep around the worst angle of the K best feasible variants.

Writes DIR/study.csv (one row per variant, units in the column names; provenance in
DIR/study.csv-metadata.json),
DIR/study.npz (SI), DIR/variants/ (one record per content hash: --resume continues a killed
study and a duplicate variant is computed once) and DIR/pareto.png, DIR/constraint_map.png.
Keys: dotted scene keys with their unit (follower.base_radius_mm, program.segment.0.beta_deg,
program.law, operating.rpm, dynamics.preload_N, ...). Values: START:STOP:STEP (stop included),
a,b,c, LO:HI (with --lhs), or ';'-separated JSON lists (control points).
"""

from __future__ import annotations

import argparse
import math
import os
import shlex

from .. import _validate
from ..study import OBJECTIVES, Constraints, EvalOptions, FEOptions, StudySpec, run_study
from ._common import add_scene_out, out_dir, plain

#: --objective name -> SI column
_OBJECTIVE = {"p0": "p0_max", "von_mises": "von_mises_max", "tau1": "tau1_max", "size": "cam_radius_max"}
assert set(_OBJECTIVE.values()) == set(OBJECTIVES)


def register(subparsers) -> None:
    """Add the ``study`` sub-parser (design studies over scene keys) and set its ``func``.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        Where ``femcam``'s parser collects its subcommands.
    """
    p = subparsers.add_parser("study", help="design study over scene keys (grid or Latin hypercube)",
                              description=plain(__doc__, 4),
                              formatter_class=argparse.RawDescriptionHelpFormatter)
    add_scene_out(p)
    p.add_argument("--vary", action="append", required=True, metavar="KEY=VALUES",
                   help="a varied scene key and its values (repeat for more keys)")
    p.add_argument("--lhs", type=int, default=None, metavar="N", help="Latin hypercube of N samples")
    p.add_argument("--seed", type=int, default=0, help="Latin-hypercube seed (default 0)")
    p.add_argument("--scheduler", default="local", metavar="local|processes|ADDRESS",
                   help="this process (default), --workers local processes, or a Dask scheduler")
    p.add_argument("--workers", default="2", metavar="N", help="processes for --scheduler processes")
    p.add_argument("--phi-max-deg", type=float, default=30.0, help="pressure-angle limit (deg, default 30)")
    p.add_argument("--rho-min-mm", type=float, default=0.0,
                   help="smallest convex cam radius of curvature (mm; default 0: undercut only)")
    p.add_argument("--allow-liftoff", action="store_true", help="do not constrain the contact force")
    p.add_argument("--sf-min", type=float, default=1.0, help="smallest assessment safety factor (default 1)")
    p.add_argument("--lambda-min", type=float, default=None, help="smallest film parameter lambda")
    p.add_argument("--p0-max-MPa", type=float, default=None, help="largest Hertz peak pressure (MPa)")
    p.add_argument("--jump-factor", type=float, default=1.0,
                   help="jump speed must exceed this multiple of the operating speed (default 1)")
    p.add_argument("--angles-per-rev", type=int, default=720, help="cam angles per revolution (default 720)")
    p.add_argument("--wear", action="store_true",
                   help="also the Archard cam wear depth per revolution (about 0.15 s per variant)")
    p.add_argument("--objective", choices=tuple(_OBJECTIVE), default="p0", help="ranks the FE candidates")
    p.add_argument("--fe-top", type=int, default=0, metavar="K", help="FE sweep of the K best feasible")
    p.add_argument("--fe-select", choices=("objective", "pareto"), default="objective",
                   help="FE candidates: the best feasible by --objective (default) or the Pareto set")
    p.add_argument("--fe-angles-deg", default="-2,-1,0,1,2", metavar="D1,D2,...",
                   help="FE angles around each candidate's Hertz worst angle (deg)")
    p.add_argument("--resume", action="store_true", help="continue the study in --out")
    p.add_argument("--overwrite", action="store_true", help="discard an earlier study in --out")
    p.add_argument("--no-plots", action="store_true", help="skip the PNG plots")
    p.set_defaults(func=_run)


def _offsets(text: str) -> tuple:
    try:
        vals = tuple(float(t) for t in text.split(",") if t.strip())
    except ValueError:
        raise _validate.fail("--fe-angles-deg", text, "deg", "must be comma-separated numbers") from None
    if not vals:
        raise _validate.fail("--fe-angles-deg", text, "deg", "give at least one angle")
    return tuple(math.radians(v) for v in vals)


def _command_line(args) -> str:
    """The command, rebuilt from the parsed arguments (also right for ``main([...])`` calls)."""
    parts = ["femcam", "study", args.scene, "--out", args.out]
    for v in args.vary:
        parts += ["--vary", v]
    for flag in ("lhs", "seed", "scheduler", "workers", "phi_max_deg", "rho_min_mm", "sf_min", "lambda_min",
                 "p0_max_MPa", "jump_factor", "angles_per_rev", "objective", "fe_top", "fe_select",
                 "fe_angles_deg"):
        if getattr(args, flag) is not None:
            parts += ["--" + flag.replace("_", "-"), str(getattr(args, flag))]
    parts += [f for f, on in (("--allow-liftoff", args.allow_liftoff), ("--wear", args.wear),
                              ("--resume", args.resume), ("--overwrite", args.overwrite),
                              ("--no-plots", args.no_plots)) if on]
    return shlex.join(parts)


def _run(args) -> int:
    spec = StudySpec.parse(args.vary, lhs=args.lhs, seed=args.seed)
    workers = _validate.workers("--workers", args.workers)
    workers = os.cpu_count() or 1 if workers == "auto" else workers
    _validate.positive("--phi-max-deg", args.phi_max_deg, "deg")
    for flag, unit in (("sf_min", ""), ("jump_factor", "x operating speed"), ("lambda_min", ""),
                       ("p0_max_MPa", "MPa")):
        if getattr(args, flag) is not None:
            _validate.positive("--" + flag.replace("_", "-"), getattr(args, flag), unit)
    _validate.nonnegative("--rho-min-mm", args.rho_min_mm, "mm")
    _validate.integer("--angles-per-rev", args.angles_per_rev, 36, "angles")
    _validate.integer("--fe-top", args.fe_top, 0, "variants")
    if args.phi_max_deg >= 90.0:
        raise _validate.fail("--phi-max-deg", args.phi_max_deg, "deg", "must be < 90")
    cons = Constraints(phi_limit=math.radians(args.phi_max_deg), rho_limit=args.rho_min_mm * 1e-3,
                       liftoff=not args.allow_liftoff, sf_limit=args.sf_min, lambda_limit=args.lambda_min,
                       p0_limit=None if args.p0_max_MPa is None else args.p0_max_MPa * 1e6,
                       jump_factor=args.jump_factor)
    out = out_dir(args.out, create=False)  # checked now, created once the keys and values pass
    fe = FEOptions(top=args.fe_top, select=args.fe_select, offsets=_offsets(args.fe_angles_deg))
    opts = EvalOptions(n_angles=args.angles_per_rev, wear=args.wear)
    res = run_study(args.scene, spec, constraints=cons, options=opts, fe=fe,
                    objective=_OBJECTIVE[args.objective], out=out, resume=args.resume,
                    overwrite=args.overwrite, scheduler=args.scheduler, workers=workers,
                    plots=not args.no_plots, command=_command_line(args))
    print(res.summary())
    for kind, path in res.paths.items():
        print(f"{kind}: {path}")
    return 0
