"""Benchmark: follower-train dynamics (femcam.dynamics).

Checks correctness first (residual vibration after a cycloidal rise against Duhamel's closed
form |sin(pi r)|/(pi r |r^2 - 1|); the stiff-train limit against eq. 11), then times

* the periodic steady state of the seed 002 1-DOF train at 3600 steps per revolution
  (contact kept: the exact linear periodic solve; and above the jump speed: free flight,
  re-impact and Newton shooting),
* an rpm sweep of 100 speeds (60..6000 rpm) on 1 and 2 processes, and the jump-speed search.

Run:  python benchmarks/bench_dynamics.py [--figures docs/img]
(the figures: seed 002 contact force rigid vs 1-DOF vs 2-DOF at 600 rpm, and the rpm sweep.)
"""

from __future__ import annotations

import argparse
import dataclasses
import math
import os
import platform
import time

import numpy as np

from femcam.dynamics import TrainModel, jump_speed, periodic_response, rpm_sweep, simulate
from femcam.kinematics import CamProgram, dwell, fall, rise
from femcam.loads import FollowerDynamics
from femcam.scene import load_scene

SCENE = "examples/seed002_dynamic.toml"
RPM = np.linspace(60.0, 6000.0, 100)
#: the 2-DOF train of the figure: seed 002's tracker (m1 = 0.2 kg on k_t) carrying an ASSUMED
#: second mass 0.1 kg on k2 = 1e6 N/m, zeta2 = 0.05 (seed 002 has no second mass)
TWO_DOF = dict(m2=0.1, k2=1.0e6, zeta2=0.05)


def check() -> float:
    """Largest relative error of the residual amplitude over r = 0.7 .. 5.2."""
    H, w_cam = 0.01, 2 * math.pi
    prog = CamProgram([rise(math.pi / 2, H), dwell(math.pi / 2), fall(math.pi / 2, H),
                       dwell(math.pi / 2)])
    worst = 0.0
    for r in (0.7, 1.5, 2.3, 3.6, 5.2):
        w = 2 * math.pi * r / 0.25
        tm = TrainModel(follower=FollowerDynamics(m=1.0, k=0.0, Fpl=1e5, c=0.0), k_t=w * w, zeta_t=0.0)
        est = -1e5 / w**2
        th, Z, _, _ = simulate(tm, prog, w_cam, z0=[est, 0.0], steps_per_rev=3600)
        i = np.searchsorted(th, math.pi - 1e-9)
        A = math.hypot(Z[i, 0] - est, Z[i, 1] / w) / H
        ref = abs(math.sin(math.pi * r)) / (math.pi * r * abs(r * r - 1))
        worst = max(worst, abs(A / ref - 1))
    assert worst < 1e-4, worst
    sc = load_scene(SCENE)
    stiff = dataclasses.replace(sc, train=TrainModel(follower=sc.dynamics, k_t=1e12, zeta_t=0.7))
    th = np.linspace(0, 2 * math.pi, 361)
    d, st = dataclasses.replace(sc, train=None).analyse(th), stiff.analyse(th)
    assert np.max(np.abs(st.Fc - d.Fc)) < 1e-6 * d.Fc.max()
    return worst


def best(fn, repeat=5):
    ts = []
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        ts.append(time.perf_counter() - t)
    return min(ts), out


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--figures", default=None, help="write the README figures into this directory")
    args = ap.parse_args(argv)
    err = check()
    sc = load_scene(SCENE)
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"python {platform.python_version()}; load average {os.getloadavg()} (shared machine)")
    print(f"correctness: residual vibration vs Duhamel closed form, max rel. error {err:.2e}; "
          "stiff train (1e12 N/m) = eq. 11 within 1e-6")
    print(f"{'case':58s} {'time':>9s}  notes")
    t, r = best(lambda: periodic_response(sc.train, sc.program, sc.omega, steps_per_rev=3600))
    print(f"{'seed 002 1-DOF, 600 rpm, 3600 steps (linear periodic)':58s} {t * 1e3:7.1f} ms  "
          f"{r.cycles} cycle, residual {r.residual:.1e}")
    w = 4600 * math.pi / 30
    t, r = best(lambda: periodic_response(sc.train, sc.program, w, steps_per_rev=3600), 3)
    print(f"{'seed 002 1-DOF, 4600 rpm, 3600 steps (jump: flight, impact)':58s} {t * 1e3:7.1f} ms  "
          f"{r.cycles} cycles, {r.n_events} events, residual {r.residual:.1e}")
    tm2 = TrainModel(follower=sc.dynamics, k_t=sc.train.k_t, zeta_t=sc.train.zeta_t, **TWO_DOF)
    t, r2 = best(lambda: periodic_response(tm2, sc.program, sc.omega, steps_per_rev=3600))
    print(f"{'seed 002 2-DOF, 600 rpm, 3600 steps':58s} {t * 1e3:7.1f} ms  {r2.message}")
    for workers in (1, 2):
        t0, c0 = time.perf_counter(), time.process_time()
        sw = rpm_sweep(sc.train, sc.program, RPM, workers=workers)
        t, c = time.perf_counter() - t0, time.process_time() - c0
        cpu = f", CPU {c:.2f} s" if workers == 1 else ""
        print(f"{f'rpm sweep, {RPM.size} speeds {RPM[0]:g}..{RPM[-1]:g} rpm, workers={workers}':58s} "
              f"{t:7.2f} s   liftoff at {int(sw.liftoff.sum())} speeds, no one-periodic motion at "
              f"{int((~sw.converged).sum())}; load {os.getloadavg()[0]:.2f}{cpu}")
    t0 = time.perf_counter()
    j = jump_speed(sc.train, sc.program, RPM[0], RPM[-1])
    print(f"{'jump speed search (scan 40 + Brent)':58s} {time.perf_counter() - t0:7.2f} s   "
          f"{j.rpm_jump:.2f} rpm ({j.iterations} Brent iterations)")
    if args.figures:
        from femcam.viz.dynamics import plot_force, plot_rpm_sweep

        r1 = sc.dynamic_response
        p1 = plot_force({"1-DOF (k_t = 2e6 N/m, zeta_t = 0.05)": r1,
                         "2-DOF (+ m2 = 0.1 kg on k2 = 1e6 N/m)": r2},
                        os.path.join(args.figures, "dynamics_seed002_force.png"),
                        title="seed 002 at 600 rpm: contact force, rigid eq. 11 (m = 0.2 kg) vs "
                              "elastic trains")
        p2 = plot_rpm_sweep(sw, os.path.join(args.figures, "dynamics_rpm_sweep.png"), jump=j,
                            title="seed 002 1-DOF train: peak and least contact force vs speed")
        print(f"figures: {p1}, {p2}")


if __name__ == "__main__":
    main()
