r"""Speed against error: femcam FE (single scenes and 360-angle sweeps) against Hertz, with a
half-space influence-coefficient solve of the same line contact as the physical floor.

Run:  python benchmarks/bench_speed_error.py [--quick] [--no-sweeps] [--memory] [--plot PNG]

Case: the seed 002 study model contact (steel/steel, Rr = 10 mm, rho = 20 mm, F = 1500 N over
l = 10 mm, plane strain). Errors relative to Hertz (Johnson 1985 §4.2): p0, a (femcam's ellipse
fit), rms(p - Hertz) / p0 at the contact nodes, and for the FE the subsurface tau1 maximum.

Half-space floor (written here, independent of femcam's FE): the two bodies are elastic
half-spaces loaded by piecewise-constant pressures ``p_j`` on ``n`` equal cells of width
``d`` centred at ``x_j`` over ``|x| <= 2.5 a``; the combined normal surface displacement at the
cell centres (Johnson 1985 eq. 2.25b, both bodies, up to a rigid constant taken into the
approach ``delta``) is

.. math:: u_i = -\frac{2}{\pi E^*}\sum_j p_j \int_{x_j - d/2}^{x_j + d/2} \ln|x_i - s|\,ds,
          \qquad \int \ln|v|\,dv = v\ln|v| - v,

and the contact conditions ``g = h0 + u - delta >= 0``, ``p >= 0``, ``p g = 0``,
``d sum p = F / l`` are solved by an active-set iteration (a dense ``n x n`` solve per
iteration). This is the work a boundary-element code does per cam angle; it has no
subsurface stresses (those would be a closed-form integral per point). ``h0`` is the exact
separation of the two circles.

Sweeps: 360 angles of README command 1 (FE, ``femcam.sweep.sweep`` in memory, cold model
cache, serial) at a/h = 10, 20 (and 26 without ``--quick``): compute time (analytic +
families + verification + solves) and the largest p0 / a error against Hertz over the angles;
the half-space solve of each angle's (F, rho) from the Hertz sweep for comparison; next to the
true errors the largest estimated p0 error of the rows (``err_est_p0``, femcam.sweep.estimate);
then sweeps with ``rtol`` = 1 %, 0.5 % (and 0.1 % without ``--quick``): the a/h the sweep chose,
the time, and the reached true and estimated p0 errors (asserted <= rtol before printing).

``--memory`` (``--memory-only``: nothing else): peak RSS (subprocess, ``VmHWM``) of a Hertz
sweep of 10 000 and 100 000 angles written chunk by chunk to a directory (chunk_size 1000),
and of the FE sweep at a/h = 26 (``--base DIR``: also the femcam checkout in DIR, for a
before/after).

Correctness first: every FE row must meet femcam's accuracy at a/h = 20 (p0 <= 0.3 %,
a <= 1 %, tau1 <= 2 % vs Hertz) and the half-space solve must converge to Hertz (p0 within
0.5 % at n = 201) before anything is timed.
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
STUDY = ROOT / "examples" / "seed002_study_model.toml"
Rr, rho, F, l = 0.01, 0.02, 1500.0, 0.01
E, nu = 210e9, 0.3
E_star = E / (2 * (1 - nu**2))  # two equal plane-strain bodies: 1/E* = 2 (1 - nu^2) / E


def hertz_ap(F_, rho_):
    """Hertz (a, p0) of the line contact (Johnson 1985 eqs. 4.43-4.45)."""
    R = 1.0 / (1.0 / Rr + (0.0 if np.isinf(rho_) else 1.0 / rho_))
    W = F_ / l
    a = np.sqrt(4 * W * R / (np.pi * E_star))
    return a, 2 * W / (np.pi * a)


# -------------------------------------------------------------- half-space influence solve
def _G(v):
    av = np.abs(v)
    return v * np.log(np.where(av > 0, av, 1.0)) - v


def halfspace_solve(F_, rho_, a_ref, a_over_h, width=2.5, max_iter=60):
    """Piecewise-constant half-space line contact (see the module docstring).

    Returns ``(x, p, iterations)``: cell centres (m), pressures (Pa).
    """
    d = a_ref / a_over_h
    n = 2 * int(round(width * a_over_h)) + 1
    x = (np.arange(n) - n // 2) * d
    t = x[:, None] - x[None, :]
    A = -(2.0 / (np.pi * E_star)) * (_G(t + d / 2) - _G(t - d / 2))
    h0 = (Rr - np.sqrt(Rr**2 - x**2)) + (0.0 if np.isinf(rho_) else rho_ - np.sqrt(rho_**2 - x**2))
    W = F_ / l
    active = np.abs(x) < a_ref
    for it in range(1, max_iter + 1):
        I = np.flatnonzero(active)
        m = I.size
        M = np.zeros((m + 1, m + 1))
        M[:m, :m] = A[np.ix_(I, I)]
        M[:m, m] = -1.0
        M[m, :m] = d
        sol = np.linalg.solve(M, np.concatenate([-h0[I], [W]]))
        p = np.zeros(n)
        p[I] = sol[:m]
        g = h0 + A @ p - sol[m]
        new = (p > 0) | ((g < 0) & ~active)
        new &= ~((p < 0) & active)
        if np.array_equal(new, active):
            return x, p, it
        active = new
    raise RuntimeError("half-space active set did not settle")


def fit_ellipse(x, p, threshold=0.2):
    """(a, p0) of the least-squares Hertz ellipse p^2 = c (a^2 - (x - x0)^2) (as femcam fits)."""
    s = p > threshold * p.max()
    c2, c1, c0 = np.polyfit(x[s], p[s] ** 2, 2)
    x0 = -c1 / (2 * c2)
    a2 = x0**2 - c0 / c2
    return float(np.sqrt(a2)), float(np.sqrt(-c2 * a2))


def hs_errors(F_, rho_, n):
    aH, p0H = hertz_ap(F_, rho_)
    x, p, _ = halfspace_solve(F_, rho_, aH, n)
    a, p0 = fit_ellipse(x, p)
    pH = p0H * np.sqrt(np.clip(1 - (x / aH) ** 2, 0, None))
    return {"p0": p0 / p0H - 1, "a": a / aH - 1,
            "rms": float(np.sqrt(np.mean((p - pH) ** 2)) / p0H)}


def best_time(f, repeat=5):
    ts = []
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        ts.append(time.perf_counter() - t)
    return min(ts)


# -------------------------------------------------------------- FE
def fe_scene(n):
    from femcam.fe import ContactModel, MeshOptions, SolverOptions
    from femcam.materials import STEEL

    aH, p0H = hertz_ap(F, rho)
    t = time.perf_counter()
    # a one-off model, as solve_contact builds it (precompute: benchmarks/bench_fe.py --modes)
    m = ContactModel.build(Rr=Rr, rho_ref=rho, cam=STEEL, roller=STEEL, length=l, a_ref=aH,
                           mesh=MeshOptions(a_over_h=n),
                           solver=SolverOptions(stress_operators="per_solve"))
    r = m.solve(F=F, rho=rho)
    tt = time.perf_counter() - t
    from femcam.hertz import LineContact

    hc = LineContact(F=F, length=l, R1=rho, R2=Rr, cam=STEEL, roller=STEEL)
    e = {"p0": r.p0 / p0H - 1, "a": r.a / aH - 1,
         "rms": float(np.sqrt(np.mean((r.p - hc.pressure(r.x)) ** 2)) / p0H),
         "tau1": r.tau1_max.value / hc.max_shear().value - 1}
    return tt, m.n_dofs, e, dict(m.timings)


def fe_sweep(n, rtol=None):
    """A cold 360-angle FE sweep at a/h = n (or chosen for ``rtol``): time, timings, max |p0|
    and |a| errors vs Hertz and the largest p0 estimate over the arc-gap rows, the table, and the
    a/h used."""
    from femcam.sweep import RunOptions, SweepOptions, sweep
    from femcam.sweep.cache import default_cache

    default_cache().clear()  # cold model cache: every family built
    t = time.perf_counter()
    res = sweep(STUDY, SweepOptions(**({"a_over_h": n} if rtol is None else {"rtol": rtol})),
                RunOptions(workers=1))
    tt = time.perf_counter() - t
    tab = res.table
    # arc-gap rows only (as bench_main_job.py): the exact-gap rows at the cam's curvature jumps
    # carry a non-Hertzian pressure, so their difference from Hertz is not an error
    ok = np.isfinite(tab["err_p0"]) & (np.asarray(tab["model"]).astype(str) == "fe_arc")
    est = float(np.nanmax(tab["err_est_p0"][ok]))
    est_all = float(np.nanmax(np.where(np.asarray(tab["status"]).astype(str) == "ok",
                                       tab["err_est_p0"], np.nan)))
    return tt, dict(res.timings), float(np.max(np.abs(tab["err_p0"][ok]))), \
        float(np.max(np.abs(tab["err_a"][ok]))), tab, max(est, est_all), res.provenance["options"]["a_over_h"]


def hs_sweep(tab, n):
    """Half-space solve at every contact angle of a sweep table: (time, max |p0 err|, max |a err|)."""
    Fs, rhos = np.asarray(tab["Fc"]), np.asarray(tab["rho"])
    ok = np.isfinite(np.asarray(tab["err_p0"])) & (Fs > 0)
    t = time.perf_counter()
    errs = [hs_errors(Fi, ri, n) for Fi, ri in zip(Fs[ok], rhos[ok], strict=True)]
    tt = time.perf_counter() - t
    return tt, max(abs(e["p0"]) for e in errs), max(abs(e["a"]) for e in errs)


# -------------------------------------------------------------- memory
MEM_CODE = """
import sys, tempfile, time, numpy as np
from femcam.sweep import RunOptions, SweepOptions, sweep
n, method, a_over_h = int(sys.argv[1]), sys.argv[2], float(sys.argv[3])
th = np.linspace(0, 2 * np.pi, n, endpoint=False)
with tempfile.TemporaryDirectory() as d:
    t = time.perf_counter()
    r = sweep(sys.argv[4], SweepOptions(angles=th, method=method, a_over_h=a_over_h, chunk_size=1000),
              RunOptions(out=d, workers=1))
    t = time.perf_counter() - t
# VmHWM, not ru_maxrss: Linux keeps ru_maxrss across exec, so a child would report its parent's
with open("/proc/self/status") as f:
    hwm = next(int(x.split()[1]) for x in f if x.startswith("VmHWM"))
print(n, t, hwm / 1024)
"""


def mem_run(n, method, a_over_h, src):
    env = dict(os.environ, PYTHONPATH=str(src))
    out = subprocess.run([sys.executable, "-c", MEM_CODE, str(n), method, str(a_over_h),
                          str(STUDY)], capture_output=True, text=True, env=env, cwd=src)
    if out.returncode:
        raise SystemExit(out.stderr)
    _, t, rss = out.stdout.split()
    return float(t), float(rss)


def section_memory(base):
    print("\n## memory: peak RSS of whole sweeps (fresh process, written to disk in chunks of 1000)\n")
    print("| sweep | angles | femcam | time (s) | peak RSS (MB) | load |")
    print("|---|---|---|---|---|---|")
    srcs = [("this branch", ROOT)] + ([("base", Path(base))] if base else [])
    for n in (10_000, 100_000):
        t, rss = mem_run(n, "hertz", 10, ROOT)
        print(f"| Hertz | {n} | this branch | {t:.2f} | {rss:.0f} | {os.getloadavg()[0]:.2f} |", flush=True)
    for lab, src in srcs:
        t, rss = mem_run(360, "fe", 26, src)
        print(f"| FE a/h = 26 | 360 | {lab} | {t:.2f} | {rss:.0f} | {os.getloadavg()[0]:.2f} |", flush=True)


# -------------------------------------------------------------- main
def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--no-sweeps", action="store_true")
    ap.add_argument("--memory", action="store_true")
    ap.add_argument("--memory-only", action="store_true")
    ap.add_argument("--sweeps-only", action="store_true")
    ap.add_argument("--base", default=None, help="another femcam checkout for the memory before/after")
    ap.add_argument("--plot", default=None, help="write the log-log plot to this PNG")
    args = ap.parse_args()
    if args.memory_only:
        section_memory(args.base)
        return 0
    print("# femcam speed vs error (single scenes, sweeps) with the half-space floor")
    print(f"machine: {platform.processor() or platform.machine()}, os.cpu_count() = {os.cpu_count()}, "
          f"load average {' / '.join(f'{x:.2f}' for x in os.getloadavg())} (shared machine)")
    # correctness first
    e = hs_errors(F, rho, 40)
    assert abs(e["p0"]) < 5e-3, f"half-space p0 vs Hertz {e['p0']:+.3%}"
    import femcam.fe  # noqa: F401  (warm imports, not timed)

    _, _, e20, _ = fe_scene(20)
    for k, tol in (("p0", 3e-3), ("a", 1e-2), ("tau1", 2e-2)):
        assert abs(e20[k]) <= tol, f"FE {k} error {e20[k]:+.3%} at a/20"
    print(f"checked: half-space n = a/40 p0 {e['p0']:+.3%}; FE a/20 p0 {e20['p0']:+.3%}, "
          f"a {e20['a']:+.3%}, tau1 {e20['tau1']:+.3%}")

    rows = []
    print("\n## single scene (cold, warm process: mesh + assembly + factorisation + condensation "
          "+ one solve, stress_operators = per_solve; half-space: best of 5)\n")
    print("| method | a/h | DOFs | time (s) | p0 err | a err | rms(p - Hertz)/p0 | τ1 err | load |")
    print("|---|---|---|---|---|---|---|---|---|")
    for n in ([] if args.sweeps_only else [10, 20] if args.quick else [10, 14, 20, 26, 40]):
        tt, nd, e, _ = fe_scene(n)
        rows.append(("FE scene", n, tt, e))
        print(f"| FE | {n} | {nd} | {tt:.2f} | {e['p0']:+.3%} | {e['a']:+.3%} | {e['rms']:.3%} | "
              f"{e['tau1']:+.2%} | {os.getloadavg()[0]:.2f} |", flush=True)
    for n in (() if args.sweeps_only else (10, 20, 40, 80, 160)):
        tt = best_time(lambda n=n: halfspace_solve(F, rho, hertz_ap(F, rho)[0], n))
        e = hs_errors(F, rho, n)
        rows.append(("half-space scene", n, tt, e))
        print(f"| half-space | {n} | {2 * int(round(2.5 * n)) + 1} cells | {tt:.4f} | {e['p0']:+.3%} | "
              f"{e['a']:+.3%} | {e['rms']:.3%} | - | {os.getloadavg()[0]:.2f} |", flush=True)
    if not args.no_sweeps:
        print("\n## 360-angle sweep of the study model (cold model cache, serial, in memory; "
              "FE errors over the arc-gap rows)\n")
        print("| method | a/h | compute (s) | analytic / verify / solves (s) | max abs p0 err | "
              "max abs a err | max p0 estimate | load |")
        print("|---|---|---|---|---|---|---|---|")
        tab = None
        for n in ([10, 20] if args.quick else [10, 20, 26]):
            tt, tm, ep, ea, tab, est, _ = fe_sweep(n)
            rows.append(("FE sweep", n, tt, {"p0": ep, "a": ea, "est p0": est}))
            print(f"| FE | {n} | {tt:.2f} | {tm['analytic']:.2f} / {tm['verify']:.2f} / {tm['compute']:.2f} "
                  f"| {ep:.3%} | {ea:.3%} | {est:.3%} | {os.getloadavg()[0]:.2f} |", flush=True)
        for rtol in (0.01, 0.005) if args.quick else (0.01, 0.005, 0.001):
            tt, tm, ep, ea, _, est, n = fe_sweep(None, rtol)
            # correctness before the time is worth anything: the requested bound holds
            assert ep <= rtol and est <= rtol, f"rtol {rtol:.1%}: true {ep:.3%}, estimate {est:.3%}"
            rows.append(("FE rtol sweep", n, tt, {"p0": ep, "est p0": est}))
            print(f"| FE rtol {100 * rtol:g} % | {n:g} (chosen) | {tt:.2f} | {tm['analytic']:.2f} / "
                  f"{tm['verify']:.2f} / {tm['compute']:.2f} | {ep:.3%} | {ea:.3%} | {est:.3%} | "
                  f"{os.getloadavg()[0]:.2f} |", flush=True)
        for n in (10, 20, 40):
            tt, ep, ea = hs_sweep(tab, n)
            rows.append(("half-space sweep", n, tt, {"p0": ep, "a": ea}))
            print(f"| half-space | {n} | {tt:.2f} | - | {ep:.3%} | {ea:.3%} | {os.getloadavg()[0]:.2f} |",
                  flush=True)
    if args.memory:
        section_memory(args.base)
    if args.plot:
        plot(rows, args.plot)
    return 0


def plot(rows, path):
    import matplotlib

    matplotlib.use("Agg")  # headless
    import matplotlib.pyplot as plt

    fig, axs = plt.subplots(1, 2, figsize=(10, 4))
    styles = {"FE scene": "o-", "half-space scene": "s--", "FE sweep": "o-", "half-space sweep": "s--",
              "FE rtol sweep": "^:"}
    for ax, kind in zip(axs, ("scene", "sweep"), strict=True):
        for lab, st in styles.items():
            if not lab.endswith(kind):
                continue
            rs = sorted((r for r in rows if r[0] == lab), key=lambda r: r[2])  # by time
            if not rs:
                continue
            t = [r[2] for r in rs]
            for key, c in (("p0", "C0"), ("a", "C1"), ("rms", "C2"), ("est p0", "C3")):
                err = [abs(r[3][key]) for r in rs if key in r[3]]
                if len(err) == len(t):
                    ax.loglog(t, err, st, color=c, label=f"{' '.join(lab.split()[:-1])} {key}")
        ax.set_xlabel("wall time (s)")
        ax.set_ylabel("relative error vs Hertz (est: the estimate)")
        ax.set_title("single scene" if kind == "scene" else "360-angle sweep (max over angles)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    print(f"\nplot: {path}")


if __name__ == "__main__":
    raise SystemExit(main())
