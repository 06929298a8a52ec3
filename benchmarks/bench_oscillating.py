"""Benchmark: an oscillating-follower FE sweep against its translating equivalent (issue 25).

The translating equivalent of ``examples/rff_valve_train.toml`` has the same cam radii, the offset
of the roller centre's path at the base circle, the arc lift ``L psi`` as its lift and the arm
train referred to the roller centre (``m = I/L^2``, ``k = k_t/L^2``, ``Fpl = M_pl/L``): the two
cams differ only by the arc of the arm, so the meshes (contact widths, model families) match.

Checks correctness first (FE p0 within 0.5 % of Hertz at every angle of both sweeps), then times
``femcam.sweep.sweep`` in-process on 72 angles (5 deg), one worker, the process model cache
cleared before each run, alternating the two scenes twice.

Run:  python benchmarks/bench_oscillating.py
"""

from __future__ import annotations

import dataclasses
import math
import platform
import time

import numpy as np

SCENE = "examples/rff_valve_train.toml"


def translating_equivalent(sc):
    """The translating roller scene the arm reduces to (module docstring)."""
    from femcam.loads import FollowerDynamics
    from femcam.profile import RollerFollower

    f, dyn = sc.follower, sc.dynamics
    b0, L = f.beta0, f.L
    Bx, By = f.a - L * math.cos(b0), f.sigma * L * math.sin(b0)
    ux, uy = math.sin(b0), f.sigma * math.cos(b0)
    e = By * ux - Bx * uy  # the signed distance of the path line from O (x = e, motion along +y)
    return dataclasses.replace(sc, follower=RollerFollower(Rb=f.Rb, Rr=f.Rr, e=e),
                               dynamics=FollowerDynamics(m=dyn.I / L**2, k=dyn.k_t / L**2,
                                                         Fpl=dyn.M_pl / L, c=dyn.c_t / L**2))


def main() -> None:
    from femcam.scene import load_scene
    from femcam.sweep import default_cache, sweep

    osc = load_scene(SCENE)
    cases = {"oscillating": osc, "translating equivalent": translating_equivalent(osc)}
    angles = np.radians(np.arange(0.0, 360.0, 5.0))
    times = {k: [] for k in cases}
    for _ in range(2):
        for name, sc in cases.items():
            default_cache().clear()
            t0 = time.perf_counter()
            r = sweep(sc, angles=angles, method="fe")
            times[name].append(time.perf_counter() - t0)
            err = np.nanmax(np.abs(r["p0_fe"] / r["p0_hertz"] - 1.0))
            assert err < 5e-3, f"{name}: FE p0 off Hertz by {err:.3%}"
    print(f"machine: {platform.processor() or platform.machine()}, python {platform.python_version()}")
    print(f"{'case':24s} {'sweep time (s), two runs':>26s}")
    for name, ts in times.items():
        print(f"{name:24s} {', '.join(f'{t:.2f}' for t in ts):>26s}")
    ratio = min(times["oscillating"]) / min(times["translating equivalent"])
    print(f"oscillating / translating (best of two): {ratio:.2f}")


if __name__ == "__main__":
    main()
