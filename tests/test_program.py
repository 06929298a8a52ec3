"""Tests of femcam.kinematics.program: closure, SVAJ against closed forms, junction report.

Closed forms (Norton, *Cam Design and Manufacturing Handbook*, 2009, ch. 3): cycloidal rise
s = h (x/beta - sin(2 pi x/beta)/(2 pi)), x = theta - theta_0; SHM rise
s = h/2 (1 - cos(pi x/beta)); uniform velocity s = h x/beta.
"""

from math import pi

import numpy as np
import pytest

from femcam.errors import InputError
from femcam.kinematics import CamProgram, Junction, dwell, fall, junction_report, law, rise

H = 0.01  # 10 mm lift
B = np.deg2rad([100.0, 60.0, 120.0, 80.0])  # rise, dwell, fall, dwell


def rdfd(rise_law="cycloidal", fall_law="cycloidal"):
    return CamProgram([rise(B[0], H, rise_law), dwell(B[1]), fall(B[2], H, fall_law), dwell(B[3])])


def test_cycloidal_svaj_closed_form():
    p = rdfd()
    omega = 20 * pi  # seed 002 Table 1: 20 pi rad/s
    th = np.linspace(0, 2 * pi, 721, endpoint=False)
    k = p.svaj(th, omega)
    # independent reference: closed-form cycloidal rise / dwell / mirrored fall / dwell
    s_ref = np.zeros_like(th)
    v_ref, a_ref, j_ref = (np.zeros_like(th) for _ in range(3))
    x = th
    m = x < B[0]
    q = 2 * pi * x[m] / B[0]
    s_ref[m] = H * (x[m] / B[0] - np.sin(q) / (2 * pi))
    v_ref[m] = H * omega / B[0] * (1 - np.cos(q))
    a_ref[m] = 2 * pi * H * omega**2 / B[0] ** 2 * np.sin(q)
    j_ref[m] = 4 * pi**2 * H * omega**3 / B[0] ** 3 * np.cos(q)
    m = (x >= B[0]) & (x < B[0] + B[1])
    s_ref[m] = H
    t0 = B[0] + B[1]
    m = (x >= t0) & (x < t0 + B[2])
    y = x[m] - t0
    q = 2 * pi * y / B[2]
    s_ref[m] = H - H * (y / B[2] - np.sin(q) / (2 * pi))
    v_ref[m] = -H * omega / B[2] * (1 - np.cos(q))
    a_ref[m] = -2 * pi * H * omega**2 / B[2] ** 2 * np.sin(q)
    j_ref[m] = -4 * pi**2 * H * omega**3 / B[2] ** 3 * np.cos(q)
    for got, ref, nm in ((k.s, s_ref, "s"), (k.v, v_ref, "v"), (k.a, a_ref, "a"), (k.j, j_ref, "j")):
        np.testing.assert_allclose(got, ref, rtol=1e-12, atol=1e-12 * np.abs(ref).max(),
                                   err_msg=f"{nm}: cycloidal closed form")
    assert k.omega == omega


def test_svaj_scales_with_omega_powers():
    p = rdfd("poly345", "modified_sine")
    th = np.linspace(0, 2 * pi, 200)
    k1, k2 = p.svaj(th, 10.0), p.svaj(th, 30.0)
    np.testing.assert_allclose(k2.s, k1.s, rtol=0, atol=0)
    np.testing.assert_allclose(k2.v, 3 * k1.v, rtol=1e-14, atol=1e-18)
    np.testing.assert_allclose(k2.a, 9 * k1.a, rtol=1e-14, atol=1e-15)
    np.testing.assert_allclose(k2.j, 27 * k1.j, rtol=1e-14, atol=1e-12)
    d = p.derivatives(th)
    np.testing.assert_allclose(k1.v, 10 * d.s1, rtol=1e-15)
    np.testing.assert_allclose(k1.j, 1000 * d["s3"], rtol=1e-15)


def test_theta_modulo_two_pi_and_shapes():
    p = rdfd("poly4567", "shm")
    th = np.linspace(-0.3, 2 * pi - 0.31, 50).reshape(5, 10)
    d0 = p.derivatives(th)
    for n in (-2, 1, 3):
        d = p.derivatives(th + 2 * pi * n)
        for nm in ("s", "s1", "s2", "s3"):
            np.testing.assert_allclose(d[nm], d0[nm], rtol=1e-9, atol=1e-9 * np.abs(d0[nm]).max())
    assert d0.s.shape == (5, 10)
    assert np.ndim(p.derivatives(1.0).s) == 0


def test_derivatives_are_consistent_by_central_differences():
    p = rdfd("modified_trapezoid", "bezier7")
    starts = np.concatenate([[0], np.cumsum(B)])
    th = np.linspace(0.01, 2 * pi - 0.01, 400)
    th = th[np.min(np.abs(th[:, None] - starts[None, :]), axis=1) > 1e-3]
    eps = 1e-5
    for f, df in (("s", "s1"), ("s1", "s2"), ("s2", "s3")):
        fd = (p.derivatives(th + eps)[f] - p.derivatives(th - eps)[f]) / (2 * eps)
        ref = p.derivatives(th)[df]
        np.testing.assert_allclose(fd, ref, atol=1e-6 * np.abs(ref).max(), err_msg=f"d{f}/dtheta")


def test_fall_is_mirrored_rise():
    p = rdfd("shm", "shm")
    y = np.linspace(0, B[2], 30)
    s = p.derivatives(B[0] + B[1] + y).s
    np.testing.assert_allclose(s, H * (1 + np.cos(pi * y / B[2])) / 2, atol=1e-15)


def test_h_max_and_segments():
    p = rdfd()
    assert p.h_max == pytest.approx(H, rel=1e-12)
    assert len(p.segments) == 4 and p.segments[1].kind == "dwell"
    np.testing.assert_allclose(p.theta_starts, np.concatenate([[0], np.cumsum(B)[:-1]]))
    # two different rises and falls; max lift is the sum of the two rises
    q = CamProgram([rise(pi / 2, 0.004, "shm"), rise(pi / 2, 0.006), fall(pi / 2, 0.01), dwell(pi / 2)])
    assert q.h_max == pytest.approx(0.01, rel=1e-12)


# --- errors -------------------------------------------------------------------------------


def test_program_must_close_to_360_degrees():
    with pytest.raises(InputError) as e:
        CamProgram([rise(np.deg2rad(100), H), dwell(np.deg2rad(50)), fall(np.deg2rad(120), H),
                    dwell(np.deg2rad(80))])
    msg = str(e.value)
    assert "350" in msg and "deg" in msg and "rad" in msg


def test_program_closes_within_tolerance():
    CamProgram([rise(2 * pi / 3, H), fall(2 * pi / 3, H), dwell(2 * pi / 3 * (1 + 1e-12))])


def test_program_must_return_to_start_lift():
    with pytest.raises(InputError, match="return to the start lift"):
        CamProgram([rise(pi, H), fall(pi, 0.9 * H)])
    with pytest.raises(InputError, match=">= 0"):
        CamProgram([fall(pi, H), rise(pi, H)])


@pytest.mark.parametrize("beta", [0.0, -0.5, np.nan])
def test_non_positive_beta(beta):
    with pytest.raises(InputError, match="beta.*rad"):
        rise(beta, H)
    with pytest.raises(InputError, match="beta.*rad"):
        dwell(beta)


@pytest.mark.parametrize("h", [0.0, -0.001, "ten"])
def test_non_positive_lift(h):
    with pytest.raises(InputError, match=r"h = .* m: must be"):
        fall(1.0, h)


def test_unknown_law_in_segment():
    with pytest.raises(InputError, match="unknown motion law.*cycloidal"):
        rise(1.0, H, "parabolic")


def test_bad_segments_and_omega():
    with pytest.raises(InputError):
        CamProgram([])
    with pytest.raises(InputError, match="Segment"):
        CamProgram([rise(pi, H), (pi, H)])
    with pytest.raises(InputError, match="omega.*rad/s"):
        rdfd().svaj(0.0, -1.0)
    with pytest.raises(InputError, match="theta"):
        rdfd().derivatives([0.0, np.nan])


# --- junctions ----------------------------------------------------------------------------


def test_uniform_velocity_next_to_dwell_is_infinite_acceleration():
    p = rdfd("uniform_velocity", "uniform_velocity")
    js = p.junctions()
    assert len(js) == 4 and all(isinstance(j, Junction) for j in js)
    assert all(j.infinite_acceleration for j in js)
    # velocity step = h/beta (closed form s' = h/beta on the ramp, 0 on the dwell)
    np.testing.assert_allclose([j.jump_s1 for j in js],
                               [-H / B[0], -H / B[2], H / B[2], H / B[0]], rtol=1e-12)
    assert "INFINITE ACCELERATION" in js[0].describe()


def test_shm_next_to_dwell_is_infinite_jerk_not_acceleration():
    p = rdfd("shm", "shm")
    js = p.junctions()
    assert not any(j.infinite_acceleration for j in js)
    assert all(j.infinite_jerk for j in js)
    # acceleration step = (pi^2/2) h/beta^2 (SHM a at the ends, Norton eq. 3.5)
    j_end_rise = js[0]
    assert j_end_rise.jump_s2 == pytest.approx(pi**2 / 2 * H / B[0] ** 2, rel=1e-12)
    assert j_end_rise.jump_s1 == 0.0
    assert "INFINITE JERK" in j_end_rise.describe()
    assert j_end_rise.kind == "infinite jerk"


def test_cycloidal_next_to_dwell_is_neither():
    js = rdfd().junctions()
    assert not any(j.infinite_acceleration or j.infinite_jerk for j in js)
    assert all(j.jump_s1 == 0.0 and j.jump_s2 == 0.0 for j in js)
    # finite jerk step: s''' = 4 pi^2 h/beta^3 at the rise end (Norton eq. 3.8)
    assert abs(js[0].jump_s3) == pytest.approx(4 * pi**2 * H / B[0] ** 3, rel=1e-12)
    assert js[0].kind == "finite jerk step"
    assert all(j.kind == "smooth" for j in rdfd("poly4567", "bezier9").junctions())


def test_junction_positions_and_wraparound():
    p = rdfd("shm", "cycloidal")
    js = p.junctions()
    np.testing.assert_allclose([j.theta for j in js], [B[0], B[0] + B[1], B[0] + B[1] + B[2], 0.0],
                               atol=1e-12)
    assert js[-1].left == "dwell" and js[-1].right == "rise(shm)"
    assert js[0].left == "rise(shm)" and js[0].right == "dwell"
    assert [j.infinite_jerk for j in js] == [True, False, False, True]


def test_rise_into_fall_with_shm_is_smooth_in_acceleration():
    # SHM rise straight into SHM fall: a = -pi^2/2 h/beta^2 on both sides, no dwell in between
    p = CamProgram([rise(pi, H, "shm"), fall(pi, H, "shm")])
    j0 = p.junctions()[0]
    assert not j0.infinite_jerk and j0.jump_s2 == pytest.approx(0.0, abs=1e-15)


def test_report_text():
    p = rdfd("uniform_velocity", "shm")
    txt = str(p)
    assert "rise(uniform_velocity)" in txt and "INFINITE ACCELERATION" in txt and "INFINITE JERK" in txt
    assert "deg" in txt and "mm" in txt
    rep = junction_report(p.junctions())
    assert "2 with infinite acceleration, 2 more with infinite jerk" in rep


def test_law_object_accepted():
    L = law("bezier", control_points=[0, 0, 0.2, 0.8, 1, 1])
    p = CamProgram([rise(pi, H, L), fall(pi, H, L)])
    assert p.segments[0].law is L
    np.testing.assert_allclose(p.derivatives(pi / 2).s, H * L.s(0.5), rtol=1e-14)


# --- junction jumps in SI at a cam speed ------------------------------------------------------
W = 20 * pi  # rad/s (600 rpm)


def test_shm_junction_acceleration_step_in_si():
    # SHM rise next to a dwell: a = (pi^2/2) h omega^2/beta^2 cos(pi u) (Norton eq. 3.5), so at the
    # rise end a = -(pi^2/2) h omega^2/beta^2 and the step onto the dwell (a = 0) is +pi^2 h w^2/(2 b^2)
    js = rdfd("shm", "shm").junctions(omega=W)
    step = pi**2 * H * W**2 / (2 * B[0] ** 2)
    assert js[0].jump_a == pytest.approx(step, rel=1e-12)  # m/s^2
    assert js[-1].jump_a == pytest.approx(step, rel=1e-12)  # dwell -> rise start: a = +step
    assert js[0].jump_v == 0.0 and js[0].jump_j == 0.0
    assert js[0].omega == W and js[0].jump_s2 == pytest.approx(step / W**2, rel=1e-12)  # per rad kept
    assert f"a = {step:+.4g} m/s^2" in js[0].describe() and "INFINITE JERK" in js[0].describe()


def test_uniform_velocity_and_cycloidal_junction_jumps_in_si():
    # uniform velocity: v = h omega/beta on the ramp -> velocity step -h omega/beta at the rise end
    js = rdfd("uniform_velocity", "uniform_velocity").junctions(W)
    assert js[0].jump_v == pytest.approx(-H * W / B[0], rel=1e-12)
    assert js[2].jump_v == pytest.approx(H * W / B[2], rel=1e-12)  # fall end -> dwell
    assert "m/s," in js[0].describe()
    # cycloidal: j = 4 pi^2 h omega^3/beta^3 cos(2 pi u) -> jerk step -4 pi^2 h w^3/b^3 at the rise end
    jc = rdfd().junctions(omega=W)[0]
    assert jc.jump_j == pytest.approx(-4 * pi**2 * H * W**3 / B[0] ** 3, rel=1e-12)
    assert "m/s^3" in jc.describe()


def test_junctions_without_omega_have_only_per_radian_jumps():
    j = rdfd("shm", "shm").junctions()[0]
    assert j.omega is None and j.jump_v is None and j.jump_a is None and j.jump_j is None
    assert j.jump_s2 == pytest.approx(pi**2 / 2 * H / B[0] ** 2, rel=1e-12)
    assert "m/rad^2" in j.describe()
    assert "per-rad units" in junction_report(rdfd().junctions())
    rep = junction_report(rdfd().junctions(W))
    assert f"omega = {W:.6g} rad/s" in rep and "m/s^3" in rep
    assert "m/s^2" in rdfd("shm", "shm").table(omega=W)
    with pytest.raises(InputError, match=r"omega = -1 rad/s"):
        rdfd().junctions(omega=-1.0)
