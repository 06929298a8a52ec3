r"""The fully refined cam disk on its shaft at one cam angle: cam-roller contact, bore, shaft.

``CamDiskModel.build`` meshes, in the contact frame of the angle (:mod:`femcam.bodies.cam_geometry`),
the whole cam disk with its outline, the fine contact arc (today's fine zone, on the osculating
circle of radius ``rho``) and the bore; the shaft (a disk, clamped on its core ``r <= 0.2 Rs``,
as the roller's pin); the solid roller (today's local roller body of :mod:`femcam.fe`) and, for
the comparison, today's local cam body (depth ``min(|rho|, Rr)``, clamped). Each body is
factorised once and condensed on the contact unknowns ``[p, lambda_bore]``:

* **cam-roller** (as :mod:`femcam.fe`): P1 pressure at the fine-zone vertices, small-slope gap
  ``h0 = d_Rr(x) + d_rho(x)``;
* **shaft-bore** (the ring-pin code of :mod:`femcam.bodies.model`): P1 pressure at ``n_bore``
  bore vertices paired with the shaft's, gap ``c + u.e_r``; unilateral (``fit = "contact"``) or a
  frictionless radial tie of either sign (``fit = "bonded"``);
* **drive torque**: the contact force's moment about the cam centre is carried by a uniform
  tangential shear on the bore (a shaft driving the cam through its fit; a key is not
  modelled), so the floating cam's 3-DOF support carries nothing,

with the cam translation ``(tx, ty)`` and the roller approach ``delta`` as rigid unknowns and the
cam's force balance plus ``int p = W`` as constraints (:func:`~femcam.bodies.contact.solve_multi_lcp`).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

from .. import _validate
from .._repr import compact_repr
from ..fe.contact import load_matrix, trapezoid_weights
from ..fe.elasticity import assemble_body
from ..fe.model import _radius
from ..materials import Material
from ..mesh import MeshOptions, _mesh_body
from .cam_geometry import CamDisk, bore_error, outline_without_arc
from .cam_mesh import mesh_cam_disk
from .contact import arc_load_matrix, arc_weights, radial_measure
from .mesh import gmsh_session, mesh_disk
from .model import _condense, _hoop_rows, check_bore_mesh


@dataclass(frozen=True, kw_only=True)
class CamMeshOptions:
    """Mesh of the cam disk and shaft.

    Parameters
    ----------
    n_bore : int, optional
        Bore vertices, a multiple of 4, >= 16.
    h_max_over_web : float, optional
        Largest element size / web ``r_min - Rb`` [-] (the size is at most ``Rb / 2``), in
        [0.02, 2].
    growth : float, optional
        Element size growth slope [-], in [0.05, 1].
    arc_over_xf : float, optional
        Half-span ``W`` of the osculating-circle arc / the fine zone's half-width [-], in
        [1.5, 40].

    Raises
    ------
    InputError
        A value out of range, naming the field.
    """

    n_bore: int = 64
    h_max_over_web: float = 0.5
    growth: float = 0.3
    arc_over_xf: float = 4.0

    def __post_init__(self):
        check_bore_mesh(self.n_bore, self.growth)
        _validate.in_range("h_max_over_web", self.h_max_over_web, 0.02, 2.0, "")
        _validate.in_range("arc_over_xf", self.arc_over_xf, 1.5, 40.0, "")


def h_max_for(disk: CamDisk, cm: CamMeshOptions) -> float:
    """Largest element size: ``h_max_over_web`` x web, at most ``Rb / 2``.

    Parameters
    ----------
    disk : CamDisk
        The cam disk (web and bore radius).
    cm : CamMeshOptions
        The mesh options.

    Returns
    -------
    float
        Largest element size [m].
    """
    return min(cm.h_max_over_web * disk.web, 0.5 * disk.Rb)


def bore_vertices_for(disk: CamDisk, layers: float = 4.0) -> int:
    """Bore vertices (multiple of 4) for a bore spacing <= web / ``layers``.

    Parameters
    ----------
    disk : CamDisk
        The cam disk (bore radius and web).
    layers : float, optional
        Bore spacings through the web [-].

    Returns
    -------
    int
        Number of bore vertices, a multiple of 4.
    """
    return 4 * math.ceil(2 * math.pi * disk.Rb / (disk.web / layers) / 4)


def check_bore_spacing(disk: CamDisk, cm: CamMeshOptions) -> None:
    """Refuse a bore spacing above half the web (as the ring: the bore contact is then not
    resolved through the web).

    Parameters
    ----------
    disk : CamDisk
        The cam disk (bore radius and web).
    cm : CamMeshOptions
        The mesh options (``n_bore``).

    Raises
    ------
    InputError
        ``2 pi Rb / n_bore`` exceeds half the web; the message gives the ``n_bore`` needed.
    """
    hb = 2 * math.pi * disk.Rb / cm.n_bore
    if hb > 0.5 * disk.web:
        need = 4 * math.ceil(2 * math.pi * disk.Rb / (0.5 * disk.web) / 4)
        raise _validate.fail("n_bore", cm.n_bore, "", f"bore spacing 2 pi Rb / n_bore = {hb * 1e3:.3g} mm "
                             f"exceeds half the web ({disk.web * 1e3:.3g} mm): a web this thin needs "
                             f"n_bore >= {need}")


#: shaft element size / Rs: the core clamp r <= 0.2 Rs then holds ~40 vertices (with 0.25 the
#: clamp held 1-3 vertices and the bore hoop stress moved 2.2 % between two meshes of the same
#: shaft; measured on a 20 mm disk with a 4 mm bore)
SHAFT_H_OVER_RS = 0.05


def shaft_operator(disk: CamDisk, n_b: int, centre, growth: float, plane: str, element: str):
    """The shaft clamped on its core ``r <= 0.2 Rs``, condensed on its bore contact.

    Parameters
    ----------
    disk : CamDisk
        The cam disk (shaft radius and material; ``shaft=None``: rigid).
    n_b : int
        Bore vertices (paired one to one with the shaft surface).
    centre : (float, float)
        Shaft centre in the mesh frame [m].
    growth : float
        Element size growth slope [-].
    plane : {"strain", "stress"}
        Plane condition.
    element : {"P2", "P1"}
        Finite element.

    Returns
    -------
    body : femcam.fe.elasticity.Body or None
        The assembled shaft (None for a rigid shaft).
    B : ndarray, shape (n_dofs, n_b) or None
        Nodal forces of the unit bore pressure hats on the shaft [N/m per Pa].
    A : ndarray, shape (n_b, n_b)
        Radial compliance of the shaft surface [m/Pa] (zeros for a rigid shaft).
    """
    if disk.shaft is None:
        return None, None, np.zeros((n_b, n_b))
    geo, surf, _, _ = mesh_disk(R=disk.Rs, n_surface=n_b, h_surface=2 * math.pi * disk.Rs / n_b,
                                h_max=SHAFT_H_OVER_RS * disk.Rs, growth=growth, cx=centre[0], cy=centre[1])
    r = np.hypot(geo.points[0] - centre[0], geo.points[1] - centre[1])
    sup = tuple((int(k), c) for k in np.nonzero(r <= 0.2 * disk.Rs)[0] for c in (0, 1))
    body = assemble_body(geo, disk.shaft, plane=plane, element=element, supports=sup)
    B = arc_load_matrix(body, surf, centre, closed=True, direction=-1.0, scale=disk.Rb / disk.Rs)
    dx, dy, ex, ey = radial_measure(body, surf, centre, direction=-1.0)
    U, _ = _condense(body, B, np.concatenate([dx, dy]))
    return body, B, ex[:, None] * U[:n_b] + ey[:, None] * U[n_b:]


def torque_vector(body, bore, centre) -> np.ndarray:
    """Nodal forces of a uniform counter-clockwise shear on the bore with unit moment,
    normalised by the moment the FE nodal forces actually have about ``centre`` (the
    chord-integrated hats carry 0.12 % less than ``2 pi Rb^2`` on 64 bore vertices).

    Parameters
    ----------
    body : femcam.fe.elasticity.Body
        The cam body.
    bore : ndarray of int, shape (n_b,)
        Bore vertex nodes, ordered by angle.
    centre : (float, float)
        Cam centre [m].

    Returns
    -------
    ndarray, shape (n_dofs,)
        Nodal forces [N/m per N m/m] (DOFs interleaved x, y).
    """
    f = arc_load_matrix(body, bore, centre, closed=True, tangential=True).sum(axis=1)
    xy = body.basis.doflocs
    moment = float(((xy[0, 0::2] - centre[0]) * f[1::2] - (xy[1, 0::2] - centre[1]) * f[0::2]).sum())
    return f / moment


def hat_resultants(B) -> np.ndarray:
    """x and y sums of the nodal forces of the columns of ``B`` (per unit hat value).

    On a bore of 64 vertices the chord-integrated radial hats give 0.12 % less than
    ``wb e_r``; the force balance uses these sums (measured: the support then carries nothing).

    Parameters
    ----------
    B : ndarray, shape (n_dofs, k)
        Nodal forces of unit pressure hats [N/m per Pa], DOFs interleaved x, y (scikit-fem).

    Returns
    -------
    ndarray, shape (2, k)
        x and y resultants per unit hat value [N/m per Pa = m].
    """
    return np.stack([B[0::2].sum(axis=0), B[1::2].sum(axis=0)])   # DOFs interleaved x, y (skfem)


def floating_supports(bore) -> tuple:
    """Statically determinate support of a floating body: bore theta = 0 (x, y), pi (y).

    Parameters
    ----------
    bore : ndarray of int, shape (n_b,)
        Bore vertex nodes ordered from ``theta = -pi/2`` (``n_b`` a multiple of 4).

    Returns
    -------
    tuple of (int, int)
        ``(node, component)`` pairs (component 0: x, 1: y) of the three clamped DOFs.
    """
    n = bore.size
    return ((int(bore[n // 4]), 0), (int(bore[n // 4]), 1), (int(bore[3 * n // 4]), 1))


@dataclass(frozen=True, eq=False)
class CamDiskModel:
    """Condensed cam disk + shaft + roller at one angle (module docstring); :meth:`build`.

    Attributes
    ----------
    disk : CamDisk
        The cam disk.
    roller : Material
        Roller material.
    Rr : float
        Roller radius [m].
    rho : float
        Cam radius of curvature at the contact [m] (< 0 concave, inf flat).
    length : float
        Face width [m].
    plane : {"strain", "stress"}
        Plane condition.
    x : ndarray, shape (nc,)
        Contact vertex abscissae [m].
    w : ndarray, shape (nc,)
        Their trapezoid weights [m].
    theta : ndarray, shape (n_b,)
        Bore vertex angles in the contact frame [rad].
    wb : ndarray, shape (n_b,)
        Bore hat weights (arc length) [m].
    bore_force : ndarray, shape (2, n_b)
        x, y resultant of each unit bore pressure hat as the FE applies it [N/m per Pa = m]
        (used in the force balance, so that the floating support carries nothing).
    centre : (float, float)
        Cam centre in the contact frame [m].
    A : ndarray, shape (nc + n_b, nc + n_b)
        Compliance of the unknowns ``[p, lambda_bore]`` [m/Pa].
    H : ndarray, shape (n_b, nc + n_b)
        Bore hoop stress per unknown [Pa/Pa].
    A_local : ndarray, shape (nc, nc)
        Compliance of today's local cam + roller bodies at the same vertices [m/Pa] (NaN
        when built with ``local=False``).
    bodies : dict of str to femcam.fe.elasticity.Body
        ``"cam"``, ``"roller"``, and ``"shaft"`` (elastic shaft), ``"local_cam"`` (``local``).
    loads : dict of str to ndarray
        Load matrices of ``"cam"`` (n_dofs, nc + n_b) and ``"shaft"`` (n_dofs, n_b) [N/m per Pa]
        (for the VTU export).
    timings : dict of str to float
        ``mesh``, ``assembly``, ``factorisation``, ``condensation`` wall times [s].
    n_dofs : int
        Degrees of freedom of the bodies (without ``local_cam``).
    """

    disk: CamDisk
    roller: Material
    Rr: float
    rho: float
    length: float
    plane: str
    x: np.ndarray
    w: np.ndarray
    theta: np.ndarray
    wb: np.ndarray
    bore_force: np.ndarray
    centre: tuple
    A: np.ndarray
    H: np.ndarray
    A_local: np.ndarray
    bodies: dict
    loads: dict
    timings: dict
    n_dofs: int

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)

    @property
    def nc(self) -> int:
        """Number of contact vertices."""
        return self.x.size

    @classmethod
    def build(cls, *, disk: CamDisk, C, n, rho: float, Rr: float, roller: Material, a_ref: float,
              length: float, mesh: MeshOptions | None = None, cam_mesh: CamMeshOptions | None = None,
              plane: str = "strain", element: str = "P2", local: bool = True) -> CamDiskModel:
        """Mesh, factorise and condense the cam disk, shaft and roller at one contact.

        Parameters
        ----------
        disk : CamDisk
            The cam disk.
        C, n : array_like, shape (2,)
            Contact point (m) and outward unit cam normal in the cam frame.
        rho : float
            Cam radius of curvature at ``C`` (m; < 0 concave, inf flat).
        Rr : float
            Roller radius (m).
        roller : Material
            Roller material.
        a_ref : float
            Contact half-width the fine zone is graded for (m).
        length : float
            Face width (m).
        mesh, cam_mesh : MeshOptions, CamMeshOptions, optional
            Fine zone (as :mod:`femcam.fe`) and disk/shaft mesh (default ``n_bore`` from the web).
        plane, element : str
            ``"strain"``/``"stress"`` and ``"P2"``/``"P1"``.
        local : bool
            Also build today's local cam body for the comparison.

        Returns
        -------
        CamDiskModel
            The condensed model.

        Raises
        ------
        InputError
            A bore too close to the contact or too coarse for the web.
        """
        a_ref = _validate.positive("a_ref", a_ref, "m")
        length = _validate.positive("length", length, "m")
        Rr = _validate.positive("Rr", Rr, "m")
        rho = _radius("rho", rho)
        C = _validate.finite_array("C", C, "m")
        n = _validate.finite_array("n", n, "")
        if C.shape != (2,) or n.shape != (2,) or abs(float(np.hypot(*n)) - 1.0) > 1e-9:
            raise _validate.fail("n", n.tolist(), "", "C and n must be 2-vectors, n of unit length")
        mesh = mesh or MeshOptions()
        cm = cam_mesh or CamMeshOptions(n_bore=max(64, bore_vertices_for(disk)))
        check_bore_spacing(disk, cm)
        t0 = time.perf_counter()
        with gmsh_session() as gmsh:
            rol_geo = _mesh_body(gmsh, "roller", Rr, Rr, a_ref, mesh)
            loc_geo = (_mesh_body(gmsh, "cam", rho, min(abs(rho) if math.isfinite(rho) else math.inf, Rr),
                                  a_ref, mesh) if local else None)
        x = rol_geo.contact_x
        W = cm.arc_over_xf * float(x[-1])
        if math.isfinite(rho):
            W = min(W, 0.25 * abs(rho))
        pts, centre = outline_without_arc(disk, np.asarray(C, float), np.asarray(n, float), rho, W)
        gap = math.hypot(*centre) - disk.Rb
        if gap < 2 * W:
            raise bore_error(disk.Rb, f"the bore comes within {gap * 1e3:.3g} mm of the contact: the fine "
                                      f"contact zone needs {2 * W * 1e3:.3g} mm (a smaller bore_mm)")
        hb = 2 * math.pi * disk.Rb / cm.n_bore
        h_max = h_max_for(disk, cm)
        cam_geo, bore, theta = mesh_cam_disk(outline=pts, centre=centre, bore=disk.Rb, n_bore=cm.n_bore,
                                             h_max=h_max, h_bore=min(hb, h_max), growth=cm.growth,
                                             contact_x=x, rho=rho, W=W, fine_depth=mesh.fine_depth * a_ref)
        t_mesh = time.perf_counter() - t0
        cam = assemble_body(cam_geo, disk.cam, plane=plane, element=element, supports=floating_supports(bore))
        rol = assemble_body(rol_geo, roller, plane=plane, element=element)
        bodies = {"cam": cam, "roller": rol}
        t1 = time.perf_counter()
        nc, n_b = x.size, bore.size
        w = trapezoid_weights(x)
        By = load_matrix(cam, cam_geo.contact, x, 1)
        m = (x - centre[0]) * w   # moment balancing the contact force (module docstring)
        Bb = arc_load_matrix(cam, bore, centre, closed=True)
        B = np.hstack([-By + torque_vector(cam, bore, centre)[:, None] * m[None, :], Bb])
        dx, dy, ex, ey = radial_measure(cam, bore, centre)
        Um, H = _condense(cam, B, np.concatenate([cam.basis.nodal_dofs[1, cam_geo.contact], dx, dy]),
                          _hoop_rows(cam, bore, theta))
        A = np.vstack([-Um[:nc], ex[:, None] * Um[nc:nc + n_b] + ey[:, None] * Um[nc + n_b:]])
        Byr = load_matrix(rol, rol_geo.contact, x, 1)
        A_rol, _ = _condense(rol, Byr, rol.basis.nodal_dofs[1, rol_geo.contact])
        A[:nc, :nc] += A_rol
        shaft, Bs, A_sh = shaft_operator(disk, n_b, centre, cm.growth, plane, element)
        A[nc:, nc:] += A_sh
        loads = {"cam": B}
        if shaft is not None:
            bodies["shaft"], loads["shaft"] = shaft, Bs
        A_local = np.full((nc, nc), np.nan)
        if loc_geo is not None:
            loc = assemble_body(loc_geo, disk.cam, plane=plane, element=element)
            A_loc, _ = _condense(loc, load_matrix(loc, loc_geo.contact, x, 1),
                                 loc.basis.nodal_dofs[1, loc_geo.contact])
            A_local = A_loc + A_rol
            bodies["local_cam"] = loc
        timings = {"mesh": t_mesh, "assembly": sum(b.t_assembly for b in bodies.values()),
                   "factorisation": sum(b.t_factor for b in bodies.values()),
                   "condensation": time.perf_counter() - t1}
        return cls(disk=disk, roller=roller, Rr=float(Rr), rho=float(rho), length=float(length), plane=plane,
                   x=x, w=w, theta=theta, wb=arc_weights(n_b, hb, True), bore_force=hat_resultants(Bb),
                   centre=centre, A=A, H=H,
                   A_local=A_local, bodies=bodies, loads=loads, timings=timings,
                   n_dofs=sum(b.n_dofs for k, b in bodies.items() if k != "local_cam"))
