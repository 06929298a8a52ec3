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
from ..errors import ConvergenceError, PhysicsError
from ..fe.recovery import fit_half_width
from ..materials import effective_modulus
from ..mesh import surface_height
from .contact import solve_multi_lcp
from .geometry import needle_approach


@dataclass(frozen=True, eq=False)
class RingResult:
    """Solution of one load case (see :func:`solve_ring`).

    a, x0, p0: cam-contact half-width, centre and fitted peak (m, m, Pa); x, p: cam-contact
    vertices and pressures; hertz_a, hertz_p0: the solid roller's Hertz values (Johnson 1985
    eq. 4.45); hoop: bore hoop stress at ``theta`` (Pa); hoop_max, hoop_theta: the largest
    (tensile) bore hoop stress and its polar angle (rad); bore_p: bore contact pressure at
    ``theta`` (pin support, Pa); pin_a, pin_p0: half-width (arc length, m) and peak of the pin
    contact (Hertz-ellipse fit) and pin_arc: angular extent of the loaded bore nodes (rad);
    needle_phi, needle_Q: needle angles (rad) and loads (N, whole face width); t: ring
    translation (m); delta: cam approach (m); flags: warnings (yield); diagnostics.
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

    @property
    def needle_Q_max(self) -> float:
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
    """(A, P, M, phi, weights): compliance of the unknowns, pressure map, bore angles."""
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
    """Solve the cam-ring-support contacts for cam force ``F`` (N), cam radius ``rho`` (m) and
    cage angle ``cage`` (rad, needles only; 0: a needle on the load line)."""
    F = _validate.positive("F", F, "N")
    rho = float(rho)
    if math.isnan(rho) or rho == 0.0 or (math.isfinite(rho) and -model.bearing.Ro <= rho < 0):
        raise _validate.fail("rho", rho, "m", "must be nonzero and not a concave cam tighter than the roller")
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
    it_total = 0
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
        Qn = Q_new
        if not needles or change < tol:
            break
    else:
        raise ConvergenceError(f"needle loads did not settle in {max_secant} secant iterations "
                               f"(last relative change {change:.3g})", (change,))
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
