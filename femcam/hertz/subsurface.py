r"""Closed-form subsurface stresses of a Hertz line contact with sliding friction.

McEwen (1949), Smith & Liu (1953), in the ``m, n`` form of Johnson, *Contact Mechanics* (1985),
eqs. 7.20 (normal pressure ``p = p0 sqrt(1 - x^2/a^2)``) and 7.21 (tangential traction
``q = q0 sqrt(1 - x^2/a^2)``, ``q0 = mu p0``, acting on the body in +x).

Symbols
-------
=======  ==========================================================  =====
symbol   meaning                                                     unit
=======  ==========================================================  =====
x, z     position along the surface and depth into the body (z >= 0)  m
a, p0    contact half-width and peak pressure                         m, Pa
mu       signed friction coefficient, ``q0 = mu p0`` (+x if mu > 0)   -
m, n     :math:`m^2, n^2 = \tfrac12[\sqrt{(a^2-x^2+z^2)^2 + 4x^2z^2}   m
         \pm (a^2-x^2+z^2)]`, sgn m = sgn z, sgn n = sgn x
sx, sz   normal stresses, tension positive                            Pa
txz      shear stress                                                 Pa
sy       out-of-plane stress: ``nu (sx + sz)`` plane strain, 0 plane  Pa
         stress
=======  ==========================================================  =====

Johnson 7.20-7.21 with :math:`D = m^2 + n^2` and :math:`G = m^2 - z^2`:

.. math::
    \sigma_x^p = -\tfrac{p_0}{a}\left[m\left(1 + \tfrac{z^2+n^2}{D}\right) - 2z\right],\quad
    \sigma_z^p = -\tfrac{p_0}{a}\, m \tfrac{G}{D},\quad
    \tau_{xz}^p = -\tfrac{p_0}{a}\, n \tfrac{G}{D}

.. math::
    \sigma_x^q = \tfrac{q_0}{a}\left[n\left(2 + \tfrac{G}{D}\right) - 2x\right],\quad
    \sigma_z^q = \tfrac{q_0}{p_0}\tau_{xz}^p,\quad \tau_{xz}^q = \tfrac{q_0}{p_0}\sigma_x^p

(Johnson prints ``m (1 - (z^2+n^2)/D) = m G / D``; the sign of :math:`\tau_{xz}^p` is fixed by
the Flamant kernel, Johnson eq. 2.23, and checked against it in the tests.)

Numerics.  Everything is evaluated in units of ``a`` and ``p0``.  ``m^2`` and ``n^2`` are formed
without cancellation (the larger one from ``(r + |A|)/2``, the smaller from
``m^2 n^2 = x^2 z^2``), ``m - z`` as ``G / (m + z)``, and the ratios ``./D`` are guarded where
``D = 0`` (only at ``z = 0, |x| = a``, where every ratio is multiplied by ``m = n = 0``), so the
field is warning-free at the surface and the contact edges, and equals
:func:`femcam.hertz.surface.surface_stress` at ``z = 0``.  ``a = 0`` (zero load) gives exact zeros.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import _validate
from .._repr import compact_repr
from ..materials import PLANES


def mn(X, Z):
    r"""Johnson's ``m, n`` and ``D = m^2 + n^2`` in units of ``a`` (``X = x/a``, ``Z = z/a >= 0``).

    .. math:: m^2, n^2 = \tfrac12\left[\sqrt{(1-X^2+Z^2)^2 + 4X^2Z^2} \pm (1-X^2+Z^2)\right]

    (Johnson 1985, eq. 7.20 definitions; ``sgn n = sgn X``).

    Parameters
    ----------
    X : float or array_like
        Position along the surface in units of the half-width, ``x / a`` [-].
    Z : float or array_like
        Depth in units of the half-width, ``z / a >= 0`` [-]; broadcasts against ``X``.

    Returns
    -------
    m, n, D : ndarray
        ``m >= 0`` and ``n`` (sign of ``X``) in units of ``a`` [-], and ``D = m^2 + n^2`` in
        units of ``a^2`` [-]; float, the broadcast shape of ``X, Z``.

    Examples
    --------
    >>> [float(v) for v in mn(0.0, 1.0)]
    [1.4142135623730951, 0.0, 2.0]
    """
    X = np.asarray(X, dtype=float)
    Z = np.asarray(Z, dtype=float)
    A = 1.0 - X * X + Z * Z
    XZ = X * Z
    D = np.hypot(A, 2.0 * XZ)                 # = m^2 + n^2 = sqrt(A^2 + 4 X^2 Z^2)
    big = 0.5 * (D + np.abs(A))
    small = np.divide(XZ * XZ, big, out=np.zeros_like(big), where=big > 0.0)  # m^2 n^2 = X^2 Z^2
    m2 = np.where(A >= 0.0, big, small)
    n2 = np.where(A >= 0.0, small, big)
    return np.sqrt(m2), np.sign(X) * np.sqrt(n2), D


def unit_stresses(X, Z, mu=0.0):
    """In-plane stresses ``(sx, sz, txz) / p0`` at ``(X, Z) = (x, z)/a`` for ``q0 = mu p0``.

    Johnson 1985 eqs. 7.20 + 7.21 (see the module docstring).

    Parameters
    ----------
    X : float or array_like
        Position along the surface ``x / a`` [-].
    Z : float or array_like
        Depth ``z / a >= 0`` [-]; broadcasts against ``X``.
    mu : float, optional
        Signed friction coefficient [-], ``q0 = mu p0`` acting on the body in +x if ``mu > 0``.
        Default 0.

    Returns
    -------
    sx, sz, txz : ndarray
        In-plane stresses divided by ``p0`` [-] (tension positive), the broadcast shape.

    Examples
    --------
    >>> [round(float(s), 6) + 0.0 for s in unit_stresses(0.0, 0.786)]   # axis, frictionless
    [-0.185643, -0.786209, 0.0]
    """
    X = _validate.finite_array("X", X, "")
    Z = _validate.nonnegative_array("Z", Z, "")
    return _unit_stresses(X, Z, _validate.finite_array("mu", mu, ""))


def _unit_stresses(X, Z, mu):
    """:func:`unit_stresses` without the input checks (for callers that checked them)."""
    X = np.asarray(X, dtype=float)
    Z = np.asarray(Z, dtype=float)
    m, n, D = mn(X, Z)
    # G = m^2 - z^2 = a^2 - x^2 + n^2: take the form that subtracts the smaller numbers
    G = np.where(1.0 - X * X + Z * Z >= 0.0, 1.0 - X * X + n * n, m * m - Z * Z)
    Dsafe = np.where(D > 0.0, D, 1.0)
    GD = np.where(D > 0.0, G / Dsafe, 0.0)          # bounded; multiplied by m or n (= 0 at D = 0)
    mz = m + Z
    m_minus_z = np.divide(G, mz, out=np.zeros_like(mz), where=mz > 0.0)
    sx_p = -(2.0 * m_minus_z - m * GD)               # -[m (1 + (z^2 + n^2)/D) - 2z]
    sz_p = -m * GD
    txz_p = -n * GD
    sx_q = n * (2.0 + GD) - 2.0 * X
    return sx_p + mu * sx_q, sz_p + mu * txz_p, txz_p + mu * sx_p


@dataclass(frozen=True)
class StressField:
    """Stress components (Pa, tension positive) and derived measures at the requested points.

    ``tau1`` is the principal shear in the x-z plane, ``tresca`` the largest principal-stress
    difference of all three principal stresses (``= 2 x`` maximum shear), ``von_mises`` the
    equivalent stress from all three.

    Parameters
    ----------
    sx, sz : ndarray
        In-plane normal stresses [Pa], along the surface and into the depth.
    txz : ndarray
        In-plane shear stress [Pa].
    sy : ndarray
        Out-of-plane normal stress [Pa] (``nu (sx + sz)`` in plane strain, 0 in plane stress).
        All four share one (broadcast) shape.
    """

    sx: np.ndarray
    sz: np.ndarray
    txz: np.ndarray
    sy: np.ndarray

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)

    @property
    def tau1(self):
        r""":math:`\tau_1 = \sqrt{((\sigma_x - \sigma_z)/2)^2 + \tau_{xz}^2}` (Pa)."""
        return np.hypot(0.5 * (self.sx - self.sz), self.txz)

    def principal(self):
        """The three principal stresses sorted ``s1 >= s2 >= s3`` (Pa), stacked on axis 0.

        Returns
        -------
        ndarray, shape (3, ...)
            ``[s1, s2, s3]`` [Pa], float; the trailing shape is that of the components.
        """
        mid = 0.5 * (self.sx + self.sz)
        t = self.tau1
        return -np.sort(-np.stack(np.broadcast_arrays(mid + t, mid - t, self.sy)), axis=0)

    @property
    def tresca(self):
        """Tresca equivalent stress ``s1 - s3`` (Pa)."""
        mid = 0.5 * (self.sx + self.sz)
        t = self.tau1
        return np.maximum(mid + t, self.sy) - np.minimum(mid - t, self.sy)

    @property
    def von_mises(self):
        r""":math:`\sqrt{\tfrac12[(\sigma_x-\sigma_y)^2 + (\sigma_y-\sigma_z)^2 +
        (\sigma_z-\sigma_x)^2] + 3\tau_{xz}^2}` (Pa)."""
        sx, sy, sz = self.sx, self.sy, self.sz
        return np.sqrt(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2) + 3.0 * self.txz ** 2)


def stress_field(x, z, a, p0, mu=0.0, *, nu=0.3, plane="strain") -> StressField:
    r"""Subsurface stresses (Pa) at ``(x, z)`` (m) for normal load + sliding traction ``mu p``.

    ``x``, ``z``, ``a`` and ``p0`` broadcast.  ``sy = nu (sx + sz)`` in plane strain, 0 in plane
    stress (Johnson 1985 §2.1).

    .. math:: \sigma_{ij}(x, z) = p_0\, \hat\sigma_{ij}(x/a,\ z/a;\ \mu)

    Parameters
    ----------
    x : float or array_like
        Position along the surface [m].
    z : float or array_like
        Depth into the body [m], ``>= 0``.
    a : float or array_like
        Contact half-width [m], ``>= 0`` (``a = 0`` gives exact zeros).
    p0 : float or array_like
        Peak pressure [Pa].
    mu : float, optional
        Signed friction coefficient [-], traction ``mu p`` on the body in +x if ``mu > 0``.
        Default 0.
    nu : float, optional
        Poisson ratio [-] for ``sy``, ``-1 < nu < 0.5``. Default 0.3.
    plane : {"strain", "stress"}, optional
        Plane strain (default) or plane stress.

    Returns
    -------
    StressField
        ``sx, sz, txz, sy`` [Pa], each of the broadcast shape of ``x, z, a, p0``.

    Raises
    ------
    InputError
        ``x`` or ``z`` not finite, ``z < 0``, ``nu`` or ``plane`` out of range.

    Examples
    --------
    >>> f = stress_field(0.0, 0.0, 1e-4, 1e9)
    >>> float(f.sx), float(f.sz), float(f.sy)
    (-1000000000.0, -1000000000.0, -600000000.0)
    """
    x = _validate.finite_array("x", x, "m")
    z = _validate.finite_array("z", z, "m")
    if np.any(z < 0.0):
        raise _validate.fail("z", z[z < 0.0].flat[0], "m", "must be >= 0 (depth into the body)")
    _validate.in_range("nu", nu, -1.0, 0.5, "", lo_open=True, hi_open=True)
    _validate.choice("plane", plane, PLANES)
    a = _validate.nonnegative_array("a", a, "m")
    p0 = _validate.nonnegative_array("p0", p0, "Pa")
    mu = _validate.finite_array("mu", mu, "")
    a_safe = np.where(a > 0.0, a, 1.0)           # a = 0 <=> p0 = 0: 0 * finite = 0, not NaN
    sx, sz, txz = _unit_stresses(x / a_safe, z / a_safe, mu)
    sx, sz, txz = p0 * sx, p0 * sz, p0 * txz
    sy = nu * (sx + sz) if plane == "strain" else np.zeros_like(sx)
    return StressField(sx=sx, sz=sz, txz=txz, sy=sy)
