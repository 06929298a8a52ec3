r"""Hertz pressure and the surface stresses (z = 0) of a sliding line contact.

Symbols: ``x`` (m) along the surface, ``a`` half-width (m), ``p0`` peak pressure (Pa), ``mu``
friction coefficient (signed here: ``mu > 0`` means the traction ``q = mu p`` on the body acts in
+x), ``sx, sz, txz`` (Pa), tension positive, ``z`` into the body (see :mod:`femcam.hertz.contact`).

Seed 002 eqs. 5-7 (after Norton, *Machine Design*, §7.10, and Johnson 1985 §7.2) superpose the
normal part (eq. 5) and the tangential part (eqs. 6a-c, 7) of the surface field:

========================  =====================================  ================================
region                    normal load (eq. 5)                    tangential ``q = mu p`` (6, 7)
========================  =====================================  ================================
``|x| <= a``              ``sx = sz = -p0 sqrt(1 - x^2/a^2)``     ``sx = -2 mu p0 x/a``,
                          ``txz = 0``                             ``txz = -mu p0 sqrt(1-x^2/a^2)``
``x > a``                 0                                      ``sx = -2 mu p0 (x/a - sqrt(x^2/a^2 - 1))``
``x < -a``                0                                      ``sx = -2 mu p0 (x/a + sqrt(x^2/a^2 - 1))``
========================  =====================================  ================================

Both outside branches are ``-2 mu p0 (x/a - sign(x) sqrt(x^2/a^2 - 1))``; the tangential
``sx`` follows from the Hilbert transform of the traction, :math:`\sigma_x = -\frac{2}{\pi}
\int_{-a}^{a} \frac{q(s)}{x - s}\,ds` (Johnson eq. 2.25b).  ``sx`` is continuous at ``|x| = a``
(``-/+ 2 mu p0``), the tensile peak is ``+2 mu p0`` at ``x = -a`` and it decays like
``mu p0 a / x`` far away.
"""

from __future__ import annotations

import numpy as np

from .. import _validate


def hertz_pressure(x, a, p0):
    r"""Hertz (elliptical) pressure distribution (Pa), zero outside ``|x| < a``.

    .. math:: p(x) = p_0 \sqrt{1 - x^2/a^2}

    (Johnson 1985 eq. 4.46).  ``a = 0`` (zero load) gives exactly 0.

    Parameters
    ----------
    x : float or array_like
        Position along the surface [m]; broadcasts against ``a`` and ``p0``.
    a : float or array_like
        Contact half-width [m], ``>= 0``.
    p0 : float or array_like
        Peak pressure [Pa].

    Returns
    -------
    ndarray
        Pressure ``p(x) >= 0`` [Pa], float, the broadcast shape of ``x, a, p0``.

    Raises
    ------
    InputError
        An input is not a number or not finite, or ``a < 0``, ``p0 < 0``.

    Examples
    --------
    >>> float(hertz_pressure(0.5, 1.0, 2.0)) == 2.0 * 0.75 ** 0.5
    True
    """
    x = _validate.finite_array("x", x, "m")
    a = _validate.nonnegative_array("a", a, "m")
    p0 = _validate.nonnegative_array("p0", p0, "Pa")
    X = x / np.where(a > 0.0, a, 1.0)
    return np.where(a > 0.0, p0 * np.sqrt(np.clip(1.0 - X * X, 0.0, None)), 0.0 * X)


def surface_stress(x, a, p0, mu=0.0):
    r"""Surface stresses ``(sx, sz, txz)`` (Pa) at ``z = 0`` for normal load + sliding friction.

    .. math::
        \sigma_x = -p - 2\mu p_0 \left(\tfrac{x}{a} - \operatorname{sgn}(x)
        \sqrt{\max(x^2/a^2 - 1, 0)}\right), \quad \sigma_z = -p, \quad \tau_{xz} = -\mu p

    with ``p = p0 sqrt(1 - x^2/a^2)`` inside the contact and 0 outside (seed 002 eqs. 5-7;
    Johnson 1985 eqs. 7.20-7.21 at ``z = 0``).  Valid for all ``x``; no warnings at ``|x| = a``.

    Parameters
    ----------
    x : float or array_like
        Position along the surface [m]; broadcasts against ``a``, ``p0`` and ``mu``.
    a : float or array_like
        Contact half-width [m], ``>= 0``.
    p0 : float or array_like
        Peak pressure [Pa].
    mu : float or array_like, optional
        Signed friction coefficient [-]: ``mu > 0`` puts the traction ``q = mu p`` on the body
        in +x. Default 0.

    Returns
    -------
    sx, sz, txz : ndarray
        Surface stresses [Pa] (tension positive), float, each of the broadcast shape.

    Raises
    ------
    InputError
        An input is not a number or not finite, or ``a < 0``, ``p0 < 0``.

    Examples
    --------
    >>> sx, sz, txz = surface_stress([-1.0, 0.0, 2.0], 1.0, 1.0, mu=0.1)
    >>> [round(float(s), 6) for s in sx]
    [0.2, -1.0, -0.05359]
    """
    x = _validate.finite_array("x", x, "m")
    a = _validate.nonnegative_array("a", a, "m")
    p0 = _validate.nonnegative_array("p0", p0, "Pa")
    mu = _validate.finite_array("mu", mu, "")
    X = x / np.where(a > 0.0, a, 1.0)            # a = 0 <=> p0 = 0: every term below is 0 * finite
    u = 1.0 - X * X
    root = np.sqrt(np.abs(u))
    inside = np.where(u > 0.0, root, 0.0)        # p / p0
    outside = np.where(u < 0.0, root, 0.0)       # sqrt(x^2/a^2 - 1), 0 inside the contact
    p = p0 * inside
    q = mu * p
    sx = -p - 2.0 * mu * p0 * (X - np.copysign(outside, X))
    sz = -p
    txz = -q
    return sx, sz, txz
