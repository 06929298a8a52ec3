"""One cold FE scene per fresh process: time per phase, peak RSS and errors, before/after.

Run:  python benchmarks/bench_fe_cold.py [--levels 10,20,26,40] [--repeat 3]
                                         [--mode per_solve|precompute] [--base DIR]

Case: the seed 002 study model contact (steel/steel, Rr = 10 mm, rho = 20 mm, F = 1500 N over
l = 10 mm, plane strain, mu = 0), ``ContactModel.build`` + one ``solve`` in a new Python process
(imports excluded from the scene time and printed apart), ``SolverOptions(stress_operators=
mode)`` (``per_solve``: a single scene, ``solve_contact``'s default).

Correctness first: every run must meet femcam's accuracy targets at a/h = 20 and finer (p0 <=
0.3 %, a <= 1 %, tau1 <= 2 % vs Hertz, Johnson 1985 §4.2), and with ``--base DIR`` (another
femcam checkout, e.g. ``git archive`` of the previous commit) the after-run's pressures,
p0, a, rms(p - Hertz), tau1 and von Mises maxima must equal the before-run's to 1e-10
relative; the script stops otherwise. Each row is the median over ``--repeat`` runs (phase
times are the model's own timers; with the two bodies built in two threads the phases overlap
and "bodies" is their wall time); CPU = process CPU seconds of the scene; peak RSS = ``VmHWM``.
The machine (2 cores, shared) and the load average are printed with each row.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
TARGETS = {"p0": 3e-3, "a": 1e-2, "tau1": 2e-2}

CODE = r"""
import json, sys, time
t0 = time.perf_counter()
import numpy as np
from femcam.fe import ContactModel, MeshOptions, SolverOptions
from femcam.hertz import LineContact
from femcam.materials import STEEL
t_imp = time.perf_counter() - t0
Rr, rho, F, l = 0.01, 0.02, 1500.0, 0.01
hc = LineContact(F=F, length=l, R1=rho, R2=Rr, cam=STEEL, roller=STEEL)
c0, t1 = time.process_time(), time.perf_counter()
m = ContactModel.build(Rr=Rr, rho_ref=rho, cam=STEEL, roller=STEEL, length=l, a_ref=float(hc.a),
                       mesh=MeshOptions(a_over_h=float(sys.argv[1])),
                       solver=SolverOptions(stress_operators=sys.argv[2]))
r = m.solve(F=F, rho=rho)
tot, cpu = time.perf_counter() - t1, time.process_time() - c0
hwm = next(int(x.split()[1]) for x in open("/proc/self/status") if x.startswith("VmHWM"))
print(json.dumps({"dofs": m.n_dofs, "timings": {k: float(v) for k, v in r.timings.items()},
                  "total": tot, "cpu": cpu, "imports": t_imp, "rss_mb": hwm / 1024,
                  "p": r.p.tolist(), "p0": r.p0 / hc.p0 - 1, "a": r.a / hc.a - 1,
                  "rms": float(np.sqrt(np.mean((r.p - hc.pressure(r.x)) ** 2)) / hc.p0),
                  "tau1": r.tau1_max.value / hc.max_shear().value - 1,
                  "vm": r.von_mises_max.value}))
"""


def run(src: Path, n: float, mode: str) -> dict:
    env = dict(os.environ, PYTHONPATH=str(src))
    out = subprocess.run([sys.executable, "-c", CODE, str(n), mode], capture_output=True,
                         text=True, check=True, env=env, cwd=str(src))
    d = json.loads(out.stdout.strip().splitlines()[-1])
    d["load"] = os.getloadavg()[0]
    if n >= 20:
        for k, tol in TARGETS.items():
            assert abs(d[k]) <= tol, f"a/h = {n}: {k} error {d[k]:+.3%} vs Hertz exceeds {tol:.1%}"
    return d


def same_numbers(a: dict, b: dict, tol: float = 1e-10) -> float:
    """Largest relative difference of the answers of two runs; stops above ``tol``."""
    pa, pb = np.array(a["p"]), np.array(b["p"])
    d = float(np.max(np.abs(pa - pb)) / np.max(np.abs(pb)))
    for k in ("p0", "a", "rms", "tau1", "vm"):
        scale = 1.0 if k in ("p0", "a", "tau1") else abs(b[k])  # errors are already relative
        d = max(d, abs(a[k] - b[k]) / scale)
    assert d <= tol, f"answers differ by {d:.3g} (relative) from the base run"
    return d


def median_row(runs: list[dict]) -> dict:
    keys = ("mesh", "assembly", "factorisation", "condensation")
    t = {k: float(np.median([r["timings"].get(k, np.nan) for r in runs])) for k in keys}
    t["solve"] = float(np.median([r["timings"]["contact"] + r["timings"]["recovery"] for r in runs]))
    t["bodies"] = float(np.median([r["timings"].get("bodies_wall", np.nan) for r in runs]))
    for k in ("total", "cpu", "imports", "rss_mb"):
        t[k] = float(np.median([r[k] for r in runs]))
    t["load"] = f"{min(r['load'] for r in runs):.1f}-{max(r['load'] for r in runs):.1f}"
    return t


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--levels", default="10,20,26,40")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--mode", default="per_solve", choices=("per_solve", "precompute"))
    ap.add_argument("--base", type=Path, default=None, help="femcam checkout of the 'before' rows")
    a = ap.parse_args()
    levels = [float(x) for x in a.levels.split(",")]
    print(f"# cold FE scene, mode {a.mode}; machine: {os.cpu_count()} CPUs (shared), "
          f"load average {' / '.join(f'{x:.2f}' for x in os.getloadavg())}")
    print("\n| a/h | DOFs | version | mesh | assembly | factor (incl. order) | condense (Schur) | "
          "bodies wall | solve | cold scene | CPU | imports | p0 err | a err | rms(p − Hertz)/p0 | "
          "τ1 err | max rel diff vs before | peak RSS (MB) | load |")
    print("|" + "---|" * 19)
    versions = [("before", a.base), ("after", ROOT)] if a.base else [("after", ROOT)]
    for n in levels:
        runs = {v: [] for v, _ in versions}
        for _ in range(a.repeat):  # interleaved: both versions see the same load
            for v, src in versions:
                runs[v].append(run(src, n, a.mode))
        for v, _ in versions:
            r0, t = runs[v][0], median_row(runs[v])
            diff = same_numbers(r0, runs["before"][0]) if a.base else float("nan")
            na = "-" if np.isnan(t["bodies"]) else f"{t['bodies']:.2f}"
            print(f"| {n:g} | {r0['dofs']} | {v} | {t['mesh']:.2f} | {t['assembly']:.2f} | "
                  f"{t['factorisation']:.2f} | {t['condensation']:.2f} | {na} | "
                  f"{1e3 * t['solve']:.0f} ms | {t['total']:.2f} | {t['cpu']:.2f} | {t['imports']:.2f} | "
                  f"{100 * r0['p0']:+.4f} % | {100 * r0['a']:+.3f} % | {100 * r0['rms']:.3f} % | "
                  f"{100 * r0['tau1']:+.3f} % | {diff:.1e} | {t['rss_mb']:.0f} | {t['load']} |",
                  flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
