r"""Lubricant properties: a small table of named oils and the viscosity-temperature laws.

Symbols
-------
=========  =========================================================  =======  =====================
symbol     meaning                                                    unit     source
=========  =========================================================  =======  =====================
nu40       kinematic viscosity at 40 degC                             m^2/s    ISO 3448 (grade)
nu100      kinematic viscosity at 100 degC                            m^2/s    product data (VI~100)
rho        density (taken constant)                                   kg/m^3
alpha      Barus pressure-viscosity coefficient (taken constant)      1/Pa     Barus 1893
eta        dynamic viscosity ``rho nu``                               Pa s
beta_T     temperature coefficient of the exponential (Reynolds)      1/K      Reynolds 1886
           law ``eta = eta_ref exp(-beta_T (T - T_ref))``
=========  =========================================================  =======  =====================

Viscosity-temperature laws:

* two kinematic viscosities (``nu40``, ``nu100``): Walther's equation as standardised in
  ASTM D341, :math:`\log_{10}\log_{10}(\nu + 0.7) = A - B\log_{10} T` (``nu`` in mm^2/s, ``T`` in K);
* one viscosity and a coefficient: Reynolds' exponential law (good over a few tens of kelvin).

Table values (assumptions, stated): ISO VG grades are the ISO 3448 mid-point kinematic viscosity at
40 degC; the 100 degC values are those of paraffinic mineral oils of viscosity index about 100
(ASTM D2270: VI 100 at these pairs to within a few units); density 0.86-0.87 g/ml; ``alpha`` =
2.0e-8 1/Pa (20 GPa^-1), the middle of the 1.5-2.5e-8 1/Pa band of mineral oils near 40 degC
(Hamrock, Schmid & Jacobson 2004 ch. 4; Stachowiak & Batchelor 2014 ch. 2). ``alpha`` falls with
temperature; taking it constant overestimates the film at high oil temperature.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..errors import InputError

#: name -> (nu40 mm^2/s, nu100 mm^2/s, density kg/m^3, alpha 1/Pa, note)
OILS = {
    "ISO VG 32 mineral": (32.0, 5.4, 857.0, 2.0e-8, "ISO 3448 grade; VI ~ 100 paraffinic mineral oil"),
    "ISO VG 46 mineral": (46.0, 6.8, 861.0, 2.0e-8, "ISO 3448 grade; VI ~ 100 paraffinic mineral oil"),
    "ISO VG 68 mineral": (68.0, 8.7, 865.0, 2.0e-8, "ISO 3448 grade; VI ~ 100 paraffinic mineral oil"),
    "ISO VG 100 mineral": (100.0, 11.1, 869.0, 2.0e-8, "ISO 3448 grade; VI ~ 100 paraffinic mineral oil"),
}


@dataclass(frozen=True, kw_only=True)
class Lubricant:
    """A lubricant: either ``nu40``/``nu100`` (m^2/s, Walther/ASTM D341) or ``eta_ref`` (Pa s) at
    ``T_ref_C`` with ``beta_T`` (1/K, exponential law); ``alpha`` (1/Pa); ``rho`` (kg/m^3).

    Parameters
    ----------
    name : str
        Label of the oil.
    alpha : float
        Barus pressure-viscosity coefficient, ``> 0`` [1/Pa].
    rho : float
        Density, ``> 0`` [kg/m^3].
    nu40, nu100 : float or None
        Kinematic viscosities at 40 and 100 degC, ``nu100 < nu40`` [m^2/s] (Walther law).
    eta_ref : float or None
        Dynamic viscosity at ``T_ref_C`` [Pa s] (exponential law).
    T_ref_C : float or None
        Reference temperature of ``eta_ref`` [degC].
    beta_T : float or None
        Temperature coefficient of the exponential law, ``>= 0`` [1/K].
    source : str
        Where the values come from.

    Raises
    ------
    InputError
        Neither or both of the two viscosity descriptions, or a value out of range.

    Examples
    --------
    >>> oil = lubricant("ISO VG 46 mineral")
    >>> round(float(oil.viscosity(40.0)) * 1e3, 2)      # mPa s = 46 mm^2/s * 0.861 g/ml
    39.61
    """

    name: str = ""
    alpha: float
    rho: float
    nu40: float | None = None
    nu100: float | None = None
    eta_ref: float | None = None
    T_ref_C: float | None = None
    beta_T: float | None = None
    source: str = ""

    def __post_init__(self):
        _validate.positive("alpha", self.alpha, "1/Pa")
        _validate.positive("rho", self.rho, "kg/m^3")
        walther = self.nu40 is not None and self.nu100 is not None
        expo = self.eta_ref is not None and self.T_ref_C is not None and self.beta_T is not None
        if walther == expo:
            raise InputError("lubricant: give either nu40 and nu100 (m^2/s) or eta_ref (Pa s), T_ref_C "
                             "(degC) and beta_T (1/K)")
        if walther:
            _validate.positive("nu40", self.nu40, "m^2/s")
            _validate.positive("nu100", self.nu100, "m^2/s")
            if not self.nu100 < self.nu40:
                raise _validate.fail("nu100", self.nu100, "m^2/s", f"must be < nu40 = {self.nu40:g} m^2/s")
        else:
            _validate.positive("eta_ref", self.eta_ref, "Pa s")
            _validate.number("T_ref_C", self.T_ref_C, "degC")
            _validate.nonnegative("beta_T", self.beta_T, "1/K")

    def viscosity(self, T_C):
        r"""Dynamic viscosity (Pa s) at ``T_C`` (degC), vectorised.

        .. math:: \log_{10}\log_{10}(\nu + 0.7) = A - B\log_{10}T \quad\text{or}\quad
                  \eta = \eta_{ref}\,e^{-\beta_T (T - T_{ref})}

        Parameters
        ----------
        T_C : float or array_like
            Oil temperature [degC].

        Returns
        -------
        ndarray, shape of ``T_C``
            Dynamic viscosity [Pa s].
        """
        T_C = np.asarray(T_C, float)
        if self.nu40 is None:
            return self.eta_ref * np.exp(-self.beta_T * (T_C - self.T_ref_C))
        T1, T2 = 313.15, 373.15
        y1 = math.log10(math.log10(self.nu40 * 1e6 + 0.7))
        y2 = math.log10(math.log10(self.nu100 * 1e6 + 0.7))
        B = (y1 - y2) / (math.log10(T2) - math.log10(T1))
        A = y1 + B * math.log10(T1)
        nu_mm2 = 10.0 ** (10.0 ** (A - B * np.log10(T_C + 273.15))) - 0.7
        return self.rho * nu_mm2 * 1e-6


def lubricant(name: str) -> Lubricant:
    """The named oil of :data:`OILS` (InputError with the valid names otherwise).

    Parameters
    ----------
    name : str
        A key of :data:`OILS`, e.g. ``"ISO VG 46 mineral"``.

    Returns
    -------
    Lubricant
        The oil with SI values (``nu40``, ``nu100`` in m^2/s).

    Raises
    ------
    InputError
        Unknown ``name``.
    """
    if name not in OILS:
        raise InputError(f"lubricant name = {name!r}: unknown; valid names: {', '.join(map(repr, OILS))}")
    nu40, nu100, rho, alpha, note = OILS[name]
    return Lubricant(name=name, nu40=nu40 * 1e-6, nu100=nu100 * 1e-6, rho=rho, alpha=alpha, source=note)
