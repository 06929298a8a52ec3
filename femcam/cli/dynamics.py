"""``femcam dynamics``: periodic response of the follower train, jump speed and rpm sweep.

``femcam dynamics SCENE.toml --out DIR [--rpm-sweep START:STOP:STEP] [--workers N]`` needs a
scene with ``[dynamics] model = "one_dof"`` or ``"two_dof"``. It writes ``DIR/dynamics.csv``
(theta_deg, s_mm, Fc_rigid_N, Fc_N (axial), liftoff, error_um per mass; provenance in the sidecar
``DIR/dynamics.csv-metadata.json``)
and ``DIR/dynamics_force.png``; with ``--rpm-sweep`` also ``DIR/rpm_sweep.csv``,
``DIR/rpm_sweep.png`` and the jump speed within the range (rpm, stop included when on the grid).
"""

from __future__ import annotations

import math
import shlex
import sys
from pathlib import Path

import numpy as np

from .. import _validate
from .._progress import phase
from ..dynamics import jump_speed, rpm_sweep
from ..dynamics.jump import MAX_SPEEDS, speeds_problem
from ..errors import InputError
from ..io import provenance, write_table
from ..scene import load_scene
from ..viz.dynamics import plot_force, plot_rpm_sweep
from ._common import add_no_plots, add_overwrite, add_scene_out, cap_workers, out_dir, plain, refuse_non_empty
from ._flags import RANGE_RULE, Range, add_number


def register(subparsers) -> None:
    """Add the ``dynamics`` sub-parser (follower-train response, jump speed) and set its ``func``.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        Where ``femcam``'s parser (:func:`femcam.cli.build_parser`) collects its subcommands.
    """
    p = subparsers.add_parser("dynamics", help="follower-train dynamics: contact force, jump speed",
                              description=plain(__doc__))
    add_scene_out(p, "scene with [dynamics] model = one_dof or two_dof")
    p.add_argument("--rpm-sweep", metavar="START:STOP:STEP", default=None,
                   help="also sweep the cam speed (rpm) and find the jump speed; "
                        f"{RANGE_RULE}: 4200:4600:200 is 4200, 4400, 4600 rpm")
    add_number(p, "--workers", Range("processes", 1, 1024, whole=True), default=1, metavar="N",
               help="processes for the rpm sweep (default 1; capped at the CPU cores and "
                    "the number of speeds)")
    add_no_plots(p)
    add_overwrite(p)
    p.set_defaults(func=run)


def _useful_workers(requested: int, n_speeds: int) -> tuple:
    """Cap ``--workers`` at the CPU cores and the number of speeds (more processes only wait),
    as ``femcam sweep`` does (:func:`femcam.cli.sweep.useful_workers`).

    Parameters
    ----------
    requested : int
        ``--workers`` after validation, ``>= 1``.
    n_speeds : int
        Number of speeds of the rpm sweep.

    Returns
    -------
    (int, str)
        ``(workers, note)``; ``note`` says why it was capped ("" when not).
    """
    return cap_workers(requested, n_speeds, f"{n_speeds} speeds")


def _rpm_range(text: str):
    try:
        a, b, c = (float(x) for x in text.split(":"))
    except ValueError:
        raise InputError(f"--rpm-sweep = {text!r}: must be START:STOP:STEP in rpm") from None
    if not all(map(math.isfinite, (a, b, c))) or not (0 < a < b and c > 0):
        raise InputError(f"--rpm-sweep = {text!r} rpm: need finite 0 < START < STOP and STEP > 0")
    n = math.floor((b - a) / c + 1e-9) + 1
    if n > MAX_SPEEDS:  # refused before the speeds are even listed
        raise InputError(f"--rpm-sweep = {text!r} rpm: {speeds_problem(n)}")
    return a + c * np.arange(n)


def _prov(scene, **extra):
    return provenance(scene_path=scene.source_path,
                      command="femcam " + shlex.join(sys.argv[1:]), **extra)


def _write_response(out: Path, scene, r):
    prov = _prov(scene, model=r.model, rpm=float(r.rpm), steps_per_rev=int(r.steps_per_rev),
                 cycles=int(r.cycles), residual=float(r.residual), converged=bool(r.converged),
                 message=r.message)
    return write_table(out / "dynamics.csv", r.csv_columns(), prov,
                       title="femcam dynamics: periodic response, one row per cam angle")


def _write_sweep(out: Path, scene, sw):
    return write_table(out / "rpm_sweep.csv", sw.csv_columns(), _prov(scene),
                       title="femcam dynamics --rpm-sweep: one row per cam speed")


def run(args) -> int:
    """``femcam dynamics``: periodic response, optional rpm sweep; CSV and PNG files.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed flags (``scene``, ``out``, ``rpm_sweep`` in rpm, ``workers``, ``no_plots``).

    Returns
    -------
    int
        Exit code 0 (errors are raised as :class:`~femcam.errors.FemcamError`).
    """
    out_dir(args.out, create=False)  # checked before any work, created below
    rpm = _rpm_range(args.rpm_sweep) if args.rpm_sweep else None  # checked before any work
    scene = load_scene(args.scene)
    if scene.train is None:
        raise InputError(f"{args.scene}: [dynamics] model = 'rigid' (eq. 11) has no train to "
                         "integrate; set model = \"one_dof\" or \"two_dof\" (docs/dynamics.md)")
    workers = int(_validate.positive("--workers", args.workers, ""))
    refuse_non_empty(args.out, args.overwrite)  # the rule of femcam sweep
    out = out_dir(args.out)
    r = scene.dynamic_response
    f_hz = ", ".join(f"{w / (2 * math.pi):.5g}" for w in r.natural_frequencies)
    print(f"{scene.name}: {r.model} at {r.rpm:g} rpm, natural frequencies {f_hz} Hz")
    print(f"  {r.steps_per_rev} steps/rev, cycles {r.cycles}, residual {r.residual:.3g}, "
          f"converged {r.converged}: {r.message}")
    print(f"  axial Fc {r.Fc_min:.6g} .. {r.Fc_max:.6g} N (rigid eq. 11: "
          f"{r.Fc_rigid_axial.min():.6g} .. {r.Fc_rigid_axial.max():.6g} N); max |x - s| "
          f"{r.max_error * 1e6:.4g} um; dwell vibration {r.dwell_vibration * 1e6:.4g} um")
    print(f"  csv: {_write_response(out, scene, r)}")
    if not args.no_plots:

        print(f"  png: {plot_force({scene.train.model: r}, out / 'dynamics_force.png')}")
    if rpm is not None:
        workers, note = _useful_workers(workers, rpm.size)
        if note:
            print(f"  {note}")
        with phase(f"dynamics: rpm sweep over {rpm.size} speeds"):
            sw = rpm_sweep(scene.train, scene.program, rpm, steps_per_rev=scene.steps_per_rev,
                           workers=workers)
        j = jump_speed(scene.train, scene.program, rpm[0], rpm[-1],
                       steps_per_rev=scene.steps_per_rev)
        print(f"  rpm sweep {rpm[0]:g}..{rpm[-1]:g} rpm ({rpm.size} speeds): {j.message}; rigid "
              f"eq. 11 lift-off: {j.rpm_rigid:.6g} rpm" if math.isfinite(j.rpm_rigid) else
              f"  rpm sweep {rpm[0]:g}..{rpm[-1]:g} rpm ({rpm.size} speeds): {j.message}; no rigid "
              "lift-off in the range")
        print(f"  csv: {_write_sweep(out, scene, sw)}")
        if not args.no_plots:
            print(f"  png: {plot_rpm_sweep(sw, out / 'rpm_sweep.png', jump=j)}")
    return 0
