"""Slip models and the local Archard wear map (femcam.wear.slip, femcam.wear.map)."""

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

from femcam.errors import InputError
from femcam.io import read_meta
from femcam.wear import map as wmap
from femcam.wear import slip as wslip

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
STUDY = str(EXAMPLES / "seed002_study_model.toml")

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


def _study_hertz(srr):
    """The seed 002 study model at ``TH``: (scene, state, Hertz line contact, slip at ``srr``)."""
    sc_mod = pytest.importorskip("femcam.scene")
    hz = pytest.importorskip("femcam.hertz")
    sc = sc_mod.load_scene(STUDY)
    st = sc.analyse(TH)
    hc = hz.LineContact(F=np.clip(st.Fc, 0, None), length=sc.length, R1=st.rho, R2=sc.follower.Rr,
                        cam=sc.cam, roller=sc.roller)
    slip = wslip.follower_slip(sc.follower, TH, st.s, st.s1, st.s2, omega=sc.omega, srr=srr)
    return sc, st, hc, slip


def test_scene_map_conservation_and_closed_form():
    from scipy.integrate import simpson

    sc, st, hc, slip = _study_hertz(0.05)
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
    assert (tmp_path / "t.csv").read_text().count("\n") == 4          # header + 3 laws
    pytest.importorskip("femcam.scene")
    rc = main(["wear", "map", STUDY, "--out", str(tmp_path), "--step-deg", "1",   # beside t.csv
               "--cycles", "1000", "--no-plots", "--overwrite"])
    assert rc == 0
    rows = (tmp_path / "wear_scene.csv").read_text().splitlines()
    assert rows[0].startswith("theta_deg") and len(rows) == 1 + 360
    out = capsys.readouterr().out
    assert "k = 5e-18 m^3/(N m) = 5e-09 mm^3/(N m) (default: seed 000's K = 1e-08 and H = 2000 N/mm^2" in out
    summ = (tmp_path / "wear_summary.csv").read_text().splitlines()
    assert "k = 5e-18 m^3/(N m)" in read_meta(tmp_path / "wear_summary.csv")["provenance"]["wear_coefficient"]
    vals = dict(zip(summ[0].split(","), summ[1].split(","), strict=True))
    assert float(vals["conservation_error"]) < 1e-3
    assert float(vals["volume_cam_mm3"]) == pytest.approx(float(vals["volume_archard_mm3"]), rel=1e-3)
    # roller: the follower CSV (arc in mm, depth per rev in nm, after N cycles in um)
    fol = (tmp_path / "wear_scene_follower.csv").read_text().splitlines()
    assert fol[0] == "roller_arc_mm,depth_per_rev_nm,depth_1000_cycles_um,depth_1000_cycles_no_drift_um"
    arc = np.array([float(r.split(",")[0]) for r in fol[1:]])
    per_rev = np.array([float(r.split(",")[1]) for r in fol[1:]]) * 1e-9          # m
    total = np.array([float(r.split(",")[2]) for r in fol[1:]]) * 1e-6            # m
    Rr, l = 0.010, 0.010
    assert arc[0] == 0.0 and arc[-1] < 2 * np.pi * Rr * 1e3 and arc[-1] > 0.99 * 2 * np.pi * Rr * 1e3
    # volume (mm^3 in the summary) = l x circumference x mean depth, per rev and after 1000 revs
    vol = float(vals["volume_follower_mm3"]) * 1e-9
    assert l * 2 * np.pi * Rr * np.mean(per_rev) * 1000 == pytest.approx(vol, rel=1e-4)
    assert l * 2 * np.pi * Rr * np.mean(total) == pytest.approx(vol, rel=1e-4)
    assert float(vals["max_depth_follower_um"]) == pytest.approx(total.max() * 1e6, rel=1e-4)
    locked = float(vals["max_depth_follower_no_drift_um"])
    assert locked == pytest.approx(1000 * per_rev.max() * 1e6, rel=1e-4)


# --------------------------------------------------------------------------- roller (follower) wear
def _roller_circle_case(turns=1.25, n_grid=4000):
    """Constant contact; the contact runs ``turns`` roller circumferences per cam revolution."""
    import dataclasses

    src, slip = _circle_case()
    Pf = 2 * math.pi * 0.004                                   # roller Rr = 4 mm
    T = 2 * math.pi / slip.omega
    Vf = turns * Pf / T
    slip = dataclasses.replace(slip, V_follower=np.full(N, Vf), follower_period=Pf)
    return src, slip, Pf, Vf


def test_roller_depth_per_pass_overlap_and_drift():
    a, p0, vs = 1e-4, 8e8, 0.3
    k = 2e-17
    src, slip, Pf, Vf = _roller_circle_case(1.25)
    wm = wmap.wear_map(src, slip, k=k, length=0.01, cycles=4, n_grid=4000)
    one = k * (math.pi * a * p0 / 2) * vs / Vf              # hand: one pass, k w v_slip / V_roller
    x = wm.x_follower
    # the contact starts at roller point 0 and runs 1.25 turns: [0, Pf/4] is passed twice
    twice = (x > 3 * a) & (x < Pf / 4 - 3 * a)
    once = (x > Pf / 4 + 3 * a) & (x < Pf - 3 * a)
    np.testing.assert_allclose(wm.depth_follower[twice], 2 * one, rtol=1e-6)
    np.testing.assert_allclose(wm.depth_follower[once], one, rtol=1e-6)
    assert wm.follower_drift == pytest.approx(Pf / 4, rel=1e-9)
    # 4 revolutions drifting by a quarter turn: every point passed exactly 4 x 1.25 = 5 times
    np.testing.assert_allclose(wm.depth_follower_cycles, 5 * one, rtol=1e-6)
    assert wm.max_depth_follower == pytest.approx(5 * one, rel=1e-6)
    assert wm.max_depth_follower_locked == pytest.approx(4 * 2 * one, rel=1e-6)   # N x per-rev bound
    # same after 1e6 revolutions (a quarter-turn drift cycles through 4 phases exactly)
    big = wmap.wear_map(src, slip, k=k, length=0.01, cycles=1e6, n_grid=4000)
    np.testing.assert_allclose(big.depth_follower_cycles, 1.25e6 * one, rtol=1e-6)
    # volume: l int h dx over the roller = k F sum v_slip dt (Archard), per revolution
    W = k * (math.pi * a * p0 / 2) * 0.01 * vs * 2 * math.pi / slip.omega
    assert wm.volume_follower == pytest.approx(W, rel=1e-9)


def test_drift_sum_against_explicit_shifts():
    P, M = 0.05, 1000
    x = np.arange(M) * P / M

    def h(y):   # band-limited periodic pattern: the grid's trigonometric interpolant is exact
        return 1.0 + 0.5 * np.cos(2 * np.pi * y / P) + 0.2 * np.sin(6 * np.pi * y / P + 0.3)

    D = 0.3141592 * P
    for N in (1, 2, 7, 7.5):
        n = int(N)
        ref = sum(h(x - j * D) for j in range(n)) + (N - n) * h(x - n * D)
        np.testing.assert_allclose(wmap.drift_sum(h(x), P, D, N), ref, atol=1e-12, err_msg=f"N={N}")
    # mean is N x mean(h) for any drift (mode 0 is untouched); the ripple stays bounded
    hN = wmap.drift_sum(h(x), P, D, 1e6)
    assert np.mean(hN) == pytest.approx(1e6, rel=1e-12)
    assert np.ptp(hN) < 1e-5 * 1e6


def test_scene_roller_wear_drift_and_mean():
    srr, k = 0.02, 5e-18
    sc, st, hc, slip = _study_hertz(srr)
    Rr = sc.follower.Rr
    wm = wmap.wear_map({"theta": TH, "a": hc.a, "p0": hc.p0, "Fc": st.Fc}, slip, k=k, length=sc.length,
                       cycles=1e6)
    # drift: the roller surface runs (2 - SRR)/(2 + SRR) x the cam perimeter per revolution;
    # perimeter from the profile polygon (independent of slip.py), modulo 2 pi Rr
    x, y = st.profile.x, st.profile.y
    perim = np.sum(np.hypot(np.roll(x, -1) - x, np.roll(y, -1) - y))
    D = np.mod(perim * (2 - srr) / (2 + srr), 2 * np.pi * Rr)
    assert wm.follower_drift == pytest.approx(D, rel=1e-5)
    # after many revolutions with a drift of 0.52 turn the roller wears evenly: the mean is the
    # Archard volume over l 2 pi Rr, for any drift
    mean = wm.cycles * wm.volume_follower / (sc.length * 2 * np.pi * Rr)
    assert np.mean(wm.depth_follower_cycles) == pytest.approx(mean, rel=1e-9)
    assert wm.max_depth_follower == pytest.approx(mean, rel=1e-2)
    assert wm.max_depth_follower < wm.max_depth_follower_locked
    assert wm.max_depth_follower_locked == pytest.approx(1e6 * np.max(wm.depth_follower), rel=1e-12)
    assert 0 <= wm.x_max_follower < 2 * np.pi * Rr


# --------------------------------------------------------------------------- missing pressure
def test_missing_pressure_raises_or_skips():
    src, slip = _circle_case()
    bad = dict(src, p0=src["p0"].copy())
    bad["p0"][[10, 11]] = np.nan                              # Fc > 0 there: a failed solve
    with pytest.raises(InputError, match=r"theta = '\[5, 5.5\]' deg: contact force Fc > 0 but"):
        wmap.wear_map(bad, slip, k=1e-17, length=0.01)
    with pytest.warns(wmap.WearInputWarning, match=r"skipped 2 angle\(s\) theta = \[5, 5.5\] deg"):
        wm = wmap.wear_map(bad, slip, k=1e-17, length=0.01, missing="skip")
    assert wm.skipped == (10, 11)
    ref = wmap.wear_map(dict(src, Fc=np.where(np.isin(np.arange(N), [10, 11]), 0.0, 1.0)), slip,
                        k=1e-17, length=0.01)
    np.testing.assert_allclose(wm.depth_cam, ref.depth_cam, rtol=1e-12)
    # the sweep-facing per-angle function keeps its behaviour (0) unless asked
    h0 = wmap.wear_depth_per_angle(TH, bad["a"], bad["p0"], bad["Fc"], slip, 1e-17)
    assert h0[10] == 0.0 and h0[12] > 0
    hn = wmap.wear_depth_per_angle(TH, bad["a"], bad["p0"], bad["Fc"], slip, 1e-17, missing="nan")
    assert np.isnan(hn[10]) and np.isnan(hn[11]) and np.isfinite(hn[12])
    with pytest.raises(InputError, match="contact force Fc > 0"):
        wmap.wear_depth_per_angle(TH, bad["a"], bad["p0"], bad["Fc"], slip, 1e-17, missing="raise")


# --------------------------------------------------------------------------- FE pressure
@pytest.fixture(scope="module")
def fe_study(study_scene):
    """A coarse real FE sweep (24 angles) of the seed 002 study model and its slip (SRR 2 %)."""
    sw = pytest.importorskip("femcam.sweep")
    sc = study_scene
    th = np.radians(np.arange(0.0, 360.0, 15.0))
    res = sw.sweep(sc, sw.SweepOptions(angles=th, method="fe"), sw.RunOptions(progress=False))
    st = sc.analyse(th)
    slip = wslip.follower_slip(sc.follower, th, st.s, st.s1, st.s2, omega=sc.omega, srr=0.02)
    return sc, res, slip


def test_fe_pressure_wear_matches_hertz_within_fe_accuracy(fe_study):
    """FE-based wear vs the hand closed form k (Fc/l) v_slip/V_cam.

    Per pass the depth depends on the pressure only through its integral w = int p dx (the
    contact sweeps its whole distribution over each point); the equilibrium of either model
    gives w = Fc/l. The map rebuilds an elliptical pressure from the sweep's a_fe/p0_fe, whose
    integral pi a p0/2 is off Fc/l by the FE's accuracy on a and p0 (targets |a| <= 2 %,
    |p0| <= 0.3 %, tests/test_sweep.py): the honest tolerance is (1.02)(1.003) - 1 = 2.3 %.
    The shape of the distribution enters only at second order, through the smoothing of the
    map over ~a where the load changes (a << the 4 mm the contact moves per 15 deg step).
    """
    sc, res, slip = fe_study
    assert np.all(res.status == "ok"), res["message"]
    k = 5e-18
    Fc = res["Fc"]
    hand = k * Fc / sc.length * slip.v_slip / slip.V_cam              # w = Fc / l
    wf = wmap.wear_map(res, slip, k=k, length=sc.length, pressure="fe", n_grid=4000)
    wh = wmap.wear_map(res, slip, k=k, length=sc.length, pressure="hertz", n_grid=4000)
    np.testing.assert_allclose(wh.depth_pass, hand, rtol=1e-12)       # Hertz: pi a p0/2 = F/l
    np.testing.assert_allclose(wf.depth_pass, hand, rtol=0.023)       # measured 1.08 %
    assert wf.load_error <= 0.023 and wh.load_error < 1e-12
    # whole map, cam and roller: pointwise within the same bound of the Hertz map's maximum
    assert np.max(np.abs(wf.depth_cam - wh.depth_cam)) <= 0.023 * np.max(wh.depth_cam)   # 0.91 %
    assert np.max(np.abs(wf.depth_follower - wh.depth_follower)) <= 0.023 * np.max(wh.depth_follower)
    assert wf.volume_cam == pytest.approx(wh.volume_cam, rel=0.023)                      # 0.34 %
    assert wf.max_depth == pytest.approx(wh.max_depth, rel=0.023)
    assert wf.conservation_error < 1e-4


def test_fe_failed_angles_are_skipped_with_a_warning(fe_study):
    import dataclasses

    sc, res, slip = fe_study
    table = {kk: np.array(v, copy=True) for kk, v in res.table.items()}
    table["status"] = table["status"].astype(object)
    table["message"] = table["message"].astype(object)
    for i in (3, 4):
        table["status"][i], table["message"][i] = "failed", "ConvergenceError: active set cycled"
        table["a_fe"][i] = table["p0_fe"][i] = table["p0_fit"][i] = np.nan
    table["status"] = table["status"].astype(str)
    table["message"] = table["message"].astype(str)
    bad = dataclasses.replace(res, table=table)
    with pytest.warns(wmap.WearInputWarning, match=r"theta = \[45, 60\] deg.*active set cycled"):
        wm = wmap.wear_map(bad, slip, k=5e-18, length=sc.length, pressure="fe")
    assert wm.skipped == (3, 4)
    # the same data without a status column: an error, not zero wear
    plain = {kk: table[kk] for kk in ("theta", "a_fe", "p0_fe", "Fc")}
    with pytest.raises(InputError, match=r"theta = '\[45, 60\]' deg"):
        wmap.wear_map(plain, slip, k=5e-18, length=sc.length, pressure="fe")


def test_fe_pressure_from_a_hertz_sweep_is_refused(fe_study):
    sc, res, slip = fe_study
    sw = pytest.importorskip("femcam.sweep")
    hz = sw.sweep(sc, sw.SweepOptions(angles=res.theta, method="hertz"))
    with pytest.raises(InputError, match="method='hertz'"):
        wmap.wear_map(hz, slip, k=5e-18, length=sc.length, pressure="fe")


# --------------------------------------------------------------------------- comparison across laws
def test_law_comparison_explained_by_load_and_sliding():
    """bezier5/7/9 on the seed 002 model (SRR 2 %): with a constant slide-to-roll ratio the
    depth per pass is k (Fc/l) 2 SRR/(2 + SRR) (V_cam cancels), so the deepest point follows the
    peak contact force; the worn volume is k 2 SRR/(2 + SRR) * l * oint (Fc/l) d(xi) =
    k int Fc v_slip dt. Both references are computed here from seed 002 eq. 11 and the cam
    profile polygon, independently of femcam.wear."""
    sc_mod = pytest.importorskip("femcam.scene")
    hz = pytest.importorskip("femcam.hertz")
    base = sc_mod.load_scene(STUDY)
    k, srr = 5e-18, 0.02
    g = 2 * srr / (2 + srr)
    got, ref_max, ref_vol = {}, {}, {}
    for name in ("bezier5", "bezier7", "bezier9"):
        sc = base.with_law(name)
        st = sc.analyse(TH)
        d, f = sc.dynamics, sc.follower
        phi = np.arctan2(st.s1, f.Rb + f.Rr + st.s)                # in-line roller pressure angle
        Fc = (d.m * st.a + d.c * st.v + d.k * st.s + d.Fpl) / np.cos(phi)   # seed 002 eq. 11
        hc = hz.LineContact(F=Fc, length=sc.length, R1=st.rho, R2=f.Rr, cam=sc.cam, roller=sc.roller)
        slip = wslip.follower_slip(f, TH, st.s, st.s1, st.s2, omega=sc.omega, srr=srr)
        got[name] = wmap.wear_map({"theta": TH, "a": hc.a, "p0": hc.p0, "Fc": Fc}, slip, k=k,
                                  length=sc.length)
        ref_max[name] = k * np.max(Fc) / sc.length * g
        x, y = st.profile.x, st.profile.y
        dxi = np.hypot(np.roll(x, -1) - x, np.roll(y, -1) - y)
        ref_vol[name] = k * g * np.sum(0.5 * (Fc + np.roll(Fc, -1)) * dxi)
    for name, wm in got.items():
        assert wm.max_depth == pytest.approx(ref_max[name], rel=3e-3), name      # measured <= 0.2 %
        assert wm.volume_cam == pytest.approx(ref_vol[name], rel=1e-4), name     # measured <= 2e-5
    order = sorted(got, key=lambda n: got[n].max_depth)
    assert order == sorted(ref_max, key=ref_max.get) == ["bezier5", "bezier7", "bezier9"]
    assert sorted(got, key=lambda n: got[n].volume_cam) == sorted(ref_vol, key=ref_vol.get)
    # the gaps (3 %) are far larger than the map-vs-reference error (0.2 %)
    assert got["bezier7"].max_depth / got["bezier5"].max_depth - 1 > 0.02


# --------------------------------------------------------------------------- knife-edge tip
def test_radiused_tip_slip_is_relative_velocity():
    prof = pytest.importorskip("femcam.profile")
    d = _program().derivatives(TH)
    Rb, rt, e, w = 0.03, 0.002, 0.004, 10.0
    p = prof.cam_profile(prof.RollerFollower(Rb=Rb, Rr=rt, e=e), TH, d.s, d.s1, d.s2)
    r = wslip.radiused_tip(TH, d.s, d.s1, d.s2, Rb=Rb, r_tip=rt, omega=w, e=e)
    # cam material at the contact point Q moves at omega z x Q, the (translating) tip at (0, omega s')
    rel = np.hypot(-w * p.contact_y - 0.0, w * p.contact_x - w * d.s1)
    np.testing.assert_allclose(r.v_slip, rel, rtol=1e-12)
    # contact travel over the tip: r_tip dphi/dt (finite differences of the profile's phi)
    m = _not_junction()
    dphi = (np.roll(p.phi, -1) - np.roll(p.phi, 1)) / (2 * (TH[1] - TH[0]))
    np.testing.assert_allclose(r.V_follower[m], rt * w * dphi[m], atol=2e-3 * np.max(np.abs(r.V_follower)))
    assert r.follower_origin == pytest.approx(rt * p.phi[0], rel=1e-12)
    # vanishing tip radius: the sharp knife-edge
    r0 = wslip.radiused_tip(TH, d.s, d.s1, d.s2, Rb=Rb, r_tip=1e-9, omega=w, e=e)
    k0 = wslip.knife_edge(TH, d.s, d.s1, Rb=Rb, omega=w, e=e)
    np.testing.assert_allclose(r0.v_slip, k0.v_slip, rtol=1e-6)


def test_tip_radius_refused_for_a_roller():
    prof = pytest.importorskip("femcam.profile")
    z = np.zeros(N)
    with pytest.raises(InputError, match=r"tip_radius = 0.001 m: applies to knife-edge followers only"):
        wslip.follower_slip(prof.RollerFollower(Rb=0.02, Rr=0.01), TH, z, z, z, omega=10.0, tip_radius=1e-3)


@pytest.mark.slow  # over 1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_knife_edge_wear_map_needs_tip_radius():
    sc_mod = pytest.importorskip("femcam.scene")
    from femcam.scene import contact_case
    from femcam.wear.scene import scene_wear

    sc = sc_mod.load_scene(str(EXAMPLES / "seed003_knife_edge.toml"))
    assert sc.tip_radius == pytest.approx(2e-3)  # [follower] tip_radius_mm = 2.0
    with pytest.raises(InputError, match=r"\[follower\] tip_radius_mm"):
        scene_wear(contact_case(dataclasses.replace(sc, tip_radius=None), TH))
    rt = 1e-3
    TH2 = TH[::2]
    wm, st, slip = scene_wear(contact_case(sc, TH2, tip_radius=rt), cycles=1.0)
    assert slip.model.startswith("knife-edge with tip radius 1 mm")
    # conservation on cam and tip: l int h = k int Fc v_slip dt (Simpson on the angle grid)
    from scipy.integrate import simpson

    f = np.clip(st.Fc, 0, None) * slip.v_slip
    W = 5e-18 * simpson(np.append(f, f[0]), x=np.append(TH2, 2 * np.pi)) / sc.omega
    assert wm.volume_cam == pytest.approx(W, rel=2e-3)
    assert wm.volume_follower == pytest.approx(W, rel=2e-3)
    # the tip coordinate is r_tip x pressure angle; the base-circle dwell sits at phi = 0, so the
    # deepest tip wear is at the tip's axis point
    assert wm.x_follower.min() < rt * st.phi.min() and wm.x_follower.max() > rt * st.phi.max()
    assert abs(wm.x_max_follower) < 0.05 * rt
    # same cam wear per pass as the closed form with the tip's Hertz contact: k (Fc/l) v/V_cam
    hand = 5e-18 * np.clip(st.Fc, 0, None) / sc.length * slip.v_slip / slip.V_cam
    np.testing.assert_allclose(wm.depth_pass, hand, rtol=1e-12)


# --------------------------------------------------------------------------- [wear] keys and k
def test_wear_table_keys_and_k_source():
    sc_mod = pytest.importorskip("femcam.scene")
    from femcam.errors import InputError, SceneError
    from femcam.scene.checker import _Checker
    from femcam.scene.wear import WearSettings, wear_settings
    from femcam.wear.options import wear_coefficient_info

    def table(raw, hardness=None):  # the loader's check of a [wear] table, then its record
        ck = _Checker("test.toml")
        out = sc_mod.wear_table(ck, raw, hardness)
        ck.raise_if_any()
        return wear_settings(out)

    sc = sc_mod.load_scene(STUDY)
    H = sc.cam.hardness
    with pytest.raises(SceneError, match=r"wear.k = 1e-17: unknown key; did you mean 'k_mm3_per_N_m' in "
                                         r"mm\^3/\(N m\)\?"):
        table({"k": 1e-17})
    with pytest.raises(SceneError, match=r"wear.srr = 3 \(dimensionless\): must be in \(-2, 2\)"):
        table({"srr": 3})
    with pytest.raises(InputError, match=r"wear.srr = 3 \(dimensionless\): must be in \(-2, 2\)"):
        WearSettings(srr=3)                                    # a record built in code
    with pytest.raises(SceneError, match=r"wear.K = 1e-08 \(dimensionless\): needs the cam hardness"):
        wear_coefficient_info(WearSettings(K=1e-8), H)
    with pytest.raises(SceneError, match="not both"):
        table({"K": 1e-8, "k_mm3_per_N_m": 1e-8}, 2e9)
    with pytest.raises(InputError, match="not both"):
        WearSettings(K=1e-8, k=1e-17)
    # defaults: seed 000's K = 1e-8, H = 2000 N/mm^2 -> 5e-18 m^3/(N m), and it says so
    k, where = wear_coefficient_info(sc.wear, H)
    assert k == pytest.approx(1e-8 / 2000e6, rel=1e-15) and where.startswith("default")
    k, where = wear_coefficient_info(table({"k_mm3_per_N_m": 3e-9}), H)
    assert k == pytest.approx(3e-18, rel=1e-15) and "scene [wear] k_mm3_per_N_m" in where
    k, where = wear_coefficient_info(table({"K": 3e-8}, 6000e6), 6000e6)
    assert k == pytest.approx(3e-8 / 6000e6, rel=1e-15) and "hardness_MPa = 6000" in where
    k, where = wear_coefficient_info(WearSettings(), 6000e6)     # default K, scene H
    assert k == pytest.approx(1e-8 / 6000e6, rel=1e-15) and where.startswith("default K = 1e-08")
    opts = table({"J_kg_m2": 2e-6, "cycles": 10})
    assert opts.J == pytest.approx(2e-6) and opts.cycles == 10.0    # SI values
    with pytest.raises(SceneError, match=r"wear.tip_radius_mm = 0.5 mm: retired; give the knife-edge "
                                         r"tip radius as \[follower\] tip_radius_mm"):
        table({"tip_radius_mm": 0.5})


@pytest.mark.slow  # over 1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_cli_map_checks_wear_keys_and_knife_edge(tmp_path, capsys):
    from femcam.cli import main

    text = Path(STUDY).read_text()
    bad = tmp_path / "typo.toml"
    bad.write_text(text + "\n[wear]\nk = 1e-17\n")
    assert main(["wear", "map", str(bad), "--out", str(tmp_path / "o"), "--no-plots"]) == 1
    err = capsys.readouterr().err
    assert "wear.k = 1e-17: unknown key; did you mean 'k_mm3_per_N_m' in mm^3/(N m)?" in err
    knife = str(EXAMPLES / "seed003_knife_edge.toml")
    sharp = tmp_path / "sharp.toml"  # the example without its [follower] tip_radius_mm
    sharp.write_text("\n".join(ln for ln in Path(knife).read_text().splitlines()
                               if not ln.startswith("tip_radius_mm")))
    assert main(["wear", "map", str(sharp), "--out", str(tmp_path / "k"), "--no-plots"]) == 1
    assert "[follower] tip_radius_mm" in capsys.readouterr().err
    assert main(["wear", "map", knife, "--out", str(tmp_path / "k"), "--no-plots", "--step-deg", "2",
                 "--tip-radius-mm", "0.5"]) == 0
    fol = (tmp_path / "k" / "wear_scene_follower.csv").read_text().splitlines()
    assert fol[0].startswith("tip_arc_mm,depth_per_rev_nm,")
    note = read_meta(tmp_path / "k" / "wear_scene_follower.csv")["provenance"]["columns_note"]
    assert "tip radius 0.5 mm" in note


@pytest.mark.slow  # over 1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_cli_map_fe_source(tmp_path):
    """``--source fe`` on a coarse grid (36 angles): same wear as ``--source hertz`` within the
    FE's a/p0 accuracy (2.3 %, see test_fe_pressure_wear_matches_hertz_within_fe_accuracy)."""
    pytest.importorskip("femcam.sweep")
    from femcam.cli import main

    vals = {}
    for src in ("fe", "hertz"):
        out = tmp_path / src
        assert main(["wear", "map", STUDY, "--out", str(out), "--source", src,
                     "--step-deg", "10", "--cycles", "1000", "--no-plots"]) == 0
        summ = (out / "wear_summary.csv").read_text().splitlines()
        vals[src] = dict(zip(summ[0].split(","), summ[1].split(","), strict=True))
    fe, hz = vals["fe"], vals["hertz"]
    assert fe["pressure"] == "fe" and fe["skipped_angles_deg"] == "-"
    assert 0 < float(fe["load_error"]) <= 0.023 and float(hz["load_error"]) < 1e-12
    for col in ("max_depth_um", "volume_cam_mm3", "max_depth_follower_um"):
        assert float(fe[col]) == pytest.approx(float(hz[col]), rel=0.023), col


def test_scene_friction_zero_stays_zero_or_is_refused_by_the_inertia_model(study_scene):
    """[contact] friction = 0 reaches the slip models as mu = 0 (it was replaced by 0.1); the
    inertia-limited roller model, which has nothing to spin the roller without friction, refuses
    it with the reason. References: the friction values typed here."""
    from femcam.wear.options import slip_kwargs

    sc = study_scene
    assert type(sc.follower).__name__ == "RollerFollower"
    from femcam.scene.wear import WearSettings

    def kw(s):
        return slip_kwargs(s.wear, omega=s.omega, mu=s.mu, follower=s.follower)

    assert kw(dataclasses.replace(sc, mu=0.0))["mu"] == 0.0          # srr model: mu unused
    assert kw(dataclasses.replace(sc, mu=0.07))["mu"] == 0.07
    inertia = WearSettings(roller_model="inertia", J=5e-3)
    assert kw(dataclasses.replace(sc, mu=0.07, wear=inertia))["mu"] == 0.07
    with pytest.raises(InputError, match=r"contact\.friction = 0: the inertia-limited roller model "
                                         r"\(\[wear\] roller_model = 'inertia'\) needs friction > 0"):
        kw(dataclasses.replace(sc, mu=0.0, wear=inertia))
