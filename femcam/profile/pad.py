r"""Curved-pad oscillating follower: a convex circular pad fixed to the arm, sliding on the cam.

The pad face is the circle of radius ``Rr`` (the pad radius, scene ``pad_radius_mm``) about the
arm point ``B`` at ``L`` from the pivot (``arm_length_mm``: pivot to the pad's centre of
curvature). Geometrically it is a roller of that radius (:mod:`femcam.profile.oscillating`): the
cam is the envelope of the pad circle, with the same pressure angle, radius of curvature and
undercut. Unlike a roller it does not turn on the arm, so the contact **slides**.

Speeds (fixed frame, cam counter-clockwise at ``omega``; ``n`` the outward cam normal at the
contact ``C = B - Rr n``, ``tau = J n`` the tangent along which the cam surface passes the
contact, ``A`` the pivot, ``Omega = -sigma psi_dot`` the arm's angular velocity):

.. math:: v_{cam} = \omega J C,\quad v_{pad} = \Omega J (C - A),\quad
          \dot C = \omega\left[\psi' L u - R_r (1 - |T|\kappa)\,\tau\right]

The surface speeds relative to the moving contact point, along ``tau``, their difference (the
sliding speed) and their mean (the entrainment or rolling speed):

.. math:: u_{cam} = (v_{cam} - \dot C)\cdot\tau = \omega |T| (1 - R_r\kappa),\qquad
          u_{pad} = (v_{pad} - \dot C)\cdot\tau = \omega R_r (1 - |T|\kappa + \sigma\psi')

.. math:: v_s = u_{cam} - u_{pad} = \omega\left(|T| - R_r(1 + \sigma\psi')\right),\qquad
          U = \tfrac12 (u_{cam} + u_{pad})

(``|T|``, ``kappa``, ``u`` from :func:`femcam.profile.arm_geometry`; ``dn/dtheta = (1 - |T|
kappa) tau`` from the Frenet formulas of the pitch curve turned with the cam.) On the base
circle ``v_s = omega Rb``; as ``L -> inf`` (``psi' -> 0``) ``v_s -> omega (|T| - Rr)``, the
translating radiused tip of :func:`femcam.wear.slip.radiused_tip`.

Friction moment about the pivot (full sliding, Coulomb ``mu``; docs/oscillating.md). The cam
pushes the pad with ``Fc n`` and drags it with ``mu Fc sign(v_s) tau`` (friction on the pad
opposes the pad's slip ``-v_s tau`` relative to the cam). A force ``F`` at the pad point ``C``
does work ``F . dC/dpsi`` per unit arm lift, ``dC/dpsi = -sigma J (C - A)``, so with
``tau . (-sigma J (C - A)) = -sigma n . (C - A)``:

.. math:: F_c\left(L\cos\varphi + s_f\,\mu\,d_t\right) = I\ddot\psi + c\dot\psi + k\psi + M_{pl},
          \qquad s_f = \sigma\,\mathrm{sign}(v_s),\quad d_t = n\cdot(A - C)

``d_t`` is the signed distance of the pivot from the tangent line through the contact (> 0: the
pivot on the pad's side of the line). :meth:`OscillatingPadFollower.friction_lever` returns
``s_f d_t``.

Symbols
-------
=========  ==================================================  =======  ===========================
symbol     meaning                                              unit     source
=========  ==================================================  =======  ===========================
Rr         pad radius (convex), the pad's centre of curvature   m        scene pad_radius_mm
           at the arm point B
tau        unit tangent J n at the contact                      -        this module
Omega      angular velocity of the arm (counter-clockwise > 0)  rad/s    -sigma psi_dot
u_cam      cam surface speed relative to the contact point      m/s      Johnson 1985 §8.1
u_pad      pad surface speed relative to the contact point      m/s      Johnson 1985 §8.1
v_s        sliding speed u_cam - u_pad (signed along tau)       m/s
U          entrainment (rolling) speed (u_cam + u_pad)/2        m/s      Dowson & Higginson
xi_pad     contact position on the pad, Rr (angle of n - arm)   m
d_t        signed distance pivot - tangent line, n . (A - C)    m        this module
s_f        sign of the friction moment, sigma sign(v_s)          -        this module
=========  ==================================================  =======  ===========================

References
----------
* K. L. Johnson, *Contact Mechanics*, CUP 1985, §8.1 (sliding and rolling velocities of two
  bodies in contact; the surface velocities relative to the contact point).
* R. L. Norton, *Cam Design and Manufacturing Handbook*, 2nd ed., 2009, ch. 8 (oscillating
  followers with curved faces: the envelope of the follower circle).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from .oscillating import OscillatingRollerFollower, arm_geometry


@dataclass(frozen=True)
class PadSpeeds:
    """Contact velocities of a curved pad on an arm (built by :meth:`OscillatingPadFollower.speeds`).

    Attributes
    ----------
    cx, cy : ndarray
        Contact point in the fixed frame (m).
    tx, ty : ndarray
        Unit tangent ``tau = J n`` (cam surface passes the contact along ``+tau``).
    v_cam, v_pad, v_contact : ndarray, shape (2, n)
        Velocities of the cam material point, the pad material point and the contact point (m/s).
    u_cam, u_pad : ndarray
        Surface speeds relative to the contact point along ``tau`` (m/s).
    v_slide : ndarray
        ``u_cam - u_pad`` (m/s, signed along ``tau``).
    U : ndarray
        Entrainment speed ``(u_cam + u_pad) / 2`` (m/s).
    xi_pad : ndarray
        Contact position on the pad, arc length from the arm line (m).
    """

    cx: np.ndarray
    cy: np.ndarray
    tx: np.ndarray
    ty: np.ndarray
    v_cam: np.ndarray
    v_pad: np.ndarray
    v_contact: np.ndarray
    u_cam: np.ndarray
    u_pad: np.ndarray
    v_slide: np.ndarray
    U: np.ndarray
    xi_pad: np.ndarray


@dataclass(frozen=True, kw_only=True)
class OscillatingPadFollower(OscillatingRollerFollower):
    """Convex curved pad on an arm pivoted at ``a`` from the cam centre (m; module docstring).

    The geometry is that of :class:`OscillatingRollerFollower` with ``Rr`` the **pad radius**
    (centre of curvature at the arm length ``L``); the pad does not turn, so the contact slides
    (:meth:`speeds`). A concave pad (negative radius) is not modelled.

    Parameters
    ----------
    Rb : float
        Base-circle radius of the cam [m], ``> 0``.
    Rr : float
        Pad radius [m], ``> 0`` (convex).
    a : float
        Cam centre to pivot [m], ``> Rb``.
    L : float
        Pivot to the pad's centre of curvature [m], ``|a - L| < Rb + Rr < a + L``.
    sigma : int, optional
        +1 (``"away_from_pivot"``, default) or -1 (``"toward_pivot"``).

    Raises
    ------
    InputError
        A radius not positive, the pivot inside the base circle, or an arm that cannot reach.

    Examples
    --------
    >>> f = OscillatingPadFollower(Rb=0.018, Rr=0.012, a=0.045, L=0.036)
    >>> round(float(f.speeds(0.0, 0.0, 0.0, omega=100.0).v_slide), 12)   # base circle: omega Rb
    1.8
    """

    kind = "oscillating_pad"
    #: the pad is fixed to the arm: it slides, it does not roll
    rolls = False
    face = "pad"

    def describe(self) -> str:
        """One line of the geometry in mm and deg (``femcam run`` prints it).

        Returns
        -------
        str
            Radii, pivot distance, arm length, direction, base-circle arm angle.
        """
        side = "away_from_pivot" if self.sigma == 1 else "toward_pivot"
        return (f"Rb = {self.Rb * 1e3:g} mm, pad radius {self.Rr * 1e3:g} mm (sliding), pivot "
                f"{self.a * 1e3:g} mm, arm {self.L * 1e3:g} mm, {side}, base-circle arm angle "
                f"{math.degrees(self.beta0):.4g} deg")

    def speeds(self, psi, psi1, psi2, *, omega: float) -> PadSpeeds:
        r"""Sliding and entrainment speeds at the contact (module docstring).

        .. math:: v_s = \omega\left(|T| - R_r(1 + \sigma\psi')\right), \qquad
                  U = \tfrac12 (u_{cam} + u_{pad})

        Parameters
        ----------
        psi, psi1, psi2 : float or array_like
            Arm angle [rad] and its theta-derivatives [rad/rad, rad/rad^2]; broadcast together.
        omega : float
            Cam speed [rad/s], ``> 0``.

        Returns
        -------
        PadSpeeds
            Arrays of the broadcast shape [m/s, m].
        """
        omega = _validate.positive("omega", omega, "rad/s")
        g = arm_geometry(self, psi, psi1, psi2)
        psi1 = np.broadcast_to(np.asarray(psi1, float), g.kappa.shape)
        R, L, sg = self.Rr, self.L, self.sigma
        cx, cy = g.Bx - R * g.nx, g.By - R * g.ny
        tx, ty = -g.ny, g.nx
        Om = -sg * omega * psi1
        v_cam = omega * np.stack([-cy, cx])
        v_pad = Om * np.stack([-cy, cx - self.a])
        turn = R * (1.0 - g.pitch_speed * g.kappa)  # R dn/dtheta along tau
        v_con = omega * np.stack([psi1 * L * g.ux - turn * tx, psi1 * L * g.uy - turn * ty])
        u_cam = omega * g.pitch_speed * (1.0 - R * g.kappa)
        u_pad = omega * R * (1.0 - g.pitch_speed * g.kappa + sg * psi1)
        xi = R * np.mod(np.arctan2(g.ny, g.nx) - np.arctan2(g.By, g.Bx - self.a) + math.pi,
                        2.0 * math.pi) - R * math.pi
        return PadSpeeds(cx=cx, cy=cy, tx=tx, ty=ty, v_cam=v_cam, v_pad=v_pad, v_contact=v_con,
                         u_cam=u_cam, u_pad=u_pad, v_slide=u_cam - u_pad, U=0.5 * (u_cam + u_pad),
                         xi_pad=xi)

    def program_speeds(self, s, s1, s2, *, omega: float) -> PadSpeeds:
        """:meth:`speeds` at a scene program's arc travel ``s = L psi`` (m), as
        :meth:`OscillatingRollerFollower.cam_profile` takes it.

        Parameters
        ----------
        s, s1, s2 : float or array_like
            Arc travel of the pad centre ``L psi`` [m] and its theta-derivatives [m/rad^k].
        omega : float
            Cam speed [rad/s], ``> 0``.

        Returns
        -------
        PadSpeeds
            As :meth:`speeds`.
        """
        L = self.L
        return self.speeds(np.asarray(s, float) / L, np.asarray(s1, float) / L, np.asarray(s2, float) / L,
                           omega=omega)

    def friction_lever(self, psi, psi1, psi2) -> np.ndarray:
        r"""Signed lever of the friction force about the pivot per unit ``mu`` (m, module docstring).

        .. math:: s_f\,d_t = \sigma\,\mathrm{sign}(v_s)\; n\cdot(A - C)

        The moment of the friction force ``mu Fc`` on the pad about the pivot, in the sense of
        ``psi``, is ``mu Fc s_f d_t``; :func:`femcam.loads.arm_contact_force` adds it to the
        normal force's ``Fc L cos(phi)``. Where ``v_s = 0`` (no sliding) it is 0.

        Parameters
        ----------
        psi, psi1, psi2 : float or array_like
            Arm angle [rad] and its theta-derivatives [rad/rad, rad/rad^2]; broadcast together.

        Returns
        -------
        ndarray
            ``s_f d_t`` [m], the broadcast shape.

        Examples
        --------
        >>> f = OscillatingPadFollower(Rb=0.018, Rr=0.012, a=0.045, L=0.036)
        >>> round(float(f.friction_lever(0.0, 0.0, 0.0)), 12)   # base circle: a Bx / Rp - Rb
        0.00915
        """
        g = self.speeds(psi, psi1, psi2, omega=1.0)   # v_s scales with omega: its sign does not
        d_t = g.ty * (self.a - g.cx) + g.tx * g.cy   # n = (ty, -tx), A - C = (a - cx, -cy)
        return self.sigma * np.sign(g.v_slide) * d_t
