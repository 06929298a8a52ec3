"""femcam.profile against closed-form geometry (eccentric circular cams), finite differences of
the computed cam points, Norton's flat-faced formula and seed 003's published pressure angle."""

import math

import numpy as np
import pytest

from femcam.errors import InputError, UndercutError
from femcam.kinematics import CamProgram, dwell, fall, rise
from femcam.profile import (
    FlatFacedFollower,
    KnifeEdgeFollower,
    RollerFollower,
    cam_profile,
    make_follower,
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


def offset_roller_case():
    """Offset roller on the stand-in 3-4-5 program, on a fine grid for central differences:
    ``(follower, profile, fixed_frame_tangent)``; ``fixed_frame_tangent(x, y)`` differentiates
    cam-frame points in theta and turns the tangent into the fixed frame, R(theta)."""
    prog = RDFD(0.01, [100, 60, 120, 80])
    th = np.linspace(0, 2 * np.pi, 20001)
    d = prog.derivatives(th)
    f = RollerFollower(Rb=0.02, Rr=0.008, e=0.005)
    p = cam_profile(f, th, d["s"], d["s1"], d["s2"])
    c, sn = np.cos(th), np.sin(th)

    def fixed_frame_tangent(x, y):
        tx, ty = np.gradient(x, th), np.gradient(y, th)
        return c * tx - sn * ty, sn * tx + c * ty

    return f, p, fixed_frame_tangent


def test_pressure_angle_matches_finite_difference_of_pitch_curve():
    _, p, fixed_frame_tangent = offset_roller_case()
    # tangent of the cam-frame pitch curve by central differences, rotated back to the fixed frame
    Tx, Ty = fixed_frame_tangent(p.pitch_x, p.pitch_y)
    # fixed-frame tangent is parallel to (d + s, s1 - e); the normal is it turned by 90 deg, so the
    # normal's angle from the follower axis equals the tangent's angle from +x
    phi_fd = np.arctan2(Ty, Tx)
    inner = slice(1, -1)
    np.testing.assert_allclose(phi_fd[inner], p.phi[inner], atol=2e-6,
                               err_msg="phi vs finite-difference normal of the pitch curve")


def test_pressure_angle_matches_finite_difference_of_cam_surface():
    # the pressure angle is the angle between the follower axis (+y) and the cam-SURFACE normal at
    # the contact point; estimate that normal from central differences of the computed surface
    # points (p.x, p.y), roller with offset
    f, p, fixed_frame_tangent = offset_roller_case()
    Tx, Ty = fixed_frame_tangent(p.x, p.y)
    nx, ny = -Ty, Tx  # tangent turned by +90 deg: the outward normal (the cam turns CCW)
    nrm = np.hypot(nx, ny)
    nx, ny = nx / nrm, ny / nrm
    assert np.all(ny > 0)  # outward: towards the follower above the cam
    phi_fd = np.arctan2(-nx, ny)  # signed angle from the +y axis to the normal
    inner = slice(1, -1)
    np.testing.assert_allclose(phi_fd[inner], p.phi[inner], atol=2e-6,
                               err_msg="phi vs finite-difference normal of the cam surface")
    # and the roller centre lies on that normal, Rr from the contact point
    np.testing.assert_allclose((p.contact_x + f.Rr * nx)[inner], f.e, atol=1e-9)
    assert np.max(np.abs(phi_fd)) > math.radians(15)  # a real test: phi is not small


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
    # exact 3-4-5 program: tan phi = s'/(Rb + s), maximised independently with scipy
    exact = seed003_phi_max_deg()
    assert exact == pytest.approx(29.4366, abs=1e-4)
    assert math.degrees(p.phi_max) == pytest.approx(exact, abs=1e-3)
    assert math.degrees(p.phi_max) <= 30.0


def seed003_phi_max_deg(Rb=0.005, h=0.003):
    """Largest |phi| (deg) of seed 003's in-line knife edge, tan phi = |s'|/(Rb + s), over its
    3-4-5 rise (beta = 120 deg) and fall (beta = 90 deg, s = h - h L(u)), each maximised with a
    bounded Brent search in u. (Seed 003's own 29.3619 deg is compared with femcam's value in
    tests/test_scene.py.)"""
    from scipy.optimize import minimize_scalar

    best = 0.0
    for b, falling in ((120.0, False), (90.0, True)):
        beta = math.radians(b)

        def neg(u, beta=beta, falling=falling):
            L, L1, _ = poly345(u)
            s = h - h * L if falling else h * L
            return -math.atan(h * L1 / beta / (Rb + s))

        r = minimize_scalar(neg, bounds=(0.0, 1.0), method="bounded", options={"xatol": 1e-12})
        best = max(best, -r.fun)
    return math.degrees(best)


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


# --- min_base_radius: edge cases ------------------------------------------------------------
def cycloidal(u):
    """Cycloidal law (Norton eq. 3.8) typed in here: s, ds/du, d2s/du2 for unit lift."""
    w = 2 * np.pi * u
    return u - np.sin(w) / (2 * np.pi), 1 - np.cos(w), 2 * np.pi * np.sin(w)


SEED000 = CamProgram([rise(math.pi, 0.010, "cycloidal"), fall(math.pi, 0.010, "cycloidal")])


def test_min_base_radius_roller_larger_than_needed_prime_radius():
    # seed 000 program (cycloidal rise of 10 mm over 180 deg, mirrored fall) with Rr = 20 mm:
    # phi <= 30 deg needs the prime radius d* = max(s'/tan 30 - s) (by hand on the rise; the fall
    # mirrors it), which the roller alone exceeds, so no Rb > 0 violates the limit
    from scipy.optimize import minimize_scalar

    h, beta = 0.010, math.pi
    neg = lambda u: -(h * cycloidal(u)[1] / beta / math.tan(math.radians(30)) - h * cycloidal(u)[0])  # noqa: E731
    d_star = -minimize_scalar(neg, bounds=(0, 1), method="bounded", options={"xatol": 1e-12}).fun
    assert d_star == pytest.approx(0.0069211, abs=1e-7) and d_star < 0.020
    r = min_base_radius("roller", SEED000, Rr=0.020)  # used to be scipy's bare ValueError
    assert r.Rb == 0.0 and float(r) == 0.0 and r.binding == "none"
    assert "Rr = 20 mm" in r.message and f"{d_star * 1e3:.4f}" in r.message
    assert "Any Rb > 0 works" in r.message
    # the limit Rb -> 0 is the in-line roller of prime radius Rr: phi_max = max atan(s'/(Rr + s))
    th = np.linspace(0, np.pi, 20001)
    u = th / beta
    s, s1 = h * cycloidal(u)[0], h * cycloidal(u)[1] / beta
    assert r.phi_max == pytest.approx(np.max(np.arctan(s1 / (0.020 + s))), abs=1e-6)
    # any small positive Rb is then accepted (no undercut) and keeps phi <= 30 deg
    d = SEED000.derivatives(TH)
    for Rb in (1e-4, 1e-3, 0.01):
        p = cam_profile(RollerFollower(Rb=Rb, Rr=0.020), TH, d.s, d.s1, d.s2)
        assert p.phi_max <= math.radians(30)
    # between, the pressure angle binds: Rb = d* - Rr (in-line), closed form
    r5 = min_base_radius("roller", SEED000, Rr=0.005)
    assert r5.binding == "pressure_angle" and r5.Rb == pytest.approx(d_star - 0.005, rel=1e-9)


def test_min_base_radius_large_roller_with_rho_min():
    # with a required cam radius of curvature the base circle binds: at theta = 0 the cycloidal
    # program has s = s' = s'' = 0, where the cam is its base circle and rho = Rb, so Rb = rho_min
    # (the nose, s = h with s'' = 0, has rho = Rb + h > Rb)
    r = min_base_radius("roller", SEED000, Rr=0.020, rho_min=0.003)
    assert r.binding == "undercut"
    assert r.Rb == pytest.approx(0.003, rel=1e-8) and r.Rb > 0.003
    # independent: polar curvature of the pitch curve r = Rp + s, cam rho = rho_pitch - Rr
    th = np.linspace(0, 2 * np.pi, 72000, endpoint=False)
    u = np.where(th < np.pi, th / np.pi, (th - np.pi) / np.pi)
    sgn = np.where(th < np.pi, 1.0, -1.0)
    L, L1, L2 = cycloidal(u)
    s = np.where(th < np.pi, 0.01 * L, 0.01 * (1 - L))
    s1, s2 = sgn * 0.01 * L1 / np.pi, sgn * 0.01 * L2 / np.pi**2

    def rho_cam_min(Rb):
        R = Rb + 0.020 + s
        return np.min((R**2 + s1**2) ** 1.5 / (R**2 + 2 * s1**2 - R * s2) - 0.020)

    assert rho_cam_min(r.Rb) >= 0.003 - 1e-12
    assert rho_cam_min(0.99 * r.Rb) < 0.003


def test_min_base_radius_flat_faced_is_closed_form_and_accepted():
    # cycloidal rise h over beta next to dwells: g = s + s'' = h (u - sin(2 pi u)/(2 pi))
    # + (2 pi h/beta^2) sin(2 pi u); g' = 0 at cos(2 pi u*) = -beta^2/(4 pi^2 - beta^2), the minimum
    # on u in (1/2, 1) (sin < 0). Norton eq. 8.27: Rb > -min g. The fall mirrors the rise.
    h, beta = 0.010, math.radians(60)
    c = -(beta**2) / (4 * math.pi**2 - beta**2)
    w = 2 * math.pi - math.acos(c)
    u_star = w / (2 * math.pi)
    g_min = h * (u_star - math.sin(w) / (2 * math.pi)) + 2 * math.pi * h / beta**2 * math.sin(w)
    Rb_exact = -g_min
    assert Rb_exact == pytest.approx(0.0482, abs=2e-4)  # about 4.8 h
    prog = CamProgram([rise(beta, h, "cycloidal"), dwell(math.radians(120)), fall(beta, h, "cycloidal"),
                       dwell(math.radians(120))])
    r = min_base_radius("flat_faced", prog)
    assert r.binding == "curvature"
    assert r.Rb == pytest.approx(Rb_exact, rel=1e-8)
    assert r.Rb > Rb_exact  # strict inequality: rho = Rb + s + s'' > 0
    assert r.theta_critical == pytest.approx(u_star * beta, abs=1e-5) or \
        r.theta_critical == pytest.approx(math.radians(240) + (1 - u_star) * beta, abs=1e-5)
    # cam_profile accepts it on the function's own grid, at the exact critical angles and densely
    theta_c = np.array([u_star * beta, math.radians(240) + (1 - u_star) * beta])
    for th in (np.linspace(0, 2 * np.pi, 7200, endpoint=False), theta_c,
               np.linspace(theta_c[0] - 1e-3, theta_c[0] + 1e-3, 20001)):
        d = prog.derivatives(th)
        p = cam_profile(FlatFacedFollower(Rb=r.Rb), th, d.s, d.s1, d.s2)
        assert np.all(p.rho > 0)
    # and it is tight: just below the closed form the cam is cusped at theta*
    d = prog.derivatives(theta_c)
    with pytest.raises(UndercutError):
        cam_profile(FlatFacedFollower(Rb=Rb_exact * (1 - 1e-7)), theta_c, d.s, d.s1, d.s2)


def test_min_base_radius_flat_faced_unconstrained():
    # seed 000's slow cycloidal program: s + s'' >= 0 everywhere (its minimum, 0, is on the base
    # circle point theta = 0), so nothing bounds Rb away from zero
    r = min_base_radius("flat_faced", SEED000)
    assert r.binding == "none" and r.Rb == 0.0 and "every Rb > 0" in r.message


@pytest.mark.parametrize("kind", ["knife_edge", "flat_faced"])
def test_min_base_radius_roller_radius_only_for_roller(kind):
    with pytest.raises(InputError, match=r"^Rr = 0.01 m: only a roller follower has a roller radius"):
        min_base_radius(kind, SEED000, Rr=0.01)
    with pytest.raises(InputError, match="only a roller follower has a roller radius"):
        make_follower(kind, Rb=0.01, Rr=0.01)


@pytest.mark.parametrize("n", [0.5, 16.0, 8, 0, -3, "100", True])
def test_min_base_radius_n_theta_must_be_integer_ge_16(n):
    with pytest.raises(InputError, match=r"^n_theta = .*: must be an integer >= 16"):
        min_base_radius("knife_edge", SEED000, n_theta=n)


def test_min_base_radius_n_theta_numpy_integer():
    r = min_base_radius("knife_edge", SEED000, n_theta=np.int64(16))
    assert r.n_theta == 16 and r.binding == "pressure_angle"


def test_follower_protocol_says_what_each_follower_does():
    """The follower protocol (docs/architecture.md): one row per follower class."""
    from femcam.profile import (
        FlatFacedFollower,
        KnifeEdgeFollower,
        OscillatingPadFollower,
        OscillatingRollerFollower,
        RollerFollower,
    )

    arm = dict(Rb=0.018, Rr=0.012, a=0.045, L=0.036)
    rows = {  # rolls, draws_circle, flat_face, needs_tip, oscillating, translating_roller
        RollerFollower(Rb=0.02, Rr=0.01): (True, True, False, False, False, True),
        KnifeEdgeFollower(Rb=0.02): (False, False, False, True, False, False),
        FlatFacedFollower(Rb=0.02): (False, False, True, False, False, False),
        OscillatingRollerFollower(**arm): (True, True, False, False, True, False),
        OscillatingPadFollower(**arm): (False, True, False, False, True, False),
    }
    for f, want in rows.items():
        got = (f.rolls, f.draws_circle, f.flat_face, f.needs_tip, f.oscillating, f.translating_roller)
        assert got == want, f.kind
    assert RollerFollower(Rb=0.02, Rr=0.01).contact_radius() == 0.01
    assert OscillatingPadFollower(**arm).contact_radius() == 0.012
    assert FlatFacedFollower(Rb=0.02).contact_radius() == math.inf
    assert KnifeEdgeFollower(Rb=0.02).contact_radius(0.003) == 0.003
    with pytest.raises(InputError, match="tip_radius_mm"):
        KnifeEdgeFollower(Rb=0.02).contact_radius()
