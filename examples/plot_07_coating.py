r"""
A coated roller and a case-hardened cam
=======================================

Surface engineering changes where a contact fails. A thin hard coating (here 2.5 µm of
diamond-like carbon on the roller) can debond when the shear stress at its interface exceeds
the adhesion strength; a case-hardened cam (nitrided 0.3 mm deep) can yield below the case,
where the shear stress under the contact meets softer core material. This example reads both
from ``examples/seed002_coated.toml``: the FE model meshes the coating as its own band of
elements, and the stresses at the interface are compared with the homogeneous Hertz field at
the same depth.
"""

# %%
# The coated FE model at the peak load
# ------------------------------------
# ``scene_layers`` turns the scene's ``[materials.roller.coating]`` and ``[materials.cam.case]``
# tables into ``Coating`` and ``Case`` records (SI). ``build_coated_model`` meshes the coating
# as its own band, at least four elements through its thickness; after the build each solve
# takes a few milliseconds.
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from femcam.hertz import LineContact
from femcam.layers import build_coated_model, case_margin, interface_stress, scene_layer_rows, scene_layers
from femcam.scene import load_scene

HERE = Path(__file__).parent if "__file__" in globals() else Path.cwd()  # sphinx-gallery: cwd
sc = load_scene(HERE / "seed002_coated.toml")
layers = scene_layers(sc.layers, sc.follower)
coat_body, coating = layers["coating"]
case_body, case = layers["case"]
print(f"coating on the {coat_body}: {coating.material.name}, t = {coating.thickness * 1e6:.1f} um, "
      f"E = {coating.material.E / 1e9:.0f} GPa; case on the {case_body}: {case.depth * 1e3:.1f} mm")

theta = np.radians(np.arange(0.0, 360.0, 1.0))
st = sc.analyse(theta)
i = int(np.argmax(st.Fc))
F, rho = float(st.Fc[i]), float(st.rho[i])
hc = LineContact(F=F, length=sc.length, R1=rho, R2=sc.follower.Rr, cam=sc.cam, roller=sc.roller, mu=sc.mu)
model = build_coated_model(Rr=sc.follower.Rr, rho_ref=rho, cam=sc.cam, roller=sc.roller, length=sc.length,
                           a_ref=float(hc.a), coating=coating, body=coat_body)
r = model.solve(F=F, rho=rho, mu=sc.mu)
print(f"theta = {np.degrees(theta[i]):.0f} deg, Fc = {F:.1f} N: p0 coated {r.p0 / 1e6:.1f} MPa, "
      f"uncoated Hertz {hc.p0 / 1e6:.1f} MPa ({r.p0 / hc.p0 - 1:+.2%})")

# %%
# The interface
# -------------
# Along the coating/substrate interface: the normal stress (compressive under the contact) and
# the shear stress, which friction (``mu`` = 0.1, full sliding) makes one-sided. A coating 40
# times thinner than the contact half-width changes little, so the homogeneous Hertz field at
# the interface depth (McEwen's closed form) is the reference: within 1 % for the normal
# stress and 5 % for the shear. The friction on the roller acts opposite to that on the cam,
# hence ``direction=-1`` for the roller's reference field.
it = interface_stress(r, coat_body)
h_roller = LineContact(F=F, length=sc.length, R1=rho, R2=sc.follower.Rr, cam=sc.cam, roller=sc.roller,
                       mu=sc.mu, direction=-1)
ref = h_roller.stress(it.x, coating.thickness, body="roller")
print(f"interface: |tau| max = {it.tau_abs_max / 1e6:.1f} MPa at x = {it.x_tau_max / hc.a:+.2f} a "
      f"(Hertz at z = t: {np.abs(ref.txz).max() / 1e6:.1f} MPa), "
      f"sigma_n min = {it.sigma_n_min / 1e6:.1f} MPa (Hertz: {ref.sz.min() / 1e6:.1f} MPa)")
print(f"utilisation of the interface shear strength {coating.interface_shear_strength / 1e6:.0f} MPa: "
      f"{it.tau_abs_max / coating.interface_shear_strength:.2f}")
assert abs(it.sigma_n_min / ref.sz.min() - 1) < 1e-2, "interface normal stress vs Hertz at z = t"
assert abs(it.tau_abs_max / np.abs(ref.txz).max() - 1) < 5e-2, "interface shear vs Hertz at z = t"

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10.0, 3.8), constrained_layout=True)
ax1.plot(it.x / hc.a, it.sigma_n / 1e6, label=r"FE $\sigma_n$")
ax1.plot(it.x / hc.a, ref.sz / 1e6, "k--", lw=1, label=r"Hertz $\sigma_z$ at z = t")
ax1.plot(it.x / hc.a, it.tau / 1e6, label=r"FE $\tau$")
ax1.plot(it.x / hc.a, ref.txz / 1e6, "k:", lw=1, label=r"Hertz $\tau_{xz}$ at z = t")
ax1.set(xlabel="x / a", ylabel="interface stress (MPa)", title="coating/substrate interface", xlim=(-2, 2))

# %%
# The case
# --------
# ``case_margin`` compares a shear-stress profile over depth with the case's shear strength
# ``k(z)``, which falls from the nitrided surface to the core. With the Hertz ``tau1`` (its
# largest value over x at each depth) the utilisation peaks a little deeper than the shear
# itself (``0.7-0.8 a``), where the strength has fallen, and still well inside the 0.3 mm case.
z = np.linspace(1e-6, 2.5 * case.depth, 300)
X, Zg = np.meshgrid(np.linspace(-1.5, 1.5, 121) * hc.a, z)
tau1 = hc.stress(X, Zg).tau1.max(axis=1)
cm = case_margin(case, z, tau1)
print(f"case: max utilisation {cm.u_max:.2f} at z = {cm.z_at_max * 1e3:.3f} mm, margin {cm.margin:.2f}")
ax2.plot(z * 1e3, tau1 / 1e6, label=r"Hertz $\tau_1$ (max over x)")
ax2.plot(z * 1e3, case.shear_strength(z) / 1e6, label="case shear strength k(z)")
ax2.axvline(case.depth * 1e3, color="k", ls=":", lw=1, label="case depth")
ax2.set(xlabel="depth z (mm)", ylabel="stress (MPa)", title="case-hardened cam")
for ax in (ax1, ax2):
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)

# %%
# Over the revolution
# -------------------
# ``scene_layer_rows`` gives the sweep's layer columns per angle (one FE solve each, on models
# graded per load bin); every 60 deg keeps it to a few solves.
theta = np.radians(np.arange(0.0, 360.0, 60.0))
st = sc.analyse(theta)
rows = scene_layer_rows(sc.layers, sc.pair, sc.follower, theta, st.Fc, st.rho)
for k in range(len(rows["theta_deg"])):
    print(f"{rows['theta_deg'][k]:5.0f} deg  F = {rows['F_N'][k]:6.1f} N  interface tau max = "
          f"{rows['interface_tau_max_MPa'][k]:5.1f} MPa (U = {rows['interface_utilisation'][k]:.2f})  "
          f"case margin {rows['case_margin'][k]:.2f} at z = {rows['case_z_at_max_mm'][k]:.3f} mm")

plt.show()
