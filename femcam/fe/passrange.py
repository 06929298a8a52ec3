r"""The range of the orthogonal shear stress over one pass, from the FE subsurface field.

A point at depth ``z`` below the surface sees the whole field ``txz(x, z)`` pass as the contact
rolls over it; the range of that cycle, largest over depth, is the stress measure of subsurface
rolling-contact fatigue (Johnson 1985 §9.2):

.. math:: \Delta\tau = \max_z\left[\max_x \tau_{xz}(x, z) - \min_x \tau_{xz}(x, z)\right]

(0.5 p0 at z = 0.5 a for a Hertz contact, frictionless or sliding up to mu ~ 0.5:
:func:`femcam.hertz.max_shear_range`). :func:`pass_grid` builds, once per model, the rows of
equal depth through a body's stress window and the sparse interpolation of the window's nodal
field onto them; :func:`grid_shear_range` (the same as :func:`pass_shear_range` on the full grid) takes the
range on those rows per load case
(:class:`ShearRange` in a :class:`femcam.fe.ContactResult`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from ..mesh import surface_height
from .elasticity import Body
from .recovery import depth


@dataclass(frozen=True)
class ShearRange:
    """The largest range of the orthogonal shear ``txz`` over one pass in one body's stress
    window (:func:`femcam.fe.passrange.pass_shear_range`): the stress cycle of subsurface
    rolling-contact fatigue (Johnson 1985 §9.2).

    Parameters
    ----------
    value : float
        ``max_x txz - min_x txz`` at the depth where it is largest [Pa].
    z : float
        That depth in the body's Johnson frame [m].
    x_max, x_min : float
        Where ``txz`` is largest and smallest at that depth [m].
    body : str
        ``"cam"`` or ``"roller"``.
    inside : bool
        Both extremes lie inside the stress window (not on its edge in ``x``, not in its deepest
        row); False: the window cuts the pass and ``value`` may be too low.
    """

    value: float
    z: float
    x_max: float
    x_min: float
    body: str
    inside: bool


def pass_grid(body: Body, nodes: np.ndarray, x: np.ndarray, z: np.ndarray, surface: np.ndarray):
    """Rows of equal depth through one body's stress window, for the range of ``txz`` over one
    pass: ``(P, xs, zs, ok)`` with ``(P @ f)[ok]`` the window's nodal field ``f`` interpolated by
    the body's own shape functions at the grid points ``(xs, zs)`` (Johnson frame).

    The window's nodes lie at scattered depths; a range taken over nodes of a depth band would
    mix depths, and with friction that biases it at first order in the band width (the
    traction's ``mu sx`` part of ``txz`` varies with depth: +0.75 % at ``mu = 0.3``, a/10, bands
    of h/2). The grid spacing is half the surface nodes' median spacing (``h/4`` for P2: the
    sampling error of a peak is second order, ~0.05 % of ``p0``); rows start one element
    (twice that spacing) below the surface, where the contact-edge error of the surface nodes
    has faded. Points in elements not wholly inside the window are left out (``ok`` False).

    The per-solve cost is one sparse product and a segmented maximum (:func:`grid_shear_range`).

    Parameters
    ----------
    body : Body
        The body.
    nodes : ndarray of int, shape (n_eval,)
        Scalar node indices of the window.
    x, z : ndarray of float, shape (n_eval,)
        Abscissae and depths of the window nodes [m].
    surface : ndarray of int
        Indices into ``nodes`` of the contact-surface nodes, sorted by x.

    Returns
    -------
    P : scipy.sparse.csr_matrix, shape (n_ok, n_eval)
        Interpolation weights [-] at the grid points where ``ok`` (rows in row-major order of
        ``(zs, xs)``, the points outside the window left out: ``ok.sum()`` rows).
    xs : ndarray of float, shape (n_x,)
        Abscissae of the grid [m].
    zs : ndarray of float, shape (n_z,)
        Depths of the rows [m].
    ok : ndarray of bool, shape (n_z, n_x)
        Grid points inside elements wholly in the window.
    """
    spacing = float(np.median(np.diff(x[surface]))) if surface.size > 1 else float(np.ptp(x)) / 8
    step = 0.5 * spacing
    n = int(np.floor(np.max(np.abs(x)) / step))
    xs = step * np.arange(-n, n + 1)
    zs = step * np.arange(4, int(np.floor(np.max(z) / step)) + 1)
    nx, nz = xs.size, zs.size
    sd = body.basis.element_dofs[::2] // 2                  # scalar nodes per element (nloc, nel)
    pos = np.full(body.n_dofs // 2, -1)
    pos[nodes] = np.arange(nodes.size)
    els = np.flatnonzero((pos[sd] >= 0).all(axis=0))
    t, sd = body.mesh.t[:, els], sd[:, els]
    p = body.mesh.p
    zv = depth(body, p[:, t.ravel()]).reshape(t.shape)
    xv = p[0, t]
    # candidate grid points per element: its bounding box in (x, z), one row of margin for the
    # curved surface (z is not affine in the FE frame; the reference coordinates decide)
    ix0 = np.ceil((xv.min(axis=0) - xs[0]) / step).astype(int) if nx else np.zeros(0, int)
    ix1 = np.floor((xv.max(axis=0) - xs[0]) / step).astype(int) if nx else np.zeros(0, int)
    iz0 = np.ceil((zv.min(axis=0) - zs[0]) / step).astype(int) - 1 if nz else np.zeros(0, int)
    iz1 = np.floor((zv.max(axis=0) - zs[0]) / step).astype(int) + 1 if nz else np.zeros(0, int)
    cx, cz = np.maximum(ix1 - ix0 + 1, 0), np.maximum(iz1 - iz0 + 1, 0)
    cnt = cx * cz
    e = np.repeat(np.arange(els.size), cnt)
    k = np.arange(e.size) - np.repeat(np.cumsum(cnt) - cnt, cnt)
    ix, iz = ix0[e] + k % np.maximum(cx[e], 1), iz0[e] + k // np.maximum(cx[e], 1)
    keep = (ix >= 0) & (ix < nx) & (iz >= 0) & (iz < nz)
    e, ix, iz = e[keep], ix[keep], iz[keep]
    px = xs[ix]
    ys = surface_height(px, body.geometry.R)
    py = (-ys - zs[iz]) if body.name == "cam" else (ys + zs[iz])
    v0, v1, v2 = (p[:, t[j]] for j in range(3))              # affine map x = v0 + A (xi, eta)
    # the map per element, then taken at each candidate's element (the same numbers)
    a11, a21, a12, a22 = v1[0] - v0[0], v1[1] - v0[1], v2[0] - v0[0], v2[1] - v0[1]
    det = (a11 * a22 - a12 * a21)[e]
    a11, a21, a12, a22 = a11[e], a21[e], a12[e], a22[e]
    dx, dy = px - v0[0, e], py - v0[1, e]
    xi, eta = (a22 * dx - a12 * dy) / det, (a11 * dy - a21 * dx) / det
    tol = 1e-9
    inside = (xi >= -tol) & (eta >= -tol) & (xi + eta <= 1.0 + tol)
    g = (iz * nx + ix)[inside]
    g, first = np.unique(g, return_index=True)               # a point on a shared edge: once
    e, ref = e[inside][first], np.vstack([xi[inside][first], eta[inside][first]])
    elem = body.basis.elem.elem
    nloc = sd.shape[0]
    w = np.stack([elem.lbasis(ref, j)[0] for j in range(nloc)])
    # g is sorted and unique: row r of P is the grid point g[r] (only the points inside)
    P = sp.csr_matrix((w.ravel(), (np.tile(np.arange(g.size), nloc), pos[sd[:, e]].ravel())),
                      shape=(g.size, nodes.size))
    ok = np.zeros(nz * nx, dtype=bool)
    ok[g] = True
    return P, xs, zs, ok.reshape(nz, nx)


def pass_shear_range(txz, xs, zs, ok) -> dict:
    r"""Largest range of ``txz`` over one pass on rows of equal depth, and where it is.

    .. math:: \Delta\tau = \max_z\left[\max_x \tau_{xz}(x, z) - \min_x \tau_{xz}(x, z)\right]

    Parameters
    ----------
    txz : ndarray of float, shape (n_z, n_x)
        Orthogonal shear stress on the grid [Pa] (any value where ``ok`` is False).
    xs : ndarray of float, shape (n_x,)
        Abscissae [m].
    zs : ndarray of float, shape (n_z,)
        Depths of the rows [m].
    ok : ndarray of bool, shape (n_z, n_x)
        The grid points that count.

    Returns
    -------
    dict
        ``value`` [Pa] (0 without points), ``z`` the depth of that row [m], ``x_max``, ``x_min``
        where ``txz`` is largest and smallest in it [m], and ``inside`` (bool): the row is not
        the deepest one with points and neither extreme has a missing or no neighbour in ``x``,
        i.e. the window does not cut the pass.

    Examples
    --------
    >>> xs, zs = np.array([-1.0, 0.0, 1.0]), np.array([0.1, 0.5, 0.9])
    >>> t = np.array([[1.0, 0.0, -1.0], [1.0, 2.0, -3.0], [0.0, 0.0, 0.0]])
    >>> r = pass_shear_range(t, xs, zs, np.ones((3, 3), bool))
    >>> r["value"], r["z"], r["x_max"], r["x_min"], r["inside"]
    (5.0, 0.5, 0.0, 1.0, False)
    """
    hi_t, lo_t = np.where(ok, txz, -np.inf), np.where(ok, txz, np.inf)
    rows = np.flatnonzero(ok.any(axis=1))
    if rows.size == 0:
        return {"value": 0.0, "z": np.nan, "x_max": np.nan, "x_min": np.nan, "inside": False}
    rng = hi_t[rows].max(axis=1) - lo_t[rows].min(axis=1)
    k = int(rows[np.argmax(rng)])
    j_hi, j_lo = int(np.argmax(hi_t[k])), int(np.argmin(lo_t[k]))
    pad = np.pad(ok[k], 1)                                    # neighbours in x (False off the grid)
    inside = bool(k < rows[-1] and pad[j_hi] and pad[j_hi + 2] and pad[j_lo] and pad[j_lo + 2])
    return {"value": float(rng.max()), "z": float(zs[k]), "x_max": float(xs[j_hi]),
            "x_min": float(xs[j_lo]), "inside": inside}


def grid_shear_range(v, xs, zs, ok) -> dict:
    r""":func:`pass_shear_range` of the values at the grid points where ``ok`` only (the rows of
    :func:`pass_grid`'s ``P``): the same result, by a segmented maximum and minimum per row
    (``np.maximum.reduceat``) instead of two full masked grids (~5x faster per solve).

    Parameters
    ----------
    v : ndarray of float, shape (n_ok,)
        ``txz`` at the points where ``ok``, in row-major order of ``(zs, xs)`` [Pa].
    xs : ndarray of float, shape (n_x,)
        Abscissae [m].
    zs : ndarray of float, shape (n_z,)
        Depths of the rows [m].
    ok : ndarray of bool, shape (n_z, n_x)
        The grid points that count (``ok.sum() == v.size``).

    Returns
    -------
    dict
        As :func:`pass_shear_range`: ``value`` [Pa], ``z`` [m], ``x_max``, ``x_min`` [m],
        ``inside`` (bool).

    Examples
    --------
    >>> xs, zs = np.array([-1.0, 0.0, 1.0]), np.array([0.1, 0.5, 0.9])
    >>> ok = np.array([[True, True, True], [True, True, True], [False, False, False]])
    >>> r = grid_shear_range(np.array([1.0, 0.0, -1.0, 1.0, 2.0, -3.0]), xs, zs, ok)
    >>> r["value"], r["z"], r["x_max"], r["x_min"], r["inside"]
    (5.0, 0.5, 0.0, 1.0, False)
    """
    counts = ok.sum(axis=1)
    rows = np.flatnonzero(counts)
    if rows.size == 0:
        return {"value": 0.0, "z": np.nan, "x_max": np.nan, "x_min": np.nan, "inside": False}
    starts = (np.cumsum(counts) - counts)[rows]
    rng = np.maximum.reduceat(v, starts) - np.minimum.reduceat(v, starts)
    i = int(np.argmax(rng))
    k = int(rows[i])
    seg = v[starts[i]:starts[i] + counts[k]]
    cols = np.flatnonzero(ok[k])
    j_hi, j_lo = int(cols[np.argmax(seg)]), int(cols[np.argmin(seg)])
    row, n = ok[k], ok.shape[1]

    def flanked(j):                                           # both neighbours in x are points
        return 0 < j < n - 1 and bool(row[j - 1]) and bool(row[j + 1])

    inside = bool(k < rows[-1] and flanked(j_hi) and flanked(j_lo))
    return {"value": float(rng[i]), "z": float(zs[k]), "x_max": float(xs[j_hi]),
            "x_min": float(xs[j_lo]), "inside": inside}
