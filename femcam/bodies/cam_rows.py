"""Sweep-facing: the cam disk on its shaft per cam angle, from one global model per scene.

``cam_disk_rows(case, state, Fc)`` builds ONE :class:`~femcam.bodies.cam_global.CamGlobalModel`
for the scene's cam (``[cam] bore_mm``; the record :class:`~femcam.scene.case.CamDiskCase`)
and solves the shaft-bore contact at the angles of ``state`` (a ``Scene.analyse``)
(global-local scheme: the cam-roller contact itself stays today's local body). It returns a
dict of SI arrays; :data:`CAM_CSV_COLUMNS` gives the CSV name (unit in the name) and the factor
from SI. Angles where ``Fc <= 0`` (lift-off) give NaN.

==================  ===========================================================  =======================
key                 meaning (SI)                                                 CSV name
==================  ===========================================================  =======================
``hoop_max``        largest tensile hoop stress at the cam bore (Pa)             ``cam_bore_hoop_max_MPa``
``hoop_angle``      its angle from the contact direction, counter-clockwise      ``cam_bore_hoop_angle_deg``
                    in the cam frame (rad)
``shaft_p0``        largest shaft-bore contact pressure (Pa)                     ``shaft_p0_MPa``
``shaft_arc``       angular extent of the loaded bore (rad; NaN bonded)          ``shaft_arc_deg``
``web``             thinnest web ``r_min - Rb`` (m, the same on every row)       ``cam_web_mm``
==================  ===========================================================  =======================

``flags`` (text, not in :data:`CAM_CSV_COLUMNS`): a row whose bore hoop stress exceeds the cam's
``yield_strength_MPa`` (``[materials.cam]``) says so with both numbers and the web.
"""

from __future__ import annotations

import math

import numpy as np

from .. import _validate
from .._columns import Column
from ..errors import InputError
from ..materials import effective_modulus
from ..scene.bodies import RealBodies
from ..scene.case import CamDiskCase
from ..scene.pair import ContactPair
from ..scene.state import SceneState
from .cam_geometry import CamDisk, outline_from_state, require_roller
from .cam_global import CamGlobalModel
from .cam_model import CamMeshOptions
from .cam_solve import shaft_arc
from .contact import solve_multi_lcp

#: key -> its :class:`femcam._columns.Column` (CSV name, factor from SI)
CAM_CSV_COLUMNS = {c.si: c for c in (
    Column("hoop_max", "cam_bore_hoop_max_MPa", 1e-6),
    Column("hoop_angle", "cam_bore_hoop_angle_deg", 180.0 / math.pi),
    Column("shaft_p0", "shaft_p0_MPa", 1e-6), Column("shaft_arc", "shaft_arc_deg", 180.0 / math.pi),
    Column("web", "cam_web_mm", 1e3),
)}


def has_cam_bore(bodies: RealBodies) -> bool:
    """True when the scene gives ``[cam] bore_mm`` (the cam disk on its shaft).

    Parameters
    ----------
    bodies : femcam.scene.bodies.RealBodies
        The scene's real bodies (``Scene.bodies``).

    Returns
    -------
    bool
        Whether the bodies hold a cam on its shaft.
    """
    return bodies.cam is not None


def disk_from_case(case: CamDiskCase, *, fit: str | None = None, Rb: float | None = None) -> CamDisk:
    """The scene's :class:`CamDisk`: outline from the case's revolution, ``[cam] bore_mm`` (or
    ``Rb``, m), shaft material ``[materials.shaft]`` (default: the cam's), the fit
    ``[cam] shaft_fit`` (or ``fit``; default ``"contact"``) and the shaft radius
    ``Rs = Rb - [cam] shaft_clearance_um`` (default 0: a line-to-line fit).

    Parameters
    ----------
    case : femcam.scene.case.CamDiskCase
        The scene's cam on its shaft (:func:`femcam.scene.case.cam_disk_case`; a roller
        follower).
    fit : {"contact", "bonded"} or None, optional
        Shaft-bore fit; None: the scene's ``[cam] shaft_fit`` (default ``"contact"``).
    Rb : float or None, optional
        Bore radius [m]; None: the scene's ``[cam] bore_mm``.

    Returns
    -------
    CamDisk
        The cam disk (cam yield strength from ``[materials.cam] yield_strength_MPa``, if given).

    Raises
    ------
    InputError
        No ``Rb`` and no ``[cam] bore_mm``, a follower that is not a translating roller, or a
        disk that does not fit.
    """
    _validate.instance("case", case, CamDiskCase, "a femcam.scene.case.CamDiskCase")
    g = case.shaft
    if Rb is None and g is None:
        raise InputError("scene has no [cam] bore_mm: the cam is today's local body (no disk model)")
    Rb = g.bore if Rb is None else Rb
    fit = (g.fit if g is not None else "contact") if fit is None else fit
    clearance = g.clearance if g is not None else 0.0
    shaft = g.shaft if g is not None and g.shaft is not None else case.pair.cam
    require_roller(case.follower)
    return CamDisk(outline=outline_from_state(case.revolution), Rb=Rb, Rs=Rb - clearance,
                   fit=fit, cam=case.pair.cam, shaft=shaft, cam_yield=case.cam_yield)


def solve_global(model: CamGlobalModel, C: np.ndarray, n: np.ndarray, F: np.ndarray) -> dict:
    """Bore hoop stress and shaft contact of the global model at k contacts (vectorised loads).

    Parameters
    ----------
    model : CamGlobalModel
        The condensed global model.
    C : ndarray, shape (2, k)
        Contact points in the cam frame (m).
    n : ndarray, shape (2, k)
        Outward unit cam normals there [-].
    F : ndarray, shape (k,)
        Contact forces (N, > 0) over the face width ``model.length``.

    Returns
    -------
    dict
        ``hoop_max`` (Pa), ``hoop_angle`` (rad, from the contact direction), ``shaft_p0`` (Pa),
        ``shaft_arc`` (rad; NaN for a bonded fit), each (k,); ``hoop`` and ``bore_p`` (k, n_b; Pa)
        at the bore angles ``model.theta``.

    Raises
    ------
    ConvergenceError
        The shaft-bore active set cycles at some angle.
    """
    d = model.disk
    W = np.asarray(F, float) / model.length
    f = -W * np.asarray(n, float)
    L = model.load_weights(np.asarray(C, float), f)
    g_f = L @ model.Uf.T                    # (k, n_b) bore radial displacement of the loads
    h_f = L @ model.Hf.T
    th = model.theta
    G = np.stack([np.cos(th), np.sin(th)], axis=1)
    Cm = model.bore_force
    bil = np.full(th.size, d.fit == "bonded")
    k = W.size
    lam = np.zeros((k, th.size))
    for i in range(k):
        toward = np.cos(th - math.atan2(-f[1, i], -f[0, i])) > 0.7
        sol = solve_multi_lcp(model.A, d.c + g_f[i], G, Cm, -f[:, i], active0=toward,
                              bilateral=bil)
        lam[i] = sol.lam
    hoop = h_f + lam @ model.H.T
    ang0 = np.arctan2(C[1], C[0])
    rel = np.angle(np.exp(1j * (th[None, :] - ang0[:, None])))
    j = np.argmax(hoop, axis=1)
    r = np.arange(k)
    arcs = (np.array([shaft_arc(rel[i], lam[i]) for i in r]) if d.fit == "contact" else np.full(k, np.nan))
    return {"hoop_max": hoop[r, j], "hoop_angle": rel[r, j], "shaft_p0": lam.max(axis=1), "shaft_arc": arcs,
            "hoop": hoop, "bore_p": lam}


def cam_disk_rows(case: CamDiskCase, state: SceneState, Fc, *, model: CamGlobalModel | None = None,
                  cam_mesh: CamMeshOptions | None = None) -> dict:
    """Per-angle cam-disk results from the global model (one per scene).

    Parameters
    ----------
    case : femcam.scene.case.CamDiskCase
        The scene's cam on its shaft (a roller follower with ``[cam] bore_mm``).
    state : femcam.scene.SceneState
        The analytic chain at the cam angles ``theta`` of the rows (``Scene.analyse(theta)``,
        rad).
    Fc : array_like of float
        Contact force at ``state.theta`` (N); ``<= 0`` or NaN gives a NaN row (lift-off).
    model : CamGlobalModel, optional
        A built model to reuse (it holds SuperLU factors and does not pickle).
    cam_mesh : CamMeshOptions, optional
        Mesh of the model built here (default: :func:`~femcam.bodies.cam_global.global_mesh_for`).

    Returns
    -------
    dict
        SI arrays shaped like ``state.theta`` under the keys of :data:`CAM_CSV_COLUMNS`
        (``hoop_max`` Pa, ``hoop_angle`` rad, ``shaft_p0`` Pa, ``shaft_arc`` rad, ``web`` m) and
        ``flags`` (text).

    Raises
    ------
    InputError
        Shapes that differ, no ``[cam] bore_mm``, or a web thinner than
        :data:`WEB_OVER_A_MIN` contact half-widths.
    """
    _validate.instance("case", case, CamDiskCase, "a femcam.scene.case.CamDiskCase")
    _validate.instance("state", state, SceneState, "a femcam.scene.SceneState")
    theta = state.theta
    Fc = _validate.data_array("Fc", Fc, "N")  # NaN or <= 0: no contact at that angle
    if theta.shape != Fc.shape:
        raise InputError(f"state.theta, Fc: shapes {theta.shape}, {Fc.shape} must match")
    on = np.flatnonzero(np.isfinite(Fc) & (Fc > 0))
    disk = model.disk if model is not None else disk_from_case(case)
    if on.size:
        check_web_against_contact(disk, case.pair, case.follower.Rr, Fc[on], state.rho[on])
    model = model or CamGlobalModel.build(disk=disk, length=case.pair.length, cam_mesh=cam_mesh,
                                          plane=case.pair.plane)
    out = {k: np.full(theta.shape, np.nan) for k in CAM_CSV_COLUMNS}
    out["web"][:] = model.disk.web
    out["flags"] = np.full(theta.shape, "", dtype=object)
    if on.size:
        p = state.profile
        C = np.stack([p.x[on], p.y[on]])
        nn = np.stack([p.pitch_x[on], p.pitch_y[on]]) - C
        nn = nn / np.hypot(*nn)
        r = solve_global(model, C, nn, Fc[on])
        for k in ("hoop_max", "hoop_angle", "shaft_p0", "shaft_arc"):
            out[k][on] = r[k]
        out["flags"][on] = yield_flags(model.disk, r["hoop_max"], r["hoop_angle"])
    return out


def yield_flags(disk: CamDisk, hoop_max, hoop_angle) -> np.ndarray:
    """Text per row: the bore hoop stress above the cam's yield strength, with the numbers.

    Parameters
    ----------
    disk : CamDisk
        The cam disk (its ``cam_yield`` [Pa] and web).
    hoop_max : ndarray, shape (k,)
        Largest bore hoop stress per row [Pa].
    hoop_angle : ndarray, shape (k,)
        Its angle from the contact direction [rad].

    Returns
    -------
    ndarray of object (str), shape (k,)
        The flag text, "" where the stress is within the yield strength (or none is given).
    """
    y = disk.cam_yield
    out = np.full(np.shape(hoop_max), "", dtype=object)
    if y is None:
        return out
    for i in np.flatnonzero(np.asarray(hoop_max) > y):
        out[i] = (f"cam bore hoop stress {hoop_max[i] / 1e6:.4g} MPa at "
                  f"{math.degrees(hoop_angle[i]):.1f} deg from the contact exceeds the cam's yield "
                  f"strength {y / 1e6:.4g} MPa (web "
                  f"{disk.web * 1e3:.3g} mm)")
    return out


#: the web must be at least this many contact half-widths (the bore outside the contact's
#: subsurface field, which the global model does not resolve: Saint-Venant needs distance)
WEB_OVER_A_MIN = 10.0


def check_web_against_contact(disk: CamDisk, pair: ContactPair, Rr: float, Fc, rho) -> None:
    """Refuse a web thinner than :data:`WEB_OVER_A_MIN` Hertz half-widths (Johnson 1985 eq. 4.45;
    ``a`` of the largest contact over the angles) with the numbers.

    Parameters
    ----------
    disk : CamDisk
        The cam disk (its web).
    pair : femcam.scene.pair.ContactPair
        The contact pair (``Scene.pair``: materials, face width, plane).
    Rr : float
        Roller radius [m].
    Fc : ndarray, shape (k,)
        Contact forces [N], > 0.
    rho : ndarray, shape (k,)
        Cam radii of curvature at those angles [m] (< 0 concave, inf flat).

    Raises
    ------
    InputError
        ``r_min - Rb < WEB_OVER_A_MIN * a_max`` (named by ``cam.bore_mm``).
    """
    inv_R = 1.0 / Rr + np.where(np.isinf(rho), 0.0, 1.0 / np.where(np.isinf(rho), 1.0, rho))
    Es = effective_modulus(pair.cam, pair.roller, pair.plane)
    a = np.sqrt(4 * np.asarray(Fc) / pair.length / (math.pi * Es * np.maximum(inv_R, 1e-300)))
    a_max = float(np.nanmax(np.where(inv_R > 0, a, np.nan), initial=0.0))
    if disk.web < WEB_OVER_A_MIN * a_max:
        raise InputError(f"cam.bore_mm = {disk.Rb * 1e3:g} mm: the web r_min - Rb = {disk.web * 1e3:.3g} mm "
                         f"is less than {WEB_OVER_A_MIN:g} contact half-widths (a = {a_max * 1e6:.3g} um): "
                         "the bore would sit in the contact's subsurface stress field")


def to_csv_columns(rows: dict) -> dict:
    """The CSV columns (unit in the name) of :func:`cam_disk_rows` output.

    Parameters
    ----------
    rows : dict
        :func:`cam_disk_rows` output (SI arrays; keys outside :data:`CAM_CSV_COLUMNS` are skipped).

    Returns
    -------
    dict of str to ndarray
        ``{csv name: array}`` in the column's unit (MPa, deg, mm).
    """
    return {CAM_CSV_COLUMNS[k].csv: np.asarray(v) * CAM_CSV_COLUMNS[k].factor for k, v in rows.items()
            if k in CAM_CSV_COLUMNS}
