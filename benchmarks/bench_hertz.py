"""Benchmark: analytic Hertz line contact vectorised over cam angles.

Checks correctness first (hand-calculated a and p0 of a steel pair, the textbook frictionless
tau1 maximum, equilibrium of a random case), then times, for n = 10^3 ... 10^5 load cases:

* ``LineContact`` construction (R, E*, w, a, p0, fmax, validity flags),
* the surface stresses (sx, sz, txz) at 5 points per case (x/a = -1, -0.5, 0, 0.5, 1),
* the subsurface field at the tau1-maximum point of every case,
* the scaled maxima (tau1, von Mises, |txz|; the dimensionless optimisation is cached per mu).

Run:  python benchmarks/bench_hertz.py [--figure docs/img/hertz_tau1.png]
"""

from __future__ import annotations

import math
import platform
import time

import numpy as np

from femcam.hertz import LineContact, max_shear, max_von_mises
from femcam.hertz.maxima import _maximise
from femcam.materials import STEEL


def check() -> None:
    hc = LineContact(F=1500.0, length=0.01, R1=0.01, R2=0.01, cam=STEEL, roller=STEEL)
    E_star = 210e9 / (2 * 0.91)
    a = math.sqrt(4 * 1.5e5 * 0.005 / (math.pi * E_star))
    assert abs(hc.a / a - 1) < 1e-13, "a = sqrt(4wR/(pi E*))"
    assert abs(hc.p0 / (2 * 1500 / (math.pi * a * 0.01)) - 1) < 1e-13, "p0 = 2F/(pi a l)"
    m = max_shear(0.0)
    assert abs(m.value - 0.300) < 5e-4 and abs(m.z - 0.786) < 1e-3, "Johnson tau1max"
    x = np.linspace(-1, 1, 200_001) * hc.a
    integral = np.trapezoid(hc.pressure(x), x) * hc.length
    assert abs(integral / hc.F - 1) < 1e-6, "int p dx l = F"


def cases(n: int, rng) -> dict:
    theta = np.linspace(0, 2 * np.pi, n, endpoint=False)
    F = 1500.0 + 800.0 * np.sin(theta) + rng.uniform(0, 50, n)
    rho = 0.02 + 0.012 * np.cos(2 * theta)          # convex cam 8-32 mm
    return dict(F=F, length=0.01, R1=rho, R2=0.01, cam=STEEL, roller=STEEL, mu=0.1)


def best_ms(fn, repeat=7) -> float:
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return 1e3 * min(times)


def main() -> None:
    check()
    rng = np.random.default_rng(0)
    try:
        model = next(line.split(":", 1)[1].strip() for line in open("/proc/cpuinfo")
                     if line.startswith("model name"))
    except (OSError, StopIteration):
        model = platform.processor() or "unknown CPU"
    print(f"machine: {model}, numpy {np.__version__}, python {platform.python_version()}")
    _maximise.cache_clear()
    t = time.perf_counter()
    max_shear(0.1), max_von_mises(0.1, 0.3)
    print(f"dimensionless maxima (tau1 + von Mises, mu = 0.1, first call): "
          f"{1e3 * (time.perf_counter() - t):.1f} ms")
    print()
    print(f"{'n':>8} | {'LineContact':>12} | {'surface x5':>11} | {'subsurface':>11} | "
          f"{'maxima x3':>10} | {'total':>8}   (ms, best of 7)")
    print("-" * 84)
    xs = np.array([-1.0, -0.5, 0.0, 0.5, 1.0])[:, None]
    for n in (1_000, 10_000, 100_000):
        kw = cases(n, rng)
        t_lc = best_ms(lambda kw=kw: LineContact(**kw))
        hc = LineContact(**kw)
        t_surf = best_ms(lambda hc=hc: hc.surface_stress(xs * hc.a))
        m = hc.max_shear()
        t_sub = best_ms(lambda hc=hc, m=m: hc.stress(m.x, m.z).von_mises)
        t_max = best_ms(lambda hc=hc: (hc.max_shear(), hc.max_von_mises(), hc.max_orthogonal_shear()))
        total = t_lc + t_surf + t_sub + t_max
        print(f"{n:>8} | {t_lc:>12.2f} | {t_surf:>11.2f} | {t_sub:>11.2f} | {t_max:>10.2f} | {total:>8.2f}")


def figure(path: str) -> None:
    """Contours of tau1/p0 and von Mises/p0 for mu = 0 and mu = 0.2 (README figure)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from femcam.hertz import StressField, unit_stresses

    X, Z = np.meshgrid(np.linspace(-2, 2, 321), np.linspace(0, 2, 161))
    fig, axes = plt.subplots(2, 2, figsize=(8, 4.6), sharex=True, sharey=True)
    for row, mu in enumerate((0.0, 0.2)):
        sx, sz, txz = unit_stresses(X, Z, mu)
        f = StressField(sx=sx, sz=sz, txz=txz, sy=0.3 * (sx + sz))
        for col, (name, val, m) in enumerate((("tau1", f.tau1, max_shear(mu)),
                                              ("von Mises", f.von_mises, max_von_mises(mu, 0.3)))):
            ax = axes[row, col]
            cs = ax.contourf(X, Z, val, levels=20, cmap="viridis")
            ax.plot(m.x, m.z, "r+", ms=10)
            ax.set_title(f"{name} / p0, mu = {mu:g}: max {m.value:.3f} at "
                         f"({round(m.x, 2) + 0.0:.2f}, {m.z:.2f})",
                         fontsize=8)
            fig.colorbar(cs, ax=ax)
    for ax in axes[:, 0]:
        ax.set_ylabel("z / a (depth)")
    for ax in axes[-1]:
        ax.set_xlabel("x / a (traction on the body in +x)")
    axes[0, 0].invert_yaxis()
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    print(f"figure written: {path}")


if __name__ == "__main__":
    import sys

    main()
    if "--figure" in sys.argv:
        figure(sys.argv[sys.argv.index("--figure") + 1])
