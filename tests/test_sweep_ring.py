"""Issue 24 item 3 for the real bodies: a roller on a pin or needles answers the sweep's headline
from the ring model (femcam.sweep.ringhead); finite-length names that cannot be confused.

References written here, never femcam output:

* Hertz line contact of the SOLID roller written out (Johnson 1985 eqs. 4.43-4.45):
  ``a = sqrt(4 w R / (pi E*))``, ``p0 = 2 w / (pi a)``, plane strain, steel on steel;
* a ring much thicker than the contact on a tight pin of its own material is a solid roller
  (Saint-Venant: the bore is 7 mm = 65 a from the contact), so its p0 is that Hertz value;
* the ring on needles: a thin wall (1 mm, 20 needles) bends between the needles and carries the
  cam with a softer ring than a solid roller, so its p0 is LOWER than the solid Hertz value
  (thin-ring bending, Roark's ring under radial loads); the value is checked against a ring
  model built here on a different mesh (n_bore 192 against the sweep's 128, fine zone a/h = 30
  against 20), whose solve is itself tested against Roark, Stribeck and the thick-ring limit
  (tests/test_bodies_ring.py, tests/test_bodies_needles.py).
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from femcam.bodies import RingMeshOptions, RingModel, solve_ring
from femcam.bodies.rows import bearing_from
from femcam.mesh import MeshOptions
from femcam.scene import load_scene
from femcam.sweep import RunOptions, SweepOptions, sweep
from femcam.sweep.extras import extra_columns
from femcam.sweep.headline import answered_by, omitted_physics

EX = Path(__file__).resolve().parents[1] / "examples"
E, NU = 210e9, 0.3
THETA_DEG = 44.0   # the seed 002 cam's peak contact force


def _hertz(F, length, rho, Rr):
    """Johnson 1985 eqs. 4.43-4.45, plane strain, steel on steel: (a, p0) of the solid roller."""
    E_star = E / (2 * (1 - NU**2))
    R = 1 / (1 / rho + 1 / Rr)
    w = F / length
    a = math.sqrt(4 * w * R / (math.pi * E_star))
    return a, 2 * w / (math.pi * a)


def _variant(tmp_path, **keys) -> Path:
    """The needle-roller example with ``[follower]`` keys replaced (``None`` drops a key)."""
    text = (EX / "seed002_needle_roller.toml").read_text()
    for k, v in keys.items():
        pat = re.compile(rf"^{k}\s*=.*$", re.M)
        text = pat.sub("" if v is None else f"{k} = {v!r}".replace("'", '"'), text)
    path = tmp_path / "ring.toml"
    path.write_text(text)
    return path


@pytest.mark.slow
def test_thick_ring_on_a_tight_pin_gives_the_solid_roller(tmp_path):
    """Ri = 0.3 Ro on a pin of the ring's steel, 1 um clearance: the headline p0 (model
    ``hertz+ring`` and ``fe_arc+ring``) within 0.5 % of the solid roller's Hertz p0 (measured
    +0.03 %), a within 1 % (measured +0.24 %).

    Error estimates (femcam.sweep.ringhead.ring_estimate): both rows carry the ring model's own
    two-level estimate (ring_level_estimate) to the ring mesh's a/h (20 at the peak force, the
    ring model's default fine zone); against the true error vs that Hertz p0 (the tight thick
    ring is the solid roller) its effectivity is within the homogeneous rows' band 0.5-3
    (tests/test_sweep_estimate.py; measured 0.93); the hertz+ring row's stresses are Hertz's
    shape factors: NaN estimates."""
    path = _variant(tmp_path, roller_support="pin", roller_bore_mm=3.0, pin_radius_mm=2.999,
                    pin_clearance_um=1.0, needle_count=None, needle_radius_mm=None)
    sc = load_scene(path)
    for method in ("hertz", "fe"):
        r = sweep(sc,
                  SweepOptions(angles=np.radians([THETA_DEG]), a_over_h=6, method=method),
                  RunOptions(workers=1))
        assert r["model"][0] == f"{'hertz' if method == 'hertz' else 'fe_arc'}+ring"
        a_h, p0_h = _hertz(float(r["Fc"][0]), sc.length, float(r["rho"][0]), 0.010)
        assert r["p0_fe"][0] == pytest.approx(p0_h, rel=5e-3), "tight thick ring = solid roller"
        assert r["a_fe"][0] == pytest.approx(a_h, rel=1e-2)
        assert r["err_p0"][0] == pytest.approx(r["p0_fe"][0] / p0_h - 1, abs=1e-12)
        assert r["wear_source"][0] == "ring"
        assert np.isfinite(r["ring_pin_p0"][0]) and "ring_p0" not in r.table
        assert r["a_over_h_row"][0] == pytest.approx(20.0, rel=2e-2), "the ring mesh's a/h"
        # the ring model's own two-level estimate answers p0 and a on both rows (it answers
        # p0_fe); the stresses of a hertz+ring row are Hertz's shape factors: no estimate
        true = abs(r["p0_fe"][0] / p0_h - 1)
        assert 0.5 <= r["err_est_p0"][0] / true <= 3.0, (r["err_est_p0"][0], true)
        assert 0.0 < r["err_est_bore_hoop"][0] < 0.1 and 0.0 < r["err_est_pin_p0"][0] < 0.1
        if method == "hertz":
            assert np.isnan(r["err_est_vm"][0])
        else:
            true = abs(r["p0_fe"][0] / p0_h - 1)
            assert 0.5 <= r["err_est_p0"][0] / true <= 3.0, (r["err_est_p0"][0], true)
            assert r["err_est_a"][0] >= 0.5 * abs(r["a_fe"][0] / a_h - 1)
            assert r["err_est_vm"][0] > r["err_est_p0"][0]   # the scaled stress carries three errors


@pytest.mark.slow
def test_thin_ring_on_needles_the_headline_is_the_ring_models(tmp_path):
    """A 1 mm wall on 20 needles: the ring's p0 lies more than the sweep tolerance (0.2 %) below
    the solid roller's Hertz p0 (measured -1.7 %, load line between two needles), and the
    headline is that answer: the peak pressure of a ring model built here on another mesh within
    0.3 % (measured 0.017 %, a 0.05 %). The stresses are the solid answer's scaled by the ring's
    p0 (global-local), checked against a solid-roller sweep of the same row; the ring's pressure
    stays elliptic (its peak within 0.2 % of the fitted ellipse's p0, measured 0.018 %)."""
    path = _variant(tmp_path, roller_bore_mm=9.0, pin_radius_mm=6.99, needle_count=20)
    sc = load_scene(path)
    th = np.radians([THETA_DEG])
    r = sweep(sc, SweepOptions(angles=th, a_over_h=6), RunOptions(workers=1))
    F, rho = float(r["Fc"][0]), float(r["rho"][0])
    a_h, p0_h = _hertz(F, sc.length, rho, 0.010)
    assert r["model"][0] == "fe_arc+ring"
    assert r["p0_fe"][0] < p0_h * (1 - 5e-3), "a thin ring carries the cam softer than a solid roller"
    # the same bearing on another mesh; the sweep reports the cage with the larger bore stress
    m = RingModel.build(bearing=bearing_from(sc.bodies.roller, sc.roller), cam=sc.cam, rho_ref=rho, a_ref=a_h,
                        length=sc.length, mesh=MeshOptions(a_over_h=30),
                        ring_mesh=RingMeshOptions(n_bore=192))
    res = [solve_ring(m, F=F, rho=rho, cage=c) for c in (0.0, math.pi / 20)]
    ref = max(res, key=lambda x: x.hoop_max)
    assert r["p0_fe"][0] == pytest.approx(float(np.max(ref.p)), rel=3e-3)
    assert r["a_fe"][0] == pytest.approx(ref.a, rel=1e-2)
    assert abs(r["p0_fe"][0] / r["p0_fit"][0] - 1) < 2e-3, "the ring's pressure is an ellipse"
    # global-local: the solid roller's stresses scaled by p0_ring / p0_solid, depths by a
    solid = sweep(load_scene(_variant(tmp_path, roller_support="solid", roller_bore_mm=None,
                                      pin_radius_mm=None, pin_clearance_um=None, needle_count=None,
                                      needle_radius_mm=None)),
                  SweepOptions(angles=th, a_over_h=6),
                  RunOptions(workers=1))
    assert solid["model"][0] == "fe_arc"
    k_p = r["p0_fe"][0] / solid["p0_fe"][0]
    k_a = r["a_fe"][0] / solid["a_fe"][0]
    for name in ("vm_max", "tau1_max", "surf_sz_min"):
        assert r[name][0] == pytest.approx(solid[name][0] * k_p, rel=1e-9), name
    assert r["vm_depth"][0] == pytest.approx(solid["vm_depth"][0] * k_a, rel=1e-9)


def test_no_column_claims_the_headline_twice():
    """The ring's side columns are the bore, pin and needles only (the cam contact is the
    headline); the finite-length columns name the most loaded slice, and the flag's sentence
    says which of p0_fe_MPa and p0_peak_slice_MPa is which."""
    ring = load_scene(EX / "seed002_needle_roller.toml")
    cols = [c.csv for c in extra_columns(ring)[0]]
    assert not [c for c in cols if c.startswith(("ring_p0", "ring_a", "solid_", "ring_d"))], cols
    assert "bore_hoop_max_MPa" in cols and "needle_Qmax_on_N" in cols
    assert omitted_physics(ring) == () and answered_by(ring)[0].startswith("headline_ring:")
    crowned = load_scene(EX / "seed002_crowned.toml")
    cols = [c.csv for c in extra_columns(crowned)[0]]
    assert {"p0_peak_slice_MPa", "a_peak_slice_um", "F_peak_slice_N"} <= set(cols)
    assert not [c for c in cols if "fe_slice" in c]
    (flag, sentence), = omitted_physics(crowned)
    assert flag == "headline_2d_mean_load"
    assert "p0_fe_MPa" in sentence and "MEAN load" in sentence
    assert "p0_peak_slice_MPa" in sentence and "MOST LOADED slice" in sentence
    shaft = load_scene(EX / "seed002_cam_on_shaft.toml")
    assert omitted_physics(shaft) == () and answered_by(shaft)[0].startswith("headline_cam_disk:")


def test_finite_length_summary_says_which_p0_is_which(tmp_path, capsys):
    """The crowned example on the console: the 2D p0 is said to be at the mean load, the most
    loaded slice is named by its column, and the report carries the same sentence."""
    from femcam.cli import main

    assert main(["sweep", str(EX / "seed002_crowned.toml"), "--out", str(tmp_path / "o"),
                 "--angles-deg", "44:45:1", "--no-plots", "--vtk-every", "0", "--a-over-h", "6",
                 "--workers", "1"]) == 0
    printed = capsys.readouterr().out
    assert "(peak of the solved pressure, 2D at the mean load Fc / length)" in printed
    line = next(x.strip() for x in printed.splitlines() if "headline_2d_mean_load:" in x)
    assert "p0_peak_slice_MPa" in line and line in (tmp_path / "o" / "report.md").read_text()


@pytest.mark.slow
def test_ring_model_estimate_against_the_solid_roller_and_a_finer_ring(tmp_path):
    """femcam.sweep.ringhead.ring_level_estimate on the thick ring on a tight pin (the solid
    roller: Hertz's p0 and a the reference) at contact a/h = 6 and 20: p0 and a effectivities in
    0.5-2 (measured p0 1.61, 0.93; a 1.30, 1.00) and the p0 estimate falls at a slope within
    0.5 of the true error's (measured 2.16 against 1.70: the coarse level a/h 3 is
    pre-asymptotic, so the estimate at a/h 6 is the larger).

    The ring's own stresses against a finer ring (512 bore vertices, h_max = wall / 16, against
    the model's 128 and wall / 4): the bore hoop stress and the pin's peak pressure converge
    unevenly under bore refinement (16.555, 16.299, 16.678 MPa at 128, 256, 512), so the estimate
    (rate 1 on the refined level) is checked to be in 1-6 times the change to the finer ring
    (measured 4.1 hoop, 1.8 pin p0): on the safe side, within a factor of a few."""
    from femcam.bodies.rows import build_for
    from femcam.sweep.ringhead import _ring_quantities, ring_level_estimate

    path = _variant(tmp_path, roller_support="pin", roller_bore_mm=3.0, pin_radius_mm=2.999,
                    pin_clearance_um=1.0, needle_count=None, needle_radius_mm=None)
    sc = load_scene(path)
    st = sc.analyse(np.radians([THETA_DEG]))
    F, rho = float(st.Fc[0]), float(st.rho[0])
    a_h, p0_h = _hertz(F, sc.length, rho, 0.010)
    est, true = {}, {}
    for n in (6.0, 20.0):
        m = build_for(sc.bodies.roller, sc.pair, np.array([F]), np.array([rho]), mesh=MeshOptions(a_over_h=n))
        est[n] = ring_level_estimate(m, MeshOptions(a_over_h=n))
        q = _ring_quantities(m, F)   # at the model's reference load: F itself
        true[n] = {"p0": abs(q["p0"] / p0_h - 1), "a": abs(q["a"] / a_h - 1)}
        for k in ("p0", "a"):
            assert 0.5 <= est[n][k] / true[n][k] <= 2.0, (n, k, est[n][k], true[n][k])
        if n == 20.0:
            q20 = q
    slope = lambda d: np.log(d[6.0] / d[20.0]) / np.log(20.0 / 6.0)  # noqa: E731
    s_est, s_true = slope({n: est[n]["p0"] for n in est}), slope({n: true[n]["p0"] for n in true})
    assert abs(s_est - s_true) <= 0.5 and 1.4 <= s_est <= 2.4, (s_est, s_true)
    fine = build_for(sc.bodies.roller, sc.pair, np.array([F]), np.array([rho]),
                     mesh=MeshOptions(a_over_h=20.0),
                     ring_mesh=RingMeshOptions(n_bore=512, h_max_over_wall=0.0625))
    qf = _ring_quantities(fine, F)
    for k in ("bore_hoop", "pin_p0"):
        change = abs(q20[k] / qf[k] - 1)
        assert 1.0 <= est[20.0][k] / change <= 6.0, (k, est[20.0][k], change)


@pytest.mark.slow
def test_needle_bore_hoop_estimate_is_of_the_reported_cage_and_against_a_finer_ring():
    """The needle example's bore hoop stress (``bore_hoop_max_MPa``: the cage position with the
    larger bore stress, here the load line between two needles) on the default ring (128 bore
    vertices) against a ring built here with 1024 bore vertices uniform in angle (8 times finer),
    at the peak contact force (44 deg). Measured (docs/bodies.md, "Bore hoop stress under the
    needles"): 125.72 MPa against 129.08 MPa (-2.6 %); the sequence 128..2048 is 125.72, 127.30,
    128.24, 129.08, 130.12 MPa: it creeps by ~0.7 % per halving because the needle spread narrows
    with the bore spacing, so the 5 % tolerance (the target for the default mesh) holds the
    default within reach of every mesh to 4096 vertices, not a fitted margin.

    The two-level estimate (``err_est_bore_hoop_pct``, femcam.sweep.ringhead.ring_level_estimate)
    now estimates the reported cage's value, not the hoop beside a needle on the load line
    (92.6 .. 127.0 MPa from 128 to 2048: 40 % before): it must be at most 5 % and within 0.5-3
    times the change to the finer ring (measured 2.63 % against 2.60 %: effectivity 1.01)."""
    from femcam.bodies.rows import build_for, ring_rows
    from femcam.sweep.providers import _GRID, ring_model
    from femcam.sweep.ringhead import ring_level_estimate

    sc = load_scene(EX / "seed002_needle_roller.toml")
    st = sc.analyse(_GRID)
    Fc = np.where(np.asarray(st.Fc) > 0, st.Fc, np.nan)
    rho = np.asarray(st.rho, float)
    k = int(np.nanargmax(Fc))
    assert abs(math.degrees(_GRID[k]) - THETA_DEG) < 1.0
    model = ring_model(sc)
    fine = build_for(sc.bodies.roller, sc.pair, Fc, rho, ring_mesh=RingMeshOptions(n_bore=1024))
    assert model.theta.size == 128 and fine.theta.size == 1024
    args = (sc.bodies.roller, sc.pair, _GRID[k:k + 1], Fc[k:k + 1], rho[k:k + 1])
    h = ring_rows(*args, model=model)["hoop_max"][0]
    h_ref = ring_rows(*args, model=fine)["hoop_max"][0]
    change = abs(h / h_ref - 1)
    assert change <= 0.05, (h, h_ref)
    est = ring_level_estimate(model)["bore_hoop"]
    assert est <= 0.05 and 0.5 <= est / change <= 3.0, (est, change)
