"""The stated range of every numeric scene key, with its source, and the cross-key limits.

A value outside its range is refused at load with one line naming the dotted key, the value,
the unit and the range (:meth:`femcam.scene.checker._Checker.value`). The ranges are in the
units the scene file is written in (mm, um, deg, GPa, MPa, degC, ...), not SI.

Every range says where it comes from, one of four kinds:

* ``physical``: a limit of nature or of a real machine (no solid is lighter than an aerogel;
  no oil flows below its pour point; a friction coefficient of 5 is not a contact);
* ``handbook``: the span of values a named handbook lists for real parts, widened by about a
  decade each side so that no real design is refused;
* ``standard``: the span a named standard defines (ISO 3448 viscosity grades, ISO 1302
  roughness grades, ...);
* ``femcam``: femcam's own validity limit (a model assumption, a mesh or memory bound).

The distinction kept with the downstream formulas: a value inside its range but outside a
formula's range of validity (a film parameter outside the Hamrock-Dowson fit, a low Peclet
number, a contact too wide for Hertz) is computed and flagged per angle by the formula's own
module (``hertz_validity``, ``low_peclet``, ``W_range``, ``U_range`` in :mod:`femcam.assess`;
``EXCEEDS limit`` of the pressure angle in ``femcam run``), never refused here. What is refused
here is a number no real cam-follower can have, or one femcam cannot compute in bounded memory.

:func:`reference_table` writes the table of keys, units, ranges and sources that
``docs/scene.md`` holds (a test checks that the doc equals it).
"""

from __future__ import annotations

from typing import NamedTuple


class Range(NamedTuple):
    """The accepted closed range ``[lo, hi]`` of a numeric key (scene units) and its source.

    A key whose basic check is ``pos`` also excludes ``lo = 0`` itself; ``open_`` excludes both
    ends (Poisson's ratio, the slide-roll ratio).
    """

    lo: float
    hi: float
    source: str
    open_: bool = False


#: bytes of memory per time step of the periodic dynamics solve: the peak of
#: :func:`femcam.dynamics.periodic_response` measured with tracemalloc on the seed 002 train
#: (examples/seed002_dynamic.toml) at 50,000 and 200,000 steps: 185 B a step one-DOF, 315 B
#: two-DOF; rounded up
STEP_BYTES = 400
#: most time steps per revolution the periodic solve accepts (femcam.dynamics.periodic.MAX_STEPS)
MAX_STEPS = 400_000

_NORTON = "handbook: Norton, Cam Design and Manufacturing Handbook (2009)"
_LEN = "femcam: sub-millimetre to 1 m bodies (the FE mesh grades from the contact width to the body)"
_E = "physical: soft elastomers (~1e-4 GPa) to diamond (~1200 GPa); femcam.materials.E_PHYSICAL"
_HARD = "physical: lead (~50 MPa) to diamond (~100 GPa)"
_STRENGTH = "physical: below ~E/20, the ideal strength of steel (~10 GPa)"
_OIL_T = ("physical: below the pour point (about -60 degC, synthetic oils) oil does not flow; "
          "above ~350 degC lubricants decompose (ASTM D92 flash points 150-300 degC)")
_DAMP = "femcam: 0 (undamped) to 10 (heavily overdamped; valve trains 0.05-0.2, " + _NORTON[10:] + ")"
_C = "femcam: up to 1e6 N s/m (and a ratio c / (2 sqrt(k m)) <= 10, checked with the mass)"
_K = "physical: up to 1e10 N/m (a 10 mm steel rod 10 mm long is ~1.6e9 N/m)"
_MASS = "physical: 1 g to 10 t; cam-driven followers weigh grams to kilograms (" + _NORTON[10:] + ")"
_RA = "standard: ISO 1302 roughness grades N1-N12 (Ra 0.025-50 um)"
_KWEAR = "handbook: Archard k 1e-9 (DLC) to 1e-2 mm^3/(N m) (severe wear), Hutchings (2017) ch. 5"

#: table group (dotted table name, ``*`` for any body, no segment index) -> key -> Range
RANGES: dict[str, dict[str, Range]] = {
    "operating": {
        "rpm": Range(0.0, 1e5, "femcam: quasi-static contact; camshafts run below ~2e4 rpm ("
                     + _NORTON[10:] + ")"),
        "omega_rad_s": Range(0.0, 1e4, "femcam: as rpm (1e4 rad/s = 95,000 rpm)"),
        "oil_temperature_C": Range(-60.0, 350.0, _OIL_T)},
    "program.segment": {
        "beta_deg": Range(0.0, 360.0, "physical: one revolution; a short segment is checked for undercut "
                          "and pressure angle at its own points"),
        "lift_mm": Range(0.0, 1000.0, "femcam: 1 m; machine cams lift at most a few hundred mm ("
                         + _NORTON[10:] + ")"),
        "lift_deg": Range(0.0, 90.0, "femcam: an arm swings less than a quarter turn (valve-train rocker "
                          "and finger followers swing ~10-25 deg, " + _NORTON[10:] + ")")},
    "follower": {
        "base_radius_mm": Range(0.1, 1000.0, _LEN),
        "roller_radius_mm": Range(0.1, 1000.0, _LEN),
        "offset_mm": Range(-1000.0, 1000.0, _LEN + "; and abs(offset) < prime radius"),
        "face_width_mm": Range(0.1, 1000.0, _LEN),
        "tip_radius_mm": Range(0.01, 1000.0, _LEN),
        "face_length_mm": Range(0.1, 2000.0, _LEN),
        "roller_width_mm": Range(0.1, 1000.0, _LEN),
        "crown_radius_mm": Range(0.0, 1e6, "femcam: above 1 km a crown drops < 0.1 um over 20 mm "
                                 "(give crown = 'none')"),
        "crown_drop_um": Range(0.0, 1000.0, "handbook: crown drops of a few to tens of um, Harris & "
                               "Kotzalas, Rolling Bearing Analysis (2007); and <= 5 % of roller_radius_mm"),
        "edge_radius_mm": Range(0.0, 1000.0, _LEN + "; and <= half the roller width"),
        "misalignment_deg": Range(-1.0, 1.0, "handbook: roller bearings tolerate 0.05-0.1 deg (SKF "
                                  "catalogue); femcam's rigid-slice strip assumes a small tilt"),
        "roller_bore_mm": Range(0.05, 1000.0, _LEN + "; and < roller_radius_mm"),
        "pin_radius_mm": Range(0.05, 1000.0, _LEN),
        "pin_clearance_um": Range(0.0, 1000.0, "standard: ISO 286 running fits give 5-200 um; "
                                  "1 mm is no fit"),
        "needle_count": Range(1.0, 500.0, "femcam: one contact a needle in the ring solve; at least 3 "
                              "hold the ring"),
        "needle_radius_mm": Range(0.05, 100.0, _LEN),
        "pivot_distance_mm": Range(0.1, 2000.0, _LEN + "; and > base_radius_mm"),
        "arm_length_mm": Range(0.1, 2000.0, _LEN + "; and the arm puts the roller on the base circle"),
        "pad_radius_mm": Range(0.1, 1000.0, _LEN + "; convex (a concave pad is not modelled) and the arm "
                               "puts the pad on the base circle")},
    "cam": {
        "face_width_mm": Range(0.1, 1000.0, _LEN),
        "bore_mm": Range(0.05, 1000.0, _LEN + "; and < base_radius_mm"),
        "shaft_clearance_um": Range(0.0, 1000.0, "standard: ISO 286 fits; and <= 0.05 x bore_mm")},
    "dynamics": {
        "mass_kg": Range(0.0, 1e4, _MASS),
        "spring_N_per_m": Range(0.0, 1e10, _K),
        "preload_N": Range(0.0, 1e7, "physical: 1000 t, beyond any cam press (large press cams ~1e6 N)"),
        "damping_N_s_per_m": Range(0.0, 1e6, _C),
        "damping_ratio": Range(0.0, 10.0, _DAMP),
        "steps_per_rev": Range(16.0, MAX_STEPS, f"femcam: whole number; at least 16 steps, at most "
                               f"{MAX_STEPS} (~{STEP_BYTES} bytes of memory a step, "
                               f"{MAX_STEPS * STEP_BYTES / 1e6:.0f} MB)"),
        "train_stiffness_N_per_m": Range(0.0, 1e10, _K),
        "train_damping_ratio": Range(0.0, 10.0, _DAMP),
        "train_damping_N_s_per_m": Range(0.0, 1e6, _C),
        "second_mass_kg": Range(0.0, 1e4, _MASS),
        "second_stiffness_N_per_m": Range(0.0, 1e10, _K),
        "second_damping_ratio": Range(0.0, 10.0, _DAMP),
        "second_damping_N_s_per_m": Range(0.0, 1e6, _C),
        "arm_inertia_kg_m2": Range(0.0, 1e3, "physical: a 1 t arm 1 m long is ~3e2 kg m^2; valve-train "
                                   "finger followers ~1e-5 kg m^2 (" + _NORTON[10:] + ")"),
        "spring_rate_N_m_per_rad": Range(0.0, 1e8, "physical: a 1e10 N/m spring on a 0.1 m lever is 1e8 "
                                         "N m/rad"),
        "preload_N_m": Range(0.0, 1e6, "physical: 1e7 N on a 0.1 m lever, beyond any cam press"),
        "damping_N_m_s_per_rad": Range(0.0, 1e4, "femcam: 1e6 N s/m on a 0.1 m lever"),
        "spring_lever_mm": Range(0.1, 2000.0, _LEN),
        "train_stiffness_N_m_per_rad": Range(0.0, 1e8, "physical: a 1e10 N/m train on a 0.1 m lever "
                                             "is 1e8 N m/rad (a 2e6 N/m train at a 35 mm finger is "
                                             "2.45e3 N m/rad)"),
        "train_damping_N_m_s_per_rad": Range(0.0, 1e4, "femcam: 1e6 N s/m on a 0.1 m lever"),
        "second_inertia_kg_m2": Range(0.0, 1e3, "physical: as arm_inertia_kg_m2 (a valve of 0.08 kg "
                                      "at 50 mm is 2e-4 kg m^2)"),
        "second_stiffness_N_m_per_rad": Range(0.0, 1e8, "physical: a 1e10 N/m valve stem on a 0.1 m "
                                              "lever is 1e8 N m/rad"),
        "second_damping_N_m_s_per_rad": Range(0.0, 1e4, "femcam: 1e6 N s/m on a 0.1 m lever")},
    "materials.*": {
        "E_GPa": Range(1e-4, 2000.0, _E),
        "nu": Range(-1.0, 0.5, "physical: a stable isotropic solid", open_=True),
        "hardness_MPa": Range(1.0, 1.5e5, _HARD),
        "yield_strength_MPa": Range(1.0, 1e4, _STRENGTH),
        "thermal_conductivity_W_per_m_K": Range(0.01, 3000.0, "physical: aerogels (~0.02) to "
                                                "diamond (~2000)"),
        "density_kg_per_m3": Range(10.0, 25000.0, "physical: foams (~10) to osmium (22,590)"),
        "specific_heat_J_per_kg_K": Range(50.0, 5000.0, "physical: lead (~130) to water (~4200)"),
        "contact_fatigue_strength_MPa": Range(1.0, 1e4, _STRENGTH),
        "contact_fatigue_cycles": Range(1e3, 1e13, "standard: a fatigue strength is a high-cycle value "
                                        "(ISO 6336-2 reference cycles 1e5-1e10)"),
        "contact_fatigue_exponent": Range(1.0, 50.0, "standard: S-N exponents 3-20 (ISO 6336-2, ISO 281)"),
        "shear_fatigue_limit_MPa": Range(1.0, 1e4, _STRENGTH),
        "scuffing_temperature_C": Range(0.0, 1000.0, "handbook: Blok's critical temperature 150-400 degC "
                                        "(Ludema, Friction, Wear, Lubrication); < 1000 degC "
                                        "(steel melts ~1450)")},
    "materials.*.coating": {
        "thickness_um": Range(0.01, 1000.0, "physical: below 10 nm no continuous film; "
                              "femcam.layers.Coating: <= 1000 um; and <= 10 % of the coated body's radius"),
        "E_GPa": Range(1e-4, 2000.0, _E),
        "nu": Range(-1.0, 0.5, "physical: a stable isotropic solid", open_=True),
        "interface_shear_strength_MPa": Range(1.0, 1e4, _STRENGTH),
        "hardness_MPa": Range(1.0, 1.5e5, _HARD),
        "wear_k_mm3_per_N_m": Range(0.0, 1e-1, _KWEAR),
        "wear_K": Range(0.0, 1.0, "physical: Archard K <= 1 (1e-8 to 1e-2 in practice, Hutchings 2017)")},
    "materials.*.case": {
        "depth_mm": Range(0.0, 20.0, "handbook: case depths 0.1-6 mm (ASM Handbook vol. 4); and < half the "
                          "body (base_radius_mm or roller_radius_mm)"),
        "surface_hardness_HV": Range(50.0, 3000.0, "handbook: steels 100-900 HV, carbides ~2000 HV"),
        "core_hardness_HV": Range(50.0, 3000.0, "handbook: steels 100-900 HV, carbides ~2000 HV"),
        "surface_yield_MPa": Range(1.0, 1e4, _STRENGTH),
        "core_yield_MPa": Range(1.0, 1e4, _STRENGTH)},
    "contact": {
        "friction": Range(0.0, 1.0, "handbook: lubricated 0.01-0.1, dry steel 0.5-0.8 (Rabinowicz, "
                          "Friction and Wear of Materials)")},
    "lubricant": {
        "viscosity_Pa_s": Range(1e-4, 1e3, "physical: light fluids (~1e-3 Pa s) to cold gear oils "
                                "(~1e2 Pa s)"),
        "temperature_C": Range(-60.0, 350.0, _OIL_T),
        "viscosity_temperature_coefficient_per_K": Range(0.0, 1.0, "handbook: 0.01-0.06 1/K (Hamrock, "
                                                         "Fundamentals of Fluid Film Lubrication)"),
        "kinematic_viscosity_40C_mm2_per_s": Range(1.0, 1e5, "standard: ISO 3448 grades VG 2-3200"),
        "kinematic_viscosity_100C_mm2_per_s": Range(0.5, 1e4, "standard: ISO 3448 grades VG 2-3200 "
                                                    "at 100 degC"),
        "pressure_viscosity_per_GPa": Range(0.1, 100.0, "handbook: 5-40 1/GPa (Hamrock)"),
        "alpha_per_Pa": Range(1e-10, 1e-7, "handbook: 5e-9 to 4e-8 1/Pa (Hamrock)"),
        "density_kg_per_m3": Range(500.0, 2500.0, "physical: light oils (~700) to "
                                   "perfluoropolyethers (~1900)")},
    "surface": {k: Range(0.0, 50.0, _RA) for k in ("cam_Ra_um", "roller_Ra_um", "cam_Rq_um", "roller_Rq_um")},
    "fe": {"a_over_h": Range(2.0, 400.0, "femcam: STUDY_RANGES (mesh resolution of the contact)"),
           "tolerance": Range(1e-4, 0.5, "femcam: STUDY_RANGES (reuse error floor)"),
           "rtol_pct": Range(0.02, 10.0, "femcam: RTOL_RANGE (estimated p0 error in %; 0.02 % = twice "
                             "the reuse tolerance floor)")},
    "sweep": {"chunk_size": Range(1.0, 1e5, "femcam: whole number of angles"),
              "vtk_every": Range(0.0, 1e5, "femcam: whole number of angles (0: none)")},
    "wear": {
        "K": Range(0.0, 1.0, "physical: Archard K <= 1"),
        "k_mm3_per_N_m": Range(0.0, 1e-1, _KWEAR),
        "srr": Range(-2.0, 2.0, "physical: |slide-roll ratio| < 2 unless the surfaces move opposite ways",
                     open_=True),
        "J_kg_m2": Range(0.0, 1e3, "physical: roller inertias are ~1e-7-1e-3 kg m^2"),
        "T_drag_N_m": Range(0.0, 1e4, "physical: bearing drag torques are ~1e-3-1 N m"),
        "cycles": Range(0.0, 1e13, "physical: 1e13 revolutions is 30 years at 6e5 rpm")},
}


def group_of(table: str) -> str:
    """The :data:`RANGES` group of a dotted table name.

    Parameters
    ----------
    table : str
        ``"follower"``, ``"program.segment[2]"``, ``"materials.cam.coating"``, ...

    Returns
    -------
    str
        The segment index dropped and the body replaced by ``*``.

    Examples
    --------
    >>> group_of("program.segment[2]"), group_of("materials.follower.case")
    ('program.segment', 'materials.*.case')
    """
    parts = table.split("[", 1)[0].split(".")
    if parts[0] == "materials" and len(parts) > 1:
        parts[1] = "*"
    return ".".join(parts)


def range_problem(group: str, key: str, x: float, unit: str, check: str) -> str | None:
    """The condition a value breaks, or None when it is inside the key's stated range.

    Parameters
    ----------
    group : str
        Table group (:func:`group_of`).
    key : str
        Key within the table.
    x : float
        The finite value, in the scene's unit (``unit``).
    unit : str
        Unit shown to the user.
    check : str
        The basic check of the key (``pos`` makes ``lo = 0`` an open end).

    Returns
    -------
    str or None
        ``"must be in [lo, hi] unit (source)"`` with a memory estimate for ``steps_per_rev``.

    Examples
    --------
    >>> range_problem("contact", "friction", 5.0, "(dimensionless)", "nonneg").split(" (handbook")[0]
    'must be in [0, 1] (dimensionless)'
    """
    r = RANGES.get(group, {}).get(key)
    if r is None:
        return None
    lo_open = r.open_ or (check == "pos" and r.lo == 0.0)
    inside = (r.lo < x if lo_open else r.lo <= x) and (x < r.hi if r.open_ else x <= r.hi)
    if inside:
        return None
    text = f"must be in {span(r, check)}{' ' + unit if unit else ''} ({r.source})"
    if key == "steps_per_rev" and x > r.hi:
        need = x * STEP_BYTES
        text += (f"; {x:g} steps would need about " + (f"{need / 1e12:.3g} TB" if need >= 1e12 else
                                                       f"{need / 1e9:.3g} GB") + " of memory")
    return text


def span(r: Range, check: str = "") -> str:
    """``"[lo, hi]"``, ``"(lo, hi]"`` or ``"(lo, hi)"`` of a range (``pos``: ``lo = 0`` open).

    Parameters
    ----------
    r : Range
        The range.
    check : str, optional
        The key's basic check.

    Returns
    -------
    str
        The interval as written in messages and in ``docs/scene.md``.

    Examples
    --------
    >>> span(Range(0.0, 1.0, "x"), "pos")
    '(0, 1]'
    """
    lo_open = r.open_ or (check == "pos" and r.lo == 0.0)
    return f"{'(' if lo_open else '['}{r.lo:g}, {r.hi:g}{')' if r.open_ else ']'}"


def reference_table(tables: dict, choices: dict) -> str:
    """The Markdown table of every scene key: table, key, unit, check, range and source.

    Parameters
    ----------
    tables : dict
        Table group -> key table (:data:`femcam.scene.schema.TABLES`).
    choices : dict
        Key -> accepted strings (:data:`femcam.scene.schema._CHOICES`).

    Returns
    -------
    str
        The table ``docs/scene.md`` holds between its markers (one row a key).
    """
    rows = ["| table | key | unit | required | accepted | source |", "|---|---|---|---|---|---|"]
    for group, spec in tables.items():
        for key, (unit, _, check, required) in spec.items():
            r = RANGES.get(group, {}).get(key)
            acc = (span(r, check) if r is not None else {"str": "text", "list": "list of numbers",
                                                          "strlist": "list of strings",
                                                          "seglist": "array of tables",
                                                          "bool": "true or false"}.get(check, check))
            if check in ("str", "strlist") and key in choices:
                acc = (("list of " if check == "strlist" else "")
                       + " \\| ".join(f"`{c}`" for c in choices[key]))
            rows.append(f"| `[{group or 'top level'}]` | `{key}` | {unit} | "
                        f"{'yes' if required else ''} | {acc} | {r.source.replace('|', '/') if r else ''} |")
    return "\n".join(rows) + "\n"

