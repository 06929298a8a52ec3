"""Benchmark of the FE sweep (issue 5): reuse vs naive, scaling, reuse error, Bezier 5/7/9.

Run:  python benchmarks/bench_sweep.py [--quick] [--bezier] [--out DIR]

Correctness is checked before anything is timed:

1. **Main case** -- a 360-angle FE sweep of the seed 002 study model, cold (model cache empty,
   meshing + assembly + factorisation + condensation included), serial. FE p0 must be within
   0.3 % of Hertz at every angle.
2. **Naive path** -- a fresh mesh + factorisation at every angle (model built for that angle's
   own rho and Hertz a), on 12 angles (every 30 deg); the time per angle is extrapolated to
   360 angles (stated as such in the table). Ratio = naive time per angle / reuse time per angle.
3. **Reuse error** -- at the same 12 angles, sweep (family model) minus fresh model, for p0, a,
   von Mises max and tau1 max.
4. **Scaling** -- time against the number of angles and against mesh size a/h.
5. ``--bezier``: the study model with bezier5/7/9 (same beta): peaks of Fc, phi, p0, von Mises,
   tau1; writes ``docs/img/sweep_bezier.png``.

Timings are wall-clock on whatever machine runs this (printed in the header); nothing here is
asserted in tests.
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
STUDY = ROOT / "examples" / "seed002_study_model.toml"


def machine() -> str:
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return f"{cpu}, {os.cpu_count()} logical cores, Python {platform.python_version()}"


def cold_sweep(angles_spec="0:360:1", a_over_h=10.0, workers=1, law=None, repeat=1):
    """Sweep in a fresh interpreter (truly cold), ``repeat`` times; the fastest run's timings.

    The minimum over repeats is the usual benchmark statistic on a shared machine (other
    processes only ever add time). Returns ``(info, table)``.
    """
    runs = [_cold_once(angles_spec, a_over_h, workers, law) for _ in range(repeat)]
    info = min((r[0] for r in runs), key=lambda i: i["sweep"])
    return info, runs[0][1]


def _cold_once(angles_spec, a_over_h, workers, law):
    code = f"""
import time, json, sys
t0 = time.perf_counter()
import numpy as np
from femcam.scene import load_scene
from femcam.sweep import sweep, parse_angles_deg
sc = load_scene({str(STUDY)!r})
if {law!r}:
    sc = sc.with_law({law!r})
t1 = time.perf_counter()
r = sweep(sc, angles=parse_angles_deg({angles_spec!r}), a_over_h={a_over_h}, workers={workers})
t2 = time.perf_counter()
np.savez(sys.argv[1], **r.table)
print(json.dumps({{"sweep": t2 - t1, "process": t2 - t0,
                  "families": r.provenance["options"]["n_families"]}}))
"""
    import json
    import tempfile

    with tempfile.TemporaryDirectory() as d:
        out = Path(d) / "t.npz"
        res = subprocess.run([sys.executable, "-c", code, str(out)], capture_output=True,
                             text=True, check=True)
        info = json.loads(res.stdout.strip().splitlines()[-1])
        with np.load(out) as z:
            table = {k: z[k] for k in z.files}
    return info, table


def naive(scene, theta, a_over_h=10.0):
    """Fresh model per angle (exact rho and Hertz a): returns per-angle time and results."""
    from femcam.sweep.pipeline import (
        SweepOptions,
        build_model,
        contact_params,
        hertz_half_width_any,
    )

    cp = contact_params(scene)
    st = scene.analyse(theta)
    opts = SweepOptions(a_over_h=a_over_h)
    rows = []
    t0 = time.perf_counter()
    for F, rho in zip(st.Fc, st.rho, strict=True):
        a = float(hertz_half_width_any(np.array([F]), np.array([rho]), cp)[0])
        m = build_model(cp, float(rho), a, opts)
        r = m.solve(F=float(F), rho=float(rho), mu=cp.mu, sliding=cp.sliding)
        rows.append((r.p0, r.a, r.von_mises_max.value, r.tau1_max.value, r.hertz_p0, r.hertz_a))
    dt = (time.perf_counter() - t0) / len(theta)
    return dt, np.array(rows)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="skip the scaling tables")
    ap.add_argument("--bezier", action="store_true", help="seed 002 Bezier 5/7/9 comparison")
    ap.add_argument("--repeat", type=int, default=3, help="cold runs per case (min reported)")
    ap.add_argument("--img", default=str(ROOT / "docs" / "img"), help="where to put PNGs")
    args = ap.parse_args(argv)

    from femcam.scene import load_scene
    from femcam.sweep import parse_angles_deg

    print(f"machine: {machine()}")
    scene = load_scene(STUDY)

    # 1. main case ---------------------------------------------------------------------------
    info, tab = cold_sweep(repeat=args.repeat)
    err = np.abs(tab["err_p0"])
    ok = tab["status"] == "ok"
    assert ok.all(), "every angle must solve"
    assert np.nanmax(err) <= 3e-3, f"FE p0 off Hertz by {100 * np.nanmax(err):.3f} % > 0.3 %"
    t_angle = info["sweep"] / tab["theta"].size
    print(f"\n## 360-angle sweep of the seed 002 study model (cold, serial, a/h = 10, best of "
          f"{args.repeat})\n")
    print("| quantity | value |\n|---|---|")
    print(f"| sweep() wall time, 360 angles, incl. meshing | {info['sweep']:.2f} s |")
    print(f"| whole process incl. Python/numpy/scipy/gmsh imports | {info['process']:.2f} s |")
    print(f"| model families built | {info['families']} |")
    print(f"| time per angle | {1e3 * t_angle:.2f} ms |")
    print(f"| max abs FE p0 - Hertz | {100 * np.nanmax(err):.3f} % |")
    print(f"| max abs FE a - Hertz | {100 * np.nanmax(np.abs(tab['err_a'])):.3f} % |")

    # 2. naive path + 3. reuse error ---------------------------------------------------------------
    th12 = parse_angles_deg("0:360:30")
    dt_naive, nv = naive(scene, th12)
    idx = np.round(np.degrees(th12)).astype(int)  # rows of the 1-deg sweep
    ratio = dt_naive / t_angle
    e_naive = np.abs(nv[:, 0] / nv[:, 4] - 1)
    print("\n## Reuse vs naive (fresh mesh + factorisation at every angle)\n")
    print("| path | time per angle | 360 angles | max abs p0 error vs Hertz |\n|---|---|---|---|")
    print(f"| femcam (families, reuse) | {1e3 * t_angle:.2f} ms | {info['sweep']:.2f} s (measured) | "
          f"{100 * np.nanmax(err):.3f} % |")
    print(f"| naive (measured on 12 angles, extrapolated) | {1e3 * dt_naive:.0f} ms | "
          f"{360 * dt_naive:.0f} s (extrapolated) | {100 * e_naive.max():.3f} % (12 angles) |")
    print(f"\nspeed-up per angle: **{ratio:.0f}x** (target >= 40x)")
    print("\n## Reuse error: family model minus fresh model at the same angle (12 angles)\n")
    print("| theta (deg) | p0 | a | von Mises max | tau1 max |\n|---|---|---|---|---|")
    dd = []
    for k, i in enumerate(idx):
        d = (tab["p0_fe"][i] / nv[k, 0] - 1, tab["a_fe"][i] / nv[k, 1] - 1,
             tab["vm_max"][i] / nv[k, 2] - 1, tab["tau1_max"][i] / nv[k, 3] - 1)
        dd.append(d)
        print(f"| {i} | " + " | ".join(f"{100 * x:+.3f} %" for x in d) + " |")
    dd = np.abs(np.array(dd))
    print("| max abs | " + " | ".join(f"{100 * x:.3f} %" for x in dd.max(axis=0)) + " |")

    if not args.quick:
        # 4. scaling ---------------------------------------------------------------------------
        print(f"\n## Scaling (fresh interpreter per run, best of {args.repeat}; sweep() time incl. "
              "meshing)\n")
        print("| angles | a/h | workers | families | sweep time | per angle | max abs p0 err |")
        print("|---|---|---|---|---|---|---|")
        cases = [("0:360:10", 10, 1), ("0:360:4", 10, 1), ("0:360:2", 10, 1), ("0:360:1", 10, 1),
                 ("0:360:0.5", 10, 1), ("0:360:1", 10, 2), ("0:360:1", 6, 1), ("0:360:1", 8, 1),
                 ("0:360:1", 14, 1), ("0:360:1", 20, 1)]
        for spec, aoh, w in cases:
            inf, t = cold_sweep(spec, aoh, w, repeat=args.repeat)
            n = t["theta"].size
            print(f"| {n} | {aoh} | {w} | {inf['families']} | {inf['sweep']:.2f} s | "
                  f"{1e3 * inf['sweep'] / n:.2f} ms | {100 * np.nanmax(np.abs(t['err_p0'])):.3f} % |")

    if args.bezier:
        bezier(args.img)


def bezier(img_dir):
    """Seed 002 comparison: the same study model with bezier5, bezier7, bezier9."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from femcam.kinematics import law

    print("\n## Seed 002: Bezier degree 5 / 7 / 9, same beta (FE sweep, 1 deg, a/h = 10)\n")
    print("| law | Cv | Ca | max s' (mm/rad) | max phi (deg) | min rho (mm) | max Fc (N) | "
          "max p0 FE (MPa) | max p0 Hertz (MPa) | max von Mises (MPa) | max tau1 (MPa) | "
          "angle of max p0 (deg) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    fig, axs = plt.subplots(1, 3, figsize=(12, 3.6))
    for name, c in (("bezier5", "C0"), ("bezier7", "C1"), ("bezier9", "C2")):
        _, t = cold_sweep(law=name)
        L = law(name)
        deg = np.degrees(t["theta"])
        rho = np.where(t["rho"] > 0, t["rho"], np.inf)
        s1max = np.max(np.abs(t["v"])) / (600 * 2 * np.pi / 60)  # s' = v / omega
        i = int(np.nanargmax(t["p0_fe"]))
        print(f"| {name} | {L.Cv:.3f} | {L.Ca:.3f} | {1e3 * s1max:.2f} | "
              f"{np.degrees(np.max(np.abs(t['phi']))):.2f} | {1e3 * np.min(rho):.2f} | "
              f"{np.max(t['Fc']):.1f} | {np.nanmax(t['p0_fe']) / 1e6:.1f} | "
              f"{np.nanmax(t['p0_hertz']) / 1e6:.1f} | {np.nanmax(t['vm_max']) / 1e6:.1f} | "
              f"{np.nanmax(t['tau1_max']) / 1e6:.1f} | {deg[i]:.0f} |")
        axs[0].plot(deg, t["p0_fe"] / 1e6, color=c, label=name)
        axs[1].plot(deg, np.degrees(t["phi"]), color=c, label=name)
        axs[2].plot(deg, 1e-3 / t["rho"], color=c, label=name)
    axs[0].set_ylabel("FE peak pressure p0 (MPa)")
    axs[1].set_ylabel("pressure angle phi (deg)")
    axs[2].set_ylabel("cam curvature 1/rho (1/mm)")
    for ax in axs:
        ax.set_xlabel("cam angle theta (deg)")
        ax.set_xlim(0, 360)
        ax.grid(alpha=0.3)
    axs[0].legend()
    fig.suptitle("Seed 002 study model: Bezier rise/fall laws of degree 5, 7, 9 (beta = 100 deg)")
    fig.tight_layout()
    p = Path(img_dir) / "sweep_bezier.png"
    fig.savefig(p, dpi=80)
    print(f"\nplot: {p}")


if __name__ == "__main__":
    main()
