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

from .. import _validate as chk
from ..materials import STEEL, Material

SUPPORTS = ("solid", "pin", "needles")
#: Palmgren's line-contact coefficient (mm N^-0.9 mm^0.8) and load exponent
PALMGREN_C = 3.84e-5
PALMGREN_EXP = 0.9


def needle_approach(Q, length: float):
    r"""Approach ``delta_n`` (m) of the two races across one needle under ``Q`` (N/m).

    .. math:: \delta_n = 2\cdot 3.84\cdot10^{-5}\,(Q l)^{0.9}\, l_{mm}^{-0.8}\ \mathrm{mm}

    >>> round(float(needle_approach(150e3, 0.01)) * 1e6, 2)   # 1500 N on a 10 mm needle: um
    8.79
    """
    Q = np.maximum(np.asarray(Q, dtype=float), 0.0)
    return 2.0 * PALMGREN_C * (Q * length) ** PALMGREN_EXP / (length * 1e3) ** 0.8 * 1e-3


def bearing_problems(*, Ro, Ri, support, Rp, c, Z, r_n) -> list[str]:
    """Every geometry problem of a ring support, as messages naming value and unit (mm, um)."""
    out = []
    if support == "solid":
        return out
    if not 0.0 < Ri < Ro:
        out.append(f"roller_bore_mm = {Ri * 1e3:g} mm: must be in (0, roller_radius_mm = {Ro * 1e3:g} mm)")
        return out
    if support == "pin":
        if not math.isclose(Rp + c, Ri, rel_tol=1e-9, abs_tol=1e-12):
            out.append(f"pin_radius_mm + pin_clearance_um = {Rp * 1e3:g} mm + {c * 1e6:g} um = "
                       f"{(Rp + c) * 1e3:g} mm: must equal roller_bore_mm = {Ri * 1e3:g} mm")
        return out
    # needles
    if Z < 3:
        out.append(f"needle_count = {Z}: at least 3 needles are needed to hold the ring")
    if r_n <= 0:
        out.append(f"needle_radius_mm = {r_n * 1e3:g} mm: must be > 0")
        return out
    if Rp <= 0 or not math.isclose(Rp + 2 * r_n + c, Ri, rel_tol=1e-9, abs_tol=1e-12):
        out.append(f"pin_radius_mm + 2 needle_radius_mm + pin_clearance_um = {Rp * 1e3:g} + "
                   f"{2 * r_n * 1e3:g} mm + {c * 1e6:g} um = {(Rp + 2 * r_n + c) * 1e3:g} mm: must "
                   f"equal roller_bore_mm = {Ri * 1e3:g} mm (with pin_radius_mm > 0)")
    if Z >= 3:
        pitch = Ri - r_n
        free = 2 * pitch * math.sin(math.pi / Z) - 2 * r_n
        if free < 0:
            zmax = int(math.pi / math.asin(min(1.0, r_n / pitch)))
            out.append(f"needle_count = {Z} needles of radius {r_n * 1e3:g} mm do not fit around "
                       f"the pitch circle of radius {pitch * 1e3:g} mm (they overlap by "
                       f"{-free * 1e6:.3g} um); at most {zmax} fit")
    return out


@dataclass(frozen=True, kw_only=True)
class RollerBearing:
    """The roller as a ring on a pin or on needles (SI units).

    Ro, Ri: ring outer and bore radii; support: "pin" or "needles"; Rp: pin radius; c: radial
    clearance (see module table); Z, r_n: needle count and radius; ring, pin, needle: materials
    (``pin=None``: a rigid pin); ring_yield: optional tensile limit (Pa) flagged in results.
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
        chk.choice("support", self.support, SUPPORTS[1:])
        chk.positive("Ro", self.Ro, "m")
        chk.positive("Ri", self.Ri, "m")
        chk.nonnegative("c", self.c, "m")
        problems = bearing_problems(Ro=self.Ro, Ri=self.Ri, support=self.support, Rp=self.Rp,
                                    c=self.c, Z=int(self.Z), r_n=self.r_n)
        if problems:
            raise chk.fail("RollerBearing", "", "", "; ".join(problems))
        if self.c > 0.05 * self.Ri:
            raise chk.fail("c", self.c, "m", f"the clearance is {self.c / self.Ri:.3g} of the bore "
                           "radius: the linearised gap (c << Ri) does not hold beyond 0.05 Ri")

    @property
    def wall(self) -> float:
        """Ring wall thickness Ro - Ri (m)."""
        return self.Ro - self.Ri

    def needle_angles(self, cage: float) -> np.ndarray:
        """Needle polar angles (rad) with needle 0 at ``-pi/2 + cage`` (``cage = 0``: a needle on
        the load line; ``cage = pi / Z``: the load line between two needles)."""
        return -0.5 * math.pi + cage + 2 * math.pi * np.arange(self.Z) / self.Z
