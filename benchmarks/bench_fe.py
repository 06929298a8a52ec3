"""Benchmark of the FE contact solver (issue 4): correctness first, then time per phase.

Run:  python benchmarks/bench_fe.py [--quick]

Sections
1. accuracy and time vs mesh density a/h (seed 002 study model, steel/steel, Rr = 10 mm,
   rho = 20 mm, F = 1500 N, l = 10 mm): DOFs, time per phase, errors of p0, a, rms(p), tau1,
   |txz| and of the trailing-edge tension peak 2 mu p0 (mu = 0.3), with log-log slopes;
2. SuperLU column orderings for one body;
3. finite-body effect vs domain size (domain_over_a);
4. model reuse: a model built for rho_ref solved at other rho vs a fresh build;
5. a 360-angle sweep-like loop of model.solve (varying F and rho).
"""

from __future__ import annotations

import sys
import time

import numpy as np

from femcam.fe import ContactModel, MeshOptions, SolverOptions
from femcam.hertz import LineContact
from femcam.materials import STEEL

Rr, rho, F, l = 0.01, 0.02, 1500.0, 0.01


def hertz(F=F, rho=rho, mu=0.0):
    return LineContact(F=F, length=l, R1=rho, R2=Rr, cam=STEEL, roller=STEEL, mu=mu)


def errors(model, F=F, rho=rho):
    hc = hertz(F, rho)
    r = model.solve(F=F, rho=rho)
    assert r.converged and abs(r.force / F - 1) < 1e-9, "equilibrium"
    e = {
        "p0": r.p0 / hc.p0 - 1,
        "a": r.a / hc.a - 1,
        "rms": float(np.sqrt(np.mean((r.p - hc.pressure(r.x)) ** 2)) / hc.p0),
        "tau1": r.tau1_max.value / hc.max_shear().value - 1,
        "txz": r.txz_abs_max.value / hc.max_orthogonal_shear().value - 1,
    }
    rf = model.solve(F=F, rho=rho, mu=0.3)
    e["sx_peak"] = float(rf.sx.max() / (0.6 * hc.p0) - 1)
    return e, r


def section_mesh(levels):
    print("\n## 1. accuracy and time vs a/h (errors relative to Hertz; times in s)\n")
    print("| a/h | DOFs | mesh | assembly | factor | condense | contact | recovery | cold total "
          "| p0 err | a err | rms(p-pH)/p0 | tau1 err | txz err | sx peak err (mu=0.3) |")
    print("|" + "---|" * 15)
    rows = []
    a_ref = float(hertz().a)
    for n in levels:
        t0 = time.perf_counter()
        m = ContactModel.build(Rr=Rr, rho_ref=rho, cam=STEEL, roller=STEEL, length=l, a_ref=a_ref,
                               mesh=MeshOptions(a_over_h=n))
        e, r = errors(m)
        tot = time.perf_counter() - t0
        t = r.timings
        print(f"| {n} | {m.n_dofs} | {t['mesh']:.2f} | {t['assembly']:.2f} | {t['factorisation']:.2f} | "
              f"{t['condensation']:.2f} | {t['contact'] * 1e3:.1f} ms | {t['recovery'] * 1e3:.1f} ms | "
              f"{tot:.2f} | {e['p0']:+.2e} | {e['a']:+.2e} | {e['rms']:.2e} | {e['tau1']:+.2e} | "
              f"{e['txz']:+.2e} | {e['sx_peak']:+.2e} |", flush=True)
        rows.append((n, e))
    if len(rows) >= 3:
        h = np.array([1 / n for n, _ in rows])
        for k in ("p0", "a", "rms", "sx_peak"):
            err = np.array([abs(e[k]) for _, e in rows])
            print(f"slope d log|{k} err| / d log h = {np.polyfit(np.log(h), np.log(err), 1)[0]:.2f}")


def section_orderings():
    from femcam.fe.elasticity import assemble_body
    from femcam.mesh import build_contact_mesh

    print("\n## 2. SuperLU orderings, one body (cam), a/h = 20\n")
    cm = build_contact_mesh(Rr=Rr, rho=rho, a_ref=float(hertz().a))
    print("| permc_spec | DOFs | factor (s) | nnz(L+U) | solve 100 RHS (s) |")
    print("|---|---|---|---|---|")
    for o in ("MMD_AT_PLUS_A", "COLAMD", "MMD_ATA"):
        b = assemble_body(cm.cam, STEEL, ordering=o)
        R = np.random.default_rng(0).standard_normal((b.free.size, 100))
        t = time.perf_counter()
        b.lu.solve(R)
        ts = time.perf_counter() - t
        print(f"| {o} | {b.n_dofs} | {b.t_factor:.2f} | {b.lu.L.nnz + b.lu.U.nnz} | {ts:.2f} |", flush=True)


def section_domain(sizes):
    print("\n## 3. finite-body effect vs domain size L = domain_over_a * a (a/h = 20)\n")
    print("| L / a | p0 err | a err | tau1 err | txz err |")
    print("|---|---|---|---|---|")
    a_ref = float(hertz().a)
    for d in sizes:
        m = ContactModel.build(Rr=Rr, rho_ref=rho, cam=STEEL, roller=STEEL, length=l, a_ref=a_ref,
                               mesh=MeshOptions(domain_over_a=d), solver=SolverOptions(kappa_tol=1e9))
        e, _ = errors(m)
        lab = f"{d:g}" if d else f"full (roller {Rr / a_ref:.0f}, cam {min(rho, Rr) / a_ref:.0f})"
        print(f"| {lab} | {e['p0']:+.2e} | {e['a']:+.2e} | {e['tau1']:+.2e} | {e['txz']:+.2e} |", flush=True)


def section_reuse():
    print("\n## 4. reuse: model built for rho_ref = 20 mm, solved at rho (fresh build for comparison)\n")
    print("| rho (mm) | covers | p0 err reuse | p0 err fresh | a err reuse | a err fresh | "
          "tau1 err reuse | tau1 err fresh |")
    print("|---|---|---|---|---|---|---|---|")
    a_ref = float(hertz().a)
    base = ContactModel.build(Rr=Rr, rho_ref=rho, cam=STEEL, roller=STEEL, length=l, a_ref=a_ref,
                              solver=SolverOptions(kappa_tol=1e9))  # solve outside covers() too
    for r_ in (0.012, 0.015, 0.03, 0.06, np.inf):
        fresh = ContactModel.build(Rr=Rr, rho_ref=r_, cam=STEEL, roller=STEEL, length=l, a_ref=a_ref)
        er, _ = errors(base, rho=r_)
        ef, _ = errors(fresh, rho=r_)
        print(f"| {r_ * 1e3:g} | {base.covers(F, r_)} | {er['p0']:+.2e} | {ef['p0']:+.2e} | {er['a']:+.2e} | "
              f"{ef['a']:+.2e} | {er['tau1']:+.2e} | {ef['tau1']:+.2e} |", flush=True)


def section_sweep():
    print("\n## 5. 360 solves on one model (F and rho vary with the angle)\n")
    a_ref = float(hertz().a)
    t0 = time.perf_counter()
    m = ContactModel.build(Rr=Rr, rho_ref=rho, cam=STEEL, roller=STEEL, length=l, a_ref=a_ref,
                           solver=SolverOptions())
    tb = time.perf_counter() - t0
    th = np.linspace(0, 2 * np.pi, 360, endpoint=False)
    Fs = F * (1 + 0.2 * np.sin(th))
    rhos = rho * (1 + 0.3 * np.cos(th))
    t0 = time.perf_counter()
    worst = 0.0
    for Fi, ri in zip(Fs, rhos, strict=True):
        r = m.solve(F=Fi, rho=ri, mu=0.1)
        worst = max(worst, abs(r.p0 / hertz(Fi, ri).p0 - 1))
    ts = time.perf_counter() - t0
    print(f"build {tb:.2f} s, 360 solves {ts:.2f} s ({ts / 360 * 1e3:.1f} ms each), "
          f"worst p0 error vs Hertz {worst:.2e}")


if __name__ == "__main__":
    quick = "--quick" in sys.argv
    print(f"# femcam FE benchmark (numpy {np.__version__})")
    section_mesh([8, 10, 14, 20] if quick else [10, 14, 20, 28, 40])
    if not quick:
        section_orderings()
        section_domain([15, 30, 60, None])
        section_reuse()
    section_sweep()
