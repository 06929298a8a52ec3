"""femcam.profile against closed-form geometry (eccentric circular cams), finite differences of
the computed cam points, Norton's flat-faced formula and seed 003's published pressure angle."""

import math

import numpy as np
import pytest

from femcam.errors import InputError, UndercutError
from femcam.profile import (
    FlatFacedFollower,
    KnifeEdgeFollower,
    RollerFollower,
    cam_profile,
    min_base_radius,
)

TH = np.linspace(0.0, 2.0 * np.pi, 721)


def eccentric_roller_motion(theta, Rc, E, Rr, e):
    """Exact follower motion of a circular disc (radius Rc, centre E from the shaft) under a
    roller (radius Rr) whose axis is the line x = e. The disc centre sits at
    C = (E sin t, -E cos t) (cam turned counter-clockwise by t); the roller centre (e, y)
    satisfies |P - C| = Rc + Rr =: L, so y = -E cos t + W with W = sqrt(L^2 - g^2),
    g = e - E sin t. Derivatives by hand (chain rule)."""
    L = Rc + Rr
    g, g1, g2 = e - E * np.sin(theta), -E * np.cos(theta), E * np.sin(theta)
    W = np.sqrt(L**2 - g**2)
    W1 = -g * g1 / W
    W2 = -(g1**2 + g * g2) / W - g**2 * g1**2 / W**3
    y, y1, y2 = -E * np.cos(theta) + W, E * np.sin(theta) + W1, E * np.cos(theta) + W2
    Rp = Rc - E + Rr  # base circle Rb = Rc - E
    d = math.sqrt(Rp**2 - e**2)
    return y - d, y1, y2, (g, W, L)


@pytest.mark.parametrize("e", [0.0, 0.004, -0.003])
def test_eccentric_circle_roller_has_constant_radius(e):
    Rc, E, Rr = 0.03, 0.008, 0.012
    s, s1, s2, (g, W, L) = eccentric_roller_motion(TH, Rc, E, Rr, e)
    f = RollerFollower(Rb=Rc - E, Rr=Rr, e=e)
    p = cam_profile(f, TH, s, s1, s2)
    # the cam surface is the disc itself: rho = Rc everywhere, pitch curve radius Rc + Rr
    np.testing.assert_allclose(p.rho, Rc, rtol=1e-9, err_msg="circle cam: rho_cam = Rc")
    np.testing.assert_allclose(p.rho_pitch, Rc + Rr, rtol=1e-9)
    # cam-frame surface points lie on the disc, centre (0, -E) at theta = 0
    np.testing.assert_allclose(np.hypot(p.x, p.y + E), Rc, rtol=1e-10)
    # pressure angle: the normal is the line of centres, n = (P - C)/L = (-sin phi, cos phi)
    np.testing.assert_allclose(np.sin(p.phi), -g / L, atol=1e-12)
    # contact point lies on the line of centres, Rc from the disc centre
    Cx, Cy = E * np.sin(TH), -E * np.cos(TH)
    np.testing.assert_allclose(np.hypot(p.contact_x - Cx, p.contact_y - Cy), Rc, rtol=1e-10)
    assert not p.cusp and not p.undercut.any()


def test_eccentric_circle_flat_faced_is_harmonic():
    Rc, E = 0.025, 0.006
    s, s1, s2 = E * (1 - np.cos(TH)), E * np.sin(TH), E * np.cos(TH)
    p = cam_profile(FlatFacedFollower(Rb=Rc - E), TH, s, s1, s2)
    np.testing.assert_allclose(p.rho, Rc, rtol=1e-12)
    np.testing.assert_allclose(p.phi, 0.0)
    np.testing.assert_allclose(np.hypot(p.x, p.y + E), Rc, rtol=1e-12)
    # contact directly above the disc centre; face width 2 max|s1| = 2E
    np.testing.assert_allclose(p.contact_x, E * np.sin(TH), atol=1e-15)
    assert p.face_width_min == pytest.approx(2 * E, rel=1e-5)


def poly345(u):
    return (10 * u**3 - 15 * u**4 + 6 * u**5, 30 * u**2 - 60 * u**3 + 30 * u**4,
            60 * u - 180 * u**2 + 120 * u**3)


class RDFD:
    """Stand-in cam program (independent of femcam.kinematics): 3-4-5 rise / dwell / 3-4-5 fall /
    dwell, betas in degrees, lift h in m."""

    def __init__(self, h, betas_deg):
        self.h = h
        self.b = np.radians(betas_deg)
        assert math.isclose(self.b.sum(), 2 * math.pi)

    def derivatives(self, theta):
        t = np.mod(np.asarray(theta, float), 2 * np.pi)
        b1, b2, b3, _ = self.b
        s, s1, s2 = (np.zeros_like(t) for _ in range(3))
        r = t < b1
        y, y1, y2 = poly345(t[r] / b1)
        s[r], s1[r], s2[r] = self.h * y, self.h * y1 / b1, self.h * y2 / b1**2
        dw = (t >= b1) & (t < b1 + b2)
        s[dw] = self.h
        fl = (t >= b1 + b2) & (t < b1 + b2 + b3)
        y, y1, y2 = poly345((t[fl] - b1 - b2) / b3)
        s[fl], s1[fl], s2[fl] = self.h * (1 - y), -self.h * y1 / b3, -self.h * y2 / b3**2
        return {"s": s, "s1": s1, "s2": s2}


def test_pressure_angle_matches_finite_difference_of_pitch_curve():
    prog = RDFD(0.01, [100, 60, 120, 80])
    th = np.linspace(0, 2 * np.pi, 20001)
    d = prog.derivatives(th)
    f = RollerFollower(Rb=0.02, Rr=0.008, e=0.005)
    p = cam_profile(f, th, d["s"], d["s1"], d["s2"])
    # tangent of the cam-frame pitch curve by central differences, rotated back to the fixed frame
    tx, ty = np.gradient(p.pitch_x, th), np.gradient(p.pitch_y, th)
    c, sn = np.cos(th), np.sin(th)
    Tx, Ty = c * tx - sn * ty, sn * tx + c * ty
    # fixed-frame tangent is parallel to (d + s, s1 - e); the normal is it turned by 90 deg, so the
    # normal's angle from the follower axis equals the tangent's angle from +x
    phi_fd = np.arctan2(Ty, Tx)
    inner = slice(1, -1)
    np.testing.assert_allclose(phi_fd[inner], p.phi[inner], atol=2e-6,
                               err_msg="phi vs finite-difference normal of the pitch curve")


def test_flat_faced_rho_is_rb_plus_s_plus_s2():
    prog = RDFD(0.008, [120, 30, 150, 60])
    d = prog.derivatives(TH)
    Rb = 0.03
    p = cam_profile(FlatFacedFollower(Rb=Rb), TH, d["s"], d["s1"], d["s2"])
    np.testing.assert_allclose(p.rho, Rb + d["s"] + d["s2"], rtol=1e-14)
    # independent check: curvature of the cam-frame envelope points by finite differences
    th = np.linspace(0.3, 1.8, 30001)
    dd = prog.derivatives(th)
    q = cam_profile(FlatFacedFollower(Rb=Rb), th, dd["s"], dd["s1"], dd["s2"])
    x1, y1 = np.gradient(q.x, th), np.gradient(q.y, th)
    x2, y2 = np.gradient(x1, th), np.gradient(y1, th)
    rho_fd = (x1**2 + y1**2) ** 1.5 / -(x1 * y2 - y1 * x2)
    np.testing.assert_allclose(rho_fd[5:-5], q.rho[5:-5], rtol=1e-4)


def test_knife_edge_rho_is_polar_curvature_and_seed003_pressure_angle():
    prog = RDFD(0.003, [120, 90, 90, 60])
    th = np.linspace(0, 2 * np.pi, 72001)
    d = prog.derivatives(th)
    p = cam_profile(KnifeEdgeFollower(Rb=0.005), th, d["s"], d["s1"], d["s2"])
    r, r1, r2 = 0.005 + d["s"], d["s1"], d["s2"]
    np.testing.assert_allclose(p.rho, (r**2 + r1**2) ** 1.5 / (r**2 + 2 * r1**2 - r * r2), rtol=1e-12)
    # seed 003 reports max phi = 29.3619 deg from its FE-approximated curve; the exact 3-4-5 curve
    # gives 29.4366 deg (derived by hand: max over the 90-deg fall of atan(|s'|/(Rb + s))).
    assert math.degrees(p.phi_max) == pytest.approx(29.3619, abs=0.1)
    assert math.degrees(p.phi_max) <= 30.0


def test_undercut_raises_and_flags():
    prog = RDFD(0.02, [40, 140, 40, 140])  # steep rise: sharp nose
    d = prog.derivatives(TH)
    f = RollerFollower(Rb=0.01, Rr=0.015)
    with pytest.raises(UndercutError, match=r"deg.*mm"):
        cam_profile(f, TH, d["s"], d["s1"], d["s2"])
    p = cam_profile(f, TH, d["s"], d["s1"], d["s2"], allow_undercut=True)
    assert p.cusp and p.undercut.any()
    # flagged exactly where the convex pitch radius is below Rr (independent polar formula)
    r, r1, r2 = f.Rp + d["s"], d["s1"], d["s2"]
    kp = (r**2 + 2 * r1**2 - r * r2) / (r**2 + r1**2) ** 1.5
    np.testing.assert_array_equal(p.undercut, f.Rr * kp >= 1.0)
    # flat-faced cusp: rho = Rb + s + s'' <= 0
    with pytest.raises(UndercutError, match="Rb \\+ s \\+ s''"):
        cam_profile(FlatFacedFollower(Rb=0.005), TH, d["s"], d["s1"], d["s2"])


@pytest.mark.parametrize("kind,Rr,e", [("roller", 0.01, 0.0), ("roller", 0.006, 0.004),
                                       ("knife_edge", 0.0, 0.0), ("flat_faced", 0.0, 0.0)])
def test_min_base_radius_is_tight(kind, Rr, e):
    prog = RDFD(0.01, [90, 90, 120, 60])
    r = min_base_radius(kind, prog, phi_max=math.radians(30), Rr=Rr, e=e)
    th = np.linspace(0, 2 * np.pi, 200001)
    d = prog.derivatives(th)

    def phi_max(Rb):
        D = math.sqrt((Rb + Rr) ** 2 - e**2)
        return np.max(np.abs(np.arctan((d["s1"] - e) / (D + d["s"]))))

    if kind == "flat_faced":
        rho = lambda Rb: np.min(Rb + d["s"] + d["s2"])  # noqa: E731
        assert rho(r.Rb * 1.000001) > 0 and rho(0.99 * r.Rb) < 0
    else:
        assert r.binding == "pressure_angle"
        assert phi_max(r.Rb) <= math.radians(30) + 1e-9
        assert phi_max(0.99 * r.Rb) > math.radians(30)


def test_min_base_radius_avoids_undercut_with_large_roller():
    prog = RDFD(0.02, [40, 140, 40, 140])
    r = min_base_radius("roller", prog, phi_max=math.radians(89), Rr=0.03)
    assert r.binding == "undercut"
    d = prog.derivatives(TH)
    cam_profile(RollerFollower(Rb=r.Rb, Rr=0.03), TH, d["s"], d["s1"], d["s2"])  # no error
    with pytest.raises(UndercutError):
        cam_profile(RollerFollower(Rb=0.99 * r.Rb, Rr=0.03), TH, d["s"], d["s1"], d["s2"])


@pytest.mark.parametrize("kw,name", [(dict(Rb=0.0, Rr=0.01), "Rb"), (dict(Rb=0.01, Rr=-1e-3), "Rr"),
                                     (dict(Rb=0.01, Rr=0.01, e=0.03), "e")])
def test_bad_follower_radius(kw, name):
    with pytest.raises(InputError, match=rf"^{name} = .* m: "):
        RollerFollower(**kw)


def test_bad_arrays():
    f = KnifeEdgeFollower(Rb=0.01)
    with pytest.raises(InputError, match="s = nan m"):
        cam_profile(f, [0.0, 1.0], [0.0, np.nan], 0.0, 0.0)
    with pytest.raises(InputError, match="broadcast"):
        cam_profile(f, [0.0, 1.0], [0.0, 0.0, 0.0], 0.0, 0.0)
