r"""FE model of the cam, the roller ring and its pin or needles: build once, solve per angle.

``RingModel.build`` meshes and factorises the cam body (as :mod:`femcam.fe`), the ring (a full,
floating annulus) and the pin (a disk clamped on its core ``r <= 0.2 Rp``, the stud), and
condenses them onto the contact unknowns: the cam-contact pressures ``p`` at the fine-zone
vertices and the bore pressures at ``n_bore`` vertices uniform in angle. The ring is
axisymmetric, so the same condensed model serves every cam angle: only the load, the cam
curvature (in the gap) and, for needles, the cage position change. Per solve:

* **pin**: unknowns ``[p, lambda_bore]``; gap at the bore ``c + u.e_r`` (ring and pin),
* **needles**: unknowns ``[p, Q_j]``; each needle force is a narrow radial pressure on the
  ring bore and the pin (a triangle two bore spacings wide) plus the needle's own approach
  :func:`~femcam.bodies.geometry.needle_approach` (nonlinear: secant iterations),

with the ring translation ``(tx, ty)`` and the cam approach ``delta`` as rigid unknowns and the
ring's force balance plus ``int p = W`` as constraints (:func:`~femcam.bodies.contact.solve_multi_lcp`).
The ring is given a statically determinate 3-DOF support (bore nodes at ``theta = 0`` (x, y)
and ``theta = pi`` (y)); its contact loads are self-equilibrated and radial at the bore, so
the support reactions vanish (the cam forces are along ``y`` at ``x_k``: their moment about the
centre, ``sum x_k p_k w_k``, is zero for a frictionless symmetric pressure; friction is not
modelled on the ring).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from .. import _validate
from .._repr import compact_repr
from .._threads import single_threaded_blas
from ..fe.contact import load_matrix, trapezoid_weights
from ..fe.elasticity import CHUNK, assemble_body, stress_operator
from ..materials import Material
from ..mesh import MeshOptions, _mesh_body
from .contact import arc_load_matrix, arc_weights, radial_measure
from .geometry import RollerBearing
from .mesh import gmsh_session, mesh_disk, mesh_ring


def check_bore_mesh(n_bore, growth) -> None:
    """Check the bore-mesh settings shared by the ring and the cam-disk mesh options.

    Parameters
    ----------
    n_bore : int
        Vertices on the bore circle: a multiple of 4, at least 16.
    growth : float
        Element size growth rate away from the refined zones [-], in [0.05, 1].

    Raises
    ------
    InputError
        A value out of range, naming the field.
    """
    n = _validate.number("n_bore", n_bore, "")
    if int(n) != n or n < 16 or n % 4:
        raise _validate.fail("n_bore", n_bore, "", "must be a multiple of 4, >= 16")
    _validate.in_range("growth", growth, 0.05, 1.0, "")


@dataclass(frozen=True, kw_only=True)
class RingMeshOptions:
    """Mesh of the ring and pin (pin surface size = bore spacing).

    Parameters
    ----------
    n_bore : int, optional
        Bore vertices, a multiple of 4, >= 16.
    h_max_over_wall : float, optional
        Largest element size / ring wall ``Ro - Ri`` [-], in [0.02, 1].
    growth : float, optional
        Element size growth slope [-], in [0.05, 1].

    Raises
    ------
    InputError
        A value out of range, naming the field.
    """

    n_bore: int = 128
    h_max_over_wall: float = 0.25
    growth: float = 0.3

    def __post_init__(self):
        check_bore_mesh(self.n_bore, self.growth)
        _validate.in_range("h_max_over_wall", self.h_max_over_wall, 0.02, 1.0, "")


def _hoop_rows(body, nodes, theta):
    """Sparse rows giving the hoop stress ``sigma_tt`` at ``nodes`` (polar angle ``theta``)."""
    S = stress_operator(body, nodes)
    n = nodes.size
    s, c = np.sin(theta), np.cos(theta)
    return (sp.diags(s * s) @ S[:n] + sp.diags(c * c) @ S[n:2 * n]
            - sp.diags(2 * s * c) @ S[2 * n:])


def _solve_rows(body, B: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """``(K^-1 B)[rows]`` (rows: global DOFs; zero on supports) without the full
    ``(n_dofs, k)`` displacement array: chunked SuperLU solves with one BLAS thread (as
    ``Body.solve``), keeping only the rows the condensation needs: the full-size zero, copy and
    scatter arrays are not made (the same values to round-off)."""
    pos = np.full(body.n_dofs, -1)
    pos[body.free] = np.arange(body.free.size)
    r = pos[rows]
    ok = r >= 0
    Bf = B[body.free]
    out = np.zeros((rows.size, B.shape[1]))
    with single_threaded_blas():
        for j in range(0, B.shape[1], CHUNK):
            x = body.lu.solve(np.asfortranarray(Bf[:, j:j + CHUNK]))
            out[ok, j:j + CHUNK] = x[r[ok]]
    return out


def _condense(body, B, meas_dofs, extra=None):
    """Rows ``meas_dofs`` of ``K^-1 B`` and, for a sparse operator ``extra`` on the DOFs,
    ``extra @ K^-1 B`` (computed on its nonzero columns only)."""
    cols = np.zeros(0, dtype=np.int64) if extra is None else np.unique(extra.tocsr().indices)
    n = meas_dofs.size
    U = _solve_rows(body, B, np.concatenate([meas_dofs, cols]))
    return U[:n], (None if extra is None else np.asarray(extra.tocsc()[:, cols] @ U[n:]))


@dataclass(frozen=True, eq=False)
class RingModel:
    """Condensed cam-ring-pin model (see the module docstring). Build with :meth:`build`.

    Attributes
    ----------
    bearing : RollerBearing
        The ring and its pin or needles.
    cam : Material
        Cam material.
    rho_ref : float
        Cam radius of curvature the cam body is meshed for [m] (< 0 concave, inf flat).
    a_ref : float
        Contact half-width the fine zone is graded for [m].
    length : float
        Face width [m].
    plane : {"strain", "stress"}
        Plane condition.
    x : ndarray, shape (nc,)
        Cam-contact abscissae [m].
    w : ndarray, shape (nc,)
        Their trapezoid weights [m].
    theta : ndarray, shape (n_b,)
        Bore vertex angles about the ring centre [rad].
    wb : ndarray, shape (n_b,)
        Bore hat weights (arc length) [m].
    A : ndarray, shape (nc + n_b, nc + n_b)
        Compliance of the basic unknowns ``[p, lambda_bore]``, ring + cam + pin [m/Pa].
    A_pin : ndarray, shape (n_b, n_b)
        The pin's part of the bore block [m/Pa] (zeros for a rigid pin).
    H : ndarray, shape (n_b, nc + n_b)
        Bore hoop stress per basic unknown [Pa/Pa].
    bodies : dict of str to femcam.fe.elasticity.Body
        ``"cam"``, ``"ring"`` and, with an elastic pin, ``"pin"``.
    loads : dict of str to ndarray
        Load matrices [N/m per Pa]: ``"ring"`` (n_dofs, nc + n_b), ``"cam"`` (n_dofs, nc),
        ``"pin"`` (n_dofs, n_b) (for the VTU export).
    timings : dict of str to float
        ``mesh``, ``assembly``, ``factorisation``, ``condensation`` wall times [s].
    n_dofs : int
        Total degrees of freedom of the bodies.
    """

    bearing: RollerBearing
    cam: Material
    rho_ref: float
    a_ref: float
    length: float
    plane: str
    x: np.ndarray
    w: np.ndarray
    theta: np.ndarray
    wb: np.ndarray
    A: np.ndarray
    A_pin: np.ndarray
    H: np.ndarray
    bodies: dict
    loads: dict
    timings: dict
    n_dofs: int

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)

    @property
    def nc(self) -> int:
        """Number of cam-contact vertices."""
        return self.x.size

    @classmethod
    def build(cls, *, bearing: RollerBearing, cam: Material, rho_ref: float, a_ref: float,
              length: float, mesh: MeshOptions | None = None, ring_mesh: RingMeshOptions | None = None,
              plane: str = "strain", element: str = "P2") -> RingModel:
        """Mesh, assemble, factorise and condense the three bodies.

        Parameters
        ----------
        bearing : RollerBearing
            The ring and its pin or needles.
        cam : Material
            Cam material.
        rho_ref : float
            Cam radius of curvature the cam body is meshed for [m] (< 0 concave, inf flat).
        a_ref : float
            Contact half-width the fine zone is graded for [m], > 0.
        length : float
            Face width [m], > 0.
        mesh : MeshOptions or None, optional
            Cam-contact fine zone (as :mod:`femcam.fe`).
        ring_mesh : RingMeshOptions or None, optional
            Ring and pin mesh.
        plane : {"strain", "stress"}, optional
            Plane condition.
        element : {"P2", "P1"}, optional
            Finite element.

        Returns
        -------
        RingModel
            The condensed model.

        Raises
        ------
        InputError
            A non-positive ``a_ref`` or ``length``, or a bore spacing above half the ring wall.
        """
        a_ref = _validate.positive("a_ref", a_ref, "m")
        length = _validate.positive("length", length, "m")
        mesh = mesh or MeshOptions()
        rm = ring_mesh or RingMeshOptions()
        b = bearing
        t0 = time.perf_counter()
        L_cam = min(abs(rho_ref) if math.isfinite(rho_ref) else math.inf, b.Ro)
        with gmsh_session() as gmsh:
            cam_geo = _mesh_body(gmsh, "cam", rho_ref, L_cam, a_ref, mesh)
        n_b = int(rm.n_bore)
        hb = 2 * math.pi * b.Ri / n_b
        if hb > 0.5 * b.wall:
            # measured: with bore spacings ~ the wall (0.3-1 mm walls, Ro = 10 mm) the bore
            # contact is not resolved through the wall and the active set cycles or spreads the
            # pin contact over 150+ deg; spacings <= 0.5 wall converged (docs/bodies.md)
            need = 4 * math.ceil(2 * math.pi * b.Ri / (0.5 * b.wall) / 4)
            raise _validate.fail("n_bore", n_b, "",
                                 f"bore spacing 2 pi Ri / n_bore = {hb * 1e3:.3g} mm exceeds "
                                 f"half the ring wall ({b.wall * 1e3:.3g} mm): a wall this thin needs "
                                 f"n_bore >= {need}")
        h_max = rm.h_max_over_wall * b.wall
        ring_geo, bore, theta = mesh_ring(Ro=b.Ro, Ri=b.Ri, contact_x=cam_geo.contact_x, n_bore=n_b,
                                          h_bore=min(hb, h_max), h_max=h_max,
                                          fine_depth=mesh.fine_depth * a_ref, growth=rm.growth)
        pin_geo = None
        if b.pin is not None:
            pin_geo, psurf, _, _ = mesh_disk(R=b.Rp, n_surface=n_b, h_surface=2 * math.pi * b.Rp / n_b,
                                              h_max=0.25 * b.Rp, growth=rm.growth, cy=b.Ro)
        t_mesh = time.perf_counter() - t0
        centre = (0.0, b.Ro)
        # determinate support of the floating ring: bore theta = 0 (x, y) and theta = pi (y)
        sup = ((int(bore[n_b // 4]), 0), (int(bore[n_b // 4]), 1), (int(bore[3 * n_b // 4]), 1))
        ring = assemble_body(ring_geo, b.ring, plane=plane, element=element, supports=sup)
        camb = assemble_body(cam_geo, cam, plane=plane, element=element)
        bodies = {"cam": camb, "ring": ring}
        t1 = time.perf_counter()
        x = cam_geo.contact_x
        nc = x.size
        # cam: pressure pushes it in -y; the gap grows with -u_y (as femcam.fe.model)
        By_cam = load_matrix(camb, cam_geo.contact, x, 1)
        A_cam, _ = _condense(camb, By_cam, camb.basis.nodal_dofs[1, cam_geo.contact])
        # ring: cam pressure +y at the fine arc, bore pressure +e_r (pushes the ring outward)
        B_ring = np.hstack([load_matrix(ring, ring_geo.contact, x, 1),
                            arc_load_matrix(ring, bore, centre, closed=True)])
        dx, dy, ex, ey = radial_measure(ring, bore, centre)
        cdofs = ring.basis.nodal_dofs[1, ring_geo.contact]
        Um, H = _condense(ring, B_ring, np.concatenate([cdofs, dx, dy]), _hoop_rows(ring, bore, theta))
        Ux, Uy = Um[nc:nc + n_b], Um[nc + n_b:]
        A = np.vstack([Um[:nc], ex[:, None] * Ux + ey[:, None] * Uy])
        A[:nc, :nc] += A_cam
        A_pin = np.zeros((n_b, n_b))
        loads = {"ring": B_ring, "cam": -By_cam}
        if pin_geo is not None:
            # the pin is held on its core r <= 0.2 Rp (the stud): clamped there
            core = np.nonzero(np.hypot(pin_geo.points[0], pin_geo.points[1] - b.Ro) <= 0.2 * b.Rp)[0]
            sup_p = tuple((int(k), c) for k in core for c in (0, 1))
            pin = assemble_body(pin_geo, b.pin, plane=plane, element=element, supports=sup_p)
            bodies["pin"] = pin
            Bp = arc_load_matrix(pin, psurf, centre, closed=True, direction=-1.0, scale=b.Ri / b.Rp)
            pdx, pdy, pex, pey = radial_measure(pin, psurf, centre, direction=-1.0)
            Up, _ = _condense(pin, Bp, np.concatenate([pdx, pdy]))
            A_pin = pex[:, None] * Up[:n_b] + pey[:, None] * Up[n_b:]
            A[nc:, nc:] += A_pin
            loads["pin"] = Bp
        t_cond = time.perf_counter() - t1
        timings = {"mesh": t_mesh,
                   "assembly": sum(x.t_assembly for x in bodies.values()),
                   "factorisation": sum(x.t_factor for x in bodies.values()),
                   "condensation": t_cond}
        return cls(bearing=b, cam=cam, rho_ref=float(rho_ref), a_ref=a_ref, length=length,
                   plane=plane, x=x, w=trapezoid_weights(x), theta=theta,
                   wb=arc_weights(n_b, 2 * math.pi * b.Ri / n_b, True), A=A, A_pin=A_pin, H=H,
                   bodies=bodies, loads=loads, timings=timings,
                   n_dofs=sum(x.n_dofs for x in bodies.values()))

    def needle_spread(self, phi: np.ndarray) -> np.ndarray:
        """Bore pressure per unit needle force: a triangle of half-width two bore spacings
        centred on each needle angle, normalised so that ``wb @ S = 1``.

        Parameters
        ----------
        phi : ndarray, shape (Z,)
            Needle angles about the ring centre [rad].

        Returns
        -------
        ndarray, shape (n_bore, Z)
            Bore pressure per needle load [Pa per N/m = 1/m].
        """
        dth = 2 * math.pi / self.theta.size
        d = np.angle(np.exp(1j * (self.theta[:, None] - phi[None, :])))
        S = np.maximum(0.0, 1.0 - np.abs(d) / (2 * dth))
        return S / (self.wb @ S)
