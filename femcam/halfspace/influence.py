r"""Influence coefficients of the elastic half-space: uniform pressure on a rectangular cell.

Symbols (Johnson, *Contact Mechanics*, 1985, §3.2; Love 1929)
---------------------------------------------------------------
=========  ===================================================  =====  ================================
symbol     meaning                                              unit   source
=========  ===================================================  =====  ================================
x          rolling direction (across the contact)               m
y          axial direction (along the roller axis)              m
dx, dy     cell sides (the cell is ``dx`` by ``dy``)            m
E_star     contact modulus, ``1/E* = sum (1-nu_i^2)/E_i``       Pa     Johnson eq. 4.22
K          normal surface displacement of both bodies per unit  m/Pa   Johnson eq. 3.25; Love 1929
           pressure on one cell (combined compliance)
=========  ===================================================  =====  ================================

The normal displacement of a half-space under a point force ``P`` is ``(1 - nu^2) P / (pi E r)``
(Boussinesq; Johnson eq. 3.22); both bodies together approach by ``P / (pi E* r)``. Integrating
over a cell of uniform pressure gives Love's (1929) closed form, written here with the primitive

.. math:: G(u, v) = \int_0^u\!\int_0^v \frac{ds\,dt}{\sqrt{s^2 + t^2}}
          = u\,\operatorname{asinh}\frac{v}{u} + v\,\operatorname{asinh}\frac{u}{v}
          \quad (u, v > 0),

odd in ``u`` and in ``v``, so that

.. math:: K(x, y) = \frac{1}{\pi E^*}\big[G(x + \tfrac{dx}{2}, y + \tfrac{dy}{2})
          - G(x + \tfrac{dx}{2}, y - \tfrac{dy}{2}) - G(x - \tfrac{dx}{2}, y + \tfrac{dy}{2})
          + G(x - \tfrac{dx}{2}, y - \tfrac{dy}{2})\big].

:func:`dcfft_kernel` lays ``K`` out on the doubled ``2 nx`` x ``2 ny`` grid of the discrete
convolution - fast Fourier transform method (DC-FFT, Liu, Wang & Liu 2000): offsets
``0 .. n-1`` first, a zero at index ``n``, then ``-(n-1) .. -1``, so that the circular convolution
with the zero-padded pressure is the exact linear (aperiodic) convolution on the ``nx`` x ``ny``
grid.
"""

from __future__ import annotations

import numpy as np

from .. import _validate


def _G(u, v):
    """Primitive of 1/r over [0, u] x [0, v], odd in u and v (0 on the axes)."""
    au, av = np.abs(u), np.abs(v)
    with np.errstate(divide="ignore", invalid="ignore"):
        g = (np.where(au > 0, au * np.arcsinh(av / np.where(au > 0, au, 1.0)), 0.0)
             + np.where(av > 0, av * np.arcsinh(au / np.where(av > 0, av, 1.0)), 0.0))
    return np.sign(u) * np.sign(v) * g


def cell_influence(x, y, dx, dy, E_star):
    r"""Combined normal displacement (m) at ``(x, y)`` of both bodies per unit pressure (Pa)
    uniform on the cell ``|x| <= dx/2, |y| <= dy/2`` (Love 1929; Johnson 1985 §3.2).

    .. math:: K(x, y) = \frac{1}{\pi E^*}\sum_{\pm\pm} \pm G(x \pm \tfrac{dx}{2}, y \pm \tfrac{dy}{2})

    At the centre of a square cell ``K = 4 dx asinh(1) / (pi E*)`` (``2 dx ln(1 + sqrt 2)``
    over ``pi E*``, Johnson eq. 3.25 with ``a = b = dx/2``).

    Parameters
    ----------
    x, y : float or array_like
        Point relative to the cell centre, rolling and axial [m] (broadcast together).
    dx, dy : float
        Cell sides [m], > 0.
    E_star : float
        Contact modulus [Pa], > 0.

    Returns
    -------
    ndarray
        Influence coefficient ``K`` [m/Pa], float, the broadcast shape of ``x`` and ``y``.

    Examples
    --------
    >>> K = cell_influence(0.0, 0.0, 1.0, 1.0, 1.0)
    >>> round(float(K * np.pi / (4.0 * np.arcsinh(1.0))), 12)
    1.0
    """
    dx = _validate.positive("dx", dx, "m")
    dy = _validate.positive("dy", dy, "m")
    E_star = _validate.positive("E_star", E_star, "Pa")
    x = _validate.finite_array("x", x, "m")
    y = _validate.finite_array("y", y, "m")
    hx, hy = 0.5 * dx, 0.5 * dy
    s = _G(x + hx, y + hy) - _G(x + hx, y - hy) - _G(x - hx, y + hy) + _G(x - hx, y - hy)
    return s / (np.pi * E_star)


def dcfft_kernel(nx: int, ny: int, dx: float, dy: float, E_star: float) -> np.ndarray:
    """The ``2 nx`` x ``2 ny`` wrap-around influence array of DC-FFT (Liu, Wang & Liu 2000).

    Returns the real array ``K[i, j]`` (m/Pa) for cell offsets ``i, j`` in wrap-around order
    (see the module docstring); its real FFT is what :class:`~femcam.halfspace.solver.HalfSpace`
    caches.

    Parameters
    ----------
    nx, ny : int
        Cells of the grid in the rolling and axial directions [-], ``>= 1``.
    dx, dy : float
        Cell sides [m], > 0.
    E_star : float
        Contact modulus [Pa], > 0.

    Returns
    -------
    ndarray, shape (2 nx, 2 ny), float
        Influence coefficients [m/Pa] in wrap-around order; row ``nx`` and column ``ny`` are 0.

    Examples
    --------
    >>> K = dcfft_kernel(4, 2, 1.0, 1.0, 1.0)
    >>> K.shape, bool(K[4, 0] == 0.0), bool(np.isclose(K[1, 0], K[-1, 0]))
    ((8, 4), True, True)
    """
    for name, n in (("nx", nx), ("ny", ny)):
        if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < 1:
            raise _validate.fail(name, n, "cells", "must be an integer >= 1")
    dx = _validate.positive("dx", dx, "m")
    dy = _validate.positive("dy", dy, "m")
    ix = np.concatenate([np.arange(nx), [0], -np.arange(nx - 1, 0, -1)]).astype(float)
    iy = np.concatenate([np.arange(ny), [0], -np.arange(ny - 1, 0, -1)]).astype(float)
    K = cell_influence(ix[:, None] * dx, iy[None, :] * dy, dx, dy, E_star)
    K[nx, :] = 0.0
    K[:, ny] = 0.0
    return K
