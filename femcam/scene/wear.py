"""``[wear]`` (Archard wear, :mod:`femcam.wear.options`): the table checked at load.

``k_mm3_per_N_m`` in mm^3/(N m), or the dimensionless ``K`` with the cam hardness (k = K / H).
"""

from __future__ import annotations

from .checker import _Checker
from .schema import _WEAR, si_named


def wear_table(ck: _Checker, raw, hardness) -> dict:
    """The [wear] table checked into ``ck``: keys, units, srr in (-2, 2), K or k, K needs the
    cam hardness. Used by :func:`femcam.scene.load_scene` and
    :func:`femcam.wear.options.wear_options`.

    Parameters
    ----------
    ck : _Checker
        Collects the problems.
    raw : object
        The [wear] table as parsed (anything but a dict is a problem).
    hardness : float or None
        Cam hardness (Pa); None: not given.

    Returns
    -------
    dict
        The valid keys with SI values under SI names (``k`` in m^3/(N m) from
        ``k_mm3_per_N_m``; ``J_kg_m2`` in kg m^2,
        ``T_drag_N_m`` in N m; ``K``, ``srr``, ``cycles`` as given).
    """
    if isinstance(raw, dict) and "tip_radius_mm" in raw:   # the retired alias: one clear line
        ck.add("wear.tip_radius_mm", f"= {raw['tip_radius_mm']} mm: retired; give the knife-edge "
               "tip radius as [follower] tip_radius_mm (mm)")
        raw = {k: v for k, v in raw.items() if k != "tip_radius_mm"}
    out = ck.table(raw, "wear", _WEAR)
    if not isinstance(raw, dict):
        return out
    out = si_named(out)
    if "srr" in out and not (-2.0 < out["srr"] < 2.0):
        ck.add("wear.srr", f"= {raw['srr']} (dimensionless): must be in (-2, 2)")
    if "K" in raw and "k_mm3_per_N_m" in raw:
        ck.add("wear", "give either K (dimensionless, with the cam hardness_MPa) or k_mm3_per_N_m "
               "(mm^3/(N m)), not both")
    elif "K" in out and not hardness:
        ck.add("wear.K", f"= {raw['K']} (dimensionless): needs the cam hardness "
               "[materials.cam] hardness_MPa (MPa), k = K/H; or give k_mm3_per_N_m (mm^3/(N m))")
    return out


def _scene_wear(ck: _Checker, raw: dict, mats: dict) -> None:
    """Check the scene's [wear] table, if any, with the cam hardness of ``mats`` (Pa)."""
    if "wear" in raw:
        cam = mats.get("cam")
        wear_table(ck, raw["wear"], cam.hardness if cam is not None else None)
