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
``femcam.io.write_msh(path, mesh)`` writes both bodies with them to a gmsh ``.msh`` file
(``ContactMesh.msh_arrays``).

Defaults of every parameter are recorded in ``meshes/contact_region.toml``; the same geometry
as a gmsh ``.geo`` file with ``DefineConstant`` sliders is ``meshes/contact_region.geo`` (one
body; a flat cam needs its ``flat`` switch; no vertex snapping; see its header).

Modules: :mod:`~femcam.mesh.options` (inputs and result objects), :mod:`~femcam.mesh.session`
(the gmsh session and its lock), :mod:`~femcam.mesh.geometry` (exact arc, body layout, outline,
size field), :mod:`~femcam.mesh.nodes` (node extraction, snapping, mirroring),
:mod:`~femcam.mesh.coating` (the coating band) and :mod:`~femcam.mesh.build` (one body, both
bodies).
"""

from __future__ import annotations

from .build import build_contact_mesh, mesh_body, mesh_plain_body
from .coating import COAT_MAX_ASPECT, mesh_coated_body
from .geometry import BodyLayout, body_layout, surface_height
from .nodes import ccw, gmsh_nodes, mirror
from .options import PHYSICAL_NAMES, BodyMesh, ContactMesh, MeshOptions, PhysicalGroup
from .session import GMSH_LOCK, gmsh_session

# names of the single-module femcam.mesh used by femcam.bodies (kept importable)
_mesh_body = mesh_body
_ccw = ccw

__all__ = [
    "COAT_MAX_ASPECT",
    "GMSH_LOCK",
    "PHYSICAL_NAMES",
    "BodyLayout",
    "BodyMesh",
    "ContactMesh",
    "MeshOptions",
    "PhysicalGroup",
    "body_layout",
    "build_contact_mesh",
    "ccw",
    "gmsh_nodes",
    "gmsh_session",
    "mesh_body",
    "mesh_coated_body",
    "mesh_plain_body",
    "mirror",
    "surface_height",
]
