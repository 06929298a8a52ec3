"""``[contact]``, ``[lubricant]``, ``[surface]``: the contact conditions (the coated and
case-hardened bodies are :mod:`femcam.scene.layers`).

Roughness in um, viscosity in Pa s or mm^2/s; the checked values are SI.
"""

from __future__ import annotations

from .checker import _Checker
from .schema import _CONTACT, _LUBRICANT, _SURFACE, si_named


def _contact(ck: _Checker, raw: dict) -> dict:
    """The checked [contact] table: ``friction`` (dimensionless), ``plane``, ``sliding``."""
    return ck.table(raw.get("contact", {}), "contact", _CONTACT)


def _tribology(ck: _Checker, raw: dict, mats: dict) -> dict:
    """Checked SI values of the assessment keys (femcam.assess): [lubricant], [surface],
    [operating] oil_temperature_C and the material extras; keys named by
    :data:`~femcam.scene.schema.SI_NAMES` (``cam_Ra`` in m, ``pressure_viscosity`` in 1/Pa)."""
    tribo = {"materials": mats.pop("extra")} if "extra" in mats else {}
    for t, spec in (("lubricant", _LUBRICANT), ("surface", _SURFACE)):
        if t in raw:
            tribo[t] = si_named(ck.table(raw[t], t, spec))
    op = raw.get("operating", {})
    if isinstance(op, dict) and isinstance(op.get("oil_temperature_C"), int | float):
        tribo["oil_temperature_C"] = float(op["oil_temperature_C"])  # checked by _operating
    return tribo
