"""Mesh-convergence and finite-body studies of the FE contact solver (slow).

Reference: Hertz line contact (Johnson 1985 eq. 4.45, McEwen 1949 subsurface field; seed 002
eqs. 5-7 for the friction surface stress). Slopes are fitted as
``np.polyfit(log h, log |err|, 1)`` over a/h = 10, 14, 20, 28, and the finest level a/h = 28
must meet: p0 0.15 %, a 1 %, rms(p - Hertz) 0.5 % of p0 (the issue's rms target; measured
0.42 % at a/28, first met at a/24, see docs/fe.md), trailing-edge peak 25 %.
"""

import numpy as np
import pytest

from femcam.fe import ContactModel, MeshOptions, SolverOptions
from femcam.hertz import LineContact
from femcam.materials import STEEL

Rr, rho, F, l = 0.01, 0.02, 1500.0, 0.01
HC = LineContact(F=F, length=l, R1=rho, R2=Rr, cam=STEEL, roller=STEEL)
LEVELS = (10, 14, 20, 28)


def build(**mesh):
    return ContactModel.build(Rr=Rr, rho_ref=rho, cam=STEEL, roller=STEEL, length=l,
                              a_ref=float(HC.a), mesh=MeshOptions(**mesh),
                              solver=SolverOptions(kappa_tol=1e9))


@pytest.fixture(scope="module")
def study():
    out = []
    for n in LEVELS:
        m = build(a_over_h=n)
        r = m.solve(F=F, rho=rho)
        rf = m.solve(F=F, rho=rho, mu=0.3)
        out.append({
            "h": 1.0 / n,
            "p0": abs(r.p0 / HC.p0 - 1),
            "a": abs(r.a / HC.a - 1),
            "rms": float(np.sqrt(np.mean((r.p - HC.pressure(r.x)) ** 2)) / HC.p0),
            "peak": abs(rf.sx.max() / (0.6 * HC.p0) - 1),  # 2 mu p0 at x = -a (seed 002 eq. 7)
        })
    return out


def slope(study, key):
    h = np.array([s["h"] for s in study])
    e = np.array([s[key] for s in study])
    return np.polyfit(np.log(h), np.log(e), 1)[0]


@pytest.mark.slow
@pytest.mark.parametrize("key, lo, hi, finest", [
    ("p0", 1.3, 2.8, 1.5e-3),   # measured slope ~1.9, 6.6e-5 at a/h = 28
    ("a", 1.3, 2.8, 1e-2),      # measured ~1.9 (fit of p^2 to an ellipse)
    ("rms", 0.7, 1.5, 5e-3),    # measured ~1.0, 0.42 % at a/28: the edge nodes dominate (sqrt edge)
    ("peak", 0.3, 0.9, 0.25),   # measured ~0.45, -18 % at a/28: trailing-edge tension, ~sqrt(h) rate
])
def test_convergence_slopes(study, key, lo, hi, finest):
    s = slope(study, key)
    assert lo <= s <= hi, f"{key}: convergence slope {s:.2f} vs Hertz outside [{lo}, {hi}]"
    assert study[-1][key] <= finest, f"{key} error at a/h = 28 vs Hertz"
    assert study[-1][key] < study[0][key]


@pytest.mark.slow
def test_finite_body_effect_decays():
    """tau1 max - Hertz shrinks as the bodies grow (domain L/a = 15, 60, full ~ 95 a)."""
    errs = []
    for d in (15, 60, None):
        r = build(domain_over_a=d).solve(F=F, rho=rho)
        errs.append(abs(r.tau1_max.value / HC.max_shear().value - 1))
    assert errs[0] > errs[-1]
    assert errs[-1] < 2e-2
