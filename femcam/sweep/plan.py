r"""Model families, planning: which angles share one FE model (before verification).

2D linear elasticity is invariant under a uniform scaling of the geometry; from angle to angle
only the gap shape and the load change. So angles are grouped into families that share one
:class:`femcam.fe.ContactModel`: greedy clusters in the Hertz half-width ``a`` (ratio
``a_span``), then in the curvature ratio ``kappa = Rr/rho`` (width ``kappa_span``). The plan is
only a first guess; :mod:`femcam.sweep.verify` checks the reuse error of every family against
the tolerance and splits the families that exceed it.

The reuse error is a discretisation effect (two discretisations of the same problem that place
the contact edge differently relative to the nodes), of the order of the FE error itself
(~0.2 % at ``a_over_h = 10``). A tolerance far below it forces nearly one model per angle;
:data:`femcam.sweep.options.TOLERANCE_FLOOR` is the smallest accepted value; refine the mesh
(``a_over_h``) to make both errors smaller. Interior angles are not checked one by one: the
benchmark measures the error at independent angles (``benchmarks/bench_sweep.py``).
"""

from __future__ import annotations

import numpy as np

from .. import _validate
from ..hertz.conformity import sizing_half_width
from .options import ContactParams

__all__ = ["curvature_ratio", "family_reference", "family_spans", "hertz_half_width", "initial_groups",
           "plan_families"]


def hertz_half_width(F, rho, cp: ContactParams) -> np.ndarray:
    """Hertz half-width for sizing meshes, also where Hertz is invalid
    (:func:`femcam.hertz.conformity.sizing_half_width` with the scene's contact parameters).

    Parameters
    ----------
    F : ndarray
        Contact forces (N).
    rho : ndarray
        Cam radii of curvature (m).
    cp : ContactParams
        Roller radius, face width, materials.

    Returns
    -------
    ndarray
        ``a`` (m).
    """
    return sizing_half_width(F, cp.length, rho, cp.Rr, cp.E_star)


def curvature_ratio(rho, Rr: float) -> np.ndarray:
    """``kappa = Rr / rho`` (dimensionless; 0 for a flat cam).

    Parameters
    ----------
    rho : ndarray
        Cam radii of curvature (m).
    Rr : float
        Roller radius (m).

    Returns
    -------
    ndarray
        ``kappa``.
    """
    rho = np.asarray(rho, float)
    with np.errstate(divide="ignore"):
        return np.where(np.isfinite(rho), Rr / rho, 0.0)


def family_spans(tolerance: float) -> tuple[float, float]:
    """Initial ``(a_span, kappa_span)`` of one family for a reuse tolerance on p0.

    A family starts with the angles with ``max(a)/min(a) <= a_span`` and
    ``max(kappa) - min(kappa) <= kappa_span``, ``kappa = Rr/rho``. This is only the first
    guess (calibrated on the study model at a_over_h = 10: ``a_span = 1 + 125 tol``,
    ``kappa_span = min(400 tol, 0.95)``); :func:`verify_families` then splits every family whose
    measured reuse error exceeds the tolerance.

    Parameters
    ----------
    tolerance : float
        Bound on the relative p0 reuse error.

    Returns
    -------
    a_span : float
        Largest ``max(a)/min(a)`` of a starting family (>= 1).
    kappa_span : float
        Largest spread of ``Rr/rho`` (dimensionless).
    """
    return 1.0 + 125.0 * tolerance, min(400.0 * tolerance, 0.95)


def _clusters(v: np.ndarray, span, ratio: bool) -> np.ndarray:
    """Greedy 1D clustering of sorted values: a new cluster when v exceeds start * span
    (``ratio``) or start + span."""
    order = np.argsort(v, kind="stable")
    lab = np.empty(v.size, dtype=int)
    k, start = -1, None
    for j in order:
        x = v[j]
        if start is None or (x > start * span if ratio else x > start + span):
            k += 1
            start = x
        lab[j] = k
    return lab


def initial_groups(a, kappa, tolerance) -> list[np.ndarray]:
    """Initial groups: clusters in a, then in kappa (:func:`family_spans`).

    Parameters
    ----------
    a : ndarray, shape (m,)
        Hertz half-widths of the contact angles [m].
    kappa : ndarray, shape (m,)
        Curvature ratios ``Rr/rho`` [-].
    tolerance : float
        Reuse tolerance on p0 [-] (sets the spans).

    Returns
    -------
    list of ndarray of int
        Index arrays into ``a``/``kappa``, one per group.
    """
    a_span, k_span = family_spans(tolerance)
    la = _clusters(a, a_span, ratio=True)
    out = []
    for ca in range(la.max() + 1):
        sel = np.flatnonzero(la == ca)
        lk = _clusters(kappa[sel], k_span, ratio=False)
        for ck in range(lk.max() + 1):
            out.append(sel[lk == ck])
    return out


def family_reference(a, kappa, rho, Rr) -> tuple[float, float]:
    """``(rho_ref, a_ref)`` of a group: geometric centre of its a range, centre of its kappa
    range; a group of one load case gets exactly that load case's rho and a.

    Parameters
    ----------
    a : ndarray, shape (m,)
        Hertz half-widths of the group's load cases [m].
    kappa : ndarray, shape (m,)
        Their curvature ratios ``Rr/rho`` [-].
    rho : ndarray, shape (m,)
        Their cam radii of curvature [m].
    Rr : float
        Roller radius [m].

    Returns
    -------
    rho_ref : float
        Reference cam radius of curvature [m] (``inf`` for a flat cam).
    a_ref : float
        Reference half-width [m].
    """
    a_ref = float(np.sqrt(a.min() * a.max()))
    if kappa.min() == kappa.max():
        return float(rho[0]), a_ref
    k_ref = 0.5 * float(kappa.min() + kappa.max())
    return (Rr / k_ref if k_ref != 0.0 else float("inf")), a_ref


def contact_rows(F, rho, contact) -> tuple[np.ndarray, np.ndarray]:
    """``F`` and ``rho`` per angle as float arrays, checked where ``contact`` is set.

    Parameters
    ----------
    F, rho : array_like, shape (n,)
        Contact force [N] (``>= 0`` at the contact angles) and cam radius of curvature [m]
        (nonzero, ``inf`` flat); other angles (lift-off) may hold any number or NaN.
    contact : array_like of bool, shape (n,)
        Angles with contact.

    Returns
    -------
    F, rho : ndarray, shape (n,), float
        The checked arrays.

    Raises
    ------
    InputError
        Text, ``None``, inf where not allowed, a bad value at a contact angle, or a shape unlike
        ``contact``'s; the message names the argument.
    """
    F = _validate.data_array("F", F, "N")
    rho = _validate.data_array("rho", rho, "m", inf_ok=True)
    c = np.asarray(contact, dtype=bool)
    if F.shape != c.shape or rho.shape != c.shape:
        raise _validate.fail("F, rho", f"shapes {F.shape}, {rho.shape}", "", f"must match contact {c.shape}")
    _validate.nonnegative_array("F", F[c], "N")
    _validate.radius_array("rho", rho[c], "m")
    return F, rho


def plan_families(F, rho, cp: ContactParams, tolerance: float, contact: np.ndarray):
    """Initial (unverified) family id per angle (``-1`` where there is no contact) and references.

    Greedy clustering of the contact angles, first in the Hertz half-width ``a`` (ratio
    ``a_span``), then in the curvature ratio ``kappa = Rr/rho`` (width ``kappa_span``), see
    :func:`family_spans`. The plan depends only on the set of angles. :func:`verify_families`
    refines it.

    Parameters
    ----------
    F, rho : ndarray, shape (n,)
        Contact force (N) and cam radius of curvature (m) per angle.
    cp : ContactParams
    tolerance : float
        Reuse tolerance (sets the spans).
    contact : ndarray of bool, shape (n,)
        Angles with contact.

    Returns
    -------
    family : ndarray of int, shape (n,)
        Family id per angle (-1: no contact).
    refs : dict[int, tuple[float, float]]
        ``refs[fid] = (rho_ref (m), a_ref (m))``.
    """
    F, rho = contact_rows(F, rho, contact)
    tolerance = _validate.positive("tolerance", tolerance, "")
    _validate.record("cp", cp, "a ContactParams (femcam.sweep.options.contact_params)", "Rr", "length")
    fam = np.full(F.shape, -1, dtype=int)
    refs: dict[int, tuple[float, float]] = {}
    idx = np.flatnonzero(contact)
    if idx.size == 0:
        return fam, refs
    a = hertz_half_width(F[idx], rho[idx], cp)
    kappa = curvature_ratio(rho[idx], cp.Rr)
    for n, g in enumerate(initial_groups(a, kappa, tolerance)):
        refs[n] = family_reference(a[g], kappa[g], rho[idx][g], cp.Rr)
        fam[idx[g]] = n
    return fam, refs
