"""Benchmark: the crowned 360-angle sweep (examples/seed002_crowned.toml, method hertz, the
half-space columns on a 128 x 64 grid), whole process and per angle.

Correctness first: the sweep's half-space provider warm-starts each angle from the previous one
within a chunk (chunks fixed by the angle list and chunk_size, not by the worker count), so

* 1 and 2 worker processes give identical half-space columns (bit for bit);
* the warm-started rows agree with cold per-angle solves within the solver tolerance (the
  largest relative difference of the axial peak and of w_max is printed and checked < 1e-3).

Then the times: the whole ``python -m femcam sweep`` process with 1 and 2 workers (median of
``--runs`` runs; wall and CPU seconds of the child process; load average), and the per-angle cost
of the half-space solve cold against warm (chunks of 30).

Run:  python benchmarks/bench_halfspace_sweep.py [--runs 3]
"""

from __future__ import annotations

import argparse
import os
import platform
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from femcam.halfspace.rows import finite_length_rows
from femcam.scene import finite_case, load_scene
from femcam.sweep import RunOptions, SweepOptions, sweep

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "examples" / "seed002_crowned.toml"
TH = np.radians(np.arange(360.0))


def rows_of(scene, th, strip=None):
    """The half-space rows of ``scene`` at ``th`` (rad), warm-started angle to angle: ``strip``
    (default: the scene's own) at the scene's state."""
    st = scene.analyse(th)
    return finite_length_rows(strip or finite_case(scene).strip(), th, st.Fc, st.rho, scene.follower.Rr)


def check(scene) -> float:
    th = TH[::4]
    r1 = sweep(scene, SweepOptions(angles=th, method="hertz", chunk_size=30), RunOptions(workers=1))
    r2 = sweep(scene, SweepOptions(angles=th, method="hertz", chunk_size=30), RunOptions(workers=2))
    for k in ("hs_p_axial_peak", "hs_w_max", "hs_y_centre", "hs_iterations"):
        assert np.array_equal(r1.table[k], r2.table[k], equal_nan=True), k
    cold = [rows_of(scene, [t]) for t in th]
    dev = 0.0
    for k in ("p_axial_peak", "w_max"):
        c = np.array([r[k][0] for r in cold])
        dev = max(dev, float(np.nanmax(np.abs(r1.table[f"hs_{k}"] / c - 1))))
    assert dev < 1e-3, dev
    return dev


def whole_process(workers: int, runs: int) -> tuple[float, float, float]:
    walls, cpus, loads = [], [], []
    for _ in range(runs):
        with tempfile.TemporaryDirectory() as out:
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            t = time.perf_counter()
            subprocess.run([sys.executable, "-m", "femcam", "sweep", str(SCENE), "--out", out, "--method",
                            "hertz", "--no-plots", "--vtk-every", "0", "--progress", "off", "--workers",
                            str(workers)], check=True, capture_output=True, env={**os.environ,
                                                                                 "PYTHONPATH": str(ROOT)})
            walls.append(time.perf_counter() - t)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpus.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
            loads.append(os.getloadavg()[0])
    return float(np.median(walls)), float(np.median(cpus)), float(np.median(loads))


def per_angle(scene, runs: int) -> tuple[float, float, float, float]:
    strip = finite_case(scene).strip()
    rows_of(scene, TH[:2], strip)             # kernels built (as a warm process)
    warm, cold, it_w, it_c = [], [], [], []
    for _ in range(runs):
        t = time.perf_counter()
        rows = [rows_of(scene, TH[i:i + 30], strip) for i in range(0, 360, 30)]
        warm.append((time.perf_counter() - t) / 360)
        it_w.append(np.mean(np.concatenate([r["iterations"] for r in rows])))
        t = time.perf_counter()
        rows = [rows_of(scene, [t_], strip) for t_ in TH]
        cold.append((time.perf_counter() - t) / 360)
        it_c.append(np.mean([r["iterations"][0] for r in rows]))
    return float(np.median(warm)), float(np.median(cold)), float(np.mean(it_w)), float(np.mean(it_c))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=3)
    args = ap.parse_args(argv)
    scene = load_scene(SCENE)
    print(f"correctness: 1 vs 2 workers identical; warm vs cold max relative difference {check(scene):.1e}")
    print(f"machine {platform.machine()}, {os.cpu_count()} cores shared with other jobs; "
          f"median of {args.runs} runs")
    w, c, itw, itc = per_angle(scene, args.runs)
    print(f"per angle (half-space 128 x 64): warm {w * 1e3:.1f} ms ({itw:.1f} CG it), cold {c * 1e3:.1f} ms "
          f"({itc:.1f} CG it); load avg {os.getloadavg()[0]:.2f}")
    print(f"{'workers':>7} {'wall (s)':>9} {'CPU (s)':>8} {'load avg':>8}")
    for n in (1, 2):
        wall, cpu, load = whole_process(n, args.runs)
        print(f"{n:>7} {wall:9.2f} {cpu:8.2f} {load:8.2f}", flush=True)


if __name__ == "__main__":
    main()
