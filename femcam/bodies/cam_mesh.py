"""gmsh mesh of the cam as a full disk with its real outline and a shaft bore.

Frame (the mesh frame): for the fully refined model (:mod:`femcam.bodies.cam_model`) it is the
contact frame of :mod:`femcam.mesh`: the cam touches the roller at the origin, ``y`` is the
outward cam normal there and the cam lies below ``y = 0``; for the global model
(:mod:`femcam.bodies.cam_global`) it is the cam frame (cam centre at the origin). The bore is a
circle about the cam centre ``(cx, cy)``.

* **outline**: a spline through the profile points (ordered counter-clockwise about the cam
  centre). With a fine zone, the outline near the contact is replaced by the osculating circle
  of radius ``rho`` over ``|x| <= W`` in three arcs; the middle one ``|x| <= xf`` is the
  transfinite fine zone, its vertices snapped to the roller's abscissae ``contact_x`` (pairs
  one to one, as :mod:`femcam.mesh`). ``rho`` < 0 (concave) and ``inf`` (flat) are allowed.
* **bore**: four transfinite quarter arcs, ``n_bore`` vertices uniform in angle from
  ``theta = -pi/2`` about the cam centre (they pair one to one with the shaft's surface).
* **size**: ``Threshold`` fields: ``h`` within ``fine_depth`` of the fine arc, ``h_bore`` within 3
  bore spacings of the bore, growing with slope ``growth`` to ``h_max``.

Parameters and defaults: ``meshes/cam_disk.toml``; the same geometry with ``DefineConstant``
sliders (a circular-arc cam) for the gmsh GUI: ``meshes/cam_disk.geo``.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import FemcamError, InputError
from ..mesh import BodyMesh, _ccw, surface_height
from .mesh import _circle_arcs, _extract, _size_field, _snap_circle, gmsh_session


def _fine_arcs(geo, rho, xs, lc):
    """Points at ``x = xs`` (decreasing) on the osculating circle and the arcs joining them."""
    ys = -surface_height(np.asarray(xs), rho)
    p = [geo.addPoint(float(x), float(y), 0.0, lc) for x, y in zip(xs, ys, strict=True)]
    if math.isinf(rho):
        return p, [geo.addLine(p[i], p[i + 1]) for i in range(len(p) - 1)]
    c = geo.addPoint(0.0, -rho, 0.0, lc)
    return p, [geo.addCircleArc(p[i], c, p[i + 1]) for i in range(len(p) - 1)]


#: most triangles of a cam disk mesh (global or fully refined model). The global model of seed
#: 002 (6 mm bore, 4 mm web) has ~4,000; a 0.01 mm bore caps the element size at half the bore
#: radius over the whole disk (~6e7 elements, hours and tens of GB): refused before gmsh
MAX_DISK_ELEMENTS = 300_000


def estimate_disk_elements(*, outline: np.ndarray, bore: float, h_max: float, h_bore: float,
                           growth: float, fine_h: float = 0.0, fine_xf: float = 0.0,
                           fine_depth: float = 0.0) -> float:
    r"""Estimated triangles of :func:`mesh_cam_disk` (area over the triangle area, per zone).

    .. math::

        N \approx \frac{A - \pi R_b^2}{c\, h_{max}^2}
          + \frac{2 \pi R_b}{c\, g\, h_b} + \frac{2\pi}{c\, g^2}\ln\frac{h_{max}}{h_b}
          + \frac{2 x_f d}{c\, h^2} + \frac{2 x_f}{c\, g\, h}

    with ``c = sqrt(3)/4`` (equilateral triangles): the disk at the largest size, the band
    graded from the bore spacing ``h_b`` with slope ``g``, and the fine contact zone.

    Parameters
    ----------
    outline : ndarray, shape (2, N)
        The cam outline (m).
    bore : float
        Bore radius (m).
    h_max, h_bore : float
        Largest element size and bore spacing (m).
    growth : float
        Size growth slope (-).
    fine_h, fine_xf, fine_depth : float, optional
        Fine contact zone: size, half-length and depth (m); 0: none.

    Returns
    -------
    float
        The estimate (-).

    Examples
    --------
    >>> t = np.linspace(0, 2 * np.pi, 361)[:-1]
    >>> round(estimate_disk_elements(outline=0.01 * np.array([np.cos(t), np.sin(t)]),
    ...       bore=0.005, h_max=1e-3, h_bore=5e-4, growth=0.3))
    1140
    """
    c = math.sqrt(3.0) / 4.0
    x, y = np.asarray(outline, float)
    area = 0.5 * abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))
    n = max(area - math.pi * bore**2, 0.0) / (c * h_max**2)
    n += 2 * math.pi * bore / (c * growth * h_bore) \
        + 2 * math.pi / (c * growth**2) * math.log(max(h_max / h_bore, 1.0))
    if fine_h > 0:
        n += 2 * fine_xf * fine_depth / (c * fine_h**2) + 2 * fine_xf / (c * growth * fine_h)
    return n


def mesh_cam_disk(*, outline: np.ndarray, centre: tuple, bore: float, n_bore: int, h_max: float,
                  h_bore: float, growth: float = 0.3, contact_x: np.ndarray | None = None,
                  rho: float = math.inf, W: float = 0.0, fine_depth: float = 0.0,
                  band: float = 3.0) -> tuple[BodyMesh, np.ndarray, np.ndarray]:
    """Mesh the cam disk with its bore (module docstring).

    Parameters
    ----------
    outline : ndarray, shape (2, N)
        Outline points [m] ordered counter-clockwise about ``centre``; with a fine zone
        (``contact_x`` given) they leave out the arc ``|x| <= W`` at the contact and run from its
        left end (``x = -W``) round to its right end (``x = +W``).
    centre : (float, float)
        Cam centre in the mesh frame [m].
    bore : float
        Bore radius [m].
    n_bore : int
        Bore vertices (a multiple of 4).
    h_max : float
        Largest element size [m].
    h_bore : float
        Element size at the bore [m].
    growth : float, optional
        Size growth slope away from the bore and fine arc [-].
    contact_x : ndarray, shape (n_fine + 1,), optional
        Roller contact abscissae [m] the fine-zone vertices snap to; None for no fine zone.
    rho : float, optional
        Cam radius of curvature at the contact [m] (< 0 concave, inf flat).
    W : float, optional
        Half-span of the osculating-circle arc at the contact [m].
    fine_depth : float, optional
        Depth below the fine arc meshed at the fine size [m].
    band : float, optional
        Width of the band at the bore meshed at ``h_bore``, in multiples of ``h_bore`` [-].

    Returns
    -------
    mesh : BodyMesh
        The cam mesh; ``contact`` are the fine-arc vertices sorted by x (empty without a fine
        zone); ``fixed`` is empty (the cam floats on its shaft).
    bore_nodes : ndarray of int, shape (n_bore,)
        Bore vertex nodes, ordered counter-clockwise from ``theta = -pi/2``.
    bore_theta : ndarray, shape (n_bore,)
        Their polar angles about ``centre`` [rad], uniform from ``-pi/2``.

    Raises
    ------
    FemcamError
        gmsh returned a fine zone with the wrong number of nodes.
    """
    cx, cy = centre
    fine = contact_x is not None
    _check_size(outline, bore, h_max, h_bore, growth, contact_x, fine_depth)
    with gmsh_session() as gmsh:
        gmsh.model.add("cam_disk")
        geo = gmsh.model.geo
        pts = [geo.addPoint(float(x), float(y), 0.0, h_max) for x, y in outline.T]
        if fine:
            xf = float(contact_x[-1])
            ends, arcs = _fine_arcs(geo, rho, [W, xf, -xf, -W], h_max)
            spline = geo.addSpline([ends[-1]] + pts + [ends[0]])
            loop = arcs + [spline]
            geo.mesh.setTransfiniteCurve(arcs[1], contact_x.size)
        else:
            loop = [geo.addSpline(pts + [pts[0]])]
        _, _, b_arcs = _circle_arcs(geo, cx, cy, bore, [-0.5 * math.pi + k * 0.5 * math.pi
                                                        for k in range(5)], h_max)
        s = geo.addPlaneSurface([geo.addCurveLoop(loop), geo.addCurveLoop(b_arcs)])
        for arc in b_arcs:
            geo.mesh.setTransfiniteCurve(arc, n_bore // 4 + 1)
        geo.synchronize()
        gmsh.model.addPhysicalGroup(1, loop, name="cam_outline")
        gmsh.model.addPhysicalGroup(1, b_arcs, name="cam_bore")
        gmsh.model.addPhysicalGroup(2, [s], name="cam")
        specs = [(b_arcs, h_bore, band * h_bore)]
        sets = {"bore": (1, b_arcs), "outer": (1, loop)}
        if fine:
            h = float(contact_x[1] - contact_x[0])
            specs.append(([arcs[1]], h, fine_depth))
            sets["fine"] = (1, [arcs[1]])
        _size_field(gmsh, specs, h_max, growth)
        gmsh.model.mesh.generate(2)
        p, tri, sets = _extract(gmsh, s, sets)
        gmsh.model.remove()
    contact = np.zeros(0, dtype=np.int64)
    cxs = np.zeros(0)
    if fine:
        contact = sets["fine"][np.argsort(p[sets["fine"], 0])]
        if contact.size != contact_x.size:
            raise FemcamError(f"gmsh returned {contact.size} fine-zone nodes, expected {contact_x.size}")
        p[contact, 0] = contact_x
        p[contact, 1] = -surface_height(contact_x, rho)
        cxs = np.asarray(contact_x, float)
    bnodes, theta = _snap_circle(p, sets["bore"], cx, cy, bore, n_bore)
    tri = _ccw(p, tri)
    body = BodyMesh(name="cam", points=p.T.copy(), triangles=tri.T.copy(), fixed=np.zeros(0, dtype=np.int64),
                    contact=contact, contact_x=cxs, surface=sets["outer"], L=float(np.hypot(cx, cy)),
                    R=float(rho))
    return body, bnodes, theta


def _check_size(outline, bore, h_max, h_bore, growth, contact_x, fine_depth) -> None:
    """Refuse a disk mesh estimated above :data:`MAX_DISK_ELEMENTS`, before gmsh, naming the
    bore radius (what sets the sizes) and why."""
    fine = contact_x is not None and len(contact_x) > 1
    n = estimate_disk_elements(
        outline=outline, bore=bore, h_max=h_max, h_bore=h_bore, growth=growth,
        fine_h=float(contact_x[1] - contact_x[0]) if fine else 0.0,
        fine_xf=float(contact_x[-1]) if fine else 0.0, fine_depth=fine_depth)
    if n > MAX_DISK_ELEMENTS:
        raise InputError(
            f"[cam] bore_mm = {bore * 1e3:.4g} mm (bore radius): the cam disk mesh would have "
            f"~{n:.3g} elements (largest element {h_max * 1e6:.3g} um, bore spacing "
            f"{h_bore * 1e6:.3g} um; the element size is at most half the bore radius and a "
            f"fraction of the web), above the cap of {MAX_DISK_ELEMENTS:,} "
            "(femcam.bodies.cam_mesh.MAX_DISK_ELEMENTS); a bore this small or a web this thin "
            "is not a cam on a shaft: use a bore radius of a few mm, or leave out [cam] bore_mm")
