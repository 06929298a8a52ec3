r"""
One finite-element contact
==========================

The Hertz example gave the closed-form answer for two cylinders. Here the same contact is
solved with finite elements: gmsh meshes a slice of the cam and of the roller, graded so the
elements under the contact are ``h = a / a_over_h`` wide, scikit-fem assembles plane-strain
elasticity with quadratic (P2) elements, and the contact pressure is the unknown of a small
condensed system on the contact nodes. The FE pressure must land on the Hertz ellipse: that is
the test every later FE result in femcam rests on.
"""

# %%
# Solve it
# --------
# ``solve_contact`` builds the mesh for this load case and solves it in one call. The FE cost
# is set by ``a_over_h``: 10 (the sweep's default, a fraction of a second here) keeps p0 within
# about 0.3 % of Hertz; a/h = 20 or 40 is what the convergence studies use.
import os
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from femcam.fe import MeshOptions, solve_contact
from femcam.hertz import LineContact
from femcam.io import write_fe_vtu
from femcam.materials import STEEL

F, rho, Rr, length, mu = 1500.0, 0.020, 0.010, 0.010, 0.1   # N, m, m, m, -
r = solve_contact(F, rho, Rr, STEEL, STEEL, length, mu, mesh=MeshOptions(a_over_h=10))
hc = LineContact(F=F, length=length, R1=rho, R2=Rr, cam=STEEL, roller=STEEL, mu=mu)
print(f"converged: {r.converged} in {r.iterations} iterations, {r.n_dofs} DOFs")
print(f"FE     a = {r.a * 1e6:7.2f} um   p0 = {r.p0 / 1e6:7.1f} MPa   tau1 max = "
      f"{r.tau1_max.value / 1e6:6.1f} MPa")
print(f"Hertz  a = {hc.a * 1e6:7.2f} um   p0 = {hc.p0 / 1e6:7.1f} MPa   tau1 max = "
      f"{hc.max_shear().value / 1e6:6.1f} MPa")

# %%
# How close?
# ----------
# The errors against Hertz, with the tolerances the test suite holds the solver to at this
# mesh size (p0 0.3 %, half-width 1 %, force balance to solver precision).
err_p0 = r.p0 / hc.p0 - 1
err_a = r.a / hc.a - 1
err_t1 = r.tau1_max.value / hc.max_shear().value - 1
print(f"p0 error {err_p0:+.3%}, a error {err_a:+.3%}, tau1 error {err_t1:+.3%}, "
      f"force error {r.force_error:.1e}")
assert r.converged
assert abs(err_p0) < 3e-3, "FE p0 vs Hertz (Johnson eq. 4.45)"
assert abs(err_a) < 1e-2, "FE a vs Hertz"
assert abs(err_t1) < 3e-2, "FE tau1 max vs McEwen's closed form"

# %%
# The pressure against the Hertz ellipse
# --------------------------------------
# The nodal pressures of the contact zone lie on ``p0 sqrt(1 - x^2/a^2)``; the last loaded
# node sits within one element of the Hertz edge.
x = np.linspace(-1.5, 1.5, 601) * hc.a
fig, ax = plt.subplots(figsize=(6.4, 3.6), constrained_layout=True)
ax.plot(x * 1e6, hc.pressure(x) / 1e6, "k-", lw=1, label="Hertz")
ax.plot(r.x * 1e6, r.p / 1e6, "o", ms=3, label="FE nodes (a/h = 10)")
ax.set(xlabel="x (um)", ylabel="contact pressure (MPa)",
       title=f"p0 FE {r.p0 / 1e6:.1f} MPa vs Hertz {hc.p0 / 1e6:.1f} MPa ({err_p0:+.2%})")
ax.grid(alpha=0.3)
ax.legend()

# %%
# The mesh
# --------
# Both bodies are slices of their cylinders, clamped far from the contact. The elements grow
# from ``h`` in the contact zone (``fine_half_width`` = 2.5 a either side, ``fine_depth`` = 0.6 a
# below) to a fraction of the body size: most of the DOFs sit where the stresses vary.
m = r.model.mesh
fig, axes = plt.subplots(1, 2, figsize=(9.6, 4.2), constrained_layout=True)
for ax, span in zip(axes, (None, 4.0 * hc.a), strict=True):
    for body, colour in ((m.cam, "C0"), (m.roller, "C1")):
        ax.triplot(body.points[0] * 1e3, body.points[1] * 1e3, body.triangles.T, lw=0.3, color=colour)
    ax.set_aspect("equal")
    ax.set(xlabel="x (mm)", ylabel="z (mm)")
    if span:
        ax.set(xlim=(-span * 1e3, span * 1e3), ylim=(-span * 1e3, span * 1e3),
               title=f"contact zone, h = {m.h * 1e6:.1f} um")
    else:
        ax.set_title(f"cam (blue) and roller (orange): {m.n_nodes} nodes")

# %%
# The full field goes to a VTU file for ParaView or pyvista; the output directory is
# ``FEMCAM_EXAMPLE_OUT`` when set, otherwise a temporary one.
out = Path(os.environ.get("FEMCAM_EXAMPLE_OUT") or tempfile.mkdtemp(prefix="femcam_"))
write_fe_vtu(out / "contact.vtu", r)
print(f"wrote {out / 'contact.vtu'}")

plt.show()
