"""One load case on a :class:`~femcam.bodies.model.RingModel`: contacts, bore stress, needle loads.

Per unit face width: ``W = F / length`` (N/m). Needle loads are reported per needle (N) and
per unit length (N/m). Angles are polar angles about the roller centre, ``-pi/2`` on the load
line at the cam side (see :mod:`femcam.bodies.mesh`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from .._repr import compact_repr
from ..errors import ConvergenceError, PhysicsError
from ..fe.recovery import fit_half_width
from ..materials import effective_modulus
from ..mesh import surface_height
from .contact import solve_multi_lcp
from .geometry import needle_approach

#: the scene keys a message names for the cam radius of curvature rho
_RHO = "rho (cam radius of curvature, from [program] and [follower] base_radius_mm)"


@dataclass(frozen=True, eq=False)
class RingResult:
    """Solution of one load case (see :func:`solve_ring`).

    Attributes
    ----------
    F : float
        Cam contact force over the face width [N].
    rho : float
        Cam radius of curvature [m].
    cage : float
        Cage angle [rad] (needles).
    a, x0, p0 : float
        Cam-contact half-width [m], centre [m] and fitted peak pressure [Pa].
    x : ndarray, shape (nc,)
        Cam-contact vertex abscissae [m].
    p : ndarray, shape (nc,)
        Cam-contact pressure at ``x`` [Pa].
    hertz_a, hertz_p0 : float
        The solid roller's Hertz half-width [m] and peak pressure [Pa] (Johnson 1985 eq. 4.45;
        NaN for a conformal contact).
    theta : ndarray, shape (n_b,)
        Bore vertex angles about the ring centre [rad].
    hoop : ndarray, shape (n_b,)
        Bore hoop stress at ``theta`` [Pa].
    hoop_max, hoop_theta : float
        The largest (tensile) bore hoop stress [Pa] and its polar angle [rad].
    bore_p : ndarray, shape (n_b,)
        Bore contact pressure at ``theta`` [Pa] (the needle spread for needles).
    pin_a, pin_p0 : float
        Pin-contact half-width (arc length) [m] and peak [Pa] (Hertz-ellipse fit; NaN for
        needles).
    pin_arc : float
        Angular extent of the loaded bore nodes [rad] (NaN for needles).
    needle_phi : ndarray, shape (Z,)
        Needle angles [rad] (empty for a pin).
    needle_Q : ndarray, shape (Z,)
        Needle loads over the whole face width [N] (empty for a pin).
    t : ndarray, shape (2,)
        Ring translation [m].
    delta : float
        Cam approach [m].
    flags : tuple of str
        Warnings (ring yield at the bore).
    iterations : int
        Active-set iterations, summed over the secant iterations.
    residual : float
        Relative complementarity residual of the last solve [-].
    converged : bool
        Whether the last active-set solve converged.
    """

    F: float
    rho: float
    cage: float
    a: float
    x0: float
    p0: float
    x: np.ndarray
    p: np.ndarray
    hertz_a: float
    hertz_p0: float
    theta: np.ndarray
    hoop: np.ndarray
    hoop_max: float
    hoop_theta: float
    bore_p: np.ndarray
    pin_a: float
    pin_p0: float
    pin_arc: float
    needle_phi: np.ndarray
    needle_Q: np.ndarray
    t: np.ndarray
    delta: float
    flags: tuple
    iterations: int
    residual: float
    converged: bool

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)

    @property
    def needle_Q_max(self) -> float:
        """Largest needle load over the face width [N] (NaN for a pin)."""
        return float(self.needle_Q.max()) if self.needle_Q.size else math.nan


def _rigid(model, phi, weights):
    """G (n, 3) rigid columns [tx, ty, delta], C (3, n) equilibrium rows."""
    nc = model.nc
    n = nc + phi.size
    G = np.zeros((n, 3))
    G[:nc, 1] = 1.0
    G[:nc, 2] = -1.0
    G[nc:, 0] = np.cos(phi)
    G[nc:, 1] = np.sin(phi)
    C = np.zeros((3, n))
    C[0, nc:] = weights * np.cos(phi)
    C[1, :nc] = model.w
    C[1, nc:] = weights * np.sin(phi)
    C[2, :nc] = model.w
    return G, C


def _operators(model, cage):
    """(A, P, phi, weights): compliance of the unknowns, pressure map, bore/needle angles and
    their force weights."""
    nc, b = model.nc, model.bearing
    if b.support == "pin":
        n = model.A.shape[0]
        return model.A, np.eye(n), model.theta, model.wb
    phi = b.needle_angles(cage)
    S = model.needle_spread(phi)
    WS = model.wb[:, None] * S
    A = np.empty((nc + phi.size,) * 2)
    A[:nc, :nc] = model.A[:nc, :nc]
    A[:nc, nc:] = model.A[:nc, nc:] @ S
    A[nc:, :nc] = WS.T @ model.A[nc:, :nc]
    A[nc:, nc:] = WS.T @ model.A[nc:, nc:] @ S
    P = np.zeros((model.A.shape[0], nc + phi.size))
    P[:nc, :nc] = np.eye(nc)
    P[nc:, nc:] = S
    return A, P, phi, np.ones(phi.size)


def _hertz(model, F, rho):
    inv_R = (0.0 if math.isinf(rho) else 1.0 / rho) + 1.0 / model.bearing.Ro
    if inv_R <= 0:
        return math.nan, math.nan
    w = F / model.length
    a = math.sqrt(4 * w / (inv_R * math.pi * effective_modulus(model.cam, model.bearing.ring, model.plane)))
    return a, 2 * w / (math.pi * a)


def solve_ring(model, *, F: float, rho: float, cage: float = 0.0, max_secant: int = 40,
               tol: float = 1e-9) -> RingResult:
    """Solve the cam-ring-support contacts for one load case.

    Parameters
    ----------
    model : RingModel
        The condensed model.
    F : float
        Cam contact force over the face width [N], > 0.
    rho : float
        Cam radius of curvature [m]: nonzero, inf for flat, and not concave tighter than the
        ring (``-Ro <= rho < 0`` is refused).
    cage : float, optional
        Cage angle [rad] (needles only; 0: a needle on the load line).
    max_secant : int, optional
        Most secant iterations on the nonlinear needle approach.
    tol : float, optional
        Relative change of the needle loads that ends the secant iterations [-].

    Returns
    -------
    RingResult
        The contact pressures, bore hoop stress, support loads and diagnostics.

    Raises
    ------
    InputError
        A bad ``F`` or ``rho``.
    PhysicsError
        The cam contact reaches the end of the fine zone, or the pin contact wraps the pin.
    ConvergenceError
        The needle loads or the active set do not settle; carries the residual history (the
        relative change of the needle loads at each secant iteration, or the active-set
        residuals).
    """
    F = _validate.positive("F", F, "N")
    rho = _validate.radius(_RHO, rho, "m")
    cage = _validate.number("cage", cage, "rad")
    max_secant = _validate.integer("max_secant", max_secant, 1, "iterations")
    tol = _validate.nonnegative("tol", tol, "")  # 0: iterate max_secant times
    _validate.record("model", model, "a RingModel (RingModel.build)", "bearing", "nc")
    if math.isfinite(rho) and -model.bearing.Ro <= rho < 0:
        raise _validate.fail(_RHO, rho, "m", "must be nonzero and not a concave cam tighter than the roller")
    b = model.bearing
    nc = model.nc
    A0, P, phi, weights = _operators(model, cage)
    G, C = _rigid(model, phi, weights)
    W = F / model.length
    d = np.array([0.0, 0.0, W])
    h0 = np.concatenate([surface_height(model.x, b.Ro) + surface_height(model.x, rho),
                         np.full(phi.size, b.c)])
    aH, p0H = _hertz(model, F, rho)
    active = np.concatenate([np.abs(model.x) < (aH if math.isfinite(aH) else model.a_ref),
                             np.sin(phi) < -0.8])
    needles = b.support == "needles"
    Qn = np.full(phi.size, W / max(phi.size, 1) * 4)
    it_total, history = 0, []  # relative change of the needle loads per secant iteration
    for _ in range(max_secant if needles else 1):
        A = A0.copy()
        if needles:
            dq = needle_approach(np.maximum(Qn, 1e-6 * W), model.length) / np.maximum(Qn, 1e-6 * W)
            A[nc:, nc:] += np.diag(dq)
        sol = solve_multi_lcp(A, h0, G, C, d, active0=active)
        it_total += sol.iterations
        active = sol.active
        Q_new = sol.lam[nc:]
        change = float(np.max(np.abs(Q_new - Qn))) / max(float(Q_new.max()), 1e-300)
        history.append(change)
        Qn = Q_new
        if not needles or change < tol:
            break
    else:
        raise ConvergenceError(f"needle loads did not settle in {max_secant} secant iterations "
                               f"(last relative change {change:.3g})", tuple(history))
    lam = sol.lam
    p = lam[:nc]
    if active[0] or active[nc - 1]:
        raise PhysicsError(f"the cam contact reaches the end of the meshed fine zone |x| <= "
                           f"{model.x[-1]:.4g} m (F = {F:g} N); rebuild with a larger a_ref")
    a, x0, p0 = fit_half_width(model.x, p)
    hoop = model.H @ (P @ lam)
    i = int(np.argmax(hoop))
    bore_p = (P @ lam)[nc:]
    pin_a = pin_p0 = pin_arc = math.nan
    if b.support == "pin":
        s = b.Ri * np.angle(np.exp(1j * (model.theta + 0.5 * math.pi)))
        o = np.argsort(s)
        pin_a, _, pin_p0 = fit_half_width(s[o], bore_p[o])
        loaded = model.theta[bore_p > 0]
        dl = np.angle(np.exp(1j * (loaded + 0.5 * math.pi)))
        pin_arc = float(dl.max() - dl.min()) if loaded.size else 0.0
        if pin_arc > math.pi * 0.999:
            raise PhysicsError(f"the pin contact spans {math.degrees(pin_arc):.0f} deg: the bore "
                               "wraps the pin and the linearised clearance gap does not hold")
    flags = []
    if b.ring_yield is not None and hoop[i] > b.ring_yield:
        flags.append(f"bore hoop stress {hoop[i] / 1e6:.4g} MPa at theta = {math.degrees(model.theta[i]):.1f}"
                     f" deg exceeds the ring's yield strength {b.ring_yield / 1e6:.4g} MPa")
    return RingResult(
        F=F, rho=rho, cage=float(cage), a=a, x0=x0, p0=p0, x=model.x, p=p, hertz_a=aH, hertz_p0=p0H,
        theta=model.theta, hoop=hoop, hoop_max=float(hoop[i]), hoop_theta=float(model.theta[i]),
        bore_p=bore_p, pin_a=pin_a, pin_p0=pin_p0, pin_arc=pin_arc,
        needle_phi=phi if needles else np.zeros(0), needle_Q=(lam[nc:] * model.length if needles
                                                              else np.zeros(0)),
        t=sol.r[:2].copy(), delta=float(sol.r[2]), flags=tuple(flags), iterations=it_total,
        residual=sol.residual, converged=sol.converged)
