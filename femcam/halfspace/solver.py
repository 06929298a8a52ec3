r"""Normal contact of two elastic half-spaces on a grid: DC-FFT plus conjugate gradients.

Symbols (Johnson 1985 §3.2, §5.1; Polonsky & Keer 1999; Liu, Wang & Liu 2000)
----------------------------------------------------------------------------------
=========  ===================================================  =====  ================================
symbol     meaning                                              unit   source
=========  ===================================================  =====  ================================
h0         initial gap (profile), ``h0 >= 0`` somewhere         m
u          combined elastic normal displacement ``K * p``       m      Johnson eq. 3.22
alpha      rigid-body approach of the two bodies                m
g          gap after loading, ``g = h0 + u - alpha``            m
p          contact pressure on the cells, ``p >= 0``            Pa
W          total normal load, ``W = dx dy sum p``               N
=========  ===================================================  =====  ================================

The discrete contact problem (Polonsky & Keer 1999) is: find ``p >= 0`` and ``alpha`` with

.. math:: g = h_0 + K * p - \alpha \ge 0,\qquad p\,g = 0,\qquad dx\,dy \sum p = W.

:class:`HalfSpace` holds the FFT of the DC-FFT kernel of one grid (Liu, Wang & Liu 2000), so
that many solves on the same grid (a sweep over cam angles) pay for it once; :meth:`HalfSpace.solve`
is Polonsky & Keer's (1999) conjugate-gradient scheme, warm-started from any previous pressure.
The convolution ``K * p`` costs two real FFTs of the ``2 nx`` x ``2 ny`` array per product.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .. import _validate
from .._repr import compact_repr
from .influence import dcfft_kernel


@dataclass(frozen=True, kw_only=True)
class ContactSolution:
    """Result of :meth:`HalfSpace.solve` (SI units; pickles: arrays and numbers only).

    ``p`` is the ``nx`` x ``ny`` cell pressure (Pa), ``alpha`` the approach (m), ``u`` the
    combined displacement (m). ``converged`` is True when the relative pressure change
    ``dx dy sum|p_k - p_(k-1)| / W`` fell below ``tol`` within ``max_iter``; ``residual`` is that
    last change, ``gap_residual`` the largest ``|g|`` on loaded cells over the largest combined
    displacement ``max u`` (the complementarity error relative to the deformation; finite for
    any ``alpha``, including 0, and independent of the free level of ``h0``) and ``history`` the
    change per iteration.

    Attributes
    ----------
    p : ndarray, shape (nx, ny), float
        Cell pressure [Pa], ``>= 0``.
    alpha : float
        Rigid-body approach of the two bodies [m].
    u : ndarray, shape (nx, ny), float
        Combined elastic normal displacement ``K * p`` [m].
    iterations : int
        Conjugate-gradient iterations done [-].
    residual : float
        Last relative pressure change ``dx dy sum|p_k - p_(k-1)| / W`` [-].
    gap_residual : float
        Largest ``|h0 + u - alpha|`` on loaded cells divided by ``max u``, the largest combined
        elastic displacement (> 0 for any load ``W > 0``; the Hertz approach for a point contact
        whose ``h0`` is 0 at the first point of contact) [-].
    converged : bool
        ``residual < tol`` within ``max_iter``.
    history : ndarray, shape (iterations,), float
        Relative pressure change per iteration [-].
    message : str
        One line saying whether and how it converged.
    """

    p: np.ndarray
    alpha: float
    u: np.ndarray = field(repr=False)
    iterations: int
    residual: float
    gap_residual: float
    converged: bool
    history: np.ndarray = field(repr=False)
    message: str = ""

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)



class HalfSpace:
    """DC-FFT influence of one grid: ``nx`` x ``ny`` cells of ``dx`` x ``dy`` (m), modulus
    ``E_star`` (Pa). Build once, solve many times.

    Parameters
    ----------
    nx, ny : int
        Cells in the rolling (``x``) and axial (``y``) directions [-], ``>= 1``.
    dx, dy : float
        Cell sides [m], > 0.
    E_star : float
        Contact modulus ``1/E* = sum (1 - nu_i^2)/E_i`` [Pa], > 0.

    Attributes
    ----------
    kernel : ndarray, shape (2 nx, 2 ny), float
        DC-FFT influence array in wrap-around order [m/Pa] (:func:`dcfft_kernel`).

    Examples
    --------
    >>> hs = HalfSpace(nx=8, ny=8, dx=1e-5, dy=1e-5, E_star=1e11)
    >>> p = np.zeros((8, 8)); p[3, 3] = 1e9
    >>> bool(np.isclose(hs.displacement(p)[3, 3], 1e9 * hs.kernel[0, 0]))
    True
    """

    def __init__(self, *, nx: int, ny: int, dx: float, dy: float, E_star: float):
        self.nx = _validate.integer("nx", nx, 1, "cells")
        self.ny = _validate.integer("ny", ny, 1, "cells")
        self.dx = _validate.positive("dx", dx, "m")
        self.dy = _validate.positive("dy", dy, "m")
        self.E_star = _validate.positive("E_star", E_star, "Pa")
        self.kernel = dcfft_kernel(nx, ny, self.dx, self.dy, self.E_star)
        import scipy.fft as sfft  # lazy: scipy.fft, ~0.05 s to import

        self._Kf = sfft.rfft2(self.kernel)
        self._pad = np.zeros((2 * self.nx, 2 * self.ny))

    def displacement(self, p) -> np.ndarray:
        """Combined normal displacement ``u = K * p`` (m) on the ``nx`` x ``ny`` grid (DC-FFT).

        Parameters
        ----------
        p : array_like, shape (nx, ny)
            Cell pressure [Pa].

        Returns
        -------
        ndarray, shape (nx, ny), float
            Combined normal displacement of both bodies [m] (a view into a new array).
        """
        # (a pruned transform that skips the zero rows measured no faster: strided column FFTs)
        import scipy.fft as sfft  # lazy: scipy.fft, ~0.05 s to import (cached after the first)

        self._pad[: self.nx, : self.ny] = p
        full = sfft.irfft2(sfft.rfft2(self._pad) * self._Kf, s=self._pad.shape)
        return full[: self.nx, : self.ny]

    def solve(self, h0, W: float, *, p0=None, tol: float = 1e-6, max_iter: int = 500) -> ContactSolution:
        """Polonsky & Keer (1999) conjugate-gradient solution of the discrete contact problem.

        Parameters
        ----------
        h0 : (nx, ny) array
            Initial gap (m); its level is free (only differences matter, ``alpha`` absorbs it).
        W : float
            Total normal load (N), > 0.
        p0 : (nx, ny) array, optional
            Starting pressure (Pa), e.g. the previous angle's solution (warm start); it is
            rescaled to the load ``W``. Default: uniform over the cells where ``h0`` is below its
            median.
        tol : float
            Stop when ``dx dy sum|p_k - p_(k-1)| / W < tol``.
        max_iter : int
            Iteration cap; not converging is reported (``converged=False``), not raised.

        Returns
        -------
        ContactSolution
            Pressure [Pa], approach [m], displacement [m] and convergence diagnostics.
        """
        h0 = _validate.finite_array("h0", h0, "m")
        if h0.shape != (self.nx, self.ny):
            raise _validate.fail("h0", f"array of shape {h0.shape}", "",
                                 f"must have shape {(self.nx, self.ny)}")
        W = _validate.positive("W", W, "N")
        tol = _validate.positive("tol", tol)
        dA = self.dx * self.dy
        p = self._start(h0, W, p0)
        G_old, delta = 1.0, 0.0
        t = np.zeros_like(p)
        hist = []
        for _ in range(int(max_iter)):
            u = self.displacement(p)
            g = h0 + u
            S = p > 0
            g_bar = g[S].mean()
            g = g - g_bar
            G = float(np.sum(g[S] ** 2))
            t = np.where(S, g + (delta * G / G_old) * t, 0.0)
            G_old = G if G > 0 else 1.0
            r = self.displacement(t)
            r = r - r[S].mean()
            rt = float(np.sum(r[S] * t[S]))
            tau = float(np.sum(g[S] * t[S])) / rt if rt != 0 else 0.0
            p_old = p
            p = np.where(S, p - tau * t, 0.0)
            p[p < 0] = 0.0
            overlap = (p == 0) & (g < 0)
            if np.any(overlap):
                delta = 0.0
                p[overlap] -= tau * g[overlap]
            else:
                delta = 1.0
            p *= W / (dA * p.sum())
            eps = dA * float(np.abs(p - p_old).sum()) / W
            hist.append(eps)
            if eps < tol:
                break
        u = self.displacement(p)
        S = p > 0
        alpha = float((h0 + u)[S].mean())
        # over max u, not alpha: alpha carries the free level of h0 and may be 0 (u > 0 for W > 0)
        gres = float(np.abs(h0 + u - alpha)[S].max() / np.max(u))
        conv = hist[-1] < tol
        msg = (f"converged in {len(hist)} iterations" if conv else
               f"not converged: pressure change {hist[-1]:.2e} > tol {tol:g} after {len(hist)} iterations")
        return ContactSolution(p=p, alpha=alpha, u=u, iterations=len(hist), residual=hist[-1],
                               gap_residual=gres, converged=conv, history=np.asarray(hist), message=msg)

    def _start(self, h0, W, p0):
        dA = self.dx * self.dy
        if p0 is not None:
            p = np.clip(_validate.finite_array("p0", p0, "Pa"), 0.0, None)
            if p.shape == h0.shape and p.sum() > 0:
                return p * (W / (dA * p.sum()))
        p = (h0 <= np.median(h0)).astype(float)
        return p * (W / (dA * p.sum()))
