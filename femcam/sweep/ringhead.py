r"""The roller on a pin or needles answers the headline: the ring model's contact, global-local.

A scene with ``roller_support = "pin"`` or ``"needles"`` asks for the real track roller: an
outer ring on its pin or needles (:mod:`femcam.bodies`). Its cam contact is solved by the
scene's :class:`~femcam.bodies.RingModel` (one per process, graded for the largest force,
:func:`femcam.sweep.providers.ring_model`), and that solve answers the row's headline:

=====================  =====================================================================
column                 on a ring row
=====================  =====================================================================
``p0_fe``              the peak of the ring model's solved cam-contact pressure
``p0_fit``, ``a_fe``   the Hertz ellipse fitted to that pressure (a fit, as on every row)
``err_p0``, ``err_a``  against ``p0_hertz``, ``a_hertz``: Hertz of the *solid* roller, the
                       reference, so the difference is the ring's effect plus the FE's error
stresses, depths       the row's solid-roller answer (FE, or the Hertz shape factors on a
                       ``hertz`` row) scaled to the ring's contact: stresses (``vm_max``,
                       ``tau1_max``, ``txz_range_max``, ``surf_*``) by ``k_p = p0_ring /
                       p0_solid``, depths (``*_depth``) and ``stick_width`` by ``k_a = a_ring
                       / a_solid``
``model``              the solid row's model with ``+ring`` (``fe_arc+ring``,
                       ``fe_exact+ring``, ``hertz+ring``)
=====================  =====================================================================

Why the stresses may be scaled (the global-local step): the elastic field of a contact is
linear in its pressure, and a pressure of the same shape ``p0 f(x / a)`` gives stresses
``p0 S(x / a, z / a)`` (Johnson 1985 §2.6, §4.2): the maxima scale with ``p0`` and their depths
with ``a``. The ring changes the contact's compliance far from it (bending of the ring, the
needles), so within the contact the pressure stays the ellipse of the solid roller at a
slightly different ``(a, p0)``: on a 1 mm wall on 20 needles (``tests/test_sweep_ring.py``) the
ring lowers p0 by 1.68 % from the solid roller's, and its peak stays within 0.02 % of the
ellipse fitted to it. The fine details of the
solid answer (the exact gap at a curvature jump, the partial-slip traction; the ring model is
frictionless on the osculating arc) stay in the scaled stresses; ``p0_fe`` is the ring
model's own peak.

Error estimates (``err_est_*``, docs/estimate.md) on a ring row: ``p0_fe`` and ``a_fe`` are the
ring model's, so the ring model's **own** two-level estimate answers them
(:func:`ring_level_estimate`: one second ring model per process, its cam-contact zone coarse,
``H = 2 h``, and its ring and pin fine, twice the bore vertices), carried to the row's resolution
``n = 20 a_ring / a_ref_ring`` (``a_over_h_row``): ``e = e_ref (20 / n)^p`` (no reuse error: the
ring model is solved at the row's own load). The scaled stresses carry three errors,
``err_est_vm = e_vm,solid + e_p0,ring + e_p0,solid`` (likewise tau1; NaN on a ``hertz+ring`` row,
whose stresses are Hertz's shape factors). The ring's own stresses get ``err_est_bore_hoop``,
``err_est_pin_p0``, ``err_est_needle_Q`` from the refined ring (:func:`ring_side_estimates`).
Checked on the thick ring on a tight pin against Hertz and against a ring of 512 bore vertices
(``tests/test_sweep_ring.py``).

Cost: the ring model built and solved for the bore and needle columns is the one the headline
reads (the solid-roller families answer the stresses); the estimate adds one second ring model
per process (its cost: docs/estimate.md). With ``--method auto`` the rows Hertz answers need
no FE model at all, so a ring scene then costs the ring models alone.
"""

from __future__ import annotations

import math

import numpy as np

from ..bodies import RingMeshOptions, RingModel
from ..bodies.rows import CSV_COLUMNS as RING_COLUMNS
from ..bodies.rows import cage_solves, ring_rows
from ..errors import FemcamError
from ..materials import effective_modulus
from ..mesh import MeshOptions
from .estimate import QUANTITIES, RATES, FamilyEstimate, coarse_mesh
from .providers import RING_ESTIMATES, RING_HEADLINE_KEYS, _cached, has_support, ring_model

#: elements per reference half-width of the ring model's contact mesh (``ring_model`` builds
#: with the default MeshOptions, :func:`femcam.bodies.rows.build_for`)
RING_A_OVER_H = MeshOptions().a_over_h

#: stress columns scaled by ``p0_ring / p0_solid`` and length columns by ``a_ring / a_solid``
SCALED_BY_P0 = ("vm_max", "tau1_max", "txz_range_max", "surf_sx_min", "surf_sx_max", "surf_sz_min",
                "surf_txz_absmax")
SCALED_BY_A = ("vm_depth", "tau1_depth", "txz_range_depth", "stick_width")
#: the ring's side columns (bore, pin, needles); the contact keys answer the headline
#: (:data:`femcam.sweep.providers.RING_HEADLINE_KEYS`)
SIDE_KEYS = tuple(k for k in RING_COLUMNS if k not in RING_HEADLINE_KEYS)


#: the ring model's quantities of the two-level estimate (:func:`ring_level_estimate`) and the
#: rates used: the contact's as the solid families' (:data:`femcam.sweep.estimate.RATES`); the
#: ring's own (bore hoop stress, pin contact peak, needle load) 1, below the measured rates of
#: these quantities under bore refinement (hoop beside a needle on the load line 0.8, a
#: concentrated load on the bore; between two needles, the reported cage, 1 with the needle
#: spread held fixed; docs/bodies.md), so the estimate stays on the safe side
RING_RATES = {"p0": RATES["p0"], "a": RATES["a"], "bore_hoop": 1.0, "pin_p0": 1.0, "needle_Q": 1.0}
#: the ring's own quantities (estimated on a refined bore, :func:`ring_level_estimate`)
RING_SIDE = ("bore_hoop", "pin_p0", "needle_Q")


def _ring_quantities(model: RingModel, F: float) -> dict:
    """The ring model's estimated quantities at force ``F`` (N) on its reference curvature, as
    the row reports them (:func:`femcam.bodies.rows.cage_solves`: on needles the contact and
    bore hoop stress of the cage position with the larger bore stress), the needle load with a
    needle on the load line (``needle_Qmax_on_N``)."""
    # the reported cage matters: on examples/seed002_needle_roller.toml the hoop beside a needle
    # on the load line moves 92.6 -> 112 MPa from 128 to 256 bore vertices (the spread narrows
    # with the mesh), the row's, between two needles, 125.7 -> 127.3 (docs/bodies.md)
    res, best = cage_solves(model, F, model.rho_ref)
    return {"p0": float(np.max(best.p)), "a": best.a, "bore_hoop": best.hoop_max, "pin_p0": best.pin_p0,
            "needle_Q": float(np.max(res[0].needle_Q)) if np.size(res[0].needle_Q) else math.nan}


def ring_level_estimate(model: RingModel, mesh: MeshOptions | None = None,
                        ring_mesh: RingMeshOptions | None = None) -> dict:
    r"""The two-level estimate of the ring model that answers a ring row, from one second model
    solved at the model's reference load (the force whose Hertz half-width is ``a_ref`` at
    ``rho_ref``): its cam contact zone **coarse** (:func:`femcam.sweep.estimate.coarse_mesh`,
    ``H = 2 h``: the contact's estimate as on the solid families) and its ring and pin **fine**
    (twice the bore vertices, half the largest element: a thin wall admits no coarser bore, the
    spacing must stay within half the wall). The two meshes hardly interact (measured: the bore
    hoop stress moves by 0.02 % from contact a/h 6 to 10, the ring's p0 by 2e-8 from 128 to 256
    bore vertices), so each quantity takes the level that changed its own mesh:

    .. math:: e_{contact} = \frac{|q_h - q_H|}{|q_h| (2^p - 1)}, \qquad
              e_{ring} = \frac{|q_h - q_{h/2}|\, 2^p}{|q_h| (2^p - 1)}

    Parameters
    ----------
    model : RingModel
        The ring model (built with ``mesh`` and ``ring_mesh``).
    mesh, ring_mesh : MeshOptions, RingMeshOptions, optional
        Its meshes (default: the defaults :func:`femcam.bodies.rows.build_for` builds with).

    Returns
    -------
    dict[str, float]
        Relative errors [-] at the reference load: ``p0``, ``a`` (cam contact), ``bore_hoop``,
        ``pin_p0`` (pin support) and ``needle_Q`` (needles); NaN where a quantity does not apply
        or the second model is refused; and ``a_over_h``, the model's elements per ``a_ref``.
    """
    mesh, ring_mesh = mesh or MeshOptions(), ring_mesh or RingMeshOptions()
    out = dict.fromkeys(RING_RATES, math.nan)
    out["a_over_h"] = float(mesh.a_over_h)
    b = model.bearing
    inv_R = 1.0 / b.Ro + (0.0 if math.isinf(model.rho_ref) else 1.0 / model.rho_ref)
    E_star = effective_modulus(model.cam, b.ring, model.plane)
    F = math.pi * E_star * model.a_ref**2 * model.length * inv_R / 4
    fine_ring = RingMeshOptions(n_bore=2 * ring_mesh.n_bore, growth=ring_mesh.growth,
                                h_max_over_wall=max(0.02, ring_mesh.h_max_over_wall / 2))
    try:
        other = RingModel.build(bearing=b, cam=model.cam, rho_ref=model.rho_ref, a_ref=model.a_ref,
                                length=model.length, mesh=coarse_mesh(mesh.a_over_h, mesh.fine_half_width),
                                ring_mesh=fine_ring, plane=model.plane)
        qh, q2 = _ring_quantities(model, F), _ring_quantities(other, F)
    except (FemcamError, ValueError, ArithmeticError):
        return out
    for q, p in RING_RATES.items():
        if qh[q] != 0 and math.isfinite(qh[q]):
            d = abs(qh[q] - q2[q]) / abs(qh[q]) / (2.0**p - 1.0)
            out[q] = d * 2.0**p if q in RING_SIDE else d
    return out


def contact_rows(rows) -> np.ndarray:
    """Rows with a contact solution to build on: ``ok``, or ``failed`` (the FE failed there, the
    contact exists); lift-off and undercut rows (the roller does not fit) get NaN.

    Parameters
    ----------
    rows : ChunkRows
        The chunk's table (``status``).

    Returns
    -------
    ndarray of bool, shape (n,)
        The rows the ring model solves.
    """
    status = np.asarray(rows.status).astype(str)
    return (status == "ok") | (status == "failed")


def ring_estimate(rows, i: int, est: FamilyEstimate | None, n_ring: float,
                  ring_est: dict | None = None) -> None:
    """Row ``i``'s error estimates once the ring model answers it (module docstring): the ring
    model's own two-level estimate (:func:`ring_level_estimate`) carried to the row's ``n_ring``
    elements per half-width for ``p0`` and ``a``; the scaled stresses add the solid row's.

    Parameters
    ----------
    rows : ChunkRows
        The chunk's table with the solid row's ``err_est_*`` (relative) filled; modified in place.
    i : int
        Row index.
    est : FamilyEstimate or None
        The solid row's family estimate (None: a Hertz row, the stress estimates become NaN).
    n_ring : float
        Elements per the row's half-width on the ring model's contact mesh [-].
    ring_est : dict, optional
        The ring model's estimate (:func:`ring_level_estimate`); None: the solid family's
        estimate carried to ``n_ring`` (the rule before the ring's own estimate).
    """
    rows.a_over_h_row[i] = n_ring
    if ring_est is not None:
        e = {q: ring_est[q] * (ring_est["a_over_h"] / n_ring) ** RING_RATES[q] for q in ("p0", "a")}
    elif est is not None:
        e = {q: est.err[q] * (est.a_over_h / n_ring) ** RATES[q] for q in ("p0", "a")}
    else:
        e = {"p0": np.nan, "a": np.nan}
    if est is None:
        for q in QUANTITIES:
            getattr(rows, f"err_est_{q}")[i] = np.nan
    p0_solid = rows.err_est_p0[i]
    for q in ("vm", "tau1"):   # the solid stress x p0_ring / p0_solid
        getattr(rows, f"err_est_{q}")[i] = getattr(rows, f"err_est_{q}")[i] + e["p0"] + p0_solid
    rows.err_est_p0[i], rows.err_est_a[i] = e["p0"], e["a"]


def ring_side_estimates(rows, ring_est: dict) -> None:
    """The ring's own stress estimates (:data:`femcam.sweep.providers.RING_ESTIMATES`) on every
    row with a finite ring value: the reference load's relative error, unchanged from row to row
    (the ring and bore mesh do not follow the load, and the bore hoop stress and the needle loads
    are close to linear in it).

    Parameters
    ----------
    rows : ChunkRows
        The chunk's table with the ``ring_*`` side columns (SI); modified in place.
    ring_est : dict
        :func:`ring_level_estimate`.
    """
    for c in RING_ESTIMATES:
        q = c.si.removeprefix("err_est_")
        value = np.asarray(getattr(rows, _RING_VALUE[q]), float)
        setattr(rows, c.si, np.where(np.isfinite(value), ring_est.get(q, np.nan), np.nan))


#: estimated ring quantity -> the side column it estimates
_RING_VALUE = {"bore_hoop": "ring_hoop_max", "pin_p0": "ring_pin_p0", "needle_Q": "ring_needle_Q_on"}


def ring_headline(task, rows) -> np.ndarray:
    """Solve the chunk's contact rows on the scene's ring model, put the ring's side columns
    (``ring_<key>`` of :data:`SIDE_KEYS`, SI) into ``rows`` and let the ring answer the headline
    of the ``ok`` rows (module docstring). Nothing happens for a solid roller.

    Parameters
    ----------
    task : femcam.sweep.pipeline.ChunkTask
        The chunk (``scene``, ``theta`` [rad]).
    rows : ChunkRows
        The chunk's table with the contact columns filled (SI; modified in place).

    Returns
    -------
    ndarray of bool, shape (n,)
        The rows the ring answered (all False for a solid roller, or when the ring model is
        refused: the :class:`~femcam.errors.FemcamError` is kept in ``rows.ring_error`` for
        the ``bodies`` provider, which reports it, and the solid roller's answer stays).
    """
    n = rows.theta.size
    done = np.zeros(n, bool)
    if not has_support(task.scene):
        return done
    Fc = np.where(contact_rows(rows), rows.Fc, 0.0)   # ring_rows: Fc <= 0 -> NaN row
    try:
        model = ring_model(task.scene)
        r = ring_rows(task.scene.bodies.roller, task.scene.pair, task.theta, Fc, rows.rho,
                      model=model)
    except FemcamError as exc:   # the bodies provider reports it (extras_error, refusals)
        rows.ring_error = exc
        return done
    for k in SIDE_KEYS:
        setattr(rows, f"ring_{k}", np.asarray(r[k], float))
    # the ring model's two-level estimate, once per process (as the model)
    ring_est = _cached("ring_estimate", task.scene, lambda: ring_level_estimate(model))
    ring_side_estimates(rows, ring_est)
    peak, fit, a = (np.asarray(r[k], float) for k in ("p0_peak", "p0", "a"))
    ok = (np.asarray(rows.status).astype(str) == "ok") & np.isfinite(peak)
    for i in np.flatnonzero(ok):
        p_s = rows.p0_fe[i] if np.isfinite(rows.p0_fe[i]) else rows.p0_hertz[i]
        a_s = rows.a_fe[i] if np.isfinite(rows.a_fe[i]) else rows.a_hertz[i]
        k_p, k_a = peak[i] / p_s, a[i] / a_s
        fid = int(rows.family[i]) if np.isfinite(rows.family[i]) else -1
        ring_estimate(rows, i, task.estimates.get(fid), RING_A_OVER_H * a[i] / model.a_ref, ring_est)
        for name in SCALED_BY_P0:
            getattr(rows, name)[i] *= k_p
        for name in SCALED_BY_A:
            getattr(rows, name)[i] *= k_a
        rows.p0_fe[i], rows.p0_fit[i], rows.a_fe[i] = peak[i], fit[i], a[i]
        rows.err_p0[i] = peak[i] / rows.p0_hertz[i] - 1.0
        rows.err_a[i] = a[i] / rows.a_hertz[i] - 1.0
        rows.model[i] = f"{rows.model[i] or 'hertz'}+ring"
        done[i] = True
    return done
