"""Pin in a hole with clearance, small to large contact arcs: femcam's ring-pin solution against
an independent series solution of the conformal contact problem written here.

The reference is Persson's (1964) problem (Ciavarella & Decuzzi 2001 give a closed-form
approximation for a pin in an infinite plate; its printed formulas were not available here, so the
same problem is solved numerically, for the femcam geometry: a finite ring loaded by the cam),
written from first principles:

* **Elasticity per Fourier mode** (Michell 1899; Barber 2010 ch. 8-9 for the displacements):
  for a load ``cos(n theta)`` (n >= 2) the Airy function ``f(r) cos(n theta)`` with
  ``f = r^n, r^-n, r^(n+2), r^(2-n)`` gives, with ``kappa = 3 - 4 nu`` (plane strain),
  ``sigma_rr = (m - n^2) r^(m-2) cos``, ``sigma_rt = n (m - 1) r^(m-2) sin`` and
  ``2G u_r = alpha_m r^(m-1) cos``, ``alpha = -n, n, kappa - n - 1, kappa + n - 1``
  (``2G u_t = beta_m r^(m-1) sin``, ``beta = n, n, kappa + n + 1, -(kappa - n + 1)``;
  checked against Hooke's law by finite differences in ``test_michell_modes_satisfy_hooke``).
  The **ring** is the annulus ``Ri <= r <= Ro`` (bore pressure ``p``, the cam's point force
  ``W`` on ``r = Ro`` at the load line, traction-free otherwise); the **pin** is the disk
  ``r <= Rp`` clamped on ``r <= rc`` (as femcam holds the stud: ``rc = 0.2 Rp``) or rigid.
  Mode 0 is Lamé's thick cylinder. Mode 1 moves the bore as a rigid translation
  (``u_r ~ cos(theta)``): it is absorbed by the unknown pin-ring approach ``e``.
* **Contact** (linearised clearance gap, as for a pin in a hole with ``c << Ri``):
  ``g(psi) = c - e cos(psi) + u_ring(psi) - u_pin(psi) = 0`` on ``|psi| <= alpha`` and
  ``p >= 0``, with ``p`` P1 on a uniform grid of ``N`` nodes (hat Fourier coefficients
  ``h/pi sinc^2(n h / 2)``, modes summed to ``64 N``, folded onto the grid by FFT), the gap
  collocated at the nodes and the arc ``alpha = k h`` found by bisection on ``k`` from the
  bounded-edge condition (gap zero at the first unloaded node). ``W = int p cos(psi) Ri dpsi``.
  Not an active-set method, no FE: independent of femcam.
* **Check of the reference**: for an infinite plate and a free pin at a small arc it gives the
  conformal Hertz values (Johnson 1985 §4.3, ``1/R = 1/Rp - 1/Ri``): W within 0.5 % and
  p0 within 0.5 % at alpha = 4-8 deg (``test_series_reference_reduces_to_conformal_hertz``).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

NU, E = 0.3, 210e9


def _terms(n, r, r_in, r_out, kap):
    """Rows (n, 4) of sigma_rr, sigma_rt, 2G u_r, 2G u_t coefficients of the four Michell terms
    ``r^m cos(n theta)``, m = n, -n, n+2, 2-n, scaled by ``r_out^-n`` (growing) or ``r_in^n``."""
    ms = [n, -n, n + 2, 2 - n]
    lnk = [-n * np.log(r_out), n * np.log(r_in), -n * np.log(r_out), n * np.log(r_in)]
    al = [-n, n, kap - n - 1, kap + n - 1]
    be = [n, n, kap + n + 1, -(kap - n + 1)]
    rows = [[], [], [], []]
    for m, lk, a, b in zip(ms, lnk, al, be, strict=True):
        rm2 = np.exp((m - 2) * np.log(r) + lk)
        vals = ((m - n * n) * rm2, n * (m - 1) * rm2, a * rm2 * r, b * rm2 * r)
        for row, v in zip(rows, vals, strict=True):
            row.append(v)
    return [np.stack(x, axis=-1) for x in rows]


def ring_modes(n, rho, nu=NU):
    """Annulus 1 <= r <= rho: 2G u_r(1) per unit bore pressure and per unit outer pressure."""
    kap = 3 - 4 * nu
    s1, t1, u1, _ = _terms(n, 1.0, 1.0, rho, kap)
    s2, t2, _, _ = _terms(n, rho, 1.0, rho, kap)
    M = np.stack([s1, t1, s2, t2], axis=1)
    rhs = np.zeros((n.size, 4, 2))
    rhs[:, 0, 0] = rhs[:, 2, 1] = -1.0
    U = np.einsum("nk,nkj->nj", u1, np.linalg.solve(M, rhs))
    return U[:, 0], U[:, 1]


def pin_modes(n, rc, nu=NU):
    """Disk r <= 1, clamped on r <= rc (rc = 0: free), unit surface pressure: -2G u_r(1)."""
    kap = 3 - 4 * nu
    if rc == 0:
        s, t, u, _ = _terms(n, 1.0, 1.0, 1.0, kap)
        M = np.stack([s[:, [0, 2]], t[:, [0, 2]]], axis=1)
        X = np.linalg.solve(M, np.tile([[-1.0], [0.0]], (n.size, 1, 1)))[..., 0]
        return -np.einsum("nk,nk->n", u[:, [0, 2]], X)
    s, t, u, _ = _terms(n, 1.0, rc, 1.0, kap)
    _, _, uc, vc = _terms(n, rc, rc, 1.0, kap)
    b = np.zeros((n.size, 4, 1))
    b[:, 0, 0] = -1.0
    X = np.linalg.solve(np.stack([s, t, uc, vc], axis=1), b)[..., 0]
    return -np.einsum("nk,nk->n", u, X)


def kernels(Ri, Ro, N, pin, rc=0.2, nu=NU, n_fold=64):
    """Circulant gap kernel K[k] (m/Pa: gap opening at psi = k h per unit nodal bore pressure,
    ring + pin) and ``uq`` (m per N/m: bore opening of a unit cam point force at psi = 0)."""
    G = E / (2 * (1 + nu))
    h = 2 * math.pi / N
    n = np.arange(2, n_fold * N, dtype=float)
    Cb, Ct = ring_modes(n, Ro / Ri, nu)
    C = Ri * Cb / (2 * G)
    rho2 = (Ro / Ri) ** 2
    B = -1.0 / (1 - 1 / rho2)  # Lame: sigma_rr = A + B/r^2, bore pressure 1, outer free
    C0 = Ri * ((1 - 2 * nu) * (-1.0 - B) - B) / (2 * G)
    if pin == "elastic":  # pressure Ri/Rp on the pin of radius Rp: opening Ri * (.) / 2G
        C = C + Ri * pin_modes(n, rc, nu) / (2 * G)
        A0 = -1.0 / (1 + (1 - 2 * nu) * rc**2) if rc else -1.0
        C0 -= Ri * (1 - 2 * nu) * A0 * (1 - rc**2) / (2 * G)
    b = np.zeros(N)
    np.add.at(b, n.astype(int) % N, h / math.pi * np.sinc(n * h / (2 * math.pi)) ** 2 * C)
    b[0] += h / (2 * math.pi) * C0
    K = np.real(np.fft.fft(b))
    psi = h * np.arange(N)
    Bq = 1.0 / (1 - 1 / rho2)  # outer pressure 1, bore free: A + B/rho^2 = -1, A + B = 0
    uq = Ri * ((1 - 2 * nu) * (-Bq) - Bq) / (2 * G) / (2 * math.pi * Ro) + np.zeros(N)
    m = slice(0, 300)  # the cam load's modes decay as (Ri/Ro)^n at the bore
    uq += (Ri * Ct[m] / (2 * G) / (math.pi * Ro)) @ np.cos(np.outer(n[m], psi))
    return K, uq, h


def _arc(K, uq, h, c, Ri, k):
    """Symmetric solution with contact nodes |j| < k (pressure) and gap 0 on |j| <= k:
    returns (W, nodal pressures p_0..p_{k-1})."""
    N = K.size
    i, j = np.arange(k), np.arange(k + 1)
    M = K[(j[:, None] - i[None, :]) % N] + (i[None, :] > 0) * K[(j[:, None] + i[None, :]) % N]
    wt = Ri * h * np.sinc(h / (2 * math.pi)) ** 2 * np.cos(i * h) * np.where(i > 0, 2, 1)
    M = np.hstack([M + uq[j][:, None] * wt[None, :], -np.cos(j * h)[:, None]])
    p = np.linalg.solve(M, np.full(k + 1, -c))[:k]
    return float(wt @ p), p


def conformal_reference(W, kern, *, Ri, c):
    """(alpha (rad), p0 (Pa)) for the bore load W (N/m) on ``kern = kernels(...)``: bisection on
    the arc index, then linear interpolation between the two bracketing arcs (alpha resolved to
    the reference grid spacing h = 2 pi / N)."""
    K, uq, h = kern
    N = K.size
    lo, hi = 1, N // 4 - 1
    W_hi, _ = _arc(K, uq, h, c, Ri, hi)
    assert 0 < W <= W_hi or W_hi < 0, "load beyond the reference's arc range"
    while hi - lo > 1:
        mid = (lo + hi) // 2
        Wm, _ = _arc(K, uq, h, c, Ri, mid)
        lo, hi = (mid, hi) if 0 < Wm < W else (lo, mid)
    (W0, p_lo), (W1, p_hi) = _arc(K, uq, h, c, Ri, lo), _arc(K, uq, h, c, Ri, hi)
    f = (W - W0) / (W1 - W0)
    return (lo + f) * h, (1 - f) * p_lo[0] + f * p_hi[0]


def test_michell_modes_satisfy_hooke():
    """Each Michell term's displacement gives, by finite differences, the strains of its
    stresses through plane-strain Hooke's law (so the typed-in table is right)."""
    kap, r, th, d = 3 - 4 * NU, 1.3, 0.4, 1e-6
    for n in (2.0, 3.0, 7.0):
        for j in range(4):
            def u(rr, tt, j=j, n=n):
                _, _, ur, ut = _terms(np.array([n]), rr, 1.0, 1.0, kap)
                return ur[0, j] * np.cos(n * tt), ut[0, j] * np.sin(n * tt)  # 2G u, G = 1/2
            s, t, _, _ = _terms(np.array([n]), r, 1.0, 1.0, kap)
            srr, srt = s[0, j] * np.cos(n * th), t[0, j] * np.sin(n * th)
            m = [n, -n, n + 2, 2 - n][j]
            stt = m * (m - 1) * r ** (m - 2) * np.cos(n * th)
            e_rr = (u(r + d, th)[0] - u(r - d, th)[0]) / (2 * d)
            e_tt = (u(r, th)[0] + (u(r, th + d)[1] - u(r, th - d)[1]) / (2 * d)) / r
            g_rt = ((u(r, th + d)[0] - u(r, th - d)[0]) / (2 * d) / r
                    + (u(r + d, th)[1] - u(r - d, th)[1]) / (2 * d) - u(r, th)[1] / r)
            tr = NU * (srr + stt)
            np.testing.assert_allclose([e_rr, e_tt, g_rt], [srr - tr, stt - tr, 2 * srt], atol=1e-7)


def test_series_reference_reduces_to_conformal_hertz():
    """Infinite plate (Ro = 1000 Ri) and a free pin, Ri = 7 mm, c = 10 um: at alpha = 4-8 deg
    the series solution is conformal Hertz (E* = E / (2 (1 - nu^2)), R = Rp Ri / c); it departs
    as the arc grows (measured at 15 deg: a -1.7 %, p0 +2.8 %: Hertz's half-space overestimates the
    arc of a conformal contact, as Persson 1964 found). Tolerance 1 %: the grid (h = 0.25 deg, 16
    nodes per half-arc at 4 deg: a +0.7 % measured) and the O(alpha^2) departure of Hertz."""
    Ri, c = 0.007, 10e-6
    Es = E / (2 * (1 - NU**2))
    R = (Ri - c) * Ri / c
    kern = kernels(Ri, 1e3 * Ri, 1440, "elastic", rc=0.0)
    for W in (4.4e3, 1.67e4, 6.7e4):
        alpha, p0 = conformal_reference(W, kern, Ri=Ri, c=c)
        a = math.sqrt(4 * W * R / (math.pi * Es))
        da, dp = Ri * alpha / a - 1, p0 / (2 * W / (math.pi * a)) - 1
        if alpha < math.radians(10):
            assert abs(da) < 0.01 and abs(dp) < 0.01, (math.degrees(alpha), da, dp)
        else:  # 15 deg: the exact conformal solution departs from Hertz, in Persson's direction
            assert da < -0.01 and dp > 0.02, (math.degrees(alpha), da, dp)


# ------------------------------------------------------------------- femcam against the reference

#: bore loads W (N/m) on Ri = 7 mm, c = 10 um: half-arcs from ~6 deg (Hertz-like) to ~70 deg
LOADS = (2e4, 2e5, 1e6, 4e6, 1.5e7)


def _femcam(pin, n_bore=256):
    from femcam.bodies import RingMeshOptions, RingModel, RollerBearing, solve_ring
    from femcam.materials import STEEL
    from femcam.mesh import MeshOptions

    Ri, c, L = 0.007, 10e-6, 0.01
    b = RollerBearing(Ro=6 * Ri, Ri=Ri, support="pin", Rp=Ri - c, c=c,
                      pin=STEEL if pin == "elastic" else None)
    m = RingModel.build(bearing=b, cam=STEEL, rho_ref=0.05, a_ref=2.4e-3, length=L,
                        ring_mesh=RingMeshOptions(n_bore=n_bore), mesh=MeshOptions(a_over_h=4))
    return m, [solve_ring(m, F=W * L, rho=0.05) for W in LOADS]


@pytest.mark.slow
@pytest.mark.parametrize("pin", ["rigid", "elastic"])
def test_pin_contact_arc_and_peak_match_the_conformal_series_small_to_large_arcs(pin):
    """Thick ring (Ro = 6 Ri = 42 mm, the cam force on its outer surface), Ri = 7 mm, c = 10 um,
    n_bore = 256 (1.41 deg): half-arc alpha and peak bore pressure over W = 20 kN/m .. 15 MN/m.

    * alpha: the reference edge must lie between femcam's last loaded node and the next node
      (femcam's arc is nodal: ``pin_arc / 2 <= alpha < pin_arc / 2 + h_bore``), widened by the
      reference grid (0.125 deg) and 0.5 deg of mesh error (taken from the run: the elastic pin
      at 15 MN/m, 73 deg, lies 0.47 deg beyond the reference bracket; all others <= 0.3 deg).
    * p0 (the bore node on the load line): within 0.5 % (rigid pin: measured <= 0.03 %).
    * elastic pin: femcam clamps the pin's mesh vertices with r <= 0.2 Rp (three vertices of
      this mesh, at 0.10, 0.14, 0.20 Rp), not the whole core circle; the stud model is
      therefore bracketed by two references, clamped on r <= 0.2 Rp and on r <= 0.05 Rp (they
      differ by 1.1 % in p0 and 0.8 deg in alpha at 72 deg, measured), and femcam must lie in
      that bracket widened by the same tolerances (measured: p0 -1.3 % from the rc = 0.2
      reference, -0.3 % from rc = 0.05).

    The finite ring matters: the arc saturates below 90 deg (~78 deg for this ring, measured in
    the reference), unlike Persson's infinite plate, because the cam force is 5 Ri from the bore.
    """
    m, res = _femcam(pin)
    kerns = [kernels(0.007, 0.042, 2880, pin, rc=rc) for rc in ((0.2, 0.05) if pin == "elastic" else (0.2,))]
    hb = 2 * math.pi / m.theta.size
    k0 = int(np.argmin(np.abs(np.angle(np.exp(1j * (m.theta + 0.5 * math.pi))))))
    slack = math.radians(0.125 + 0.5)
    for W, r in zip(LOADS, res, strict=True):
        ref = np.array([conformal_reference(W, k, Ri=0.007, c=10e-6) for k in kerns])
        lo, hi = r.pin_arc / 2, r.pin_arc / 2 + hb
        assert lo - slack <= ref[:, 0].max() and ref[:, 0].min() <= hi + slack, (
            W, np.degrees(ref[:, 0]), math.degrees(lo), math.degrees(hi))
        p_fe = r.bore_p[k0]
        assert ref[:, 1].min() * (1 - 0.005) <= p_fe <= ref[:, 1].max() * (1 + 0.005), (W, p_fe, ref[:, 1])
        assert abs(-(m.wb * np.sin(m.theta)) @ r.bore_p / W - 1) < 1e-9, "the pin carries the cam load"
