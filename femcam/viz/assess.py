"""Plots and the one-page Markdown report of an assessment (:func:`femcam.assess.assess`).

Figures: lambda and film thickness vs cam angle, temperatures vs angle, safety factors vs angle,
and the cam outline coloured by lambda and by the smallest safety factor. matplotlib is imported
inside the functions (optional dependency, keeps ``import femcam`` headless).
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np

from ._mpl import pyplot, save

#: safety-factor columns plotted, with their labels
SAFETY = (("sf_yield", "first yield"), ("sf_shakedown", "shakedown"), ("sf_subsurface", "subsurface fatigue"),
          ("sf_surface_fatigue", "surface fatigue"), ("sf_scuffing", "scuffing"))


def _save(fig, path: Path) -> str:
    return str(save(fig, path, dpi=90, tight=True))


def _angle_axes(rows, figsize):
    """``(fig, ax, cam angle (deg))`` of a one-panel plot against the cam angle."""
    fig, ax = pyplot().subplots(figsize=figsize)
    return fig, ax, np.degrees(rows["theta"])


def _finish(fig, ax, ylabel: str, path, *, legend_loc: str = "best", grid: str = "major") -> str:
    """Label the cam-angle axis and ``ylabel``, legend, grid; save to ``path``."""
    ax.set_xlabel("cam angle (deg)")
    ax.set_ylabel(ylabel)
    ax.legend(fontsize=7, loc=legend_loc)
    ax.grid(alpha=0.3, which=grid)
    return _save(fig, Path(path))


def plot_lambda(rows, path) -> str:
    """lambda (left) and h_min, h_c (right) vs cam angle, regime limits 1 and 3 drawn.

    Parameters
    ----------
    rows : dict of ndarray
        :func:`femcam.assess.assess_rows` columns (SI; ``theta`` in rad).
    path : str or os.PathLike
        Output PNG.

    Returns
    -------
    str
        The path written.
    """
    plt = pyplot()
    deg = np.degrees(rows["theta"])
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 3.4))
    ax.plot(deg, rows["lam"], "C0-")
    for y, name in ((1.0, "boundary | mixed"), (3.0, "mixed | full film")):
        ax.axhline(y, color="0.5", ls="--", lw=0.8)
        ax.text(deg[0], y, " " + name, fontsize=7, va="bottom", color="0.4")
    ax.set_xlabel("cam angle (deg)")
    ax.set_ylabel("lambda = h_min / sigma")
    ax.set_ylim(bottom=0)
    bx.plot(deg, rows["h_min"] * 1e6, "C0-", label="h_min (Pan-Hamrock 1989)")
    bx.plot(deg, rows["h_c"] * 1e6, "C1--", label="h_c")
    bx.set_xlabel("cam angle (deg)")
    bx.set_ylabel("film thickness (um)")
    bx.legend(fontsize=8)
    for a in (ax, bx):
        a.grid(alpha=0.3)
    return _save(fig, Path(path))


def plot_temperatures(rows, path, *, T_oil=None, T_scuff=None) -> str:
    """Flash temperature rise and contact temperature vs cam angle (scuffing limit dashed).

    Parameters
    ----------
    rows : dict of ndarray
        :func:`femcam.assess.assess_rows` columns (SI; ``theta`` in rad).
    path : str or os.PathLike
        Output PNG.
    T_oil : float, optional
        Bulk oil temperature drawn as a line (C).
    T_scuff : float, optional
        Scuffing limit drawn dashed (C).

    Returns
    -------
    str
        The path written.
    """
    fig, ax, deg = _angle_axes(rows, (6.5, 3.4))
    ax.plot(deg, rows["T_contact"], "C3-", label="contact temperature T_oil + dT_flash")
    if T_oil is not None:
        ax.axhline(T_oil, color="C0", lw=0.8, label=f"oil (bulk) {T_oil:g} C")
    if T_scuff is not None:
        ax.axhline(T_scuff, color="k", ls="--", lw=0.8, label=f"scuffing {T_scuff:g} C")
    bx = ax.twinx()
    bx.plot(deg, rows["dT_flash"], "C1:", label="dT_flash (Blok), right axis")
    bx.set_ylabel("flash temperature rise (K)", color="C1")
    bx.set_ylim(bottom=0)
    bx.legend(fontsize=7, loc="upper right")
    return _finish(fig, ax, "temperature (C)", path, legend_loc="upper left")


def plot_safety(rows, path) -> str:
    """Safety factors vs cam angle on a log axis, the line SF = 1 drawn.

    Parameters
    ----------
    rows : dict of ndarray
        :func:`femcam.assess.assess_rows` columns (SI; ``theta`` in rad).
    path : str or os.PathLike
        Output PNG.

    Returns
    -------
    str
        The path written.
    """
    fig, ax, deg = _angle_axes(rows, (6.5, 3.6))
    for i, (col, label) in enumerate(SAFETY):
        v = np.where(np.isfinite(rows[col]), rows[col], np.nan)
        if np.any(np.isfinite(v)):
            ax.semilogy(deg, v, f"C{i}-", label=label)
    ax.axhline(1.0, color="k", lw=1.0)
    return _finish(fig, ax, "safety factor", path, grid="both")


def plot_outline(rows, path) -> str:
    """The cam outline coloured by lambda (left) and by the smallest safety factor (right).

    Parameters
    ----------
    rows : dict of ndarray
        :func:`femcam.assess.assess_rows` columns (SI; ``theta`` in rad). Needs ``cam_x``, ``cam_y`` (m).
    path : str or os.PathLike
        Output PNG.

    Returns
    -------
    str
        The path written.
    """
    plt = pyplot()
    x, y = rows["cam_x"] * 1e3, rows["cam_y"] * 1e3
    sf = np.full(x.shape, np.inf)
    for col, _ in SAFETY:
        sf = np.fmin(sf, np.where(np.isfinite(rows[col]), rows[col], np.inf))
    fig, axs = plt.subplots(1, 2, figsize=(9, 4.2))
    for ax, val, label, cmap in ((axs[0], rows["lam"], "lambda", "viridis"),
                                 (axs[1], np.where(np.isfinite(sf), sf, np.nan), "smallest safety factor",
                                  "RdYlGn")):
        ax.plot(x, y, color="0.8", lw=4, zorder=0)
        sc = ax.scatter(x, y, c=val, s=10, cmap=cmap)
        fig.colorbar(sc, ax=ax, label=label, shrink=0.8)
        ax.set_aspect("equal")
        ax.set_xlabel("x (mm)")
        ax.set_ylabel("y (mm)")
    return _save(fig, Path(path))


def _fmt(v) -> str:
    return "inf" if v == math.inf else f"{v:.3g}"


WORST_UNITS = {"film (lambda)": "", "contact temperature": " C", "pitting life": " cycles"}


def report_markdown(assessment, plots: dict, *, title: str = "", provenance: str = "", base=None) -> str:
    """The one-page report: inputs, worst angle per criterion, flags, skipped criteria, plots
    (linked relative to the directory ``base`` of the report file).

    Parameters
    ----------
    assessment : femcam.assess.Assessment
        The assessment (rows, inputs, worst angles, flags).
    plots : dict of str to path
        ``{name: PNG path}`` to link.
    title : str
        Report title ("": a default).
    provenance : str
        Text of the provenance section.
    base : str or os.PathLike, optional
        Directory of the report; links are made relative to it.

    Returns
    -------
    str
        The Markdown text (angles in deg, stresses in MPa, temperatures in C).
    """
    a = assessment
    r, inp = a.rows, a.inputs
    on = r["Fc"] > 0
    lines = [f"# Assessment: {title or a.scene_name}", ""]
    if provenance:
        lines += [provenance, ""]
    if inp.lubricant is not None:
        lub = inp.lubricant
        lines += [f"Lubricant: {lub.name} (alpha = {lub.alpha * 1e9:g} 1/GPa, {lub.rho:g} kg/m^3; "
                  f"{lub.source}); "
                  f"oil temperature {inp.T_oil:g} C, viscosity {lub.viscosity(inp.T_oil) * 1e3:.3g} mPa s; "
                  f"composite roughness sigma = {inp.sigma * 1e6:.3g} um.", ""]
    lines += ["## Worst angle per criterion", "", "| criterion | worst value | cam angle (deg) |",
              "|---|---|---|"]
    for crit, (val, th, _) in a.worst.items():
        lines.append(f"| {crit} | {_fmt(val)}{WORST_UNITS.get(crit, '')} | {math.degrees(th):.1f} |")
    regimes, counts = np.unique(np.asarray(r["regime"])[on].astype(str), return_counts=True)
    lines += ["", "Lubrication regime (contact angles): "
              + ", ".join(f"{g} {c}" for g, c in zip(regimes, counts, strict=True)) + "."]
    flags = {}
    for f in np.asarray(r["flags"]).astype(str):
        for name in filter(None, f.split(";")):
            flags[name] = flags.get(name, 0) + 1
    lines += ["", "Flags (angles computed outside a formula's range of validity): "
              + (", ".join(f"{k} at {v} angles" for k, v in flags.items()) or "none") + "."]
    src, nsrc = np.unique(np.asarray(r.get("source", ())).astype(str), return_counts=True)
    if src.size:
        lines += ["", "Contact source (source column): "
                  + ", ".join(f"{g} at {c} angles" for g, c in zip(src, nsrc, strict=True)) + "."]
    for o in getattr(a, "omitted", ()):
        lines += ["", f"**Not modelled:** {o}."]
    if a.notes:
        lines += ["", "Notes (criteria skipped, fallbacks): " + "; ".join(a.notes) + "."]
    lines += [""]
    for name, path in plots.items():
        link = os.path.relpath(path, base) if base is not None else str(path)
        lines += [f"![{name}]({Path(link).as_posix()})", ""]
    return "\n".join(lines)


def plot_assessment(assessment, out) -> dict:
    """All four figures into ``out`` (a directory); returns ``{name: path}``.

    Parameters
    ----------
    assessment : femcam.assess.Assessment
        The assessment.
    out : str or os.PathLike
        Output directory.

    Returns
    -------
    dict of str to str
        ``{name: path}`` of the PNGs written (lambda only with a lubricant, temperatures only
        where they are finite).
    """
    out = Path(out)
    r, inp = assessment.rows, assessment.inputs
    T_s = min((m["T_scuff"] for m in (inp.cam, inp.roller) if "T_scuff" in m), default=None)
    plots = {"lambda": plot_lambda(r, out / "assess_lambda.png")} if inp.lubricant is not None else {}
    if np.any(np.isfinite(r["T_contact"])):
        plots["temperatures"] = plot_temperatures(r, out / "assess_temperature.png", T_oil=inp.T_oil,
                                                  T_scuff=T_s)
    plots["safety"] = plot_safety(r, out / "assess_safety.png")
    plots["outline"] = plot_outline(r, out / "assess_outline.png")
    return plots
