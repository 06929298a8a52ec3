"""``femcam sweep SCENE.toml --out DIR``: the FE (or Hertz) sweep over cam angle.

Writes ``DIR/sweep.csv`` (units in the column names, provenance header), ``DIR/sweep.npz``
(SI), ``DIR/chunks/`` (the resumable store), ``DIR/sweep.pvd`` + ``DIR/vtk/*.vtu``
(every 10th angle by default; ``--vtk-every K``) and PNG plots in ``DIR/plots/`` (unless ``--no-plots``).
"""

from __future__ import annotations

import shlex
import sys


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "sweep", help="FE contact sweep over cam angle (CSV/NPZ, VTK series, plots)",
        description=__doc__.split("\n\n")[0])
    p.add_argument("scene", metavar="SCENE.toml", help="scene file")
    p.add_argument("--out", required=True, metavar="DIR", help="output directory")
    p.add_argument("--angles-deg", default="0:360:1", metavar="START:STOP:STEP",
                   help="cam angles in degrees, stop exclusive (default 0:360:1)")
    p.add_argument("--workers", type=int, default=1, metavar="N",
                   help="local worker processes (default 1 = serial)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="Dask scheduler address, e.g. tcp://host:8786 (needs femcam[dask])")
    p.add_argument("--resume", action="store_true",
                   help="continue an interrupted sweep in DIR (computes only missing chunks)")
    p.add_argument("--mesh-size", type=float, default=10.0, metavar="A_OVER_H",
                   help="FE element size in the contact zone, h = a / A_OVER_H (default 10)")
    p.add_argument("--tolerance", type=float, default=2e-3, metavar="TOL",
                   help="relative p0 error allowed from reusing a model across angles (default 2e-3)")
    p.add_argument("--chunk-size", type=int, default=30, metavar="N",
                   help="angles per chunk on disk / per parallel task (default 30)")
    p.add_argument("--vtk-every", type=int, default=10, metavar="K",
                   help="write a .vtu (both bodies, ~1 MB) every K angles plus sweep.pvd "
                        "(default 10; 1 = every angle; 0 = none)")
    p.add_argument("--method", choices=("fe", "hertz"), default="fe",
                   help="fe: FE contact solve (default); hertz: analytic only")
    p.add_argument("--law", default=None, metavar="NAME",
                   help="override the rise/fall motion law of the scene (e.g. bezier7)")
    p.add_argument("--no-plots", action="store_true", help="skip the PNG plots")
    p.add_argument("--progress", choices=("auto", "on", "off"), default="auto",
                   help="progress bar on stderr (auto: only on a terminal)")
    p.set_defaults(func=_run)


def _command_line(args) -> str:
    """The command, rebuilt from the parsed arguments (also right for ``main([...])`` calls)."""
    parts = ["femcam", "sweep", args.scene, "--out", args.out, "--angles-deg", args.angles_deg,
             "--workers", str(args.workers), "--mesh-size", f"{args.mesh_size:g}",
             "--tolerance", f"{args.tolerance:g}", "--chunk-size", str(args.chunk_size),
             "--vtk-every", str(args.vtk_every), "--method", args.method]
    if args.scheduler:
        parts += ["--scheduler", args.scheduler]
    if args.law:
        parts += ["--law", args.law]
    if args.resume:
        parts.append("--resume")
    if args.no_plots:
        parts.append("--no-plots")
    return shlex.join(parts)


def _run(args) -> int:
    from ..scene import load_scene
    from ..sweep import parse_angles_deg, sweep

    angles = parse_angles_deg(args.angles_deg)
    scene = load_scene(args.scene)
    if args.law:
        scene = scene.with_law(args.law)
    progress = {"auto": None, "on": True, "off": False}[args.progress]
    res = sweep(scene, angles=angles, method=args.method, a_over_h=args.mesh_size,
                tolerance=args.tolerance, chunk_size=args.chunk_size, out=args.out,
                resume=args.resume, workers=args.workers, scheduler=args.scheduler,
                vtk_every=args.vtk_every, progress=progress, plots=not args.no_plots,
                command=_command_line(args),
                scene_path=args.scene)
    s = res.summary()
    print(f"femcam sweep: {res.n_angles} angles ({res.n_chunks_resumed} chunks resumed, "
          f"{res.n_chunks_computed} computed) in {res.timings['total']:.2f} s; "
          f"liftoff {s['n_liftoff']}, failed {s['n_failed']}")
    print(f"  peak Fc {s['Fc_max']:.1f} N, p0 Hertz {s['p0_hertz_max'] / 1e6:.1f} MPa"
          + (f", p0 FE {s['p0_fe_max'] / 1e6:.1f} MPa (max |err| {100 * s['err_p0_absmax']:.3f} %)"
             if res.method == "fe" else "")
          + f", von Mises {s['vm_max'] / 1e6:.1f} MPa, tau1 {s['tau1_max'] / 1e6:.1f} MPa")
    for k, v in res.paths.items():
        print(f"  {k}: {v}")
    if s["n_failed"]:
        print(f"femcam sweep: warning: {s['n_failed']} angle(s) failed; see the status and "
              "message columns", file=sys.stderr)
    return 0
