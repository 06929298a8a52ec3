"""The ``lambda`` and ``residual_vibration`` objectives of femcam.optimise, each checked against
an independent recomputation (femcam.assess.assess, femcam.dynamics.periodic_response)."""

import dataclasses
import math

import numpy as np
import pytest

from femcam.assess import assess
from femcam.dynamics import periodic_response
from femcam.errors import InputError
from femcam.kinematics import law
from femcam.optimise import optimise
from femcam.optimise.chain import residual_vibration
from femcam.scene import contact_case, load_scene

ASSESS = "examples/seed002_assess.toml"
DYNAMIC = "examples/seed002_dynamic.toml"
CONS = {"phi_max": math.radians(30.0), "rho_min": 0.0}


def _variant(scene, res):
    return dataclasses.replace(scene, follower=res.follower, program=res.program)


def _residual_direct(scene):
    """max |x - s - e_static| in the dwell after the rise, straight from periodic_response
    (1-DOF: the static compression of the train is -(k s + Fpl)/(k_t + k))."""
    tr = scene.train
    d = periodic_response(tr, scene.program, scene.omega)
    sg = scene.program.segments
    assert sg[0].kind == "rise" and sg[1].law is None
    t0, t1 = sg[0].beta, sg[0].beta + sg[1].beta
    sel = (d.theta >= t0) & (d.theta <= t1)
    f = tr.follower
    e_st = -(f.k * sg[0].h + f.Fpl) / (tr.k_t + f.k)
    return float(np.max(np.abs(d.e[sel, 0] - e_st)))


def _with_law(scene, lw):
    segs = tuple(dataclasses.replace(s, law=lw) if s.law is not None else s for s in scene.program.segments)
    return dataclasses.replace(scene, program=dataclasses.replace(scene.program, segments=segs))


def test_lambda_objective_raises_lambda_min_and_matches_assess():
    sc = load_scene(ASSESS)
    r = optimise(sc, objective="lambda", variables={"base_radius": (0.008, 0.014)}, constraints=CONS,
                 verify_fe=False)
    assert r.converged, r.message
    lam_start, lam_opt = 1.0 / r.start_value, 1.0 / r.value   # the objective is 1/lambda_min
    assert lam_opt >= lam_start
    # independent: the assessment's own lambda of the optimal design on a uniform 0.1 deg grid
    th = np.linspace(0.0, 2.0 * math.pi, 3601)
    lam = np.asarray(assess(contact_case(_variant(sc, r), th)).rows["lam"], float)
    np.testing.assert_allclose(np.nanmin(lam), lam_opt, rtol=1e-9,
                               err_msg="lambda_min of the optimum against femcam.assess.assess")
    lam0 = np.asarray(assess(contact_case(sc, th)).rows["lam"], float)
    np.testing.assert_allclose(np.nanmin(lam0), lam_start, rtol=1e-9)


def test_objectives_refused_without_their_data():
    free = {"control_point_4": (-1.0, 2.0)}
    with pytest.raises(InputError, match=r"objective = 'lambda'.*\[lubricant\]"):
        optimise(DYNAMIC, objective="lambda", variables=free, verify_fe=False)
    with pytest.raises(InputError, match=r"objective = 'residual_vibration'.*\[dynamics\] model"):
        optimise(ASSESS, objective="residual_vibration", variables=free, verify_fe=False)


def test_residual_vibration_matches_dynamics_directly():
    sc = load_scene(DYNAMIC)
    r, _ = residual_vibration(sc)
    np.testing.assert_allclose(r[0], _residual_direct(sc), rtol=1e-12,
                               err_msg="residual vibration against periodic_response directly")


def test_stiff_train_residual_vanishes():
    """k_t x 1e4: the residual -> 0. bezier5 (= 3-4-5) has a jerk step of 60 h/beta^3 at the
    dwell, and a 1-DOF train answers a jerk step with an amplitude ~ dj/omega_n^3 ~ k_t^-1.5
    (faster than 1/k), so the slope of log r against log k_t is -1.5."""
    sc = load_scene(DYNAMIC)
    f = np.array([1.0, 1e2, 1e4])
    r = np.array([_residual_direct(dataclasses.replace(
        sc, train=dataclasses.replace(sc.train, k_t=sc.train.k_t * x, c_t=None))) for x in f])
    assert r[-1] < 2e-12, r                      # 0.8 um at k_t = 2e6 N/m -> 8.1e-13 m at 2e10 N/m
    slope = np.polyfit(np.log(f), np.log(r), 1)[0]
    assert -1.6 < slope < -1.4, (slope, r)


@pytest.mark.slow
def test_residual_vibration_optimum():
    sc = load_scene(DYNAMIC)
    free = {f"control_point_{i}": (-1.0, 2.0) for i in (3, 4, 5, 6)}
    r = optimise(sc, objective="residual_vibration", variables=free, constraints=CONS, verify_fe=False)
    assert r.constraints["phi_max"]["margin"] >= -1e-6
    # (a) below the start (the scene's bezier5) and below 3-4-5 on the same scene
    r345 = _residual_direct(_with_law(sc, law("poly345")))
    assert r.value <= r.start_value and r.value <= r345
    # (b) the optimal design recomputed with femcam.dynamics directly
    direct = _residual_direct(_variant(sc, r))
    assert abs(direct - r.value) <= 1e-12 + 1e-9 * r345
    assert direct < 1e-3 * r345
