"""The result of a sweep (:class:`SweepResult`: the table, provenance, model families, timings,
output paths) and its Markdown report.

The table's columns, statuses and flags are described in :mod:`femcam.sweep.table`.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .._columns import Column
from .._repr import compact_repr, dataframe, span
from ..errors import InputError
from ..viz.sweep import plot_caption
from .estimate import estimate_text
from .realrows import FLAT_BIN_RATIO
from .table import COLUMNS, NUMERIC, PROFILE_PREFIX, STATUSES, TEXT_COLUMNS, worst_row
from .worst import angle_text, estimate_rows, peak_rows

__all__ = ["SweepResult", "families_text", "hertz_check_text", "plot_data_arrays", "report_markdown"]


@dataclass(frozen=True)
class SweepResult:
    """Everything a sweep produced.

    Attributes
    ----------
    table : dict[str, ndarray]
        One array per column (SI names from :data:`COLUMNS`, plus ``status``, ``flags``,
        ``wear_source``, ``message`` and the diagnostics ``iterations``, ``residual``,
        ``n_dofs``, ``family``). ``fe_time`` is the contact solve + stress recovery of the angle
        (the solve's own timing, no model build, no file writing); ``build_time`` the model
        builds this row caused in the process that computed it (0 when the model came from the
        cache; the per-family build times are in ``families``). A sweep into an output
        directory with at least :data:`femcam.sweep.store.STREAM_ANGLES` angles returns a
        read-only mapping instead (:class:`femcam.sweep.store.StoredTable`: each column read
        from ``DIR/chunks`` when asked), so its memory does not grow with the table.
    method : ``"fe"`` or ``"hertz"``.
    provenance : dict
        femcam/gmsh/scikit-fem/numpy versions, scene file and hash, command line, date, options,
        ``families`` (one record per model family: references, checked reuse errors, build
        time; see :func:`femcam.sweep.verify.verify_families`) and ``wear`` (k, slip model).
    paths : dict[str, str]
        Files written (``csv``, ``npz``, ``pvd``, plots ...); empty for an in-memory sweep.
    timings : dict[str, float]
        Wall times in s: ``analytic``, ``verify`` (family planning and reuse checks, FE only),
        ``compute`` (all chunks), ``total``.
    n_chunks_computed, n_chunks_resumed : int
        How many chunks this call computed / loaded from disk.
    surface_profile : dict or None
        The worst angle's surface stresses (:func:`femcam.sweep.profile.worst_surface_profile`),
        computed during the sweep when plots are written (None otherwise).
    hertz_factors : dict or None
        Hertz maxima in units of p0 and a (:func:`femcam.hertz.conformity.shape_factors`), with
        the plots.
    """

    table: dict
    method: str
    provenance: dict = field(default_factory=dict)
    paths: dict = field(default_factory=dict)
    timings: dict = field(default_factory=dict)
    n_chunks_computed: int = 0
    n_chunks_resumed: int = 0
    surface_profile: dict | None = None
    hertz_factors: dict | None = None

    def __getitem__(self, name):
        return self.table[name]

    def __repr__(self) -> str:
        """Method, angles, status counts and the peaks with units (a compact line)."""
        t = self.table
        status = np.asarray(t["status"]).astype(str)
        counts = ", ".join(f"{k} {int(np.count_nonzero(status == k))}" for k in STATUSES
                           if np.any(status == k))
        facts = [f"method {self.method!r}", f"{self.n_angles} angles "
                 f"{span(t['theta'], 180 / np.pi, 'deg', '.5g')}", counts or "no rows"]
        if self.n_angles:
            s = self.summary()
            facts += [f"{label} {s[key] * scale:.5g} {unit}" for label, key, scale, unit in (
                ("Fc max", "Fc_max", 1.0, "N"), ("p0 Hertz max", "p0_hertz_max", 1e-6, "MPa"),
                ("p0 FE max", "p0_fe_max", 1e-6, "MPa"), ("von Mises max", "vm_max", 1e-6, "MPa"))
                if np.isfinite(s[key])]
            facts.append(f"{s['n_families']} families")
        facts.append(f"{len(t)} columns")
        if self.paths:
            facts.append("files: " + " ".join(sorted(self.paths)))
        return compact_repr(self, facts)

    def csv_layout(self) -> tuple[list, list]:
        """The columns of ``sweep.csv``: ``(numeric, text)``, as written by the sweep.

        Returns
        -------
        numeric : list of femcam._columns.Column
            (SI name, CSV name, factor SI -> CSV unit): :data:`COLUMNS` then the extra
            column providers' (from ``provenance["extras"]``; a sweep stored before their CSV
            names were recorded keeps its SI names, factor 1).
        text : list of str
            :data:`TEXT_COLUMNS` then the providers' text columns.
        """
        ex = self.provenance.get("extras", {})
        numeric = list(COLUMNS) + [Column(*c) for c in ex.get("csv_columns", ())]
        known = {c.si for c in numeric}
        text = list(TEXT_COLUMNS)
        for name in ex.get("columns", ()):
            if name in known or name not in self.table:
                continue
            if np.asarray(self.table[name]).dtype.kind in "USO":
                text.append(name)
            else:
                numeric.append(Column(name, name, 1.0))
        return numeric, text

    def to_dataframe(self):
        """The table as a ``pandas.DataFrame`` with the columns of ``sweep.csv``: the same names
        (unit in the name: ``theta_deg``, ``p0_fe_MPa``, ...) and units (:meth:`csv_layout`),
        text columns as ``str`` (the exact text; the CSV replaces ``,``, ``#``, quotes, line
        breaks and writes an empty field as ``-``, see :func:`femcam.io.csv_text`).

        Returns
        -------
        pandas.DataFrame
            One row per cam angle.

        Raises
        ------
        ImportError
            pandas is not installed (femcam does not require it).
        """
        numeric, text = self.csv_layout()
        cols = {c.csv: np.asarray(self.table[c.si], dtype=float) * c.factor for c in numeric}
        cols.update({k: np.asarray(self.table[k]).astype(str) for k in text})
        return dataframe(cols, "SweepResult.to_dataframe")

    @property
    def theta(self) -> np.ndarray:
        """Cam angles (rad), shape (n,)."""
        return self.table["theta"]

    @property
    def status(self) -> np.ndarray:
        """Per-angle status (``ok``, ``liftoff``, ``undercut``, ``failed``), shape (n,)."""
        return self.table["status"]

    @property
    def refused(self) -> tuple[tuple[str, str], ...]:
        """The parts the scene asks for that were refused at run time (an extra column
        provider, :func:`femcam.sweep.worst.refusals`): ``(part, reason)`` each, empty when
        every part answered. A sweep with a refusal is not a complete answer to its scene
        (``femcam sweep`` exits 1)."""
        return tuple((r["part"], r["reason"]) for r in self.provenance.get("extras", {}).get("refused", ()))

    @property
    def n_angles(self) -> int:
        """Number of angles."""
        return int(self.table["theta"].size)

    @property
    def ok(self) -> np.ndarray:
        """Rows with contact and an answer."""
        return self.table["status"] == "ok"

    @property
    def families(self) -> list[dict]:
        """Family records (``provenance["families"]``): ``id, rho_ref, a_ref, n_angles, a_ratio,
        kappa, checks [(theta_deg, a/a_ref, Rr/rho, reuse_error)], reuse_error, build_time,
        check_time, n_rebuilt``; empty for a Hertz sweep."""
        return list(self.provenance.get("families", []))

    @property
    def reuse_error(self) -> float:
        """Largest checked ``|p0(family model)/p0(fresh model) - 1|`` over all families (NaN if
        none was checked)."""
        errs = [f["reuse_error"] for f in self.families]
        return float(max(errs)) if errs else float("nan")

    @property
    def n_failed(self) -> int:
        """Number of angles whose solve failed."""
        return int(np.count_nonzero(self.table["status"] == "failed"))

    def worst_index(self, column: str = "p0_fe") -> int:
        """Row index of the largest ``column`` among ``ok`` rows (:func:`worst_row`).

        Parameters
        ----------
        column : str
            Column name (SI).

        Returns
        -------
        int
        """
        return worst_row(self.table, column)

    def summary(self) -> dict:
        """Peak values over the cycle, for tables and reports.

        Returns
        -------
        dict
            ``Fc_max`` (N), ``phi_max`` (rad), ``p0_hertz_max``, ``p0_fe_max``, ``vm_max``,
            ``tau1_max`` (Pa), ``err_p0_absmax``, ``err_a_absmax`` (relative, all ``ok`` rows),
            ``err_p0_absmax_arc`` (relative, the rows where Hertz is the reference: all but the
            exact-gap ``fe_exact`` rows), ``err_p0_absmax_exact`` (relative, the exact-gap rows at
            a curvature jump, which the arc-gap Hertz cannot see: a departure, not an error),
            ``err_p0_absmax_ring`` (relative, the rows the ring model answered, ``...+ring``,
            against the solid roller's Hertz: the ring's effect, not an FE error; left out of
            the other two), ``n_vs_hertz`` (FE rows compared with Hertz), ``n_exact``
            (exact-gap rows), ``n_coated`` (rows the coated model answered), ``n_ring`` (ring rows),
            ``n_binned`` (FE rows on binned models without a verified family: flat-faced),
            ``n_liftoff``, ``n_failed``, ``n_undercut``, ``n_families`` (counts),
            ``reuse_error_max`` (relative), ``wear_depth_max`` (m per revolution), ``extras``
            (the extra column providers that ran and their summary, :mod:`femcam.sweep.extras`).
        """
        t = self.table
        ok = self.ok

        def peak(name, rows=ok):
            v = np.where(rows, np.abs(t[name]), np.nan)
            return float(np.nanmax(v)) if np.any(np.isfinite(v)) else float("nan")

        model = np.asarray(t["model"]).astype(str) if "model" in t else np.full(ok.shape, "")
        coated = ok & (np.char.find(model, "+coating") >= 0)   # the coated model answered
        ring = ok & np.char.endswith(model, "+ring")   # the ring model answered: Hertz is the solid's
        model = np.array([m.split("+")[0] for m in model], dtype=str)   # fe_arc+coating: fe_arc
        exact = ok & (model == "fe_exact") & ~ring   # exact-gap FE: Hertz (arc gap) is not its reference
        family = np.asarray(t["family"], float) if "family" in t else np.zeros(ok.shape)
        binned = ok & np.isin(model, ("fe_arc", "fe_exact")) & ~(family >= 0)

        return {
            "Fc_max": peak("Fc"),
            "phi_max": peak("phi"),
            "p0_hertz_max": peak("p0_hertz"),
            "p0_fe_max": peak("p0_fe"),
            "vm_max": peak("vm_max"),
            "tau1_max": peak("tau1_max"),
            "err_p0_absmax": peak("err_p0"),
            "err_p0_absmax_arc": peak("err_p0", ok & ~exact & ~ring),
            "err_p0_absmax_exact": peak("err_p0", exact),
            "err_p0_absmax_ring": peak("err_p0", ring),
            "n_vs_hertz": int(np.count_nonzero(ok & ~exact & ~ring & np.isfinite(t["err_p0"]))),
            "n_exact": int(np.count_nonzero(exact)),
            "n_coated": int(np.count_nonzero(coated)),
            "n_ring": int(np.count_nonzero(ring)),
            "n_binned": int(np.count_nonzero(binned)),
            "err_a_absmax": peak("err_a"),
            "n_liftoff": int(np.count_nonzero(t["status"] == "liftoff")),
            "n_failed": self.n_failed,
            "n_undercut": int(np.count_nonzero(t["status"] == "undercut")),
            "n_families": len(self.families),
            "reuse_error_max": self.reuse_error,
            "wear_depth_max": peak("wear_depth"),
            "extras": self.provenance.get("extras", {}),
        }

    @classmethod
    def load(cls, directory) -> SweepResult:
        """Reload a finished sweep from its output directory (``DIR/sweep.npz``).

        The table (SI), provenance (families, options, versions) and, when the sweep wrote its
        plots, the plots' data: ``plot_sweep(SweepResult.load(DIR), DIR)`` re-plots it.

        Parameters
        ----------
        directory : str or Path
            The sweep's ``out``.

        Returns
        -------
        SweepResult
            ``paths`` lists the output files found; ``timings`` is empty.
        """
        d = Path(directory)
        npz = d / "sweep.npz"
        if not npz.is_file():
            raise InputError(f"directory = {d}: no sweep.npz (not a finished sweep's output "
                             "directory; an interrupted one resumes with --resume)")
        profile, table = {}, {}
        with np.load(npz, allow_pickle=False) as z:
            prov = json.loads(str(z["provenance_json"]))
            extra_names = set(prov.get("extras", {}).get("columns", ()))
            for name in z.files:
                if name.startswith(PROFILE_PREFIX):
                    v = z[name]
                    profile[name[len(PROFILE_PREFIX):]] = v.item() if v.ndim == 0 else v
                elif name in NUMERIC:
                    v = z[name]
                    # integer columns are stored with -1 for "undefined" (NaN in the table)
                    table[name] = np.where(v < 0, np.nan, v).astype(float) if v.dtype.kind == "i" \
                        else v.astype(float)
                elif name in TEXT_COLUMNS:
                    table[name] = z[name].astype(str)
                elif name in extra_names:  # extra column providers (femcam.sweep.extras)
                    v = z[name]
                    table[name] = v.astype(str) if v.dtype.kind in "US" else v.astype(float)
            hf = json.loads(str(z["hertz_factors_json"])) if "hertz_factors_json" in z.files else None
        method = prov.get("options", {}).get("method", "fe")
        names = {"csv": "sweep.csv", "npz": "sweep.npz", "pvd": "sweep.pvd",
                 "scene": "scene.toml", "report": "report.md", "report_html": "report.html"}
        paths = {k: str(d / f) for k, f in names.items() if (d / f).exists()}
        return cls(table=table, method=method, provenance=prov, paths=paths,
                   surface_profile=profile or None, hertz_factors=hf)


def plot_data_arrays(result: SweepResult) -> dict:
    """The plots' data of ``result`` as ``sweep.npz`` arrays (read back by
    :meth:`SweepResult.load`): the surface profile under :data:`PROFILE_PREFIX` and the Hertz
    factors as JSON. Empty when the sweep computed no plot data.

    Parameters
    ----------
    result : SweepResult
        A computed or loaded sweep.

    Returns
    -------
    dict[str, ndarray]
        ``sweep.npz`` key -> array (profile arrays as stored in ``result.surface_profile``).
    """
    out = {}
    for k, v in (result.surface_profile or {}).items():
        out[PROFILE_PREFIX + k] = np.asarray(v)
    if result.hertz_factors is not None:
        out["hertz_factors_json"] = np.array(json.dumps(result.hertz_factors, sort_keys=True))
    return out


def _fmt(x: float, scale: float = 1.0, digits: int = 1, spec: str = "f") -> str:
    return "-" if not np.isfinite(x) else f"{x * scale:.{digits}{spec}}"


def families_text(n_families: int, reuse_error_max: float, n_binned: int = 0) -> str:
    """``"1 model family, reuse error <= 0.012 % at the checked angles"``; without verified
    families says so instead of a NaN error, and what the FE rows use instead (flat-faced: models
    binned by half-width and cam radius, :func:`femcam.sweep.realrows.flat_rows`).

    Parameters
    ----------
    n_families : int
        Number of verified model families.
    reuse_error_max : float
        Largest reuse error of the families [-] (a fraction; printed in %).
    n_binned : int, optional
        FE rows answered by binned models without a family (``SweepResult.summary()["n_binned"]``).

    Returns
    -------
    str
        One line of text.
    """
    n = int(n_families)
    if (n == 0 or not np.isfinite(reuse_error_max)) and n_binned:
        return (f"no verified model families: the {n_binned} flat-faced FE rows use models binned by "
                f"contact half-width and cam radius (geometric bins of ratio {FLAT_BIN_RATIO:g}, "
                "each angle solved at its own load and curvature); the reuse error within a bin is "
                "not checked: the FE-vs-Hertz p0 error is the check")
    if n == 0 or not np.isfinite(reuse_error_max):
        return "no verified model families, no reuse error to check"
    return (f"{n} model {'family' if n == 1 else 'families'}, reuse error <= "
            f"{100 * reuse_error_max:.3f} % at the checked angles")


def hertz_check_text(s: dict) -> str:
    """What the FE headline p0 was checked against, for the summary line and ``report.md``.

    ``p0_fe`` is the peak of the solved pressure; Hertz is its reference on the arc-gap rows
    only. Exact-gap rows (a curvature jump) have no Hertz reference: the arc gap cannot see the
    jump; their check is the exact-gap half-space reference of the tests (docs/fe_real_cam.md).

    Parameters
    ----------
    s : dict
        :meth:`SweepResult.summary`.

    Returns
    -------
    str
        E.g. ``"max |p0_fe/p0_hertz - 1| 0.136 % over 344 arc-gap rows; 16 exact-gap rows: no
        Hertz reference (curvature jump)"``.
    """
    parts = []
    if s.get("n_vs_hertz", 0):
        parts.append(f"max |p0_fe/p0_hertz - 1| {100 * s['err_p0_absmax_arc']:.3f} % over "
                     f"{s['n_vs_hertz']} arc-gap rows")
    if s.get("n_exact", 0):
        parts.append(f"{s['n_exact']} exact-gap rows: no Hertz reference (the cam's curvature "
                     f"changes across the contact, at a join or on a fast-changing flank: the "
                     f"parabolic gap of Hertz does not hold; they "
                     f"depart from Hertz by up to {100 * s['err_p0_absmax_exact']:.3f} %)")
    if s.get("n_coated", 0):
        parts.append(f"{s['n_coated']} rows answered by the coated model: Hertz (homogeneous "
                     "substrates) is the reference there, the difference is the coating's effect "
                     "plus the FE error")
    if s.get("n_ring", 0):
        parts.append(f"{s['n_ring']} ring rows: the ring model against the solid roller's Hertz, "
                     f"up to {100 * s['err_p0_absmax_ring']:.3f} % (the ring's effect and the ring "
                     "model's discretisation)")
    return "; ".join(parts) or "no FE row compared with Hertz"


def report_markdown(result: SweepResult) -> str:
    """The sweep's summary as Markdown (``DIR/report.md``): each headline quantity's worst value,
    unit, cam angle and depth (:func:`femcam.sweep.worst.peak_rows`), the plots as ``plots/*.png``
    images (``DIR/report.html`` embeds them: :func:`femcam.sweep.report.report_html`).

    Parameters
    ----------
    result : SweepResult

    Returns
    -------
    str
    """
    s, p = result.summary(), result.provenance
    o = p.get("options", {})
    lines = ["# femcam sweep report", "",
             f"- scene: `{p.get('scene', '(in memory)')}` (sha256 `{str(p.get('scene_sha256', ''))[:16]}`)",
             f"- command: `{p.get('command', '')}`",
             f"- method: {result.method}; {result.n_angles} angles; "
             f"{result.n_chunks_resumed} chunks resumed, {result.n_chunks_computed} computed",
             f"- lift-off {s['n_liftoff']}, undercut {s['n_undercut']}, failed {s['n_failed']} "
             "angle(s)"]
    if result.method == "fe":
        lines.append(f"- {families_text(s['n_families'], s['reuse_error_max'], s['n_binned'])} "
                     "(reuse tolerance "
                     f"{100 * float(o.get('tolerance', float('nan'))):g} %)")
    if o.get("models"):   # the model that answered, rows per model (report.html explains each)
        lines.append("- models (rows): " + ", ".join(f"`{m}` {n}" for m, n in o["models"].items()
                                                     if n))
    lines += ["", "| quantity | worst value | unit | at cam angle (deg) | depth (um) | note |",
              "|---|---|---|---|---|---|"]
    lines += [f"| {r['what']} | {r['value']:.4g} | {r['unit']} | {angle_text(r['theta_deg'])} | "
              f"{_fmt(r['depth_um'], 1.0, 4, 'g')} | {r['note']} |"
              for r in peak_rows(result.table)]   # the providers' worst values: _extras_lines
    # the text holds |...|: escaped, or Markdown splits the row at each bar
    lines += [f"| p0 FE vs Hertz | {hertz_check_text(s).replace('|', chr(92) + '|')} | | | | |"]
    lines += [f"- {t}" for t in p.get("extras", {}).get("headline", ())]   # what the headline omits
    lines += _estimate_lines(result)
    lines += _extras_lines(p.get("extras", {}))
    plots = {k: f"plots/{Path(v).name}" for k, v in result.paths.items() if k.startswith("plot_")}
    if plots:
        lines += ["", "## Plots", ""]
        lines += [f"![{plot_caption(Path(v).name)}]({v})\n\n*{plot_caption(Path(v).name)}* (`{v}`)\n"
                  for v in plots.values()]
    lines += ["", "Files: " + ", ".join(f"`{plots.get(k, Path(v).name)}`" for k, v in result.paths.items())
              + (", `report.html` (this report with the plots embedded: one file to send)"
                 if result.paths else ""), ""]
    return "\n".join(lines)


def _estimate_lines(result: SweepResult) -> list[str]:
    """``report.md``'s error estimates: per headline quantity at its worst row and the largest
    (:func:`femcam.sweep.worst.estimate_rows`), and the rtol reached."""
    rows = estimate_rows(result.table, result.provenance.get("options", {}))
    if not rows:
        return []
    lines = ["", "## Error estimates", "", "| quantity | estimate at its worst row (%) | largest "
             "estimate (%) | FE rows | requested (rtol) |", "|---|---|---|---|---|"]
    lines += [f"| {r['what']} | {r['at_worst_pct']:.3g} | {r['max_pct']:.3g} | {r['n_rows']} | "
              + ("" if r["met"] is None else
                 f"{r['rtol_pct']:g} %: {'met by every row' if r['met'] else 'NOT met'}") + " |"
              for r in rows]
    return lines + ["", estimate_text(result) + "."]


def _extras_lines(ex: dict) -> list[str]:
    """Report lines of the extra column providers (:mod:`femcam.sweep.extras`): which ran, the
    assessment's worst angle per criterion, refusals."""
    if not ex.get("providers"):
        return []
    lines = ["", f"Extra columns from: {', '.join(ex['providers'])}."]
    lines += [""] + [f"- {t}" for t in ex.get("worst", ())] if ex.get("worst") else []
    if ex.get("assess"):
        lines += ["", "| criterion (assessment) | worst value | at cam angle (deg) |", "|---|---|---|"]
        lines += [f"| {c} | {w['value']:.4g} | {w['theta_deg']:.1f} |" for c, w in ex["assess"].items()]
    refused = ex.get("refused")
    if refused:
        lines += ["", f"**Not a complete answer: {len(refused)} part(s) the scene asks for were refused** "
                  "(`femcam sweep` exits 1):", ""] + [f"- refused: {r['line']}" for r in refused]
    else:   # a sweep stored before the refusal records: the raw reasons
        lines += [f"- refused: {e}" for e in ex.get("errors", ())]
    lines += [f"- {t}" for t in ex.get("notes", ())]   # e.g. the cam disk check (femcam.sweep.extras)
    return lines
