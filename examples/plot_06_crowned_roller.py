r"""
A crowned roller of finite length
=================================

Two-dimensional Hertz theory spreads the contact force evenly over the face width. A real
roller has ends: a straight roller presses hardest at its edges, so rollers are crowned, and
a small misalignment of the roller axis shifts the load towards one end. femcam solves the
finite-length contact on an elastic half-space (influence coefficients with FFTs) over a grid
of cells across and along the contact. This example runs ``examples/seed002_crowned.toml``
(seed 002's roller with a logarithmic crown and a 0.02 deg tilt) and reads the axial pressure
along the roller and the most loaded slice.
"""

# %%
# Solve the contact at a few angles
# ---------------------------------
# ``finite_case(sc).strip()`` builds the half-space strip of the scene's roller once (64 cells
# across the contact, 128 along the roller; the logarithmic crown designed for the largest
# contact force of the revolution). ``finite_length_rows`` solves it at each angle of the
# analysed scene by conjugate gradients, starting from the previous angle's pressure. Every
# 30 deg keeps this to about a second; the sweep does every degree.
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from femcam.halfspace import finite_length_rows
from femcam.hertz import LineContact
from femcam.scene import finite_case, load_scene

HERE = Path(__file__).parent if "__file__" in globals() else Path.cwd()  # sphinx-gallery: cwd
sc = load_scene(HERE / "seed002_crowned.toml")
st = sc.analyse(np.radians(np.arange(0.0, 360.0, 30.0)))
rows = finite_length_rows(finite_case(sc).strip(), st.theta, st.Fc, st.rho, sc.follower.Rr)
deg = np.degrees(rows["theta"])
y = rows["y"]                                  # slice centres along the roller axis (m)
hz = LineContact(F=rows["Fc"], length=sc.length, R1=np.inf, R2=rows["R"], cam=sc.cam, roller=sc.roller)
for k in range(0, len(deg), 3):
    print(f"{deg[k]:5.0f} deg  Fc = {rows['Fc'][k]:6.1f} N  axial peak p = "
          f"{rows['p_axial_peak'][k] / 1e6:6.1f} MPa at y = {rows['y_peak'][k] * 1e3:+.2f} mm  "
          f"(2D Hertz {hz.p0[k] / 1e6:6.1f} MPa, "
          f"edge factor {rows['edge_factor'][k]:.2f})")

# %%
# Checks
# ------
# The slices carry the whole contact force, ``integral w dy = Fc``; and away from the roller
# ends each slice is a Hertz line contact of its own load ``w(y)`` (Johnson eq. 4.45), within
# 1 %. Only the last few cells at each end (0.3 mm), where the pressure is no longer
# two-dimensional, depart from it (by up to 18 % in the end cell).
dy = y[1] - y[0]
assert np.allclose(rows["w"].sum(axis=1) * dy, rows["Fc"], rtol=1e-6), "slice loads add up to Fc"
slice_hertz = LineContact(F=rows["w"], length=1.0, R1=np.inf, R2=rows["R"][:, None],
                          cam=sc.cam, roller=sc.roller)
inner = slice(4, -4)
ratio = rows["p_line"][:, inner] / slice_hertz.p0[:, inner]
print(f"interior slices vs Hertz of their own load: {ratio.min():.4f} .. {ratio.max():.4f}")
assert np.all(np.abs(ratio - 1) < 1e-2)

# %%
# The axial pressure along the roller
# -----------------------------------
# At the angle of the largest axial peak, the peak pressure of each slice along the roller,
# against the uniform 2D Hertz value. A logarithmic crown alone would keep the pressure nearly
# flat and relieve both ends; the 0.02 deg tilt is more than this crown absorbs, so the load
# shifts towards the lower end (y < 0) and peaks at its sharp corner, nearly twice the 2D
# Hertz value (``edge_factor``). A 2D analysis cannot see this.
k = int(np.nanargmax(rows["p_axial_peak"]))
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10.0, 3.8), constrained_layout=True)
ax1.plot(y * 1e3, rows["p_line"][k] / 1e6, label="half-space, peak of each slice")
ax1.axhline(hz.p0[k] / 1e6, color="k", ls="--", lw=1, label="2D Hertz, uniform load")
ax1.set(xlabel="y along the roller (mm)", ylabel="peak pressure (MPa)",
        title=f"theta = {deg[k]:.0f} deg, Fc = {rows['Fc'][k]:.0f} N")
ax2.plot(deg, rows["p_axial_peak"] / 1e6, "o-", label="half-space axial peak")
ax2.plot(deg, hz.p0 / 1e6, "k--", lw=1, label="2D Hertz")
ax2.set(xlabel="cam angle (deg)", ylabel="peak pressure (MPa)", title="over the revolution")
for ax in (ax1, ax2):
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)

# %%
# The most loaded slice
# ---------------------
# The largest load per unit length ``w_max`` and where it sits: this slice is the one an FE
# check of the section should take (the sweep can solve it in 2D FE at its ``w_max``).
j = int(np.argmax(rows["w"][k]))
print(f"most loaded slice at y = {y[j] * 1e3:+.2f} mm: w = {rows['w'][k, j] / 1e3:.1f} N/mm "
      f"(uniform {rows['Fc'][k] / sc.length / 1e3:.1f} N/mm), p0 = {rows['p_line'][k, j] / 1e6:.1f} MPa")

plt.show()
