"""A body with a coating band over its whole surface arc (used by :mod:`femcam.layers`).

The band is three structured (transfinite) strips of triangles bounded by the surface arc, the
concentric arc at depth ``t`` (the coating-substrate interface) and radial lines: ``n`` layers
through the thickness (``max(coat_layers, ceil(t / h))``), the fine-zone spacing ``h`` along
the middle strip and a geometric growth (ratio 1.15) from ``h`` outwards along the side strips.
The substrate below is meshed as the plain body (size field on the fine zone). Physical groups
``<body>_coating`` (band triangles) and ``<body>_interface`` (interface curves) are added;
``BodyMesh.coating`` marks the band triangles.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from .. import _validate
from ..errors import InputError
from .geometry import BodyLayout, size_field, surface_height
from .nodes import extract, finish_body
from .options import BodyMesh, MeshOptions

#: largest in-plane / through-thickness element size ratio in the coating band's fine zone
COAT_MAX_ASPECT = 40.0

#: largest a_over_h the scene and --a-over-h accept (femcam.scene.ranges)
A_OVER_H_MAX = 400.0

#: growth ratio of the element size along the side strips of the band
_SIDE_RATIO = 1.15


def _layers(lay: BodyLayout, opts: MeshOptions) -> int:
    """Element layers through the coating; refuses a band too thin for the mesh or too thick
    for the body (``InputError`` naming ``coat_thickness`` in um)."""
    t, h = opts.coat_thickness, lay.h
    n = max(int(opts.coat_layers), math.ceil(t / h - 1e-9))
    if h / (t / n) > COAT_MAX_ASPECT:
        need = lay.a_ref / (COAT_MAX_ASPECT * t / n)
        raise _validate.fail("coat_thickness ([materials.*.coating] thickness_um)", t * 1e6, "um",
                             f"is too thin for the mesh: {n} layers of {t / n * 1e6:.3g} um under a "
                             f"fine-zone spacing h = {h * 1e6:.3g} um give an element aspect ratio "
                             f"{h / (t / n):.0f} > {COAT_MAX_ASPECT:g}; use a_over_h >= {need:.0f} "
                             "([fe] a_over_h or --a-over-h)"
                             + (f", beyond its limit {A_OVER_H_MAX:g}: the contact FE cannot resolve "
                                "a coating this thin" if need > A_OVER_H_MAX else ""))
    if t > 0.25 * lay.L:
        raise _validate.fail("coat_thickness ([materials.*.coating] thickness_um)", t * 1e6, "um",
                             f"must be <= L/4 = {0.25 * lay.L * 1e6:.4g} um (body {lay.name} size L)")
    return n


def _band_geometry(gmsh, lay: BodyLayout, t: float):
    """Surface arcs, interface arcs, radial lines, band and substrate surfaces and the fixed
    bottom (gmsh tags) of a body coated to depth ``t`` (m)."""
    geo = gmsh.model.geo
    R, L, W, lc = lay.R, lay.L, lay.W, lay.lc
    xs = np.array([-W, -lay.xf, lay.xf, W])
    ys = -surface_height(xs, R)
    if math.isinf(R):
        qx, qy = xs, ys - t
    else:  # concentric arc at depth t (centre (0, -R); R < 0 concave)
        s = (R - t) / R
        qx, qy = s * xs, -R + s * (ys + R)
    if not (qy[0] > -L + 1e-12 * L and qy[3] > -L + 1e-12 * L):
        raise InputError(f"body {lay.name}: coated arc reaches the fixed support; use a larger |R|")
    p = [geo.addPoint(x, y, 0.0, lc) for x, y in zip(xs, ys, strict=True)]
    q = [geo.addPoint(x, y, 0.0, lc) for x, y in zip(qx, qy, strict=True)]
    if math.isinf(R):
        arcs = [geo.addLine(p[i], p[i + 1]) for i in range(3)]
        inner = [geo.addLine(q[i], q[i + 1]) for i in range(3)]
    else:
        c = geo.addPoint(0.0, -R, 0.0, lc)
        arcs = [geo.addCircleArc(p[i], c, p[i + 1]) for i in range(3)]
        inner = [geo.addCircleArc(q[i], c, q[i + 1]) for i in range(3)]
    radial = [geo.addLine(q[i], p[i]) for i in range(4)]
    band = [geo.addPlaneSurface([geo.addCurveLoop([inner[i], radial[i + 1], -arcs[i], -radial[i]])])
            for i in range(3)]
    br, bl = geo.addPoint(W, -L, 0.0, lc), geo.addPoint(-W, -L, 0.0, lc)
    right, bottom, left = geo.addLine(q[3], br), geo.addLine(br, bl), geo.addLine(bl, q[0])
    sub = geo.addPlaneSurface([geo.addCurveLoop(inner + [right, bottom, left])])
    return arcs, inner, radial, band, sub, bottom


def _transfinite_band(geo, lay: BodyLayout, n: int, arcs, inner, radial, band) -> None:
    """Structured strips: ``n`` layers radially, spacing ``h`` in the middle strip, geometric
    growth from ``h`` along the side strips."""
    r = _SIDE_RATIO
    n_side = max(2, math.ceil(math.log(1.0 + (lay.W - lay.xf) * (r - 1.0) / lay.h) / math.log(r)))
    for cv in radial:
        geo.mesh.setTransfiniteCurve(cv, n + 1)
    for k in (0, 2):  # small elements next to the fine zone
        prog = 1.0 / r if k == 0 else r
        geo.mesh.setTransfiniteCurve(arcs[k], n_side + 1, "Progression", prog)
        geo.mesh.setTransfiniteCurve(inner[k], n_side + 1, "Progression", prog)
    geo.mesh.setTransfiniteCurve(arcs[1], lay.n_fine + 1)
    geo.mesh.setTransfiniteCurve(inner[1], lay.n_fine + 1)
    for sf in band:
        geo.mesh.setTransfiniteSurface(sf)


def mesh_coated_body(gmsh, lay: BodyLayout, opts: MeshOptions) -> BodyMesh:
    """Mesh one body with a coating band of thickness ``opts.coat_thickness`` (m).

    Parameters
    ----------
    gmsh : module
        The gmsh module; :func:`~femcam.mesh.mesh_body` has added the body's empty model.
    lay : BodyLayout
        Fine spacing ``h``, fine zone ``xf``, arc half-width ``W`` and body size ``L`` (m).
    opts : MeshOptions
        ``coat_body == lay.name``; ``coat_thickness`` (m) and ``coat_layers`` set the band.

    Returns
    -------
    BodyMesh
        In the cam orientation, with ``coating`` set (bool per triangle).

    Raises
    ------
    InputError
        The coating is too thin for the mesh or too thick for the body.
    """
    n = _layers(lay, opts)
    name = lay.name
    arcs, inner, radial, band, sub, bottom = _band_geometry(gmsh, lay, opts.coat_thickness)
    _transfinite_band(gmsh.model.geo, lay, n, arcs, inner, radial, band)
    gmsh.model.geo.synchronize()
    gmsh.model.addPhysicalGroup(1, arcs, name=f"{name}_contact")
    gmsh.model.addPhysicalGroup(1, [bottom], name=f"{name}_fixed")
    gmsh.model.addPhysicalGroup(2, band + [sub], name=name)
    gmsh.model.addPhysicalGroup(2, band, name=f"{name}_coating")
    gmsh.model.addPhysicalGroup(1, inner, name=f"{name}_interface")
    size_field(gmsh, arcs[1], lay, opts)
    gmsh.model.mesh.generate(2)
    parts = extract(gmsh, -1, arcs, bottom)
    gmsh.model.remove()
    body = finish_body(lay, *parts)
    coat = body.groups[f"{name}_coating"].elements
    key = np.sort(body.triangles, axis=0)
    ck = {tuple(e) for e in np.sort(coat, axis=0).T}
    mask = np.fromiter((tuple(e) in ck for e in key.T), dtype=bool, count=key.shape[1])
    return replace(body, coating=mask)
