"""The elastic train and the jump speed of an oscillating arm (femcam.dynamics.arm; docs/oscillating.md,
docs/dynamics.md). References: the translating follower's train with the matching mass and
springs (long-arm limit), a rotational-coordinate ODE solved by DOP853, the moment balance about
the pivot from the profile's contact point and normal (power), and the closed-form rigid jump
speed of the cycloidal law written here from first principles."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import tomllib

from femcam.dynamics import (
    TrainModel,
    arm_follower,
    arm_train,
    jump_speed,
    lever_spring,
    periodic_response,
    rigid_jump_speed,
)
from femcam.errors import InputError, SceneError
from femcam.kinematics import CamProgram, dwell, fall, rise
from femcam.loads import ArmDynamics, FollowerDynamics
from femcam.profile import OscillatingRollerFollower, RollerFollower, cam_profile, oscillating_profile
from femcam.scene import load as scene_load
from femcam.scene import load_scene

Rb, Rr = 0.020, 0.008
W = 300.0                                   # cam speed, rad/s
m, k, Fpl, c = 0.1, 2e4, 300.0, 2.0         # translating follower: kg, N/m, N, N s/m
k_t, m2, k2 = 5e6, 0.05, 8e6                # train, second mass (N/m, kg, N/m)
EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "rff_valve_train.toml"


def _program(h):
    return CamProgram([rise(1.6, h), dwell(0.8), fall(1.6, h), dwell(2 * math.pi - 4.0)])


def _trains(L, two):
    """(translating TrainModel, arm TrainModel): the same train, the arm's referred by I = m L^2 ..."""
    sec = dict(m2=m2, k2=k2, zeta2=0.04) if two else {}
    tr = TrainModel(follower=FollowerDynamics(m=m, k=k, Fpl=Fpl, c=c), k_t=k_t, zeta_t=0.05, **sec)
    arm = ArmDynamics(I=m * L**2, k_t=k * L**2, M_pl=Fpl * L, c_t=c * L**2)
    rsec = dict(I2=m2 * L**2, K2=k2 * L**2, zeta2=0.04) if two else {}
    return tr, arm_train(arm, L, K_t=k_t * L**2, zeta_t=0.05, **rsec)


def _limit_error(L, two, e=0.004, h=0.006):
    """Largest relative difference of the normal contact force, arm (pivot placed so that the roller
    path is tangent to the translating axis x = e at the base circle) against translating."""
    th = np.linspace(0.0, 2.0 * math.pi, 721)
    a = math.hypot(e + L, math.sqrt((Rb + Rr)**2 - e**2))
    dt, do = _program(h).derivatives(th), _program(h / L).derivatives(th)
    pt = cam_profile(RollerFollower(Rb=Rb, Rr=Rr, e=e), th, dt.s, dt.s1, dt.s2)
    po = oscillating_profile(OscillatingRollerFollower(Rb=Rb, Rr=Rr, a=a, L=L), th, do.s, do.s1, do.s2)
    tr, ar = _trains(L, two)
    Ft = periodic_response(tr, _program(h), W).load_result(th, pt.phi).Fc
    # the arm's program holds the roller centre's arc travel L psi (m), as a scene's does
    Fo = periodic_response(ar, _program(h), W).load_result(th, po.phi).Fc
    jt = jump_speed(tr, _program(h), 500.0, 6000.0, n_scan=12).rpm_jump
    jo = jump_speed(ar, _program(h), 500.0, 6000.0, n_scan=12).rpm_jump
    return float(np.max(np.abs(Fo - Ft) / Ft)), abs(jo / jt - 1.0)


@pytest.mark.parametrize("two", [False, True], ids=["one_dof", "two_dof"])
def test_long_arm_limit_is_the_translating_train(two):
    """The referral along the arc is exact; the arm's geometry enters through phi only, whose
    departure from the translating one is O(h/L): the force error shrinks ~1/L. The jump speed
    (where the path force vanishes, whatever phi) matches at every L."""
    f1, j1 = _limit_error(0.5, two)
    f2, j2 = _limit_error(5.0, two)
    assert f1 < 0.02, f"L = 0.5 m: Fc differs by {f1:.3g}"
    assert 7.0 < f1 / f2 < 13.0, f"Fc error {f1:.3g} -> {f2:.3g} for a tenfold arm: not O(1/L)"
    assert j1 < 1e-6 and j2 < 1e-6, (j1, j2)


@pytest.mark.slow
def test_rotational_ode_reference():
    """A 35 mm arm in rotational coordinates, I psi_x'' = M_c - k_psi psi_x - M_pl - c_psi psi_x',
    M_c = K_t (psi - psi_x) + C_t (psi' - psi_x'), integrated by DOP853 over one revolution from
    femcam's periodic start: the contact moment / L equals femcam's path force, and the state
    returns to its start (periodicity, independent of femcam's solve)."""
    from scipy.integrate import solve_ivp

    L, lift = 0.035, math.radians(12.0)
    arm = ArmDynamics(I=2.5e-4, k_t=100.0, M_pl=12.5, c_t=0.002)
    K_t, C_t = 2.0e4, 0.8
    prog_psi = _program(lift)                              # psi (rad)
    prog_arc = _program(lift * L)                          # L psi (m), what femcam integrates
    r = periodic_response(arm_train(arm, L, K_t=K_t, C_t=C_t), prog_arc, W, steps_per_rev=7200)

    def rhs(t, y):
        d = prog_psi.derivatives(np.array([W * t]))
        Mc = K_t * (d.s[0] - y[0]) + C_t * (W * d.s1[0] - y[1])
        return [y[1], (Mc - arm.k_t * y[0] - arm.M_pl - arm.c_t * y[1]) / arm.I]

    y0 = [(r.s[0] + r.e[0, 0]) / L, (r.v[0] + r.ed[0, 0]) / L]
    t = r.theta / W
    sol = solve_ivp(rhs, (0.0, t[-1]), y0, method="DOP853", t_eval=t, rtol=1e-11, atol=1e-14,
                    max_step=t[1] * 20)
    d = prog_psi.derivatives(r.theta)
    Mc = K_t * (d.s - sol.y[0]) + C_t * (W * d.s1 - sol.y[1])
    scale = float(np.max(r.Fc_axial))
    # femcam's first-order hold is O(h^2): 7200 steps give ~1e-6 of the peak
    np.testing.assert_allclose(r.Fc_axial, Mc / L, rtol=0, atol=2e-5 * scale,
                               err_msg="path force vs the rotational ODE's contact moment / L")
    assert abs(sol.y[0, -1] - y0[0]) < 1e-6 * lift, "not periodic in the rotational ODE"


def test_power_balance_elastic_and_rigid():
    """Cam torque x omega, from the profile's contact point and normal and the normal force, equals
    the power into the arm's train end M_c psi' = (d/dt)(kinetic + spring + train energy) +
    damping losses: pointwise (psi_x'' from the arm's equation of motion) to round-off, and over the
    periodic cycle (energy returns) to the quadrature error."""
    L, lift = 0.035, math.radians(12.0)
    f = OscillatingRollerFollower(Rb=Rb, Rr=Rr, a=0.05, L=L, sigma=-1)
    arm = ArmDynamics(I=2.5e-4, k_t=100.0, M_pl=12.5, c_t=0.002)
    K_t, C_t = 2.0e4, 0.8
    r = periodic_response(arm_train(arm, L, K_t=K_t, C_t=C_t), _program(lift * L), W)
    th = r.theta
    d = _program(lift).derivatives(th)
    p = oscillating_profile(f, th, d.s, d.s1, d.s2)
    Fc = r.load_result(th, p.phi).Fc
    nx, ny = (p.pitch_x - p.x) / Rr, (p.pitch_y - p.y) / Rr
    torque = Fc * (p.x * ny - p.y * nx)
    px, pxd = (r.s + r.e[:, 0]) / L, (r.v + r.ed[:, 0]) / L      # arm angle and rate (rad, rad/s)
    pc, pcd = d.s, W * d.s1                                       # the cam-imposed angle and rate
    Mc = K_t * (pc - px) + C_t * (pcd - pxd)
    pxdd = (Mc - arm.k_t * px - arm.M_pl - arm.c_t * pxd) / arm.I
    dE = (arm.I * pxdd * pxd + (arm.k_t * px + arm.M_pl) * pxd + K_t * (pc - px) * (pcd - pxd))
    loss = arm.c_t * pxd**2 + C_t * (pcd - pxd)**2
    peak = float(np.max(np.abs(Mc * pcd)))
    assert peak > 1.0
    np.testing.assert_allclose(torque * W, dE + loss, rtol=0, atol=1e-11 * peak)
    cycle_in = np.trapezoid(torque * W, r.t)
    assert abs(cycle_in - np.trapezoid(loss, r.t)) < 1e-4 * np.trapezoid(np.abs(torque * W), r.t)
    # rigid arm (K_t -> inf): the same torque identity with psi_x = psi
    Fr = r.Fc_rigid_axial / np.cos(p.phi)
    arm_power = (arm.I * W**2 * d.s2 + arm.c_t * pcd + arm.k_t * pc + arm.M_pl) * pcd
    np.testing.assert_allclose(Fr * (p.x * ny - p.y * nx) * W, arm_power, rtol=0, atol=1e-11 * peak)


def _cycloid_jump_rpm(I, k_psi, M_pl, Psi, beta):
    """Closed form: Fc = 0 first where I w^2 psi'' + k_psi psi + M_pl = 0 (no damping). On the
    cycloidal rise psi = Psi (u - sin(2 pi u)/(2 pi)), psi'' = 2 pi Psi sin(2 pi u)/beta^2 < 0 for
    u in (1/2, 1): w^2 = min_u (k_psi psi + M_pl)/(-I psi''). The fall mirrors it (same minimum)."""
    from scipy.optimize import minimize_scalar

    def w2(u):
        psi = Psi * (u - math.sin(2 * math.pi * u) / (2 * math.pi))
        return (k_psi * psi + M_pl) / (-I * 2 * math.pi * Psi * math.sin(2 * math.pi * u) / beta**2)

    res = minimize_scalar(w2, bounds=(0.5 + 1e-9, 1 - 1e-9), method="bounded", options={"xatol": 1e-12})
    return math.sqrt(res.fun) * 30.0 / math.pi


def test_jump_speed_rigid_and_stiff_elastic_match_the_closed_form():
    L, Psi, beta = 0.035, math.radians(10.0), 1.6
    arm = ArmDynamics(I=2.5e-4, k_t=100.0, M_pl=2.0)
    ref = _cycloid_jump_rpm(arm.I, arm.k_t, arm.M_pl, Psi, beta)
    prog = _program(Psi * L)                                     # arc travel, as in a scene
    rigid = rigid_jump_speed(arm_follower(arm, L), prog, 500.0, 20000.0, n=20000)
    assert abs(rigid / ref - 1) < 0.005, (rigid, ref)
    # a stiff, lightly damped train jumps at the rigid speed
    j = jump_speed(arm_train(arm, L, K_t=1e6, zeta_t=0.05), prog, 500.0, 6000.0, n_scan=12)
    assert abs(j.rpm_jump / ref - 1) < 0.005, (j.rpm_jump, ref)


def test_lever_spring_is_k_l2_and_the_scene_reads_it(monkeypatch):
    """40 N/mm, 250 N at 50 mm is the example's torsional 100 N m/rad, 12.5 N m: the same forces."""
    assert lever_spring(40e3, 0.05, 250.0) == pytest.approx((100.0, 12.5), rel=1e-15)
    th = np.radians(np.arange(0.0, 360.0, 5.0))
    b = load_scene(EXAMPLE).analyse(th).Fc             # before the reader is replaced
    raw = tomllib.loads(EXAMPLE.read_text(encoding="utf-8"))
    for key in ("spring_rate_N_m_per_rad", "preload_N_m"):
        del raw["dynamics"][key]
    raw["dynamics"].update(spring_N_per_m=40e3, preload_N=250.0, spring_lever_mm=50.0)
    monkeypatch.setattr(scene_load, "_read_toml", lambda path: raw)
    sc = load_scene("lever.toml")
    assert (sc.dynamics.k_t, sc.dynamics.M_pl) == pytest.approx((100.0, 12.5), rel=1e-15)
    np.testing.assert_allclose(sc.analyse(th).Fc, b, rtol=1e-13)


def _elastic(**kw):
    def change(raw):
        raw["dynamics"].update(model="one_dof", train_stiffness_N_m_per_rad=2.0e4, train_damping_ratio=0.05)
        raw["dynamics"].update(kw)
    return change


def test_elastic_scene_follows_the_rigid_arm_when_stiff(monkeypatch):
    """The example with a stiff train (1e8 N m/rad): Scene.analyse gives the rigid moment balance
    times k_t/(k_t + k_s) in dwells (the return spring sits at x, docs/dynamics.md) within 1e-4."""
    th = np.radians(np.arange(0.0, 360.0, 2.0))
    rig = load_scene(EXAMPLE).analyse(th).Fc           # before the reader is replaced
    raw = tomllib.loads(EXAMPLE.read_text(encoding="utf-8"))
    _elastic(train_stiffness_N_m_per_rad=1e8, train_damping_ratio=0.3)(raw)
    monkeypatch.setattr(scene_load, "_read_toml", lambda path: raw)
    sc = load_scene("stiff.toml")
    assert sc.train is not None and sc.train.model == "one_dof"
    np.testing.assert_allclose(sc.analyse(th).Fc, rig, rtol=1e-4)


@pytest.fixture
def load_raw(monkeypatch):
    def load(change):
        raw = tomllib.loads(EXAMPLE.read_text(encoding="utf-8"))
        change(raw)
        monkeypatch.setattr(scene_load, "_read_toml", lambda path: raw)
        return load_scene("arm.toml")
    return load


def _both_springs(raw):
    raw["dynamics"].update(spring_N_per_m=40e3, preload_N=250.0, spring_lever_mm=50.0)


def _no_lever(raw):
    for key in ("spring_rate_N_m_per_rad", "preload_N_m"):
        del raw["dynamics"][key]
    raw["dynamics"].update(spring_N_per_m=40e3, preload_N=250.0)


@pytest.mark.parametrize("change, pattern", [
    (_both_springs, r"dynamics.spring_lever_mm = 50.0 mm: give the arm's spring either as torsional"),
    (_no_lever, r"dynamics.spring_lever_mm.*missing required key.*\(unit: mm\)"),
    (_elastic(train_stiffness_N_per_m=2e6), r"dynamics.train_stiffness_N_per_m = 2000000.0 N/m: a "
     r"translating train's key; .*train_stiffness_N_m_per_rad \(N m/rad\)"),
    (_elastic(model="two_dof"), r"dynamics.second_inertia_kg_m2.*missing required key for model = "
     r"'two_dof'.*\(unit: kg m\^2\)"),
    (_elastic(train_stiffness_N_m_per_rad=-5.0), r"dynamics.train_stiffness_N_m_per_rad = -5.0 N m/rad"),
    (_elastic(spring_lever_mm=50.0), r"dynamics.spring_lever_mm = 50.0 mm"),
    (_elastic(arm_inertia_kg_m2=0.0), r"dynamics.arm_inertia_kg_m2 = 0.0 kg m\^2, model = 'one_dof'"),
    (_elastic(train_damping_N_m_s_per_rad=0.5), r"give exactly one of train_damping_ratio "
     r"\(dimensionless\) or train_damping_N_m_s_per_rad \(N m s/rad\)"),
])
def test_scene_refusals_name_key_value_and_unit(load_raw, change, pattern):
    with pytest.raises(SceneError, match=pattern):
        load_raw(change)


def test_api_refusals():
    arm = ArmDynamics(I=2.5e-4, k_t=100.0, M_pl=12.5)
    with pytest.raises(InputError, match=r"K_t = -1\.?0? N m/rad"):
        arm_train(arm, 0.035, K_t=-1.0, zeta_t=0.05)
    with pytest.raises(InputError, match=r"I2 = None kg m\^2"):
        arm_train(arm, 0.035, K_t=1e4, zeta_t=0.05, K2=1e4, zeta2=0.1)
    with pytest.raises(InputError, match=r"lever = 0(\.0)? m"):
        lever_spring(40e3, 0.0, 250.0)
    with pytest.raises(InputError, match=r"rpm_hi = 100(\.0)? rpm: must be > rpm_lo"):
        rigid_jump_speed(arm_follower(arm, 0.035), _program(0.001), 200.0, 100.0)


def test_femcam_run_prints_the_rigid_arm_jump_speed(tmp_path, capsys):
    """The example's arm (I = 2.5e-4 kg m^2, 100 N m/rad, 12.5 N m, 10 deg cycloidal rise over
    65 deg): the summary line against the closed form."""
    from femcam.cli import main

    assert main(["run", str(EXAMPLE), "--out", str(tmp_path / "run"), "--no-plots"]) == 0
    line = next(ln for ln in capsys.readouterr().out.splitlines() if "jump speed" in ln)
    rpm = float(line.split("=")[1].split("rpm")[0])
    ref = _cycloid_jump_rpm(2.5e-4, 100.0, 12.5, math.radians(10.0), math.radians(65.0))
    assert abs(rpm / ref - 1) < 0.005, (line, ref)
    # a curved pad on the same arm: the contact force is the arm's moment over a lever that stays
    # positive (self-locking is refused), so it reaches zero where the moment does: the same speed
    pad = EXAMPLE.read_text(encoding="utf-8").replace('type = "roller"', 'type = "curved_pad"')
    pad = pad.replace("roller_radius_mm = 9.0", "pad_radius_mm = 12.0")
    (tmp_path / "pad.toml").write_text(pad, encoding="utf-8")
    assert main(["run", str(tmp_path / "pad.toml"), "--out", str(tmp_path / "pad"), "--no-plots"]) == 0
    line = next(ln for ln in capsys.readouterr().out.splitlines() if "jump speed" in ln)
    assert abs(float(line.split("=")[1].split("rpm")[0]) / ref - 1) < 0.005, (line, ref)


def test_two_dof_stiff_scene_is_the_rigid_arm_with_both_inertias(monkeypatch):
    """Stiff train and stiff coupling (1e8 N m/rad): the two_dof arm moves as one rigid arm of
    inertia I + I2 (femcam.loads.arm_contact_force with the sum), within 1e-4 of Fc."""
    from femcam.loads import arm_contact_force

    raw = tomllib.loads(EXAMPLE.read_text(encoding="utf-8"))
    _elastic(model="two_dof", train_stiffness_N_m_per_rad=1e8, train_damping_ratio=0.3,
             second_inertia_kg_m2=2e-5, second_stiffness_N_m_per_rad=1e8, second_damping_ratio=0.3)(raw)
    monkeypatch.setattr(scene_load, "_read_toml", lambda path: raw)
    sc = load_scene("two.toml")
    th = np.radians(np.arange(0.0, 360.0, 2.0))
    st = sc.analyse(th)
    L, w = sc.follower.L, sc.omega
    d = sc.program.derivatives(th)
    arm = ArmDynamics(I=2.5e-4 + 2e-5, k_t=100.0, M_pl=12.5)
    ref = arm_contact_force(arm, th, d.s / L, w * d.s1 / L, w**2 * d.s2 / L, L, st.phi).Fc
    assert sc.train.model == "two_dof"
    np.testing.assert_allclose(st.Fc, ref, rtol=1e-4)


def test_elastic_arm_feeds_the_sweep_and_femcam_dynamics(monkeypatch, tmp_path, capsys):
    """The Hertz sweep's Fc column is Scene.analyse's dynamic force; `femcam dynamics` prints the
    arm's natural frequency sqrt((K_t + k_psi)/I)/(2 pi) (closed form of the one_dof arm)."""
    from femcam.cli import main
    from femcam.sweep import SweepOptions, sweep

    text = EXAMPLE.read_text(encoding="utf-8").replace(
        "damping_N_m_s_per_rad = 0.0", 'damping_N_m_s_per_rad = 0.0\nmodel = "one_dof"\n'
        "train_stiffness_N_m_per_rad = 2.0e4\ntrain_damping_ratio = 0.05")
    path = tmp_path / "elastic.toml"
    path.write_text(text, encoding="utf-8")
    sc = load_scene(path)
    th = np.radians([0.0, 20.0, 60.0, 120.0])
    r = sweep(sc, SweepOptions(angles=th, method="hertz"))
    np.testing.assert_allclose(r.table["Fc"], sc.analyse(th).Fc, rtol=1e-12)
    assert main(["dynamics", str(path), "--out", str(tmp_path / "dyn"), "--no-plots"]) == 0
    out = capsys.readouterr().out
    f_ref = math.sqrt((2.0e4 + 100.0) / 2.5e-4) / (2 * math.pi)        # 1427.08 Hz
    f_printed = float(out.split("natural frequencies ")[1].split(" Hz")[0])
    assert abs(f_printed / f_ref - 1) < 1e-4, (f_printed, f_ref)


def test_lever_spring_linearisation_error():
    """What lever_spring models: the first-order term of the exact moment of a spring whose end
    moves on a fixed line perpendicular to the arm at psi = 0, (F + k l sin psi) l cos psi. The
    difference tends to F l psi^2/2 + (2/3) k l^2 psi^3 (Taylor, written here); at the example's
    10 deg swing 0.54 N m, 1.8 % of the moment at full lift (docs/oscillating.md)."""
    k, l, F = 40e3, 0.05, 250.0
    k_psi, M_pl = lever_spring(k, l, F)
    psi = np.radians([10.0, 5.0, 2.5, 1.25])
    lin = M_pl + k_psi * psi
    err = lin - (F + k * l * np.sin(psi)) * l * np.cos(psi)
    taylor = F * l * psi**2 / 2 + 2.0 / 3.0 * k * l**2 * psi**3
    ratio = err / taylor
    assert abs(ratio[-1] - 1) < 0.01 and abs(ratio[0] - 1) < 0.1, ratio
    assert abs(err[0] / lin[0] - 0.018) < 0.001, err[0] / lin[0]
