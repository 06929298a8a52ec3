"""Follower-train dynamics (femcam.dynamics): closed-form references typed in each test.

References: Duhamel's integral for the undamped oscillator driven by the cam acceleration
(Koster 1974; Norton 2009 ch. 10), the free vibration of 1- and 2-DOF systems, energy balance,
seed 002 eq. 11 (rigid follower) in the stiff-train limit, and the rigid lift-off speed.
"""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from femcam.dynamics import TrainModel, jump_speed, periodic_response, rpm_sweep, simulate
from femcam.errors import InputError, SceneError
from femcam.kinematics import CamProgram, dwell, fall, rise
from femcam.loads import FollowerDynamics, contact_force
from femcam.scene import load_scene

H = 0.01  # lift (m)
RPM60 = 2.0 * math.pi  # omega = 2 pi rad/s: one revolution per second


def _program(law="cycloidal", beta_deg=90.0):
    b = math.radians(beta_deg)
    rest = (2.0 * math.pi - 2.0 * b) / 2.0
    return CamProgram([rise(b, H, law), dwell(rest), fall(b, H, law), dwell(rest)])


def _train(m=1.0, k_s=0.0, Fpl=1e5, c_s=0.0, k_t=1e4, zeta_t=0.0, **kw):
    return TrainModel(follower=FollowerDynamics(m=m, k=k_s, Fpl=Fpl, c=c_s), k_t=k_t, zeta_t=zeta_t, **kw)


# ------------------------------------------------------------------------------------------
# residual vibration after a rise: Duhamel's integral in closed form
# ------------------------------------------------------------------------------------------
def _cycloid_residual(r):
    """A/h after a cycloidal rise of duration T = r T_n (undamped, from rest), derived by
    Duhamel: A = |int_0^T a e^{-i w t} dt|/w with a = (2 pi h/T^2) sin(2 pi t/T)."""
    return abs(math.sin(math.pi * r)) / (math.pi * r * abs(r * r - 1.0))


def _poly345_integral(w, T):
    """I = int_0^T a(t) e^{-i w t} dt for the 3-4-5 rise a = h/T^2 (60u - 180u^2 + 120u^3),
    by repeated integration by parts (a is a cubic: four terms, exact)."""
    p = -1j * w
    d0 = [0.0, 60 * H / T**3, -360 * H / T**4, 720 * H / T**5]  # a, a', a'', a''' at t = 0
    d1 = [0.0, 60 * H / T**3, 360 * H / T**4, 720 * H / T**5]  # ... at t = T
    return sum((-1) ** k * (np.exp(p * T) * d1[k] - d0[k]) / p ** (k + 1) for k in range(4))


def _residual_amplitude(law, r, beta_deg=90.0, N=3600):
    T_r = math.radians(beta_deg) / RPM60
    w = 2.0 * math.pi * r / T_r
    tm = _train(k_t=w**2)  # m = 1 kg, k_s = 0: w_n^2 = k_t/m
    e_st = -1e5 / w**2  # static compression by the preload
    theta, Z, C, F = simulate(tm, _program(law, beta_deg), RPM60, z0=[e_st, 0.0], steps_per_rev=N)
    i = np.searchsorted(theta, math.pi - 1e-9)  # end of the top dwell (rise 90 + dwell 90 deg)
    assert C.all()
    return math.hypot(Z[i, 0] - e_st, Z[i, 1] / w), w, T_r, theta[i], Z[i, 0] - e_st


@pytest.mark.parametrize("r", [0.7, 1.5, 2.3, 3.6, 5.2])
def test_cycloidal_residual_vibration_matches_closed_form(r):
    A, *_ = _residual_amplitude("cycloidal", r)
    np.testing.assert_allclose(A / H, _cycloid_residual(r), rtol=1e-4, atol=1e-7,
                               err_msg="Duhamel closed form |sin(pi r)|/(pi r |r^2-1|)")


@pytest.mark.parametrize("r", [0.8, 1.7, 2.5, 4.1])
def test_poly345_residual_vibration_matches_closed_form(r):
    A, w, T_r, *_ = _residual_amplitude("poly345", r)
    ref = abs(_poly345_integral(w, T_r)) / w
    np.testing.assert_allclose(A, ref, rtol=1e-4, atol=1e-10, err_msg="Duhamel, 3-4-5 rise")


def test_time_step_convergence_is_second_order():
    """e(t) in the dwell against Duhamel's closed form e = -(1/w) Im(e^{iwt} I)."""
    r = 2.3
    errs, hs = [], []
    for N in (360, 720, 1440, 2880):
        _, w, T_r, t_deg, de = _residual_amplitude("cycloidal", r, N=N)
        t = t_deg / RPM60
        nu = 2 * math.pi / T_r
        I = (2 * math.pi * H / T_r**2) * nu * (1 - np.exp(-1j * w * T_r)) / (nu**2 - w**2)
        errs.append(abs(de - (-(np.exp(1j * w * t) * I).imag / w)))
        hs.append(1.0 / N)
    order = np.polyfit(np.log(hs), np.log(errs), 1)[0]
    assert 1.8 < order < 2.3, f"observed order {order:.3f}, errors {errs}"
    assert errs[-1] < 1e-6 * H


# ------------------------------------------------------------------------------------------
# free vibration
# ------------------------------------------------------------------------------------------
def _dwell_first():
    return CamProgram([dwell(math.pi), rise(math.pi / 2, H), fall(math.pi / 2, H)])


@pytest.mark.parametrize("zeta", [0.0, 0.1])
def test_free_vibration_frequency(zeta):
    m, k_s, k_t, Fpl = 0.5, 500.0, 4.0e4, 200.0
    tm = TrainModel(follower=FollowerDynamics(m=m, k=k_s, Fpl=Fpl, c=0.0), k_t=k_t, zeta_t=zeta)
    wn = math.sqrt((k_t + k_s) / m)
    c = zeta * 2 * math.sqrt(k_t * m)
    wd = wn * math.sqrt(1 - (c / (2 * m * wn)) ** 2)
    e_st = -Fpl / (k_t + k_s)
    theta, Z, C, _ = simulate(tm, _dwell_first(), RPM60, z0=[e_st + 1e-4, 0.0], steps_per_rev=7200)
    dw = theta < math.pi
    y, t = Z[dw, 0] - e_st, theta[dw] / RPM60
    k = np.flatnonzero(np.sign(y[:-1]) != np.sign(y[1:]))
    tz = t[k] - y[k] * (t[k + 1] - t[k]) / (y[k + 1] - y[k])  # zero crossings (linear)
    half = np.diff(tz).mean()
    np.testing.assert_allclose(half, math.pi / wd, rtol=2e-5, err_msg="half period pi/w_d")
    np.testing.assert_allclose(tm.natural_frequencies[0], wn, rtol=1e-12)


def test_critically_damped_free_vibration_defective_system():
    """zeta = 1 makes the state matrix defective (one double eigenvalue): the Van Loan path.
    Closed form: e - e_st = d0 (1 + w t) exp(-w t) from rest."""
    m, k_t, Fpl = 0.5, 4.0e4, 200.0
    w = math.sqrt(k_t / m)
    tm = TrainModel(follower=FollowerDynamics(m=m, k=0.0, Fpl=Fpl, c=0.0), k_t=k_t, zeta_t=1.0)
    e_st, d0 = -Fpl / k_t, 1e-4
    theta, Z, C, _ = simulate(tm, _dwell_first(), RPM60, z0=[e_st + d0, 0.0], steps_per_rev=3600)
    t = theta[theta < math.pi] / RPM60
    ref = d0 * (1 + w * t) * np.exp(-w * t)
    np.testing.assert_allclose(Z[: t.size, 0] - e_st, ref, rtol=0, atol=1e-10 * d0,
                               err_msg="critically damped oscillator")


def test_two_dof_natural_frequencies():
    m1, m2, k_t, k2, k_s = 0.2, 0.1, 2e6, 1e6, 800.0
    tm = _train(m=m1, k_s=k_s, k_t=k_t, m2=m2, k2=k2, zeta2=0.0)
    # det(K - w^2 M) = 0: m1 m2 w^4 - (m1 (k2 + k_s) + m2 (k_t + k2)) w^2 + det K = 0
    b = m1 * (k2 + k_s) + m2 * (k_t + k2)
    detK = (k_t + k2) * (k2 + k_s) - k2**2
    disc = math.sqrt(b * b - 4 * m1 * m2 * detK)
    ref = np.sqrt([(b - disc) / (2 * m1 * m2), (b + disc) / (2 * m1 * m2)])
    np.testing.assert_allclose(tm.natural_frequencies, ref, rtol=1e-12)


# ------------------------------------------------------------------------------------------
# energy balance of the undamped train
# ------------------------------------------------------------------------------------------
def test_energy_balance_undamped_one_cycle():
    m, k_s, k_t, Fpl = 0.3, 1000.0, 3e5, 800.0
    tm = TrainModel(follower=FollowerDynamics(m=m, k=k_s, Fpl=Fpl, c=0.0), k_t=k_t, zeta_t=0.0)
    prog = _program()
    theta, Z, C, F = simulate(tm, prog, 3 * RPM60, z0=[-Fpl / (k_t + k_s), 0.0], steps_per_rev=7200)
    assert C.all()
    d = prog.derivatives(theta)
    s, v = d.s, 3 * RPM60 * d.s1
    x, xd = s + Z[:, 0], v + Z[:, 1]
    E = 0.5 * m * xd**2 + 0.5 * k_t * (s - x) ** 2 + 0.5 * k_s * x**2 + Fpl * x
    P = F * v  # power of the cam on the train
    t = theta / (3 * RPM60)
    W = np.concatenate([[0.0], np.cumsum(0.5 * (P[1:] + P[:-1]) * np.diff(t))])
    scale = np.max(np.abs(W))
    assert np.max(np.abs(E - E[0] - W)) < 1e-5 * scale, "dE = work of the cam (undamped)"


def test_periodic_undamped_cam_work_vanishes():
    tm = _train(m=0.3, k_s=1000.0, Fpl=800.0, k_t=3e5)
    r = periodic_response(tm, _program(), 3 * RPM60, steps_per_rev=7200)
    t = r.theta / r.omega
    W = np.trapezoid(r.Fc_axial * r.v, t)
    assert r.converged and r.residual < 1e-9
    assert abs(W) < 1e-6 * np.trapezoid(np.abs(r.Fc_axial * r.v), t)


# ------------------------------------------------------------------------------------------
# stiff-train limit: seed 002 eq. 11
# ------------------------------------------------------------------------------------------
def _eq11(scene, m):
    d = scene.analyse(np.linspace(0, 2 * math.pi, 721))
    f = scene.dynamics
    return d, (m * d.a + f.c * d.v + f.k * d.s + f.Fpl) / np.cos(d.phi)


@pytest.mark.parametrize("k_t, rtol", [(1e8, 1e-4), (1e12, 1e-7)])
def test_stiff_train_recovers_eq11(k_t, rtol):
    """1e12 N/m with zeta_t = 0.7 is a stiff ODE (w_n h = 63 at 3600 steps, no refinement
    needed: the mode decays by e^-44 per step): the exact integrator stays stable and lands on
    eq. 11 (8e-10 of Fc, run). At 1e8 N/m the train's compliance is still felt: the force
    differs by O((w_rise/w_n)^2) plus ringing at the bezier5 jerk steps, 2.7e-5 of Fc (run)."""
    import dataclasses

    sc = load_scene("examples/seed002_dynamic.toml")
    dyn = dataclasses.replace(sc, train=TrainModel(follower=sc.dynamics, k_t=k_t, zeta_t=0.7))
    d, ref = _eq11(sc, sc.dynamics.m)
    st = dyn.analyse(d.theta)
    np.testing.assert_allclose(st.Fc, ref, rtol=0, atol=rtol * ref.max(), err_msg="seed 002 eq. 11")
    rigid = contact_force(sc.dynamics, d.theta, d.s, d.v, d.a, d.phi)
    np.testing.assert_allclose(rigid.Fc, ref, rtol=1e-12)


def test_two_dof_stiff_limit_uses_total_mass():
    sc = load_scene("examples/seed002_dynamic.toml")
    import dataclasses

    tm = TrainModel(follower=sc.dynamics, k_t=1e12, zeta_t=0.7, m2=0.1, k2=1e12, zeta2=0.7)
    d, ref = _eq11(sc, 0.3)
    st = dataclasses.replace(sc, train=tm).analyse(d.theta)
    np.testing.assert_allclose(st.Fc, ref, rtol=0, atol=1e-6 * ref.max())


# ------------------------------------------------------------------------------------------
# jump: contact loss, free flight, jump speed
# ------------------------------------------------------------------------------------------
def _rigid_liftoff_rpm(m, k, Fpl, beta):
    """min over theta of m w^2 s'' + k s + Fpl = 0 for the cycloidal program (c = 0)."""
    u = np.linspace(0, 1, 20001)
    s = H * (u - np.sin(2 * math.pi * u) / (2 * math.pi))
    s2 = 2 * math.pi * H / beta**2 * np.sin(2 * math.pi * u)  # rise; the fall mirrors it
    s_all, s2_all = np.r_[s, H - s], np.r_[s2, -s2]
    g = lambda w: np.min(m * w**2 * s2_all + k * s_all + Fpl)  # noqa: E731
    return brentq(g, 1.0, 1e4, xtol=1e-12) * 30 / math.pi


def test_jump_speed_stiff_train_matches_rigid_liftoff():
    m, k, Fpl = 0.2, 800.0, 100.0
    prog = _program()
    ref = _rigid_liftoff_rpm(m, k, Fpl, math.pi / 2)
    tm = TrainModel(follower=FollowerDynamics(m=m, k=k, Fpl=Fpl, c=0.0), k_t=1e9, zeta_t=0.7)
    j = jump_speed(tm, prog, 0.5 * ref, 1.5 * ref, n_scan=11)
    np.testing.assert_allclose(j.rpm_jump, ref, rtol=1e-4, err_msg="rigid lift-off speed")
    np.testing.assert_allclose(j.rpm_rigid, ref, rtol=1e-6)
    below = periodic_response(tm, prog, 0.98 * ref / 30 * math.pi)
    above = periodic_response(tm, prog, 1.05 * ref / 30 * math.pi)
    assert not below.any_liftoff and above.any_liftoff and above.converged


def test_two_dof_jump_speed_stiff_limit_uses_total_mass():
    m1, m2, k, Fpl = 0.15, 0.05, 800.0, 100.0
    ref = _rigid_liftoff_rpm(m1 + m2, k, Fpl, math.pi / 2)
    tm = TrainModel(follower=FollowerDynamics(m=m1, k=k, Fpl=Fpl, c=0.0), k_t=1e9, zeta_t=0.7,
                    m2=m2, k2=1e9, zeta2=0.7)
    j = jump_speed(tm, _program(), 0.5 * ref, 1.5 * ref, n_scan=11)
    np.testing.assert_allclose(j.rpm_jump, ref, rtol=1e-4, err_msg="rigid lift-off, m = m1 + m2")
    above = periodic_response(tm, _program(), 1.05 * ref / 30 * math.pi)
    assert above.any_liftoff and above.converged, above.message


def test_free_flight_follows_the_return_spring():
    """During lift-off the mass moves on the return spring alone (closed form, c_s = 0)."""
    m, k, Fpl = 0.2, 800.0, 100.0
    tm = TrainModel(follower=FollowerDynamics(m=m, k=k, Fpl=Fpl, c=0.0), k_t=1e7, zeta_t=0.3)
    prog = _program()
    w_cam = 1.1 * _rigid_liftoff_rpm(m, k, Fpl, math.pi / 2) / 30 * math.pi
    r = periodic_response(tm, prog, w_cam)
    assert r.converged and r.any_liftoff and r.n_events >= 2
    free = np.flatnonzero(~r.contact)
    runs = np.split(free, np.flatnonzero(np.diff(free) > 1) + 1)  # one flight per run
    x, xd, t = r.s + r.e[:, 0], r.v + r.ed[:, 0], r.t
    ws = math.sqrt(k / m)
    for run in runs:
        i0, i1 = run[0], run[-1]
        tau = t[i0:i1 + 1] - t[i0]
        x0, v0 = x[i0] + Fpl / k, xd[i0]
        ref = -Fpl / k + x0 * np.cos(ws * tau) + v0 / ws * np.sin(ws * tau)
        # relative coordinates e = x - s interpolate the cam acceleration linearly over a step,
        # so x carries an O(h^2) error even in flight: 1.6e-8 m at 3600 steps (run)
        np.testing.assert_allclose(x[i0:i1 + 1], ref, rtol=0, atol=5e-6 * H,
                                   err_msg="free flight on the return spring")
    assert np.all(r.Fc_axial[free] == 0.0)
    trial = tm.trial_force(np.column_stack([r.e, r.ed]))  # -k_t e - c_t e' (Kelvin-Voigt train)
    assert np.all(trial[free] <= 0.0), "in flight the train end does not press on the cam"
    assert np.max(x - r.s) > 1e-4 * H, "the follower leaves the cam surface"


def test_rpm_sweep_rows_and_liftoff():
    tm = _train(m=0.2, k_s=800.0, Fpl=100.0, k_t=1e7, zeta_t=0.3)
    ref = _rigid_liftoff_rpm(0.2, 800.0, 100.0, math.pi / 2)
    sw = rpm_sweep(tm, _program(), [0.5 * ref, 0.9 * ref, 1.1 * ref])
    assert list(sw.liftoff) == [False, False, True]
    assert sw.Fc_min[2] == 0.0 and sw.Fc_min[0] > 0.0


# ------------------------------------------------------------------------------------------
# hard cases and bad input
# ------------------------------------------------------------------------------------------
def test_soft_train_that_cannot_follow_is_refused():
    tm = _train(m=1.0, k_s=0.0, k_t=10.0)  # w_n = 3.16 rad/s < cam 6.28 rad/s
    with pytest.raises(InputError, match=r"k_t \(\[dynamics\] train_stiffness_N_per_m\) = 10 N/m.*"
                       r"0\.5033 Hz.*1 Hz.*cannot follow"):
        periodic_response(tm, _program(), RPM60)


def test_unresolved_time_step_is_refused_with_numbers():
    tm = _train(m=0.2, k_t=1e8, zeta_t=0.0)  # 3559 Hz undamped: 0.28 steps per period at 360
    with pytest.raises(InputError, match=r"steps_per_rev = 360: .*3558\.8.* Hz.*steps_per_rev >= "):
        periodic_response(tm, _program(), RPM60, steps_per_rev=360)
    tm = _train(m=0.2, k_t=1e14, zeta_t=0.0)
    with pytest.raises(InputError, match="more than 400000 steps per revolution.*rigid"):
        periodic_response(tm, _program(), RPM60)


def test_undamped_bouncing_is_flagged_not_hidden():
    """Zero damping everywhere and a weak spring well above the jump speed: the impacts are
    elastic and nothing removes energy, so there is no attracting one-periodic motion; the
    result says so (converged False, with the reason) instead of returning the last cycle."""
    tm = _train(m=0.2, k_s=800.0, Fpl=100.0, k_t=1e6, zeta_t=0.0)
    r = periodic_response(tm, _program(), 1.6 * _rigid_liftoff_rpm(0.2, 800, 100, math.pi / 2)
                          / 30 * math.pi, max_cycles=60)
    assert r.any_liftoff
    assert not r.converged and ("unstable" in r.message or "not periodic" in r.message)


def test_counts_are_whole_numbers_never_truncated():
    """workers = 0.5 passed the > 0 check and became 0 (a raw ProcessPoolExecutor ValueError);
    n_scan = 2.5 and cycles = 1.5 were silently truncated."""
    tm, prog = _train(m=0.2, k_s=800.0, Fpl=100.0, k_t=1e6, zeta_t=0.3), _program()
    with pytest.raises(InputError, match=r"workers = 0\.5: must be a whole number >= 1"):
        rpm_sweep(tm, prog, [60.0], workers=0.5)
    with pytest.raises(InputError, match=r"n_scan = 2\.5: must be a whole number >= 1"):
        jump_speed(tm, prog, 60.0, 120.0, n_scan=2.5)
    with pytest.raises(InputError, match=r"cycles = 1\.5: must be a whole number >= 1"):
        simulate(tm, prog, RPM60, cycles=1.5)


def test_simulate_checks_its_inputs_like_periodic_response():
    tm, prog = _train(m=0.2, k_s=800.0, Fpl=100.0, k_t=1e6, zeta_t=0.3), _program()
    with pytest.raises(InputError, match="train = 'x': must be a TrainModel"):
        simulate("x", prog, RPM60)
    with pytest.raises(InputError, match="program = 3: must be a CamProgram"):
        simulate(tm, 3, RPM60)
    with pytest.raises(InputError, match=r"z0 = .*must have shape \(2,\).*got shape \(3,\)"):
        simulate(tm, prog, RPM60, z0=[0.0, 0.0, 0.0])
    with pytest.raises(InputError, match="z0 = .*must be finite"):
        simulate(tm, prog, RPM60, z0=[float("nan"), 0.0])
    # a valid z0 at rest is the default start: the same response (reference: z0 = None)
    a, b = simulate(tm, prog, RPM60, z0=[0.0, 0.0])[1], simulate(tm, prog, RPM60)[1]
    assert np.array_equal(a, b)


def test_cli_dynamics_workers_capped_at_cores_and_speeds():
    import os

    from femcam.cli.dynamics import _useful_workers

    cap = min(os.cpu_count() or 1, 3)  # 3 speeds
    assert _useful_workers(64, 3) == (cap, f"--workers 64 capped at {cap} (the useful number: "
                                           f"{os.cpu_count() or 1} CPU cores, 3 speeds)")
    assert _useful_workers(1, 3) == (1, "")


def test_train_input_errors():
    f = FollowerDynamics(m=0.2, k=800.0, Fpl=100.0, c=0.0)
    with pytest.raises(InputError, match="k_t = -1 N/m: must be > 0"):
        TrainModel(follower=f, k_t=-1.0, zeta_t=0.1)
    with pytest.raises(InputError, match="exactly one"):
        TrainModel(follower=f, k_t=1e6)
    with pytest.raises(InputError, match="give m2"):
        TrainModel(follower=f, k_t=1e6, zeta_t=0.1, k2=1e6)
    with pytest.raises(InputError, match="m \\(follower mass\\) = 0 kg"):
        TrainModel(follower=FollowerDynamics(m=0.0, k=1.0, Fpl=1.0, c=0.0), k_t=1e6, zeta_t=0.1)


# ------------------------------------------------------------------------------------------
# scene integration
# ------------------------------------------------------------------------------------------
SCENE = open("examples/seed002_dynamic.toml").read()


def _scene(tmp_path, old, new):
    assert old in SCENE
    p = tmp_path / "s.toml"
    p.write_text(SCENE.replace(old, new))
    return p


def test_scene_dynamic_force_reaches_analyse():
    sc = load_scene("examples/seed002_dynamic.toml")
    res = sc.dynamic_response
    th = res.theta[::90]
    st = sc.analyse(th)
    np.testing.assert_allclose(st.Fc * np.cos(st.phi), res.Fc_axial[::90], rtol=1e-12)
    assert res.converged and res.message.startswith("linear periodic")
    assert sc.analyse(th).Fc is not None and sc.dynamic_response is res  # cached


@pytest.mark.parametrize("old, new, msg", [
    ('model = "one_dof"', 'model = "one_dff"', "dynamics.model = 'one_dff': must be one of"),
    ('model = "one_dof"', 'model = "rigid"', "train_stiffness_N_per_m = 2000000.0: not used by model"),
    ('train_damping_ratio = 0.05', 'train_damping_ratio = 0.05\ntrain_damping_N_s_per_m = 1.0',
     "exactly one of train_damping_ratio"),
    ('train_stiffness_N_per_m = 2.0e6', 'train_stiffness_N_per_m = -2.0e6', "must be > 0"),
    ('model = "one_dof"', 'model = "two_dof"', "second_mass_kg: missing required key for model"),
    ('model = "one_dof"', 'model = "one_dof"\nsteps_per_rev = 3600.5', "must be a whole number"),
    ('model = "one_dof"', 'model = "one_dof"\nsecond_mass_kg = 0.1', "not used by model = 'one_dof'"),
    ('model = "one_dof"', 'model = "rigid"\nsteps_per_rev = 7200', "steps_per_rev = 7200: not used"),
])
def test_scene_dynamics_bad_input(tmp_path, old, new, msg):
    with pytest.raises(SceneError, match=msg):
        load_scene(_scene(tmp_path, old, new))


def test_scene_two_dof_and_liftoff_rows(tmp_path):
    p = _scene(tmp_path, 'model = "one_dof"', 'model = "two_dof"\nsecond_mass_kg = 0.1\n'
               'second_stiffness_N_per_m = 1.0e6\nsecond_damping_ratio = 0.05')
    sc = load_scene(p)
    assert sc.train.model == "two_dof" and sc.dynamic_response.converged
    weak = load_scene(_scene(tmp_path, "rpm = 600.0 ", "rpm = 4600.0"))  # jump ~4402 rpm
    st = weak.analyse(np.linspace(0, 2 * math.pi, 361))
    assert st.liftoff.any() and np.all(st.Fc[st.liftoff] <= 0.0)
    assert st.loads.liftoff_intervals


def test_cli_dynamics_writes_csv_and_plots(tmp_path, capsys):
    from femcam.cli import main

    out = tmp_path / "dyn"
    assert main(["dynamics", "examples/seed002_dynamic.toml", "--out", str(out),
                 "--rpm-sweep", "4200:4600:200", "--no-plots"]) == 0
    text = capsys.readouterr().out
    assert "503.39 Hz" in text and "contact lost from 44" in text  # sqrt(2000800/0.2)/(2 pi)
    rows = [r for r in (out / "rpm_sweep.csv").read_text().splitlines() if not r.startswith("#")]
    assert rows[0].startswith("rpm,Fc_max_N,Fc_min_N") and len(rows) == 4
    lines = [r for r in (out / "dynamics.csv").read_text().splitlines() if not r.startswith("#")]
    assert lines[0] == "theta_deg,s_mm,Fc_rigid_N,Fc_N,liftoff,error_mass1_um" and len(lines) == 3601
    assert main(["dynamics", "examples/seed002_study_model.toml", "--out", str(out)]) == 1
    assert "model = 'rigid' (eq. 11) has no train" in capsys.readouterr().err


@pytest.mark.slow
def test_cli_dynamics_plots(tmp_path):
    from femcam.cli import main

    out = tmp_path / "dyn"
    assert main(["dynamics", "examples/seed002_dynamic.toml", "--out", str(out),
                 "--rpm-sweep", "4200:4600:200"]) == 0
    assert (out / "dynamics_force.png").stat().st_size > 10_000
    assert (out / "rpm_sweep.png").stat().st_size > 10_000


@pytest.mark.slow
def test_hertz_sweep_takes_the_dynamic_force_and_liftoff_rows(tmp_path):
    """The sweep reads Fc through Scene.analyse: at 4600 rpm (above the 4402 rpm jump speed)
    its rows in free flight are 'liftoff' and the others carry the dynamic force."""
    from femcam.cli import main

    p = _scene(tmp_path, "rpm = 600.0 ", "rpm = 4600.0")
    out = tmp_path / "sw"
    assert main(["sweep", str(p), "--method", "hertz", "--angles-deg", "200:222:2", "--out", str(out),
                 "--no-plots", "--workers", "1", "--vtk-every", "0", "--progress", "off"]) == 0
    lines = [r.split(",") for r in (out / "sweep.csv").read_text().splitlines() if not r.startswith("#")]
    head, rows = lines[0], lines[1:]
    th = np.radians([float(r[head.index("theta_deg")]) for r in rows])
    status = [r[head.index("status")] for r in rows]
    res = load_scene(p).dynamic_response
    free = res.at(th) <= 0.0
    assert free.any() and (~free).any()
    assert [s == "liftoff" for s in status] == list(free)
    Fc = np.array([float(r[head.index("Fc_N")]) for r in rows])
    st = load_scene(p).analyse(th)
    np.testing.assert_allclose(Fc[~free], st.Fc[~free], rtol=1e-6)


def _cycloid_program_s(theta):
    """s, ds/dtheta of _program() (cycloidal rise 90, dwell 90, fall 90, dwell 90 deg), typed in."""
    b = math.pi / 2
    t = np.mod(theta, 2 * math.pi)
    u = np.clip(t / b, 0, 1)
    uf = np.clip((t - math.pi) / b, 0, 1)
    cyc = lambda x: H * (x - np.sin(2 * math.pi * x) / (2 * math.pi))  # noqa: E731
    cyc1 = lambda x: H / b * (1 - np.cos(2 * math.pi * x))  # noqa: E731
    rise_s, rise_v, fall_s, fall_v = cyc(u), cyc1(u), cyc(uf), cyc1(uf)
    s = np.where(t < b, rise_s, np.where(t < math.pi, H, np.where(t < math.pi + b, H - fall_s, 0.0)))
    v = np.where(t < b, rise_v, np.where(t < math.pi, 0.0, np.where(t < math.pi + b, -fall_v, 0.0)))
    return s, v


@pytest.mark.slow
def test_contact_loss_and_reimpact_match_an_event_driven_rk_solution():
    """A different method written here: DOP853 (rtol 1e-9) on the absolute coordinate x with
    terminal events at the contact switches. femcam's lift-off and re-impact (linear event
    location, exact modes) must follow it through the flight."""
    from scipy.integrate import solve_ivp

    m, k, Fpl, k_t = 0.2, 800.0, 100.0, 1e6
    c_t = 0.3 * 2 * math.sqrt(k_t * m)
    w = 1.1 * _rigid_liftoff_rpm(m, k, Fpl, math.pi / 2) / 30 * math.pi
    tm = TrainModel(follower=FollowerDynamics(m=m, k=k, Fpl=Fpl, c=0.0), k_t=k_t, c_t=c_t)
    x0 = -Fpl / (k_t + k)
    theta, Z, C, F = simulate(tm, _program(), w, z0=[x0, 0.0], steps_per_rev=7200)
    t_grid = theta / w

    def trial(t, y):
        s, sd = _cycloid_program_s(w * t)
        return k_t * (s - y[0]) + c_t * (w * sd - y[1])

    def rhs(contact):
        return lambda t, y: [y[1], ((trial(t, y) if contact else 0.0) - k * y[0] - Fpl) / m]

    t0, y0, contact, pieces, switches = 0.0, [x0, 0.0], True, [], 0
    while t0 < t_grid[-1]:
        ev = lambda t, y: trial(t, y)  # noqa: E731
        ev.terminal, ev.direction = True, (-1 if contact else 1)
        sol = solve_ivp(rhs(contact), (t0, t_grid[-1]), y0, method="DOP853", rtol=1e-9,
                        atol=1e-12, events=ev, dense_output=True)
        pieces.append((t0, sol.t[-1], sol.sol))
        if sol.status != 1:
            break
        t0, y0, contact, switches = sol.t_events[0][0], sol.y_events[0][0], not contact, switches + 1
    x_ref = np.empty_like(t_grid)
    for a, b_, f in pieces:
        sel = (t_grid >= a) & (t_grid <= b_)
        x_ref[sel] = f(t_grid[sel])[0]
    s, _ = _cycloid_program_s(theta)
    assert switches >= 2 and (~C).any()
    # measured 5.3e-7 h at 7200 steps: the O(h^2) input interpolation and event location
    np.testing.assert_allclose(s + Z[:, 0], x_ref, rtol=0, atol=2e-6 * H,
                               err_msg="x(t) through lift-off, flight and re-impact vs DOP853")
