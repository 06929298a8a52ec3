"""``[wear]`` (Archard wear, :mod:`femcam.wear.options`): the table checked at load, and its
typed SI record :class:`WearSettings` (:attr:`femcam.scene.Scene.wear`).

``k_mm3_per_N_m`` in mm^3/(N m), or the dimensionless ``K`` with the cam hardness (k = K / H).
"""

from __future__ import annotations

from dataclasses import dataclass

from .. import _validate
from ..errors import InputError
from .checker import _Checker
from .schema import _CHOICES, _WEAR, si_named

#: the slide-to-roll ratio of the ``srr`` roller model when the scene gives none (dimensionless)
DEFAULT_SRR = 0.02


@dataclass(frozen=True, kw_only=True)
class WearSettings:
    """The ``[wear]`` table of a scene in SI (keyword-only; defaults: the table not given).

    Parameters
    ----------
    K : float or None
        Dimensionless Archard coefficient (needs the cam hardness, k = K / H); None: not given.
    k : float or None
        Dimensional wear coefficient (m^3/(N m), from ``k_mm3_per_N_m``); None: not given.
    roller_model : {"srr", "inertia"}
        Roller slip model.
    srr : float
        Slide-to-roll ratio of the ``srr`` model (dimensionless, -2 < srr < 2).
    J : float or None
        Roller polar inertia (kg m^2, ``J_kg_m2``; inertia model).
    T_drag : float
        Roller bearing drag torque (N m, ``T_drag_N_m``; inertia model).
    cycles : float or None
        Cam revolutions to wear over (revolutions); None: the caller's default.

    Raises
    ------
    InputError
        A value out of range, or both ``K`` and ``k``.
    """

    K: float | None = None
    k: float | None = None
    roller_model: str = "srr"
    srr: float = DEFAULT_SRR
    J: float | None = None
    T_drag: float = 0.0
    cycles: float | None = None

    def __post_init__(self):
        v = _validate
        set_ = object.__setattr__
        set_(self, "K", v.optional(v.nonnegative, "wear.K", self.K, "(dimensionless)"))
        set_(self, "k", v.optional(v.nonnegative, "wear.k", self.k, "m^3/(N m)"))
        if self.K is not None and self.k is not None:
            raise InputError("wear: give either K (dimensionless, with the cam hardness_MPa) or "
                             "k_mm3_per_N_m (mm^3/(N m)), not both")
        v.choice("wear.roller_model", self.roller_model, _CHOICES["roller_model"])
        set_(self, "srr", v.in_range("wear.srr", self.srr, -2.0, 2.0, "(dimensionless)",
                                     lo_open=True, hi_open=True))
        set_(self, "J", v.optional(v.positive, "wear.J", self.J, "kg m^2"))
        set_(self, "T_drag", v.nonnegative("wear.T_drag", self.T_drag, "N m"))
        set_(self, "cycles", v.optional(v.nonnegative, "wear.cycles", self.cycles, "revolutions"))


def wear_settings(table: dict) -> WearSettings:
    """The :class:`WearSettings` of a checked SI ``[wear]`` table (:func:`wear_table`).

    Parameters
    ----------
    table : dict
        Checked values under SI names (``k`` in m^3/(N m), ``J_kg_m2`` in kg m^2,
        ``T_drag_N_m`` in N m, ``K``, ``srr``, ``roller_model``, ``cycles``).

    Returns
    -------
    WearSettings
        The typed record (absent keys at their defaults).

    >>> wear_settings({"k": 1e-18, "srr": 0.05}).srr
    0.05
    """
    names = {"J_kg_m2": "J", "T_drag_N_m": "T_drag"}
    return WearSettings(**{names.get(k, k): v for k, v in table.items()})


def wear_table(ck: _Checker, raw, hardness) -> dict:
    """The [wear] table checked into ``ck``: keys, units, srr in (-2, 2), K or k, K needs the
    cam hardness. Used by :func:`femcam.scene.load_scene` (then :func:`wear_settings`).

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


def _scene_wear(ck: _Checker, raw: dict, mats: dict) -> dict:
    """The scene's [wear] table, if any, checked with the cam hardness of ``mats`` (Pa); the
    valid keys in SI ({} when not given)."""
    if "wear" not in raw:
        return {}
    cam = mats.get("cam")
    return wear_table(ck, raw["wear"], cam.hardness if cam is not None else None)
