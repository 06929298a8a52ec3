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
* **Elastic shakedown** (elastic-perfectly plastic, Melan's static theorem; Johnson 1985 §9.2):
  the largest ``p0/k`` for which a residual stress ``rho_x(z)`` exists with
  ``((sx + rho_x - sz)/2)^2 + txz^2 <= k^2`` at every ``(x, z)``. At each depth a feasible
  ``rho_x`` exists iff :math:`\max_x(-g - d) \le \min_x(g - d)`,
  :math:`d = \sigma_x - \sigma_z`, :math:`g = 2\sqrt{k^2 - \tau_{xz}^2}`; found by bisection on
  ``p0/k``. It gives 4.0 without friction (the orthogonal shear ``|txz| = p0/4`` governs) and the
  surface limit ``1/mu`` at large ``mu`` (:func:`shakedown_limit`).
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
from functools import lru_cache

import numpy as np

from .. import _validate as chk
from ..hertz import max_shear, unit_stresses

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

    >>> round(first_yield_limit(0.0), 2)
    3.33
    """
    return 1.0 / float(max_shear(chk.nonnegative("mu", mu, "")).value)


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


def shakedown_limit(mu: float = 0.0) -> float:
    r"""Elastic shakedown limit ``p0/k`` of a line contact (elastic-perfectly plastic, Melan).

    .. math:: \max_x(-g-d) \le \min_x(g-d),\quad d = \sigma_x - \sigma_z,\ g = 2\sqrt{k^2-\tau_{xz}^2}

    >>> round(shakedown_limit(0.0), 2)
    4.0
    """
    return _shakedown(chk.nonnegative("mu", mu, ""))[0]


@lru_cache(maxsize=64)
def _orth(mu: float) -> tuple[float, float]:
    _, t, Z = _fields(mu)
    rng = np.max(t, axis=1) - np.min(t, axis=1)
    i = int(np.argmax(rng[1:])) + 1                       # below the surface (z > 0)
    return float(rng[i]), float(Z[i])


def orthogonal_shear_range(mu: float = 0.0) -> tuple[float, float]:
    r"""``(dtau/p0, z/a)``: the largest range of ``txz`` over one pass, and its depth (z > 0).

    .. math:: \Delta\tau = \max_z\left[\max_x\tau_{xz} - \min_x\tau_{xz}\right]

    >>> [round(v, 3) for v in orthogonal_shear_range(0.0)]
    [0.5, 0.5]
    """
    return _orth(chk.nonnegative("mu", mu, ""))


def sn_cycles(p0, strength, *, N_ref=SN_CYCLES_ISO6336, m=SN_EXPONENT_ISO6336):
    r"""Cycles to pitting ``N = N_ref (sigma_Hlim / p0)^m`` (inf where ``p0 = 0``).

    .. math:: N = N_{ref}\left(\frac{\sigma_{Hlim}}{p_0}\right)^m

    >>> f"{float(sn_cycles(1.6e9, 1.0e9)):.3g}"      # Z_NT = 1.6 at 1e5 cycles
    '1e+05'
    """
    p0 = np.asarray(p0, float)
    strength = chk.positive("strength", strength, "Pa")
    with np.errstate(divide="ignore"):
        return np.where(p0 > 0, N_ref * (strength / np.where(p0 > 0, p0, 1.0)) ** m, np.inf)
