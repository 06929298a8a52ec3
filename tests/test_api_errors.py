"""API bad input, exact messages: ``ContactModel.build`` / ``.solve`` refuse wrong types with an
InputError naming the parameter and its unit (reference: the bad values typed in the test),
before any mesh is built.

The generic fault injection over every public callable (string, None, NaN, inf, negative, zero
into each numeric argument) is ``tests/test_api_faults.py``; this file keeps the exact messages
and the methods of built models (``ContactModel``, ``Body``) that it does not reach."""

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


# --------------------------------------------------------------------------- fe / layers checks
# References: the bad values typed in the test and the message format of femcam._validate
# ("<name> = <value> <unit>: <condition>"); before these checks each case gave a bare
# KeyError / ValueError / AttributeError / RuntimeError or silently nan.
def _bare_model():
    """A ContactModel instance without a mesh: the checks run before any model data is read."""
    model = object.__new__(ContactModel)
    object.__setattr__(model, "bodies", {"cam": None, "roller": None})
    return model


def test_stress_at_refuses_an_unknown_body():
    with pytest.raises(InputError, match=r"body = 'wheel': must be one of \['cam', 'roller'\]"):
        _bare_model().stress_at(None, 0.0, 1e-4, body="wheel")


@pytest.mark.parametrize("rho, msg", [("abc", "rho = 'abc' m: must be a number"),
                                      (0.0, "rho = 0 m: must be nonzero")])
def test_solve_contact_refuses_a_bad_rho(rho, msg):
    from femcam.fe import solve_contact

    with pytest.raises(InputError) as ei:
        solve_contact(100.0, rho, 0.01, STEEL, STEEL, 0.01)
    assert msg in str(ei.value)


@pytest.mark.parametrize("method", ["hertz", "coverage", "covers"])
@pytest.mark.parametrize("F, rho, msg", [(-1.0, 0.02, "F = -1 N: must be >= 0"),
                                         (None, 0.02, "F = None N: must be a number"),
                                         (100.0, "abc", "rho = 'abc' m: must be a number"),
                                         (100.0, math.nan, "rho = nan m: must be nonzero")])
def test_hertz_and_coverage_check_their_inputs(method, F, rho, msg):
    with pytest.raises(InputError) as ei:
        getattr(_bare_model(), method)(F, rho)
    assert msg in str(ei.value)


@pytest.fixture(scope="module")
def small_body():
    """A coarse P2 cam body assembled without ``contact_last``."""
    from femcam.fe.elasticity import assemble_body
    from femcam.mesh import MeshOptions, build_contact_mesh

    cm = build_contact_mesh(Rr=0.01, rho=0.02, a_ref=1e-4, options=MeshOptions(a_over_h=5))
    return assemble_body(cm.cam, STEEL, element="P2")


def test_probe_matrix_refuses_points_outside_the_mesh(small_body):
    from femcam.fe.elasticity import probe_matrix

    with pytest.raises(InputError, match=r"xy = \[\[1\.0, 1\.0\]\] m: must lie inside the mesh of body cam"):
        probe_matrix(small_body, np.array([[1.0], [1.0]]))
    with pytest.raises(InputError, match=r"xy = 'shape \(3,\)' m: must have the shape \(2, n\)"):
        probe_matrix(small_body, np.zeros(3))


@pytest.mark.parametrize("method", ["schur_inverse", "schur_solve"])
def test_schur_methods_need_contact_last(small_body, method):
    args = () if method == "schur_inverse" else (np.zeros((4, 1)),)
    msg = (rf"contact_last = False: Body\.{method} of body cam needs the body assembled with "
           r"assemble_body\(\.\.\., contact_last=True\)")
    with pytest.raises(InputError, match=msg):
        getattr(small_body, method)(*args)


def test_edge_midside_dofs_names_the_unjoined_vertices(small_body):
    from femcam.errors import FemcamError
    from femcam.fe.contact import edge_midside_dofs

    c = np.asarray(small_body.geometry.contact)
    bad = np.array([c[0], c[2]])  # every other vertex: no mesh edge joins them
    with pytest.raises(FemcamError, match=rf"contact = 'vertices {c[0]}, {c[2]}': consecutive contact "
                                          "vertices must be joined by a mesh edge"):
        edge_midside_dofs(small_body, bad)
    assert edge_midside_dofs(small_body, c[:3]).shape == (2, 2)  # the joined ones still work


@pytest.mark.parametrize("omega, msg", [("fast", "omega = 'fast' rad/s: must be a number"),
                                        (math.nan, "omega = nan rad/s: must be finite"),
                                        (0.0, "omega = 0 rad/s: must be > 0")])
def test_mechanism_Q_checks_omega(omega, msg):
    from femcam.fe.choice import mechanism_Q

    th = np.linspace(0.0, 2 * math.pi, 8, endpoint=False)
    with pytest.raises(InputError) as ei:
        mechanism_Q(np.ones(8), th, omega, J=1e-6, T_drag=0.0, Rr=0.01)
    assert msg in str(ei.value)


def test_local_surface_reports_the_half_width_in_mm():
    """A contact zone |x| <= 0.5 m cannot fit on a cam of base radius 20 mm: the message names
    half_width in mm (0.5 m = 500 mm), as the undercut message does."""
    from femcam.errors import PhysicsError
    from femcam.fe.gap import local_surface
    from femcam.kinematics import CamProgram, dwell, fall, rise
    from femcam.profile import RollerFollower

    prog = CamProgram([dwell(math.pi), rise(math.pi / 2, 0.005, "cycloidal"),
                       fall(math.pi / 2, 0.005, "cycloidal")])
    with pytest.raises(PhysicsError, match=r"does not cover \|x\| <= half_width = 500 mm"):
        local_surface(prog, RollerFollower(Rb=0.02, Rr=0.01), 0.5, 0.5)


def test_layer_checks_of_an_unpickled_result_ask_for_the_model():
    """A ContactResult after pickling has model None: the coating/case checks say so."""
    from femcam.fe import ContactResult
    from femcam.layers.interface import _case_row, interface_stress

    r = object.__new__(ContactResult)
    object.__setattr__(r, "model", None)  # what __getstate__ leaves after a pickle round trip
    msg = r"model = None: this ContactResult was unpickled without its factorised model"
    with pytest.raises(InputError, match=msg):
        interface_stress(r, "roller")
    with pytest.raises(InputError, match=msg):
        _case_row(r, None, "cam")


# --------------------------------------------------------------------------- signatures
def test_exact_integrals_are_annotated_as_fractions():
    """They return fractions.Fraction (exact rational), not float."""
    import typing
    from fractions import Fraction

    from femcam.wear import seed000

    for f in (seed000.bezier_v2_integral, seed000.polynomial_v2_integral):
        assert typing.get_type_hints(f)["return"] is Fraction
    assert isinstance(seed000.bezier_v2_integral([0, 0, 1, 1]), Fraction)
    assert seed000.polynomial_v2_integral([0, 1]) == 1  # v = 1 on [0, 1]: int v^2 = 1


def test_unused_parameters_are_gone():
    import inspect

    from femcam.fe.gap import contact_geometry
    from femcam.fe.result import traction_fields

    assert list(inspect.signature(traction_fields).parameters) == ["trac", "q", "w", "x", "length"]
    assert list(inspect.signature(contact_geometry).parameters) == ["follower", "tip_radius"]


# --------------------------------------------------------------------------- issue 29 reproductions
# The tracebacks of the independent API campaign, each now one message in the house format
# (reference: the format of femcam._validate, "<name> = <value> <unit>: must be ...").
def _campaign_calls():
    from femcam.bodies import needle_approach
    from femcam.halfspace import circular_drop
    from femcam.hertz import effective_radius, half_width, peak_pressure

    return [
        # was "can't multiply sequence by non-int of type 'numpy.float64'"
        (lambda: half_width(1.5e5, "abc", 1.15e11), "R = 'abc' m: must be a number or an array of numbers"),
        # was "unsupported operand type(s) for *: 'float' and 'NoneType'"
        (lambda: needle_approach(150e3, None), "length = None m: must be a number"),
        # was "could not convert string to float: 'abc'"
        (lambda: effective_radius("abc", 0.01), "R1 = 'abc' m: must be a number or an array of numbers"),
        # was a NaN result
        (lambda: peak_pressure(math.nan, 1e-4), "w = nan N/m: must be finite"),
        # was a silently negative crown drop
        (lambda: circular_drop(0.001, -0.5), "Rc = -0.5 m: must be > 0"),
    ]


@pytest.mark.parametrize("case", range(5))
def test_campaign_tracebacks_are_one_message(case):
    call, msg = _campaign_calls()[case]
    with pytest.raises(InputError) as ei:
        call()
    assert msg in str(ei.value)
