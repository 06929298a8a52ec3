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
    slice (Pa). ``flags`` lists what the caller must know: ``"short_contact"`` (fewer than
    ``MIN_CELLS`` loaded cells along the length: refine ``ny``), ``"end_lift"`` (an end of the
    contact length carries no load: the tilt or crown lifted it off), ``"x_clipped"`` (pressure
    at the ``x`` border even on the last rung), ``"not_converged"``."""

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
    """

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
        self.nx, self.ny, self.tol, self.max_iter = int(nx), int(ny), float(tol), int(max_iter)
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

    @property
    def _X0(self) -> float:
        return 1e-6

    def solve(self, F: float, R: float, *, p_start=None) -> StripResult:
        """Contact at normal force ``F`` (N, > 0) and relative radius ``R`` (m, > 0)."""
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
        return self._result(x, hs.dx, sol, clipped)

    def _result(self, x, dx, sol, clipped) -> StripResult:
        p, y = sol.p, self.y
        w = p.sum(axis=0) * dx
        p_line = p.max(axis=0)
        i, j = np.unravel_index(int(np.argmax(p)), p.shape)
        loaded = w > 0
        jw = int(np.argmax(w))
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
                           L_eff=float(loaded.sum() * self.dy), w_max=float(w[jw]), y_wmax=float(y[jw]),
                           y_centre=float((w * y).sum() * self.dy / W), alpha=sol.alpha,
                           iterations=sol.iterations, residual=sol.residual, converged=sol.converged,
                           flags=tuple(flags))
