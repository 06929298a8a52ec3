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
                       RADIUS), shaft_fit? ("contact"|"bonded"), shaft_clearance_um? (shaft
                       radius = bore - clearance), [materials.shaft]?
    [fe]?              a_over_h?, tolerance? (femcam sweep's --a-over-h, --tolerance)
    [sweep]?           method?, angles_deg? ("0:360:1"), chunk_size?, vtk_every?, plots?
    [wear]?            K | k_mm3_per_N_m, roller_model?, srr?, J_kg_m2?, T_drag_N_m?, cycles?
                       (femcam.wear.options)

Every numeric key has a stated range with its source (``ranges``; the table of all keys is
docs/scene.md), and keys that must fit together are checked together (``cross``).

Modules: ``schema`` (the key tables and units, the study-setting ranges), ``ranges``, ``cross``,
``checker`` (the
problem collector, did-you-mean), ``load`` (TOML reading, :func:`load_scene`), one module per
table group (``program``, ``follower`` with ``[cam]``, ``dynamics``, ``materials``, ``contact``
with ``[lubricant]``/``[surface]``, ``layers`` for coatings and cases, ``bodies``, ``study`` for
``[fe]``/``[sweep]``, ``wear``), the typed records they hand on (``bodies``: ``RealBodies``;
``layers``: ``BodyLayers``; ``finite``: ``FiniteLength``; ``pair``: ``ContactPair``;
``finite_case``: ``FiniteCase``, the finite-length contact femcam.halfspace takes) and
``state`` (:class:`Scene`, :class:`SceneState`, :meth:`Scene.analyse`, the undercut check).

Only numpy/scipy and the standard library (``tomllib``) are imported.
"""

from .bodies import CamShaft, RealBodies, RollerSupport, roller_support_problems
from .case import CamDiskCase, ContactCase, cam_disk_case, contact_case
from .checker import MAX_PROBLEMS
from .finite import FiniteLength
from .finite_case import FiniteCase, finite_case
from .layers import BodyLayers, CaseSpec, CoatingSpec
from .load import load_scene
from .pair import ContactPair
from .schema import METHODS, STUDY_RANGES, STUDY_WHOLE, TOLERANCE_FLOOR, study_problem
from .state import UNDERCUT_CHECK_N, Scene, SceneState
from .study import StudySettings
from .tribology import LubricantData, MaterialData, SurfaceRoughness, Tribology
from .wear import WearSettings, wear_table

__all__ = ["MAX_PROBLEMS", "METHODS", "STUDY_RANGES", "STUDY_WHOLE", "TOLERANCE_FLOOR",
           "UNDERCUT_CHECK_N", "BodyLayers", "CamDiskCase", "CamShaft", "CaseSpec", "CoatingSpec",
           "ContactCase", "ContactPair", "FiniteCase", "FiniteLength", "LubricantData", "MaterialData",
           "RealBodies", "RollerSupport", "Scene", "SceneState", "StudySettings", "SurfaceRoughness",
           "Tribology", "WearSettings", "cam_disk_case", "contact_case", "finite_case", "load_scene",
           "roller_support_problems", "study_problem", "wear_table"]
