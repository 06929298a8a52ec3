r"""The cam as a disk on its shaft: outline, bore, shaft and the contact frame of one angle.

Symbols (SI inside; mm only at the scene edge)

==============  ==========================================================  ====  ======================
symbol          meaning                                                     unit  source
==============  ==========================================================  ====  ======================
``outline``     cam surface points in the cam frame (cam centre at 0)        m     :mod:`femcam.profile`
``Rb``          shaft bore radius of the cam                                m     ``[cam] bore_mm``
``Rs``          shaft radius (``Rb - c``; ``c = 0``: line-to-line fit)       m     ``Rb`` (scene)
``r_min``       smallest outline radius (the base circle for a roller cam)  m     outline
``web``         ``r_min - Rb``: the thinnest ring of cam round the bore      m
``C``, ``n``    contact point and outward cam normal at one cam angle       m, -  :mod:`femcam.profile`
==============  ==========================================================  ====  ======================

Contact frame of one angle (the frame of :mod:`femcam.mesh`): ``x = (P - C) . t``,
``y = (P - C) . n`` with ``t = (n_y, -n_x)``, so the cam lies below ``y = 0`` and a point going
counter-clockwise round the cam centre over the contact moves towards ``-x``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..errors import InputError
from ..materials import STEEL, Material
from ..mesh import surface_height
from ..scene.bodies import SHAFT_CLEARANCE_MAX


def bore_error(Rb: float, condition: str) -> InputError:
    """The refusal of a bore, led by the scene key the user wrote in its own unit:
    ``[cam] bore_mm = 9.99 mm: ...`` (the bore radius ``Rb``, not the base radius).

    Parameters
    ----------
    Rb : float
        Bore radius [m].
    condition : str
        What it breaks, and what to change.

    Returns
    -------
    InputError
        The error (the caller raises it).
    """
    return InputError(f"[cam] bore_mm = {Rb * 1e3:.6g} mm: {condition}")


def _clearance_error(c: float, condition: str) -> InputError:
    """``[cam] shaft_clearance_um = ... um: ...`` (the radial clearance ``Rb - Rs``)."""
    return InputError(f"[cam] shaft_clearance_um = {c * 1e6:.6g} um: {condition}")

FITS = ("contact", "bonded")


def _check_outline(outline) -> np.ndarray:
    o = _validate.finite_array("outline", outline, "m")
    if o.ndim != 2 or o.shape[0] != 2 or o.shape[1] < 16:
        raise InputError(f"outline: shape {o.shape}: must be (2, N >= 16) finite points (m)")
    ang = np.arctan2(o[1], o[0])
    order = np.argsort(ang)
    return o[:, order]


@dataclass(frozen=True, kw_only=True)
class CamDisk:
    """The cam as a disk with its outline and a shaft bore (SI units).

    Parameters
    ----------
    outline : ndarray, shape (2, N)
        Cam surface points [m] in the cam frame (cam centre at 0), N >= 16; reordered
        counter-clockwise by polar angle.
    Rb : float
        Bore radius [m], below the smallest outline radius.
    Rs : float or None, optional
        Shaft radius [m]; default ``Rb`` (a line-to-line fit); the clearance ``Rb - Rs`` must
        be in [0, 0.05 Rb].
    fit : {"contact", "bonded"}, optional
        ``"contact"``: unilateral shaft-bore contact (the shaft carries no tension);
        ``"bonded"``: a frictionless radial tie (``Rs == Rb`` only).
    cam : Material, optional
        Cam material (default steel).
    shaft : Material or None, optional
        Shaft material (default steel); None for a rigid shaft.
    cam_yield : float or None, optional
        Tensile limit of the cam [Pa] flagged in results; None for no flag.

    Raises
    ------
    InputError
        A bad outline, a bore that does not fit, a clearance out of range or a bad ``fit``.
    """

    outline: np.ndarray
    Rb: float
    Rs: float | None = None
    fit: str = "contact"
    cam: Material = STEEL
    shaft: Material | None = STEEL
    cam_yield: float | None = None

    def __post_init__(self):
        object.__setattr__(self, "outline", _check_outline(self.outline))
        _validate.positive("Rb", self.Rb, "m")
        _validate.choice("fit", self.fit, FITS)
        Rs = self.Rb if self.Rs is None else _validate.positive("Rs", self.Rs, "m")
        object.__setattr__(self, "Rs", float(Rs))
        r_min = self.r_min
        if self.Rb >= r_min:
            raise bore_error(self.Rb, f"the bore does not fit: the smallest outline radius of the cam "
                                      f"is {r_min * 1e3:.4g} mm (bore radius {self.Rb * 1e3:.4g} mm)")
        c = self.Rb - Rs
        if c < 0 or c > SHAFT_CLEARANCE_MAX * self.Rb:
            c_max = SHAFT_CLEARANCE_MAX * self.Rb
            raise _clearance_error(c, f"the radial clearance bore - shaft must be in [0, "
                                      f"{SHAFT_CLEARANCE_MAX:g} x bore radius = {c_max * 1e6:.4g} um] "
                                      "(linearised gap)")
        if self.fit == "bonded" and c != 0.0:
            raise _clearance_error(c, "a bonded fit (shaft_fit = \"bonded\") needs no clearance")
        if self.cam_yield is not None:
            _validate.positive("cam_yield", self.cam_yield, "Pa")

    @property
    def r(self) -> np.ndarray:
        """Outline radii (m)."""
        return np.hypot(*self.outline)

    @property
    def r_min(self) -> float:
        """Smallest outline radius [m] (the base circle for a roller cam)."""
        return float(self.r.min())

    @property
    def web(self) -> float:
        """``r_min - Rb`` (m)."""
        return self.r_min - self.Rb

    @property
    def c(self) -> float:
        """Radial clearance ``Rb - Rs`` [m]."""
        return self.Rb - self.Rs


def outline_from_state(state) -> np.ndarray:
    """The cam surface in the cam frame from the analytic chain over one revolution.

    Parameters
    ----------
    state : femcam.scene.SceneState
        ``Scene.analyse`` at equally spaced cam angles over [0, 2 pi) (a roller follower).

    Returns
    -------
    ndarray, shape (2, n)
        Cam surface points ``(x, y)`` [m], cam centre at 0.
    """
    return np.stack([state.profile.x, state.profile.y])


def require_roller(follower) -> None:
    """Refuse a follower that is not a translating roller (the cam disk model needs one).

    Parameters
    ----------
    follower : femcam.profile follower
        The scene's follower.

    Raises
    ------
    InputError
        The follower is not a translating roller (its ``kind`` named).
    """
    if not getattr(follower, "translating_roller", False):
        kind = getattr(follower, "kind", "")
        raise InputError(f"follower type = {kind!r}: the cam disk model needs a roller follower")


def contact_frame(state, i: int = 0) -> tuple[np.ndarray, np.ndarray, float, float]:
    """Contact point, normal, curvature radius and force at one cam angle.

    Parameters
    ----------
    state : femcam.scene.SceneState
        ``Scene.analyse`` of a roller-follower scene.
    i : int, optional
        Index of the angle in ``state``.

    Returns
    -------
    C : ndarray, shape (2,)
        Contact point in the cam frame [m].
    n : ndarray, shape (2,)
        Outward unit cam normal at ``C`` [-].
    rho : float
        Cam radius of curvature at ``C`` [m].
    Fc : float
        Contact force [N].
    """
    p = state.profile
    C = np.array([p.x[i], p.y[i]])
    d = np.array([p.pitch_x[i], p.pitch_y[i]]) - C
    return C, d / np.hypot(*d), float(state.rho[i]), float(state.Fc[i])


def to_contact_frame(xy: np.ndarray, C: np.ndarray, n: np.ndarray) -> np.ndarray:
    """Points of the cam frame in the contact frame (module docstring).

    Parameters
    ----------
    xy : ndarray, shape (2, N)
        Points in the cam frame [m].
    C : ndarray, shape (2,)
        Contact point in the cam frame [m].
    n : ndarray, shape (2,)
        Outward unit cam normal at ``C`` [-].

    Returns
    -------
    ndarray, shape (2, N)
        The points ``(x, y)`` in the contact frame [m].
    """
    t = np.array([n[1], -n[0]])
    d = xy - C[:, None]
    return np.stack([t @ d, n @ d])


def outline_without_arc(disk: CamDisk, C: np.ndarray, n: np.ndarray, rho: float,
                        W: float) -> tuple[np.ndarray, tuple]:
    """Outline points in the contact frame without the arc ``|x| <= W`` at the contact.

    Parameters
    ----------
    disk : CamDisk
        The cam disk (its outline).
    C : ndarray, shape (2,)
        Contact point in the cam frame [m].
    n : ndarray, shape (2,)
        Outward unit cam normal at ``C`` [-].
    rho : float
        Cam radius of curvature at ``C`` [m] (inf: flat).
    W : float
        Half-length of the removed arc along the contact tangent [m].

    Returns
    -------
    points : ndarray, shape (2, M)
        The remaining outline points in the contact frame [m], from the arc's left end
        counter-clockwise round to its right end.
    centre : (float, float)
        The cam centre in the contact frame [m].
    """
    o = to_contact_frame(disk.outline, C, n)
    c = to_contact_frame(np.zeros((2, 1)), C, n)[:, 0]
    ends = np.array([[-W, W], [0.0, 0.0]])
    ends[1] = -surface_height(ends[0], rho)
    psi = np.arctan2(o[1] - c[1], o[0] - c[0])
    pL, pR = (math.atan2(e[1] - c[1], e[0] - c[0]) for e in ends.T)
    span = (pR - pL) % (2 * math.pi)
    s = (psi - pL) % (2 * math.pi)
    step = 2 * math.pi / o.shape[1]
    keep = (s > 0.5 * step) & (s < span - 0.5 * step)
    order = np.argsort(s[keep])
    return o[:, keep][:, order], (float(c[0]), float(c[1]))
