r"""Coulomb partial slip on the condensed contact: a given tangential force with stick and slip.

Unknowns: the tangential traction ``q_k`` (Pa) at the contact vertices (P1 hats, the pressure's
discretisation), acting on the CAM in ``+x`` (on the roller in ``-x``; the sign convention of
:mod:`femcam.fe.contact`). ``u = C_tt q`` is the relative tangential surface displacement
``u_cam,x - u_roller,x`` (m) of the condensed bodies, ``C_tt`` positive definite.

Two regimes (K. L. Johnson, *Contact Mechanics*, 1985, §7.1 and §8.2; the normal pressure ``p``
is solved first and held, Goodman's approximation, exact for similar materials):

* ``rolling = 0`` -- Cattaneo-Mindlin shift, the force ``Q`` applied monotonically after the
  normal load: the slip of the roller relative to the cam is ``s = delta - u`` with ``delta`` the
  rigid shift. Stick: ``u = delta``; slip: ``q = mu p sign(s)``.
* ``rolling = +1 / -1`` -- Carter steady rolling, the surface material flowing through the
  contact in ``rolling * x`` (it enters at ``x = -rolling a``, the leading edge). The slip
  velocity per rolled length is ``xi - rolling du/dx`` with ``xi`` the creepage. Stick:
  ``u = rolling xi x + C``; slip: ``q = mu p sign(rolling (rolling xi - du/dx))``.

.. math:: |q| \le \mu p,\qquad \sum_k w_k q_k = Q/\ell

The stick set is found by an active-set iteration (stick nodes whose traction exceeds
``mu p`` become slip nodes; slip nodes whose slip opposes their traction become stick nodes),
which stops when the set repeats. ``|Q| >= mu P`` is full sliding: ``q = sign(Q) mu p``,
reported as ``slip_state = "sliding"``, never as a failed solve.

Symbols
-------
=======  =========================================================  =====  ======================
symbol   meaning                                                    unit   source
=======  =========================================================  =====  ======================
p        contact pressure at the vertices                           Pa     femcam.fe.contact
q        tangential traction on the cam in +x                       Pa     Johnson 1985 §7.1
Q        tangential force per unit length on the cam (w . q)        N/m
mu       Coulomb friction coefficient                               -
C_tt     tangential compliance u per unit traction hat              m/Pa   condensed FE
delta    rigid tangential shift (Cattaneo)                          m      Johnson 1985 §7.1
xi       creepage (Carter), rigid slip per rolled length            -      Johnson 1985 §8.2
c        stick half-width; c/a = sqrt(1 - Q/(mu P)) for Hertz       m      Cattaneo 1938, Carter 1926
=======  =========================================================  =====  ======================

References
----------
* K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985, §7.1 (Cattaneo-Mindlin,
  line contact), §8.2 (Carter's steady rolling with traction).
* F. W. Carter, On the action of a locomotive driving wheel, Proc. R. Soc. A 112, 1926.
* C. Cattaneo, Sul contatto di due corpi elastici, Rend. Accad. Lincei 27, 1938.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate

SLIP_STATES = ("none", "stick", "partial slip", "sliding")


@dataclass(frozen=True, eq=False)
class TractionSolution:
    """Tangential (partial-slip) solution at the contact vertices.

    Parameters
    ----------
    q : ndarray of float, shape (n_c,)
        Tangential traction on the cam in +x [Pa].
    stick : ndarray of bool, shape (n_c,)
        Stick nodes.
    slip_state : str
        One of :data:`SLIP_STATES`.
    stick_width : float
        Extent of the stick nodes plus one node spacing [m].
    shift : float
        Cattaneo rigid shift delta [m] (nan when rolling or sliding; 0 when ``Q = 0``).
    creep : float
        Carter creepage xi [-] (nan without rolling or when sliding; 0 when ``Q = 0``).
    iterations : int
        Active-set iterations.
    converged : bool
        True when the stick/slip sets settled.
    message : str, optional
        Why it did not converge (empty when it did).
    """

    q: np.ndarray
    stick: np.ndarray
    slip_state: str
    stick_width: float
    shift: float
    creep: float
    iterations: int
    converged: bool
    message: str = ""


def _stick_width(x: np.ndarray, stick: np.ndarray) -> float:
    if not stick.any():
        return 0.0
    k = np.nonzero(stick)[0]
    h = float(np.mean(np.diff(x))) if x.size > 1 else 0.0
    return float(x[k[-1]] - x[k[0]]) + h


def upwind_derivative(M: np.ndarray, x: np.ndarray, rolling: int) -> np.ndarray:
    """du/dx of the rows of ``M`` (n or (n, k)) by one-sided differences with the upstream
    neighbour (the material arrives from ``-rolling x``), so that a stick node's condition links
    it to where its material was. Row differences, not a matrix product: a threaded BLAS gemm
    on these small blocks busy-waits on a shared machine (docs/performance.md).

    Parameters
    ----------
    M : ndarray of float, shape (n,) or (n, k)
        Values at the nodes ``x`` (e.g. displacements [m] or compliances [m/Pa]).
    x : ndarray of float, shape (n,)
        Increasing node abscissae [m].
    rolling : {+1, -1}
        Direction of the material flow along x.

    Returns
    -------
    ndarray of float, same shape as ``M``
        ``dM/dx`` per node, in the units of ``M`` per m.
    """
    h = np.diff(x)
    d = (M[1:] - M[:-1]) / (h[:, None] if M.ndim == 2 else h)
    # upstream difference at each node; the end node without an upstream neighbour takes its
    # downstream one (it is outside the loaded zone, p = 0, never a stick node)
    return np.concatenate([d[:1], d]) if rolling > 0 else np.concatenate([d, d[-1:]])


def _solve_sets(C, u0, w, qs, stick, Qw):
    """Stick tractions with the slip tractions ``qs`` fixed: ``C[S] q + u0[S] = r`` (one rigid
    unknown ``r``: the shift delta, or the creepage xi' when C, u0 are derivatives), ``w.q = Qw``."""
    S = np.nonzero(stick)[0]
    m = S.size
    M = np.zeros((m + 1, m + 1))
    M[:m, :m] = C[np.ix_(S, S)]
    M[:m, m] = -1.0
    M[m, :m] = w[S]
    rhs = np.concatenate([-(C[S] @ qs + u0[S]), [Qw - w @ qs]])
    sol = np.linalg.solve(M, rhs)
    q = qs.copy()
    q[S] = sol[:m]
    return q, float(sol[m])


def solve_partial_slip(C: np.ndarray, x: np.ndarray, w: np.ndarray, p: np.ndarray, Qw: float,
                       mu: float, *, rolling: int = 0, u0: np.ndarray | None = None,
                       max_iter: int = 100) -> TractionSolution:
    """Coulomb partial slip with the tangential force given (see the module docstring).

    Parameters
    ----------
    C : ndarray (n, n)
        Tangential compliance (m/Pa): relative displacement ``u_cam,x - u_roller,x`` at node i
        per unit traction hat k on the cam in +x.
    x, w : ndarray (n,)
        Vertex abscissae (m) and quadrature weights (m).
    p : ndarray (n,)
        Contact pressure (Pa), held fixed.
    Qw : float
        Tangential force per unit length on the cam in +x (N/m).
    mu : float
        Friction coefficient (-).
    rolling : {0, +1, -1}
        0: Cattaneo-Mindlin shift; +-1: Carter steady rolling with the material flowing in +-x.
    u0 : ndarray (n,), optional
        Relative tangential displacement from the pressure (m; rolling only, zero for similar
        materials).
    max_iter : int
        Active-set iteration limit.

    Returns
    -------
    TractionSolution
    """
    mu = _validate.nonnegative("mu", mu, "")
    Qw = _validate.number("Q", Qw, "N/m")
    if rolling not in (0, 1, -1):
        raise _validate.fail("rolling", rolling, "", "must be 0 (shift), +1 or -1 (rolling direction)")
    n = x.size
    loaded = p > 0.0
    Wq = mu * float(w @ p)
    zero = np.zeros(n)
    if Qw == 0.0:
        return TractionSolution(zero, loaded.copy(), "none", _stick_width(x, loaded), 0.0, 0.0, 0, True)
    if abs(Qw) >= Wq:
        q = math.copysign(1.0, Qw) * mu * p
        return TractionSolution(q, np.zeros(n, bool), "sliding", 0.0, math.nan, math.nan, 0, True)
    u0 = zero if (u0 is None or not rolling) else np.asarray(u0, dtype=float)
    return _active_set(C, x, w, p, Qw, mu, rolling, u0, loaded, max_iter)


def _initial_stick(x, p, loaded, f, rolling):
    """Stick-set guess from the Hertz-like closed forms: c = a sqrt(1 - |Q|/(mu P)), centred
    (Cattaneo) or touching the leading edge ``x = -rolling a`` (Carter)."""
    k = np.nonzero(loaded)[0]
    lo, hi = float(x[k[0]]), float(x[k[-1]])
    a, mid = 0.5 * (hi - lo), 0.5 * (hi + lo)
    c = a * math.sqrt(max(1.0 - f, 0.0))
    centre = mid - rolling * (a - c)
    guess = loaded & (np.abs(x - centre) <= c)
    return guess if guess.any() else loaded.copy()


def _active_set(C, x, w, p, Qw, mu, rolling, u0, loaded, max_iter):
    n = x.size
    zero = np.zeros(n)
    if rolling:  # stick: du/dx = xi' (upwind); the unknown rigid term is the creepage xi'
        C, u0 = upwind_derivative(C, x, rolling), upwind_derivative(u0, x, rolling)
    stick = _initial_stick(x, p, loaded, abs(Qw) / (mu * float(w @ p)), rolling)
    sig = np.where(loaded & ~stick, math.copysign(1.0, Qw), 0.0)
    seen = set()
    q, r = zero, 0.0
    for it in range(1, max_iter + 1):
        qs = np.where(stick, 0.0, sig * mu * p)
        q, r = _solve_sets(C, u0, w, qs, stick, Qw)
        # slip of the roller on the cam (Cattaneo) or its rate per rolled length (Carter)
        slip = rolling * (r - (C @ q + u0)) if rolling else r - C @ q
        over = stick & (np.abs(q) > mu * p * (1 + 1e-12))
        back = loaded & ~stick & (slip * sig < 0.0)
        new = stick.copy()
        new[over] = False
        sig[over] = np.sign(q[over])
        new[back] = True
        key = new.tobytes()
        if np.array_equal(new, stick):
            state = "stick" if stick[loaded].all() else "partial slip"
            return _result(q, stick, state, x, r, rolling, it, "")
        if key in seen:
            return _result(q, stick, "partial slip", x, r, rolling, it,
                           f"stick set cycles after {it} iterations")
        seen.add(key)
        stick = new
    return _result(q, stick, "partial slip", x, r, rolling, max_iter,
                   f"stick set still changing after {max_iter} iterations")


def _result(q, stick, state, x, r, rolling, it, msg):
    shift, creep = (math.nan, rolling * r) if rolling else (r, math.nan)
    return TractionSolution(q, stick, state, _stick_width(x, stick), shift, creep, it, not msg, msg)
