"""The bounds of a design variable against the stated range of the scene key it sets
(``base_radius`` -> ``[follower] base_radius_mm``, ...; :mod:`femcam.scene.ranges`)."""

from __future__ import annotations

import math

from ..errors import InputError
from ..scene.ranges import range_problem

#: the scene key each scalar variable sets: (table, key, factor SI -> key unit, key unit, the
#: ``--vary`` name); its
#: bounds must lie in the key's stated range (femcam.scene.ranges), the scene's own rule
SCENE_KEYS = {"base_radius": ("follower", "base_radius_mm", 1e3, "mm", "base_radius_mm"),
              "roller_radius": ("follower", "roller_radius_mm", 1e3, "mm", "roller_radius_mm"),
              "rise_angle": ("program.segment", "beta_deg", 180.0 / math.pi, "deg", "rise_angle_deg")}


def check_scene_range(v) -> None:
    """Refuse a scalar variable whose bounds leave the stated range of the scene key it sets
    (``base_radius`` -> ``[follower] base_radius_mm``, ...): an optimum there is a design no
    scene may hold (a 5 m cam where the scene caps the key at 1000 mm).

    Parameters
    ----------
    v : Variable
        The variable (SI bounds).

    Raises
    ------
    InputError
        A bound outside the key's range; the message gives the bounds in the key's unit (as
        ``--vary`` takes them) and the range with its source.
    """
    if v.name not in SCENE_KEYS:
        return
    table, key, f, unit, flag = SCENE_KEYS[v.name]
    for which, x in (("LO", v.lower * f), ("HI", v.upper * f)):
        problem = range_problem(table, key, x, unit, "pos")
        if problem:
            raise InputError(f"--vary {flag} {which} = {x:g} {unit} (design variable {v.name}, bounds "
                             f"{v.lower * f:g}:{v.upper * f:g} {unit}): the scene key [{table}] {key} "
                             f"{problem}")
