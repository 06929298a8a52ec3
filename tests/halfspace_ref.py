"""Independent references shared by the real-cam tests (tests/test_fe_gap.py,
tests/test_sweep_real_cam.py): a half-space influence-coefficient line-contact solve and the cam
surface as the envelope of roller circles. Written from Johnson 1985 eq. 2.25b and the envelope
definition; they use no femcam code."""

from __future__ import annotations

import functools
import math

import numpy as np


# ----------------------------------------------------------------- independent references
def _G(t):
    """Antiderivative of ln|t|: t ln|t| - t (0 ln 0 = 0)."""
    at = np.abs(t)
    return np.where(at > 0, t * np.log(np.where(at > 0, at, 1.0)), 0.0) - t


@functools.lru_cache(maxsize=4)
def _kernel(xmax, n, E_star):
    e = np.linspace(-xmax, xmax, n + 1)
    xc, dx = 0.5 * (e[1:] + e[:-1]), np.diff(e)
    A = -(2.0 / (math.pi * E_star)) * (_G(xc[:, None] - e[None, :-1]) - _G(xc[:, None] - e[None, 1:]))
    return xc, dx, A


def halfspace_solve(h0, W, E_star, xmax, n=500):
    """Line contact on two elastic half-spaces (Johnson 1985 eq. 2.25b for each body, summed):
    relative normal displacement -(2/(pi E*)) int p ln|x - s| ds + C; uniform-pressure strips,
    collocation at strip centres, active set on the strips. Returns strip centres and p."""
    xc, dx, A = _kernel(float(xmax), n, float(E_star))
    g0 = h0(xc)
    act = g0 <= np.sort(g0)[int(0.4 * n)]
    for _ in range(200):
        idx = np.nonzero(act)[0]
        m = idx.size
        M = np.zeros((m + 1, m + 1))
        M[:m, :m], M[:m, m], M[m, :m] = A[np.ix_(idx, idx)], -1.0, dx[idx]
        sol = np.linalg.solve(M, np.concatenate([-g0[idx], [W]]))
        p = np.zeros(n)
        p[idx] = sol[:m]
        g = g0 + A @ p - sol[m]
        new = p - g / np.mean(np.diag(A)) > 0.0  # primal-dual update of the contact set
        if np.array_equal(new, act):
            assert p.min() >= 0.0 and g.min() >= -1e-12 * g0.max(), "reference: not complementary"
            return xc, p
        act = new
    raise AssertionError("reference half-space solve did not settle")


def envelope_height(program, Rr, Rb, theta, x, n=40001, window=0.2):
    """Cam surface height y_c(x) in the contact frame at ``theta`` from its definition: the cam
    lies below every roller position, so y_c(x) is the lowest bottom arc over all roller
    circles whose centres run on the pitch curve
    (cam frame: R(-t) (0, Rb + Rr + s(t)), in-line follower), seen in the frame of ``theta``."""
    t = theta + np.linspace(-window, window, n)
    s = program.derivatives(t).s
    rp = Rb + Rr + s
    # centres in the fixed frame at theta: rotate the cam by (theta - t)
    d = theta - t
    cx, cy = -rp * np.sin(d), rp * np.cos(d)
    s0, s1 = program.derivatives(np.array([theta])).s[0], program.derivatives(np.array([theta])).s1[0]
    phi = math.atan2(s1, Rb + Rr + s0)
    c0 = np.array([0.0, Rb + Rr + s0]) - Rr * np.array([-math.sin(phi), math.cos(phi)])
    tv, nv = np.array([math.cos(phi), math.sin(phi)]), np.array([-math.sin(phi), math.cos(phi)])
    X, Y = cx - c0[0], cy - c0[1]
    xl, yl = X * tv[0] + Y * tv[1], X * nv[0] + Y * nv[1]
    out = np.empty(len(x))
    for i, xi in enumerate(x):
        ok = np.abs(xi - xl) < Rr
        out[i] = np.min(yl[ok] - np.sqrt(Rr**2 - (xi - xl[ok]) ** 2))
    return out
