"""Benchmark of coated bodies (femcam.layers): correctness first, then the cost of the layer.

Run:  python benchmarks/bench_layers.py [--quick]

Seed 002 study model load case (steel/steel, Rr = 10 mm, rho = 20 mm, F = 1500 N, l = 10 mm)
with and without a 2.5 um DLC coating on the roller (E = 170 GPa, nu = 0.22). Before timing it
checks: the uncoated FE p0 against Hertz (<= 1 %) and the coated p0 against the uncoated Hertz
p0 (a 2.5 um DLC layer is t/a ~ 0.02: <= 1.5 %). Then it prints, per a/h: DOFs (uncoated,
coated, added by the layer), the build time (mesh + assembly + factorisation + condensation)
and one solve + interface recovery, the ratio coated / uncoated, and the load average (the
machine is shared; times move with the load).
"""

from __future__ import annotations

import os
import platform
import sys
import time

from femcam.fe import ContactModel, MeshOptions
from femcam.hertz import LineContact
from femcam.layers import Coating, build_coated_model, interface_stress
from femcam.materials import STEEL, Material

RR, RHO, L, F = 0.01, 0.02, 0.01, 1500.0
DLC = Coating(thickness=2.5e-6, material=Material(E=170e9, nu=0.22), interface_shear_strength=250e6,
              hardness=18e9)


def _time(build):
    t0 = time.perf_counter()
    m = build()
    t1 = time.perf_counter()
    r = m.solve(F=F, rho=RHO)
    return m, r, t1 - t0, time.perf_counter() - t1


def main(argv):
    quick = "--quick" in argv
    hc = LineContact(F=F, length=L, R1=RHO, R2=RR, cam=STEEL, roller=STEEL)
    a = float(hc.a)
    print(f"# bench_layers  machine: {platform.processor() or platform.machine()}, "
          f"{os.cpu_count()} CPUs (shared), load average {os.getloadavg()[0]:.2f}")
    print(f"Hertz a = {a * 1e6:.1f} um, p0 = {float(hc.p0) / 1e6:.1f} MPa, DLC t = 2.5 um = "
          f"{2.5e-6 / a:.3f} a")
    print("| a/h | DOFs uncoated | DOFs coated | added | build uncoated s | build coated s | "
          "ratio | solve+interface coated s | p0 err uncoated | p0 coated/uncoated | "
          "max interface shear MPa | load |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for aoh in ((10, 20) if quick else (10, 20, 26)):
        mesh = MeshOptions(a_over_h=aoh)
        kw = dict(Rr=RR, rho_ref=RHO, cam=STEEL, roller=STEEL, length=L, a_ref=a, mesh=mesh)
        m0, r0, b0, _ = _time(lambda kw=kw: ContactModel.build(**kw))
        m1, r1, b1, s1 = _time(lambda kw=kw: build_coated_model(coating=DLC, **kw))
        t2 = time.perf_counter()
        it = interface_stress(r1)
        s1 += time.perf_counter() - t2
        e0 = r0.p0_nodal / float(hc.p0) - 1
        e1 = r1.p0_nodal / r0.p0_nodal - 1
        assert abs(e0) <= 1e-2, f"uncoated p0 vs Hertz {e0:.3%}"
        assert abs(r1.p0_nodal / float(hc.p0) - 1) <= 1.5e-2, "coated p0 vs uncoated Hertz"
        print(f"| {aoh} | {m0.n_dofs} | {m1.n_dofs} | {m1.n_dofs - m0.n_dofs} | {b0:.2f} | {b1:.2f} | "
              f"{b1 / b0:.2f} | {s1:.2f} | {e0:+.3%} | {e1:+.3%} | {it.tau_abs_max / 1e6:.1f} | "
              f"{os.getloadavg()[0]:.2f} |")


if __name__ == "__main__":
    main(sys.argv[1:])
