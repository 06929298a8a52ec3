"""The worst values of a sweep, with units and angles: one row per headline column
(:func:`peak_rows`, the reports' table) and one sentence per extra column provider.

The sweep's headline (p0 FE/Hertz, von Mises, tau1) is the 2D line contact at the mean load;
a provider (:mod:`femcam.sweep.extras`) can change the answer (the axial peak of a crowned
roller, the needle loads of a needle roller). :func:`worst_lines` writes its worst values as
sentences for the CLI summary and ``report.md``; each value is the column's largest (or
smallest, for margins) over the ``ok`` rows, the same number as the CSV column's extreme.
:func:`refusals` writes the providers refused at run time the same way (part, reason, the scene
keys to change).
"""

from __future__ import annotations

import math

import numpy as np

from ..assess.core import column_extreme
from .table import COLUMNS

#: the headline columns' worst values (SI column, what, unit shown, "max"|"min"|"absmax", depth
#: column or ""); the factor SI -> unit is the CSV's (:data:`femcam.sweep.table.COLUMNS`)
PEAKS = (("Fc", "contact force Fc", "N", "max", ""),
         ("phi", "pressure angle phi (largest magnitude)", "deg", "absmax", ""),
         ("p0_hertz", "p0 Hertz", "MPa", "max", ""),
         ("p0_fe", "p0 FE (peak of the solved pressure)", "MPa", "max", ""),
         ("a_hertz", "half-width a, Hertz", "um", "max", ""),
         ("a_fe", "half-width a, FE (fitted ellipse)", "um", "max", ""),
         ("vm_max", "von Mises maximum", "MPa", "max", "vm_depth"),
         ("tau1_max", "max shear tau1 maximum", "MPa", "max", "tau1_depth"),
         ("txz_range_max", "orthogonal shear range txz (one pass)", "MPa", "max", "txz_range_depth"),
         ("surf_sx_min", "surface sx, most compressive", "MPa", "min", ""),
         ("surf_sx_max", "surface sx, most tensile", "MPa", "max", ""),
         ("surf_sz_min", "surface sz, most compressive", "MPa", "min", ""),
         ("surf_txz_absmax", "surface txz (largest magnitude)", "MPa", "max", ""),
         ("Q", "tangential force Q (largest magnitude)", "N", "absmax", ""),
         ("v_slip", "slip speed v_slip (largest magnitude)", "m/s", "absmax", ""),
         ("wear_depth", "wear depth per revolution", "nm", "max", ""))

#: the note of a worst value flagged ``surf_edge_dominated:<column>`` at its angle
EDGE_NOTE = ("edge-dominated at this angle: a value of the FE contact edge's singularity, "
             "not a result (flags)")


def angle_text(theta_deg: float) -> str:
    """A cam angle for the reports: up to 3 decimals, at least one (``"240.0"``, ``"100.05"``),
    so the refined angles around a curvature jump stay distinct.

    Parameters
    ----------
    theta_deg : float
        Cam angle [deg].

    Returns
    -------
    str
        E.g. ``"74.125"``; ``"-"`` for NaN.
    """
    if not math.isfinite(theta_deg):
        return "-"
    s = f"{theta_deg:.3f}".rstrip("0")
    return s + "0" if s.endswith(".") else s

#: provider -> its label and items (SI column, what, unit shown, factor SI -> unit, "max"|"min")
ITEMS = {
    "halfspace": ("finite length", (("hs_p_axial_peak", "axial peak", "MPa", 1e-6, "max"),
                                    ("p0_peak_slice", "p0 at the most loaded slice (2D FE)", "MPa",
                                     1e-6, "max"))),
    "bodies": ("roller support", (("ring_hoop_max", "bore hoop stress", "MPa", 1e-6, "max"),
                                  ("ring_pin_p0", "pin pressure", "MPa", 1e-6, "max"),
                                  ("ring_needle_Q_on", "worst needle load", "N", 1.0, "max"))),
    "cam_disk": ("cam disk", (("camdisk_hoop_max", "bore hoop stress", "MPa", 1e-6, "max"),
                              ("camdisk_shaft_p0", "shaft pressure", "MPa", 1e-6, "max"))),
    "layers": ("layers", (("layer_interface_tau_max", "interface shear", "MPa", 1e-6, "max"),
                          ("layer_interface_utilisation", "interface utilisation", "", 1.0, "max"),
                          ("layer_case_margin", "smallest case margin", "", 1.0, "min"))),
}


def _extreme(table, name, ok, how):
    """``(value, theta_deg, index)`` of the largest/smallest (``"absmax"``: largest in magnitude,
    returned with its sign) finite ``ok`` value, or None."""
    if name not in table:
        return None
    v = np.asarray(table[name], float)
    e = column_extreme(np.abs(v) if how == "absmax" else v, ok, "max" if how == "absmax" else how)
    if e is None:
        return None
    return float(v[e[1]]), math.degrees(float(np.asarray(table["theta"], float)[e[1]])), e[1]


def peak_rows(table, names=()) -> list[dict]:
    """The worst value of each headline column (:data:`PEAKS`) and of each extra provider's
    column (:data:`ITEMS`, for the providers in ``names``) over the ``ok`` rows, with its cam
    angle and, for a subsurface maximum, its depth: the rows of the reports' worst-angle table.

    Parameters
    ----------
    table : Mapping[str, ndarray]
        The sweep table (SI columns, ``theta`` [rad], ``status``).
    names : sequence of str, optional
        The providers that ran (``provenance["extras"]["providers"]``).

    Returns
    -------
    list of dict
        ``{"column", "csv", "what", "unit", "value", "theta_deg", "depth_um", "index",
        "source"}`` per column with a finite ``ok`` value: ``column`` the SI name (a
        ``sweep.npz`` key), ``csv`` its ``sweep.csv`` name ("" for a provider's column), ``value``
        in ``unit`` (the factor of the CSV), ``depth_um`` NaN without a depth column, ``source``
        ``"headline"`` or the provider's label, ``note`` :data:`EDGE_NOTE` where the row's
        ``flags`` say this surface value is the contact edge's discretisation singularity
        (``surf_edge_dominated:<column>``, :func:`femcam.sweep.headline.edge_flags`), else "".
    """
    ok = np.asarray(table["status"]).astype(str) == "ok"
    csv = {c.si: (c.csv, c.factor) for c in COLUMNS}
    items = [(c, what, unit, csv[c][1], how, depth, "headline", csv[c][0])
             for c, what, unit, how, depth in PEAKS]
    items += [(c, what, unit, f, how, "", label, "") for name in names if name in ITEMS
              for label, its in [ITEMS[name]] for c, what, unit, f, how in its]
    flags = np.asarray(table["flags"]).astype(str) if "flags" in table else None
    rows = []
    for c, what, unit, f, how, depth, source, csv_name in items:
        e = _extreme(table, c, ok, how)
        if e is None:
            continue
        d = float(np.asarray(table[depth], float)[e[2]]) * 1e6 if depth and depth in table else math.nan
        edge = f"surf_edge_dominated:{c}" in str(flags[e[2]]).split(";") if flags is not None else False
        rows.append({"column": c, "csv": csv_name, "what": what, "unit": unit, "value": e[0] * f,
                     "theta_deg": e[1], "depth_um": d, "index": e[2], "source": source,
                     "note": EDGE_NOTE if edge else ""})
    return rows


def _halfspace_tail(table, found) -> str:
    """``" (2D Hertz at the mean load there 1127 MPa): the 2D p0 above is not the peak"`` for
    the axial peak."""
    if "hs_p_axial_peak" not in found:
        return ""
    i = found["hs_p_axial_peak"][2]
    p_h = float(np.asarray(table["p0_hertz"], float)[i]) * 1e-6
    return f" (2D Hertz at the mean load there {p_h:.0f} MPa): the 2D p0 above is not the peak"


def assess_line(extras: dict) -> str:
    """The assessment's worst angle per criterion as one line (the CLI's; ``report.md`` has
    them as a table), or "" when the sweep ran no assessment.

    Parameters
    ----------
    extras : dict
        The providers' summary of :func:`femcam.sweep.extras.extras_provenance`.

    Returns
    -------
    str
        E.g. ``"assessment (worst per criterion, SI units): film (lambda) 0.2079 at 0.0 deg, ..."``.
    """
    worst = extras.get("assess")
    if not worst:
        return ""
    return "assessment (worst per criterion, SI units): " + ", ".join(
        f"{c} {w['value']:.4g} at {w['theta_deg']:.1f} deg" for c, w in worst.items())


def worst_lines(names, table, extras: dict | None = None) -> list[str]:
    """One line per provider in ``names``: its worst values, with the unit and the cam angle.

    Parameters
    ----------
    names : sequence of str
        The providers that ran (:func:`femcam.sweep.extras.providers_for`).
    table : Mapping[str, ndarray]
        The sweep table (SI columns, ``theta`` [rad], ``status``, ``p0_hertz`` [Pa]).
    extras : dict, optional
        The rest of the providers' summary (``coating_wear``: ``revolutions_through``; the
        assessment's line is :func:`assess_line`), as built by
        :func:`femcam.sweep.extras.extras_provenance`.

    Returns
    -------
    list of str
        E.g. ``"finite length: axial peak 2032 MPa at 72.0 deg (2D Hertz at the mean load there
        1127 MPa): the 2D p0 above is not the peak"``; providers without a finite value are left out.
    """
    ok = np.asarray(table["status"]).astype(str) == "ok"
    extras = extras or {}
    lines = []
    for name in names:
        if name not in ITEMS:
            continue
        label, items = ITEMS[name]
        found = {c: e for c, *_, how in items if (e := _extreme(table, c, ok, how)) is not None}
        parts = [f"{what} {found[c][0] * f:.4g}{' ' + unit if unit else ''} at {found[c][1]:.1f} deg"
                 for c, what, unit, f, _ in items if c in found]
        if parts:
            tail = _halfspace_tail(table, found) if name == "halfspace" else ""
            lines.append(f"{label}: " + ", ".join(parts) + tail)
    n = extras.get("coating_wear", {}).get("revolutions_through")
    if n is not None and math.isfinite(n):
        lines.append(f"coating: worn through after {n:.4g} revolutions at the deepest wear rate")
    return lines


def refusals(table, keys: dict[str, str], column: str = "extras_error") -> list[dict]:
    """The providers refused at run time (the text column ``column``), one record per provider:
    a part the scene asks for that answered nothing at some angles.

    Parameters
    ----------
    table : Mapping[str, ndarray]
        The sweep table (``column``: ``"<provider>: <error>: <reason>"`` per row, several joined
        by ``" | "``).
    keys : dict[str, str]
        Provider name -> the scene keys that ask for it, in run order
        (:data:`femcam.sweep.extras.PROVIDERS`).
    column : str, optional
        The text column of the refusals (:data:`femcam.sweep.extras.ERROR_COLUMN`).

    Returns
    -------
    list of dict
        ``{"part", "reason", "angles", "keys", "line"}`` per refused provider, in run order:
        ``reason`` the first refusal's ``"<error>: <message>"`` (with how many other reasons the
        column holds), ``angles`` the number of rows refused, ``keys`` the scene keys that ask
        for the part, ``line`` one sentence naming all of it (CLI, ``report.md``).
    """
    cells = np.asarray(table.get(column, [])).astype(str)
    reasons: dict[str, list[str]] = {}
    rows: dict[str, int] = {}
    for cell in cells:
        parts = set()
        for e in (cell.split(" | ") if cell else ()):
            part, _, reason = e.partition(": ")
            if reason not in reasons.setdefault(part, []):
                reasons[part].append(reason)
            parts.add(part)
        for part in parts:
            rows[part] = rows.get(part, 0) + 1
    out = []
    for part in [q for q in keys if q in reasons] + [q for q in reasons if q not in keys]:
        first, n = reasons[part], rows[part]
        reason = first[0] + (f" (and {len(first) - 1} other reason(s) in {column})"
                             if len(first) > 1 else "")
        line = (f"{part} refused at {n} of {cells.size} angle(s), its columns are NaN there: {reason}"
                + (f"; change the scene keys {keys[part]}" if keys.get(part) else ""))
        out.append({"part": part, "reason": reason, "angles": n, "keys": keys.get(part, ""), "line": line})
    return out


#: headline columns whose FE rows carry an error estimate: column -> ``err_est_*`` column
#: (:mod:`femcam.sweep.estimate`)
ESTIMATED = {"p0_fe": "err_est_p0", "a_fe": "err_est_a", "vm_max": "err_est_vm", "tau1_max": "err_est_tau1"}
#: the providers' estimated columns: column -> (``err_est_*`` column, what, worst by ``max`` or
#: ``min``) (the interface stresses of a coating, the ring's own stresses)
ESTIMATED_EXTRA = {
    "layer_interface_tau_max": ("err_est_interface_tau", "interface shear (largest magnitude)", "max"),
    "layer_interface_sn_min": ("err_est_interface_sn", "interface normal stress, most compressive", "min"),
    "ring_hoop_max": ("err_est_bore_hoop", "bore hoop stress, largest tensile", "max"),
    "ring_pin_p0": ("err_est_pin_p0", "pin contact peak pressure", "max"),
    "ring_needle_Q_on": ("err_est_needle_Q", "most loaded needle", "max")}


def estimate_rows(table, options: dict | None = None) -> list[dict]:
    """The error estimate of each headline quantity that has one: at the row of its worst value
    (the row of :func:`peak_rows`) and the largest over the ``ok`` FE rows, with the rtol asked
    for and whether every row met it (the quantities ``rtol`` controls, ``options["rtol_on"]``,
    default p0); then the providers' estimated columns (:data:`ESTIMATED_EXTRA`).

    Parameters
    ----------
    table : Mapping[str, ndarray]
        The sweep table (SI columns, ``err_est_*`` relative, ``status``).
    options : dict, optional
        ``provenance["options"]`` (its ``rtol``, relative, when the sweep chose the mesh, and
        its ``rtol_choice["rtol_on"]``).

    Returns
    -------
    list of dict
        ``{"column", "what", "at_worst_pct", "max_pct", "n_rows", "rtol_pct", "met"}`` per
        quantity with a finite estimate (percent; ``rtol_pct`` and ``met`` None except for the
        controlled quantities with an rtol); empty without estimates (method hertz).
    """
    if "err_est_p0" not in table:
        return []
    ok = np.asarray(table["status"]).astype(str) == "ok"
    worst = {r["column"]: r for r in peak_rows(table)}
    rtol = (options or {}).get("rtol")
    on = ((options or {}).get("rtol_choice") or {}).get("rtol_on") or ["p0"]
    for c, (e, what, sense) in ESTIMATED_EXTRA.items():
        v = np.where(ok, np.asarray(table.get(c, np.full(ok.shape, np.nan)), float), np.nan)
        if e in table and np.any(np.isfinite(v)):
            worst[c] = {"what": what, "index": int(np.nanargmax(v) if sense == "max" else np.nanargmin(v))}
    out = []
    for c, e in {**ESTIMATED, **{c: v[0] for c, v in ESTIMATED_EXTRA.items()}}.items():
        if e not in table:
            continue
        est = np.where(ok, np.asarray(table[e], float), np.nan)
        fin = np.isfinite(est)
        if c not in worst or not fin.any():
            continue
        at = float(est[worst[c]["index"]])
        ctrl = rtol is not None and e.removeprefix("err_est_") in on
        met = bool(np.all(est[fin] <= rtol)) if ctrl else None
        out.append({"column": c, "what": worst[c]["what"], "at_worst_pct": 100.0 * at,
                    "max_pct": 100.0 * float(np.max(est[fin])), "n_rows": int(fin.sum()),
                    "rtol_pct": 100.0 * rtol if met is not None else None, "met": met})
    return out
