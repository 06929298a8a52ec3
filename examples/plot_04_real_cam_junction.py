r"""
A real cam: the curvature jump at a junction
============================================

Hertz theory, and an FE model whose cam is a circular arc of the local radius of curvature,
both assume the curvature is constant across the contact width. A simple-harmonic rise next
to a dwell breaks that: the acceleration steps at the junction, so the cam's radius of
curvature jumps there (here from 20 mm on the base circle to 54 mm at the start of the rise).
When the contact straddles the junction the pressure is no longer a Hertz ellipse. femcam
detects these angles, inserts extra ones around each jump and solves them on the *exact* cam
surface; the ``model`` column of the sweep says which model answered each row.
"""

# %%
# Sweep across the junction
# -------------------------
# ``examples/shm_dwell_junction.toml``: dwell, SHM rise of 8 mm over 90 deg, dwell, SHM fall; a
# 10 mm roller on a 20 mm base circle. The sweep is asked for every 2 deg from 80 to 100 deg;
# it adds 8 angles per side over the span in which the contact straddles the 90 deg junction
# (plus +-0.05 and +-0.1 deg) and flags them ``curvature_jump``. A few angles keep this fast;
# ``femcam sweep`` on the whole revolution does the same at all four junctions.
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import femcam

HERE = Path(__file__).parent if "__file__" in globals() else Path.cwd()  # sphinx-gallery: cwd
res = femcam.sweep(HERE / "shm_dwell_junction.toml",
                   femcam.SweepOptions(angles=np.radians(np.arange(80.0, 100.1, 2.0)), plots=False))
t = res.table
deg = np.degrees(t["theta"])
jump = t["curvature_jump"] == 1
print(f"{len(deg)} rows, {jump.sum()} inserted at the junction; models: "
      f"{ {str(m): int(n) for m, n in zip(*np.unique(t['model'], return_counts=True), strict=True)} }")
for k in np.flatnonzero(jump)[::3]:
    print(f"{deg[k]:8.3f} deg  {t['model'][k]:8s}  p0 = {t['p0_fe'][k] / 1e6:6.1f} MPa  Hertz = "
          f"{t['p0_hertz'][k] / 1e6:6.1f} MPa  arc vs exact = {100 * t['exact_vs_arc_p0'][k]:+5.2f} %")

# %%
# What the exact gap changes
# --------------------------
# Away from the junction the two FE models and Hertz agree. At 90 deg Hertz (and the arc-gap
# FE) takes the rise side's 54 mm radius and answers 660 MPa; the exact surface still carries
# half the contact on the 20 mm base circle, and the peak pressure is 708 MPa: the arc gap
# (and Hertz) fall 6.8 % short of it.
# The exact-gap pressure moves smoothly from one Hertz value to the other as the contact
# rolls over the junction. ``est_err_hertz`` is femcam's estimate of Hertz's error from the
# change of curvature across the contact; where it exceeds the sweep's tolerance the exact gap
# is solved.
k90 = int(np.argmin(np.abs(deg - 90.0)))
far = np.abs(deg - 90.0) > 0.3
p_before, p_after = t["p0_hertz"][deg < 89.0].max(), t["p0_hertz"][k90]
print(f"at 90 deg: exact-gap FE {t['p0_fe'][k90] / 1e6:.1f} MPa, Hertz {p_after / 1e6:.1f} MPa "
      f"(arc-gap FE {100 * t['exact_vs_arc_p0'][k90]:+.2f} % off the exact gap)")
assert np.all(np.abs(t["p0_fe"][far] / t["p0_hertz"][far] - 1) < 3e-3), "FE = Hertz away from the jump"
assert -7.5 < 100 * t["exact_vs_arc_p0"][k90] < -6.0, "arc gap misses the junction peak by ~6.8 %"
assert p_after < t["p0_fe"][k90] < p_before, "the junction p0 lies between the two Hertz values"

# %%
# The picture: p0 against the angle, each point coloured by the model that answered, with
# the Hertz values of the two sides; below, the estimated Hertz error that triggers the
# exact gap.
fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(6.4, 5.4), sharex=True, constrained_layout=True)
ax1.plot(deg, t["p0_hertz"] / 1e6, "k-", lw=1, label="Hertz (local radius)")
for model, marker in (("fe_arc", "o"), ("fe_exact", "s")):
    sel = t["model"] == model
    ax1.plot(deg[sel], t["p0_fe"][sel] / 1e6, marker, ms=4, mfc="none", label=f"FE, model = {model}")
ax1.set(ylabel="p0 (MPa)", title="SHM rise after a dwell: the 90 deg junction")
ax1.legend()
ax2.semilogy(deg, 100 * np.maximum(t["est_err_hertz"], 1e-6), ".-", ms=3)
ax2.axhline(100 * res.provenance["options"]["tolerance"], color="r", lw=1, ls="--", label="tolerance")
ax2.set(xlabel="cam angle (deg)", ylabel="est. Hertz error (%)", ylim=(1e-3, 30))
ax2.legend()
for ax in (ax1, ax2):
    ax.grid(alpha=0.3)
    ax.set_xlim(87.5, 92.5)

plt.show()
