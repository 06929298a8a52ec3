r"""Case-hardened bodies: hardness-depth law, shear strength over depth, case-core margin.

=============  ==========================================================  =====  ==========================
symbol         meaning                                                     unit   source
=============  ==========================================================  =====  ==========================
``z``          depth below the surface                                     m
``d_c``        effective case depth: ``H(d_c) = H_core + 50 HV``           m      DIN 50190-3 (nitriding)
``H_s, H_c``   surface and core hardness                                   Pa     scene ``*_hardness_HV``
``delta``      decay length of the exponential law                         m
``sigma_y``    yield strength, ``H/3`` from a hardness                     Pa     Tabor 1951, Johnson 1985
``k``          shear yield strength, ``sigma_y / sqrt 3`` (von Mises)      Pa     Johnson 1985 §6.2
``U``          utilisation: local max shear ``tau_1(z)`` over ``k(z)``     -
=============  ==========================================================  =====  ==========================

The case is elastic like the core (same modulus: a case changes strength, not stiffness); only
its strength varies with depth. Laws (``CASE_LAWS``), both with ``H(0) = H_s``,
``H(d_c) = H_c + 50 HV`` and ``H -> H_c`` in the core:

.. math:: H_{exp}(z) = H_c + (H_s - H_c)\,e^{-z/\delta},\quad
          \delta = d_c / \ln\frac{H_s - H_c}{50\,\mathrm{HV}}

.. math:: H_{lin}(z) = \max\!\left(H_c,\; H_s - (H_s - H_c - 50\,\mathrm{HV})\,z/d_c\right)

If yield strengths are given instead of hardness, the same laws apply to ``sigma_y`` with the
50 HV step converted by ``sigma_y = H/3``. The case-core margin is ``1 / max_z U(z)``: below 1
the subsurface shear yields the case or the core (case crushing).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from .._repr import compact_repr

CASE_LAWS = ("exponential", "linear")
#: 1 HV (kgf/mm^2) in Pa
HV = 9.80665e6
#: the effective-case-depth criterion: core hardness + 50 HV (DIN 50190-3)
DELTA_H = 50.0 * HV


def shear_strength_from_hardness(H):
    r"""Shear yield strength from a hardness (Pa): ``k = H / (3 sqrt 3)``.

    .. math:: k = \frac{\sigma_y}{\sqrt 3},\qquad \sigma_y = \frac{H}{3}

    (Tabor 1951 for ``H ~ 3 sigma_y``; von Mises ``k = sigma_y/sqrt 3``, Johnson 1985 §6.2).

    Parameters
    ----------
    H : float or array_like
        Hardness [Pa] (1 HV = :data:`HV` Pa).

    Returns
    -------
    float or ndarray
        Shear yield strength ``k`` [Pa], shape of ``H``.

    >>> round(float(shear_strength_from_hardness(600 * 9.80665e6)) / 1e6, 1)
    1132.4
    """
    return _validate.positive_array("H", H, "Pa") / (3.0 * math.sqrt(3.0))


@dataclass(frozen=True, kw_only=True)
class Case:
    """A hardened case: give surface and core hardness OR surface and core yield strength.

    Parameters
    ----------
    depth : float
        Effective case depth ``d_c`` [m], > 0.
    surface_hardness, core_hardness : float, optional
        Hardness at the surface and in the core [Pa] (1 HV = :data:`HV` Pa).
    surface_yield, core_yield : float, optional
        Uniaxial yield strength at the surface and in the core [Pa].
    law : {"exponential", "linear"}, optional
        Hardness-depth law (:data:`CASE_LAWS`, module docstring).

    Raises
    ------
    InputError
        Both or neither pair given, a missing or non-positive value, or a surface-core step not
        above the 50 HV criterion.
    """

    depth: float
    surface_hardness: float | None = None
    core_hardness: float | None = None
    surface_yield: float | None = None
    core_yield: float | None = None
    law: str = "exponential"

    def __post_init__(self):
        _validate.positive("depth", self.depth, "m")
        _validate.choice("law", self.law, CASE_LAWS)
        hard = self.surface_hardness is not None or self.core_hardness is not None
        yld = self.surface_yield is not None or self.core_yield is not None
        if hard == yld:
            raise _validate.fail("case strengths", None, "Pa", "give surface and core hardness OR "
                                 "surface and core yield strength (one pair)")
        s, c = self._pair()
        step = DELTA_H if hard else DELTA_H / 3.0
        if s - c <= step:
            raise _validate.fail("surface - core", (s - c) / 1e6, "MPa",
                                 f"must exceed the case-depth criterion {step / 1e6:.4g} MPa (50 HV)")

    def _pair(self):
        hard = self.surface_hardness is not None or self.core_hardness is not None
        names = ("surface_hardness", "core_hardness") if hard else ("surface_yield", "core_yield")
        for n in names:
            if getattr(self, n) is None:
                raise _validate.fail(n, None, "Pa", "is missing (give both surface and core)")
            _validate.positive(n, getattr(self, n), "Pa")
        return getattr(self, names[0]), getattr(self, names[1])

    def yield_strength(self, z):
        """Uniaxial yield strength at depth ``z`` (``H/3`` from hardness).

        Parameters
        ----------
        z : float or array_like
            Depth below the surface [m], >= 0.

        Returns
        -------
        float or ndarray
            ``sigma_y(z)`` [Pa], shape of ``z``.
        """
        z = np.asarray(z, dtype=float)
        if np.any(z < 0):
            raise _validate.fail("z", float(z.min()), "m", "must be >= 0 (depth)")
        s, c = self._pair()
        hard = self.surface_hardness is not None
        step = DELTA_H if hard else DELTA_H / 3.0
        if self.law == "exponential":
            delta = self.depth / math.log((s - c) / step)
            v = c + (s - c) * np.exp(-z / delta)
        else:
            v = np.maximum(c, s - (s - c - step) * z / self.depth)
        return v / 3.0 if hard else v

    def shear_strength(self, z):
        """Shear yield strength ``k(z) = sigma_y(z)/sqrt 3`` (von Mises).

        Parameters
        ----------
        z : float or array_like
            Depth below the surface [m], >= 0.

        Returns
        -------
        float or ndarray
            ``k(z)`` [Pa], shape of ``z``.
        """
        return self.yield_strength(z) / math.sqrt(3.0)

    def check_body(self, size: float, name: str = "cam") -> None:
        """Refuse a case deeper than half the body.

        Parameters
        ----------
        size : float
            Body size [m].
        name : str, optional
            Body name for the message.

        Raises
        ------
        InputError
            ``depth >= size / 2`` (a through-hardened body is not a case).
        """
        if self.depth >= 0.5 * size:
            raise _validate.fail("case.depth", self.depth * 1e3, "mm",
                                 f"must be < {0.5 * size * 1e3:.4g} mm, half the {name} body size "
                                 f"{size * 1e3:.4g} mm (a through-hardened body is not a case)")


@dataclass(frozen=True)
class CaseMargin:
    """Utilisation ``U = tau / k`` over depth, and the case-core margin.

    Parameters
    ----------
    z : ndarray of float, shape (n,)
        Depths [m].
    utilisation : ndarray of float, shape (n,)
        ``U(z) = |tau(z)| / k(z)`` [-].
    u_max : float
        ``max U`` [-].
    z_at_max : float
        Depth of ``u_max`` [m].
    margin : float
        ``1 / u_max`` [-] (``inf`` when ``u_max = 0``).
    """

    z: np.ndarray
    utilisation: np.ndarray
    u_max: float
    z_at_max: float
    margin: float

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)



def case_margin(case: Case, z, tau) -> CaseMargin:
    r"""Case-core utilisation ``U(z) = tau(z) / k(z)`` and margin ``1/max U``.

    .. math:: U(z) = \frac{\tau_1(z)}{k(z)},\qquad \mathrm{margin} = \frac{1}{\max_z U}

    ``z`` depths (m), ``tau`` local maximum shear stress there (Pa, e.g. Hertz ``tau_1`` below
    the contact, peak ``0.30 p_0`` at ``0.78 a``, Johnson 1985 §4.2).

    Parameters
    ----------
    case : Case
        The hardened case.
    z : array_like of float, shape (n,)
        Depths [m], >= 0.
    tau : array_like of float, shape (n,)
        Local maximum shear stress at those depths [Pa].

    Returns
    -------
    CaseMargin
        Utilisation over depth, its maximum and the margin.
    """
    z = _validate.finite_array("z", z, "m")
    tau = _validate.finite_array("tau", tau, "Pa")
    _validate.instance("case", case, Case)
    if z.shape != tau.shape or z.size == 0:
        raise _validate.fail("tau", tau.shape, "", f"must have the shape of z {z.shape} (non-empty)")
    u = np.abs(tau) / case.shear_strength(z)
    i = int(np.argmax(u))
    return CaseMargin(z=z, utilisation=u, u_max=float(u[i]), z_at_max=float(z[i]),
                      margin=float(1.0 / u[i]) if u[i] > 0 else math.inf)
