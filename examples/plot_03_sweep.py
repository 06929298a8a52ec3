r"""
A sweep over the cam angle
==========================

The main job: the seed 002 study model (a Bézier-5 rise and fall of 10 mm, a 10 mm roller on a
10 mm base circle, 600 rpm) is swept over a full revolution. At every angle femcam computes the
kinematics, the contact force, the Hertz answer and an FE contact solve, then writes a table
(CSV/NPZ) and a VTU file every few angles. This example plots the FE peak pressure against
Hertz around the cam and opens one of the VTU files to read a stress field.
"""

# %%
# Run the sweep
# -------------
# ``femcam.sweep`` takes the scene file and keyword options. The FE settings here are the
# defaults of ``femcam sweep``: elements ``h = a/10`` in the contact zone, and one mesh (a
# *family*) reused for every angle whose contact it covers, checked against fresh models to a
# 0.2 % reuse error. That reuse is what makes 360 FE angles take a few seconds: a handful of
# models are built and each further angle is a ~2 ms solve. ``vtk_every=30`` writes 12 VTU
# files; ``plots=False`` skips the PNGs the command line would write.
import os
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
import pyvista as pv

import femcam

HERE = Path(__file__).parent if "__file__" in globals() else Path.cwd()  # sphinx-gallery: cwd
out = Path(os.environ.get("FEMCAM_EXAMPLE_OUT") or tempfile.mkdtemp(prefix="femcam_")) / "sweep"
res = femcam.sweep(HERE / "seed002_study_model.toml",
                   femcam.SweepOptions(vtk_every=30, plots=False),
                   femcam.RunOptions(out=out))
t = res.table                                  # SI columns, one entry per angle
theta_deg = np.degrees(t["theta"])
print(f"{len(theta_deg)} angles, models used: {res.provenance['options']['models']}")

# %%
# FE against Hertz
# ----------------
# ``p0_fe`` is the peak of the solved pressure, ``p0_hertz`` the closed form with the cam's
# local radius of curvature. They differ by the discretisation error (about 0.1 %) except
# beside the jerk steps of the motion law, where the curvature changes within the contact
# width: there the rows are solved on the exact cam surface (``model`` = ``fe_exact``).
err = t["p0_fe"] / t["p0_hertz"] - 1
i = int(np.argmax(t["p0_fe"]))
print(f"worst angle {theta_deg[i]:.0f} deg: Fc = {t['Fc'][i]:.1f} N, p0 FE = "
      f"{t['p0_fe'][i] / 1e6:.1f} MPa, Hertz = {t['p0_hertz'][i] / 1e6:.1f} MPa")
print(f"max |p0 FE / Hertz - 1| = {np.abs(err).max():.3%}")
assert np.abs(err).max() < 3e-3, "FE p0 within 0.3 % of Hertz at every angle (a/h = 10)"

fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(6.4, 5.2), sharex=True, constrained_layout=True)
ax1.plot(theta_deg, t["p0_hertz"] / 1e6, "k-", lw=1, label="Hertz")
ax1.plot(theta_deg, t["p0_fe"] / 1e6, ".", ms=3, label="FE (a/h = 10)")
ax1.set(ylabel="p0 (MPa)", title="seed 002 study model, 600 rpm")
ax1.legend()
exact = t["model"] == "fe_exact"
ax2.plot(theta_deg, 100 * err, ".", ms=3, label="fe_arc rows")
ax2.plot(theta_deg[exact], 100 * err[exact], "rs", ms=4, mfc="none", label="fe_exact rows")
ax2.set(xlabel="cam angle (deg)", ylabel="p0 FE / Hertz - 1 (%)")
ax2.legend()
for ax in (ax1, ax2):
    ax.grid(alpha=0.3)

# %%
# Open a VTU file
# ---------------
# Each VTU holds both bodies at one angle, with the stresses, the displacement and the contact
# pressure as point data (SI units in the names). ``pyvista.read`` opens it (ParaView opens the
# ``sweep.pvd`` series); here the most loaded of the written angles.
vtus = sorted((out / "vtk").glob("*.vtu"))
grid = {int(round(float(pv.read(f).field_data["theta_deg"][0]))): f for f in vtus}
k = max(grid, key=lambda deg: t["p0_fe"][np.argmin(np.abs(theta_deg - deg))])
mesh = pv.read(grid[k])
print(f"{grid[k].name}: {mesh.n_points} points, fields {list(mesh.point_data)}")
row = int(np.argmin(np.abs(theta_deg - k)))
p_vtu = mesh.point_data["contact_pressure_Pa"].max()
print(f"max contact_pressure_Pa in the VTU = {p_vtu / 1e6:.1f} MPa (table: {t['p0_fe'][row] / 1e6:.1f} MPa)")
assert np.isclose(p_vtu, t["p0_fe"][row], rtol=1e-6)

# %%
# The von Mises field under the contact, drawn from the VTU's points and the corner nodes of
# its quadratic triangles: the maximum sits below the surface, as the Hertz example showed.
tri = mesh.cells_dict[pv.CellType.QUADRATIC_TRIANGLE][:, :3]
xy = mesh.points[:, :2] * 1e3
a_mm = t["a_fe"][row] * 1e3
fig, ax = plt.subplots(figsize=(6.4, 4.0), constrained_layout=True)
tc = ax.tripcolor(xy[:, 0], xy[:, 1], tri, mesh.point_data["von_mises_Pa"] / 1e6, shading="gouraud")
fig.colorbar(tc, ax=ax, label="von Mises (MPa)")
ax.set(xlim=(-4 * a_mm, 4 * a_mm), ylim=(-3 * a_mm, 3 * a_mm), aspect="equal",
       xlabel="x (mm)", ylabel="z (mm)", title=f"theta = {k} deg, cam below, roller above")

plt.show()
