r"""
Wear over a revolution
======================

Archard's law says the volume worn is proportional to the normal load and the sliding
distance: ``V = k F s``. Over one cam revolution the contact moves round the cam and slides a
little against the roller (a rolling roller slips by its slide-to-roll ratio), so each point of
the cam profile collects wear from every pass of the contact over it. femcam's wear map
integrates this per point from the Hertz pressure and the slip speed at each angle. This
example maps the wear of the seed 002 study model for its three Bézier laws, and then
recomputes seed 000's shortcut (*Influence of kinematic parameters on wear reduction in
cam-follower system*), which ranks motion laws by the RMS follower velocity.
"""

# %%
# The wear map of three laws
# --------------------------
# ``scene_wear`` analyses the scene at the given angles (uniform over one revolution), takes
# the slip model and the wear coefficient from the scene's ``[wear]`` table (here the roller
# slides at 2 % of its rolling speed, ``k`` = 5e-18 m³/(N m)) and returns a ``WearMap``:
# depth per revolution along the cam profile and the worn volumes. ``Scene.with_law`` swaps
# the motion law of the rise and fall.
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from femcam.kinematics import law
from femcam.scene import contact_case, load_scene
from femcam.wear import format_table3, seed000_table
from femcam.wear.scene import scene_wear

HERE = Path(__file__).parent if "__file__" in globals() else Path.cwd()  # sphinx-gallery: cwd
sc = load_scene(HERE / "seed002_study_model.toml")
theta = np.radians(np.arange(0.0, 360.0, 0.5))
fig, ax = plt.subplots(figsize=(6.4, 3.8), constrained_layout=True)
for name in ("bezier5", "bezier7", "bezier9"):
    wm, st, slip = scene_wear(contact_case(sc.with_law(name), theta))
    print(f"{name}: max cam wear {wm.max_depth * 1e9:.2f} nm after {wm.cycles:.0e} revolutions at "
          f"{np.degrees(wm.theta_max):.1f} deg; volume {wm.volume_cam * 1e18:.2f} um^3 per revolution "
          f"(Archard {wm.volume_archard * 1e18:.2f} um^3)")
    # The map conserves the Archard volume k * sum(F v_slip dt) and every pressure profile
    # carries its force (l pi a p0 / 2 = Fc).
    assert wm.conservation_error < 1e-4 and wm.load_error < 1e-9
    ax.plot(np.degrees(wm.theta), wm.depth_at_theta * wm.cycles * 1e9, label=name)
ax.set(xlabel="cam angle of the contact (deg)", ylabel="cam wear depth (nm)",
       title=f"Archard wear after {wm.cycles:.0e} revolutions ({wm.model})")
ax.grid(alpha=0.3)
ax.legend()

# %%
# The wear is deepest on the flanks, where the contact force and the curvature give the
# highest pressure, and the higher-degree laws, with their larger peak accelerations, wear a
# little more. The FE sweep can feed the same map with its own pressures
# (``scene_wear(..., fe=result)``, or ``femcam wear map --source fe``).
#
# Seed 000's RMS-velocity method
# ------------------------------
# Seed 000 takes the sliding distance as proportional to the RMS follower velocity of the
# law, ``v_rms = (h omega / beta) sqrt(int_0^1 v(u)^2 du)``, and Archard's ``W = K L S / H``.
# ``seed000_table`` recomputes its Table 3 from the exact laws; for simple harmonic motion the
# integral is ``pi^2 / 8``, which a quadrature of the law's velocity must reproduce.
tab = seed000_table()
print("\n\n".join(format_table3(tab).split("\n\n")[:3]))
u = np.linspace(0.0, 1.0, 200_001)
for row in tab.rows:
    I_quad = np.trapezoid(law(row.law).v(u) ** 2, u)
    assert abs(I_quad / row.I_closed - 1) < 1e-6, f"{row.law}: int v^2 du"
assert abs(next(r for r in tab.rows if r.law == "shm").I_closed - np.pi**2 / 8) < 1e-12

# %%
# The ratio to SHM ranks the laws. From the exact laws uniform velocity comes out lowest and
# cycloidal highest: the reverse of the ranking printed in seed 000, whose v_rms for SHM and
# cycloidal differ from the exact integrals (its uniform-velocity value agrees).
# ``femcam wear seed000`` prints both side by side.
fig, ax = plt.subplots(figsize=(6.4, 3.4), constrained_layout=True)
names = [r.law for r in tab.rows]
x = np.arange(len(names))
ax.bar(x - 0.2, [r.ratio for r in tab.rows], width=0.4, label="femcam (exact laws)")
ax.bar(x + 0.2, [tab.paper[n]["ratio"] for n in names], width=0.4, label="seed 000, printed")
ax.set_xticks(x, names)
ax.set(ylabel="v_rms / v_rms(SHM)", title="seed 000: wear ranking by RMS velocity")
ax.legend()

plt.show()
