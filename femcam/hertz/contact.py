r"""Hertz line contact of two parallel cylinders: effective radius, E*, half-width, peak pressure.

Symbols (Johnson, *Contact Mechanics*, 1985, ch. 4 and §7.1; seed 002 eqs. 8-10)
------------------------------------------------------------------------------
=========  ===================================================  =====  ================================
symbol     meaning                                              unit   source
=========  ===================================================  =====  ================================
F          normal contact force (seed 002: ``Fc``)              N      seed 002 eq. 11
length     face width of the contact (seed 002: ``l``)          m
w          load per unit length, ``F / length``                 N/m    Johnson eq. 4.45
R1, R2     radii of curvature; R1 < 0 concave, inf flat         m
R          effective radius, ``1/R = 1/R1 + 1/R2``              m      Johnson eq. 4.44
E_star     contact modulus, ``1/E* = sum (1-nu_i^2)/E_i``       Pa     Johnson eq. 4.22; 002 eq. 10
a          contact HALF-width (seed 002 eq. 10 calls it alpha)  m      Johnson eq. 4.45; 002 eq. 10
p0         peak pressure (seed 002: ``pmax``)                   Pa     Johnson eq. 4.45; 002 eq. 9
mu         coefficient of (full-sliding) friction               -      seed 002 eq. 8
fmax       peak tangential traction ``mu p0``                   Pa     seed 002 eq. 8
=========  ===================================================  =====  ================================

Sign conventions used in the whole :mod:`femcam.hertz` package: tension positive, ``x`` along
the surface, ``z >= 0`` depth into the body under consideration, the pressure ``p(x) >= 0`` pushes
into it (so ``sigma_z(x, 0) = -p``) and the friction traction ``q(x) = mu p(x)`` exerted **on the
body** acts in **+x** (``tau_xz(x, 0) = -q``, Johnson §2.1): the other body slides in +x over it.
The tensile surface peak ``sigma_x = +2 mu p0`` is then at ``x = -a`` (the trailing edge of the
traction).  For the opposite sliding direction mirror ``x -> -x`` (``sigma``'s even,
``tau_xz`` odd) or pass ``direction=-1``.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np

from .. import _validate
from ..errors import HertzValidityError
from ..materials import PLANES, Material, effective_modulus
from .maxima import ScaledMaximum, max_orthogonal_shear, max_shear, max_von_mises
from .subsurface import stress_field
from .surface import hertz_pressure, surface_stress

#: a / (smallest radius) above which the half-space idealisation of Hertz theory is flagged.
VALIDITY_RATIO = 0.1


class HertzValidityWarning(UserWarning):
    """The contact half-width is not small against the radii (``a / R_min > VALIDITY_RATIO``)."""


def effective_radius(R1, R2):
    r"""Effective radius of two cylinders (m): ``inf`` for flat on flat, ``< 0`` if non-Hertzian;
    the exactly conformal ``R1 = -R2`` (finite) is refused. Validity is judged on the curvature
    ``1/R <= 0`` by :class:`LineContact`.

    .. math:: \frac{1}{R} = \frac{1}{R_1} + \frac{1}{R_2}

    A concave surface has a negative radius, a flat one an infinite radius (Johnson 1985 eq. 4.44;
    the denominator of seed 002 eq. 10).

    Parameters
    ----------
    R1, R2 : float or array_like
        Radii of curvature [m], broadcast against each other; ``< 0`` concave, ``inf`` flat.

    Returns
    -------
    ndarray
        Effective radius ``R`` [m], float, the broadcast shape (``inf`` for flat on flat).

    Raises
    ------
    HertzValidityError
        Equal and opposite finite radii (a conformal contact, ``1/R = 0``).
    InputError
        A radius that is zero, NaN or not a number; shapes that do not broadcast.

    Examples
    --------
    >>> float(effective_radius(0.01, 0.01))
    0.005
    >>> round(float(effective_radius(-0.03, 0.01)), 12)
    0.015
    """
    R1, R2 = _validate.broadcast(R1=_validate.radius_array("R1", R1), R2=_validate.radius_array("R2", R2))
    conformal = np.isfinite(R1) & (R1 == -R2)
    if conformal.any():   # 1/R = 0 of two curved surfaces: no Hertz contact (flat on flat stays inf)
        i = int(np.flatnonzero(conformal)[0])
        raise HertzValidityError(f"R1 = {R1.flat[i]:g} m, R2 = {R2.flat[i]:g} m: equal and opposite radii "
                                 "are a conformal contact (1/R = 0) with no Hertz answer")
    return _effective_radius(R1, R2)


def _effective_radius(R1, R2):
    """:func:`effective_radius` without the input checks."""
    R1 = np.asarray(R1, dtype=float)
    R2 = np.asarray(R2, dtype=float)
    with np.errstate(divide="ignore"):
        inv = 1.0 / R1 + 1.0 / R2
        return 1.0 / inv


def half_width(w, R, E_star):
    r"""Contact half-width ``a`` (m) of a Hertz line contact.

    .. math:: a = \sqrt{\frac{4 w R}{\pi E^*}}

    (Johnson 1985 eq. 4.45; seed 002 eq. 10 with ``w = Fc/l``).

    Parameters
    ----------
    w : float or array_like
        Load per unit length [N/m], ``>= 0``.
    R : float or array_like
        Effective radius [m], ``> 0``.
    E_star : float or array_like
        Contact modulus ``E*`` [Pa].

    Returns
    -------
    ndarray
        Half-width ``a`` [m], float, the broadcast shape of ``w, R, E_star``.

    Examples
    --------
    >>> round(float(half_width(1.5e5, 0.005, 115.3846e9)) * 1e6, 2)   # um
    90.97
    """
    w, R, E_star = _validate.broadcast(w=_validate.nonnegative_array("w", w, "N/m"),
                                       R=_validate.positive_array("R", R, "m"),
                                       E_star=_validate.positive_array("E_star", E_star, "Pa"))
    return _half_width(w, R, E_star)


def _half_width(w, R, E_star):
    """:func:`half_width` without the input checks."""
    return np.sqrt(4.0 * np.asarray(w, dtype=float) * R / (np.pi * E_star))


def peak_pressure(w, a):
    r"""Peak (maximum) contact pressure ``p0`` (Pa); exactly 0 when ``w = 0``.

    .. math:: p_0 = \frac{2 w}{\pi a} = \frac{2 F}{\pi a l} = \sqrt{\frac{w E^*}{\pi R}}

    (Johnson 1985 eq. 4.45; seed 002 eq. 9).

    Parameters
    ----------
    w : float or array_like
        Load per unit length [N/m], ``>= 0``.
    a : float or array_like
        Contact half-width [m], ``>= 0``; broadcasts against ``w``.

    Returns
    -------
    ndarray
        Peak pressure ``p0`` [Pa], float, the broadcast shape (0 where ``a = 0``).

    Examples
    --------
    >>> round(float(peak_pressure(1.5e5, 90.97e-6)) / 1e6, 1)   # MPa
    1049.7
    """
    _validate.nonnegative_array("w", w, "N/m")
    _validate.nonnegative_array("a", a, "m")
    return _peak_pressure(w, a)


def _peak_pressure(w, a):
    """:func:`peak_pressure` without the input checks."""
    w = np.asarray(w, dtype=float)
    a = np.asarray(a, dtype=float)
    safe = np.where(a > 0.0, a, 1.0)  # w = 0 <=> a = 0: p0 = 0, not 0/0
    return np.where(a > 0.0, 2.0 * w / (np.pi * safe), 0.0)


def _scalar(x):
    """0-d arrays -> numpy scalars so scalar input gives scalar output."""
    x = np.asarray(x)
    return x[()] if x.ndim == 0 else x


def _broadcast(names: str, *arrays) -> tuple:
    """The broadcast shape of ``arrays``, or an :class:`InputError` naming ``names`` and the
    shapes (instead of numpy's broadcasting traceback)."""
    try:
        return np.broadcast_shapes(*(np.shape(a) for a in arrays))
    except ValueError:
        shapes = ", ".join(str(np.shape(a)) for a in arrays)
        raise _validate.fail(names, f"arrays of shapes {shapes}", "",
                             "must broadcast against each other (one value, or one per load case)") from None


def _radius(name, value):
    if value is None or isinstance(value, bool):
        raise _validate.fail(name, value, "m", "must be a number (negative = concave, inf = flat)")
    try:
        arr = np.asarray(value, dtype=float) if not isinstance(value, str | bytes) else None
    except (TypeError, ValueError):
        arr = None
    if arr is None or np.any(np.isnan(arr)):
        bad = value if arr is None else arr[np.isnan(arr)].flat[0]
        raise _validate.fail(name, bad, "m", "must be a number (negative = concave, inf = flat)")
    if np.any(arr == 0.0):
        raise _validate.fail(name, 0.0, "m", "must be nonzero (negative = concave, inf = flat)")
    return arr


@dataclass(frozen=True, kw_only=True)
class LineContact:
    r"""Hertz line contact of a cam (radius ``R1``) and a roller (radius ``R2``).

    ``F``, ``R1`` and ``R2`` broadcast against each other (one entry per cam angle, say), so every
    derived attribute has the broadcast shape; scalar input gives scalar output.

    Parameters
    ----------
    F : float or array_like
        Normal contact force [N], ``>= 0``.  ``F = 0`` gives ``a = p0 = 0`` and zero stresses.
        A negative force is an :class:`~femcam.errors.InputError`: lift-off is decided upstream
        (:mod:`femcam.loads` flags it), this module only takes a contact-force magnitude.
    length : float
        Face width ``l`` [m], ``> 0``.
    R1, R2 : float or array_like
        Radii of curvature [m] of cam and roller, nonzero; ``R1 < 0``: concave cam; ``inf``: flat.
    cam, roller : Material
        :class:`~femcam.materials.Material` of body 1 and body 2.
    mu : float, optional
        Friction coefficient [-] (full sliding, ``q = mu p``), ``>= 0``. Default 0.
    plane : {"strain", "stress"}, optional
        ``"strain"`` (long cylinders, default) or ``"stress"`` (thin discs), see ``E_star``.
    direction : {1, -1}, optional
        ``+1`` (default) traction on the analysed body in +x, ``-1`` in -x.

    Attributes
    ----------
    R : float or ndarray
        Effective radius [m], the broadcast shape of ``F, R1, R2``.
    E_star : float
        Contact modulus ``E*`` [Pa].
    w : float or ndarray
        Load per unit length ``F / length`` [N/m].
    a : float or ndarray
        Contact half-width [m].
    p0 : float or ndarray
        Peak pressure [Pa].
    fmax : float or ndarray
        Peak tangential traction ``mu p0`` [Pa].
    a_over_R : float or ndarray
        ``a / R`` [-].
    a_over_rmin : float or ndarray
        ``a / min(R, |R1|, |R2|)`` [-] -- the ratio the half-space idealisation needs small.
    valid : bool or ndarray of bool
        ``a_over_rmin <= VALIDITY_RATIO`` (a :class:`HertzValidityWarning` is issued otherwise).

    Raises
    ------
    HertzValidityError
        ``1/R <= 0`` (conformal, flat-on-flat, or concave cam with ``|R1| <= R2``).
    InputError
        A negative or non-finite ``F``, a zero or NaN radius, shapes that do not broadcast, or
        an out-of-range ``length``, ``mu``, ``plane``, ``direction`` or material.

    Examples
    --------
    >>> from femcam.materials import STEEL
    >>> hc = LineContact(F=1500.0, length=0.01, R1=0.01, R2=0.01, cam=STEEL, roller=STEEL)
    >>> round(float(hc.a) * 1e6, 2), round(float(hc.p0) / 1e6, 1)   # um, MPa
    (90.97, 1049.7)
    """

    F: object
    length: float
    R1: object
    R2: object
    cam: Material
    roller: Material
    mu: float = 0.0
    plane: str = "strain"
    direction: int = 1

    R: object = field(init=False, repr=False)
    E_star: float = field(init=False, repr=False)
    w: object = field(init=False, repr=False)
    a: object = field(init=False, repr=False)
    p0: object = field(init=False, repr=False)
    fmax: object = field(init=False, repr=False)
    a_over_R: object = field(init=False, repr=False)
    a_over_rmin: object = field(init=False, repr=False)
    valid: object = field(init=False, repr=False)

    def __post_init__(self):
        def put(name, value):
            object.__setattr__(self, name, value)

        F = _validate.finite_array("F", self.F, "N")
        if np.any(F < 0.0):
            raise _validate.fail("F", F[F < 0.0].flat[0], "N",
                                 "must be >= 0 (a negative contact force is lift-off; see femcam.loads)")
        length = _validate.positive("length", self.length, "m")
        R1 = _radius("R1", self.R1)
        R2 = _radius("R2", self.R2)
        _broadcast("F, R1, R2", F, R1, R2)
        for name in ("cam", "roller"):
            if not isinstance(getattr(self, name), Material):
                raise _validate.fail(name, getattr(self, name), "", "must be a femcam.materials.Material")
        mu = _validate.nonnegative("mu", self.mu, "")
        _validate.choice("plane", self.plane, PLANES)
        if self.direction not in (1, -1):
            raise _validate.fail("direction", self.direction, "", "must be +1 or -1")

        inv_R = 1.0 / R1 + 1.0 / R2                       # 1/inf = 0: flat surfaces
        if np.any(inv_R <= 0.0):
            i = np.argwhere(np.broadcast_to(inv_R, np.broadcast_shapes(R1.shape, R2.shape)) <= 0.0)[0]
            r1 = np.broadcast_to(R1, inv_R.shape)[tuple(i)]
            r2 = np.broadcast_to(R2, inv_R.shape)[tuple(i)]
            n_bad = int(np.count_nonzero(inv_R <= 0.0))
            where = f" (first of {n_bad} at index {tuple(int(k) for k in i)})" if inv_R.ndim else ""
            raise HertzValidityError(
                f"Hertz line contact needs 1/R = 1/R1 + 1/R2 > 0, got R1 = {r1 * 1e3:g} mm, "
                f"R2 = {r2 * 1e3:g} mm{where}: conformal, flat-on-flat or concave-over-roller "
                "(|R1| <= R2 with R1 < 0) contact is outside Hertz theory")
        R = 1.0 / inv_R
        E_star = effective_modulus(self.cam, self.roller, self.plane)
        w = F / length
        a = _half_width(w, R, E_star)  # checked above
        p0 = _peak_pressure(w, a)
        with np.errstate(divide="ignore"):
            inv_rmin = np.maximum(inv_R, np.maximum(np.abs(1.0 / R1), np.abs(1.0 / R2)))
        a_over_rmin = a * inv_rmin
        valid = a_over_rmin <= VALIDITY_RATIO
        if not np.all(valid):
            warnings.warn(
                f"Hertz half-space idealisation strained: a / min(R, |R1|, |R2|) = "
                f"{float(np.max(a_over_rmin)):.3g} > {VALIDITY_RATIO:g} "
                f"({int(np.size(valid) - np.count_nonzero(valid))} case(s)); see LineContact.valid",
                HertzValidityWarning, stacklevel=3)

        put("F", _scalar(F))
        put("length", length)
        put("R1", _scalar(R1))
        put("R2", _scalar(R2))
        put("mu", mu)
        put("R", _scalar(R))
        put("E_star", float(E_star))
        put("w", _scalar(w))
        put("a", _scalar(a))
        put("p0", _scalar(p0))
        put("fmax", _scalar(mu * p0))                    # seed 002 eq. 8
        put("a_over_R", _scalar(a * inv_R))
        put("a_over_rmin", _scalar(a_over_rmin))
        put("valid", _scalar(valid))

    # -- fields -------------------------------------------------------------------------------
    @property
    def shape(self) -> tuple:
        """Broadcast shape of the load cases (``()`` for a single contact)."""
        return np.shape(self.a)

    def pressure(self, x):
        """Hertz pressure ``p(x) >= 0`` (Pa); ``x`` (m) broadcasts against :attr:`shape`.

        Parameters
        ----------
        x : float or array_like
            Position along the surface [m].

        Returns
        -------
        float or ndarray
            Pressure [Pa], the broadcast shape of ``x`` and the load cases.
        """
        x = _validate.finite_array("x", x, "m")
        _broadcast("x and the load cases", x, self.a)
        return _scalar(hertz_pressure(x, self.a, self.p0))

    def surface_stress(self, x):
        """``(sx, sz, txz)`` (Pa) on ``z = 0`` for all ``x`` (m); seed 002 eqs. 5-7.

        Parameters
        ----------
        x : float or array_like
            Position along the surface [m]; broadcasts against :attr:`shape`.

        Returns
        -------
        sx, sz, txz : float or ndarray
            Surface stresses [Pa] (tension positive), the broadcast shape.
        """
        x = _validate.finite_array("x", x, "m")
        _broadcast("x and the load cases", x, self.a)
        return tuple(_scalar(s) for s in surface_stress(x, self.a, self.p0, self.direction * self.mu))

    def stress(self, x, z, *, body: str = "cam"):
        """Subsurface :class:`~femcam.hertz.subsurface.StressField` at ``(x, z)`` (m), ``z >= 0``.

        ``body`` ("cam" or "roller") picks the Poisson ratio used for the out-of-plane stress
        ``sy = nu (sx + sz)`` in plane strain (``sy = 0`` in plane stress); the in-plane
        half-space field is the same in both bodies.

        Parameters
        ----------
        x : float or array_like
            Position along the surface [m].
        z : float or array_like
            Depth into the body [m], ``>= 0``; ``x``, ``z`` and :attr:`shape` broadcast.
        body : {"cam", "roller"}, optional
            Body whose Poisson ratio sets ``sy``. Default ``"cam"``.

        Returns
        -------
        StressField
            ``sx, sz, txz, sy`` [Pa], each of the broadcast shape.
        """
        _validate.choice("body", body, ("cam", "roller"))
        x = _validate.finite_array("x", x, "m")
        z = _validate.finite_array("z", z, "m")
        _broadcast("x, z and the load cases", x, z, self.a)
        nu = (self.cam if body == "cam" else self.roller).nu
        return stress_field(x, z, self.a, self.p0, self.direction * self.mu, nu=nu, plane=self.plane)

    # -- maxima (value in Pa, location in m; vectorised over the load cases) --------------------
    def _scaled(self, m):
        s = -1.0 if self.direction == -1 else 1.0
        return ScaledMaximum(value=_scalar(m.value * np.asarray(self.p0)),
                             x=_scalar(s * m.x * np.asarray(self.a)),
                             z=_scalar(m.z * np.asarray(self.a)), unit=m)

    def max_shear(self):
        """Maximum in-plane principal shear ``tau1`` (Pa) and its location (m).

        Returns
        -------
        ScaledMaximum
            ``value`` [Pa] and ``x``, ``z`` [m], one per load case.
        """
        return self._scaled(max_shear(self.mu))

    def max_von_mises(self, body: str = "cam"):
        """Maximum von Mises stress (Pa) in ``body`` and its location (m).

        Parameters
        ----------
        body : {"cam", "roller"}, optional
            Body whose Poisson ratio sets ``sy``. Default ``"cam"``.

        Returns
        -------
        ScaledMaximum
            ``value`` [Pa] and ``x``, ``z`` [m], one per load case.
        """
        _validate.choice("body", body, ("cam", "roller"))
        nu = (self.cam if body == "cam" else self.roller).nu
        return self._scaled(max_von_mises(self.mu, nu, self.plane))

    def max_orthogonal_shear(self):
        """Maximum ``|tau_xz|`` (Pa) and its location (m).

        Returns
        -------
        ScaledMaximum
            ``value`` [Pa] and ``x``, ``z`` [m], one per load case.
        """
        return self._scaled(max_orthogonal_shear(self.mu))
