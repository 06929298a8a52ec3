r"""All three followers in the FE: which bodies meet, how they slide, where the face ends.

* **Roller** (radius ``Rr``): the FE "roller" body; it rolls, the tangential force is what its
  inertia and bearing drag need (:func:`femcam.wear.slip.roller_inertia`), solved as Coulomb
  partial slip (:mod:`femcam.fe.traction`) with the material flowing through the contact in
  ``rolling x`` (:func:`rolling_direction`).
* **Knife-edge**: a sharp tip has no contact width; with ``tip_radius`` (scene key
  ``follower.tip_radius_mm``) it is a NON-ROTATING roller of that radius on the cam cut for it
  (:func:`femcam.fe.gap.contact_geometry`) and slides fully. Refused without the key.
* **Flat-faced**: the face (R = inf) against the cam. The FE mesh needs a finite radius on its
  "roller" body, so the bodies swap roles: the FE "roller" is the CAM (radius rho) and the FE
  "cam" the flat FOLLOWER (``rho = inf``). The gap is symmetric, so only the labels change
  (:data:`FLAT_FACE_BODIES`). It slides fully. Past the end of the face (``face_length``, scene
  key ``follower.face_length_mm``) the contact is an edge contact: refused with the angle range
  (:func:`face_edge_intervals`), never answered with Hertz.

Sliding direction (knife-edge, flat-faced, the curved pad on an arm): the friction traction on
the cam points along the follower's velocity relative to the cam surface at the contact,
``sign((v_f - v_c) . t)`` with ``v_c = omega (-c_y, c_x)`` (counter-clockwise cam),
``v_f = (0, omega s')`` (translating follower; the pad's own ``program_speeds`` on an arm,
:mod:`femcam.profile.pad`) and ``t`` the local x axis of :mod:`femcam.fe.gap` (Johnson 1985
§7.1: friction opposes the relative slip).

References: K. L. Johnson, *Contact Mechanics*, 1985, §7.1, §8.2; R. L. Norton, *Design of
Machinery*, ch. 8.
"""

from __future__ import annotations

import math

import numpy as np

from .. import _validate
from ..errors import PhysicsError
from ..profile import bool_intervals, cam_profile
from .gap import _contact_frame, contact_geometry

#: FE body name -> physical body, for a flat-faced follower (the bodies swap roles)
FLAT_FACE_BODIES = {"cam": "follower", "roller": "cam"}


def fe_radius(follower, *, tip_radius: float | None = None) -> float:
    """Radius of the FE "roller" body's surface for the follower.

    Parameters
    ----------
    follower : RollerFollower, KnifeEdgeFollower or FlatFacedFollower
        The follower (:mod:`femcam.profile`).
    tip_radius : float, optional
        Knife-edge tip radius [m] (required for a knife-edge follower).

    Returns
    -------
    float
        ``Rr`` (roller) or ``tip_radius`` (knife-edge) [m]; ``nan`` for flat-faced (the cam's own
        rho is used, see the module docstring).
    """
    _, R = contact_geometry(follower, tip_radius)
    return math.nan if math.isinf(R) else R


def sliding_sign(program, follower, theta, *, tip_radius: float | None = None) -> np.ndarray:
    """Sign (+1/-1) of the friction traction on the cam along local x for a sliding follower
    (knife-edge with tip radius, flat-faced) at cam angles ``theta`` (rad); see the module
    docstring. The cam speed only scales the velocities, so it does not enter.

    Parameters
    ----------
    program : femcam.kinematics.CamProgram
        The cam program.
    follower : KnifeEdgeFollower or FlatFacedFollower
        The sliding follower (:mod:`femcam.profile`).
    theta : array_like of float, shape (n,)
        Cam angles [rad].
    tip_radius : float, optional
        Knife-edge tip radius [m] (required for a knife-edge follower).

    Returns
    -------
    ndarray of int, shape (n,)
        +1 or -1 per angle.
    """
    th = _validate.finite_array("theta", theta, "rad")
    gen, R = contact_geometry(follower, tip_radius)
    d = program.derivatives(th)
    own = getattr(gen, "program_speeds", None)
    if own is not None:  # a follower that owns its sliding velocity (femcam.profile.pad)
        # its v_slide = (v_c - v_f) . tau with tau = J n = -t: the same sign as (v_f - v_c) . t
        return np.where(own(d.s, d.s1, d.s2, omega=1.0).v_slide >= 0.0, 1, -1)
    pr = cam_profile(gen, th, d.s, d.s1, d.s2, allow_undercut=True)
    t, _ = _contact_frame(pr, th, R)
    vc = np.stack([-pr.contact_y, pr.contact_x])  # omega x c, per unit omega
    vf = np.stack([np.zeros_like(d.s1), d.s1])
    rel = np.sum((vf - vc) * t, axis=0)
    return np.where(rel >= 0.0, 1, -1)


def rolling_direction(program, follower, theta, *, tip_radius: float | None = None) -> np.ndarray:
    """Direction (+1/-1) in which the cam's surface material flows through the contact along
    local x at ``theta`` (rad): opposite to the travel of the contact point over the cam (the
    leading edge, where material enters, is at ``x = -rolling a``).

    Parameters
    ----------
    program : femcam.kinematics.CamProgram
        The cam program.
    follower : RollerFollower, KnifeEdgeFollower or FlatFacedFollower
        The follower (:mod:`femcam.profile`).
    theta : array_like of float, shape (n,)
        Cam angles [rad].
    tip_radius : float, optional
        Knife-edge tip radius [m] (required for a knife-edge follower).

    Returns
    -------
    ndarray of int, shape (n,)
        +1 or -1 per angle.
    """
    th = _validate.finite_array("theta", theta, "rad")
    gen, R = contact_geometry(follower, tip_radius)
    dth = 1e-6
    both = np.concatenate([th, th + dth])
    d = program.derivatives(both)
    pr = cam_profile(gen, both, d.s, d.s1, d.s2, allow_undercut=True)
    n = th.size
    # the cam-frame travel of the contact, rotated into the fixed frame at theta, along t
    dx, dy = pr.x[n:] - pr.x[:n], pr.y[n:] - pr.y[:n]
    c, s = np.cos(th), np.sin(th)
    fx, fy = c * dx - s * dy, s * dx + c * dy
    t, _ = _contact_frame(pr, both, R)
    along = fx * t[0, :n] + fy * t[1, :n]
    return np.where(along > 0.0, -1, 1)


def face_edge_intervals(program, follower, face_length: float, theta, a) -> list:
    """Cam-angle intervals (rad) where a contact of half-width ``a`` (m, scalar or per angle)
    reaches past the end of a flat face of length ``face_length`` (m) centred on the follower
    axis: ``|s' - e| + a > face_length / 2``. These are edge contacts.

    Parameters
    ----------
    program : femcam.kinematics.CamProgram
        The cam program.
    follower : FlatFacedFollower
        The flat-faced follower.
    face_length : float
        Face length [m], > 0.
    theta : array_like of float, shape (n,)
        Cam angles [rad].
    a : float or array_like, shape (n,)
        Contact half-width [m].

    Returns
    -------
    list of tuple of float
        ``(theta_start, theta_end)`` intervals of edge contact [rad]; empty if none.

    Raises
    ------
    InputError
        ``follower`` is not flat-faced, or ``face_length`` is not positive.
    """
    if not getattr(follower, "flat_face", False):
        raise _validate.fail("follower", type(follower).__name__, "", "must be a flat-faced follower")
    L = _validate.positive("face_length", face_length, "m")
    th = _validate.finite_array("theta", theta, "rad")
    off = np.abs(program.derivatives(th).s1 - follower.e)
    return bool_intervals(th, off + np.broadcast_to(np.asarray(a, float), th.shape) > 0.5 * L)


def check_face(program, follower, face_length: float | None, theta, a) -> None:
    """Refuse an edge contact of a flat face; no check without ``face_length`` or for other
    followers.

    Parameters
    ----------
    program : femcam.kinematics.CamProgram
        The cam program.
    follower : RollerFollower, KnifeEdgeFollower or FlatFacedFollower
        The follower (:mod:`femcam.profile`).
    face_length : float or None
        Flat-face length [m]; None = no check.
    theta : array_like of float, shape (n,)
        Cam angles [rad].
    a : float or array_like, shape (n,)
        Contact half-width [m].

    Raises
    ------
    PhysicsError
        The contact runs past the face end, naming the angle range in degrees.
    """
    if face_length is None or not getattr(follower, "flat_face", False):
        return
    iv = face_edge_intervals(program, follower, face_length, theta, a)
    if iv:
        rng = ", ".join(f"{math.degrees(lo):.2f}..{math.degrees(hi):.2f} deg" for lo, hi in iv)
        raise PhysicsError(f"flat face of length {face_length * 1e3:g} mm: the contact runs past the "
                           f"face end (edge contact) for theta in {rng}; an edge contact is not a "
                           "Hertz case and is not modelled: lengthen face_length_mm")


def follower_kind(follower) -> str:
    """Kind of relative motion at the contact.

    Parameters
    ----------
    follower : RollerFollower, KnifeEdgeFollower or FlatFacedFollower
        The follower (:mod:`femcam.profile`).

    Returns
    -------
    str
        ``"rolling"`` for a roller, ``"sliding"`` for knife-edge and flat-faced followers.

    Raises
    ------
    InputError
        Any other object.
    """
    if hasattr(follower, "rolls") and not follower.oscillating:  # a translating follower
        return "rolling" if follower.rolls else "sliding"
    raise _validate.fail("follower", follower, "", "must be a roller, knife-edge or flat-faced follower")
