r"""Roller on a cam of signed curvature: does the roller fit, how parabolic is the gap, how wide
is the contact for sizing a mesh, and the self-similar Hertz maxima.

One copy of each check, used by the mesh (:mod:`femcam.mesh`), the FE model
(:mod:`femcam.fe.model`) and the sweep (:mod:`femcam.sweep`).

==========  ==========================================================  =======  ==================
symbol      meaning                                                     unit     source
==========  ==========================================================  =======  ==================
``rho``     cam surface radius of curvature (< 0 concave, inf flat)     m        Johnson 1985 §4.3
``Rr``      roller radius (> 0)                                         m
``1/R``     curvature sum ``1/rho + 1/Rr``                              1/m      Johnson 1985 (4.44)
``a``       contact half-width                                          m        Johnson 1985 (4.45)
``eps``     quartic / quadratic gap term at ``x = a``                   1        Taylor series
``w``       load per unit length ``F / l``                              N/m
``E_star``  plane effective modulus                                     Pa       Johnson 1985 (4.22)
==========  ==========================================================  =======  ==================

References: docs/references.md (Johnson 1985; McEwen 1949; seed 002).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .contact import _effective_radius, half_width
from .maxima import max_shear, max_shear_range, max_von_mises
from .surface import surface_stress

#: ``nearly_conformal`` flag threshold on :func:`gap_nonparabolicity`
NEARLY_CONFORMAL_GAP = 1e-3
#: cap on ``|R| / Rr`` in :func:`sizing_half_width` (nearly conformal: the FE decides the width)
SIZING_R_CAP = 1e3


def roller_does_not_fit(rho, Rr) -> np.ndarray:
    r"""True where a concave cam is no wider than the roller: no contact solution.

    .. math:: \frac{1}{\rho} + \frac{1}{R_r} \le 0

    For a roller follower ``rho = rho_pitch - Rr``, so ``-Rr < rho < 0`` means a convex pitch
    curve tighter than the roller (an undercut cam) and ``rho = -Rr`` a perfectly conformal
    (zero-clearance) fit. Neither Hertz nor the FE has a contact solution there.

    Parameters
    ----------
    rho : float or ndarray
        Cam radius of curvature (m; negative concave, ``inf`` flat).
    Rr : float
        Roller radius (m, > 0).

    Returns
    -------
    ndarray of bool, shape of ``rho``
        True where the roller does not fit (``1/rho + 1/Rr <= 0``).

    Examples
    --------
    >>> roller_does_not_fit([-0.009, -0.011, 0.02, np.inf], 0.01).tolist()
    [True, False, False, False]
    """
    with np.errstate(divide="ignore"):
        return (1.0 / np.asarray(rho, float) + 1.0 / Rr) <= 0.0


def undercut_message(rho: float, Rr: float) -> str:
    """Why a load case with :func:`roller_does_not_fit` has no contact solution.

    Parameters
    ----------
    rho, Rr : float
        Cam radius of curvature and roller radius (m).

    Returns
    -------
    str
        A message with both radii in mm.
    """
    return (f"concave cam with |rho| = {abs(rho) * 1e3:.6g} mm <= roller radius Rr = {Rr * 1e3:.6g} mm:"
            f" the roller does not fit the concave cam (pitch-curve radius rho + Rr = "
            f"{(rho + Rr) * 1e3:.6g} mm; undercut/interference), no contact solution")


def gap_nonparabolicity(a, rho, Rr) -> np.ndarray:
    r"""Relative error of Hertz's parabolic gap at the contact edge ``x = a``.

    The gap between two circles of signed radii ``rho`` (cam) and ``Rr`` (roller) is
    :math:`h(x) = \frac{x^2}{2}(\frac1{R_r} + \frac1\rho) + \frac{x^4}{8}(\frac1{R_r^3} +
    \frac1{\rho^3}) + O(x^6)`; Hertz keeps the first term. The ratio of the second to the first
    at ``x = a``,

    .. math:: \epsilon = \frac{a^2}{4}\,\frac{1/R_r^3 + 1/\rho^3}{1/R_r + 1/\rho},

    is tiny for convex contacts (``a^2 / 4 R^2``) but grows without bound for a concave cam
    nearly conformal with the roller, where the quadratic terms cancel and the quartic ones do
    not. (Measured: rho = -1.02 Rr, eps = 0.62 %, FE p0 - Hertz = +0.55 %; rho = -1.005 Rr,
    eps = 2.5 %, FE - Hertz = +2.4 %.)

    Parameters
    ----------
    a : float or ndarray
        Contact half-width (m).
    rho : float or ndarray
        Cam radius of curvature (m).
    Rr : float
        Roller radius (m).

    Returns
    -------
    ndarray
        ``eps`` (dimensionless).

    Examples
    --------
    >>> round(float(gap_nonparabolicity(1e-4, np.inf, 0.01)), 12)   # flat cam: a^2 / (4 Rr^2)
    2.5e-05
    """
    rho = np.asarray(rho, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        k = np.where(np.isfinite(rho), 1.0 / rho, 0.0)
        eps = 0.25 * np.asarray(a, float) ** 2 * (1.0 / Rr**3 + k**3) / (1.0 / Rr + k)
    return eps


def sizing_half_width(F, length: float, rho, Rr: float, E_star: float) -> np.ndarray:
    r"""Hertz-like half-width for sizing meshes, also where Hertz is invalid.

    .. math:: a = \sqrt{\frac{4 \max(F, 0) |R|}{\pi l E^*}}, \quad
              |R| = \min\left(\left|\frac{1}{1/\rho + 1/R_r}\right|, 10^3 R_r\right)

    Johnson 1985 eq. 4.45 with the magnitude of the effective radius, capped where the cam is
    nearly conformal with the roller (there the FE decides the real width).

    Parameters
    ----------
    F : float or ndarray
        Contact force (N over ``length``).
    length : float
        Face width (m).
    rho : float or ndarray
        Cam radius of curvature (m).
    Rr : float
        Roller radius (m).
    E_star : float
        Effective modulus (Pa).

    Returns
    -------
    ndarray
        ``a`` (m), shape of ``F`` and ``rho`` broadcast.

    Examples
    --------
    >>> round(float(sizing_half_width(1e3, 0.01, np.inf, 0.01, 1e11)) * 1e6, 3)   # um
    112.838
    """
    R = np.minimum(np.abs(_effective_radius(rho, Rr)), SIZING_R_CAP * Rr)   # conformal: capped
    return half_width(np.maximum(F, 0.0) / length, R, E_star)


@lru_cache(maxsize=256)  # the sweep's traction-ratio grid: up to 101 ratios per (mu, nu, plane)
def shape_factors(mu: float, nu: float, plane: str) -> dict:
    r"""Maxima of the Hertz fields in units of p0 and a, for friction ``mu``.

    Hertz line-contact stresses are self-similar: :math:`\sigma/p_0` depends only on
    :math:`(x/a, z/a, \mu, \nu)` (Johnson 1985 §7.1, McEwen 1949), so the maxima of von Mises
    and tau1 and the range of txz over one pass (:mod:`femcam.hertz.maxima`) are found once and
    scaled by each angle's p0 and a. Surface extremes: seed 002 eqs. 5-7 on a fine grid of ``x/a``.

    Parameters
    ----------
    mu : float
        Friction coefficient (dimensionless, >= 0).
    nu : float
        Poisson's ratio of the cam (dimensionless).
    plane : str
        ``"strain"`` or ``"stress"``.

    Returns
    -------
    dict
        ``von_mises``, ``tau1`` and ``txz_range`` (:func:`~femcam.hertz.maxima.max_shear_range`):
        ``(value / p0, depth / a)``; ``surf_sx_min``, ``surf_sx_max``, ``surf_sz_min``,
        ``surf_txz_absmax``: surface (z = 0) extremes / p0.
    """
    vm = max_von_mises(mu, nu, plane)
    t1 = max_shear(mu)
    tr = max_shear_range(mu)
    xs = np.linspace(-3.0, 3.0, 60001)
    sx, sz, txz = surface_stress(xs, 1.0, 1.0, mu)
    return {"von_mises": (vm.value, vm.z), "tau1": (t1.value, t1.z), "txz_range": (tr.value, tr.z),
            "surf_sx_min": float(np.min(sx)), "surf_sx_max": float(np.max(sx)),
            "surf_sz_min": float(np.min(sz)), "surf_txz_absmax": float(np.max(np.abs(txz)))}
