r"""The extra column providers' columns, per-chunk compute functions and per-process models
(the mechanism and the table are :mod:`femcam.sweep.extras`; what each provider does and why is
documented there and in docs/sweep.md, "Extra columns").

Columns are :class:`femcam._columns.Column` (SI name in the sweep table, CSV name with unit,
factor SI -> CSV); each
compute function takes the chunk's task and rows and returns the provider's arrays (shape (n,)).
"""

from __future__ import annotations

import math
import threading
from collections.abc import Callable
from pathlib import Path

import numpy as np

from .._columns import Column
from ..assess import COLUMNS as ASSESS_COLUMNS
from ..assess import assess_rows
from ..bodies.cam_geometry import contact_frame
from ..bodies.cam_global import CamGlobalModel
from ..bodies.cam_rows import CAM_CSV_COLUMNS, cam_disk_rows, disk_from_case
from ..bodies.cam_study import check_local_body
from ..bodies.rows import CSV_COLUMNS as RING_COLUMNS
from ..bodies.rows import build_for
from ..errors import FemcamError
from ..halfspace.rows import COLUMNS as HS_COLUMNS
from ..halfspace.rows import anchor_angles, finite_length_rows
from ..io import vtu_name, write_global_cam_vtu
from ..layers import SWEEP_COLUMNS, result_layer_row, scene_layer_rows, scene_layers
from ..layers.from_scene import scene_coatings
from ..scene.case import cam_disk_case, contact_case
from ..scene.finite_case import finite_case
from ..wear.coating import coating_wear
from ..wear.map import wear_depth_per_angle
from .cache import default_cache
from .options import contact_params
from .plan import hertz_half_width

#: angles of the revolution on which per-process models are graded (independent of chunking)
_GRID = np.linspace(0.0, 2.0 * math.pi, 720, endpoint=False)


# ---------------------------------------------------------------------------------------------
# per-process models
# ---------------------------------------------------------------------------------------------
_CACHE: dict = {}
_LOCK = threading.RLock()


def _cached(kind: str, scene, build: Callable):
    """``build()`` once per process for ``(kind, repr(scene))``."""
    key = (kind, repr(scene))
    with _LOCK:
        if key not in _CACHE:
            _CACHE[key] = build()
        return _CACHE[key]


def ring_model(scene):
    """The scene's ring model (:func:`femcam.bodies.rows.build_for`), graded for the largest
    contact force over one revolution (720 angles), built once per process: the rows then do
    not depend on how the sweep is chunked.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene swept.

    Returns
    -------
    femcam.bodies.RingModel
        The ring (pin or needle bearing) model.
    """
    def build():
        st = scene.analyse(_GRID)
        Fc = np.where(np.asarray(st.Fc) > 0, st.Fc, np.nan)
        return build_for(scene.bodies.roller, scene.pair, Fc, np.asarray(st.rho, float))
    return _cached("ring", scene, build)


def cam_disk_model(scene):
    """The scene's global cam disk on its shaft (:class:`~femcam.bodies.cam_global.CamGlobalModel`),
    built once per process (it does not depend on the angles).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene swept.

    Returns
    -------
    femcam.bodies.cam_global.CamGlobalModel
        The cam disk model.
    """
    return _cached("cam_disk", scene, lambda: CamGlobalModel.build(
        disk=disk_from_case(cam_disk_record(scene)), length=scene.length, plane=scene.plane))


def cam_disk_record(scene):
    """The scene's :class:`~femcam.scene.case.CamDiskCase` (its outline analysed over one
    revolution), built once per process.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene swept.

    Returns
    -------
    femcam.scene.case.CamDiskCase
        The cam on its shaft.
    """
    return _cached("cam_disk_case", scene, lambda: cam_disk_case(scene))


def strip_model(scene):
    """The scene's finite-length contact (:func:`femcam.scene.finite_case`) and its
    :class:`~femcam.halfspace.strip.FiniteLengthContact` (kernel FFTs), once per process.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene swept.

    Returns
    -------
    finite : femcam.scene.FiniteCase
        The roller's finite-length records (m, rad).
    strip : femcam.halfspace.strip.FiniteLengthContact
        The finite-length contact of the scene's roller.
    """
    def build():
        fc = finite_case(scene)
        return fc, fc.strip()
    return _cached("strip", scene, build)


# ---------------------------------------------------------------------------------------------
# providers
# ---------------------------------------------------------------------------------------------
def assess_name(name: str) -> str:
    """The sweep table's name of an assessment column.

    Parameters
    ----------
    name : str
        SI name in :data:`femcam.assess.COLUMNS`.

    Returns
    -------
    str
        ``"assess_<name>"``.
    """
    return f"assess_{name}"


ASSESS_SKIP = ("theta", "Fc")
ASSESS = tuple(Column(assess_name(c.si), c.csv if c.csv not in ("a_um", "p0_MPa") else f"assess_{c.csv}",
                      c.factor, c.description) for c in ASSESS_COLUMNS if c.si not in ASSESS_SKIP)
ASSESS_TEXT = ("assess_regime", "assess_flags", "assess_source")
#: the 2D FE at the most loaded slice (method fe): F = w_max * length
FE_SLICE = (Column("F_peak_slice", "F_peak_slice_N", 1.0), Column("a_peak_slice", "a_peak_slice_um", 1e6),
            Column("p0_peak_slice", "p0_peak_slice_MPa", 1e-6),
            Column("vm_max_peak_slice", "vm_max_peak_slice_MPa", 1e-6),
            Column("tau1_max_peak_slice", "tau1_max_peak_slice_MPa", 1e-6),
            Column("surf_txz_absmax_peak_slice", "surf_txz_absmax_peak_slice_MPa", 1e-6),
            Column("txz_range_max_peak_slice", "txz_range_max_peak_slice_MPa", 1e-6))
HALFSPACE = tuple(Column(f"hs_{c.si}", c.csv, c.factor, c.description)
                  for c in HS_COLUMNS.values()) + FE_SLICE
#: the ring model's cam contact answers the headline (``p0_fe``, ``p0_fit``, ``a_fe``, ``err_*``;
#: :mod:`femcam.sweep.ringhead`): those keys of :data:`femcam.bodies.rows.CSV_COLUMNS` are no
#: side columns; the bore, pin and needle columns are
RING_HEADLINE_KEYS = ("theta", "p0", "a", "p0_peak", "p0_solid", "a_solid", "dp0", "da")
#: two-level estimates of the ring's own stresses (:func:`femcam.sweep.ringhead.ring_level_estimate`;
#: relative, the CSV in percent of the row's value)
RING_ESTIMATES = (Column("err_est_bore_hoop", "err_est_bore_hoop_pct", 100.0,
                         "estimated discretisation error of bore_hoop_max_MPa"),
                  Column("err_est_pin_p0", "err_est_pin_p0_pct", 100.0,
                         "estimated discretisation error of pin_p0_MPa"),
                  Column("err_est_needle_Q", "err_est_needle_Q_pct", 100.0,
                         "estimated discretisation error of needle_Qmax_on_N"))
RING = tuple(Column(f"ring_{c.si}", c.csv, c.factor, c.description) for c in RING_COLUMNS.values()
             if c.si not in RING_HEADLINE_KEYS) + RING_ESTIMATES
CAM_DISK = tuple(Column(f"camdisk_{c.si}", c.csv, c.factor, c.description) for c in CAM_CSV_COLUMNS.values())
#: the layer checks' columns, declared by femcam.layers (SI names, Pa and m; CSV names with units)
LAYERS = SWEEP_COLUMNS
#: two-level error estimates of the interface stresses of a coated FE row (relative; the CSV in
#: percent of the row's own value; :data:`femcam.sweep.estimate.LAYER_QUANTITIES`)
LAYER_ESTIMATES = (Column("err_est_interface_tau", "err_est_interface_tau_pct", 100.0,
                          "estimated discretisation error of interface_tau_max_MPa"),
                   Column("err_est_interface_sn", "err_est_interface_sn_pct", 100.0,
                          "estimated discretisation error of interface_sn_min_MPa"))


def axial_contact(p_axial_peak, w_max) -> tuple[np.ndarray, np.ndarray]:
    """``(a, p0)`` (m, Pa) of the most loaded slice of a finite-length contact: ``p0 =
    p_axial_peak`` and ``a = 2 w_max / (pi p_axial_peak)``, so ``pi a p0 / 2 = w_max``.

    Parameters
    ----------
    p_axial_peak : array_like, shape (n,)
        Axial peak pressure (the chunk's ``hs_p_axial_peak``) [Pa].
    w_max : array_like, shape (n,)
        Load per length of the most loaded slice (``hs_w_max``) [N/m].

    Returns
    -------
    a : ndarray, shape (n,)
        Half-width [m] (NaN where the peak is not finite and positive).
    p0 : ndarray, shape (n,)
        Peak pressure [Pa] (NaN there too).

    >>> a, p0 = axial_contact(np.array([1e9]), np.array([1e5]))
    >>> round(float(a[0]) * 1e6, 3), float(p0[0])
    (63.662, 1000000000.0)
    """
    p = np.asarray(p_axial_peak, float)
    w = np.asarray(w_max, float)
    ok = np.isfinite(p) & np.isfinite(w) & (p > 0)
    a = np.where(ok, 2.0 * w / (np.pi * np.where(ok, p, 1.0)), np.nan)
    return a, np.where(ok, p, np.nan)


def _fe_slice(task, rows, out) -> None:
    """The 2D FE at the most loaded slice: ``F = w_max * length`` at every ``ok`` row (method
    fe), with the family's model where it covers that load, else a model of the angle's own (as
    the chunk runner does), through the process's :class:`~femcam.sweep.cache.ModelCache`."""
    n = rows.theta.size
    for c in FE_SLICE:
        out[c.si] = np.full(n, np.nan)
    out["fe_load_basis"] = np.full(n, "", dtype=object)
    if task.options.method != "fe":
        return
    cp, cache = contact_params(task.scene), default_cache()
    status = np.asarray(rows.status).astype(str)
    for i in np.flatnonzero((status == "ok") & np.isfinite(out["hs_w_max"])):
        F, rho = float(out["hs_w_max"][i]) * cp.length, float(rows.rho[i])
        try:
            r = _solve_slice(task, cp, cache, i, F, rho)
        except (FemcamError, ValueError, ArithmeticError, RuntimeError, MemoryError) as exc:
            out["fe_load_basis"][i] = f"w_max*length: failed: {type(exc).__name__}: {exc}"
            continue
        if not r.converged:
            out["fe_load_basis"][i] = f"w_max*length: not converged ({r.iterations} iterations)"
            continue
        for si, v in (("F_peak_slice", F), ("a_peak_slice", r.a), ("p0_peak_slice", r.p0_nodal),
                      ("vm_max_peak_slice", r.von_mises_max.value), ("tau1_max_peak_slice", r.tau1_max.value),
                      ("surf_txz_absmax_peak_slice", float(np.abs(r.txz).max()) if r.txz.size else np.nan),
                      ("txz_range_max_peak_slice", r.txz_range.value if r.txz_range.inside else np.nan)):
            out[si][i] = v
        out["fe_load_basis"][i] = "w_max*length"


def _solve_slice(task, cp, cache, i: int, F: float, rho: float):
    """Row ``i`` at load ``F`` (N): its family's model if it covers ``(F, rho)``, else one of
    its own (sized by the Hertz half-width at ``F``), as the chunk runner does."""
    fid = int(task.family[i]) if task.family.size else -1
    opts = task.family_options(fid)
    model = cache.model_for(cp, *task.refs[fid], opts) if fid in task.refs else None
    if model is None or not model.covers(F, rho):
        a_i = float(hertz_half_width(np.array([F]), np.array([rho]), cp)[0])
        model = cache.model_for(cp, rho, a_i, opts)
    return cache.solve(model, F, rho, cp.mu, cp.sliding, check=False)


def halfspace_rows(scene, theta) -> dict:
    """The half-space columns at ``theta`` (rad, one sweep chunk), each angle warm-started from
    the cold solution at its nearest anchor angle (``start="anchor"`` of
    :func:`femcam.halfspace.rows.finite_length_rows`; kernel FFTs and anchors cached per process):
    a row depends on its own angle alone, so the columns are bit-identical whatever the chunk
    size or a resume (a warm start from the chunk's previous angle moved the rows by up to 4e-5
    relative with the chunk boundaries).

    Parameters
    ----------
    scene : femcam.scene.Scene
        A scene with a roller follower.
    theta : array_like, shape (n,)
        The chunk's cam angles [rad], in sweep order.

    Returns
    -------
    dict[str, ndarray]
        ``hs_<key>`` for each key of :data:`femcam.halfspace.rows.COLUMNS`, shape (n,), float, SI
        (Pa, m, N/m; counts and 0/1 flags as float), and ``hs_flags`` (object, the strip flags
        of each angle joined by ``;``).
    """
    fc, strip = strip_model(scene)
    th = np.asarray(theta, float)
    st, anchors = scene.analyse(th), scene.analyse(anchor_angles(th))
    r = finite_length_rows(strip, th, st.Fc, st.rho, fc.Rr, start="anchor", anchor_Fc=anchors.Fc,
                           anchor_rho=anchors.rho)
    out = {f"hs_{k}": np.asarray(r[k], float) for k in HS_COLUMNS}
    out["hs_flags"] = np.array([";".join(f) for f in r["flags"]], dtype=object)
    return out


def halfspace_chunk(task, rows) -> dict:
    """The finite-length columns of one chunk, the 2D FE at the most loaded slice (method fe)
    and, with wear, the wear column at the axial peak (module docstring of
    :mod:`femcam.sweep.extras`).

    Parameters
    ----------
    task : femcam.sweep.pipeline.ChunkTask
        The chunk (scene, ``theta`` [rad], options, slip, ``wear_k``).
    rows : ChunkRows
        The chunk's table with the contact and wear columns filled (SI).

    Returns
    -------
    dict[str, ndarray]
        ``hs_*`` columns (SI), ``hs_flags``, ``fe_load_basis``; with wear also
        ``wear_depth`` [m per revolution] and ``wear_source``.
    """
    out = halfspace_rows(task.scene, task.theta)
    _fe_slice(task, rows, out)
    if task.slip is not None and math.isfinite(task.wear_k):
        a, p0 = axial_contact(out["hs_p_axial_peak"], out["hs_w_max"])
        use = np.isfinite(a) & (np.asarray(rows.status).astype(str) == "ok")
        depth = wear_depth_per_angle(rows.theta, np.where(use, a, 0.0), np.where(use, p0, 0.0),
                                     np.where(use, rows.Fc, 0.0), task.slip, task.wear_k)
        out["wear_depth"] = np.where(use, depth, rows.wear_depth)
        out["wear_source"] = np.where(use, "axial_peak", np.asarray(rows.wear_source).astype(str))
    return out


def assess_chunk(task, rows) -> dict:
    """The assessment of the chunk's angles except undercut ones (no contact solution: NaN and
    empty text there), with the sweep's FE (or the most loaded slice's) contact as its table.

    Parameters
    ----------
    task : femcam.sweep.pipeline.ChunkTask
        The chunk (scene, ``theta`` [rad], options, slip, ``wear_k``).
    rows : ChunkRows
        The chunk's table with the contact and wear columns filled (SI).

    Returns
    -------
    dict[str, ndarray]
        ``assess_*`` columns (SI, :data:`femcam.assess.COLUMNS`) and the text
        columns ``assess_regime``, ``assess_flags``, ``assess_source``.
    """
    table = {"a_fe": rows.a_fe, "p0_fe": rows.p0_fe, "tau1_max": rows.tau1_max,
             "txz_range_max": rows.txz_range_max}
    axial = "hs_p_axial_peak" in rows
    if axial:  # finite length: the most loaded slice, Hertz shape factors at its p0
        a, p0 = axial_contact(rows.hs_p_axial_peak, rows.hs_w_max)
        table = {"a_fe": a, "p0_fe": p0, "tau1_max": rows.tau1_max_peak_slice,
                 "txz_range_max": rows.txz_range_max_peak_slice}
    n = task.theta.size
    idx = np.flatnonzero(np.asarray(rows.status).astype(str) != "undercut")
    out = {assess_name(c.si): np.full(n, np.nan) for c in ASSESS_COLUMNS if c.si not in ASSESS_SKIP}
    out.update({t: np.full(n, "", dtype=object) for t in ASSESS_TEXT})
    if idx.size == 0:
        return out
    r = assess_rows(contact_case(task.scene, task.theta[idx]),
                    table={k: np.asarray(v)[idx] for k, v in table.items()},
                    coatings=scene_coatings(task.scene.layers))
    for c in ASSESS_COLUMNS:
        if c.si not in ASSESS_SKIP:
            out[assess_name(c.si)][idx] = r[c.si]
    src = np.asarray(r["source"]).astype(str)
    if axial:
        src = np.where(src == "fe", "axial_peak", src)
    for name, v in (("assess_regime", r["regime"]), ("assess_flags", r["flags"]), ("assess_source", src)):
        out[name][idx] = np.asarray(v).astype(str)
    return out


def _contact_rows(rows) -> np.ndarray:
    """Rows with a contact solution to build on: ``ok``, or ``failed`` (the FE failed there, the
    contact exists); lift-off and undercut rows (the roller does not fit) get NaN."""
    status = np.asarray(rows.status).astype(str)
    return (status == "ok") | (status == "failed")


def ring_chunk(task, rows) -> dict:
    """The ring (pin or needle bearing) side columns of one chunk, solved before the wear and
    the assessment by :func:`femcam.sweep.ringhead.ring_headline` (which also lets the ring
    answer the headline); NaN where there is no contact.

    Parameters
    ----------
    task : femcam.sweep.pipeline.ChunkTask
        The chunk (scene, ``theta`` [rad], options, slip, ``wear_k``).
    rows : ChunkRows
        The chunk's table with the contact, wear and ``ring_*`` columns filled (SI).

    Returns
    -------
    dict[str, ndarray]
        ``ring_*`` columns of :data:`RING` (SI).

    Raises
    ------
    FemcamError
        The ring model's refusal kept by the headline step (the provider's columns stay NaN).
    """
    exc, rows.ring_error = rows.ring_error, None
    if exc is not None:
        raise exc
    n = task.theta.size
    return {c.si: np.asarray(rows.get(c.si, np.full(n, np.nan)), float) for c in RING}


def cam_disk_chunk(task, rows) -> dict:
    """The cam disk on its shaft (bore hoop stress, shaft contact) of one chunk; NaN where
    there is no contact.

    Parameters
    ----------
    task : femcam.sweep.pipeline.ChunkTask
        The chunk (scene, ``theta`` [rad], options, slip, ``wear_k``).
    rows : ChunkRows
        The chunk's table with the contact and wear columns filled (SI).

    Returns
    -------
    dict[str, ndarray]
        ``camdisk_*`` columns (SI) and ``camdisk_flags``.
    """
    Fc = np.where(_contact_rows(rows), rows.Fc, 0.0)   # cam_disk_rows: Fc <= 0 -> NaN row
    model = cam_disk_model(task.scene)
    r = cam_disk_rows(cam_disk_record(task.scene), task.scene.analyse(task.theta), Fc, model=model)
    out = {f"camdisk_{k}": np.asarray(r[k], float) for k in CAM_CSV_COLUMNS}
    out["camdisk_flags"] = r["flags"]
    if task.vtk_dir is not None and task.vtk_mask is not None:
        cam_disk_vtus(task, model, Fc)
    return out


def cam_disk_check(scene, table, tolerance: float) -> dict:
    """"Model only what the scene needs", verified once per sweep: the fully refined disk model
    at the swept angle of the largest contact force (``ok`` rows) against today's local cam body
    (:func:`femcam.bodies.cam_study.check_local_body`, ~4 s).

    Parameters
    ----------
    scene : femcam.scene.Scene
        A scene with ``[cam] bore_mm``.
    table : dict of ndarray
        The sweep table (``theta`` rad, ``Fc`` N, ``status``).
    tolerance : float
        The sweep's tolerance (relative).

    Returns
    -------
    dict
        The check's dict; ``{}`` without an ``ok`` contact row; a refusal (a
        :class:`~femcam.errors.FemcamError` of the refined model) as ``{"refused": reason, ...}``.
    """
    ok = np.asarray(table["status"]).astype(str) == "ok"
    Fc = np.where(ok, np.asarray(table["Fc"], float), np.nan)
    if not np.any(np.isfinite(Fc) & (Fc > 0)):
        return {}
    theta = float(np.asarray(table["theta"], float)[int(np.nanargmax(Fc))])
    try:
        case = cam_disk_record(scene)
        return check_local_body(case, scene.analyse(np.array([theta])), tolerance=tolerance,
                                disk=disk_from_case(case))
    except FemcamError as exc:
        return {"theta_deg": math.degrees(theta), "refused": f"{type(exc).__name__}: {exc}",
                "line": f"cam disk check at {math.degrees(theta):.1f} deg refused: {exc}", "flag": ""}


def cam_disk_vtu_name(theta: float) -> str:
    """``camdisk_<vtu_name>``: the complete cam body beside the sweep's VTU of the same angle.

    Parameters
    ----------
    theta : float
        Cam angle (rad).

    Returns
    -------
    str

    >>> cam_disk_vtu_name(0.0)
    'camdisk_angle_0000.000deg.vtu'
    """
    return "camdisk_" + vtu_name(theta)


def cam_disk_vtus(task, model, Fc) -> None:
    """The global model's complete cam body at the chunk's VTK angles with a contact
    (:func:`femcam.io.write_global_cam_vtu`; one back-substitution each); a stale
    file of an angle without contact is removed.

    Parameters
    ----------
    task : femcam.sweep.pipeline.ChunkTask
        ``scene``, ``theta``, ``vtk_dir``, ``vtk_mask`` of the chunk.
    model : CamGlobalModel
        The scene's global model (:func:`cam_disk_model`).
    Fc : ndarray
        The chunk's contact force (N; <= 0: no contact, no file).
    """
    for i in np.flatnonzero(task.vtk_mask):
        path = Path(task.vtk_dir) / cam_disk_vtu_name(task.theta[i])
        if not (np.isfinite(Fc[i]) and Fc[i] > 0):
            path.unlink(missing_ok=True)
            continue
        C, n, _, _ = contact_frame(task.scene.analyse(task.theta[i:i + 1]))
        write_global_cam_vtu(path, model, C, n, float(Fc[i]), theta=float(task.theta[i]))


def layers_chunk(task, rows, solved) -> dict:
    """The coating interface and case-hardening columns of one chunk (the scene's layers);
    NaN where there is no contact.

    An ``ok`` row the FE answered takes them from the stress field of that very solve (the
    coated model of the headline, :func:`femcam.sweep.cache.build_model`; ``layer_source =
    "headline"``); a contact row without one (method hertz, a Hertz row of method auto, a
    failed FE row, a flat-faced follower) from the layered FE of the angle alone
    (:func:`femcam.layers.scene_layer_rows`, ``layer_source = "layer_model"``).

    Parameters
    ----------
    task : femcam.sweep.pipeline.ChunkTask
        The chunk (scene, ``theta`` [rad], options, slip, ``wear_k``).
    rows : ChunkRows
        The chunk's table with the contact and wear columns filled (SI).
    solved : dict[int, femcam.fe.ContactResult]
        The FE solves that answered the chunk's rows (row index -> result).

    Returns
    -------
    dict[str, ndarray]
        ``layer_*`` columns under their SI names, SI values (:data:`LAYERS`; the CSV names
        carry the unit), the estimates :data:`LAYER_ESTIMATES` (relative; NaN on a
        ``layer_model`` row) and the text column ``layer_source``.
    """
    n = task.theta.size
    out = {c.si: np.full(n, np.nan) for c in LAYERS + LAYER_ESTIMATES}
    out["layer_source"] = np.full(n, "", dtype=object)
    status = np.asarray(rows.status).astype(str)
    contact = _contact_rows(rows)
    head = [i for i in np.flatnonzero(contact) if i in solved and status[i] == "ok"]
    if head:
        lay = scene_layers(task.scene.layers, task.scene.follower)
        kw = dict(coating=lay["coating"][1] if lay["coating"] else None,
                  coat_body=lay["coating"][0] if lay["coating"] else "roller",
                  case=lay["case"][1] if lay["case"] else None,
                  case_body=lay["case"][0] if lay["case"] else "cam")
        for i in head:
            r = result_layer_row(solved[i], **kw)
            for c in LAYERS:
                out[c.si][i] = r[c.csv] / c.factor
            out["layer_source"][i] = "headline"
            _layer_estimate(task, rows, i, out)
    idx = np.setdiff1d(np.flatnonzero(contact), np.asarray(head, int))
    if idx.size:
        st = task.scene.analyse(task.theta[idx])
        r = scene_layer_rows(task.scene.layers, task.scene.pair, task.scene.follower, task.theta[idx],
                             st.Fc, st.rho, a_over_h=task.options.a_over_h)
        for c in LAYERS:
            if c.csv in r:
                out[c.si][idx] = np.asarray(r[c.csv], float) / c.factor
        out["layer_source"][idx] = "layer_model"
    return out


def _layer_estimate(task, rows, i: int, out: dict) -> None:
    """Row ``i``'s interface-stress estimates (:data:`LAYER_ESTIMATES`): its family's two-level
    estimate carried to the row's own ``a_over_h_row`` (``e_ref (n_ref / n_row)^p``, as
    :func:`femcam.sweep.estimate.row_estimate`); NaN without a family estimate."""
    fam = rows.family[i]
    est = task.estimates.get(int(fam)) if np.isfinite(fam) else None
    n_row = float(rows.a_over_h_row[i])
    if est is None or not n_row > 0:
        return
    for c in LAYER_ESTIMATES:
        q = c.si.removeprefix("err_est_")
        out[c.si][i] = est.carried(q, n_row)


def coated_cam(scene) -> bool:
    """True when the cam is coated and the scene gives a coating wear coefficient
    (:func:`femcam.wear.coating.coating_wear`).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene swept.

    Returns
    -------
    bool
        The ``coating_wear`` provider applies.
    """
    cw = coating_wear(scene.layers, scene.wear, scene.cam.hardness)
    return cw is not None and cw.body == "cam"


def coating_wear_chunk(task, rows) -> dict:
    """A coated cam with a coating wear coefficient: the wear column (cam depth per revolution
    at the contact) with the coating's k, ``wear_source`` gets ``;coating``.

    Parameters
    ----------
    task : femcam.sweep.pipeline.ChunkTask
        The chunk (scene, ``theta`` [rad], options, slip, ``wear_k``).
    rows : ChunkRows
        The chunk's table with the contact and wear columns filled (SI).

    Returns
    -------
    dict[str, ndarray]
        ``wear_depth`` [m per revolution] scaled by the coating/substrate k ratio
        where positive, and ``wear_source``.
    """
    cw = coating_wear(task.scene.layers, task.scene.wear, task.scene.cam.hardness)
    depth = np.asarray(rows.wear_depth, float)
    src = np.asarray(rows.wear_source).astype(str)
    on = np.isfinite(depth) & (depth > 0)
    return {"wear_depth": np.where(on, depth * cw.ratio, depth),
            "wear_source": np.where(on, np.char.add(src, ";coating"), src)}


def has_support(scene) -> bool:
    """True when the roller runs on a pin or needles (``[follower] roller_support`` is not
    ``solid``; ``scene.bodies.roller``).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene swept.

    Returns
    -------
    bool
        The ``bodies`` provider applies.
    """
    return scene.bodies.roller is not None


MPA = 1e-6
HS_PANELS = (("peak pressure (MPa)", (("hs_p_axial_peak", "axial peak p(x, y) (3D half-space)", MPA),
                                               ("p0_hertz", "2D Hertz p0 at Fc / length", MPA),
                                               ("p0_peak_slice", "2D FE p0 at the most loaded slice", MPA)),
               False),
              ("most loaded slice\nw_max (N/mm)", (("hs_w_max", "load per length of the most loaded slice",
                                                   1e-3),), False))
ASSESS_PANELS = (("lambda (-)", (("assess_lam", "lambda = h_min / sigma", 1.0),), True),
                  ("safety factor (-)", (("assess_sf_yield", "first yield", 1.0),
                                         ("assess_sf_shakedown", "shakedown", 1.0),
                                         ("assess_sf_subsurface", "subsurface fatigue", 1.0),
                                         ("assess_sf_surface_fatigue", "surface fatigue", 1.0)), True),
                  ("temperature (degC)", (("assess_T_contact", "contact temperature", 1.0),), False))
RING_PANELS = (("bore hoop stress (MPa)", (("ring_hoop_max", "largest tensile bore hoop stress", MPA),),
                 False),
                ("cam-roller p0 (MPa)", (("p0_fe", "ring model (headline p0_fe)", MPA),
                                         ("p0_hertz", "Hertz, solid roller", MPA)), False),
                ("needle load (N)", (("ring_needle_Q_on", "most loaded, needle on the load line", 1.0),
                                     ("ring_needle_Q_between", "most loaded, load between needles", 1.0)),
                 False))
CAM_DISK_PANELS = (("cam bore hoop stress (MPa)", (("camdisk_hoop_max", "largest tensile hoop stress at the "
                                                  "cam bore", MPA),), False),
                   ("shaft contact pressure (MPa)", (("camdisk_shaft_p0", "shaft-bore peak pressure", MPA),),
                    False))
LAYER_PANELS = (("interface shear (MPa)", (("layer_interface_tau_max", "max |tau| at the interface",
                                             MPA),), False),
                 ("utilisation (-)", (("layer_interface_utilisation", "interface shear / strength", 1.0),
                                      ("layer_case_utilisation_max", "case: tau1 / k(z) max", 1.0)), False))
