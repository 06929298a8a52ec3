"""Analytic Hertz line contact with sliding friction (numpy/scipy only).

Every FE result in femcam is judged against this package.

* :mod:`~femcam.hertz.contact` -- :class:`LineContact`: ``R``, ``E_star``, ``w``, ``a``,
  ``p0``, ``fmax`` (Johnson 1985 eqs. 4.44-4.45; seed 002 eqs. 8-10), validity checks.
* :mod:`~femcam.hertz.surface` -- pressure and surface stresses on ``z = 0`` (seed 002 eqs. 5-7).
* :mod:`~femcam.hertz.subsurface` -- closed-form field ``sx, sz, txz, sy`` and ``tau1``,
  Tresca, von Mises (McEwen 1949; Johnson eqs. 7.20-7.21).
* :mod:`~femcam.hertz.maxima` -- maxima of ``tau1``, von Mises and ``|txz|``, and the range of
  ``txz`` over one pass, for any ``mu``.

Sign convention: tension positive, ``z >= 0`` into the body, friction traction on the body in
+x (the other body slides in +x), so the tensile surface peak ``2 mu p0`` sits at ``x = -a``.
"""

from .contact import (
    VALIDITY_RATIO,
    HertzValidityWarning,
    LineContact,
    effective_radius,
    half_width,
    peak_pressure,
)
from .maxima import (
    ScaledMaximum,
    StressMaximum,
    max_orthogonal_shear,
    max_shear,
    max_shear_range,
    max_von_mises,
)
from .subsurface import StressField, stress_field, unit_stresses
from .surface import hertz_pressure, surface_stress

__all__ = [
    "VALIDITY_RATIO",
    "HertzValidityWarning",
    "LineContact",
    "ScaledMaximum",
    "StressField",
    "StressMaximum",
    "effective_radius",
    "half_width",
    "hertz_pressure",
    "max_orthogonal_shear",
    "max_shear",
    "max_shear_range",
    "max_von_mises",
    "peak_pressure",
    "stress_field",
    "surface_stress",
    "unit_stresses",
]
