"""Tests of femcam.mesh: the gmsh contact-region mesh (geometry checked against analytic areas)."""

import math

import numpy as np
import pytest

from femcam.errors import InputError
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


def test_geo_file_matches_api_mesh():
    """meshes/contact_region.geo (GUI source, mm) draws the same cam body as the API."""
    from pathlib import Path

    import gmsh

    geo = Path(__file__).resolve().parents[1] / "meshes" / "contact_region.geo"
    gmsh.initialize(["-nopopup"], readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(str(geo))
        gmsh.model.mesh.generate(2)
        _, xyz, _ = gmsh.model.mesh.getNodes(2, -1, includeBoundary=True)
        n_geo = xyz.size // 3
    finally:
        gmsh.finalize()
    m = build_contact_mesh(Rr=0.01, rho=0.02, a_ref=0.105e-3)
    assert n_geo == pytest.approx(m.cam.points.shape[1], rel=0.02)
