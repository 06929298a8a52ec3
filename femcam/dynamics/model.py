r"""Lumped follower-train models and their exact piecewise-linear time integration.

The cam drives the lift ``s(t)`` into a train of stiffness ``k_t`` (damping ``c_t``) that
pushes the follower mass ``m1``; the return spring ``k_s`` (preload ``Fpl``, damping to
ground ``c_s``) acts on the last mass (Norton 2009 ch. 10; Koster 1974; Chen 1982). In the
relative coordinates ``e_i = x_i - s`` (displacement error against the rigid lift):

.. math::
    M \ddot e + C \dot e + K e = -M\mathbf 1\, a - \mathbf g\,(k_s s + c_s v + F_{pl}),
    \qquad F_c = \max\bigl(0,\ -k_t e_1 - c_t \dot e_1\bigr)

``one_dof``: ``M = m1``, ``K = k_t + k_s``, ``C = c_t + c_s``. ``two_dof``: a second mass ``m2``
(valve) hangs on ``m1`` by ``k2, c2`` and carries the return spring. The train is unilateral:
while the trial force ``-k_t e_1 - c_t \dot e_1`` is negative the train end leaves the cam,
the ``k_t, c_t`` terms drop out (free flight under the return spring), and contact resumes
when the trial force turns positive again (re-impact). Both modes are linear, so each is
integrated *exactly* for an input (``a`` and ``g``) linear in time over each step (first-order
hold): the only errors are the O(h^2) input interpolation and the O(h^2) linear location of
the contact events, so the method is second order and unconditionally stable for any train
stiffness. Bulk steps run modally (``scipy.signal.lfilter`` on each eigen-coordinate); single
partial steps and defective systems use the Van Loan (1978) block exponential.

Symbols
-------
======  ==============================================  =======  ======================
symbol  meaning                                         unit     source
======  ==============================================  =======  ======================
m1      follower (first) mass, touches the cam           kg       seed 002 m_r / Norton 10
m2      second (valve) mass, two_dof only                kg       Norton 2009 ch. 10
k_t     train stiffness between cam and m1               N/m      Koster 1974
c_t     train damping                                    N s/m    c_t = zeta_t 2 sqrt(k_t m1)
k2, c2  stiffness, damping between m1 and m2             N/m, ..  c2 = zeta_2 2 sqrt(k2 m2)
k_s     return spring; Fpl its preload; c_s ground damp  N/m, N   seed 002 Table 1
e_i     x_i - s, displacement error of mass i            m
Fc      axial contact force (normal force: / cos phi)    N        seed 002 eq. 11 when rigid
h       time step = 2 pi / (omega N)                     s
======  ==============================================  =======  ======================
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import expm

from .. import _validate
from ..errors import InputError
from ..loads import FollowerDynamics

#: fewest time steps per damped period of a mode that still rings after one step
STEPS_PER_PERIOD = 20
#: a mode whose amplitude falls below this factor in one step does not ring (quasi-static)
RING_FACTOR = 0.5
#: runs of at most this many steps use a Toeplitz product instead of lfilter (call overhead)
SHORT_RUN = 64


def _damping(name, c, zeta, k, m, unit="N s/m"):
    """c from exactly one of (c, zeta); zeta relative to 2 sqrt(k m). ``name`` is the suffix of the
    parameters (``"_t"``: ``c_t``/``zeta_t``; ``"2"``: ``c2``/``zeta2``)."""
    if (c is None) == (zeta is None):
        raise InputError(f"c{name}, zeta{name}: give exactly one of the damping c (N s/m) or the ratio zeta; "
                         f"got c = {c!r}, zeta = {zeta!r}")
    if c is not None:
        return _validate.nonnegative(f"c{name}", c, unit)
    return _validate.nonnegative(f"zeta{name}", zeta, "") * 2.0 * math.sqrt(k * m)


@dataclass(frozen=True, kw_only=True)
class TrainModel:
    """An elastic follower train on the return spring of ``follower`` (a FollowerDynamics).

    ``k_t`` (N/m) and ``c_t`` (N s/m) or ``zeta_t`` couple the cam to the follower mass
    ``follower.m``; giving ``m2`` (kg), ``k2`` (N/m) and ``c2`` or ``zeta2`` makes it two_dof,
    the return spring then acting on ``m2``.

    Parameters
    ----------
    follower : FollowerDynamics
        Follower mass ``m1 = follower.m`` [kg] (``> 0``), return spring ``k_s = follower.k``
        [N/m], preload ``Fpl`` [N] and ground damping ``c_s = follower.c`` [N s/m].
    k_t : float
        Train stiffness between cam and ``m1`` [N/m], ``> 0``.
    c_t : float or None, optional
        Train damping [N s/m], ``>= 0``; give exactly one of ``c_t`` and ``zeta_t``. Stored
        as the resolved damping [N s/m].
    zeta_t : float or None, optional
        Train damping ratio [-], ``c_t = zeta_t 2 sqrt(k_t m1)``.
    m2 : float or None, optional
        Second (valve) mass [kg], ``> 0``; None (default) for a one_dof train.
    k2 : float or None, optional
        Stiffness between ``m1`` and ``m2`` [N/m], ``> 0`` (two_dof only).
    c2 : float or None, optional
        Damping between ``m1`` and ``m2`` [N s/m] (two_dof only; exactly one of ``c2``, ``zeta2``).
    zeta2 : float or None, optional
        Damping ratio between ``m1`` and ``m2`` [-], ``c2 = zeta2 2 sqrt(k2 m2)``.

    Raises
    ------
    InputError
        Not a FollowerDynamics, a non-positive mass or stiffness, both or neither of a damping
        and its ratio, or two_dof parameters without ``m2``.

    Examples
    --------
    >>> tm = TrainModel(follower=FollowerDynamics(m=0.2, k=800.0, Fpl=1500.0, c=0.0),
    ...                 k_t=2.0e6, zeta_t=0.0)
    >>> round(float(tm.natural_frequencies[0]), 3)    # sqrt((k_t + k_s)/m) rad/s
    3162.91
    """

    follower: FollowerDynamics
    k_t: float
    c_t: float | None = None
    zeta_t: float | None = None
    m2: float | None = None
    k2: float | None = None
    c2: float | None = None
    zeta2: float | None = None

    def __post_init__(self):
        f = self.follower
        if not isinstance(f, FollowerDynamics):
            raise InputError(f"follower = {f!r}: must be a FollowerDynamics")
        _validate.positive("m (follower mass)", f.m, "kg")
        k_t = _validate.positive("k_t", self.k_t, "N/m")
        object.__setattr__(self, "k_t", k_t)
        object.__setattr__(self, "c_t", _damping("_t", self.c_t, self.zeta_t, k_t, f.m))
        if self.m2 is None:
            if any(x is not None for x in (self.k2, self.c2, self.zeta2)):
                raise InputError("k2, c2, zeta2 belong to a two_dof train: give m2 (kg) too")
            return
        object.__setattr__(self, "m2", _validate.positive("m2", self.m2, "kg"))
        object.__setattr__(self, "k2", _validate.positive("k2", self.k2, "N/m"))
        object.__setattr__(self, "c2", _damping("2", self.c2, self.zeta2, self.k2, self.m2))

    @property
    def model(self) -> str:
        """``"one_dof"`` or ``"two_dof"`` (with ``m2``)."""
        return "one_dof" if self.m2 is None else "two_dof"

    @property
    def ndof(self) -> int:
        """Number of masses ``n``: 1 or 2."""
        return 1 if self.m2 is None else 2

    @property
    def total_mass(self) -> float:
        """Mass moved by the cam (kg): eq. 11 uses it in the stiff-train limit."""
        return self.follower.m + (self.m2 or 0.0)

    def mck(self, contact: bool = True):
        """Mass, damping and stiffness matrices (relative coordinates) and the g-input vector.

        Parameters
        ----------
        contact : bool, optional
            True (default) with the train coupling ``k_t, c_t``; False for free flight.

        Returns
        -------
        M : ndarray, shape (n, n)
            Mass matrix [kg].
        C : ndarray, shape (n, n)
            Damping matrix [N s/m].
        K : ndarray, shape (n, n)
            Stiffness matrix [N/m].
        g : ndarray, shape (n,)
            Unit vector [-] selecting the mass the return-spring force acts on (the last).
        """
        f = self.follower
        kt, ct = (self.k_t, self.c_t) if contact else (0.0, 0.0)
        if self.m2 is None:
            return (np.array([[f.m]]), np.array([[ct + f.c]]), np.array([[kt + f.k]]),
                    np.array([1.0]))
        M = np.diag([f.m, self.m2])
        C = np.array([[ct + self.c2, -self.c2], [-self.c2, self.c2 + f.c]])
        K = np.array([[kt + self.k2, -self.k2], [-self.k2, self.k2 + f.k]])
        return M, C, K, np.array([0.0, 1.0])

    @property
    def natural_frequencies(self) -> np.ndarray:
        r"""Undamped natural frequencies in contact (rad/s), ascending:
        :math:`\omega^2` are the eigenvalues of :math:`M^{-1}K`."""
        M, _, K, _ = self.mck(True)
        return np.sqrt(np.sort(np.linalg.eigvals(np.linalg.solve(M, K)).real))

    def state_space(self, contact: bool = True):
        """``A`` (2n x 2n) and ``B`` (2n x 2) of ``z' = A z + B u``, ``z = (e, e')``,
        ``u = (a, k_s s + c_s v + Fpl)``.

        Parameters
        ----------
        contact : bool, optional
            True (default) with the train coupling ``k_t, c_t``; False for free flight.

        Returns
        -------
        A : ndarray, shape (2n, 2n)
            State matrix ``[[0, I], [-M^-1 K, -M^-1 C]]`` (blocks [-], [-], [1/s^2], [1/s])
            for ``z = (e [m], e' [m/s])``.
        B : ndarray, shape (2n, 2)
            Input matrix for ``u = (a [m/s^2], g [N])``: ``-1`` [-] and ``-M^-1 g`` [1/kg].
        """
        M, C, K, g = self.mck(contact)
        n = M.shape[0]
        Mi = np.linalg.inv(M)
        A = np.block([[np.zeros((n, n)), np.eye(n)], [-Mi @ K, -Mi @ C]])
        B = np.zeros((2 * n, 2))
        B[n:, 0] = -1.0
        B[n:, 1] = -Mi @ g
        return A, B

    def trial_force(self, Z) -> np.ndarray:
        """Trial contact force ``-k_t e_1 - c_t e_1'`` (N) of states ``Z`` (..., 2n).

        Parameters
        ----------
        Z : array_like, shape (..., 2n)
            States ``(e [m], e' [m/s])`` on the last axis.

        Returns
        -------
        ndarray, shape (...)
            Trial contact force [N]; negative means the train end leaves the cam.
        """
        Z = np.asarray(Z)
        return -self.k_t * Z[..., 0] - self.c_t * Z[..., self.ndof]


def _e12(z):
    """E1 = (e^z - 1)/z and E2 = (e^z - 1 - z)/z^2, with series near z = 0."""
    z = np.asarray(z, complex)
    small = np.abs(z) < 1e-2
    zs = np.where(small, 1.0, z)
    em1 = np.expm1(zs)
    E1 = np.where(small, 1 + z / 2 + z**2 / 6 + z**3 / 24 + z**4 / 120, em1 / zs)
    E2 = np.where(small, 0.5 + z / 6 + z**2 / 24 + z**3 / 120 + z**4 / 720, (em1 - zs) / zs**2)
    return E1, E2


class Mode:
    """Exact first-order-hold propagation of ``z' = A z + B u`` (one contact mode).

    Parameters
    ----------
    A : ndarray, shape (2n, 2n)
        State matrix from :meth:`TrainModel.state_space`.
    B : ndarray, shape (2n, 2)
        Input matrix from :meth:`TrainModel.state_space`.
    h : float
        Grid time step [s].
    """

    def __init__(self, A, B, h):
        self.A, self.B, self.h = A, B, h
        lam, Vm = np.linalg.eig(A)
        self.lam = lam
        self.modal = bool(np.linalg.cond(Vm) < 1e8)  # else defective (e.g. critical damping)
        if self.modal:
            self.V, self.W = Vm, np.linalg.inv(Vm)
            self.Bm = self.W @ B
            z = lam * h
            E1, E2 = _e12(z)
            self.mu = np.exp(z)
            self.c0, self.c1 = h * (E1 - E2), h * E2
        if not self.modal:  # defective systems (critical damping)
            self.Phi, self.P1, self.P2 = self._vanloan(h)

    def _vanloan(self, h):
        """Phi, P1, P2 with z(h) = Phi z0 + P1 u0 + P2 (u1 - u0) (Van Loan 1978)."""
        n, m = self.B.shape
        F = np.zeros((n + 2 * m, n + 2 * m))
        F[:n, :n], F[:n, n:n + m] = self.A * h, self.B * h
        F[n:n + m, n + m:] = np.eye(m)
        E = expm(F)
        return E[:n, :n], E[:n, n:n + m], E[:n, n + m:]

    def step(self, z0, dt, u0, u1):
        """One exact step of length ``dt`` (any, > 0) for the input linear from u0 to u1.

        Parameters
        ----------
        z0 : ndarray, shape (2n,)
            Start state ``(e [m], e' [m/s])``.
        dt : float
            Step length [s], ``> 0``.
        u0, u1 : ndarray, shape (2,)
            Inputs ``(a [m/s^2], g [N])`` at the start and the end of the step.

        Returns
        -------
        ndarray, shape (2n,)
            State after ``dt``, float.
        """
        if self.modal:
            E1, E2 = _e12(self.lam * dt)
            q0, q1 = self.Bm @ u0, self.Bm @ u1
            y = np.exp(self.lam * dt) * (self.W @ z0) + dt * ((E1 - E2) * q0 + E2 * q1)
            return (self.V @ y).real
        Phi, P1, P2 = self._vanloan(dt)  # defective systems only
        return Phi @ z0 + P1 @ u0 + P2 @ (u1 - u0)

    def forcing(self, U):
        """Modal step forcing ``r_k`` of the inputs ``U`` (K+1, 2) -> (K, 2n) complex.

        Parameters
        ----------
        U : ndarray, shape (K+1, 2)
            Inputs ``(a [m/s^2], g [N])`` at the grid points (step ``h``).

        Returns
        -------
        ndarray, shape (K, 2n), complex
            Forced response of each step in modal coordinates (state units, m and m/s).
        """
        Q = U @ self.Bm.T
        return self.c0 * Q[:-1] + self.c1 * Q[1:]

    def run(self, z0, U, R=None):
        """States at the grid points of ``U`` (K+1 inputs, step h) starting from ``z0``
        (``R``: its :meth:`forcing`, if already computed).

        Parameters
        ----------
        z0 : ndarray, shape (2n,)
            Start state ``(e [m], e' [m/s])``.
        U : ndarray, shape (K+1, 2)
            Inputs ``(a [m/s^2], g [N])`` at the grid points.
        R : ndarray, shape (K, 2n), complex, optional
            :meth:`forcing` of ``U``, if already computed (modal modes only).

        Returns
        -------
        ndarray, shape (K+1, 2n)
            States at the grid points, the first being ``z0``.
        """
        K = U.shape[0] - 1
        out = np.empty((K + 1, z0.size))
        out[0] = z0
        if K == 0:
            return out
        if not self.modal:  # defective systems (critical damping)
            Gu = U[:-1] @ (self.P1 - self.P2).T + U[1:] @ self.P2.T
            for k in range(K):
                out[k + 1] = self.Phi @ out[k] + Gu[k]
            return out
        R = self.forcing(U) if R is None else R
        y0 = self.W @ z0
        if K <= SHORT_RUN:  # y_k = mu^k y0 + sum_j mu^(k-1-j) r_j: a small Toeplitz product
            T = self._powers(K)  # (2n, K, K), mu^(k-j) below the diagonal (|mu| <= 1)
            Y = np.einsum("ikj,ji->ki", T, R) + self.mu * T[:, :, 0].T * y0
        else:
            from scipy.signal import lfilter  # lazy: scipy.signal adds ~0.5-0.7 s to ``import femcam``

            Y = np.empty((K, z0.size), complex)
            for i, mu in enumerate(self.mu):
                Y[:, i] = lfilter([1.0], [1.0, -mu], R[:, i], zi=[mu * y0[i]])[0]
        out[1:] = (Y @ self.V.T).real
        return out

    def _powers(self, K):
        """mu_i^(k-j) for k >= j (else 0), shape (2n, K, K); cached per K."""
        cache = self.__dict__.setdefault("_pow", {})
        if K not in cache:
            d = np.arange(K)[:, None] - np.arange(K)[None, :]
            with np.errstate(under="ignore"):
                P = self.mu[:, None, None] ** np.maximum(d, 0)[None]
            cache[K] = np.where(d[None] >= 0, P, 0.0)
        return cache[K]

    def power(self, N):
        """State transition over N steps, Phi^N.

        Parameters
        ----------
        N : int
            Number of steps of length ``h``.

        Returns
        -------
        ndarray, shape (2n, 2n)
            Transition matrix over ``N h`` [SI].
        """
        if self.modal:
            return ((self.V * self.mu**N) @ self.W).real
        return np.linalg.matrix_power(self.Phi, N)  # defective only


def check_resolution(train: TrainModel, omega: float, N: int) -> str | None:
    """None if N steps per revolution resolve every ringing mode, else the reason (numbers).

    A mode rings if it is oscillatory and decays by less than ``RING_FACTOR`` in one step; it
    is resolved with at least ``STEPS_PER_PERIOD`` steps per damped period.

    Parameters
    ----------
    train : TrainModel
        The follower train (contact and free-flight modes are both checked).
    omega : float
        Cam speed [rad/s], ``> 0``.
    N : int
        Time steps per revolution.

    Returns
    -------
    str or None
        None if resolved, else the reason ending in ``steps_per_rev >= <count>)``.
    """
    omega = _validate.positive("omega", omega, "rad/s")
    N = _validate.integer("N", N, 1, "steps per revolution")
    _validate.instance("train", train, TrainModel)
    h = 2.0 * math.pi / (omega * N)
    for contact in (True, False):
        lam = np.linalg.eigvals(train.state_space(contact)[0])
        ring = (np.abs(lam.imag) > 0) & (np.exp(lam.real * h) > RING_FACTOR)
        wd = float(np.max(np.abs(lam.imag[ring]), initial=0.0))
        if wd * h > 2.0 * math.pi / STEPS_PER_PERIOD:
            need = math.ceil(STEPS_PER_PERIOD * wd / omega)
            return (f"steps_per_rev = {N}: the time step h = {h:.4g} s does not resolve the "
                    f"{'contact' if contact else 'free-flight'} mode of damped frequency "
                    f"{wd / (2 * math.pi):.6g} Hz (period {2 * math.pi / wd:.4g} s, "
                    f"{2 * math.pi / (wd * h):.3g} steps; at least {STEPS_PER_PERIOD} needed, "
                    f"i.e. steps_per_rev >= {need})")
    return None


def march(train: TrainModel, modes, U, z0, contact0: bool):
    """Integrate one pass over the inputs ``U`` (N+1, 2) from ``z0``, switching between the
    contact mode ``modes[True]`` and free flight ``modes[False]`` at the events.

    Returns ``(Z, contact, n_events)``; an event is located by linear interpolation of the
    trial force between grid points; each mode keeps at least one grid point (no chatter).

    Parameters
    ----------
    train : TrainModel
        The follower train.
    modes : dict of bool to Mode
        ``{True: contact mode, False: free-flight mode}`` on one step ``h``.
    U : ndarray, shape (N+1, 2)
        Inputs ``(a [m/s^2], g [N])`` at the grid points.
    z0 : ndarray, shape (2n,)
        Start state ``(e [m], e' [m/s])``.
    contact0 : bool
        Whether the train is in contact at the start.

    Returns
    -------
    Z : ndarray, shape (N+1, 2n)
        States at the grid points.
    contact : ndarray of bool, shape (N+1,)
        Contact flag at each grid point.
    n_events : int
        Lift-offs plus re-impacts in the pass.
    """
    N = U.shape[0] - 1
    h = modes[True].h
    Z = np.empty((N + 1, z0.size))
    C = np.empty(N + 1, bool)
    Z[0], C[0] = z0, contact0
    R = {c: modes[c].forcing(U) if modes[c].modal else None for c in (True, False)}
    # state zt at grid point b (fresh = False) or, just after an event, at time tau inside
    # (t_{b}, t_{b+1}) (fresh = True)
    b, tau, zt, contact, fresh, events, window = 0, 0.0, z0, contact0, False, 0, 256
    while b < N:
        md = modes[contact]
        if fresh:  # partial step to the next grid point, which this mode keeps (no chatter)
            b += 1
            zt = md.step(zt, b * h - tau, _u_at(U, tau / h), U[b])
            Z[b], C[b] = zt, contact
            if b == N:
                break
        kw = min(N, b + window)
        Zs = md.run(zt, U[b:kw + 1], None if R[contact] is None else R[contact][b:kw])
        F = train.trial_force(Zs)
        bad = (F[1:] < 0.0) if contact else (F[1:] > 0.0)
        hits = np.flatnonzero(bad)
        if hits.size == 0:
            Z[b + 1:kw + 1], C[b + 1:kw + 1] = Zs[1:], contact
            b, zt, fresh, window = kw, Zs[-1], False, min(2 * window, N)
            continue
        j = int(hits[0]) + 1  # first violating point (index in Zs); Zs[j - 1] is accepted
        Z[b + 1:b + j], C[b + 1:b + j] = Zs[1:j], contact
        frac = F[j - 1] / (F[j - 1] - F[j])
        tau = (b + j - 1 + frac) * h
        zt = md.step(Zs[j - 1], frac * h, U[b + j - 1], _u_at(U, tau / h))
        b, contact, fresh, events, window = b + j - 1, not contact, True, events + 1, 64
    return Z, C, events


def _u_at(U, x):
    """Input at fractional grid index x (linear, as the first-order hold assumes)."""
    i = min(int(math.floor(x)), U.shape[0] - 2)
    f = x - i
    return (1.0 - f) * U[i] + f * U[i + 1]
