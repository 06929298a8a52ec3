"""Knife-edge (with a tip radius) and flat-faced followers in the FE, sliding directions, the
flat-face edge refusal, the traction from the roller mechanism and the per-angle model choice.

References written here: Hertz line contact (Johnson 1985 eq. 4.45) with the cam radius from the
polar pitch-curve formula (Norton ch. 8) or rho = Rb + s + s'' (flat face, Norton eq. 8.24);
velocities of a counter-clockwise cam on its base circle worked by hand.
"""

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

from femcam.errors import InputError, PhysicsError, SceneError
from femcam.fe import MeshOptions, SolverOptions
from femcam.fe.choice import build_real_cam, mechanism_Q, solve_angle
from femcam.fe.followers import face_edge_intervals, rolling_direction, sliding_sign
from femcam.fe.gap import exact_gap
from femcam.materials import effective_modulus
from femcam.profile import KnifeEdgeFollower
from femcam.scene import load_scene

EX = Path(__file__).resolve().parents[1] / "examples"
FAST = dict(mesh=MeshOptions(a_over_h=12), solver=SolverOptions(eval_depth=0.0))


def hertz_p0(F, length, R, rho, Es):
    inv = (0 if math.isinf(R) else 1 / R) + 1 / rho
    a = math.sqrt(4 * F / length / inv / (math.pi * Es))
    return 2 * F / length / (math.pi * a)


def test_knife_edge_without_tip_radius_is_refused():
    sc = load_scene(EX / "seed003_knife_edge.toml")
    f = KnifeEdgeFollower(Rb=0.005)
    with pytest.raises(InputError, match="tip_radius_mm"):
        exact_gap(sc.program, f, 0.1, np.zeros(3))
    with pytest.raises(InputError, match="tip_radius_mm"):
        build_real_cam(program=sc.program, follower=f, cam=sc.cam, roller=sc.roller, length=sc.length,
                       F_ref=20.0, rho_ref=0.005)


def test_tip_radius_on_a_roller_is_a_scene_error(tmp_path):
    txt = (EX / "shm_dwell_junction.toml").read_text()
    txt = txt.replace("offset_mm = 0.0", "offset_mm = 0.0\ntip_radius_mm = 1.0")
    p = tmp_path / "bad.toml"
    p.write_text(txt)
    with pytest.raises(SceneError, match="follower.tip_radius_mm.*only a knife_edge"):
        load_scene(p)
    knife = (EX / "seed003_knife_edge.toml").read_text()
    knife = knife.replace("tip_radius_mm = 2.0", "tip_radius_mm = -2.0")
    p.write_text(knife)
    with pytest.raises(SceneError, match=r"follower.tip_radius_mm.*-2.*mm"):
        load_scene(p)
    flat = (EX / "flat_faced.toml").read_text().replace("face_length_mm = 30.0", "face_length_mm = 0.0")
    p.write_text(flat)
    with pytest.raises(SceneError, match=r"follower.face_length_mm"):
        load_scene(p)


def test_directions_on_the_base_circle():
    """Dwell at the base circle: contact at (0, Rb), the cam surface moves at omega (-Rb, 0) and
    the follower is at rest, so the follower slides +x over the cam (friction on the cam +x) and
    the cam material flows through the contact in -x (rolling = -1)."""
    sc = load_scene(EX / "flat_faced.toml")
    th = np.radians([320.0, 330.0])  # the last dwell
    assert sliding_sign(sc.program, sc.follower, th).tolist() == [1, 1]
    rs = load_scene(EX / "shm_dwell_junction.toml")
    assert rolling_direction(rs.program, rs.follower, np.radians([45.0])).tolist() == [-1]


def test_seed003_knife_edge_fe_vs_hertz():
    """seed 003 with a 2 mm tip: the cam cut for the radiused tip has the pitch curve of base
    radius Rb + r; rho = rho_pitch - r from the polar formula. FE p0 within 0.5 % of Hertz
    (smooth 3-4-5 law), full sliding with |Q| = mu Fc."""
    sc = load_scene(EX / "seed003_knife_edge.toml")
    r_tip = sc.origin["follower"]["tip_radius_mm"] * 1e-3
    th = np.radians([40.0, 100.0, 250.0])
    st = sc.analyse(th)
    Es = effective_modulus(sc.cam, sc.roller, sc.plane)
    rc = build_real_cam(program=sc.program, follower=sc.follower, cam=sc.cam, roller=sc.roller,
                        length=sc.length, F_ref=float(st.Fc.max()), rho_ref=0.008, tip_radius=r_tip, **FAST)
    d = sc.program.derivatives(th)
    rp = sc.follower.Rb + r_tip + d.s
    kp = (rp**2 + 2 * d.s1**2 - rp * d.s2) / (rp**2 + d.s1**2) ** 1.5
    for k, t in enumerate(th):
        res = solve_angle(rc, t, float(st.Fc[k]), mu=sc.mu, force_exact=True)
        ref = hertz_p0(st.Fc[k], sc.length, r_tip, 1 / kp[k] - r_tip, Es)
        assert res.p0 == pytest.approx(ref, rel=5e-3), f"theta = {math.degrees(t)} deg"
        assert res.slip_state == "sliding" and abs(res.Q) == pytest.approx(sc.mu * st.Fc[k], rel=1e-9)


def test_flat_faced_fe_vs_hertz_and_edge_refusal():
    """Flat face on the cycloidal cam: rho = Rb + s + s'' (Norton eq. 8.24), R = inf; FE p0
    within 0.5 % of Hertz. A 15 mm face is too short where |s'| + a > 7.5 mm: refused with the
    angle range; the interval agrees with the condition evaluated here."""
    sc = load_scene(EX / "flat_faced.toml")
    th = np.radians([40.0, 100.0, 200.0])
    st = sc.analyse(th)
    Es = effective_modulus(sc.cam, sc.roller, sc.plane)
    rc = build_real_cam(program=sc.program, follower=sc.follower, cam=sc.cam, roller=sc.roller,
                        length=sc.length, F_ref=float(st.Fc.max()), rho_ref=0.025,
                        face_length=sc.origin["follower"]["face_length_mm"] * 1e-3, **FAST)
    d = sc.program.derivatives(th)
    for k, t in enumerate(th):
        res = solve_angle(rc, t, float(st.Fc[k]), mu=sc.mu, force_exact=True)
        ref = hertz_p0(st.Fc[k], sc.length, math.inf, sc.follower.Rb + d.s[k] + d.s2[k], Es)
        assert res.p0 == pytest.approx(ref, rel=5e-3), f"theta = {math.degrees(t)} deg"
        assert res.slip_state == "sliding" and res.Q == pytest.approx(sc.mu * st.Fc[k], rel=1e-9)
    short = dataclasses.replace(rc, face_length=0.015)
    h, beta = 0.01, math.radians(120)
    s1_60 = h / beta * (1 - math.cos(2 * math.pi * math.radians(60) / beta))  # cycloidal s' = 2h/beta
    assert s1_60 > 0.0075
    with pytest.raises(PhysicsError, match=r"edge contact.*deg"):
        solve_angle(short, math.radians(60.0), float(st.Fc[0]), mu=sc.mu)
    grid = np.radians(np.arange(0.0, 360.0, 0.5))
    iv = face_edge_intervals(sc.program, sc.follower, 0.015, grid, 1e-4)
    s1 = np.abs(sc.program.derivatives(grid).s1)
    inside = np.zeros(grid.size, bool)
    for lo, hi in iv:
        inside |= (grid >= lo - 1e-12) & (grid <= hi + 1e-12)
    np.testing.assert_array_equal(inside, s1 + 1e-4 > 0.0075)


def test_mechanism_Q_closed_form():
    """Omega = W0 + A sin(theta): Q = -(J omega A cos(theta) + T_drag sign(Omega)) / Rr."""
    th = np.linspace(0, 2 * math.pi, 720, endpoint=False)
    Om = -50.0 + 5.0 * np.sin(th)
    J, T, Rr, w = 2e-6, 0.01, 0.01, 30.0
    ref = -(J * w * 5.0 * np.cos(th) - T) / Rr
    np.testing.assert_allclose(mechanism_Q(Om, th, w, J=J, T_drag=T, Rr=Rr), ref, rtol=1e-4, atol=1e-6)


def test_model_choice_per_angle():
    """Smooth base-circle angle: Hertz answers within 1 %; at the junction the arc-gap estimate
    exceeds 1 % and the exact FE answers. A roller with Q = 0.5 mu Fc is in partial slip."""
    sc = load_scene(EX / "shm_dwell_junction.toml")
    th = np.radians([45.0, 90.0])
    st = sc.analyse(th)
    rc = build_real_cam(program=sc.program, follower=sc.follower, cam=sc.cam, roller=sc.roller,
                        length=sc.length, F_ref=1001.0, rho_ref=0.02, **FAST)
    smooth = solve_angle(rc, th[0], float(st.Fc[0]), mu=sc.mu, Q=0.0)
    assert smooth.model == "hertz" and smooth.est_err_hertz_pct < 1.0
    jump = solve_angle(rc, th[1], float(st.Fc[1]), mu=sc.mu, Q=0.5 * sc.mu * float(st.Fc[1]))
    assert jump.model == "fe_exact" and jump.est_err_arc_pct > 1.0
    assert jump.slip_state == "partial slip" and jump.Q_over_muFc == pytest.approx(0.5, rel=1e-9)
    row = jump.row()
    assert {"model", "curvature_jump", "exact_vs_arc_p0_pct", "Q_N", "Q_over_muFc", "stick_width_um",
            "slip_state"} <= set(row)
