"""Scene files: one TOML file describes a whole cam-follower case, with units in the key names.

``load_scene(path) -> Scene`` reads the file, checks every key and converts to SI; a bad file
raises one :class:`~femcam.errors.SceneError` that lists each problem with its dotted key
(``program.segment[1].beta_deg``), the value found and the expected unit. ``Scene.analyse``
runs the analytic chain (kinematics -> profile -> loads) at given cam angles.

Schema (all keys; ``?`` = optional; see ``docs/profile.md`` for the full table)::

    name, description?, source?
    [operating]        rpm | omega_rad_s
    [program]          law?  (default law of rise/fall segments), control_points?
    [[program.segment]] kind = "rise"|"dwell"|"fall", beta_deg, lift_mm (rise/fall),
                        law? | control_points?
    [follower]         type = "roller"|"knife_edge"|"flat_faced", base_radius_mm,
                       roller_radius_mm (roller), offset_mm?, face_width_mm,
                       tip_radius_mm? (knife_edge), face_length_mm? (flat_faced)
    [dynamics]         mass_kg, spring_N_per_m, preload_N, damping_N_s_per_m | damping_ratio,
                       model? = "rigid"|"one_dof"|"two_dof" (docs/dynamics.md), steps_per_rev?,
                       train_stiffness_N_per_m, train_damping_ratio | train_damping_N_s_per_m,
                       second_mass_kg, second_stiffness_N_per_m, second_damping_ratio | ..._N_s_per_m
    [materials.cam], [materials.roller] (alias [materials.follower]):
                       E_GPa, nu, hardness_MPa?, name?
    [contact]?         friction?, plane? = "strain"|"stress", sliding? = "+x"|"-x" (sweep: explicit
                       full-sliding override; default: traction from the mechanism)
    assessment (femcam.assess; all optional): [operating] oil_temperature_C?;
    [lubricant]?       name? (femcam.tribology.OILS) | viscosity_Pa_s + temperature_C +
                       viscosity_temperature_coefficient_per_K | kinematic_viscosity_40C_mm2_per_s +
                       kinematic_viscosity_100C_mm2_per_s, pressure_viscosity_per_GPa | alpha_per_Pa,
                       density_kg_per_m3, source?
    [surface]?         cam_Ra_um | cam_Rq_um, roller_Ra_um | roller_Rq_um
    [materials.*]      yield_strength_MPa?, thermal_conductivity_W_per_m_K?, density_kg_per_m3?,
                       specific_heat_J_per_kg_K?, contact_fatigue_strength_MPa?,
                       contact_fatigue_cycles?, contact_fatigue_exponent?, shear_fatigue_limit_MPa?,
                       scuffing_temperature_C?
    finite length (roller only, all optional; used by femcam.halfspace, see docs/halfspace.md):
    [follower]         roller_width_mm?, crown? = "none"|"circular"|"logarithmic",
                       crown_radius_mm? | crown_drop_um?, edge_radius_mm?, misalignment_deg?
    [cam]?             face_width_mm?  (cam face width; follower.face_width_mm stays the 2D length)
    roller on a pin or needles (femcam.bodies; docs/bodies.md): [follower] roller_support? =
                       "solid"|"pin"|"needles", roller_bore_mm (ring bore RADIUS), pin_radius_mm,
                       pin_clearance_um, needle_count, needle_radius_mm; [materials.pin]?
                       (pin and needles, default: the roller's); [cam]? bore_mm (shaft bore
                       RADIUS), [materials.shaft]?
    [fe]?              a_over_h?, tolerance? (femcam sweep's --mesh-size, --tolerance)
    [sweep]?           method?, angles_deg? ("0:360:1"), chunk_size?, vtk_every?, plots?
    [wear]?            K | k_mm3_per_N_m, roller_model?, srr?, J_kg_m2?, T_drag_N_m?, tip_radius_mm?,
                       cycles? (femcam.wear.options)

Only numpy/scipy and the standard library (``tomllib``) are imported.
"""

from __future__ import annotations

import dataclasses
import difflib
import math
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import numpy as np

from . import _validate
from .dynamics import TrainModel, periodic_response
from .errors import ConvergenceError, InputError, SceneError, UndercutError
from .halfspace.crown import RollerProfile
from .kinematics import CamProgram, dwell, fall, law, rise
from .loads import FollowerDynamics, LoadResult, contact_force
from .materials import E_PHYSICAL, Material
from .profile import CamProfile, bool_intervals, cam_profile, make_follower

try:  # Python >= 3.11
    import tomllib
except ModuleNotFoundError:  # pragma: no cover - Python 3.10
    import tomli as tomllib


# --------------------------------------------------------------------------------------------
# schema: key -> (unit shown to the user, SI factor, check, required)
# check: "pos" > 0, "nonneg" >= 0, "num" any finite, "nu" in (-1, 0.5), "str", "list"
# --------------------------------------------------------------------------------------------
#: angles of the dense undercut check of Scene.analyse over one revolution (0.05 deg apart)
UNDERCUT_CHECK_N = 7200


def _dense_theta() -> np.ndarray:
    """The ``UNDERCUT_CHECK_N`` angles (rad) of the dense undercut check."""
    return np.linspace(0.0, 2.0 * math.pi, UNDERCUT_CHECK_N, endpoint=False)


_TOP = {"name": ("", None, "str", True), "description": ("", None, "str", False),
        "source": ("", None, "str", False)}
_TABLES = ("operating", "program", "follower", "dynamics", "materials", "contact", "fe", "wear",
           "lubricant", "surface", "cam")
_OPERATING = {"rpm": ("rpm", 2.0 * math.pi / 60.0, "pos", False),
              "omega_rad_s": ("rad/s", 1.0, "pos", False)}
_PROGRAM = {"law": ("", None, "str", False), "control_points": ("", None, "list", False),
            "segment": ("", None, "seglist", True)}
_SEGMENT = {"kind": ("", None, "str", True), "beta_deg": ("deg", math.pi / 180.0, "pos", True),
            "lift_mm": ("mm", 1e-3, "pos", False), "law": ("", None, "str", False),
            "control_points": ("", None, "list", False)}
_FOLLOWER = {"type": ("", None, "str", True), "base_radius_mm": ("mm", 1e-3, "pos", True),
             "roller_radius_mm": ("mm", 1e-3, "pos", False), "offset_mm": ("mm", 1e-3, "num", False),
             "face_width_mm": ("mm", 1e-3, "pos", True),
             # FE contact of the non-roller followers (femcam.fe.followers)
             "tip_radius_mm": ("mm", 1e-3, "pos", False), "face_length_mm": ("mm", 1e-3, "pos", False)}
_FOLLOWER_ONLY = {"tip_radius_mm": "knife_edge", "face_length_mm": "flat_faced"}
_DYNAMICS = {"mass_kg": ("kg", 1.0, "nonneg", True), "spring_N_per_m": ("N/m", 1.0, "nonneg", True),
             "preload_N": ("N", 1.0, "nonneg", True),
             "damping_N_s_per_m": ("N s/m", 1.0, "nonneg", False),
             "damping_ratio": ("(dimensionless)", 1.0, "nonneg", False)}
# --- follower-train dynamics (femcam.dynamics): model = "rigid" (eq. 11, default) | one_dof | two_dof
_TRAIN = {"model": ("", None, "str", False), "steps_per_rev": ("(count)", 1.0, "pos", False),
          "train_stiffness_N_per_m": ("N/m", 1.0, "pos", False),
          "train_damping_ratio": ("(dimensionless)", 1.0, "nonneg", False),
          "train_damping_N_s_per_m": ("N s/m", 1.0, "nonneg", False),
          "second_mass_kg": ("kg", 1.0, "pos", False), "second_stiffness_N_per_m": ("N/m", 1.0, "pos", False),
          "second_damping_ratio": ("(dimensionless)", 1.0, "nonneg", False),
          "second_damping_N_s_per_m": ("N s/m", 1.0, "nonneg", False)}
_DYNAMICS.update(_TRAIN)
_MATERIAL = {"E_GPa": ("GPa", 1e9, "pos", True), "nu": ("(dimensionless)", 1.0, "nu", True),
             "hardness_MPa": ("MPa", 1e6, "pos", False), "name": ("", None, "str", False)}
_CONTACT = {"friction": ("(dimensionless)", 1.0, "nonneg", False), "plane": ("", None, "str", False),
            "sliding": ("", None, "str", False)}
# -- assessment keys (femcam.assess): lubricant, roughness, oil temperature, material extras --
_OPERATING["oil_temperature_C"] = ("degC", 1.0, "num", False)
_MATERIAL_EXTRA = {"yield_strength_MPa": ("MPa", 1e6, "pos", False),
                   "thermal_conductivity_W_per_m_K": ("W/(m K)", 1.0, "pos", False),
                   "density_kg_per_m3": ("kg/m^3", 1.0, "pos", False),
                   "specific_heat_J_per_kg_K": ("J/(kg K)", 1.0, "pos", False),
                   "contact_fatigue_strength_MPa": ("MPa", 1e6, "pos", False),
                   "contact_fatigue_cycles": ("cycles", 1.0, "pos", False),
                   "contact_fatigue_exponent": ("(dimensionless)", 1.0, "pos", False),
                   "shear_fatigue_limit_MPa": ("MPa", 1e6, "pos", False),
                   "scuffing_temperature_C": ("degC", 1.0, "num", False)}
_MATERIAL.update(_MATERIAL_EXTRA)
_LUBRICANT = {"name": ("", None, "str", False), "source": ("", None, "str", False),
              "viscosity_Pa_s": ("Pa s", 1.0, "pos", False), "temperature_C": ("degC", 1.0, "num", False),
              "viscosity_temperature_coefficient_per_K": ("1/K", 1.0, "nonneg", False),
              "kinematic_viscosity_40C_mm2_per_s": ("mm^2/s", 1e-6, "pos", False),
              "kinematic_viscosity_100C_mm2_per_s": ("mm^2/s", 1e-6, "pos", False),
              "pressure_viscosity_per_GPa": ("1/GPa", 1e-9, "pos", False),
              "alpha_per_Pa": ("1/Pa", 1.0, "pos", False), "density_kg_per_m3": ("kg/m^3", 1.0, "pos", False)}
_SURFACE = {k: ("um", 1e-6, "nonneg", False)
            for k in ("cam_Ra_um", "roller_Ra_um", "cam_Rq_um", "roller_Rq_um")}
_CHOICES = {"kind": ("rise", "dwell", "fall"), "type": ("roller", "knife_edge", "flat_faced"),
            "plane": ("strain", "stress"), "sliding": ("+x", "-x"),
            "model": ("rigid", "one_dof", "two_dof"),
            "crown": ("none", "circular", "logarithmic")}
# -- study settings read by `femcam sweep` (CLI flags override them), and the [wear] table
#    (femcam.wear.options); ranges: femcam.sweep.options (a_over_h [2, 400], TOLERANCE_FLOOR) --
_FE = {"a_over_h": ("(elements per contact half-width)", 1.0, "pos", False),
       "tolerance": ("(relative p0 reuse error)", 1.0, "pos", False)}
_SWEEP = {"method": ("", None, "str", False), "angles_deg": ("", None, "str", False),
          "chunk_size": ("angles", 1.0, "int1", False), "vtk_every": ("angles", 1.0, "int0", False),
          "plots": ("", None, "bool", False)}
_RANGES = {"a_over_h": (2.0, 400.0), "tolerance": (1e-4, 0.5)}
_WEAR = {"K": ("(dimensionless)", 1.0, "nonneg", False),
         "k_mm3_per_N_m": ("mm^3/(N m)", 1e-9, "nonneg", False),
         "roller_model": ("", None, "str", False), "srr": ("(dimensionless)", 1.0, "num", False),
         "J_kg_m2": ("kg m^2", 1.0, "pos", False), "T_drag_N_m": ("N m", 1.0, "nonneg", False),
         "tip_radius_mm": ("mm", 1e-3, "pos", False), "cycles": ("revolutions", 1.0, "nonneg", False)}
_CHOICES.update(method=("fe", "hertz"), roller_model=("srr", "inertia"))
_TABLES += ("sweep",)


def _train(ck, raw: dict, dy: dict, dyn):
    """The TrainModel of [dynamics] (None for model = "rigid"); problems go to ``ck``."""
    if "model" in raw and "model" not in dy:  # a bad model name, reported already
        return None
    model = dy.get("model", "rigid")
    allowed = {"rigid": (), "one_dof": ("train_",), "two_dof": ("train_", "second_")}.get(model, ())
    for k in raw:
        if (k.startswith(("train_", "second_")) and not k.startswith(allowed)
                or k == "steps_per_rev" and model == "rigid"):
            ck.add(f"dynamics.{k}", f"= {_fmt(raw[k])}: not used by model = {model!r}")
    if "steps_per_rev" in dy and dy["steps_per_rev"] != int(dy["steps_per_rev"]):
        ck.add("dynamics.steps_per_rev", f"= {_fmt(raw['steps_per_rev'])}: must be a whole number")
    if model == "rigid":
        return None
    parts = ["train"] + (["second"] if model == "two_dof" else [])
    need = ["train_stiffness_N_per_m"] + (["second_mass_kg", "second_stiffness_N_per_m"]
                                          if model == "two_dof" else [])
    ok = dyn is not None
    for k in need:
        if k not in raw:
            ck.add(f"dynamics.{k}", f"missing required key for model = {model!r} (unit: {_TRAIN[k][0]})")
        ok = ok and k in dy
    for p in parts:
        given = [k for k in (f"{p}_damping_ratio", f"{p}_damping_N_s_per_m") if k in raw]
        if len(given) != 1:
            ck.add("dynamics", f"model = {model!r}: give exactly one of {p}_damping_ratio "
                   f"(dimensionless) or {p}_damping_N_s_per_m (N s/m); got {given or 'none'}")
        ok = ok and len(given) == 1 and given[0] in dy
    if not ok:
        return None
    sec = ({} if model == "one_dof" else
           {"m2": dy["second_mass_kg"], "k2": dy["second_stiffness_N_per_m"],
            "c2": dy.get("second_damping_N_s_per_m"), "zeta2": dy.get("second_damping_ratio")})
    try:
        return TrainModel(follower=dyn, k_t=dy["train_stiffness_N_per_m"],
                          c_t=dy.get("train_damping_N_s_per_m"), zeta_t=dy.get("train_damping_ratio"),
                          **sec)
    except InputError as exc:  # mass_kg = 0: a massless follower has no train dynamics
        ck.add("dynamics", f"model = {model!r}: {exc}")
        return None


def _follower_only_keys(ck, raw, ftype) -> bool:
    """Report keys of another follower type (tip_radius_mm on a roller, ...); True if any."""
    bad = [k for k in _FOLLOWER_ONLY if ftype and isinstance(raw, dict) and k in raw
           and _FOLLOWER_ONLY[k] != ftype]
    for k in bad:
        ck.add(f"follower.{k}", f"= {_fmt(raw[k])}: only a {_FOLLOWER_ONLY[k]} follower has this key, "
               f"not a {ftype}")
    return bool(bad)


# ---- finite-length contact keys (femcam.halfspace; docs/halfspace.md) -------------------------
# follower.face_width_mm stays the 2D contact length (w = Fc / face_width in Hertz and the 2D FE);
# roller_width_mm and cam.face_width_mm default to it and only enter the half-space strip, whose
# contact length is min(roller_width_mm, cam.face_width_mm).
_FINITE = {"roller_width_mm": ("mm", 1e-3, "pos", False), "crown": ("", None, "str", False),
           "crown_radius_mm": ("mm", 1e-3, "pos", False), "crown_drop_um": ("um", 1e-6, "pos", False),
           "edge_radius_mm": ("mm", 1e-3, "nonneg", False),
           "misalignment_deg": ("deg", math.pi / 180.0, "num", False)}
_FOLLOWER.update(_FINITE)
_CAM = {"face_width_mm": ("mm", 1e-3, "pos", False)}
_FINITE_SI = {"roller_width_mm": "roller_width", "crown": "crown", "crown_radius_mm": "crown_radius",
              "crown_drop_um": "crown_drop", "edge_radius_mm": "edge_radius",
              "misalignment_deg": "misalignment"}


def _finite_length(ck: _Checker, raw: dict, fo: dict, ftype) -> dict:
    """Check the finite-length keys; returns them in SI (``roller_width``, ``cam_width``, ``crown``,
    ``crown_radius``, ``crown_drop``, ``edge_radius``, ``misalignment``) or {} on a problem."""
    cam = ck.table(raw.get("cam", {}), "cam", _CAM)
    graw = raw.get("follower", {}) if isinstance(raw.get("follower"), dict) else {}
    given = [k for k in _FINITE if k in graw]
    if given and ftype in ("knife_edge", "flat_faced"):
        ck.add(f"follower.{given[0]}", f"= {_fmt(graw[given[0]])}: a {ftype} follower has no roller")
        return {}
    if any(k in graw and k not in fo for k in _FINITE) or "face_width_mm" not in fo:
        return {}
    out = {v: fo[k] for k, v in _FINITE_SI.items() if k in fo}
    out.setdefault("roller_width", fo["face_width_mm"])
    out["cam_width"] = cam.get("face_width_mm", fo["face_width_mm"])
    kw = {k: out[k] for k in ("crown", "crown_radius", "crown_drop", "edge_radius", "misalignment")
          if k in out}
    try:
        RollerProfile(width=out["roller_width"], **kw)
    except InputError as exc:
        msg = str(exc)
        for k, v in _FINITE_SI.items():  # name the scene key and unit, not the SI parameter
            if msg.startswith(v + " ") or msg.startswith(v + ":"):
                unit = _FINITE[k][0]
                ck.add(f"follower.{k}", f"= {_fmt(graw.get(k, fo.get(k)))}{' ' + unit if unit else ''}: "
                       f"{msg.split(': ', 1)[-1]}")
                return {}
        ck.add("follower", msg)
        return {}
    return out

# ---- real bodies (femcam.bodies): the roller as a ring on a pin or needles, the cam on a shaft
_FOLLOWER.update({"roller_support": ("", None, "str", False), "roller_bore_mm": ("mm", 1e-3, "pos", False),
                  "pin_radius_mm": ("mm", 1e-3, "pos", False),
                  "pin_clearance_um": ("um", 1e-6, "nonneg", False),
                  "needle_count": ("(count)", 1.0, "pos", False),
                  "needle_radius_mm": ("mm", 1e-3, "pos", False)})
_CHOICES["roller_support"] = ("solid", "pin", "needles")
_CAM["bore_mm"] = ("mm", 1e-3, "pos", False)  # shaft bore radius (femcam.bodies)
_BODY_MATERIALS = ("pin", "shaft")
_SUPPORT_KEYS = {"solid": (), "pin": ("roller_bore_mm", "pin_radius_mm", "pin_clearance_um"),
                 "needles": ("roller_bore_mm", "pin_radius_mm", "pin_clearance_um", "needle_count",
                             "needle_radius_mm")}


def roller_support_problems(*, Ro, Ri, support, Rp, c, Z, r_n) -> list[str]:
    """Geometry problems of a ring support (SI in, messages in the scene's mm / um): bore inside
    the roller, pin + clearance = bore (pin), pin + 2 needles + clearance = bore and needles
    that fit around the pitch circle (needles)."""
    out = []
    if support == "solid":
        return out
    if not 0.0 < Ri < Ro:
        return [f"roller_bore_mm = {Ri * 1e3:g} mm: must be in (0, roller_radius_mm = {Ro * 1e3:g} mm)"]
    if support == "pin":
        if not math.isclose(Rp + c, Ri, rel_tol=1e-9, abs_tol=1e-12):
            out.append(f"pin_radius_mm + pin_clearance_um = {Rp * 1e3:g} mm + {c * 1e6:g} um = "
                       f"{(Rp + c) * 1e3:g} mm: must equal roller_bore_mm = {Ri * 1e3:g} mm")
        return out
    if Z < 3 or Z != int(Z):
        out.append(f"needle_count = {Z:g}: must be a whole number >= 3 (fewer cannot hold the ring)")
    if not math.isclose(Rp + 2 * r_n + c, Ri, rel_tol=1e-9, abs_tol=1e-12):
        out.append(f"pin_radius_mm + 2 needle_radius_mm + pin_clearance_um = {Rp * 1e3:g} + "
                   f"{2 * r_n * 1e3:g} mm + {c * 1e6:g} um = {(Rp + 2 * r_n + c) * 1e3:g} mm: must "
                   f"equal roller_bore_mm = {Ri * 1e3:g} mm")
    pitch = Ri - r_n
    if Z >= 3 and pitch > 0 and 2 * pitch * math.sin(math.pi / Z) < 2 * r_n:
        zmax = int(math.pi / math.asin(min(1.0, r_n / pitch)))
        out.append(f"needle_count = {Z:g} needles of radius {r_n * 1e3:g} mm do not fit around the "
                   f"pitch circle of radius {pitch * 1e3:g} mm (they overlap by "
                   f"{(2 * r_n - 2 * pitch * math.sin(math.pi / Z)) * 1e6:.3g} um); at most {zmax} fit")
    return out


def _check_bodies(ck, raw: dict, fo: dict, mats: dict) -> dict:
    """The real-body keys: which apply, their geometry, the pin/shaft materials. Returns the SI
    dict stored in ``Scene.bodies`` (empty for today's solid roller and local cam body)."""
    fraw = raw.get("follower", {}) if isinstance(raw.get("follower"), dict) else {}
    support = fo.get("roller_support", "solid")
    given = [k for k in _SUPPORT_KEYS["needles"] if k in fraw]
    needed = _SUPPORT_KEYS.get(support, ())
    for k in given:
        if k not in needed:
            ck.add(f"follower.{k}", f"= {_fmt(fraw[k])}: not used with roller_support = {support!r}")
    for k in needed:
        if k not in fraw:
            ck.add(f"follower.{k}", f"missing: required with roller_support = {support!r} "
                   f"(unit: {_FOLLOWER[k][0]})")
    out = {}
    if needed and all(k in fo for k in needed) and "roller_radius_mm" in fo:
        geo = dict(Ro=fo["roller_radius_mm"], Ri=fo["roller_bore_mm"], support=support,
                   Rp=fo["pin_radius_mm"], c=fo["pin_clearance_um"], Z=fo.get("needle_count", 0.0),
                   r_n=fo.get("needle_radius_mm", 0.0))
        for msg in roller_support_problems(**geo):
            ck.add("follower", msg)
        out.update(geo, Z=int(geo["Z"]))
    # [cam] is checked once, by _finite_length (one _CAM schema); here only a valid bore is used
    bore = raw.get("cam", {}).get("bore_mm") if isinstance(raw.get("cam"), dict) else None
    ok = isinstance(bore, int | float) and not isinstance(bore, bool) and math.isfinite(bore) and bore > 0
    cam = {"bore_mm": bore * 1e-3} if ok else {}
    if "bore_mm" in cam and "base_radius_mm" in fo and cam["bore_mm"] >= fo["base_radius_mm"]:
        ck.add("cam.bore_mm", f"= {_fmt(raw['cam']['bore_mm'])} mm: the shaft bore radius must be < "
               f"base_radius_mm = {fo['base_radius_mm'] * 1e3:g} mm")
    if "bore_mm" in cam:
        out["cam_bore"] = cam["bore_mm"]
    out.update({k: v for k, v in mats.items() if k in _BODY_MATERIALS})
    return out
# ---- end of the real-bodies block

_CHOICES["hardness_law"] = ("exponential", "linear")
# --- coated and case-hardened bodies (femcam.layers): [materials.<body>.coating|case] ---------
_COATING = {"thickness_um": ("um", 1e-6, "pos", True), "E_GPa": ("GPa", 1e9, "pos", True),
            "nu": ("(dimensionless)", 1.0, "nu", True), "name": ("", None, "str", False),
            "interface_shear_strength_MPa": ("MPa", 1e6, "pos", False),
            "hardness_MPa": ("MPa", 1e6, "pos", False),
            # coating wear (femcam.wear.coating): k directly, or Archard K with hardness_MPa
            "wear_k_mm3_per_N_m": ("mm^3/(N m)", 1e-9, "pos", False),
            "wear_K": ("(dimensionless)", 1.0, "pos", False)}
_CASE = {"depth_mm": ("mm", 1e-3, "pos", True), "hardness_law": ("", None, "str", False),
         "surface_hardness_HV": ("HV", 9.80665e6, "pos", False),
         "core_hardness_HV": ("HV", 9.80665e6, "pos", False),
         "surface_yield_MPa": ("MPa", 1e6, "pos", False), "core_yield_MPa": ("MPa", 1e6, "pos", False)}


def _layers(ck, raw: dict) -> dict:
    """``{body: {"coating": {...}, "case": {...}}}`` (SI, checked) from [materials.<body>.*]."""
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
    return out
# --- end of the layers block -------------------------------------------------------------------


def _fmt(v) -> str:
    return repr(v) if isinstance(v, str) else str(v).lower() if isinstance(v, bool) else f"{v}"


#: problems one SceneError lists (then "... and N more")
MAX_PROBLEMS = 20


class _Checker:
    """Collects every problem of a scene file, then raises one SceneError."""

    def __init__(self, path: str):
        self.path = path
        self.problems: list[str] = []

    def add(self, key: str, msg: str) -> None:
        # "key = value unit: condition" (like femcam._validate), or "key: message"
        self.problems.append(f"{key} {msg}" if msg.startswith("= ") else f"{key}: {msg}")

    def table(self, raw, key: str, spec: dict, *, extra: tuple = ()) -> dict:
        """Check one table: types, ranges, unknown and missing keys. Returns SI values."""
        out = {}
        if not isinstance(raw, dict):
            self.add(key, f"= {_fmt(raw)}: must be a table [{key}]")
            return out
        for k, v in raw.items():
            dk = f"{key}.{k}" if key else k
            if k in extra:
                continue
            if k not in spec:
                self.add(dk, f"= {_fmt(v)}: unknown key{self._hint(k, spec)}")
                continue
            unit, factor, check, _ = spec[k]
            val = self.value(dk, k, v, unit, factor, check)
            if val is not None:
                out[k] = val
        for k, (unit, _, _, required) in spec.items():
            if required and k not in raw:
                u = f" (unit: {unit})" if unit else ""
                self.add(f"{key}.{k}" if key else k, f"missing required key{u}")
        return out

    @staticmethod
    def _hint(k: str, spec: dict) -> str:
        pref = [n for n in spec if n.startswith(k + "_")]
        near = pref or difflib.get_close_matches(k, list(spec), n=1, cutoff=0.6)
        if not near:
            return f"; valid keys: {', '.join(spec)}"
        unit = spec[near[0]][0]
        why = " (units go in the key name)" if pref else ""
        return f"; did you mean {near[0]!r}{' in ' + unit if unit else ''}?{why}"

    def value(self, dk, k, v, unit, factor, check):
        """One value checked by ``check`` and converted to SI with ``factor`` (None: a problem
        was added)."""
        if check == "str":
            if not isinstance(v, str):
                self.add(dk, f"= {_fmt(v)}: must be a string")
                return None
            if k in _CHOICES and v not in _CHOICES[k]:
                self.add(dk, f"= {v!r}: must be one of {', '.join(map(repr, _CHOICES[k]))}")
                return None
            return v
        if check == "list":
            ok = isinstance(v, list) and all(isinstance(x, int | float) and not isinstance(x, bool)
                                             for x in v)
            if not ok:
                self.add(dk, f"= {_fmt(v)}: must be a list of numbers")
                return None
            return [float(x) for x in v]
        if check == "seglist":
            return v  # handled by the caller
        if check == "bool":
            if not isinstance(v, bool):
                self.add(dk, f"= {_fmt(v)}: must be true or false")
                return None
            return v
        x = self._number(dk, v, unit, factor, check)
        if x is not None and k in _RANGES and not _RANGES[k][0] <= x <= _RANGES[k][1]:
            self.add(dk, f"= {_fmt(v)} {unit}: must be in [{_RANGES[k][0]:g}, {_RANGES[k][1]:g}]")
            return None
        return x

    def _number(self, dk, v, unit, factor, check):
        u = f" {unit}" if unit else ""
        if isinstance(v, bool) or not isinstance(v, int | float):
            self.add(dk, f"= {_fmt(v)}: must be a number in{u or ' (dimensionless)'}")
            return None
        x = float(v)
        bad = None
        if not math.isfinite(x):
            bad = "must be finite"
        elif check == "pos" and x <= 0:
            bad = "must be > 0"
        elif check == "nonneg" and x < 0:
            bad = "must be >= 0"
        elif check == "nu" and not (-1.0 < x < 0.5):
            bad = "Poisson's ratio must be in (-1, 0.5)"
        elif check in ("int0", "int1") and (x != int(x) or x < int(check[-1])):
            bad = f"must be a whole number >= {check[-1]}"
        if bad:
            self.add(dk, f"= {_fmt(v)}{u}: {bad}")
            return None
        return int(x) if check in ("int0", "int1") else x * factor

    def raise_if_any(self):
        if self.problems:
            n = len(self.problems)
            head = f"scene file {self.path}: {n} problem{'s' if n > 1 else ''}"
            shown = self.problems[:MAX_PROBLEMS] + ([f"... and {n - MAX_PROBLEMS} more"]
                                                    if n > MAX_PROBLEMS else [])
            raise SceneError(head + "\n  " + "\n  ".join(shown))


# --------------------------------------------------------------------------------------------
# scene
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class SceneState:
    """The analytic chain at cam angles ``theta``; SI units throughout.

    Attributes
    ----------
    theta : ndarray, shape (n,), float
        Cam angles (rad).
    s, v, a, j : ndarray, shape (n,), float
        Lift (m), velocity (m/s), acceleration (m/s^2), jerk (m/s^3) at ``omega``.
    s1, s2 : ndarray, shape (n,), float
        ds/dtheta (m/rad), d2s/dtheta2 (m/rad^2).
    phi : ndarray, shape (n,), float
        Pressure angle (rad).
    rho : ndarray, shape (n,), float
        Cam surface radius of curvature at the contact (m; < 0 concave, inf flat).
    Fc : ndarray, shape (n,), float
        Contact force (N; <= 0 at lift-off).
    liftoff : ndarray, shape (n,), bool
        Follower off the cam.
    contact_x, contact_y : ndarray, shape (n,), float
        Contact point in the cam frame (m).
    profile : femcam.profile.CamProfile
    loads : femcam.loads.LoadResult
    undercut_intervals : list of (float, float)
        Undercut angle intervals of the whole revolution (rad), from the dense check.
    """

    theta: np.ndarray
    s: np.ndarray
    v: np.ndarray
    a: np.ndarray
    j: np.ndarray
    s1: np.ndarray
    s2: np.ndarray
    phi: np.ndarray
    rho: np.ndarray
    Fc: np.ndarray
    liftoff: np.ndarray
    contact_x: np.ndarray
    contact_y: np.ndarray
    profile: CamProfile
    loads: LoadResult
    undercut_intervals: list = field(default_factory=list)

    @property
    def undercut(self) -> np.ndarray:
        """Undercut flags at the analysed angles ``theta`` (see ``undercut_intervals`` for the
        whole revolution)."""
        return self.profile.undercut


@dataclass(frozen=True)
class Scene:
    """A cam-follower case in SI units (built by :func:`load_scene`).

    Attributes
    ----------
    name : str
    program : femcam.kinematics.CamProgram
    follower : RollerFollower, KnifeEdgeFollower or FlatFacedFollower
    dynamics : femcam.loads.FollowerDynamics
    omega : float
        Cam speed (rad/s).
    cam, roller : femcam.materials.Material
        Cam and follower materials.
    length : float
        Axial contact length (face width / cam thickness, m).
    mu : float
        Friction coefficient.
    plane : str
        ``"strain"`` or ``"stress"``.
    sliding : str or None
        ``"+x"`` or ``"-x"``: direction of the friction traction on the cam. The sweep takes the
        traction from the mechanism (femcam.sweep.realcam); this key is an explicit override
        (full sliding in this direction at every angle).
    description, source : str
    fe, sweep : dict
        The checked study settings of [fe] (``a_over_h``, ``tolerance``) and [sweep]
        (``method``, ``angles_deg``, ``chunk_size``, ``vtk_every``, ``plots``): ``femcam sweep``
        uses them where no flag is given.
    wear : dict
        The [wear] table as written (checked at load; SI values: :mod:`femcam.wear.options`).
    source_path : str
        The scene file ("" if built in code).
    raw : dict
        The parsed TOML.
    """

    name: str
    program: CamProgram
    follower: object
    dynamics: FollowerDynamics
    omega: float
    cam: Material
    roller: Material
    length: float
    mu: float = 0.0
    plane: str = "strain"
    sliding: str | None = None
    description: str = ""
    source: str = ""
    fe: dict = field(default_factory=dict)
    wear: dict = field(default_factory=dict)
    finite_length: dict = field(default_factory=dict)  # femcam.halfspace keys in SI (_finite_length)
    #: coatings and cases per body (SI, checked; femcam.layers.scene_layers builds them)
    layers: dict = field(default_factory=dict)
    source_path: str = ""
    #: checked SI values of the assessment keys: lubricant, surface, oil_temperature_C, materials
    tribology: dict = field(default_factory=dict)
    raw: dict = field(default_factory=dict, repr=False)
    train: TrainModel | None = None  # [dynamics] model one_dof/two_dof; None: rigid eq. 11
    steps_per_rev: int | None = None
    #: real bodies (femcam.bodies): roller support geometry (SI: Ro, Ri, support, Rp, c, Z, r_n),
    #: cam_bore (m) and the "pin" / "shaft" Materials; empty for the solid roller
    bodies: dict = field(default_factory=dict)
    #: checked [sweep] settings (see ``fe``)
    sweep: dict = field(default_factory=dict)
    #: knife-edge tip radius (m, [follower] tip_radius_mm) and flat-face length (m,
    #: [follower] face_length_mm); None when not given (femcam.fe.followers)
    tip_radius: float | None = None
    face_length: float | None = None

    @property
    def rpm(self) -> float:
        return self.omega * 60.0 / (2.0 * math.pi)

    @cached_property
    def _dense_undercut(self) -> tuple:
        """``(flags, message)`` of the dense undercut check on :func:`_dense_theta` (``message``:
        the :class:`~femcam.errors.UndercutError` text of :func:`~femcam.profile.cam_profile`,
        or None). Computed once per scene (the scene is immutable), not per :meth:`analyse`
        call (the sweep analyses chunk by chunk)."""
        dense = _dense_theta()
        dd = self.program.derivatives(dense)
        try:
            return cam_profile(self.follower, dense, dd.s, dd.s1, dd.s2).undercut, None
        except UndercutError as exc:
            flags = cam_profile(self.follower, dense, dd.s, dd.s1, dd.s2, allow_undercut=True).undercut
            return flags, str(exc)

    @cached_property
    def dynamic_response(self):
        """Periodic response of the follower train (:class:`femcam.dynamics.DynamicsResult`),
        computed once per scene; None for the rigid model (eq. 11)."""
        if self.train is None:
            return None
        return periodic_response(self.train, self.program, self.omega, steps_per_rev=self.steps_per_rev)

    def undercut_check(self, theta=None, undercut=None) -> list:
        """Undercut intervals ``[(start, end), ...]`` (rad, in [0, 2 pi)) of the whole cam.

        The profile is checked on a dense grid of ``UNDERCUT_CHECK_N`` angles over one
        revolution (0.05 deg apart; computed once per scene) merged with ``theta`` (taken mod
        2 pi; ``undercut``, if given, are its already computed flags), so a narrow undercut band
        between coarse analysis angles is still found. Vectorised.
        """
        dense, flags = _dense_theta(), self._dense_undercut[0]
        if theta is None:
            return bool_intervals(dense, flags)
        extra = np.mod(np.ravel(np.asarray(theta, float)), 2.0 * math.pi)
        if undercut is None:
            de = self.program.derivatives(extra)
            undercut = cam_profile(self.follower, extra, de.s, de.s1, de.s2,
                                   allow_undercut=True).undercut
        undercut = np.ravel(np.asarray(undercut, bool))
        if undercut.size != extra.size:
            raise InputError(f"undercut has {undercut.size} flags: must have one per theta "
                             f"({extra.size} angles)")
        th = np.concatenate([dense, extra])
        order = np.argsort(th, kind="stable")
        return bool_intervals(th[order], np.concatenate([flags, undercut])[order])

    def analyse(self, theta, *, allow_undercut: bool = False) -> SceneState:
        """Kinematics, profile and contact force at cam angles ``theta`` (rad), vectorised.

        Undercut is a property of the whole cam, so besides ``theta`` the profile is checked on a
        dense grid over one revolution (:meth:`undercut_check`). Raises
        :class:`~femcam.errors.UndercutError` (with the angle ranges in degrees) for an
        undercut cam unless ``allow_undercut=True``; the intervals found are
        ``SceneState.undercut_intervals`` (rad, in [0, 2 pi)).

        ``Fc`` is seed 002's eq. 11 (rigid follower) unless ``[dynamics] model`` is one_dof or
        two_dof: then it is the periodic contact force of the elastic train
        (:attr:`dynamic_response`, interpolated to ``theta``; free flight is ``liftoff``), and a
        response that is not one-periodic raises :class:`~femcam.errors.ConvergenceError`.
        """
        d = self.program.derivatives(theta)
        w = self.omega
        v, a, j = w * d.s1, w**2 * d.s2, w**3 * d.s3
        p = cam_profile(self.follower, d.theta, d.s, d.s1, d.s2, allow_undercut=allow_undercut)
        intervals = self.undercut_check(d.theta, p.undercut)
        if intervals and not allow_undercut:
            # cam_profile passed on theta, so the dense grid found it (and holds the message)
            raise UndercutError(f"{self._dense_undercut[1]} (found by the dense check on "
                                f"{UNDERCUT_CHECK_N} angles over one revolution; the analysed "
                                "angles miss it)")
        if self.train is None:
            r = contact_force(self.dynamics, d.theta, d.s, v, a, p.phi)
        else:  # the dynamic contact force of the periodic train response, at theta
            res = self.dynamic_response
            if not res.converged:
                raise ConvergenceError(f"[dynamics] model = {res.model!r} at {self.rpm:g} rpm: {res.message}")
            r = res.load_result(d.theta, p.phi)
        return SceneState(theta=np.asarray(d.theta, float), s=d.s, v=v, a=a, j=j, s1=d.s1, s2=d.s2,
                          phi=p.phi, rho=p.rho, Fc=r.Fc, liftoff=r.liftoff, contact_x=p.contact_x,
                          contact_y=p.contact_y, profile=p, loads=r, undercut_intervals=intervals)

    def with_law(self, name: str, **params) -> Scene:
        """The same scene with every rise/fall segment using motion law ``name``."""
        lw = law(name, **params)
        segs = [s if s.law is None else dataclasses.replace(s, law=lw) for s in self.program.segments]
        return dataclasses.replace(self, program=CamProgram(segs))


def _law_from(ck: _Checker, key: str, tab: dict, default):
    if "law" in tab and "control_points" in tab:
        ck.add(key, "give either law or control_points, not both")
        return None
    if "control_points" in tab:
        try:
            return law("bezier", control_points=tab["control_points"])
        except InputError as exc:
            ck.add(f"{key}.control_points", str(exc))
            return None
    if "law" in tab:
        try:
            return law(tab["law"])
        except InputError as exc:
            ck.add(f"{key}.law", str(exc))
            return None
    return default


def load_scene(path) -> Scene:
    """Read a scene TOML file (units in key names) and convert it to SI.

    Parameters
    ----------
    path : str or Path
        The scene file.

    Returns
    -------
    Scene

    Raises
    ------
    SceneError
        Listing every problem (dotted key, value, expected unit) if the file is malformed.
    """
    path = Path(path)
    raw = _read_toml(path)
    ck = _Checker(str(path))
    top = _top_level(ck, raw)
    omega = _operating(ck, raw)
    program = _program(ck, raw)
    fo, follower = _follower(ck, raw)
    dyn, train, steps_per_rev = _dynamics(ck, raw)
    mats = _materials(ck, raw)
    tribo = _tribology(ck, raw, mats)
    finite = _finite_length(ck, raw, fo, fo.get("type"))
    bodies = _check_bodies(ck, raw, fo, mats)
    layers = _layers(ck, raw)
    co = ck.table(raw.get("contact", {}), "contact", _CONTACT)
    study = _study(ck, raw, mats)
    ck.raise_if_any()

    return Scene(name=top["name"], description=top.get("description", ""), source=top.get("source", ""),
                 program=program, follower=follower, dynamics=dyn, omega=omega, cam=mats["cam"],
                 roller=mats["roller"], length=fo["face_width_mm"], mu=co.get("friction", 0.0),
                 plane=co.get("plane", "strain"), sliding=co.get("sliding"), fe=study["fe"],
                 wear=dict(raw.get("wear", {})), source_path=str(path), raw=raw, train=train,
                 tribology=tribo, finite_length=finite, bodies=bodies, layers=layers,
                 steps_per_rev=steps_per_rev, sweep=study["sweep"], tip_radius=fo.get("tip_radius_mm"),
                 face_length=fo.get("face_length_mm"))


def _study(ck: _Checker, raw: dict, mats: dict) -> dict:
    """``{"fe": ..., "sweep": ...}``: the checked [fe] and [sweep] settings (SI), and the
    [wear] table checked by :func:`wear_table` (the cam hardness from ``mats``)."""
    out = {t: ck.table(raw[t], t, spec) if t in raw else {} for t, spec in (("fe", _FE), ("sweep", _SWEEP))}
    if isinstance(out["sweep"].get("angles_deg"), str):
        try:
            _validate.angles_deg("sweep.angles_deg", out["sweep"]["angles_deg"])
        except InputError as exc:
            ck.add("sweep.angles_deg", str(exc).removeprefix("sweep.angles_deg "))
    if "wear" in raw:
        cam = mats.get("cam")
        wear_table(ck, raw["wear"], cam.hardness if cam is not None else None)
    return out


def wear_table(ck: _Checker, raw, hardness) -> dict:
    """The [wear] table checked into ``ck`` (keys, units, srr in (-2, 2), K or k, K needs the
    cam ``hardness`` (Pa, None: not given)); SI values. Used by :func:`load_scene` and
    :func:`femcam.wear.options.wear_options`."""
    out = ck.table(raw, "wear", _WEAR)
    if not isinstance(raw, dict):
        return out
    if "srr" in out and not (-2.0 < out["srr"] < 2.0):
        ck.add("wear.srr", f"= {raw['srr']} (dimensionless): must be in (-2, 2)")
    if "K" in raw and "k_mm3_per_N_m" in raw:
        ck.add("wear", "give either K (dimensionless, with the cam hardness_MPa) or k_mm3_per_N_m "
               "(mm^3/(N m)), not both")
    elif "K" in out and not hardness:
        ck.add("wear.K", f"= {raw['K']} (dimensionless): needs the cam hardness "
               "[materials.cam] hardness_MPa (MPa), k = K/H; or give k_mm3_per_N_m (mm^3/(N m))")
    return out


def _read_toml(path: Path) -> dict:
    try:
        with open(path, "rb") as fh:
            return tomllib.load(fh)
    except FileNotFoundError:
        raise SceneError(f"scene file {path}: not found") from None
    except IsADirectoryError:
        raise SceneError(f"scene file {path}: is a directory; give a .toml file") from None
    except UnicodeDecodeError as exc:  # a binary file, or text not saved as UTF-8
        raise SceneError(f"scene file {path}: not a UTF-8 text file (byte {exc.start}: "
                         f"{exc.object[exc.start:exc.start + 1]!r}); TOML must be UTF-8") from None
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(f"scene file {path}: not valid TOML: {exc}") from None
    except OSError as exc:  # permission denied, a path under a file, ...
        raise SceneError(f"scene file {path}: cannot be read ({exc.strerror or exc})") from None


def _top_level(ck: _Checker, raw: dict) -> dict:
    """Unknown and missing tables; the top-level keys (name, description, source)."""
    for k, v in raw.items():  # a table that is not one of ours: "[contactt]"
        if k not in _TABLES and k not in _TOP and isinstance(v, dict):
            near = difflib.get_close_matches(k, _TABLES, n=1, cutoff=0.6)
            hint = (f"; did you mean [{near[0]}]?" if near
                    else f"; valid tables: {', '.join(f'[{n}]' for n in _TABLES)}")
            ck.add(k, f"unknown table [{k}]{hint}")
    top = ck.table({k: v for k, v in raw.items()
                    if k not in _TABLES and (k in _TOP or not isinstance(v, dict))}, "", _TOP)
    for t in ("operating", "program", "follower", "dynamics", "materials"):
        if t not in raw:
            ck.add(t, f"missing required table [{t}]")
    return top


def _operating(ck: _Checker, raw: dict):
    """The operating speed omega (rad/s), from exactly one of rpm and omega_rad_s."""
    op = ck.table(raw.get("operating", {}), "operating", _OPERATING)
    if "operating" in raw and isinstance(raw["operating"], dict):
        given = [k for k in ("rpm", "omega_rad_s") if k in raw["operating"]]
        if len(given) != 1:
            ck.add("operating", "give exactly one of rpm (rpm) or omega_rad_s (rad/s); "
                   f"got {given or 'none'}")
    return op.get("rpm", op.get("omega_rad_s"))


def _program(ck: _Checker, raw: dict) -> CamProgram | None:
    """The cam program from [program] and its [[program.segment]] tables."""
    g = raw.get("program", {})
    prog_tab = ck.table(g, "program", _PROGRAM)
    default_law = _law_from(ck, "program", prog_tab, None)
    segments = []
    closure = []  # same betas and lifts, a placeholder law where the law is bad: closure check
    segs_raw = g.get("segment", []) if isinstance(g, dict) else []
    if "program" in raw and not (isinstance(segs_raw, list) and segs_raw):
        ck.add("program.segment", "must be an array of tables [[program.segment]] with at least one segment")
        segs_raw = []
    prog_law = isinstance(g, dict) and ("law" in g or "control_points" in g)
    for i, sr in enumerate(segs_raw):
        _segment(ck, f"program.segment[{i}]", sr, default_law, prog_law, segments, closure)
    program = None
    if closure and len(closure) == len(segs_raw):
        # closure (sum of beta = 360 deg, rises = falls) depends on betas and lifts only, so it is
        # reported even when other keys (a law, another table) have problems too
        try:
            program = CamProgram(closure)
        except InputError as exc:
            ck.add("program.segment", str(exc))
        else:
            program = CamProgram(segments) if len(segments) == len(segs_raw) else None
    return program


def _segment(ck: _Checker, key: str, sr, default_law, prog_law: bool, segments: list,
             closure: list) -> None:
    """One [[program.segment]]: appended to ``segments`` (if valid) and ``closure``."""
    sg = ck.table(sr, key, _SEGMENT)
    kind = sg.get("kind")
    if kind is None or "beta_deg" not in sg:
        return
    if kind == "dwell":
        for k in ("lift_mm", "law", "control_points"):
            if k in sg:
                ck.add(f"{key}.{k}", f"= {_fmt(sr[k])}: a dwell takes only kind and beta_deg")
        segments.append(dwell(sg["beta_deg"]))
        closure.append(segments[-1])
        return
    if "lift_mm" not in sg:
        if isinstance(sr, dict) and "lift_mm" not in sr:
            ck.add(f"{key}.lift_mm", f"missing required key for a {kind} (unit: mm)")
        return
    make = rise if kind == "rise" else fall
    lw = _law_from(ck, key, sg, default_law)
    closure.append(make(sg["beta_deg"], sg["lift_mm"], lw or "cycloidal"))
    if lw is None:
        if "law" not in sg and "control_points" not in sg and not prog_law:  # else reported
            ck.add(f"{key}.law", "missing: give law (e.g. 'cycloidal') or control_points, "
                   "here or in [program]")
        return
    segments.append(make(sg["beta_deg"], sg["lift_mm"], lw))


def _follower(ck: _Checker, raw: dict):
    """``(checked [follower] table in SI, follower or None)``."""
    g = raw.get("follower", {})
    fo = ck.table(g, "follower", _FOLLOWER)
    ftype = fo.get("type")
    follower = None
    if ftype == "roller" and "roller_radius_mm" not in g:
        ck.add("follower.roller_radius_mm", "missing required key for a roller follower (unit: mm)")
    elif _follower_only_keys(ck, g, ftype):
        pass
    elif ftype in ("knife_edge", "flat_faced") and "roller_radius_mm" in g:
        ck.add("follower.roller_radius_mm", f"= {_fmt(g['roller_radius_mm'])}: "
               f"a {ftype} follower has no roller")
    elif ftype and isinstance(g, dict) and set(g) <= set(fo) and "base_radius_mm" in fo:
        try:
            follower = make_follower(ftype, Rb=fo["base_radius_mm"], Rr=fo.get("roller_radius_mm", 0.0),
                                     e=fo.get("offset_mm", 0.0))
        except InputError:  # only the offset can fail here: |e| < prime radius
            Rr_m = fo.get("roller_radius_mm", 0.0) if ftype == "roller" else 0.0
            Rp_mm = (fo["base_radius_mm"] + Rr_m) * 1e3
            ck.add("follower.offset_mm", f"= {_fmt(g['offset_mm'])} mm: must satisfy "
                   f"|offset| < prime-circle radius {Rp_mm:g} mm")
    return fo, follower


def _tribology(ck: _Checker, raw: dict, mats: dict) -> dict:
    """Checked SI values of the assessment keys (femcam.assess): [lubricant], [surface],
    [operating] oil_temperature_C and the material extras."""
    tribo = {"materials": mats.pop("extra")} if "extra" in mats else {}
    for t, spec in (("lubricant", _LUBRICANT), ("surface", _SURFACE)):
        if t in raw:
            tribo[t] = ck.table(raw[t], t, spec)
    op = raw.get("operating", {})
    if isinstance(op, dict) and isinstance(op.get("oil_temperature_C"), int | float):
        tribo["oil_temperature_C"] = float(op["oil_temperature_C"])  # checked by _operating
    return tribo


def _dynamics(ck: _Checker, raw: dict) -> tuple:
    """``(FollowerDynamics | None, TrainModel | None, steps_per_rev | None)`` from [dynamics]
    (exactly one of the two damping keys; the train of ``model = one_dof | two_dof``)."""
    g = raw.get("dynamics", {})
    dy = ck.table(g, "dynamics", _DYNAMICS)
    if not (isinstance(g, dict) and "dynamics" in raw):
        return None, None, None
    dyn = _follower_dynamics(ck, g, dy)
    steps = int(dy["steps_per_rev"]) if "steps_per_rev" in dy else None
    return dyn, _train(ck, g, dy, dyn), steps


def _follower_dynamics(ck: _Checker, g: dict, dy: dict) -> FollowerDynamics | None:
    """The rigid-follower dynamics of eq. 11 (mass, spring, preload, damping)."""
    given = [k for k in ("damping_N_s_per_m", "damping_ratio") if k in g]
    if len(given) != 1:
        ck.add("dynamics", "give exactly one of damping_N_s_per_m (N s/m) or damping_ratio "
               f"(dimensionless); got {given or 'none'}")
        return None
    if not all(k in dy for k in ("mass_kg", "spring_N_per_m", "preload_N", given[0])):
        return None
    try:
        return FollowerDynamics(m=dy["mass_kg"], k=dy["spring_N_per_m"], Fpl=dy["preload_N"],
                                c=dy.get("damping_N_s_per_m"), zeta=dy.get("damping_ratio"))
    except InputError:  # only a damping ratio with c_c = 2 sqrt(k m) = 0 fails here
        ck.add("dynamics.damping_ratio",
               f"= {_fmt(g['damping_ratio'])} (dimensionless): the critical "
               f"damping c_c = 2 sqrt(k m) = 2 sqrt({dy['spring_N_per_m']:g} N/m * "
               f"{dy['mass_kg']:g} kg) = 0 N s/m, so a ratio cannot set the damping; give "
               "damping_N_s_per_m (N s/m) instead")
        return None


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
    extra = {x: m[x] for x in _MATERIAL_EXTRA if x in m}
    if extra:  # assessment data (femcam.assess), kept in Scene.tribology["materials"]
        mats.setdefault("extra", {})[k] = extra
    if "E_GPa" in m and "nu" in m:
        mats[k] = _material(ck, alias, m, given)


def _materials(ck: _Checker, raw: dict) -> dict:
    """``{"cam": Material, "roller": Material, "extra": {body: {key: SI value}}}`` from
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
