r"""Parameters of the real roller: outer ring, pin or needles (and the cam's shaft bore).

Symbols (SI inside; mm, um only at the scene edge)

=============  =====================================================  ====  ==========================
symbol         meaning                                                unit  source
=============  =====================================================  ====  ==========================
``Ro``         ring outer radius (the roller radius ``Rr``)            m     scene ``roller_radius_mm``
``Ri``         ring bore radius                                       m     ``roller_bore_mm``
``Rp``         pin (or inner raceway) radius                          m     ``pin_radius_mm``
``c``          radial clearance: ``Ri - Rp`` (pin) or                 m     ``pin_clearance_um``
               ``Ri - 2 r_n - Rp`` (needles)
``Z``          needle count                                           -     ``needle_count``
``r_n``        needle radius                                          m     ``needle_radius_mm``
``l``          face width (ring and needle length)                    m     ``face_width_mm``
``Q``          needle load per unit length                            N/m
``delta_n``    approach of ring and pin across one needle (2 contacts) m     Palmgren 1959
=============  =====================================================  ====  ==========================

Needle load-deflection (two steel line contacts per needle; Palmgren 1959, as quoted by Harris &
Kotzalas 2006 §7.3 for roller-raceway contacts; mm and N in the original):

.. math:: \delta_n = 2 \times 3.84\times10^{-5}\,\frac{(Q l)^{0.9}}{l^{0.8}}
          \quad [\mathrm{mm};\ Q l\ \mathrm{in\ N},\ l\ \mathrm{in\ mm}]

i.e. ``Q ~ delta^n`` with ``n = 10/9``: the exponent of the Stribeck sum (tests/test_bodies_needles.py).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..errors import InputError
from ..materials import STEEL, Material
from ..scene import roller_support_problems

#: the scene key a message names for the clearance c
_CLEARANCE = "c ([follower] pin_clearance_um)"

SUPPORTS = ("solid", "pin", "needles")
#: Palmgren's line-contact coefficient (mm N^-0.9 mm^0.8) and load exponent
PALMGREN_C = 3.84e-5
PALMGREN_EXP = 0.9


def needle_approach(Q, length: float):
    r"""Approach ``delta_n`` (m) of the two races across one needle under ``Q`` (N/m).

    .. math:: \delta_n = 2\cdot 3.84\cdot10^{-5}\,(Q l)^{0.9}\, l_{mm}^{-0.8}\ \mathrm{mm}

    Parameters
    ----------
    Q : float or ndarray
        Needle load per unit length [N/m] (negative values count as 0).
    length : float
        Needle length (face width) [m].

    Returns
    -------
    float or ndarray
        Approach ``delta_n`` [m], shaped like ``Q``.

    >>> round(float(needle_approach(150e3, 0.01)) * 1e6, 2)   # 1500 N on a 10 mm needle: um
    8.79
    """
    Q = np.maximum(_validate.finite_array("Q", Q, "N/m"), 0.0)
    length = _validate.positive("length", length, "m")
    return 2.0 * PALMGREN_C * (Q * length) ** PALMGREN_EXP / (length * 1e3) ** 0.8 * 1e-3


def bearing_problems(*, Ro, Ri, support, Rp, c, Z, r_n) -> list[str]:
    """Every geometry problem of a ring support, as scene-style messages (mm, um).

    The relations between the dimensions are checked by the scene's
    :func:`femcam.scene.roller_support_problems` (one copy, with the scene keys it names); each
    argument is first checked alone here, so a wrong type or sign raises naming the argument.

    Parameters
    ----------
    Ro, Ri : float
        Outer and bore radius of the ring [m], > 0.
    support : str
        ``"pin"`` or ``"needles"``.
    Rp, c : float
        Pin radius and diametral clearance [m], >= 0.
    Z : int
        Number of needles, >= 0.
    r_n : float
        Needle radius [m], >= 0.

    Returns
    -------
    list of str
        The problems (empty when the geometry fits).
    """
    Ro = _validate.positive("Ro", Ro, "m")
    Ri = _validate.positive("Ri", Ri, "m")
    Rp = _validate.nonnegative("Rp", Rp, "m")
    c = _validate.nonnegative("c", c, "m")
    Z = _validate.integer("Z", Z, 0, "needles")
    r_n = _validate.nonnegative("r_n", r_n, "m")
    return roller_support_problems(Ro=Ro, Ri=Ri, support=support, Rp=Rp, c=c, Z=Z, r_n=r_n)


@dataclass(frozen=True, kw_only=True)
class RollerBearing:
    """The roller as a ring on a pin or on needles (SI units).

    Parameters
    ----------
    Ro : float
        Ring outer radius (the roller radius) [m].
    Ri : float
        Ring bore radius [m].
    support : {"pin", "needles"}, optional
        What carries the ring.
    Rp : float, optional
        Pin (or inner raceway) radius [m].
    c : float, optional
        Radial clearance [m] (module table), at most 0.05 ``Ri``.
    Z : int, optional
        Needle count (needles only).
    r_n : float, optional
        Needle radius [m] (needles only).
    ring : Material, optional
        Ring material (default steel).
    pin : Material or None, optional
        Pin material (default steel); None for a rigid pin.
    needle : Material, optional
        Needle material (default steel).
    ring_yield : float or None, optional
        Tensile limit of the ring [Pa] flagged in results; None for no flag.

    Raises
    ------
    InputError
        Every geometry problem at once (:func:`bearing_problems`), or a clearance above 0.05 Ri.
    """

    Ro: float
    Ri: float
    support: str = "pin"
    Rp: float = 0.0
    c: float = 0.0
    Z: int = 0
    r_n: float = 0.0
    ring: Material = STEEL
    pin: Material | None = STEEL
    needle: Material = STEEL
    ring_yield: float | None = None

    def __post_init__(self):
        _validate.choice("support", self.support, SUPPORTS[1:])
        _validate.positive("Ro", self.Ro, "m")
        _validate.positive("Ri", self.Ri, "m")
        _validate.nonnegative("c", self.c, "m")
        _validate.optional(_validate.positive, "ring_yield", self.ring_yield, "Pa")
        problems = bearing_problems(Ro=self.Ro, Ri=self.Ri, support=self.support, Rp=self.Rp,
                                    c=self.c, Z=self.Z, r_n=self.r_n)
        if problems:
            raise InputError("; ".join(problems))  # each names its key, value and unit
        if self.c > 0.05 * self.Ri:
            raise _validate.fail(_CLEARANCE, self.c, "m", f"the clearance is {self.c / self.Ri:.3g} of "
                                 "the bore radius: the linearised gap (c << Ri) does not hold beyond 0.05 Ri")

    @property
    def wall(self) -> float:
        """Ring wall thickness Ro - Ri (m)."""
        return self.Ro - self.Ri

    def needle_angles(self, cage: float) -> np.ndarray:
        """Needle polar angles with needle 0 at ``-pi/2 + cage``.

        Parameters
        ----------
        cage : float
            Cage angle [rad]: 0 puts a needle on the load line, ``pi / Z`` the load line between
            two needles.

        Returns
        -------
        ndarray, shape (Z,)
            Needle polar angles about the ring centre [rad].
        """
        return -0.5 * math.pi + cage + 2 * math.pi * np.arange(self.Z) / self.Z
