"""The sweep's headline columns hold the answer of the model the row's ``model`` column names,
for every example scene (issue 29: numbers that cannot mislead).

References written here, never femcam output:

* Hertz line contact written out (Johnson 1985 eqs. 4.43-4.45): ``a = sqrt(4 w R / (pi E*))``,
  ``p0 = 2 w / (pi a)``, ``E*`` from the scene's materials (plane strain or stress), and the
  Hertz surface field at z = 0 (``sz = -p``, ``txz = -q``, ``q = (|Q|/F) p``; seed 002 eqs. 5-7,
  Johnson 1985 §7.1) for the rows Hertz answers;
* the pressure the solve itself wrote: the ``contact_pressure_Pa`` of the row's ``.vtu``, read
  back with meshio (a different path from the table: the VTU writer gets the solve's nodal
  pressure, or Hertz's ellipse on a Hertz row), whose largest value is the peak of the solved
  pressure;
* what the headline omits, read from the scene's TOML text here (a coating table, a roller
  support other than solid, a cam bore, finite-length keys), not from femcam's scene objects.

Every file of ``examples/*.toml`` is swept at its peak-force angle and, where its cam has a
curvature jump, at the jump (which inserts the exact-gap rows of the straddle span), on a coarse
mesh (a/h = 6): a new example is covered without anyone remembering to.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import meshio
import numpy as np
import pytest
import tomllib

from femcam.fe import ContactModel, MeshOptions
from femcam.fe.angles import curvature_jumps
from femcam.hertz.surface import surface_stress
from femcam.io import vtu_name
from femcam.materials import Material
from femcam.profile import OscillatingRollerFollower, RollerFollower
from femcam.scene import load_scene
from femcam.sweep import RunOptions, SweepOptions, sweep
from femcam.sweep.headline import SURF_EDGE_TOL, edge_flags, omitted_physics

EX = Path(__file__).resolve().parents[1] / "examples"
#: scenes whose extra providers cost seconds (the cam disk model): run in the slow suite only
HEAVY = {"seed002_cam_on_shaft": "the fully refined cam disk model, ~4 s",
         "seed002_needle_roller": "the ring and needle model, ~3 s"}
A_OVER_H = 6.0  # coarse: the consistency checks are exact identities, not accuracy

#: the followers that carry a roller (radius Rr): on a slide or on an arm
ROLLERS = (RollerFollower, OscillatingRollerFollower)


def _e_star(cam, roller, plane):
    """Johnson 1985 eq. 4.22 (plane strain: E/(1 - nu^2) per body; plane stress: E)."""
    if plane == "strain":
        return 1.0 / ((1 - cam.nu**2) / cam.E + (1 - roller.nu**2) / roller.E)
    return 1.0 / (1 / cam.E + 1 / roller.E)


def _hertz(F, length, rho, Rr, E_star):
    """Johnson 1985 eqs. 4.43-4.45 written out: (a, p0) at load F over length, radii rho and Rr."""
    R = 1.0 / (1.0 / rho + (1.0 / Rr if math.isfinite(Rr) else 0.0))
    w = F / length
    a = math.sqrt(4 * w * R / (math.pi * E_star))
    return a, 2 * w / (math.pi * a)


def _omitted_from_toml(path) -> set[str]:
    """The headline flags a scene's TOML text asks for (docs/sweep.md, "Which column answers
    what") in an FE sweep: a coating table on a flat-faced follower (its real-cam FE has no
    coating band; other followers' coated FE answers), finite-length keys (a roller support and a
    cam bore are answered by their models: :func:`_answered_from_toml`)."""
    d = tomllib.loads(Path(path).read_text())
    fo, cam = d.get("follower", {}), d.get("cam", {})
    out = set()
    if _coated_toml(path) and fo.get("type") == "flat_faced":
        out.add("headline_omits_coating")
    width = fo.get("face_width_mm")
    if (any(k in fo for k in ("crown", "crown_radius_mm", "crown_drop_um", "edge_radius_mm",
                              "misalignment_deg"))
            or fo.get("roller_width_mm", width) != width or cam.get("face_width_mm", width) != width):
        out.add("headline_2d_mean_load")
    return out


def _coated_toml(path) -> bool:
    """The scene's TOML has a ``[materials.<body>.coating]`` table."""
    d = tomllib.loads(Path(path).read_text())
    return any("coating" in v for v in d.get("materials", {}).values() if isinstance(v, dict))


def _answered_from_toml(path) -> set[str]:
    """The sentences naming the model that answers (no row flag): a roller support, a cam bore."""
    d = tomllib.loads(Path(path).read_text())
    out = set()
    if d.get("follower", {}).get("roller_support", "solid") != "solid":
        out.add("headline_ring")
    if "bore_mm" in d.get("cam", {}):
        out.add("headline_cam_disk")
    return out


def _angles(sc) -> np.ndarray:
    """The peak-force angle (on a 2 deg grid) and, for a roller cam with a curvature jump, the
    first jump."""
    grid = np.radians(np.arange(0.0, 360.0, 2.0))
    Fc = np.asarray(sc.analyse(grid).Fc, float)
    th = [float(grid[int(np.argmax(np.where(Fc > 0, Fc, -np.inf)))])]
    if isinstance(sc.follower, ROLLERS):   # curvature_jumps takes a roller follower
        jumps = curvature_jumps(sc.program, sc.follower)
        if jumps:
            th.append(float(jumps[0].theta))
    return np.array(sorted(th))


def _vtu_peak(out, theta) -> float:
    m = meshio.read(Path(out) / "vtk" / vtu_name(theta))
    return float(np.max(m.point_data["contact_pressure_Pa"]))


def check_headline(sc, path, r, out) -> int:
    """Every ``ok`` row: the headline columns are those of the model its ``model`` column names.
    Returns the number of rows checked."""
    E_star = _e_star(sc.cam, sc.roller, sc.plane)
    # the second radius: the roller's, a knife-edge's tip radius, or none (flat face)
    Rr = sc.follower.Rr if isinstance(sc.follower, ROLLERS) else (sc.tip_radius or math.inf)
    omitted = _omitted_from_toml(path)
    ok = np.flatnonzero(r.status == "ok")
    assert ok.size, f"{path.name}: no ok row"
    for i in ok:
        where = f"{path.name} at {math.degrees(r['theta'][i]):.3f} deg ({r['model'][i]})"
        F, rho = float(r["Fc"][i]), float(r["rho"][i])
        a_h, p0_h = _hertz(F, sc.length, rho, Rr, E_star)
        assert r["p0_hertz"][i] == pytest.approx(p0_h, rel=1e-9), where
        assert r["a_hertz"][i] == pytest.approx(a_h, rel=1e-9), where
        model = r["model"][i]
        # a coated scene's FE rows are the coated model's (issue 24 item 3): "fe_arc+coating"
        coated = _coated_toml(path) and model != "hertz" and "headline_omits_coating" not in omitted
        assert ("+coating" in model) == coated, where
        model = model.replace("+coating", "")
        ring = "headline_ring" in _answered_from_toml(path)
        assert model in (("fe_arc+ring", "fe_exact+ring", "hertz+ring") if ring
                         else ("hertz", "fe_arc", "fe_exact")), where
        flags = set(r["flags"][i].split(";")) - {""}
        assert {f for f in flags if f.startswith("headline_")} == omitted, where
        if ring:
            # the ring model answered (tests/test_sweep_ring.py checks its value against another
            # ring model; the VTU holds the solid roller's fine field of the global-local scheme):
            # the example's 3 mm wall on needles stays within 0.5 % of the solid roller's Hertz
            assert r["err_p0"][i] == pytest.approx(r["p0_fe"][i] / p0_h - 1, abs=1e-12), where
            assert abs(r["err_p0"][i]) < 5e-3 and np.isfinite(r["a_fe"][i]), where
            continue
        if model == "hertz":
            # no FE headline on a row the FE did not answer
            assert np.isnan(r["p0_fe"][i]) and np.isnan(r["a_fe"][i]) and np.isnan(r["p0_fit"][i]), where
            assert _vtu_peak(out, r["theta"][i]) == pytest.approx(p0_h, rel=1e-9), where
            # the Hertz surface field: sz = -p, |txz| = (|Q|/F) p0 (the shape factors' traction
            # ratio sits on a grid of mu/100: up to mu/200 p0 off)
            assert r["surf_sz_min"][i] == pytest.approx(-p0_h, rel=1e-6), where
            ratio = abs(float(r["Q"][i])) / F
            grid = sc.mu / 200 * p0_h + 1e-9
            assert r["surf_txz_absmax"][i] == pytest.approx(ratio * p0_h, abs=grid), where
            continue
        # an FE row: the headline p0 is the peak of the pressure this solve wrote
        peak = _vtu_peak(out, r["theta"][i])
        assert r["p0_fe"][i] == pytest.approx(peak, rel=1e-9), where
        assert r["err_p0"][i] == pytest.approx(r["p0_fe"][i] / p0_h - 1, abs=1e-12), where
        assert np.isfinite(r["p0_fit"][i]) and np.isfinite(r["a_fe"][i]), where
        if model == "fe_arc" and not coated and not flags & {"hertz_large_a", "nearly_conformal"}:
            # the FE's own error against Hertz at a/h = 6: measured <= 0.26 % on these rows
            # (0.3 % is femcam's target at a/h = 10); 0.5 % leaves room for a new example
            assert abs(r["err_p0"][i]) < 5e-3, where
    return int(ok.size)


def _params():
    out = []
    for p in sorted(EX.glob("*.toml")):
        marks = [pytest.mark.slow] if p.stem in HEAVY else []
        out.append(pytest.param(p, id=p.stem, marks=marks))
    return out


@pytest.mark.parametrize("path", _params())
def test_headline_is_the_answering_models(path, tmp_path):
    """Issue 29 item 4: each headline column equals the quantity of the model the row names
    (Hertz rows: Hertz; FE rows: the peak of that solve's pressure), and the flags name the
    physics the headline model omits (also in the summary sentences and report.md)."""
    sc = load_scene(path)
    r = sweep(sc,
              SweepOptions(angles=_angles(sc), a_over_h=A_OVER_H, vtk_every=1, plots=False),
              RunOptions(workers=1, out=tmp_path))
    assert check_headline(sc, path, r, tmp_path) >= 1
    sentences = r.provenance.get("extras", {}).get("headline", [])
    assert {s.split(":")[0] for s in sentences} == _omitted_from_toml(path) | _answered_from_toml(path)
    report = (tmp_path / "report.md").read_text()
    for s in sentences:
        assert s in report


def test_hertz_rows_of_method_auto_and_exact_gap_rows(tmp_path):
    """Method auto on the curvature-jump scene: dwell rows answered by Hertz hold Hertz in the
    headline (p0_fe NaN); the jump's exact-gap rows hold the peak of their own solve."""
    path = EX / "shm_dwell_junction.toml"
    sc = load_scene(path)
    jump = curvature_jumps(sc.program, sc.follower)[0].theta
    r = sweep(sc,
              SweepOptions(angles=np.array([math.radians(30.0), jump]),  method="auto",  a_over_h=A_OVER_H,
                           vtk_every=1,  plots=False),
              RunOptions(workers=1, out=tmp_path))
    models = set(r["model"][r.status == "ok"])
    assert {"hertz", "fe_exact"} <= models, models
    check_headline(sc, path, r, tmp_path)


def test_omitted_physics_of_every_example():
    """The flag list of each example (cheap: no sweep) matches what its TOML asks for, and at
    least one example exercises each flag."""
    seen = set()
    for p in sorted(EX.glob("*.toml")):
        sc = load_scene(p)
        got = {flag for flag, _ in omitted_physics(sc)}
        assert got == _omitted_from_toml(p), p.name
        # method hertz: the homogeneous Hertz answers, so a coating is omitted there
        hertz = {flag for flag, _ in omitted_physics(sc, "hertz")}
        assert ("headline_omits_coating" in hertz) == _coated_toml(p), p.name
        seen |= got | hertz
    assert seen == {"headline_omits_coating", "headline_2d_mean_load"}


# ------------------------------------------------------------------ surface columns at the edge
STEEL = Material(E=210e9, nu=0.3)
RR, RHO, L, F, MU = 0.010, 0.020, 0.010, 1000.0, 0.1


@pytest.fixture(scope="module")
def hertzian():
    """A Hertzian row (steel on steel, Rr = 10 mm, rho = 20 mm, 1000 N over 10 mm) and its model
    at a/h = 10, the sweep's default."""
    a, p0 = _hertz(F, L, RHO, RR, _e_star(STEEL, STEEL, "strain"))
    m = ContactModel.build(Rr=RR, rho_ref=RHO, cam=STEEL, roller=STEEL, length=L, a_ref=a,
                           mesh=MeshOptions(a_over_h=10))
    return m, a, p0


def test_sliding_row_surface_columns_are_hertz(hertzian):
    """Full sliding at mu = 0.1: the FE surface extremes against the Hertz surface field (seed 002
    eqs. 5-7): sz min = -p0, |txz| max = mu p0, sx min = -p0 sqrt(1 + 4 mu^2), within the FE's
    surface error away from the edge (SURF_EDGE_TOL p0, measured 1.9 %); nothing flagged. (The
    tensile sx peak 2 mu p0 sits at the edge and is under-resolved, below Hertz: not flagged.)"""
    m, a, p0 = hertzian
    r = m.solve(F=F, rho=RHO, mu=MU)
    S = r.surface_by_body["cam"]
    tol = SURF_EDGE_TOL * p0
    assert S.sz.min() == pytest.approx(-p0, abs=tol)
    assert np.abs(S.txz).max() == pytest.approx(MU * p0, abs=tol)
    assert S.sx.min() == pytest.approx(-p0 * math.sqrt(1 + 4 * MU**2), abs=tol)
    assert S.sx.max() <= 2 * MU * p0 + tol
    assert edge_flags(r) == []


def test_sticking_row_flags_the_edge_shear(hertzian):
    """Tangential force 0 (stick): Hertz has txz = 0 on the whole surface. The FE's surface |txz|
    peaks within one element of the contact edge, above SURF_EDGE_TOL p0 (the discretisation's
    edge singularity, 27 MPa at p0 = 742 MPa measured), and is flagged; away from the edge (two
    elements) it is Hertz's 0 within that error, and sx, sz are not flagged."""
    m, a, p0 = hertzian
    r = m.solve(F=F, rho=RHO, mu=MU, Q=0.0)
    S = r.surface_by_body["cam"]
    _, _, txz_h = surface_stress(S.x, a, p0, 0.0)
    assert np.all(txz_h == 0.0)
    h = a / 10
    j = int(np.argmax(np.abs(S.txz)))
    assert abs(abs(S.x[j]) - a) <= h and abs(S.txz[j]) > SURF_EDGE_TOL * p0
    far = np.abs(np.abs(S.x) - a) > 2 * h
    assert np.abs(S.txz[far]).max() <= SURF_EDGE_TOL * p0
    assert edge_flags(r) == ["surf_edge_dominated:surf_txz_absmax"]


def test_layer_stresses_without_strengths_through_the_sweep(tmp_path):
    """Issue 29 item 2: the coating interface stresses are reported without the coating's
    hardness and interface strength (only the utilisations need them): the same stresses as
    with the strengths (they do not enter the solve), utilisations NaN."""
    sc = load_scene(EX / "seed002_coated.toml")
    layers = tuple(b if b.coating is None else dataclasses.replace(
        b, coating=dataclasses.replace(b.coating, hardness=None, interface_shear_strength=None))
        for b in sc.layers)
    bare = dataclasses.replace(sc, layers=layers)
    th = _angles(sc)
    with_s = sweep(sc, SweepOptions(angles=th, a_over_h=A_OVER_H), RunOptions(workers=1))
    without = sweep(bare, SweepOptions(angles=th, a_over_h=A_OVER_H), RunOptions(workers=1))
    for name in ("layer_interface_tau_max", "layer_interface_sn_min", "layer_coating_sx_max"):
        assert np.all(np.isfinite(without[name])), name
        np.testing.assert_allclose(without[name], with_s[name], rtol=1e-12, err_msg=name)
    assert np.all(np.isnan(without["layer_interface_utilisation"]))
    assert np.all(np.isfinite(with_s["layer_interface_utilisation"]))


def test_cli_summary_says_what_the_headline_omits(tmp_path, capsys):
    """Issue 29 item 2, on the console: with method hertz the coated scene's summary names the
    omitted coating with its thickness and modulus as the TOML gives them (2.5 um, 170 GPa);
    with method fe the coated model answers (issue 24 item 3) and the summary says so."""
    from femcam.cli import main

    args = ["sweep", str(EX / "seed002_coated.toml"), "--angles-deg", "60:61:1", "--no-plots",
            "--vtk-every", "0", "--a-over-h", "6", "--workers", "1"]
    assert main(args + ["--out", str(tmp_path / "h"), "--method", "hertz"]) == 0
    printed = capsys.readouterr().out
    assert "headline_omits_coating: the roller's 2.5 um coating (E 170 GPa)" in printed
    assert "layers: interface shear " in printed   # said even where no strength is given
    assert main(args + ["--out", str(tmp_path / "o")]) == 0
    printed = capsys.readouterr().out
    assert "headline_omits_coating" not in printed
    assert "(peak of the solved pressure, coated model)" in printed and "nan %" not in printed
    assert "2 rows answered by the coated model" in printed
