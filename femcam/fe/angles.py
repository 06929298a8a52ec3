r"""Curvature jumps of the cam surface and the cam angles a sweep must solve around them.

Where the cam program joins two segments with a step in ``s''`` (an acceleration step: SHM next
to a dwell, say), the pitch-curve curvature

.. math:: \kappa = \frac{r^2 + 2 s'^2 - r s''}{(r^2 + s'^2)^{3/2}},\qquad r = d + s

jumps, and so does the cam surface radius ``rho`` (Norton ch. 8; :func:`femcam.profile.pitch_curvature`).
A Hertz or osculating-arc answer then jumps too, while the real contact zone, of half-width
``a``, straddles the junction point over a span of cam angles and the peak pressure goes
continuously from one side's value to the other's. The span is where the junction point's local
abscissa ``x_j`` is inside the contact, ``|x_j| <= a``; ``x_j ~ (theta - theta_j) |dP/dtheta|``
with ``|dP/dtheta|`` the speed (m/rad) of the contact point along the cam surface, so

.. math:: \Delta\theta = a / |dP/d\theta|.

The speed differs on the two sides (``|dP/dtheta| = rho dpsi/dtheta``), so the span is
``(a / speed_left, a / speed_right)``. A velocity step (``s'`` jumps) is a corner of the
surface: that is a cusp, refused by the gap.

Symbols: ``theta_j`` junction angle (rad), ``rho_left, rho_right`` cam radius of curvature just
before/after it (m), ``a`` contact half-width (m), ``dtheta`` the straddle half-span (rad).

References: R. L. Norton, *Design of Machinery*, ch. 8; K. L. Johnson, *Contact Mechanics*,
1985, §4.1.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..profile import cam_profile
from .gap import contact_geometry

#: one-sided limits are taken this far (rad) from the junction
_SIDE = 1e-9


@dataclass(frozen=True)
class CurvatureJump:
    """A junction where the cam surface curvature jumps (a step in ``s''``).

    The contact-point speeds differ on the two sides: ``|dP/dtheta| = rho |dpsi/dtheta|`` with
    the local rho.

    Parameters
    ----------
    theta : float
        Cam angle of the junction [rad].
    jump_s2 : float
        Step of ``s''`` across the junction [m/rad^2].
    rho_left, rho_right : float
        Cam surface radius of curvature just before / after the junction [m], signed
        (negative = concave).
    speed_left, speed_right : float
        Speed ``|dP/dtheta|`` of the contact point along the cam surface before / after [m/rad].
    left, right : str
        Names of the cam-program segments before / after the junction.
    """

    theta: float
    jump_s2: float
    rho_left: float
    rho_right: float
    speed_left: float
    speed_right: float
    left: str
    right: str

    def span(self, a: float) -> tuple[float, float]:
        """Cam-angle spans before and after ``theta`` over which a contact straddles the jump.

        Parameters
        ----------
        a : float
            Contact half-width [m], > 0.

        Returns
        -------
        tuple of float
            ``(a / speed_left, a / speed_right)`` [rad].
        """
        a = _validate.positive("a", a, "m")
        return a / self.speed_left, a / self.speed_right


def curvature_jumps(program, follower, *, tip_radius: float | None = None) -> list[CurvatureJump]:
    """Every junction of ``program`` with a step in ``s''`` (from
    :meth:`femcam.kinematics.CamProgram.junctions`), with the cam radius on both sides.

    Parameters
    ----------
    program : femcam.kinematics.CamProgram
        The cam program (lift vs cam angle).
    follower : RollerFollower, KnifeEdgeFollower or FlatFacedFollower
        The follower geometry (:mod:`femcam.profile`).
    tip_radius : float, optional
        Knife-edge followers only (required there): tip radius of the cam cut [m].

    Returns
    -------
    list of CurvatureJump
        One per junction with a step in ``s''`` or ``s'``, in the program's order.
    """
    gen, _ = contact_geometry(follower, tip_radius)
    out = []
    for jn in program.junctions():
        if jn.jump_s2 == 0.0 and jn.jump_s1 == 0.0:
            continue
        th = jn.theta + np.array([-_SIDE, _SIDE, -2e-6, -1e-6, 1e-6, 2e-6])
        d = program.derivatives(th)
        pr = cam_profile(gen, th, d.s, d.s1, d.s2, allow_undercut=True)
        sp = [math.hypot(pr.x[i + 1] - pr.x[i], pr.y[i + 1] - pr.y[i]) / 1e-6 for i in (2, 4)]
        out.append(CurvatureJump(theta=float(jn.theta), jump_s2=float(jn.jump_s2),
                                 rho_left=float(pr.rho[0]), rho_right=float(pr.rho[1]),
                                 speed_left=sp[0], speed_right=sp[1], left=jn.left, right=jn.right))
    return out


def refine_angles(theta, jumps, a, *, n_refine: int = 8, extra_deg=(0.05, 0.1)):
    """Requested angles ``theta`` (rad) plus, for each :class:`CurvatureJump`, the junction angle,
    ``n_refine`` angles evenly spaced over each side of its straddle span (``a`` the contact
    half-width there, m, scalar or one per jump) and the offsets ``extra_deg`` (deg).

    Angles are compared mod 2 pi.

    Parameters
    ----------
    theta : array_like of float
        Requested cam angles [rad].
    jumps : sequence of CurvatureJump
        The junctions (:func:`curvature_jumps`).
    a : float or array_like, shape (len(jumps),)
        Contact half-width at each junction [m], > 0.
    n_refine : int, optional
        Angles added on each side of each straddle span.
    extra_deg : sequence of float, optional
        Extra offsets from each junction, added on both sides [deg].

    Returns
    -------
    theta_sorted : ndarray of float, shape (m,)
        Sorted unique angles in ``[0, 2 pi)`` [rad].
    curvature_jump : ndarray of bool, shape (m,)
        True for the angles inside a straddle span (the rows a sweep marks ``curvature_jump``).

    >>> from femcam.fe.angles import CurvatureJump
    >>> j = CurvatureJump(1.0, 0.1, 0.02, -0.07, 0.02, 0.02, "dwell", "rise")
    >>> th, flag = refine_angles([0.5, 1.5], [j], 2e-4, n_refine=2, extra_deg=())
    >>> [round(float(t), 4) for t in th], flag.tolist()
    ([0.5, 0.99, 0.995, 1.0, 1.005, 1.01, 1.5], [False, True, True, True, True, True, False])
    """
    th = np.mod(_validate.finite_array("theta", theta, "rad").ravel(), 2 * math.pi)
    n_refine = _validate.integer("n_refine", n_refine, 0)
    a_arr = np.broadcast_to(_validate.positive_array("a", a, "m"), (len(jumps),))
    spans, new = [], [th]
    for jmp, aj in zip(jumps, a_arr, strict=True):
        dl, dr = jmp.span(float(aj))
        spans.append((jmp.theta, dl, dr))
        k = np.arange(1, n_refine + 1) / max(n_refine, 1)
        off = np.radians(np.asarray(extra_deg, dtype=float))
        new.append(np.mod(np.concatenate([[jmp.theta], jmp.theta - k * dl, jmp.theta + k * dr,
                                          jmp.theta + off, jmp.theta - off]), 2 * math.pi))
    allt = np.unique(np.round(np.concatenate(new), 12))
    flag = np.zeros(allt.shape, bool)
    for tj, dl, dr in spans:
        dist = (allt - tj + math.pi) % (2 * math.pi) - math.pi
        flag |= (dist >= -dl * (1 + 1e-9)) & (dist <= dr * (1 + 1e-9))
    return allt, flag
