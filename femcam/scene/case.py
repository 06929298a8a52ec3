"""One scene's contact at cam angles as a typed record (:class:`ContactCase`): what the physics
packages (femcam.assess) read instead of the whole :class:`~femcam.scene.Scene`.

:func:`contact_case` is the adapter: it runs the analytic chain of the scene at the angles (for
a knife edge with a tip radius, of the cam cut for the radiused tip: a roller of that radius
that does not turn, Johnson 1985 §4.3) and hands on the records a contact computation needs.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..errors import InputError
from ..loads import ArmDynamics, FollowerDynamics
from ..profile import RollerFollower
from .bodies import CamShaft
from .pair import ContactPair
from .state import Scene, SceneState
from .tribology import Tribology
from .wear import WearSettings

#: uniform angles over one revolution of :attr:`ContactCase.revolution` (the inertia-limited
#: roller model integrates the roller's spin over a whole revolution)
REVOLUTION_N = 720
#: the angles of :func:`contact_case` when none are given (one revolution, 1 deg apart)
DEFAULT_N = 360


@dataclass(frozen=True, kw_only=True)
class ContactCase:
    """A scene's contact at cam angles (keyword-only; built by :func:`contact_case`), SI units.

    Parameters
    ----------
    name : str
        The scene's name.
    where : str
        The scene as errors name it (its file, or its name).
    follower : object
        The scene's follower (m; a knife edge stays a knife edge, see ``state``).
    pair : femcam.scene.pair.ContactPair
        The contact pair (``Scene.pair``: cam and follower materials in Pa, axial contact length
        in m, plane model, friction coefficient, sliding direction).
    omega : float
        Cam speed (rad/s).
    dynamics : femcam.loads.FollowerDynamics or femcam.loads.ArmDynamics
        The follower train's rigid dynamics (kg, N/m, N, N s/m; an arm's about its pivot).
    tip_radius : float or None
        Knife-edge tip radius (m); None: not a knife edge, or not given.
    tribology : femcam.scene.tribology.Tribology
        The assessment data.
    wear : femcam.scene.wear.WearSettings
        The ``[wear]`` settings.
    state : femcam.scene.SceneState
        The analytic chain at the case's angles (rad); for a knife edge with a tip radius, of
        the cam cut for the radiused tip.
    revolution : femcam.scene.SceneState or None
        The same on :data:`REVOLUTION_N` uniform angles over one revolution, for the
        inertia-limited roller model (``wear.roller_model == "inertia"`` on a translating
        roller); None otherwise.
    """

    name: str
    where: str
    follower: object
    pair: ContactPair
    omega: float
    dynamics: FollowerDynamics | ArmDynamics
    tip_radius: float | None
    tribology: Tribology
    wear: WearSettings
    state: SceneState
    revolution: SceneState | None = None

    def __post_init__(self):
        _validate.instance("tribology", self.tribology, Tribology, "a femcam.scene.tribology.Tribology")
        _validate.instance("wear", self.wear, WearSettings, "a femcam.scene.wear.WearSettings")
        _validate.instance("state", self.state, SceneState, "a femcam.scene.SceneState")
        _validate.optional(_validate.instance, "revolution", self.revolution, SceneState,
                           "a femcam.scene.SceneState or None")
        _validate.instance("pair", self.pair, ContactPair, "a femcam.scene.pair.ContactPair (Scene.pair)")
        _validate.instance("dynamics", self.dynamics, FollowerDynamics | ArmDynamics,
                           "a femcam.loads.FollowerDynamics or ArmDynamics")
        _validate.record("follower", self.follower, "a femcam follower (femcam.profile)", "kind", "Rb")
        _validate.optional(_validate.positive, "tip_radius", self.tip_radius, "m")

    def __repr__(self) -> str:
        """The scene name, the follower kind and the angles (a compact line)."""
        return (f"ContactCase({self.name!r}, {getattr(self.follower, 'kind', '?')}, "
                f"{self.state.theta.size} angles)")

    @property
    def theta(self) -> np.ndarray:
        """The case's cam angles (rad)."""
        return self.state.theta


def tip_scene(scene: Scene, tip_radius: float | None) -> Scene:
    """The scene whose cam is cut for a radiused knife-edge tip.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene.
    tip_radius : float or None
        Tip radius (m); knife-edge followers only.

    Returns
    -------
    femcam.scene.Scene
        A knife-edge scene with a roller of radius ``tip_radius`` (which the slip model keeps
        from turning); any other follower: the scene itself.

    Raises
    ------
    InputError
        A tip radius for a follower that is not a knife edge, or none for a knife edge.
    """
    if not scene.follower.needs_tip:
        if tip_radius is not None:
            raise InputError(f"tip radius = {tip_radius * 1e3:g} mm: applies to knife-edge followers only "
                             f"(this scene's follower is a {scene.follower.kind} follower)")
        return scene
    if tip_radius is None:
        raise InputError("follower type = knife_edge: a sharp tip has no contact width, so the contact "
                         "pressure and the wear depth are undefined; give the tip radius: scene [follower] "
                         "tip_radius_mm (mm) or --tip-radius-mm (mm)")
    f = scene.follower
    return dataclasses.replace(scene, follower=RollerFollower(Rb=f.Rb, Rr=tip_radius, e=f.e))


def contact_case(scene: Scene, theta=None, *, tip_radius: float | None = None) -> ContactCase:
    """The :class:`ContactCase` of ``scene`` at cam angles ``theta``.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene.
    theta : float or array_like of float, optional
        Cam angles (rad); default :data:`DEFAULT_N` uniform angles over one revolution.
    tip_radius : float, optional
        Knife-edge tip radius (m); default the scene's ``[follower] tip_radius_mm`` (a knife
        edge without one: the state of the sharp edge, ``tip_radius`` None).

    Returns
    -------
    ContactCase
        The records and the analysed state.

    Raises
    ------
    InputError
        A tip radius that is not > 0 (knife edge) or given for another follower; more angles
        than :meth:`Scene.analyse` takes.
    UndercutError
        An undercut cam.
    """
    _validate.record("scene", scene, "a femcam.scene.Scene", "analyse", "tribology", "wear")
    if theta is None:
        theta = np.linspace(0.0, 2.0 * math.pi, DEFAULT_N, endpoint=False)
    f = scene.follower
    tip = _validate.optional(_validate.positive, "tip_radius", tip_radius, "m")
    if tip is None and f.needs_tip:
        tip = scene.tip_radius
    geo = tip_scene(scene, tip) if tip is not None else scene  # a knife edge: the cam cut for its tip
    revolution = None
    if scene.wear.roller_model == "inertia" and getattr(f, "translating_roller", False):
        revolution = geo.analyse(np.linspace(0.0, 2.0 * math.pi, REVOLUTION_N, endpoint=False))
    return ContactCase(name=scene.name, where=scene.source_path or scene.name, follower=f, pair=scene.pair,
                       omega=scene.omega, dynamics=scene.dynamics, tip_radius=tip if f.needs_tip else None,
                       tribology=scene.tribology, wear=scene.wear, state=geo.analyse(theta),
                       revolution=revolution)


# --- the cam on its shaft (femcam.bodies.cam_rows, cam_study) ---------------------------------

#: uniform angles over one revolution of :attr:`CamDiskCase.revolution` (the disk's outline)
OUTLINE_N = 720


@dataclass(frozen=True, kw_only=True)
class CamDiskCase:
    """A scene's cam on its shaft (keyword-only; built by :func:`cam_disk_case`), SI units: what
    the cam-disk functions of femcam.bodies (``cam_rows``, ``cam_study``) read instead of the
    scene; the states at the angles they solve (:meth:`Scene.analyse`) are passed beside it.

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
