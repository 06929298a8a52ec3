r"""
Hertz line contact with friction
================================

A cam and its roller touch along a line. Before any finite element is built, Hertz theory gives
the answer the FE has to reproduce: the contact half-width ``a``, the peak pressure ``p0`` and
the stress field under the surface. This example computes them for a seed 002-like contact
(the study model of *a study of the stresses in a cam mechanism with a roller follower whose
displacement law is designed with Bézier curves*, eqs. 5-10), draws the surface stresses and the
subsurface field with sliding friction (McEwen 1949, in Johnson's *Contact Mechanics* form),
and finds the two maxima a designer checks: the principal shear ``tau1`` and the von Mises
stress.
"""

# %%
# The contact
# -----------
# Everything inside femcam is SI: newtons, metres, pascals. A 1500 N force on a 10 mm wide
# roller of radius 10 mm against a cam whose radius of curvature is 20 mm at this angle; both
# bodies are steel, and the roller slides with friction coefficient 0.1 (seed 002 eq. 8 takes
# full sliding, ``q = mu p``).
import matplotlib.pyplot as plt
import numpy as np

from femcam.hertz import LineContact
from femcam.materials import STEEL

hc = LineContact(F=1500.0, length=0.010, R1=0.020, R2=0.010, cam=STEEL, roller=STEEL, mu=0.1)
print(f"E* = {hc.E_star / 1e9:.1f} GPa, R = {hc.R * 1e3:.3f} mm, w = {hc.w / 1e3:.1f} N/mm")
print(f"half-width a = {hc.a * 1e6:.2f} um, peak pressure p0 = {hc.p0 / 1e6:.1f} MPa")

# %%
# ``LineContact`` is the closed form of Johnson eq. 4.45 (seed 002 eqs. 9-10). Written out by
# hand, ``a = sqrt(4 w R / (pi E*))`` and ``p0 = 2 w / (pi a)``: the two must agree to rounding.
a_hand = np.sqrt(4.0 * hc.w * hc.R / (np.pi * hc.E_star))
p0_hand = 2.0 * hc.w / (np.pi * a_hand)
assert np.isclose(hc.a, a_hand, rtol=1e-12) and np.isclose(hc.p0, p0_hand, rtol=1e-12)

# %%
# Surface stresses
# ----------------
# On the surface (seed 002 eqs. 5-7) the normal stress equals minus the pressure, and friction
# adds a tensile ``sigma_x`` peak of ``2 mu p0`` at the trailing edge ``x = -a``: the stress
# that starts surface cracks when the roller slides.
x = np.linspace(-2.0, 2.0, 801) * hc.a
sx, sz, txz = hc.surface_stress(x)
fig, ax = plt.subplots(figsize=(6.4, 3.6), constrained_layout=True)
ax.plot(x / hc.a, sx / hc.p0, label=r"$\sigma_x$")
ax.plot(x / hc.a, sz / hc.p0, label=r"$\sigma_z = -p$")
ax.plot(x / hc.a, txz / hc.p0, label=r"$\tau_{xz} = -\mu p$")
ax.set(xlabel="x / a", ylabel="stress / p0", title="Surface stresses, mu = 0.1")
ax.grid(alpha=0.3)
ax.legend()
print(f"tensile surface peak sigma_x = {sx.max() / 1e6:.1f} MPa "
      f"at x = {x[np.argmax(sx)] / hc.a:+.2f} a (2 mu p0 = {2 * hc.mu * hc.p0 / 1e6:.1f} MPa)")
assert np.isclose(sx.max(), 2 * hc.mu * hc.p0, rtol=2e-3)

# %%
# The subsurface field
# --------------------
# ``hc.stress(x, z)`` evaluates McEwen's closed form on any grid (depth ``z >= 0`` into the
# cam). Without friction ``tau1`` peaks at ``0.300 p0`` at depth ``0.786 a`` under the centre;
# friction pulls the maximum towards the surface and forward.
X, Z = np.meshgrid(np.linspace(-2.0, 2.0, 241), np.linspace(0.0, 2.0, 121))
field = hc.stress(X * hc.a, Z * hc.a)
fig, axes = plt.subplots(1, 2, figsize=(9.6, 3.6), sharey=True, constrained_layout=True)
for ax, values, name in zip(axes, (field.tau1, field.von_mises), (r"$\tau_1$", "von Mises"), strict=True):
    cs = ax.contourf(X, Z, values / hc.p0, levels=20, cmap="viridis")
    fig.colorbar(cs, ax=ax, label=f"{name} / p0")
    ax.set(xlabel="x / a", title=name)
    ax.invert_yaxis()
axes[0].set_ylabel("depth z / a")

# %%
# The maxima
# ----------
# ``max_shear`` and ``max_von_mises`` locate the maxima by a zoomed search on the closed form;
# the grid above must come close from below (its spacing is a/60).
t1, vm = hc.max_shear(), hc.max_von_mises()
for name, m in (("tau1", t1), ("von Mises", vm)):
    print(f"max {name:9s} = {m.value / 1e6:6.1f} MPa = {m.value / hc.p0:.4f} p0 "
          f"at x = {m.x / hc.a:+.3f} a, z = {m.z / hc.a:.3f} a")
for m, values in ((t1, field.tau1), (vm, field.von_mises)):
    assert values.max() <= m.value * (1 + 1e-9)
    assert values.max() >= m.value * (1 - 2e-3)
for ax, m in zip(axes, (t1, vm), strict=True):
    ax.plot(m.x / hc.a, m.z / hc.a, "r+", ms=12, mew=2)

# %%
# The frictionless reference (Johnson 1985 §4.2.3) is the classic check: 0.300 p0 at 0.786 a.
t1_0 = LineContact(F=1500.0, length=0.010, R1=0.020, R2=0.010, cam=STEEL, roller=STEEL).max_shear()
print(f"frictionless tau1 = {t1_0.unit.value:.4f} p0 at z = {t1_0.unit.z:.4f} a")
assert abs(t1_0.unit.value - 0.3004) < 1e-3 and abs(t1_0.unit.z - 0.7861) < 1e-3

plt.show()
