"""Benchmark of femcam.bodies: correctness first, then time (cold build, per-angle solves, sweep).

    PYTHONPATH=. python benchmarks/bench_bodies.py [--quick]

1. Validation errors against closed forms written here (the same references as the tests):
   Roark thin ring (t/R = 0.1, bore stress at 90 deg, Winkler), Brazilian disk (centre stress),
   pin in a hole (conformal Hertz, c = 0.1 mm, elastic pin), rigid-ring needles (Stribeck),
   thick ring on a tight pin vs the solid roller's Hertz p0.
2. Per support type (solid = femcam.fe, pin, needles) on the seed 002 needle-roller example
   (examples/seed002_needle_roller.toml; the pin variant uses the same ring with Rp = Ri - c):
   DOFs, phase times of the cold build, time per angle, a 360-angle ring_rows sweep.
Times are wall-clock on a shared machine: the load average is printed next to them.
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

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from femcam.bodies import RingMeshOptions, RingModel, RollerBearing, solve_ring  # noqa: E402
from femcam.bodies.rows import build_for, ring_rows  # noqa: E402
from femcam.materials import STEEL, Material  # noqa: E402
from femcam.mesh import MeshOptions  # noqa: E402
from femcam.scene import load_scene  # noqa: E402

E_STAR = 1.0 / (2 * (1 - 0.3**2) / 210e9)


def load() -> str:
    return "load avg " + " ".join(f"{x:.2f}" for x in os.getloadavg())


def validation() -> list[tuple]:
    sys.path.insert(0, str(ROOT / "tests"))
    from test_bodies_ring import ring_two_forces, roark_section_90

    rows = []
    t0 = time.perf_counter()
    _, M, s_bore, (Ro, Ri, t) = ring_two_forces(0.1, layers=4)
    _, M_ref, s_ref = roark_section_90(1e5, 1.0, Ro, Ri, t)
    rows.append(("ring, 2 forces (t/R=0.1)", "Roark M(90deg), Winkler bore stress",
                 f"{abs(M / M_ref - 1):.2e}, {abs(s_bore / s_ref - 1):.2e}", time.perf_counter() - t0))
    # pin in a hole, conformal Hertz limit
    t0 = time.perf_counter()
    Ri, c, W = 0.007, 0.1e-3, 1.5e5
    b = RollerBearing(Ro=6 * Ri, Ri=Ri, support="pin", Rp=Ri - c, c=c)
    m = RingModel.build(bearing=b, cam=STEEL, rho_ref=0.05, a_ref=2e-4, length=0.01,
                        ring_mesh=RingMeshOptions(n_bore=512), mesh=MeshOptions(a_over_h=8))
    r = solve_ring(m, F=W * 0.01, rho=0.05)
    a = math.sqrt(4 * W * (Ri - c) * Ri / c / (math.pi * E_STAR))
    rows.append(("pin, c = 0.1 mm (n_bore 512)", "conformal Hertz a, p0",
                 f"{abs(r.pin_a / a - 1):.2e}, {abs(r.pin_p0 / (2 * W / (math.pi * a)) - 1):.2e}",
                 time.perf_counter() - t0))
    # Stribeck
    t0 = time.perf_counter()
    rigid = Material(E=210e9 * 1e5, nu=0.3)
    b = RollerBearing(Ro=0.01, Ri=0.007, support="needles", Rp=0.005, c=0.0, Z=18, r_n=0.001,
                      ring=rigid, pin=None)
    m = RingModel.build(bearing=b, cam=STEEL, rho_ref=0.02, a_ref=1.05e-4, length=0.01,
                        ring_mesh=RingMeshOptions(n_bore=72), mesh=MeshOptions(a_over_h=8))
    r = solve_ring(m, F=1500.0, rho=0.02)
    psi = 2 * math.pi * np.arange(18) / 18
    cs = np.cos(psi)
    ref = 1500.0 / np.sum(cs[cs > 1e-12] ** (1 + 10 / 9))
    rows.append(("needles, rigid ring, Z = 18", "Stribeck Q_max", f"{abs(r.needle_Q_max / ref - 1):.2e}",
                 time.perf_counter() - t0))
    # thick ring on a tight pin -> solid roller
    t0 = time.perf_counter()
    b = RollerBearing(Ro=0.01, Ri=0.003, support="pin", Rp=0.003 - 1e-6, c=1e-6)
    m = RingModel.build(bearing=b, cam=STEEL, rho_ref=0.02, a_ref=1.05e-4, length=0.01)
    r = solve_ring(m, F=1500.0, rho=0.02)
    rows.append(("thick ring, tight pin (a/h=20)", "Hertz solid roller a, p0",
                 f"{abs(r.a / r.hertz_a - 1):.2e}, {abs(r.p0 / r.hertz_p0 - 1):.2e}",
                 time.perf_counter() - t0))
    return rows


def support_table(n_angles: int) -> list[tuple]:
    from femcam.fe import solve_contact

    sc = load_scene(ROOT / "examples" / "seed002_needle_roller.toml")
    theta = np.radians(np.linspace(0.0, 360.0, n_angles, endpoint=False))
    st = sc.analyse(theta)
    k = int(np.argmax(st.Fc))
    out = []
    t0 = time.perf_counter()
    rs = solve_contact(st.Fc[k], st.rho[k], 0.01, sc.cam, sc.roller, sc.length)
    out.append(("solid (femcam.fe)", rs.n_dofs, rs.timings, time.perf_counter() - t0, math.nan, math.nan,
                f"p0 vs Hertz {abs(rs.p0 / rs.hertz_p0 - 1):.1e}"))
    needles = sc.bodies.roller
    pin = dataclasses.replace(needles, support="pin", Rp=needles.Ri - 10e-6, c=10e-6, Z=0, r_n=0.0)
    for label, support in (("pin, c = 10 um", pin), ("needles, Z = 18", needles)):
        t0 = time.perf_counter()
        m = build_for(support, sc.pair, st.Fc, st.rho)
        r = solve_ring(m, F=st.Fc[k], rho=st.rho[k])
        t_cold = time.perf_counter() - t0
        t1 = time.perf_counter()
        rows = ring_rows(support, sc.pair, theta, st.Fc, st.rho, model=m)
        t_sweep = time.perf_counter() - t1
        solves = n_angles * (2 if support.support == "needles" else 1)
        out.append((label, m.n_dofs, m.timings, t_cold, t_sweep, t_sweep / solves,
                    f"p0 vs Hertz {abs(r.p0 / r.hertz_p0 - 1):.1e}; bore max "
                    f"{np.nanmax(rows['hoop_max']) / 1e6:.0f} MPa"))
    return out


def main(argv=None) -> int:
    quick = "--quick" in (argv or sys.argv[1:])
    print(f"# femcam.bodies benchmark - {platform.node()} {platform.machine()}, {os.cpu_count()} cores, "
          f"shared machine; {load()}")
    print("\n## Validation (checked before timing)\n")
    print("| case | reference | rel. error | time (s) |\n|---|---|---|---|")
    for case, ref, err, t in validation():
        print(f"| {case} | {ref} | {err} | {t:.2f} |")
    print(f"\n({load()})")
    n = 36 if quick else 360
    print(f"\n## Support types on the seed 002 needle roller ({n}-angle sweep)\n")
    print("| support | DOFs | mesh | assembly | factorisation | condensation | cold build + 1 solve (s) "
          f"| {n}-angle ring_rows (s) | per solve (ms) | check |\n|---|---|---|---|---|---|---|---|---|---|")
    for label, nd, tm, tc, ts, tper, chk in support_table(n):
        ph = [tm.get(k, math.nan) for k in ("mesh", "assembly", "factorisation", "condensation")]
        print(f"| {label} | {nd} | " + " | ".join(f"{x:.2f}" for x in ph) +
              f" | {tc:.2f} | {ts:.2f} | {tper * 1e3:.1f} | {chk} |")
    print(f"\n({load()})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
