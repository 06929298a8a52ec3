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
from .._progress import phase
from ..study import OBJECTIVES, Constraints, EvalOptions, FEOptions, StudySpec, run_study
from ..study.spec import MAX_VARIANTS
from ._common import add_overwrite, add_scene_out, out_dir, plain, refuse_non_empty
from ._flags import Range, add_number

#: --objective name -> SI column
_OBJECTIVE = {"p0": "p0_max", "von_mises": "von_mises_max", "tau1": "tau1_max", "size": "cam_radius_max"}
assert set(_OBJECTIVE.values()) == set(OBJECTIVES)
#: the end of the jump-speed search (x operating speed): --jump-factor cannot exceed it
_JUMP_HI = EvalOptions().jump_factor_hi


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
    add_number(p, "--lhs", Range("samples", 1, MAX_VARIANTS, whole=True,
                                 why="one table row per sample, held in memory; a typo is refused"),
               default=None, metavar="N", help="Latin hypercube of N samples")
    add_number(p, "--seed", Range("", 0, 2**53, whole=True, why="a numpy seed, exact as a float"),
               default=0, help="Latin-hypercube seed (default 0)")
    p.add_argument("--scheduler", default="local", metavar="local|processes|ADDRESS",
                   help="this process (default), --workers local processes, or a Dask scheduler")
    add_number(p, "--workers", Range("processes", 1, 1024, whole=True, words=("auto",)), default=2,
               metavar="N|auto", help="processes for --scheduler processes (default 2; auto = CPU cores)")
    add_number(p, "--phi-max-deg", Range("deg", 0.0, 90.0, lo_open=True, hi_open=True,
                                         why="no cam meets 0 deg; 90 deg jams the follower"),
               default=30.0, help="pressure-angle limit (default 30)")
    add_number(p, "--rho-min-mm", Range("mm", 0.0, 1000.0, why="the scene's radius range"), default=0.0,
               help="smallest convex cam radius of curvature (default 0: undercut only)")
    p.add_argument("--allow-liftoff", action="store_true", help="do not constrain the contact force")
    add_number(p, "--sf-min", Range("", 0.0, 100.0, lo_open=True, why="a safety factor > 0"), default=1.0,
               help="smallest assessment safety factor (default 1)")
    add_number(p, "--lambda-min", Range("", 0.0, 100.0, lo_open=True, why="a film ratio > 0"), default=None,
               help="smallest film parameter lambda")
    add_number(p, "--p0-max-MPa", Range("MPa", 0.0, 1e5, lo_open=True,
                                        why="100 GPa is far above the hardness of any cam material"),
               default=None, help="largest Hertz peak pressure")
    add_number(p, "--jump-factor", Range("x operating speed", 0.0, _JUMP_HI, lo_open=True,
                                         why=f"the jump-speed search ends at {_JUMP_HI:g} x the operating "
                                             "speed, so a larger factor can never be met"),
               default=1.0, help="jump speed must exceed this multiple of the operating speed (default 1)")
    add_number(p, "--angles-per-rev", Range("angles", 36, 100_000, whole=True,
                                            why="36 resolves the program's segments; above 1e5 a variant's "
                                                "arrays and time grow without changing its worst values"),
               default=720, help="cam angles per revolution (default 720)")
    p.add_argument("--wear", action="store_true",
                   help="also the Archard cam wear depth per revolution (costly: off by default)")
    p.add_argument("--objective", choices=tuple(_OBJECTIVE), default="p0", help="ranks the FE candidates")
    add_number(p, "--fe-top", Range("variants", 0, MAX_VARIANTS, whole=True,
                                    why="0: no FE; at most the study's variants"),
               default=0, metavar="K", help="FE sweep of the K best feasible")
    p.add_argument("--fe-select", choices=("objective", "pareto"), default="objective",
                   help="FE candidates: the best feasible by --objective (default) or the Pareto set")
    p.add_argument("--fe-angles-deg", default="-2,-1,0,1,2", metavar="D1,D2,...",
                   help="FE angles around each candidate's Hertz worst angle (deg)")
    p.add_argument("--resume", action="store_true", help="continue the study in --out")
    add_overwrite(p)
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
    workers = _validate.workers("--workers", args.workers)  # the ranges were checked while parsing
    workers = (os.cpu_count() or 1) if workers == "auto" else workers
    cons = Constraints(phi_limit=math.radians(args.phi_max_deg), rho_limit=args.rho_min_mm * 1e-3,
                       liftoff=not args.allow_liftoff, sf_limit=args.sf_min, lambda_limit=args.lambda_min,
                       p0_limit=None if args.p0_max_MPa is None else args.p0_max_MPa * 1e6,
                       jump_factor=args.jump_factor)
    out = out_dir(args.out, create=False)  # checked now, created once the keys and values pass
    refuse_non_empty(out, args.overwrite, resume=args.resume, what="study")  # every subcommand's rule
    fe = FEOptions(top=args.fe_top, select=args.fe_select, offsets=_offsets(args.fe_angles_deg))
    opts = EvalOptions(n_angles=args.angles_per_rev, wear=args.wear)
    with phase("study: variants"):
        res = run_study(args.scene, spec, constraints=cons, options=opts, fe=fe,
                        objective=_OBJECTIVE[args.objective], out=out, resume=args.resume,
                        overwrite=args.overwrite, scheduler=args.scheduler, workers=workers,
                        plots=not args.no_plots, command=_command_line(args))
    print(res.summary())
    for kind, path in res.paths.items():
        print(f"{kind}: {path}")
    return 0
