"""Hertz-answered sweep rows (method auto) carry the traction of their row: the stress maxima
use q = (|Q|/Fc) p, not full sliding q = mu p (femcam.sweep.realrows).

References written here, never femcam output:

* the McEwen / Smith-Liu line-contact field with q = r p (Johnson 1985 eqs. 7.20-7.21, a = p0 = 1)
  typed in numpy below, its von Mises (plane strain) and tau1 maxima found by a dense grid
  search refined with Nelder-Mead;
* the surface closed forms of that field (Johnson 1985 §7.1): sigma_x = -sqrt(1 - X^2) - 2 r X
  for |X| <= 1, so min sigma_x = -p0 sqrt(1 + 4 r^2) at X = 2r / sqrt(1 + 4 r^2),
  max sigma_x = +2 r p0 at X = -1, max |tau_xz| = r p0, min sigma_z = -p0.
"""

import copy
import math

import numpy as np
import pytest
from scipy.optimize import minimize

from femcam.materials import Material
from femcam.sweep.chunk import ChunkRows
from femcam.sweep.options import ContactParams
from femcam.sweep.realcam import Traction
from femcam.sweep.realrows import RATIO_STEPS, hertz_answer, hertz_row_traction

NU = 0.3
MAT = Material(E=210e9, nu=NU)
P0, A = 1.0e9, 1.0e-4


def field(X, Z, r):
    """(sx, sz, txz)/p0 of Hertz pressure plus traction q = r p in +x (Johnson eqs. 7.20-7.21)."""
    X, Z = np.asarray(X, float), np.asarray(Z, float)
    Aq = 1 - X * X + Z * Z
    rr = np.sqrt(Aq * Aq + 4 * X * X * Z * Z)
    m = np.sqrt(0.5 * (rr + Aq))
    n = np.copysign(np.sqrt(np.maximum(0.5 * (rr - Aq), 0.0)), X)
    D = m * m + n * n
    sx = -(m * (1 + (Z * Z + n * n) / D) - 2 * Z)
    sz = -m * (1 - (Z * Z + n * n) / D)
    txz = -n * (m * m - Z * Z) / D
    sxq = n * (2 - (Z * Z - m * m) / D) - 2 * X
    szq = -n * (m * m - Z * Z) / D
    txzq = -(m * (1 + (Z * Z + n * n) / D) - 2 * Z)
    return sx + r * sxq, sz + r * szq, txz + r * txzq


def measure(q, X, Z, r):
    sx, sz, txz = field(X, Z, r)
    if q == "tau1":
        return np.hypot((sx - sz) / 2, txz)
    sy = NU * (sx + sz)  # plane strain
    return np.sqrt(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2) + 3 * txz**2)


def reference_max(q, r):
    """(max / p0, depth / a): grid search (X in [-1.5, 1.5], Z in [0, 1.5]) + Nelder-Mead."""
    X, Z = np.meshgrid(np.linspace(-1.5, 1.5, 600), np.linspace(0.0, 1.5, 301))  # X = +-1 avoided
    with np.errstate(invalid="ignore", divide="ignore"):
        v = measure(q, X, Z, r)
    k = np.nanargmax(v)

    def neg(p):
        with np.errstate(invalid="ignore", divide="ignore"):
            f = measure(q, p[0], abs(p[1]), r)
        return -float(f) if np.isfinite(f) else 0.0
    res = minimize(neg, [X.flat[k], Z.flat[k]], method="Nelder-Mead",
                   options={"xatol": 1e-9, "fatol": 1e-14, "maxiter": 4000})
    return -res.fun, abs(res.x[1])


def _rows(Q_over_F, mu):
    n = len(Q_over_F)
    rows = ChunkRows(n)
    F = np.linspace(100.0, 500.0, n)
    rows.Fc[:], rows.a_hertz[:], rows.p0_hertz[:] = F, A, P0
    cp = ContactParams(Rr=0.01, length=0.01, cam=MAT, roller=MAT, mu=mu, plane="strain", sliding=1)
    tr = Traction(np.asarray(Q_over_F, float) * F, np.ones(n, int), "test")
    flags = [[] for _ in range(n)]
    hertz_answer(rows, np.arange(n), cp, tr, flags)
    return rows, flags


MU = 0.25


@pytest.fixture(scope="module")
def answered():
    # |Q|/F: on the ratio grid (0.05 = 20/100 mu), full sliding (no Q), none, off the grid and
    # negative, and more than mu F (clipped: full sliding)
    return _rows([0.05, math.nan, 0.0, -0.0123, 0.4], MU)


@pytest.mark.parametrize("i, r", [(0, 0.05), (1, MU), (2, 0.0), (4, MU)])
def test_subsurface_maxima_use_the_row_traction_ratio(answered, i, r):
    rows, _ = answered
    for q, col in (("von_mises", "vm"), ("tau1", "tau1")):
        val, z = reference_max(q, r)
        # both maximisers converge to ~1e-10 p0; the depth of a flat maximum is fixed only to
        # ~sqrt(value error / curvature): 1e-6 p0 on the value, 1e-4 a on the depth
        assert getattr(rows, f"{col}_max")[i] / P0 == pytest.approx(val, abs=1e-6), (q, r)
        assert getattr(rows, f"{col}_depth")[i] / A == pytest.approx(z, abs=1e-4), (q, r)


@pytest.mark.parametrize("i, r", [(0, 0.05), (1, MU), (2, 0.0), (3, 0.0123), (4, MU)])
def test_surface_extremes_use_the_row_traction_ratio(answered, i, r):
    rows, _ = answered
    # off the ratio grid the ratio is taken within mu / (2 RATIO_STEPS): each extreme moves by
    # its slope (d/dr of the closed forms: 4r/sqrt(1+4r^2) <= 2, 2, 1) times that
    tol = 1e-6 + 2.0 * MU / (2 * RATIO_STEPS) * (i == 3)
    assert rows.surf_sx_min[i] / P0 == pytest.approx(-math.sqrt(1 + 4 * r * r), abs=tol)
    assert rows.surf_sx_max[i] / P0 == pytest.approx(2 * r, abs=tol)
    assert rows.surf_txz_absmax[i] / P0 == pytest.approx(r, abs=tol)
    assert rows.surf_sz_min[i] / P0 == pytest.approx(-1.0, abs=1e-6)


def test_off_grid_ratio_is_within_the_grid_bound(answered):
    """|Q|/F = 0.0123 (mu = 0.25: grid step 0.0025): the von Mises maximum is the reference's at
    0.0123 within the reference's own change over half a grid step."""
    rows, _ = answered
    h = MU / (2 * RATIO_STEPS)
    val = reference_max("von_mises", 0.0123)[0]
    spread = max(abs(reference_max("von_mises", 0.0123 + s * h)[0] - val) for s in (-1, 1))
    assert rows.vm_max[3] / P0 == pytest.approx(val, abs=spread + 1e-6)


def test_traction_columns_and_states(answered):
    rows, flags = answered
    F = rows.Fc
    np.testing.assert_allclose(rows.Q, [0.05 * F[0], MU * F[1], 0.0, -0.0123 * F[3], MU * F[4]],
                               rtol=1e-12)
    assert list(rows.slip_state) == ["partial slip", "sliding", "none", "partial slip", "sliding"]
    # Cattaneo-Mindlin stick zone 2 a sqrt(1 - |Q|/(mu F)) (Johnson 1985 §7.2)
    assert rows.stick_width[0] == pytest.approx(2 * A * math.sqrt(1 - 0.05 / MU), rel=1e-12)
    assert all(f == [] for f in flags)


def test_frictionless_row_with_mechanism_Q_is_flagged():
    """mu = 0 cannot carry the mechanism's Q: Q = 0, the frictionless Hertz maxima, and the row
    says so."""
    rows, flags = _rows([0.02, 0.0], 0.0)
    assert flags == [["Q_without_friction"], []]
    assert rows.Q[0] == 0.0 and rows.slip_state[0] == "none"
    val, z = reference_max("von_mises", 0.0)
    assert rows.vm_max[0] / P0 == pytest.approx(val, abs=1e-6)
    assert rows.vm_depth[0] / A == pytest.approx(z, abs=1e-4)


def test_row_traction_for_the_analytic_vtu(answered):
    rows, _ = answered
    cp = ContactParams(Rr=0.01, length=0.01, cam=MAT, roller=MAT, mu=MU, plane="strain", sliding=-1)
    assert hertz_row_traction(rows, 0, cp) == pytest.approx((0.05, 1))
    assert hertz_row_traction(rows, 3, cp) == pytest.approx((0.0123, -1))
    assert hertz_row_traction(rows, 2, cp) == (0.0, -1)          # no traction: cp's direction
    rows = copy.copy(rows)                                       # the fixture's rows, shallow
    rows.Q = np.full(5, np.nan)
    assert hertz_row_traction(rows, 1, cp) == (MU, -1)           # no Q: full sliding
