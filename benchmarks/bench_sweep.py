"""Benchmark of the FE sweep (docs/sweep.md): reuse vs naive, reuse error, tolerance, scaling, Bezier.

Run:  python benchmarks/bench_sweep.py [--markdown] [--quick] [--full-naive] [--bezier]

Prints the machine (CPU, cores, Python, library versions) and the load average (other jobs on
a shared machine only ever add time), then:

1. **Correctness first** -- one cold 360-angle FE sweep of the seed 002 study model in a fresh
   interpreter; every angle must solve and the FE p0 must be within 0.3 % of Hertz at every
   angle, else the script stops before timing anything.
2. **Main case, timed** -- the same sweep, cold (fresh interpreter, empty model cache, meshing,
   family verification, assembly, factorisation, condensation included), serial, best of
   ``--repeat``.
3. **Naive path** -- a fresh mesh + factorisation at every angle (model built for that angle's
   own rho and Hertz a), on 36 angles (every 10 deg; ``--full-naive``: all 360). Its p0 must
   also be within 0.3 % of Hertz. The 360-angle time is measured with ``--full-naive``, else
   extrapolated as ``360 x`` the measured mean time per angle (said so in the table).
4. **Reuse error** -- at the naive angles, p0 of the sweep (family model) minus p0 of the fresh
   model: an independent measurement of the quantity ``--tolerance`` bounds (the sweep itself
   verifies it only at each family's checked angles).
5. **Tolerance** -- families, verification time and measured reuse error against
   ``--tolerance``.
6. **Scaling** -- time against the number of angles, mesh size a/h and workers.
7. ``--bezier``: the study model with bezier5/7/9 (same beta): peaks of Fc, phi, p0, von Mises,
   tau1; writes ``docs/img/sweep_bezier.png``.

``--markdown`` prints every table as Markdown (for the README); the default is aligned text.
Nothing here is asserted in tests.
"""

from __future__ import annotations

import argparse
import importlib
import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
STUDY = ROOT / "examples" / "seed002_study_model.toml"
P0_LIMIT = 3e-3  # FE p0 within 0.3 % of Hertz at every angle (docs/sweep.md)

MD = False  # set by --markdown


def table(headers, rows, title=None):
    """Print a table as Markdown (``--markdown``) or as aligned text."""
    rows = [[str(c) for c in r] for r in rows]
    if title:
        print(f"\n{'## ' if MD else ''}{title}\n")
    if MD:
        print("| " + " | ".join(headers) + " |")
        print("|" + "|".join("---" for _ in headers) + "|")
        for r in rows:
            print("| " + " | ".join(r) + " |")
        return
    w = [max(len(h), *(len(r[j]) for r in rows)) if rows else len(h) for j, h in enumerate(headers)]
    print("  ".join(h.ljust(w[j]) for j, h in enumerate(headers)))
    print("  ".join("-" * w[j] for j in range(len(headers))))
    for r in rows:
        print("  ".join(c.ljust(w[j]) for j, c in enumerate(r)))


def machine() -> str:
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    try:
        n_avail = len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover
        n_avail = os.cpu_count()
    libs = []
    for mod, name in (("numpy", "numpy"), ("scipy", "scipy"), ("skfem", "scikit-fem"), ("gmsh", "gmsh")):
        try:
            libs.append(f"{name} {importlib.import_module(mod).__version__}")
        except Exception:  # pragma: no cover
            libs.append(f"{name} ?")
    return (f"{cpu}, {os.cpu_count()} logical cores ({n_avail} available), "
            f"Python {platform.python_version()}, " + ", ".join(libs))


def load() -> str:
    try:
        l1, l5, l15 = os.getloadavg()
        return f"load average {l1:.2f} / {l5:.2f} / {l15:.2f} (1 / 5 / 15 min)"
    except OSError:  # pragma: no cover
        return "load average n/a"


# ---------------------------------------------------------------------------------------------
# cold runs in a fresh interpreter
# ---------------------------------------------------------------------------------------------
_COLD = """
import time, json, sys
t0 = time.perf_counter()
import numpy as np
from femcam.scene import load_scene
from femcam.sweep import RunOptions, SweepOptions, sweep, parse_angles_deg
args = json.loads(sys.argv[2])
sc = load_scene(args["scene"])
if args["law"]:
    sc = sc.with_law(args["law"])
t1 = time.perf_counter()
r = sweep(sc, SweepOptions(angles=parse_angles_deg(args["angles"]), a_over_h=args["a_over_h"],
                          tolerance=args["tolerance"]), RunOptions(workers=args["workers"]))
t2 = time.perf_counter()
np.savez(sys.argv[1], **{k: np.asarray(v) for k, v in r.table.items()})
print(json.dumps({"sweep": t2 - t1, "process": t2 - t0, "verify": r.timings.get("verify", 0.0),
                  "families": len(r.families), "reuse_error": r.reuse_error,
                  "workers": r.provenance["options"]["workers"]}))
"""


def cold_once(angles="0:360:1", a_over_h=10.0, workers=1, law=None, tolerance=2e-3):
    args = {"scene": str(STUDY), "law": law, "angles": angles, "a_over_h": a_over_h,
            "workers": workers, "tolerance": tolerance}
    with tempfile.TemporaryDirectory() as d:
        out = Path(d) / "t.npz"
        res = subprocess.run([sys.executable, "-c", _COLD, str(out), json.dumps(args)],
                             capture_output=True, text=True)
        if res.returncode != 0:
            raise SystemExit(f"cold sweep failed:\n{res.stderr}")
        info = json.loads(res.stdout.strip().splitlines()[-1])
        with np.load(out) as z:
            tab = {k: z[k] for k in z.files}
    return info, tab


def cold_best(repeat, **kw):
    """Best (minimum) of ``repeat`` cold runs: the usual statistic on a shared machine."""
    runs = [cold_once(**kw) for _ in range(repeat)]
    info = min((r[0] for r in runs), key=lambda i: i["sweep"])
    return info, runs[0][1]


def check_correct(tab, what):
    ok = tab["status"] == "ok"
    if not ok.all():
        raise SystemExit(f"{what}: {np.count_nonzero(~ok)} angle(s) did not solve")
    err = float(np.nanmax(np.abs(tab["err_p0"])))
    if not err <= P0_LIMIT:
        raise SystemExit(f"{what}: FE p0 off Hertz by {100 * err:.3f} % > {100 * P0_LIMIT:.1f} %")
    return err


def naive(scene, theta, a_over_h=10.0):
    """Fresh model per angle (exact rho and Hertz a), timed per angle; the tangential traction is
    the sweep's (the mechanism's Q, partial slip), so the reuse error compares like with like."""
    from femcam.sweep.cache import build_model
    from femcam.sweep.options import ResolvedOptions, contact_params
    from femcam.sweep.plan import hertz_half_width
    from femcam.sweep.realcam import scene_traction, traction_args

    cp = contact_params(scene)
    st = scene.analyse(theta)
    tr = scene_traction(scene, theta)
    opts = ResolvedOptions(a_over_h=a_over_h)
    rows = []
    t0 = time.perf_counter()
    for i, (F, rho) in enumerate(zip(st.Fc, st.rho, strict=True)):
        a = float(hertz_half_width(np.array([F]), np.array([rho]), cp)[0])
        m = build_model(cp, float(rho), a, opts)
        sl, Q, roll = traction_args(tr, i, cp.sliding)
        r = m.solve(F=float(F), rho=float(rho), mu=cp.mu, sliding=sl, Q=Q,
                    rolling=roll if Q is not None else 0)
        rows.append((r.p0_nodal, r.a, r.von_mises_max.value, r.tau1_max.value, r.hertz_p0, r.hertz_a))
    dt = (time.perf_counter() - t0) / len(theta)
    return dt, np.array(rows)


def main(argv=None):
    global MD
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--markdown", action="store_true", help="print the tables as Markdown")
    ap.add_argument("--quick", action="store_true", help="skip the tolerance and scaling tables")
    ap.add_argument("--full-naive", action="store_true",
                    help="run the naive path on all 360 angles (~3 min) instead of 36")
    ap.add_argument("--bezier", action="store_true", help="seed 002 Bezier 5/7/9 comparison")
    ap.add_argument("--repeat", type=int, default=3, help="cold runs per timed case (min reported)")
    ap.add_argument("--img", default=str(ROOT / "docs" / "img"), help="where to put PNGs")
    args = ap.parse_args(argv)
    MD = args.markdown

    from femcam.scene import load_scene
    from femcam.sweep import parse_angles_deg

    t_bench = time.perf_counter()
    print(f"machine: {machine()}")
    print(f"at start: {load()}")
    scene = load_scene(STUDY)

    # 1. correctness before timing -------------------------------------------------------------
    info0, tab = cold_once()
    err_fe = check_correct(tab, "360-angle sweep")
    print(f"\ncorrectness: 360/360 angles solved, max |FE p0 / Hertz - 1| = {100 * err_fe:.3f} % "
          f"<= 0.3 %; {info0['families']} families, reported reuse error "
          f"{100 * info0['reuse_error']:.3f} % (tolerance 0.2 %)")

    # 2. main case, timed ------------------------------------------------------------------------
    info, tab_t = cold_best(args.repeat)
    check_correct(tab_t, "timed sweep")
    t_angle = info["sweep"] / tab["theta"].size
    table(["quantity", "value"], [
        ["sweep() wall time, 360 angles, incl. meshing and family verification",
         f"{info['sweep']:.2f} s (target <= 5 s)"],
        ["of which family verification (model builds, fresh-model checks, the solves the "
         "chunks then reuse)", f"{info['verify']:.2f} s"],
        ["whole process incl. Python/numpy/scipy/gmsh imports", f"{info['process']:.2f} s"],
        ["model families (verified)", f"{info['families']}"],
        ["largest reuse error at the checked angles", f"{100 * info['reuse_error']:.3f} %"],
        ["time per angle", f"{1e3 * t_angle:.2f} ms"],
        ["max abs FE p0 - Hertz, 360 angles", f"{100 * err_fe:.3f} % (target <= 0.3 %)"],
        ["max abs FE a - Hertz", f"{100 * np.nanmax(np.abs(tab['err_a'])):.3f} %"],
    ], title=f"360-angle sweep of the seed 002 study model (cold, serial, a/h = 10, tolerance "
             f"2e-3, best of {args.repeat})")

    # 3. naive path ----------------------------------------------------------------------------
    spec = "0:360:1" if args.full_naive else "0:360:10"
    th_n = parse_angles_deg(spec)
    dt_naive, nv = naive(scene, th_n)
    e_naive = np.abs(nv[:, 0] / nv[:, 4] - 1)
    if not np.all(e_naive <= P0_LIMIT):
        raise SystemExit(f"naive path: FE p0 off Hertz by {100 * e_naive.max():.3f} % > 0.3 %")
    n_n = th_n.size
    naive_360 = (f"{360 * dt_naive:.0f} s (measured)" if n_n == 360 else
                 f"{360 * dt_naive:.0f} s (extrapolated: 360 x the mean of {n_n} angles)")
    table(["path", "time per angle", "360 angles", "max abs p0 error vs Hertz"], [
        ["femcam (verified families, reuse)", f"{1e3 * t_angle:.2f} ms",
         f"{info['sweep']:.2f} s (measured)", f"{100 * err_fe:.3f} % (360 angles)"],
        [f"naive: fresh mesh + factorisation per angle (measured on {n_n} angles)",
         f"{1e3 * dt_naive:.0f} ms", naive_360, f"{100 * e_naive.max():.3f} % ({n_n} angles)"],
    ], title="Reuse vs naive (fresh mesh + factorisation at every angle)")
    print(f"\nspeed-up per angle: {dt_naive / t_angle:.0f}x (target >= 40x)")

    # 4. reuse error at the naive angles ------------------------------------------------------------
    idx = np.round(np.degrees(th_n)).astype(int)  # rows of the 1-deg sweep
    # rows the sweep answered with the exact profile gap compare another gap: left out
    arc = np.asarray(tab["model"]).astype(str)[idx] == "fe_arc"
    dd = np.array([(tab["p0_fe"][i] / nv[k, 0] - 1, tab["a_fe"][i] / nv[k, 1] - 1,
                    tab["vm_max"][i] / nv[k, 2] - 1, tab["tau1_max"][i] / nv[k, 3] - 1)
                   if arc[k] else (np.nan,) * 4 for k, i in enumerate(idx)])
    show = [k for k, i in enumerate(idx) if i % 30 == 0 and arc[k]]
    rows = [[str(idx[k])] + [f"{100 * x:+.3f} %" for x in dd[k]] for k in show]
    rows.append([f"max abs, {int(arc.sum())} arc-gap angles of {n_n}"]
                + [f"{100 * x:.3f} %" for x in np.nanmax(np.abs(dd), axis=0)])
    table(["theta (deg)", "p0", "a", "von Mises max", "tau1 max"], rows,
          title=f"Reuse error: family model minus fresh model at the same angle (every 30 deg "
                f"shown; max over {n_n} angles; tolerance on p0: 0.2 %)")

    if not args.quick:
        # 5. tolerance ---------------------------------------------------------------------------
        rows = []
        for tol in (5e-3, 2e-3, 1e-3, 5e-4):
            inf, t = cold_once(tolerance=tol)
            d = np.abs(t["p0_fe"][idx] / nv[:, 0] - 1)[arc]  # arc-gap rows (see above)
            rows.append([f"{tol:g}", inf["families"], f"{inf['verify']:.2f} s", f"{inf['sweep']:.2f} s",
                         f"{100 * inf['reuse_error']:.3f} %", f"{100 * d.max():.3f} %",
                         f"{100 * np.nanmax(np.abs(t['err_p0'])):.3f} %"])
        table(["tolerance", "families", "of which verify", "sweep time", "reuse error (checked)",
               f"reuse error ({n_n} independent angles)", "max abs p0 err vs Hertz"], rows,
              title="Tolerance: verified families (360 angles, a/h = 10, cold, one run each)")

        # 6. scaling ---------------------------------------------------------------------------
        rows = []
        cases = [("0:360:10", 10, 1), ("0:360:4", 10, 1), ("0:360:2", 10, 1), ("0:360:1", 10, 1),
                 ("0:360:0.5", 10, 1), ("0:360:1", 10, 2), ("0:360:0.25", 10, 1),
                 ("0:360:0.25", 10, 2), ("0:360:0.25", 10, "auto"), ("0:360:1", 6, 1),
                 ("0:360:1", 8, 1), ("0:360:1", 14, 1), ("0:360:1", 20, 1)]
        for spec_s, aoh, w in cases:
            inf, t = cold_best(args.repeat, angles=spec_s, a_over_h=aoh, workers=w)
            n = t["theta"].size
            wlabel = f"auto -> {inf['workers']}" if w == "auto" else str(w)
            rows.append([n, aoh, wlabel, inf["families"], f"{inf['verify']:.2f} s",
                         f"{inf['sweep']:.2f} s", f"{1e3 * inf['sweep'] / n:.2f} ms",
                         f"{100 * inf['reuse_error']:.3f} %",
                         f"{100 * np.nanmax(np.abs(t['err_p0'])):.3f} %"])
        table(["angles", "a/h", "workers", "families", "of which verify", "sweep time", "per angle",
               "reuse error (checked)", "max abs p0 err vs Hertz"], rows,
              title=f"Scaling (fresh interpreter per run, best of {args.repeat}; sweep() time incl. "
                    "meshing and verification)")

    if args.bezier:
        bezier(args.img, args.repeat)
    print(f"\nat end: {load()}; benchmark wall time {time.perf_counter() - t_bench:.0f} s")


def bezier(img_dir, repeat=1):
    """Seed 002 comparison: the same study model with bezier5, bezier7, bezier9."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from femcam.kinematics import law

    rows = []
    fig, axs = plt.subplots(1, 3, figsize=(12, 3.6))
    for name, c in (("bezier5", "C0"), ("bezier7", "C1"), ("bezier9", "C2")):
        _, t = cold_once(law=name)
        L = law(name)
        deg = np.degrees(t["theta"])
        rho = np.where(t["rho"] > 0, t["rho"], np.inf)
        s1max = np.max(np.abs(t["v"])) / (600 * 2 * np.pi / 60)  # s' = v / omega
        i = int(np.nanargmax(t["p0_fe"]))
        rows.append([name, f"{L.Cv:.3f}", f"{L.Ca:.3f}", f"{1e3 * s1max:.2f}",
                     f"{np.degrees(np.max(np.abs(t['phi']))):.2f}", f"{1e3 * np.min(rho):.2f}",
                     f"{np.max(t['Fc']):.1f}", f"{np.nanmax(t['p0_fe']) / 1e6:.1f}",
                     f"{np.nanmax(t['p0_hertz']) / 1e6:.1f}", f"{np.nanmax(t['vm_max']) / 1e6:.1f}",
                     f"{np.nanmax(t['tau1_max']) / 1e6:.1f}", f"{deg[i]:.0f}"])
        axs[0].plot(deg, t["p0_fe"] / 1e6, color=c, label=name)
        axs[1].plot(deg, np.degrees(t["phi"]), color=c, label=name)
        axs[2].plot(deg, 1e-3 / t["rho"], color=c, label=name)
    table(["law", "Cv", "Ca", "max s' (mm/rad)", "max phi (deg)", "min rho (mm)", "max Fc (N)",
           "max p0 FE (MPa)", "max p0 Hertz (MPa)", "max von Mises (MPa)", "max tau1 (MPa)",
           "angle of max p0 (deg)"], rows,
          title="Seed 002: Bezier degree 5 / 7 / 9, same beta (FE sweep, 1 deg, a/h = 10)")
    axs[0].set_ylabel("FE peak pressure p0 (MPa)")
    axs[1].set_ylabel("pressure angle phi (deg)")
    axs[2].set_ylabel("cam curvature 1/rho (1/mm)")
    for ax in axs:
        ax.set_xlabel("cam angle theta (deg)")
        ax.set_xlim(0, 360)
        ax.grid(alpha=0.3)
    axs[0].legend()
    fig.suptitle("Seed 002 study model: Bezier rise/fall laws of degree 5, 7, 9 (beta = 100 deg)")
    fig.tight_layout()
    p = Path(img_dir) / "sweep_bezier.png"
    fig.savefig(p, dpi=80)
    print(f"\nplot: {p}")


if __name__ == "__main__":
    main()
