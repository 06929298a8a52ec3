"""API fault injection, generated from the public API (issue 29).

Every callable in ``__all__`` of ``femcam`` and of its sub-packages (plus the public names of
the modules ``femcam.materials``, ``femcam.loads`` and ``femcam.io``, which have no
``__all__``) must have an entry in :data:`CASES` (a valid base call and the kind of each
numeric parameter) or in :data:`NOT_AN_INPUT` (why it takes no physical number). A new public
callable without an entry fails :func:`test_every_public_callable_has_an_entry`, so nothing is
silently skipped.

For each numeric parameter the test replaces its valid value by a string, None, a list of
strings, NaN and inf (and a negative value, zero or an out-of-range value where the parameter
forbids it) and expects a :class:`femcam.errors.FemcamError` whose message names the
parameter: never a numpy ``TypeError``/``ValueError``, an ``AttributeError``, a
``ZeroDivisionError`` or a NaN result. The reference is the rule itself (the house message
format of ``femcam._validate``: ``"<name> = <value> <unit>: must be ..."``), not femcam's output.

The valid base calls of FE/gmsh-heavy callables are marked slow; their argument checks run
before any mesh is built, so their faults are injected in the default suite (with a bare
stand-in model where a method of a built model is checked).
"""

from __future__ import annotations

import dataclasses
import functools
import importlib
import inspect
import math
import pkgutil
import tempfile
import warnings
from pathlib import Path

import numpy as np
import pytest

import femcam
from femcam.errors import FemcamError
from femcam.sweep import run_tasks as _sweep_run_tasks

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"

# ----------------------------------------------------------------------------- fault kinds
# REAL: any finite number; NONNEG: >= 0; POS: > 0; NONZERO: != 0 (a signed radius);
# INT: an integer (2.5 is a fault too). ``opt(...)`` drops the None fault for a parameter
# whose default is None. A float in a tuple is one more bad value (outside a stated range).
REAL = ("str", "none", "strlist", "nan", "inf")
NONNEG = REAL + ("neg",)
POS = NONNEG + ("zero",)
NONZERO = REAL + ("zero",)
RADIUS = ("str", "none", "strlist", "nan", "zero")  # signed radius of curvature: inf is flat
MISSING = ("str", "none", "strlist", "inf")  # data where NaN documents a missing value (failed solve)
INT = ("str", "none", "strlist", "nan", "inf", 2.5)
INT_POS = INT + ("neg", "zero")
INT_NONNEG = INT + ("neg",)
#: "numlist": a list of two valid numbers, given where the call's other arguments are arrays of
#: another length (or the parameter is a scalar): numpy would raise its own TypeError or broadcast
#: ValueError ("can't multiply sequence", "operands could not be broadcast") unless the function
#: converts and broadcasts its inputs itself (issue 29 review: the kinds above never held a list
#: of numbers, so half_width(1e5, [0.005, 0.01], ...) and flat_face_radius(..., Rb=[...]) slipped)
NUMLIST = ("numlist",)


def opt(kinds):
    """The same faults without None (None is a valid 'not given')."""
    return tuple(k for k in kinds if k != "none")


@dataclasses.dataclass(frozen=True)
class Case:
    """A valid call and the numeric parameters to corrupt.

    base : callable() -> (args, kwargs), the valid call (built fresh for every fault); None
        where the valid call needs a built FE model (its own test module solves one)
    numeric : {param: fault kinds}
    slow : the valid base call meshes or solves an FE model (marked slow)
    fault_base : callable() -> (args, kwargs) used instead of ``base`` for the faults (a
        cheap stand-in: the checks run before the stand-in is read)
    call : how to call (default: the public object itself)
    """

    base: object
    numeric: dict
    slow: bool = False
    fault_base: object = None
    call: object = None


def kw(**kwargs):
    """A base call with keyword arguments only."""
    return lambda: ((), dict(kwargs))


def lazy(fn):
    """A base call built by ``fn()`` (returns the kwargs dict) when the test runs."""
    return lambda: ((), fn())


# ----------------------------------------------------------------------------- shared inputs
@functools.cache
def scene(name="seed002_study_model"):
    from femcam.scene import load_scene

    return load_scene(EXAMPLES / f"{name}.toml")


TH = np.radians(np.arange(0.0, 360.0, 30.0))


@functools.cache
def state():
    return scene().analyse(TH)


def _contact_case():
    """The study model's contact over one revolution (5 deg apart)."""
    from femcam.scene import contact_case

    return contact_case(scene(), np.radians(np.arange(0.0, 360.0, 5.0)))


@functools.cache
def _cam_disk_case(name="seed002_study_model"):
    """The cam-on-shaft record of a scene (its outline analysed over one revolution)."""
    from femcam.scene import cam_disk_case

    return cam_disk_case(scene(name))


def _cam_disk_fields():
    """The fields of a valid CamDiskCase (the study model: a roller, no bore)."""
    c = _cam_disk_case()
    return {f.name: getattr(c, f.name) for f in dataclasses.fields(c)}


def _hs_rows():
    """A valid finite_length_rows call: the crowned example's strip (16 x 16 cells) at TH[:2]
    with the anchor start."""
    from femcam.halfspace import anchor_angles
    from femcam.scene import finite_case

    sc = scene("seed002_crowned")
    st, an = sc.analyse(TH[:2]), sc.analyse(anchor_angles(TH[:2]))
    return dict(strip=finite_case(sc).strip(nx=16, ny=16), theta=TH[:2], Fc=st.Fc, rho=st.rho,
                Rr=sc.follower.Rr, start="anchor", anchor_Fc=an.Fc, anchor_rho=an.rho)


def _case_fields():
    """The fields of a valid ContactCase (the study model's contact at TH)."""
    from femcam.scene import contact_case

    c = contact_case(scene(), TH)
    return {f.name: getattr(c, f.name) for f in dataclasses.fields(c)}


def _pair_fields():
    """The fields of a valid ContactPair (the study model's ``Scene.pair``)."""
    p = scene().pair
    return {f.name: getattr(p, f.name) for f in dataclasses.fields(p)}


def steel():
    from femcam.materials import STEEL

    return STEEL


def program():
    return scene().program


def follower():
    return scene().follower


def train():
    from femcam.dynamics import TrainModel

    return TrainModel(follower=scene().dynamics, k_t=2e5, zeta_t=0.05)


def srr_slip():
    from femcam.wear import roller_srr

    st = state()
    return roller_srr(TH, st.s, st.s1, st.s2, Rb=0.01, Rr=0.01, omega=scene().omega, srr=0.02)


def bare(cls, **fields):
    """An instance without ``__init__``: the argument checks run before it is read."""
    obj = object.__new__(cls)
    for k, v in fields.items():
        object.__setattr__(obj, k, v)
    return obj


def roller_profile():
    from femcam.halfspace import RollerProfile

    return RollerProfile(width=0.01, crown="circular", crown_radius=0.5)


def circle_outline(R=0.03, n=64):
    t = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    return np.array([R * np.cos(t), R * np.sin(t)])


def cp():
    from femcam.sweep.options import contact_params

    return contact_params(scene())


@functools.cache
def evolution_case():
    from femcam.scene import contact_case
    from femcam.wear import evolution_case as ec

    return ec(contact_case(scene(), np.radians(np.arange(0.0, 360.0, 5.0))))


def synthesis_result_stub():
    from femcam.synthesis import SynthesisResult

    return bare(SynthesisResult)


def study_var():
    from femcam.study import Variable

    return Variable(key="follower.base_radius_mm", values=(10.0, 12.0))


def study_options():
    from femcam.study import EvalOptions

    return EvalOptions(n_angles=72)


def StudySpec_(**kwargs):  # noqa: N802 - the class it builds
    from femcam.study import StudySpec

    return StudySpec(**kwargs)


ARR = np.array([1e-3, 2e-3, 3e-3])
A12 = np.full(12, 1e-4)
P12 = np.full(12, 1e9)
F12 = np.full(12, 1000.0)

# ----------------------------------------------------------------------------- the table
CASES: dict[str, Case] = {
    # femcam (root) and femcam.materials
    "femcam.Material": Case(kw(E=210e9, nu=0.3, hardness=6e9),
                            {"E": POS, "nu": REAL + (-1.0, 0.5, 0.7), "hardness": opt(POS)}),
    "femcam.materials.lame_parameters": Case(kw(E=210e9, nu=0.3),
                                             {"E": POS, "nu": REAL + (-1.0, 0.5, 0.7)}),
    # femcam.loads
    "femcam.loads.FollowerDynamics": Case(kw(m=0.2, k=800.0, Fpl=1500.0, zeta=0.06),
                                          {"m": POS, "k": NONNEG, "Fpl": NONNEG,
                                           "zeta": opt(NONNEG)}),
    "femcam.loads.contact_force": Case(
        lazy(lambda: dict(dyn=scene().dynamics, theta=TH, s=state().s, v=state().v,
                          a=state().a, phi=state().phi)),
        {"theta": REAL, "s": REAL, "v": REAL, "a": REAL, "phi": REAL + (2.0,)}),
    "femcam.loads.ArmDynamics": Case(kw(I=1e-5, k_t=20.0, M_pl=5.0, c_t=0.01),
                                     {"I": NONNEG, "k_t": NONNEG, "M_pl": NONNEG, "c_t": NONNEG}),
    "femcam.loads.arm_contact_force": Case(
        lazy(lambda: dict(dyn=_arm_dyn(), theta=TH, psi=0.1 + 0 * TH, psi_dot=0 * TH, psi_ddot=TH,
                          L=0.035, phi=0.1 + 0 * TH)),
        {"theta": REAL, "psi": REAL, "psi_dot": REAL, "psi_ddot": REAL, "L": POS, "phi": REAL + (2.0,),
         "mu": NONNEG, "friction_lever": REAL}),
    "femcam.loads.arm_lever": Case(
        lazy(lambda: dict(L=0.035, phi=0.1 + 0 * TH, mu=0.1, friction_lever=0.01 + 0 * TH, theta=TH)),
        {"L": POS, "phi": REAL, "mu": NONNEG, "friction_lever": REAL + (-1.0,), "theta": REAL}),
    # femcam.io
    "femcam.io.vtu_name": Case(kw(theta=0.5), {"theta": REAL}),
    "femcam.io.write_hertz_vtu": Case(
        lazy(lambda: dict(path=Path(tempfile.mkdtemp()) / "hertz.vtu", hc=_line_contact(), n=5)),
        {"n": INT_POS}, slow=True,
        fault_base=lazy(lambda: dict(path=Path("unused.vtu"), hc=None, n=5))),
    "femcam.io.write_global_cam_vtu": Case(
        None, {"F": POS, "theta": opt(REAL)}, slow=True,
        fault_base=lazy(lambda: dict(path=Path("unused.vtu"), model=bare(object), C=[0.0, 0.02],
                                     n=[0.0, 1.0], F=1000.0, theta=0.5))),
    # femcam.assess
    # femcam.bodies
    "femcam.bodies.CamDisk": Case(lazy(lambda: dict(outline=circle_outline(), Rb=0.01)),
                                  {"outline": REAL, "Rb": POS, "Rs": opt(POS),
                                   "cam_yield": opt(POS)}),
    "femcam.bodies.CamMeshOptions": Case(kw(), {"n_bore": INT_POS, "h_max_over_web": POS,
                                                "growth": POS, "arc_over_xf": POS}),
    "femcam.bodies.RingMeshOptions": Case(kw(), {"n_bore": INT_POS, "h_max_over_wall": POS,
                                                 "growth": POS}),
    "femcam.bodies.RollerBearing": Case(kw(Ro=0.01, Ri=0.006, support="pin", Rp=0.00598, c=2e-5),
                                        {"Ro": POS, "Ri": POS, "Rp": NONNEG, "c": NONNEG,
                                         "ring_yield": opt(POS)}),
    "femcam.bodies.bearing_problems": Case(kw(Ro=0.01, Ri=0.006, support="pin", Rp=0.00598,
                                              c=2e-5, Z=0, r_n=0.0),
                                           {"Ro": POS, "Ri": POS, "Rp": NONNEG, "c": NONNEG,
                                            "Z": INT_NONNEG, "r_n": NONNEG}),
    "femcam.bodies.build_for": Case(
        lazy(lambda: dict(support=scene("seed002_needle_roller").bodies.roller,
                          pair=scene("seed002_needle_roller").pair, Fc=1500.0, rho=0.02)),
        {"Fc": MISSING, "rho": RADIUS}, slow=True),
    "femcam.bodies.cam_disk_rows": Case(
        lazy(lambda: dict(case=_cam_disk_case("seed002_cam_on_shaft"),
                          state=scene("seed002_cam_on_shaft").analyse(TH[:1]), Fc=F12[:1])),
        {"Fc": MISSING}, slow=True),
    "femcam.bodies.needle_approach": Case(kw(Q=150e3, length=0.01), {"Q": REAL, "length": POS}),
    "femcam.bodies.ring_rows": Case(
        lazy(lambda: dict(support=scene("seed002_needle_roller").bodies.roller,
                          pair=scene("seed002_needle_roller").pair, theta=TH[:1], Fc=F12[:1],
                          rho=np.full(1, 0.02))),
        {"theta": REAL, "Fc": MISSING, "rho": RADIUS}, slow=True),
    "femcam.bodies.solve_cam_disk": Case(
        None, {"F": POS}, slow=True,
        fault_base=lazy(lambda: dict(model=bare(object), F=1000.0))),
    "femcam.bodies.solve_ring": Case(
        None,
        {"F": POS, "rho": RADIUS, "cage": REAL, "max_secant": INT_POS, "tol": NONNEG}, slow=True,
        fault_base=lazy(lambda: dict(model=bare(object), F=1000.0, rho=0.02))),
    # femcam.dynamics
    "femcam.dynamics.TrainModel": Case(lazy(lambda: dict(follower=scene().dynamics, k_t=2e5,
                                                         zeta_t=0.05, m2=0.1, k2=1e6, zeta2=0.05)),
                                       {"k_t": POS, "zeta_t": opt(NONNEG), "m2": opt(POS),
                                        "k2": opt(POS), "zeta2": opt(NONNEG)}),
    "femcam.dynamics.check_resolution": Case(lazy(lambda: dict(train=train(), omega=62.8, N=720)),
                                             {"omega": POS, "N": INT_POS}),
    "femcam.dynamics.periodic_response": Case(
        lazy(lambda: dict(train=train(), program=program(), omega=62.8, steps_per_rev=720)),
        {"omega": POS, "steps_per_rev": opt(INT_POS), "tol": POS, "max_cycles": INT_POS}),
    "femcam.dynamics.simulate": Case(
        lazy(lambda: dict(train=train(), program=program(), omega=62.8, steps_per_rev=360)),
        {"omega": POS, "steps_per_rev": opt(INT_POS), "cycles": INT_POS}),
    "femcam.dynamics.jump_speed": Case(
        lazy(lambda: dict(train=train(), program=program(), rpm_lo=500.0, rpm_hi=700.0,
                          n_scan=3, steps_per_rev=720)),
        {"rpm_lo": POS, "rpm_hi": POS, "n_scan": INT_POS, "xtol_rpm": POS}, slow=True),
    "femcam.dynamics.rpm_sweep": Case(
        lazy(lambda: dict(train=train(), program=program(), rpm=np.array([600.0]),
                          steps_per_rev=360)),
        {"rpm": POS, "steps_per_rev": opt(INT_POS), "max_cycles": INT_POS}),
    "femcam.dynamics.arm_follower": Case(lazy(lambda: dict(arm=_arm_dyn(), L=0.035)), {"L": POS}),
    "femcam.dynamics.arm_train": Case(
        lazy(lambda: dict(arm=_arm_dyn(), L=0.035, K_t=2e4, zeta_t=0.05, I2=1e-4, K2=3e4, C2=0.1)),
        {"L": POS, "K_t": POS, "zeta_t": opt(NONNEG), "I2": opt(POS), "C2": opt(NONNEG)}),
    "femcam.dynamics.lever_spring": Case(kw(k=40e3, lever=0.05, Fpl=250.0),
                                         {"k": NONNEG, "lever": POS, "Fpl": NONNEG}),
    "femcam.dynamics.rigid_jump_speed": Case(
        lazy(lambda: dict(follower=scene().dynamics, program=program(), rpm_lo=500.0, rpm_hi=700.0,
                          n=360, n_scan=3)),
        {"rpm_lo": POS, "rpm_hi": POS, "n": INT_POS, "n_scan": INT_POS, "xtol_rpm": POS}),
    # femcam.fe
    "femcam.fe.MeshOptions": Case(kw(), {"a_over_h": POS, "fine_half_width": POS,
                                         "fine_depth": NONNEG + (25.0,), "growth": POS,
                                         "domain_over_a": opt(POS), "max_size_fraction": POS,
                                         "coat_thickness": NONNEG, "coat_layers": INT_POS}),
    "femcam.fe.SolverOptions": Case(kw(), {"max_iter": INT_POS, "tol": POS, "kappa_tol": POS,
                                           "eval_depth": NONNEG + (25.0,),
                                           "fit_threshold": NONNEG + (0.95,)}),
    "femcam.fe.solve_contact": Case(
        lazy(lambda: dict(F=1500.0, rho=0.02, Rr=0.01, cam=steel(), roller=steel(),
                          length=0.01, mu=0.1)),
        {"F": NONNEG, "rho": RADIUS, "Rr": POS, "length": POS, "mu": NONNEG,
         "a_ref": opt(POS)}, slow=True),
    # femcam.halfspace
    "femcam.halfspace.FiniteLengthContact": Case(
        lazy(lambda: dict(profile=roller_profile(), cam_width=0.01, E_star=1.15e11, nx=16,
                          ny=16)),
        {"cam_width": POS, "E_star": POS, "design_load": opt(POS), "design_radius": opt(POS),
         "nx": INT_POS, "ny": INT_POS, "tol": POS, "max_iter": INT_POS}),
    "femcam.halfspace.HalfSpace": Case(kw(nx=8, ny=8, dx=1e-5, dy=1e-4, E_star=1.15e11),
                                       {"nx": INT_POS, "ny": INT_POS, "dx": POS, "dy": POS,
                                        "E_star": POS}),
    "femcam.halfspace.RollerProfile": Case(kw(width=0.01, crown="circular", crown_radius=0.5),
                                           {"width": POS, "crown_radius": opt(POS),
                                            "edge_radius": NONNEG, "misalignment": REAL}),
    "femcam.halfspace.cell_influence": Case(kw(x=ARR, y=ARR, dx=1e-5, dy=1e-4, E_star=1.15e11),
                                            {"x": REAL, "y": REAL, "dx": POS, "dy": POS,
                                             "E_star": POS}),
    "femcam.halfspace.circular_drop": Case(kw(y=ARR, Rc=0.5), {"y": REAL, "Rc": POS}),
    "femcam.halfspace.dcfft_kernel": Case(kw(nx=8, ny=8, dx=1e-5, dy=1e-4, E_star=1.15e11),
                                          {"nx": INT_POS, "ny": INT_POS, "dx": POS, "dy": POS,
                                           "E_star": POS}),
    "femcam.halfspace.edge_drop": Case(kw(y=ARR, l=0.01, re=0.001),
                                       {"y": REAL, "l": POS, "re": NONNEG}),
    "femcam.halfspace.log_drop": Case(kw(y=ARR, l=0.01, Q=1000.0, b=5e-5, E_star=1.15e11),
                                      {"y": REAL, "l": POS, "Q": POS, "b": POS, "E_star": POS}),
    "femcam.halfspace.anchor_angles": Case(kw(theta=TH), {"theta": REAL}),
    "femcam.halfspace.finite_length_rows": Case(lazy(_hs_rows), {
        "theta": REAL, "Fc": REAL, "rho": RADIUS, "Rr": POS, "anchor_Fc": opt(REAL),
        "anchor_rho": opt(RADIUS)}),
    # finite None: a straight roller as wide as the cam (None is valid, so not a record fault)
    "femcam.halfspace.strip_for": Case(
        lazy(lambda: dict(finite=None, pair=scene("seed002_crowned").pair, Rr=0.01,
                          Fc=state().Fc, rho=state().rho, nx=16, ny=16)),
        {"Rr": POS, "Fc": opt(REAL), "rho": opt(RADIUS), "nx": INT_POS, "ny": INT_POS, "tol": POS}),
    # femcam.hertz
    "femcam.hertz.LineContact": Case(
        lazy(lambda: dict(F=1500.0, length=0.01, R1=0.02, R2=0.01, cam=steel(),
                          roller=steel(), mu=0.1)),
        {"F": NONNEG, "length": POS, "R1": RADIUS, "R2": RADIUS, "mu": NONNEG}),
    # R2 = -R1: equal and opposite radii, a conformal contact with no Hertz answer
    "femcam.hertz.effective_radius": Case(kw(R1=0.02, R2=0.01), {"R1": RADIUS, "R2": RADIUS + (-0.02,)}),
    "femcam.hertz.half_width": Case(kw(w=ARR * 1.5e8, R=0.0067, E_star=1.15e11),
                                    {"w": NONNEG, "R": POS + NUMLIST, "E_star": POS + NUMLIST}),
    "femcam.hertz.hertz_pressure": Case(kw(x=ARR, a=1e-4, p0=1e9),
                                        {"x": REAL, "a": NONNEG, "p0": NONNEG}),
    "femcam.hertz.max_orthogonal_shear": Case(kw(mu=0.1), {"mu": NONNEG}),
    "femcam.hertz.max_shear": Case(kw(mu=0.1), {"mu": NONNEG}),
    "femcam.hertz.max_shear_range": Case(kw(mu=0.1), {"mu": NONNEG}),
    "femcam.hertz.max_von_mises": Case(kw(mu=0.1, nu=0.3), {"mu": NONNEG,
                                                            "nu": REAL + (-1.0, 0.5)}),
    "femcam.hertz.peak_pressure": Case(kw(w=1.5e5, a=1e-4), {"w": NONNEG, "a": NONNEG}),
    "femcam.hertz.stress_field": Case(kw(x=ARR, z=ARR, a=1e-4, p0=1e9, mu=0.1),
                                      {"x": REAL, "z": NONNEG, "a": NONNEG, "p0": NONNEG,
                                       "mu": REAL, "nu": REAL + (-1.0, 0.5)}),
    "femcam.hertz.surface_stress": Case(kw(x=ARR, a=1e-4, p0=1e9, mu=0.1),
                                        {"x": REAL, "a": NONNEG, "p0": NONNEG, "mu": REAL}),
    "femcam.hertz.unit_stresses": Case(kw(X=ARR, Z=ARR, mu=0.1),
                                       {"X": REAL, "Z": NONNEG, "mu": REAL}),
    # femcam.kinematics
    "femcam.kinematics.bernstein": Case(kw(n=5, i=2, u=np.array([0.0, 0.5, 1.0])),
                                        {"n": INT_NONNEG, "i": INT_NONNEG, "u": REAL}),
    "femcam.kinematics.law": Case(kw(name="bezier", control_points=[0, 0, 0, 1, 1, 1]),
                                  {"control_points": REAL}),
    "femcam.kinematics.Segment": Case(kw(kind="dwell", beta=1.0), {"beta": POS, "h": NONNEG}),
    "femcam.kinematics.dwell": Case(kw(beta=1.0), {"beta": POS}),
    "femcam.kinematics.fall": Case(kw(beta=1.0, h=0.01), {"beta": POS, "h": POS}),
    "femcam.kinematics.rise": Case(kw(beta=1.0, h=0.01), {"beta": POS, "h": POS}),
    # femcam.layers
    "femcam.layers.Case": Case(kw(depth=1e-3, surface_yield=1.5e9, core_yield=0.8e9),
                               {"depth": POS, "surface_yield": POS, "core_yield": POS}),
    "femcam.layers.CoatedMaterial": Case(kw(E=210e9, nu=0.3),
                                         {"E": POS, "nu": REAL + (-1.0, 0.5),
                                          "hardness": opt(POS)}),
    "femcam.layers.Coating": Case(lazy(lambda: dict(thickness=2e-6, material=steel(),
                                                    interface_shear_strength=5e8)),
                                  {"thickness": POS, "interface_shear_strength": opt(POS),
                                   "hardness": opt(POS)}),
    "femcam.layers.build_coated_model": Case(
        lazy(lambda: dict(Rr=0.01, rho_ref=0.02, cam=steel(), roller=steel(), length=0.01,
                          a_ref=1e-4, coating=_coating())),
        {"Rr": POS, "rho_ref": RADIUS, "length": POS, "a_ref": POS}, slow=True),
    "femcam.layers.case_margin": Case(
        lazy(lambda: dict(case=_case(), z=np.array([1e-4, 5e-4]), tau=np.array([3e8, 2e8]))),
        {"z": NONNEG, "tau": REAL}),
    "femcam.layers.layer_rows": Case(
        None,
        {"F": NONNEG, "rho": RADIUS, "mu": NONNEG}, slow=True,
        fault_base=lazy(lambda: dict(model=bare(object), F=1500.0, rho=0.02, mu=0.1))),
    "femcam.layers.scene_layer_rows": Case(
        lazy(lambda: dict(layers=scene("seed002_coated").layers, pair=scene("seed002_coated").pair,
                          follower=scene("seed002_coated").follower, theta=TH[:1], Fc=F12[:1],
                          rho=np.full(1, 0.02))),
        {"theta": REAL, "Fc": MISSING, "rho": RADIUS, "a_over_h": POS}, slow=True),
    "femcam.layers.shear_strength_from_hardness": Case(kw(H=6e9), {"H": POS}),
    # femcam.mesh
    "femcam.mesh.body_layout": Case(
        lazy(lambda: dict(name="cam", R=0.02, L=0.01, a_ref=1e-4, opts=_mesh_options())),
        {"R": RADIUS, "L": POS, "a_ref": POS}),
    "femcam.mesh.build_contact_mesh": Case(kw(Rr=0.01, rho=0.02, a_ref=1e-4),
                                           {"Rr": POS, "rho": RADIUS, "a_ref": POS}, slow=True),
    "femcam.mesh.ccw": Case(kw(pts=np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]),
                               tri=np.array([[0, 2, 1]])), {"pts": REAL}),
    "femcam.mesh.surface_height": Case(kw(x=ARR, R=0.02), {"x": REAL, "R": RADIUS}),
    # femcam.profile
    "femcam.profile.FlatFacedFollower": Case(kw(Rb=0.02, e=0.0), {"Rb": POS, "e": REAL}),
    "femcam.profile.KnifeEdgeFollower": Case(kw(Rb=0.02, e=0.0), {"Rb": POS, "e": REAL}),
    "femcam.profile.RollerFollower": Case(kw(Rb=0.01, Rr=0.01, e=0.0),
                                          {"Rb": POS, "Rr": POS, "e": REAL}),
    "femcam.profile.OscillatingRollerFollower": Case(
        kw(Rb=0.02, Rr=0.008, a=0.05, L=0.035, sigma=1),
        {"Rb": POS, "Rr": POS, "a": POS, "L": POS, "sigma": ("str", "none", "nan", 2.5)}),
    "femcam.profile.OscillatingPadFollower": Case(
        kw(Rb=0.02, Rr=0.012, a=0.05, L=0.035, sigma=1),
        {"Rb": POS, "Rr": POS, "a": POS, "L": POS, "sigma": ("str", "none", "nan", 2.5)}),
    "femcam.profile.arm_geometry": Case(lazy(lambda: dict(f=_osc(), psi=0.1 + 0 * TH, psi1=0 * TH,
                                                          psi2=0 * TH)),
                                        {"psi": REAL, "psi1": REAL, "psi2": REAL}),
    "femcam.profile.oscillating_profile": Case(
        lazy(lambda: dict(f=_osc(), theta=TH, psi=0.1 + 0 * TH, psi1=0 * TH, psi2=0 * TH)),
        {"theta": REAL, "psi": REAL, "psi1": REAL, "psi2": REAL}),
    "femcam.profile.min_base_radius_oscillating": Case(
        lazy(lambda: dict(program=_osc_program(), Rr=0.008, a=0.05, L=0.035, n_theta=360)),
        {"Rr": POS, "a": POS, "L": POS, "phi_max": POS + (1.6,), "n_theta": INT_POS}),
    "femcam.profile.bool_intervals": Case(kw(theta=TH, mask=TH > 1.0), {"theta": REAL}),
    "femcam.profile.cam_profile": Case(
        lazy(lambda: dict(f=follower(), theta=TH, s=state().s, s1=state().s1, s2=state().s2)),
        {"theta": REAL, "s": REAL, "s1": REAL, "s2": REAL}),
    "femcam.profile.flat_face_radius": Case(
        lazy(lambda: dict(s=state().s, s2=state().s2, Rb=0.02)),
        {"s": REAL, "s2": REAL, "Rb": POS + NUMLIST}),
    "femcam.profile.make_follower": Case(kw(kind="roller", Rb=0.01, Rr=0.01),
                                         {"Rb": POS, "Rr": POS, "e": REAL}),
    "femcam.optimise.optimise": Case(
        lazy(lambda: dict(scene_or_path=scene(), objective="size", variables={"base_radius": (0.005, 0.02)},
                          constraints={"phi_max": 0.5}, verify_fe=False)),
        {"starts": INT_POS, "n_motion": INT_POS, "maxiter": INT_POS}),
    "femcam.optimise.Variable": Case(lazy(lambda: dict(name="base_radius", lower=0.005, upper=0.02)),
                                     {"lower": REAL, "upper": REAL, "start": opt(REAL)}),
    "femcam.optimise.BezierRise": Case(lazy(lambda: dict(degree=9, zero_derivatives=2)),
                                       {"degree": INT_POS, "zero_derivatives": INT_POS}),
    "femcam.optimise.compare_laws": Case(lazy(lambda: dict(scene=scene(), laws=("bezier5",))), {}),
    # femcam.study
    "femcam.study.Constraints": Case(kw(phi_limit=0.5, rho_limit=0.0, sf_limit=1.0, lambda_limit=1.0,
                                        p0_limit=1.5e9, jump_factor=1.0),
                                     {"phi_limit": POS + (2.0,), "rho_limit": NONNEG, "sf_limit": POS,
                                      "lambda_limit": opt(POS), "p0_limit": opt(POS), "jump_factor": POS}),
    "femcam.study.EvalOptions": Case(kw(n_angles=72, jump_factor_hi=2.0),
                                     {"n_angles": INT_POS + (35.0, 1e9), "jump_factor_hi": POS + (1.0,)}),
    "femcam.study.FEOptions": Case(kw(top=1, offsets=(0.0, 0.01), a_over_h=10.0, tolerance=2e-3),
                                   {"top": INT_NONNEG, "offsets": REAL, "a_over_h": POS, "tolerance": POS}),
    "femcam.study.Variable": Case(kw(key="follower.base_radius_mm", lo=10.0, hi=12.0),
                                  {"lo": REAL, "hi": REAL}),
    "femcam.study.StudySpec": Case(lazy(lambda: dict(vary=(study_var(),), lhs=4, seed=0)),
                                   {"lhs": opt(INT_POS) + (2e6,), "seed": INT_NONNEG}),
    "femcam.study.parse_vary": Case(kw(text="follower.base_radius_mm=10:12:1"), {}),
    "femcam.study.evaluate": Case(lazy(lambda: dict(scene=scene(), options=study_options())), {}),
    "femcam.study.pareto_mask": Case(kw(f1=[3.0, 2.0, 1.0], f2=[1.0, 2.0, 3.0], candidates=[True] * 3),
                                     {"f1": ("str", "none", "strlist"), "f2": ("str", "none", "strlist")}),
    "femcam.study.run_study": Case(
        lazy(lambda: dict(scene=str(EXAMPLES / "seed002_study_model.toml"),
                          spec=StudySpec_(vary=(study_var(),)))),
        {"workers": INT_POS, "batch_size": opt(INT_POS)}),
    "femcam.profile.min_base_radius": Case(
        lazy(lambda: dict(kind="roller", program=program(), Rr=0.01, n_theta=360)),
        {"phi_max": POS + (1.6,), "Rr": NONNEG, "e": REAL, "rho_min": NONNEG,
         "n_theta": INT_POS}),
    "femcam.profile.pitch_curvature": Case(
        lazy(lambda: dict(s=state().s, s1=state().s1, s2=state().s2, Rp=0.02)),
        {"s": REAL, "s1": REAL, "s2": REAL, "Rp": POS, "e": REAL}),
    "femcam.profile.pressure_angle": Case(
        lazy(lambda: dict(s=state().s, s1=state().s1, Rp=0.02)),
        {"s": REAL, "s1": REAL, "Rp": POS, "e": REAL}),
    # femcam.sweep
    "femcam.sweep.ModelCache": Case(kw(max_models=4), {"max_models": INT_POS}),
    "femcam.sweep.Progress": Case(kw(total=10, enabled=False), {"total": INT_NONNEG,
                                                               "delay_s": NONNEG}),
    "femcam.scene.cam_disk_case": Case(lazy(lambda: dict(scene=scene("seed002_cam_on_shaft"))),
                                       {"n_outline": INT_POS}),
    "femcam.scene.CamDiskCase": Case(lazy(_cam_disk_fields), {"cam_yield": opt(POS)}),
    "femcam.scene.StudySettings": Case(kw(), {"a_over_h": opt(POS), "tolerance": opt(POS),
                                              "rtol": opt(POS), "chunk_size": opt(INT_POS),
                                              "vtk_every": opt(INT_NONNEG)}),
    "femcam.SweepOptions": Case(lazy(lambda: dict(angles=TH[:2])),
                                {"a_over_h": opt(POS), "tolerance": opt(POS), "rtol": opt(POS),
                                 "chunk_size": opt(INT_POS), "vtk_every": opt(INT_NONNEG),
                                 "angles": opt(REAL)}),
    "femcam.RunOptions": Case(kw(workers=2), {"workers": opt(INT_POS), "chunk_delay_s": NONNEG}),
    "femcam.sweep.auto_workers": Case(kw(n_tasks=4, n_solves=100, t_solve=0.01, n_families=2,
                                         t_build=1.0, cpus=2),
                                      {"n_tasks": INT_NONNEG, "n_solves": INT_NONNEG,
                                       "t_solve": NONNEG, "n_families": INT_NONNEG,
                                       "t_build": NONNEG, "t_other": NONNEG,
                                       "cpus": opt(INT_POS)}),
    "femcam.sweep.plan_families": Case(
        lazy(lambda: dict(F=state().Fc, rho=state().rho, cp=cp(), tolerance=2e-3,
                          contact=np.ones(12, bool))),
        {"F": NONNEG, "rho": RADIUS, "tolerance": POS}),
    "femcam.sweep.run_tasks": Case(kw(fn=abs, tasks=[-1, 2], workers=1), {"workers": opt(INT_POS)},
                                   call=lambda *a, **k: list(_sweep_run_tasks(*a, **k))),
    # the numbers are the two option records' (above); the records themselves:
    # tests/test_sweep_api_cli.py::test_old_keywords_are_gone_and_options_are_typed
    "femcam.sweep": Case(lazy(lambda: dict(scene=scene(), options=_sweep_user_options())), {},
                         slow=True),
    "femcam.sweep.verify_families": Case(
        lazy(lambda: dict(F=state().Fc, rho=state().rho, theta=TH, cp=cp(),
                          options=_sweep_options(), contact=np.ones(12, bool))),
        {"F": NONNEG, "rho": RADIUS, "theta": REAL, "n_checks": INT_POS}, slow=True),
    # femcam.synthesis
    "femcam.synthesis.SynthesisOptions": Case(kw(), {"n_elements": INT_POS, "k": POS, "mu": POS,
                                                     "quad_points": INT_POS, "rtol": POS,
                                                     "xtol": NONNEG, "max_iter": INT_POS,
                                                     "k_factor": POS, "k_start": POS,
                                                     "phi_limit": POS + (1.6,)}),
    "femcam.synthesis.pressure_angle_exact": Case(
        lazy(lambda: dict(Rb=0.02, s=state().s, s1=state().s1)),
        {"Rb": POS, "s": REAL, "s1": REAL}),
    "femcam.synthesis.synthesize_knife_edge": Case(
        lazy(lambda: dict(program=_seed003(), Rb=0.03, options=_synth_options())),
        {"Rb": POS, "samples_per_element": INT_POS}, slow=True),
    "femcam.synthesis.seed003_program": Case(kw(h=0.003), {"h": POS}),
    "femcam.synthesis.compare_direct": Case(
        None, {"n_dense": INT_POS}, slow=True,
        fault_base=lazy(lambda: dict(result=synthesis_result_stub(), program=_seed003()))),
    "femcam.synthesis.direct_profile": Case(lazy(lambda: dict(program=_seed003(), Rb=0.03,
                                                              theta=TH)),
                                            {"Rb": POS, "theta": REAL}),
    "femcam.synthesis.study_k": Case(
        lazy(lambda: dict(program=_seed003(), Rb=0.03, ks=[1e6], options=_synth_options())),
        {"Rb": POS, "ks": POS, "mu": POS}, slow=True),
    "femcam.synthesis.study_k_over_mu": Case(
        lazy(lambda: dict(program=_seed003(), Rb=0.03, ratios=[1e6], options=_synth_options())),
        {"Rb": POS, "ratios": POS, "k": POS}, slow=True),
    # femcam.tribology
    "femcam.tribology.Lubricant": Case(kw(alpha=2e-8, rho=870.0, nu40=100.0, nu100=11.0),
                                       {"alpha": POS, "rho": POS, "nu40": opt(POS),
                                        "nu100": opt(POS)}),
    "femcam.tribology.composite_roughness": Case(kw(Rq1=2e-7, Rq2=3e-7),
                                                 {"Rq1": NONNEG, "Rq2": NONNEG}),
    "femcam.tribology.dimensionless_groups": Case(
        kw(U=1.0, w=1.5e5, R=0.0067, E_star=1.15e11, eta0=0.05, alpha=2e-8),
        {"U": REAL, "w": NONNEG, "R": POS, "E_star": POS, "eta0": POS, "alpha": POS}),
    "femcam.tribology.effusivity": Case(kw(K=46.0, rho=7850.0, c=460.0),
                                        {"K": POS, "rho": POS, "c": POS}),
    "femcam.tribology.film_thickness": Case(
        kw(U=1.0, w=1.5e5, R=0.0067, E_star=1.15e11, eta0=0.05, alpha=2e-8, sigma=3e-7),
        {"U": REAL, "w": NONNEG, "R": ("str", "none", "strlist", "nan", "neg", "zero"),
         "E_star": POS, "eta0": POS, "alpha": POS, "sigma": opt(POS)}),
    "femcam.tribology.first_yield_limit": Case(kw(mu=0.1), {"mu": NONNEG}),
    "femcam.tribology.flash_temperature": Case(
        kw(mu=0.1, w=1.5e5, a=1e-4, u1=1.0, u2=0.9, beta1=1.2e4, beta2=1.2e4),
        {"mu": NONNEG, "w": NONNEG, "a": NONNEG, "u1": REAL, "u2": REAL, "beta1": POS,
         "beta2": POS, "C": POS}),
    "femcam.tribology.greenwood_tripp": Case(kw(n=2.5, lam=1.0), {"lam": NONNEG, "n": NONNEG}),
    "femcam.tribology.lubrication_regime": Case(kw(lam=ARR * 1e3), {"lam": NONNEG}),
    "femcam.tribology.orthogonal_shear_range": Case(kw(mu=0.1), {"mu": NONNEG}),
    "femcam.tribology.peclet": Case(kw(u=1.0, a=1e-4, kappa=1.2e-5),
                                    {"u": REAL, "a": NONNEG, "kappa": POS}),
    "femcam.tribology.scuffing_safety": Case(kw(T_scuff=300.0, T_bulk=80.0, dT_flash=50.0),
                                             {"T_scuff": REAL + ("neg",), "T_bulk": REAL,
                                              "dT_flash": NONNEG}),
    "femcam.tribology.shakedown_limit": Case(kw(mu=0.1), {"mu": NONNEG}),
    "femcam.tribology.sn_cycles": Case(kw(p0=1.5e9, strength=1.5e9),
                                       {"p0": NONNEG, "strength": POS, "N_ref": POS, "m": POS}),
    "femcam.tribology.wear_coefficient": Case(kw(k0=1e-15, lam=ARR * 1e3),
                                              {"k0": NONNEG, "lam": NONNEG}),   # a film ratio >= 0
    # femcam.scene: the typed records of a scene (None: not given)
    "femcam.scene.WearSettings": Case(kw(), {"K": opt(NONNEG), "k": opt(NONNEG), "srr": REAL + (2.5, -2.0),
                                             "J": opt(POS), "T_drag": NONNEG, "cycles": opt(NONNEG)}),
    "femcam.scene.Tribology": Case(kw(), {"oil_temperature_C": opt(REAL)}),
    "femcam.scene.contact_case": Case(
        lazy(lambda: dict(scene=scene("seed003_knife_edge"), theta=TH, tip_radius=5e-4)),
        {"theta": opt(REAL), "tip_radius": opt(POS)}),
    "femcam.scene.ContactCase": Case(lazy(_case_fields), {"tip_radius": opt(POS)}),
    "femcam.scene.ContactPair": Case(lazy(_pair_fields), {"length": POS, "mu": NONNEG}),
    "femcam.scene.finite_case": Case(lazy(lambda: dict(scene=scene("seed002_crowned"))), {}),
    # finite and design None: a straight roller as wide as the cam, no logarithmic crown
    "femcam.scene.FiniteCase": Case(lazy(lambda: dict(finite=None, pair=scene().pair, Rr=0.01, design=None)),
                                    {"Rr": POS}),
    "femcam.scene.LubricantData": Case(kw(), {
        "viscosity_Pa_s": opt(POS), "temperature_C": opt(REAL),
        "viscosity_temperature_coefficient_per_K": opt(NONNEG), "kinematic_viscosity_40C": opt(POS),
        "kinematic_viscosity_100C": opt(POS), "pressure_viscosity": opt(POS), "alpha_per_Pa": opt(POS),
        "density_kg_per_m3": opt(POS)}),
    "femcam.scene.SurfaceRoughness": Case(kw(), {k: opt(NONNEG) for k in ("cam_Ra", "roller_Ra", "cam_Rq",
                                                                           "roller_Rq")}),
    "femcam.scene.MaterialData": Case(kw(), {
        "yield_strength": opt(POS), "thermal_conductivity_W_per_m_K": opt(POS), "density_kg_per_m3": opt(POS),
        "specific_heat_J_per_kg_K": opt(POS), "contact_fatigue_strength": opt(POS),
        "contact_fatigue_cycles": opt(POS), "contact_fatigue_exponent": opt(POS),
        "shear_fatigue_limit": opt(POS), "scuffing_temperature_C": opt(REAL)}),
    # femcam.wear
    "femcam.wear.wear_coefficient_info": Case(lazy(lambda: dict(wear=scene().wear, hardness=2e9)),
                                              {"hardness": opt(POS)}),
    "femcam.wear.archard_volume": Case(kw(k=1e-15, L=500.0, S=1.0),
                                       {"k": NONNEG, "L": NONNEG, "S": NONNEG}),
    "femcam.wear.dimensional_coefficient": Case(kw(K=1e-8, H=2e9), {"K": NONNEG, "H": POS}),
    "femcam.wear.dimensionless_coefficient": Case(kw(k=1e-15, H=2e9), {"k": NONNEG, "H": POS}),
    "femcam.wear.convergence_table": Case(
        lazy(lambda: dict(case=evolution_case(), cycles=1e5, max_blocks=2)),
        {"cycles": POS, "max_blocks": INT_POS, "n_grid": opt(INT_POS)}, slow=True),
    "femcam.wear.evolution_case": Case(
        lazy(lambda: dict(contact=_contact_case())), {"k": opt(NONNEG)}),
    "femcam.wear.evolve": Case(
        lazy(lambda: dict(case=evolution_case(), cycles=1e5, block=1e5, n_grid=2000)),
        {"cycles": NONNEG, "block": POS, "n_grid": opt(INT_POS)}, slow=True),
    "femcam.wear.worn_curvature": Case(kw(kappa=ARR, dkappa_ds=ARR, h=ARR, h1=ARR, h2=ARR),
                                       {"kappa": REAL, "dkappa_ds": REAL, "h": REAL,
                                        "h1": REAL, "h2": REAL}),
    "femcam.wear.depth_per_pass": Case(kw(k=1e-15, w=1.5e5, v_slip=0.1, V_transport=1.0),
                                       {"k": NONNEG, "w": MISSING, "v_slip": REAL,
                                        "V_transport": REAL}),
    "femcam.wear.drift_sum": Case(kw(h=ARR, period=4.0, drift=1.0, cycles=4),
                                  {"h": REAL, "period": POS, "drift": REAL, "cycles": NONNEG}),
    "femcam.wear.surface_depth": Case(
        kw(x=np.linspace(-1e-3, 1e-3, 5), xi=np.array([0.0, 1e-4]), a=np.array([1e-4]),
           p0=np.array([1e9]), v_slip=np.array([0.1]), dt=np.array([1e-3]), k=1e-15),
        {"x": REAL, "xi": REAL, "a": MISSING, "p0": MISSING, "v_slip": MISSING, "dt": MISSING,
         "k": NONNEG, "period": opt(POS), "chunk": INT_POS}),
    "femcam.wear.wear_depth_per_angle": Case(
        lazy(lambda: dict(theta=TH, a=A12, p0=P12, Fc=F12, slip=srr_slip(), k=1e-15)),
        {"theta": REAL, "a": MISSING, "p0": MISSING, "Fc": MISSING, "k": NONNEG}),
    "femcam.wear.wear_map": Case(
        lazy(lambda: dict(source=dict(theta=TH, a_hertz=A12, p0_hertz=P12, Fc=F12),
                          slip=srr_slip(), k=1e-15, length=0.01, n_grid=2000)),
        {"k": NONNEG, "length": POS, "cycles": NONNEG, "n_grid": opt(INT_POS),
         "k_factor": opt(NONNEG)}),
    "femcam.wear.Seed000Inputs": Case(kw(), {"K": NONNEG, "L": NONNEG, "H": POS, "h": POS,
                                             "beta": POS, "omega": POS}),
    "femcam.wear.rms_velocity": Case(kw(law="cycloidal", h=0.01, beta=np.pi, omega=1.0),
                                     {"h": POS, "beta": POS, "omega": POS}),
    "femcam.wear.flat_faced": Case(
        lazy(lambda: dict(theta=TH, s=state().s, s1=state().s1, s2=state().s2, Rb=0.02,
                          omega=62.8)),
        {"theta": REAL, "s": REAL, "s1": REAL, "s2": REAL, "Rb": POS, "omega": POS}),
    "femcam.wear.follower_slip": Case(
        lazy(lambda: dict(follower=follower(), theta=TH, s=state().s, s1=state().s1,
                          s2=state().s2, omega=62.8)),
        {"theta": REAL, "s": REAL, "s1": REAL, "s2": REAL, "omega": POS, "srr": REAL + (2.0,),
         "mu": NONNEG}),
    "femcam.wear.knife_edge": Case(
        lazy(lambda: dict(theta=TH, s=state().s, s1=state().s1, Rb=0.02, omega=62.8)),
        {"theta": REAL, "s": REAL, "s1": REAL, "Rb": POS, "omega": POS, "e": REAL}),
    "femcam.wear.radiused_tip": Case(
        lazy(lambda: dict(theta=TH, s=state().s, s1=state().s1, s2=state().s2, Rb=0.02,
                          r_tip=0.005, omega=62.8)),
        {"theta": REAL, "s": REAL, "s1": REAL, "s2": REAL, "Rb": POS, "r_tip": POS,
         "omega": POS, "e": REAL}),
    "femcam.wear.roller_inertia": Case(
        lazy(lambda: dict(theta=TH, s=state().s, s1=state().s1, s2=state().s2, Fc=state().Fc,
                          Rb=0.01, Rr=0.01, omega=62.8, mu=0.1, J=1e-6)),
        {"theta": REAL, "s": REAL, "s1": REAL, "s2": REAL, "Fc": REAL, "Rb": POS, "Rr": POS,
         "omega": POS, "mu": NONNEG, "J": POS, "T_drag": NONNEG, "e": REAL,
         "max_revolutions": INT_POS, "tol": POS}),
    "femcam.wear.roller_srr": Case(
        lazy(lambda: dict(theta=TH, s=state().s, s1=state().s1, s2=state().s2, Rb=0.01,
                          Rr=0.01, omega=62.8, srr=0.02)),
        {"theta": REAL, "s": REAL, "s1": REAL, "s2": REAL, "Rb": POS, "Rr": POS,
         "omega": POS, "srr": REAL + (2.0, -2.0), "e": REAL}),
}


def _line_contact():
    from femcam.hertz import LineContact

    return LineContact(F=1500.0, length=0.01, R1=0.02, R2=0.01, cam=steel(), roller=steel())


def _coating():
    from femcam.layers import Coating

    return Coating(thickness=2e-6, material=steel())


def _case():
    from femcam.layers import Case as LayerCase

    return LayerCase(depth=1e-3, surface_yield=1.5e9, core_yield=0.8e9)


def _mesh_options():
    from femcam.mesh import MeshOptions

    return MeshOptions()


def _sweep_options():
    from femcam.sweep.options import ResolvedOptions

    return ResolvedOptions()


def _sweep_user_options():
    return femcam.SweepOptions(angles=TH[:2], method="hertz")


def _seed003():
    from femcam.synthesis import seed003_program

    return seed003_program()


def _synth_options():
    from femcam.synthesis import SynthesisOptions

    return SynthesisOptions(n_elements=36)


def _osc():
    from femcam.profile import OscillatingRollerFollower

    return OscillatingRollerFollower(Rb=0.02, Rr=0.008, a=0.05, L=0.035)


def _osc_program():
    from femcam.kinematics import CamProgram, dwell, fall, rise

    return CamProgram([rise(1.6, 0.2), dwell(0.8), fall(1.6, 0.2), dwell(2 * math.pi - 4.0)])


def _arm_dyn():
    from femcam.loads import ArmDynamics

    return ArmDynamics(I=1e-5, k_t=20.0, M_pl=5.0)


# Public callables that take no physical number of their own, with the reason. Records a
# function returns (results, built models, mesh records) are made by femcam, not by a user.
RESULT = "a result or built-model record femcam returns (its inputs are checked where it is made)"
RECORDS = "takes records only (Scene, Material, results, rows), checked where they are made"
NOT_AN_INPUT: dict[str, str] = {
    "femcam.io.Column": "a column declaration of femcam's own tables (names and a unit factor), "
                        "not a physical input",
    **{n: RESULT for n in (
        "femcam.assess.AssessInputs", "femcam.assess.Assessment", "femcam.bodies.CamDiskModel",
        "femcam.bodies.CamDiskResult", "femcam.bodies.CamGlobalModel", "femcam.bodies.RingModel",
        "femcam.bodies.RingResult", "femcam.dynamics.DynamicsResult",
        "femcam.dynamics.JumpResult", "femcam.dynamics.RpmSweep", "femcam.fe.ContactModel",
        "femcam.fe.ContactResult", "femcam.fe.ShearRange", "femcam.fe.StressMax", "femcam.fe.SurfaceStress",
        "femcam.halfspace.ContactSolution", "femcam.halfspace.StripResult",
        "femcam.hertz.ScaledMaximum", "femcam.hertz.StressField", "femcam.hertz.StressMaximum",
        "femcam.kinematics.LawEnds", "femcam.kinematics.MotionLaw", "femcam.kinematics.SVAJ",
        "femcam.kinematics.Derivatives", "femcam.kinematics.Junction",
        "femcam.layers.CaseMargin", "femcam.layers.InterfaceStress", "femcam.mesh.BodyLayout",
        "femcam.mesh.BodyMesh", "femcam.mesh.ContactMesh", "femcam.mesh.PhysicalGroup",
        "femcam.optimise.OptimiseResult", "femcam.optimise.StartRecord", "femcam.optimise.FECheck",
        "femcam.study.StudyResult",
        "femcam.profile.BaseRadiusResult", "femcam.profile.ArmGeometry", "femcam.profile.CamProfile",
        "femcam.profile.PadSpeeds",
        "femcam.Scene",
        "femcam.scene.SceneState", "femcam.SweepResult",
        "femcam.synthesis.SynthesisResult", "femcam.synthesis.Comparison",
        "femcam.synthesis.StudyRow", "femcam.wear.ConvergenceTable", "femcam.wear.EvolutionCase",
        "femcam.wear.EvolutionResult", "femcam.wear.WearMap", "femcam.wear.Seed000Table",
        "femcam.wear.SlipResult", "femcam.loads.LoadResult")},
    **{n: RECORDS for n in (
        "femcam.effective_modulus", "femcam.assess.assessment_inputs", "femcam.assess.sweep_table",
        "femcam.assess.assess", "femcam.assess.assess_rows", "femcam.assess.wear_factor",
        "femcam.assess.csv_columns", "femcam.assess.worst_angles",
        "femcam.bodies.to_csv_columns",
        "femcam.halfspace.to_csv_columns", "femcam.kinematics.CamProgram",
        "femcam.kinematics.junction_report", "femcam.layers.interface_stress",
        "femcam.layers.result_layer_row",
        "femcam.layers.scene_layers", "femcam.mesh.gmsh_nodes", "femcam.mesh.mirror",
        "femcam.mesh.mesh_coated_body", "femcam.mesh.mesh_plain_body",
        "femcam.sweep.run_chunk", "femcam.wear.format_table3", "femcam.wear.seed000_table",
        "femcam.io.atomic_write_bytes", "femcam.io.atomic_write_text", "femcam.io.versions",
        "femcam.io.provenance", "femcam.io.csv_text", "femcam.io.write_csv",
        "femcam.io.read_csv", "femcam.io.write_npz", "femcam.io.write_pvd",
        "femcam.io.write_vtu", "femcam.io.write_fe_vtu", "femcam.synthesis.study_columns",
        "femcam.io.header_dict", "femcam.io.meta_path", "femcam.io.read_meta", "femcam.io.write_rows",
        "femcam.io.write_table", "femcam.io.atomic_write_path", "femcam.io.write_arrays",
        "femcam.io.write_ring_vtu", "femcam.io.write_cam_vtu", "femcam.io.write_msh")},
    "femcam.mesh.mesh_body": "takes an open gmsh session; its numbers are checked by body_layout",
    **{n: "a typed record the checked scene loader builds (load_scene checks its values)" for n in (
        "femcam.scene.BodyLayers", "femcam.scene.CamShaft", "femcam.scene.CaseSpec",
        "femcam.scene.CoatingSpec", "femcam.scene.FiniteLength",
        "femcam.scene.RealBodies", "femcam.scene.RollerSupport")},
    "femcam.halfspace.has_finite_length": "takes the scene's FiniteLength record (None: not given) "
                                          "and its contact length, both made by the checked loader",
    "femcam.scene.roller_support_problems": "the scene's support check (h4-scene's femcam/scene); the "
                                            "API entry with argument checks is bodies.bearing_problems",
    "femcam.mesh.gmsh_session": "a context manager named by a string",
    "femcam.optimise.Design": "the map from a design vector to a scene variant; built by optimise "
                              "from checked Variables and a BezierRise",
    "femcam.load_scene": "reads a file; scene faults are tests/test_scene*.py (h4-scene)",
    "femcam.scene.study_problem": "returns the problem text of one [fe]/[sweep] value",
    "femcam.scene.wear_table": "the scene loader's [wear] table reader (scene faults)",
    "femcam.sweep.default_cache": "no arguments",
    "femcam.sweep.parse_angles_deg": "parses a 'start:stop:step' string (tests/test_cli_errors.py)",
    "femcam.tribology.lubricant": "looks a lubricant up by name",
}

# ----------------------------------------------------------------------------- discovery
FLAT_MODULES = ("femcam.materials", "femcam.loads", "femcam.io")


def public_callables() -> dict[str, object]:
    """Every public callable once, under its first public name (root package first)."""
    names = ["femcam"] + sorted(
        f"femcam.{m.name}" for m in pkgutil.iter_modules(femcam.__path__)
        if m.ispkg and m.name not in ("cli", "viz"))
    found: dict[str, object] = {}
    seen: set[int] = set()

    def add(qual, obj):
        if id(obj) in seen or not callable(obj):
            return
        if inspect.isclass(obj) and issubclass(obj, BaseException | Warning):
            return
        if not (inspect.isfunction(obj) or inspect.isclass(obj)):
            return  # locks, constants
        seen.add(id(obj))
        found[qual] = obj

    for mod_name in names:
        mod = importlib.import_module(mod_name)
        for n in getattr(mod, "__all__", ()):
            add(f"{mod_name}.{n}", getattr(mod, n))
    for mod_name in FLAT_MODULES:
        mod = importlib.import_module(mod_name)
        for n, obj in sorted(vars(mod).items()):
            if not n.startswith("_") and getattr(obj, "__module__", None) == mod_name:
                add(f"{mod_name}.{n}", obj)
    return found


PUBLIC = public_callables()


def test_every_public_callable_has_an_entry():
    missing = sorted(set(PUBLIC) - set(CASES) - set(NOT_AN_INPUT))
    assert not missing, (
        f"public callables without a fault-injection entry: {missing}. Add a valid base call "
        "and the kind of each numeric parameter to CASES in tests/test_api_faults.py (or the "
        "reason it takes no physical number to NOT_AN_INPUT)")
    stale = sorted((set(CASES) | set(NOT_AN_INPUT)) - set(PUBLIC))
    assert not stale, f"entries for names that are no longer public: {stale}"


def test_every_numeric_parameter_is_in_the_signature():
    for name, case in CASES.items():
        params = inspect.signature(PUBLIC[name]).parameters
        if any(q.kind is q.VAR_KEYWORD for q in params.values()):
            continue  # law(name, **params): the parameters are the law's
        unknown = set(case.numeric) - set(params)
        assert not unknown, f"{name}: {sorted(unknown)} not parameters of {list(params)}"


# ----------------------------------------------------------------------------- faults
def bad_value(kind, good):
    """The faulty replacement of a valid value ``good``."""
    arr = isinstance(good, np.ndarray | list | tuple)
    if kind == "str":
        return "abc"
    if kind == "none":
        return None
    if kind == "strlist":
        return ["a", "b"]
    if kind == "numlist":
        g = float(np.ravel(np.asarray(good, dtype=float))[0]) if good is not None else 1.0
        return [g, 1.5 * g]
    if isinstance(kind, float):
        return kind
    special = {"nan": math.nan, "inf": math.inf, "neg": -1.0, "zero": 0.0}[kind]
    if not arr:
        if kind == "neg" and good is not None and good != 0:
            return -abs(float(good))
        return special
    out = np.array(good, dtype=float).copy()
    out.flat[0] = -abs(out.flat[0]) if kind == "neg" and out.flat[0] != 0 else special
    return out


def _call(name, args, kwargs):
    case = CASES[name]
    fn = case.call or PUBLIC[name]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return fn(*args, **kwargs)


def _has_nan(out) -> bool:
    if isinstance(out, float | np.floating | np.ndarray):
        return bool(np.any(np.isnan(np.asarray(out, dtype=float))))
    if isinstance(out, tuple):
        return any(_has_nan(o) for o in out if isinstance(o, float | np.ndarray))
    return False


FAULTS = [(name, p) for name, case in CASES.items() for p in case.numeric]


@pytest.mark.parametrize("name, param", FAULTS, ids=[f"{n}:{p}" for n, p in FAULTS])
def test_fault_is_refused_naming_the_parameter(name, param):
    case = CASES[name]
    make = case.fault_base or case.base
    problems = []
    for kind in case.numeric[param]:
        args, kwargs = make()
        sig = inspect.signature(PUBLIC[name]).parameters
        good = kwargs.get(param, sig[param].default if param in sig else None)
        if good is inspect.Parameter.empty:
            good = None
        kwargs[param] = bad_value(kind, good)
        try:
            out = _call(name, args, kwargs)
        except FemcamError as e:
            if param not in str(e):
                problems.append(f"{kind}: message does not name {param!r}: {e}")
        except Exception as e:  # noqa: BLE001 - any other exception is the fault found
            problems.append(f"{kind}: {type(e).__name__}: {e}")
        else:
            problems.append(f"{kind}: accepted ({'NaN result' if _has_nan(out) else 'no error'})")
    assert not problems, f"{name}({param}=...):\n  " + "\n  ".join(problems)


def _is_record(value) -> bool:
    """A record argument (scene, model, program, options, slip result, task function)."""
    plain = (bool, int, float, str, bytes, np.ndarray, list, tuple, dict, np.floating)
    return value is not None and not isinstance(value, plain)


def test_record_arguments_are_refused_naming_them():
    """A string or None where a record (Scene, CamProgram, TrainModel, SlipResult, a model, ...)
    belongs raises a FemcamError naming the argument, not an AttributeError from deep inside.
    Slow cases are left out: their record is the built model the fault stand-in replaces."""
    problems, n = [], 0
    for name, case in CASES.items():
        if case.slow:
            continue
        _, kwargs0 = case.base()
        for param in [p for p, v in kwargs0.items() if p not in case.numeric and _is_record(v)]:
            for bad in ("abc", None):
                args, kwargs = case.base()
                kwargs[param] = bad
                n += 1
                try:
                    _call(name, args, kwargs)
                except FemcamError as e:
                    if param not in str(e):
                        problems.append(f"{name}({param}={bad!r}): message does not name it: {e}")
                except Exception as e:  # noqa: BLE001 - any other exception is the fault found
                    problems.append(f"{name}({param}={bad!r}): {type(e).__name__}: {e}")
                else:
                    problems.append(f"{name}({param}={bad!r}): accepted")
    assert n >= 40, n  # the table holds this many record arguments (guards against an empty loop)
    assert not problems, "\n".join(problems)


N_FAULTS = sum(len(k) for c in CASES.values() for k in c.numeric.values())

FAST = [n for n, c in CASES.items() if not c.slow]
SLOW = [pytest.param(n, marks=pytest.mark.slow) for n, c in CASES.items() if c.slow
        and c.base is not None]


@pytest.mark.parametrize("name", FAST + SLOW)
def test_valid_base_call_succeeds(name):
    args, kwargs = CASES[name].base()
    _call(name, args, kwargs)


def test_counts():
    """The size of the campaign (reported in the README): public callables and faults."""
    assert not set(CASES) & set(NOT_AN_INPUT), "a name is either injected or excused, not both"
    assert len(CASES) + len(NOT_AN_INPUT) == len(PUBLIC)
    assert N_FAULTS > 5 * len(CASES)
