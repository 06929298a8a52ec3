"""The finite-length contact of a roller (femcam.halfspace; docs/halfspace.md) as the scene hands
it on: :class:`FiniteLength`, in SI, built by the scene loader (:mod:`femcam.scene.follower`)
from ``[follower] roller_width_mm``, ``crown``, ``crown_radius_mm``, ``crown_drop_um``,
``edge_radius_mm``, ``misalignment_deg`` and ``[cam] face_width_mm``.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..halfspace.crown import RollerProfile

#: the roller-profile keys of :class:`FiniteLength` (the widths aside)
SHAPE_KEYS = ("crown", "crown_radius", "crown_drop", "edge_radius", "misalignment")


@dataclass(frozen=True, kw_only=True)
class FiniteLength:
    """A roller's finite-length contact in SI; a roller-profile value is None when its scene key
    is not given (the :class:`~femcam.halfspace.RollerProfile` default then applies).

    Parameters
    ----------
    roller_width : float
        Roller width (m; ``[follower] roller_width_mm``, default ``face_width_mm``).
    cam_width : float
        Cam face width (m; ``[cam] face_width_mm``, default ``[follower] face_width_mm``).
    crown : str or None
        ``"none"``, ``"circular"`` or ``"logarithmic"`` (``[follower] crown``).
    crown_radius : float or None
        Circular crown radius (m; ``crown_radius_mm``).
    crown_drop : float or None
        Crown drop at the roller end (m; ``crown_drop_um``).
    edge_radius : float or None
        Edge radius (m; ``edge_radius_mm``).
    misalignment : float or None
        Axis tilt (rad; ``misalignment_deg``).
    """

    roller_width: float
    cam_width: float
    crown: str | None = None
    crown_radius: float | None = None
    crown_drop: float | None = None
    edge_radius: float | None = None
    misalignment: float | None = None

    @property
    def shaped(self) -> bool:
        """True when a crown, edge radius or misalignment key is given (even a zero one)."""
        return any(getattr(self, k) is not None for k in SHAPE_KEYS)

    def roller_profile(self) -> RollerProfile:
        """The roller's axial profile (:class:`~femcam.halfspace.RollerProfile`, m, rad).

        Returns
        -------
        femcam.halfspace.RollerProfile
            Width ``roller_width``; the keys not given at their defaults (no crown, no edge
            radius, aligned).
        """
        return RollerProfile(width=self.roller_width, crown=self.crown or "none",
                             crown_radius=self.crown_radius, crown_drop=self.crown_drop,
                             edge_radius=self.edge_radius or 0.0, misalignment=self.misalignment or 0.0)
