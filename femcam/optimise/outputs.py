"""Edges of ``femcam optimise``: ``--vary`` specs with units in the name, and the output files
(``optimum.json``, ``starts.csv``, ``compare.csv``) written through :mod:`femcam.io`.
"""

from __future__ import annotations

import json
import math

import numpy as np

from .. import _validate
from ..errors import InputError
from ..io import atomic_write_text, write_csv
from .compare import COMPARE_COLUMNS
from .design import Variable

__all__ = ["EDGE_UNITS", "parse_vary", "result_dict", "write_outputs"]

#: ``--vary`` names with their edge unit and the factor to SI
EDGE_UNITS = {"base_radius_mm": ("base_radius", 1e-3), "roller_radius_mm": ("roller_radius", 1e-3),
              "rise_angle_deg": ("rise_angle", math.pi / 180.0)}


def parse_vary(spec: str, free: tuple = ()) -> list:
    """One ``--vary NAME=LO:HI`` spec as :class:`~femcam.optimise.Variable` objects (SI).

    ``NAME`` is ``base_radius_mm``, ``roller_radius_mm``, ``rise_angle_deg``,
    ``control_point_<i>`` or ``control_points`` (every free ordinate of ``free``).

    Parameters
    ----------
    spec : str
        The flag value.
    free : tuple of int
        Free Bezier ordinates (:attr:`femcam.optimise.BezierRise.free`).

    Returns
    -------
    list of Variable

    Raises
    ------
    InputError
        A malformed spec, an unknown name (with the accepted ones) or bad bounds.

    Examples
    --------
    >>> parse_vary("base_radius_mm=5:20")[0].upper
    0.02
    """
    name, sep, rng = str(spec).partition("=")
    lo_s, sep2, hi_s = rng.partition(":")
    if not sep or not sep2:
        raise InputError(f"--vary = {spec!r}: must be NAME=LO:HI (e.g. base_radius_mm=5:20)")
    name = name.strip()
    unit = name.rsplit("_", 1)[1] if name in EDGE_UNITS else ""
    lo = _validate.number(f"--vary {name} LO", lo_s, unit)
    hi = _validate.number(f"--vary {name} HI", hi_s, unit)
    if not lo < hi:
        raise InputError(f"--vary {name} = {lo:g}:{hi:g}{' ' + unit if unit else ''}: empty or inverted "
                         "range (must have LO < HI)")
    if name in EDGE_UNITS:
        si, f = EDGE_UNITS[name]
        return [Variable(name=si, lower=lo * f, upper=hi * f)]
    if name == "control_points":
        return [Variable(name=f"control_point_{i}", lower=lo, upper=hi) for i in free]
    if name.startswith("control_point_"):
        return [Variable(name=name, lower=lo, upper=hi)]
    raise InputError(f"--vary {name!r}: unknown; use one of {sorted(EDGE_UNITS)}, control_point_<i> or "
                     "control_points")


def _json(v):
    if isinstance(v, dict):
        return {k: _json(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [_json(x) for x in v]
    if isinstance(v, (np.floating, float)):
        return float(v) if math.isfinite(v) else None
    if isinstance(v, np.integer):
        return int(v)
    return v


def result_dict(res) -> dict:
    """The JSON-able summary of an :class:`~femcam.optimise.OptimiseResult` (SI, names say so).

    Parameters
    ----------
    res : femcam.optimise.OptimiseResult

    Returns
    -------
    dict
    """
    fe = None if res.fe is None else {"theta_rad": res.fe.theta, "p0_hertz_Pa": res.fe.p0_hertz,
                                      "p0_fe_Pa": res.fe.p0_fe, "rel_diff": res.fe.rel_diff,
                                      "status": res.fe.status, "message": res.fe.message}
    return _json({"objective": res.objective, "unit": res.unit, "value": res.value,
                  "start_value": res.start_value,
                  "design_SI": res.design(), "control_points": res.control_points,
                  "constraints_SI": res.constraints, "theta_worst_rad": res.theta_worst,
                  "optimiser": res.optimiser, "iterations": res.iterations, "nfev": res.nfev,
                  "converged": res.converged, "message": res.message, "spread": res.spread,
                  "exchange_rounds": res.exchange_rounds, "grid_gap": res.grid_gap, "fe": fe,
                  "starts": [{"x0_SI": s.x0, "x_SI": s.x, "value": s.value, "feasible": s.feasible,
                              "converged": s.converged, "iterations": s.iterations, "message": s.message}
                             for s in res.starts]})


def write_outputs(out, res, table: dict, prov: dict) -> list:
    """Write ``optimum.json`` and ``compare.csv`` (the :func:`~femcam.optimise.compare_laws` table).

    Parameters
    ----------
    out : pathlib.Path
        Existing output directory.
    res : femcam.optimise.OptimiseResult
    table : dict
        :func:`femcam.optimise.compare_laws` output.
    prov : dict
        Provenance (:func:`femcam.io.provenance`).

    Returns
    -------
    list of pathlib.Path
        The files written.
    """
    j = out / "optimum.json"
    atomic_write_text(j, json.dumps({"provenance": _json(prov), **result_dict(res)}, indent=2) + "\n")
    rows = {**table, "theta": np.zeros(len(table["law"]))}  # io.write_csv counts the rows by "theta"
    c = write_csv(out / "compare.csv", rows, prov, columns=COMPARE_COLUMNS, text_columns=("law",),
                  title="femcam optimise: the motion laws compared, one row per law")
    return [j, c]
