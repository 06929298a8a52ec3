"""A scene's ``[wear]`` table: checked keys (units in the key names) and the wear coefficient used.

The scene loader passes ``[wear]`` through unchecked; :func:`wear_options` checks it the way the
scene loader checks its own tables (unknown key, value, expected unit, a "did you mean" hint),
and raises one :class:`~femcam.errors.SceneError` listing every problem.

Keys (all optional)
-------------------
=================  ==================  ===================================================
key                unit                meaning
=================  ==================  ===================================================
K                  (dimensionless)     Archard coefficient; needs the cam's hardness_MPa
k_mm3_per_N_m      mm^3/(N m)          dimensional coefficient k (instead of K)
roller_model       "srr" | "inertia"   roller slip model (default "srr")
srr                (dimensionless)     slide-to-roll ratio, -2 < srr < 2 (default 0.02)
J_kg_m2            kg m^2              roller polar inertia (inertia model)
T_drag_N_m         N m                 roller bearing drag torque (inertia model)
tip_radius_mm      mm                  DEPRECATED alias of [follower] tip_radius_mm (warns)
cycles             revolutions         number of cam revolutions (default 1e6)
=================  ==================  ===================================================

Wear coefficient (:func:`wear_coefficient_info`), in this order: ``k_mm3_per_N_m``; ``K`` with
``[materials.cam] hardness_MPa`` (``K`` without a hardness is an error: K alone has no unit of
wear); neither: seed 000's K = 1e-8 with the cam hardness if the scene gives one, else with
seed 000's H = 2000 N/mm^2. The returned text says which case applied.
"""

from __future__ import annotations

import warnings

from ..errors import InputError
from ..scene import _Checker
from .archard import dimensional_coefficient

#: key -> (unit shown to the user, SI factor, check, required) -- the scene loader's convention
WEAR_KEYS = {
    "K": ("(dimensionless)", 1.0, "nonneg", False),
    "k_mm3_per_N_m": ("mm^3/(N m)", 1e-9, "nonneg", False),
    "roller_model": ("", None, "str", False),
    "srr": ("(dimensionless)", 1.0, "num", False),
    "J_kg_m2": ("kg m^2", 1.0, "pos", False),
    "T_drag_N_m": ("N m", 1.0, "nonneg", False),
    "tip_radius_mm": ("mm", 1e-3, "pos", False),
    "cycles": ("revolutions", 1.0, "nonneg", False),
}

#: seed 000's inputs, the defaults
DEFAULT_K = 1e-8
DEFAULT_H = 2000e6


def wear_options(scene) -> dict:
    """The scene's ``[wear]`` table checked and converted to SI (keys as in the table).

    Raises :class:`~femcam.errors.SceneError` (an ``InputError``) naming every unknown key or
    bad value with the expected unit, e.g. ``wear.k = 1e-17: unknown key; did you mean
    'k_mm3_per_N_m' in mm^3/(N m)? (units go in the key name)``.
    """
    raw = dict(scene.wear or {})
    ck = _Checker(scene.source_path or scene.name)
    out = ck.table(raw, "wear", WEAR_KEYS)
    if "roller_model" in out and out["roller_model"] not in ("srr", "inertia"):
        ck.add("wear.roller_model", f"= {out['roller_model']!r}: must be one of 'srr', 'inertia'")
    if "srr" in out and not (-2.0 < out["srr"] < 2.0):
        ck.add("wear.srr", f"= {raw['srr']} (dimensionless): must be in (-2, 2)")
    if "K" in raw and "k_mm3_per_N_m" in raw:
        ck.add("wear", "give either K (dimensionless, with the cam hardness_MPa) or k_mm3_per_N_m "
               "(mm^3/(N m)), not both")
    hardness = scene.cam.hardness
    if "K" in out and "k_mm3_per_N_m" not in raw and not hardness:
        ck.add("wear.K", f"= {raw['K']} (dimensionless): needs the cam hardness "
               "[materials.cam] hardness_MPa (MPa), k = K/H; or give k_mm3_per_N_m (mm^3/(N m))")
    if ck.problems:
        ck.raise_if_any()
    return out


def wear_coefficient_info(scene) -> tuple[float, str]:
    """``(k, where)``: the dimensional wear coefficient (m^3/(N m)) the scene asks for, and a
    sentence saying where it came from (scene key or default)."""
    opts = wear_options(scene)
    hardness = scene.cam.hardness
    if "k_mm3_per_N_m" in opts:
        k = opts["k_mm3_per_N_m"]
        return k, f"scene [wear] k_mm3_per_N_m = {k * 1e9:g} mm^3/(N m)"
    if "K" in opts:
        k = dimensional_coefficient(opts["K"], hardness)
        return k, (f"scene [wear] K = {opts['K']:g} / [materials.cam] hardness_MPa = "
                   f"{hardness / 1e6:g} MPa")
    if hardness:
        return dimensional_coefficient(DEFAULT_K, hardness), (
            f"default K = {DEFAULT_K:g} of seed 000, the scene gives no [wear] K or k_mm3_per_N_m; "
            f"H from the scene's [materials.cam] hardness_MPa = {hardness / 1e6:g} MPa")
    return dimensional_coefficient(DEFAULT_K, DEFAULT_H), (
        f"default: seed 000's K = {DEFAULT_K:g} and H = {DEFAULT_H / 1e6:g} N/mm^2; the scene gives "
        "no [wear] K or k_mm3_per_N_m and no [materials.cam] hardness_MPa")


def slip_kwargs(scene, opts: dict | None = None) -> dict:
    """Keyword arguments of :func:`~femcam.wear.slip.follower_slip` from the scene (``omega``,
    ``mu``) and its checked ``[wear]`` table ``opts`` (default: :func:`wear_options`)."""
    if opts is None:
        opts = wear_options(scene)
    return dict(omega=scene.omega, roller_model=opts.get("roller_model", "srr"), srr=opts.get("srr", 0.02),
                mu=scene.mu or 0.1, J=opts.get("J_kg_m2"), T_drag=opts.get("T_drag_N_m", 0.0))


def describe_k(k: float, where: str) -> str:
    """``k = 5e-18 m^3/(N m) = 5e-09 mm^3/(N m) (where)``."""
    return f"k = {k:.4g} m^3/(N m) = {k * 1e9:.4g} mm^3/(N m) ({where})"


def follower_tip_radius(scene) -> float | None:
    """Knife-edge tip radius (m) of a scene: ``[follower] tip_radius_mm`` (``Scene.tip_radius``),
    or the deprecated alias ``[wear] tip_radius_mm`` (a ``FutureWarning``); None if neither.

    Raises
    ------
    InputError
        Both keys given with different values.
    """
    tip = getattr(scene, "tip_radius", None)
    legacy = wear_options(scene).get("tip_radius_mm")
    if legacy is None:
        return tip
    warnings.warn("scene [wear] tip_radius_mm is deprecated: give the knife-edge tip radius as "
                  "[follower] tip_radius_mm (mm)", FutureWarning, stacklevel=2)
    if tip is not None and abs(tip - legacy) > 1e-12:
        raise InputError(f"[follower] tip_radius_mm = {tip * 1e3:g} mm and the deprecated [wear] "
                         f"tip_radius_mm = {legacy * 1e3:g} mm differ: give [follower] tip_radius_mm only")
    return legacy if tip is None else tip
