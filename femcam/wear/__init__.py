"""Wear: seed 000's Archard/RMS estimate reproduced, and femcam's local wear-depth map.

* :mod:`.archard` -- ``W = k L S``, ``k = K / H`` (k in m^3/(N m), K dimensionless, H in Pa).
* :mod:`.seed000` -- seed 000's Table 3 (v_rms, S = h v_rms/v_rms,SHM, W = K L S/H) for every
  motion law, closed form and quadrature; peak jerk and junction continuity.
* :mod:`.slip` -- sliding speed at the contact per follower type (knife-edge, knife-edge with a
  tip radius, flat-faced, roller with a slide-to-roll ratio or the inertia-limited slip model).
* :mod:`.map` -- Archard depth ``h(x) = k int p v_slip dt`` on the cam and follower surfaces;
  the roller's drift from one revolution to the next (:func:`drift_sum`).
* :mod:`.surface` -- the closed forms of the map: load per unit length, depth per pass, the
  exact depth of a moving Hertz contact on a grid, the drift sum.
* :mod:`.inputs` -- the per-angle contact columns of the map (``theta, a, p0, Fc``) from a sweep
  result or a mapping, with the missing-pressure policy (raise, skip with a warning, zero).
* :mod:`.axial` -- the wear map of a finite-length roller laid down by its most loaded slice
  (half-space strip of :mod:`femcam.halfspace`).
* :mod:`.evolution` -- the profile worn in blocks of cycles (wear -> worn curvature and lift ->
  force and Hertz pressure -> wear), explicit Euler, and its convergence in the block size.
* :mod:`.options` -- a scene's ``[wear]`` table checked (units in key names) and the wear
  coefficient used, with where it came from.

numpy/scipy only.
"""

from .archard import archard_volume, dimensional_coefficient, dimensionless_coefficient
from .evolution import (
    ConvergenceTable,
    EvolutionCase,
    EvolutionResult,
    convergence_table,
    evolution_case,
    evolve,
    worn_curvature,
)
from .map import (
    WearInputWarning,
    WearMap,
    depth_per_pass,
    drift_sum,
    surface_depth,
    wear_depth_per_angle,
    wear_map,
)
from .options import wear_coefficient_info
from .seed000 import Seed000Inputs, Seed000Table, format_table3, rms_velocity, seed000_table
from .slip import (
    SlipResult,
    flat_faced,
    follower_slip,
    knife_edge,
    radiused_tip,
    roller_inertia,
    roller_srr,
)

__all__ = [
    "archard_volume", "dimensional_coefficient", "dimensionless_coefficient",
    "ConvergenceTable", "EvolutionCase", "EvolutionResult", "convergence_table", "evolution_case", "evolve",
    "worn_curvature",
    "WearInputWarning", "WearMap", "depth_per_pass", "drift_sum", "surface_depth", "wear_depth_per_angle",
    "wear_map", "wear_coefficient_info",
    "Seed000Inputs", "Seed000Table", "format_table3", "rms_velocity", "seed000_table",
    "SlipResult", "flat_faced", "follower_slip", "knife_edge", "radiused_tip", "roller_inertia",
    "roller_srr",
]
