"""The per-solve range of txz over one pass (femcam.fe.passrange.grid_shear_range) against a
plain Python loop over the rows of the full grid (the definition, Johnson 1985 §9.2:
max over depth of max_x txz - min_x txz)."""

import numpy as np
import pytest

from femcam.fe.passrange import grid_shear_range, pass_shear_range


def _loop_reference(full, xs, zs, ok):
    """The definition row by row, in plain Python (first extreme in x order on ties)."""
    best = None
    for k in range(full.shape[0]):
        cols = [j for j in range(full.shape[1]) if ok[k, j]]
        if not cols:
            continue
        hi = max(cols, key=lambda j: (full[k, j], -j))
        lo = min(cols, key=lambda j: (full[k, j], j))
        rng = full[k, hi] - full[k, lo]
        if best is None or rng > best[0]:
            best = (rng, k, hi, lo)
    return best


@pytest.mark.parametrize("seed", range(6))
def test_grid_shear_range_matches_the_row_loop_and_the_full_grid(seed):
    rng = np.random.default_rng(seed)
    nz, nx = 9, 13
    xs, zs = np.linspace(-1.0, 1.0, nx), np.linspace(0.1, 1.0, nz)
    full = rng.normal(size=(nz, nx))
    ok = rng.random((nz, nx)) > 0.3
    ok[rng.integers(nz)] = False                            # a row without points
    r = grid_shear_range(full[ok], xs, zs, ok)
    value, k, hi, lo = _loop_reference(full, xs, zs, ok)
    assert r["value"] == pytest.approx(value, rel=1e-15, abs=0.0)
    assert (r["z"], r["x_max"], r["x_min"]) == (zs[k], xs[hi], xs[lo])
    assert r == pass_shear_range(np.where(ok, full, np.nan), xs, zs, ok)


def test_grid_shear_range_without_points():
    ok = np.zeros((3, 4), bool)
    r = grid_shear_range(np.zeros(0), np.arange(4.0), np.arange(3.0), ok)
    assert r["value"] == 0.0 and not r["inside"] and np.isnan(r["z"])
