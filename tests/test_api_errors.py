"""API bad input: ``ContactModel.build`` / ``.solve`` refuse wrong types with an InputError
naming the parameter and its unit (reference: the bad values typed in the test), before any
mesh is built."""

import math

import numpy as np
import pytest

from femcam.errors import InputError
from femcam.fe import ContactModel
from femcam.materials import Material

STEEL = Material(E=210e9, nu=0.3)
BASE = dict(Rr=0.01, rho_ref=0.02, cam=STEEL, roller=STEEL, length=0.01, a_ref=2e-4)


@pytest.mark.parametrize("key, value, msg", [
    ("rho_ref", "abc", "rho_ref = 'abc' m: must be a number (inf for a flat cam)"),
    ("rho_ref", np.array([0.01, 0.02]), "rho_ref = array([0.01, 0.02]) m: must be a number"),
    ("rho_ref", None, "rho_ref = None m: must be a number"),
    ("rho_ref", True, "rho_ref = True m: must be a number"),
    ("rho_ref", 0.0, "rho_ref = 0 m: must be nonzero"),
    ("rho_ref", math.nan, "rho_ref = nan m: must be nonzero"),
    ("cam", None, "cam = None: must be a Material"),
    ("roller", "steel", "roller = 'steel': must be a Material"),
    ("mesh", "fine", "mesh = 'fine': must be a MeshOptions or None"),
    ("solver", 3, "solver = 3: must be a SolverOptions or None"),
])
def test_build_refuses_bad_arguments(key, value, msg):
    with pytest.raises(InputError) as ei:
        ContactModel.build(**{**BASE, key: value})
    assert msg in str(ei.value)


@pytest.mark.parametrize("rho, msg", [("abc", "rho = 'abc' m: must be a number"),
                                      (np.array([0.02]), "rho = array([0.02]) m: must be a number"),
                                      (math.nan, "rho = nan m: must be nonzero")])
def test_solve_refuses_bad_rho(rho, msg):
    # solve checks its arguments before touching the model, so a bare instance is enough
    model = object.__new__(ContactModel)
    with pytest.raises(InputError) as ei:
        model.solve(F=100.0, rho=rho)
    assert msg in str(ei.value)


def test_numpy_scalar_radius_is_accepted():
    from femcam.fe.model import _radius
    assert _radius("rho", np.float32(0.5)) == 0.5 and _radius("rho", -math.inf) == -math.inf
