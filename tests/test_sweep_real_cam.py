"""The sweep on the real cam (femcam.sweep.realcam): curvature jumps, model choice, traction from
the mechanism, knife-edge and flat-faced followers.

References written here, never femcam output: the half-space influence-coefficient solve on the
cam surface built as the envelope of roller circles (tests/halfspace_ref.py, Johnson 1985 eq.
2.25b), Hertz line contact written out (Johnson 1985 eq. 4.45), Carter/Cattaneo's stick width
(Johnson 1985 §7.1, §8.2), and first-principles velocities on the base circle.
"""

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest
from halfspace_ref import envelope_height, halfspace_solve  # tests/ is on sys.path (pytest rootdir)

from femcam.errors import SceneError
from femcam.scene import load_scene
from femcam.scene.wear import WearSettings
from femcam.sweep import RunOptions, SweepOptions, sweep

EX = Path(__file__).resolve().parents[1] / "examples"
E_STEEL = 210e9 / (2 * (1 - 0.3**2))  # plane strain E* of steel on steel (E = 210 GPa, nu = 0.3)


def hertz_p0(F, L, R_eff):
    """Johnson 1985 eq. 4.45 written out: p0 = sqrt(F E* / (pi L R))."""
    return math.sqrt(F * E_STEEL / (math.pi * L * R_eff))


@pytest.fixture(scope="module")
def junction_sweep():
    sc = load_scene(EX / "shm_dwell_junction.toml")
    return sc, sweep(sc, SweepOptions(angles=np.radians([89.0, 91.0])), RunOptions(workers=1))


@pytest.fixture(scope="module")
def references(junction_sweep):
    """Half-space solves at the junction (90 deg) and +-0.05, +-0.1 deg from it, on the exact gap
    (the envelope of roller circles: Rb = 20 mm, Rr = 10 mm, SHM rise 8 mm over 90 deg)."""
    sc, r = junction_sweep
    Rr, Rb = 0.010, 0.020
    out = {}
    for d in (-0.1, -0.05, 0.0, 0.05, 0.1):
        i = int(np.argmin(np.abs(np.degrees(r["theta"]) - (90.0 + d))))
        th, F = float(r["theta"][i]), float(r["Fc"][i])
        x = np.linspace(-3e-4, 3e-4, 601)
        yc = envelope_height(sc.program, Rr, Rb, th, x, n=20001, window=0.05)
        g = (Rr - np.sqrt(Rr**2 - x**2)) - yc  # small-slope gap of the exact shapes

        def h0(xx, x=x, g=g):
            return np.interp(xx, x, g)

        # 2.5 um strips (a / 34): the reference's own p0 error vs Hertz is 0.1 % (checked below)
        _, p = halfspace_solve(h0, F / sc.length, E_STEEL, 2.5e-4, n=200)
        # on the osculating-arc gap (the row's rho) the half-space answer is Hertz
        pa = hertz_p0(F, sc.length, 1 / (1 / Rr + 1 / float(r["rho"][i])))
        out[d] = (i, p.max(), pa)
    # the reference at this resolution, pinned to Hertz on the base circle (rho = 20 mm, 1000 N)
    R = 1 / (1 / Rr + 1 / Rb)
    _, p = halfspace_solve(lambda xx: xx**2 / (2 * R), 1000.0 / sc.length, E_STEEL, 2.5e-4, n=200)
    assert p.max() == pytest.approx(hertz_p0(1000.0, sc.length, R), rel=1e-3)
    return out


def test_junction_rows_inserted_flagged_and_vs_halfspace(junction_sweep, references):
    """The sweep inserts the junction and +-0.05, +-0.1 deg, flags the straddle span, answers
    with the exact gap; its headline p0_fe (the peak of the solved pressure, not the elliptic fit
    p0_fit, which sits up to 1.5 % below at the junction) within 1 % of the half-space reference
    (measured <= 0.3 % at a/h = 10); exact-vs-arc p0 difference within 0.5 %-points of the
    reference's own arc/exact ratio (up to 6.7 % at the junction)."""
    sc, r = junction_sweep
    deg = np.degrees(r["theta"])
    for d, (i, p_ex, p_arc) in references.items():
        assert abs(deg[i] - (90.0 + d)) < 1e-9, "junction and +-0.05, +-0.1 deg inserted"
        assert r["curvature_jump"][i] == 1 and r["model"][i] == "fe_exact" and r.status[i] == "ok"
        assert r["p0_fe"][i] == pytest.approx(p_ex, rel=1e-2), f"p0 at {d:+} deg vs half-space"
        assert 100 * r["exact_vs_arc_p0"][i] == pytest.approx(100 * (p_arc / p_ex - 1), abs=0.5)
    # the requested angles are outside the straddle span (-0.29 .. +0.23 deg): not flagged
    for t in (89.0, 91.0):
        k = int(np.argmin(np.abs(deg - t)))
        assert r["curvature_jump"][k] == 0 and r["model"][k] == "fe_arc"
    o = r.provenance["options"]
    assert o["n_curvature_jump"] == int(np.sum(r["curvature_jump"] == 1)) >= 21
    assert o["models"]["fe_exact"] == o["n_curvature_jump"]


def test_junction_p0_curve_is_smooth(junction_sweep):
    """Across the jump the peak pressure goes monotonically from the dwell side's Hertz value to
    the rise side's: every step below a third of the Hertz jump, ends within 0.5 % of Hertz
    (dwell: rho = Rb = 20 mm; rise start: rho = 1/kappa_p - Rr, kappa_p = (Rp^2 - Rp s'')/Rp^3,
    s'' = h pi^2 / (2 beta^2), Norton ch. 8)."""
    sc, r = junction_sweep
    deg = np.degrees(r["theta"])
    j = (deg > 89.5) & (deg < 90.5)
    p0 = r["p0_fe"][j]
    F = r["Fc"][j]
    Rr, Rp, s2 = 0.010, 0.030, 0.008 * math.pi**2 / (2 * (math.pi / 2) ** 2)
    rho_r = 1 / ((Rp**2 - Rp * s2) / Rp**3) - Rr
    hz = (hertz_p0(F[0], sc.length, 1 / (1 / Rr + 1 / 0.020)),
          hertz_p0(F[-1], sc.length, 1 / (1 / Rr + 1 / rho_r)))
    assert np.all(np.diff(p0) <= 1e-4 * p0[0]), "monotone from the dwell to the rise side"
    assert np.max(np.abs(np.diff(p0))) < (hz[0] - hz[1]) / 3
    assert p0[0] == pytest.approx(hz[0], rel=5e-3) and p0[-1] == pytest.approx(hz[1], rel=5e-3)


def test_roller_traction_from_bearing_drag_partial_slip_and_sliding():
    """On the base circle the roller spins at Omega = omega - V_p/Rr = -2 omega (V_p = omega
    (Rb + Rr), Rb = 2 Rr): the friction needs only the drag, Q = -T_drag sign(Omega) / Rr on the
    cam. Carter/Cattaneo stick width 2a sqrt(1 - Q/(mu F)) within one node (h = a/10); a drag the
    friction cannot carry is full sliding (Q = mu F), never a failed solve."""
    sc = load_scene(EX / "shm_dwell_junction.toml")
    th = np.radians([30.0, 45.0])
    F, mu, Rr = 1000.0, 0.1, 0.010
    a = 2 * math.sqrt(F / sc.length * (1 / (1 / Rr + 1 / 0.020)) / (math.pi * E_STEEL))
    r = sweep(dataclasses.replace(sc, wear=WearSettings(T_drag=0.03)), SweepOptions(angles=th),
              RunOptions(workers=1))
    Q = 0.03 / Rr
    np.testing.assert_allclose(r["Fc"], F, rtol=1e-9)  # dwell: the preload only
    np.testing.assert_allclose(r["Q"], Q, rtol=1e-6)
    np.testing.assert_allclose(r["Q_over_muFc"], Q / (mu * F), rtol=1e-6)
    assert set(r["slip_state"]) == {"partial slip"}
    np.testing.assert_allclose(r["stick_width"], 2 * a * math.sqrt(1 - Q / (mu * F)), atol=2 * a / 10)
    s = sweep(dataclasses.replace(sc, wear=WearSettings(T_drag=2.0)), SweepOptions(angles=th),
              RunOptions(workers=1))
    assert set(s["slip_state"]) == {"sliding"} and np.all(s.status == "ok")
    np.testing.assert_allclose(s["Q_over_muFc"], 1.0, rtol=1e-9)
    # [contact] sliding: the explicit override, full sliding in the fixed direction
    o = sweep(dataclasses.replace(sc, sliding="-x"), SweepOptions(angles=th), RunOptions(workers=1))
    np.testing.assert_allclose(o["Q"], -mu * F, rtol=1e-9)
    assert o.provenance["options"]["traction"].startswith("[contact] sliding")


def test_method_auto_answers_with_the_cheapest_model():
    """Base circle: Hertz's error (a/R)^2 ~ 1e-4 % is within the 0.2 % tolerance, Hertz answers
    (p0 = Hertz written out, no FE); the curvature-jump rows need the exact gap."""
    sc = load_scene(EX / "shm_dwell_junction.toml")
    r = sweep(sc, SweepOptions(angles=np.radians([45.0, 89.0, 91.0]), method="auto"), RunOptions(workers=1))
    deg = np.degrees(r["theta"])
    i45 = int(np.argmin(np.abs(deg - 45.0)))
    assert r["model"][i45] == "hertz" and np.isnan(r["p0_fe"][i45])
    assert r["p0_hertz"][i45] == pytest.approx(hertz_p0(1000.0, sc.length, 1 / (1 / 0.01 + 1 / 0.02)),
                                               rel=1e-9)
    assert 100 * r["est_err_hertz"][i45] < 0.2
    assert set(r["model"][r["curvature_jump"] == 1]) == {"fe_exact"}
    m = r.provenance["options"]["models"]
    assert sum(m.values()) == r.n_angles and m["hertz"] >= 1


@pytest.mark.slow  # ~1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_seed003_knife_edge_sweeps(tmp_path):
    """Knife-edge with [follower] tip_radius_mm = 2: the cam cut for the tip; on the base circle
    (300..360 deg) rho = Rb = 5 mm, Fc = preload 20 N: FE p0 within 0.3 % of Hertz (tip 2 mm on
    the 5 mm circle); full sliding, traction on the cam along +x (the cam surface runs under the
    still tip in -x, so the tip drags it along +x): Q = +mu Fc."""
    from femcam.cli import main

    out = tmp_path / "k"
    assert main(["sweep", str(EX / "seed003_knife_edge.toml"), "--out", str(out),
                 "--angles-deg", "0:360:60", "--no-plots", "--vtk-every", "6"]) == 0
    head = (out / "sweep.csv").read_text().splitlines()[0].split(",")
    for col in ("model", "curvature_jump", "exact_vs_arc_p0_pct", "Q_N", "Q_over_muFc",
                "stick_width_um", "slip_state", "est_err_hertz_pct", "est_err_arc_pct"):
        assert col in head
    r = np.load(out / "sweep.npz", allow_pickle=False)
    deg = np.degrees(r["theta"])
    base = deg >= 300.0
    assert base.any() and np.all(r["status"] == "ok")
    p0 = hertz_p0(20.0, 0.005, 1 / (1 / 0.005 + 1 / 0.002))
    np.testing.assert_allclose(r["p0_fe"][base], p0, rtol=3e-3)
    np.testing.assert_allclose(r["Q"][base], 0.1 * 20.0, rtol=1e-9)
    assert set(r["slip_state"]) == {"sliding"}
    # the VTU carries the traction: Coulomb full sliding, |q| = mu p at every contact node
    meshio = pytest.importorskip("meshio")
    m = meshio.read(out / "vtk" / "angle_0000.000deg.vtu")
    q, p = np.abs(m.point_data["contact_traction_Pa"]), m.point_data["contact_pressure_Pa"]
    q = np.linalg.norm(q, axis=1) if q.ndim == 2 else q
    assert p.max() > 0
    np.testing.assert_allclose(q, 0.1 * np.abs(p), rtol=1e-9, atol=1e-9 * p.max())


@pytest.mark.slow  # ~1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_flat_faced_sweep_and_edge_contact():
    """Flat face (R = inf): on the dwells rho = 20 mm (Fc = 500 N) and 30 mm (700 N): FE p0
    within 0.3 % of Hertz; full sliding with Q = +mu Fc on the base circle (as the knife-edge).
    A 15 mm face: at mid-rise the contact offset s' = 2h/beta = 9.55 mm passes the face end
    (7.5 mm): status edge_contact naming the angle range, no Hertz answer."""
    sc = load_scene(EX / "flat_faced.toml")
    r = sweep(sc, SweepOptions(angles=np.radians([150.0, 330.0])), RunOptions(workers=1))
    assert np.all(r.status == "ok"), r["message"]
    np.testing.assert_allclose(r["p0_fe"], [hertz_p0(700.0, 0.010, 0.030), hertz_p0(500.0, 0.010, 0.020)],
                               rtol=3e-3)
    np.testing.assert_allclose(r["Q"][1], 0.1 * 500.0, rtol=1e-9)
    e = sweep(dataclasses.replace(sc, face_length=0.015),
              SweepOptions(angles=np.radians([60.0, 150.0]), method="auto"),
              RunOptions(workers=1))
    assert list(e.status) == ["edge_contact", "ok"]
    assert "edge contact" in e["message"][0] and "deg" in e["message"][0]
    assert np.isnan(e["p0_hertz"][0]) and e["model"][0] == ""


def test_tip_radius_key_and_the_retired_alias(tmp_path):
    """[follower] tip_radius_mm is the key; the retired [wear] tip_radius_mm is refused in one
    line naming the key to use."""
    sc = load_scene(EX / "seed003_knife_edge.toml")
    assert sc.tip_radius == pytest.approx(2e-3)
    p = tmp_path / "old.toml"
    p.write_text((EX / "seed003_knife_edge.toml").read_text(encoding="utf-8")
                 + "\n[wear]\ntip_radius_mm = 1.5\n", encoding="utf-8")
    with pytest.raises(SceneError, match=r"wear.tip_radius_mm = 1.5 mm: retired; give the knife-edge "
                                         r"tip radius as \[follower\] tip_radius_mm \(mm\)"):
        load_scene(p)


def test_method_auto_writes_the_hertz_vtu_of_hertz_rows(tmp_path):
    """--method auto with a VTU at every angle: the rows Hertz answers get the analytic Hertz
    field, so the series is complete (the end-of-run check stays strict); the VTU's peak
    pressure is Hertz p0 written out (Johnson 1985 eq. 4.45) at the row's Fc and rho."""
    from femcam.cli import main

    out = tmp_path / "auto"
    assert main(["sweep", str(EX / "seed002_study_model.toml"), "--out", str(out), "--method", "auto",
                 "--angles-deg", "0:360:30", "--vtk-every", "1", "--no-plots", "--workers", "1"]) == 0
    assert len(list((out / "vtk").glob("*.vtu"))) == 12
    r = np.load(out / "sweep.npz", allow_pickle=False)
    i = int(np.flatnonzero(r["model"] == "hertz")[0])
    meshio = pytest.importorskip("meshio")
    m = meshio.read(out / "vtk" / f"angle_{np.degrees(r['theta'][i]):08.3f}deg.vtu")
    p0 = hertz_p0(float(r["Fc"][i]), 0.010, 1 / (1 / float(r["rho"][i]) + 1 / 0.010))  # face 10 mm, Rr 10 mm
    assert m.point_data["contact_pressure_Pa"].max() == pytest.approx(p0, rel=1e-9)
    # ... and the traction the row carries: surface txz = -q = -(|Q|/Fc) p (Johnson 1985 §7.1),
    # not full sliding mu p (the mechanism's Q here is far below mu Fc)
    ratio = abs(float(r["Q"][i])) / float(r["Fc"][i])
    assert ratio < 0.1 * 0.1
    surf = m.points[:, 1] == 0.0
    assert np.abs(m.point_data["stress_Pa"][surf, 3]).max() == pytest.approx(ratio * p0, rel=1e-9, abs=1e-6)


def test_worst_profile_is_the_rows_own_solve_with_its_traction():
    """The worst-angle profile is solved with the row's gap and the mechanism's traction: its FE
    surface sx maximum is the row's sx_max (the same solve: 1e-9), the title states the traction,
    and for |Q| << mu Fc the Hertz curve is the frictionless one, sx = -p0 sqrt(1 - x^2/a^2)
    (Johnson 1985 eq. 4.45), labelled so."""
    from femcam.sweep.options import ResolvedOptions, contact_params
    from femcam.sweep.profile import worst_surface_profile

    sc = load_scene(EX / "seed002_study_model.toml")
    r = sweep(sc, SweepOptions(angles=np.radians([180.0, 210.0, 240.0])), RunOptions(workers=1))
    i = r.worst_index("p0_fe")
    assert r["slip_state"][i] == "stick" and abs(r["Q_over_muFc"][i]) < 1e-3
    prof = worst_surface_profile(r.table, "fe", contact_params(sc), r.families, ResolvedOptions(), scene=sc)
    assert prof["sx_fe"].max() == pytest.approx(r["surf_sx_max"][i], rel=1e-9)
    assert "stick" in prof["traction"] and "Q/(mu Fc)" in prof["traction"]
    assert "frictionless" in prof["hertz_label"]
    x, a = prof["x_hertz"], prof["a_hertz"]
    p0 = hertz_p0(r["Fc"][i], 0.010, 1 / (1 / r["rho"][i] + 1 / 0.010))
    p = p0 * np.sqrt(np.clip(1 - (x / a) ** 2, 0, None))
    np.testing.assert_allclose(prof["sx_hertz"], -p, rtol=0, atol=1e-9 * p0)


def test_profile_hertz_curve_with_cattaneo_partial_slip():
    """Partial slip Q = 0.5 mu F (Johnson 1985 §7.1): stick zone |x| < c = a sqrt(1 - 0.5);
    q = mu p on the slip zone, q = mu p - mu p0 (c/a) sqrt(1 - x^2/c^2) on the stick zone, and in
    the stick zone the tangential parts of sx cancel (2 mu p0 x/a - 2 mu p0 (c/a) x/c = 0):
    sx = -p there."""
    from femcam.sweep.options import contact_params
    from femcam.sweep.profile import _hertz_curve

    cp = contact_params(load_scene(EX / "seed002_study_model.toml"))
    h = _hertz_curve({"Q_over_muFc": np.array([0.5]), "slip_state": np.array(["partial slip"])}, 0, cp,
                     1000.0, 0.02)
    x, a, mu = h["x_hertz"], h["a_hertz"], cp.mu
    p0 = hertz_p0(1000.0, 0.010, 1 / (1 / 0.02 + 1 / 0.010))
    c = a * math.sqrt(0.5)
    p = p0 * np.sqrt(np.clip(1 - (x / a) ** 2, 0, None))
    q = mu * p - mu * p0 * (c / a) * np.sqrt(np.clip(1 - (x / c) ** 2, 0, None))
    np.testing.assert_allclose(np.abs(h["txz_hertz"]), q, rtol=0, atol=1e-9 * p0)
    stick = np.abs(x) < c
    np.testing.assert_allclose(h["sx_hertz"][stick], -p[stick], rtol=0, atol=1e-9 * p0)
    assert "Cattaneo" in h["hertz_label"]


def test_worst_profile_of_method_auto_includes_the_hertz_rows():
    """Method auto: the worst angle is by the row's answer (Hertz p0 where Hertz answered), not
    only among the FE rows; a Hertz row gets the Hertz curve and no FE points."""
    from femcam.sweep.options import ResolvedOptions, contact_params
    from femcam.sweep.profile import worst_surface_profile

    cp = contact_params(load_scene(EX / "seed002_study_model.toml"))
    t = {"theta": np.radians([10.0, 20.0]), "Fc": np.array([1600.0, 1000.0]), "rho": np.array([0.02, 0.02]),
         "status": np.array(["ok", "ok"]), "model": np.array(["hertz", "fe_arc"]),
         "p0_fe": np.array([np.nan, 9e8]), "p0_hertz": np.array([1.1e9, 9e8]),
         "Q_over_muFc": np.array([0.0, 0.0]), "slip_state": np.array(["stick", "stick"])}
    prof = worst_surface_profile(t, "fe", cp, [], ResolvedOptions())
    assert prof["theta_deg"] == pytest.approx(10.0) and "x_fe" not in prof
    p0 = hertz_p0(1600.0, 0.010, 1 / (1 / 0.02 + 1 / 0.010))
    assert -prof["sx_hertz"].min() == pytest.approx(p0, rel=1e-6)  # grid point at x = 0
