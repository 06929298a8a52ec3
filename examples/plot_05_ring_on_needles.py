r"""
The roller as a ring on needles
===============================

A track roller is not a solid cylinder: it is a ring running on needles around a stud. The cam
contact barely notices (its pressure stays within a fraction of a per cent of the solid
roller's Hertz value), but the ring bends between the needles, so the bore carries a tensile
hoop stress and the needle under the load line carries far more than a rigid-ring bearing
calculation says. This example builds the ring-on-needles model of
``examples/seed002_needle_roller.toml`` (seed 002's roller as a 3 mm ring on 18 needles of
1 mm radius) and reads both answers.
"""

# %%
# Build the model once, solve the most loaded angle
# -------------------------------------------------
# ``build_for`` meshes the ring, the stud and the cam's contact zone once, graded for the
# largest contact force of the angles given; each load case after that is a condensed solve of
# about 10 ms. Twelve angles (every 30 deg) keep the example short, and the most loaded of
# them is solved in detail; the sweep does every angle with the same model.
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from femcam.bodies import build_for, ring_rows, solve_ring
from femcam.scene import load_scene

HERE = Path(__file__).parent if "__file__" in globals() else Path.cwd()  # sphinx-gallery: cwd
sc = load_scene(HERE / "seed002_needle_roller.toml")
theta = np.radians(np.arange(0.0, 360.0, 30.0))
st = sc.analyse(theta)                      # contact force Fc (N) and cam radius rho (m)
model = build_for(sc.bodies.roller, sc.pair, st.Fc, st.rho)
i = int(np.argmax(st.Fc))
F, rho = float(st.Fc[i]), float(st.rho[i])
Z = model.bearing.Z

# %%
# Two cage positions bound the needle loads: a needle right on the load line, and the load
# line between two needles (the cage turned by half a pitch).
on = solve_ring(model, F=F, rho=rho, cage=0.0)
between = solve_ring(model, F=F, rho=rho, cage=np.pi / Z)
print(f"theta = {np.degrees(theta[i]):.0f} deg, Fc = {F:.1f} N, rho = {rho * 1e3:.2f} mm, Z = {Z}")
print(f"cam contact p0: ring {on.p0 / 1e6:.1f} MPa vs solid roller (Hertz) {on.hertz_p0 / 1e6:.1f} MPa "
      f"({on.p0 / on.hertz_p0 - 1:+.2%})")
stribeck = 4.08 * F / Z                     # rigid ring, line contact (Stribeck)
for name, r in (("needle on the load line", on), ("load line between needles", between)):
    print(f"{name:26s}: Q_max = {r.needle_Q.max():6.1f} N ({r.needle_Q.max() / stribeck:.2f} x Stribeck "
          f"{stribeck:.0f} N), bore hoop max = {r.hoop_max / 1e6:6.1f} MPa")

# %%
# Checks: the needle loads carry the cam force (the ring is in equilibrium), and the cam
# contact of the ring stays within 0.5 % of the solid roller's Hertz pressure.
for r in (on, between):
    resultant = np.hypot((r.needle_Q * np.cos(r.needle_phi)).sum(), (r.needle_Q * np.sin(r.needle_phi)).sum())
    assert np.isclose(resultant, F, rtol=1e-6), "needle loads balance the cam force"
    assert abs(r.p0 / r.hertz_p0 - 1) < 5e-3, "ring p0 vs solid-roller Hertz (Johnson eq. 4.45)"

# %%
# Needle loads and the bore hoop stress
# -------------------------------------
# Angles are measured from the load line (the cam contact pushes the ring towards -90 deg in
# the model's frame). Only the needles within about 40 deg of it carry load. The bore is in
# tension under the load, where the ring bends over its supports, and in compression over the
# loaded needles either side.
def from_load_line(angle):
    return (np.degrees(angle) + 270.0) % 360.0 - 180.0


fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10.0, 3.8), constrained_layout=True)
for r, label in ((on, "needle on the load line"), (between, "between needles")):
    ax1.bar(from_load_line(r.needle_phi), r.needle_Q, width=6, alpha=0.7, label=label)
    order = np.argsort(from_load_line(r.theta))
    ax2.plot(from_load_line(r.theta)[order], r.hoop[order] / 1e6, label=label)
ax1.axhline(stribeck, color="k", ls="--", lw=1, label="Stribeck 4.08 F/Z (rigid ring)")
ax1.set(xlabel="needle angle from the load line (deg)", ylabel="needle load (N)", xlim=(-90, 90),
        title="needle loads")
ax2.set(xlabel="bore angle from the load line (deg)", ylabel="bore hoop stress (MPa)", title="ring bore")
for ax in (ax1, ax2):
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)

# %%
# Over the revolution
# -------------------
# ``ring_rows`` gives the ring's rows per angle with the same model (both cage positions each
# time): the bore hoop maximum and the most loaded needle follow the contact force. In
# ``femcam sweep`` the same rows answer the headline: ``p0_fe_MPa`` is ``ring_rows``' peak
# ``p0_peak`` (model ``fe_arc+ring``), and the bore and needle columns sit beside it.
rows = ring_rows(sc.bodies.roller, sc.pair, theta, st.Fc, st.rho, model=model)
deg = np.degrees(rows["theta"])
fig, ax = plt.subplots(figsize=(6.4, 3.6), constrained_layout=True)
ax.plot(deg, rows["hoop_max"] / 1e6, "o-", label="bore hoop max (MPa)")
ax.plot(deg, rows["needle_Q_on"], "s-", label="needle Q max, on the load line (N)")
ax.plot(deg, rows["needle_Q_between"], "^-", label="needle Q max, between (N)")
ax.set(xlabel="cam angle (deg)", title="ring on needles over the revolution")
ax.grid(alpha=0.3)
ax.legend(fontsize=8)
k = int(np.nanargmax(rows["hoop_max"]))
print(f"largest bore hoop stress {rows['hoop_max'][k] / 1e6:.1f} MPa at {deg[k]:.0f} deg")

plt.show()
