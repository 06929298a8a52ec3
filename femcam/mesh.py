"""gmsh mesh of the contact region of a cam-roller pair (one mesh per body).

Geometry (local contact frame, SI units)
----------------------------------------
The two bodies touch at the origin; ``x`` runs along the common tangent, ``y`` points from the
cam into the roller. Each body is meshed on its own (no shared nodes):

* **cam** (below, ``y <= 0``): surface arc of signed radius ``rho`` (> 0 convex, < 0 concave,
  ``inf`` flat), ``y_s(x) = -kappa x^2 / (1 + sqrt(1 - kappa^2 x^2))`` with ``kappa = 1/rho``
  (this is ``-(rho - sqrt(rho^2 - x^2))`` written so that it stays exact as ``kappa -> 0``);
  the arc spans ``|x| <= W = 0.9 L``, vertical sides run down to ``y = -L`` and the bottom
  ``y = -L`` is the fixed support (``"cam_fixed"``).
* **roller** (above): the same construction with radius ``Rr`` mirrored to ``y >= 0``; its
  far cut ``y = L`` is fixed (``"roller_fixed"``). With ``L = Rr`` the roller is a disk sector
  clamped along (most of) its diameter: the bore/pin far from the contact.

``L = min(|R|, Lcap)`` per body with ``Lcap = MeshOptions.domain_over_a * a_ref`` (default: no
cap for the roller, ``Rr`` for a flat or large cam), so the finite-body effect is a parameter
that can be studied (``docs/fe.md``).

Mesh: linear triangles. The surface is split at ``x = +-c a_ref`` (``c = fine_half_width``); the
middle curve is transfinite with a uniform vertex spacing ``h = a_ref / a_over_h`` and its
vertices are snapped to the exact uniform abscissae ``x_i = -c a_ref + i h`` on the arc, so that
the cam and roller contact vertices pair one to one. A gmsh ``Threshold`` field on the distance
to that curve keeps ``h`` within ``fine_depth * a_ref`` of it and then grows linearly with slope
``growth`` up to ``L / 8``. Size-from-points/curvature/boundary are switched off because they
override the field. Arc-centre points that gmsh returns unreferenced are dropped.

Physical groups (``PHYSICAL_NAMES``) are read back from gmsh before its model is removed and
kept in ``BodyMesh.groups`` (dimension, tag, elements in the body's node numbering);
``ContactMesh.write_msh`` writes both bodies with them to a gmsh ``.msh`` file.

Defaults of every parameter are recorded in ``meshes/contact_region.toml``; the same geometry
as a gmsh ``.geo`` file with ``DefineConstant`` sliders is ``meshes/contact_region.geo`` (one
body; a flat cam needs its ``flat`` switch; no vertex snapping; see its header).
"""

from __future__ import annotations

import math
import os
import threading
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from . import _validate
from .errors import FemcamError, InputError
from .hertz.conformity import roller_does_not_fit

#: Held around every use of gmsh (initialise, mesh, finalise): gmsh keeps one global state per
#: process and is not thread-safe (Dask runs several tasks in threads of one worker process).
GMSH_LOCK = threading.RLock()

#: physical names written into the gmsh model (one set per body)
PHYSICAL_NAMES = ("roller_contact", "cam_contact", "roller_fixed", "cam_fixed", "roller", "cam")


@dataclass(frozen=True, kw_only=True)
class MeshOptions:
    """Mesh parameters, all relative to the reference half-width ``a_ref``.

    a_over_h: number of elements per half-width in the fine zone (h = a_ref / a_over_h).
    fine_half_width: fine zone spans |x| <= fine_half_width * a_ref along each contact curve.
    fine_depth: the mesh stays at size h up to this distance (x a_ref) from the fine curve.
    growth: slope d(size)/d(distance) beyond the fine band (0.05 .. 1).
    domain_over_a: body size cap L <= domain_over_a * a_ref (None: roller L = Rr,
        cam L = min(|rho|, Rr)).
    max_size_fraction: largest element size as a fraction of the body size L.
    """

    a_over_h: float = 20.0
    fine_half_width: float = 2.5
    fine_depth: float = 0.6
    growth: float = 0.3
    domain_over_a: float | None = None
    max_size_fraction: float = 0.125
    #: optional coating band on one body (femcam.layers): body name, thickness (m), layers
    coat_body: str | None = None
    coat_thickness: float = 0.0
    coat_layers: int = 4

    def __post_init__(self):
        _validate.in_range("a_over_h", self.a_over_h, 2.0, 400.0, "")
        _validate.in_range("fine_half_width", self.fine_half_width, 1.2, 20.0, "(x a_ref)")
        _validate.in_range("fine_depth", self.fine_depth, 0.0, 20.0, "(x a_ref)")
        _validate.in_range("growth", self.growth, 0.05, 1.0, "")
        if self.domain_over_a is not None:
            _validate.in_range("domain_over_a", self.domain_over_a, 5.0 * self.fine_half_width, 1e7,
                               "(x a_ref)")
        _validate.in_range("max_size_fraction", self.max_size_fraction, 0.01, 0.5, "")
        if self.coat_body is not None:
            _validate.choice("coat_body", self.coat_body, ("cam", "roller"))
            _validate.positive("coat_thickness", self.coat_thickness, "m")
            _validate.in_range("coat_layers", self.coat_layers, 2, 200, "")


@dataclass(frozen=True)
class PhysicalGroup:
    """A gmsh physical group of one body, kept after the gmsh model is removed.

    name (e.g. ``"cam_contact"``), dim (1 curve, 2 surface), tag (gmsh physical tag) and
    elements (k, n): node indices of this body's mesh, k = 2 (line segments) or 3 (triangles,
    counter-clockwise), as gmsh meshed them.
    """

    name: str
    dim: int
    tag: int
    elements: np.ndarray

    @property
    def nodes(self) -> np.ndarray:
        """Sorted unique node indices of the group."""
        return np.unique(self.elements)


@dataclass(frozen=True)
class BodyMesh:
    """Linear triangle mesh of one body.

    points (2, N) m; triangles (3, T) counter-clockwise; fixed (nodes on the fixed support);
    contact (fine-zone vertex nodes, sorted by x); contact_x their abscissae (m, uniform);
    surface (all nodes on the contact surface curve); L body size (m); R surface radius (m,
    signed, inf for flat); groups: the gmsh physical groups ``{name: PhysicalGroup}``
    (``<body>_contact``, ``<body>_fixed`` curves and the ``<body>`` surface).
    """

    name: str
    points: np.ndarray
    triangles: np.ndarray
    fixed: np.ndarray
    contact: np.ndarray
    contact_x: np.ndarray
    surface: np.ndarray
    L: float
    R: float
    groups: dict = field(default_factory=dict)
    #: bool per triangle, True in the coating band (None: uncoated body)
    coating: np.ndarray | None = None


@dataclass(frozen=True)
class ContactMesh:
    """The two body meshes and the parameters they were built with.

    Attributes
    ----------
    cam, roller : BodyMesh
        The roller mirrored above y = 0.
    Rr, rho : float
        Roller and cam radii (m; rho < 0 concave, inf flat).
    a_ref, h : float
        Reference half-width and fine element size (m).
    options : MeshOptions
    """

    cam: BodyMesh
    roller: BodyMesh
    Rr: float
    rho: float
    a_ref: float
    h: float
    options: MeshOptions

    @property
    def n_nodes(self) -> int:
        return self.cam.points.shape[1] + self.roller.points.shape[1]

    @property
    def physical_groups(self) -> dict:
        """``{name: PhysicalGroup}`` of both bodies (node indices are per body)."""
        return {**self.cam.groups, **self.roller.groups}

    def write_msh(self, path):
        """Write both bodies (final snapped/mirrored nodes, m) to a gmsh 2.2 ASCII ``.msh`` with
        the physical names ``roller_contact, cam_contact, roller_fixed, cam_fixed, roller, cam``
        (via meshio; roller nodes follow the cam's). ``path`` must end in ``.msh``. Returns the
        path."""
        import meshio  # lazy: meshio loads its many format plugins; only .msh export needs it

        if not isinstance(path, str | os.PathLike):
            raise _validate.fail("path", path, "", "must be a file path (str or os.PathLike) ending in .msh")
        path = Path(path)
        if path.suffix.lower() != ".msh":
            raise _validate.fail("path", str(path), "", "must end in .msh (gmsh 2.2 ASCII mesh)")
        pts, cells, phys, names = [], [], [], {}
        off = 0
        for b in (self.cam, self.roller):
            pts.append(np.column_stack([b.points.T, np.zeros(b.points.shape[1])]))
            for g in b.groups.values():
                # tags unique over both bodies: cam groups keep theirs, roller's are shifted
                tag = g.tag + (0 if b is self.cam else 100)
                cells.append(("line" if g.dim == 1 else "triangle", g.elements.T + off))
                phys.append(np.full(g.elements.shape[1], tag))
                names[g.name] = np.array([tag, g.dim])
            off += b.points.shape[1]
        mesh = meshio.Mesh(np.concatenate(pts), cells,
                           cell_data={"gmsh:physical": phys, "gmsh:geometrical": phys},
                           field_data=names)
        path.parent.mkdir(parents=True, exist_ok=True)
        meshio.write(path, mesh, file_format="gmsh22", binary=False)
        return path


def surface_height(x, R):
    r"""Depth of a circular arc of signed radius ``R`` below its tangent at x = 0 (m).

    .. math:: \delta(x) = R - \sqrt{R^2 - x^2} = \frac{\kappa x^2}{1 + \sqrt{1 - \kappa^2 x^2}},
              \quad \kappa = 1/R

    exact for every ``R`` including ``inf`` (flat, 0) and ``R < 0`` (concave, negative).

    >>> round(float(surface_height(0.006, 0.01)) * 1e3, 6)
    2.0
    """
    x = np.asarray(x, dtype=float)
    k = 0.0 if math.isinf(R) else 1.0 / R
    return k * x**2 / (1.0 + np.sqrt(np.maximum(1.0 - (k * x) ** 2, 0.0)))


def _body_size(R: float, cap: float | None, default_cap: float) -> float:
    L = abs(R) if math.isfinite(R) else math.inf
    c = cap if cap is not None else default_cap
    return min(L, c)


def _mesh_body(gmsh, name: str, R: float, L: float, a_ref: float, opts: MeshOptions) -> BodyMesh:
    """Mesh one body in the cam orientation (below y = 0); caller mirrors the roller."""
    h = a_ref / opts.a_over_h
    xf = opts.fine_half_width * a_ref
    n_fine = int(round(2 * xf / h))
    xf = 0.5 * n_fine * h  # exact multiple of h
    W = 0.9 * L
    if W <= xf * 1.5:
        raise InputError(f"body size L = {L:g} m is too small for the fine zone |x| <= {xf:g} m "
                         f"({name}); increase domain_over_a or reduce fine_half_width")
    lc = L * opts.max_size_fraction
    gmsh.model.add(name)
    if opts.coat_body == name:
        return _mesh_coated_body(gmsh, name, R, L, W, xf, lc, h, n_fine, a_ref, opts)
    arcs, bottom, surface = _geometry(gmsh, name, R, L, W, xf, lc)
    geo = gmsh.model.geo
    geo.mesh.setTransfiniteCurve(arcs[1], n_fine + 1)
    geo.synchronize()
    gmsh.model.addPhysicalGroup(1, arcs, name=f"{name}_contact")
    gmsh.model.addPhysicalGroup(1, [bottom], name=f"{name}_fixed")
    gmsh.model.addPhysicalGroup(2, [surface], name=name)
    _size_field(gmsh, arcs[1], n_fine, h, lc, a_ref, opts)
    gmsh.model.mesh.generate(2)
    pts, tri, fine, surf, fixed, groups = _extract(gmsh, surface, arcs, bottom)
    gmsh.model.remove()
    return _body_mesh(name, R, L, pts, tri, fine, surf, fixed, groups, n_fine, xf, h)


def _geometry(gmsh, name: str, R: float, L: float, W: float, xf: float, lc: float):
    """The body's outline: three surface arcs (the middle one is the fine zone ``|x| <= xf``),
    the sides and the fixed bottom at ``y = -L``. Returns ``(arcs, bottom, surface)`` tags."""
    geo = gmsh.model.geo
    ys = -surface_height(np.array([-W, -xf, xf, W]), R)
    if not (ys[3] > -L + 1e-12 * L and ys[0] > -L + 1e-12 * L):
        raise InputError(f"body {name}: arc reaches the fixed support; use a larger |R| or smaller W")
    p = [geo.addPoint(x, y, 0.0, lc) for x, y in zip((-W, -xf, xf, W), ys, strict=True)]
    if math.isinf(R):
        arcs = [geo.addLine(p[0], p[1]), geo.addLine(p[1], p[2]), geo.addLine(p[2], p[3])]
    else:
        c = geo.addPoint(0.0, -R, 0.0, lc)
        arcs = [geo.addCircleArc(p[i], c, p[i + 1]) for i in range(3)]
    br = geo.addPoint(W, -L, 0.0, lc)
    bl = geo.addPoint(-W, -L, 0.0, lc)
    right = geo.addLine(p[3], br)
    bottom = geo.addLine(br, bl)
    left = geo.addLine(bl, p[0])
    cl = geo.addCurveLoop(arcs + [right, bottom, left])
    return arcs, bottom, geo.addPlaneSurface([cl])


def _size_field(gmsh, fine_curve, n_fine: int, h: float, lc: float, a_ref: float,
                opts: MeshOptions) -> None:
    """Element size ``h`` within ``fine_depth * a_ref`` of the fine zone, growing to ``lc``."""
    f = gmsh.model.mesh.field
    fd = f.add("Distance")
    f.setNumbers(fd, "CurvesList", [fine_curve])
    f.setNumber(fd, "Sampling", max(2 * n_fine, 100))
    ft = f.add("Threshold")
    f.setNumber(ft, "InField", fd)
    f.setNumber(ft, "SizeMin", h)
    f.setNumber(ft, "SizeMax", lc)
    f.setNumber(ft, "DistMin", opts.fine_depth * a_ref)
    f.setNumber(ft, "DistMax", opts.fine_depth * a_ref + (lc - h) / opts.growth)
    f.setAsBackgroundMesh(ft)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.Algorithm", 6)  # Frontal-Delaunay: good quality graded meshes
    gmsh.option.setNumber("Mesh.ElementOrder", 1)


def _extract(gmsh, surface, arcs, bottom):
    """Nodes, triangles, node sets (fine zone, surface, fixed) and physical groups of the meshed
    model, in gmsh's node numbering mapped to 0-based indices."""
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    pts = xyz.reshape(-1, 3)[:, :2]
    index = np.full(int(tags.max()) + 1, -1, dtype=np.int64)
    index[tags.astype(np.int64)] = np.arange(tags.size)
    _, _, ntri = gmsh.model.mesh.getElements(2, surface)
    tri = index[np.asarray(ntri[0], dtype=np.int64)].reshape(-1, 3)

    def curve_nodes(curves):
        out = []
        for cv in curves:
            nt = gmsh.model.mesh.getNodes(1, cv, includeBoundary=True)[0]
            out.append(index[nt.astype(np.int64)])
        return np.unique(np.concatenate(out))

    groups = {}
    for gdim, gtag in gmsh.model.getPhysicalGroups():
        blocks = []
        for ent in gmsh.model.getEntitiesForPhysicalGroup(gdim, gtag):
            types, _, ntags = gmsh.model.mesh.getElements(gdim, int(ent))
            for et, nt in zip(types, ntags, strict=True):
                nn = gmsh.model.mesh.getElementProperties(et)[3]
                blocks.append(index[np.asarray(nt, dtype=np.int64)].reshape(-1, nn))
        groups[gmsh.model.getPhysicalName(gdim, gtag)] = (gdim, int(gtag), np.concatenate(blocks))
    return pts, tri, curve_nodes([arcs[1]]), curve_nodes(arcs), curve_nodes([bottom]), groups


def _body_mesh(name, R, L, pts, tri, fine, surf, fixed, groups, n_fine, xf, h) -> BodyMesh:
    """Drop unreferenced nodes, snap the fine zone to the exact arc, orient triangles."""
    # drop unreferenced nodes (arc centres, geometry-only points)
    used = np.unique(tri)
    renum = np.full(pts.shape[0], -1, dtype=np.int64)
    renum[used] = np.arange(used.size)
    pts = pts[used]
    tri = renum[tri]
    fine, surf, fixed = renum[fine], renum[surf], renum[fixed]
    groups = {k: (d, t, renum[e]) for k, (d, t, e) in groups.items()}
    # snap fine-zone vertices to the uniform abscissae on the exact arc
    order = np.argsort(pts[fine, 0])
    fine = fine[order]
    if fine.size != n_fine + 1:
        raise FemcamError(f"gmsh returned {fine.size} fine-zone nodes, expected {n_fine + 1}")
    xs = -xf + h * np.arange(n_fine + 1)
    pts[fine, 0] = xs
    pts[fine, 1] = -surface_height(xs, R)
    # counter-clockwise triangles
    tri = _ccw(pts, tri)
    phys = {k: PhysicalGroup(name=k, dim=d, tag=t, elements=(_ccw(pts, e) if d == 2 else e).T.copy())
            for k, (d, t, e) in groups.items()}
    return BodyMesh(name=name, points=pts.T.copy(), triangles=tri.T.copy(), fixed=fixed,
                    contact=fine, contact_x=xs, surface=surf, L=float(L), R=float(R), groups=phys)


def _ccw(pts: np.ndarray, tri: np.ndarray) -> np.ndarray:
    """Triangles (T, 3) reordered counter-clockwise for points (N, 2)."""
    tri = tri.copy()
    d = pts[tri]
    det = (d[:, 1, 0] - d[:, 0, 0]) * (d[:, 2, 1] - d[:, 0, 1]) - \
          (d[:, 2, 0] - d[:, 0, 0]) * (d[:, 1, 1] - d[:, 0, 1])
    tri[det < 0] = tri[det < 0][:, [0, 2, 1]]
    return tri


def _mirror(b: BodyMesh) -> BodyMesh:
    pts = b.points.copy()
    pts[1] *= -1.0
    tri = b.triangles[[0, 2, 1]].copy()
    groups = {k: PhysicalGroup(name=g.name, dim=g.dim, tag=g.tag,
                               elements=g.elements[[0, 2, 1]].copy() if g.dim == 2 else g.elements)
              for k, g in b.groups.items()}
    return BodyMesh(name=b.name, points=pts, triangles=tri, fixed=b.fixed, contact=b.contact,
                    contact_x=b.contact_x, surface=b.surface, L=b.L, R=b.R, groups=groups,
                    coating=b.coating)


def build_contact_mesh(*, Rr: float, rho: float, a_ref: float,
                       options: MeshOptions | None = None) -> ContactMesh:
    """Mesh the cam and roller bodies around the contact (see module docstring).

    Rr roller radius (m, > 0); rho cam surface radius of curvature (m; < 0 concave, inf flat);
    a_ref the contact half-width the mesh is graded for (m).
    """
    opts = options or MeshOptions()
    Rr = _validate.positive("Rr", Rr, "m")
    a_ref = _validate.positive("a_ref", a_ref, "m")
    rho = float(rho)
    if math.isnan(rho) or rho == 0.0:
        raise _validate.fail("rho", rho, "m", "must be nonzero (use inf for a flat cam)")
    if roller_does_not_fit(rho, Rr):
        raise _validate.fail("rho", rho, "m", f"a concave cam needs |rho| > Rr = {Rr:g} m (else the roller "
                     "does not fit)")
    if opts.fine_half_width * a_ref > 0.5 * Rr:
        raise _validate.fail("a_ref", a_ref, "m", f"must be <= Rr/(2 fine_half_width) = "
                     f"{Rr / (2 * opts.fine_half_width):g} m: the contact zone would not be small "
                     "against the roller (far outside Hertz theory and this mesh layout)")
    cap = None if opts.domain_over_a is None else opts.domain_over_a * a_ref
    L_roller = _body_size(Rr, cap, math.inf)
    L_cam = _body_size(rho, cap, Rr)
    import gmsh  # lazy: gmsh is a large native library, loaded only to build meshes

    with GMSH_LOCK:  # gmsh is one global, non-thread-safe state per process
        init_here = not gmsh.isInitialized()
        if init_here:
            # interruptible=False: gmsh would install its own SIGINT handler (which ends the
            # process silently on Ctrl-C, and which Python allows only in the main thread, while
            # Dask runs tasks in worker threads); Python's KeyboardInterrupt stays in charge
            gmsh.initialize(["-nopopup"], readConfigFiles=False, interruptible=False)
        try:
            gmsh.option.setNumber("General.Terminal", 0)
            gmsh.option.setNumber("General.Verbosity", 1)
            cam = _mesh_body(gmsh, "cam", rho, L_cam, a_ref, opts)
            roller = _mirror(_mesh_body(gmsh, "roller", Rr, L_roller, a_ref, opts))
        except FemcamError:
            raise
        except Exception as exc:  # gmsh raises plain Exception
            raise FemcamError(f"gmsh failed to mesh the contact region: {exc}") from None
        finally:
            if init_here:
                gmsh.finalize()
    return ContactMesh(cam=cam, roller=roller, Rr=Rr, rho=rho, a_ref=a_ref,
                       h=a_ref / opts.a_over_h, options=opts)


# ---------------------------------------------------------------------------- coating band
#: largest in-plane / through-thickness element size ratio in the coating band's fine zone
COAT_MAX_ASPECT = 40.0


def _mesh_coated_body(gmsh, name, R, L, W, xf, lc, h, n_fine, a_ref, opts) -> BodyMesh:
    """Mesh one body with a coating band of thickness ``t`` over its whole surface arc.

    The band is three structured (transfinite) strips of triangles bounded by the surface arc,
    the concentric arc at depth ``t`` (the coating-substrate interface) and radial lines: ``n``
    layers through the thickness (``max(coat_layers, ceil(t / h))``), the fine-zone spacing
    ``h`` along the middle strip and a geometric growth (ratio 1.15) from ``h`` outwards along
    the side strips. The substrate below is meshed as before (size field on the fine zone).
    Physical groups ``<body>_coating`` (band triangles) and ``<body>_interface`` (interface
    curves) are added; ``BodyMesh.coating`` marks the band triangles.
    """
    t = opts.coat_thickness
    n = max(int(opts.coat_layers), math.ceil(t / h - 1e-9))
    if h / (t / n) > COAT_MAX_ASPECT:
        need = a_ref / (COAT_MAX_ASPECT * t / n)
        raise _validate.fail("coat_thickness", t * 1e6, "um",
                             f"is too thin for the mesh: {n} layers of {t / n * 1e6:.3g} um under a "
                             f"fine-zone spacing h = {h * 1e6:.3g} um give an element aspect ratio "
                             f"{h / (t / n):.0f} > {COAT_MAX_ASPECT:g}; use a_over_h >= {need:.0f} "
                             "or more coat_layers")
    if t > 0.25 * L:
        raise _validate.fail("coat_thickness", t * 1e6, "um",
                             f"must be <= L/4 = {0.25 * L * 1e6:.4g} um (body {name} size L)")
    geo = gmsh.model.geo
    xs = np.array([-W, -xf, xf, W])
    ys = -surface_height(xs, R)
    if math.isinf(R):
        qx, qy = xs, ys - t
    else:  # concentric arc at depth t (centre (0, -R); R < 0 concave)
        s = (R - t) / R
        qx, qy = s * xs, -R + s * (ys + R)
    if not (qy[0] > -L + 1e-12 * L and qy[3] > -L + 1e-12 * L):
        raise InputError(f"body {name}: coated arc reaches the fixed support; use a larger |R|")
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
    r = 1.15
    n_side = max(2, math.ceil(math.log(1.0 + (W - xf) * (r - 1.0) / h) / math.log(r)))
    for cv in radial:
        geo.mesh.setTransfiniteCurve(cv, n + 1)
    for k in (0, 2):  # small elements next to the fine zone
        prog = 1.0 / r if k == 0 else r
        geo.mesh.setTransfiniteCurve(arcs[k], n_side + 1, "Progression", prog)
        geo.mesh.setTransfiniteCurve(inner[k], n_side + 1, "Progression", prog)
    geo.mesh.setTransfiniteCurve(arcs[1], n_fine + 1)
    geo.mesh.setTransfiniteCurve(inner[1], n_fine + 1)
    for sf in band:
        geo.mesh.setTransfiniteSurface(sf)
    geo.synchronize()
    gmsh.model.addPhysicalGroup(1, arcs, name=f"{name}_contact")
    gmsh.model.addPhysicalGroup(1, [bottom], name=f"{name}_fixed")
    gmsh.model.addPhysicalGroup(2, band + [sub], name=name)
    gmsh.model.addPhysicalGroup(2, band, name=f"{name}_coating")
    gmsh.model.addPhysicalGroup(1, inner, name=f"{name}_interface")
    _size_field(gmsh, arcs[1], n_fine, h, lc, a_ref, opts)
    gmsh.model.mesh.generate(2)
    pts, tri, fine, surf, fixed, groups = _extract(gmsh, -1, arcs, bottom)
    gmsh.model.remove()
    body = _body_mesh(name, R, L, pts, tri, fine, surf, fixed, groups, n_fine, xf, h)
    coat = body.groups[f"{name}_coating"].elements
    key = np.sort(body.triangles, axis=0)
    ck = {tuple(e) for e in np.sort(coat, axis=0).T}
    mask = np.fromiter((tuple(e) in ck for e in key.T), dtype=bool, count=key.shape[1])
    return replace(body, coating=mask)
