"""``femcam synth``: knife-edge cam curve by potential-energy FE (seed 003).

``femcam synth [SCENE.toml | --case seed003] --out DIR [--elements N] [--k K] [--mu MU]
[--base-radius-mm auto|RB_MM] [--max-iter N] [--study]`` writes ``DIR/synth_curve.csv``
(theta_deg, r_mm, x_mm, y_mm, error_mm, phi_deg, phi_exact_deg; provenance in
``DIR/synth_curve.csv-metadata.json``),
``DIR/synth_curve.png``, ``DIR/synth_error_phi.png`` and, with ``--study``,
``DIR/synth_study_k.{md,csv,png}`` and ``DIR/synth_study_k_mu.{md,csv,png}``.

``--base-radius-mm auto`` takes the smallest base circle whose exact maximum pressure angle
is 30 deg (:func:`femcam.profile.min_base_radius`); the default is the case's 5 mm (seed
003) or the scene's ``Rb``. A failed Newton solve exits with code 1 and one message that
ends with the last residuals of the history.
"""

from __future__ import annotations

import math
import shlex
import sys

import numpy as np

from .. import io
from .._progress import phase
from ..errors import ConvergenceError, InputError
from ..kinematics import LAW_NAMES
from ..profile import min_base_radius
from ..scene import load_scene
from ..synthesis import SynthesisOptions, compare_direct, synthesize_knife_edge
from ..synthesis.options import MAX_ELEMENTS
from ..synthesis.study import (
    SEED003_RB,
    format_table,
    seed003_program,
    study_columns,
    study_k,
    study_k_over_mu,
)
from ..viz import synthesis as vz
from ._common import add_overwrite, out_dir, plain, refuse_non_empty
from ._flags import Range, add_number

#: design limit used by ``--base-radius-mm auto`` (seed 003 section 5: phi <= 30 deg)
AUTO_PHI_MAX_DEG = 30.0
#: residuals shown when Newton fails
N_RESIDUALS_SHOWN = 5


#: ranges of the numeric flags (femcam.cli._flags); the element cap is the library's
ELEMENTS = Range("elements around the cam", 3, MAX_ELEMENTS, whole=True,
                 why="femcam.synthesis.options.MAX_ELEMENTS: time and memory")
_WHY = "the studies span 1e2-1e10; beyond 1e14 the tangent is singular in double precision"
PENALTY = Range("(penalty constant, dimensionless)", 0.0, 1e14, lo_open=True, why=_WHY)
STABILISATION = Range("(stabilisation parameter, dimensionless)", 0.0, 1e14, lo_open=True, why=_WHY)
BASE_RADIUS = Range("mm", 0.0, 1000.0, lo_open=True, words=("auto",),
                    why="a base circle of more than 1 m is not a cam")
MAX_ITER = Range("iterations", 1, 10_000, whole=True)


def register(subparsers) -> None:
    """Add the ``synth`` sub-parser (seed-003 knife-edge synthesis) and set its ``func``.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        Where ``femcam``'s parser (:func:`femcam.cli.build_parser`) collects its subcommands.
    """
    p = subparsers.add_parser("synth", help="knife-edge cam curve by potential-energy FE (seed 003)",
                              description=plain(__doc__))
    p.add_argument("scene", nargs="?", metavar="SCENE.toml",
                   help="scene with a knife_edge follower; its rise/fall laws are any of: "
                        + ", ".join(LAW_NAMES) + " (or control_points)")
    p.add_argument("--case", choices=["seed003"],
                   help="built-in case instead of a scene: seed 003's in-line knife edge, "
                        "poly345 rise 120 deg to 3 mm, dwell 90, fall 90, dwell 60, Rb = 5 mm")
    p.add_argument("--out", required=True, metavar="DIR", help="output directory")
    add_number(p, "--elements", ELEMENTS, default=180, metavar="N",
               help="quadratic elements around the cam (default 180)")
    add_number(p, "--k", PENALTY, default=1e6, metavar="K",
               help="penalty constant k (dimensionless; default 1e6)")
    add_number(p, "--mu", STABILISATION, default=1.0, metavar="MU",
               help="stabilisation parameter mu (dimensionless; default 1)")
    add_number(p, "--base-radius-mm", BASE_RADIUS, default=None, metavar="auto|RB_MM",
               help="base circle radius in mm, or 'auto': the smallest one with max "
                    "pressure angle <= 30 deg (femcam.profile.min_base_radius); default: "
                    "the case's 5 mm or the scene's Rb")
    add_number(p, "--max-iter", MAX_ITER, default=50, metavar="N",
               help="Newton iterations per k stage before giving up (default 50)")
    p.add_argument("--study", action="store_true",
                   help="also run the k and k/mu studies (tables .md/.csv and plots; off by default)")
    add_overwrite(p)
    p.set_defaults(func=run)


def _case(args):
    if (args.scene is None) == (args.case is None):
        raise InputError("synth: give exactly one of SCENE.toml or --case seed003")
    if args.case:
        return "seed003", seed003_program(), SEED003_RB
    sc = load_scene(args.scene)
    if not sc.follower.needs_tip or sc.follower.e != 0.0:
        raise InputError(f"scene {args.scene}: [follower] type = "
                         f"{sc.follower.kind!r}: synth needs an in-line "
                         "knife_edge follower (offset_mm = 0)")
    return sc.name, sc.program, sc.follower.Rb


def _base_radius(value, Rb_default, program, default_source):
    """``(Rb in m, description)`` from the ``--base-radius-mm`` string (None: the default)."""
    if value is None:
        return Rb_default, default_source
    if str(value).strip().lower() == "auto":
        br = min_base_radius("knife_edge", program, phi_max=math.radians(AUTO_PHI_MAX_DEG))
        return br.Rb, (f"auto: min_base_radius, exact max phi = {AUTO_PHI_MAX_DEG:g} deg at "
                       f"theta = {math.degrees(br.theta_critical):.2f} deg")
    return BASE_RADIUS.parse("--base-radius-mm", value) * 1e-3, "given"


def _residual_tail(history, n=N_RESIDUALS_SHOWN) -> str:
    h = list(history)
    if not h:
        return "no residual history"
    tail = ", ".join(f"{v:.1e}" for v in h[-n:])
    return f"residuals (last {min(n, len(h))} of {len(h)}): {tail}"


def run(args) -> int:
    """``femcam synth``: synthesise, compare with the direct profile, write CSV/PNG.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed flags (``scene`` or ``case``, ``out``, ``elements``, ``k``, ``mu``,
        ``base_radius_mm`` in mm, ``max_iter``, ...).

    Returns
    -------
    int
        Exit code 0 (errors are raised as :class:`~femcam.errors.FemcamError`).
    """
    out_dir(args.out, create=False)  # checked before any work, created below
    refuse_non_empty(args.out, args.overwrite)  # the rule of every subcommand
    ELEMENTS.parse("--elements", args.elements)   # the flags' ranges (also for main(...) values)
    PENALTY.parse("--k", args.k)
    STABILISATION.parse("--mu", args.mu)
    name, program, Rb = _case(args)
    Rb, rb_source = _base_radius(args.base_radius_mm, Rb, program,
                                 "seed 003 case" if args.case else "scene")
    MAX_ITER.parse("--max-iter", args.max_iter)
    opt = SynthesisOptions(n_elements=args.elements, k=args.k, mu=args.mu, max_iter=args.max_iter)
    try:
        with phase("synth: potential-energy FE"):
            res = synthesize_knife_edge(program, Rb=Rb, options=opt)
    except ConvergenceError as exc:   # one message, ending with the last residuals
        raise ConvergenceError(f"{exc} (Rb = {Rb * 1e3:.6g} mm); {_residual_tail(exc.history)}",
                               exc.history) from None
    cmp_ = compare_direct(res, program)
    out = out_dir(args.out)
    prov = io.provenance(scene_path=args.scene, command="femcam " + shlex.join(sys.argv[1:]),
                         options={"n_elements": opt.n_elements, "k": opt.k, "mu": opt.mu,
                                  "max_iter": opt.max_iter, "Rb_mm": Rb * 1e3,
                                  "Rb_source": rb_source})
    io.write_table(out / "synth_curve.csv",
                   {"theta_deg": np.degrees(res.theta), "r_mm": res.r * 1e3, "x_mm": res.x * 1e3,
                    "y_mm": res.y * 1e3, "error_mm": res.error * 1e3,
                    "phi_deg": np.degrees(res.phi), "phi_exact_deg": np.degrees(res.phi_exact)},
                   dict(prov, case=name),
                   title="femcam synth (seed 003 potential-energy FE): the synthesised cam curve")
    vz.plot_curve(res, out / "synth_curve.png", direct_r=res.Rb + (res.r - res.Rb - res.error))
    vz.plot_error_phi(res, out / "synth_error_phi.png")
    print(f"femcam synth: {name}, Rb = {Rb * 1e3:.6g} mm ({rb_source}), {opt.n_elements} "
          f"elements, k = {opt.k:g}, mu = {opt.mu:g}")
    print(f"  {res.message}; residuals: " + " ".join(f"{h:.1e}" for h in res.residual_history))
    print(f"  max transfer-function error {res.max_error * 1e3:.4e} mm; max phi FE "
          f"{math.degrees(res.phi_max):.4f} deg, exact {math.degrees(cmp_.phi_max_direct):.4f} deg")
    print(f"  vs direct profile: max |dr| {cmp_.max_radius_deviation * 1e3:.3e} mm; time FE "
          f"{cmp_.time_fe:.3f} s, direct {cmp_.time_direct:.4f} s; cond. est. "
          f"{res.condition_estimate:.2e}")
    if args.study:
        rows = study_k(program, Rb=Rb, ks=[10.0**p for p in range(2, 11)], mu=1.0, options=opt)
        rows2 = study_k_over_mu(program, Rb=Rb, ratios=[10.0**p for p in range(1, 9)], k=1e6,
                                options=opt)
        io.atomic_write_text(out / "synth_study_k.md", format_table(rows) + "\n")
        io.atomic_write_text(out / "synth_study_k_mu.md", format_table(rows2) + "\n")
        title = f"femcam synth study (seed 003), case {name}, Rb = {Rb * 1e3:.6g} mm"
        io.write_table(out / "synth_study_k.csv", study_columns(rows), dict(prov, case=name),
                       title=title + ", mu = 1, k varied")
        io.write_table(out / "synth_study_k_mu.csv", study_columns(rows2), dict(prov, case=name),
                       title=title + ", k = 1e6, mu = k/(k/mu)")
        vz.plot_study(rows, out / "synth_study_k.png", x="k")
        vz.plot_study(rows2, out / "synth_study_k_mu.png", x="k/mu")
        print(format_table(rows))
        print(format_table(rows2))
    print(f"  wrote {out}/synth_curve.csv and PNGs" + (" and study tables (.md, .csv)"
                                                       if args.study else ""))
    return 0
