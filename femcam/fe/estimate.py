r"""A local a posteriori indicator of the FE stress error: the recovery (ZZ-type) jump of the
element stresses at each node (Zienkiewicz and Zhu 1987).

==============  ======================================================  =====
symbol          meaning                                                  unit
==============  ======================================================  =====
``sigma_e(n)``  in-plane stress of element ``e`` at its node ``n``        Pa
                (from the P2/P1 displacement field, discontinuous)
``sigma*(n)``   recovered nodal stress: the mean of ``sigma_e(n)`` over   Pa
                the ``m(n)`` elements around ``n`` (the field femcam
                reports, :func:`femcam.fe.elasticity.stress_operator`)
``eta(n)``      the indicator at node ``n``                               Pa
==============  ======================================================  =====

.. math:: \eta(n) = \Big(\frac{1}{m(n)} \sum_{e \ni n} \|\sigma_e(n) - \sigma^*(n)\|_F^2\Big)^{1/2},
          \qquad \|s\|_F^2 = s_{xx}^2 + s_{yy}^2 + 2 s_{xy}^2

The recovered stress is closer to the exact one than the element stresses (superconvergent
patch recovery), so the spread of the element stresses around it measures where the mesh is too
coarse for the stress field. It is local (a field, written to the VTU as ``err_est_stress_Pa``),
not a bound on a reported value: the sweep's ``err_est_*_pct`` columns come from the two-level
estimate of :mod:`femcam.sweep.estimate`.
"""

from __future__ import annotations

import numpy as np

from .elasticity import element_gradients

__all__ = ["zz_indicator"]


def zz_indicator(body, u: np.ndarray, gradients: tuple | None = None) -> np.ndarray:
    """The recovery indicator ``eta`` at every scalar node of one body.

    Parameters
    ----------
    body : femcam.fe.elasticity.Body
        The assembled body.
    u : ndarray of float, shape (2, n)
        Nodal displacements ``(u_x, u_y)`` [m] (:meth:`femcam.fe.ContactModel.full_field`).
    gradients : tuple, optional
        ``element_gradients(body)`` (:func:`femcam.fe.elasticity.element_gradients`), when the
        caller keeps it for several displacement fields of the body (a sweep's ``.vtu``
        files); default computed here.

    Returns
    -------
    ndarray of float, shape (n,)
        ``eta`` [Pa] (0 where all elements around a node agree).
    """
    dphi, sdofs, edofs, lam, mu, cnt = element_gradients(body) if gradients is None else gradients
    flat = np.empty(2 * u.shape[1])
    flat[0::2], flat[1::2] = u[0], u[1]
    uv = np.stack([flat[edofs[0::2]], flat[edofs[1::2]]])   # (2 [u, v], nloc, nel)
    g = np.einsum("jiek,cje->cike", dphi, uv)               # g[c, i]: d(u_c)/dx_i, (nloc, nel)
    (dudx, dudy), (dvdx, dvdy) = g
    s = np.stack([(lam + 2 * mu) * dudx + lam * dvdy,     # (3, nloc, nel) element stresses
                  lam * dudx + (lam + 2 * mu) * dvdy,
                  mu * (dudy + dvdx)])
    n = cnt.size
    avg = np.stack([np.bincount(sdofs.ravel(), c.ravel(), minlength=n) for c in s]) / np.maximum(cnt, 1)
    d = s - avg[:, sdofs]
    sq = d[0] ** 2 + d[1] ** 2 + 2 * d[2] ** 2
    return np.sqrt(np.bincount(sdofs.ravel(), sq.ravel(), minlength=n) / np.maximum(cnt, 1))
