"""The study table: its columns (SI name, CSV name with unit, factor), the Pareto set, and
:class:`StudyResult`.

One row per variant, never dropped: the varied keys (CSV name = the scene key, in its unit),
the worst-angle Hertz results (:data:`femcam.study.evaluate.METRICS`), one margin per
constraint (``margin_<name>``, positive = satisfied; :mod:`femcam.study.constraints`),
``feasible``, ``binding`` (the smallest margin), ``pareto`` (non-dominated in peak p0 and cam
size among the feasible variants), the FE columns of the candidates (``p0_fe_MPa``,
``theta_fe_deg``; NaN where the FE did not run), and text: ``model`` (``hertz`` or
``hertz+fe``), ``status`` (``ok``, ``failed``, ``refused``), ``reason``, ``hash`` and
``duplicate_of`` (the first variant with the same content hash, or -1).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .. import _validate
from .._columns import Column
from .._repr import compact_repr, dataframe
from .constraints import NAMES

_DEG = 180.0 / math.pi

#: numeric result columns (:class:`femcam._columns.Column`: SI name, CSV name, factor SI -> CSV)
RESULT_COLUMNS = (
    Column("theta", "theta_p0_deg", _DEG),
    Column("p0_max", "p0_max_MPa", 1e-6),
    Column("Fc_at_p0", "Fc_at_p0_N", 1.0),
    Column("a_at_p0", "a_at_p0_um", 1e6),
    Column("R_at_p0", "R_at_p0_mm", 1e3),
    Column("von_mises_max", "von_mises_max_MPa", 1e-6),
    Column("tau1_max", "tau1_max_MPa", 1e-6),
    Column("phi_max", "phi_max_deg", _DEG),
    Column("rho_min", "rho_min_mm", 1e3),
    Column("undercut", "undercut", 1.0),
    Column("Fc_min", "Fc_min_N", 1.0),
    Column("Fc_max", "Fc_max_N", 1.0),
    Column("cam_radius_max", "cam_radius_max_mm", 1e3),
    Column("sf_min", "sf_min", 1.0),
    Column("lambda_min", "lambda_min", 1.0),
    Column("rpm", "rpm", 1.0),
    Column("rpm_jump", "rpm_jump", 1.0),
    Column("wear_depth_per_rev", "wear_depth_per_rev_nm", 1e9),
) + tuple(Column(f"margin_{k}", f"margin_{k}", 1.0) for k in NAMES) + (
    Column("feasible", "feasible", 1.0),
    Column("pareto", "pareto", 1.0),
    Column("p0_fe", "p0_fe_MPa", 1e-6),
    Column("theta_fe", "theta_fe_deg", _DEG),
    Column("duplicate_of", "duplicate_of", 1.0),
)
#: text columns
TEXT_COLUMNS = ("model", "status", "binding", "reason", "hash")
#: numeric columns stored as integers in the NPZ
INTEGER_COLUMNS = ("variant", "undercut", "feasible", "pareto", "duplicate_of")


def pareto_mask(f1, f2, candidates) -> np.ndarray:
    """Non-dominated rows when minimising both ``f1`` and ``f2`` among ``candidates``.

    A row is dominated when another candidate is no worse in both and better in one.

    Parameters
    ----------
    f1, f2 : array_like, shape (n,)
        The two objectives (any units; NaN rows are never non-dominated).
    candidates : array_like of bool, shape (n,)
        Rows that take part (the feasible ones).

    Returns
    -------
    ndarray of bool, shape (n,)
        The Pareto set.

    >>> pareto_mask([3, 2, 1, 2], [1, 2, 3, 3], [True] * 4).tolist()
    [True, True, True, False]
    """
    f1 = _validate.data_array("f1", f1, inf_ok=True)
    f2 = _validate.data_array("f2", f2, inf_ok=True)
    if f1.shape != f2.shape or np.shape(candidates) != f1.shape:
        raise _validate.fail("f2", f"shape {f2.shape}", "", f"f1, f2 and candidates must have one shape "
                             f"(f1 {f1.shape}, candidates {np.shape(candidates)})")
    ok = np.asarray(candidates, bool) & np.isfinite(f1) & np.isfinite(f2)
    idx = np.flatnonzero(ok)
    out = np.zeros(f1.shape, bool)
    order = idx[np.lexsort((f2[idx], f1[idx]))]  # by f1, ties by f2
    best = np.inf
    for i in order:  # sweep in f1: a row is kept when it improves the best f2 seen so far
        if f2[i] < best:
            out[i], best = True, f2[i]
    return out


@dataclass(frozen=True, kw_only=True)
class StudyResult:
    """A design study: the table and how it was obtained (pickles: arrays and text only).

    Parameters
    ----------
    table : dict of str -> ndarray, shape (n,)
        One row per variant (module docstring), SI units under the internal names; the varied
        keys under their scene keys, in the scene file's units.
    columns : tuple of femcam._columns.Column
        The numeric columns in CSV order (SI name, CSV name, factor).
    text_columns : tuple of str
        The text columns.
    keys : tuple of str
        The varied scene keys.
    n_variants, n_unique, n_computed, n_reused : int
        Rows, distinct content hashes, evaluations run by this call, records reused from the
        store (resume).
    n_feasible : int
        Feasible variants.
    message : str
        Why no variant is feasible ("" when some is), or what else the user should know.
    fe : dict
        FE candidates: ``{"top": K, "angles_deg": [...], "ran": m, "failed": f}``.
    provenance : dict
        The provenance record of the written files.
    paths : dict
        Written files (``csv``, ``npz``, plots) by kind.
    """

    table: dict
    columns: tuple
    text_columns: tuple
    keys: tuple
    n_variants: int
    n_unique: int
    n_computed: int
    n_reused: int
    n_feasible: int
    message: str = ""
    fe: dict = field(default_factory=dict)
    provenance: dict = field(default_factory=dict)
    paths: dict = field(default_factory=dict)

    def __repr__(self) -> str:
        """Counts, the varied keys and the lowest feasible p0 (a compact line)."""
        facts = [f"{self.n_variants} variants ({self.n_unique} distinct)", f"{self.n_feasible} feasible",
                 "keys: " + " ".join(self.keys)]
        b = self.best()
        if b is not None:
            facts.append(f"lowest feasible p0 {self.table['p0_max'][b] * 1e-6:.5g} MPa (variant {b})")
        if self.paths:
            facts.append("files: " + " ".join(sorted(self.paths)))
        return compact_repr(self, facts)

    def to_dataframe(self):
        """The table as a ``pandas.DataFrame`` with the columns of ``study.csv`` (names with
        units, values in those units: ``columns`` then ``text_columns``; text as ``str``).

        Returns
        -------
        pandas.DataFrame
            One row per variant.

        Raises
        ------
        ImportError
            pandas is not installed (femcam does not require it).
        """
        cols = {c.csv: np.asarray(self.table[c.si], dtype=float) * c.factor for c in self.columns}
        cols.update({k: np.asarray(self.table[k]).astype(str) for k in self.text_columns})
        return dataframe(cols, "StudyResult.to_dataframe")

    def best(self, objective: str = "p0_max") -> int | None:
        """Row of the feasible variant with the smallest ``objective``.

        Parameters
        ----------
        objective : str
            An SI result column (``p0_max``, ``von_mises_max``, ``tau1_max``, ``cam_radius_max``).

        Returns
        -------
        int or None
            The row index, or None when no variant is feasible.
        """
        v = np.where(self.table["feasible"] > 0, np.asarray(self.table[objective], float), np.nan)
        return None if not np.any(np.isfinite(v)) else int(np.nanargmin(v))

    def summary(self) -> str:
        """A few lines for the terminal: counts, the best feasible variant, the message.

        Returns
        -------
        str
            Text.
        """
        lines = [f"study: {self.n_variants} variants ({self.n_unique} distinct; {self.n_computed} "
                 f"computed, {self.n_reused} reused), {self.n_feasible} feasible, "
                 f"{int(np.sum(self.table['pareto']))} on the Pareto front (p0 vs cam size)"]
        b = self.best()
        if b is not None:
            vals = ", ".join(f"{k}={self.table[k][b]}" for k in self.keys)
            lines.append(f"lowest feasible p0: variant {b} ({vals}): p0 = "
                         f"{self.table['p0_max'][b] * 1e-6:.1f} MPa, max phi = "
                         f"{math.degrees(self.table['phi_max'][b]):.2f} deg, cam radius "
                         f"{self.table['cam_radius_max'][b] * 1e3:.2f} mm")
        if self.message:
            lines.append(self.message)
        bad = int(np.sum(self.table["status"] != "ok"))
        if bad:
            lines.append(f"{bad} variants failed or were refused (status, reason columns)")
        return "\n".join(lines)
