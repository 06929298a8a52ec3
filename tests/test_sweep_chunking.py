"""The sweep's rows do not depend on how the angles are split into chunks (docs/sweep.md,
"Chunking").

Reference: the same angles swept with a different ``chunk_size``. Every per-angle model is chosen
from the angle's own load case (layer models by :func:`femcam.layers.from_scene.model_grading`,
the half-space strip warm-started from the cold solution at the angle's anchor,
:data:`femcam.halfspace.rows.ANCHOR_STEP`), so the rows must be bit-identical: the
comparison is exact (``equal_nan``), without a tolerance. The timing columns are left out
(wall clock).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from femcam.layers.from_scene import model_grading
from femcam.scene import load_scene
from femcam.sweep import RunOptions, SweepOptions, providers, sweep

EX = "examples/"
TIMING = ("fe_time", "build_time")


def _table(scene, theta, chunk_size):
    r = sweep(scene,
              SweepOptions(angles=theta, method="hertz", chunk_size=chunk_size, plots=False, vtk_every=0),
              RunOptions(workers=1))
    return r.table


def _assert_identical(t1, t2, columns):
    for c in columns:
        a, b = np.asarray(t1[c]), np.asarray(t2[c])
        if a.dtype.kind == "f":
            np.testing.assert_array_equal(a, b, err_msg=f"column {c} depends on the chunk size")
        else:
            assert list(a.astype(str)) == list(b.astype(str)), f"column {c} depends on the chunk size"


def test_layer_columns_do_not_depend_on_chunk_size():
    # 20 and 40 deg on the rise: in one chunk the old code solved 40 deg with the model it had
    # built for 20 deg (it covered the case), in chunks of 1 with a model of its own, and the
    # coating stress read 123.3 or 102.1 MPa (21 %)
    scene = load_scene(EX + "seed002_coated.toml")
    th = np.radians([20.0, 40.0])
    t1, t2 = _table(scene, th, 1), _table(scene, th, 2)
    cols = [c.si for c in providers.LAYERS]
    assert np.all(np.isfinite(np.asarray(t1["layer_coating_sx_max"], float)))
    _assert_identical(t1, t2, [c for c in t1 if c not in TIMING])
    assert set(cols) <= set(t1)


@pytest.mark.slow
def test_halfspace_columns_do_not_depend_on_chunk_size():
    # the crowned roller: a warm start from the chunk's previous angle moved p_axial_peak by
    # up to 4e-5 relative between chunk sizes 1 and 36
    scene = load_scene(EX + "seed002_crowned.toml")
    th = np.radians(np.arange(0.0, 360.0, 30.0))
    t1, t2, t5 = _table(scene, th, 1), _table(scene, th, 12), _table(scene, th, 5)
    _assert_identical(t1, t2, [c for c in t1 if c not in TIMING])
    _assert_identical(t1, t5, [c for c in t1 if c not in TIMING])


def test_halfspace_rows_of_one_angle_do_not_depend_on_its_neighbours():
    # the provider's function directly (no FE): an angle alone and after two others
    scene = load_scene(EX + "seed002_crowned.toml")
    alone = providers.halfspace_rows(scene, np.radians([60.0]))
    after = providers.halfspace_rows(scene, np.radians([0.0, 30.0, 60.0]))
    for k, v in alone.items():
        if np.asarray(v).dtype.kind == "f":
            np.testing.assert_array_equal(v[0], after[k][2], err_msg=k)
        else:
            assert v[0] == after[k][2], k


def test_model_grading_depends_on_the_load_case_only():
    # the bin centre: a_ref within a factor 1.25**0.5 of a, and the curvature within K_BIN / 2
    Rr = 0.01
    for a, rho in ((1e-4, math.inf), (3.7e-5, 0.012), (2e-4, -0.05)):
        rho_ref, a_ref = model_grading(a, rho, Rr)
        assert 1.25 ** -0.5 <= a / a_ref <= 1.25 ** 0.5
        k = 0.0 if math.isinf(rho) else Rr / rho
        assert abs(k - Rr / rho_ref) <= 0.125 + 1e-12
        assert model_grading(a * 1.0000001, rho, Rr) == (rho_ref, a_ref)


@pytest.mark.slow
def test_fe_sweep_of_the_crowned_roller_does_not_depend_on_chunk_size():
    # method fe: the FE contact (families planned over the whole angle list) and the 2D FE at the
    # most loaded slice, whose load comes from the half-space rows
    scene = load_scene(EX + "seed002_crowned.toml")
    th = np.radians([0.0, 50.0, 130.0])
    t = [sweep(scene,
               SweepOptions(angles=th, method="fe", chunk_size=c, plots=False, vtk_every=0),
               RunOptions(workers=1)).table
         for c in (1, 3)]
    assert np.all(np.isfinite(np.asarray(t[0]["p0_peak_slice"], float)))
    _assert_identical(t[0], t[1], [c for c in t[0] if c not in TIMING])
