"""The worst angle's surface stresses, computed during the sweep so that the plot only draws.

At the angle of highest p0: Hertz surface ``sx, sz, txz`` along ``x`` (seed 002 eqs. 5-7) with
the row's traction and, for an FE sweep, the FE cam-surface stresses of that row solved again
with the same inputs as the sweep: the family's model (references from the family records; in
the process that ran the sweep it is the cached model and its cached solution), or the angle's
own model for a ``rebuilt`` row; the row's gap (``fe_exact``: the exact gap, ``fe_arc``: the
osculating arc) and the row's traction from the mechanism (Q and sliding direction,
:func:`femcam.sweep.realcam.scene_traction`).

The Hertz curve carries the row's traction (Johnson 1985 §7.1): full sliding ``q = mu p``;
Carter/Cattaneo partial slip ``q = mu p - mu p0 (c/a) sqrt(1 - x^2/c^2)`` on the stick zone
``|x| < c = a sqrt(1 - |Q|/(mu F))``, whose surface stresses are those of full sliding minus the
full-sliding traction field of a Hertz contact of half-width ``c`` and peak ``p0 c / a``
(the traction field is linear in ``mu``); frictionless when ``|Q| <= 1e-3 mu F``.
"""

from __future__ import annotations

import math

import numpy as np

from ..hertz.conformity import roller_does_not_fit
from ..hertz.surface import surface_stress
from .cache import ModelCache, default_cache
from .options import ContactParams, ResolvedOptions
from .pipeline import line_contact
from .plan import hertz_half_width
from .realcam import scene_traction, traction_args
from .realrows import exact_solve
from .table import worst_row

FRICTIONLESS_Q = 1e-3  # |Q| / (mu F) below which the Hertz curve is drawn frictionless


def worst_surface_profile(table: dict, method: str, cp: ContactParams, families: list[dict],
                          options: ResolvedOptions, cache: ModelCache | None = None,
                          scene=None) -> dict:
    """Surface stresses along x at the angle of highest p0 (the row's answer: FE p0, or Hertz
    p0 for the rows Hertz answered): Hertz lines (+ FE points for an FE row).

    Parameters
    ----------
    table : dict[str, ndarray]
        The sweep table (:mod:`femcam.sweep.table`).
    method : str
        ``"fe"`` or ``"hertz"``.
    cp : ContactParams
    families : list of dict
        Family records (``id``, ``rho_ref``, ``a_ref``), empty for a Hertz sweep.
    options : ResolvedOptions
        ``a_over_h`` and ``tolerance`` of the sweep's models.
    cache : ModelCache, optional
        Where the sweep's models are (default: this process's).
    scene : femcam.scene.Scene, optional
        The sweep's scene: the FE row is solved again with its gap (exact or arc) and its
        traction from the mechanism, as the sweep did. Without it: the arc gap in full sliding
        in the scene's direction (``cp.sliding``).

    Returns
    -------
    dict
        ``theta_deg`` (deg), ``Fc`` (N), ``rho`` (m), ``mu``, ``a_hertz`` (m), ``traction``
        (text: ``"Q/(mu Fc) = ..., <slip state>"``); where Hertz applies ``x_hertz`` (m),
        ``sx_hertz, sz_hertz, txz_hertz`` (Pa), arrays of shape (1001,) and ``hertz_label``;
        for an FE row ``x_fe`` (m), ``sx_fe, sz_fe, txz_fe`` (Pa), ``p0_fe`` (Pa) and
        ``fe_model`` (``"family <id>"`` or ``"own"``).
    """
    cache = default_cache() if cache is None else cache
    # the row's answer: FE p0 where the FE answered, else Hertz (method auto's Hertz rows)
    p0 = np.where(np.isfinite(table["p0_fe"]), table["p0_fe"], table["p0_hertz"])
    i = worst_row({**table, "p0_answer": p0}, "p0_answer" if method == "fe" else "p0_hertz")
    F, rho, theta = float(table["Fc"][i]), float(table["rho"][i]), float(table["theta"][i])
    out = {"theta_deg": float(np.degrees(theta)), "Fc": F, "rho": rho, "mu": cp.mu,
           "traction": _traction_text(table, i, cp)}
    a_est = float(hertz_half_width(np.array([F]), np.array([rho]), cp)[0])
    out["a_hertz"] = a_est
    if not bool(roller_does_not_fit(rho, cp.Rr)):
        out.update(_hertz_curve(table, i, cp, F, rho))
    # +coating: the coated model; +ring: the solid roller's fine field (global-local scheme)
    fe_row = str(table["model"][i]).split("+")[0] in ("fe_arc", "fe_exact", "")
    if method == "fe" and table["status"][i] == "ok" and fe_row:
        r, out["fe_model"] = _fe_solve(table, i, cp, families, options, cache, scene)
        out.update(x_fe=np.asarray(r.x_surface, float), sx_fe=np.asarray(r.sx, float),
                   sz_fe=np.asarray(r.sz, float), txz_fe=np.asarray(r.txz, float),
                   p0_fe=float(r.p0_nodal))
    return out


def _row_q(table, i, cp) -> tuple[float, str]:
    """``(Q / (mu F), slip state)`` of row ``i``; full sliding in ``cp.sliding`` when the row
    has none (method hertz)."""
    f = float(table["Q_over_muFc"][i]) if "Q_over_muFc" in table else math.nan
    state = str(table["slip_state"][i]) if "slip_state" in table else ""
    if not math.isfinite(f):
        return float(cp.sliding), "sliding"
    return f, state or "sliding"


def _traction_text(table, i, cp) -> str:
    f, state = _row_q(table, i, cp)
    return f"Q/(mu Fc) = {f:.2g}, {state}"


def _hertz_curve(table, i, cp, F, rho) -> dict:
    """Hertz surface stresses with the row's traction (module docstring)."""
    hc = line_contact(cp, F, rho)
    a, p0 = float(hc.a), float(hc.p0)
    x = np.linspace(-2.5, 2.5, 1001) * a
    f, _ = _row_q(table, i, cp)
    if cp.mu == 0 or abs(f) <= FRICTIONLESS_Q:
        sx, sz, txz = surface_stress(x, a, p0, 0.0)
        label = f"Hertz, frictionless (|Q| <= {FRICTIONLESS_Q:g} mu Fc)"
    elif abs(f) >= 1.0:
        sx, sz, txz = surface_stress(x, a, p0, math.copysign(cp.mu, f))
        label = "Hertz, full sliding"
    else:
        mu_s = math.copysign(cp.mu, f)
        sx, sz, txz = (np.asarray(s, float) for s in surface_stress(x, a, p0, mu_s))
        c = a * math.sqrt(1.0 - abs(f))
        t = [np.asarray(s1, float) - np.asarray(s0, float) for s1, s0 in
             zip(surface_stress(x, c, p0 * c / a, mu_s), surface_stress(x, c, p0 * c / a, 0.0),
                 strict=True)]
        sx, txz = sx - t[0], txz - t[2]
        label = "Hertz + Cattaneo partial slip"
    return {"x_hertz": x, "sx_hertz": np.asarray(sx, float), "sz_hertz": np.asarray(sz, float),
            "txz_hertz": np.asarray(txz, float), "a_hertz": a, "hertz_label": label}


def _fe_solve(table, i, cp, families, options, cache, scene):
    """Row ``i`` solved again as the sweep solved it: ``(ContactResult, fe_model)``."""
    F, rho, theta = float(table["Fc"][i]), float(table["rho"][i]), float(table["theta"][i])
    refs = {int(f["id"]): (float(f["rho_ref"]), float(f["a_ref"])) for f in families}
    fid = int(table["family"][i]) if np.isfinite(table["family"][i]) else -1
    rebuilt = "rebuilt" in str(table["flags"][i]).split(";")
    own = {int(f["id"]): f.get("a_over_h") for f in families}   # rtol: each family's own a/h
    options = options.for_family(own.get(fid))
    if rebuilt or fid not in refs:
        a_est = float(hertz_half_width(np.array([F]), np.array([rho]), cp)[0])
        model, name = cache.model_for(cp, rho, a_est, options), "own"
    else:
        model, name = cache.model_for(cp, *refs[fid], options), f"family {fid}"
    if scene is None:
        return cache.solve(model, F, rho, cp.mu, cp.sliding, check=False), name
    sl, Q, roll = traction_args(scene_traction(scene, np.array([theta])), 0, cp.sliding)
    if str(table["model"][i]).split("+")[0] == "fe_exact":
        jump = bool(table["curvature_jump"][i] == 1)
        res = exact_solve(scene, cp, model, theta, F, Q=Q, jump=jump,
                          tol_pct=100.0 * options.tolerance)
        if res is not None:
            return res.result, name
    return cache.solve(model, F, rho, cp.mu, sl, check=False, Q=Q, rolling=roll), name
