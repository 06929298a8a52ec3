"""Tests of femcam.synthesis (seed 003 potential-energy FE cam synthesis).

Independent references: the closed-form 3-4-5 polynomial written out here (not femcam's
kinematics), the analytic knife-edge pressure angle atan(s'/(Rb + s)), central finite
differences of the discrete energy/residual, and a brentq root for the smallest base circle.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from femcam.errors import ConvergenceError, InputError
from femcam.synthesis import (
    PressureAngleError,
    SynthesisOptions,
    compare_direct,
    seed003_program,
    synthesize_knife_edge,
)
from femcam.synthesis import pefem as P  # noqa: N812

H, RB = 3e-3, 5e-3
B1, B2, B3 = np.radians([120.0, 90.0, 90.0])


def law345(theta):
    """Seed 003 case written out by hand: 3-4-5 rise/fall (Norton eq. 8.24), s, s', s''."""
    th = np.mod(np.asarray(theta, float), 2 * np.pi)
    s, s1, s2 = (np.zeros_like(th) for _ in range(3))
    for start, beta, sign, base in ((0.0, B1, 1.0, 0.0), (B1 + B2, B3, -1.0, H)):
        m = (th >= start) & (th < start + beta)
        u = (th[m] - start) / beta
        s[m] = base + sign * H * (10 * u**3 - 15 * u**4 + 6 * u**5)
        s1[m] = sign * H * (30 * u**2 - 60 * u**3 + 30 * u**4) / beta
        s2[m] = sign * H * (60 * u - 180 * u**2 + 120 * u**3) / beta**2
    s[(th >= B1) & (th < B1 + B2)] = H
    return s, s1, s2


@pytest.fixture(scope="module")
def solved():
    """Seed 003 case, 180 elements, k = 1e6, mu = 1 (the CLI default)."""
    return synthesize_knife_edge(seed003_program(), Rb=RB, options=SynthesisOptions(n_elements=180))


# ----------------------------------------------------------------------------- derivatives
@pytest.mark.parametrize("kind", ["sauer", "eq12"])
def test_tangent_and_residual_match_finite_differences(kind):
    """K = dR/du and R = dPi/du against central differences on a distorted curve."""
    D = P._Discretisation(8, 3)
    rng = np.random.default_rng(3)
    u = D.X * (1 + 0.3 * np.sin(3 * D.xi_nodes))[:, None] + 0.02 * rng.standard_normal(D.X.shape)

    def law(a):
        return tuple(v / RB for v in law345(a))

    Pi, R, (K, _) = P._evaluate(u, D, law, 1e3, 2.0, kind)
    n, h = R.size, 1e-6
    J, g = np.zeros((n, n)), np.zeros(n)
    for i in range(n):
        up, um = u.ravel().copy(), u.ravel().copy()
        up[i] += h
        um[i] -= h
        Ep, Rp, _ = P._evaluate(up.reshape(-1, 2), D, law, 1e3, 2.0, kind, False)
        Em, Rm, _ = P._evaluate(um.reshape(-1, 2), D, law, 1e3, 2.0, kind, False)
        J[:, i], g[i] = (Rp - Rm) / (2 * h), (Ep - Em) / (2 * h)
    assert np.abs(J - K.toarray()).max() / np.abs(J).max() < 1e-6, "tangent != FD Jacobian"
    assert np.abs(g - R).max() / np.abs(R).max() < 1e-6, "residual != FD gradient of Pi"


def test_paper_b_vector_is_gradient_of_the_folded_acos_angle():
    """Seed 003 eqs. 2, 16-17: b = d + B r, c1 = y_o'/sqrt(1 - cos^2 alpha), alpha = acos(d.x1).
    FD references: b is the gradient of e with the *folded* angle acos (mirror-symmetric about
    x, so a 360 deg program cannot be represented); it differs from the gradient of e with the
    polar angle atan2 (used by femcam) in the lower half plane."""
    def yo(a):
        return 0.1 * np.sin(a) + 0.05 * np.cos(2 * a)

    def yo1(a):
        return 0.1 * np.cos(a) - 0.1 * np.sin(2 * a)

    def e_atan2(x):
        return np.hypot(*x) - 1.0 - yo(np.arctan2(x[1], x[0]))

    def e_acos(x):
        return np.hypot(*x) - 1.0 - yo(np.arccos(x[0] / np.hypot(*x)))

    def fd(f, x, h=1e-7):
        return np.array([(f(x + h * ei) - f(x - h * ei)) / (2 * h) for ei in np.eye(2)])

    for alpha in (1.0, -1.0):
        x = 1.2 * np.array([np.cos(alpha), np.sin(alpha)])
        rho = np.hypot(*x)
        d = x / rho
        B = (np.eye(2) - np.outer(d, d)) / rho
        a = math.acos(d[0])                          # eq. 2
        c1 = yo1(a) / math.sqrt(1 - math.cos(a) ** 2)
        b_paper = d + B @ (x + c1 * np.array([1.0, 0.0]))
        assert np.allclose(b_paper, fd(e_acos, x), atol=1e-7)
        assert np.allclose(b_paper, fd(e_atan2, x), atol=1e-7) == (alpha > 0)


# ----------------------------------------------------------------------------- Newton
def test_quadratic_convergence_in_last_iterations():
    res = synthesize_knife_edge(seed003_program(), Rb=RB,
                                options=SynthesisOptions(n_elements=60, k=1e4))
    r = np.array(res.residual_history)
    assert res.extras["modes"][-3:] == ("newton",) * 3
    # last step: r_{n} <= C r_{n-1}^2 with a bounded C, and a drop of many decades
    assert r[-1] / r[-2] ** 2 < 1.0, r[-4:]
    assert r[-1] < 1e-4 * r[-2], r[-4:]
    assert r[-1] <= 1e-10 * r[0]


def test_failing_newton_raises_with_history():
    with pytest.raises(ConvergenceError) as ei:
        synthesize_knife_edge(seed003_program(), Rb=RB,
                              options=SynthesisOptions(n_elements=30, max_iter=1, k_factor=1))
    assert len(ei.value.history) == 2 and ei.value.history[0] > ei.value.history[1] > 0
    assert "did not converge in 1 iterations" in str(ei.value)


# ----------------------------------------------------------------------------- accuracy
def test_reproduces_345_law_with_mesh_refinement():
    """Max |r - Rb - s_exact| at 8 points per element shrinks ~h^3 (k/mu = 1e8)."""
    errs = []
    ns = (45, 90, 180)
    for n in ns:
        res = synthesize_knife_edge(seed003_program(), Rb=RB,
                                    options=SynthesisOptions(n_elements=n, k=1e8))
        errs.append(np.max(np.abs(res.r - RB - law345(res.theta)[0])))
    slope = np.polyfit(np.log(ns), np.log(errs), 1)[0]
    assert errs[0] > errs[1] > errs[2], errs
    assert slope < -2.5, (slope, errs)
    assert errs[-1] < 5e-8, "180 elements: error < 5e-5 mm (seed 003 prints 5.4363e-5 mm)"


def test_pressure_angle_matches_analytic_knife_edge(solved):
    s, s1, _ = law345(solved.theta)
    phi_ref = np.arctan2(s1, RB + s)                 # Norton eq. 8.31, e = 0
    assert np.max(np.abs(solved.phi - phi_ref)) < math.radians(0.1)   # C0 tangent, O(h^2)
    th = np.linspace(0, 2 * np.pi, 400001)
    s, s1, _ = law345(th)
    phimax_ref = np.max(np.abs(np.arctan2(s1, RB + s)))
    assert math.degrees(phimax_ref) == pytest.approx(29.4366, abs=1e-3)
    assert solved.phi_max == pytest.approx(phimax_ref, abs=math.radians(0.02))
    assert solved.phi_max <= math.radians(30.0)


def test_base_circle_for_30_degrees():
    """Smallest Rb with phi_max <= 30 deg: closed-form root (independent of femcam) 4.8602 mm."""
    th = np.linspace(0, 2 * np.pi, 200001)
    s, s1, _ = law345(th)
    Rb30 = brentq(lambda Rb: np.max(np.abs(np.arctan2(s1, Rb + s))) - math.radians(30), 1e-3, 1e-2,
                  xtol=1e-12)
    assert Rb30 == pytest.approx(4.8602e-3, abs=1e-7)
    assert RB > Rb30, "seed 003's Rb = 5 mm satisfies the 30 deg rule"


def test_compare_with_direct_profile(solved):
    c = compare_direct(solved, seed003_program())
    s = law345(solved.theta)[0]
    assert c.max_radius_deviation == pytest.approx(np.max(np.abs(solved.r - RB - s)), rel=1e-6)
    assert c.max_radius_deviation < 5e-8
    assert c.phi_max_direct == pytest.approx(math.radians(29.4366), abs=math.radians(1e-3))


def test_sauer_vs_eq12_stabilisation_same_curve():
    opts = dict(n_elements=60, k=1e8)
    a = synthesize_knife_edge(seed003_program(), Rb=RB, options=SynthesisOptions(**opts))
    b = synthesize_knife_edge(seed003_program(), Rb=RB,
                              options=SynthesisOptions(stabilization="eq12", **opts))
    s = law345(b.theta)[0]
    assert np.max(np.abs(b.r - RB - s)) < 1e-6          # both reproduce the law
    assert np.max(np.abs(a.r - RB - law345(a.theta)[0])) < 1e-6


# ----------------------------------------------------------------------------- hard cases
def test_small_base_circle_refused_with_reason():
    with pytest.raises(PressureAngleError, match=r"8\d\.\d+ deg > phi_limit = 80\.00 deg"):
        synthesize_knife_edge(seed003_program(), Rb=1e-5)
    with pytest.raises(PressureAngleError, match="increase the base circle"):
        synthesize_knife_edge(seed003_program(), Rb=4.5e-3,
                              options=SynthesisOptions(phi_limit=math.radians(30.0)))


def test_very_large_k_converges_or_fails_clearly():
    """k/mu = 1e12: condition estimate ~ k/mu; either converged or a ConvergenceError."""
    try:
        res = synthesize_knife_edge(seed003_program(), Rb=RB,
                                    options=SynthesisOptions(n_elements=60, k=1e12))
    except ConvergenceError as exc:
        assert "did not converge" in str(exc) and "k = 1e+12" in str(exc)
        assert len(exc.history) > 10 and np.all(np.isfinite(exc.history))
    else:
        assert res.condition_estimate > 1e11
        assert np.max(np.abs(res.r - RB - law345(res.theta)[0])) < 1e-6


def test_many_elements_converge():
    res = synthesize_knife_edge(seed003_program(), Rb=RB,
                                options=SynthesisOptions(n_elements=2000, k=1e6))
    assert res.converged and res.nodes.shape == (4000, 2)
    assert np.max(np.abs(res.r - RB - law345(res.theta)[0])) < 1e-8


def test_input_validation():
    with pytest.raises(InputError, match="n_elements"):
        SynthesisOptions(n_elements=2)
    with pytest.raises(InputError, match="mu = -1"):
        SynthesisOptions(mu=-1)
    with pytest.raises(InputError, match=r"Rb = -0\.005 m"):
        synthesize_knife_edge(seed003_program(), Rb=-5e-3)
    with pytest.raises(InputError, match="stabilization"):
        SynthesisOptions(stabilization="nope")


# ----------------------------------------------------------------------------- CLI
def test_cli_writes_csv_and_png(tmp_path):
    import csv

    from femcam.cli import main

    out = tmp_path / "o"
    assert main(["synth", "--case", "seed003", "--out", str(out), "--elements", "60"]) == 0
    with open(out / "synth_curve.csv") as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    assert rows[0][:6] == ["theta_deg", "r_mm", "x_mm", "y_mm", "error_mm", "phi_deg"]
    data = np.array(rows[1:], float)
    s = law345(np.radians(data[:, 0]))[0]
    assert np.max(np.abs(data[:, 1] - 5.0 - s * 1e3)) < 1e-3          # mm
    assert np.allclose(np.hypot(data[:, 2], data[:, 3]), data[:, 1], rtol=1e-9)
    assert (out / "synth_curve.png").stat().st_size > 1000
    assert main(["synth", "--out", str(out)]) == 1                    # neither scene nor case


def test_plain_newton_fold_is_refused_not_returned():
    """The paper's plain Newton (full steps from the base circle, no line search) at k = 1e4
    with 60 elements either lands on a folded curve (a saddle of Pi) or wanders without
    converging; which of the two depends on round-off in the first steps (the BLAS kernel).
    Both must raise with the residual history, never return a wrong curve."""
    with pytest.raises(ConvergenceError, match="folded curve|did not converge") as ei:
        synthesize_knife_edge(seed003_program(), Rb=RB,
                              options=SynthesisOptions(n_elements=60, k=1e4, line_search=False))
    assert len(ei.value.history) > 2


def test_curve_depends_on_k_over_mu_only():
    """Pi(k, mu) = mu Pi(k/mu, 1): the minimiser depends on k/mu only (seed 003 Figs. 8-9)."""
    a = synthesize_knife_edge(seed003_program(), Rb=RB,
                              options=SynthesisOptions(n_elements=60, k=1e4, mu=1.0))
    b = synthesize_knife_edge(seed003_program(), Rb=RB,
                              options=SynthesisOptions(n_elements=60, k=1e6, mu=100.0))
    assert np.allclose(a.nodes, b.nodes, atol=1e-12)
    # and the penalty error scales like mu/k while it dominates (k/mu = 1e2 -> 1e3)
    e = [synthesize_knife_edge(seed003_program(), Rb=RB,
                               options=SynthesisOptions(n_elements=60, k=q)).max_error
         for q in (1e2, 1e3)]
    assert e[0] / e[1] == pytest.approx(10.0, rel=0.1)
