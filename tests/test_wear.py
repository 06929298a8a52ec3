"""Slip models and the local Archard wear map (femcam.wear.slip, femcam.wear.map)."""

import math

import numpy as np
import pytest

from femcam.errors import InputError
from femcam.wear import map as wmap
from femcam.wear import slip as wslip

N = 720
TH = np.linspace(0.0, 2 * np.pi, N, endpoint=False)


def _program():
    kin = pytest.importorskip("femcam.kinematics")
    return kin.CamProgram([kin.rise(math.radians(120), 0.008, "cycloidal"), kin.dwell(math.radians(60)),
                           kin.fall(math.radians(120), 0.008, "poly345"), kin.dwell(math.radians(60))])


def _arc_rate(x, y, theta):
    """|dP/dtheta| by periodic central differences of profile points (independent of slip.py)."""
    dx = np.roll(x, -1) - np.roll(x, 1)
    dy = np.roll(y, -1) - np.roll(y, 1)
    return np.hypot(dx, dy) / (2 * (theta[1] - theta[0]))


def _not_junction():
    """Mask without the grid points at the four junctions (0, 120, 180, 300 deg), where s2 has a
    kink and central differences of profile points are only first-order accurate."""
    m = np.ones(N, bool)
    for deg in (0, 120, 180, 300):
        m[int(round(deg / 360 * N)) % N] = False
    return m


# --------------------------------------------------------------------------- slip
def test_knife_edge_slip_is_profile_arc_rate():
    prof = pytest.importorskip("femcam.profile")
    d = _program().derivatives(TH)
    f = prof.KnifeEdgeFollower(Rb=0.03, e=0.005)
    p = prof.cam_profile(f, TH, d.s, d.s1, d.s2)
    r = wslip.knife_edge(TH, d.s, d.s1, Rb=0.03, e=0.005, omega=10.0)
    np.testing.assert_allclose(r.v_slip, 10.0 * _arc_rate(p.x, p.y, TH), rtol=2e-4,
                               err_msg="knife-edge slip = omega |dP/dtheta| of the cam profile")
    assert np.all(r.V_follower == 0)


def test_flat_faced_slip_kinematics():
    prof = pytest.importorskip("femcam.profile")
    d = _program().derivatives(TH)
    f = prof.FlatFacedFollower(Rb=0.04)
    p = prof.cam_profile(f, TH, d.s, d.s1, d.s2)
    w = 5.0
    r = wslip.flat_faced(TH, d.s, d.s1, d.s2, Rb=0.04, omega=w)
    np.testing.assert_allclose(r.v_slip, w * (0.04 + d.s), rtol=1e-12)
    # contact travel over the cam = omega |dP/dtheta| of the cam surface points (independent)
    m = _not_junction()
    np.testing.assert_allclose(r.V_cam[m], w * _arc_rate(p.x, p.y, TH)[m], rtol=5e-4)
    # over the face: d(contact x = s1)/dt = omega s2 (finite difference of s1)
    fd = (np.roll(d.s1, -1) - np.roll(d.s1, 1)) / (2 * (TH[1] - TH[0])) * w
    np.testing.assert_allclose(r.V_follower[m], fd[m], atol=2e-3 * np.max(np.abs(fd)))
    np.testing.assert_allclose(r.V_cam - r.V_follower, r.v_slip, rtol=1e-12)


def test_roller_rolling_kinematics():
    prof = pytest.importorskip("femcam.profile")
    d = _program().derivatives(TH)
    Rb, Rr, w = 0.03, 0.01, 20.0
    p = prof.cam_profile(prof.RollerFollower(Rb=Rb, Rr=Rr, e=0.004), TH, d.s, d.s1, d.s2)
    r = wslip.roller_srr(TH, d.s, d.s1, d.s2, Rb=Rb, Rr=Rr, e=0.004, omega=w, srr=0.0)
    assert np.all(r.v_slip == 0.0), "pure rolling: no sliding"
    m = _not_junction()
    np.testing.assert_allclose(r.V_cam[m], w * _arc_rate(p.x, p.y, TH)[m], rtol=5e-4,
                               err_msg="contact travel over the cam vs profile points")
    # base circle (theta in the last dwell, e = 0): roller spins at -omega Rb/Rr
    r0 = wslip.roller_srr(TH, 0 * d.s, 0 * d.s, 0 * d.s, Rb=Rb, Rr=Rr, omega=w, srr=0.0)
    np.testing.assert_allclose(r0.Omega_req, -w * Rb / Rr, rtol=1e-12)
    # SRR definition: 2 (u1 - u2)/(u1 + u2)
    r2 = wslip.roller_srr(TH, d.s, d.s1, d.s2, Rb=Rb, Rr=Rr, omega=w, srr=0.1)
    srr = 2 * (r2.V_cam - r2.V_follower) / (r2.V_cam + r2.V_follower)
    np.testing.assert_allclose(srr, 0.1, rtol=1e-12)
    np.testing.assert_allclose(r2.v_slip, r2.V_cam - r2.V_follower, rtol=1e-12)


def test_roller_inertia_model_limits():
    d = _program().derivatives(TH)
    Rb, Rr, w, J = 0.03, 0.01, 200.0, 2e-6
    Fc = np.full(N, 50.0)
    # huge friction: the roller always follows -> no sliding
    big = wslip.roller_inertia(TH, d.s, d.s1, d.s2, Fc, Rb=Rb, Rr=Rr, omega=w, mu=1e6, J=J)
    assert np.max(big.v_slip) < 1e-9
    # small friction: slides, and the roller's angular acceleration never exceeds mu Fc Rr / J
    r = wslip.roller_inertia(TH, d.s, d.s1, d.s2, Fc, Rb=Rb, Rr=Rr, omega=w, mu=0.06, J=J)
    assert r.converged and r.slipping.any() and (~r.slipping).any()
    dt = (TH[1] - TH[0]) / w
    alpha = np.diff(np.append(r.Omega, r.Omega[0])) / dt
    amax = 0.06 * 50.0 * Rr / J
    assert np.max(np.abs(alpha)) <= amax * (1 + 1e-9)
    # while sliding the friction torque is saturated
    sl = r.slipping & np.roll(r.slipping, -1)
    np.testing.assert_allclose(np.abs(alpha[sl]), amax, rtol=1e-9)
    # no friction at all: the roller keeps a constant speed
    r0 = wslip.roller_inertia(TH, d.s, d.s1, d.s2, Fc, Rb=Rb, Rr=Rr, omega=w, mu=0.0, J=J)
    np.testing.assert_allclose(r0.v_slip, Rr * np.abs(r0.Omega[0] - r0.Omega_req), rtol=1e-12)


# --------------------------------------------------------------------------- map
def _circle_case(a=1e-4, p0=8e8, vs=0.3, Vc=0.06, omega=10.0):
    """Constant contact on a circle of radius Vc/omega: every point sees identical passes."""
    n = np.ones(N)
    slip = wslip.SlipResult(theta=TH, v_slip=vs * n, V_cam=Vc * n, V_follower=0 * n, omega=omega,
                            model="test")
    return {"theta": TH, "a": a * n, "p0": p0 * n, "Fc": n}, slip


def test_per_pass_closed_form_constant_contact():
    a, p0, vs, Vc, k = 1e-4, 8e8, 0.3, 0.12, 3e-17
    src, slip = _circle_case(a, p0, vs, Vc)
    wm = wmap.wear_map(src, slip, k=k, length=0.01)
    w = math.pi * a * p0 / 2                  # int p dx of the Hertz ellipse (Johnson 4.44)
    expected = k * w * vs / Vc                # k w (slip per rolled length)
    np.testing.assert_allclose(wm.depth_cam, expected, rtol=1e-6)
    np.testing.assert_allclose(wm.depth_pass, expected, rtol=1e-12)
    assert wm.perimeter == pytest.approx(2 * math.pi * Vc / 10.0, rel=1e-12)


def test_linearity_in_k_load_and_sliding():
    src, slip = _circle_case()
    base = wmap.wear_map(src, slip, k=1e-17, length=0.01).depth_cam
    h3 = wmap.wear_map(src, slip, k=3e-17, length=0.01).depth_cam
    np.testing.assert_allclose(h3, 3 * base, rtol=1e-12)
    src2 = dict(src, p0=2 * src["p0"])                      # twice the load per length, same a
    h2 = wmap.wear_map(src2, slip, k=1e-17, length=0.01).depth_cam
    np.testing.assert_allclose(h2, 2 * base, rtol=1e-12)
    import dataclasses

    slip2 = dataclasses.replace(slip, v_slip=0.5 * slip.v_slip)
    np.testing.assert_allclose(wmap.wear_map(src, slip2, k=1e-17, length=0.01).depth_cam, 0.5 * base,
                               rtol=1e-12)


def test_zero_sliding_and_no_contact_give_zero_wear():
    import dataclasses

    src, slip = _circle_case()
    z = wmap.wear_map(src, dataclasses.replace(slip, v_slip=0 * slip.v_slip), k=1e-17, length=0.01)
    assert np.all(z.depth_cam == 0) and z.volume_cam == 0 and z.max_depth == 0
    lift = dict(src, Fc=np.zeros(N), a=np.full(N, np.nan))
    z2 = wmap.wear_map(lift, slip, k=1e-17, length=0.01)
    assert np.all(z2.depth_cam == 0)


def test_scene_map_conservation_and_closed_form():
    sc_mod = pytest.importorskip("femcam.scene")
    hz = pytest.importorskip("femcam.hertz")
    from scipy.integrate import simpson

    sc = sc_mod.load_scene("examples/seed002_study_model.toml")
    st = sc.analyse(TH)
    hc = hz.LineContact(F=np.clip(st.Fc, 0, None), length=sc.length, R1=st.rho, R2=sc.follower.Rr,
                        cam=sc.cam, roller=sc.roller)
    slip = wslip.follower_slip(sc.follower, TH, st.s, st.s1, st.s2, omega=sc.omega, srr=0.05)
    k = 5e-18
    wm = wmap.wear_map({"theta": TH, "a": hc.a, "p0": hc.p0, "Fc": st.Fc}, slip, k=k, length=sc.length)
    # independent Archard total: k * int Fc v_slip dt (Simpson on the periodic angle grid)
    f = np.append(st.Fc * slip.v_slip, st.Fc[0] * slip.v_slip[0])
    W = k * simpson(f, x=np.append(TH, 2 * np.pi)) / sc.omega
    assert wm.volume_cam == pytest.approx(W, rel=2e-3), "l int h ds vs k int F v_slip dt"
    assert wm.volume_follower == pytest.approx(W, rel=2e-3)
    # map vs quasi-stationary closed form k w v_slip / V_cam (a << length scale of change)
    np.testing.assert_allclose(wm.depth_at_theta, wm.depth_pass, rtol=2e-2)
    assert wm.max_depth == pytest.approx(np.max(wm.depth_pass), rel=1e-2)


def test_wear_depth_per_angle_function():
    src, slip = _circle_case()
    h = wmap.wear_depth_per_angle(TH, src["a"], src["p0"], src["Fc"], slip, 1e-17)
    np.testing.assert_allclose(h, 1e-17 * math.pi * 1e-4 * 8e8 / 2 * 0.3 / 0.06, rtol=1e-12)
    Fc = src["Fc"].copy()
    Fc[:10] = 0.0
    h2 = wmap.wear_depth_per_angle(TH, src["a"], src["p0"], Fc, slip, 1e-17)
    assert np.all(h2[:10] == 0) and np.all(h2[10:] > 0)


def test_bad_inputs():
    src, slip = _circle_case()
    with pytest.raises(InputError, match=r"k = -1e-17 m\^3/\(N m\)"):
        wmap.wear_map(src, slip, k=-1e-17, length=0.01)
    with pytest.raises(InputError, match="length"):
        wmap.wear_map(src, slip, k=1e-17, length=0.0)
    with pytest.raises(InputError, match="a = -0.0001 m"):
        wmap.wear_map(dict(src, a=-src["a"]), slip, k=1e-17, length=0.01)
    with pytest.raises(InputError, match="theta"):
        half = wslip.SlipResult(TH / 2, *(np.ones(N),) * 3, 1.0, "x")
        wmap.wear_map(dict(src, theta=TH / 2), half, k=1e-17, length=0.01)
    with pytest.raises(InputError, match="srr"):
        wslip.roller_srr(TH, 0 * TH, 0 * TH, 0 * TH, Rb=0.02, Rr=0.01, omega=1.0, srr=2.5)
    with pytest.raises(InputError, match="omega"):
        wslip.knife_edge(TH, 0 * TH, 0 * TH, Rb=0.02, omega=-1.0)


def test_cli_seed000_and_map(tmp_path, capsys):
    from femcam.cli import main

    assert main(["wear", "seed000", "--csv", str(tmp_path / "t.csv")]) == 0
    out = capsys.readouterr().out
    assert "11.03" in out and "3.536" in out          # hand-derived S_cyc (mm), v_rms,SHM (mm/s)
    assert (tmp_path / "t.csv").read_text().count("\n") == 5
    pytest.importorskip("femcam.scene")
    rc = main(["wear", "map", "examples/seed002_study_model.toml", "--out", str(tmp_path), "--step-deg", "1",
               "--cycles", "1000", "--no-plots"])
    assert rc == 0
    rows = (tmp_path / "wear_scene.csv").read_text().splitlines()
    assert rows[1].startswith("theta_deg") and len(rows) == 2 + 360
    summ = (tmp_path / "wear_summary.csv").read_text().splitlines()
    vals = dict(zip(summ[1].split(","), summ[2].split(","), strict=True))
    assert float(vals["conservation_error"]) < 1e-3
    assert float(vals["volume_cam_mm3"]) == pytest.approx(float(vals["volume_archard_mm3"]), rel=1e-3)
