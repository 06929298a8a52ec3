"""The sweep's report as one self-contained HTML page (``DIR/report.html``, written beside
``report.md`` by :func:`femcam.sweep.sweep` with an output directory).

One file a designer can send: the plots are embedded as base64 PNG ``data:`` URIs, the style is
inline, and the only links are relative ones to the files beside it (``sweep.pvd``,
``sweep.csv`` ...). It reads what the sweep computed (:class:`~femcam.sweep.result.SweepResult`,
the files in its folder) and never calls a solver: :func:`report_html` of
``SweepResult.load(DIR)`` rebuilds the page of a finished sweep.

Order of the page: a refused part first ("Not a complete answer"), then the title (scene name,
description, source), the run (date, versions, command line), what the headline omits, the
worst angle of each quantity (:func:`femcam.sweep.worst.peak_rows`), the models that answered,
the validation against Hertz, the plots, the scene (inputs with units, the TOML text) and the
files.
"""

from __future__ import annotations

import html
import math
from pathlib import Path

import numpy as np

try:  # Python >= 3.11
    import tomllib
except ModuleNotFoundError:  # pragma: no cover - Python 3.10 (as femcam.scene.load)
    import tomli as tomllib

from ..assess.core import WORST as ASSESS_WORST
from ..viz.html import html_table, page_html, png_data_uri
from ..viz.sweep import PLOT_CAPTIONS, plot_caption
from .estimate import estimate_text
from .result import SweepResult, families_text, hertz_check_text
from .worst import angle_text, estimate_rows, peak_rows

__all__ = ["report_html", "scene_inputs"]

#: how each value of the ``model`` column was chosen (docs/sweep.md, "Model per angle")
MODEL_REASONS = {
    "hertz": "Hertz line contact: method hertz, or (method auto) the estimated error of Hertz "
             "is within the tolerance",
    "fe_arc": "FE contact with the osculating-arc gap: the estimated error of the arc gap is "
              "within the tolerance",
    "fe_exact": "FE contact with the exact cam gap: a curvature jump, or the arc-gap estimate "
                "exceeds the tolerance",
    "fe_arc+coating": "FE contact with the osculating-arc gap, the coating band in the coated body "
                      "(the scene's coated model answers the headline)",
    "fe_exact+coating": "FE contact with the exact cam gap, the coating band in the coated body",
    "": "no model (no contact, or the row was not solved; see status)",
}

#: suffix of a row the ring model answered (femcam.sweep.ringhead) and why
RING_SUFFIX = "+ring"
RING_REASON = ("the roller runs on a pin or needles: the ring model answers p0, a, err_* and the "
               "stresses are the solid answer's scaled to its contact (global-local)")

#: unit of the assessment's worst values (the others are safety factors, ratios)
ASSESS_UNITS = {"contact temperature": "°C", "pitting life": "cycles"}

#: scene-key suffix -> unit shown (longest first: ``_mm3_per_N_m`` before ``_m``)
UNITS = (("_J_per_kg_K", "J/(kg K)"), ("_N_s_per_m", "N s/m"), ("_rad_s", "rad/s"),
         ("_mm3_per_N_m", "mm^3/(N m)"), ("_m3_per_N_m", "m^3/(N m)"), ("_mm2_per_s", "mm^2/s"),
         ("_W_per_m_K", "W/(m K)"), ("_kg_per_m3", "kg/m^3"), ("_N_per_m", "N/m"),
         ("_s_per_m", "s/m"), ("_per_GPa", "1/GPa"), ("_per_K", "1/K"), ("_kg_m2", "kg m^2"),
         ("_mm", "mm"), ("_um", "µm"), ("_nm", "nm"), ("_GPa", "GPa"), ("_MPa", "MPa"),
         ("_Pa", "Pa"), ("_deg", "deg"), ("_kg", "kg"), ("_HV", "HV"), ("_N", "N"), ("_C", "°C"),
         ("_s", "s"), ("_m2", "m^2"), ("_m", "m"))

_e = html.escape


def _num(x: float, spec: str = ".4g") -> str:
    return "-" if x is None or not math.isfinite(float(x)) else format(float(x), spec)


def scene_inputs(text: str) -> list[tuple[str, str, str]]:
    """The scene's inputs as ``(key, value, unit)`` rows, the unit read from the key's suffix
    (scene keys carry their unit: ``roller_radius_mm``).

    Parameters
    ----------
    text : str
        The scene's TOML text.

    Returns
    -------
    list of (str, str, str)
        ``("follower.roller_radius", "10", "mm")``; tables of tables are dotted, arrays of tables
        numbered from 1 (``program.segment[2].beta``). ``name``, ``description`` and ``source``
        are left out (the title shows them); empty for a text that does not parse.
    """
    try:
        data = tomllib.loads(text)
    except (tomllib.TOMLDecodeError, TypeError):
        return []
    rows = []

    def walk(prefix, d):
        for k, v in d.items():
            if isinstance(v, dict):
                walk(f"{prefix}{k}.", v)
            elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
                for i, x in enumerate(v, 1):
                    walk(f"{prefix}{k}[{i}].", x)
            elif prefix or k not in ("name", "description", "source"):
                suffix, unit = next(((s, u) for s, u in UNITS if k.endswith(s)), ("", ""))
                key, unit = (k, "rpm") if k == "rpm" else (k[: len(k) - len(suffix)], unit)
                val = ", ".join(map(str, v)) if isinstance(v, list) else str(v)
                rows.append((prefix + key, val, unit))

    walk("", data)
    return rows


def _refused(ex: dict) -> str:
    refused = ex.get("refused") or [{"line": e} for e in ex.get("errors", ())]
    if not refused:
        return ""
    items = "".join(f"<li>{_e(r['line'])}</li>" for r in refused)
    return (f"<div class=refused id=refused><h2>Not a complete answer: {len(refused)} part(s) the "
            "scene asks for were refused</h2><p>Their columns are NaN at the angles listed; "
            f"everything else below was computed (<code>femcam sweep</code> exits 1).</p>"
            f"<ul>{items}</ul></div>")


def _title(p: dict, text: str) -> tuple[str, str]:
    """The scene's name, and the title block (name, description, source) as HTML."""
    try:
        head = tomllib.loads(text) if text else {}
    except tomllib.TOMLDecodeError:
        head = {}
    name = head.get("name") or Path(str(p.get("scene", "scene built in code"))).stem
    out = [f"<h1>{_e(str(name))}</h1>"]
    if head.get("description"):
        out.append(f"<p>{_e(str(head['description']))}</p>")
    if head.get("source"):
        out.append(f"<p class=muted>Source: {_e(str(head['source']))}</p>")
    return str(name), "".join(out)


def _run(result: SweepResult, s: dict) -> str:
    p, v = result.provenance, result.provenance.get("versions", {})
    vers = ", ".join(f"{k} {v[k]}" for k in ("femcam", "gmsh", "scikit-fem", "numpy", "scipy", "python")
                     if k in v)
    st = np.asarray(result.status).astype(str)
    counts = ", ".join(f"{k} {int(np.count_nonzero(st == k))}" for k in dict.fromkeys(st))
    rows = [("date (UTC)", p.get("date", "")), ("versions", vers), ("machine", p.get("machine", "")),
            ("scene file", f"{p.get('scene', '(in memory)')} (sha256 {str(p.get('scene_sha256', ''))[:16]})"),
            ("method", f"{result.method}; {result.n_angles} angles ({counts})")]
    out = html_table(("run", ""), [(_e(a), _e(str(b))) for a, b in rows])
    return out + f"<p>Command line:</p><pre>{_e(str(p.get('command', '')))}</pre>"


def _omits(ex: dict) -> str:
    lines = list(ex.get("headline", ())) + list(ex.get("flags", ()))
    if not lines:
        return ""
    return ("<div class=omits><p><b>What the headline omits</b> (the headline is the 2D contact of "
            "two homogeneous solid bodies at Fc / length):</p><ul>"
            + "".join(f"<li>{_e(t)}</li>" for t in lines) + "</ul></div>")


def _worst(result: SweepResult) -> str:
    ex = result.provenance.get("extras", {})
    rows = peak_rows(result.table, ex.get("providers", ()))
    body = "".join(
        f"<tr data-column={_e(r['column'])}><td>{_e(r['what'])}</td><td class=num>{_num(r['value'])}</td>"
        f"<td>{_e(r['unit'].replace('um', 'µm'))}</td><td class=num>{angle_text(r['theta_deg'])}</td>"
        f"<td class=num>{_num(r['depth_um'], '.4g')}</td><td><code>{_e(r['csv'] or r['column'])}</code>"
        f"</td><td>{_e(r['source'])}</td><td>{_e(r['note'])}</td></tr>" for r in rows)
    out = ("<p>Each quantity's worst value over the angles with contact (status ok) and the cam "
           "angle where it occurs; depths are below the surface of the body where the maximum lies.</p>"
           "<table id=worst><thead><tr><th>quantity</th><th>worst value</th><th>unit</th>"
           "<th>at cam angle (deg)</th><th>depth (µm)</th><th>column</th><th>from</th><th>note</th>"
           "</tr></thead>"
           f"<tbody>{body}</tbody></table>")
    if ex.get("assess"):
        out += "<h3>Assessment: the worst angle per criterion</h3>" + html_table(
            ("criterion", "worst value", "unit", "at cam angle (deg)", "column"),
            [(_e(c), _num(w["value"]), ASSESS_UNITS.get(c, ""), angle_text(w["theta_deg"]),
              f"<code>assess_{_e(ASSESS_WORST[c][0])}</code>" if c in ASSESS_WORST else "")
             for c, w in ex["assess"].items()], num=(1, 3), attrs="id=assess")
    extra = [t for t in ex.get("notes", ())]
    n = ex.get("coating_wear", {}).get("revolutions_through")
    if n is not None and math.isfinite(n):
        extra.insert(0, f"coating: worn through after {n:.4g} revolutions at the deepest wear rate")
    return out + "".join(f"<p>{_e(t)}</p>" for t in extra)


def _models(result: SweepResult, s: dict) -> str:
    model = np.asarray(result.table.get("model", np.full(result.n_angles, ""))).astype(str)
    rows = [(f"<code>{_e(m or '(none)')}</code>", str(int(np.count_nonzero(model == m))),
             _e(MODEL_REASONS.get(m, "") if not m.endswith(RING_SUFFIX) else
                f"{MODEL_REASONS.get(m.removesuffix(RING_SUFFIX), '')}; {RING_REASON}"))
            for m in dict.fromkeys(model)]
    out = html_table(("model", "angles", "why"), rows, num=(1,))
    if result.method != "hertz":
        out += f"<p>{_e(families_text(s['n_families'], s['reuse_error_max'], s['n_binned']))}.</p>"
    return out


def _validation(result: SweepResult, s: dict) -> str:
    tol = result.provenance.get("options", {}).get("tolerance")
    if result.method == "hertz":
        return "<p>Method hertz: every row is Hertz's line contact, there is no FE answer to check.</p>"
    out = [f"<p>p0 FE against Hertz: {_e(hertz_check_text(s))}.</p>"]
    if math.isfinite(s.get("err_a_absmax", math.nan)):
        out.append(f"<p>Largest |a_fe/a_hertz - 1|: {100 * s['err_a_absmax']:.3f} %.</p>")
    fams = result.families
    if fams:
        rows = [(str(f.get("id", "")), str(f.get("n_angles", "")),
                 _num(1e3 * float(f.get("rho_ref", math.nan))), _num(1e6 * float(f.get("a_ref", math.nan))),
                 str(len(f.get("checks", ()))), _num(100 * float(f.get("reuse_error", math.nan)), ".3f"),
                 _num(float(f.get("a_over_h", math.nan)), "g"))   # rtol: each family's own mesh
                for f in fams]
        out.append("<p>Model families (one FE model reused over neighbouring angles), each checked "
                   "against a model built for the checked angle"
                   + (f", reuse tolerance {100 * float(tol):g} %" if tol is not None else "") + ":</p>")
        out.append(html_table(("family", "angles", "rho_ref (mm)", "a_ref (µm)", "checked angles",
                           "reuse error (%)", "a/h"), rows, num=(1, 2, 3, 4, 5, 6)))
    return "".join(out)


def _estimates(result: SweepResult) -> str:
    rows = estimate_rows(result.table, result.provenance.get("options", {}))
    if not rows:
        return ("<p>No error estimate: the rows are Hertz's (method hertz), or no FE row was "
                "solved on a model family.</p>")
    out = ("<p>Estimated discretisation error of each FE headline quantity (two-level estimate "
           "on the row's model family, docs/estimate.md): at the row of the quantity's worst "
           "value and the largest over the FE rows; p0 includes the family's reuse error.</p>")
    out += html_table(
        ("quantity", "estimate at its worst row (%)", "largest estimate (%)", "FE rows", "requested (rtol)"),
        [(_e(r["what"]), _num(r["at_worst_pct"], ".3g"), _num(r["max_pct"], ".3g"), str(r["n_rows"]),
          "" if r["met"] is None else f"{r['rtol_pct']:g} %: {'met by every row' if r['met'] else 'NOT met'}")
         for r in rows], num=(1, 2, 3), attrs="id=estimates")
    return out + f"<p>{_e(estimate_text(result))}.</p>"


def _plots(out: Path, plots) -> str:
    # the sweep's own in the order of their captions, then the others
    found = sorted(p.name for p in (out / "plots").glob("*.png")) if plots is None \
        else sorted(Path(p).name for p in plots)
    names = [n for n in PLOT_CAPTIONS if n in found] + [n for n in found if n not in PLOT_CAPTIONS]
    figs = []
    for png in (out / "plots" / n for n in names if (out / "plots" / n).is_file()):
        figs.append(f"<figure><img src=\"{png_data_uri(png)}\" alt=\"{_e(png.name)}\"><figcaption>"
                    f"{_e(plot_caption(png.name))} <span class=muted>(plots/{_e(png.name)})</span>"
                    "</figcaption></figure>")
    return "".join(figs) or "<p>This run wrote no plots (<code>--no-plots</code>).</p>"


def _scene(text: str) -> str:
    if not text:
        return "<p>The scene was built in code: no TOML text (its repr is in sweep.npz).</p>"
    rows = [(f"<code>{_e(k)}</code>", _e(v), _e(u)) for k, v, u in scene_inputs(text)]
    return html_table(("input", "value", "unit"), rows) + f"<pre>{_e(text)}</pre>"


#: files linked from the report when present, with what they hold
FILES = (("sweep.pvd", "VTK series of the stress fields (ParaView, pyvista)"),
         ("sweep.csv", "the table, one row per cam angle, units in the column names"),
         ("sweep.npz", "the table in SI units and the provenance (numpy)"),
         ("scene.toml", "the scene swept"), ("report.md", "this report as Markdown"),
         ("animation.gif", "animation of the VTK series"),
         ("camdisk.pvd", "VTK series of the cam disk on its shaft"))


def _files(out: Path) -> str:
    rows = [(f"<a href=\"{_e(name)}\">{_e(name)}</a>", _e(what)) for name, what in FILES
            if (out / name).is_file()]
    return html_table(("file", "what it holds"), rows) if rows else "<p>No files.</p>"


def report_html(result: SweepResult, out, plots=None) -> str:
    """The sweep's report as one self-contained HTML page (plots embedded as base64 PNG, inline
    style, relative links to the files in ``out`` only).

    Parameters
    ----------
    result : SweepResult
        A computed or loaded sweep.
    out : str or Path
        Its output directory: the plots (``plots/*.png``), ``scene.toml`` and the linked files
        are read from there.
    plots : sequence of str or Path, optional
        The plots this run wrote (files in ``out/plots``; :func:`femcam.sweep.sweep` passes them,
        so a plot left in the folder by an earlier run is not shown as this run's). None: every
        ``out/plots/*.png`` (a reloaded sweep).

    Returns
    -------
    str
        The HTML text (``DIR/report.html``).
    """
    out = Path(out)
    s, ex = result.summary(), result.provenance.get("extras", {})
    scene = out / "scene.toml"
    text = scene.read_text(encoding="utf-8") if scene.is_file() else ""
    name, title = _title(result.provenance, text)
    sections = [("The run", _run(result, s)), ("Worst values and where they occur", _worst(result)),
                ("Models used", _models(result, s)), ("Validation against Hertz", _validation(result, s)),
                ("Error estimates", _estimates(result)),
                ("Plots", _plots(out, plots)), ("The scene", _scene(text)), ("Files", _files(out))]
    body = _refused(ex) + title + _omits(ex) + "".join(
        f"<h2>{_e(h)}</h2>{c}" for h, c in sections)
    version = str(result.provenance.get("versions", {}).get("femcam", ""))
    return page_html(f"femcam sweep report: {name}", f"{body}<p class=muted>Written by femcam "
                     f"{_e(version)}; every number is from sweep.npz in this folder.</p>")
