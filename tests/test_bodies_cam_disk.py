"""The cam as a disk on its shaft (femcam.bodies.cam_*): closed-form references written here.

* Lame (thick-walled cylinder, Timoshenko & Goodier 1970 §28): annulus Ri <= r <= Ro under internal
  pressure p, hoop stress at the bore ``p (Ro^2 + Ri^2) / (Ro^2 - Ri^2)``.
* Kirsch (1898) small hole in the Brazilian disk (Hertz 1883; Timoshenko & Goodier §41): the
  centre field of a disk of diameter D under two opposite forces W (per unit length) is
  ``s_x = 2W/(pi D)``, ``s_y = -6W/(pi D)``; a small hole there has the hoop stress
  ``s_x + s_y - 2 (s_x - s_y) cos 2 psi``: ``+12 W/(pi D)`` on the load line, ``-20 W/(pi D)``
  across it.
* Hertz line contact (Johnson 1985 eq. 4.45): a cam disk with a small bore carries the roller
  contact like a solid body.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from femcam.bodies.cam_geometry import CamDisk
from femcam.bodies.cam_global import CamGlobalModel
from femcam.bodies.cam_mesh import mesh_cam_disk
from femcam.bodies.cam_model import (
    CamDiskModel,
    CamMeshOptions,
    check_bore_spacing,
    floating_supports,
    hat_resultants,
)
from femcam.bodies.cam_rows import solve_global
from femcam.bodies.cam_solve import solve_cam_disk
from femcam.bodies.contact import arc_load_matrix
from femcam.bodies.model import _hoop_rows
from femcam.errors import InputError
from femcam.fe.elasticity import assemble_body
from femcam.materials import STEEL

E, NU = 210e9, 0.3


def circle(R, n=720):
    t = np.linspace(0.0, 2 * math.pi, n, endpoint=False)
    return np.stack([R * np.cos(t), R * np.sin(t)])


def test_annulus_under_internal_pressure_matches_lame():
    Ro, Ri, p = 0.02, 0.008, 100e6
    geo, bore, theta = mesh_cam_disk(outline=circle(Ro), centre=(0.0, 0.0), bore=Ri, n_bore=64,
                                     h_max=0.003, h_bore=2 * math.pi * Ri / 64)
    body = assemble_body(geo, STEEL, supports=floating_supports(bore))
    u = body.solve(p * arc_load_matrix(body, bore, (0.0, 0.0), closed=True).sum(axis=1))
    hoop = _hoop_rows(body, bore, theta) @ u
    ref = p * (Ro**2 + Ri**2) / (Ro**2 - Ri**2)          # Lame
    err = np.abs(hoop / ref - 1)
    assert err.max() < 0.01, err.max()    # P2, 64 bore vertices: measured 0.13 %


def kirsch(W, D, psi):
    """Kirsch hoop stress at a small hole in the Brazilian disk's centre field (psi from x)."""
    sx, sy = 2 * W / (math.pi * D), -6 * W / (math.pi * D)
    return sx + sy - 2 * (sx - sy) * np.cos(2 * psi)


def test_small_hole_in_a_brazilian_disk_matches_kirsch_direct():
    """One solve of the meshed disk (1 mm hole in a 40 mm disk, Ri / R = 0.05), the two forces
    at the outline vertices nearest the vertical diameter."""
    R, Ri, W = 0.02, 0.001, 1e5
    geo, bore, theta = mesh_cam_disk(outline=circle(R), centre=(0.0, 0.0), bore=Ri, n_bore=64,
                                     h_max=0.002, h_bore=2 * math.pi * Ri / 64, growth=0.2)
    body = assemble_body(geo, STEEL, supports=floating_supports(bore))
    f = np.zeros(body.n_dofs)
    p = geo.points
    for sign in (1.0, -1.0):
        k = int(np.argmin(np.hypot(p[0], p[1] - sign * R)))
        f[body.basis.nodal_dofs[1, k]] = -sign * W
    hoop = _hoop_rows(body, bore, theta) @ body.solve(f)
    D = 2 * R
    err = np.abs(hoop - kirsch(W, D, theta)) / (20 * W / (math.pi * D))
    assert err.max() < 0.02, err.max()    # measured 0.85 %: mesh, and the field varying over the hole
    assert hoop[np.argmin(np.abs(theta - 0.5 * math.pi))] == pytest.approx(12 * W / (math.pi * D), rel=0.02)


@pytest.mark.slow
def test_small_hole_in_a_brazilian_disk_matches_kirsch():
    """Global model's station forces: two opposite forces W on the vertical diameter of a 40 mm
    disk with a 1 mm hole (Ri / R = 0.05: the centre field varies by ~(Ri/R)^2 over the hole)."""
    R, Ri, W = 0.02, 0.001, 1e5
    disk = CamDisk(outline=circle(R), Rb=Ri, shaft=None)
    g = CamGlobalModel.build(disk=disk, length=0.01, cam_mesh=CamMeshOptions(n_bore=64, h_max_over_web=0.1))
    C = np.array([[0.0, 0.0], [R, -R]])
    f = np.array([[0.0, 0.0], [-W, W]])
    hoop = (g.load_weights(C, f).sum(axis=0) @ g.Hf.T)   # free hole: loads only
    D = 2 * R
    psi = g.theta                                         # from the x axis
    ref = kirsch(W, D, psi)
    on_line = np.argmin(np.abs(psi - 0.5 * math.pi))
    across = np.argmin(np.abs(psi))
    assert hoop[on_line] == pytest.approx(12 * W / (math.pi * D), rel=0.02)
    assert hoop[across] == pytest.approx(-20 * W / (math.pi * D), rel=0.02)
    assert np.max(np.abs(hoop - ref)) < 0.02 * 20 * W / (math.pi * D)


def test_bore_geometry_problems_are_refused_with_numbers():
    with pytest.raises(InputError, match=r"^\[cam\] bore_mm = 21 mm: the bore does not fit.*20 mm"):
        CamDisk(outline=circle(0.02), Rb=0.021)
    with pytest.raises(InputError, match=r"^\[cam\] shaft_clearance_um = 1000 um: the radial clearance"):
        CamDisk(outline=circle(0.02), Rb=0.01, Rs=0.009)
    with pytest.raises(InputError, match=r"^\[cam\] shaft_clearance_um = 10 um: a bonded fit"):
        CamDisk(outline=circle(0.02), Rb=0.01, Rs=0.00999, fit="bonded")
    thin = CamDisk(outline=circle(0.02), Rb=0.0195)      # 0.5 mm web
    need = 4 * math.ceil(2 * math.pi * 19.5 / (0.5 * 0.5) / 4)   # bore spacing <= web / 2: 492
    with pytest.raises(InputError, match=rf"n_bore.*web \(0.5 mm\).*n_bore >= {need}"):
        check_bore_spacing(thin, CamMeshOptions(n_bore=64))


@pytest.mark.slow
def test_cam_disk_with_a_small_bore_carries_the_roller_like_hertz():
    """Circle cam R = 20 mm, 3 mm bore, steel shaft, roller Rr = 10 mm, 2 kN on 10 mm: Johnson
    eq. 4.45. Measured: a +0.25 %, p0 -0.02 % (a/h = 20, as the ring test's 1.5 % tolerance)."""
    R, Rr, F, L = 0.02, 0.01, 2000.0, 0.01
    Es = 1 / (2 * (1 - NU**2) / E)
    Rs = 1 / (1 / R + 1 / Rr)
    aH = math.sqrt(4 * F / L * Rs / (math.pi * Es))
    p0H = 2 * F / L / (math.pi * aH)
    m = CamDiskModel.build(disk=CamDisk(outline=circle(R), Rb=0.003), C=np.array([0.0, R]),
                           n=np.array([0.0, 1.0]), rho=R, Rr=Rr, roller=STEEL, a_ref=aH, length=L)
    r = solve_cam_disk(m, F=F)
    assert r.converged
    assert r.a == pytest.approx(aH, rel=0.015)
    assert r.p0 == pytest.approx(p0H, rel=0.015)
    assert r.a_local == pytest.approx(aH, rel=0.015)
    assert abs(r.hoop_theta) < 0.05                       # tension at the bore under the contact


@pytest.mark.slow
def test_global_model_matches_the_fully_refined_model():
    """Global-local coupling check: an oval cam (not a circle), contact at the top; bore hoop
    stress and shaft peak pressure of the global model (point force at the stations) against the
    fully refined model (fine contact zone, roller) on a finer mesh (0.1 x web, growth 0.1).
    Measured: hoop -0.14 %, shaft p0 -0.07 % (the global model's own discretisation: with growth
    0.3 it was 1.8 % low, docs/bodies.md)."""
    t = np.linspace(0.0, 2 * math.pi, 720, endpoint=False)
    R = 0.02
    out = np.stack([R * np.cos(t) * (1 + 0.15 * np.cos(t)), R * np.sin(t)])
    disk = CamDisk(outline=out, Rb=0.006)
    C, n = np.array([0.0, R]), np.array([0.0, 1.0])
    # radius of curvature of the outline at the top, by finite differences of the points
    x, y = out[:, 179:182]
    d1 = (np.array([x[2], y[2]]) - np.array([x[0], y[0]])) / 2
    d2 = np.array([x[2], y[2]]) - 2 * np.array([x[1], y[1]]) + np.array([x[0], y[0]])
    rho = float(np.hypot(*d1) ** 3 / abs(d1[0] * d2[1] - d1[1] * d2[0]))
    g = CamGlobalModel.build(disk=disk, length=0.01)
    rg = solve_global(g, C[:, None], n[:, None], np.array([2000.0]))
    m = CamDiskModel.build(disk=disk, C=C, n=n, rho=rho, Rr=0.01, roller=STEEL, a_ref=1e-4, length=0.01,
                           local=False, cam_mesh=CamMeshOptions(h_max_over_web=0.1, growth=0.1))
    rr = solve_cam_disk(m, F=2000.0, local=False)
    assert rg["hoop_max"][0] == pytest.approx(rr.hoop_max, rel=0.01)
    assert rg["shaft_p0"][0] == pytest.approx(rr.shaft_p0, rel=0.01)


def test_a_web_too_thin_for_the_disk_model_is_refused_with_numbers():
    from femcam.bodies.cam_global import global_mesh_for

    thin = CamDisk(outline=circle(0.02), Rb=0.0198)      # 0.2 mm web: 2 pi 19.8 / 0.05 -> 2492 vertices
    need = 4 * math.ceil(2 * math.pi * 19.8 / (0.25 * 0.2) / 4)
    with pytest.raises(InputError, match=rf"web r_min - Rb = 0.2 mm is too thin.*{need} bore vertices"):
        global_mesh_for(thin)


def test_a_web_within_ten_contact_half_widths_is_refused(tmp_path):
    """Seed 002 cam (base radius 10 mm) with a 9.5 mm bore: web 0.5 mm; its largest Hertz
    half-width is ~0.1 mm (Johnson eq. 4.45 at ~1.6 kN), so the web is < 10 a."""
    from femcam.bodies.cam_rows import cam_disk_rows
    from femcam.scene import cam_disk_case, load_scene

    ex = Path(__file__).resolve().parents[1] / "examples" / "seed002_cam_on_shaft.toml"
    text = ex.read_text().replace("bore_mm = 6.0", "bore_mm = 9.5")
    (tmp_path / "s.toml").write_text(text)
    sc = load_scene(tmp_path / "s.toml")
    th = np.radians(np.arange(0.0, 360.0, 10.0))
    with pytest.raises(InputError, match=r"bore_mm = 9.5 mm: the web r_min - Rb = 0.5 mm is less than 10 "
                                         r"contact half-widths \(a = \d+"):
        st = sc.analyse(th)
        cam_disk_rows(cam_disk_case(sc), st, st.Fc)


@pytest.mark.slow
def test_thin_web_that_would_yield_is_flagged_with_both_numbers():
    """1.5 mm web (20 mm circle cam, 18.5 mm bore, rigid shaft), 2 kN on 10 mm at the top, a
    cam yield strength of 30 MPa: the hub bends like a thin ring; only the flag (both stresses,
    the web) is asserted here."""
    from femcam.bodies.cam_rows import yield_flags

    disk = CamDisk(outline=circle(0.02), Rb=0.0185, shaft=None, cam_yield=30e6)
    g = CamGlobalModel.build(disk=disk, length=0.01)
    r = solve_global(g, np.array([[0.0], [0.02]]), np.array([[0.0], [1.0]]), np.array([2000.0]))
    flags = yield_flags(disk, r["hoop_max"], r["hoop_angle"])
    m = re.match(r"cam bore hoop stress ([\d.]+) MPa at -?[\d.]+ deg from the contact exceeds the cam's "
                 r"yield strength 30 MPa \(web 1.5 mm\)", flags[0])
    assert m and float(m.group(1)) == pytest.approx(r["hoop_max"][0] / 1e6, abs=0.05)  # the flag's number


@pytest.mark.slow
def test_sweep_writes_the_cam_disk_columns(tmp_path):
    """Wiring: `femcam sweep` on the example writes the cam-disk columns (units in the names)
    with a tensile bore stress and a loaded shaft at every contact angle, and the 4 mm web."""
    import csv

    from femcam.cli import main

    ex = Path(__file__).resolve().parents[1] / "examples" / "seed002_cam_on_shaft.toml"
    out = tmp_path / "sw"
    assert main(["sweep", str(ex), "--out", str(out), "--method", "hertz", "--angles-deg", "0:360:30",
                 "--no-plots", "--workers", "1"]) == 0
    lines = [ln for ln in (out / "sweep.csv").read_text().splitlines() if not ln.startswith("#")]
    rows = list(csv.DictReader(lines))
    for r in rows:
        assert float(r["cam_bore_hoop_max_MPa"]) > 0
        assert float(r["shaft_p0_MPa"]) > 0
        assert 0 < float(r["shaft_arc_deg"]) <= 185
        assert float(r["cam_web_mm"]) == pytest.approx(4.0)
        assert r["camdisk_flags"] in ("", "-")


def lame_bonded_to_rigid_shaft(q, Ro, Ri, E=E, nu=NU):
    """Plane-strain annulus, u_r(Ri) = 0 (bonded to a rigid shaft), sigma_r(Ro) = -q:
    u = A r + B / r, B = -A Ri^2; returns (bore hoop stress, bore contact pressure = -sigma_r(Ri))."""
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    A = -q / (2 * (lam + mu) + 2 * mu * Ri**2 / Ro**2)
    return 2 * lam * A, -2 * (lam + 2 * mu) * A


@pytest.mark.parametrize("fit", ["bonded", pytest.param("contact", marks=pytest.mark.slow)])
def test_shaft_fit_under_outward_traction_bonded_holds_in_tension_contact_lets_go(fit):
    """A 20 mm circular cam on a rigid 8 mm shaft pulled outward all round (sigma_r(Ro) = +50 MPa,
    as station forces of the global model): bonded, the bore carries tension (Lame with u_r(Ri)
    = 0, written here); unilateral, the shaft lets go (no bore pressure) and the cam is a free
    annulus: Lame hoop at the bore 2 q Ro^2 / (Ro^2 - Ri^2)."""
    from femcam.bodies.contact import solve_multi_lcp

    Ro, Ri, q = 0.02, 0.008, -50e6
    disk = CamDisk(outline=circle(Ro), Rb=Ri, shaft=None, fit=fit)
    g = CamGlobalModel.build(disk=disk, length=0.01)
    P = g.stations
    ds = 0.5 * (np.hypot(*(np.roll(P, -1, 1) - P)) + np.hypot(*(P - np.roll(P, 1, 1))))
    er = P / np.hypot(*P)
    L = np.zeros(g.Uf.shape[1])
    L[0:-1:2] = -q * ds * er[0]
    L[1:-1:2] = -q * ds * er[1]
    th = g.theta
    G = np.stack([np.cos(th), np.sin(th)], axis=1)
    sol = solve_multi_lcp(g.A, g.Uf @ L, G, g.bore_force, -np.array([L[0:-1:2].sum(), L[1:-1:2].sum()]),
                          active0=np.ones(th.size, bool), bilateral=np.full(th.size, fit == "bonded"))
    hoop = g.Hf @ L + g.H @ sol.lam
    if fit == "bonded":
        hoop_ref, p_ref = lame_bonded_to_rigid_shaft(q, Ro, Ri)
        assert p_ref < 0                                   # tension at the bore
        assert np.max(np.abs(sol.lam / p_ref - 1)) < 0.01
    else:
        hoop_ref = -2 * q * Ro**2 / (Ro**2 - Ri**2)        # free annulus, external traction -q
        assert np.all(sol.lam == 0.0)
    assert np.max(np.abs(hoop / hoop_ref - 1)) < 0.01     # measured 0.12 % (bonded), see docs


@pytest.mark.slow
def test_global_model_over_a_thin_web_hard_case():
    """Hard case of the global-local coupling: seed 002 cam on a 8.5 mm bore (web 1.5 mm, 14 contact
    half-widths) with the contact on the base circle right over the web (theta = 300 deg, 1500 N).
    The bore now sits 7 a from a point-force station, so Saint-Venant weakens: measured, the global
    model reads the bore hoop stress 1.9 % (1.1 mm web: 2.6 %) below the fully refined model;
    hence the 3 % tolerance and the refusal of webs below 10 a. The contact itself still does not
    see the disk (p0, a within 0.05 % of the local body)."""
    from femcam.bodies.cam_model import bore_vertices_for
    from femcam.bodies.cam_rows import disk_from_case
    from femcam.bodies.cam_study import _contact_at, refined_at
    from femcam.scene import cam_disk_case, load_scene

    sc = load_scene(Path(__file__).resolve().parents[1] / "examples" / "seed002_cam_on_shaft.toml")
    th = math.radians(300.0)
    case, at = cam_disk_case(sc), sc.analyse(np.array([th]))
    d = disk_from_case(case, Rb=0.0085)
    m, r = refined_at(case, d, at, cam_mesh=CamMeshOptions(arc_over_xf=1.5, n_bore=bore_vertices_for(d)))
    g = CamGlobalModel.build(disk=d, length=sc.length)
    rg = solve_global(g, *_contact_at(at), np.array([r.F]))
    assert rg["hoop_max"][0] == pytest.approx(r.hoop_max, rel=0.03)
    assert rg["shaft_p0"][0] == pytest.approx(r.shaft_p0, rel=0.03)
    # 5e-4 is taken from runs (README web table: dp0 -0.007 %, da +0.008 % at this web), 6x their
    # size; the only independent bound is the Saint-Venant order (a / web)^2 = 5e-3, an estimate
    # of magnitude, not a limit, so it cannot serve as the tighter reference
    assert abs(r.dp0) < 5e-4 and abs(r.da) < 5e-4


def test_hat_resultants_sum_the_interleaved_dofs():
    """hat_resultants(B) takes only B (no unused body): x and y sums of the nodal forces,
    DOFs interleaved x0, y0, x1, y1, ... (scikit-fem). Reference summed by hand."""
    B = np.arange(1.0, 13.0).reshape(6, 2)  # rows x0 y0 x1 y1 x2 y2, two hats
    np.testing.assert_array_equal(hat_resultants(B), [[1 + 5 + 9, 2 + 6 + 10], [3 + 7 + 11, 4 + 8 + 12]])



@pytest.mark.parametrize("kw, message", [
    (dict(length=0.0), r"length = 0 m: must be > 0"),
    (dict(Rr=-0.01), r"Rr = -0.01 m: must be > 0"),
    (dict(rho=0.0), r"rho = 0 m"),
    (dict(n=[0.0, 2.0]), r"n = \[0.0, 2.0\]: C and n must be 2-vectors, n of unit length"),
])
def test_cam_disk_model_inputs_are_checked_before_meshing(kw, message):
    disk = CamDisk(outline=circle(0.02), Rb=0.006)
    args = dict(disk=disk, C=[0.0, 0.02], n=[0.0, 1.0], rho=0.02, Rr=0.01, roller=STEEL, a_ref=1e-4,
                length=0.01)
    with pytest.raises(InputError, match=message):
        CamDiskModel.build(**{**args, **kw})
    if "length" in kw:
        with pytest.raises(InputError, match=message):
            CamGlobalModel.build(disk=disk, length=0.0)
