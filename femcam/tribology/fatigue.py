r"""Yield, shakedown and contact fatigue of a Hertz line contact with sliding friction.

Symbols (Johnson, *Contact Mechanics*, 1985, §4.2, §9.2; Johnson 1989)
---------------------------------------------------------------------
==========  ========================================================  =====  =========================
symbol      meaning                                                   unit   source
==========  ========================================================  =====  =========================
p0, a       Hertz peak pressure and half-width                        Pa, m  Johnson 1985 eq. 4.45
mu          sliding friction coefficient, ``q = mu p``                -
k           yield stress in shear (Tresca: ``k = Y / 2``)             Pa     Johnson 1985 §9.2
rho_x(z)    residual stress parallel to the surface (free of ``x``)   Pa     Johnson 1985 §9.2
dtau        range of the orthogonal shear ``txz`` over one pass       Pa     Johnson 1985 §9.2
tau_e       shear fatigue (endurance) limit                           Pa
sigma_Hlim  contact fatigue strength (allowable ``p0`` at N_ref)      Pa     ISO 6336-2 / AGMA 2001
N_ref, m    reference cycles and exponent of the S-N law              -      ISO 6336-2 (Z_NT)
==========  ========================================================  =====  =========================

* **First yield** (Tresca): the largest in-plane principal shear of the McEwen field reaches ``k``:
  ``p0/k = 1 / max(tau1/p0)``; ``3.33`` without friction (Johnson 1985 §4.2: ``tau1 = 0.300 p0``).
* **Shakedown**, elastic-perfectly plastic (Melan's static theorem; Johnson 1985 §9.2):
  the largest ``p0/k`` for which a residual stress ``rho_x(z)`` exists with
  ``((sx + rho_x - sz)/2)^2 + txz^2 <= k^2`` at every ``(x, z)``. At each depth a feasible
  ``rho_x`` exists iff :math:`\max_x(-g - d) \le \min_x(g - d)`,
  :math:`d = \sigma_x - \sigma_z`, :math:`g = 2\sqrt{k^2 - \tau_{xz}^2}`; found by bisection on
  ``p0/k``. It gives 4.0 without friction (the orthogonal shear ``|txz| = p0/4`` governs) and the
  surface limit ``1/mu`` at large ``mu`` (:func:`shakedown_limit`). Kinematic hardening
  (``hardening="kinematic"``): the smallest circle enclosing the stress path of one pass at each
  depth (Welzl 1991) has radius ``k``; also 4.0 without friction, higher than the perfectly
  plastic limit with friction, and ``1/mu`` once the surface governs.
* **Subsurface fatigue**: the range of the orthogonal shear stress over one pass through the
  contact, ``dtau = 0.5 p0`` at ``z = 0.5 a`` without friction (Johnson 1985 §9.2), against a
  shear endurance limit: utilisation ``(dtau/2) / tau_e``.
* **Surface fatigue**: ``p0`` against the contact fatigue strength with an S-N law
  ``N = N_ref (sigma_Hlim / p0)^m`` (ISO 6336-2 life factor Z_NT for through/case-hardened
  steel: 1.6 at 1e5 cycles, 1.0 at 5e7, i.e. ``m = ln(500)/ln(1.6) = 13.2``).

All dimensionless limits depend on ``mu`` only and are computed once per ``mu`` (cached).
"""

from __future__ import annotations

import math
import random
from functools import lru_cache

import numpy as np

from .. import _validate
from ..hertz import max_shear, max_shear_range, unit_stresses

#: ISO 6336-2 Z_NT slope (see the module docstring) and its reference cycles
SN_EXPONENT_ISO6336 = math.log(5e7 / 1e5) / math.log(1.6)
SN_CYCLES_ISO6336 = 5e7


def _grid(n_x=601, n_z=151):
    X = np.linspace(-3.0, 3.0, n_x)
    Z = np.linspace(0.0, 1.5, n_z)
    return X[None, :], Z[:, None]


@lru_cache(maxsize=64)
def _fields(mu: float):
    X, Z = _grid()
    sx, sz, txz = unit_stresses(X, Z, mu)
    return sx - sz, txz, Z[:, 0]


def first_yield_limit(mu: float = 0.0) -> float:
    r"""``p0/k`` at first yield (Tresca, in-plane principal shear), from the McEwen field.

    .. math:: \left(\frac{p_0}{k}\right)_{y} = \frac{1}{\max \tau_1/p_0}

    Parameters
    ----------
    mu : float
        Sliding friction coefficient, ``>= 0`` [-].

    Returns
    -------
    float
        Load factor ``p0/k`` at first yield [-].

    Examples
    --------
    >>> round(first_yield_limit(0.0), 2)
    3.33
    """
    return 1.0 / float(max_shear(_validate.nonnegative("mu", mu, "")).value)


@lru_cache(maxsize=64)
def _shakedown(mu: float) -> tuple[float, float]:
    d, t, Z = _fields(mu)
    lo, hi = np.zeros(Z.size), np.full(Z.size, 1.0 / max(float(np.max(np.abs(t))), 1e-12))
    for _ in range(40):                                  # bisection on P = p0/k at every depth
        P = 0.5 * (lo + hi)[:, None]
        g = 2.0 * np.sqrt(np.clip(1.0 - (t * P) ** 2, 0.0, None))
        ok = np.max(-g - d * P, axis=1) <= np.min(g - d * P, axis=1)
        lo, hi = np.where(ok, 0.5 * (lo + hi), lo), np.where(ok, hi, 0.5 * (lo + hi))
    i = int(np.argmin(lo))
    return float(lo[i]), float(Z[i])


def _circle2(a, b):
    cx, cy = 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])
    return cx, cy, math.hypot(a[0] - cx, a[1] - cy)


def _circle3(a, b, c):
    (ax, ay), (bx, by), (cx, cy) = a, b, c
    d = 2.0 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    if d == 0.0:                                         # collinear: the widest pair
        return max((_circle2(p, q) for p, q in ((a, b), (a, c), (b, c))), key=lambda t: t[2])
    a2, b2, c2 = ax * ax + ay * ay, bx * bx + by * by, cx * cx + cy * cy
    ux = (a2 * (by - cy) + b2 * (cy - ay) + c2 * (ay - by)) / d
    uy = (a2 * (cx - bx) + b2 * (ax - cx) + c2 * (bx - ax)) / d
    return ux, uy, math.hypot(ax - ux, ay - uy)


def enclosing_radius(P) -> float:
    """Radius of the smallest circle enclosing the 2-D points ``P`` (n x 2): Welzl's algorithm
    (Welzl 1991, iterative form, expected linear time) on the convex hull.

    Parameters
    ----------
    P : array_like, shape (n, 2)
        Points in a plane (any length or stress unit; here ``((sx - sz)/2, txz) / p0``).

    Returns
    -------
    float
        Radius of the smallest enclosing circle [unit of ``P``].

    Examples
    --------
    >>> enclosing_radius(np.array([[1.0, 0.0], [-1.0, 0.0], [0.0, 0.5], [0.0, -1.0]]))
    1.0
    """
    from scipy.spatial import ConvexHull, QhullError  # lazy: scipy.spatial, ~0.03 s to import

    P = np.asarray(P, float)
    try:
        P = P[ConvexHull(P).vertices]
    except QhullError:                                   # flat or repeated points: extremes suffice
        P = P[[int(np.argmin(P[:, 0])), int(np.argmax(P[:, 0])), int(np.argmin(P[:, 1])),
               int(np.argmax(P[:, 1]))]]
    pts = [tuple(p) for p in P.tolist()]
    random.Random(0).shuffle(pts)
    cx, cy, r = pts[0][0], pts[0][1], 0.0
    tol = 1e-12
    for i, p in enumerate(pts):
        if math.hypot(p[0] - cx, p[1] - cy) <= r + tol:
            continue
        cx, cy, r = p[0], p[1], 0.0
        for j in range(i):
            q = pts[j]
            if math.hypot(q[0] - cx, q[1] - cy) <= r + tol:
                continue
            cx, cy, r = _circle2(p, q)
            for k in range(j):
                if math.hypot(pts[k][0] - cx, pts[k][1] - cy) > r + tol:
                    cx, cy, r = _circle3(p, q, pts[k])
    return float(r)


@lru_cache(maxsize=64)
def _kinematic(mu: float) -> float:
    """Largest enclosing radius (units of p0) of the in-plane stress path over one pass, over z."""
    X, Z = _grid()
    sx, sz, txz = unit_stresses(X, Z, mu)
    d = 0.5 * (sx - sz)
    rd = np.maximum(d.max(axis=1), 0.0) - np.minimum(d.min(axis=1), 0.0)     # (0, 0): unloaded state
    rt = np.maximum(txz.max(axis=1), 0.0) - np.minimum(txz.min(axis=1), 0.0)
    upper, best = 0.5 * np.hypot(rd, rt), float(np.max(0.5 * np.maximum(rd, rt)))
    for i in np.argsort(-upper):                         # branch and bound over the depths
        if upper[i] <= best:
            break
        best = max(best, enclosing_radius(np.column_stack([np.append(d[i], 0.0), np.append(txz[i], 0.0)])))
    return best


def shakedown_limit(mu: float = 0.0, hardening: str = "perfectly_plastic") -> float:
    r"""Shakedown limit ``p0/k`` of a line contact with friction ``mu``.

    ``hardening="perfectly_plastic"`` (default, the lower and so conservative limit): Melan's
    theorem with a residual ``rho_x(z)``,

    .. math:: \max_x(-g-d) \le \min_x(g-d),\quad d = \sigma_x - \sigma_z,\ g = 2\sqrt{k^2-\tau_{xz}^2}

    ``hardening="kinematic"`` (plastic shakedown of a kinematically hardening material): the back
    stress may move the yield circle anywhere, so the limit is reached when the smallest circle
    enclosing the in-plane stress path ``((sx - sz)/2, txz)`` over one pass (with the unloaded
    state) has radius ``k`` at some depth (Johnson 1985 §9.2; Johnson 1989).

    Parameters
    ----------
    mu : float
        Sliding friction coefficient, ``>= 0`` [-].
    hardening : {"perfectly_plastic", "kinematic"}
        Material model of the shakedown theorem.

    Returns
    -------
    float
        Shakedown limit ``p0/k`` [-].

    Raises
    ------
    InputError
        ``mu < 0`` or an unknown ``hardening``.

    Examples
    --------
    >>> round(shakedown_limit(0.0), 2), round(shakedown_limit(0.0, "kinematic"), 2)
    (4.0, 4.0)
    """
    mu = _validate.nonnegative("mu", mu, "")
    _validate.choice("hardening", hardening, ("perfectly_plastic", "kinematic"))
    return _shakedown(mu)[0] if hardening == "perfectly_plastic" else 1.0 / _kinematic(mu)


def orthogonal_shear_range(mu: float = 0.0) -> tuple[float, float]:
    r"""``(dtau/p0, z/a)``: the largest range of ``txz`` over one pass, and its depth.

    .. math:: \Delta\tau = \max_z\left[\max_x\tau_{xz} - \min_x\tau_{xz}\right]

    The McEwen field's :func:`femcam.hertz.max_shear_range` (the sweep's Hertz rows use the same
    function, so a Hertz-fed and a Hertz-row-fed assessment agree): ``0.5`` at ``z = 0.5 a`` for
    ``mu`` up to about 0.5, then the surface range ``mu``.

    Parameters
    ----------
    mu : float
        Sliding friction coefficient, ``>= 0`` [-].

    Returns
    -------
    tuple of float
        ``(dtau/p0, z/a)``: orthogonal shear range over one pass and its depth, both normalised
        by the Hertz peak pressure and half-width [-].

    Examples
    --------
    >>> [round(v, 3) for v in orthogonal_shear_range(0.0)]
    [0.5, 0.5]
    """
    m = max_shear_range(_validate.nonnegative("mu", mu, ""))
    return m.value, m.z


def sn_cycles(p0, strength, *, N_ref=SN_CYCLES_ISO6336, m=SN_EXPONENT_ISO6336):
    r"""Cycles to pitting ``N = N_ref (sigma_Hlim / p0)^m`` (inf where ``p0 = 0``).

    .. math:: N = N_{ref}\left(\frac{\sigma_{Hlim}}{p_0}\right)^m

    Parameters
    ----------
    p0 : float or ndarray
        Hertz peak pressure, ``>= 0`` [Pa].
    strength : float
        Contact fatigue strength ``sigma_Hlim`` at ``N_ref`` cycles [Pa].
    N_ref : float
        Reference cycles of the S-N law [-] (default ISO 6336-2, ``5e7``).
    m : float
        Exponent of the S-N law [-] (default ISO 6336-2, ``13.2``).

    Returns
    -------
    ndarray, shape of ``p0``
        Cycles to pitting [-]; ``inf`` where ``p0 = 0``.

    Examples
    --------
    >>> f"{float(sn_cycles(1.6e9, 1.0e9)):.3g}"      # Z_NT = 1.6 at 1e5 cycles
    '1e+05'
    """
    p0 = _validate.nonnegative_array("p0", p0, "Pa")
    strength = _validate.positive("strength", strength, "Pa")
    N_ref = _validate.positive("N_ref", N_ref, "")
    m = _validate.positive("m", m, "")
    with np.errstate(divide="ignore"):
        return np.where(p0 > 0, N_ref * (strength / np.where(p0 > 0, p0, 1.0)) ** m, np.inf)
