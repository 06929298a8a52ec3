"""The files of a study, all through :mod:`femcam.io` (atomic, one provenance layout):
``study.csv`` (CSV units in the column names), ``study.npz`` (SI, the base scene's text) and,
when asked, ``pareto.png`` and ``constraint_map.png`` (:mod:`femcam.viz.study`).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .._columns import Column
from ..io import write_csv, write_npz
from ..viz.study import plot_constraint_map, plot_pareto
from .result import INTEGER_COLUMNS, RESULT_COLUMNS, TEXT_COLUMNS


def columns(spec, combos: list, table: dict) -> tuple:
    """The table's numeric columns (SI name, CSV name, factor) and text columns, in CSV order.

    Parameters
    ----------
    spec : StudySpec
        The varied keys (first columns: ``variant`` then each key, in its scene-file unit).
    combos : list of dict
        The variants' values.
    table : dict
        The study table (a key whose column is text goes to the text columns).

    Returns
    -------
    numeric : tuple of femcam._columns.Column
    text : tuple of str
    """
    num = [Column("variant", "variant", 1.0)]
    text = []
    for k in spec.keys:
        if np.asarray(table[k]).dtype.kind == "f":
            num.append(Column(k, k, 1.0))
        else:
            text.append(k)
    return tuple(num) + RESULT_COLUMNS, tuple(text) + TEXT_COLUMNS


def _numeric_keys(res) -> list:
    return [k for k in res.keys if np.asarray(res.table[k]).dtype.kind == "f"]


def write_outputs(res, out, *, scene_toml: str = "", plots: bool = False) -> dict:
    """Write ``study.csv``, ``study.npz`` and the plots of a study into ``out``.

    Parameters
    ----------
    res : StudyResult
        The study.
    out : str or Path
        Output directory.
    scene_toml : str
        The base scene file's text (stored in the NPZ).
    plots : bool
        Write ``pareto.png`` and, with two numeric varied keys, ``constraint_map.png``.

    Returns
    -------
    dict
        Written paths by kind (``csv``, ``npz``, ``pareto``, ``constraint_map``).
    """
    out = Path(out)
    paths = {"csv": str(write_csv(out / "study.csv", res.table, res.provenance, columns=res.columns,
                                  text_columns=res.text_columns,
                                  title="femcam study: one row per variant")),
             "npz": str(write_npz(out / "study.npz", res.table, res.provenance,
                                  numeric=[c.si for c in res.columns], text_columns=res.text_columns,
                                  integer_columns=INTEGER_COLUMNS, scene_toml=scene_toml))}
    if plots:
        t = res.table
        paths["pareto"] = plot_pareto(t["cam_radius_max"], t["p0_max"], t["feasible"] > 0, t["pareto"] > 0,
                                      out / "pareto.png", fe=t["p0_fe"])
        num = _numeric_keys(res)
        if len(num) >= 2:
            paths["constraint_map"] = plot_constraint_map(
                t[num[0]], t[num[1]], t["binding"], t["feasible"] > 0, out / "constraint_map.png",
                xlabel=num[0], ylabel=num[1])
    return paths
