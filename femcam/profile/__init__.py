"""Follower geometry: cam surface, pressure angle, radius of curvature, smallest base circle.

Modules: ``geometry`` (the followers, :func:`cam_profile` and the pure formulas, with the frames,
sign conventions and the symbol table) and ``base_radius`` (:func:`min_base_radius`)
``oscillating`` (the oscillating roller follower) and ``pad`` (the curved-pad oscillating
follower, which slides).
"""

from .base_radius import RB_MARGIN, BaseRadiusResult, min_base_radius
from .geometry import (
    FOLLOWER_KINDS,
    CamProfile,
    FlatFacedFollower,
    Follower,
    KnifeEdgeFollower,
    RollerFollower,
    bool_intervals,
    cam_profile,
    flat_face_radius,
    make_follower,
    pitch_curvature,
    pressure_angle,
)
from .oscillating import (
    DIRECTIONS,
    ArmGeometry,
    OscillatingRollerFollower,
    arm_geometry,
    min_base_radius_oscillating,
    oscillating_profile,
)
from .pad import OscillatingPadFollower, PadSpeeds

__all__ = ["DIRECTIONS", "FOLLOWER_KINDS", "RB_MARGIN", "ArmGeometry", "BaseRadiusResult",
           "CamProfile", "FlatFacedFollower", "Follower", "KnifeEdgeFollower",
           "OscillatingPadFollower", "OscillatingRollerFollower", "PadSpeeds", "RollerFollower",
           "arm_geometry", "bool_intervals",
           "cam_profile", "flat_face_radius", "make_follower", "min_base_radius",
           "min_base_radius_oscillating", "oscillating_profile", "pitch_curvature", "pressure_angle"]
