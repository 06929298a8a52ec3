"""Mesh inputs and results: :class:`MeshOptions`, :class:`PhysicalGroup`, :class:`BodyMesh`,
:class:`ContactMesh` (with its gmsh ``.msh`` writer). No gmsh here (see
:mod:`femcam.mesh.session`)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .. import _validate
from .._repr import compact_repr

#: physical names written into the gmsh model (one set per body)
PHYSICAL_NAMES = ("roller_contact", "cam_contact", "roller_fixed", "cam_fixed", "roller", "cam")


@dataclass(frozen=True, kw_only=True)
class MeshOptions:
    """Mesh parameters, all relative to the reference half-width ``a_ref`` (keyword-only).

    Parameters
    ----------
    a_over_h : float
        Elements per half-width in the fine zone, ``h = a_ref / a_over_h`` (-, 2 to 400).
    fine_half_width : float
        The fine zone spans ``|x| <= fine_half_width * a_ref`` along each contact curve
        (x a_ref, 1.2 to 20).
    fine_depth : float
        The mesh stays at size ``h`` up to this distance from the fine curve (x a_ref, 0 to 20).
    growth : float
        Slope d(size)/d(distance) beyond the fine band (-, 0.05 to 1).
    domain_over_a : float or None
        Body size cap ``L <= domain_over_a * a_ref`` (x a_ref, >= 5 fine_half_width); None:
        roller ``L = Rr``, cam ``L = min(|rho|, Rr)``.
    max_size_fraction : float
        Largest element size as a fraction of the body size ``L`` (-, 0.01 to 0.5).
    coat_body : {"cam", "roller"} or None
        Body carrying a coating band (:mod:`femcam.layers`); None: no coating.
    coat_thickness : float
        Coating thickness (m, > 0 when ``coat_body`` is set).
    coat_layers : int
        Least number of element layers through the coating (-, 2 to 200).

    Raises
    ------
    InputError
        A value out of its range (names the parameter, value and unit).
    """

    a_over_h: float = 20.0
    fine_half_width: float = 2.5
    fine_depth: float = 0.6
    growth: float = 0.3
    domain_over_a: float | None = None
    max_size_fraction: float = 0.125
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
        _validate.nonnegative("coat_thickness", self.coat_thickness, "m")
        _validate.integer("coat_layers", self.coat_layers, 2, "layers")
        if self.coat_body is not None:
            _validate.choice("coat_body", self.coat_body, ("cam", "roller"))
            _validate.positive("coat_thickness", self.coat_thickness, "m")
            _validate.in_range("coat_layers", self.coat_layers, 2, 200, "")


@dataclass(frozen=True)
class PhysicalGroup:
    """A gmsh physical group of one body, kept after the gmsh model is removed.

    Parameters
    ----------
    name : str
        Physical name, e.g. ``"cam_contact"`` (:data:`PHYSICAL_NAMES`, plus ``<body>_coating``
        and ``<body>_interface`` on a coated body).
    dim : int
        1 (curve) or 2 (surface).
    tag : int
        gmsh physical tag.
    elements : ndarray of int, shape (k, n)
        Node indices into this body's mesh, ``k = 2`` (line segments) or 3 (triangles,
        counter-clockwise), as gmsh meshed them.
    """

    name: str
    dim: int
    tag: int
    elements: np.ndarray

    @property
    def nodes(self) -> np.ndarray:
        """Sorted unique node indices of the group (ndarray of int, shape (m,))."""
        return np.unique(self.elements)


@dataclass(frozen=True)
class BodyMesh:
    """Linear triangle mesh of one body.

    Parameters
    ----------
    name : {"cam", "roller"}
        The body.
    points : ndarray, shape (2, N)
        Node coordinates (m) in the contact frame.
    triangles : ndarray of int, shape (3, T)
        Counter-clockwise triangles (node indices).
    fixed : ndarray of int
        Nodes on the fixed support.
    contact : ndarray of int, shape (n_fine + 1,)
        Fine-zone vertex nodes, sorted by x.
    contact_x : ndarray, shape (n_fine + 1,)
        Their abscissae (m, uniform spacing ``h``).
    surface : ndarray of int
        All nodes on the contact surface curve.
    L : float
        Body size (m).
    R : float
        Signed surface radius (m; < 0 concave, inf flat).
    groups : dict of str to PhysicalGroup
        The gmsh physical groups (``<body>_contact``, ``<body>_fixed`` curves and the
        ``<body>`` surface).
    coating : ndarray of bool, shape (T,), or None
        True on the triangles of the coating band; None for an uncoated body.
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
    coating: np.ndarray | None = None

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)



@dataclass(frozen=True)
class ContactMesh:
    """The two body meshes and the parameters they were built with.

    Parameters
    ----------
    cam, roller : BodyMesh
        The cam below ``y = 0`` and the roller mirrored above it.
    Rr : float
        Roller radius (m).
    rho : float
        Cam surface radius of curvature (m; < 0 concave, inf flat).
    a_ref : float
        Reference half-width the mesh is graded for (m).
    h : float
        Fine element size ``a_ref / a_over_h`` (m).
    options : MeshOptions
        The options used.
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
        """Number of nodes of both bodies (-)."""
        return self.cam.points.shape[1] + self.roller.points.shape[1]

    @property
    def physical_groups(self) -> dict:
        """``{name: PhysicalGroup}`` of both bodies (node indices are per body)."""
        return {**self.cam.groups, **self.roller.groups}

    def msh_arrays(self):
        """Both bodies as the arrays of a gmsh 2.2 ``.msh`` file (:func:`femcam.io.write_msh`).

        The final (snapped, mirrored) nodes in m, the roller's after the cam's, with the
        physical names ``roller_contact, cam_contact, roller_fixed, cam_fixed, roller, cam``
        (roller tags shifted by 100 so tags are unique).

        Returns
        -------
        points : ndarray of float, shape (n, 3)
            Node coordinates [m] (z = 0).
        cells : list of (str, ndarray of int)
            One ``("line" or "triangle", connectivity)`` block per physical group.
        cell_data : dict of str to list of ndarray
            ``gmsh:physical`` and ``gmsh:geometrical`` tags, one array per block.
        field_data : dict of str to ndarray
            Physical name -> ``[tag, dim]``.
        """
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
        return (np.concatenate(pts), cells, {"gmsh:physical": phys, "gmsh:geometrical": phys},
                names)
