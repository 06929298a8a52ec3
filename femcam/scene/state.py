"""The scene in SI (:class:`Scene`) and the analytic chain at cam angles (:class:`SceneState`):
kinematics -> profile -> contact force, with the dense undercut check of the whole cam.

Only numpy/scipy and the femcam analytic chain (kinematics, profile, loads, dynamics) are
imported.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from .. import _validate
from .._repr import compact_repr, span
from ..dynamics import TrainModel, periodic_response
from ..errors import ConvergenceError, InputError, UndercutError
from ..kinematics import CamProgram, law
from ..loads import ArmDynamics, FollowerDynamics, LoadResult, arm_contact_force, arm_lever, contact_force
from ..materials import Material
from ..profile import CamProfile, bool_intervals, cam_profile
from .bodies import RealBodies
from .finite import FiniteLength
from .layers import BodyLayers
from .origin import FrozenMapping, freeze
from .pair import ContactPair
from .study import StudySettings
from .tribology import Tribology
from .wear import WearSettings

#: angles of the dense undercut check of Scene.analyse over one revolution (0.05 deg apart)
UNDERCUT_CHECK_N = 7200
#: angles of the check inside each segment, ends included, however short the segment: a rise
#: over 0.01 deg falls between two of the uniform angles and is seen only at its own points
SEGMENT_CHECK_N = 257


def _dense_theta(program: CamProgram | None = None) -> np.ndarray:
    """The angles (rad, sorted, in [0, 2 pi)) of the whole-cam check: ``UNDERCUT_CHECK_N``
    uniform angles, plus ``SEGMENT_CHECK_N`` in each segment of ``program``."""
    th = np.linspace(0.0, 2.0 * math.pi, UNDERCUT_CHECK_N, endpoint=False)
    if program is None:
        return th
    u = np.linspace(0.0, 1.0, SEGMENT_CHECK_N)
    own = [t0 + sg.beta * u for t0, sg in zip(program.theta_starts, program.segments, strict=True)]
    return np.unique(np.mod(np.concatenate([th, *own]), 2.0 * math.pi))


@dataclass(frozen=True)
class SceneState:
    """The analytic chain at cam angles ``theta`` (built by :meth:`Scene.analyse`); SI units.

    Parameters
    ----------
    theta : ndarray, shape (n,), float
        Cam angles (rad).
    s, v, a, j : ndarray, shape (n,), float
        Lift (m), velocity (m/s), acceleration (m/s^2), jerk (m/s^3) at ``omega``; for an
        oscillating follower the roller centre's travel along its arc, ``L psi`` and its rates.
    s1, s2 : ndarray, shape (n,), float
        ds/dtheta (m/rad), d2s/dtheta2 (m/rad^2).
    phi : ndarray, shape (n,), float
        Pressure angle (rad).
    rho : ndarray, shape (n,), float
        Cam surface radius of curvature at the contact (m; < 0 concave, inf flat).
    Fc : ndarray, shape (n,), float
        Contact force (N; <= 0 at lift-off).
    liftoff : ndarray, shape (n,), bool
        Follower off the cam.
    contact_x, contact_y : ndarray, shape (n,), float
        Contact point in the cam frame (m).
    profile : femcam.profile.CamProfile
        The cam profile at ``theta`` (m, rad).
    loads : femcam.loads.LoadResult
        The contact force and lift-off (N).
    undercut_intervals : list of (float, float)
        Undercut angle intervals of the whole revolution (rad), from the dense check.
    """

    theta: np.ndarray
    s: np.ndarray
    v: np.ndarray
    a: np.ndarray
    j: np.ndarray
    s1: np.ndarray
    s2: np.ndarray
    phi: np.ndarray
    rho: np.ndarray
    Fc: np.ndarray
    liftoff: np.ndarray
    contact_x: np.ndarray
    contact_y: np.ndarray
    profile: CamProfile
    loads: LoadResult
    undercut_intervals: list = field(default_factory=list)

    def __repr__(self) -> str:
        """The angles, the ranges of phi, rho and Fc, lift-off and undercut counts (a compact line)."""
        return compact_repr(self, [
            f"{self.theta.size} angles {span(self.theta, 180 / np.pi, 'deg', '.5g')}",
            f"phi {span(self.phi, 180 / np.pi, 'deg')}",
            f"rho {span(self.rho, 1e3, 'mm')}",
            f"Fc {span(self.Fc, 1.0, 'N')}",
            f"lift-off {int(np.count_nonzero(self.liftoff))}",
            f"undercut {int(np.count_nonzero(self.undercut))}",
        ])

    @property
    def undercut(self) -> np.ndarray:
        """Undercut flags at the analysed angles ``theta`` (bool, shape (n,); see
        ``undercut_intervals`` for the whole revolution)."""
        return self.profile.undercut


@dataclass(frozen=True)
class Scene:
    """A cam-follower case in SI units (built by :func:`femcam.scene.load_scene`).

    Parameters
    ----------
    name : str
        Case name.
    program : femcam.kinematics.CamProgram
        The cam program (segment angles in rad, lifts in m).
    follower : RollerFollower, KnifeEdgeFollower or FlatFacedFollower
        Follower geometry (m).
    dynamics : femcam.loads.FollowerDynamics or femcam.loads.ArmDynamics
        Rigid-follower dynamics of seed 002 eq. 11 (kg, N/m, N, N s/m), or an oscillating
        arm's about its pivot (kg m^2, N m/rad, N m, N m s/rad).
    omega : float
        Cam speed (rad/s).
    cam, roller : femcam.materials.Material
        Cam and follower materials (Pa).
    length : float
        Axial contact length (face width / cam thickness, m).
    mu : float
        Friction coefficient (dimensionless); for a curved pad on an arm it also enters ``Fc``
        (the friction moment about the pivot, :meth:`analyse`).
    plane : str
        ``"strain"`` or ``"stress"``.
    sliding : str or None
        ``"+x"`` or ``"-x"``: direction of the friction traction on the cam. The sweep takes the
        traction from the mechanism (femcam.sweep.realcam); this key is an explicit override
        (full sliding in this direction at every angle).
    description, source : str
        Free text of the scene file.
    study : femcam.scene.study.StudySettings
        The checked study settings of [fe] and [sweep] (``a_over_h``, ``tolerance``, ``rtol``
        dimensionless; ``method``, ``angles_deg`` in deg, ``chunk_size``, ``vtk_every`` in
        angles, ``plots``; None where not given): a sweep uses them where its options leave
        None (:mod:`femcam.sweep.settings`).
    wear : femcam.scene.wear.WearSettings
        The [wear] table in SI (:mod:`femcam.wear.options` reads it).
    finite_length : femcam.scene.finite.FiniteLength or None
        The finite-length contact keys (femcam.halfspace) in SI; None without a face width.
    layers : tuple of femcam.scene.layers.BodyLayers
        Coating and case per body (SI, checked; :func:`femcam.layers.scene_layers` builds the
        models' ``Coating`` and ``Case`` from them); empty for uncoated, unhardened bodies.
    source_path : str
        The scene file ("" if built in code).
    tribology : femcam.scene.tribology.Tribology
        The assessment data in SI: ``lubricant``, ``surface`` (``cam_Ra`` ... in m),
        ``oil_temperature_C`` (degC), each body's material data (``yield_strength`` ... in Pa).
    origin : femcam.scene.origin.FrozenMapping
        The TOML as written, read-only (empty if built in code): for provenance (copying,
        hashing or varying the scene file), never read for physics.
    train : femcam.dynamics.TrainModel or None
        The elastic follower train of ``[dynamics] model = one_dof | two_dof`` (an arm's is
        referred to the roller's arc travel, femcam.dynamics.arm_train); None: rigid.
    steps_per_rev : int or None
        Time steps per revolution of the train response (None: its default).
    bodies : femcam.scene.bodies.RealBodies
        Real bodies (femcam.bodies): the roller on a pin or needles and the cam on its shaft
        (m, Pa); both None for the solid roller and the cam as a local body.
    tip_radius : float or None
        Knife-edge tip radius (m, ``[follower] tip_radius_mm``); None when not given
        (femcam.fe.followers).
    face_length : float or None
        Flat-face length (m, ``[follower] face_length_mm``); None when not given.
    """

    name: str
    program: CamProgram
    follower: object
    dynamics: FollowerDynamics
    omega: float
    cam: Material
    roller: Material
    length: float
    mu: float = 0.0
    plane: str = "strain"
    sliding: str | None = None
    description: str = ""
    source: str = ""
    study: StudySettings = field(default_factory=StudySettings)
    wear: WearSettings = field(default_factory=WearSettings)
    finite_length: FiniteLength | None = None
    layers: tuple[BodyLayers, ...] = ()
    source_path: str = ""
    tribology: Tribology = field(default_factory=Tribology)
    origin: FrozenMapping = field(default_factory=FrozenMapping, repr=False)
    train: TrainModel | None = None
    steps_per_rev: int | None = None
    bodies: RealBodies = field(default_factory=RealBodies)
    tip_radius: float | None = None
    face_length: float | None = None
    #: what the program was changed to after loading (:meth:`with_law`): ``(("law", name),
    #: (param, value), ...)`` (values frozen: lists as tuples), written into the copy of the scene
    #: file a sweep keeps (femcam.scene.override)
    overrides: tuple = field(default=(), repr=False, compare=False)

    def __post_init__(self):
        _validate.instance("Scene.tribology", self.tribology, Tribology)
        _validate.instance("Scene.wear", self.wear, WearSettings)
        if not isinstance(self.origin, FrozenMapping):  # the TOML as written, made read-only
            object.__setattr__(self, "origin", freeze(dict(self.origin)))
        object.__setattr__(self, "overrides", tuple((str(k), freeze(v)) for k, v in self.overrides))

    @property
    def rpm(self) -> float:
        """Cam speed (rpm)."""
        return self.omega * 60.0 / (2.0 * math.pi)

    @property
    def pair(self) -> ContactPair:
        """The contact pair (materials, length in m, plane, friction) the physics packages take."""
        return ContactPair(cam=self.cam, roller=self.roller, length=self.length, plane=self.plane,
                           mu=self.mu, sliding=self.sliding)

    @cached_property
    def _dense_undercut(self) -> tuple:
        """``(flags, message)`` of the dense undercut check on :func:`_dense_theta` (``message``:
        the :class:`~femcam.errors.UndercutError` text of :func:`~femcam.profile.cam_profile`,
        or None). Computed once per scene (the scene is immutable), not per :meth:`analyse`
        call (the sweep analyses chunk by chunk)."""
        dense = _dense_theta(self.program)
        dd = self.program.derivatives(dense)
        try:
            return cam_profile(self.follower, dense, dd.s, dd.s1, dd.s2).undercut, None
        except UndercutError as exc:
            flags = cam_profile(self.follower, dense, dd.s, dd.s1, dd.s2, allow_undercut=True).undercut
            return flags, str(exc)

    @cached_property
    def max_pressure_angle(self) -> tuple:
        """``(phi, theta)``: the largest ``|phi|`` over the whole cam (rad) and its cam angle
        (rad), from the dense check (every segment at its own points) refined to the maximum
        between the neighbouring check angles; computed once per scene."""
        dense = _dense_theta(self.program)

        def phi(th):
            dd = self.program.derivatives(th)
            return np.abs(cam_profile(self.follower, dd.theta, dd.s, dd.s1, dd.s2,
                                      allow_undercut=True).phi)

        f = phi(dense)
        i = int(np.argmax(f))
        lo, hi = dense[max(i - 1, 0)], dense[min(i + 1, dense.size - 1)]
        if hi > lo:  # |phi| is smooth inside a segment: the bounded maximum between neighbours
            from scipy.optimize import minimize_scalar  # lazy: scipy.optimize, 0.3-0.5 s to import

            res = minimize_scalar(lambda t: -float(phi(np.array([t]))[0]), bounds=(lo, hi),
                                  method="bounded", options={"xatol": 1e-12})
            if -res.fun > f[i]:
                return float(-res.fun), float(res.x)
        return float(f[i]), float(dense[i])

    @cached_property
    def dynamic_response(self):
        """Periodic response of the follower train (:class:`femcam.dynamics.DynamicsResult`),
        computed once per scene; None for the rigid model (eq. 11)."""
        if self.train is None:
            return None
        return periodic_response(self.train, self.program, self.omega, steps_per_rev=self.steps_per_rev)

    def undercut_check(self, theta=None, undercut=None) -> list:
        """Undercut intervals of the whole cam, found on a dense grid.

        The profile is checked on a dense grid of ``UNDERCUT_CHECK_N`` angles over one
        revolution (0.05 deg apart) and ``SEGMENT_CHECK_N`` inside each segment (so a segment
        shorter than the grid step is seen; computed once per scene) merged with ``theta``, so a narrow
        undercut band between coarse analysis angles is still found. Vectorised.

        Parameters
        ----------
        theta : array_like of float, optional
            Extra cam angles (rad, taken mod 2 pi).
        undercut : array_like of bool, optional
            The already computed undercut flags at ``theta`` (one per angle).

        Returns
        -------
        list of (float, float)
            ``[(start, end), ...]`` (rad, in [0, 2 pi)).

        Raises
        ------
        InputError
            ``undercut`` without one flag per angle of ``theta``.
        """
        dense, flags = _dense_theta(self.program), self._dense_undercut[0]
        if theta is None:
            return bool_intervals(dense, flags)
        extra = np.mod(np.ravel(np.asarray(theta, float)), 2.0 * math.pi)
        if undercut is None:
            de = self.program.derivatives(extra)
            undercut = cam_profile(self.follower, extra, de.s, de.s1, de.s2,
                                   allow_undercut=True).undercut
        undercut = np.ravel(np.asarray(undercut, bool))
        if undercut.size != extra.size:
            raise InputError(f"undercut has {undercut.size} flags: must have one per theta "
                             f"({extra.size} angles)")
        th = np.concatenate([dense, extra])
        order = np.argsort(th, kind="stable")
        return bool_intervals(th[order], np.concatenate([flags, undercut])[order])

    def analyse(self, theta, *, allow_undercut: bool = False) -> SceneState:
        """Kinematics, profile and contact force at cam angles ``theta``, vectorised.

        Undercut is a property of the whole cam, so besides ``theta`` the profile is checked on a
        dense grid over one revolution (:meth:`undercut_check`).

        ``Fc`` is seed 002's eq. 11 (rigid follower) unless ``[dynamics] model`` is one_dof or
        two_dof (an oscillating arm: its moment balance, or its train referred to the roller
        path): then it is the periodic contact force of the elastic train
        (:attr:`dynamic_response`, interpolated to ``theta``; free flight is ``liftoff``).
        A sliding pad on an arm adds the friction force's moment about the pivot,
        ``Fc (L cos phi + mu s_f d_t) = M`` (rigid or elastic arm; ``mu`` = :attr:`mu`, the
        sign from the mechanism's sliding velocity, not the ``[contact] sliding`` override).

        Parameters
        ----------
        theta : float or array_like of float
            Cam angles (rad).
        allow_undercut : bool
            Return the state of an undercut cam instead of raising.

        Returns
        -------
        SceneState
            SI values at ``theta``; ``undercut_intervals`` (rad, in [0, 2 pi)) of the whole cam.

        Raises
        ------
        UndercutError
            An undercut cam (angle ranges in degrees), unless ``allow_undercut=True``.
        ConvergenceError
            A train response that is not one-periodic.
        InputError
            More than :data:`femcam._validate.MAX_ANGLES` angles (memory, estimate in the message).
        """
        _validate.angle_count("theta", f"{np.size(theta)} angles", int(np.size(theta)), 241.0,
                              "Scene.analyse")   # before any work: bounded memory
        d = self.program.derivatives(theta)
        w = self.omega
        v, a, j = w * d.s1, w**2 * d.s2, w**3 * d.s3
        p = cam_profile(self.follower, d.theta, d.s, d.s1, d.s2, allow_undercut=allow_undercut)
        intervals = self.undercut_check(d.theta, p.undercut)
        if intervals and not allow_undercut:
            # cam_profile passed on theta, so the dense grid found it (and holds the message)
            raise UndercutError(f"{self._dense_undercut[1]} (found by the dense check on "
                                f"{UNDERCUT_CHECK_N} angles over one revolution and "
                                f"{SEGMENT_CHECK_N} in each segment; the analysed angles miss it)")
        if isinstance(self.dynamics, ArmDynamics):  # an arm: the pad's friction moment about the pivot
            L = self.follower.L
            lev = self.follower.friction_lever(d.s / L, d.s1 / L, d.s2 / L)
        if self.train is not None:  # the periodic train response at theta (an arm's: on its arc travel)
            res = self.dynamic_response
            if not res.converged:
                raise ConvergenceError(f"[dynamics] model = {res.model!r} at {self.rpm:g} rpm: {res.message}")
            r = res.load_result(d.theta, p.phi)
            if isinstance(self.dynamics, ArmDynamics) and self.mu > 0:  # Fc = M_c / D, D > 0: same lift-off
                arm_lever(L, p.phi, mu=self.mu, friction_lever=lev, theta=d.theta)
                r = dataclasses.replace(r, Fc=r.F_axial / (np.cos(p.phi) + self.mu * lev / L))
        elif isinstance(self.dynamics, ArmDynamics):  # oscillating arm: s, v, a are L psi and its rates
            r = arm_contact_force(self.dynamics, d.theta, d.s / L, v / L, a / L, L, p.phi, mu=self.mu,
                                  friction_lever=lev)
        else:
            r = contact_force(self.dynamics, d.theta, d.s, v, a, p.phi)
        return SceneState(theta=np.asarray(d.theta, float), s=d.s, v=v, a=a, j=j, s1=d.s1, s2=d.s2,
                          phi=p.phi, rho=p.rho, Fc=r.Fc, liftoff=r.liftoff, contact_x=p.contact_x,
                          contact_y=p.contact_y, profile=p, loads=r, undercut_intervals=intervals)

    def with_law(self, name: str, **params) -> Scene:
        """The same scene with every rise/fall segment using one motion law.

        Parameters
        ----------
        name : str
            Motion law name (:data:`femcam.kinematics.LAW_NAMES`).
        **params
            Law parameters (e.g. ``control_points`` of ``"bezier"``, normalised lift).

        Returns
        -------
        Scene
            A copy with the new program (dwells unchanged).
        """
        lw = law(name, **params)
        segs = [s if s.law is None else dataclasses.replace(s, law=lw) for s in self.program.segments]
        given = {**dict(self.overrides), "law": name, **params}
        return dataclasses.replace(self, program=CamProgram(segs), overrides=tuple(given.items()))
