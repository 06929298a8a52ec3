"""Benchmark: FE on the real cam (exact gap vs osculating-arc gap vs Hertz) at a curvature jump,
and the cost of a partial-slip solve.

Run:  python benchmarks/bench_real_cam.py [--plots] [--quick]

1. Junction scene (examples/shm_dwell_junction.toml, SHM rise after a dwell at 90 deg): at
   the junction and around it, p0 of Hertz, of the FE with the arc gap and with the exact gap,
   against an independent half-space influence-coefficient solve on the exact gap (uniform
   strips, exact log kernel; Johnson 1985 §2.8). CORRECTNESS FIRST: the exact-gap FE must be
   within 1 % of the reference at every angle, else the benchmark stops. Then the time per
   angle of each model (gap construction included for the exact FE).
2. Partial slip: time of ContactModel.solve with Q (Cattaneo and Carter) minus the time of the
   full-sliding solve, median over repeats (seed 002 study model, a/h = 20); checked first
   against Carter's stick size.
3. The sweep at the junction scene (``femcam.sweep.sweep``, 80..100 deg every 1 deg plus the
   jump refinement): models per angle (method fe and auto), total time and median time per angle
   of each model, and the partial-slip cost in the sweep (median fe_time of the arc-gap rows with
   the mechanism's Q minus the same rows with the ``[contact] sliding`` full-sliding override).
   CORRECTNESS FIRST: the sweep's exact-gap p0 within 1 % of the half-space reference at the
   junction and +-0.1 deg.
4. ``--plots``: docs/img/sweep_junction_p0.png (the sweep's junction rows: Hertz, arc FE, exact
   FE, reference; :func:`femcam.viz.sweep.plot_junction_p0`), docs/img/fe_junction_p0.png
   (p0 vs angle: Hertz, arc FE, exact FE, reference),
   docs/img/fe_carter.png (FE traction vs Carter), docs/img/fe_followers.png (seed 003
   knife-edge with a 2 mm tip and the flat-faced scene: FE p0 over the revolution vs Hertz).

Times depend on the machine load: the header prints it (the machine is shared).
"""

from __future__ import annotations

import math
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

from femcam.fe import ContactModel, MeshOptions, SolverOptions
from femcam.fe.angles import curvature_jumps
from femcam.fe.choice import build_real_cam, solve_angle
from femcam.fe.gap import arc_gap, exact_gap
from femcam.materials import STEEL, effective_modulus
from femcam.scene import load_scene

ROOT = Path(__file__).resolve().parents[1]


def _G(t):
    at = np.abs(t)
    return np.where(at > 0, t * np.log(np.where(at > 0, at, 1.0)), 0.0) - t


def halfspace_p0(h0, W, Es, xmax, n=500):
    """Independent reference: line contact on half-spaces, uniform strips, active set."""
    e = np.linspace(-xmax, xmax, n + 1)
    xc, dx = 0.5 * (e[1:] + e[:-1]), np.diff(e)
    A = -(2 / (math.pi * Es)) * (_G(xc[:, None] - e[None, :-1]) - _G(xc[:, None] - e[None, 1:]))
    g0 = h0(xc)
    act = g0 <= np.sort(g0)[int(0.4 * n)]
    for _ in range(200):
        idx = np.nonzero(act)[0]
        m = idx.size
        M = np.zeros((m + 1, m + 1))
        M[:m, :m], M[:m, m], M[m, :m] = A[np.ix_(idx, idx)], -1.0, dx[idx]
        sol = np.linalg.solve(M, np.concatenate([-g0[idx], [W]]))
        p = np.zeros(n)
        p[idx] = sol[:m]
        new = np.where(act, p > 0, g0 + A @ p - sol[m] < 0)
        if np.array_equal(new, act):
            return float(p.max())
        act = new
    raise RuntimeError("reference did not settle")


def header():
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} CPUs, "
          f"load average {os.getloadavg()[0]:.2f} (shared machine), python {sys.version.split()[0]}")


def junction_table(offsets_deg, a_over_h=20):
    sc = load_scene(ROOT / "examples" / "shm_dwell_junction.toml")
    j = curvature_jumps(sc.program, sc.follower)[0]
    Es = effective_modulus(sc.cam, sc.roller, sc.plane)
    th = j.theta + np.radians(offsets_deg)
    st = sc.analyse(th)
    rc = build_real_cam(program=sc.program, follower=sc.follower, cam=sc.cam, roller=sc.roller,
                        length=sc.length, F_ref=1.0 + float(st.Fc.max()), rho_ref=j.rho_right,
                        mesh=MeshOptions(a_over_h=a_over_h), solver=SolverOptions(eval_depth=0.0))
    m = rc.model
    rows = []
    for t, F, rho in zip(th, st.Fc, st.rho, strict=True):
        t0 = time.perf_counter()
        R = 1 / (1 / 0.01 + 1 / rho)
        a = math.sqrt(4 * F / sc.length * R / (math.pi * Es))
        p_h = 2 * F / sc.length / (math.pi * a)
        t1 = time.perf_counter()
        r_arc = m.solve(F=F, rho=rho, gap=arc_gap(m.x, 0.01, rho), check=False)
        t2 = time.perf_counter()
        g = exact_gap(sc.program, sc.follower, t, m.x)
        r_ex = m.solve(F=F, rho=rho, gap=g, check=False)
        t3 = time.perf_counter()
        ref = halfspace_p0(lambda x, t=t: exact_gap(sc.program, sc.follower, t, x, kind="vertical"),
                           F / sc.length, Es, float(m.x[-1]))
        rows.append((math.degrees(t - j.theta), ref, p_h, r_arc.p0_nodal, r_ex.p0_nodal,
                     t1 - t0, t2 - t1, t3 - t2))
    return rows, m


def carter_check(m, A, P0, mu=0.3, F=1500.0, fs=(0.25, 0.5, 0.75)):
    out = []
    for f in fs:
        r = m.solve(F=F, rho=0.02, mu=mu, Q=f * mu * F, rolling=1)
        c = A * math.sqrt(1 - f)
        assert abs(r.stick_width / 2 - c) <= A / 20, "Carter stick size check failed"
        out.append((f, r))
    return out


def slip_timing(m, F=1500.0, mu=0.3, n=30):
    def med(fn):
        ts = []
        for _ in range(n):
            t0 = time.perf_counter()
            fn()
            ts.append(time.perf_counter() - t0)
        return float(np.median(ts))

    from femcam.fe.traction import solve_partial_slip

    base = med(lambda: m.solve(F=F, rho=0.02, mu=mu))
    catt = med(lambda: m.solve(F=F, rho=0.02, mu=mu, Q=0.5 * mu * F))
    cart = med(lambda: m.solve(F=F, rho=0.02, mu=mu, Q=0.5 * mu * F, rolling=1))
    p = m.solve(F=F, rho=0.02).p
    alone = med(lambda: solve_partial_slip(m.Ctt, m.x, m.w, p, 0.5 * mu * F / m.length, mu, rolling=1,
                                           u0=m.Ctn @ p))
    return base, catt, cart, alone


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    quick = "--quick" in argv
    header()
    offs = [-0.3, -0.2, -0.1, -0.05, 0.0, 0.05, 0.1, 0.2, 0.3] if not quick else [-0.1, 0.0, 0.1]
    rows, _ = junction_table(offs, a_over_h=14 if quick else 20)
    for r in rows:  # correctness before timing
        assert abs(r[4] / r[1] - 1) < 1e-2, f"exact-gap FE off the reference at {r[0]:+.2f} deg"
    print(f"\n1. junction scene (SHM after a dwell, 90 deg), a/h = {14 if quick else 20}; errors vs "
          "half-space reference")
    print("| dtheta (deg) | reference p0 (MPa) | Hertz err % | arc FE err % | exact FE err % | "
          "Hertz (ms) | arc FE (ms) | exact FE incl. gap (ms) |")
    print("|---|---|---|---|---|---|---|---|")
    for d, ref, ph, pa, pe, th_, ta, te in rows:
        print(f"| {d:+.2f} | {ref / 1e6:.1f} | {100 * (ph / ref - 1):+.2f} | {100 * (pa / ref - 1):+.2f} | "
              f"{100 * (pe / ref - 1):+.3f} | {th_ * 1e3:.3f} | {ta * 1e3:.1f} | {te * 1e3:.1f} |")
    Es = effective_modulus(STEEL, STEEL, "strain")
    R = 1 / (1 / 0.01 + 1 / 0.02)
    A = math.sqrt(4 * 1.5e5 * R / (math.pi * Es))
    P0 = 2 * 1.5e5 / (math.pi * A)
    m = ContactModel.build(Rr=0.01, rho_ref=0.02, cam=STEEL, roller=STEEL, length=0.01, a_ref=A,
                           mesh=MeshOptions(a_over_h=20))
    carter = carter_check(m, A, P0)
    base, catt, cart, alone = slip_timing(m, n=10 if quick else 30)
    print(f"\n2. partial slip on the condensed system (n_c = {m.x.size} vertices, a/h = 20), median "
          f"solve time incl. stress recovery; load average {os.getloadavg()[0]:.2f}")
    print("| solve | time (ms) | added vs full sliding (ms) |\n|---|---|---|")
    print(f"| full sliding (mu p) | {base * 1e3:.2f} | - |")
    print(f"| Cattaneo, Q = 0.5 mu P | {catt * 1e3:.2f} | {(catt - base) * 1e3:+.2f} |")
    print(f"| Carter, Q = 0.5 mu P | {cart * 1e3:.2f} | {(cart - base) * 1e3:+.2f} |")
    print(f"| solve_partial_slip alone (Carter) | {alone * 1e3:.2f} | - |")
    sweep_table(quick, plots="--plots" in argv)
    if "--plots" in argv:
        plots(A, P0, carter)


def sweep_table(quick, plots=False):
    import dataclasses

    from femcam.fe.angles import curvature_jumps as jumps_of
    from femcam.sweep import RunOptions, SweepOptions, sweep
    from femcam.sweep.cache import default_cache

    sc = load_scene(ROOT / "examples" / "shm_dwell_junction.toml")
    Es = effective_modulus(sc.cam, sc.roller, sc.plane)
    thj = jumps_of(sc.program, sc.follower)[0].theta
    ang = np.radians(np.arange(80.0, 100.01, 2.0 if quick else 1.0))
    cases = (("fe", "mechanism", sc), ("auto", "mechanism", sc),
             ("fe", "override +x", dataclasses.replace(sc, sliding="+x")))
    res = {}
    for method, trac, scene in cases:
        default_cache().clear()
        t0 = time.perf_counter()
        r = sweep(scene, SweepOptions(angles=ang, method=method), RunOptions(workers=1))
        res[(method, trac)] = (r, time.perf_counter() - t0, os.getloadavg()[0])
    r = res[("fe", "mechanism")][0]
    refs = []
    for d in (-0.1, 0.0, 0.1):  # correctness before timing
        i = int(np.argmin(np.abs(r["theta"] - (thj + math.radians(d)))))
        t, F = float(r["theta"][i]), float(r["Fc"][i])
        ref = halfspace_p0(lambda x, t=t: exact_gap(sc.program, sc.follower, t, x, kind="vertical"),
                           F / sc.length, Es, 3e-4)
        assert abs(r["p0_nodal"][i] / ref - 1) < 1e-2, f"sweep exact-gap p0 off the reference at {d:+} deg"
        refs.append((math.degrees(t), ref, r["p0_nodal"][i]))
    print(f"\n3. sweep of the junction scene, {ang.size} requested angles 80..100 deg + jump refinement "
          f"({r.n_angles} rows), a/h = 10, serial, cold cache")
    print("| method | traction | rows hertz / fe_arc / fe_exact | total (s) | median per angle (ms): "
          "hertz / fe_arc / fe_exact | load |\n|---|---|---|---|---|---|")
    for (method, trac), (rr, tt, load) in res.items():
        m = rr["model"]
        med = [float(np.median(rr["fe_time"][m == k])) * 1e3 if np.any(m == k) else float("nan")
               for k in ("hertz", "fe_arc", "fe_exact")]
        cnt = " / ".join(str(int(np.sum(m == k))) for k in ("hertz", "fe_arc", "fe_exact"))
        print(f"| {method} | {trac} | {cnt} | {tt:.2f} | {med[0]:.2f} / {med[1]:.2f} / {med[2]:.2f} | "
              f"{load:.2f} |")
    a, b = res[("fe", "mechanism")][0], res[("fe", "override +x")][0]
    arc = (a["model"] == "fe_arc") & (b["model"] == "fe_arc")
    print(f"partial slip in the sweep: median fe_time of the {int(arc.sum())} arc-gap rows "
          f"{np.median(a['fe_time'][arc]) * 1e3:.2f} ms (mechanism Q, partial slip) vs "
          f"{np.median(b['fe_time'][arc]) * 1e3:.2f} ms (full sliding): "
          f"{(np.median(a['fe_time'][arc]) - np.median(b['fe_time'][arc])) * 1e3:+.2f} ms per angle")
    print("| dtheta (deg) | reference p0 (MPa) | sweep exact FE p0 (MPa) | error % |\n|---|---|---|---|")
    for t, ref, p in refs:
        print(f"| {t - math.degrees(thj):+.2f} | {ref / 1e6:.1f} | {p / 1e6:.1f} | "
              f"{100 * (p / ref - 1):+.3f} |")
    if plots:
        from femcam.viz.sweep import plot_junction_p0

        rr = sweep(sc, SweepOptions(angles=np.radians([89.0, 91.0])), RunOptions(workers=1))
        deg = np.degrees(rr["theta"][rr["curvature_jump"] == 1])
        ref = [halfspace_p0(lambda x, t=t: exact_gap(sc.program, sc.follower, t, x, kind="vertical"),
                            F / sc.length, Es, 3e-4)
               for t, F in zip(np.radians(deg), rr["Fc"][rr["curvature_jump"] == 1], strict=True)]
        print(plot_junction_p0(rr, ROOT / "docs" / "img" / "sweep_junction_p0.png", reference=(deg, ref)))
        sweep_follower_plots()


def sweep_follower_plots():
    """The p0 plot of a seed 003 knife-edge sweep and of a flat-faced sweep (every 5 deg) ->
    docs/img/sweep_knife_edge_p0.png, docs/img/sweep_flat_faced_p0.png."""
    import shutil
    import tempfile

    from femcam.sweep import RunOptions, SweepOptions, sweep

    for fname, png in (("seed003_knife_edge.toml", "sweep_knife_edge_p0.png"),
                       ("flat_faced.toml", "sweep_flat_faced_p0.png")):
        with tempfile.TemporaryDirectory() as d:
            t0 = time.perf_counter()
            r = sweep(ROOT / "examples" / fname,
                      SweepOptions(angles=np.radians(np.arange(0.0, 360.0, 5.0)), plots=True),
                      RunOptions(out=d, workers=1))
            print(f"{fname}: {r.n_angles} angles in {time.perf_counter() - t0:.1f} s (load "
                  f"{os.getloadavg()[0]:.2f}), models {r.provenance['options']['models']}, max |FE p0 / "
                  f"Hertz - 1| = {100 * np.nanmax(np.abs(r['err_p0'])):.3f} %")
            shutil.copy(r.paths["plot_p0"], ROOT / "docs" / "img" / png)


def plots(A, P0, carter):
    import matplotlib  # lazy: optional plotting dependency

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    img = ROOT / "docs" / "img"
    offs = np.linspace(-0.4, 0.4, 33)
    rows, _ = junction_table(list(offs), a_over_h=14)
    d = np.array([r[0] for r in rows])
    fig, ax = plt.subplots(figsize=(6.4, 4))
    for k, lab, sty in ((2, "Hertz (osculating radius)", "k--"), (3, "FE, arc gap", "C1-"),
                        (4, "FE, exact gap", "C0-"), (1, "half-space reference (exact gap)", "C3o")):
        ax.plot(d, [r[k] / 1e6 for r in rows], sty, label=lab, ms=3)
    ax.set_xlabel("cam angle - junction angle (deg)")
    ax.set_ylabel("peak pressure p0 (MPa)")
    ax.set_title("SHM rise after a dwell: curvature jump at 90 deg")
    ax.legend()
    fig.tight_layout()
    fig.savefig(img / "fe_junction_p0.png", dpi=120)
    fig, ax = plt.subplots(figsize=(6.4, 4))
    xs = np.linspace(-A, A, 400)
    for k, (f, r) in enumerate(carter):
        c = A * math.sqrt(1 - f)
        dd = -(A - c)
        q = 0.3 * P0 * np.sqrt(np.clip(1 - (xs / A) ** 2, 0, None))
        ins = np.abs(xs - dd) < c
        q[ins] -= 0.3 * P0 * (c / A) * np.sqrt(1 - ((xs[ins] - dd) / c) ** 2)
        ax.plot(xs / A, q / (0.3 * P0), f"C{k}-", label=f"Carter, Q/(mu P) = {f:g}")
        ax.plot(r.x / A, r.q / (0.3 * P0), f"C{k}o", ms=3, label=f"FE a/h = 20, Q/(mu P) = {f:g}")
    ax.set_xlim(-1.3, 1.3)
    ax.set_xlabel("x / a (rolling: material enters at x = -a)")
    ax.set_ylabel("q / (mu p0)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(img / "fe_carter.png", dpi=120)
    followers_plot(img, plt)


def followers_plot(img, plt):
    fig, axs = plt.subplots(1, 2, figsize=(9, 3.6))
    for ax, (fname, kw, title) in zip(axs, (
            ("seed003_knife_edge.toml", {"tip_radius": 0.002}, "seed 003 knife-edge, 2 mm tip"),
            ("flat_faced.toml", {"face_length": 0.03}, "flat-faced, 30 mm face")), strict=True):
        sc = load_scene(ROOT / "examples" / fname)
        th = np.radians(np.arange(0.0, 360.0, 5.0))
        st = sc.analyse(th)
        rc = build_real_cam(program=sc.program, follower=sc.follower, cam=sc.cam, roller=sc.roller,
                            length=sc.length, F_ref=float(st.Fc.max()), rho_ref=float(np.median(st.rho)),
                            mesh=MeshOptions(a_over_h=12), solver=SolverOptions(eval_depth=0.0), **kw)
        res = [solve_angle(rc, t, float(F), mu=sc.mu, force_exact=True)
               for t, F in zip(th, st.Fc, strict=True)]
        ax.plot(np.degrees(th), [r.p0_hertz / 1e6 for r in res], "k--", label="Hertz")
        ax.plot(np.degrees(th), [r.p0 / 1e6 for r in res], "C0o", ms=3, label="FE, exact gap (sliding)")
        ax.set_xlabel("cam angle (deg)")
        ax.set_ylabel("p0 (MPa)")
        ax.set_title(title, fontsize=9)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(img / "fe_followers.png", dpi=120)


if __name__ == "__main__":
    main()
