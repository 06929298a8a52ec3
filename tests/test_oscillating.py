"""Oscillating roller follower (femcam.profile.oscillating, femcam.loads.arm_contact_force):
the long-arm limit against the translating roller, the dwell arc, the envelope identity, the
power balance and the refusals (docs/oscillating.md)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import tomllib

from femcam.errors import InputError, SceneError, UndercutError
from femcam.kinematics import CamProgram, dwell, fall, rise
from femcam.loads import ArmDynamics, FollowerDynamics, arm_contact_force, contact_force
from femcam.profile import (
    OscillatingRollerFollower,
    RollerFollower,
    arm_geometry,
    cam_profile,
    min_base_radius_oscillating,
    oscillating_profile,
)
from femcam.scene import load as scene_load
from femcam.scene import load_scene

Rb, Rr = 0.020, 0.008
TH = np.linspace(0.0, 2.0 * math.pi, 721)


def _program(h):
    return CamProgram([rise(1.6, h), dwell(0.8), fall(1.6, h), dwell(2 * math.pi - 4.0)])


def _limit_errors(L, e=0.004, h=0.006):
    """Max differences oscillating (arm L, pivot placed so the roller path is tangent to the
    translating axis x = e at the base circle) minus translating: profile (m), phi (rad),
    1/rho (1/m), Fc (relative)."""
    Rp = Rb + Rr
    d = math.sqrt(Rp**2 - e**2)
    a, alpha = math.hypot(e + L, d), math.atan2(d, e + L)  # pivot at (e + L, d) in the translating frame
    dt = _program(h).derivatives(TH)
    pt = cam_profile(RollerFollower(Rb=Rb, Rr=Rr, e=e), TH, dt.s, dt.s1, dt.s2)
    f = OscillatingRollerFollower(Rb=Rb, Rr=Rr, a=a, L=L)
    do = _program(h / L).derivatives(TH)  # arc length L psi = translating lift
    po = oscillating_profile(f, TH, do.s, do.s1, do.s2)
    # the oscillating fixed frame is the translating one turned by -alpha (pivot onto +x)
    c, s = math.cos(alpha), math.sin(alpha)
    xt, yt = c * pt.x + s * pt.y, -s * pt.x + c * pt.y
    w, m, k, Fpl, cd = 300.0, 0.1, 2e4, 300.0, 2.0
    Ft = contact_force(FollowerDynamics(m=m, k=k, Fpl=Fpl, c=cd), TH, dt.s, w * dt.s1, w**2 * dt.s2,
                       pt.phi).Fc
    # the same train referred to the pivot: I = m L^2, k_t = k L^2, M_pl = Fpl L, c_t = c L^2
    dyn = ArmDynamics(I=m * L**2, k_t=k * L**2, M_pl=Fpl * L, c_t=cd * L**2)
    Fo = arm_contact_force(dyn, TH, do.s, w * do.s1, w**2 * do.s2, L, po.phi).Fc
    return (np.max(np.hypot(xt - po.x, yt - po.y)), np.max(np.abs(po.phi - pt.phi)),
            np.max(np.abs(1 / po.rho - 1 / pt.rho)), np.max(np.abs(Fo - Ft) / Ft))


def test_long_arm_limit_is_the_translating_roller():
    """The arm's arc departs from the translating line by ~h^2/(2L): every error is O(1/L)."""
    e1, e2 = _limit_errors(0.5), _limit_errors(5.0)
    # L = 0.5 m, h = 6 mm: h^2/(2L) = 36 um of sideways roller travel bounds the profile error
    assert e1[0] < 0.036e-3 and e1[1] < 0.02 and e1[3] < 0.02
    # tenfold arm: each error shrinks ~tenfold (band 7-13: the O(1/L^2) remainder)
    for a, b, what in zip(e1, e2, ("profile", "phi", "1/rho", "Fc"), strict=True):
        assert 7.0 < a / b < 13.0, f"{what}: {a:.3g} -> {b:.3g}, not O(1/L)"


def test_dwell_is_a_circular_arc_of_the_predicted_radius():
    """On a dwell at arm angle psi the cam is an arc about O of radius |B(psi)| - Rr, with
    |B|^2 = a^2 + L^2 - 2 a L cos(beta0 + psi) (cosine rule)."""
    f = OscillatingRollerFollower(Rb=Rb, Rr=Rr, a=0.05, L=0.035)
    psi = 0.15
    th = np.linspace(0.0, 1.0, 50)
    p = oscillating_profile(f, th, psi, 0.0, 0.0)
    R = math.sqrt(f.a**2 + f.L**2 - 2 * f.a * f.L * math.cos(f.beta0 + psi)) - Rr
    # round-off of a few multiplications of 5e-2 m numbers
    np.testing.assert_allclose(np.hypot(p.x, p.y), R, rtol=0, atol=1e-15)
    np.testing.assert_allclose(p.rho, R, rtol=1e-12)
    np.testing.assert_allclose(oscillating_profile(f, th, 0.0, 0.0, 0.0).rho, Rb, rtol=1e-12)


@pytest.mark.parametrize("sigma", [1, -1])
def test_envelope_normal_passes_through_the_roller_centre(sigma):
    """The profile tangent (numerical, independent of the formulas' normal) is perpendicular to
    the roller centre - contact segment, whose length is Rr to round-off."""
    f = OscillatingRollerFollower(Rb=Rb, Rr=Rr, a=0.05, L=0.035, sigma=sigma)
    prog = _program(0.25)
    d = prog.derivatives(TH)
    p = oscillating_profile(f, TH, d.s, d.s1, d.s2)
    np.testing.assert_allclose(np.hypot(p.pitch_x - p.x, p.pitch_y - p.y), Rr, rtol=1e-13)
    hstep = 1e-5
    dp, dm = prog.derivatives(TH + hstep), prog.derivatives(TH - hstep)
    pp = oscillating_profile(f, TH + hstep, dp.s, dp.s1, dp.s2)
    pm = oscillating_profile(f, TH - hstep, dm.s, dm.s1, dm.s2)
    tx, ty = pp.x - pm.x, pp.y - pm.y
    cos_ = (tx * (p.pitch_x - p.x) + ty * (p.pitch_y - p.y)) / (np.hypot(tx, ty) * Rr)
    # central difference: O(h^2 * curvature terms) ~ 1e-10, far below any real misalignment
    assert np.max(np.abs(cos_)) < 1e-8


def test_power_balance():
    """Cam torque x omega = (I psi'' + c psi' + k psi + M) psi_dot at every angle. The torque is
    taken from the contact point and the normal of the profile (cam frame), not from the lever."""
    f = OscillatingRollerFollower(Rb=Rb, Rr=Rr, a=0.05, L=0.035, sigma=-1)
    d, w = _program(0.25).derivatives(TH), 400.0
    p = oscillating_profile(f, TH, d.s, d.s1, d.s2)
    dyn = ArmDynamics(I=2e-5, k_t=30.0, M_pl=4.0, c_t=0.01)
    Fc = arm_contact_force(dyn, TH, d.s, w * d.s1, w**2 * d.s2, f.L, p.phi).Fc
    nx, ny = (p.pitch_x - p.x) / Rr, (p.pitch_y - p.y) / Rr
    torque = Fc * (p.x * ny - p.y * nx)  # drive torque balancing the cam's reaction -Fc n at x
    arm = (dyn.I * w**2 * d.s2 + dyn.c_t * w * d.s1 + dyn.k_t * d.s + dyn.M_pl) * w * d.s1
    # round-off relative to the largest power (products of ~1e2 W terms)
    np.testing.assert_allclose(torque * w, arm, rtol=0, atol=1e-11 * np.max(np.abs(arm)))
    assert np.max(np.abs(arm)) > 1.0  # not a trivial 0 = 0


def test_min_base_radius_meets_the_limit():
    prog, lim = _program(0.2), math.radians(25.0)
    R = min_base_radius_oscillating(prog, Rr=Rr, a=0.05, L=0.035, phi_max=lim)
    th = np.linspace(0, 2 * math.pi, 4001)
    d = prog.derivatives(th)

    def phimax(rb):
        f = OscillatingRollerFollower(Rb=rb, Rr=Rr, a=0.05, L=0.035)
        return np.max(np.abs(arm_geometry(f, d.s, d.s1, d.s2).phi))

    # the root find runs on 2048 angles; the 4001-angle maximum may sit a hair above
    assert abs(phimax(R) - lim) < 1e-3 and phimax(0.98 * R) > lim


def test_refusals_name_the_value():
    with pytest.raises(InputError, match=r"a = 0\.01 m.*inside the base circle"):
        OscillatingRollerFollower(Rb=0.02, Rr=0.008, a=0.01, L=0.035)
    with pytest.raises(InputError, match=r"L = 0\.005 m.*cannot put the roller"):
        OscillatingRollerFollower(Rb=0.02, Rr=0.008, a=0.05, L=0.005)
    f = OscillatingRollerFollower(Rb=0.02, Rr=0.008, a=0.05, L=0.035)
    with pytest.raises(InputError, match=r"psi = 3 rad.*folds the arm"):
        arm_geometry(f, 3.0, 0.0, 0.0)
    # a 0.2 rad swing over 0.6 rad of cam: the pitch curve's nose is sharper than the roller
    d = CamProgram([rise(0.6, 0.2), fall(0.6, 0.2), dwell(2 * math.pi - 1.2)]).derivatives(TH)
    f = OscillatingRollerFollower(Rb=0.015, Rr=0.008, a=0.05, L=0.035)
    with pytest.raises(UndercutError, match=r"undercut .*Rr = 8 mm"):
        oscillating_profile(f, TH, d.s, d.s1, d.s2)


# ---------------------------------------------------------------------------- the scene
EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "rff_valve_train.toml"


@pytest.fixture
def load_raw(monkeypatch):
    """Load a parsed scene dict (the example, changed) through load_scene."""
    def load(change):
        raw = tomllib.loads(EXAMPLE.read_text(encoding="utf-8"))
        change(raw)
        monkeypatch.setattr(scene_load, "_read_toml", lambda path: raw)
        return load_scene("osc.toml")
    return load


def _set(table, **kw):
    return lambda raw: raw[table].update(kw)


def _lift(deg):
    def change(raw):
        for sg in raw["program"]["segment"]:
            if "lift_deg" in sg:
                sg["lift_deg"] = deg
    return change


def _fold(raw):
    """Pivot 20 mm from the cam centre, 15 mm arm: the base-circle arm angle is ~100 deg, so an
    85 deg swing passes 180 deg (the arm folds over the line pivot-cam centre)."""
    raw["follower"].update(pivot_distance_mm=20.0, arm_length_mm=15.0)
    _lift(85.0)(raw)


@pytest.mark.parametrize("change, pattern", [
    (_set("follower", pivot_distance_mm=15.0), r"pivot_distance_mm = 15.0 mm: the pivot lies inside"),
    (_set("follower", arm_length_mm=5.0), r"follower.arm_length_mm = 5.0 mm: the arm cannot put the roller"),
    (_lift(150.0), r"program.segment\[0\].lift_deg = 150.0 deg: must be in \(0, 90\]"),
    (_fold, r"program.segment.lift_deg = 85 deg .*folds the arm past the line pivot-cam centre"),
    (_set("dynamics", model="one_dof"), r"dynamics.train_stiffness_N_m_per_rad.*missing required key for "
     r"model = 'one_dof' of an oscillating arm \(unit: N m/rad\)"),
    (_set("dynamics", mass_kg=0.1), r"dynamics.mass_kg = 0.1 kg: a translating follower's key"),
    (_set("follower", offset_mm=2.0), r"follower.offset_mm = 2.0 mm: not a key of an oscillating follower"),
])
def test_scene_refusals_name_key_value_and_unit(load_raw, change, pattern):
    with pytest.raises(SceneError, match=pattern):
        load_raw(change)


def test_scene_undercut_is_refused_at_analyse(load_raw):
    """A 40 deg swing over 30 deg of cam on this RFF: the nose is sharper than the 9 mm roller."""
    def change(raw):
        segs = raw["program"]["segment"]
        segs[0].update(beta_deg=30.0, lift_deg=40.0)
        segs[2].update(beta_deg=30.0, lift_deg=40.0)
        segs[3]["beta_deg"] = 290.0
    sc = load_raw(change)
    with pytest.raises(UndercutError, match=r"undercut .*base radius Rb \(now 18 mm\)"):
        sc.analyse(np.radians([0.0]))


def test_example_scene_state_is_the_arm_model():
    """Scene.analyse of the example: Fc from the moment balance, phi and rho of the arm geometry."""
    sc = load_scene(EXAMPLE)
    th = np.radians(np.arange(0.0, 360.0, 1.0))
    st = sc.analyse(th)
    d, L = sc.program.derivatives(th), sc.follower.L
    psi, psi1, psi2 = d.s / L, d.s1 / L, d.s2 / L  # the scene program holds the arc travel L psi
    assert np.max(psi) == pytest.approx(math.radians(10.0), rel=1e-12)  # lift_deg = 10
    g = arm_geometry(sc.follower, psi, psi1, psi2)
    w, dyn = sc.omega, sc.dynamics
    M = dyn.I * w**2 * psi2 + dyn.k_t * psi + dyn.M_pl + dyn.c_t * w * psi1
    np.testing.assert_allclose(st.Fc, M / g.lever, rtol=1e-12)  # the same formula, one division apart
    np.testing.assert_allclose(st.phi, g.phi, rtol=0, atol=1e-15)
    assert not st.liftoff.any() and not st.undercut_intervals


@pytest.mark.parametrize("sigma", [1, -1])
def test_a_rise_adds_a_positive_pressure_angle_on_either_side(sigma):
    """Sign convention (docs/oscillating.md): phi - phi(base circle) has the sign of psi' while the
    arm swings, on both sides of the pivot; the side only changes the base-circle value, whose
    size is the angle between the roller path u and the radius OB (cosine rule reference)."""
    f = OscillatingRollerFollower(Rb=Rb, Rr=Rr, a=0.05, L=0.035, sigma=sigma)
    th = np.linspace(0.2, 1.4, 7)  # inside the rise
    d = _program(0.2).derivatives(th)
    rise_part = arm_geometry(f, d.s, d.s1, d.s2).phi - arm_geometry(f, d.s, 0.0 * d.s1, 0.0).phi
    assert np.all(rise_part > 0.0)
    base = float(arm_geometry(f, 0.0, 0.0, 0.0).phi)
    # at B0: |OB| = Rp; the angle at B between B->O and the arm is gamma, cos gamma by the cosine
    # rule; u is perpendicular to the arm, so |phi_base| = |90 deg - gamma|
    cos_g = (f.Rp**2 + f.L**2 - f.a**2) / (2 * f.Rp * f.L)
    assert abs(base) == pytest.approx(abs(0.5 * math.pi - math.acos(cos_g)), abs=1e-14)
    assert math.copysign(1.0, base) == -sigma  # this geometry: the path leans away from O on +1


def test_surface_speed_on_the_base_circle_and_a_dwell():
    """On a dwell the roller centre stands still, so the cam surface passes the contact at
    omega x (cam radius there): omega Rb on the base circle, omega (|B| - Rr) on the top dwell."""
    from femcam.wear.slip import follower_slip

    sc = load_scene(EXAMPLE)
    th = np.radians([70.0, 200.0])  # the top dwell (65-75 deg) and the base circle
    d = sc.program.derivatives(th)
    r = follower_slip(sc.follower, th, d.s, d.s1, d.s2, omega=sc.omega, roller_model="srr", srr=0.0)
    f, psi = sc.follower, math.radians(10.0)
    R_top = math.sqrt(f.a**2 + f.L**2 - 2 * f.a * f.L * math.cos(f.beta0 + psi)) - f.Rr
    # round-off of the arm geometry (a few products of 1e-2 m numbers)
    np.testing.assert_allclose(r.V_cam, sc.omega * np.array([R_top, f.Rb]), rtol=1e-12)
    assert np.all(r.v_slip == 0.0)  # srr = 0: pure rolling


def test_assessment_columns_of_an_arm(load_raw):
    """The assessment (film, fatigue) runs on the arm's state: the cam surface speed on the base
    circle is omega Rb, and the safety factors are numbers."""
    from femcam.sweep import SweepOptions, sweep

    assess = tomllib.loads((EXAMPLE.parent / "seed002_assess.toml").read_text(encoding="utf-8"))

    def change(raw):
        raw["operating"]["oil_temperature_C"] = 90.0
        for k in ("materials", "lubricant", "surface"):
            raw[k] = assess[k]
    sc = load_raw(change)
    t = sweep(sc, SweepOptions(angles=np.radians([20.0, 200.0]), method="hertz")).table
    assert t["assess_u_cam"][1] == pytest.approx(sc.omega * sc.follower.Rb, rel=1e-12)
    assert np.all(np.isfinite(t["assess_sf_yield"])) and np.all(np.isfinite(t["assess_h_c"]))
