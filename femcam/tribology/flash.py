r"""Flash temperature of a sliding line contact (Blok 1937, Jaeger 1942) and a scuffing check.

Symbols
-------
=========  ==========================================================  ===========  ==================
symbol     meaning                                                     unit         source
=========  ==========================================================  ===========  ==================
mu         friction coefficient                                        -
w          load per unit length                                        N/m          Johnson 1985 4.45
a          Hertz contact half-width                                    m            Johnson 1985 4.45
u1, u2     speeds of the two surfaces relative to the contact          m/s
K          thermal conductivity                                        W/(m K)
rho, c     density, specific heat                                      kg/m^3,
                                                                       J/(kg K)
kappa      thermal diffusivity ``K/(rho c)``                           m^2/s
beta       thermal effusivity (contact coefficient) ``sqrt(K rho c)``  W s^0.5/     AGMA 925 (B_M)
                                                                       (m^2 K)
Pe         Peclet number ``|u| a / (2 kappa)``                         -            Johnson 1985 §13.3
dT_f       flash temperature rise (maximum over the band)              K            Blok 1937
T_c        contact temperature ``T_bulk + dT_f``                       degC         AGMA 925
=========  ==========================================================  ===========  ==================

Blok's flash temperature.  At high Peclet number each surface point passes under the band in a
time ``2a/u`` too short for heat to flow sideways, so it sees 1-D transient conduction into a
half-space (Jaeger 1942): :math:`T(t) = \frac{1}{\beta\sqrt\pi}\int_0^t q(\tau)(t-\tau)^{-1/2}d\tau`.
For the semi-elliptical (Hertzian) frictional heat flux ``q = mu p |u1 - u2|`` shared between the two
bodies so that their maximum surface temperatures are equal (Blok's postulate):

.. math:: \Delta T_f = C_B\,\frac{\mu\,w\,|u_1 - u_2|}{\sqrt{a}\,(\beta_1\sqrt{|u_1|} + \beta_2\sqrt{|u_2|})},
          \qquad C_B = \frac{2 I_{max}}{\pi^{3/2}} = 0.786

``I_max = max_s int_0^s sqrt(1-(sigma-1)^2) (s - sigma)^{-1/2} d sigma = 2.1883`` (the maximum is at
``x = 0.652 a`` behind the centre). AGMA 925-A03 uses the same form with the rounded constant
``K = 0.80`` (its eq. for the flash temperature, with ``B_M = beta``); the tests check both the
constant (by an independent numerical Duhamel integral) and the AGMA form.

Validity: the high-Peclet form needs ``Pe >= 5`` on a body that carries heat away (Tian & Kennedy
1994 put the fast-source limit there); below it the band heats the body more slowly than assumed
and the formula underestimates; computed and flagged ``low_peclet``. Zero sliding gives exactly 0.
"""

from __future__ import annotations

import numpy as np

from .. import _validate

#: Blok's constant for a semi-elliptical heat source and equal flash temperatures (see above)
C_BLOK = 0.78598
#: AGMA 925-A03's rounded constant for the same case
K_AGMA925 = 0.80
#: Peclet number below which the high-speed form is flagged (Tian & Kennedy 1994)
PECLET_MIN = 5.0


def effusivity(K, rho, c):
    r"""Thermal effusivity ``beta = sqrt(K rho c)`` (W s^0.5 / (m^2 K)).

    .. math:: \beta = \sqrt{K\rho c}

    Parameters
    ----------
    K : float
        Thermal conductivity [W/(m K)].
    rho : float
        Density [kg/m^3].
    c : float
        Specific heat [J/(kg K)].

    Returns
    -------
    float
        Thermal effusivity ``beta`` [W s^0.5/(m^2 K)].

    Examples
    --------
    >>> round(float(effusivity(46.0, 7850.0, 470.0)))
    13028
    """
    return np.sqrt(_validate.positive("K", K, "W/(m K)") * _validate.positive("rho", rho, "kg/m^3")
                   * _validate.positive("c", c, "J/(kg K)"))


def peclet(u, a, kappa):
    r"""Peclet number ``Pe = |u| a / (2 kappa)`` of a band of half-width ``a`` moving at ``u``.

    .. math:: Pe = \frac{|u|\,a}{2\kappa}

    Parameters
    ----------
    u : float or ndarray
        Speed of the surface relative to the contact [m/s].
    a : float or ndarray
        Hertz contact half-width [m].
    kappa : float
        Thermal diffusivity ``K/(rho c)`` [m^2/s].

    Returns
    -------
    ndarray, broadcast shape of ``u`` and ``a``
        Peclet number [-].

    Examples
    --------
    >>> round(float(peclet(2.0, 1e-4, 1.25e-5)), 6)
    8.0
    """
    u = _validate.finite_array("u", u, "m/s")
    a = _validate.nonnegative_array("a", a, "m")
    kappa = _validate.positive("kappa", kappa, "m^2/s")
    return np.abs(u) * a / (2.0 * kappa)


def flash_temperature(mu, w, a, u1, u2, beta1, beta2, *, C=C_BLOK):
    r"""Blok's maximum flash temperature rise ``dT_f`` (K) of a line contact, vectorised.

    .. math:: \Delta T_f = C\,\frac{\mu w |u_1-u_2|}{\sqrt a\,(\beta_1\sqrt{|u_1|}+\beta_2\sqrt{|u_2|})}

    ``u1 = u2`` (pure rolling), ``w = 0`` or ``mu = 0`` give 0. Where both speeds vanish but the
    surfaces slide (impossible: ``u1 - u2`` is then 0 too) the result would be 0/0 and is 0.

    Parameters
    ----------
    mu : float
        Friction coefficient, ``>= 0`` [-].
    w : float or ndarray
        Load per unit length [N/m], ``>= 0``.
    a : float or ndarray
        Hertz contact half-width [m], ``>= 0``.
    u1, u2 : float or ndarray
        Speeds of the two surfaces relative to the contact [m/s].
    beta1, beta2 : float
        Thermal effusivities of the two bodies [W s^0.5/(m^2 K)].
    C : float
        Flash constant [-]: :data:`C_BLOK` (default) or :data:`K_AGMA925`.

    Returns
    -------
    ndarray, broadcast shape of the inputs
        Maximum flash temperature rise ``dT_f`` [K].

    Examples
    --------
    >>> round(float(flash_temperature(0.1, 1e5, 1e-4, 3.0, 1.0, 13020.0, 13020.0)), 2)   # K
    44.19
    """
    mu = _validate.nonnegative("mu", mu, "")
    w = _validate.nonnegative_array("w", w, "N/m")
    a = _validate.nonnegative_array("a", a, "m")
    u1 = _validate.finite_array("u1", u1, "m/s")
    u2 = _validate.finite_array("u2", u2, "m/s")
    beta1 = _validate.positive("beta1", beta1, "W s^0.5/(m^2 K)")
    beta2 = _validate.positive("beta2", beta2, "W s^0.5/(m^2 K)")
    C = _validate.positive("C", C, "")
    den = np.sqrt(np.where(a > 0, a, 1.0)) * (beta1 * np.sqrt(np.abs(u1)) + beta2 * np.sqrt(np.abs(u2)))
    num = C * mu * w * np.abs(u1 - u2)
    ok = (den > 0) & (a > 0)
    return np.where(ok, num / np.where(ok, den, 1.0), 0.0)


def scuffing_safety(T_scuff, T_bulk, dT_flash):
    r"""AGMA 925-style scuffing safety factor ``(T_s - T_bulk) / dT_f`` (inf where ``dT_f = 0``).

    .. math:: S_{sc} = \frac{T_s - T_{bulk}}{\Delta T_f}

    Below 1 the contact temperature ``T_bulk + dT_f`` exceeds the scuffing temperature.

    Parameters
    ----------
    T_scuff : float
        Scuffing temperature [degC].
    T_bulk : float or ndarray
        Bulk temperature [degC].
    dT_flash : float or ndarray
        Flash temperature rise [K].

    Returns
    -------
    ndarray, broadcast shape of ``T_bulk`` and ``dT_flash``
        Scuffing safety factor [-]; ``inf`` where ``dT_flash = 0``.

    Examples
    --------
    >>> float(scuffing_safety(150.0, 90.0, 30.0))
    2.0
    """
    dT = _validate.nonnegative_array("dT_flash", dT_flash, "K")
    # the scene key's range ([materials.*] scuffing_temperature_C, femcam.scene.ranges): a
    # negative scuffing temperature would give a negative "safety factor"
    T_s = _validate.in_range("T_scuff", T_scuff, 0.0, 1000.0, "degC")
    margin = T_s - _validate.finite_array("T_bulk", T_bulk, "degC")
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(dT > 0, margin / np.where(dT > 0, dT, 1.0), np.inf)
