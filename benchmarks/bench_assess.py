"""Benchmark: the full assessment of a 360-angle seed 002 sweep (femcam.assess.assess_rows).

Checks correctness first (the base-circle angle against a hand calculation: Pan-Hamrock film with
the ASTM D341 viscosity, Blok flash temperature against AGMA 925's K = 0.80 form, ISO 6336 surface
fatigue; Johnson's shakedown 4.0 at mu = 0), then times on ``examples/seed002_assess.toml``:

* ``cold``: assess_rows in a fresh process (subprocess) (the per-mu shakedown/first-yield limits and the
  scene's dense undercut check not yet cached) - what a first ``femcam assess`` call costs;
* ``after sweep``: assess_rows on the table of a Hertz sweep of the same scene (which has cached
  the scene's undercut check and the Hertz maxima of its mu): what the assessment adds to a sweep;
* ``warm``: every cache hot (the per-chunk cost the sweep would pay from the 2nd chunk on).

Run:  python benchmarks/bench_assess.py [--figures docs/img]   (the README figures: assess_*.png)
"""

from __future__ import annotations

import math
import os
import platform
import time

import numpy as np

SCENE = "examples/seed002_assess.toml"


def check(scene) -> None:
    from femcam.assess import assess_rows
    from femcam.scene import contact_case
    from femcam.tribology import shakedown_limit

    r = assess_rows(contact_case(scene, np.radians([300.0])))
    E_star = 210e9 / (2 * 0.91)
    w, R = 1.5e5, 0.005
    a = math.sqrt(4 * w * R / (math.pi * E_star))
    u1 = 20 * math.pi * 0.01
    u2 = u1 * 1.98 / 2.02
    y = [math.log10(math.log10(v + 0.7)) for v in (46.0, 6.8)]
    x = [math.log10(T) for T in (313.15, 373.15)]
    yT = y[0] + (y[1] - y[0]) * (math.log10(343.15) - x[0]) / (x[1] - x[0])
    eta = 861 * (10 ** 10**yT - 0.7) * 1e-6
    Ep = 2 * E_star
    U = (u1 + u2) / 2
    h = R * 1.714 * (w / (Ep * R)) ** -0.128 * (eta * U / (Ep * R)) ** 0.694 * (2e-8 * Ep) ** 0.568
    assert abs(r["h_min"][0] / h - 1) < 1e-9, "Pan-Hamrock film"
    beta = math.sqrt(46.6 * 7810 * 475)
    agma = 0.80 * 0.1 * w * (u1 - u2) / (math.sqrt(a) * beta * (math.sqrt(u1) + math.sqrt(u2)))
    assert abs(r["dT_flash"][0] / agma - 1) < 0.02, "AGMA 925 flash temperature"
    assert abs(r["sf_surface_fatigue"][0] * (2 * w / (math.pi * a)) / 1500e6 - 1) < 1e-9, "ISO 6336"
    assert abs(shakedown_limit(0.0) - 4.0) < 0.01, "Johnson shakedown 4.0"


def main() -> None:
    import argparse

    ap = argparse.ArgumentParser()
    ap.add_argument("--figures", default=None, metavar="DIR", help="write the assessment plots there")
    args = ap.parse_args()
    t0 = time.perf_counter()
    from femcam.assess import assess_rows
    from femcam.scene import contact_case, load_scene
    from femcam.sweep import RunOptions, SweepOptions, sweep

    scene = load_scene(SCENE)
    theta = np.radians(np.arange(0.0, 360.0, 1.0))
    t = time.perf_counter()
    table = sweep(scene, SweepOptions(angles=theta, method="hertz"), RunOptions(progress=False))
    t_sweep = time.perf_counter() - t
    t = time.perf_counter()
    rows = assess_rows(contact_case(scene, theta), table)      # first assessment in this process
    after = time.perf_counter() - t
    warm = min(_timed(lambda: assess_rows(contact_case(scene, theta))) for _ in range(5))
    cold = _cold()
    check(scene)
    assert np.all(np.isfinite(rows["lam"])) and np.all(rows["source"] == "hertz")
    load = os.getloadavg()
    try:
        model = next(line.split(":", 1)[1].strip() for line in open("/proc/cpuinfo") if "model name" in line)
    except (OSError, StopIteration):
        model = platform.processor()
    print(f"machine: {model}, {os.cpu_count()} CPUs (shared), load average {load[0]:.2f} {load[1]:.2f} "
          f"{load[2]:.2f}; total script {time.perf_counter() - t0:.1f} s")
    print("checks passed: Pan-Hamrock film (1e-9), AGMA 925 flash (2 %), ISO 6336 (1e-9), shakedown 4.0")
    print(f"{'case':<44}{'angles':>8}{'time (s)':>10}")
    print(f"{'assess_rows, cold (first call in a process)':<44}{360:>8}{cold:>10.3f}")
    print(f"{'Hertz sweep of the same scene (reference)':<44}{360:>8}{t_sweep:>10.3f}")
    print(f"{'assess_rows after the sweep (added cost)':<44}{360:>8}{after:>10.3f}")
    print(f"{'assess_rows, warm (best of 5)':<44}{360:>8}{warm:>10.4f}")
    if args.figures:
        from femcam.assess import assess
        from femcam.viz.assess import plot_assessment

        res = assess(contact_case(scene, theta))
        for name, path in plot_assessment(res, args.figures).items():
            print(f"figure {name}: {path}")
        for crit, (v, th, _) in res.worst.items():
            print(f"worst {crit}: {v:.4g} at {math.degrees(th):.0f} deg")
        _flat_figure(args.figures)


def _flat_figure(out) -> None:
    """The same cam program (cycloidal) with a flat-faced follower of base radius 20 mm: the
    entrainment speed omega (Rb + s + 2 s'')/2 reverses near the nose and the film collapses."""
    import re
    import tempfile
    from pathlib import Path

    from femcam.assess import assess
    from femcam.scene import contact_case, load_scene
    from femcam.viz.assess import plot_lambda

    text = open(SCENE).read().replace('law = "bezier5"', 'law = "cycloidal"')
    text = re.sub(r"\[follower\].*?face_width_mm = 10.0\n", '[follower]\ntype = "flat_faced"\n'
                  'base_radius_mm = 20.0\nface_width_mm = 10.0\n', text, flags=re.S)
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "flat.toml"
        p.write_text(text)
        res = assess(contact_case(load_scene(p), np.radians(np.arange(0.0, 360.0, 0.5))))
    r = res.rows
    off = r["U"] <= 0
    print(f"flat-faced: U <= 0 (film collapsed, flagged no_entrainment) at {int(off.sum())} of {off.size} "
          f"angles, {np.degrees(r['theta'][off]).min():.1f}..{np.degrees(r['theta'][off]).max():.1f} deg; "
          f"max lambda {np.nanmax(r['lam']):.3g}")
    print("figure flat-faced lambda:", plot_lambda(r, Path(out) / "assess_flat_lambda.png"))


def _cold() -> float:
    """assess_rows on a fresh scene in a fresh process (nothing cached)."""
    import subprocess
    import sys

    code = ("import time, numpy as np\nfrom femcam.scene import contact_case, load_scene\n"
            "from femcam.assess import assess_rows\n"
            f"sc = load_scene({SCENE!r})\nth = np.radians(np.arange(0.0, 360.0, 1.0))\n"
            "t = time.perf_counter(); assess_rows(contact_case(sc, th)); print(time.perf_counter() - t)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return float(out.stdout.strip())


def _timed(fn, *args) -> float:
    t = time.perf_counter()
    fn(*args)
    return time.perf_counter() - t


if __name__ == "__main__":
    main()
