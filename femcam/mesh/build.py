"""The contact-region mesh: one body (:func:`mesh_body`, plain or coated) and both bodies
(:func:`build_contact_mesh`).

:func:`mesh_body` is the one place that chooses between the plain body (here) and the coated
body (:mod:`femcam.mesh.coating`): both share the layout, size field and node extraction of
:mod:`femcam.mesh.geometry` and :mod:`femcam.mesh.nodes`, so neither imports the other.
"""

from __future__ import annotations

import math

from .. import _validate
from ..errors import InputError
from ..hertz.conformity import roller_does_not_fit
from .coating import mesh_coated_body
from .estimate import check_contact_elements
from .geometry import BodyLayout, body_layout, body_size, outline, size_field
from .nodes import extract, finish_body, mirror
from .options import BodyMesh, ContactMesh, MeshOptions
from .session import gmsh_session

#: the scene keys a message names for the cam radius of curvature rho
_RHO = "rho (cam radius of curvature, from [program] and [follower] base_radius_mm)"


def mesh_plain_body(gmsh, lay: BodyLayout, opts: MeshOptions) -> BodyMesh:
    """Mesh one uncoated body in the cam orientation (below ``y = 0``).

    Parameters
    ----------
    gmsh : module
        gmsh of an open session with an empty current model.
    lay : BodyLayout
        The body's sizes (m).
    opts : MeshOptions
        Mesh options (size field).

    Returns
    -------
    BodyMesh
        The body, fine zone snapped to the exact arc.
    """
    name = lay.name
    arcs, bottom, surface = outline(gmsh, lay)
    gmsh.model.geo.mesh.setTransfiniteCurve(arcs[1], lay.n_fine + 1)
    gmsh.model.geo.synchronize()
    gmsh.model.addPhysicalGroup(1, arcs, name=f"{name}_contact")
    gmsh.model.addPhysicalGroup(1, [bottom], name=f"{name}_fixed")
    gmsh.model.addPhysicalGroup(2, [surface], name=name)
    size_field(gmsh, arcs[1], lay, opts)
    gmsh.model.mesh.generate(2)
    parts = extract(gmsh, surface, arcs, bottom)
    gmsh.model.remove()
    return finish_body(lay, *parts)


def mesh_body(gmsh, name: str, R: float, L: float, a_ref: float, opts: MeshOptions) -> BodyMesh:
    """Mesh one body in the cam orientation (below ``y = 0``); the caller mirrors the roller.

    Parameters
    ----------
    gmsh : module
        gmsh of an open :func:`~femcam.mesh.gmsh_session`.
    name : {"cam", "roller"}
        The body; coated when ``opts.coat_body == name``.
    R : float
        Signed surface radius (m; < 0 concave, inf flat).
    L : float
        Body size (m).
    a_ref : float
        Reference half-width (m).
    opts : MeshOptions
        Mesh options.

    Returns
    -------
    BodyMesh
        The body mesh (``coating`` set on a coated body).

    Raises
    ------
    InputError
        The body is too small for the fine zone, or the coating does not fit the mesh.
    """
    lay = body_layout(name, R, L, a_ref, opts)
    gmsh.model.add(name)
    if opts.coat_body == name:
        return mesh_coated_body(gmsh, lay, opts)
    return mesh_plain_body(gmsh, lay, opts)


def build_contact_mesh(*, Rr: float, rho: float, a_ref: float,
                       options: MeshOptions | None = None) -> ContactMesh:
    """Mesh the cam and roller bodies around the contact (see :mod:`femcam.mesh`).

    Parameters
    ----------
    Rr : float
        Roller radius (m, > 0).
    rho : float
        Cam surface radius of curvature (m; < 0 concave, ``inf`` flat; nonzero).
    a_ref : float
        Contact half-width the mesh is graded for (m, <= Rr / (2 fine_half_width)).
    options : MeshOptions, optional
        Mesh options (default ``MeshOptions()``).

    Returns
    -------
    ContactMesh
        Both bodies (the roller mirrored to ``y >= 0``) and the parameters.

    Raises
    ------
    InputError
        A bad radius or half-width, a concave cam the roller does not fit
        (``|rho| <= Rr``), or a mesh estimated above
        :data:`~femcam.mesh.estimate.MAX_CONTACT_ELEMENTS` elements (refused before gmsh).
    FemcamError
        gmsh failed to mesh the contact region.
    """
    opts = options or MeshOptions()
    Rr = _validate.positive("Rr", Rr, "m")
    a_ref = _validate.positive("a_ref", a_ref, "m")
    rho = _validate.radius("rho", rho, "m")
    if roller_does_not_fit(rho, Rr):
        raise _validate.fail(_RHO, rho, "m", f"a concave cam needs |rho| > Rr = {Rr:g} m ([follower] "
                             "roller_radius_mm; else the roller does not fit)")
    if opts.fine_half_width * a_ref > 0.5 * Rr:
        # named by the scene keys it comes from: a user of `femcam sweep` wrote those, not a_ref
        raise InputError(f"[materials.*] E_GPa, nu, [follower] roller_radius_mm = {Rr * 1e3:.4g} mm, "
                         "face_width_mm and the contact force ([dynamics] preload_N, spring_N_per_m) give "
                         f"a Hertz contact half-width (a_ref) of {a_ref * 1e3:.4g} mm here: it must be <= "
                         f"roller radius / {2 * opts.fine_half_width:g} = "
                         f"{Rr / (2 * opts.fine_half_width) * 1e3:.4g} mm: the contact zone would not be "
                         "small against the roller (far outside Hertz theory and this mesh layout); give "
                         "stiffer materials, a wider face or a lighter load ([dynamics] preload_N, "
                         "spring_N_per_m)")
    cap = None if opts.domain_over_a is None else opts.domain_over_a * a_ref
    L_roller = body_size(Rr, cap, math.inf)
    L_cam = body_size(rho, cap, Rr)
    check_contact_elements(opts, "a_over_h", max(L_roller, L_cam) / a_ref)  # before gmsh
    with gmsh_session("the contact region") as gmsh:
        cam = mesh_body(gmsh, "cam", rho, L_cam, a_ref, opts)
        roller = mirror(mesh_body(gmsh, "roller", Rr, L_roller, a_ref, opts))
    return ContactMesh(cam=cam, roller=roller, Rr=Rr, rho=rho, a_ref=a_ref,
                       h=a_ref / opts.a_over_h, options=opts)
