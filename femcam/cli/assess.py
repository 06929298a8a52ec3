"""``femcam assess SCENE.toml --out DIR``: will it fail? Film, flash temperature, yield,
shakedown, contact fatigue, scuffing and the lubrication regime at every cam angle.

Writes ``DIR/assessment.csv`` (units in the column names, provenance header), ``DIR/summary.json``
(worst angle per criterion, skipped criteria, flags), ``DIR/report.md`` (one page with the plots)
and ``DIR/plots/assess_*.png``. ``--sweep SWEEP_DIR`` takes the angles and the FE ``a``/``p0`` of a
finished sweep (``SWEEP_DIR/sweep.npz``) instead of Hertz.
"""

from __future__ import annotations

import json
import math
import shlex
import sys
import zipfile
from pathlib import Path

import numpy as np

from .. import _validate
from .._files import check_regular
from ..assess import assess, csv_columns
from ..errors import InputError
from ..io import atomic_write_text, csv_text, provenance
from ..scene import load_scene
from ..viz.assess import plot_assessment, report_markdown
from ._common import add_no_plots, add_overwrite, add_scene_out, out_dir, plain, refuse_non_empty


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
                   help="cam angles in degrees, stop exclusive (default 0:360:1)")
    p.add_argument("--sweep", default=None, metavar="SWEEP_DIR",
                   help="use the angles and FE a/p0 of a finished sweep (SWEEP_DIR/sweep.npz)")
    add_no_plots(p)
    add_overwrite(p)
    p.set_defaults(func=_run)


#: largest sweep.npz read by --sweep (bytes): 360,000 angles of ~150 columns are ~0.4 GB
MAX_SWEEP_BYTES = 2_000_000_000


def _sweep_table(path):
    f = Path(path) / "sweep.npz"
    if not f.exists() and not f.is_symlink():
        raise InputError(f"--sweep = {path}: no sweep.npz there (run femcam sweep SCENE --out {path} first)")
    check_regular(f, f"--sweep = {path}:", MAX_SWEEP_BYTES)   # a FIFO or a device there is not read
    try:
        with np.load(f, allow_pickle=False) as z:
            return {k: np.asarray(z[k]) for k in ("theta", "a_fe", "p0_fe", "tau1_max", "txz_absmax")
                    if k in z.files}
    except (OSError, ValueError, EOFError, zipfile.BadZipFile) as exc:  # truncated or not an npz
        why = (str(exc).splitlines() or [""])[0][:80]
        raise InputError(f"--sweep = {path}: {f} is not a readable sweep result "
                         f"({type(exc).__name__}: {why}); rerun femcam sweep") from None


def _write_csv(path, cols: dict, header: list[str]) -> None:


    names = list(cols)
    lines = [",".join(names)] + ["# " + h for h in header]
    arrs = [np.asarray(cols[n]) for n in names]
    for i in range(len(arrs[0])):
        lines.append(",".join(f"{a[i]:.8g}" if a.dtype.kind == "f" else csv_text(a[i]) for a in arrs))
    atomic_write_text(path, "\n".join(lines) + "\n")


def _run(args) -> int:
    out_dir(args.out, create=False)  # checked before any work, created below
    scene = load_scene(args.scene)
    table = _sweep_table(args.sweep) if args.sweep else None
    theta = table["theta"] if table is not None else _validate.angles_deg("--angles-deg", args.angles_deg)
    refuse_non_empty(args.out, args.overwrite)  # the rule of every subcommand, before the work
    res = assess(scene, theta, table=table)
    out = out_dir(args.out)
    prov = provenance(scene_path=args.scene, command=shlex.join(["femcam", "assess", *sys.argv[2:]]))
    head = ["femcam assess results (units in the column names)", f"scene: {args.scene}",
            f"command: {prov['command']}", f"date: {prov['date']}",
            "versions: " + ", ".join(f"{k} {v}" for k, v in prov["versions"].items())]
    _write_csv(out / "assessment.csv", csv_columns(res.rows), head)
    summary = {"scene": scene.name, "n_angles": int(len(theta)),
               "worst": {c: {"value": v, "theta_deg": math.degrees(t)} for c, (v, t, _) in res.worst.items()},
               "skipped": list(res.notes), "provenance": prov}
    (out / "summary.json").write_text(json.dumps(summary, indent=1, default=str))
    plots = {}
    if not args.no_plots:

        plots = plot_assessment(res, out / "plots")

    (out / "report.md").write_text(report_markdown(res, plots, provenance=f"Scene `{args.scene}`, "
                                                   f"{len(theta)} cam angles; {prov['date']}.", base=out))
    for crit, (v, t, _) in res.worst.items():
        print(f"{crit:>22s}: worst {v:.4g} at {math.degrees(t):6.1f} deg")
    for n in res.notes:
        print(f"note: {n}")
    print(f"wrote {out / 'assessment.csv'}, {out / 'summary.json'}, {out / 'report.md'}")
    return 0
