"""gmsh meshes of the real bodies: the roller ring (full annulus) and the pin (full disk).

Frame (the roller frame of :mod:`femcam.mesh`): the cam touches the ring at the origin, ``y``
points from the cam into the roller, so the ring and pin centre is ``(0, Ro)``. Angles ``theta``
are polar angles about that centre; ``theta = -pi/2`` is the bottom, the side of the cam.

* **ring**: outer circle ``Ro``, bore ``Ri``. The outer arc ``|x| <= xf`` at the bottom is the
  cam-contact fine zone: transfinite, its vertices snapped to the cam's uniform abscissae
  ``contact_x`` (so cam and ring contact vertices pair one to one, as in :mod:`femcam.mesh`).
  The bore is four transfinite quarter arcs: ``n_bore`` vertices uniform in angle from
  ``theta = -pi/2``. A ``Threshold`` field keeps the size ``h`` near the fine arc, ``h_bore``
  near the bore, growing with slope ``growth`` up to ``h_max``.
* **pin**: a disk of radius ``Rp`` with ``n_bore`` uniform surface vertices at the same angles
  (so pin and bore vertices pair one to one).

Parameters and defaults: ``meshes/roller_ring.toml``; the same geometry with ``DefineConstant``
sliders for the gmsh GUI: ``meshes/roller_ring.geo``.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import FemcamError
from ..mesh import BodyMesh, _ccw, gmsh_nodes
from ..mesh import gmsh_session as _gmsh_session


def gmsh_session():
    """An initialised gmsh for the bodies (:func:`femcam.mesh.gmsh_session`).

    Returns
    -------
    contextlib.AbstractContextManager
        A context manager yielding the ``gmsh`` module (errors name "the bodies").
    """
    return _gmsh_session("the bodies")


def _circle_arcs(geo, cx, cy, R, angles, lc):
    """Points on a circle at ``angles`` (rad, increasing) joined by arcs; returns
    (centre point, points, arcs)."""
    c = geo.addPoint(cx, cy, 0.0, lc)
    pts = [geo.addPoint(cx + R * math.cos(t), cy + R * math.sin(t), 0.0, lc) for t in angles[:-1]]
    pts.append(pts[0])
    arcs = [geo.addCircleArc(pts[i], c, pts[i + 1]) for i in range(len(angles) - 1)]
    return c, pts[:-1], arcs


def _size_field(gmsh, specs, h_max, growth):
    """Background size = min over ``specs`` [(curves, h, band), ...] of threshold fields."""
    f = gmsh.model.mesh.field
    fields = []
    for curves, h, band in specs:
        fd = f.add("Distance")
        f.setNumbers(fd, "CurvesList", curves)
        f.setNumber(fd, "Sampling", 400)
        ft = f.add("Threshold")
        f.setNumber(ft, "InField", fd)
        f.setNumber(ft, "SizeMin", h)
        f.setNumber(ft, "SizeMax", h_max)
        f.setNumber(ft, "DistMin", band)
        f.setNumber(ft, "DistMax", band + (h_max - h) / growth)
        fields.append(ft)
    fm = f.add("Min")
    f.setNumbers(fm, "FieldsList", fields)
    f.setAsBackgroundMesh(fm)
    for k in ("MeshSizeFromPoints", "MeshSizeFromCurvature", "MeshSizeExtendFromBoundary"):
        gmsh.option.setNumber(f"Mesh.{k}", 0)
    gmsh.option.setNumber("Mesh.Algorithm", 6)
    gmsh.option.setNumber("Mesh.ElementOrder", 1)


def _extract(gmsh, surface, curve_sets):
    """(points (N, 2), triangles (T, 3), {name: node indices}) with unused nodes dropped."""
    pts, index, tri = gmsh_nodes(gmsh, surface)
    sets = {}
    for name, (dim, ents) in curve_sets.items():
        out = [index[gmsh.model.mesh.getNodes(dim, e, includeBoundary=True)[0].astype(np.int64)]
               for e in ents]
        sets[name] = np.unique(np.concatenate(out))
    used = np.unique(tri)
    renum = np.full(pts.shape[0], -1, dtype=np.int64)
    renum[used] = np.arange(used.size)
    return pts[used].copy(), renum[tri], {k: renum[v] for k, v in sets.items()}


def _snap_circle(pts, nodes, cx, cy, R, n, theta0=-0.5 * math.pi):
    """Sort ``nodes`` by angle from ``theta0`` and move them to the exact uniform angles."""
    th = np.mod(np.arctan2(pts[nodes, 1] - cy, pts[nodes, 0] - cx) - theta0, 2 * math.pi)
    th[th > 2 * math.pi - math.pi / n] -= 2 * math.pi  # the node at theta0 itself
    nodes = nodes[np.argsort(th)]
    if nodes.size != n:
        raise FemcamError(f"gmsh returned {nodes.size} nodes on a circle, expected {n}")
    t = theta0 + 2 * math.pi * np.arange(n) / n
    pts[nodes, 0] = cx + R * np.cos(t)
    pts[nodes, 1] = cy + R * np.sin(t)
    return nodes, t


def mesh_ring(*, Ro: float, Ri: float, contact_x: np.ndarray, n_bore: int, h_bore: float,
              h_max: float, fine_depth: float, growth: float = 0.3,
              band: float = 3.0) -> tuple[BodyMesh, np.ndarray, np.ndarray]:
    """Mesh the ring (see module docstring).

    Parameters
    ----------
    Ro : float
        Ring outer radius [m].
    Ri : float
        Ring bore radius [m].
    contact_x : ndarray, shape (n_fine + 1,)
        Cam contact abscissae [m], uniform; the fine-arc vertices snap to them.
    n_bore : int
        Bore vertices (a multiple of 4).
    h_bore : float
        Element size at the bore [m].
    h_max : float
        Largest element size [m].
    fine_depth : float
        Depth below the fine arc meshed at the fine size [m].
    growth : float, optional
        Size growth slope [-].
    band : float, optional
        Width of the band at the bore meshed at ``h_bore``, in multiples of ``h_bore`` [-].

    Returns
    -------
    mesh : BodyMesh
        The ring; ``contact`` are the fine-arc vertices sorted by x (``contact_x``), ``fixed``
        is empty (the ring floats: it is held by its contacts).
    bore_nodes : ndarray of int, shape (n_bore,)
        Bore vertex nodes, counter-clockwise from ``theta = -pi/2``.
    bore_theta : ndarray, shape (n_bore,)
        Their polar angles about the ring centre ``(0, Ro)`` [rad].

    Raises
    ------
    FemcamError
        gmsh returned the wrong number of fine-zone or bore nodes.
    """
    xf = float(contact_x[-1])
    n_fine = contact_x.size - 1
    h = float(contact_x[1] - contact_x[0])
    cy = Ro
    with gmsh_session() as gmsh:
        gmsh.model.add("ring")
        geo = gmsh.model.geo
        a0 = -0.5 * math.pi - math.asin(xf / Ro)
        a1 = -0.5 * math.pi + math.asin(xf / Ro)
        _, _, o_arcs = _circle_arcs(geo, 0.0, cy, Ro, [a0, a1, 0.0, 0.5 * math.pi, math.pi,
                                                        a0 + 2 * math.pi], h_max)
        q = n_bore // 4
        _, _, b_arcs = _circle_arcs(geo, 0.0, cy, Ri, [-0.5 * math.pi + k * 0.5 * math.pi
                                                        for k in range(5)], h_max)
        s = geo.addPlaneSurface([geo.addCurveLoop(o_arcs), geo.addCurveLoop(b_arcs)])
        geo.mesh.setTransfiniteCurve(o_arcs[0], n_fine + 1)
        for arc in b_arcs:
            geo.mesh.setTransfiniteCurve(arc, q + 1)
        geo.synchronize()
        gmsh.model.addPhysicalGroup(1, [o_arcs[0]], name="ring_contact")
        gmsh.model.addPhysicalGroup(1, b_arcs, name="ring_bore")
        gmsh.model.addPhysicalGroup(2, [s], name="ring")
        _size_field(gmsh, [([o_arcs[0]], h, fine_depth), (b_arcs, h_bore, band * h_bore)], h_max, growth)
        gmsh.model.mesh.generate(2)
        pts, tri, sets = _extract(gmsh, s, {"fine": (1, [o_arcs[0]]), "bore": (1, b_arcs),
                                            "outer": (1, o_arcs)})
        gmsh.model.remove()
    fine = sets["fine"][np.argsort(pts[sets["fine"], 0])]
    if fine.size != n_fine + 1:
        raise FemcamError(f"gmsh returned {fine.size} fine-zone nodes, expected {n_fine + 1}")
    pts[fine, 0] = contact_x
    pts[fine, 1] = cy - np.sqrt(Ro**2 - contact_x**2)
    bore, theta = _snap_circle(pts, sets["bore"], 0.0, cy, Ri, n_bore)
    tri = _ccw(pts, tri)
    body = BodyMesh(name="ring", points=pts.T.copy(), triangles=tri.T.copy(),
                    fixed=np.zeros(0, dtype=np.int64), contact=fine, contact_x=np.asarray(contact_x),
                    surface=sets["outer"], L=float(Ro), R=float(Ro))
    return body, bore, theta


def mesh_disk(*, R: float, n_surface: int, h_surface: float, h_max: float, growth: float = 0.3,
              band: float = 3.0, cy: float | None = None,
              cx: float = 0.0) -> tuple[BodyMesh, np.ndarray, np.ndarray, int]:
    """Mesh a full disk (the pin, the cam's shaft).

    Parameters
    ----------
    R : float
        Disk radius [m].
    n_surface : int
        Surface vertices (a multiple of 4), uniform in angle from ``theta = -pi/2``.
    h_surface : float
        Element size at the surface [m].
    h_max : float
        Largest element size [m].
    growth : float, optional
        Size growth slope [-].
    band : float, optional
        Width of the surface band meshed at ``h_surface``, in multiples of it [-].
    cy : float or None, optional
        Centre y [m]; None: ``R``.
    cx : float, optional
        Centre x [m].

    Returns
    -------
    mesh : BodyMesh
        The disk (``contact`` = ``surface`` = the surface nodes, ``contact_x`` their angles).
    surface_nodes : ndarray of int, shape (n_surface,)
        Surface vertex nodes, counter-clockwise from ``theta = -pi/2``.
    theta : ndarray, shape (n_surface,)
        Their polar angles about the centre [rad].
    centre_node : int
        The node nearest to the centre.

    Raises
    ------
    FemcamError
        gmsh returned the wrong number of surface nodes.
    """
    cy = R if cy is None else cy
    q = n_surface // 4
    with gmsh_session() as gmsh:
        gmsh.model.add("disk")
        geo = gmsh.model.geo
        _, _, arcs = _circle_arcs(geo, cx, cy, R, [-0.5 * math.pi + k * 0.5 * math.pi
                                                for k in range(5)], h_max)
        s = geo.addPlaneSurface([geo.addCurveLoop(arcs)])
        for arc in arcs:
            geo.mesh.setTransfiniteCurve(arc, q + 1)
        geo.synchronize()
        # no embedded centre point: with it gmsh 4.15 ignored the size field (700 instead of
        # 7446 triangles for Rp = 6.7 mm, 512 surface vertices); callers take the nearest node
        gmsh.model.addPhysicalGroup(1, arcs, name="pin_surface")
        gmsh.model.addPhysicalGroup(2, [s], name="pin")
        _size_field(gmsh, [(arcs, h_surface, band * h_surface)], h_max, growth)
        gmsh.model.mesh.generate(2)
        pts, tri, sets = _extract(gmsh, s, {"surface": (1, arcs)})
        gmsh.model.remove()
    surf, theta = _snap_circle(pts, sets["surface"], cx, cy, R, n_surface)
    tri = _ccw(pts, tri)
    body = BodyMesh(name="pin", points=pts.T.copy(), triangles=tri.T.copy(),
                    fixed=np.zeros(0, dtype=np.int64), contact=surf, contact_x=theta,
                    surface=surf, L=float(R), R=float(R))
    return body, surf, theta, int(np.argmin(np.hypot(pts[:, 0] - cx, pts[:, 1] - cy)))
