r"""Maxima of the Hertz line-contact stress field: ``tau1``, von Mises and ``|txz|``, for any ``mu``.

Everything is dimensionless here: the value is returned as ``value / p0`` and the location as
``(x/a, z/a)``; :class:`~femcam.hertz.contact.LineContact` scales them to Pa and m for every
load case at once (the dimensionless maximum depends on ``mu``, ``nu`` and the plane only).

Method: a dense grid over ``-2 <= x/a <= 2``, ``0 <= z/a <= 2`` (the maximum always lies there:
the field decays like ``1/r`` outside), then the best grid points are refined by zoomed
sampling (21 x 21 points over +-1 step, 10x finer per pass, to a step below 1e-11 a;
derivative-free because the field has square-root kinks at the surface edges ``|x| = a``;
numpy only, so the main job does not import ``scipy.optimize``; a bounded Nelder-Mead search
gives the same maxima to 7e-16).  Diagnostics (grid value, ``nfev``
= field evaluations, ``converged``) travel with the result.

Textbook values (frictionless, Johnson 1985 §4.2.3 and Fig. 4.6):

* ``tau1`` max ``= 0.300 p0`` at ``x = 0, z = 0.786 a``;
* ``|txz|`` max ``= p0/4`` at ``x = +-sqrt(3)/2 a, z = a/2`` (exact);
* von Mises max ``~ 0.557 p0`` at ``z ~ 0.70 a`` for ``nu = 0.3`` (plane strain);
* range of ``txz`` over one pass, ``max_z [max_x txz - min_x txz]`` (:func:`max_shear_range`)
  ``= p0/2`` at ``z = a/2`` (Johnson 1985 §9.2), unchanged by a sliding traction ``q = mu p``
  up to ``mu ~ 0.5``: the traction adds ``mu sx_p`` to ``txz``, and at the extremes of ``txz_p``
  equilibrium (``d sx/dx = -d txz/dz = 0`` there) leaves ``sx_p`` stationary in ``x``, so both
  peaks move alike. Above that the surface range ``mu p0`` (``txz = -q`` at ``z = 0``) governs.

With friction the maxima move towards the surface and to the trailing side; above
``mu ~ 0.25-0.3`` ``tau1`` peaks at the surface.  There ``tau1(x, 0) = mu p0`` for every
``|x| <= a`` (a plateau: ``(sx - sz)/2 = -mu p0 x/a`` and ``txz = -mu p0 sqrt(1 - x^2/a^2)``),
so the reported location is one point of a flat set; see :attr:`StressMaximum.message`.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import _validate
from .._repr import compact_repr
from ..materials import PLANES
from .subsurface import StressField, _unit_stresses

_X_BOUNDS = (-2.0, 2.0)
_Z_BOUNDS = (0.0, 2.0)


@dataclass(frozen=True)
class StressMaximum:
    """Maximum of a stress measure: ``value`` in units of ``p0``, location in units of ``a``.

    Attributes
    ----------
    quantity : str
        Stress measure: ``"tau1"``, ``"von_mises"``, ``"txz"`` (``|tau_xz|``) or
        ``"txz_range"`` (range of ``tau_xz`` over one pass, :func:`max_shear_range`).
    value : float
        Maximum divided by ``p0`` [-].
    x, z : float
        Location ``x / a`` and depth ``z / a >= 0`` [-] (``txz_range``: ``x`` of the largest
        ``tau_xz`` at that depth).
    mu : float
        Friction coefficient [-] the maximum was computed for.
    nu : float or None
        Poisson ratio [-] (von Mises only; ``None`` for ``tau1`` and ``txz``).
    grid_value : float
        Best value on the search grid divided by ``p0`` [-] (``value >= grid_value``).
    nfev : int
        Number of field evaluations of the Nelder-Mead refinement.
    converged : bool
        Every refinement reported success.
    message : str
        Surface or subsurface maximum, and the ``tau1`` plateau note.
    """

    quantity: str
    value: float          # max / p0
    x: float              # x / a
    z: float              # z / a
    mu: float
    nu: float | None
    grid_value: float     # best value on the search grid (value >= grid_value)
    nfev: int
    converged: bool
    message: str


@dataclass(frozen=True)
class ScaledMaximum:
    """A :class:`StressMaximum` scaled to a load case: ``value`` (Pa), ``x``, ``z`` (m).

    Attributes
    ----------
    value : float or ndarray
        Maximum [Pa], one per load case (shape of :attr:`LineContact.shape`).
    x, z : float or ndarray
        Location along the surface and depth into the body [m], same shape as ``value``.
    unit : StressMaximum
        The dimensionless maximum with its search diagnostics.
    """

    value: object
    x: object
    z: object
    unit: StressMaximum

    def __repr__(self) -> str:
        """The scalar fields and the arrays' shapes, never their values (a compact line)."""
        return compact_repr(self)



def _measure(quantity, X, Z, mu, nu, plane):
    sx, sz, txz = _unit_stresses(X, Z, mu)  # X, Z, mu checked by the callers
    if quantity == "txz":
        return np.abs(txz)
    if quantity == "tau1":
        return np.hypot(0.5 * (sx - sz), txz)
    sy = nu * (sx + sz) if plane == "strain" else np.zeros_like(sx)
    f = StressField(sx=sx, sz=sz, txz=txz, sy=sy)
    return f.von_mises


@lru_cache(maxsize=256)
def _maximise(quantity, mu, nu, plane, n_x=401, n_z=201):
    X = np.linspace(*_X_BOUNDS, n_x)
    Z = np.linspace(*_Z_BOUNDS, n_z)
    XX, ZZ = np.meshgrid(X, Z, indexing="ij")
    F = _measure(quantity, XX, ZZ, mu, nu, plane)
    grid_best = float(F.max())

    # Refine from the best grid point and from the best surface point (for mu > ~0.3 the
    # surface maximum competes with the subsurface one).
    # A third start, the best interior point, keeps the subsurface peak in view near the
    # friction value where both are almost equal.
    inner = np.unravel_index(np.argmax(F[:, 1:]), (n_x, n_z - 1))
    starts = [np.unravel_index(np.argmax(F), F.shape), (int(np.argmax(F[:, 0])), 0),
              (int(inner[0]), int(inner[1]) + 1)]
    best, nfev = None, 0
    for i, j in starts:
        r = _zoom(quantity, mu, nu, plane, X[i], Z[j], X[1] - X[0], Z[1] - Z[0])
        nfev += r[3]
        if best is None or r[0] > best[0]:
            best = r
    value, x, z, converged = best[0], best[1], best[2], True
    if value < grid_best:                                  # never worse than the grid
        i, j = starts[0]
        value, x, z = grid_best, float(X[i]), float(Z[j])
    msg = "subsurface maximum" if z > 1e-6 else "surface maximum"
    if quantity == "tau1" and z <= 1e-6 and abs(value - abs(mu)) < 1e-9:
        # flat set: report its centre rather than wherever the search stopped
        x, msg = 0.0, "surface maximum tau1 = mu p0 on the whole plateau |x| <= a at z = 0"
    return StressMaximum(quantity=quantity, value=value, x=x, z=max(z, 0.0), mu=mu,
                         nu=nu if quantity == "von_mises" else None, grid_value=grid_best,
                         nfev=nfev, converged=converged, message=msg)


def _zoom(quantity, mu, nu, plane, x0, z0, hx, hz, n=21, tol=1e-11):
    """``(value, x, z, evaluations)``: the maximum near the grid point ``(x0, z0)`` (steps
    ``hx``, ``hz``) by zoomed sampling: an ``n`` x ``n`` grid over +-1 step (inside the search
    box), then again around its best point, each pass 10x finer, until the step is below
    ``tol`` (in units of ``a``). Vectorised, derivative-free (the field has square-root kinks at
    the surface edges) and never below the best sample."""
    best, evals = -np.inf, 0
    while True:
        xs = np.linspace(max(x0 - hx, _X_BOUNDS[0]), min(x0 + hx, _X_BOUNDS[1]), n)
        zs = np.linspace(max(z0 - hz, _Z_BOUNDS[0]), min(z0 + hz, _Z_BOUNDS[1]), n)
        XX, ZZ = np.meshgrid(xs, zs, indexing="ij")
        F = _measure(quantity, XX, ZZ, mu, nu, plane)
        evals += F.size
        k = np.unravel_index(np.argmax(F), F.shape)
        if F[k] >= best:
            best, x0, z0 = float(F[k]), float(xs[k[0]]), float(zs[k[1]])
        hx, hz = xs[1] - xs[0], zs[1] - zs[0]
        if max(hx, hz) < tol:
            return best, x0, z0, evals


def _mu(mu):
    return _validate.nonnegative("mu", mu, "")


def max_shear(mu: float = 0.0) -> StressMaximum:
    r"""Maximum in-plane principal shear :math:`\tau_1/p_0` and its location ``(x/a, z/a)``.

    .. math:: \tau_1 = \sqrt{\left(\tfrac{\sigma_x - \sigma_z}{2}\right)^2 + \tau_{xz}^2}

    Frictionless: 0.300 at (0, 0.786) (Johnson 1985 §4.2.3).

    Parameters
    ----------
    mu : float, optional
        Friction coefficient [-], ``>= 0``. Default 0.

    Returns
    -------
    StressMaximum
        ``value = tau1_max / p0`` [-] at ``(x/a, z/a)`` [-], with search diagnostics.

    Raises
    ------
    InputError
        ``mu`` is negative or not finite.

    Examples
    --------
    >>> m = max_shear()
    >>> round(m.value, 3), round(m.z, 3)
    (0.3, 0.786)
    """
    return _maximise("tau1", _mu(mu), None, "strain")


def max_von_mises(mu: float = 0.0, nu: float = 0.3, plane: str = "strain") -> StressMaximum:
    r"""Maximum von Mises stress / ``p0`` (all three principal stresses) and its location.

    .. math:: \sigma_{vM} = \sqrt{\tfrac12[(\sigma_1-\sigma_2)^2 + (\sigma_2-\sigma_3)^2
              + (\sigma_3-\sigma_1)^2]},\quad \sigma_y = \nu(\sigma_x+\sigma_z)\ \text{(plane strain)}

    Parameters
    ----------
    mu : float, optional
        Friction coefficient [-], ``>= 0``. Default 0.
    nu : float, optional
        Poisson ratio [-] of the body, ``-1 < nu < 0.5``. Default 0.3.
    plane : {"strain", "stress"}, optional
        ``sy = nu (sx + sz)`` in plane strain (default), ``sy = 0`` in plane stress.

    Returns
    -------
    StressMaximum
        ``value = sigma_vM_max / p0`` [-] at ``(x/a, z/a)`` [-], with search diagnostics.

    Raises
    ------
    InputError
        ``mu``, ``nu`` or ``plane`` out of range.

    Examples
    --------
    >>> round(max_von_mises(0.0, 0.3).value, 4)   # textbook ~0.557
    0.5575
    """
    nu = _validate.in_range("nu", nu, -1.0, 0.5, "", lo_open=True, hi_open=True)
    _validate.choice("plane", plane, PLANES)
    return _maximise("von_mises", _mu(mu), nu, plane)


def max_orthogonal_shear(mu: float = 0.0) -> StressMaximum:
    r"""Maximum orthogonal shear :math:`|\tau_{xz}|/p_0` and its location.

    Frictionless: exactly 1/4 at :math:`(\pm\sqrt3/2,\ 1/2)` (Johnson 1985 §4.2.3); the
    reported ``x`` is the one the search lands on (the field is antisymmetric in ``x``).

    Parameters
    ----------
    mu : float, optional
        Friction coefficient [-], ``>= 0``. Default 0.

    Returns
    -------
    StressMaximum
        ``value = |tau_xz|_max / p0`` [-] at ``(x/a, z/a)`` [-], with search diagnostics.

    Raises
    ------
    InputError
        ``mu`` is negative or not finite.

    Examples
    --------
    >>> round(max_orthogonal_shear().value, 6)
    0.25
    """
    return _maximise("txz", _mu(mu), None, "strain")


def _pass_range(X, Z, mu):
    """``(range, x of the largest txz)`` of ``txz / p0`` along the rows ``Z`` (units of a)."""
    t = _unit_stresses(X[None, :], Z[:, None], mu)[2]
    return t.max(axis=1) - t.min(axis=1), X[np.argmax(t, axis=1)]


def _x_extreme(z, x0, h, sign, mu, tol=1e-11):
    """``(sign * extreme of sign * txz / p0, x)`` at depth ``z`` near ``x0`` by zoomed sampling."""
    best = -np.inf
    while h > tol:
        xs = np.linspace(x0 - h, x0 + h, 21)
        t = sign * _unit_stresses(xs, z, mu)[2]
        k = int(np.argmax(t))
        if t[k] >= best:
            best, x0 = float(t[k]), float(xs[k])
        h = float(xs[1] - xs[0])
    return sign * best, x0


@lru_cache(maxsize=256)
def _shear_range(mu: float, n_x: int = 601, n_z: int = 61) -> StressMaximum:
    X = np.linspace(-3.0, 3.0, n_x)            # txz decays like 1/r: the extremes lie in |x| < 3a
    Z = np.linspace(0.0, 1.5, n_z)
    r, _ = _pass_range(X, Z, mu)
    grid_best = float(r.max())
    z0, h, best, evals = float(Z[int(np.argmax(r))]), float(Z[1] - Z[0]), grid_best, r.size * n_x
    while h > 1e-6:                             # zoomed sampling in z (as _zoom, one dimension)
        zs = np.linspace(max(z0 - h, 0.0), z0 + h, 21)
        rr, _ = _pass_range(X, zs, mu)
        evals += rr.size * n_x
        k = int(np.argmax(rr))
        if rr[k] >= best:
            best, z0 = float(rr[k]), float(zs[k])
        h = float(zs[1] - zs[0])
    # the x extremes at that depth, refined off the grid (the range is flat in z at its maximum)
    t = _unit_stresses(X, z0, mu)[2]
    hi, x = _x_extreme(z0, X[int(np.argmax(t))], X[1] - X[0], 1.0, mu)
    lo, _ = _x_extreme(z0, X[int(np.argmin(t))], X[1] - X[0], -1.0, mu)
    value, x = max(best, hi - lo), min(max(x, -3.0), 3.0)
    msg = "subsurface maximum" if z0 > 1e-6 else "surface maximum (txz = -q at z = 0)"
    return StressMaximum(quantity="txz_range", value=value, x=x, z=z0, mu=mu, nu=None,
                         grid_value=grid_best, nfev=evals, converged=True, message=msg)


def max_shear_range(mu: float = 0.0) -> StressMaximum:
    r"""Largest range of the orthogonal shear :math:`\tau_{xz}` over one pass, / ``p0``, and its depth.

    A point at depth ``z`` sees the whole field ``txz(x, z)`` pass as the load rolls over it
    (Johnson 1985 §9.2: the stress cycle of rolling contact fatigue):

    .. math:: \frac{\Delta\tau}{p_0} = \max_z\left[\max_x \tau_{xz}(x, z) -
              \min_x \tau_{xz}(x, z)\right] / p_0

    Frictionless: exactly 1/2 at ``z = a/2`` (the peaks ``+-p0/4`` at ``x = -+sqrt(3)/2 a``);
    the same up to ``mu ~ 0.5`` (module docstring), then the surface range ``mu``. Search: the
    field on 601 points of ``-3 <= x/a <= 3`` at 61 depths ``0 <= z/a <= 1.5``, zoomed sampling
    in ``z`` to a step below 1e-6 a (the range is stationary in ``z`` there, so the value is not
    sensitive to it), then both ``x`` extremes at that depth refined off the grid by zoomed
    sampling to 1e-11 a.

    Parameters
    ----------
    mu : float, optional
        Friction coefficient [-], ``>= 0``; traction ``q = mu p`` (full sliding). Default 0.

    Returns
    -------
    StressMaximum
        ``value = dtau / p0`` [-] at depth ``z / a`` [-] (``x / a``: where ``txz`` is largest at
        that depth), with search diagnostics.

    Raises
    ------
    InputError
        ``mu`` is negative or not finite.

    Examples
    --------
    >>> m = max_shear_range()
    >>> round(m.value, 6), round(m.z, 3)
    (0.5, 0.5)
    """
    return _shear_range(_mu(mu))
