"""FE two-body contact against analytic Hertz theory (femcam.hertz, Johnson 1985 / seed 002).

Study model of seed 002: steel/steel, Rr = 10 mm, rho = 20 mm, F = 1500 N, l = 10 mm
(a ~ 0.105 mm, p0 ~ 0.91 GPa), h = a/20. Tolerances are the issue-4 targets unless stated.
That model has a/R = 0.016 (R = 6.67 mm), just outside the issue's Hertz regime a/R <= 0.01:
test_targets_in_hertz_regime repeats the targets at F = 500 N (a/R = 0.0091).
"""

import math
import warnings

import numpy as np
import pytest

from femcam.errors import InputError, PhysicsError
from femcam.fe import ContactModel, ContactResult, MeshOptions, SolverOptions, solve_contact
from femcam.hertz import LineContact
from femcam.materials import STEEL, Material

Rr, rho, F, l = 0.01, 0.02, 1500.0, 0.01


def hertz(F=F, rho=rho, mu=0.0, cam=STEEL, roller=STEEL, direction=1):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return LineContact(F=F, length=l, R1=rho, R2=Rr, cam=cam, roller=roller, mu=mu,
                           direction=direction)


@pytest.fixture(scope="module")
def model():
    return ContactModel.build(Rr=Rr, rho_ref=rho, cam=STEEL, roller=STEEL, length=l,
                              a_ref=float(hertz().a), mesh=MeshOptions(a_over_h=20))


@pytest.fixture(scope="module")
def frictionless(model):
    return model.solve(F=F, rho=rho)


def test_pressure_peak_and_width(frictionless):
    r, hc = frictionless, hertz()
    assert isinstance(r, ContactResult) and r.converged
    assert r.p0 == pytest.approx(hc.p0, rel=3e-3), "p0 vs Hertz p0 = 2w/(pi a) (target 0.3 %)"
    assert r.p0_nodal == pytest.approx(hc.p0, rel=3e-3)
    assert r.a == pytest.approx(hc.a, rel=1e-2), "fitted a vs Hertz a = sqrt(4wR/(pi E*))"
    assert abs(r.x0) < 1e-3 * hc.a, "symmetric contact centred at x = 0"


def rms_vs_hertz(r, hc):
    """rms over the fine-zone nodes |x| <= 2.5 a of (p - Hertz p(x)) / Hertz p0."""
    return float(np.sqrt(np.mean(((r.p - hc.pressure(r.x)) / hc.p0) ** 2)))


def test_pressure_profile_rms(frictionless):
    """rms(p - Hertz) over the +-2.5a fine-zone nodes at a/h = 20: measured 0.59 % p0, so the
    0.5 % target is NOT met at a/20 (tolerance here 0.7 %). The error sits at the two nodes next
    to each contact edge (the exact pressure has a square-root edge that a P1 pressure cannot
    follow). With the Hertz edge on a node (even a/h, the worst alignment, as here) 0.5 % is
    first met at a/h = 24 (0.49 %): a/26 is tested below (0.45 %), a/28 in the slow convergence
    test (0.42 %). Interior nodes |x| < 0.9 a: <= 0.25 % p0 (measured 0.17 %)."""
    r, hc = frictionless, hertz()
    err = (r.p - hc.pressure(r.x)) / hc.p0
    assert rms_vs_hertz(r, hc) < 7e-3, "rms(p - Hertz) at a/20 (measured 0.59 % p0)"
    assert np.abs(err[np.abs(r.x) < 0.9 * hc.a]).max() < 2.5e-3


@pytest.mark.slow  # a fine a/26 model build (~2-4 s on 2 shared cores); a/20 runs by default above
def test_pressure_profile_rms_target_at_a26():
    """The issue's rms(p - Hertz) <= 0.5 % p0 target, same metric and +-2.5a zone as above, at
    a/h = 26 (edge on a node; measured 0.454 %). Only the pressure is needed, so the
    subsurface stress operators are skipped (eval_depth = 0) to keep the build short."""
    hc = hertz()
    m = ContactModel.build(Rr=Rr, rho_ref=rho, cam=STEEL, roller=STEEL, length=l, a_ref=float(hc.a),
                           mesh=MeshOptions(a_over_h=26), solver=SolverOptions(eval_depth=0.0))
    r = m.solve(F=F, rho=rho)
    np.testing.assert_allclose(r.x[[0, -1]], [-2.5 * hc.a, 2.5 * hc.a], rtol=1e-9)
    e = rms_vs_hertz(r, hc)
    np.testing.assert_array_less(e, 5e-3, err_msg=f"rms(p - Hertz p(x)) / Hertz p0 = {e:.4%} at a/h = 26 "
                                 "exceeds the 0.5 % target")


def test_equilibrium_and_complementarity(frictionless):
    r = frictionless
    assert r.force == pytest.approx(F, rel=1e-12), "integral p dx * l = F"
    assert np.all(r.p >= 0.0)
    assert np.all(r.gap >= -1e-9 * r.delta)
    assert np.max(np.abs(r.p * r.gap)) <= 1e-9 * r.p.max() * r.delta
    assert r.iterations >= 1 and r.residual < 1e-9 and r.active.sum() == np.count_nonzero(r.p > 0)


def test_subsurface_maxima(frictionless):
    r, hc = frictionless, hertz()
    ms, mo = hc.max_shear(), hc.max_orthogonal_shear()
    assert r.txz_abs_max.value == pytest.approx(mo.value, rel=5e-3), "|txz| max = 0.25 p0"
    assert r.tau1_max.value == pytest.approx(ms.value, rel=2e-2), "tau1 max = 0.30 p0 at z = 0.78 a"
    assert r.tau1_max.z == pytest.approx(ms.z, abs=0.1 * hc.a)
    assert abs(r.tau1_max.x) < 0.1 * hc.a
    vm = hc.max_von_mises("cam")
    assert r.max_by_body["cam"]["von_mises"].value == pytest.approx(vm.value, rel=2e-2)


@pytest.mark.slow  # over 1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_targets_in_hertz_regime():
    """The issue's targets inside its Hertz regime a/R <= 0.01: F = 500 N (same pair), a/R =
    0.0091, h = a/20. p0 0.3 % (measured -0.019 %), a 1 % (+0.25 %), |txz| max 0.5 %
    (+0.11 %), tau1 max 2 % (+0.76 %: finite-body effect, smaller than at 1500 N because the
    bodies are now 165 a instead of 95 a)."""
    Fr = 500.0
    hc = hertz(F=Fr)
    assert float(hc.a_over_R) <= 0.01 and float(hc.a_over_rmin) <= 0.01, "inside the Hertz regime"
    r = ContactModel.build(Rr=Rr, rho_ref=rho, cam=STEEL, roller=STEEL, length=l, a_ref=float(hc.a),
                           mesh=MeshOptions(a_over_h=20)).solve(F=Fr, rho=rho)
    assert r.converged and r.force == pytest.approx(Fr, rel=1e-12)
    assert r.p0 == pytest.approx(hc.p0, rel=3e-3), "p0 vs Hertz 2w/(pi a) (target 0.3 %)"
    assert r.a == pytest.approx(hc.a, rel=1e-2), "a vs Hertz sqrt(4wR/(pi E*)) (target 1 %)"
    assert r.txz_abs_max.value == pytest.approx(hc.max_orthogonal_shear().value, rel=5e-3), \
        "|txz| max vs Hertz 0.25 p0 (target 0.5 %)"
    assert r.tau1_max.value == pytest.approx(hc.max_shear().value, rel=2e-2), \
        "tau1 max vs Hertz 0.300 p0 (target 2 %)"


def test_stress_at_points_matches_hertz(frictionless):
    r, hc = frictionless, hertz()
    z = np.array([0.3, 0.78, 1.5]) * hc.a
    sx, sz, txz, sy, tau1, vm = r.stress_at(np.zeros(3), z, body="roller")
    ref = hc.stress(np.zeros(3), z, body="roller")
    np.testing.assert_allclose(sz, ref.sz, atol=1e-2 * hc.p0, err_msg="McEwen sz on the axis")
    np.testing.assert_allclose(sx, ref.sx, atol=1e-2 * hc.p0, err_msg="McEwen sx on the axis")
    np.testing.assert_allclose(tau1, ref.tau1, atol=1e-2 * hc.p0)


@pytest.mark.parametrize("mu", [0.1, 0.3])
def test_surface_stresses_with_friction(model, mu):
    """Seed 002 eqs. 5-7 on |x| < 0.9 a. Tolerances (of p0): sx 1.5 %, sz 0.6 %, txz 0.7 %
    (nodal averaging at the surface is one-sided); outside the contact, 1.1 a < |x| < 2.4 a,
    1 % of p0 for all three (measured <= 0.41 %, 0.17 %, 0.47 %); the tensile peak 2 mu p0 at
    x = -a is tested separately (slow convergence)."""
    r, hc = model.solve(F=F, rho=rho, mu=mu), hertz(mu=mu)
    sx, sz, txz = hc.surface_stress(r.x_surface)
    inside = np.abs(r.x_surface) < 0.9 * hc.a
    outside = (np.abs(r.x_surface) > 1.1 * hc.a) & (np.abs(r.x_surface) < 2.4 * hc.a)
    assert np.count_nonzero(outside) >= 2 * 25, "both sides of the contact are sampled"
    for name, fe, an, tol in (("sx", r.sx, sx, 1.5e-2), ("sz", r.sz, sz, 6e-3), ("txz", r.txz, txz, 7e-3)):
        err = np.abs(fe - an)[inside].max() / hc.p0
        assert err < tol, f"surface {name} vs seed 002 eqs. 5-7, mu = {mu}: {err:.3g} p0"
        err = np.abs(fe - an)[outside].max() / hc.p0
        assert err < 1e-2, f"surface {name} outside the contact vs seed 002 eqs. 5-7, mu = {mu}: {err:.3g} p0"
    i = np.argmax(r.sx)
    assert -1.15 * hc.a < r.x_surface[i] < -0.95 * hc.a, "tension peak at the trailing edge x = -a"
    assert r.sx[i] == pytest.approx(2 * mu * hc.p0, rel=0.3), "peak 2 mu p0 (slow convergence)"
    assert r.p0 == pytest.approx(hc.p0, rel=3e-3), "similar materials: friction leaves p unchanged"
    # reversing the sliding direction mirrors the field, sx(x) -> sx(-x) (up to the asymmetry
    # of the unstructured mesh)
    rm = model.solve(F=F, rho=rho, mu=mu, sliding=-1)
    np.testing.assert_allclose(rm.sx, r.sx[::-1], atol=5e-3 * hc.p0)


@pytest.mark.parametrize("mu", [0.0, 0.3])
def test_roller_surface_stresses(model, mu):
    """The roller's surface stresses (its own Johnson frame; its friction traction acts in -x
    for sliding = +1, i.e. Hertz direction = -1) vs seed 002 eqs. 5-7. Tolerances (of p0):
    |x| < 0.9 a: sx 1.5 %, sz 0.6 %, txz 1 % (measured 1.3 %, 0.35 %, 0.87 % at mu = 0.3; the
    roller mesh is slightly less regular than the cam's); 1.1 a < |x| < 2.4 a: 1 % (measured
    <= 0.66 %). Tension peak 2 mu p0 at the roller's trailing edge x = +a (slow convergence)."""
    r, hc = model.solve(F=F, rho=rho, mu=mu), hertz(mu=mu, direction=-1)
    s = r.surface_by_body["roller"]
    assert s.body == "roller" and np.all(np.diff(s.x) > 0)
    sx, sz, txz = hc.surface_stress(s.x)
    inside = np.abs(s.x) < 0.9 * hc.a
    outside = (np.abs(s.x) > 1.1 * hc.a) & (np.abs(s.x) < 2.4 * hc.a)
    for name, fe, an, tol in (("sx", s.sx, sx, 1.5e-2), ("sz", s.sz, sz, 6e-3), ("txz", s.txz, txz, 1e-2)):
        err = np.abs(fe - an)[inside].max() / hc.p0
        assert err < tol, f"roller surface {name} vs seed 002 eqs. 5-7, mu = {mu}: {err:.3g} p0"
        err = np.abs(fe - an)[outside].max() / hc.p0
        assert err < 1e-2, f"roller surface {name} outside the contact, mu = {mu}: {err:.3g} p0"
    np.testing.assert_allclose(s.sy, 0.3 * (s.sx + s.sz), rtol=1e-12, err_msg="plane strain sy")
    cam = r.surface_by_body["cam"]
    np.testing.assert_array_equal(cam.sx, r.sx)  # the cam's are also the top-level arrays
    if mu > 0:
        i = np.argmax(s.sx)
        assert 0.95 * hc.a < s.x[i] < 1.15 * hc.a, "roller tension peak at its trailing edge x = +a"
        assert s.sx[i] == pytest.approx(2 * mu * hc.p0, rel=0.3)


def hertz_extrema(hc, body="cam"):
    """Signed extrema of sx, sz, sy of the Hertz field (femcam.hertz, McEwen / seed 002) over the
    FE stress window |x| <= 2.5 a, 0 <= z <= 2 a (grid a/400 x a/40): {key: (value, x, z)}."""
    X, Z = np.meshgrid(np.linspace(-2.5, 2.5, 2001) * hc.a, np.linspace(0.0, 2.0, 81) * hc.a)
    f = hc.stress(X, Z, body=body)
    out = {}
    for c in ("sx", "sz", "sy"):
        v = getattr(f, c)
        for kind, fn in (("max", np.argmax), ("min", np.argmin)):
            i = np.unravel_index(fn(v), v.shape)
            out[f"{c}_{kind}"] = (float(v[i]), float(X[i]), float(Z[i]))
    return out


@pytest.mark.parametrize("mu", [0.0, 0.3])
def test_stress_extrema_vs_hertz(model, mu):
    """Signed maxima/minima of sx, sz, sy with locations vs the Hertz field's extrema over the
    same window. Tolerances (of p0): sz_min = -p0 at (0, 0): 0.5 % (measured -1.0004 p0); sx_min
    (-p0 at x = 0; -1.166 p0 at x = 0.51 a for mu = 0.3): 1.5 %, one-sided surface averaging as
    for the surface sx (measured 1.0 %, 0.9 %); sy_min = nu (sx + sz): 1 % (measured 0.3 %);
    locations within 0.1 a. sx_max: no tension without friction (Hertz 0; FE noise <= 1 % p0,
    measured 0.5 %); with mu = 0.3 the trailing-edge peak 2 mu p0 at x = -a, z = 0 (cam) and
    x = +a (roller) within 30 % (measured -22 %, converging as h^0.5; slow test)."""
    r, p0, a = model.solve(F=F, rho=rho, mu=mu), float(hertz().p0), float(hertz().a)
    for body, direction in (("cam", 1), ("roller", -1)):
        ref = hertz_extrema(hertz(mu=mu, direction=direction), body)
        m = r.max_by_body[body]
        for key, tol in (("sz_min", 5e-3), ("sx_min", 1.5e-2), ("sy_min", 1e-2)):
            v, x, z = ref[key]
            assert m[key].value == pytest.approx(v, abs=tol * p0), f"{body} {key} vs Hertz {v / p0:.4f} p0"
            assert m[key].x == pytest.approx(x, abs=0.1 * a) and m[key].z == pytest.approx(z, abs=0.1 * a)
            assert m[key].body == body
        sx_max = m["sx_max"]
        if mu == 0:
            assert ref["sx_max"][0] <= 1e-9 * p0, "Hertz: no tension without friction"
            assert sx_max.value < 1e-2 * p0
        else:
            v, x, z = ref["sx_max"]
            assert v == pytest.approx(2 * mu * p0, rel=1e-6)
            assert x == pytest.approx(-direction * a, abs=1e-9 * a)
            assert sx_max.value == pytest.approx(v, rel=0.3), f"{body} trailing-edge tension 2 mu p0"
            # z: surface node (P2 midside nodes sit on the chords, ~1e-6 a below the arc)
            assert 0.95 * a < -direction * sx_max.x < 1.15 * a and sx_max.z < 1e-3 * a
    # over both bodies: the extreme of the per-body extremes
    for key in ("sx_max", "sz_max", "sy_max"):
        assert getattr(r, key).value == max(r.max_by_body[b][key].value for b in ("cam", "roller"))
    for key in ("sx_min", "sz_min", "sy_min"):
        assert getattr(r, key).value == min(r.max_by_body[b][key].value for b in ("cam", "roller"))
    assert r.sz_min.value == pytest.approx(-p0, rel=5e-3), "sz min = -p0 (Hertz)"


def test_reuse_with_other_rho(model):
    """Mesh built for rho_ref = 20 mm, gap with the true rho = 15 mm: compare with Hertz(rho)."""
    hc = hertz(rho=0.015)
    assert model.covers(F, 0.015)
    r = model.solve(F=F, rho=0.015)
    assert r.p0 == pytest.approx(hc.p0, rel=3e-3)
    assert r.a == pytest.approx(hc.a, rel=1e-2)


def test_coverage_refusal(model):
    assert not model.covers(F, -0.03), "curvature change too large for the cam mesh"
    assert not model.covers(20 * F, rho), "a leaves a_range"
    with pytest.raises(PhysicsError, match="rebuild"):
        model.solve(F=20 * F, rho=rho)
    with pytest.raises(PhysicsError, match="concave"):
        model.solve(F=F, rho=-0.009, check=False)
    with pytest.raises(PhysicsError, match="fine zone"):
        model.solve(F=12 * F, rho=rho, check=False)  # a = 3.5 a_ref > 2.5 a_ref


def test_zero_load(model):
    r = model.solve(F=0.0, rho=rho)
    assert r.a == 0.0 and r.p0 == 0.0 and r.force == 0.0
    assert np.all(r.p == 0.0) and r.von_mises_max.value == 0.0
    assert np.all(np.isfinite(r.sx)) and np.all(r.sx == 0.0)


@pytest.mark.parametrize("kw, word", [
    (dict(F=-1.0, rho=rho), "F"), (dict(F=F, rho=0.0), "rho"), (dict(F=F, rho=rho, mu=-0.1), "mu"),
    (dict(F=F, rho=rho, sliding=0), "sliding"), (dict(F=math.nan, rho=rho), "F"),
])
def test_bad_input(model, kw, word):
    with pytest.raises(InputError, match=word):
        model.solve(**kw)


def test_bad_build_input():
    with pytest.raises(InputError, match="plane"):
        ContactModel.build(Rr=Rr, rho_ref=rho, cam=STEEL, roller=STEEL, length=l, a_ref=1e-4, plane="x")
    with pytest.raises(InputError, match="ordering"):
        SolverOptions(ordering="METIS")


# ---------------------------------------------------------------------------------- hard cases
COARSE = MeshOptions(a_over_h=12)


def check_hertz(r, hc, tol_p0=5e-3, tol_a=1e-2):
    assert r.converged and r.force == pytest.approx(r.F, rel=1e-10)
    assert r.p0 == pytest.approx(float(hc.p0), rel=tol_p0)
    assert r.a == pytest.approx(float(hc.a), rel=tol_a)


def test_tiny_load():
    """a/R = 1e-4: the mesh spans four decades of element size (h = a/12 to L/8)."""
    R = 1 / (1 / rho + 1 / Rr)
    Fs = 1.0 * (1e-4 * R) ** 2 * math.pi * hertz().E_star / (4 * R) * l  # F giving a = 1e-4 R
    r = solve_contact(Fs, rho, Rr, STEEL, STEEL, l, mesh=COARSE)
    hc = hertz(F=Fs)
    assert float(hc.a) / R == pytest.approx(1e-4, rel=1e-9)
    check_hertz(r, hc)


def test_nearly_incompressible():
    m = Material(E=210e9, nu=0.49)
    r = solve_contact(F, rho, Rr, m, m, l, mesh=COARSE)
    check_hertz(r, hertz(cam=m, roller=m))


def halfspace_bem(F, rho, cam, roller, mu, sliding, L, n):
    """Independent reference: two elastic half-spaces (Johnson 1985 eqs. 2.18-2.19, plane strain)
    with piecewise-constant pressure on n cells over |x| <= L, collocation at cell centres.

    Surface displacement into a body: normal load ``-(2 (1-nu^2) / (pi E)) int p ln|x-s| ds``,
    tangential traction Q_x ``+C int Q_x sgn(x - s) ds``, ``C = (1-2nu)(1+nu)/(2E)`` (sign by
    Betti reciprocity with the inward surface drag under a normal load). Friction q = mu p acts
    on the cam in +sliding x and on the roller in -sliding x, so the gap gets
    ``(C_cam - C_roller) sliding mu int p sgn(x - s) ds``.
    """
    from femcam.fe.contact import solve_lcp
    from femcam.materials import effective_modulus
    from femcam.mesh import surface_height

    d = 2 * L / n
    xc = -L + d * (np.arange(n) + 0.5)
    t1 = xc[:, None] - (xc[None, :] - d / 2)
    t2 = xc[:, None] - (xc[None, :] + d / 2)

    def G(t):  # antiderivative of ln|t|
        return t * np.log(np.abs(t)) - t

    Lg = G(t1) - G(t2)
    S = np.where(np.abs(t1) < d, 0.0, np.sign(t1) * d)  # own cell: 0 at its centre
    Es = effective_modulus(cam, roller, "strain")

    def C(m):
        return (1 - 2 * m.nu) * (1 + m.nu) / (2 * m.E)

    A = -(2 / (np.pi * Es)) * Lg + (C(cam) - C(roller)) * sliding * mu * S
    h0 = surface_height(xc, Rr) + surface_height(xc, rho)
    s = solve_lcp(A, h0, np.full(n, d), F / l, active0=np.abs(xc) < L / 2)
    return xc, s.p


def test_polymer_roller_and_friction_coupling():
    """E ratio 1:100 (polymer roller). Frictionless: Hertz. With mu = 0.3 the normal-tangential
    coupling of dissimilar materials (Dundurs beta != 0) shifts the pressure towards +x
    (sliding = +1): compared with an independent half-space BEM (measured centroid shift FE
    0.060 a, BEM 0.057 a at a/h = 20)."""
    poly = Material(E=2.1e9, nu=0.35)
    Fp = 150.0
    hc = hertz(F=Fp, roller=poly)
    a = float(hc.a)
    model = ContactModel.build(Rr=Rr, rho_ref=rho, cam=STEEL, roller=poly, length=l, a_ref=a,
                               mesh=COARSE)
    r0 = model.solve(F=Fp, rho=rho)
    check_hertz(r0, hc)
    assert abs(r0.x0) < 1e-3 * r0.a
    r = model.solve(F=Fp, rho=rho, mu=0.3)
    assert r.force == pytest.approx(Fp, rel=1e-10)
    xb, pb = halfspace_bem(Fp, rho, STEEL, poly, 0.3, 1, 2.5 * a, 500)
    shift_bem = np.sum(xb * pb) / np.sum(pb)
    shift_fe = np.sum(r.x * r.p) / np.sum(r.p)
    xh, ph = halfspace_bem(Fp, rho, STEEL, poly, 0.0, 1, 2.5 * a, 500)
    assert ph.max() == pytest.approx(hc.p0, rel=2e-3), "BEM reproduces Hertz without friction"
    assert shift_bem > 0.02 * a
    assert shift_fe == pytest.approx(shift_bem, abs=0.006 * a), "pressure centroid vs half-space BEM"
    assert np.sqrt(np.mean((r.p - np.interp(r.x, xb, pb)) ** 2)) < 1.5e-2 * hc.p0
    rs = model.solve(F=Fp, rho=rho, mu=0.3, sliding=-1)
    assert rs.x0 == pytest.approx(-r.x0, rel=1e-3), "opposite sliding mirrors the shift"


def test_similar_materials_no_coupling():
    """Dundurs beta = 0 for identical materials: friction does not move the pressure."""
    r = solve_contact(F, rho, Rr, STEEL, STEEL, l, mu=0.3, mesh=COARSE)
    assert abs(r.x0) < 2e-3 * r.a


def test_flat_cam():
    r = solve_contact(F, math.inf, Rr, STEEL, STEEL, l, mesh=COARSE)
    check_hertz(r, hertz(rho=math.inf))


def test_concave_cam():
    r = solve_contact(F, -0.03, Rr, STEEL, STEEL, l, mesh=COARSE)
    check_hertz(r, hertz(rho=-0.03))


def test_nearly_conformal_concave():
    """|rho| = 1.02 Rr: R = 51 Rr, a = 0.092 Rr. Hertz still applies (a / min radius <= 0.1,
    not flagged); the FE answers (equilibrium, symmetry) and stays within 2 % of Hertz p0 and a
    (measured +0.55 %, +0.7 %; small-slope gap, finite roller)."""
    r = solve_contact(F, -1.02 * Rr, Rr, STEEL, STEEL, l, mesh=MeshOptions(a_over_h=10, fine_half_width=1.5))
    hc = hertz(rho=-1.02 * Rr)
    assert bool(hc.valid) and not r.outside_hertz
    assert r.converged and r.force == pytest.approx(F, rel=1e-10)
    assert abs(r.x0) < 1e-3 * r.a
    np.testing.assert_allclose(r.p, r.p[::-1], atol=1e-3 * r.p0)  # mesh asymmetry only
    assert r.p0 == pytest.approx(float(hc.p0), rel=2e-2)
    assert r.a == pytest.approx(float(hc.a), rel=2e-2)


def test_conformal_outside_hertz_validity_answered_by_fe():
    """rho = -1.005 Rr: 1/R = 1/Rr - 1/(1.005 Rr) > 0, so Hertz does not refuse (only |rho| <= Rr
    is refused), but its a = 0.182 Rr is outside its validity (a / Rr > 0.1: warned, valid =
    False). The FE (default a_ref = Hertz a, no manual grading) returns an equilibrated,
    symmetric pressure flagged outside_hertz. Against the Hertz formulas typed here (Johnson
    eq. 4.45: a = sqrt(4 w R / (pi E*)), p0 = 2 w / (pi a)): a within 3 %, p0 within 3.5 %
    (measured -1.7 %, +2.4 % at a/h = 10; a -1.1 % at a/8, -2.0 % at a/12: the difference is
    the finite roller and the small-slope gap at a/R_min = 0.18, not discretisation)."""
    from femcam.hertz import HertzValidityWarning
    from femcam.materials import effective_modulus

    rr = -1.005 * Rr
    with pytest.warns(HertzValidityWarning):
        hc = LineContact(F=F, length=l, R1=rr, R2=Rr, cam=STEEL, roller=STEEL)
    assert not bool(hc.valid), "flagged, not refused"
    R = 1.0 / (1.0 / rr + 1.0 / Rr)
    w = F / l
    a_h = math.sqrt(4 * w * R / (math.pi * effective_modulus(STEEL, STEEL, "strain")))
    p0_h = 2 * w / (math.pi * a_h)
    assert a_h / Rr == pytest.approx(0.1824, rel=1e-3)
    r = solve_contact(F, rr, Rr, STEEL, STEEL, l, mesh=MeshOptions(a_over_h=10))
    assert r.outside_hertz and r.converged
    assert r.force == pytest.approx(F, rel=1e-10)
    np.testing.assert_allclose(r.p, r.p[::-1], atol=1e-3 * r.p0)  # mesh asymmetry only
    assert r.a == pytest.approx(a_h, rel=3e-2), "FE a vs Hertz a = sqrt(4wR/(pi E*))"
    assert r.p0 == pytest.approx(p0_h, rel=3.5e-2), "FE p0 vs Hertz p0 = 2w/(pi a)"


def test_huge_load_flagged():
    """a ~ 0.12 R: solved but flagged outside Hertz validity (a / min radius > 0.1)."""
    r = solve_contact(200e3, rho, Rr, STEEL, STEEL, l, mesh=COARSE)
    assert r.outside_hertz and r.converged
    assert r.force == pytest.approx(200e3, rel=1e-10)


def test_load_too_large_refused():
    with pytest.raises(InputError, match=r"^\[materials\.\*\] E_GPa, nu, \[follower\] roller_radius_mm = .* "
                                         "Hertz contact half-width \\(a_ref\\) of"):
        solve_contact(2e6, rho, Rr, STEEL, STEEL, l, mesh=COARSE)


def test_plane_stress():
    """Thin disc: E* with E instead of E/(1-nu^2) (Johnson 1985 §4.3 note; hertz plane='stress')."""
    r = solve_contact(F, rho, Rr, STEEL, STEEL, l, mesh=COARSE, plane="stress")
    hc = LineContact(F=F, length=l, R1=rho, R2=Rr, cam=STEEL, roller=STEEL, plane="stress")
    check_hertz(r, hc)


def test_linear_elements():
    """P1 (for comparison) converges to the same Hertz answer, less accurately."""
    r = solve_contact(F, rho, Rr, STEEL, STEEL, l, mesh=MeshOptions(a_over_h=16), element="P1")
    check_hertz(r, hertz(), tol_p0=1e-2, tol_a=2e-2)
