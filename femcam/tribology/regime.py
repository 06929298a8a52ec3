r"""Archard wear coefficient as a function of the film parameter lambda (mixed lubrication).

Symbols
-------
=========  ==========================================================  =====  ======================
symbol     meaning                                                     unit   source
=========  ==========================================================  =====  ======================
lam        film parameter ``h / sigma``                                -      Tallian 1967
F_n        Greenwood-Tripp integral of a Gaussian height distribution  -      Greenwood & Tripp 1970
k0         boundary (dry, ``lam = 0``) dimensional wear coefficient    m^3/   Archard 1953
                                                                       (N m)
k          wear coefficient at ``lam``                                 m^3/
                                                                       (N m)
=========  ==========================================================  =====  ======================

Law.  In mixed lubrication the asperities carry the part of the load that wears (Archard's law
applied to the asperity load); with Gaussian heights the asperity contact pressure at film
separation ``h = lam sigma`` is proportional to the Greenwood-Tripp integral ``F_{5/2}(lam)``
(Greenwood & Tripp 1970). femcam therefore scales the boundary coefficient by the asperity load
share relative to touching surfaces:

.. math:: k(\lambda) = k_0\,\frac{F_{5/2}(\lambda)}{F_{5/2}(0)},\qquad
          F_n(\lambda) = \frac{1}{\sqrt{2\pi}}\int_\lambda^\infty (s-\lambda)^n e^{-s^2/2}\,ds

It gives ``k = k0`` at ``lam = 0``, 0.13 ``k0`` at ``lam = 1`` (boundary/mixed limit) and 2.8e-4 ``k0``
at ``lam = 3`` (full film): wear all but stops in full-film lubrication. This is femcam's
modelling choice built from the references above (the load-sharing idea of Johnson, Greenwood &
Poon 1972), not a fitted wear law: use the scene's ``k`` as the boundary value.

Closed form used: ``F_n(lam) = Gamma(n+1) exp(-lam^2/4) D_{-n-1}(lam) / sqrt(2 pi)`` with the
parabolic cylinder function ``D`` (Abramowitz & Stegun 1964 eq. 19.5.3 / 19.3.1).
"""

from __future__ import annotations

import math

import numpy as np

from .. import _validate


def greenwood_tripp(n, lam):
    r"""Greenwood-Tripp integral ``F_n(lam)`` (dimensionless), vectorised over ``lam >= 0``.

    .. math:: F_n(\lambda) = \frac{\Gamma(n+1)\,e^{-\lambda^2/4}\,D_{-n-1}(\lambda)}{\sqrt{2\pi}}

    Parameters
    ----------
    n : float
        Order of the integral, ``>= 0`` [-] (5/2 for the asperity pressure).
    lam : float or array_like
        Film parameter ``h / sigma`` [-].

    Returns
    -------
    ndarray, shape of ``lam``
        ``F_n(lam)`` [-].

    Examples
    --------
    >>> round(float(greenwood_tripp(2.5, 0.0)), 6)     # 2^(3/4) Gamma(7/4) / sqrt(2 pi)
    0.616634
    """
    lam = _validate.nonnegative_array("lam", lam, "")   # a film ratio h / sigma is >= 0
    n = _validate.nonnegative("n", n, "")
    from scipy.special import gamma, pbdv  # lazy: scipy.special, ~0.04 s to import

    D, _ = pbdv(-n - 1.0, lam)
    return gamma(n + 1.0) * np.exp(-lam * lam / 4.0) * D / math.sqrt(2.0 * math.pi)


def wear_coefficient(k0, lam):
    r"""Wear coefficient ``k(lam) = k0 F_{5/2}(lam)/F_{5/2}(0)`` (units of ``k0``); ``lam >= 0``
    (a film ratio; a negative one is refused).

    .. math:: k(\lambda) = k_0\,F_{5/2}(\lambda)/F_{5/2}(0)

    Parameters
    ----------
    k0 : float
        Boundary (``lam = 0``) dimensional wear coefficient, ``>= 0`` [m^3/(N m)].
    lam : float or array_like
        Film parameter ``h / sigma`` [-]; negative values are taken as 0.

    Returns
    -------
    ndarray, shape of ``lam``
        Wear coefficient at ``lam`` [m^3/(N m)] (the unit of ``k0``).

    Examples
    --------
    >>> [round(float(x), 4) for x in wear_coefficient(1.0, [0.0, 1.0])]
    [1.0, 0.1306]
    """
    k0 = _validate.nonnegative("k0", k0, "m^3/(N m)")
    lam = _validate.nonnegative_array("lam", lam, "")   # a film ratio h / sigma is >= 0
    return k0 * greenwood_tripp(2.5, lam) / greenwood_tripp(2.5, 0.0)
