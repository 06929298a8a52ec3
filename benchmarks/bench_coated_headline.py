"""The coated model answers the sweep's headline: p0 against the two homogeneous limits.

Run:  python benchmarks/bench_coated_headline.py [--quick]

The seed 002 study model (examples/seed002_study_model.toml) at the angle of its largest Hertz p0, with a
100 GPa (nu 0.3) coating on the cam of thickness 10, 100 and 600 um, swept by
:func:`femcam.sweep.sweep` (method fe, a/h = 10). Hertz is computed here from first principles
(Johnson 1985 eqs. 4.22, 4.43-4.45) for a homogeneous steel cam (the substrate) and a
homogeneous cam of the coating material. Checks before timing: the uncoated headline within
0.5 % of the steel Hertz, and the coated headline between the two limits (and, at t >= 6 a,
within 3 % of the coating's Hertz). Then a table of p0 (coated FE, both Hertz limits), the
models built (one per family: no side model) and the wall time of each sweep, with the load
average (the machine is shared; times move with the load).
"""

from __future__ import annotations

import dataclasses
import math
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

from femcam.scene import load_scene
from femcam.sweep import RunOptions, SweepOptions, default_cache, sweep

SCENE = Path(__file__).resolve().parents[1] / "examples" / "seed002_study_model.toml"
E_C, NU_C = 100e9, 0.3


def hertz_p0(F, length, rho, Rr, cam, roller):
    """Johnson 1985 eqs. 4.22, 4.43-4.45, plane strain: p0 (Pa) and a (m)."""
    E_star = 1.0 / ((1 - cam[1] ** 2) / cam[0] + (1 - roller[1] ** 2) / roller[0])
    R = 1.0 / (1.0 / rho + 1.0 / Rr)
    w = F / length
    a = math.sqrt(4 * w * R / (math.pi * E_star))
    return 2 * w / (math.pi * a), a


def coated(sc, t):
    layers = {"cam": {"coating": {"thickness": t, "E": E_C, "nu": NU_C, "name": "coating"}}}
    return dataclasses.replace(sc, layers=layers)


def main(argv):
    quick = "--quick" in argv
    sc = load_scene(SCENE)
    grid = np.radians(np.arange(0.0, 360.0, 1.0))
    st = sc.analyse(grid)
    steel, roller = (sc.cam.E, sc.cam.nu), (sc.roller.E, sc.roller.nu)
    p0_grid = [hertz_p0(f, sc.length, r_, sc.follower.Rr, steel, roller)[0] if f > 0 else -1.0
               for f, r_ in zip(np.asarray(st.Fc, float), np.asarray(st.rho, float), strict=True)]
    i = int(np.argmax(p0_grid))   # the angle of the largest Hertz p0
    theta, F, rho = float(grid[i]), float(st.Fc[i]), float(st.rho[i])
    pS, aS = hertz_p0(F, sc.length, rho, sc.follower.Rr, steel, (sc.roller.E, sc.roller.nu))
    pC, aC = hertz_p0(F, sc.length, rho, sc.follower.Rr, (E_C, NU_C), (sc.roller.E, sc.roller.nu))
    print(f"# bench_coated_headline  machine: {platform.processor() or platform.machine()}, "
          f"{os.cpu_count()} CPUs (shared), load average {os.getloadavg()[0]:.2f}")
    print(f"seed 002 study model at {math.degrees(theta):.0f} deg: Fc = {F:.1f} N, rho = {rho * 1e3:.2f} mm, "
          f"Hertz steel p0 = {pS / 1e6:.1f} MPa (a = {aS * 1e6:.1f} um), Hertz coating-material cam "
          f"p0 = {pC / 1e6:.1f} MPa (a = {aC * 1e6:.1f} um)")
    rows = []
    for t in [None] + ([100e-6] if quick else [10e-6, 100e-6, 600e-6]):
        s = sc if t is None else coated(sc, t)
        default_cache().clear()
        b0 = default_cache().stats["built"]
        t0 = time.perf_counter()
        r = sweep(s, SweepOptions(angles=np.array([theta]), a_over_h=10.0), RunOptions(workers=1))
        wall = time.perf_counter() - t0
        built = default_cache().stats["built"] - b0
        assert r["status"][0] == "ok", r["message"][0]
        p0 = float(r["p0_fe"][0])
        if t is None:
            assert abs(p0 / pS - 1) < 5e-3, "uncoated headline vs Hertz"
        else:
            assert min(pC, pS) * 0.99 < p0 < max(pC, pS) * 1.01, "between the homogeneous limits"
            if t >= 6 * aC:
                assert abs(p0 / pC - 1) < 3e-2, "thick coating vs the coating's Hertz"
        rows.append((t, str(r["model"][0]), p0, built, wall, os.getloadavg()[0]))
    print("| coating t (um) | t / a_coating | model | p0 FE (MPa) | vs Hertz steel | vs Hertz coating "
          "| models built | sweep wall s | load |")
    print("|---|---|---|---|---|---|---|---|---|")
    for t, model, p0, built, wall, load in rows:
        tt = "none" if t is None else f"{t * 1e6:g}"
        ta = "-" if t is None else f"{t / aC:.2f}"
        print(f"| {tt} | {ta} | {model} | {p0 / 1e6:.1f} | {100 * (p0 / pS - 1):+.2f} % | "
              f"{100 * (p0 / pC - 1):+.2f} % | {built} | {wall:.2f} | {load:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
