"""The optimum against standard laws on the same scene: one row per law, worst-angle values and
constraint margins on the fine grid (:data:`femcam.optimise.solve.DENSE` samples per rise/fall).
"""

from __future__ import annotations

import math

import numpy as np

from .. import _validate
from .._columns import Column
from ..errors import InputError
from ..kinematics import LAW_NAMES
from .chain import angle_grid, constraint_value, evaluate, residual_vibration
from .solve import DENSE

__all__ = ["STANDARD_LAWS", "COMPARE_COLUMNS", "compare_laws"]

#: seed 002's Bezier degrees and the classical laws with zero velocity at the dwells
STANDARD_LAWS = ("bezier5", "bezier7", "bezier9", "cycloidal", "poly345", "poly4567", "modified_sine",
                 "modified_trapezoid")

#: the comparison table's columns (:class:`femcam._columns.Column`; write with femcam.io.write_csv)
COMPARE_COLUMNS = (Column("p0_max", "p0_max_MPa", 1e-6), Column("phi_max", "phi_max_deg", 180.0 / math.pi),
                   Column("rho_min", "rho_min_mm", 1e3), Column("a_max", "a_max_m_per_s2", 1.0),
                   Column("margin_phi", "margin_phi_deg", 180.0 / math.pi),
                   Column("margin_rho", "margin_rho_mm", 1e3),
                   Column("margin_liftoff", "margin_liftoff_Fc_over_Fpl", 1.0),
                   Column("wear_max", "wear_max_m_per_rev", 1.0), Column("lambda_min", "lambda_min", 1.0),
                   Column("residual_vibration", "residual_vibration_um", 1e6))


def compare_laws(scene, *, optimum=None, laws=STANDARD_LAWS, constraints=None) -> dict:
    """Worst-angle p0, phi, rho, acceleration and constraint margins of laws on one scene.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene (roller follower); every rise/fall uses each law in turn.
    optimum : femcam.optimise.OptimiseResult, optional
        Adds the row ``"optimum"`` (its program and follower on ``scene``).
    laws : sequence of str
        Law names (:data:`femcam.kinematics.LAW_NAMES`).
    constraints : dict, optional
        ``{"phi_max": rad, "rho_min": m, "liftoff_omega": rad/s}``; a missing one gives NaN
        margins.

    Returns
    -------
    dict
        ``"law"`` (str array) and, per row, ``p0_max`` (Pa), ``phi_max`` (rad), ``rho_min``
        (m, smallest convex cam radius), ``a_max`` (m/s^2), ``margin_phi`` (limit - max
        ``|phi|``, rad), ``margin_rho`` (min ``rho`` - limit, m), ``margin_liftoff`` (min
        ``Fc/Fpl`` at the lift-off speed, -); >= 0 means the limit holds; ``wear_max``: the
        largest Archard cam wear depth per revolution at the contact (m; NaN when the scene's
        slip model is not the pointwise slide-to-roll one); ``lambda_min``: the assessment's
        smallest film ratio (-; NaN without [lubricant]); ``residual_vibration``: the follower's
        vibration in the dwell after the rise (m, :func:`~femcam.optimise.chain.residual_vibration`;
        NaN for a rigid train).
    """
    if not (hasattr(scene, "program") and hasattr(scene, "with_law")):
        raise _validate.fail("scene", scene, "", "must be a femcam.scene.Scene")
    lim = dict(constraints or {})
    names = [_validate.choice("laws", n, LAW_NAMES) for n in laws]
    variants = [(n, scene.with_law(n)) for n in names]
    if optimum is not None:
        variants.append(("optimum", optimum.apply(scene)))
    rows = {k: [] for k in ("law", "p0_max", "phi_max", "rho_min", "a_max", "margin_phi", "margin_rho",
                            "margin_liftoff", "wear_max", "lambda_min", "residual_vibration")}
    lubricated = scene.tribology.lubricant is not None
    for name, sc in variants:
        theta, _ = angle_grid(sc.program, DENSE)
        try:
            wear = float(np.max(evaluate(sc, theta, "wear", phi_max=None, rho_min=None,
                                         liftoff_omega=None)["objective"]))
        except InputError:  # the inertia-limited roller: no pointwise wear
            wear = math.nan
        rows["wear_max"].append(wear)
        rows["residual_vibration"].append(float(residual_vibration(sc)[0][0]) if sc.train is not None
                                          else math.nan)
        rows["lambda_min"].append(float(np.min(evaluate(sc, theta, "lambda", phi_max=None, rho_min=None,
                                                        liftoff_omega=None)["lam"])) if lubricated
                                  else math.nan)
        r = evaluate(sc, theta, "p0", phi_max=lim.get("phi_max"), rho_min=lim.get("rho_min"),
                     liftoff_omega=lim.get("liftoff_omega"))
        phi = constraint_value("phi_max", r, 0.0)
        rho = constraint_value("rho_min", r, 0.0)
        rows["law"].append(name)
        rows["p0_max"].append(float(np.max(r["p0"])))
        rows["phi_max"].append(phi)
        rows["rho_min"].append(rho)
        rows["a_max"].append(float(np.max(np.abs(r["a"]))))
        rows["margin_phi"].append(lim["phi_max"] - phi if "phi_max" in lim else math.nan)
        rows["margin_rho"].append(rho - lim["rho_min"] if "rho_min" in lim else math.nan)
        lift = float(np.min(r["liftoff_omega"])) if "liftoff_omega" in lim else math.nan
        rows["margin_liftoff"].append(lift)
    return {k: np.array(v) for k, v in rows.items()}
