"""Benchmark: design studies (femcam.study) on a Dask LocalCluster.

Checks correctness first (a base-radius grid brackets femcam.profile.min_base_radius for
phi <= 30 deg; the 2-worker Dask table equals the serial one bit for bit), then times a Latin
hypercube of N seed 002 variants (base radius, roller radius, preload, law; Hertz chain over
720 angles each):

* serially in this process (the reference),
* on a LocalCluster of 1 and 2 worker processes (one thread each),

and prints variants/s, variants/s per worker, the speed-up from 1 to 2 workers and the
machine's load average before and after each run (a shared machine: the load says how many
cores the run really had).

Run:  python benchmarks/bench_study.py [--n 1000] [--figures docs/img]   (--n 0: figures only)
(the figures: the README's seed 002 Pareto plot, from a 9 x 4 grid of base radius and law,
study_pareto_seed002.png; the constraint map over base and roller radius with rho >= 3 mm,
study_constraint_map_seed002.png.)
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import time

import numpy as np

from femcam.profile import min_base_radius
from femcam.scene import load_scene
from femcam.study import Constraints, StudySpec, run_study

SCENE = "examples/seed002_study_model.toml"
LHS = ["follower.base_radius_mm=8:20", "follower.roller_radius_mm=5:15", "dynamics.preload_N=800:2000",
       "program.law=bezier5,bezier7,bezier9,cycloidal"]


def check() -> float:
    """The smallest feasible grid base radius minus min_base_radius (m; in [0, step))."""
    Rr = load_scene(SCENE).follower.Rr
    exact = min_base_radius("roller", load_scene(SCENE).with_law("cycloidal").program,
                            phi_max=math.radians(30.0), Rr=Rr).Rb
    r = run_study(SCENE, StudySpec.parse(["program.law=cycloidal", "follower.base_radius_mm=3:8:0.25"]),
                  constraints=Constraints(phi_limit=math.radians(30.0)))
    grid = np.min(r.table["follower.base_radius_mm"][r.table["margin_phi"] >= 0]) * 1e-3
    assert 0.0 <= grid - exact < 0.25e-3, (grid, exact)
    return grid - exact


def _cpu(client) -> float:
    """CPU seconds of this process plus (with a Dask client) all its workers."""
    own = time.process_time()
    return own if client is None else own + sum(client.run(time.process_time).values())


def _timed(spec, client=None):
    l0, c0 = os.getloadavg()[0], _cpu(client)
    t = time.perf_counter()
    res = run_study(SCENE, spec, scheduler=client)
    return res, time.perf_counter() - t, _cpu(client) - c0, l0, os.getloadavg()[0]


def bench(n: int) -> None:
    from dask.distributed import Client, LocalCluster  # lazy: dask is the optional extra

    spec = StudySpec.parse(LHS, lhs=n, seed=1)
    rows = []
    ref, dt, cpu, l0, l1 = _timed(spec)
    rows.append(("serial (this process)", 1, dt, cpu, l0, l1))
    for w in (1, 2):
        with LocalCluster(n_workers=w, threads_per_worker=1, processes=True, dashboard_address=None) as lc, \
                Client(lc) as client:
            client.run(lambda: __import__("femcam.study"))  # warm the workers' imports (not timed)
            res, dt, cpu, l0, l1 = _timed(spec, client)
        if w == 2:  # correctness of the distributed run: the serial table, bit for bit
            for k, v in ref.table.items():
                assert np.array_equal(np.asarray(v), np.asarray(res.table[k]), equal_nan=True) \
                    if np.asarray(v).dtype.kind == "f" else list(v) == list(res.table[k]), k
        rows.append((f"Dask LocalCluster, {w} worker{'s' * (w > 1)}", w, dt, cpu, l0, l1))
    print(f"\n{n} variants (Latin hypercube, 4 keys), Hertz chain on 720 angles per variant; "
          f"{ref.n_feasible} feasible, {int(ref.table['pareto'].sum())} on the Pareto front")
    print(f"{'where':34s} {'workers':>7s} {'time s':>8s} {'variants/s':>11s} {'per worker':>11s} "
          f"{'speed-up':>9s} {'CPU s':>7s} {'ms CPU/variant':>15s} {'load before/after':>18s}")
    base = rows[1][2]
    for name, w, dt, cpu, l0, l1 in rows:
        print(f"{name:34s} {w:7d} {dt:8.2f} {n / dt:11.1f} {n / dt / w:11.1f} "
              f"{(base / dt if 'Dask' in name else float('nan')):9.2f} {cpu:7.2f} {cpu / n * 1e3:15.2f} "
              f"{l0:8.2f} / {l1:6.2f}")
    print("(CPU s: this process plus the workers; with the wall time and the load it says how much of "
          "the machine the run had)")


def figures(folder: str) -> None:
    """The README's seed 002 Pareto plot (base radius 6..22 mm x four laws, phi <= 30 deg) and
    a constraint map (base radius 4..14 mm x roller radius 4..20 mm, rho >= 3 mm, lift-off
    allowed)."""
    import shutil
    import tempfile

    runs = ((["follower.base_radius_mm=6:22:2", "program.law=bezier5,bezier7,bezier9,cycloidal"],
             Constraints(), "pareto", "study_pareto_seed002.png"),
            (["follower.base_radius_mm=4:14:1", "follower.roller_radius_mm=4:20:2"],
             Constraints(rho_limit=3e-3, liftoff=False), "constraint_map",
             "study_constraint_map_seed002.png"))
    for vary, cons, kind, name in runs:
        with tempfile.TemporaryDirectory(prefix="femcam-study-figure-") as tmp:
            res = run_study(SCENE, StudySpec.parse(vary), constraints=cons, out=tmp, plots=True)
            shutil.copyfile(res.paths[kind], os.path.join(folder, name))
        print(res.summary())
        print(f"figure: {os.path.join(folder, name)}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=1000)
    ap.add_argument("--figures", default=None, metavar="DIR")
    args = ap.parse_args()
    t0 = time.perf_counter()
    print(f"check: smallest feasible grid Rb - min_base_radius = {check() * 1e3:.4f} mm (in [0, 0.25))")
    if args.n > 0:
        bench(args.n)
    if args.figures:
        figures(args.figures)
    load = os.getloadavg()
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} CPUs (shared), load "
          f"average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}; total script {time.perf_counter() - t0:.1f} s")


if __name__ == "__main__":
    main()
