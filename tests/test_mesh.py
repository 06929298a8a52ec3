"""Tests of femcam.mesh: the gmsh contact-region mesh (geometry checked against analytic areas)."""

import math
from pathlib import Path

import numpy as np
import pytest

from femcam.errors import InputError
from femcam.io import write_msh
from femcam.mesh import MeshOptions, build_contact_mesh, surface_height

Rr, a_ref = 0.01, 1e-4


@pytest.fixture(scope="module")
def cm():
    return build_contact_mesh(Rr=Rr, rho=0.02, a_ref=a_ref, options=MeshOptions(a_over_h=10))


def tri_area(b):
    p = b.points[:, b.triangles]
    return 0.5 * ((p[0, 1] - p[0, 0]) * (p[1, 2] - p[1, 0]) - (p[0, 2] - p[0, 0]) * (p[1, 1] - p[1, 0]))


def segment_area(R, W):
    """Area between the chord-free tangent line y=0 and a circle of radius R over |x| <= W."""
    # int_{-W}^{W} (R - sqrt(R^2 - x^2)) dx, closed form
    return 2 * R * W - (W * math.sqrt(R**2 - W**2) + R**2 * math.asin(W / R))


def test_surface_height_matches_circle():
    x = np.linspace(-0.005, 0.005, 11)
    np.testing.assert_allclose(surface_height(x, 0.02), 0.02 - np.sqrt(0.02**2 - x**2), rtol=1e-12,
                               atol=1e-18, err_msg="circle sagitta R - sqrt(R^2 - x^2)")
    np.testing.assert_allclose(surface_height(x, -0.02), -(0.02 - np.sqrt(0.02**2 - x**2)), rtol=1e-12,
                               atol=1e-18)
    assert np.all(surface_height(x, math.inf) == 0.0)


def test_fine_zone_uniform_and_paired(cm):
    h = a_ref / 10
    for b in (cm.cam, cm.roller):
        np.testing.assert_allclose(np.diff(b.contact_x), h, rtol=1e-9)
        np.testing.assert_allclose(b.contact_x[[0, -1]], [-2.5 * a_ref, 2.5 * a_ref], rtol=1e-9)
        # the contact vertices lie on the exact arc
        sign = -1.0 if b.name == "cam" else 1.0
        np.testing.assert_allclose(b.points[1, b.contact], sign * surface_height(b.contact_x, b.R),
                                   rtol=1e-12, atol=1e-18)
    np.testing.assert_array_equal(cm.cam.contact_x, cm.roller.contact_x)


def test_mesh_is_valid_and_has_no_orphans(cm):
    for b in (cm.cam, cm.roller):
        assert np.all(tri_area(b) > 0), "counter-clockwise triangles"
        used = np.unique(b.triangles)
        assert used.size == b.points.shape[1], "no unreferenced nodes (gmsh arc centres dropped)"
        assert b.fixed.size >= 2


@pytest.mark.parametrize("rho", [0.02, math.inf, -0.03])
def test_body_area_matches_geometry(rho):
    """Mesh area = 2 W L - (signed) circular segment area (polygon error ~ h^2/R is negligible)."""
    m = build_contact_mesh(Rr=Rr, rho=rho, a_ref=a_ref, options=MeshOptions(a_over_h=5))
    for b in (m.cam, m.roller):
        W = 0.9 * b.L
        seg = 0.0 if math.isinf(b.R) else math.copysign(segment_area(abs(b.R), W), b.R)
        ref = 2 * W * b.L - seg
        # the straight-edged mesh cuts each arc chord c off a circular segment R^2 (t - sin t)/2,
        # t = 2 asin(c / 2R): the polygon has that much less (convex) or more (concave) area
        xs = np.sort(b.points[0, b.surface])
        ys = surface_height(xs, b.R)
        c = np.hypot(np.diff(xs), np.diff(ys))
        if math.isinf(b.R):
            chord = 0.0
        else:
            t = 2 * np.arcsin(c / (2 * abs(b.R)))
            chord = math.copysign(np.sum(b.R**2 * (t - np.sin(t)) / 2), b.R)
        assert tri_area(b).sum() == pytest.approx(ref - chord, rel=1e-9), f"{b.name} area vs analytic"
    assert m.roller.L == pytest.approx(Rr)
    assert m.cam.L == pytest.approx(min(abs(rho), Rr))


def test_domain_cap():
    m = build_contact_mesh(Rr=Rr, rho=0.02, a_ref=a_ref, options=MeshOptions(a_over_h=5, domain_over_a=30))
    assert m.cam.L == pytest.approx(30 * a_ref) and m.roller.L == pytest.approx(30 * a_ref)


@pytest.mark.parametrize("kw, word", [
    (dict(rho=0.0), "rho"), (dict(rho=-0.009), "rho"), (dict(rho=math.nan), "rho"),
    (dict(rho=0.02, a_ref=0.003), "a_ref"), (dict(rho=0.02, a_ref=-1.0), "a_ref"),
])
def test_bad_input(kw, word):
    args = dict(Rr=Rr, a_ref=a_ref) | kw
    with pytest.raises(InputError, match=word):
        build_contact_mesh(**args)


def test_bad_options():
    with pytest.raises(InputError, match="a_over_h"):
        MeshOptions(a_over_h=0.5)
    with pytest.raises(InputError, match="growth"):
        MeshOptions(growth=3.0)


GEO = Path(__file__).resolve().parents[1] / "meshes" / "contact_region.geo"


def mesh_geo(**onelab):
    """Mesh meshes/contact_region.geo with the given GUI parameters; (node count, fine-curve xy
    in mm, physical groups {name: dim})."""
    import gmsh

    gmsh.initialize(["-nopopup"], readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        for k, v in onelab.items():
            gmsh.onelab.setNumber(k, [v])
        gmsh.open(str(GEO))
        gmsh.model.mesh.generate(2)
        _, xyz, _ = gmsh.model.mesh.getNodes(2, -1, includeBoundary=True)
        _, fine, _ = gmsh.model.mesh.getNodes(1, 2, includeBoundary=True)
        groups = {gmsh.model.getPhysicalName(d, t): d for d, t in gmsh.model.getPhysicalGroups()}
        return xyz.size // 3, fine.reshape(-1, 3)[:, :2], groups
    finally:
        gmsh.finalize()


def test_geo_file_matches_api_mesh():
    """meshes/contact_region.geo (GUI source, mm) draws the same cam body as the API."""
    n_geo, fine, groups = mesh_geo()
    m = build_contact_mesh(Rr=0.01, rho=0.02, a_ref=0.105e-3)
    assert n_geo == pytest.approx(m.cam.points.shape[1], rel=0.02)
    assert groups == {"cam_contact": 1, "cam_fixed": 1, "cam": 2}
    # fine-curve nodes on the arc of radius 20 mm (circle sagitta)
    np.testing.assert_allclose(fine[:, 1], -surface_height(fine[:, 0], 20.0), atol=1e-9)


def test_geo_file_flat_switch():
    """flat = 1 draws the flat cam (rho = inf) that k = 1/R cannot; R = 0 stops with a message."""
    n_geo, fine, _ = mesh_geo(**{"Geometry/Flat surface": 1})
    m = build_contact_mesh(Rr=0.01, rho=math.inf, a_ref=0.105e-3)
    assert n_geo == pytest.approx(m.cam.points.shape[1], rel=0.02)
    assert np.all(fine[:, 1] == 0.0), "flat surface y = 0"
    with pytest.raises(Exception, match="R = 0"):
        mesh_geo(**{"Geometry/Surface radius R (mm, <0 concave)": 0.0})


def min_max_angles(b):
    """Smallest and largest interior angle (degrees) of the triangles of a body mesh."""
    p = b.points[:, b.triangles]  # (2, 3, T)
    ang = []
    for i in range(3):
        u = p[:, (i + 1) % 3] - p[:, i]
        v = p[:, (i + 2) % 3] - p[:, i]
        c = (u * v).sum(0) / np.sqrt((u * u).sum(0) * (v * v).sum(0))
        ang.append(np.degrees(np.arccos(np.clip(c, -1.0, 1.0))))
    ang = np.array(ang)
    return ang.min(), ang.max()


@pytest.mark.parametrize("rho", [0.02, math.inf, -0.03])
def test_physical_groups_and_quality(rho, tmp_path):
    """The gmsh physical groups survive meshing (kept in BodyMesh.groups and written to .msh)
    with the right dimension and nodes, and the graded mesh is well shaped: every angle in
    [20, 130] degrees (measured 30.7-110 degrees for these cases)."""
    import gmsh

    m = build_contact_mesh(Rr=Rr, rho=rho, a_ref=a_ref, options=MeshOptions(a_over_h=10))
    dims = {"roller_contact": 1, "cam_contact": 1, "roller_fixed": 1, "cam_fixed": 1, "roller": 2, "cam": 2}
    assert {k: g.dim for k, g in m.physical_groups.items()} == dims
    for b in (m.cam, m.roller):
        g = b.groups
        assert set(g) == {f"{b.name}_contact", f"{b.name}_fixed", b.name}
        np.testing.assert_array_equal(g[f"{b.name}_contact"].nodes, np.sort(b.surface))
        assert np.isin(b.contact, g[f"{b.name}_contact"].nodes).all(), "fine zone on the contact curve"
        np.testing.assert_array_equal(g[f"{b.name}_fixed"].nodes, np.sort(b.fixed))
        sign = -1.0 if b.name == "cam" else 1.0
        np.testing.assert_allclose(b.points[1, b.fixed], sign * b.L, rtol=1e-12,
                                   err_msg="fixed support on the far side y = -+L")
        surf = g[b.name].elements
        assert surf.shape == b.triangles.shape
        def tri_set(t):
            return {tuple(c) for c in np.sort(t, axis=0).T}

        assert tri_set(surf) == tri_set(b.triangles), "surface group = the body's triangles"
        lo, hi = min_max_angles(b)
        assert lo > 20.0 and hi < 130.0, f"{b.name}: triangle angles {lo:.1f}-{hi:.1f} deg"
    # the same groups read back by gmsh from the written .msh
    path = write_msh(tmp_path / "contact.msh", m)
    gmsh.initialize(["-nopopup"], readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(str(path))
        got = {}
        for d, t in gmsh.model.getPhysicalGroups():
            n = sum(gmsh.model.mesh.getElements(d, e)[1][0].size
                    for e in gmsh.model.getEntitiesForPhysicalGroup(d, t))
            got[gmsh.model.getPhysicalName(d, t)] = (d, n)
    finally:
        gmsh.finalize()
    assert got == {k: (g.dim, g.elements.shape[1]) for k, g in m.physical_groups.items()}


def test_write_msh_bad_path(cm, tmp_path):
    """write_msh names the parameter and value: a path not ending in .msh, or not a path."""
    with pytest.raises(InputError, match=r"path = .*contact\.vtu.*must end in \.msh"):
        write_msh(tmp_path / "contact.vtu", cm)
    with pytest.raises(InputError, match=r"path = None: must be a file path"):
        write_msh(None, cm)
    assert not (tmp_path / "contact.vtu").exists()


def test_names_of_the_single_module_still_import():
    """femcam.mesh became a package: every name the single module had (also the private ones
    femcam.bodies uses) imports from femcam.mesh and is the package's function."""
    import femcam.mesh as M  # noqa: N812
    from femcam.mesh import build, coating, nodes, session

    for name in ("MeshOptions", "PhysicalGroup", "BodyMesh", "ContactMesh", "GMSH_LOCK",
                 "PHYSICAL_NAMES", "COAT_MAX_ASPECT", "gmsh_session", "surface_height",
                 "gmsh_nodes", "build_contact_mesh", "_mesh_body", "_ccw"):
        assert hasattr(M, name), name
    assert M._mesh_body is build.mesh_body and M._ccw is nodes.ccw
    assert M.gmsh_session is session.gmsh_session and M.COAT_MAX_ASPECT == coating.COAT_MAX_ASPECT


def test_meshes_under_a_kept_gmsh_equal_fresh_sessions():
    """``gmsh_kept`` (gmsh initialised once for the sweep's background builds): every mesh is the
    one a freshly initialised gmsh gives, bit for bit, whatever was meshed before it (a kept gmsh
    without the options reset carried them from mesh to mesh: other nodes)."""
    from femcam.mesh.session import gmsh_kept

    cases = [dict(rho=0.012, a_ref=9.6e-5, options=MeshOptions(a_over_h=6)),
             dict(rho=-0.03, a_ref=1.2e-4, options=MeshOptions(a_over_h=3, growth=0.5))]
    fresh = [build_contact_mesh(Rr=0.01, **c) for c in cases]
    with gmsh_kept():
        kept = [build_contact_mesh(Rr=0.01, **c) for c in cases[::-1]][::-1]
    for f, k in zip(fresh, kept, strict=True):
        for body in ("cam", "roller"):
            np.testing.assert_array_equal(getattr(f, body).points, getattr(k, body).points)
            np.testing.assert_array_equal(getattr(f, body).triangles, getattr(k, body).triangles)
