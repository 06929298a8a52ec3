"""``[contact]``, ``[lubricant]``, ``[surface]``: the contact conditions (the coated and
case-hardened bodies are :mod:`femcam.scene.layers`).

Roughness in um, viscosity in Pa s or mm^2/s; the checked values are SI.
"""

from __future__ import annotations

from .checker import _Checker
from .schema import _CONTACT, _LUBRICANT, _SURFACE, si_named
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
