r"""Extra column providers of the sweep: physics packages that answer per cam angle.

Each :class:`Provider` says when it applies (from the scene), which columns it adds (SI name,
CSV name with its unit, factor SI -> CSV, like :data:`femcam.sweep.table.COLUMNS`; text
columns separately) and how one chunk computes them. :func:`fill_extras` is called once per
chunk by :func:`femcam.sweep.pipeline.run_chunk`, after the contact rows (Hertz, FE, wear) are
filled; the writers get :func:`extra_columns`; the provenance gets :func:`extras_provenance`.

=============  ===========================================  ==============================================
provider       applies when                                 columns (CSV)
=============  ===========================================  ==============================================
``halfspace``  finite-length keys (:func:`has_finite_length`) ``p_axial_peak_MPa``, ``y_axial_peak_mm``,
                                                            ``L_eff_mm``, ``w_max_N_per_mm``, ... ,
                                                            ``hs_flags``
``assess``     ``scene.tribology`` has a lubricant          ``lambda``, ``h_min_um``, ``dT_flash_K``,
                                                            ``sf_*``, ... , ``assess_regime``,
                                                            ``assess_flags``, ``assess_source``
``bodies``     ``roller_support`` is ``pin``/``needles``    ``bore_hoop_max_MPa``, ``pin_p0_MPa``,
                                                            ``needle_Qmax_on_N``, ... (the ring's
                                                            contact answers the headline,
                                                            :mod:`femcam.sweep.ringhead`)
``cam_disk``   ``[cam] bore_mm`` given                       ``cam_bore_hoop_max_MPa``, ``shaft_p0_MPa``, ...
``layers``     ``scene.layers`` non-empty                   ``interface_tau_max_MPa``, ``case_margin``, ...
``coating_``   a coated cam with ``wear_k_mm3_per_N_m`` or  (none: the wear column uses the coating's k,
``wear``       ``wear_K`` (:mod:`femcam.wear.coating`)      ``wear_source`` gets ``;coating``)
=============  ===========================================  ==============================================

Finite length (the axial slices of :mod:`femcam.halfspace.strip`):

* the 2D FE answers again at the most loaded slice with that slice's load per unit length
  (method fe): ``F = w_max * length``, columns ``F_peak_slice_N``, ``a_peak_slice_um``,
  ``p0_peak_slice_MPa`` (the peak of the solved pressure), ``vm_max_peak_slice_MPa``,
  ``tau1_max_peak_slice_MPa``, ``surf_txz_absmax_peak_slice_MPa``, ``txz_range_max_peak_slice_MPa``
  (the range of ``txz`` over one pass, fed to the assessment's subsurface fatigue) and the text
  column ``fe_load_basis = "w_max*length"``; the sweep's
  own FE columns (``a_fe``, ``p0_fe``, ``vm_max``, ...) stay at the mean load ``Fc / length``,
  comparable with Hertz (``err_a``, ``err_p0``);
* the wear column uses the axial peak: the Archard per-pass depth ``k w v_slip / V_cam`` depends
  on the pressure only through ``w = pi a p0 / 2``, so it is recomputed with ``p0 ->
  p_axial_peak`` and ``a -> 2 w_max / (pi p_axial_peak)`` (i.e. ``w = w_max``), ``wear_source =
  "axial_peak"``;
* the assessment (run after it) gets the same ``a``, ``p0`` in place of the FE/Hertz ones (its
  ``source`` reads ``axial_peak``) and the FE stress maxima of the most loaded slice where the FE
  answered (method hertz: Hertz shape factors at the axial peak).

A provider that the physics refuses for a documented reason (a :class:`~femcam.errors.FemcamError`)
leaves its columns NaN and writes the reason in the text column ``extras_error``; it never stops
the contact sweep, but the part the scene asked for is missing: :func:`femcam.sweep.worst.refusals` names it
(``provenance["extras"]["refused"]``, ``SweepResult.refused``), ``report.md`` and the CLI say it
and ``femcam sweep`` exits 1. Models are built once per process (the ring model does not pickle; its rows
do): ``femcam.sweep.providers.ring_model`` and ``strip_model``, keyed by the scene's ``repr``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .._columns import Column
from ..assess import COLUMNS as ASSESS_COLUMNS
from ..assess import worst_angles
from ..bodies.cam_rows import has_cam_bore
from ..errors import FemcamError
from ..halfspace.rows import has_finite_length
from ..io import write_pvd
from ..viz.extras import plot_extra_panels
from ..wear.coating import coating_wear
from .headline import answered_by, omitted_physics
from .providers import (
    ASSESS,
    ASSESS_PANELS,
    ASSESS_SKIP,
    ASSESS_TEXT,
    CAM_DISK,
    CAM_DISK_PANELS,
    HALFSPACE,
    HS_PANELS,
    LAYER_ESTIMATES,
    LAYER_PANELS,
    LAYERS,
    RING,
    RING_PANELS,
    assess_chunk,
    assess_name,
    cam_disk_check,
    cam_disk_chunk,
    cam_disk_vtu_name,
    coated_cam,
    coating_wear_chunk,
    halfspace_chunk,
    has_support,
    layers_chunk,
    ring_chunk,
)
from .worst import refusals, worst_lines

#: text column of every sweep with providers: ``"<provider>: <reason>"`` where one was refused
ERROR_COLUMN = "extras_error"


@dataclass(frozen=True)
class Provider:
    """One extra column provider.

    Parameters
    ----------
    name : str
        Short name (provenance, ``extras_error``).
    applies : callable(scene) -> bool
    columns : tuple of femcam._columns.Column
        Numeric columns (SI name in the table, ``csv = SI * factor``).
    text : tuple of str
        Text columns.
    compute : callable(task, rows) -> dict
        The chunk's values: SI arrays of shape (n,) for ``columns`` and ``text``. May also
        replace sweep columns it documents (``halfspace``: ``wear_depth``, ``wear_source``).
    panels : tuple of (ylabel, ((SI column, label, factor), ...), log)
        Plots against cam angle (:func:`femcam.viz.extras.plot_extra_panels`).
    title : str, optional
        What the plot shows (its title after the scene name; default: ``name``).
    keys : str, optional
        The scene keys that ask for the provider: what a refusal tells the user to change.
    solved : bool, optional
        ``compute(task, rows, solved)`` also gets the chunk's FE solves ``{row: ContactResult}``
        (the layers take their columns from the solve that answered the row).
    """

    name: str
    applies: Callable
    columns: tuple
    text: tuple
    compute: Callable
    panels: tuple = ()
    title: str = ""
    keys: str = ""
    solved: bool = False


#: the table, in the order the providers run (halfspace before assess: the axial peak)
PROVIDERS: tuple[Provider, ...] = (
    Provider("halfspace", lambda s: has_finite_length(s.finite_length, s.length), HALFSPACE,
             ("hs_flags", "fe_load_basis"), halfspace_chunk, HS_PANELS,
             "finite-length contact along the roller:\naxial peak pressure and most loaded slice",
             keys="[follower] crown, crown_*, edge_radius_mm, misalignment_deg, roller_width_mm; "
                  "[cam] face_width_mm"),
    Provider("assess", lambda s: s.tribology.lubricant is not None, ASSESS,
             ASSESS_TEXT, assess_chunk, ASSESS_PANELS,
             keys="[lubricant], [surface] and the materials' strength keys"),
    Provider("bodies", has_support, RING, (), ring_chunk, RING_PANELS,
             keys="[follower] roller_support, roller_bore_mm, pin_radius_mm, pin_clearance_um, "
                  "needle_count, needle_radius_mm"),
    Provider("cam_disk", lambda s: has_cam_bore(s.bodies), CAM_DISK, ("camdisk_flags",), cam_disk_chunk,
             CAM_DISK_PANELS,
             keys="[cam] bore_mm, shaft_fit, shaft_clearance_um"),
    Provider("layers", lambda s: bool(s.layers), LAYERS + LAYER_ESTIMATES,
             ("layer_source",), layers_chunk, LAYER_PANELS,
             keys="[materials.<body>.coating] and [materials.<body>.case]", solved=True),
    Provider("coating_wear", coated_cam, (), (), coating_wear_chunk,
             keys="[materials.cam.coating] wear keys"),
)


def plot_extras(scene, table, out) -> dict[str, str]:
    """One PNG per applicable provider with panels, ``out/plots/extras_<name>.png`` (rows that
    are not ``ok`` are left out).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene swept (which providers apply).
    table : Mapping[str, ndarray]
        The sweep table (SI columns, ``theta`` [rad], ``status``).
    out : str or Path
        Output directory.

    Returns
    -------
    dict[str, str]
        ``{"plot_extras_<name>": path}``.
    """
    ok = np.asarray(table["status"]).astype(str) == "ok"
    paths = {}
    for p in providers_for(scene):
        if not p.panels:
            continue
        panels = [(ylabel, [(label, np.where(ok, np.asarray(table[c], float) * f, np.nan))
                            for c, label, f in series
                            if c in table and np.any(np.isfinite(np.asarray(table[c], float)[ok]))], log)
                  for ylabel, series, log in p.panels]
        panels = [q for q in panels if q[1]]
        if not panels:
            continue
        path = Path(out) / "plots" / f"extras_{p.name}.png"
        paths[f"plot_extras_{p.name}"] = str(plot_extra_panels(table["theta"], panels, path,
                                                               title=f"{scene.name}: {p.title or p.name}"))
    return paths


def providers_for(scene) -> tuple[Provider, ...]:
    """The providers that apply to ``scene``, in run order.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene swept.

    Returns
    -------
    tuple of Provider
        The applicable providers of :data:`PROVIDERS`.
    """
    return tuple(p for p in PROVIDERS if p.applies(scene))


def extra_columns(scene) -> tuple[tuple[Column, ...], tuple[str, ...]]:
    """``(numeric columns, text columns)`` the providers of ``scene`` add to the sweep table
    (both empty when none applies; ``extras_error`` is the last text column otherwise).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene swept.

    Returns
    -------
    columns : tuple of femcam._columns.Column
        The numeric columns (SI name, CSV name, factor SI -> CSV unit).
    text : tuple of str
        Text column names.
    """
    ps = providers_for(scene)
    if not ps:
        return (), ()
    return (tuple(c for p in ps for c in p.columns),
            tuple(t for p in ps for t in p.text) + (ERROR_COLUMN,))


def fill_extras(task, rows, solved: dict | None = None) -> None:
    """Compute the applicable providers' columns of one chunk into ``rows`` (in place).

    Parameters
    ----------
    task : femcam.sweep.pipeline.ChunkTask
        ``scene``, ``theta``, ``options``, ``slip``, ``wear_k`` of the chunk.
    rows : ChunkRows
        The chunk's table with the contact and wear columns filled.
    solved : dict[int, femcam.fe.ContactResult], optional
        The FE solves that answered the chunk's rows (row index -> result), for the providers
        that take their columns from them (``Provider.solved``).
    """
    ps = providers_for(task.scene)
    if not ps:
        return
    n = rows.theta.size
    errors = []
    for p in ps:
        try:
            vals = p.compute(task, rows, solved or {}) if p.solved else p.compute(task, rows)
        except FemcamError as exc:
            errors.append(f"{p.name}: {type(exc).__name__}: {exc}")
            vals = {}
        for c in p.columns:
            setattr(rows, c.si, np.asarray(vals.get(c.si, np.full(n, np.nan)), float))
        for t in p.text:
            setattr(rows, t, np.asarray(vals.get(t, np.full(n, "")), dtype=object))
        for k in ("wear_depth", "wear_source"):
            if k in vals:
                setattr(rows, k, vals[k])
    setattr(rows, ERROR_COLUMN, np.full(n, " | ".join(errors), dtype=object))


def _peak(table, name, ok, how=np.nanmax):
    v = np.where(ok, np.asarray(table[name], float), np.nan)
    return float(how(v)) if np.any(np.isfinite(v)) else float("nan")


def extras_files(scene, table, out, vtk_mask) -> dict[str, str]:
    """Files of the providers beside the sweep's own in ``out``: ``camdisk.pvd``, the series of
    the complete cam body's VTUs (``vtk/camdisk_angle_*.vtu``,
    :func:`~femcam.sweep.providers.cam_disk_vtus`) at the VTK angles whose file exists.

    Parameters
    ----------
    scene : femcam.scene.Scene
    table : dict of ndarray
        The sweep table (``theta``, rad).
    out : str or Path
        The sweep's output directory.
    vtk_mask : ndarray of bool or None
        The rows of the VTK series.

    Returns
    -------
    dict[str, str]
        ``{"pvd_camdisk": path}`` or empty.
    """
    if vtk_mask is None or "cam_disk" not in [p.name for p in providers_for(scene)]:
        return {}
    theta = np.asarray(table["theta"], float)
    entries = [(math.degrees(theta[i]), Path(out) / "vtk" / cam_disk_vtu_name(theta[i]))
               for i in np.flatnonzero(vtk_mask)]
    entries = [(t, p) for t, p in entries if p.exists()]
    return {"pvd_camdisk": str(write_pvd(Path(out) / "camdisk.pvd", entries))} if entries else {}


def extras_provenance(scene, table, tolerance: float | None = None, method: str = "fe") -> dict:
    """Which providers ran and their summary over the swept angles (JSON-able).

    ``providers``: names; ``headline``: what the headline model omits (:func:`omitted_physics`)
    and which model answers it (:func:`answered_by`), one sentence each; ``columns``: the SI
    names of their columns; ``errors``: the refusals;
    ``refused``: the same, one record per provider (:func:`femcam.sweep.worst.refusals`);
    ``assess``: the worst angle per criterion (:func:`femcam.assess.worst_angles`:
    ``{criterion: {"value", "theta_deg"}}``);
    ``halfspace``: largest axial peak (MPa) and the FE load basis; ``bodies``: largest bore hoop
    stress (MPa) and needle load (N); ``layers``: largest interface utilisation, smallest case margin;
    ``cam_disk``: largest cam bore hoop stress and shaft pressure (MPa) and, given the sweep's
    ``tolerance``, ``check``: the fully refined disk vs the local body at the peak force
    (:func:`~femcam.sweep.providers.cam_disk_check`); ``notes``: its sentence (report, CLI) and
    ``flags``: the sentence again when the change exceeds the tolerance; ``worst``: one sentence
    per provider with its worst values, units and angles (:func:`femcam.sweep.worst.worst_lines`;
    the CLI summary and ``report.md`` print them).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene swept.
    table : Mapping[str, ndarray]
        The sweep table (SI columns).
    tolerance : float or None, optional
        The sweep's relative p0 tolerance [-]; None: no cam-disk check.
    method : str, optional
        The sweep's method (``fe``, ``auto``, ``hertz``): whether the coating is in the headline.

    Returns
    -------
    dict
        The summary above (units in the key names).
    """
    ps = providers_for(scene)
    out = {"providers": [p.name for p in ps]}
    headline = [sentence for _, sentence in omitted_physics(scene, method)] + list(answered_by(scene))
    if headline:
        out["headline"] = headline
    if not ps:
        return out
    cols, text = extra_columns(scene)
    out["columns"] = [c.si for c in cols] + list(text)   # SI names (SweepResult.load reads them)
    out["csv_columns"] = [[c.si, c.csv, c.factor] for c in cols]   # SweepResult.to_dataframe
    errs = sorted({e for e in np.asarray(table.get(ERROR_COLUMN, [])).astype(str) if e})
    if errs:
        out["errors"] = errs
        out["refused"] = refusals(table, {p.name: p.keys for p in PROVIDERS}, ERROR_COLUMN)
    ok = np.asarray(table["status"]).astype(str) == "ok"
    names = [p.name for p in ps]
    if "assess" in names:
        rows = {c.si: np.asarray(table[assess_name(c.si)], float) for c in ASSESS_COLUMNS
                if c.si not in ASSESS_SKIP}
        rows.update(theta=table["theta"], Fc=np.where(ok, table["Fc"], 0.0))
        out["assess"] = {c: {"value": v, "theta_deg": math.degrees(t)}
                         for c, (v, t, _) in worst_angles(rows).items()}
    if "halfspace" in names:
        out["halfspace"] = {"p_axial_peak_max_MPa": _peak(table, "hs_p_axial_peak", ok) * 1e-6,
                            "wear": "most loaded slice: p0 = p_axial_peak, a = 2 w_max/(pi p0)",
                            "fe_load_basis": ("a_fe, p0_fe, vm_max, ...: mean load Fc; *_peak_slice: "
                                              "F = w_max * length (most loaded slice)")}
    if "bodies" in names:
        out["bodies"] = {"bore_hoop_max_MPa": _peak(table, "ring_hoop_max", ok) * 1e-6,
                         "needle_Qmax_N": _peak(table, "ring_needle_Q_on", ok)}
    if "cam_disk" in names:
        out["cam_disk"] = {"cam_bore_hoop_max_MPa": _peak(table, "camdisk_hoop_max", ok) * 1e-6,
                           "shaft_p0_max_MPa": _peak(table, "camdisk_shaft_p0", ok) * 1e-6}
        check = cam_disk_check(scene, table, tolerance) if tolerance is not None else {}
        if check:
            out["cam_disk"]["check"] = check
            out["notes"] = [check["line"]]
            out["flags"] = [check["flag"]] if check["flag"] else []
    if "layers" in names:
        out["layers"] = {"interface_utilisation_max": _peak(table, "layer_interface_utilisation", ok),
                         "case_margin_min": _peak(table, "layer_case_margin", ok, np.nanmin)}
    if "coating_wear" in names:
        cw = coating_wear(scene.layers, scene.wear, scene.cam.hardness)
        d = _peak(table, "wear_depth", ok)
        out["coating_wear"] = {"k_coating_m3_per_N_m": cw.k_coating, "k_substrate_m3_per_N_m": cw.k_substrate,
                               "thickness_m": cw.thickness, "source": cw.source,
                               "revolutions_through": cw.thickness / d if d > 0 else math.inf}
    out["worst"] = worst_lines(names, table, out)
    return out
