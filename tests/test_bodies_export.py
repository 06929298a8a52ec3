"""VTU export of the ring model (meshio round-trip) and the gmsh .geo of the ring."""

from __future__ import annotations

import pickle
from pathlib import Path

import numpy as np

from femcam.bodies import RingMeshOptions, RingModel, RollerBearing, solve_ring
from femcam.io import write_ring_vtu
from femcam.materials import STEEL
from femcam.mesh import MeshOptions

GEO = Path(__file__).resolve().parent.parent / "meshes" / "roller_ring.geo"


def test_ring_vtu_round_trip_carries_the_bore_stress(tmp_path):
    """The hoop field written to the VTU (full back-solve) and the condensed bore operator of the
    model (RingResult.hoop) are two code paths to the same nodal stress: they must agree at the
    bore vertices to round-off, and the file must hold the three bodies."""
    import meshio

    b = RollerBearing(Ro=0.01, Ri=0.007, support="pin", Rp=0.007 - 20e-6, c=20e-6)
    m = RingModel.build(bearing=b, cam=STEEL, rho_ref=0.02, a_ref=1.05e-4, length=0.01,
                        ring_mesh=RingMeshOptions(n_bore=64), mesh=MeshOptions(a_over_h=8))
    r = solve_ring(m, F=1500.0, rho=0.02)
    back = pickle.loads(pickle.dumps(r))  # results cross process boundaries (no solver inside)
    np.testing.assert_array_equal(back.hoop, r.hoop)
    path = write_ring_vtu(tmp_path / "ring.vtu", m, r)
    mesh = meshio.read(path)
    assert set(np.unique(mesh.cell_data["body"][0])) == {0, 1, 2}
    ring = m.bodies["ring"]
    n_ring = ring.n_dofs // 2
    hoop = mesh.point_data["hoop"][:n_ring]  # the ring is written first
    bore = m.bodies["ring"].mesh.p  # vertices are the first scalar nodes
    pts = mesh.points[:n_ring, :2]
    np.testing.assert_allclose(pts[: bore.shape[1]], bore.T, atol=1e-15)
    th = np.arctan2(pts[:, 1] - 0.01, pts[:, 0])
    on_bore = np.isclose(np.hypot(pts[:, 0], pts[:, 1] - 0.01), 0.007, rtol=1e-9, atol=1e-12)
    i = np.nonzero(on_bore)[0]
    order = np.argsort(np.mod(th[i] + np.pi / 2, 2 * np.pi))
    vert = i[order][np.isin(i[order], np.arange(bore.shape[1]))]
    np.testing.assert_allclose(hoop[vert], r.hoop, rtol=1e-8, atol=1e-6 * np.abs(r.hoop).max())


def test_ring_geo_opens_and_meshes_in_gmsh():
    import gmsh

    gmsh.initialize(["-nopopup"], readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(str(GEO))
        gmsh.model.mesh.generate(2)
        names = {gmsh.model.getPhysicalName(d, t) for d, t in gmsh.model.getPhysicalGroups()}
        n_tri = [len(gmsh.model.mesh.getElements(2, s)[1][0]) for _, s in gmsh.model.getEntities(2)]
    finally:
        gmsh.finalize()
    assert names == {"ring_contact", "ring_bore", "ring", "pin_surface", "pin"}
    assert all(n > 500 for n in n_tri), n_tri


def test_wall_study_figure_is_a_png(tmp_path):
    from femcam.viz.bodies import plot_wall_study

    w = np.array([1.5e-3, 3e-3])
    s = {"wall": w, "hoop_max": np.array([3e8, 1.2e8]), "p0": np.array([0.99, 1.0]),
         "p0_solid": np.ones(2), "a": np.array([1.01, 1.0]), "a_solid": np.ones(2)}
    png = plot_wall_study({"needles": s}, tmp_path / "w.png")
    assert png.stat().st_size > 5000 and png.read_bytes()[:4] == b"\x89PNG"
