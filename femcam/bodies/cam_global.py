r"""The global (coarse) cam disk on its shaft, built once per cam: bore stress and shaft contact
at every cam angle (global-local scheme).

The cam is not axisymmetric, but it is one linear body: the global model meshes the whole cam
(outline, bore; no fine zone) and the shaft once, factorises them and solves the cam for unit
point forces ``x`` and ``y`` at every outline vertex ("stations") and for a unit drive torque
(a uniform shear on the bore), keeping only the bore's radial displacement and hoop stress. Per
cam angle the contact force ``f = -F n`` at the contact ``C`` is split linearly between the two
stations that bracket ``C`` (by polar angle), the torque ``-(P x f)`` balances its moment, and the
shaft-bore contact is solved (:func:`~femcam.bodies.contact.solve_multi_lcp`; unknowns the bore
pressures, rigid the cam translation, constraints the cam's force balance):

.. math:: g = c + A_{bb}\,\lambda + u_r(f) + t\cdot e_r \ge 0,\ \lambda \ge 0,\ \lambda^T g = 0,
          \quad \int \lambda\, e_r\, ds + f = 0

The bore is ``Rb`` away from a contact zone of half-width ``a`` (``a / web`` ~ 0.02 for seed 002),
so by Saint-Venant the bore sees the contact only through its resultant: the fine contact zone
stays today's local body (p0, a, subsurface stresses). The coupling is checked against the fully
refined model (:mod:`femcam.bodies.cam_model`; tests/test_bodies_cam_disk.py).
"""

from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from .. import _validate
from .._repr import compact_repr
from ..fe.elasticity import assemble_body
from .cam_geometry import CamDisk, bore_error
from .cam_mesh import mesh_cam_disk
from .cam_model import (
    CamMeshOptions,
    bore_vertices_for,
    check_bore_spacing,
    floating_supports,
    hat_resultants,
    shaft_operator,
    torque_vector,
)
from .contact import arc_load_matrix, arc_weights, radial_measure
from .model import _condense, _hoop_rows

#: default mesh of the global model: largest element 0.1 x web (at least 0.07 r_min), growth 0.1
#: from the bore. Measured (bore hoop stress under a 2 kN contact, 6 mm bore): with the refined
#: model's 0.5 x web and growth 0.3 the global model was 1.6 % low on a 20 mm circle with a rigid
#: shaft (10.71 vs 10.89 MPa) and 1.8 % low on an oval cam with a steel shaft (16.85 vs 17.16);
#: growth 0.15: 16.97; growth 0.1: 17.05 MPa against the refined model's 17.07 MPa on its own
#: finer mesh (0.05 x web, growth 0.1): the growth slope, not the largest element, set the error
GLOBAL_MESH = CamMeshOptions(h_max_over_web=0.1, growth=0.1)


#: finest bore the global model accepts (a thinner web is refused: see global_mesh_for)
N_BORE_MAX = 1024


def global_mesh_for(disk: CamDisk) -> CamMeshOptions:
    """:data:`GLOBAL_MESH` with ``n_bore`` raised so that the bore spacing is <= a quarter of the
    web (>= 4 P2 layers through it, as the ring's wall).

    Parameters
    ----------
    disk : CamDisk
        The cam disk (its bore radius and web).

    Returns
    -------
    CamMeshOptions
        The global model's mesh options for this disk.

    Raises
    ------
    InputError
        A web that would need more than :data:`N_BORE_MAX` bore vertices (named by ``Rb``).
    """
    need = bore_vertices_for(disk)
    if need > N_BORE_MAX:
        raise bore_error(disk.Rb, f"the web r_min - Rb = {disk.web * 1e3:.3g} mm is too thin for the "
                             f"disk model ({need} bore vertices needed, at most {N_BORE_MAX}); "
                             "such a hub is a thin ring: model it as one")
    return dataclasses.replace(GLOBAL_MESH, n_bore=max(GLOBAL_MESH.n_bore, need))


@dataclass(frozen=True, eq=False)
class CamGlobalModel:
    """Condensed global cam disk + shaft (module docstring); build with :meth:`build`.

    Attributes
    ----------
    disk : CamDisk
        The cam disk.
    length : float
        Face width [m].
    plane : {"strain", "stress"}
        Plane condition.
    stations : ndarray, shape (2, N_s)
        Outline vertices in the cam frame [m], sorted by polar angle.
    psi : ndarray, shape (N_s,)
        Their polar angles [rad], sorted.
    theta : ndarray, shape (n_b,)
        Bore vertex angles in the cam frame [rad].
    wb : ndarray, shape (n_b,)
        Bore hat weights (arc length) [m].
    bore_force : ndarray, shape (2, n_b)
        x, y resultant of each unit bore pressure hat as the FE applies it [N/m per Pa = m].
    A : ndarray, shape (n_b, n_b)
        Bore radial compliance of cam + shaft [m/Pa].
    Uf : ndarray, shape (n_b, 2 N_s + 1)
        Bore radial displacement per unit station force (x, y interleaved) [m per N/m] and per
        unit torque (last column) [m per N m/m].
    Hf : ndarray, shape (n_b, 2 N_s + 1)
        Bore hoop stress per the same unit loads [Pa per N/m; Pa per N m/m].
    H : ndarray, shape (n_b, n_b)
        Bore hoop stress per bore pressure [Pa/Pa].
    station_nodes, bore_nodes : ndarray of int
        Vertex indices of the stations and of the bore in the cam mesh.
    loads : dict
        ``"bore"`` (sparse, n_dofs x n_b) nodal forces of the bore pressure hats [N/m per Pa]
        and ``"torque"`` (n_dofs,) of the unit drive torque, for the full field of a load case
        (:func:`femcam.bodies.cam_export.global_cam_fields`).
    cache : dict
        Per-model scratch (the cam's stress operator, built on first use).
    bodies : dict of str to femcam.fe.elasticity.Body
        ``"cam"`` and, with an elastic shaft, ``"shaft"``.
    timings : dict of str to float
        ``mesh``, ``assembly``, ``factorisation``, ``condensation`` wall times [s].
    n_dofs : int
        Total degrees of freedom of the bodies.
    """

    disk: CamDisk
    length: float
    plane: str
    stations: np.ndarray
    psi: np.ndarray
    theta: np.ndarray
    wb: np.ndarray
    bore_force: np.ndarray
    A: np.ndarray
    Uf: np.ndarray
    Hf: np.ndarray
    H: np.ndarray
    bodies: dict
    timings: dict
    n_dofs: int
    station_nodes: np.ndarray
    bore_nodes: np.ndarray
    loads: dict
    cache: dict = dataclasses.field(default_factory=dict)

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)

    @classmethod
    def build(cls, *, disk: CamDisk, length: float, cam_mesh: CamMeshOptions | None = None,
              plane: str = "strain", element: str = "P2") -> CamGlobalModel:
        """Mesh, factorise and condense the whole cam disk (cam frame) and its shaft once.

        Parameters
        ----------
        disk : CamDisk
            The cam disk.
        length : float
            Face width [m].
        cam_mesh : CamMeshOptions or None, optional
            Disk and shaft mesh; default :func:`global_mesh_for` ``(disk)``.
        plane : {"strain", "stress"}, optional
            Plane condition.
        element : {"P2", "P1"}, optional
            Finite element.

        Returns
        -------
        CamGlobalModel
            The condensed model.

        Raises
        ------
        InputError
            A bore too coarse for the web (:func:`~femcam.bodies.cam_model.check_bore_spacing`)
            or a web too thin for the model.
        """
        length = _validate.positive("length", length, "m")
        cm = cam_mesh or global_mesh_for(disk)
        check_bore_spacing(disk, cm)
        t0 = time.perf_counter()
        hb = 2 * math.pi * disk.Rb / cm.n_bore
        # far from the bore the size is set by the cam, not the web: a 1 mm web with 0.1 mm
        # elements everywhere took 325 s (load ~4); the bore band keeps the web fine
        h_max = min(max(cm.h_max_over_web * disk.web, 0.07 * disk.r_min), 0.5 * disk.Rb)
        geo, bore, theta = mesh_cam_disk(outline=disk.outline, centre=(0.0, 0.0), bore=disk.Rb,
                                         n_bore=cm.n_bore, h_max=h_max, h_bore=min(hb, h_max),
                                         growth=cm.growth)
        t_mesh = time.perf_counter() - t0
        cam = assemble_body(geo, disk.cam, plane=plane, element=element, supports=floating_supports(bore))
        t1 = time.perf_counter()
        out = np.unique(geo.surface)
        P = geo.points[:, out]
        psi = np.arctan2(P[1], P[0])
        o = np.argsort(psi)
        out, P, psi = out[o], P[:, o], psi[o]
        n_s, n_b = out.size, bore.size
        B = np.zeros((cam.n_dofs, 2 * n_s + 1))
        B[cam.basis.nodal_dofs[0, out], 2 * np.arange(n_s)] = 1.0
        B[cam.basis.nodal_dofs[1, out], 2 * np.arange(n_s) + 1] = 1.0
        torque = torque_vector(cam, bore, (0.0, 0.0))
        B[:, -1] = torque
        Bb = arc_load_matrix(cam, bore, (0.0, 0.0), closed=True)
        dx, dy, ex, ey = radial_measure(cam, bore, (0.0, 0.0))
        U, Hall = _condense(cam, np.hstack([B, Bb]), np.concatenate([dx, dy]), _hoop_rows(cam, bore, theta))
        Ur = ex[:, None] * U[:n_b] + ey[:, None] * U[n_b:]
        k = B.shape[1]
        shaft, _, A_sh = shaft_operator(disk, n_b, (0.0, 0.0), cm.growth, plane, element)
        bodies = {"cam": cam} | ({"shaft": shaft} if shaft is not None else {})
        timings = {"mesh": t_mesh, "assembly": sum(b.t_assembly for b in bodies.values()),
                   "factorisation": sum(b.t_factor for b in bodies.values()),
                   "condensation": time.perf_counter() - t1}
        return cls(disk=disk, length=float(length), plane=plane, stations=P, psi=psi, theta=theta,
                   wb=arc_weights(n_b, hb, True),
                   bore_force=hat_resultants(Bb), A=Ur[:, k:] + A_sh, Uf=Ur[:, :k], Hf=Hall[:, :k],
                   H=Hall[:, k:], bodies=bodies, timings=timings,
                   n_dofs=sum(b.n_dofs for b in bodies.values()), station_nodes=out, bore_nodes=bore,
                   loads={"bore": sp.csr_matrix(Bb), "torque": torque})

    def load_weights(self, C: np.ndarray, f: np.ndarray) -> np.ndarray:
        """Station load coefficients of the contact forces, split between the bracketing stations,
        plus the balancing torque ``-(P x f)`` of the loads as applied (vectorised).

        Parameters
        ----------
        C : ndarray, shape (2, n)
            Contact points in the cam frame [m], one per cam angle.
        f : ndarray, shape (2, n)
            Contact forces on the cam per unit face width [N/m].

        Returns
        -------
        ndarray, shape (n, 2 N_s + 1)
            Station forces (x, y interleaved) [N/m] and the balancing torque (last column)
            [N m/m], the load vector of :attr:`Uf` and :attr:`Hf`.
        """
        n_s = self.psi.size
        ang = np.arctan2(C[1], C[0])
        j1 = np.searchsorted(self.psi, ang) % n_s
        j0 = (j1 - 1) % n_s
        span = (self.psi[j1] - self.psi[j0]) % (2 * math.pi)
        s = ((ang - self.psi[j0]) % (2 * math.pi)) / span
        L = np.zeros((ang.size, 2 * n_s + 1))
        rows = np.arange(ang.size)
        moment = np.zeros(ang.size)
        for j, wgt in ((j0, 1.0 - s), (j1, s)):
            L[rows, 2 * j] += wgt * f[0]
            L[rows, 2 * j + 1] += wgt * f[1]
            Pj = self.stations[:, j]
            moment += wgt * (Pj[0] * f[1] - Pj[1] * f[0])
        L[:, -1] = -moment
        return L
