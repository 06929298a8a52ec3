"""Needle load sharing (femcam.bodies) against the Stribeck distribution, derived here.

Reference (Stribeck 1901; Harris & Kotzalas 2006 §7.4), typed in with its assumptions: rigid
ring and pin, zero clearance, Z needles at angles psi_j from the load line, each with the
load-deflection law Q = K delta^n. A rigid translation delta_r of the ring along the load
compresses needle j by delta_r cos(psi_j) (only where cos > 0), so

    Q_j = K (delta_r cos psi_j)^n,   F = sum_j Q_j cos psi_j = K delta_r^n sum_j cos^(n+1) psi_j

    Q(psi_0) = F cos^n(psi_0) / sum_{cos psi_j > 0} cos^(n+1) psi_j,

the most loaded needle at psi_0 = 0 (a needle on the load line: Q_max = F / sum cos^(n+1)) or
psi_0 = pi / Z (the load line between two needles). For line contacts n = 10/9 (Palmgren's
delta ~ Q^0.9, femcam.bodies.geometry). (Stribeck's classical Q_max = 5 F / Z for balls and
~4.6 F / Z for rollers add a clearance allowance to the zero-clearance value 4.37 F / Z and
4.08 F / Z.)
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from femcam.bodies import RingMeshOptions, RingModel, RollerBearing, needle_approach, solve_ring
from femcam.errors import ConvergenceError
from femcam.materials import STEEL, Material
from femcam.mesh import MeshOptions

RIGID = Material(E=210e9 * 1e5, nu=0.3)
Z = 18


@pytest.fixture(scope="module")
def rigid_model():
    b = RollerBearing(Ro=0.01, Ri=0.007, support="needles", Rp=0.005, c=0.0, Z=Z, r_n=0.001,
                      ring=RIGID, pin=None)
    return RingModel.build(bearing=b, cam=STEEL, rho_ref=0.02, a_ref=1.05e-4, length=0.01,
                           ring_mesh=RingMeshOptions(n_bore=72), mesh=MeshOptions(a_over_h=8))


@pytest.mark.parametrize("cage", [0.0, math.pi / Z], ids=["needle_on_load_line", "between_needles"])
def test_rigid_ring_needle_loads_follow_stribeck(rigid_model, cage):
    F, n = 1500.0, 10.0 / 9.0
    r = solve_ring(rigid_model, F=F, rho=0.02, cage=cage)
    psi = np.angle(np.exp(1j * (-0.5 * math.pi + cage + 2 * math.pi * np.arange(Z) / Z + 0.5 * math.pi)))
    cs = np.cos(psi)
    s = np.sum(cs[cs > 1e-12] ** (n + 1))
    ref = F * np.clip(cs, 0, None) ** n / s
    np.testing.assert_allclose(r.needle_Q, ref, rtol=1e-4, atol=1e-6 * F,
                               err_msg="Stribeck: Q_j = F cos^n psi_j / sum cos^(n+1)")
    # the classical zero-clearance line-contact number for a needle on the load line
    if cage == 0.0:
        assert abs(r.needle_Q_max * Z / F - Z / s) < 1e-3 and 4.0 < Z / s < 4.2


def test_needle_law_is_palmgren():
    """delta = 2 x 3.84e-5 (Q l)^0.9 / l^0.8 mm (Q l in N, l in mm): 1500 N on l = 10 mm."""
    ref_mm = 2 * 3.84e-5 * 1500**0.9 / 10**0.8
    np.testing.assert_allclose(needle_approach(150e3, 0.01), ref_mm * 1e-3, rtol=1e-12)


def test_needle_secant_failure_carries_the_full_history(rigid_model):
    """tol = 0 never settles: the ConvergenceError holds one relative change per secant
    iteration (max_secant = 3 of them, not only the last), the last one quoted in the message,
    and the secant iteration contracts (the first change is the largest)."""
    with pytest.raises(ConvergenceError) as exc:
        solve_ring(rigid_model, F=1500.0, rho=0.02, max_secant=3, tol=0.0)
    h = exc.value.history
    assert len(h) == 3 and all(math.isfinite(x) and x >= 0.0 for x in h)
    assert f"last relative change {h[-1]:.3g}" in str(exc.value)
    assert h[0] > h[-1]

