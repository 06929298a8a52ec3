"""femcam.loads: seed 002 eq. 11 against hand calculations and analytic lift-off angles."""

import math
import re

import numpy as np
import pytest

from femcam.errors import InputError, LiftOffError, PhysicsError
from femcam.loads import FollowerDynamics, contact_force


def test_contact_force_hand_calculation():
    # m a + c v + k s + Fpl = 0.2*(-350) + 1.5*0.4 + 800*0.004 + 1500 = 1433.8 N; / cos 25 deg
    dyn = FollowerDynamics(m=0.2, k=800.0, Fpl=1500.0, c=1.5)
    r = contact_force(dyn, 1.0, 0.004, 0.4, -350.0, math.radians(25.0))
    assert float(r.Fc) == pytest.approx(1433.8 / math.cos(math.radians(25.0)), rel=1e-13)
    assert float(r.F_axial) == pytest.approx(1433.8, rel=1e-13)
    assert not r.any_liftoff


def test_seed002_damping_ratio():
    # seed 002 Table 1: c = 0.06 c_c, c_c = 2 sqrt(k m) with the tracker mass 0.2 kg
    dyn = FollowerDynamics(m=0.2, k=800.0, Fpl=1500.0, zeta=0.06)
    assert dyn.c == pytest.approx(0.06 * 2 * math.sqrt(800 * 0.2), rel=1e-14)
    assert dyn.c == pytest.approx(1.517893, abs=1e-6)
    assert FollowerDynamics(m=0.2, k=800.0, Fpl=0.0, c=dyn.c).zeta == pytest.approx(0.06)


def test_liftoff_angles_harmonic_follower():
    # eccentric cam under a flat face: s = E(1 - cos t), a = E w^2 cos t, v = E w sin t; no damping.
    # Fc = m E w^2 cos t + k E (1 - cos t) + Fpl <= 0  <=>  cos t <= -(kE + Fpl)/(mEw^2 - kE)
    m, k, Fpl, E, w = 0.5, 200.0, 5.0, 0.005, 150.0
    t = np.linspace(0, 2 * np.pi, 36001)
    dyn = FollowerDynamics(m=m, k=k, Fpl=Fpl, c=0.0)
    r = contact_force(dyn, t, E * (1 - np.cos(t)), E * w * np.sin(t), E * w**2 * np.cos(t), 0.0)
    c0 = -(k * E + Fpl) / (m * E * w**2 - k * E)
    t0 = math.acos(c0)  # lift-off interval is [t0, 2 pi - t0]
    assert len(r.liftoff_intervals) == 1
    a, b = r.liftoff_intervals[0]
    dt = t[1] - t[0]
    assert a == pytest.approx(t0, abs=dt) and b == pytest.approx(2 * np.pi - t0, abs=dt)
    np.testing.assert_array_equal(r.liftoff_angles, t[r.liftoff])
    assert r.Fc_min == pytest.approx(-m * E * w**2 + 2 * k * E + Fpl, rel=1e-6)


@pytest.mark.parametrize("kw,match", [
    (dict(m=-0.1, k=1.0, Fpl=0.0, c=0.0), r"^m = -0.1 kg: must be >= 0"),
    (dict(m=0.1, k=-1.0, Fpl=0.0, c=0.0), r"^k = -1 N/m"),
    (dict(m=0.1, k=1.0, Fpl=0.0), "exactly one"),
    (dict(m=0.1, k=1.0, Fpl=0.0, c=1.0, zeta=0.1), "exactly one"),
    (dict(m=0.1, k=1.0, Fpl=0.0, zeta=-0.1), r"^zeta = -0.1"),
])
def test_bad_dynamics(kw, match):
    with pytest.raises(InputError, match=match):
        FollowerDynamics(**kw)


def test_bad_pressure_angle():
    dyn = FollowerDynamics(m=0.1, k=1.0, Fpl=1.0, c=0.0)
    with pytest.raises(InputError, match=r"phi = .* rad: pressure angle \(90 deg\)"):
        contact_force(dyn, [0, 1], 0.0, 0.0, 0.0, [0.0, math.pi / 2])


def test_liftoff_raise_lists_intervals_in_degrees():
    # same harmonic follower as above: lift-off on [t0, 2 pi - t0], t0 = acos(-(kE + Fpl)/(mEw^2 - kE))
    m, k, Fpl, E, w = 0.5, 200.0, 5.0, 0.005, 150.0
    t = np.linspace(0, 2 * np.pi, 36001)
    dyn = FollowerDynamics(m=m, k=k, Fpl=Fpl, c=0.0)
    args = (t, E * (1 - np.cos(t)), E * w * np.sin(t), E * w**2 * np.cos(t), 0.0)
    flagged = contact_force(dyn, *args)  # default: flag, as before
    assert flagged.any_liftoff
    t0 = math.degrees(math.acos(-(k * E + Fpl) / (m * E * w**2 - k * E)))
    with pytest.raises(LiftOffError) as info:
        contact_force(dyn, *args, on_liftoff="raise")
    msg = str(info.value)
    nums = [float(x) for x in re.findall(r"\[([-\d.]+), ([-\d.]+)\] deg", msg)[0]]
    dt = 360.0 / 36000
    assert nums[0] == pytest.approx(t0, abs=dt + 0.01) and nums[1] == pytest.approx(360 - t0, abs=dt + 0.01)
    # smallest Fc by hand, at theta = 180 deg: -m E w^2 + 2 k E + Fpl
    assert f"{-m * E * w**2 + 2 * k * E + Fpl:.4g} N at theta = 180.00 deg" in msg
    assert isinstance(info.value, PhysicsError) and not isinstance(info.value, ValueError)
    # no lift-off: "raise" returns the result
    ok = contact_force(FollowerDynamics(m=m, k=k, Fpl=1e4, c=0.0), *args, on_liftoff="raise")
    assert not ok.any_liftoff


def test_bad_on_liftoff():
    dyn = FollowerDynamics(m=0.1, k=1.0, Fpl=1.0, c=0.0)
    with pytest.raises(InputError, match="on_liftoff = 'warn'"):
        contact_force(dyn, 0.0, 0.0, 0.0, 0.0, 0.0, on_liftoff="warn")


@pytest.mark.parametrize("m,k", [(0.0, 800.0), (0.2, 0.0), (0.0, 0.0)])
def test_damping_ratio_without_critical_damping(m, k):
    # c_c = 2 sqrt(k m) = 0: a ratio cannot set c (it used to give c = 0 silently)
    with pytest.raises(InputError, match=r"^zeta \(damping_ratio\) = 0.06: .*c_c = 2 sqrt\(k m\).*= 0 N s/m"
                       r".*damping coefficient c in N s/m"):
        FollowerDynamics(m=m, k=k, Fpl=1.0, zeta=0.06)
    # zeta = 0 is unambiguous (no damping); an explicit c is always fine
    assert FollowerDynamics(m=m, k=k, Fpl=1.0, zeta=0.0).c == 0.0
    assert FollowerDynamics(m=m, k=k, Fpl=1.0, c=2.5).c == 2.5
