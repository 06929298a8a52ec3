r"""Archard wear depth laid down by a moving Hertz contact: the closed forms of the wear map.

Archard's law per unit area, :math:`dh = k\,p\,ds_{slip}` (Archard 1953), summed over the time a
surface point spends under the moving contact, ``h(x) = k int p(x - xi(t)) v_slip dt``; see
:mod:`femcam.wear.map` for the symbols, the per-pass closed form ``k w v_slip / V`` and the exact
time integral over a step, and for the roller's drift sum (:func:`drift_sum`).
"""

from __future__ import annotations

import numpy as np

from .. import _validate


def hertz_load_per_length(a, p0):
    r"""``w = int p dx = pi a p0 / 2`` (N/m) for the Hertz elliptical pressure (Johnson eq. 4.44).

    Parameters
    ----------
    a : float or array_like
        Contact half-width [m].
    p0 : float or array_like
        Peak contact pressure [Pa].

    Returns
    -------
    ndarray
        Load per unit length ``w`` [N/m], float, the broadcast shape of ``a`` and ``p0``.

    Examples
    --------
    >>> round(float(hertz_load_per_length(1e-4, 1e9)), 3)
    157079.633
    """
    return 0.5 * np.pi * np.asarray(a, dtype=float) * np.asarray(p0, dtype=float)


def depth_per_pass(k, w, v_slip, V_transport):
    r"""Wear depth left by one pass of the contact over a surface point (m).

    .. math:: \Delta h = k\,w\,v_{slip}/V

    ``V_transport = 0`` (the contact sits still on that surface, e.g. a knife-edge tip) gives
    ``inf`` where ``k w v_slip > 0``.

    Parameters
    ----------
    k : float
        Dimensional wear coefficient [m^3/(N m)], >= 0.
    w : float or array_like
        Load per unit length [N/m]; NaN and negative values count as 0.
    v_slip : float or array_like
        Sliding speed [m/s] (its magnitude is used).
    V_transport : float or array_like
        Speed of the contact over the surface [m/s] (its magnitude is used).

    Returns
    -------
    ndarray
        Depth per pass [m], float, the broadcast shape of the inputs.

    Examples
    --------
    >>> float(depth_per_pass(1e-17, 1e5, 0.2, 1.0))     # k w (slip per rolled length)
    2e-13
    """
    return _depth_per_pass(_validate.nonnegative("k", k, "m^3/(N m)"), _validate.data_array("w", w, "N/m"),
                           _validate.finite_array("v_slip", v_slip, "m/s"),
                           _validate.finite_array("V_transport", V_transport, "m/s"))


def _depth_per_pass(k, w, v_slip, V_transport):
    """:func:`depth_per_pass` without the input checks."""
    w = np.clip(np.nan_to_num(np.asarray(w, dtype=float), nan=0.0), 0.0, None)
    v = np.abs(np.asarray(v_slip, dtype=float))
    Vt = np.abs(np.asarray(V_transport, dtype=float))
    num = k * w * v
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.where(Vt > 0, num / np.where(Vt > 0, Vt, 1.0), np.where(num > 0, np.inf, 0.0))
    return out


def _ellipse_primitive(y, a, p0):
    """P(y) = int_{-a}^{y} p0 sqrt(1 - t^2/a^2) dt - w/2 (odd; constant -+ w/2 outside)."""
    eta = np.clip(y / a, -1.0, 1.0)
    return 0.5 * p0 * a * (eta * np.sqrt(1.0 - eta * eta) + np.arcsin(eta))


def surface_depth(x, xi, a, p0, v_slip, dt, *, k, period=None, chunk: int = 256):
    r"""Archard depth ``h(x) = k int p(x - xi(t)) v_slip dt`` on grid ``x`` (m).

    ``xi`` (n+1 contact positions, m) bound n steps of duration ``dt`` (s); ``a``, ``p0``,
    ``v_slip`` (n values) hold in each step. ``period`` makes the coordinate periodic (cam
    perimeter, roller circumference). Steps with ``a <= 0``, NaN or ``p0 <= 0`` carry no load.
    Vectorised over the grid; steps are processed in chunks of ``chunk``.

    Parameters
    ----------
    x : array_like, shape (m,)
        Surface grid [m].
    xi : array_like, shape (n + 1,)
        Contact-centre positions at the step ends [m].
    a : array_like, shape (n,)
        Contact half-width in each step [m].
    p0 : array_like, shape (n,)
        Peak pressure in each step [Pa].
    v_slip : array_like, shape (n,)
        Sliding speed in each step [m/s] (its magnitude is used).
    dt : array_like, shape (n,)
        Step durations [s].
    k : float
        Dimensional wear coefficient [m^3/(N m)], >= 0.
    period : float, optional
        Period of the coordinate [m]; None for an open coordinate.
    chunk : int
        Steps per vectorised block (memory ``m x chunk`` floats).

    Returns
    -------
    ndarray, shape (m,), float
        Wear depth on ``x`` [m].
    """
    k = _validate.nonnegative("k", k, "m^3/(N m)")
    x = _validate.finite_array("x", x, "m")
    xi = _validate.finite_array("xi", xi, "m")
    a = np.nan_to_num(_validate.data_array("a", a, "m"), nan=0.0)        # NaN: no load
    p0 = np.nan_to_num(_validate.data_array("p0", p0, "Pa"), nan=0.0)
    v = np.abs(_validate.data_array("v_slip", v_slip, "m/s"))
    dt = _validate.data_array("dt", dt, "s")
    period = _validate.optional(_validate.positive, "period", period, "m")
    chunk = _validate.integer("chunk", chunk, 1, "steps")
    live = (a > 0) & (p0 > 0) & (v > 0) & (dt > 0)
    idx = np.flatnonzero(live)
    h = np.zeros_like(x)
    if idx.size == 0 or k == 0.0:
        return h
    x0 = xi[idx]
    dxi = xi[idx + 1] - xi[idx]
    a_, p_, g = a[idx], p0[idx], k * v[idx] * dt[idx]           # g = k v_slip dt (m^3/N)
    # moving steps: exact time integral; near-still steps (|dxi| < 1e-6 a): p(x - xi) dt
    moving = np.abs(dxi) > 1e-6 * a_
    safe = np.where(moving, dxi, 1.0)
    for s0 in range(0, idx.size, chunk):
        sl = slice(s0, s0 + chunk)
        y = x[:, None] - x0[None, sl]
        if period is not None:
            y = (y + 0.5 * period) % period - 0.5 * period
        A, P0 = a_[None, sl], p_[None, sl]
        exact = (_ellipse_primitive(y, A, P0) - _ellipse_primitive(y - dxi[None, sl], A, P0)) / safe[None, sl]
        eta = np.clip(y / A, -1.0, 1.0)
        still = P0 * np.sqrt(1.0 - eta * eta)
        h += np.where(moving[None, sl], exact, still) @ g[sl]
    return h


def drift_sum(h, period: float, drift: float, cycles: float) -> np.ndarray:
    r"""Depth after ``cycles`` revolutions when each revolution shifts the pattern by ``drift``.

    ``h`` is the one-revolution depth on a uniform periodic grid ``x_j = j period / M``; the
    contact starts revolution n at ``n D`` (D = ``drift``), so

    .. math:: h_N(x) = \sum_{n=0}^{N-1} h(x - nD),\qquad
              \hat h_N(m) = \hat h(m)\,\frac{1 - z_m^N}{1 - z_m},\ z_m = e^{-2\pi i m D/P}

    (Fourier coefficients ``hat h(m)`` by FFT; ``z_m = 1`` gives ``N``). The grid function is
    interpreted as its trigonometric interpolant, so a shift by a non-grid ``D`` is exact for it.
    A non-integer ``cycles = N + f`` adds ``f`` times the pattern shifted by ``N D`` (a partial
    revolution as a share of the whole one, like ``cycles x depth`` does). The mean is
    ``cycles x mean(h)`` for any ``D``; for large N and ``D/P`` not close to a ratio of small
    integers the pattern smears towards that mean.

    Parameters
    ----------
    h : array_like, shape (M,)
        One-revolution depth on the uniform periodic grid [m].
    period : float
        Period ``P`` of the coordinate (roller circumference) [m], > 0.
    drift : float
        Shift ``D`` of the pattern per revolution [m].
    cycles : float
        Number of revolutions ``N`` [-], >= 0 (non-integer allowed).

    Returns
    -------
    ndarray, shape (M,), float
        Depth after ``cycles`` revolutions [m].

    Examples
    --------
    >>> import numpy as np
    >>> h = np.array([1.0, 0.0, 0.0, 0.0])
    >>> drift_sum(h, 4.0, 1.0, 4).round(12).tolist()       # shift by one cell per revolution
    [1.0, 1.0, 1.0, 1.0]
    >>> drift_sum(h, 4.0, 4.0, 3).round(12).tolist()       # D = period: phase-locked, 3 h
    [3.0, 0.0, 0.0, 0.0]
    """
    h = _validate.finite_array("h", h, "m")
    period = _validate.positive("period", period, "m")
    drift = _validate.number("drift", drift, "m")
    cycles = _validate.nonnegative("cycles", cycles, "revolutions")
    M = h.size
    n_full = int(np.floor(cycles))
    frac = cycles - n_full
    H = np.fft.rfft(h)
    m = np.arange(H.size)
    # phases as fractions of a turn, reduced before multiplying by 2 pi (keeps N m D/P accurate)
    f1 = np.mod(m * (drift / period), 1.0)
    z = np.exp(-2j * np.pi * f1)
    zN = np.exp(-2j * np.pi * np.mod(m * ((drift / period) * n_full % 1.0), 1.0))
    one = np.abs(1.0 - z) < 1e-12
    geo = np.where(one, float(n_full), (1.0 - zN) / np.where(one, 1.0, 1.0 - z))
    total = geo + frac * zN
    if M % 2 == 0:  # Nyquist term of a real signal: keep it real (cos of the shift)
        total[-1] = total[-1].real
    return np.fft.irfft(H * total, n=M)
