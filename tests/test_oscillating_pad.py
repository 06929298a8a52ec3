"""Curved-pad oscillating follower (femcam.profile.pad): the envelope identity, the sliding and
entrainment speeds against finite differences of the material points of the two bodies, the
long-arm limit against the translating radiused tip, Hertz against the closed form, the FE exact
gap in the arm's contact frame, and the refusals (docs/oscillating.md, "Curved pad")."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest
import tomllib

from femcam.errors import SceneError, UndercutError
from femcam.fe.followers import sliding_sign
from femcam.fe.gap import arc_gap, exact_gap
from femcam.kinematics import CamProgram, dwell, fall, rise
from femcam.profile import OscillatingPadFollower, cam_profile
from femcam.scene import load as scene_load
from femcam.scene import load_scene
from femcam.wear.slip import follower_slip, radiused_tip

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "rff_valve_train.toml"
Rb, Rpad = 0.020, 0.008


def _program(h):
    return CamProgram([rise(1.6, h), dwell(0.8), fall(1.6, h), dwell(2 * math.pi - 4.0)])


def _pad_raw(raw):
    """The example RFF with a 12 mm curved pad instead of the roller, friction 0.08."""
    fo = raw["follower"]
    fo["type"] = "curved_pad"
    fo["pad_radius_mm"] = 12.0
    del fo["roller_radius_mm"]
    raw["contact"]["friction"] = 0.08


@pytest.fixture
def load_raw(monkeypatch):
    """Load the example changed to a pad (and then by ``change``) through load_scene."""
    def load(change=lambda raw: None):
        raw = tomllib.loads(EXAMPLE.read_text(encoding="utf-8"))
        _pad_raw(raw)
        change(raw)
        monkeypatch.setattr(scene_load, "_read_toml", lambda path: raw)
        return load_scene("pad.toml")
    return load


@pytest.mark.parametrize("sigma", [1, -1])
def test_envelope_normal_passes_through_the_pad_centre(sigma):
    """The cam is the envelope of the pad circle: every surface point lies at Rr from the pad
    centre B (pitch point) and the surface tangent (central difference) is perpendicular to B - x."""
    f = OscillatingPadFollower(Rb=Rb, Rr=Rpad, a=0.05, L=0.035, sigma=sigma)
    prog = _program(0.2)
    th = np.linspace(0.01, 2 * math.pi - 0.01, 400)
    d = prog.derivatives(th)
    p = cam_profile(f, th, d.s * f.L, d.s1 * f.L, d.s2 * f.L)   # the scene program holds L psi
    r = np.hypot(p.pitch_x - p.x, p.pitch_y - p.y)
    np.testing.assert_allclose(r, Rpad, rtol=0, atol=1e-17)   # round-off of 5e-2 m coordinates
    h = 1e-6
    dp, dm = prog.derivatives(th + h), prog.derivatives(th - h)
    pp = cam_profile(f, th + h, dp.s * f.L, dp.s1 * f.L, dp.s2 * f.L)
    pm = cam_profile(f, th - h, dm.s * f.L, dm.s1 * f.L, dm.s2 * f.L)
    tx, ty = pp.x - pm.x, pp.y - pm.y
    cos = (tx * (p.pitch_x - p.x) + ty * (p.pitch_y - p.y)) / (np.hypot(tx, ty) * r)
    # central-difference tangent: O(h^2) plus round-off 1e-16 / 1e-6 of the coordinates
    assert np.max(np.abs(cos)) < 1e-8


def _fd_speeds(f, prog, th, omega, h=1e-5):
    """Independent speeds from finite differences of material points (fixed frame): the cam
    point at the contact rotated with the cam, the pad point at the contact carried by the arm
    (its angle gamma from the arm geometry written out here), and the contact's arc positions on
    the cam (cam frame) and on the pad (arm frame)."""
    def state(t):
        d = prog.derivatives(t)
        p = cam_profile(f, t, d.s * f.L, d.s1 * f.L, d.s2 * f.L)
        beta = f.beta0 + d.s
        B = np.stack([f.a - f.L * np.cos(beta), f.sigma * f.L * np.sin(beta)])
        return p, B, np.arctan2(B[1], B[0] - f.a)

    def rot(ang, v):
        c, s = np.cos(ang), np.sin(ang)
        return np.stack([c * v[0] - s * v[1], s * v[0] + c * v[1]])

    p, B, gam = state(th)
    C = np.stack([p.contact_x, p.contact_y])
    A = np.array([[f.a], [0.0]])
    pc = rot(-th, C)                         # the cam's material point, cam frame
    q = rot(-gam, C - A)                     # the pad's material point, arm frame
    (_, _, gp), (_, _, gm) = state(th + h)[:3], state(th - h)[:3]
    v_cam = omega * (rot(th + h, pc) - rot(th - h, pc)) / (2 * h)
    v_pad = omega * (rot(gp, q) - rot(gm, q)) / (2 * h)
    n = (B - C) / f.Rr
    tau = np.stack([-n[1], n[0]])
    slide = np.sum((v_cam - v_pad) * tau, axis=0)
    normal = np.sum((v_cam - v_pad) * n, axis=0)
    # the contact's travel: over the cam (cam frame) and over the pad (angle in the arm frame)
    Pp, Bp, gp = state(th + h)
    Pm, Bm, gm = state(th - h)
    u_cam = omega * np.hypot(Pp.x - Pm.x, Pp.y - Pm.y) / (2 * h)

    def pad_angle(P, Bq, g):
        w = rot(-g, np.stack([P.contact_x, P.contact_y]) - Bq)
        return np.arctan2(w[1], w[0])

    dang = np.angle(np.exp(1j * (pad_angle(Pp, Bp, gp) - pad_angle(Pm, Bm, gm))))
    u_pad = omega * f.Rr * dang / (2 * h)
    return slide, normal, u_cam, u_pad


@pytest.mark.parametrize("sigma", [1, -1])
def test_sliding_and_entrainment_speeds_against_finite_differences(sigma):
    """v_s = (v_cam - v_pad) . tau of the two material points (finite differences, 1e-6
    relative); their normal components agree (contact kept); u_cam, u_pad from the contact's
    travel over each body; U = (u_cam + u_pad) / 2."""
    f = OscillatingPadFollower(Rb=Rb, Rr=Rpad, a=0.05, L=0.035, sigma=sigma)
    prog, omega = _program(0.2), 300.0
    th = np.concatenate([np.linspace(0.05, 1.55, 16), np.linspace(2.45, 3.95, 16), [5.0]])
    d = prog.derivatives(th)
    sp = f.speeds(d.s, d.s1, d.s2, omega=omega)
    slide, normal, u_cam, u_pad = _fd_speeds(f, prog, th, omega)
    scale = np.max(np.abs(sp.v_slide))
    # central differences at h = 1e-5 rad: O(h^2) ~ 1e-10 plus round-off ~1e-11 relative
    np.testing.assert_allclose(sp.v_slide, slide, rtol=1e-6, atol=1e-6 * scale)
    assert np.max(np.abs(normal)) < 1e-6 * scale
    np.testing.assert_allclose(sp.u_cam, u_cam, rtol=1e-6)
    np.testing.assert_allclose(sp.u_pad, u_pad, rtol=0, atol=1e-6 * scale)
    np.testing.assert_allclose(sp.U, 0.5 * (u_cam + u_pad), rtol=0, atol=1e-6 * scale)
    # the FE's sliding sign: friction on the cam along the pad's velocity relative to the cam,
    # projected on the FE local x = (n_y, -n_x) = -tau (femcam.fe.gap): the sign of slide
    sg = sliding_sign(_program(0.2 * f.L), f, th)   # a scene program holds the arc travel L psi
    np.testing.assert_array_equal(sg, np.where(slide >= 0.0, 1, -1))
    # base circle (theta = 5 rad, a dwell): the pad stands still, the cam slides at omega Rb
    assert sp.v_slide[-1] == pytest.approx(omega * Rb, rel=1e-12) and abs(sp.u_pad[-1]) < 1e-12


def _limit_errors(L, e=0.004, h=0.006, omega=100.0):
    """Relative max differences pad (arm L, pivot so that the pad centre's path is tangent to
    the translating axis x = e on the base circle) minus the translating radiused tip of the same
    radius: sliding speed, entrainment speed."""
    Rp = Rb + Rpad
    d = math.sqrt(Rp**2 - e**2)
    dt = _program(h).derivatives(np.linspace(0.0, 2 * math.pi, 721))
    rt = radiused_tip(dt.theta, dt.s, dt.s1, dt.s2, Rb=Rb, r_tip=Rpad, omega=omega, e=e)
    f = OscillatingPadFollower(Rb=Rb, Rr=Rpad, a=math.hypot(e + L, d), L=L)
    do = _program(h / L).derivatives(dt.theta)  # arc travel L psi = translating lift
    sp = f.speeds(do.s, do.s1, do.s2, omega=omega)
    U_t = 0.5 * (rt.V_cam + rt.V_follower)
    return (np.max(np.abs(np.abs(sp.v_slide) - rt.v_slip)) / np.max(rt.v_slip),
            np.max(np.abs(sp.U - U_t)) / np.max(np.abs(U_t)))


def test_long_arm_limit_is_the_translating_radiused_tip():
    """A pad on a very long arm is a translating non-rotating circle (the radiused knife-edge of
    femcam.wear.slip.radiused_tip, a different derivation): the errors are O(1/L)."""
    e1, e2 = _limit_errors(0.5), _limit_errors(5.0)
    assert e1[0] < 5e-3 and e1[1] < 7e-3        # measured 0.33 %, 0.51 % at L = 0.5 m
    assert e2[0] < 5e-4 and e2[1] < 7e-4        # measured 0.033 %, 0.051 % at L = 5 m
    for a, b, what in zip(e1, e2, ("v_slide", "U"), strict=True):
        assert 7.0 < a / b < 13.0, f"{what}: {a:.3g} -> {b:.3g}, not O(1/L)"


def test_scene_slip_and_hertz_against_closed_forms(load_raw):
    """The pad scene: full sliding at omega Rb on the base circle (the wear slip), Hertz p0 with
    the pad radius as the second body (closed form, Johnson 1985 eq. 4.45 with the base circle's
    rho = Rb), traction full sliding."""
    from femcam.sweep import SweepOptions, sweep
    from femcam.sweep.realcam import scene_traction

    sc = load_raw()
    th = np.radians([200.0, 300.0, 20.0])       # base circle twice, then the rise
    t = sweep(sc, SweepOptions(angles=th, method="hertz")).table
    st = sc.analyse(th)
    E_star = 210e9 / (2 * (1 - 0.3**2))
    R = 1 / (1 / 0.018 + 1 / 0.012)
    p0 = np.sqrt(st.Fc[:2] * E_star / (math.pi * R * 0.010))
    np.testing.assert_allclose(t["p0_hertz"][:2], p0, rtol=1e-12)
    np.testing.assert_allclose(t["v_slip"][:2], sc.omega * 0.018, rtol=1e-12)
    assert np.all(t["v_slip"] > 0) and np.isfinite(t["wear_depth"]).all()
    tr = scene_traction(sc, th)
    assert "full sliding" in tr.source and np.all(np.isnan(tr.Q))
    d = sc.program.derivatives(th)
    r = follower_slip(sc.follower, th, d.s, d.s1, d.s2, omega=sc.omega)
    assert r.follower_period is None                # the pad does not turn: an open coordinate


def test_wear_of_both_bodies_is_archard_over_the_sliding_distance(load_raw):
    """Archard on both bodies: the worn volume per revolution of the cam and of the pad equals
    k * sum(Fc |v_s| dt), with v_s from the finite differences of the material points (not the
    class) on the same 1 deg grid; the pad coordinate is open (the contact swings over ~8 mm)."""
    from femcam.scene import contact_case
    from femcam.wear.options import wear_coefficient_info
    from femcam.wear.scene import scene_wear

    sc = load_raw()
    f, n = sc.follower, 360
    th = np.linspace(0.0, 2 * math.pi, n, endpoint=False)
    wm, st, _ = scene_wear(contact_case(sc, th), cycles=1.0)
    k, _ = wear_coefficient_info(sc.wear, sc.cam.hardness)
    slide = _fd_speeds(f, CamProgram([dataclasses.replace(sg, h=sg.h / f.L) for sg in sc.program.segments]),
                       th, sc.omega)[0]
    V = k * np.sum(st.Fc * np.abs(slide)) * (2 * math.pi / n) / sc.omega
    # the map's trapezoidal steps against this rectangle sum: a few 1e-4 on a smooth revolution
    assert wm.volume_cam == pytest.approx(V, rel=1e-3) and wm.volume_follower == pytest.approx(V, rel=1e-3)
    assert wm.follower_period is None and 5e-3 < np.ptp(wm.x_follower) < 2e-2


def test_assessment_film_uses_the_entrainment_speed(load_raw):
    """The assessment's film and flash temperature take the pad's surface speeds: U (and the
    sliding speed) against the finite-difference speeds of the contact's travel over each body."""
    from femcam.sweep import SweepOptions, sweep

    assess = tomllib.loads((EXAMPLE.parent / "seed002_assess.toml").read_text(encoding="utf-8"))

    def change(raw):
        raw["operating"]["oil_temperature_C"] = 90.0
        for k in ("materials", "lubricant", "surface"):
            raw[k] = assess[k]
    sc = load_raw(change)
    th = np.radians([20.0, 50.0, 110.0, 200.0])
    t = sweep(sc, SweepOptions(angles=th, method="hertz")).table
    f = sc.follower
    _, _, u_cam, u_pad = _fd_speeds(
        f, CamProgram([dataclasses.replace(sg, h=sg.h / f.L) for sg in sc.program.segments]), th, sc.omega)
    np.testing.assert_allclose(t["assess_U"], 0.5 * (u_cam + u_pad), rtol=1e-6)
    np.testing.assert_allclose(t["assess_v_slide"], np.abs(u_cam - u_pad), rtol=1e-6)
    assert np.all(np.isfinite(t["assess_h_c"])) and np.all(np.isfinite(t["assess_dT_flash"]))


@pytest.mark.parametrize("pad", [True, False])
def test_exact_gap_in_the_arm_frame_is_the_arc_gap_near_the_contact(load_raw, pad):
    """The exact gap is taken in the contact frame of the arm (normal through the pad's or the
    roller's centre): inside |x| <= 0.1 mm it matches the osculating-arc gap x^2/(2R) to the
    cubic term (a frame turned by the pressure angle gave a gap linear in x and negative)."""
    sc = load_raw() if pad else load_scene(EXAMPLE)
    x = np.linspace(-1e-4, 1e-4, 9)
    for deg in (0.0, 30.0, 60.0, 90.0):
        th = math.radians(deg)
        rho = float(sc.analyse(np.array([th])).rho[0])
        g, ga = exact_gap(sc.program, sc.follower, th, x), arc_gap(x, sc.follower.Rr, rho)
        assert np.all(g >= -1e-15)
        # kappa' x^3 / 6 over x^2 / (2 R): below 1 % at 0.1 mm on this cam
        np.testing.assert_allclose(g[x != 0], ga[x != 0], rtol=1e-2)


@pytest.mark.slow
def test_fe_sweep_of_the_pad_against_hertz(load_raw):
    """FE (arc and exact gap, full sliding mu = 0.08) against Hertz within 1 %."""
    from femcam.sweep import SweepOptions, sweep

    sc = load_raw()
    t = sweep(sc, SweepOptions(angles=np.radians([0.0, 20.0, 60.0, 200.0]), method="fe", a_over_h=10)).table
    assert np.all(t["status"] == "ok")
    np.testing.assert_allclose(t["p0_fe"], t["p0_hertz"], rtol=1e-2,
                               err_msg="FE p0 of the sliding pad vs Hertz (Johnson 1985 §4.2)")


def _drop(key):
    return lambda raw: raw["follower"].pop(key)


@pytest.mark.parametrize("change, pattern", [
    (lambda raw: raw["follower"].update(pad_radius_mm=-5.0),
     r"follower.pad_radius_mm = -5.0 mm: must be in .*concave pad is not modelled"),
    (lambda raw: raw["follower"].update(pad_radius_mm=0.0), r"follower.pad_radius_mm = 0.0 mm: must be in"),
    (lambda raw: raw["follower"].update(pad_radius_mm=70.0),
     r"follower.pad_radius_mm = 70.0 mm: the arm cannot put the pad on the base circle"),
    (lambda raw: raw["follower"].update(roller_radius_mm=9.0),
     r"follower.roller_radius_mm = 9.0 mm: not a key of an oscillating follower of type 'curved_pad'"),
    (_drop("pad_radius_mm"), r"follower.pad_radius_mm: missing required key .*\(unit: mm\)"),
    (lambda raw: raw["follower"].pop("motion"), r"follower.type = 'curved_pad': a curved pad is modelled "
     r"on an arm only"),
])
def test_scene_refusals_name_key_value_and_unit(load_raw, change, pattern):
    with pytest.raises(SceneError, match=pattern):
        load_raw(change)


def test_pad_too_large_for_the_nose_is_undercut(load_raw):
    """A 40 deg swing over 30 deg of cam: the nose's pitch curve is sharper than a 12 mm pad."""
    def change(raw):
        segs = raw["program"]["segment"]
        segs[0].update(beta_deg=30.0, lift_deg=40.0)
        segs[2].update(beta_deg=30.0, lift_deg=40.0)
        segs[3]["beta_deg"] = 290.0
    sc = load_raw(change)
    with pytest.raises(UndercutError, match=r"oscillating_pad cam profile is undercut .*pad radius Rr = 12"):
        sc.analyse(np.radians([0.0]))
