r"""
Will it fail? Film, flash temperature and safety factors
========================================================

Contact stresses become a design answer once they are set against the lubricant and the
material. ``femcam.assess`` does this per cam angle for ``examples/seed002_assess.toml``
(seed 002's cam with an ISO VG 46 mineral oil at 70 °C, stated roughnesses and a hardened
bearing steel, every assumption commented in the file): the film thickness and the film
parameter ``lambda``, the flash temperature, and safety factors against first yield,
shakedown, subsurface and surface fatigue and scuffing. The governing criterion is the one
with the smallest safety factor, at its angle.
"""

# %%
# Assess the scene
# ----------------
# ``assess`` runs the analytic chain over 360 angles (Hertz contact, entrainment and sliding
# speeds, film by Dowson-Higginson / Pan-Hamrock, Blok flash temperature, fatigue limits) in
# about a second. ``res.rows`` holds the columns in SI; ``res.worst`` the worst value of each
# criterion and its angle.
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from femcam.assess import assess
from femcam.hertz import max_shear
from femcam.scene import contact_case, load_scene

HERE = Path(__file__).parent if "__file__" in globals() else Path.cwd()  # sphinx-gallery: cwd
sc = load_scene(HERE / "seed002_assess.toml")
res = assess(contact_case(sc))
r = res.rows
deg = np.degrees(r["theta"])
for criterion, (value, theta, _) in res.worst.items():
    print(f"{criterion:20s} {value:10.3g} at {np.degrees(theta):5.0f} deg")

# %%
# Two identities to check the columns against: ``lambda`` is the minimum film thickness over
# the composite roughness ``sigma`` of the two surfaces, and the first-yield safety factor is
# the Tresca shear strength ``Y/2`` over the largest Hertz shear stress ``tau1`` (Johnson 1985
# §4.2; 0.30 p0 without friction, a little more with it).
sigma = res.inputs.sigma
Y = res.inputs.cam["Y"]
assert np.allclose(r["lam"], r["h_min"] / sigma, rtol=1e-12), "lambda = h_min / sigma"
assert np.allclose(r["sf_yield"], Y / (2.0 * max_shear(sc.mu).value * r["p0"]), rtol=1e-9)
print(f"composite roughness sigma = {sigma * 1e6:.3f} um; "
      f"lambda {r['lam'].min():.2f} .. {r['lam'].max():.2f}")

# %%
# The governing criterion
# -----------------------
# Of the safety factors, the smallest decides; here subsurface fatigue, at the angle of the
# peak contact pressure. ``lambda`` below 1 at every angle means boundary lubrication: the
# asperities touch, and the wear coefficient is chosen for that regime. The rolling roller
# slides little (2 % slide-to-roll), so the flash temperature rise stays below 1 K and
# scuffing is far away.
safety = {"first yield": "sf_yield", "shakedown": "sf_shakedown", "subsurface fatigue": "sf_subsurface",
          "surface fatigue": "sf_surface_fatigue", "scuffing": "sf_scuffing"}
governing = min(safety, key=lambda name: res.worst[name][0])
value, theta, _ = res.worst[governing]
print(f"governing: {governing}, safety factor {value:.2f} at {np.degrees(theta):.0f} deg "
      f"(p0 = {np.interp(theta, r['theta'], r['p0']) / 1e6:.0f} MPa)")
assert value == min(np.nanmin(r[key]) for key in safety.values())

fig, axes = plt.subplots(3, 1, figsize=(6.4, 8.0), sharex=True, constrained_layout=True)
axes[0].plot(deg, r["lam"])
axes[0].axhspan(0, 1, color="r", alpha=0.1, label="boundary (lambda < 1)")
axes[0].axhspan(1, 3, color="y", alpha=0.1, label="mixed (1-3)")
axes[0].set(ylabel="film parameter lambda", ylim=(0, 3.5), title=sc.name)
axes[1].plot(deg, r["dT_flash"], label=f"flash rise over the {res.inputs.T_oil:.0f} °C oil")
axes[1].set(ylabel="flash temperature rise (K)")
for name, key in safety.items():
    axes[2].semilogy(deg, r[key], label=name)
axes[2].axhline(1.0, color="k", lw=1)
axes[2].plot(np.degrees(theta), value, "ko", mfc="none", ms=10)
axes[2].set(xlabel="cam angle (deg)", ylabel="safety factor")
for ax in axes:
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)

plt.show()
