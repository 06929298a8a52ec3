r"""Elastohydrodynamic (EHL) film thickness of a line contact, and the film parameter lambda.

Symbols (Hamrock, Schmid & Jacobson 2004 ch. 8; Pan & Hamrock 1989; Dowson & Higginson 1977)
------------------------------------------------------------------------------------------------
=========  =========================================================  ======  =========================
symbol     meaning                                                    unit    source
=========  =========================================================  ======  =========================
u1, u2     surface speeds of cam and follower relative to the contact  m/s
U          mean entrainment (rolling) speed ``(u1 + u2)/2``           m/s     Hamrock 2004 ch. 8
w          load per unit length                                       N/m     Johnson 1985 eq. 4.45
R          effective radius ``1/R = 1/R1 + 1/R2``                     m       Johnson 1985 eq. 4.44
E_red      Hamrock's reduced modulus ``E' = 2 E*``                    Pa      Hamrock 2004 ch. 8
eta0       dynamic viscosity at the inlet (ambient pressure)          Pa s
alpha      pressure-viscosity coefficient (Barus)                     1/Pa    Barus 1893
Ud, G, W   speed ``eta0 U/(E' R)``, material ``alpha E'``, load       -       Pan & Hamrock 1989
           ``w/(E' R)`` parameters
h_min      minimum film thickness (outlet constriction)               m       Pan & Hamrock 1989
h_c        central film thickness                                     m       Pan & Hamrock 1989
sigma      composite RMS roughness ``sqrt(Rq1^2 + Rq2^2)``            m       Hamrock 2004 ch. 8
lam        film parameter ``h_min / sigma``                           -       Tallian 1967
=========  =========================================================  ======  =========================

Formula used: **Pan & Hamrock (1989)**, the curve fit of full numerical isothermal EHL line-contact
solutions that gives both the minimum and the central film,

.. math:: \frac{h_{min}}{R} = 1.714\,W^{-0.128}\,U_d^{0.694}\,G^{0.568},\qquad
          \frac{h_c}{R} = 2.922\,W^{-0.166}\,U_d^{0.692}\,G^{0.470}

Why Pan-Hamrock: it is the line-contact formula of Hamrock, Schmid & Jacobson's textbook, it was
fitted to numerical solutions over the range of ``W, Ud, G`` of machine elements, and it gives
``h_c`` as well. Dowson & Higginson (1977), :math:`h_{min}/R = 2.65\,U_d^{0.70}G^{0.54}W^{-0.13}`,
is provided as :func:`dowson_higginson_min` for comparison (they agree within 10 % for
``U`` = 0.1-10 m/s and ``w`` = 20-500 kN/m on a 5 mm steel contact; the test checks it).

Range of validity (flagged, never refused): the fits were made over the load and speed
parameters of machine elements (``W`` of order 1e-5..1e-4, ``Ud`` of order 1e-12..1e-10);
femcam flags ``W`` outside 1e-6..1e-3 and ``Ud`` outside 1e-13..1e-9 (about a decade beyond).
The fits assume rolling in one direction: ``U <= 0`` (entrainment reversing, e.g. near the nose
of a flat-faced follower) gives **no** EHL film (``h = 0``, flagged "no_entrainment"); squeeze
films are not modelled. The formulas are isothermal and fully flooded (no inlet shear heating, no
starvation): both would thin the film, so lambda here is an upper estimate.
"""

from __future__ import annotations

import numpy as np

from .. import _validate

#: Pan & Hamrock 1989 coefficients and exponents: (C, exponent of W, of Ud, of G)
PAN_HAMROCK_MIN = (1.714, -0.128, 0.694, 0.568)
PAN_HAMROCK_CENTRAL = (2.922, -0.166, 0.692, 0.470)
#: Dowson & Higginson 1977 minimum film: (C, exponent of W, of Ud, of G)
DOWSON_HIGGINSON_MIN = (2.65, -0.13, 0.70, 0.54)
#: ranges outside of which a result is flagged (W, Ud), see the module docstring
W_RANGE = (1e-6, 1e-3)
U_RANGE = (1e-13, 1e-9)
#: regime limits of lambda: boundary below 1, mixed 1..3, full film above 3 (Hamrock 2004 ch. 8)
LAMBDA_MIXED, LAMBDA_FULL = 1.0, 3.0
#: Rq / Ra of a Gaussian height distribution, sqrt(pi/2) (Thomas 1999)
RQ_PER_RA = float(np.sqrt(np.pi / 2.0))


def dimensionless_groups(U, w, R, E_star, eta0, alpha):
    r"""``(Ud, G, W)``: speed, material and load parameters of a line contact (Hamrock's
    ``E' = 2 E*``).

    .. math:: U_d = \frac{\eta_0 U}{E' R},\quad G = \alpha E',\quad W = \frac{w}{E' R}

    Parameters
    ----------
    U : float or ndarray
        Mean entrainment speed [m/s].
    w : float or ndarray
        Load per unit length [N/m].
    R : float or ndarray
        Effective radius [m].
    E_star : float or ndarray
        Contact modulus ``E*`` (Hamrock's ``E' = 2 E*``) [Pa].
    eta0 : float or ndarray
        Inlet dynamic viscosity [Pa s].
    alpha : float or ndarray
        Barus pressure-viscosity coefficient [1/Pa].

    Returns
    -------
    tuple of 3 ndarray, broadcast shape of the inputs
        ``(Ud, G, W)``: speed, material and load parameters [-].

    Examples
    --------
    >>> [float(f"{x:.4g}") for x in dimensionless_groups(1.0, 1e5, 0.01, 115.4e9, 0.01, 2e-8)]
    [4.333e-12, 4616.0, 4.333e-05]
    """
    return _groups(_validate.finite_array("U", U, "m/s"), _validate.nonnegative_array("w", w, "N/m"),
                   _validate.positive_array("R", R, "m"), _validate.positive_array("E_star", E_star, "Pa"),
                   _validate.positive_array("eta0", eta0, "Pa s"),
                   _validate.positive_array("alpha", alpha, "1/Pa"))


def _groups(U, w, R, E_star, eta0, alpha):
    """:func:`dimensionless_groups` without the input checks."""
    E_red = 2.0 * np.asarray(E_star, float)
    ER = E_red * np.asarray(R, float)
    return (np.asarray(eta0, float) * np.asarray(U, float) / ER, np.asarray(alpha, float) * E_red,
            np.asarray(w, float) / ER)


def _fit(coef, Ud, G, W):
    C, eW, eU, eG = coef
    Ud = np.asarray(Ud, float)
    pos = Ud > 0.0
    Us = np.where(pos, Ud, 1.0)
    Ws = np.where(np.asarray(W, float) > 0.0, W, 1.0)
    return np.where(pos & (np.asarray(W, float) > 0.0), C * Ws**eW * Us**eU * np.asarray(G, float)**eG, 0.0)


def pan_hamrock_min(Ud, G, W):
    r"""Dimensionless minimum film ``h_min / R`` (Pan & Hamrock 1989); 0 where ``Ud <= 0``.

    .. math:: H_{min} = 1.714\,W^{-0.128}U_d^{0.694}G^{0.568}

    Parameters
    ----------
    Ud : float or ndarray
        Speed parameter ``eta0 U / (E' R)`` [-].
    G : float or ndarray
        Material parameter ``alpha E'`` [-].
    W : float or ndarray
        Load parameter ``w / (E' R)`` [-].

    Returns
    -------
    ndarray, broadcast shape of the inputs
        Minimum film ``h_min / R`` [-].

    Examples
    --------
    >>> f"{float(pan_hamrock_min(1e-11, 5000.0, 1e-4)):.4g}"
    '1.633e-05'
    """
    return _fit(PAN_HAMROCK_MIN, Ud, G, W)


def pan_hamrock_central(Ud, G, W):
    r"""Dimensionless central film ``h_c / R`` (Pan & Hamrock 1989); 0 where ``Ud <= 0``.

    .. math:: H_c = 2.922\,W^{-0.166}U_d^{0.692}G^{0.470}

    Parameters
    ----------
    Ud : float or ndarray
        Speed parameter ``eta0 U / (E' R)`` [-].
    G : float or ndarray
        Material parameter ``alpha E'`` [-].
    W : float or ndarray
        Load parameter ``w / (E' R)`` [-].

    Returns
    -------
    ndarray, broadcast shape of the inputs
        Central film ``h_c / R`` [-].

    Examples
    --------
    >>> f"{float(pan_hamrock_central(1e-11, 5000.0, 1e-4)):.4g}"
    '1.804e-05'
    """
    return _fit(PAN_HAMROCK_CENTRAL, Ud, G, W)


def dowson_higginson_min(Ud, G, W):
    r"""Dimensionless minimum film ``h_min / R`` (Dowson & Higginson 1977); 0 where ``Ud <= 0``.

    .. math:: H_{min} = 2.65\,U_d^{0.70}G^{0.54}W^{-0.13}

    Parameters
    ----------
    Ud : float or ndarray
        Speed parameter ``eta0 U / (E' R)`` [-].
    G : float or ndarray
        Material parameter ``alpha E'`` [-].
    W : float or ndarray
        Load parameter ``w / (E' R)`` [-].

    Returns
    -------
    ndarray, broadcast shape of the inputs
        Minimum film ``h_min / R`` [-].

    Examples
    --------
    >>> f"{float(dowson_higginson_min(1e-11, 5000.0, 1e-4)):.4g}"
    '1.741e-05'
    """
    return _fit(DOWSON_HIGGINSON_MIN, Ud, G, W)


def composite_roughness(Rq1, Rq2):
    r"""Composite RMS roughness ``sigma`` (m) of two surfaces.

    .. math:: \sigma = \sqrt{R_{q1}^2 + R_{q2}^2}

    Parameters
    ----------
    Rq1, Rq2 : float
        RMS roughness of the two surfaces, ``>= 0`` [m].

    Returns
    -------
    float
        Composite RMS roughness ``sigma`` [m].

    Examples
    --------
    >>> round(float(composite_roughness(0.3e-6, 0.4e-6)) * 1e6, 12)
    0.5
    """
    return np.hypot(_validate.nonnegative("Rq1", Rq1, "m"), _validate.nonnegative("Rq2", Rq2, "m"))


def lubrication_regime(lam):
    """Lubrication regime per lambda: 0 boundary (``lam < 1``), 1 mixed (``1 <= lam < 3``),
    2 full film (``lam >= 3``) (Hamrock, Schmid & Jacobson 2004 ch. 8).

    Parameters
    ----------
    lam : float or array_like
        Film parameter ``h_min / sigma`` [-].

    Returns
    -------
    ndarray of int, shape of ``lam``
        Regime code 0, 1 or 2 (names in :data:`REGIME_NAMES`).

    Examples
    --------
    >>> lubrication_regime([0.5, 1.0, 2.9, 3.0]).tolist()
    [0, 1, 1, 2]
    """
    return _regime(_validate.nonnegative_array("lam", lam, ""))


def _regime(lam):
    """:func:`lubrication_regime` without the input checks."""
    lam = np.asarray(lam, float)
    return np.where(lam < LAMBDA_MIXED, 0, np.where(lam < LAMBDA_FULL, 1, 2))


REGIME_NAMES = ("boundary", "mixed", "full")


def film_thickness(*, U, w, R, E_star, eta0, alpha, sigma=None) -> dict:
    """Pan-Hamrock minimum and central film and lambda at every case (arrays broadcast).

    Parameters
    ----------
    U : mean entrainment speed (m/s); ``<= 0`` gives no film (flagged ``no_entrainment``).
    w : load per length (N/m). R : effective radius (m; ``inf`` gives a flagged 0 film).
    E_star : contact modulus (Pa). eta0 : inlet viscosity (Pa s). alpha : pressure-viscosity (1/Pa).
    sigma : composite RMS roughness (m), optional: gives ``lam`` and ``regime``.

    Returns
    -------
    dict with ``h_min, h_c`` (m), ``Ud, G, W``, ``lam`` and ``regime`` (if sigma), and ``flags``: a
    list of ``(name, bool array)``: ``no_entrainment``, ``W_range``, ``U_range``.

    >>> r = film_thickness(U=1.0, w=1e5, R=0.01, E_star=115.4e9, eta0=0.01, alpha=2e-8, sigma=0.25e-6)
    >>> round(float(r["h_min"]) * 1e6, 3), round(float(r["lam"]), 2)
    (0.097, 0.39)
    """
    _validate.positive("E_star", E_star, "Pa")
    eta0 = _validate.finite_array("eta0", eta0, "Pa s")
    alpha = _validate.finite_array("alpha", alpha, "1/Pa")
    if np.any(eta0 <= 0) or np.any(alpha <= 0):
        bad = ("eta0", eta0, "Pa s") if np.any(eta0 <= 0) else ("alpha", alpha, "1/Pa")
        raise _validate.fail(bad[0], float(np.min(bad[1])), bad[2], "must be > 0")
    U = _validate.finite_array("U", U, "m/s")
    w = _validate.nonnegative_array("w", w, "N/m")
    R = _validate.radius_array("R", R, "m")             # inf (flat on flat) gives a flagged 0 film
    if np.any(R < 0.0):
        raise _validate.fail("R", float(R[R < 0.0].flat[0]), "m", "must be > 0 (inf: flat)")
    finite_R = np.isfinite(R) & (R > 0)
    Ud, G, W = _groups(U, w, np.where(finite_R, R, 1.0), E_star, eta0, alpha)
    Rs = np.where(finite_R, R, 0.0)
    out = {"Ud": Ud, "G": G, "W": W,
           "h_min": Rs * pan_hamrock_min(Ud, G, W), "h_c": Rs * pan_hamrock_central(Ud, G, W)}
    pos = Ud > 0
    out["flags"] = [("no_entrainment", ~pos | ~finite_R),
                    ("W_range", pos & ((W < W_RANGE[0]) | (W > W_RANGE[1]))),
                    ("U_range", pos & ((Ud < U_RANGE[0]) | (Ud > U_RANGE[1])))]
    if sigma is not None:
        sigma = _validate.positive("sigma", sigma, "m")
        out["lam"] = out["h_min"] / sigma
        out["regime"] = _regime(out["lam"])
    return out
