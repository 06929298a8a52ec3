r"""
Follower dynamics: an elastic train and its jump speed
======================================================

Seed 002's contact force (its eq. 11) treats the follower as a rigid mass on a preloaded
return spring: ``Fc = m a + c v + k s + Fpl``. A real follower train is elastic, so it
vibrates, and above some cam speed the return spring can no longer keep the roller on the cam:
the follower *jumps*. This example computes the periodic steady state of the elastic train
of ``examples/seed002_dynamic.toml`` (one degree of freedom), adds a second mass for a 2-DOF
train, compares both with the rigid force, and finds the jump speed.
"""

# %%
# The 1-DOF train at the scene's speed
# ------------------------------------
# The scene's ``[dynamics]`` table gives the tracker mass (0.2 kg), the return spring (800 N/m,
# 1500 N preload) and an assumed train stiffness of 2e6 N/m. ``scene.dynamic_response`` is the
# periodic steady state at 600 rpm (3600 steps per revolution, an exact propagator per step);
# it is what ``Scene.analyse`` hands to the FE sweep, the wear map and the assessment as ``Fc``.
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from femcam.dynamics import TrainModel, jump_speed, periodic_response
from femcam.scene import load_scene

HERE = Path(__file__).parent if "__file__" in globals() else Path.cwd()  # sphinx-gallery: cwd
sc = load_scene(HERE / "seed002_dynamic.toml")
r1 = sc.dynamic_response
deg = np.degrees(r1.theta)
f1_Hz = r1.natural_frequencies[0] / (2 * np.pi)
print(f"{sc.rpm:.0f} rpm, 1-DOF natural frequency {f1_Hz:.0f} Hz: {r1.message}")
print(f"1-DOF Fc (axial) {r1.Fc_axial.min():.1f} .. {r1.Fc_axial.max():.1f} N, "
      f"rigid eq. 11 {r1.Fc_rigid_axial.min():.1f} .. {r1.Fc_rigid_axial.max():.1f} N")

# %%
# The rigid reference is seed 002's eq. 11 itself; written out from the motion program it must
# match to rounding. The stiff, preloaded train follows the cam closely at 600 rpm: within 1 %
# of the rigid force at every angle.
f = sc.train.follower
k = sc.program.svaj(r1.theta, r1.omega)
eq11 = f.m * k.a + f.c * k.v + f.k * k.s + f.Fpl
assert np.allclose(r1.Fc_rigid_axial, eq11, rtol=1e-10), "rigid force = seed 002 eq. 11"
assert np.abs(r1.Fc_axial / r1.Fc_rigid_axial - 1).max() < 1e-2

# %%
# A 2-DOF train
# -------------
# ``TrainModel`` with a second mass ``m2`` on a spring ``k2`` (here an assumed 0.1 kg on
# 1e6 N/m, say a valve on its stem) has two modes; the lower one is below the 1-DOF train's
# frequency, and the force swings wider about the rigid value.
tr2 = TrainModel(follower=f, k_t=sc.train.k_t, c_t=sc.train.c_t, m2=0.1, k2=1.0e6, zeta2=0.05)
r2 = periodic_response(tr2, sc.program, sc.omega)
print(f"2-DOF modes {np.round(r2.natural_frequencies / (2 * np.pi)).astype(int)} Hz: "
      f"Fc {r2.Fc_axial.min():.1f} .. {r2.Fc_axial.max():.1f} N")

fig, ax = plt.subplots(figsize=(6.4, 3.8), constrained_layout=True)
ax.plot(deg, r1.Fc_rigid_axial, "k-", lw=1.5, label="rigid (seed 002 eq. 11)")
ax.plot(deg, r1.Fc_axial, label="1-DOF train")
ax.plot(np.degrees(r2.theta), r2.Fc_axial, label="2-DOF train", alpha=0.8)
ax.set(xlabel="cam angle (deg)", ylabel="axial contact force (N)", title=f"contact force at {sc.rpm:.0f} rpm")
ax.grid(alpha=0.3)
ax.legend()

# %%
# The jump speed
# --------------
# ``jump_speed`` scans the least contact force of the periodic response over a speed range
# and refines the first speed at which it reaches zero (the follower leaves the cam), with the
# same time step throughout so that the least force is a continuous function of speed. It also
# reports the rigid train's lift-off speed. A negative least force is the pull the cam would
# need to keep contact. Just below the jump speed contact is never lost.
j = jump_speed(sc.train, sc.program, 100.0, 8000.0)
print(f"jump speed {j.rpm_jump:.0f} rpm (rigid train: {j.rpm_rigid:.0f} rpm); {j.message}")
below = periodic_response(sc.train, sc.program, 0.99 * j.rpm_jump * np.pi / 30.0,
                          steps_per_rev=j.steps_per_rev)
assert below.Fc_axial.min() > 0.0, "contact kept just below the jump speed"
assert j.rpm_jump < j.rpm_rigid, "the elastic train jumps before the rigid one lifts off"

fig, ax = plt.subplots(figsize=(6.4, 3.6), constrained_layout=True)
ax.plot(j.rpm_scan, j.Fc_min_scan, "o-", ms=3, label="least contact force, 1-DOF")
ax.axhline(0.0, color="k", lw=1)
ax.axvline(j.rpm_jump, color="r", ls="--", label=f"jump {j.rpm_jump:.0f} rpm")
ax.axvline(j.rpm_rigid, color="k", ls=":", label=f"rigid lift-off {j.rpm_rigid:.0f} rpm")
ax.set(xlabel="cam speed (rpm)", ylabel="least axial force (N)", ylim=(-2000, 1700))
ax.grid(alpha=0.3)
ax.legend()

plt.show()
