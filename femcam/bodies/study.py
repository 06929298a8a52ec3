"""Wall-thickness study: how the ring changes the cam contact and the bore stress.

``wall_study`` solves one load case (F, rho) for a list of ring walls on the same roller radius,
each with its own model, and returns SI arrays for the README figure
(:func:`femcam.viz.bodies.plot_wall_study`). Needles: radius ``r_n`` kept, the full complement
that fits (``Z = floor(pi / asin(r_n / (Ri - r_n)))``), raceway ``Rp = Ri - 2 r_n - c``.
"""

from __future__ import annotations

import math
import time

import numpy as np

from ..materials import Material, effective_modulus
from ..mesh import MeshOptions
from .geometry import RollerBearing
from .model import RingMeshOptions, RingModel
from .solve import solve_ring


def bearing_for_wall(Ro, wall, support, *, c, r_n=1e-3, ring: Material, pin: Material) -> RollerBearing:
    """The ring on a pin (``Rp = Ri - c``) or on a full complement of needles of radius r_n.

    Parameters
    ----------
    Ro : float
        Ring outer radius [m].
    wall : float
        Ring wall ``Ro - Ri`` [m].
    support : {"pin", "needles"}
        What carries the ring.
    c : float
        Radial clearance [m].
    r_n : float, optional
        Needle radius [m].
    ring : Material
        Ring material.
    pin : Material
        Pin (and needle) material.

    Returns
    -------
    RollerBearing
        The bearing; needles: ``Z = floor(pi / asin(r_n / (Ri - r_n)))``,
        ``Rp = Ri - 2 r_n - c``.
    """
    Ri = Ro - wall
    if support == "pin":
        return RollerBearing(Ro=Ro, Ri=Ri, support="pin", Rp=Ri - c, c=c, ring=ring, pin=pin)
    Z = int(math.pi / math.asin(r_n / (Ri - r_n)))
    return RollerBearing(Ro=Ro, Ri=Ri, support="needles", Rp=Ri - 2 * r_n - c, c=c, Z=Z, r_n=r_n,
                         ring=ring, pin=pin, needle=pin)


def wall_study(*, Ro, walls, support, F, rho, length, cam: Material, ring: Material, pin: Material,
               c=10e-6, r_n=1e-3, mesh: MeshOptions | None = None,
               ring_mesh: RingMeshOptions | None = None) -> dict:
    """One load case on a ring model per wall thickness (same roller radius).

    Parameters
    ----------
    Ro : float
        Ring outer radius (the roller radius) [m].
    walls : sequence of float
        Ring walls ``Ro - Ri`` [m].
    support : {"pin", "needles"}
        What carries the ring.
    F : float
        Cam contact force over the face width [N].
    rho : float
        Cam radius of curvature [m].
    length : float
        Face width [m].
    cam, ring, pin : Material
        Cam, ring and pin (and needle) materials.
    c : float, optional
        Radial clearance [m].
    r_n : float, optional
        Needle radius [m].
    mesh : MeshOptions or None, optional
        Cam-contact fine zone.
    ring_mesh : RingMeshOptions or None, optional
        Ring and pin mesh.

    Returns
    -------
    dict of str to ndarray
        Float arrays over ``walls``: ``wall`` [m], ``p0`` [Pa], ``a`` [m], their Hertz (solid)
        values ``p0_solid`` [Pa], ``a_solid`` [m], ``hoop_max`` [Pa] (the larger of the two
        extreme cage positions for needles), ``needle_Q_max`` [N], ``n_dofs``, ``t_build`` [s].
    """

    out = {k: [] for k in ("wall", "p0", "a", "p0_solid", "a_solid", "hoop_max", "needle_Q_max",
                           "n_dofs", "t_build")}
    for wall in walls:
        b = bearing_for_wall(Ro, wall, support, c=c, r_n=r_n, ring=ring, pin=pin)
        t0 = time.perf_counter()
        m = RingModel.build(bearing=b, cam=cam, rho_ref=rho, a_ref=_a_ref(F, rho, Ro, length, cam, ring),
                            length=length, mesh=mesh, ring_mesh=ring_mesh)
        t1 = time.perf_counter()
        cages = (0.0, math.pi / b.Z) if support == "needles" else (0.0,)
        res = [solve_ring(m, F=F, rho=rho, cage=cg) for cg in cages]
        r = max(res, key=lambda x: x.hoop_max)
        for k, v in (("wall", wall), ("p0", r.p0), ("a", r.a), ("p0_solid", r.hertz_p0),
                     ("a_solid", r.hertz_a), ("hoop_max", r.hoop_max),
                     ("needle_Q_max", max(x.needle_Q_max for x in res)), ("n_dofs", m.n_dofs),
                     ("t_build", t1 - t0)):
            out[k].append(v)
    return {k: np.asarray(v, dtype=float) for k, v in out.items()}


def _a_ref(F, rho, Ro, length, cam, ring):

    inv_R = 1 / Ro + (0.0 if math.isinf(rho) else 1 / rho)
    return math.sqrt(4 * F / length / (inv_R * math.pi * effective_modulus(cam, ring)))
