"""The scene schema: every key of every table, its unit, SI factor and check, and the accepted
ranges of the study settings.

A key table maps ``key -> (unit shown to the user, SI factor, check, required)``; the checks
are applied by :class:`femcam.scene.checker._Checker`:

=============== ==============================================================
check           accepted value
=============== ==============================================================
``pos``         a finite number > 0
``nonneg``      a finite number >= 0
``num``         any finite number
``nu``          Poisson's ratio, in (-1, 0.5)
``str``         a string (one of ``_CHOICES`` where the key is listed there)
``list``        a list of numbers
``strlist``     a list of strings (each one of ``_CHOICES`` where the key is listed there)
``seglist``     the ``[[program.segment]]`` array (checked by :mod:`femcam.scene.program`)
``bool``        true or false
=============== ==============================================================

The numbers of ``[fe]`` and ``[sweep]`` (``a_over_h``, ``tolerance``, ``chunk_size``,
``vtk_every``) are then checked by :func:`study_problem` (range or whole number).

One compact block per table group; a new key goes into its group's block. The ranges of the
``[fe]``/``[sweep]`` settings are written once here (:data:`STUDY_RANGES`,
:data:`STUDY_WHOLE`, :func:`study_problem`) and used by both the scene checker and
:class:`femcam.sweep.options.SweepOptions`.
"""

from __future__ import annotations

import math

_DEG = math.pi / 180.0

# ---- top level, [operating] ------------------------------------------------------------------
_TOP = {"name": ("", None, "str", True), "description": ("", None, "str", False),
        "source": ("", None, "str", False)}
_TABLES = ("operating", "program", "follower", "dynamics", "materials", "contact", "fe", "wear",
           "lubricant", "surface", "cam", "sweep")
_OPERATING = {"rpm": ("rpm", 2.0 * math.pi / 60.0, "pos", False),
              "omega_rad_s": ("rad/s", 1.0, "pos", False),
              "oil_temperature_C": ("degC", 1.0, "num", False)}  # assessment (femcam.assess)

# ---- [program], [[program.segment]] ------------------------------------------------------------
_PROGRAM = {"law": ("", None, "str", False), "control_points": ("", None, "list", False),
            "segment": ("", None, "seglist", True)}
_SEGMENT = {"kind": ("", None, "str", True), "beta_deg": ("deg", _DEG, "pos", True),
            "lift_mm": ("mm", 1e-3, "pos", False), "law": ("", None, "str", False),
            # the angular lift of an oscillating arm (femcam.profile.oscillating): lift_deg, not lift_mm
            "lift_deg": ("deg", _DEG, "pos", False),
            "control_points": ("", None, "list", False)}

# ---- [follower] and [cam] ----------------------------------------------------------------------
_FOLLOWER = {"type": ("", None, "str", True), "base_radius_mm": ("mm", 1e-3, "pos", True),
             "roller_radius_mm": ("mm", 1e-3, "pos", False), "offset_mm": ("mm", 1e-3, "num", False),
             "face_width_mm": ("mm", 1e-3, "pos", True),
             # FE contact of the non-roller followers (femcam.fe.followers)
             "tip_radius_mm": ("mm", 1e-3, "pos", False), "face_length_mm": ("mm", 1e-3, "pos", False)}
# the oscillating roller follower (femcam.profile.oscillating; docs/oscillating.md)
_ARM = {"motion": ("", None, "str", False), "pivot_distance_mm": ("mm", 1e-3, "pos", False),
        "arm_length_mm": ("mm", 1e-3, "pos", False), "direction": ("", None, "str", False),
        # the curved-pad oscillating follower (type = "curved_pad"; femcam.profile.pad)
        "pad_radius_mm": ("mm", 1e-3, "num", False)}  # num: a concave (negative) pad gets the range text
_FOLLOWER.update(_ARM)
#: keys only one follower type has
_FOLLOWER_ONLY = {"tip_radius_mm": "knife_edge", "face_length_mm": "flat_faced"}
# finite-length contact (femcam.halfspace; docs/halfspace.md): follower.face_width_mm stays the
# 2D contact length (w = Fc / face_width in Hertz and the 2D FE); roller_width_mm and
# cam.face_width_mm default to it and only enter the half-space strip, whose contact length is
# min(roller_width_mm, cam.face_width_mm).
_FINITE = {"roller_width_mm": ("mm", 1e-3, "pos", False), "crown": ("", None, "str", False),
           "crown_radius_mm": ("mm", 1e-3, "pos", False), "crown_drop_um": ("um", 1e-6, "pos", False),
           "edge_radius_mm": ("mm", 1e-3, "nonneg", False),
           "misalignment_deg": ("deg", _DEG, "num", False)}
#: scene key -> SI name in ``Scene.finite_length`` (and ``RollerProfile`` parameter)
_FINITE_SI = {"roller_width_mm": "roller_width", "crown": "crown", "crown_radius_mm": "crown_radius",
              "crown_drop_um": "crown_drop", "edge_radius_mm": "edge_radius",
              "misalignment_deg": "misalignment"}
# real bodies (femcam.bodies): the roller as a ring on a pin or needles, the cam on a shaft
_SUPPORT = {"roller_support": ("", None, "str", False), "roller_bore_mm": ("mm", 1e-3, "pos", False),
            "pin_radius_mm": ("mm", 1e-3, "pos", False),
            "pin_clearance_um": ("um", 1e-6, "nonneg", False),
            "needle_count": ("(count)", 1.0, "pos", False),
            "needle_radius_mm": ("mm", 1e-3, "pos", False)}
_FOLLOWER.update(_FINITE)
_FOLLOWER.update(_SUPPORT)
#: the follower keys each ``roller_support`` needs
_SUPPORT_KEYS = {"solid": (), "pin": ("roller_bore_mm", "pin_radius_mm", "pin_clearance_um"),
                 "needles": ("roller_bore_mm", "pin_radius_mm", "pin_clearance_um", "needle_count",
                             "needle_radius_mm")}
_CAM = {"face_width_mm": ("mm", 1e-3, "pos", False),
        "bore_mm": ("mm", 1e-3, "pos", False),  # shaft bore radius (femcam.bodies)
        # the shaft-bore fit (femcam.bodies.cam_geometry.CamDisk): unilateral "contact" (default) or
        # "bonded"; radial clearance: shaft radius = bore_mm - shaft_clearance_um
        "shaft_fit": ("", None, "str", False), "shaft_clearance_um": ("um", 1e-6, "nonneg", False)}

# ---- [dynamics] ----------------------------------------------------------------------------------
# mass_kg, spring_N_per_m, preload_N: required for a translating follower (femcam.scene.dynamics)
_DYNAMICS = {"mass_kg": ("kg", 1.0, "nonneg", False), "spring_N_per_m": ("N/m", 1.0, "nonneg", False),
             "preload_N": ("N", 1.0, "nonneg", False),
             "damping_N_s_per_m": ("N s/m", 1.0, "nonneg", False),
             "damping_ratio": ("(dimensionless)", 1.0, "nonneg", False)}
# follower-train dynamics (femcam.dynamics): model = "rigid" (eq. 11, default) | one_dof | two_dof
_TRAIN = {"model": ("", None, "str", False), "steps_per_rev": ("(count)", 1.0, "pos", False),
          "train_stiffness_N_per_m": ("N/m", 1.0, "pos", False),
          "train_damping_ratio": ("(dimensionless)", 1.0, "nonneg", False),
          "train_damping_N_s_per_m": ("N s/m", 1.0, "nonneg", False),
          "second_mass_kg": ("kg", 1.0, "pos", False), "second_stiffness_N_per_m": ("N/m", 1.0, "pos", False),
          "second_damping_ratio": ("(dimensionless)", 1.0, "nonneg", False),
          "second_damping_N_s_per_m": ("N s/m", 1.0, "nonneg", False)}
_DYNAMICS.update(_TRAIN)
# the oscillating arm about its pivot (femcam.loads.ArmDynamics): required for motion = oscillating
_ARM_DYNAMICS = {"arm_inertia_kg_m2": ("kg m^2", 1.0, "nonneg", False),
                 "spring_rate_N_m_per_rad": ("N m/rad", 1.0, "nonneg", False),
                 "preload_N_m": ("N m", 1.0, "nonneg", False),
                 "damping_N_m_s_per_rad": ("N m s/rad", 1.0, "nonneg", False),
                 # a linear spring (spring_N_per_m, preload_N) acting at this lever (femcam.dynamics.arm)
                 "spring_lever_mm": ("mm", 1e-3, "pos", False),
                 # the arm's elastic train in rotational units (femcam.dynamics.arm.arm_train)
                 "train_stiffness_N_m_per_rad": ("N m/rad", 1.0, "pos", False),
                 "train_damping_N_m_s_per_rad": ("N m s/rad", 1.0, "nonneg", False),
                 "second_inertia_kg_m2": ("kg m^2", 1.0, "pos", False),
                 "second_stiffness_N_m_per_rad": ("N m/rad", 1.0, "pos", False),
                 "second_damping_N_m_s_per_rad": ("N m s/rad", 1.0, "nonneg", False)}
_DYNAMICS.update(_ARM_DYNAMICS)

# ---- [materials.<body>] (cam, roller alias follower, pin, shaft) ---------------------------------
_MATERIAL = {"E_GPa": ("GPa", 1e9, "pos", True), "nu": ("(dimensionless)", 1.0, "nu", True),
             "hardness_MPa": ("MPa", 1e6, "pos", False), "name": ("", None, "str", False)}
# assessment data (femcam.assess), kept in Scene.tribology (femcam.scene.tribology.MaterialData)
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
#: material tables of the real bodies (femcam.bodies), besides cam and roller
_BODY_MATERIALS = ("pin", "shaft")

# ---- [contact], [lubricant], [surface] -----------------------------------------------------------
_CONTACT = {"friction": ("(dimensionless)", 1.0, "nonneg", False), "plane": ("", None, "str", False),
            "sliding": ("", None, "str", False)}
_LUBRICANT = {"name": ("", None, "str", False), "source": ("", None, "str", False),
              "viscosity_Pa_s": ("Pa s", 1.0, "pos", False), "temperature_C": ("degC", 1.0, "num", False),
              "viscosity_temperature_coefficient_per_K": ("1/K", 1.0, "nonneg", False),
              "kinematic_viscosity_40C_mm2_per_s": ("mm^2/s", 1e-6, "pos", False),
              "kinematic_viscosity_100C_mm2_per_s": ("mm^2/s", 1e-6, "pos", False),
              "pressure_viscosity_per_GPa": ("1/GPa", 1e-9, "pos", False),
              "alpha_per_Pa": ("1/Pa", 1.0, "pos", False), "density_kg_per_m3": ("kg/m^3", 1.0, "pos", False)}
_SURFACE = {k: ("um", 1e-6, "nonneg", False)
            for k in ("cam_Ra_um", "roller_Ra_um", "cam_Rq_um", "roller_Rq_um")}

# ---- coated and case-hardened bodies (femcam.layers): [materials.<body>.coating|case] -----------
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

# ---- SI names of the values the scene hands on (Scene.layers, Scene.tribology) -----------------
#: scene key (edge unit in the name) -> the name of its SI value in the dicts the scene hands on
#: (units only at the edges: a key that names mm must not hold m). Keys not listed keep their
#: name: dimensionless, already SI-named (``density_kg_per_m3``, ``alpha_per_Pa``), or degC
#: (``temperature_C``, ``scuffing_temperature_C``: kept in degC, as named).
SI_NAMES = {"thickness_um": "thickness", "E_GPa": "E", "interface_shear_strength_MPa":
            "interface_shear_strength", "hardness_MPa": "hardness", "wear_k_mm3_per_N_m": "wear_k",
            "depth_mm": "depth", "surface_hardness_HV": "surface_hardness",
            "core_hardness_HV": "core_hardness", "surface_yield_MPa": "surface_yield",
            "core_yield_MPa": "core_yield", "yield_strength_MPa": "yield_strength",
            "contact_fatigue_strength_MPa": "contact_fatigue_strength",
            "shear_fatigue_limit_MPa": "shear_fatigue_limit",
            "kinematic_viscosity_40C_mm2_per_s": "kinematic_viscosity_40C",
            "kinematic_viscosity_100C_mm2_per_s": "kinematic_viscosity_100C",
            "pressure_viscosity_per_GPa": "pressure_viscosity", "cam_Ra_um": "cam_Ra",
            "roller_Ra_um": "roller_Ra", "cam_Rq_um": "cam_Rq", "roller_Rq_um": "roller_Rq",
            "k_mm3_per_N_m": "k", "tip_radius_mm": "tip_radius"}


def si_named(table: dict) -> dict:
    """A checked table (SI values) with its keys renamed by :data:`SI_NAMES`.

    Parameters
    ----------
    table : dict
        Scene key -> value already converted to SI by the checker.

    Returns
    -------
    dict
        The same values under their SI names (hardness in Pa, lengths in m, 1/Pa, m^2/s).

    Examples
    --------
    >>> si_named({"thickness_um": 2e-6, "nu": 0.3})
    {'thickness': 2e-06, 'nu': 0.3}
    """
    return {SI_NAMES.get(k, k): v for k, v in table.items()}


# ---- study settings read by `femcam sweep` (CLI flags override them): [fe], [sweep] ----------
#: sweep methods: ``fe`` (the FE answers every contact angle), ``hertz`` (analytic only),
#: ``auto`` (the cheapest model within the tolerance)
METHODS = ("fe", "hertz", "auto")
#: smallest accepted ``tolerance`` (relative p0 reuse error); see :mod:`femcam.sweep.plan`
TOLERANCE_FLOOR = 1e-4
#: the quantities ``[fe] rtol_on`` may control: the stems of the sweep's ``err_est_*`` columns
#: that a family's mesh refines (:mod:`femcam.sweep.rtol`; the interface ones on coated scenes)
RTOL_ON = ("p0", "a", "vm", "tau1", "interface_tau", "interface_sn")
#: closed ranges of the real-valued study settings
STUDY_RANGES = {"a_over_h": (2.0, 400.0), "tolerance": (TOLERANCE_FLOOR, 0.5)}
#: what the study settings measure, as error messages write them after the value
STUDY_UNITS = {"a_over_h": "(elements per contact half-width, a/h)",
               "tolerance": "(relative p0 reuse error)", "chunk_size": "angles", "vtk_every": "angles"}
_RANGES = STUDY_RANGES  # the name tests/test_scene_tables.py reads
#: whole-number study settings and their smallest value
STUDY_WHOLE = {"chunk_size": 1, "vtk_every": 0}
_FLOOR_WHY = ("the reuse error is a discretisation effect of the order of the FE error itself "
              "(~0.2 % at a_over_h = 10, smaller on finer meshes); below the floor nearly every "
              "angle needs its own model. Refine a_over_h for more accurate p0")
_FE = {"a_over_h": ("(elements per contact half-width)", 1.0, "pos", False),
       "tolerance": ("(relative p0 reuse error)", 1.0, "pos", False),
       "rtol_pct": ("%", 1.0, "pos", False), "rtol_on": ("", None, "strlist", False)}
_SWEEP = {"method": ("", None, "str", False), "angles_deg": ("", None, "str", False),
          "chunk_size": ("angles", 1.0, "num", False), "vtk_every": ("angles", 1.0, "num", False),
          "plots": ("", None, "bool", False)}


def study_problem(key: str, x: float) -> str | None:
    """The condition a study setting breaks, or None if it is accepted (the one range check).

    Parameters
    ----------
    key : str
        ``"a_over_h"`` (elements per contact half-width), ``"tolerance"`` (relative p0 reuse
        error), ``"chunk_size"`` or ``"vtk_every"`` (angles).
    x : float
        The value, finite (dimensionless, or a count of angles).

    Returns
    -------
    str or None
        ``"must be ..."`` (the end of a ``"<name> = <value> <unit>: must be ..."`` message), or
        None for an accepted value.

    Examples
    --------
    >>> study_problem("a_over_h", 1.0)
    'must be in [2, 400]'
    >>> study_problem("chunk_size", 2.5)
    'must be a whole number >= 1'
    >>> study_problem("tolerance", 2e-3) is None
    True
    """
    if key in STUDY_WHOLE:
        lo = STUDY_WHOLE[key]
        return None if x == int(x) and x >= lo else f"must be a whole number >= {lo}"
    lo, hi = STUDY_RANGES[key]
    if lo <= x <= hi:
        return None
    if key == "tolerance" and x < lo:
        return f"must be >= {lo:g}: {_FLOOR_WHY}"
    return f"must be in [{lo:g}, {hi:g}]"


# ---- [wear] (femcam.wear.options) --------------------------------------------------------------
_WEAR = {"K": ("(dimensionless)", 1.0, "nonneg", False),
         "k_mm3_per_N_m": ("mm^3/(N m)", 1e-9, "nonneg", False),
         "roller_model": ("", None, "str", False), "srr": ("(dimensionless)", 1.0, "num", False),
         "J_kg_m2": ("kg m^2", 1.0, "pos", False), "T_drag_N_m": ("N m", 1.0, "nonneg", False),
         "cycles": ("revolutions", 1.0, "nonneg", False)}

#: the accepted strings of the ``str`` keys
_CHOICES = {"kind": ("rise", "dwell", "fall"), "type": ("roller", "knife_edge", "flat_faced", "curved_pad"),
            "plane": ("strain", "stress"), "sliding": ("+x", "-x"),
            "model": ("rigid", "one_dof", "two_dof"),
            "crown": ("none", "circular", "logarithmic"),
            "method": METHODS, "roller_model": ("srr", "inertia"),
            "roller_support": ("solid", "pin", "needles"), "shaft_fit": ("contact", "bonded"),
            "hardness_law": ("exponential", "linear"), "motion": ("translating", "oscillating"),
            "direction": ("away_from_pivot", "toward_pivot"), "rtol_on": RTOL_ON}

#: every key table by its table group (``*``: any body; the segment index dropped): the one
#: list the range table (:data:`femcam.scene.ranges.RANGES`), the scene reference
#: (``docs/scene.md``) and tests/test_scene_faults.py iterate, so a key added to a table above
#: is covered everywhere
TABLES = {"": _TOP, "operating": _OPERATING, "program": _PROGRAM, "program.segment": _SEGMENT,
          "follower": _FOLLOWER, "cam": _CAM, "dynamics": _DYNAMICS, "materials.*": _MATERIAL,
          "materials.*.coating": _COATING, "materials.*.case": _CASE, "contact": _CONTACT,
          "lubricant": _LUBRICANT, "surface": _SURFACE, "fe": _FE, "sweep": _SWEEP, "wear": _WEAR}
