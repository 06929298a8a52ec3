"""Benchmark: finite-length half-space contact (DC-FFT + conjugate gradients) on seed 002.

Checks correctness first (3D Hertz sphere on flat; 2D Hertz at mid-length of a long straight
roller), then times on the default 128 (axial) x 64 (rolling) grid:

* one angle, cold (kernel FFT built) and warm (kernel cached, CG warm-started);
* a 360-angle sweep of seed 002 for the none / circular / logarithmic crowns, on one process and
  on two processes (each half of the revolution, contiguous so the warm start still helps);
* the CG tolerance: peak pressure of the sweep at tol = 1e-5 (default) against 1e-7.

With ``--figures DIR`` it also writes the plots of ``docs/halfspace.md``: the pressure map at the
worst angle, the peak pressure along the length against cam angle for the three crowns, and the
crown comparison against misalignment at the worst angle.

Run:  python benchmarks/bench_halfspace.py [--figures docs/img]
"""

from __future__ import annotations

import argparse
import dataclasses
import math
import os
import platform
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

from femcam.halfspace import HalfSpace
from femcam.halfspace.crown import RollerProfile, log_drop
from femcam.halfspace.rows import finite_length_rows
from femcam.halfspace.strip import FiniteLengthContact
from femcam.scene import finite_case, load_scene
from femcam.scene.finite import FiniteLength

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "examples" / "seed002_study_model.toml"
E_STAR = 210e9 / (2 * 0.91)


def check() -> dict:
    R, W, n = 0.01, 100.0, 65
    a = (3 * W * R / (4 * E_STAR)) ** (1 / 3)
    p0 = 3 * W / (2 * math.pi * a * a)
    dx = 2.6 * a / n
    x = (np.arange(n) - (n - 1) / 2) * dx
    X, Y = np.meshgrid(x, x, indexing="ij")
    s = HalfSpace(nx=n, ny=n, dx=dx, dy=dx, E_star=E_STAR).solve((X**2 + Y**2) / (2 * R), W, tol=1e-8)
    m = X**2 + Y**2 < (0.8 * a) ** 2
    c = np.polyfit((X**2 + Y**2)[m], s.p[m] ** 2, 1)
    e_p0, e_a = math.sqrt(c[1]) / p0 - 1, math.sqrt(-c[1] / c[0]) / a - 1
    assert abs(e_p0) < 5e-3 and abs(e_a) < 5e-3, "3D Hertz"
    fl = FiniteLengthContact(RollerProfile(width=0.01), cam_width=0.01, E_star=E_STAR, tol=1e-8)
    r = fl.solve(1500.0, 0.005)
    j = fl.ny // 2
    e_2d = r.p_line[j] / math.sqrt(r.w[j] * E_STAR / (math.pi * 0.005)) - 1
    assert abs(e_2d) < 5e-3, "2D Hertz at mid-length"
    return {"sphere p0": e_p0, "sphere a": e_a, "mid-length 2D p0": e_2d}


def crowned(sc, crown, drop=None, misalignment=None):
    fl = FiniteLength(roller_width=sc.length, cam_width=sc.length, crown=crown, crown_drop=drop,
                      misalignment=misalignment)
    return dataclasses.replace(sc, finite_length=fl)


def rows_of(sc, th, *, tol=1e-5):
    """The half-space rows of scene ``sc`` at ``th`` (rad): its roller's strip, its state."""
    st = sc.analyse(th)
    return finite_length_rows(finite_case(sc).strip(tol=tol), th, st.Fc, st.rho, sc.follower.Rr)


def log_end_drop(sc) -> float:
    """End drop of the logarithmic crown designed for the cycle's peak force (for a circular
    crown of the same drop)."""
    st = sc.analyse(np.linspace(0, 2 * math.pi, 720, endpoint=False))
    i = int(np.argmax(st.Fc))
    R = 1 / (1 / st.rho[i] + 1 / sc.follower.Rr)
    b = math.sqrt(4 * st.Fc[i] / sc.length * R / (math.pi * E_STAR))
    return float(log_drop(sc.length / 2, sc.length, st.Fc[i], b, E_STAR))


def _half(args):
    sc, th = args
    return rows_of(sc, th)


def sweep_two(sc, th):
    with ProcessPoolExecutor(2) as ex:
        parts = list(ex.map(_half, [(sc, th[: th.size // 2]), (sc, th[th.size // 2:])]))
    return {k: np.concatenate([parts[0][k], parts[1][k]]) for k in ("p_axial_peak", "iterations")}


def timing(sc, th, drop):
    cpu = platform.processor() or platform.machine()
    print(f"\n360-angle sweep, seed 002, 128 x 64 grid (machine: {cpu}, {os.cpu_count()} cores, shared "
          "with other jobs)")
    print(f"{'crown':<12} {'1 proc (s)':>10} {'ms/angle':>9} {'CG it':>6} {'2 procs (s)':>11} "
          f"{'max p (MPa)':>11}  load avg")
    out = {}
    for crown in ("none", "circular", "logarithmic"):
        s2 = crowned(sc, crown, drop if crown == "circular" else None)
        t = time.perf_counter()
        rows = rows_of(s2, th)
        t1 = time.perf_counter() - t
        t = time.perf_counter()
        two = sweep_two(s2, th)
        t2 = time.perf_counter() - t
        assert np.allclose(two["p_axial_peak"], rows["p_axial_peak"], rtol=1e-3)
        print(f"{crown:<12} {t1:10.2f} {t1 / th.size * 1e3:9.1f} {np.mean(rows['iterations']):6.1f} "
              f"{t2:11.2f} {np.nanmax(rows['p_axial_peak']) * 1e-6:11.0f}  "
              f"{' '.join(f'{x:.2f}' for x in os.getloadavg())}")
        out[crown] = rows
    return out


def single(sc):
    fl = finite_case(crowned(sc, "logarithmic")).strip()
    t = time.perf_counter()
    r = fl.solve(2000.0, 0.006)
    cold = time.perf_counter() - t
    t = time.perf_counter()
    r2 = fl.solve(2010.0, 0.006, p_start=r.p)
    warm = time.perf_counter() - t
    print(f"\none angle, 128 x 64: cold {cold * 1e3:.1f} ms ({r.iterations} CG it), warm {warm * 1e3:.1f} ms "
          f"({r2.iterations} CG it); load avg {os.getloadavg()[0]:.2f}")


def figures(sc, rows, drop, outdir: Path):
    from femcam.viz.halfspace import plot_crown_comparison, plot_peak_along_length, plot_pressure_map

    p0 = np.sqrt(rows["none"]["Fc"] / sc.length * E_STAR / (math.pi * rows["none"]["R"]))
    i = int(np.nanargmax(p0))                       # worst angle of the 2D model
    th_w, F, R = rows["none"]["theta"][i], rows["none"]["Fc"][i], rows["none"]["R"][i]
    plot_peak_along_length({f"{c}": r for c, r in rows.items()}, outdir / "halfspace_peak_vs_angle.png",
                           p0_2d=p0, title="seed 002: peak pressure along the length (128 x 64 grid)")
    strips = {c: finite_case(crowned(sc, c, drop if c == "circular" else None)).strip() for c in rows}
    res = {c: fl.solve(F, R) for c, fl in strips.items()}
    plot_pressure_map(res["none"], outdir / "halfspace_map_worst.png",
                      title=f"straight roller, seed 002 worst angle {math.degrees(th_w):.0f} deg: "
                            f"peak {res['none'].p_max * 1e-6:.0f} MPa at the end")
    tilts = np.array([0.0, 0.005, 0.01, 0.02, 0.05, 0.1])
    peaks = {}
    for c in rows:
        pk = []
        for g in tilts:
            s2 = crowned(sc, c, drop if c == "circular" else None, math.radians(g))
            pk.append(finite_case(s2).strip().solve(F, R).p_max)
        peaks[c] = np.array(pk)
    plot_crown_comparison(res["none"].y, {c: r.p_line for c, r in res.items()}, tilts, peaks,
                          outdir / "halfspace_crowns.png", p0_2d=p0[i],
                          title=f"seed 002 worst angle {math.degrees(th_w):.0f} deg, Fc = {F:.0f} N, "
                                f"R = {R * 1e3:.2f} mm; circular drop = log end drop {drop * 1e6:.1f} um")
    print(f"\nworst angle {math.degrees(th_w):.1f} deg (2D p0 {p0[i] * 1e-6:.0f} MPa), "
          "axial peak (MPa) vs tilt:")
    print("tilt (deg) " + " ".join(f"{g:>7g}" for g in tilts))
    for c, pk in peaks.items():
        print(f"{c:<10} " + " ".join(f"{x * 1e-6:7.0f}" for x in pk))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--figures", type=Path, default=None)
    args = ap.parse_args(argv)
    print("correctness (relative errors):", {k: f"{v:+.2e}" for k, v in check().items()})
    sc = load_scene(SCENE)
    drop = log_end_drop(sc)
    single(sc)
    th = np.radians(np.arange(360.0))
    rows = timing(sc, th, drop)
    fine = rows_of(crowned(sc, "logarithmic"), th, tol=1e-7)
    dev = np.nanmax(np.abs(rows["logarithmic"]["p_axial_peak"] / fine["p_axial_peak"] - 1))
    print(f"\ntol 1e-5 vs 1e-7 (logarithmic sweep): max relative change of the axial peak {dev:.1e}")
    if args.figures:
        args.figures.mkdir(parents=True, exist_ok=True)
        figures(sc, rows, drop, args.figures)


if __name__ == "__main__":
    main()
