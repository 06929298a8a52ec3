r"""Finite-length cam-roller contact at each cam angle: the half-space strip.

Symbols (Johnson 1985 §4.3, §5.4; Lundberg 1939; Polonsky & Keer 1999)
--------------------------------------------------------------------------
=========  ===================================================  =====  ================================
symbol     meaning                                              unit   source
=========  ===================================================  =====  ================================
F          normal contact force (``Scene.analyse().Fc``)         N      seed 002 eq. 11
R          relative radius in the rolling direction,            m      Johnson eq. 4.44
           ``1/R = 1/rho + 1/Rr``
L          contact length, ``min(roller width, cam face)``      m
w(y)       slice load per unit length, ``int p dx``             N/m
b          2D Hertz half-width at ``w = F / L``                 m      Johnson eq. 4.45
=========  ===================================================  =====  ================================

The strip ``|x| <= X, |y| <= L/2`` (x rolling, y axial, both mid-planes centred) is divided into
``nx`` x ``ny`` cells; the initial gap is ``x^2 / 2R + c(y)`` with the roller drop ``c`` of
:class:`~femcam.halfspace.crown.RollerProfile`. Pressure outside ``|y| <= L/2`` is zero: the
shorter body ends there. Both bodies are half-spaces, so a free end of the shorter body is
modelled as if the material continued (the free-end error, see ``docs/halfspace.md``).

The half-extent ``X`` is taken from a geometric ladder ``X_k = X_0 1.25^k`` so that a sweep
reuses a handful of kernels (the kernel FFT of :class:`~femcam.halfspace.solver.HalfSpace` is
cached per rung); if pressure reaches the ``x`` border the strip is re-solved on the next rung.

The most loaded slice (``w_max``, ``y_wmax``) is the largest load per unit length averaged over
an axial window of the contact width ``2b`` (``b`` at ``F / L``, at least one cell), not the
largest single cell: the end of a roller with sharp corners is a flat-punch edge in ``y``
(Johnson 1985 §5.2), where ``w ~ d^(-1/2)`` and the end cell's load grows without bound as the
cells shrink, while the window average converges. A plane-strain slice narrower than the contact
width has no meaning for the 2D FE that answers at that slice, and the Archard depth per pass is
proportional to it. ``w`` keeps the per-cell values; ``p_max`` stays the peak cell pressure.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .. import _validate
from .crown import RollerProfile
from .solver import HalfSpace

#: fewer loaded cells than this along the length flags the contact as under-resolved
MIN_CELLS = 4
_LADDER = 1.25


@dataclass(frozen=True, kw_only=True)
class StripResult:
    """One angle's finite-length contact (SI; pickles). ``p`` (Pa) on ``x`` x ``y`` (m);
    ``w`` the slice load per unit length (N/m) along ``y``, ``p_line`` the peak pressure of each
    slice (Pa). ``w_max`` (N/m) is the largest mean of ``w`` over an axial window of ``window``
    (m, the contact width ``2b``), centred at ``y_wmax`` (m). ``flags`` lists what the caller
    must know: ``"short_contact"`` (fewer than ``MIN_CELLS`` loaded cells along the length:
    refine ``ny``), ``"end_lift"`` (an end of the contact length carries no load: the tilt or
    crown lifted it off), ``"x_clipped"`` (pressure at the ``x`` border even on the last rung),
    ``"not_converged"``.

    Attributes
    ----------
    x : ndarray, shape (nx,), float
        Cell centres in the rolling direction [m].
    y : ndarray, shape (ny,), float
        Cell centres along the axis [m], 0 at the mid-plane.
    p : ndarray, shape (nx, ny), float
        Cell pressure [Pa].
    w : ndarray, shape (ny,), float
        Slice load per unit length ``int p dx`` [N/m].
    p_line : ndarray, shape (ny,), float
        Peak pressure of each axial slice [Pa].
    p_max : float
        Peak cell pressure [Pa].
    y_peak : float
        Axial position of ``p_max`` [m].
    L_eff : float
        Loaded length (cells with ``w > 0`` times ``dy``) [m].
    w_max : float
        Largest mean of ``w`` over an axial window of ``window`` [N/m].
    y_wmax : float
        Centre of that window [m].
    y_centre : float
        Load centre ``int w y dy / int w dy`` [m].
    alpha : float
        Rigid-body approach [m].
    iterations : int
        Conjugate-gradient iterations [-].
    residual : float
        Last relative pressure change [-].
    converged : bool
        The conjugate gradients met ``tol``.
    flags : tuple of str
        Warnings, see above; empty when all is well.
    window : float
        Axial averaging window of ``w_max``, ``min(2b, L)`` [m].
    """

    x: np.ndarray = field(repr=False)
    y: np.ndarray = field(repr=False)
    p: np.ndarray = field(repr=False)
    w: np.ndarray = field(repr=False)
    p_line: np.ndarray = field(repr=False)
    p_max: float
    y_peak: float
    L_eff: float
    w_max: float
    y_wmax: float
    y_centre: float
    alpha: float
    iterations: int
    residual: float
    converged: bool
    flags: tuple = ()
    window: float = 0.0


def window_max(w, dy: float, width: float) -> tuple[float, float]:
    r"""Largest mean of the cell loads ``w`` (N/m, uniform on cells of ``dy``, m, from
    ``y = -ny dy / 2``) over an axial window of ``width`` (m), and the window's centre (m).

    .. math:: \bar w(s) = \frac{W(s + \ell) - W(s)}{\ell},\qquad W(y) = \int_{-L/2}^{y} w\,dy

    ``W`` is piecewise linear, so the maximum over the start ``s`` lies where ``s`` or ``s + l``
    is a cell edge; both sets are evaluated (fractional cells count by their share).

    Parameters
    ----------
    w : array_like, shape (ny,)
        Load per unit length of each cell [N/m].
    dy : float
        Cell length along the axis [m].
    width : float
        Window length [m], clipped to ``[0, ny dy]``; 0 returns the largest single cell.

    Returns
    -------
    w_mean : float
        Largest window mean of ``w`` [N/m].
    y_centre : float
        Centre of that window [m], 0 at the mid-plane.

    Examples
    --------
    >>> window_max(np.array([1.0, 1.0, 4.0, 1.0]), 1.0, 2.0)      # cells 2-3 (first of two)
    (2.5, 0.0)
    >>> window_max(np.array([1.0, 1.0, 4.0, 1.0]), 1.0, 0.5)      # half of the cell of 4
    (4.0, 0.25)
    """
    w = np.asarray(w, float)
    n = w.size
    L = n * dy
    width = min(max(float(width), 0.0), L)
    edges = np.arange(n + 1) * dy - 0.5 * L
    if width <= 0.0:
        j = int(np.argmax(w))
        return float(w[j]), float(edges[j] + 0.5 * dy)
    cum = np.concatenate([[0.0], np.cumsum(w) * dy])
    s = np.unique(np.clip(np.concatenate([edges, edges - width]), -0.5 * L, 0.5 * L - width))
    mean = (np.interp(s + width, edges, cum) - np.interp(s, edges, cum)) / width
    k = int(np.argmax(mean))
    return float(mean[k]), float(s[k] + 0.5 * width)


class FiniteLengthContact:
    """Cam-roller strip solver for one geometry; :meth:`solve` per angle (warm-started).

    Parameters
    ----------
    profile : RollerProfile
        Roller axial geometry.
    cam_width : float
        Cam face width (m); the contact length is ``min(profile.width, cam_width)``.
    E_star : float
        Contact modulus (Pa).
    design_load : float, optional
        Design load (N) of a logarithmic crown.
    design_radius : float, optional
        Relative radius (m) at which ``b`` of the logarithmic crown is evaluated.
    nx, ny : int
        Cells across (rolling) and along (axial) the strip; default 64 x 128.
    tol : float
        CG tolerance on the relative pressure change; 1e-5 moves the peak pressure of a sweep by
        < 1e-4 relative against 1e-7 (measured on seed 002, see ``docs/halfspace.md``).
    max_iter : int
        CG iteration cap per solve; not converging is flagged ``"not_converged"``, not raised.
    """

    #: half-length (m) of the smallest rolling-direction window of the grid ladder
    #: ``X = _X0 _LADDER^k``, k >= 0
    _X0 = 1e-6

    def __init__(self, profile: RollerProfile, *, cam_width: float, E_star: float,
                 design_load: float | None = None, design_radius: float | None = None,
                 nx: int = 64, ny: int = 128, tol: float = 1e-5, max_iter: int = 500):
        if not isinstance(profile, RollerProfile):
            raise _validate.fail("profile", type(profile).__name__, "", "must be a RollerProfile")
        self.profile = profile
        self.cam_width = _validate.positive("cam_width", cam_width, "m")
        self.E_star = _validate.positive("E_star", E_star, "Pa")
        for name, n in (("nx", nx), ("ny", ny)):
            if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < 4:
                raise _validate.fail(name, n, "cells", "must be an integer >= 4")
        self.nx, self.ny = int(nx), int(ny)
        self.tol = _validate.positive("tol", tol, "")
        self.max_iter = _validate.integer("max_iter", max_iter, 1, "iterations")
        _validate.optional(_validate.positive, "design_load", design_load, "N")
        _validate.optional(_validate.positive, "design_radius", design_radius, "m")
        self.L = min(profile.width, self.cam_width)
        self.dy = self.L / self.ny
        self.y = (np.arange(self.ny) + 0.5) * self.dy - 0.5 * self.L
        kw = {}
        if profile.crown == "logarithmic":
            Q = _validate.positive("design_load", design_load, "N")
            Rd = _validate.positive("design_radius", design_radius, "m")
            kw = dict(design_load=Q, b=math.sqrt(4.0 * Q / profile.width * Rd / (math.pi * E_star)),
                      E_star=E_star)
        self.c = profile.drop(self.y, **kw)
        self.c = self.c - self.c.min()
        self._cache: dict[int, HalfSpace] = {}

    def _space(self, k: int) -> HalfSpace:
        if k not in self._cache:
            X = self._X0 * _LADDER**k
            self._cache[k] = HalfSpace(nx=self.nx, ny=self.ny, dx=2.0 * X / self.nx, dy=self.dy,
                                       E_star=self.E_star)
        return self._cache[k]

    def solve(self, F: float, R: float, *, p_start=None) -> StripResult:
        """Contact at normal force ``F`` (N, > 0) and relative radius ``R`` (m, > 0).

        Parameters
        ----------
        F : float
            Normal contact force [N], > 0.
        R : float
            Relative radius in the rolling direction [m], > 0.
        p_start : ndarray, shape (nx, ny), optional
            Starting pressure [Pa] (warm start, e.g. the previous angle's ``StripResult.p``).

        Returns
        -------
        StripResult
            Pressure field [Pa], slice loads [N/m], peaks and flags of this angle.
        """
        F = _validate.positive("F", F, "N")
        R = _validate.positive("R", R, "m")
        b = math.sqrt(4.0 * F / self.L * R / (math.pi * self.E_star))
        k = max(0, math.ceil(math.log(1.4 * b / self._X0) / math.log(_LADDER)))
        for _ in range(8):
            hs = self._space(k)
            x = (np.arange(self.nx) + 0.5) * hs.dx - 0.5 * self.nx * hs.dx
            h0 = x[:, None] ** 2 / (2.0 * R) + self.c[None, :]
            sol = hs.solve(h0, F, p0=p_start, tol=self.tol, max_iter=self.max_iter)
            clipped = bool(np.any(sol.p[0]) or np.any(sol.p[-1]))
            if not clipped:
                break
            k += 1
        return self._result(x, hs.dx, sol, clipped, b)

    def _result(self, x, dx, sol, clipped, b: float) -> StripResult:
        p, y = sol.p, self.y
        w = p.sum(axis=0) * dx
        p_line = p.max(axis=0)
        i, j = np.unravel_index(int(np.argmax(p)), p.shape)
        loaded = w > 0
        width = min(2.0 * b, self.L)
        w_max, y_wmax = window_max(w, self.dy, width)
        flags = []
        if loaded.sum() < MIN_CELLS:
            flags.append("short_contact")
        if not (loaded[0] and loaded[-1]):
            flags.append("end_lift")
        if clipped:
            flags.append("x_clipped")
        if not sol.converged:
            flags.append("not_converged")
        W = float(w.sum() * self.dy)
        return StripResult(x=x, y=y, p=p, w=w, p_line=p_line, p_max=float(p[i, j]), y_peak=float(y[j]),
                           L_eff=float(loaded.sum() * self.dy), w_max=w_max, y_wmax=y_wmax,
                           y_centre=float((w * y).sum() * self.dy / W), alpha=sol.alpha,
                           iterations=sol.iterations, residual=sol.residual, converged=sol.converged,
                           flags=tuple(flags), window=width)
