"""One load case on a :class:`~femcam.bodies.cam_model.CamDiskModel`: the cam-roller contact on the
cam disk and on today's local cam body, the bore hoop stress and the shaft contact.

Per unit face width: ``W = F / length`` (N/m). Bore angles are reported from the direction of the
contact as seen from the cam centre (0: the bore point nearest the contact), counter-clockwise.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from .._repr import compact_repr
from ..errors import PhysicsError
from ..fe.recovery import fit_half_width
from ..hertz.conformity import roller_does_not_fit
from ..hertz.contact import effective_radius, half_width
from ..materials import effective_modulus
from ..mesh import surface_height
from .contact import solve_multi_lcp


@dataclass(frozen=True, eq=False)
class CamDiskResult:
    """Solution of one load case (see :func:`solve_cam_disk`).

    Attributes
    ----------
    F : float
        Contact force over the face width [N].
    a, x0, p0 : float
        Cam-roller half-width [m], centre [m] and fitted peak pressure [Pa] on the cam disk.
    x : ndarray, shape (nc,)
        Contact vertex abscissae [m].
    p : ndarray, shape (nc,)
        Contact pressure at ``x`` [Pa].
    a_local, p0_local : float
        Half-width [m] and peak pressure [Pa] on today's local cam body (NaN if not solved).
    delta_local : float
        Roller approach on the local bodies [m] (NaN if not solved).
    delta : float
        Roller approach towards the shaft core [m].
    t : ndarray, shape (2,)
        Cam translation in the contact frame [m].
    theta : ndarray, shape (n_b,)
        Bore angles from the contact direction, counter-clockwise [rad].
    hoop : ndarray, shape (n_b,)
        Bore hoop stress [Pa].
    hoop_max, hoop_theta : float
        The largest (tensile) bore hoop stress [Pa] and its angle [rad].
    bore_p : ndarray, shape (n_b,)
        Shaft-bore pressure [Pa] (negative = tension, bonded fit only).
    shaft_p0 : float
        Its peak [Pa].
    shaft_arc : float
        Angular extent of the loaded bore nodes [rad] (NaN for a bonded fit).
    flags : tuple of str
        Warnings (cam yield at the bore).
    iterations : int
        Active-set iterations.
    residual : float
        Relative complementarity residual of the last iteration [-].
    converged : bool
        Whether the active-set solve converged.
    """

    F: float
    a: float
    x0: float
    p0: float
    x: np.ndarray
    p: np.ndarray
    a_local: float
    p0_local: float
    delta_local: float
    delta: float
    t: np.ndarray
    theta: np.ndarray
    hoop: np.ndarray
    hoop_max: float
    hoop_theta: float
    bore_p: np.ndarray
    shaft_p0: float
    shaft_arc: float
    flags: tuple
    iterations: int
    residual: float
    converged: bool

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)

    @property
    def dp0(self) -> float:
        """p0 on the disk / p0 on the local body - 1."""
        return self.p0 / self.p0_local - 1.0

    @property
    def da(self) -> float:
        """a on the disk / a on the local body - 1."""
        return self.a / self.a_local - 1.0


def _system(model):
    """G (n, 3) rigid columns [tx, ty, delta]; C (3, n) cam force balance and int p."""
    nc, th = model.nc, model.theta
    n = nc + th.size
    G = np.zeros((n, 3))
    G[:nc, 1] = -1.0
    G[:nc, 2] = -1.0
    G[nc:, 0] = np.cos(th)
    G[nc:, 1] = np.sin(th)
    C = np.zeros((3, n))
    C[0, nc:] = model.bore_force[0]
    C[1, :nc] = -model.w
    C[1, nc:] = model.bore_force[1]
    C[2, :nc] = model.w
    return G, C


def shaft_arc(theta, p) -> float:
    """Angular extent of the loaded nodes ``p > 0`` about their mean direction.

    Parameters
    ----------
    theta : ndarray, shape (n,)
        Node angles [rad].
    p : ndarray, shape (n,)
        Node pressures [Pa] (only their sign is used).

    Returns
    -------
    float
        Angle from the first to the last loaded node about their mean direction [rad]; 0 if
        none is loaded.
    """
    on = p > 0
    if not np.any(on):
        return 0.0
    z = np.exp(1j * theta[on])
    d = np.angle(z / (z.sum() / abs(z.sum())))
    return float(d.max() - d.min())


def _local(model, h0, W, active):
    nc = model.nc
    sol = solve_multi_lcp(model.A_local, h0, -np.ones((nc, 1)), model.w[None, :], np.array([W]),
                          active0=active)
    a, _, p0 = fit_half_width(model.x, sol.lam)
    return a, p0, float(sol.r[0])


def solve_cam_disk(model, *, F: float, local: bool = True) -> CamDiskResult:
    """Solve the cam disk, shaft and roller for one contact force.

    Parameters
    ----------
    model : CamDiskModel
        The condensed model.
    F : float
        Contact force (N) over the face width ``model.length``.
    local : bool
        Also solve today's local cam body (``model.A_local``) for the comparison.

    Returns
    -------
    CamDiskResult
        Contact, bore and shaft results with diagnostics.

    Raises
    ------
    InputError
        ``F`` not a positive number.
    PhysicsError
        The contact reaches the end of the fine zone.
    ConvergenceError
        The active set cycles.
    """
    F = _validate.positive("F", F, "N")
    _validate.record("model", model, "a CamDiskModel (CamDiskModel.build)", "nc", "disk")
    nc, d = model.nc, model.disk
    W = F / model.length
    h0c = surface_height(model.x, model.Rr) + surface_height(model.x, model.rho)
    h0 = np.concatenate([h0c, np.full(model.theta.size, d.c)])
    G, C = _system(model)
    if roller_does_not_fit(model.rho, model.Rr):
        a_guess = model.x[-1] / 2
    else:  # twice the Hertz half-width: the first active set (Johnson 1985 eq. 4.45)
        a_guess = 2 * float(half_width(W, effective_radius(model.rho, model.Rr),
                                       effective_modulus(d.cam, model.roller, model.plane)))
    toward = np.cos(model.theta - math.atan2(-model.centre[1], -model.centre[0]))
    active = np.concatenate([np.abs(model.x) < a_guess, toward > 0.8])
    bil = np.concatenate([np.zeros(nc, bool), np.full(model.theta.size, d.fit == "bonded")])
    sol = solve_multi_lcp(model.A, h0, G, C, np.array([0.0, 0.0, W]), active0=active, bilateral=bil)
    p = sol.lam[:nc]
    if sol.active[0] or sol.active[nc - 1]:
        raise PhysicsError(f"the cam contact reaches the end of the meshed fine zone |x| <= "
                           f"{model.x[-1]:.4g} m (F = {F:g} N); rebuild with a larger a_ref")
    a, x0, p0 = fit_half_width(model.x, p)
    hoop = model.H @ sol.lam
    # bore angles from the contact direction (the cam centre looks at the contact along -centre)
    th = np.angle(np.exp(1j * (model.theta - math.atan2(-model.centre[1], -model.centre[0]))))
    i = int(np.argmax(hoop))
    bp = sol.lam[nc:]
    a_l = p0_l = dl = math.nan
    if local and np.all(np.isfinite(model.A_local)):
        a_l, p0_l, dl = _local(model, h0c, W, sol.active[:nc])
    flags = []
    if d.cam_yield is not None and hoop[i] > d.cam_yield:
        flags.append(f"cam bore hoop stress {hoop[i] / 1e6:.4g} MPa at {math.degrees(th[i]):.1f} deg "
                     f"from the contact exceeds the cam's yield strength {d.cam_yield / 1e6:.4g} MPa (web "
                     f"{d.web * 1e3:.3g} mm)")
    return CamDiskResult(
        F=F, a=a, x0=x0, p0=p0, x=model.x, p=p, a_local=a_l, p0_local=p0_l, delta_local=dl,
        delta=float(sol.r[2]), t=sol.r[:2].copy(), theta=th, hoop=hoop, hoop_max=float(hoop[i]),
        hoop_theta=float(th[i]), bore_p=bp, shaft_p0=float(bp.max()),
        shaft_arc=shaft_arc(th, bp) if d.fit == "contact" else math.nan, flags=tuple(flags),
        iterations=sol.iterations, residual=sol.residual, converged=sol.converged)
