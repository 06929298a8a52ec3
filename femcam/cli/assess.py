"""``femcam assess SCENE.toml --out DIR``: will it fail? Film, flash temperature, yield,
shakedown, contact fatigue, scuffing and the lubrication regime at every cam angle.

Writes ``DIR/assessment.csv`` (units in the column names; provenance in the sidecar
``DIR/assessment.csv-metadata.json``), ``DIR/summary.json``
(worst angle per criterion, skipped criteria, flags), ``DIR/report.md`` (one page with the plots)
and ``DIR/plots/assess_*.png``. ``--sweep SWEEP_DIR`` takes the angles, the FE ``a``/``p0``, the FE
``tau1_max`` and the FE range of ``txz`` over one pass (``txz_range_max``) of a finished sweep
(``SWEEP_DIR/sweep.npz``) instead of Hertz; a sweep written without ``txz_range_max`` keeps
Hertz's range at the FE ``p0`` and says so.
"""

from __future__ import annotations

import json
import math
import shlex
import sys

from .. import _validate
from ..assess import assess, csv_columns, sweep_table
from ..io import atomic_write_text, provenance, write_table
from ..layers.from_scene import scene_coatings
from ..scene import load_scene
from ..scene.case import contact_case
from ..scene.digest import scene_digest
from ..viz.assess import plot_assessment, report_markdown
from ..viz.html import markdown_page
from ._common import add_no_plots, add_overwrite, add_scene_out, out_dir, plain, refuse_non_empty
from ._flags import RANGE_RULE


def register(subparsers) -> None:
    """Add the ``assess`` sub-parser (film, flash temperature, fatigue, safety factors) and set its ``func``.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        Where ``femcam``'s parser (:func:`femcam.cli.build_parser`) collects its subcommands.
    """
    p = subparsers.add_parser("assess", help="will it fail? film, flash temperature, fatigue, safety factors",
                              description=plain(__doc__))
    add_scene_out(p, "scene file (with [lubricant], [surface], ...)")
    p.add_argument("--angles-deg", default="0:360:1", metavar="START:STOP:STEP",
                   help=f"cam angles in degrees, {RANGE_RULE}: 0:360:1 is 0 to 359, 0:90:30 is 0 to 90 "
                        "(default 0:360:1)")
    p.add_argument("--sweep", default=None, metavar="SWEEP_DIR",
                   help="use the angles and FE a/p0 of a finished sweep (SWEEP_DIR/sweep.npz)")
    add_no_plots(p)
    add_overwrite(p)
    p.set_defaults(func=_run)


#: what the printed worst value of each criterion is (femcam.assess.WORST: its column and unit)
_MEANING = {"film (lambda)": "(film parameter h_min/sigma: < 1 boundary, 1-3 mixed, > 3 full film)",
            "contact temperature": "degC", "scuffing": "(safety factor)", "first yield": "(safety factor)",
            "shakedown": "(safety factor)", "subsurface fatigue": "(safety factor)",
            "surface fatigue": "(safety factor)", "pitting life": "cycles"}


def _sweep_table(path, digest):
    """The sweep's columns the assessment uses (the subsurface ``txz_range_max``, never a
    surface value); a sweep of another scene (``digest``: the scene's
    :func:`~femcam.scene.digest.scene_digest`), a corrupted folder or a ``sweep.npz`` that is not
    a regular file is refused by the library (:func:`femcam.assess.sweep_table`)."""
    z = sweep_table(path, digest)
    return {k: z[k] for k in ("theta", "a_fe", "p0_fe", "tau1_max", "txz_range_max") if k in z}


def _run(args) -> int:
    out_dir(args.out, create=False)  # checked before any work, created below
    scene = load_scene(args.scene)
    table = _sweep_table(args.sweep, scene_digest(scene)) if args.sweep else None
    theta = table["theta"] if table is not None else _validate.angles_deg("--angles-deg", args.angles_deg)
    _validate.angle_count("--sweep" if table is not None else "--angles-deg",
                          args.sweep if table is not None else args.angles_deg, theta.size, 3600.0,
                          "femcam assess", _validate.MAX_ASSESS_ANGLES)
    if table is None and (hint := _validate.radians_hint("--angles-deg", args.angles_deg)):
        print(f"femcam assess: note: {hint}", file=sys.stderr)
    refuse_non_empty(args.out, args.overwrite)  # the rule of every subcommand, before the work
    res = assess(contact_case(scene, theta), table=table, coatings=scene_coatings(scene.layers))
    out = out_dir(args.out)
    prov = provenance(scene_path=args.scene, command=shlex.join(["femcam", "assess", *sys.argv[2:]]))
    write_table(out / "assessment.csv", csv_columns(res.rows), prov,
                title="femcam assess: one row per cam angle")
    summary = {"scene": scene.name, "n_angles": int(len(theta)),
               "worst": {c: {"value": v, "theta_deg": math.degrees(t)} for c, (v, t, _) in res.worst.items()},
               "skipped": list(res.notes), "omitted": list(res.omitted), "provenance": prov}
    atomic_write_text(out / "summary.json", json.dumps(summary, indent=1, default=str))
    plots = {}
    if not args.no_plots:

        plots = plot_assessment(res, out / "plots")

    md = report_markdown(res, plots, provenance=f"Scene `{args.scene}`, {len(theta)} cam angles; "
                         f"{prov['date']}.", base=out)
    atomic_write_text(out / "report.md", md)
    atomic_write_text(out / "report.html", markdown_page(md, out))   # plots embedded: one file to send
    for crit, (v, t, _) in res.worst.items():
        print(f"{crit:>22s}: worst {v:.4g} {_MEANING.get(crit, '')} at {math.degrees(t):6.1f} deg")
    for n in res.notes:
        print(f"note: {n}")
    for o in res.omitted:
        print(f"note: {o}")
    print(f"wrote {out / 'assessment.csv'}, {out / 'summary.json'}, {out / 'report.md'}, "
          f"{out / 'report.html'}")
    return 0
