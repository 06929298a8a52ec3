"""Benchmark: an oscillating-follower FE sweep against its translating equivalent (issue 25).

The translating equivalent of ``examples/rff_valve_train.toml`` has the same cam radii, the offset
of the roller centre's path at the base circle, the arc lift ``L psi`` as its lift and the arm
train referred to the roller centre (``m = I/L^2``, ``k = k_t/L^2``, ``Fpl = M_pl/L``): the two
cams differ only by the arc of the arm, so the meshes (contact widths, model families) match.

Checks correctness first (FE p0 within 0.5 % of Hertz at every angle of both sweeps), then times
``femcam.sweep.sweep`` in-process on 72 angles (5 deg), one worker, the process model cache
cleared before each run, alternating the two scenes twice.

Second part, **whole process** (issue 25's target: within 20 %): ``python -m femcam sweep`` of the
example against the same translating equivalent written as a scene file (``lift_mm``,
``offset_mm``, ``mass_kg``, ...), both at ``--a-over-h 10`` on 72 angles, ``--no-plots``; FE p0
within 0.5 % of Hertz in both CSVs first, then ``PAIRS`` paired runs (alternating order): the
median wall and CPU (user + system of the child process) time of each and the medians of the
paired ratios. On a shared machine the CPU ratio is the steadier figure.

Run:  python benchmarks/bench_oscillating.py [--process-only]
"""

from __future__ import annotations

import dataclasses
import math
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import tomllib

SCENE = "examples/rff_valve_train.toml"
#: paired whole-process runs
PAIRS = 5
SWEEP_FLAGS = ["--angles-deg", "0:360:5", "--method", "fe", "--a-over-h", "10", "--no-plots", "-q",
               "--workers", "1"]


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
    from femcam.sweep import SweepOptions, default_cache, sweep

    osc = load_scene(SCENE)
    cases = {"oscillating": osc, "translating equivalent": translating_equivalent(osc)}
    angles = np.radians(np.arange(0.0, 360.0, 5.0))
    times = {k: [] for k in cases}
    for _ in range(2):
        for name, sc in cases.items():
            default_cache().clear()
            t0 = time.perf_counter()
            r = sweep(sc, SweepOptions(angles=angles, method="fe"))
            times[name].append(time.perf_counter() - t0)
            err = np.nanmax(np.abs(r["p0_fe"] / r["p0_hertz"] - 1.0))
            assert err < 5e-3, f"{name}: FE p0 off Hertz by {err:.3%}"
    print(f"machine: {platform.processor() or platform.machine()}, python {platform.python_version()}")
    print(f"{'case':24s} {'sweep time (s), two runs':>26s}")
    for name, ts in times.items():
        print(f"{name:24s} {', '.join(f'{t:.2f}' for t in ts):>26s}")
    ratio = min(times["oscillating"]) / min(times["translating equivalent"])
    print(f"oscillating / translating (best of two): {ratio:.2f}")


def _toml(d: dict, prefix: str = "") -> str:
    """A minimal TOML writer for a parsed scene (tables, arrays of tables, scalars, strings)."""
    def val(v):
        return f'"{v}"' if isinstance(v, str) else ("true" if v is True else "false" if v is False
                                                     else repr(v))
    lines = [f"{k} = {val(v)}" for k, v in d.items() if not isinstance(v, dict | list)
             or (isinstance(v, list) and not (v and isinstance(v[0], dict)))]
    for k, v in d.items():
        name = f"{prefix}{k}"
        if isinstance(v, dict):
            lines += ["", f"[{name}]", _toml(v, name + ".")]
        elif isinstance(v, list) and v and isinstance(v[0], dict):
            for item in v:
                lines += ["", f"[[{name}]]", _toml(item, name + ".")]
    return "\n".join(ln for ln in lines if ln is not None)


def translating_scene_file(path: Path) -> Path:
    """The translating equivalent of :data:`SCENE` as a scene file in ``path`` (module docstring)."""
    from femcam.scene import load_scene

    osc = load_scene(SCENE)
    tr = translating_equivalent(osc)
    raw = tomllib.loads(Path(SCENE).read_text(encoding="utf-8"))
    raw["name"] = "rff_translating_equivalent"
    for sg in raw["program"]["segment"]:
        if "lift_deg" in sg:
            sg["lift_mm"] = math.radians(sg.pop("lift_deg")) * osc.follower.L * 1e3
    fo = raw["follower"]
    for k in ("motion", "direction", "pivot_distance_mm", "arm_length_mm"):
        fo.pop(k, None)
    fo["offset_mm"] = tr.follower.e * 1e3
    dyn = tr.dynamics
    raw["dynamics"] = {"mass_kg": dyn.m, "spring_N_per_m": dyn.k, "preload_N": dyn.Fpl,
                       "damping_N_s_per_m": dyn.c}
    out = path / "rff_translating.toml"
    out.write_text(_toml(raw) + "\n", encoding="utf-8")
    return out


def _cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def _run(scene: Path, out: Path) -> tuple[float, float]:
    """``(wall, cpu)`` seconds of one ``femcam sweep`` process (CPU: user + system of the child,
    less sensitive than the wall time to other jobs on a shared machine)."""
    t0, c0 = time.perf_counter(), _cpu()
    subprocess.run([sys.executable, "-m", "femcam", "sweep", str(scene), "--out", str(out), "--overwrite",
                    *SWEEP_FLAGS], check=True, capture_output=True)
    return time.perf_counter() - t0, _cpu() - c0


def _check_csv(out: Path, name: str) -> float:
    from femcam.io import read_csv

    t, _ = read_csv(out / "sweep.csv")
    err = float(np.nanmax(np.abs(np.asarray(t["p0_fe_MPa"]) / np.asarray(t["p0_hertz_MPa"]) - 1.0)))
    assert err < 5e-3, f"{name}: FE p0 off Hertz by {err:.3%}"
    return err


def process_main() -> None:
    """Whole-process ``femcam sweep``: oscillating example vs the translating scene file."""
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        scenes = {"oscillating": Path(SCENE), "translating equivalent": translating_scene_file(tmp)}
        for name, sc in scenes.items():   # correctness first (and a warm file cache)
            _run(sc, tmp / "check")
            print(f"{name}: FE p0 vs Hertz max {_check_csv(tmp / 'check', name):.3%}")
        times = {k: [] for k in scenes}
        for i in range(PAIRS):
            order = list(scenes) if i % 2 == 0 else list(reversed(scenes))
            for name in order:
                times[name].append(_run(scenes[name], tmp / "run"))
    with open("/proc/loadavg", encoding="ascii") as fh:
        load = fh.read().split()[:3]
    print(f"machine: {platform.processor() or platform.machine()}, python {platform.python_version()}, "
          f"load after {' '.join(load)}")
    for k, what in enumerate(("wall", "cpu")):
        print(f"{'case':24s} {what + ' median (s)':>16s}  runs (s)")
        for name, ts in times.items():
            v = [t[k] for t in ts]
            print(f"{name:24s} {statistics.median(v):16.2f}  {', '.join(f'{t:.2f}' for t in v)}")
        ratios = [a[k] / b[k] for a, b in zip(times["oscillating"], times["translating equivalent"],
                                                strict=True)]
        print(f"oscillating / translating, whole process {what}: median of {PAIRS} paired ratios "
              f"{statistics.median(ratios):.2f} (target <= 1.2)")


if __name__ == "__main__":
    if "--process-only" not in sys.argv:
        main()
    process_main()
