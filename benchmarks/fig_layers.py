"""Figures of docs/layers.md: interface shear and case-core margin vs cam angle on
examples/seed002_coated.toml (DLC roller, nitrided cam), and the layered-solid comparison
(FE vs the Fourier layered half-space reference of tests/test_layers.py).

Run:  python benchmarks/fig_layers.py [--step-deg 5] [--a-over-h 20] [--no-angles] [--no-reference]
Writes docs/img/layers_seed002.png and docs/img/layers_reference.png and prints the numbers.
"""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent


def angles_figure(step_deg: float, a_over_h: float):
    import matplotlib  # lazy: plotting only

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from femcam.layers import scene_layer_rows
    from femcam.scene import load_scene

    sc = load_scene(ROOT / "examples" / "seed002_coated.toml")
    th = np.radians(np.arange(0.0, 360.0, step_deg))
    t0 = time.perf_counter()
    st = sc.analyse(th)
    r = scene_layer_rows(sc.layers, sc.pair, sc.follower, th, st.Fc, st.rho, a_over_h=a_over_h)
    dt = time.perf_counter() - t0
    print(f"{th.size} angles, {r['models']} models, {dt:.1f} s, load {os.getloadavg()[0]:.2f}")
    i = np.nanargmax(r["interface_tau_max_MPa"])
    j = np.nanargmin(r["case_margin"])
    print(f"max interface shear {r['interface_tau_max_MPa'][i]:.1f} MPa at {r['theta_deg'][i]:.0f} deg "
          f"(utilisation {r['interface_utilisation'][i]:.3f}); coating sx max "
          f"{np.nanmax(r['coating_sx_max_MPa']):.1f} MPa; min case margin {r['case_margin'][j]:.2f} at "
          f"{r['theta_deg'][j]:.0f} deg, depth {r['case_z_at_max_mm'][j]:.3f} mm")
    fig, ax = plt.subplots(3, 1, figsize=(7, 7), sharex=True)
    ax[0].plot(r["theta_deg"], r["F_N"], "k-")
    ax[0].set_ylabel("contact force F (N)")
    ax[1].plot(r["theta_deg"], r["interface_tau_max_MPa"], "b.-", label="max |interface shear|")
    ax[1].plot(r["theta_deg"], r["coating_sx_max_MPa"], "r.-", label="coating surface tension sx max")
    ax[1].set_ylabel("stress (MPa)")
    ax[1].legend(fontsize=8)
    ax[1].set_title("DLC 2.5 um on the roller (interface strength 250 MPa, assumed)", fontsize=9)
    ax[2].plot(r["theta_deg"], r["case_margin"], "g.-")
    ax[2].set_ylabel("case-core margin 1/max(tau1/k)")
    ax[2].set_xlabel("cam angle (deg)")
    ax[2].set_title("nitrided cam: 0.3 mm, 700/300 HV, exponential law", fontsize=9)
    fig.tight_layout()
    out = ROOT / "docs" / "img" / "layers_seed002.png"
    fig.savefig(out, dpi=110)
    print("wrote", out)


def reference_figure():
    import matplotlib  # lazy: plotting only

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    sys.path.insert(0, str(ROOT / "tests"))
    import test_layers as T  # noqa: N812  the reference lives in the test (independent of femcam)

    a0, p00 = T._hertz(T.STEEL.E, T.STEEL.nu, T.STEEL.E, T.STEEL.nu)
    fig, ax = plt.subplots(1, 2, figsize=(10, 3.8))
    print("| E_c/E_s | t/a | p0/p0_Hertz ref | FE | max|tau_i|/p0 ref | FE | min sn/p0 ref | FE |")
    print("|---|---|---|---|---|---|---|---|")
    for Ec, col in ((420e9, "r"), (105e9, "b")):
        coat = T.Material(E=Ec, nu=0.3)
        for toa in (0.25, 0.5, 1.0):
            x, p, tau, sn = T.layered_contact(toa * a0, coat)
            rr = T._coated(toa * a0, coat).solve(F=T.F, rho=T.RHO)
            it = T.interface_stress(rr, "roller")
            print(f"| {Ec / 210e9:.1f} | {toa} | {p.max() / p00:.4f} | {rr.p0_nodal / p00:.4f} | "
                  f"{np.abs(tau).max() / p00:.4f} | {it.tau_abs_max / p00:.4f} | {sn.min() / p00:.4f} | "
                  f"{it.sigma_n_min / p00:.4f} |")
            if toa == 0.5:
                k = np.abs(x) < 2.5 * a0
                ax[0].plot(x[k] / a0, p[k] / p00, col + "-", label=f"reference E_c/E_s = {Ec / 210e9:.1f}")
                ax[0].plot(rr.x / a0, rr.p / p00, col + "o", ms=3, label="FE")
                ax[1].plot(x[k] / a0, np.abs(tau[k]) / p00, col + "-")
                ax[1].plot(it.x / a0, np.abs(it.tau) / p00, col + "o", ms=3)
    ax[0].set_xlabel("x / a_Hertz")
    ax[0].set_ylabel("p / p0_Hertz (uncoated)")
    ax[0].legend(fontsize=7)
    ax[0].set_title("contact pressure, t = a/2", fontsize=9)
    ax[1].set_xlabel("x / a_Hertz")
    ax[1].set_ylabel("|interface shear| / p0_Hertz")
    ax[1].set_title("interface shear, t = a/2 (lines: Fourier layered half-space)", fontsize=9)
    fig.tight_layout()
    out = ROOT / "docs" / "img" / "layers_reference.png"
    fig.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    args = sys.argv[1:]
    step = float(args[args.index("--step-deg") + 1]) if "--step-deg" in args else 5.0
    aoh = float(args[args.index("--a-over-h") + 1]) if "--a-over-h" in args else 20.0
    if "--no-angles" not in args:
        angles_figure(step, aoh)
    if "--no-reference" not in args:
        reference_figure()
