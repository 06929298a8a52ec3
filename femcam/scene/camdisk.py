"""One scene's cam on its shaft as a typed record (:class:`CamDiskCase`): what the cam-disk
functions of femcam.bodies (``cam_rows``, ``cam_study``) read instead of the whole
:class:`~femcam.scene.Scene`.

:func:`cam_disk_case` is the adapter: it hands on the follower, the contact pair, the
``[cam] bore_mm`` record, the cam's yield strength and the analytic chain over one revolution
(the cam outline the disk is meshed from, and the angle of the largest contact force). The
states at the angles a caller solves (:meth:`Scene.analyse`) are passed beside it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..errors import InputError
from .bodies import CamShaft
from .pair import ContactPair
from .state import Scene, SceneState

#: uniform angles over one revolution of :attr:`CamDiskCase.revolution` (the disk's outline)
OUTLINE_N = 720


@dataclass(frozen=True, kw_only=True)
class CamDiskCase:
    """A scene's cam on its shaft (keyword-only; built by :func:`cam_disk_case`), SI units.

    Parameters
    ----------
    follower : object
        The scene's follower (m; the disk model needs a translating roller, its ``Rr``).
    pair : femcam.scene.pair.ContactPair
        The contact pair (materials in Pa, face width in m, plane).
    revolution : femcam.scene.SceneState
        The analytic chain at uniform angles over one revolution (rad; the outline).
    shaft : femcam.scene.bodies.CamShaft or None
        ``[cam] bore_mm``, ``shaft_fit``, ``shaft_clearance_um``, ``[materials.shaft]`` (m, Pa);
        None: the scene gives no bore.
    cam_yield : float or None
        The cam's yield strength (Pa, ``[materials.cam] yield_strength_MPa``); None: not given.
    """

    follower: object
    pair: ContactPair
    revolution: SceneState
    shaft: CamShaft | None = None
    cam_yield: float | None = None

    def __post_init__(self):
        _validate.record("follower", self.follower, "a femcam follower (femcam.profile)", "kind", "Rb")
        _validate.instance("pair", self.pair, ContactPair, "a femcam.scene.ContactPair")
        _validate.optional(_validate.instance, "shaft", self.shaft, CamShaft,
                           "a femcam.scene.CamShaft or None")
        _validate.optional(_validate.positive, "cam_yield", self.cam_yield, "Pa")
        _validate.instance("revolution", self.revolution, SceneState, "a femcam.scene.SceneState")

    def __repr__(self) -> str:
        """The follower kind, the bore and the outline's angles (a compact line)."""
        bore = "no bore" if self.shaft is None else f"bore {self.shaft.bore * 1e3:g} mm"
        n = self.revolution.theta.size
        return f"CamDiskCase({getattr(self.follower, 'kind', '?')}, {bore}, {n} outline angles)"


def cam_disk_case(scene: Scene, *, n_outline: int = OUTLINE_N) -> CamDiskCase:
    """The :class:`CamDiskCase` of ``scene``.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene.
    n_outline : int, optional
        Uniform angles over one revolution of :attr:`CamDiskCase.revolution` (>= 16).

    Returns
    -------
    CamDiskCase
        The records and the revolution.

    Raises
    ------
    InputError
        A follower that is not a translating roller (the disk model meshes the cam outline of a
        roller), ``n_outline`` not a whole number >= 16, or more angles than
        :meth:`Scene.analyse` takes.
    UndercutError
        An undercut cam.
    """
    _validate.record("scene", scene, "a femcam.scene.Scene", "analyse", "tribology", "bodies")
    n = _validate.integer("n_outline", n_outline, 16)
    if not getattr(scene.follower, "translating_roller", False):
        kind = getattr(scene.follower, "kind", "")
        raise InputError(f"follower type = {kind!r}: the cam disk model needs a roller follower")
    revolution = scene.analyse(np.linspace(0.0, 2 * math.pi, n, endpoint=False))
    return CamDiskCase(follower=scene.follower, pair=scene.pair, shaft=scene.bodies.cam,
                       cam_yield=scene.tribology.cam.yield_strength, revolution=revolution)
