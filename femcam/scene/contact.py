"""``[contact]``, ``[lubricant]``, ``[surface]`` and the coated and case-hardened bodies
(``[materials.<body>.coating|case]``, :mod:`femcam.layers`): the contact conditions.

Roughness in um, viscosity in Pa s or mm^2/s, thicknesses in um, depths in mm; the checked
values are SI.
"""

from __future__ import annotations

from .checker import _Checker, _fmt
from .schema import _CASE, _COATING, _CONTACT, _LUBRICANT, _SURFACE, si_named
from .tribology import Tribology, tribology_record


def _contact(ck: _Checker, raw: dict) -> dict:
    """The checked [contact] table: ``friction`` (dimensionless), ``plane``, ``sliding``."""
    return ck.table(raw.get("contact", {}), "contact", _CONTACT)


def _tribology(ck: _Checker, raw: dict, mats: dict) -> Tribology | None:
    """The :class:`~femcam.scene.tribology.Tribology` of the assessment keys (femcam.assess):
    [lubricant], [surface], [operating] oil_temperature_C and the material extras, in SI
    (``cam_Ra`` in m, ``pressure_viscosity`` in 1/Pa); None when a table has a problem (then
    in ``ck``)."""
    extra = mats.pop("extra", {})
    tabs = {}
    for t, spec in (("lubricant", _LUBRICANT), ("surface", _SURFACE)):
        if t in raw:
            tabs[t] = si_named(ck.table(raw[t], t, spec))
    op = raw.get("operating", {})
    T_oil = None
    if isinstance(op, dict) and isinstance(op.get("oil_temperature_C"), int | float):
        T_oil = float(op["oil_temperature_C"])  # checked by _operating
    if not isinstance(raw.get("lubricant", {}), dict) or not isinstance(raw.get("surface", {}), dict):
        return None  # not a table: the problem is in ck
    try:
        return tribology_record(tabs.get("lubricant"), tabs.get("surface"), T_oil, extra)
    except (TypeError, ValueError):  # an invalid key or value: already a problem in ck
        return None



def _layers(ck: _Checker, raw: dict) -> dict:
    """``{body: {"coating": {...}, "case": {...}}}`` (SI, checked) from [materials.<body>.*],
    keys named by :data:`~femcam.scene.schema.SI_NAMES` (``thickness``, ``depth`` in m, ...)."""
    out = {}
    mraw = raw.get("materials", {}) if isinstance(raw.get("materials", {}), dict) else {}
    for alias, tabs in mraw.items():
        body = "roller" if alias == "follower" else alias
        for t, spec in (("coating", _COATING), ("case", _CASE)):
            if isinstance(tabs, dict) and t in tabs:
                out.setdefault(body, {})[t] = ck.table(tabs[t], f"materials.{alias}.{t}", spec)
        coat = out.get(body, {}).get("coating", {})
        if "wear_k_mm3_per_N_m" in coat and "wear_K" in coat:
            ck.add(f"materials.{alias}.coating", "give wear_k_mm3_per_N_m or wear_K, not both")
        elif "wear_K" in coat and "hardness_MPa" not in coat:
            ck.add(f"materials.{alias}.coating.wear_K", f"= {_fmt(coat['wear_K'])}: needs the "
                   "coating's hardness_MPa (k = K / H)")
        case = out.get(body, {}).get("case", {})
        pairs = [("surface_hardness_HV", "core_hardness_HV"), ("surface_yield_MPa", "core_yield_MPa")]
        given = [p for p in pairs if any(k in case for k in p)]
        if case and (len(given) != 1 or not all(k in case for k in given[0])):
            ck.add(f"materials.{alias}.case", "give surface_hardness_HV and core_hardness_HV, or "
                   "surface_yield_MPa and core_yield_MPa (one complete pair)")
    return {b: {t: si_named(v) for t, v in tabs.items()} for b, tabs in out.items()}
