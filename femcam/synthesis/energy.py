r"""Energy, residual and consistent tangent of the seed-003 PE-FEM (shape functions, the
periodic quadratic discretisation, the stabilisation psi(a11)); symbols as in
:mod:`femcam.synthesis.pefem`.

Derivation and the seed's typos (checked against a finite-difference Jacobian in the tests)
-----------------------------------------------------------------------------------------
* **alpha.** Eq. 2, ``alpha = acos(d . x1)``, only covers [0, pi]: it folds the lower half
  plane onto the upper one, so ``y_o(alpha)`` is mirror-symmetric about x and a 360 deg
  program (120 deg rise, ...) cannot be represented; its derivative produces the
  ``1/sqrt(1 - cos^2 alpha) = 1/|sin alpha|`` factor of ``c1`` (eq. 17), singular at
  alpha = 0, pi. We use the polar angle ``alpha = atan2(x_2, x_1)`` with
  ``grad alpha = t/|x|``, regular everywhere.
* **b (eqs. 15-17).** ``grad e = b = d - y_o'(alpha) t/|x|``. The paper's ``d + B r`` is the
  gradient of the folded-acos error; it equals ours only for sin(alpha) > 0 (``B x = 0``, so
  the ``x`` in ``r`` contributes nothing).
* **E (eqs. 27-29).** Exact Hessian of e:
  ``E = t(x)t/|x| - y_o'' t(x)t/|x|^2 + y_o' (d(x)t + t(x)d)/|x|^2``. The paper's middle
  term ``B(r(x)d - d(x)r)B`` is identically zero (``B d = 0``), the ``d(x)t`` coupling is
  missing, and ``c2`` carries a spurious ``1/|sin alpha|`` and the wrong sign on ``y_o''``.
* **Stabilisation (eqs. 12, 18, 32, 34).** Eq. 18 is the variation of Sauer's (2016) energy
  ``psi = 1/2 (A^11 a11 - 1 - ln(a11/A11))`` (no square), and its ``(A^11 - a_11)`` must read
  ``(A^11 - a^11)`` with the *contravariant* ``a^11 = 1/a11`` (dimensionally required). Eq. 32
  /34 are then the exact linearisation. Eq. 12 as printed (squared) is available as
  ``stabilization="eq12"``; we differentiate it exactly too.
* **Pressure angle (eqs. 10, 40).** ``a1/|a1|`` is the unit *tangent*, not the normal, so eq.
  40 as printed gives 90 deg - phi. We use ``phi = atan2(d . a1, t . a1)``, i.e.
  ``tan phi = r'/r`` for the polar curve (Norton, *Design of Machinery*, ch. 8).
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from ..errors import ConvergenceError


# --------------------------------------------------------------------------- element kernel
def _shape(nq):
    """Quadratic Lagrange shape functions on eta in [-1, 1] and Gauss rule (nq points)."""
    eta, w = np.polynomial.legendre.leggauss(nq)
    N = np.stack([eta * (eta - 1) / 2, 1 - eta**2, eta * (eta + 1) / 2], axis=1)
    dN = np.stack([eta - 0.5, -2 * eta, eta + 0.5], axis=1)
    return N, dN, w


class _Discretisation:
    """Periodic quadratic mesh of the unit base circle (lengths scaled by R_b)."""

    def __init__(self, ne, nq):
        self.ne, self.nn = ne, 2 * ne
        self.xi_nodes = 2 * np.pi * np.arange(self.nn) / self.nn
        self.X = np.stack([np.cos(self.xi_nodes), np.sin(self.xi_nodes)], axis=1)
        self.conn = (2 * np.arange(ne)[:, None] + np.arange(3)[None, :]) % self.nn
        N, dN, w = _shape(nq)
        J = np.pi / ne                      # dxi/deta, element length in xi is 2 pi / ne
        self.N, self.dN, self.w = N, dN / J, w * J
        Xe = self.X[self.conn]
        self.A11 = np.einsum("qa,eai->eqi", self.dN, Xe)
        self.A11 = np.einsum("eqi,eqi->eq", self.A11, self.A11)
        dofs = (2 * self.conn[:, :, None] + np.arange(2)[None, None, :]).reshape(ne, 6)
        self.dofs = dofs
        self.rows = np.repeat(dofs, 6, axis=1).ravel()
        self.cols = np.tile(dofs, (1, 6)).ravel()


def _stab(a11, A11, mu, kind):
    """psi(a11) and its first two derivatives in a11 (per unit dxi)."""
    if kind == "sauer":        # Sauer (2016): mu/2 (A^11 a11 - 1 - ln(a11/A11)); eq. 18 form
        psi = 0.5 * mu * (a11 / A11 - 1.0 - np.log(a11 / A11))
        d1 = 0.5 * mu * (1.0 / A11 - 1.0 / a11)
        d2 = 0.5 * mu / a11**2
    else:                      # eq. 12 as printed: mu/2 (A^11 a11 - ln(a11/A11))^2
        g = a11 / A11 - np.log(a11 / A11)
        g1 = 1.0 / A11 - 1.0 / a11
        psi = 0.5 * mu * g**2
        d1 = mu * g * g1
        d2 = mu * (g1**2 + g / a11**2)
    return psi, d1, d2


def _evaluate(u, D, law, k, mu, kind, want_tangent=True):
    """Energy, residual R = dPi/du and tangent K = d2Pi/du2 (u: (nn, 2), scaled)."""
    xe = u[D.conn]
    x = np.einsum("qa,eai->eqi", D.N, xe)
    a1 = np.einsum("qa,eai->eqi", D.dN, xe)
    rho = np.hypot(x[..., 0], x[..., 1])
    if np.any(rho <= 1e-12):
        raise ConvergenceError("the cam curve passed through the cam centre", [])
    d = x / rho[..., None]
    t = np.stack([-d[..., 1], d[..., 0]], axis=-1)
    alpha = np.mod(np.arctan2(x[..., 1], x[..., 0]), 2 * np.pi)
    s, s1, s2 = law(alpha)
    e = rho - 1.0 - s                                  # eq. 8 minus eq. 1 (scaled)
    b = d - (s1 / rho)[..., None] * t                  # grad e (corrects eqs. 16-17)
    a11 = np.einsum("eqi,eqi->eq", a1, a1)
    if np.any(a11 <= 0):
        raise ConvergenceError("an element collapsed (a11 <= 0)", [])
    psi, p1, p2 = _stab(a11, D.A11, mu, kind)
    w = D.w[None, :]
    energy = float(np.sum(w * (0.5 * k * e**2 + psi)))
    gx = (k * e)[..., None] * b                        # dPi_p/dx   (eq. 15)
    ga = (2 * p1)[..., None] * a1                      # dPi_s/da1  (eq. 18 with a^11)
    Re = (np.einsum("q,qa,eqi->eai", D.w, D.N, gx) + np.einsum("q,qa,eqi->eai", D.w, D.dN, ga))
    R = np.zeros((D.nn, 2))
    np.add.at(R, D.conn, Re)
    if not want_tangent:
        return energy, R.ravel(), None
    # Hessian of e: E = t t/rho - s2 t t/rho^2 + s1 (d t + t d)/rho^2   (corrects eq. 28)
    tt = np.einsum("eqi,eqj->eqij", t, t)
    dt = np.einsum("eqi,eqj->eqij", d, t)
    E = ((1.0 / rho - s2 / rho**2)[..., None, None] * tt
         + (s1 / rho**2)[..., None, None] * (dt + np.swapaxes(dt, -1, -2)))
    Hx = k * (np.einsum("eqi,eqj->eqij", b, b) + e[..., None, None] * E)        # eq. 31
    Ha = ((4 * p2)[..., None, None] * np.einsum("eqi,eqj->eqij", a1, a1)
          + (2 * p1)[..., None, None] * np.eye(2))                             # eq. 34 (fixed)
    Ke = (np.einsum("q,qa,qb,eqij->eaibj", D.w, D.N, D.N, Hx)
          + np.einsum("q,qa,qb,eqij->eaibj", D.w, D.dN, D.dN, Ha)).reshape(D.ne, 36)
    n = 2 * D.nn
    K = sp.csc_matrix((Ke.ravel(), (D.rows, D.cols)), shape=(n, n))
    # positive semi-definite "Gauss-Newton" tangent for the globalisation phase: drop the
    # k e E curvature term and the compressive part of the stabilisation (psi' < 0)
    Hx_gn = k * np.einsum("eqi,eqj->eqij", b, b)
    Ha_gn = Ha - (2 * np.minimum(p1, 0.0))[..., None, None] * np.eye(2)
    Kg = (np.einsum("q,qa,qb,eqij->eaibj", D.w, D.N, D.N, Hx_gn)
          + np.einsum("q,qa,qb,eqij->eaibj", D.w, D.dN, D.dN, Ha_gn)).reshape(D.ne, 36)
    Kgn = sp.csc_matrix((Kg.ravel(), (D.rows, D.cols)), shape=(n, n))
    return energy, R.ravel(), (K, Kgn)
