r"""Roller profiles along the axis: crown, edge radius and misalignment tilt.

Symbols (Johnson 1985 §5.4; Lundberg 1939; Johns & Gohar 1981; Harris & Kotzalas 2007 §6.7)
---------------------------------------------------------------------------------------------
=========  ===================================================  =====  ================================
symbol     meaning                                              unit   source
=========  ===================================================  =====  ================================
y          axial coordinate from the roller's mid-plane         m
l          roller width (length of the roller generatrix)       m
Rc         crown radius of a circular crown                     m
d          crown drop at the roller end ``y = +-l/2``           m
Q          design load of the logarithmic profile               N
b          Hertz half-width at ``w = Q / l``                    m      Johnson eq. 4.45
E_star     contact modulus                                      Pa     Johnson eq. 4.22
re         edge (corner) radius blending the roller end         m
gamma      tilt of the roller axis towards the cam, in the      rad
           plane holding the axis and the contact normal
=========  ===================================================  =====  ================================

The drop ``c(y) >= 0`` is the distance the roller surface recedes from the cam at ``y``; the
initial gap of the strip is ``x^2 / 2R + c(y) + y tan(gamma)`` (``+y`` end lifted for
``gamma > 0``).

* circular crown: :math:`c = R_c - \sqrt{R_c^2 - y^2}` (drop ``d = c(l/2)``);
* logarithmic crown (Lundberg 1939, with the end correction of Johns & Gohar 1981): the drop
  that keeps a uniform line load ``Q / l`` uniform on the half-space,
  :math:`c = \frac{Q}{\pi l E^*}\ln\frac{1}{1 - (1 - 2b/l)(2y/l)^2}`; ``1 - 2b/l`` keeps the
  end drop finite, :math:`d = \frac{Q}{\pi l E^*}\ln\frac{l}{2b}`;
* edge radius: a circle of radius ``re`` tangent to the generatrix at ``|y| = l/2 - re``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate

CROWNS = ("none", "circular", "logarithmic")


def circular_drop(y, Rc):
    r"""Drop (m) of a circular crown of radius ``Rc`` (m) at ``y`` (m).

    .. math:: c(y) = R_c - \sqrt{R_c^2 - y^2}

    Parameters
    ----------
    y : float or array_like
        Axial coordinate from the roller's mid-plane [m].
    Rc : float
        Crown radius [m]; ``|y| > Rc`` is clipped to the drop ``Rc``.

    Returns
    -------
    ndarray
        Drop ``c(y)`` [m], float, the shape of ``y``.

    Examples
    --------
    >>> round(float(circular_drop(0.005, 1.0)) * 1e6, 4)   # um, ~ y^2 / 2 Rc = 12.5 um
    12.5001
    """
    y = _validate.finite_array("y", y, "m")
    Rc = _validate.positive("Rc", Rc, "m")
    return Rc - np.sqrt(np.maximum(Rc * Rc - y * y, 0.0))


def log_drop(y, l, Q, b, E_star):
    r"""Drop (m) of the logarithmic crown of Lundberg (1939) with the Johns & Gohar (1981) end
    correction, designed for the load ``Q`` (N) on a roller of width ``l`` (m).

    .. math:: c(y) = \frac{Q}{\pi l E^*}\ln\frac{1}{1 - (1 - 2b/l)(2y/l)^2}

    Parameters
    ----------
    y : float or array_like
        Axial coordinate from the roller's mid-plane [m]; ``|y| > l/2`` is clipped to the end.
    l : float
        Roller width [m].
    Q : float
        Design load of the profile [N].
    b : float
        Hertz half-width at the line load ``Q / l`` [m].
    E_star : float
        Contact modulus [Pa].

    Returns
    -------
    ndarray
        Drop ``c(y)`` [m], float, the shape of ``y``.

    Examples
    --------
    At the end the drop is ``Q ln(l / 2b) / (pi l E*)``:

    >>> c = log_drop(0.005, 0.01, 1000.0, 5e-5, 1.15e11)
    >>> bool(np.isclose(c, 1000.0 / (np.pi * 0.01 * 1.15e11) * np.log(0.01 / 1e-4)))
    True
    """
    y = _validate.finite_array("y", y, "m")
    l = _validate.positive("l", l, "m")
    Q = _validate.positive("Q", Q, "N")
    b = _validate.in_range("b", b, 0.0, 0.5 * l, "m", lo_open=True, hi_open=True)
    E_star = _validate.positive("E_star", E_star, "Pa")
    k = 1.0 - 2.0 * b / l
    return Q / (math.pi * l * E_star) * -np.log1p(-k * np.minimum((2.0 * y / l) ** 2, 1.0))


def edge_drop(y, l, re):
    r"""Extra drop (m) of an edge radius ``re`` (m) at the ends of a roller of width ``l`` (m).

    .. math:: c_e = r_e - \sqrt{r_e^2 - s^2},\quad s = \max(|y| - (l/2 - r_e), 0)

    Parameters
    ----------
    y : float or array_like
        Axial coordinate from the roller's mid-plane [m].
    l : float
        Roller width [m].
    re : float
        Edge radius [m]; ``0`` for none (zero drop).

    Returns
    -------
    ndarray
        Extra drop ``c_e(y)`` [m], float, the shape of ``y``; at most ``re``.

    Examples
    --------
    >>> float(edge_drop(0.005, 0.01, 0.001)) * 1e3   # mm: the full radius at the end
    1.0
    """
    y = _validate.finite_array("y", y, "m")
    l = _validate.positive("l", l, "m")
    re = _validate.nonnegative("re", re, "m")
    if re <= 0.0:
        return np.zeros_like(y)
    s = np.clip(np.abs(y) - (0.5 * l - re), 0.0, re)
    return re - np.sqrt(re * re - s * s)


@dataclass(frozen=True, kw_only=True)
class RollerProfile:
    """Axial profile of a roller (SI). ``crown`` is ``"none"``, ``"circular"`` (give
    ``crown_radius`` or ``crown_drop``) or ``"logarithmic"`` (designed for ``design_load`` at the
    strip's ``E_star`` and radius; ``crown_drop``, if given, rescales it to that end drop).

    Parameters
    ----------
    width : float
        Roller width ``l`` [m], > 0.
    crown : {"none", "circular", "logarithmic"}
        Crown shape.
    crown_radius : float or None
        Circular crown radius ``Rc`` [m], > ``width / 2``; only for ``crown="circular"``.
    crown_drop : float or None
        Crown drop at the roller end ``y = +-l/2`` [m], > 0; for the circular crown it sets
        ``Rc``, for the logarithmic one it rescales the designed profile to this end drop.
    edge_radius : float
        Edge (corner) radius ``re`` [m], ``0 <= re <= width / 2``; 0 for none.
    misalignment : float
        Tilt ``gamma`` of the roller axis towards the cam [rad], in [-0.1, 0.1]; ``gamma > 0``
        lifts the ``+y`` end.

    Examples
    --------
    >>> RollerProfile(width=0.01, crown="circular", crown_drop=10e-6).Rc   # m
    1.250005
    """

    width: float
    crown: str = "none"
    crown_radius: float | None = None
    crown_drop: float | None = None
    edge_radius: float = 0.0
    misalignment: float = 0.0

    def __post_init__(self):
        _validate.positive("roller_width", self.width, "m")
        if self.crown not in CROWNS:
            raise _validate.fail("crown", self.crown, "", f"must be one of {', '.join(map(repr, CROWNS))}")
        if self.crown_radius is not None and self.crown != "circular":
            raise _validate.fail("crown_radius", self.crown_radius, "m", "is only for crown = 'circular'")
        if self.crown_drop is not None:
            _validate.positive("crown_drop", self.crown_drop, "m")
            if self.crown == "none":
                raise _validate.fail("crown_drop", self.crown_drop, "m", "is not used with crown = 'none'")
        if self.crown == "circular":
            if (self.crown_radius is None) == (self.crown_drop is None):
                raise _validate.fail("crown", "circular", "",
                                     "give exactly one of crown_radius or crown_drop")
            if self.crown_radius is not None:
                _validate.positive("crown_radius", self.crown_radius, "m")
                if self.crown_radius <= 0.5 * self.width:
                    raise _validate.fail("crown_radius", self.crown_radius, "m",
                                         f"must exceed half the roller width {0.5 * self.width:g} m")
        re = _validate.nonnegative("edge_radius", self.edge_radius, "m")
        if re > 0.5 * self.width:
            raise _validate.fail("edge_radius", re, "m",
                                 f"must be <= half the roller width {0.5 * self.width:g} m")
        _validate.in_range("misalignment", self.misalignment, -0.1, 0.1, "rad")

    @property
    def Rc(self) -> float:
        """Circular crown radius (m) from ``crown_radius`` or from the end drop."""
        if self.crown_radius is not None:
            return float(self.crown_radius)
        d, h = float(self.crown_drop), 0.5 * self.width
        return (h * h + d * d) / (2.0 * d)

    def drop(self, y, *, design_load=None, b=None, E_star=None) -> np.ndarray:
        """Drop (m) of the crown plus edge radius plus tilt ``y tan(gamma)`` at ``y`` (m).

        Parameters
        ----------
        y : float or array_like
            Axial coordinate from the roller's mid-plane [m].
        design_load : float, optional
            Design load ``Q`` of the logarithmic crown [N]; logarithmic crown only.
        b : float, optional
            Hertz half-width at the line load ``design_load / width`` [m]; logarithmic crown
            only (capped at ``width / 4``).
        E_star : float, optional
            Contact modulus [Pa]; logarithmic crown only.

        Returns
        -------
        ndarray
            Drop ``c(y)`` [m], float, the shape of ``y``; negative where the tilt brings the
            surface closer.

        Raises
        ------
        InputError
            For the logarithmic crown if ``design_load``, ``b`` or ``E_star`` is missing.
        """
        y = np.asarray(y, float)
        c = edge_drop(y, self.width, self.edge_radius) + y * math.tan(self.misalignment)
        if self.crown == "circular":
            c = c + circular_drop(y, self.Rc)
        elif self.crown == "logarithmic":
            if design_load is None or b is None or E_star is None:
                raise _validate.fail("design_load", design_load, "N",
                                     "the logarithmic crown needs design_load, b and E_star")
            lg = log_drop(y, self.width, design_load, min(b, 0.25 * self.width), E_star)
            if self.crown_drop is not None:
                lg = lg * (self.crown_drop / float(log_drop(0.5 * self.width, self.width, design_load,
                                                            min(b, 0.25 * self.width), E_star)))
            c = c + lg
        return c
