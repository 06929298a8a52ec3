"""The contact pair a physics package needs from a scene: :class:`ContactPair` (the two
materials, the contact length, the plane model, the friction), built by :attr:`Scene.pair`, so
that femcam.bodies, femcam.layers and the contact record :class:`femcam.scene.case.ContactCase`
take it instead of the whole scene.
"""

from __future__ import annotations

from dataclasses import dataclass

from .. import _validate
from ..materials import Material


@dataclass(frozen=True, kw_only=True)
class ContactPair:
    """The cam-follower contact of a scene in SI (:attr:`femcam.scene.Scene.pair`).

    Parameters
    ----------
    cam, roller : femcam.materials.Material
        Cam and follower materials (Pa; ``[materials.cam]``, ``[materials.roller]``).
    length : float
        Axial contact length (m; ``[follower] face_width_mm``).
    plane : {"strain", "stress"}
        Plane model (``[contact] plane``).
    mu : float
        Friction coefficient (-; ``[contact] friction``).
    sliding : {"+x", "-x"} or None
        Direction of the friction traction on the cam (``[contact] sliding``); None: not given
        (``+x`` where a direction is needed).
    """

    cam: Material
    roller: Material
    length: float
    plane: str = "strain"
    mu: float = 0.0
    sliding: str | None = None

    def __post_init__(self):
        _validate.instance("cam", self.cam, Material, "a femcam.materials.Material")
        _validate.instance("roller", self.roller, Material, "a femcam.materials.Material")
        _validate.positive("length", self.length, "m")
        _validate.nonnegative("mu", self.mu)
