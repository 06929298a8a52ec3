"""A posteriori error estimates of the FE rows (femcam.sweep.estimate) and the mesh chosen for a
requested p0 error (femcam.sweep.rtol, ``--rtol-pct``).

References written here, never femcam output: Hertz line contact (Johnson 1985 eqs. 4.43-4.45,
written out), and on the curvature-jump scene the half-space influence-coefficient solve on the
cam surface built as the envelope of roller circles (tests/halfspace_ref.py, Johnson 1985 eq.
2.25b).

Effectivity = estimated error / true error. The band accepted here is 0.5-3: below 0.5 the
estimate would hide more than half of the error (a user asking for 0.5 % could get 1 %); above 3
an rtol would buy three times the needed accuracy (at the rate p ~ 1.7 about 1.9x the elements
per half-width, 3.7x the contact-zone DOFs). Measured on the study model at even a/h = 6-24:
0.94-1.69 for p0, 1.01-1.36 for a.

The FE-vs-Hertz difference also holds a finite-body part (the FE bodies are clamped at the depth
min(|rho|, Rr) = 95 a; Hertz is a half-space) that no mesh refinement removes. For p0 it is below
2e-5 (the fitted p0's error at a/h = 40 is -1e-5, docs/fe.md), under a quarter of the smallest
true error tested (9e-5 at a/h = 40); the estimator leaves it out on purpose (it is a model
difference, not a discretisation error), so the band is checked on p0 and a only. For tau1 max it
is +1.1 % (docs/estimate.md), which is why tau1 and von Mises estimates are not compared with
Hertz here.
"""

import math
from pathlib import Path

import numpy as np
import pytest

from femcam.errors import InputError
from femcam.io import write_fe_vtu
from femcam.materials import STEEL
from femcam.scene import load_scene
from femcam.sweep import RunOptions, SweepOptions, sweep
from femcam.sweep.cache import ModelCache
from femcam.sweep.estimate import coarse_mesh, family_estimate, row_estimate
from femcam.sweep.options import ResolvedOptions, contact_params
from femcam.sweep.rtol import even_ceil, rtol_settings

EX = Path(__file__).resolve().parents[1] / "examples"
STUDY = EX / "seed002_study_model.toml"
E_STAR = STEEL.E / (2 * (1 - STEEL.nu**2))  # steel on steel, plane strain
BAND = (0.5, 3.0)


def hertz(F, L, R):
    """Johnson 1985 eqs. 4.43-4.45 written out: a = sqrt(4 w R / (pi E*)), p0 = 2 w / (pi a)."""
    w = F / L
    a = math.sqrt(4 * w * R / (math.pi * E_STAR))
    return a, 2 * w / (math.pi * a)


def fine_nodes(a_over_h, fine_half_width):
    """Abscissae (in a_ref) of the uniform fine-zone vertices: n = round(2 xf a/h) steps of h."""
    n = int(round(2 * fine_half_width * a_over_h))
    h = 1.0 / a_over_h
    return 0.5 * n * h - h * np.arange(n + 1)


@pytest.mark.parametrize("a_over_h", [6.0, 8.0, 10.0, 12.0, 20.0, 40.0])
def test_coarse_level_nests_in_the_fine_level(a_over_h):
    """H = 2h, and every coarse fine-zone vertex inside the fine level's zone |x| <= 2.5 a_ref is
    a fine vertex (x = 0 and x = a_ref included on both levels): the node pattern the estimate was
    validated on. (The coarse zone may reach one coarse element further, to keep the parity.)"""
    m = coarse_mesh(a_over_h)
    assert m.a_over_h == pytest.approx(a_over_h / 2, rel=1e-12)
    fine = fine_nodes(a_over_h, 2.5)
    coarse = fine_nodes(m.a_over_h, m.fine_half_width)
    assert coarse.max() >= 2.5 - 1e-12, "the coarse zone covers the fine zone"
    inside = coarse[np.abs(coarse) <= 2.5 + 1e-12]
    d = np.abs(inside[:, None] - fine[None, :]).min(axis=1)
    assert d.max() < 1e-9, "coarse vertices are fine vertices"
    assert np.abs(coarse).min() < 1e-12 and np.abs(coarse - 1.0).min() < 1e-12


def test_even_ceil_and_rtol_settings():
    """rtol picks even a/h >= 6; tolerance <= rtol / 2; rtol with a_over_h or method hertz refused."""
    assert [even_ceil(x) for x in (2.0, 6.0, 6.01, 15.2)] == [6.0, 6.0, 8.0, 16.0]
    assert rtol_settings(None, 0.005, "fe", 2e-3)[1:] == (2e-3, 0.005)
    assert rtol_settings(None, 0.001, "fe", 2e-3)[1] == pytest.approx(5e-4)
    assert rtol_settings(None, 0.01, "fe", None)[1] == pytest.approx(5e-3)   # no tolerance given
    assert rtol_settings(10.0, None, "fe", None) == (10.0, 2e-3, None)
    with pytest.raises(InputError, match="a_over_h"):
        rtol_settings(10.0, 0.005, "fe", 2e-3)
    with pytest.raises(InputError, match="rtol"):
        rtol_settings(None, 0.005, "hertz", 2e-3)
    with pytest.raises(InputError, match="rtol"):
        sweep(load_scene(STUDY), SweepOptions(angles=np.radians([0.0]), a_over_h=10.0, rtol=0.005))


def _effectivity(a_over_h):
    """Estimate and true p0/a errors of the study model's reference load (Rr = 10 mm, rho = 20 mm,
    F = 1500 N) on a model graded to it."""
    cp = contact_params(load_scene(STUDY))
    a, p0 = hertz(1500.0, cp.length, 1 / (1 / cp.Rr + 1 / 0.02))
    cache = ModelCache()
    opts = ResolvedOptions(a_over_h=a_over_h)
    est = family_estimate(cp, 0.02, a, opts, cache)
    r = cache.solve(cache.model_for(cp, 0.02, a, opts), 1500.0, 0.02, cp.mu, cp.sliding, check=False)
    return est, abs(r.p0_nodal / p0 - 1), abs(r.a / a - 1)


def test_effectivity_vs_hertz_at_a_over_h_6():
    """p0 and a estimates within the band of the true error against Hertz (a/h = 6, ~0.5 s)."""
    est, e_p0, e_a = _effectivity(6.0)
    assert BAND[0] <= est.err["p0"] / e_p0 <= BAND[1], (est.err, e_p0)
    assert BAND[0] <= est.err["a"] / e_a <= BAND[1], (est.err, e_a)


@pytest.mark.slow
def test_effectivity_band_and_rate_over_a_over_h_6_to_40():
    """Effectivity in the band from a/h = 6 to 40 for p0 and a; the estimates fall at the
    observed rates (log-log slope vs h: p0 1.4-2.3, a 1.6-2.3; measured 1.7 and 1.9)."""
    levels = (6.0, 10.0, 16.0, 24.0, 40.0)
    ests, trues = [], []
    for n in levels:
        est, e_p0, e_a = _effectivity(n)
        ests.append((est.err["p0"], est.err["a"]))
        trues.append((e_p0, e_a))
        assert BAND[0] <= est.err["p0"] / e_p0 <= BAND[1], f"p0 at a/h = {n}: {est.err['p0']} vs {e_p0}"
        assert BAND[0] <= est.err["a"] / e_a <= BAND[1], f"a at a/h = {n}: {est.err['a']} vs {e_a}"
    h = 1.0 / np.array(levels)
    ests = np.array(ests)
    assert 1.4 <= np.polyfit(np.log(h), np.log(ests[:, 0]), 1)[0] <= 2.3
    assert 1.6 <= np.polyfit(np.log(h), np.log(ests[:, 1]), 1)[0] <= 2.3


def test_row_estimate_scales_with_the_rows_own_a_over_h():
    """A row with half the family's a has twice its h/a: estimate x 2^p, + the reuse error on p0."""
    from femcam.sweep.estimate import RATES, FamilyEstimate
    est = FamilyEstimate(a_ref=1e-4, a_over_h=10.0, a_over_h_coarse=5.0,
                         err={"p0": 1e-3, "a": 2e-3, "vm": 3e-3, "tau1": 4e-3}, reuse=5e-4)
    r = row_estimate(est, 0.5e-4)
    assert r["a"] == pytest.approx(2e-3 * 2 ** RATES["a"])
    assert r["p0"] == pytest.approx(1e-3 * 2 ** RATES["p0"] + 5e-4)
    own = row_estimate(est, 0.5e-4, a_model=0.5e-4)   # a model of its own: no reuse, no scaling
    assert own["p0"] == pytest.approx(1e-3) and own["tau1"] == pytest.approx(4e-3)


def test_family_need_meets_the_target_on_the_family_s_smallest_row():
    """rtol per family: n_f = n0 (e0 (a_ref / a_min)^p / target)^(1/p), rounded up to even >= 6,
    written out here; a family of larger rows (a_min = a_ref) needs fewer elements."""
    from femcam.sweep.estimate import RATES, FamilyEstimate
    from femcam.sweep.rtol import family_need
    p = RATES["p0"]
    est = FamilyEstimate(a_ref=1e-4, a_over_h=8.0, a_over_h_coarse=4.0,
                         err={"p0": 1.6e-3, "a": 1e-3, "vm": 1e-3, "tau1": 1e-3})
    a_rows = np.array([0.8e-4, 1.0e-4, 1.2e-4])
    n = 8.0 * (1.6e-3 * (1e-4 / 0.8e-4) ** p / 5e-4) ** (1 / p)   # 24.3 -> 26
    assert family_need(est, a_rows, 5e-4) == 2 * math.ceil(n / 2)
    n_big = 8.0 * (1.6e-3 / 5e-4) ** (1 / p)   # 15.8 -> 16: the rows no smaller than a_ref
    assert family_need(est, a_rows[1:], 5e-4) == 2 * math.ceil(n_big / 2)
    assert family_need(est, a_rows, 1.0) == 6.0   # loose target: the validated floor
    nan = FamilyEstimate(1e-4, 8.0, 4.0, {q: math.nan for q in ("p0", "a", "vm", "tau1")})
    assert family_need(nan, a_rows, 5e-4) == 16.0   # a failed pilot: twice the pilot's a/h


@pytest.mark.slow
def test_rtol_half_percent_on_the_study_model():
    """--rtol 0.5 %: every arc-gap row's true p0 error vs Hertz <= 0.5 %, every row's estimate
    <= 0.5 % and not below half the true error (measured on all 360 angles: a/h = 8 chosen,
    true <= 0.223 %, estimates <= 0.315 %)."""
    sc = load_scene(STUDY)
    r = sweep(sc,
              SweepOptions(angles=np.radians(np.arange(0.0, 360.0, 5.0)), rtol=0.005),
              RunOptions(workers=1))
    t = r.table
    arc = (t["status"] == "ok") & (t["model"] == "fe_arc")
    F, rho = t["Fc"][arc], t["rho"][arc]
    p0 = np.array([hertz(f, sc.length, 1 / (1 / sc.follower.Rr + 1 / q))[1]
                   for f, q in zip(F, rho, strict=True)])
    true = np.abs(t["p0_fe"][arc] / p0 - 1)
    assert arc.sum() >= 60 and true.max() <= 0.005
    assert np.nanmax(t["err_est_p0"][t["status"] == "ok"]) <= 0.005
    assert np.all(t["err_est_p0"][arc] >= BAND[0] * true)
    choice = r.provenance["options"]["rtol_choice"]
    assert choice["a_over_h"] % 2 == 0 and choice["tolerance"] <= 0.0025


@pytest.mark.slow
def test_rtol_tenth_percent_on_the_study_model():
    """--rtol 0.1 %: every arc-gap row's true p0 error vs Hertz <= 0.1 % (measured on all 360
    angles: a/h = 18, true <= 0.048 %, estimates <= 0.062 %)."""
    sc = load_scene(STUDY)
    r = sweep(sc,
              SweepOptions(angles=np.radians(np.arange(0.0, 360.0, 15.0)), rtol=0.001),
              RunOptions(workers=1))
    t = r.table
    arc = (t["status"] == "ok") & (t["model"] == "fe_arc")
    p0 = np.array([hertz(f, sc.length, 1 / (1 / sc.follower.Rr + 1 / q))[1]
                   for f, q in zip(t["Fc"][arc], t["rho"][arc], strict=True)])
    true = np.abs(t["p0_fe"][arc] / p0 - 1)
    assert arc.sum() >= 10 and true.max() <= 0.001
    assert np.nanmax(t["err_est_p0"][t["status"] == "ok"]) <= 0.001
    assert np.all(t["err_est_p0"][arc] >= BAND[0] * true)
    # the mesh is each family's own: every row's a/h is its family's a/h scaled to the row
    fams = {f["id"]: f for f in r.provenance["families"]}
    choice = r.provenance["options"]["rtol_choice"]
    assert sorted(choice["family_a_over_h"]) == sorted(f["a_over_h"] for f in fams.values())
    assert choice["a_over_h"] == max(choice["family_a_over_h"])
    assert len(choice["pilots"]) >= 2 and all(f["a_over_h"] % 2 == 0 for f in fams.values())
    family_model = np.array(["rebuilt" not in str(x).split(";") for x in t["flags"]])
    for i in np.flatnonzero(arc & family_model):
        f = fams[int(t["family"][i])]
        assert t["a_over_h_row"][i] == pytest.approx(f["a_over_h"] * t["a_hertz"][i] / f["a_ref"], rel=1e-9)


@pytest.mark.slow
def test_curvature_jump_estimate_vs_exact_gap_halfspace():
    """shm_dwell_junction: on every exact-gap row of the jump's straddle span the p0 estimate is
    not below half the true error against the exact-gap half-space reference (800 strips, its own
    p0 error 3e-6 on the base circle; measured effectivity >= 1.46 at a/h = 10)."""
    from halfspace_ref import envelope_height, halfspace_solve  # tests/ is on sys.path

    sc = load_scene(EX / "shm_dwell_junction.toml")
    r = sweep(sc, SweepOptions(angles=np.radians([89.0, 91.0])), RunOptions(workers=1))
    Rr, Rb = 0.010, 0.020
    rows = np.flatnonzero((r["model"] == "fe_exact") & (r.status == "ok"))
    assert rows.size >= 21
    for i in rows:
        x = np.linspace(-3e-4, 3e-4, 1201)
        yc = envelope_height(sc.program, Rr, Rb, float(r["theta"][i]), x, n=20001, window=0.05)
        g = (Rr - np.sqrt(Rr**2 - x**2)) - yc

        def h0(xx, x=x, g=g):
            return np.interp(xx, x, g)

        _, p = halfspace_solve(h0, float(r["Fc"][i]) / sc.length, E_STAR, 2.5e-4, n=800)
        true = abs(r["p0_fe"][i] / p.max() - 1)
        assert r["err_est_p0"][i] >= BAND[0] * true, (np.degrees(r["theta"][i]), true)
        assert r["err_est_p0"][i] < 0.01


def test_cli_refuses_rtol_with_mesh_size(tmp_path, capsys):
    """--rtol-pct chooses the mesh: with --a-over-h it is refused before any work; a scene with
    both [fe] rtol_pct and [fe] a_over_h likewise."""
    from femcam.cli import main
    code = main(["sweep", str(STUDY), "--out", str(tmp_path / "o"), "--rtol-pct", "0.5",
                 "--a-over-h", "10"])
    assert code != 0 and "--rtol-pct" in capsys.readouterr().err
    scene = tmp_path / "s.toml"
    scene.write_text(STUDY.read_text() + "\n[fe]\nrtol_pct = 0.5\na_over_h = 10\n")
    code = main(["sweep", str(scene), "--out", str(tmp_path / "p")])
    assert code != 0 and "rtol_pct" in capsys.readouterr().err
    # the scene's rtol is for its FE runs: a Hertz sweep of the same scene ignores it
    scene.write_text(STUDY.read_text() + "\n[fe]\nrtol_pct = 0.5\n")
    code = main(["sweep", str(scene), "--out", str(tmp_path / "q"), "--method", "hertz",
                 "--angles-deg", "0:360:90", "--no-plots", "--vtk-every", "0"])
    assert code == 0, capsys.readouterr().err


def _zz_window(a_over_h, tmp_path=None):
    """The recovery indicator of the study contact (mu = 0) and the true stress error of the
    recovered field against Hertz's subsurface field (McEwen 1949 / Johnson 1985 §4.2 through
    femcam.hertz, the analytic module) over the cam's window |x| < 2a, 0.3a < z < 2a."""
    from femcam.fe import ContactModel, SolverOptions
    from femcam.fe.export import scene_arrays
    from femcam.hertz import LineContact
    from femcam.mesh import MeshOptions

    Rr, rho, F, L = 0.01, 0.02, 1500.0, 0.01
    hc = LineContact(F=F, length=L, R1=rho, R2=Rr, cam=STEEL, roller=STEEL, mu=0.0, plane="strain")
    m = ContactModel.build(Rr=Rr, rho_ref=rho, cam=STEEL, roller=STEEL, length=L, a_ref=float(hc.a),
                           mesh=MeshOptions(a_over_h=a_over_h),
                           solver=SolverOptions(stress_operators="per_solve"), plane="strain")
    r = m.solve(F=F, rho=rho, mu=0.0)
    if tmp_path is not None:
        write_fe_vtu(tmp_path / "zz.vtu", r)
    pts, _, _, d, _ = scene_arrays(r)
    cam = np.arange(pts.shape[0]) < m.bodies["cam"].basis.N // 2
    x, z = pts[:, 0], d["depth"]
    win = cam & (np.abs(x) < 2 * hc.a) & (z < 2 * hc.a) & (z > 0.3 * hc.a)
    sf = hc.stress(x[win], z[win])
    err = np.sqrt((d["sx"][win] - sf.sx) ** 2 + (d["sz"][win] - sf.sz) ** 2
                  + 2 * (d["txz"][win] - sf.txz) ** 2)
    eta = d["err_est_stress"]
    return eta, win, float(np.sqrt(np.mean(eta[win] ** 2)) / hc.p0), float(np.sqrt(np.mean(err**2)) / hc.p0)


def test_vtu_holds_the_recovery_indicator(tmp_path):
    """err_est_stress_Pa is a point field of the VTU: finite, >= 0, largest within 2.5 a of the
    contact (where the stress gradients are)."""
    import meshio

    eta, win, _, _ = _zz_window(6.0, tmp_path)
    got = meshio.read(tmp_path / "zz.vtu").point_data["err_est_stress_Pa"]
    np.testing.assert_allclose(got, eta, rtol=1e-12)
    assert np.all(np.isfinite(eta)) and eta.min() >= 0.0 and eta[win].max() > 0.0


@pytest.mark.slow
def test_recovery_indicator_vs_hertz_stress_error():
    """Against Hertz's subsurface field: the FE-vs-Hertz stress error holds a finite-body floor
    (measured 0.67 % p0 rms over the window at a/h = 20, where the indicator is 0.07 %); with
    it taken out in quadrature the discretisation part at a/h = 5 and 10 (0.58 % and 0.17 % p0)
    is matched by the indicator with effectivity 0.68 and 0.87 (band 0.5-3), and the indicator
    falls at a rate 1-2 (measured 1.4)."""
    _, _, e5, t5 = _zz_window(5.0)
    _, _, e10, t10 = _zz_window(10.0)
    _, _, e20, t20 = _zz_window(20.0)
    floor = t20   # the finite-body part: t20 is 0.674 % p0 with an indicator of 0.066 % p0
    for e, t in ((e5, t5), (e10, t10)):
        disc = math.sqrt(max(t**2 - floor**2, 0.0))
        assert BAND[0] <= e / disc <= BAND[1], (e, t, floor)
    assert 1.0 <= math.log(e5 / e20) / math.log(4.0) <= 2.0


@pytest.mark.slow
def test_cli_rtol_writes_the_estimate_columns(tmp_path, capsys):
    """femcam sweep --rtol-pct 0.5: the CSV's err_est_*_pct columns (percent) hold every FE row's
    estimate, p0 within the requested 0.5 %, and the summary line says what was reached."""
    import pandas as pd

    from femcam.cli import main
    out = tmp_path / "o"
    assert main(["sweep", str(STUDY), "--out", str(out), "--rtol-pct", "0.5", "--angles-deg",
                 "0:360:30", "--no-plots", "--vtk-every", "0"]) == 0
    text = capsys.readouterr().out
    assert "estimated discretisation error" in text and "rtol 0.5 % on p0" in text
    d = pd.read_csv(out / "sweep.csv")
    fe = d[d["status"] == "ok"]
    for c in ("err_est_p0_pct", "err_est_a_pct", "err_est_vm_pct", "err_est_tau1_pct", "a_over_h_row"):
        assert np.all(np.isfinite(fe[c])), c
    assert fe["err_est_p0_pct"].max() <= 0.5
    assert "rtol" in (out / "report.md").read_text()


def test_pilot_is_solved_at_the_curvature_extremes_and_interpolated_between(monkeypatch):
    """rtol per family: the pilot p0 estimate is solved on the planned families with the smallest
    and largest Rr/rho and linear in Rr/rho between them (written out here); each family then
    needs its own a/h: a family with a larger pilot error gets a finer mesh."""
    import importlib
    rt = importlib.import_module("femcam.sweep.rtol")
    from femcam.sweep.estimate import FamilyEstimate
    cp = contact_params(load_scene(STUDY))
    err = {0.2: 1e-3, 1.0: 4e-3}            # Rr/rho -> pilot p0 error of the solved families
    calls = []

    def fake(cp_, rho_ref, a_ref, options, cache=None, reuse=0.0):
        calls.append((cp.Rr / rho_ref, options.a_over_h))
        return FamilyEstimate(a_ref, options.a_over_h, options.a_over_h / 2,
                              {"p0": err[round(cp.Rr / rho_ref, 6)], "a": 0.0, "vm": 0.0, "tau1": 0.0})

    monkeypatch.setattr(rt, "family_estimate", fake)
    refs = {0: (cp.Rr / 0.2, 1e-4), 1: (cp.Rr / 0.6, 1e-4), 2: (cp.Rr / 1.0, 1e-4)}
    est = rt._pilot_estimates(cp, refs, ResolvedOptions(), None)
    assert sorted(round(k, 6) for k, _ in calls) == [0.2, 1.0] and {n for _, n in calls} == {8.0}
    assert est[1].err["p0"] == pytest.approx(1e-3 + (0.6 - 0.2) / (1.0 - 0.2) * 3e-3)
    a = np.array([1e-4])
    need = [rt.family_need(est[f], a, 5e-4) for f in (0, 1, 2)]
    assert need == sorted(need) and need[0] < need[2]
    assert need[2] == 2 * math.ceil(8.0 * (4e-3 / 5e-4) ** (1 / 1.7) / 2)
