"""Archard's wear law and the conversion between its two coefficients.

Symbols
-------
======  ===============================================  ===========  =====================
symbol  meaning                                          unit         source
======  ===============================================  ===========  =====================
K       dimensionless wear coefficient                   -            Archard (1953); seed 000
H       hardness of the softer (worn) surface            Pa           seed 000 (N/mm^2 there)
k       dimensional wear coefficient, k = K / H          m^3/(N m)    Archard (1953)
W       worn volume                                      m^3          seed 000 ``W = K L S / H``
L       normal load (seed 000's symbol; F elsewhere)     N            seed 000
S       sliding distance                                 m            seed 000
======  ===============================================  ===========  =====================

Archard's law, :math:`W = K L S / H = k L S`, says the worn volume is proportional to the load
and the sliding distance and inversely proportional to the hardness. Locally (per unit area) it
reads :math:`dh = k\\,p\\,ds_{slip}`: the depth increment equals k times the contact pressure
times the distance slid; :mod:`femcam.wear.map` integrates that form.

The two coefficients carry the same information only together with H: ``k = K / H`` and
``K = k H``. A K of 1e-8 with H = 2000 N/mm^2 = 2e9 Pa is k = 5e-18 m^3/(N m)
= 5e-9 mm^3/(N m) (seed 000's inputs).
"""

from __future__ import annotations

import numpy as np

from .. import _validate


def _nonneg_array(name, value, unit):
    arr = _validate.finite_array(name, value, unit)
    if np.any(arr < 0):
        bad = arr[arr < 0].flat[0]
        raise _validate.fail(name, float(bad), unit, "must be >= 0")
    return arr


def dimensional_coefficient(K, H):
    r"""Dimensional wear coefficient k (m^3/(N m)) from K (-) and hardness H (Pa).

    .. math:: k = K / H

    References: Archard, J. Appl. Phys. 24 (1953) 981; seed 000, Archard model section.

    Parameters
    ----------
    K : float
        Dimensionless wear coefficient, ``>= 0`` [-].
    H : float
        Hardness of the worn surface, ``> 0`` [Pa].

    Returns
    -------
    float
        Dimensional wear coefficient ``k`` [m^3/(N m)].

    Examples
    --------
    >>> dimensional_coefficient(1e-8, 2000e6)    # seed 000: K = 1e-8, H = 2000 N/mm^2
    5e-18
    """
    K = _validate.nonnegative("K", K, "(dimensionless wear coefficient)")
    H = _validate.positive("H", H, "Pa")
    return K / H


def dimensionless_coefficient(k, H):
    r"""Dimensionless wear coefficient K (-) from k (m^3/(N m)) and hardness H (Pa).

    .. math:: K = k H

    Parameters
    ----------
    k : float
        Dimensional wear coefficient, ``>= 0`` [m^3/(N m)].
    H : float
        Hardness of the worn surface, ``> 0`` [Pa].

    Returns
    -------
    float
        Dimensionless wear coefficient ``K`` [-].

    Examples
    --------
    >>> dimensionless_coefficient(5e-18, 2e9)
    1e-08
    """
    k = _validate.nonnegative("k", k, "m^3/(N m)")
    H = _validate.positive("H", H, "Pa")
    return k * H


def archard_volume(k, L, S):
    r"""Worn volume W = k L S (m^3), with k in m^3/(N m), load L in N, sliding distance S in m.

    .. math:: W = k L S = \frac{K L S}{H}

    ``L`` and ``S`` may be arrays (broadcast). Negative k, L or S raise
    :class:`~femcam.errors.InputError`; zero load or zero sliding gives zero wear.

    References: Archard (1953); seed 000, ``W = K L S / H``.

    Parameters
    ----------
    k : float
        Dimensional wear coefficient, ``>= 0`` [m^3/(N m)].
    L : float or array_like
        Normal load, ``>= 0`` [N].
    S : float or array_like
        Sliding distance, ``>= 0`` [m].

    Returns
    -------
    float or ndarray, broadcast shape of ``L`` and ``S``
        Worn volume [m^3] (a float for scalar input).

    Raises
    ------
    InputError
        A negative or non-finite ``k``, ``L`` or ``S``.

    Examples
    --------
    >>> archard_volume(5e-18, 500.0, 0.010)   # seed 000 inputs, S = h = 10 mm
    2.5e-17
    """
    k = _validate.nonnegative("k", k, "m^3/(N m)")
    L = _nonneg_array("L", L, "N")
    S = _nonneg_array("S", S, "m")
    W = k * L * S
    return float(W) if W.ndim == 0 else W
