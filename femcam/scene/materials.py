"""``[materials.<body>]``: the elastic materials of the cam, the roller (alias follower), the
pin and the shaft, and their assessment data (femcam.assess).

Moduli in GPa, hardness in MPa; the checked values are SI (:class:`femcam.materials.Material`).
"""

from __future__ import annotations

from ..materials import E_PHYSICAL, Material
from .checker import _Checker, _fmt
from .schema import _BODY_MATERIALS, _MATERIAL, _MATERIAL_EXTRA, si_named


def _materials(ck: _Checker, raw: dict) -> dict:
    """``{"cam": Material, "roller": Material, "extra": {body: {SI name: SI value}}}`` from
    [materials.*] (roller alias follower; ``extra``: the assessment keys, when given)."""
    mats = {}
    mraw = raw.get("materials", {})
    if not isinstance(mraw, dict):
        if "materials" in raw:
            ck.add("materials", f"= {_fmt(mraw)}: must be a table")
        return mats
    for k in mraw:
        if k not in ("cam", "roller", "follower") + _BODY_MATERIALS:
            ck.add(f"materials.{k}", "unknown material table; use [materials.cam], [materials.roller] "
                   "(or [materials.follower]), [materials.pin], [materials.shaft]")
    if "roller" in mraw and "follower" in mraw:
        ck.add("materials", "give [materials.roller] or its alias [materials.follower], not both")
    for k, alias in (("cam", "cam"), ("roller", "roller"), ("roller", "follower"), ("pin", "pin"),
                     ("shaft", "shaft")):
        if alias in mraw:
            _body_material(ck, mats, k, alias, mraw[alias])
    if "materials" in raw:
        for k in ("cam", "roller"):
            if k not in mraw and not (k == "roller" and "follower" in mraw):
                ck.add(f"materials.{k}", "missing required table (keys E_GPa, nu)")
    return mats


def _material(ck: _Checker, alias: str, m: dict, given: dict) -> Material | None:
    """The Material of one checked [materials.<alias>] table (None, with a problem added, for a
    modulus outside :data:`femcam.materials.E_PHYSICAL`)."""
    lo, hi = E_PHYSICAL
    if not lo <= m["E_GPa"] <= hi:  # a unit mistake (Pa typed as GPa, say)
        ck.add(f"materials.{alias}.E_GPa", f"= {_fmt(given['E_GPa'])} GPa: must be "
               f"in [{lo / 1e9:g}, {hi / 1e9:g}] GPa (soft elastomers to diamond)")
        return None
    return Material(E=m["E_GPa"], nu=m["nu"], name=m.get("name", alias), hardness=m.get("hardness_MPa"))


def _body_material(ck: _Checker, mats: dict, k: str, alias: str, given) -> None:
    """Check [materials.<alias>] and put body ``k``'s Material (and assessment extras) in ``mats``."""
    m = ck.table(given, f"materials.{alias}", _MATERIAL, extra=("coating", "case"))
    extra = si_named({x: m[x] for x in _MATERIAL_EXTRA if x in m})
    if extra:  # assessment data (femcam.assess): Scene.tribology's MaterialData (femcam.scene.tribology)
        mats.setdefault("extra", {})[k] = extra
    if "E_GPa" in m and "nu" in m:
        mats[k] = _material(ck, alias, m, given)

