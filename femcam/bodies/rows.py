"""Sweep-facing: ring, pin and needle results per cam angle from one reusable model.

``ring_rows(support, pair, theta, Fc, rho)`` builds ONE :class:`~femcam.bodies.model.RingModel`
for the scene's roller support (the ring is axisymmetric and the model is graded for the
largest load) and solves every angle on it. It returns a dict of SI arrays; :data:`CSV_COLUMNS`
gives the CSV name (unit in the name) and the factor from SI for each key. Angles where
``Fc <= 0`` (lift-off) give NaN.

For needles every angle is solved at the two extreme cage positions (``cage = 0``: a needle on
the load line; ``cage = pi / Z``: the load line between two needles); the bore stress and the
cam contact are taken at the cage position that gives the larger bore stress.

Columns (key: meaning, SI unit -> CSV name):

==================  ==========================================================  ====================
``theta``           cam angle (rad)                                             ``theta_deg``
``p0``, ``a``       cam-roller pressure and half-width on the ring (the Hertz    ``ring_p0_MPa``,
                    ellipse fitted to the solved pressure)                      ``ring_a_um``
``p0_peak``         cam-roller peak of the solved pressure on the ring (Pa)     ``ring_p0_peak_MPa``
``p0_solid``,       Hertz solid roller (Johnson 1985 eq. 4.45)                   ``solid_p0_MPa``,
``a_solid``                                                                     ``solid_a_um``
``dp0``, ``da``     relative change ring vs solid (-)                           ``ring_dp0_pct``,
                                                                                ``ring_da_pct``
``hoop_max``        largest tensile bore hoop stress (Pa)                       ``bore_hoop_max_MPa``
``hoop_angle``      its angle from the load line at the cam side (rad)           ``bore_hoop_angle_deg``
``pin_p0``          pin contact peak pressure (Pa; pin support)                 ``pin_p0_MPa``
``pin_arc``         pin contact arc (rad; pin support)                          ``pin_arc_deg``
``needle_Q_on``     most loaded needle, needle on the load line (N)              ``needle_Qmax_on_N``
``needle_Q_between``  most loaded needle, load between two needles (N)          ``needle_Qmax_between_N``
==================  ==========================================================  ====================

Distributions (2-D arrays, not CSV columns; :func:`to_csv_columns` skips them):
``needle_loads_on`` / ``needle_loads_between`` (n_angles, Z): needle loads (N) from the needle
at or just past the load line, counter-clockwise, for the two cage positions;
``bore_pressure`` (n_angles, n_bore): bore contact pressure (Pa; pin support, at the model's
bore angles ``model.theta``).
"""

from __future__ import annotations

import math

import numpy as np

from .. import _validate
from .._columns import Column
from ..errors import InputError
from ..materials import Material, effective_modulus
from ..mesh import MeshOptions
from ..scene.bodies import RollerSupport
from ..scene.pair import ContactPair
from .geometry import RollerBearing
from .model import RingMeshOptions, RingModel
from .solve import RingResult, solve_ring

#: key -> its :class:`femcam._columns.Column` (CSV name, factor from SI)
CSV_COLUMNS = {c.si: c for c in (
    Column("theta", "theta_deg", 180.0 / math.pi), Column("p0", "ring_p0_MPa", 1e-6),
    Column("a", "ring_a_um", 1e6), Column("p0_peak", "ring_p0_peak_MPa", 1e-6),
    Column("p0_solid", "solid_p0_MPa", 1e-6), Column("a_solid", "solid_a_um", 1e6),
    Column("dp0", "ring_dp0_pct", 100.0), Column("da", "ring_da_pct", 100.0),
    Column("hoop_max", "bore_hoop_max_MPa", 1e-6),
    Column("hoop_angle", "bore_hoop_angle_deg", 180.0 / math.pi),
    Column("pin_p0", "pin_p0_MPa", 1e-6), Column("pin_arc", "pin_arc_deg", 180.0 / math.pi),
    Column("needle_Q_on", "needle_Qmax_on_N", 1.0), Column("needle_Q_between", "needle_Qmax_between_N", 1.0),
)}


def bearing_from(support: RollerSupport, ring: Material) -> RollerBearing:
    """The :class:`RollerBearing` of a roller on a pin or needles.

    Parameters
    ----------
    support : femcam.scene.bodies.RollerSupport
        The scene's roller support (``Scene.bodies.roller``; m, Pa).
    ring : femcam.materials.Material
        The roller's material (Pa), the ring's.

    Returns
    -------
    RollerBearing
        Ring on ``ring``; pin and needles on ``support.pin`` (default: ``ring``).

    Raises
    ------
    InputError
        No support (the solid roller has no ring model), or a bad geometry.
    """
    if not isinstance(support, RollerSupport):
        raise InputError(f"support = {type(support).__name__}: the solid roller has no ring model "
                         "(roller_support = 'pin' | 'needles'; otherwise use femcam.fe / femcam.hertz)")
    pin = support.pin or ring
    return RollerBearing(Ro=support.Ro, Ri=support.Ri, support=support.support, Rp=support.Rp,
                         c=support.c, Z=support.Z, r_n=support.r_n, ring=ring, pin=pin, needle=pin)


def build_for(support: RollerSupport, pair: ContactPair, Fc, rho, *, mesh: MeshOptions | None = None,
              ring_mesh: RingMeshOptions | None = None) -> RingModel:
    """A ring model graded for the largest contact force and the cam radius there.

    Parameters
    ----------
    support : femcam.scene.bodies.RollerSupport
        The roller on a pin or needles (``Scene.bodies.roller``).
    pair : femcam.scene.pair.ContactPair
        The contact pair (``Scene.pair``: materials, length in m, plane).
    Fc : ndarray, shape (n,)
        Contact forces over the face width [N] (NaN skipped by the maximum).
    rho : ndarray, shape (n,)
        Cam radii of curvature at the same angles [m].
    mesh : MeshOptions or None, optional
        Cam-contact fine zone (as :mod:`femcam.fe`).
    ring_mesh : RingMeshOptions or None, optional
        Ring and pin mesh.

    Returns
    -------
    RingModel
        The model, its fine zone graded for the Hertz half-width of the largest ``Fc``.
    """
    Fc = np.atleast_1d(_validate.data_array("Fc", Fc, "N"))
    rho = np.atleast_1d(_validate.radius_array("rho", rho, "m"))
    if Fc.shape != rho.shape:
        raise InputError(f"Fc, rho: shapes {Fc.shape}, {rho.shape} must match")
    if not np.any(Fc > 0):
        raise _validate.fail("Fc", f"max {np.nanmax(Fc, initial=-np.inf):g}", "N",
                             "needs a positive contact force at one angle at least")
    _validate.instance("pair", pair, ContactPair, "a femcam.scene ContactPair (Scene.pair)")
    b = bearing_from(support, pair.roller)
    k = int(np.nanargmax(np.where(Fc > 0, Fc, np.nan)))
    F, r = float(Fc[k]), float(rho[k])
    inv_R = 1.0 / b.Ro + (0.0 if math.isinf(r) else 1.0 / r)
    a_ref = math.sqrt(4 * F / pair.length / (inv_R * math.pi *
                                              effective_modulus(pair.cam, b.ring, pair.plane)))
    return RingModel.build(bearing=b, cam=pair.cam, rho_ref=r, a_ref=a_ref, length=pair.length,
                           mesh=mesh, ring_mesh=ring_mesh, plane=pair.plane)


def cage_solves(model: RingModel, F: float, rho: float) -> tuple[list[RingResult], RingResult]:
    """The ring solves of one angle and the one its row reports.

    On needles the two extreme cage positions (``cage = 0``: a needle on the load line;
    ``cage = pi / Z``: the load line between two needles), on a pin the one solve; the row
    reports the contact and bore stress of the solve with the larger bore hoop stress.

    Parameters
    ----------
    model : RingModel
        The ring model.
    F : float
        Contact force [N].
    rho : float
        Cam radius of curvature [m].

    Returns
    -------
    solves : list of femcam.bodies.solve.RingResult
        ``[cage 0, cage pi / Z]`` on needles, ``[cage 0]`` on a pin.
    reported : femcam.bodies.solve.RingResult
        The solve the row reports.
    """
    b = model.bearing
    cages = (0.0, math.pi / b.Z) if b.support == "needles" else (0.0,)
    res = [solve_ring(model, F=F, rho=rho, cage=c) for c in cages]
    return res, max(res, key=lambda x: x.hoop_max)


def _one(model, F, r, needles):
    """Row values of one angle (see CSV_COLUMNS)."""
    res, best = cage_solves(model, F, r)
    ang = math.remainder(best.hoop_theta + 0.5 * math.pi, 2 * math.pi)
    dist = {"needle_loads_on": res[0].needle_Q, "needle_loads_between": res[-1].needle_Q,
            "bore_pressure": best.bore_p}
    return dist, {"p0": best.p0, "a": best.a, "p0_peak": float(np.max(best.p)),
            "p0_solid": best.hertz_p0, "a_solid": best.hertz_a,
            "dp0": best.p0 / best.hertz_p0 - 1, "da": best.a / best.hertz_a - 1,
            "hoop_max": best.hoop_max, "hoop_angle": ang, "pin_p0": best.pin_p0, "pin_arc": best.pin_arc,
            "needle_Q_on": res[0].needle_Q_max,
            "needle_Q_between": res[-1].needle_Q_max if needles else math.nan}


def ring_rows(support: RollerSupport, pair: ContactPair, theta, Fc, rho, *, model: RingModel | None = None,
              mesh: MeshOptions | None = None, ring_mesh: RingMeshOptions | None = None) -> dict:
    """Per-angle ring/pin/needle results from one model.

    Parameters
    ----------
    support : femcam.scene.bodies.RollerSupport
        The roller on a pin or needles (``Scene.bodies.roller``).
    pair : femcam.scene.pair.ContactPair
        The contact pair (``Scene.pair``).
    theta : array_like of float, shape (n,)
        Cam angles [rad].
    Fc : array_like of float, shape (n,)
        Contact force over the face width [N]; ``<= 0`` (lift-off) gives a NaN row.
    rho : array_like of float, shape (n,)
        Cam radius of curvature [m] (< 0 concave, inf flat).
    model : RingModel or None, optional
        A built model to reuse; None builds one (:func:`build_for`).
    mesh : MeshOptions or None, optional
        Fine zone of the model built here.
    ring_mesh : RingMeshOptions or None, optional
        Ring and pin mesh of the model built here.

    Returns
    -------
    dict of str to ndarray
        SI arrays of shape (n,) under the keys of :data:`CSV_COLUMNS` (module table), plus
        ``needle_loads_on``/``needle_loads_between`` (n, Z) [N] for needles or
        ``bore_pressure`` (n, n_bore) [Pa] for a pin.

    Raises
    ------
    InputError
        Shapes that differ, non-finite ``theta``, or no support (a solid roller).
    """
    theta = _validate.finite_array("theta", theta, "rad")
    Fc = _validate.data_array("Fc", Fc, "N")  # NaN or <= 0: no contact at that angle
    rho = _validate.radius_array("rho", rho, "m")
    if not (theta.shape == Fc.shape == rho.shape):
        raise InputError(f"theta, Fc, rho: shapes {theta.shape}, {Fc.shape}, {rho.shape} must match")
    model = model or build_for(support, pair, np.where(Fc > 0, Fc, np.nan), rho, mesh=mesh,
                               ring_mesh=ring_mesh)
    b = model.bearing
    needles = b.support == "needles"
    out = {k: np.full(theta.shape, np.nan) for k in CSV_COLUMNS}
    out["theta"] = theta.copy()
    if needles:
        out["needle_loads_on"] = np.full(theta.shape + (b.Z,), np.nan)
        out["needle_loads_between"] = np.full(theta.shape + (b.Z,), np.nan)
    else:
        out["bore_pressure"] = np.full(theta.shape + (model.theta.size,), np.nan)
    for i in np.nonzero(Fc > 0)[0]:
        dist, row = _one(model, float(Fc[i]), float(rho[i]), needles)
        for k, v in row.items():
            out[k][i] = v
        for k in dist:
            if k in out:
                out[k][i] = dist[k]
    return out


def to_csv_columns(rows: dict) -> dict:
    """The CSV columns (unit in the name) of :func:`ring_rows` output.

    Parameters
    ----------
    rows : dict
        :func:`ring_rows` output (SI arrays; keys outside :data:`CSV_COLUMNS` are skipped).

    Returns
    -------
    dict of str to ndarray
        ``{csv name: array}`` in the column's unit (deg, MPa, um, %, N).
    """
    return {CSV_COLUMNS[k].csv: np.asarray(v) * CSV_COLUMNS[k].factor for k, v in rows.items()
            if k in CSV_COLUMNS}
