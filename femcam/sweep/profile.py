"""The worst angle's surface stresses, computed during the sweep so that the plot only draws.

At the angle of highest p0: Hertz surface ``sx, sz, txz`` along ``x`` (seed 002 eqs. 5-7) and,
for an FE sweep, the FE cam-surface stresses from the model the sweep used for that angle: its
family's model (references from the family records; in the process that ran the sweep it is the
cached model and its cached solution, nothing is built or solved again), or the angle's own
model for a ``rebuilt`` row.
"""

from __future__ import annotations

import numpy as np

from ..hertz.conformity import roller_does_not_fit
from .cache import ModelCache, default_cache
from .families import hertz_half_width
from .options import ContactParams, SweepOptions
from .pipeline import line_contact
from .result import worst_row


def worst_surface_profile(table: dict, method: str, cp: ContactParams, families: list[dict],
                          options: SweepOptions, cache: ModelCache | None = None) -> dict:
    """Surface stresses along x at the angle of highest p0: Hertz lines (+ FE points).

    Parameters
    ----------
    table : dict[str, ndarray]
        The sweep table (:mod:`femcam.sweep.result`).
    method : str
        ``"fe"`` or ``"hertz"``.
    cp : ContactParams
    families : list of dict
        Family records (``id``, ``rho_ref``, ``a_ref``), empty for a Hertz sweep.
    options : SweepOptions
        ``a_over_h`` of the sweep's models.
    cache : ModelCache, optional
        Where the sweep's models are (default: this process's).

    The FE profile is recomputed with the family's osculating-arc gap and full sliding in the
    scene's direction (``cp.sliding``): for rows the sweep answered with the exact gap or with
    the mechanism's partial slip it is the full-sliding, arc-gap companion of that row.

    Returns
    -------
    dict
        ``theta_deg`` (deg), ``Fc`` (N), ``rho`` (m), ``mu``, ``a_hertz`` (m); where Hertz
        applies ``x_hertz`` (m) and ``sx_hertz, sz_hertz, txz_hertz`` (Pa), arrays of shape
        (1001,); for an FE row ``x_fe`` (m), ``sx_fe, sz_fe, txz_fe`` (Pa), ``p0_fe`` (Pa) and
        ``fe_model`` (``"family <id>"`` or ``"own"``).
    """
    cache = default_cache() if cache is None else cache
    i = worst_row(table, "p0_fe" if method == "fe" else "p0_hertz")
    F, rho, theta = float(table["Fc"][i]), float(table["rho"][i]), float(table["theta"][i])
    out = {"theta_deg": float(np.degrees(theta)), "Fc": F, "rho": rho, "mu": cp.mu}
    a_est = float(hertz_half_width(np.array([F]), np.array([rho]), cp)[0])
    out["a_hertz"] = a_est
    if not bool(roller_does_not_fit(rho, cp.Rr)):
        hc = line_contact(cp, F, rho)
        x = np.linspace(-2.5, 2.5, 1001) * float(hc.a)
        sx, sz, txz = hc.surface_stress(x)
        out.update(x_hertz=x, sx_hertz=sx, sz_hertz=sz, txz_hertz=txz, a_hertz=float(hc.a))
    if method == "fe" and table["status"][i] == "ok":
        refs = {int(f["id"]): (float(f["rho_ref"]), float(f["a_ref"])) for f in families}
        fid = int(table["family"][i]) if np.isfinite(table["family"][i]) else -1
        rebuilt = "rebuilt" in str(table["flags"][i]).split(";")
        if rebuilt or fid not in refs:
            model, out["fe_model"] = cache.model_for(cp, rho, a_est, options), "own"
        else:
            model, out["fe_model"] = cache.model_for(cp, *refs[fid], options), f"family {fid}"
        r = cache.solve(model, F, rho, cp.mu, cp.sliding, check=False)
        out.update(x_fe=np.asarray(r.x_surface, float), sx_fe=np.asarray(r.sx, float),
                   sz_fe=np.asarray(r.sz, float), txz_fe=np.asarray(r.txz, float),
                   p0_fe=float(r.p0))
    return out
