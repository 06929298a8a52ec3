r"""Normalised cam motion laws: unit lift over the unit interval.

A motion law maps the normalised cam angle ``u = (theta - theta_0)/beta`` in [0, 1] to the
normalised lift ``s(u)`` in units of the segment lift ``h`` (``s(0) = 0``, ``s(1) = 1``).
Every law gives its first three derivatives *exactly* (closed forms, no finite differences):

.. math:: v = ds/du, \quad a = d^2 s/du^2, \quad j = d^3 s/du^3

and the peak coefficients ``Cv = max|v|``, ``Ca = max|a|``, ``Cj = max|j|`` over [0, 1].
For a rise of lift ``h`` over ``beta`` rad at constant speed ``omega`` the physical peaks are
``Cv h omega/beta``, ``Ca h omega^2/beta^2`` and ``Cj h omega^3/beta^3``.

Symbols
-------
=======  ==========================================  =====  ==================================
symbol   meaning                                      unit   source
=======  ==========================================  =====  ==================================
u        normalised cam angle, theta/beta             -      Norton, *Cam Design and
                                                             Manufacturing Handbook* (2009) ch. 3
s        normalised lift                              -      same
v, a, j  d^k s / du^k, k = 1, 2, 3                    -      same
Cv..Cj   peak |v|, |a|, |j| on [0, 1]                 -      Norton (2009) table 3-2
P_i      Bezier control points (P_0 = 0, P_n = 1)     -      seed 002 eq. 1 (corrected)
=======  ==========================================  =====  ==================================

Singular ends (delta functions)
-------------------------------
Cv, Ca, Cj are peaks of the *smooth* functions on the closed interval. A law whose ``v`` is not
zero at an end (uniform velocity) produces a step in velocity against a dwell, i.e. an
infinite (delta-function) acceleration; a law whose ``a`` is not zero at an end (SHM) produces
a step in acceleration, i.e. infinite jerk. These are properties of a *junction* between
segments, so the laws only report their end values (:attr:`MotionLaw.ends`) and
:class:`femcam.kinematics.CamProgram.junctions` detects the jumps.

Seed 002 eq. 1 typo
-------------------
Seed 002 prints the Bernstein basis as ``C(n,i) u^i (1-u)^(n-1)``; the exponent must be
``n - i``. With ``n - 1`` the basis is not a partition of unity and the degree-5 curve with
control points 0,0,0,1,1,1 does not give the paper's own eq. 12 (``10u^3 - 15u^4 + 6u^5``).
"""

from __future__ import annotations

from functools import cached_property
from math import comb, pi

import numpy as np

from .. import _validate
from ..errors import InputError

__all__ = ["LAW_NAMES", "MotionLaw", "LawEnds", "law", "bernstein"]

#: every name accepted by :func:`law`
LAW_NAMES = (
    "uniform_velocity",
    "shm",
    "cycloidal",
    "poly345",
    "poly4567",
    "modified_sine",
    "modified_trapezoid",
    "bezier5",
    "bezier7",
    "bezier9",
    "bezier",
    "polynomial",
)

_U_TOL = 1e-12  # u may overshoot [0, 1] by this much (round-off in theta - theta_0)
_N_SAMPLE = 4001  # dense sampling for the peak search, then zoomed sampling (_peak)
_N_ZOOM = 1001  # samples per zoom of the peak search


def bernstein(n: int, i: int, u) -> np.ndarray:
    r"""Bernstein basis polynomial of degree ``n``.

    .. math:: B_i^n(u) = \binom{n}{i} u^i (1-u)^{n-i}

    Reference: seed 002 eq. 1, with the printed exponent ``n - 1`` corrected to ``n - i``.

    Parameters
    ----------
    n : int
        Degree, ``>= 0``.
    i : int
        Index of the basis polynomial, ``0 <= i <= n``.
    u : float or array_like
        Normalised parameter [-], usually in [0, 1].

    Returns
    -------
    ndarray
        :math:`B_i^n(u)` [-], float, the shape of ``u``.

    Examples
    --------
    >>> round(float(sum(bernstein(5, i, 0.3) for i in range(6))), 12)  # partition of unity
    1.0
    """
    n = _validate.integer("n", n, 0)
    i = _validate.integer("i", i, 0)
    u = _validate.finite_array("u", u, "")
    return comb(n, i) * u**i * (1.0 - u) ** (n - i)


class LawEnds:
    """Values of v, a, j (d^k s/du^k) at u = 0 and u = 1, for junction analysis.

    All values are normalised (derivatives of the unit lift with respect to ``u``), stored as
    ``float``.

    Parameters
    ----------
    v0, a0, j0 : float
        ``ds/du``, ``d^2 s/du^2``, ``d^3 s/du^3`` at ``u = 0`` [-].
    v1, a1, j1 : float
        The same at ``u = 1`` [-].
    """

    __slots__ = ("v0", "a0", "j0", "v1", "a1", "j1")

    def __init__(self, v0, a0, j0, v1, a1, j1):
        self.v0, self.a0, self.j0 = float(v0), float(a0), float(j0)
        self.v1, self.a1, self.j1 = float(v1), float(a1), float(j1)

    def __repr__(self):
        return (f"LawEnds(u=0: v={self.v0:g}, a={self.a0:g}, j={self.j0:g}; "
                f"u=1: v={self.v1:g}, a={self.a1:g}, j={self.j1:g})")


class MotionLaw:
    """Base class of the normalised motion laws (use :func:`law` to build one).

    Subclasses implement ``_deriv(u, k)`` for k = 0..3 on a validated float array ``u``.
    """

    name: str = "?"
    #: interior points where the closed form changes piece (helps the peak search)
    breakpoints: tuple = ()

    def _deriv(self, u: np.ndarray, k: int) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    @staticmethod
    def _u(u) -> np.ndarray:
        arr = _validate.finite_array("u", u, "")
        if arr.size and (arr.min() < -_U_TOL or arr.max() > 1.0 + _U_TOL):
            bad = arr[(arr < -_U_TOL) | (arr > 1.0 + _U_TOL)].flat[0]
            raise _validate.fail("u", float(bad), "", "must be in [0, 1] (normalised cam angle)")
        return np.clip(arr, 0.0, 1.0)

    def s(self, u) -> np.ndarray:
        """Normalised lift s(u).

        Parameters
        ----------
        u : float or array_like
            Normalised cam angle [-] in [0, 1] (round-off overshoot up to 1e-12 is clipped).

        Returns
        -------
        ndarray
            Lift ``s`` in units of the segment lift ``h`` [-], float, the shape of ``u``.

        Raises
        ------
        InputError
            ``u`` not finite or outside [0, 1].
        """
        return self._deriv(self._u(u), 0)

    def v(self, u) -> np.ndarray:
        """ds/du.

        Parameters
        ----------
        u : float or array_like
            Normalised cam angle [-] in [0, 1] (round-off overshoot up to 1e-12 is clipped).

        Returns
        -------
        ndarray
            ``ds/du`` [-], float, the shape of ``u``.

        Raises
        ------
        InputError
            ``u`` not finite or outside [0, 1].
        """
        return self._deriv(self._u(u), 1)

    def a(self, u) -> np.ndarray:
        """d^2 s/du^2.

        Parameters
        ----------
        u : float or array_like
            Normalised cam angle [-] in [0, 1] (round-off overshoot up to 1e-12 is clipped).

        Returns
        -------
        ndarray
            ``d^2 s/du^2`` [-], float, the shape of ``u``.

        Raises
        ------
        InputError
            ``u`` not finite or outside [0, 1].
        """
        return self._deriv(self._u(u), 2)

    def j(self, u) -> np.ndarray:
        """d^3 s/du^3.

        Parameters
        ----------
        u : float or array_like
            Normalised cam angle [-] in [0, 1] (round-off overshoot up to 1e-12 is clipped).

        Returns
        -------
        ndarray
            ``d^3 s/du^3`` [-], float, the shape of ``u``.

        Raises
        ------
        InputError
            ``u`` not finite or outside [0, 1].
        """
        return self._deriv(self._u(u), 3)

    def derivative(self, u, k: int) -> np.ndarray:
        """d^k s/du^k for k in 0..3.

        Parameters
        ----------
        u : float or array_like
            Normalised cam angle [-] in [0, 1].
        k : int
            Order of the derivative, 0, 1, 2 or 3.

        Returns
        -------
        ndarray
            ``d^k s/du^k`` [-], float, the shape of ``u``.

        Raises
        ------
        InputError
            ``k`` not in 0..3, or ``u`` not finite or outside [0, 1].
        """
        if k not in (0, 1, 2, 3):
            raise _validate.fail("k", k, "", "must be 0, 1, 2 or 3")
        return self._deriv(self._u(u), k)

    # --- peaks -------------------------------------------------------------------------
    def _peak(self, k: int) -> float:
        """max |d^k s/du^k| on [0, 1]: dense sampling, then the same sampling zoomed four times
        onto +-1 step around the best sample (each zoom shrinks the step ~500x, to ~1e-14 in u;
        numpy only, so the main job does not import scipy.optimize)."""
        u = np.union1d(np.linspace(0.0, 1.0, _N_SAMPLE), np.asarray(self.breakpoints, float))
        best = 0.0
        for _ in range(5):
            f = np.abs(self._deriv(u, k))
            i = int(np.argmax(f))
            best = max(best, float(f[i]))
            lo, hi = u[max(i - 1, 0)], u[min(i + 1, u.size - 1)]
            if not hi > lo:
                break
            u = np.linspace(lo, hi, _N_ZOOM)
        return best

    @cached_property
    def Cv(self) -> float:
        """Peak ``|ds/du|`` on [0, 1]."""
        return self._peak(1)

    @cached_property
    def Ca(self) -> float:
        """Peak ``|d^2 s/du^2|`` on [0, 1] (delta functions at the ends are *not* included)."""
        return self._peak(2)

    @cached_property
    def Cj(self) -> float:
        """Peak ``|d^3 s/du^3|`` on [0, 1] (delta functions at the ends are *not* included)."""
        return self._peak(3)

    @cached_property
    def s_range(self) -> tuple[float, float]:
        """(min s, max s) on [0, 1]; (0, 1) for monotone laws, wider if a Bezier overshoots."""
        u = np.union1d(np.linspace(0.0, 1.0, _N_SAMPLE), np.asarray(self.breakpoints, float))
        s = self._deriv(u, 0)
        return float(min(s.min(), 0.0)), float(max(s.max(), 1.0))

    @cached_property
    def ends(self) -> LawEnds:
        """v, a, j at u = 0 and u = 1."""
        e = np.array([0.0, 1.0])
        v, a, j = (self._deriv(e, k) for k in (1, 2, 3))
        return LawEnds(v[0], a[0], j[0], v[1], a[1], j[1])

    @property
    def v_end_nonzero(self) -> bool:
        """True if v != 0 at an end: against a dwell this gives infinite acceleration."""
        e = self.ends
        return abs(e.v0) > 1e-9 * max(self.Cv, 1.0) or abs(e.v1) > 1e-9 * max(self.Cv, 1.0)

    @property
    def a_end_nonzero(self) -> bool:
        """True if a != 0 at an end: against a dwell this gives infinite jerk."""
        e = self.ends
        tol = 1e-9 * max(self.Ca, 1.0)
        return abs(e.a0) > tol or abs(e.a1) > tol

    def __repr__(self):
        return f"<MotionLaw {self.name}>"


# --- closed-form elementary laws ---------------------------------------------------------


class _UniformVelocity(MotionLaw):
    r"""Uniform (constant) velocity: :math:`s = u`. Norton (2009) sec. 3.3; a is a delta at the ends."""

    name = "uniform_velocity"

    def _deriv(self, u, k):
        return u.copy() if k == 0 else (np.ones_like(u) if k == 1 else np.zeros_like(u))


class _SHM(MotionLaw):
    r"""Simple harmonic motion: :math:`s = (1 - \cos \pi u)/2`. Norton (2009) eq. 3.5."""

    name = "shm"

    def _deriv(self, u, k):
        x = pi * u
        return [0.5 * (1.0 - np.cos(x)), 0.5 * pi * np.sin(x), 0.5 * pi**2 * np.cos(x),
                -0.5 * pi**3 * np.sin(x)][k]


class _Cycloidal(MotionLaw):
    r"""Cycloidal: :math:`s = u - \sin(2\pi u)/(2\pi)`. Norton (2009) eq. 3.8."""

    name = "cycloidal"

    def _deriv(self, u, k):
        x = 2.0 * pi * u
        return [u - np.sin(x) / (2.0 * pi), 1.0 - np.cos(x), 2.0 * pi * np.sin(x),
                4.0 * pi**2 * np.cos(x)][k]


class _Polynomial(MotionLaw):
    r"""Polynomial :math:`s = \sum_k c_k u^k` (coefficients ascending), e.g. 3-4-5 (Norton eq. 3.13)."""

    def __init__(self, coefficients, name="polynomial"):
        c = _validate.finite_array("coefficients", coefficients, "")
        if c.ndim != 1 or c.size < 2:
            raise _validate.fail("coefficients", coefficients, "", "must be a 1-D list of >= 2 numbers "
                                 "c_0..c_n (s = sum c_k u^k)")
        if abs(c[0]) > 1e-12:
            raise _validate.fail("coefficients[0]", float(c[0]), "", "must be 0 so that s(0) = 0")
        if abs(c.sum() - 1.0) > 1e-9:
            raise _validate.fail("sum(coefficients)", float(c.sum()), "", "must be 1 so that s(1) = 1")
        self.name = name
        self.coefficients = c
        P = np.polynomial.polynomial
        self._c = [c, P.polyder(c, 1), P.polyder(c, 2), P.polyder(c, 3)]

    def _deriv(self, u, k):
        return np.polynomial.polynomial.polyval(u, self._c[k])


class _Bezier(MotionLaw):
    r"""Bezier (Bernstein) law of degree n with control points :math:`P_0 = 0, ..., P_n = 1`.

    .. math:: s(u) = \sum_{i=0}^n P_i B_i^n(u), \qquad
              \frac{d^k s}{du^k} = \frac{n!}{(n-k)!} \sum_{i=0}^{n-k} \Delta^k P_i B_i^{n-k}(u)

    evaluated by de Casteljau's algorithm (vectorised over u; one loop over the degree).
    Reference: seed 002 eq. 1 (exponent corrected, see module docstring); Farin,
    *Curves and Surfaces for CAGD*, ch. 4-5.
    """

    def __init__(self, control_points, name="bezier"):
        P = _validate.finite_array("control_points", control_points, "")
        if P.ndim != 1 or P.size < 2:
            raise _validate.fail("control_points", control_points, "", "must be a 1-D list of >= 2 numbers")
        if abs(P[0]) > 1e-12:
            raise _validate.fail("control_points[0]", float(P[0]), "", "must be 0 so that s(0) = 0")
        if abs(P[-1] - 1.0) > 1e-12:
            raise _validate.fail("control_points[-1]", float(P[-1]), "", "must be 1 so that s(1) = 1")
        self.name = name
        self.control_points = P
        self.degree = n = P.size - 1
        # derivative control polygons: n!/(n-k)! * forward differences of order k
        self._D = []
        for k in range(4):
            if k <= n:
                self._D.append(np.diff(P, k) * (comb(n, k) * np.prod(np.arange(1, k + 1))))
            else:
                self._D.append(np.zeros(1))

    @staticmethod
    def _casteljau(D, u):
        b = np.broadcast_to(D[:, None], (D.size, u.size)).copy()
        for _ in range(D.size - 1):
            b = (1.0 - u) * b[:-1] + u * b[1:]
        return b[0]

    def _deriv(self, u, k):
        shape = u.shape
        return self._casteljau(self._D[k], u.ravel()).reshape(shape)


class _PiecewiseSine(MotionLaw):
    r"""Laws built from pieces of sinusoidal and constant acceleration (modified sine/trapezoid).

    On piece ``[u_0, u_1]`` with ``t = u - u_0``, integrating twice in closed form:

    .. math::
        a = c_0 + c_1 \sin(w t + \varphi), \quad j = c_1 w \cos(w t + \varphi) \\
        v = v_0 + c_0 t - \frac{c_1}{w}(\cos(w t + \varphi) - \cos\varphi) \\
        s = s_0 + v_0 t + \frac{c_0 t^2}{2}
            - \frac{c_1}{w}\Big(\frac{\sin(w t + \varphi) - \sin\varphi}{w} - t\cos\varphi\Big)

    ``s_0, v_0`` are chained from the previous piece, so s and v are continuous by
    construction; the pieces are defined so that a is continuous too. Finally everything is
    scaled by ``1/s(1)`` so that the lift is 1 (that scale is the law's ``Ca``).
    Reference: Norton (2009) sec. 3.9 (modified trapezoid) and 3.10 (modified sine).
    """

    def __init__(self, name, edges, pieces):
        self.name = name
        self._edges = np.asarray(edges, float)
        self.breakpoints = tuple(self._edges[1:-1])
        c0, c1, w, ph = (np.array(x, float) for x in zip(*pieces, strict=True))
        s0 = np.zeros(c0.size)
        v0 = np.zeros(c0.size)
        for p in range(c0.size - 1):  # chain the integration constants (loop over pieces)
            T = self._edges[p + 1] - self._edges[p]
            s0[p + 1], v0[p + 1] = self._sv(T, c0[p], c1[p], w[p], ph[p], s0[p], v0[p])
        T = self._edges[-1] - self._edges[-2]
        s_end, _ = self._sv(T, c0[-1], c1[-1], w[-1], ph[-1], s0[-1], v0[-1])
        scale = 1.0 / s_end
        self._c0, self._c1, self._w, self._ph = c0 * scale, c1 * scale, w, ph
        self._s0, self._v0 = s0 * scale, v0 * scale

    @staticmethod
    def _sv(t, c0, c1, w, ph, s0, v0):
        v = v0 + c0 * t - c1 / w * (np.cos(w * t + ph) - np.cos(ph))
        s = s0 + v0 * t + 0.5 * c0 * t**2 - c1 / w * ((np.sin(w * t + ph) - np.sin(ph)) / w
                                                      - t * np.cos(ph))
        return s, v

    def _deriv(self, u, k):
        p = np.clip(np.searchsorted(self._edges, u, side="right") - 1, 0, self._c0.size - 1)
        t = u - self._edges[p]
        c0, c1, w, ph = self._c0[p], self._c1[p], self._w[p], self._ph[p]
        if k == 0:
            return self._sv(t, c0, c1, w, ph, self._s0[p], self._v0[p])[0]
        if k == 1:
            return self._sv(t, c0, c1, w, ph, self._s0[p], self._v0[p])[1]
        if k == 2:
            return c0 + c1 * np.sin(w * t + ph)
        return c1 * w * np.cos(w * t + ph)


def _modified_trapezoid():
    # acceleration (before scaling): quarter sine up over 1/8, flat 1/4, half cosine down over
    # 1/4, flat -1 over 1/4, quarter cosine back to zero over 1/8 (Norton 2009 fig. 3-8).
    w = 4.0 * pi
    pieces = [(0.0, 1.0, w, 0.0), (1.0, 0.0, 1.0, 0.0), (0.0, 1.0, w, pi / 2),
              (-1.0, 0.0, 1.0, 0.0), (0.0, 1.0, w, -pi / 2)]
    return _PiecewiseSine("modified_trapezoid", [0, 1 / 8, 3 / 8, 5 / 8, 7 / 8, 1], pieces)


def _modified_sine():
    # acceleration: quarter sine of period 1/2 up to the peak at u = 1/8, a sine of period 3/2
    # from +peak (u = 1/8) through zero (u = 1/2) to -peak (u = 7/8), quarter sine back to 0.
    w = 4.0 * pi
    pieces = [(0.0, 1.0, w, 0.0), (0.0, 1.0, w / 3.0, pi / 2), (0.0, 1.0, w, -pi / 2)]
    return _PiecewiseSine("modified_sine", [0, 1 / 8, 7 / 8, 1], pieces)


_FIXED = {
    "uniform_velocity": _UniformVelocity,
    "shm": _SHM,
    "cycloidal": _Cycloidal,
    # 3-4-5 and 4-5-6-7 polynomials, Norton (2009) eqs. 3.13 and 3.14
    "poly345": lambda: _Polynomial([0, 0, 0, 10, -15, 6], name="poly345"),
    "poly4567": lambda: _Polynomial([0, 0, 0, 0, 35, -84, 70, -20], name="poly4567"),
    "modified_sine": _modified_sine,
    "modified_trapezoid": _modified_trapezoid,
    # seed 002 eqs. 12-14 are Bezier curves with half the control points 0 and half 1
    "bezier5": lambda: _Bezier([0, 0, 0, 1, 1, 1], name="bezier5"),
    "bezier7": lambda: _Bezier([0, 0, 0, 0, 1, 1, 1, 1], name="bezier7"),
    "bezier9": lambda: _Bezier([0] * 5 + [1] * 5, name="bezier9"),
}


def law(name: str, **params) -> MotionLaw:
    """Build a normalised motion law by name.

    ``law("bezier", control_points=[0, 0, 0, 1, 1, 1])`` and
    ``law("polynomial", coefficients=[0, 0, 0, 10, -15, 6])`` take parameters; the other
    names in :data:`LAW_NAMES` take none. A :class:`MotionLaw` passed as ``name`` is returned.

    Parameters
    ----------
    name : str or MotionLaw
        One of :data:`LAW_NAMES`, or a ready :class:`MotionLaw` (returned unchanged).
    **params
        ``control_points`` (Bezier ordinates [-], first 0, last 1) for ``"bezier"``, or
        ``coefficients`` (ascending powers of ``u`` [-], ``c_0 = 0``, sum 1) for
        ``"polynomial"``; nothing for the other names.

    Returns
    -------
    MotionLaw
        The normalised law ``s(u)`` with exact derivatives and peak coefficients.

    Raises
    ------
    InputError
        Unknown name, missing or unexpected parameters, or invalid control points/coefficients.

    Examples
    --------
    >>> round(law("cycloidal").Cv, 6)
    2.0
    """
    if isinstance(name, MotionLaw):
        if params:
            raise InputError(f"law: parameters {sorted(params)} given with a ready MotionLaw")
        return name
    if not isinstance(name, str) or name not in LAW_NAMES:
        raise InputError(f"law = {name!r}: unknown motion law; valid names: {', '.join(LAW_NAMES)}")
    if name == "bezier":
        if set(params) != {"control_points"}:
            raise InputError(f"law 'bezier' needs exactly control_points=[...]; got {sorted(params)}")
        return _Bezier(params["control_points"])
    if name == "polynomial":
        if set(params) != {"coefficients"}:
            raise InputError(f"law 'polynomial' needs exactly coefficients=[...]; got {sorted(params)}")
        return _Polynomial(params["coefficients"])
    if params:
        raise InputError(f"law {name!r} takes no parameters; got {sorted(params)}")
    return _FIXED[name]()
