"""The half-space solver's complementarity residual at any approach, and the strip's window ladder.

References, written here: Hertz point contact (Johnson 1985 eqs. 4.22-4.23: ``a^3 = 3 W R /
(4 E*)``, approach ``delta = a^2 / R``, which is also the largest combined displacement when the
initial gap is 0 at the first point of contact) and, for a single loaded cell, the gap
``h0 + u - alpha`` that is 0 by definition of ``alpha`` (the mean of ``h0 + u`` over the loaded
cells).
"""

from __future__ import annotations

import numpy as np
import pytest

from femcam.halfspace import HalfSpace
from femcam.halfspace.strip import FiniteLengthContact

E_STAR = 210e9 / (2.0 * (1.0 - 0.3**2))      # steel on steel, Johnson eq. 4.22 (Pa)


def test_gap_residual_is_finite_at_zero_approach():
    # one cell, powers of two throughout (exact arithmetic): h0 = -u makes alpha exactly 0
    dx, W = 2.0**-10, 2.0**-10
    hs = HalfSpace(nx=1, ny=1, dx=dx, dy=dx, E_star=1e11)
    h0 = -hs.displacement(np.full((1, 1), W / dx**2)).copy()
    sol = hs.solve(h0, W)
    assert sol.alpha == 0.0                     # the construction
    assert sol.gap_residual == 0.0              # one loaded cell: g = 0 by the definition of alpha


def test_gap_residual_does_not_depend_on_the_level_of_h0():
    # Hertz sphere; the second solve's h0 is lowered by the Hertz approach, so its alpha is ~0
    # (the grid's error on delta, 2e-4 relative at 33 x 33 cells, measured)
    R, W, n = 0.01, 100.0, 33
    a = (3.0 * W * R / (4.0 * E_STAR)) ** (1.0 / 3.0)
    delta = a * a / R
    dx = 2.6 * a / n
    x = (np.arange(n) - (n - 1) / 2) * dx
    X, Y = np.meshgrid(x, x, indexing="ij")
    h0 = (X**2 + Y**2) / (2 * R)
    hs = HalfSpace(nx=n, ny=n, dx=dx, dy=dx, E_star=E_STAR)
    sol = hs.solve(h0, W, tol=1e-8)
    low = hs.solve(h0 - delta, W, tol=1e-8)
    assert abs(low.alpha) < 1e-3 * delta       # the construction
    g = np.abs(h0 + sol.u - sol.alpha)[sol.p > 0].max()
    # relative to the deformation: max u = delta within the grid's error (5e-3 as the Hertz test)
    assert sol.gap_residual == pytest.approx(g / delta, rel=5e-3)
    # converged at tol 1e-8: the complementarity error is far below 1e-6 of the approach,
    # whatever the level of h0 (the old |alpha| scale gave 8e-6 for the lowered h0)
    assert sol.gap_residual < 1e-6 and low.gap_residual < 1e-6
    assert np.isfinite(low.gap_residual)


def test_strip_window_ladder_starts_at_a_class_constant():
    # the smallest rolling-direction half-window is a class constant (1 um), not a property
    assert isinstance(FiniteLengthContact.__dict__["_X0"], float)
    assert FiniteLengthContact._X0 == 1e-6
