"""Elastic materials and the combined moduli of a contact pair.

Symbols
-------
=========  ==========================================  ======  ==========================
symbol     meaning                                      unit    source
=========  ==========================================  ======  ==========================
E          Young's modulus                              Pa
nu         Poisson's ratio, -1 < nu < 0.5               -
E_star     contact modulus, 1/E* = sum (1-nu_i^2)/E_i   Pa      Johnson (1985) eq. 4.22;
                                                                seed 002 eq. 10
H          hardness (for Archard wear), optional        Pa      seed 000
=========  ==========================================  ======  ==========================

Plane strain (long cylinders) uses E/(1-nu^2); plane stress (thin discs) uses E.
"""

from __future__ import annotations

from dataclasses import dataclass

from . import _validate

PLANES = ("strain", "stress")
#: accepted Young's moduli (Pa) in the API: soft elastomers (1e5) up to 1e18, which leaves room for
#: the "rigid body" limit of numerical studies (1e5 x steel) but refuses unit mistakes such as
#: 1e30 Pa (a contact of zero width that no mesh can resolve)
E_MIN, E_MAX = 1e5, 1e18
#: moduli of real engineering materials (Pa), soft elastomers to diamond (1.2e12 Pa): the range a
#: scene file accepts (femcam.scene), where a value outside it is a unit mistake
E_PHYSICAL = (1e5, 2e12)


@dataclass(frozen=True, kw_only=True)
class Material:
    """An isotropic linear-elastic material (SI units).

    Parameters
    ----------
    E : float
        Young's modulus [Pa], in [E_MIN, E_MAX] = [1e5, 1e18].
    nu : float
        Poisson's ratio [-], in (-1, 0.5).
    name : str, optional
        Label used in messages and reports.
    hardness : float or None, optional
        Hardness H [Pa] (> 0) for Archard wear; None when not given.

    Raises
    ------
    InputError
        A value out of range, naming the field, value and unit.

    >>> Material(E=210e9, nu=0.3, name="steel").E
    210000000000.0
    """

    E: float
    nu: float
    name: str = ""
    hardness: float | None = None

    def __post_init__(self):
        # see E_MIN, E_MAX
        object.__setattr__(self, "E", _validate.in_range("E", self.E, E_MIN, E_MAX, "Pa"))
        object.__setattr__(self, "nu", _validate.in_range("nu", self.nu, -1.0, 0.5, "", lo_open=True,
                                                          hi_open=True))
        if self.hardness is not None:
            object.__setattr__(self, "hardness", _validate.positive("hardness", self.hardness, "Pa"))

    def modulus(self, plane: str = "strain") -> float:
        """E' = E/(1-nu^2) in plane strain, E in plane stress (Pa).

        Parameters
        ----------
        plane : {"strain", "stress"}, optional
            Plane strain (long cylinders, default) or plane stress (thin discs).

        Returns
        -------
        float
            Plane modulus E' [Pa].
        """
        _validate.choice("plane", plane, PLANES)
        return self.E / (1.0 - self.nu**2) if plane == "strain" else self.E


STEEL = Material(E=210e9, nu=0.3, name="steel")


def effective_modulus(m1: Material, m2: Material, plane: str = "strain") -> float:
    r"""Contact modulus E* of two bodies (Pa).

    .. math:: \frac{1}{E^*} = \frac{1-\nu_1^2}{E_1} + \frac{1-\nu_2^2}{E_2}

    (plane strain; Johnson, *Contact Mechanics*, 1985, eq. 4.22 with 4.43; seed 002 eq. 10).
    In plane stress the (1 - nu^2) factors are dropped.

    Parameters
    ----------
    m1, m2 : Material
        Materials of body 1 and body 2.
    plane : {"strain", "stress"}, optional
        Plane strain (default) or plane stress.

    Returns
    -------
    float
        Contact modulus E* [Pa].

    >>> round(effective_modulus(STEEL, STEEL) / 1e9, 2)
    115.38
    """
    return 1.0 / (1.0 / m1.modulus(plane) + 1.0 / m2.modulus(plane))


def lame_parameters(E, nu, plane: str = "strain"):
    r"""Lamé parameters (lambda, mu) for 2D elasticity (Pa).

    Plane strain: :math:`\lambda = E\nu/((1+\nu)(1-2\nu))`, :math:`\mu = E/(2(1+\nu))`; plane
    stress uses the reduced :math:`\lambda^* = 2\lambda\mu/(\lambda + 2\mu) = E\nu/(1-\nu^2)`.
    ``E`` (Pa) must be > 0 and ``nu`` in (-1, 0.5) (scalars or arrays); otherwise
    :class:`~femcam.errors.InputError` (``nu = 0.5`` would give an infinite lambda).

    Parameters
    ----------
    E : float or ndarray
        Young's modulus [Pa], > 0.
    nu : float or ndarray
        Poisson's ratio [-], in (-1, 0.5); broadcasts with ``E``.
    plane : {"strain", "stress"}, optional
        Plane strain (default) or plane stress (reduced lambda*).

    Returns
    -------
    lam, mu : float or ndarray
        Lamé's first parameter lambda (lambda* in plane stress) and the shear modulus mu [Pa],
        of the broadcast shape of ``E`` and ``nu`` (numpy floats for scalar input).

    >>> [round(float(x) / 1e9, 6) for x in lame_parameters(200e9, 0.25)]
    [80.0, 80.0]
    """
    _validate.choice("plane", plane, PLANES)
    E = _validate.positive_array("E", E, "Pa")
    nu = _validate.in_range_array("nu", nu, -1.0, 0.5, "", lo_open=True, hi_open=True)
    mu = E / (2.0 * (1.0 + nu))
    lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    if plane == "stress":
        lam = 2.0 * lam * mu / (lam + 2.0 * mu)
    return lam, mu
