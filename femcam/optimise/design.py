r"""Design variables of a cam optimisation and the scene variant they describe.

A design is a point ``x`` of named, bounded, continuous variables (SI). :class:`Design` maps
it onto a scene through public constructors only (``dataclasses.replace`` on the follower,
a new :class:`~femcam.kinematics.CamProgram`), so the scene loader is never touched.

Symbols
-------
=============  ==============================================  =====  ============================
symbol         meaning                                         unit   source
=============  ==============================================  =====  ============================
Rb             base-circle radius (``base_radius``)            m      Norton, *Design of
                                                                      Machinery*, ch. 8
Rr             roller radius (``roller_radius``)               m      same
beta           angle of every rise and fall (``rise_angle``)   rad    same
n              degree of the Bezier rise                       -      seed 002 eq. 1
c              derivatives that vanish at each end (v, a, j)   -      Farin, *Curves and Surfaces
                                                                      for CAGD*, ch. 5
P_i            Bezier ordinates; ``control_point_i`` free       -      seed 002 eqs. 12-14
=============  ==============================================  =====  ============================

End continuity of a Bezier rise
-------------------------------
The k-th derivative at ``u = 0`` is ``n!/(n-k)! Delta^k P_0``, so ``v = a = ... = 0`` (c
derivatives) at ``u = 0`` if and only if ``P_0 = ... = P_c = 0``, and at ``u = 1`` if and only
if ``P_{n-c} = ... = P_n = 1``. Those ordinates stay fixed; only ``P_{c+1} ... P_{n-c-1}``
move, so every design meets the dwells with the continuity the law needs, to round-off.
Degree 9 with ``c = 2`` (the default) contains seed 002's degree-5, 7 and 9 laws (degree
elevation keeps the end zeros) and the 3-4-5 polynomial (= seed 002 degree 5).

Rise angle
----------
``rise_angle`` sets every rise and fall segment to ``beta``; the dwells are scaled by one
common factor so the segments still sum to 2 pi (the seed 002 model: rise, dwell, mirrored
fall, dwell).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..errors import InputError
from ..kinematics import CamProgram, law
from .bounds import check_scene_range

__all__ = ["Variable", "BezierRise", "Design", "VARIABLE_UNITS"]

#: scalar variables and their SI unit (control points: ``control_point_<i>``, dimensionless)
VARIABLE_UNITS = {"base_radius": "m", "roller_radius": "m", "rise_angle": "rad"}
@dataclass(frozen=True, kw_only=True)
class Variable:
    """One continuous design variable (SI) and its bounds.

    Parameters
    ----------
    name : str
        ``"base_radius"`` (m), ``"roller_radius"`` (m), ``"rise_angle"`` (rad) or
        ``"control_point_<i>"`` (a free interior Bezier ordinate, dimensionless).
    lower, upper : float
        Bounds, ``lower < upper`` (SI).
    start : float or None
        First starting value; default the scene's value clipped to the bounds.
    """

    name: str
    lower: float
    upper: float
    start: float | None = None

    def __post_init__(self):
        unit = unit_of(self.name)
        lo = _validate.number(f"{self.name} lower bound", self.lower, unit)
        hi = _validate.number(f"{self.name} upper bound", self.upper, unit)
        if not lo < hi:
            raise InputError(f"{self.name} bounds = [{lo:g}, {hi:g}] {unit}: empty or inverted "
                             "(must have lower < upper)")
        if self.start is not None:
            _validate.in_range(f"{self.name} start", self.start, lo, hi, unit)


@dataclass(frozen=True, kw_only=True)
class BezierRise:
    """The family of Bezier rises whose interior ordinates are design variables.

    Parameters
    ----------
    degree : int
        Degree ``n`` of the Bernstein polynomial (>= 2 c + 2 so one ordinate is free).
    zero_derivatives : int
        ``c``: v, a (, j, ...) that vanish at both ends; 2 = finite jerk against the dwells
        (as 3-4-5 and seed 002 degree 5), 3 = zero jerk (seed 002 degree 7).
    """

    degree: int = 9
    zero_derivatives: int = 2

    def __post_init__(self):
        c = _validate.integer("zero_derivatives", self.zero_derivatives, 1)
        _validate.integer("degree", self.degree, 2 * c + 2)

    @property
    def free(self) -> tuple[int, ...]:
        """Indices of the free ordinates ``c+1 ... n-c-1``."""
        c, n = self.zero_derivatives, self.degree
        return tuple(range(c + 1, n - c))

    def control_points(self, free_values) -> np.ndarray:
        """All ``n + 1`` ordinates: the fixed ends (0 ... 0, 1 ... 1) and ``free_values``.

        Parameters
        ----------
        free_values : array_like, shape (len(free),)
            Free ordinates (dimensionless).

        Returns
        -------
        ndarray, shape (n + 1,)
            Control ordinates (dimensionless).
        """
        P = np.zeros(self.degree + 1)
        P[self.degree - self.zero_derivatives:] = 1.0
        P[list(self.free)] = np.asarray(free_values, float)
        return P

    def default_free(self) -> np.ndarray:
        """Free ordinates evenly spaced in (0, 1): the starting law when the scene gives none.

        Returns
        -------
        ndarray, shape (len(free),)
            Ordinates ``1/(m+1) ... m/(m+1)`` (dimensionless).
        """
        m = len(self.free)
        return np.arange(1, m + 1) / (m + 1.0)


def unit_of(name: str) -> str:
    """Unit of a design variable (``""`` for a control point).

    Parameters
    ----------
    name : str
        Variable name.

    Returns
    -------
    str
        SI unit.

    Raises
    ------
    InputError
        An unknown variable name (with the accepted names).
    """
    if name in VARIABLE_UNITS:
        return VARIABLE_UNITS[name]
    if name.startswith("control_point_") and name[len("control_point_"):].isdigit():
        return ""
    raise InputError(f"design variable {name!r}: unknown; use one of {sorted(VARIABLE_UNITS)} or "
                     "control_point_<i> (a free interior Bezier ordinate)")


@dataclass(frozen=True)
class Design:
    """The map from a design vector ``x`` (SI, ordered as ``variables``) to a scene variant.

    Parameters
    ----------
    scene : femcam.scene.Scene
        The base scene.
    variables : tuple of Variable
        The design variables.
    bezier : BezierRise or None
        The Bezier family when a ``control_point_<i>`` is a variable (else None).
    """

    scene: object
    variables: tuple
    bezier: BezierRise | None

    def __post_init__(self):
        names = [v.name for v in self.variables]
        if not names:
            raise InputError("variables = []: give at least one design variable")
        if len(set(names)) != len(names):
            raise InputError(f"variables = {names}: a variable is given twice")
        for v in self.variables:
            check_scene_range(v)   # femcam.optimise.bounds
        f = self.scene.follower
        if f.flat_face:
            raise InputError("follower type = flat_faced: femcam.optimise handles roller and knife-edge "
                             "followers")
        if "roller_radius" in names and not f.translating_roller:
            raise InputError(f"design variable 'roller_radius': this scene's follower is a {f.kind} follower")
        cps = [n for n in names if n.startswith("control_point_")]
        if cps:
            free = self.bezier.free
            for n in cps:
                i = int(n[len("control_point_"):])
                if i not in free:
                    raise InputError(f"design variable {n!r}: not a free ordinate of a degree-"
                                     f"{self.bezier.degree} Bezier rise with {self.bezier.zero_derivatives} "
                                     f"zero derivatives at each end (free: control_point_{free[0]} .. "
                                     f"control_point_{free[-1]})")
        if "rise_angle" in names:
            motion = [s for s in self.scene.program.segments if s.law is not None]
            dwell = sum(s.beta for s in self.scene.program.segments if s.law is None)
            hi = self.variables[names.index("rise_angle")].upper
            if dwell <= 0.0 or len(motion) * hi >= 2.0 * math.pi:
                raise InputError(f"rise_angle upper bound = {math.degrees(hi):g} deg: {len(motion)} "
                                 "rise/fall segments of that angle leave no dwell to absorb the change "
                                 "(the segments must sum to 360 deg)")

    @property
    def names(self) -> tuple[str, ...]:
        """Variable names, in the order of ``x``."""
        return tuple(v.name for v in self.variables)

    def base_free(self) -> np.ndarray:
        """Free Bezier ordinates of the base scene: its rise law's, degree-elevated to the family's
        degree (Farin ch. 5: the curve is unchanged), if that law is of the family.

        Returns
        -------
        ndarray, shape (len(free),)
            Free ordinates (dimensionless); :meth:`BezierRise.default_free` otherwise.
        """
        lw = next(s.law for s in self.scene.program.segments if s.law is not None)
        P = getattr(lw, "control_points", None)
        while P is not None and len(P) < self.bezier.degree + 1:
            m = len(P)  # elevate degree m-1 -> m: Q_i = i/m P_{i-1} + (1 - i/m) P_i
            i = np.arange(1, m)
            P = np.r_[P[0], i / m * P[:-1] + (1.0 - i / m) * P[1:], P[-1]]
        if P is not None and len(P) == self.bezier.degree + 1:
            cand = np.asarray(P, float)
            if np.allclose(self.bezier.control_points(cand[list(self.bezier.free)]), cand, atol=1e-12):
                return cand[list(self.bezier.free)]
        return self.bezier.default_free()

    def base_value(self, name: str) -> float:
        """The base scene's value of a variable.

        Parameters
        ----------
        name : str
            Variable name.

        Returns
        -------
        float
            Its value in the base scene (SI).
        """
        f = self.scene.follower
        if name == "base_radius":
            return float(f.Rb)
        if name == "roller_radius":
            return float(f.Rr)
        if name == "rise_angle":
            return float(next(s.beta for s in self.scene.program.segments if s.law is not None))
        i = self.bezier.free.index(int(name[len("control_point_"):]))
        return float(self.base_free()[i])

    def start(self) -> np.ndarray:
        """The first starting point: each variable's ``start``, else the scene's value, clipped.

        Returns
        -------
        ndarray, shape (n_variables,)
            Design vector (SI).
        """
        return np.array([v.start if v.start is not None else
                         min(max(self.base_value(v.name), v.lower), v.upper) for v in self.variables])

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """The bounds.

        Returns
        -------
        lower, upper : ndarray, shape (n_variables,)
            Bounds (SI).
        """
        return (np.array([v.lower for v in self.variables]), np.array([v.upper for v in self.variables]))

    def control_points(self, x) -> np.ndarray | None:
        """All Bezier ordinates of the design.

        Parameters
        ----------
        x : array_like, shape (n_variables,)
            Design vector (SI).

        Returns
        -------
        ndarray, shape (n + 1,) or None
            Ordinates (dimensionless); None when no control point is a variable.
        """
        if self.bezier is None or not any(n.startswith("control_point_") for n in self.names):
            return None
        free = self.base_free().copy()
        for n, xi in zip(self.names, x, strict=True):
            if n.startswith("control_point_"):
                free[self.bezier.free.index(int(n[len("control_point_"):]))] = xi
        return self.bezier.control_points(free)

    def follower(self, x):
        """The follower of the design.

        Parameters
        ----------
        x : array_like, shape (n_variables,)
            Design vector (SI).

        Returns
        -------
        RollerFollower or KnifeEdgeFollower
            ``dataclasses.replace`` of the scene's follower (m).
        """
        kw = {}
        for n, xi in zip(self.names, x, strict=True):
            if n == "base_radius":
                kw["Rb"] = float(xi)
            elif n == "roller_radius":
                kw["Rr"] = float(xi)
        return dataclasses.replace(self.scene.follower, **kw) if kw else self.scene.follower

    def program(self, x) -> CamProgram:
        """The cam program of the design: new Bezier law and/or rise angle; dwells rescaled.

        Parameters
        ----------
        x : array_like, shape (n_variables,)
            Design vector (SI).

        Returns
        -------
        femcam.kinematics.CamProgram
            The program (rad, m).
        """
        segs = list(self.scene.program.segments)
        P = self.control_points(x)
        if P is not None:
            lw = law("bezier", control_points=P)
            segs = [s if s.law is None else dataclasses.replace(s, law=lw) for s in segs]
        if "rise_angle" in self.names:
            beta = float(x[self.names.index("rise_angle")])
            motion = sum(1 for s in segs if s.law is not None)
            dwell = sum(s.beta for s in segs if s.law is None)
            scale = (2.0 * math.pi - motion * beta) / dwell
            segs = [dataclasses.replace(s, beta=beta) if s.law is not None
                    else dataclasses.replace(s, beta=s.beta * scale) for s in segs]
        return CamProgram(segs) if segs != list(self.scene.program.segments) else self.scene.program

    def apply(self, x):
        """The scene variant at ``x``.

        Parameters
        ----------
        x : array_like, shape (n_variables,)
            Design vector (SI).

        Returns
        -------
        femcam.scene.Scene
            ``dataclasses.replace(scene, program=..., follower=...)``.
        """
        return dataclasses.replace(self.scene, program=self.program(x), follower=self.follower(x))
