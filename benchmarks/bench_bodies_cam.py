"""Benchmark of the cam disk on its shaft (femcam.bodies.cam_*): correctness first, then time.

    PYTHONPATH=. python benchmarks/bench_bodies_cam.py

1. Validation errors against closed forms written here (the references of
   tests/test_bodies_cam_disk.py): Lame (annulus, internal pressure, bore hoop stress) and Kirsch
   (1 mm hole in a 40 mm Brazilian disk, hoop stress round the hole); the global model against the
   fully refined one at one angle of the example.
2. The example examples/seed002_cam_on_shaft.toml (bore 6 mm): DOFs and phase times of the global
   model's cold build (mesh, assembly, factorisation, condensation), the 360-angle cam_disk_rows
   (the sweep provider's work), and the fully refined model at the peak-force angle.
Times are wall-clock on a shared machine: the load average is printed next to them.
"""

from __future__ import annotations

import math
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from femcam.bodies.cam_global import CamGlobalModel  # noqa: E402
from femcam.bodies.cam_mesh import mesh_cam_disk  # noqa: E402
from femcam.bodies.cam_model import floating_supports  # noqa: E402
from femcam.bodies.cam_rows import cam_disk_rows, disk_from_case, solve_global  # noqa: E402
from femcam.bodies.cam_study import _contact_at, peak_angle, refined_at  # noqa: E402
from femcam.bodies.contact import arc_load_matrix  # noqa: E402
from femcam.bodies.model import _hoop_rows  # noqa: E402
from femcam.fe.elasticity import assemble_body  # noqa: E402
from femcam.materials import STEEL  # noqa: E402
from femcam.scene import cam_disk_case, load_scene  # noqa: E402


def load() -> str:
    return "load avg " + " ".join(f"{x:.2f}" for x in os.getloadavg())


def circle(R, n=720):
    t = np.linspace(0.0, 2 * math.pi, n, endpoint=False)
    return np.stack([R * np.cos(t), R * np.sin(t)])


def lame() -> float:
    Ro, Ri, p = 0.02, 0.008, 100e6
    geo, bore, th = mesh_cam_disk(outline=circle(Ro), centre=(0.0, 0.0), bore=Ri, n_bore=64, h_max=0.003,
                                  h_bore=2 * math.pi * Ri / 64)
    body = assemble_body(geo, STEEL, supports=floating_supports(bore))
    hoop = _hoop_rows(body, bore, th) @ body.solve(p * arc_load_matrix(body, bore, (0.0, 0.0), True).sum(1))
    return float(np.max(np.abs(hoop / (p * (Ro**2 + Ri**2) / (Ro**2 - Ri**2)) - 1)))


def kirsch() -> float:
    R, Ri, W = 0.02, 0.001, 1e5
    geo, bore, th = mesh_cam_disk(outline=circle(R), centre=(0.0, 0.0), bore=Ri, n_bore=64, h_max=0.002,
                                  h_bore=2 * math.pi * Ri / 64, growth=0.2)
    body = assemble_body(geo, STEEL, supports=floating_supports(bore))
    f = np.zeros(body.n_dofs)
    for s in (1.0, -1.0):
        f[body.basis.nodal_dofs[1, int(np.argmin(np.hypot(geo.points[0], geo.points[1] - s * R)))]] = -s * W
    hoop = _hoop_rows(body, bore, th) @ body.solve(f)
    sx, sy = 2 * W / (math.pi * 2 * R), -6 * W / (math.pi * 2 * R)
    ref = sx + sy - 2 * (sx - sy) * np.cos(2 * th)
    return float(np.max(np.abs(hoop - ref)) / (20 * W / (math.pi * 2 * R)))


def main() -> int:
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} CPUs (shared); {load()}")
    print("\n| check | reference | error | time (s) |\n|---|---|---|---|")
    t0 = time.perf_counter()
    e = lame()
    print(f"| annulus Ro/Ri = 2.5, internal pressure | Lame bore hoop stress | {e:.2e} | "
          f"{time.perf_counter() - t0:.2f} |")
    assert e < 0.01
    t0 = time.perf_counter()
    e = kirsch()
    print(f"| 1 mm hole, 40 mm Brazilian disk | Kirsch hoop round the hole (/ 20W/(pi D)) | {e:.2e} | "
          f"{time.perf_counter() - t0:.2f} |")
    assert e < 0.02
    sc = load_scene(ROOT / "examples" / "seed002_cam_on_shaft.toml")
    case = cam_disk_case(sc)
    disk = disk_from_case(case)
    t0 = time.perf_counter()
    g = CamGlobalModel.build(disk=disk, length=sc.length, plane=sc.plane)
    t_build = time.perf_counter() - t0
    at = sc.analyse(np.array([peak_angle(case.revolution)]))
    t0 = time.perf_counter()
    m, r = refined_at(case, disk, at)
    t_ref = time.perf_counter() - t0
    rg = solve_global(g, *_contact_at(at), np.array([r.F]))
    e_h = rg["hoop_max"][0] / r.hoop_max - 1
    e_s = rg["shaft_p0"][0] / r.shaft_p0 - 1
    print(f"| seed002_cam_on_shaft at the peak force | fully refined model | hoop {e_h:+.2%}, "
          f"shaft p0 {e_s:+.2%} | {t_ref:.2f} |")
    assert abs(e_h) < 0.02 and abs(e_s) < 0.02
    theta = np.radians(np.arange(0.0, 360.0, 1.0))
    st = sc.analyse(theta)
    t0 = time.perf_counter()
    rows = cam_disk_rows(case, st, st.Fc, model=g)
    t_rows = time.perf_counter() - t0
    print(f"\n{load()}")
    print("| model | DOFs | mesh (s) | assembly (s) | factorisation (s) | condensation (s) | total build (s) "
          "| per angle (ms) |\n|---|---|---|---|---|---|---|---|")
    tg = g.timings
    print(f"| global (cam + shaft, {g.psi.size} stations, n_bore {g.theta.size}) | {g.n_dofs} | "
          f"{tg['mesh']:.2f} | {tg['assembly']:.2f} | {tg['factorisation']:.2f} | {tg['condensation']:.2f} | "
          f"{t_build:.2f} | "
          f"{1e3 * t_rows / theta.size:.2f} (360 angles: {t_rows:.2f} s) |")
    tm = m.timings
    print(f"| refined (cam + shaft + roller + local cam), one angle | {m.n_dofs} | {tm['mesh']:.2f} | "
          f"{tm['assembly']:.2f} | {tm['factorisation']:.2f} | {tm['condensation']:.2f} | {t_ref:.2f} | - |")
    k = int(np.nanargmax(rows["hoop_max"]))
    print(f"\nlargest cam bore hoop stress {rows['hoop_max'][k] / 1e6:.1f} MPa at theta = "
          f"{math.degrees(theta[k]):.0f} deg ({math.degrees(rows['hoop_angle'][k]):.1f} deg from the contact "
          f"direction); {load()}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
