"""The coated and case-hardened bodies (``[materials.<body>.coating|case]``; femcam.layers,
docs/layers.md) as the scene hands them on: one :class:`BodyLayers` per body, holding a
:class:`CoatingSpec` and/or a :class:`CaseSpec` in SI.

Thicknesses in um, depths in mm, moduli in GPa, hardness in MPa or HV in the scene file; the
records hold SI values. They are plain records (the scene is below femcam.layers):
:func:`femcam.layers.scene_layers` builds its ``Coating`` and ``Case`` from them.
"""

from __future__ import annotations

from dataclasses import dataclass

from .checker import _Checker, _fmt
from .schema import _CASE, _COATING, si_named


@dataclass(frozen=True, kw_only=True)
class CoatingSpec:
    """A body's coating (``[materials.<body>.coating]``), SI.

    Parameters
    ----------
    thickness : float
        Coating thickness (m; ``thickness_um``).
    E : float
        Coating Young's modulus (Pa; ``E_GPa``).
    nu : float
        Coating Poisson's ratio (-; ``nu``).
    name : str
        Coating name (``name``; default ``"coating"``).
    interface_shear_strength : float or None
        Interface shear strength (Pa; ``interface_shear_strength_MPa``).
    hardness : float or None
        Coating hardness (Pa; ``hardness_MPa``).
    wear_k : float or None
        Coating wear coefficient (m^3/(N m); ``wear_k_mm3_per_N_m``).
    wear_K : float or None
        Coating Archard coefficient (-; ``wear_K``, with ``hardness``: ``k = K / H``).
    """

    thickness: float
    E: float
    nu: float
    name: str = "coating"
    interface_shear_strength: float | None = None
    hardness: float | None = None
    wear_k: float | None = None
    wear_K: float | None = None


@dataclass(frozen=True, kw_only=True)
class CaseSpec:
    """A body's hardened case (``[materials.<body>.case]``), SI; one complete pair of surface and
    core values (hardness or yield strength).

    Parameters
    ----------
    depth : float
        Case depth (m; ``depth_mm``).
    hardness_law : str
        Hardness profile through the case (``hardness_law``; default ``"exponential"``).
    surface_hardness, core_hardness : float or None
        Surface and core hardness (Pa; ``surface_hardness_HV``, ``core_hardness_HV``).
    surface_yield, core_yield : float or None
        Surface and core yield strength (Pa; ``surface_yield_MPa``, ``core_yield_MPa``).
    """

    depth: float
    hardness_law: str = "exponential"
    surface_hardness: float | None = None
    core_hardness: float | None = None
    surface_yield: float | None = None
    core_yield: float | None = None


@dataclass(frozen=True, kw_only=True)
class BodyLayers:
    """The coating and case of one body.

    Parameters
    ----------
    body : {"cam", "roller"}
        The body (``[materials.follower.*]`` is the roller's).
    coating : CoatingSpec or None
        Its coating; None: uncoated.
    case : CaseSpec or None
        Its hardened case; None: none.
    """

    body: str
    coating: CoatingSpec | None = None
    case: CaseSpec | None = None


def _layers(ck: _Checker, raw: dict) -> tuple[BodyLayers, ...]:
    """One :class:`BodyLayers` per body with a ``[materials.<body>.coating|case]`` table (SI,
    checked), in the order of the scene file."""
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
    if ck.problems:   # a table with a problem has missing keys: the loader raises anyway
        return ()
    return tuple(BodyLayers(body=b, coating=_record(CoatingSpec, tabs.get("coating")),
                            case=_record(CaseSpec, tabs.get("case"))) for b, tabs in out.items())


def _record(cls, table):
    """``cls`` of a checked table's SI-named values, or None when the table is not given."""
    return None if table is None else cls(**si_named(table))
