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

Cost: no model beyond today's: the ring model was already built and solved for its bore and
needle columns; those solves are now read by the headline as well (the solid-roller families
still answer the stresses). With ``--method auto`` the rows Hertz answers need no FE model at
all, so a ring scene then costs the ring model alone.
"""

from __future__ import annotations

import numpy as np

from ..bodies.rows import CSV_COLUMNS as RING_COLUMNS
from ..bodies.rows import ring_rows
from ..errors import FemcamError
from .providers import RING_ERROR, RING_HEADLINE_KEYS, has_support, ring_model

#: stress columns scaled by ``p0_ring / p0_solid`` and length columns by ``a_ring / a_solid``
SCALED_BY_P0 = ("vm_max", "tau1_max", "txz_range_max", "surf_sx_min", "surf_sx_max", "surf_sz_min",
                "surf_txz_absmax")
SCALED_BY_A = ("vm_depth", "tau1_depth", "txz_range_depth", "stick_width")
#: the ring's side columns (bore, pin, needles); the contact keys answer the headline
#: (:data:`femcam.sweep.providers.RING_HEADLINE_KEYS`)
SIDE_KEYS = tuple(k for k in RING_COLUMNS if k not in RING_HEADLINE_KEYS)


def contact_rows(rows) -> np.ndarray:
    """Rows with a contact solution to build on: ``ok``, or ``failed`` (the FE failed there, the
    contact exists); lift-off and undercut rows (the roller does not fit) get NaN.

    Parameters
    ----------
    rows : dict[str, ndarray]
        The chunk's table (``status``).

    Returns
    -------
    ndarray of bool, shape (n,)
        The rows the ring model solves.
    """
    status = np.asarray(rows["status"]).astype(str)
    return (status == "ok") | (status == "failed")


def ring_headline(task, rows) -> np.ndarray:
    """Solve the chunk's contact rows on the scene's ring model, put the ring's side columns
    (``ring_<key>`` of :data:`SIDE_KEYS`, SI) into ``rows`` and let the ring answer the headline
    of the ``ok`` rows (module docstring). Nothing happens for a solid roller.

    Parameters
    ----------
    task : femcam.sweep.pipeline.ChunkTask
        The chunk (``scene``, ``theta`` [rad]).
    rows : dict[str, ndarray]
        The chunk's table with the contact columns filled (SI; modified in place).

    Returns
    -------
    ndarray of bool, shape (n,)
        The rows the ring answered (all False for a solid roller, or when the ring model is
        refused: the :class:`~femcam.errors.FemcamError` is kept under :data:`RING_ERROR` for
        the ``bodies`` provider, which reports it, and the solid roller's answer stays).
    """
    n = rows["theta"].size
    done = np.zeros(n, bool)
    if not has_support(task.scene):
        return done
    Fc = np.where(contact_rows(rows), rows["Fc"], 0.0)   # ring_rows: Fc <= 0 -> NaN row
    try:
        r = ring_rows(task.scene, task.theta, Fc, rows["rho"], model=ring_model(task.scene))
    except FemcamError as exc:   # the bodies provider reports it (extras_error, refusals)
        rows[RING_ERROR] = exc
        return done
    for k in SIDE_KEYS:
        rows[f"ring_{k}"] = np.asarray(r[k], float)
    peak, fit, a = (np.asarray(r[k], float) for k in ("p0_peak", "p0", "a"))
    ok = (np.asarray(rows["status"]).astype(str) == "ok") & np.isfinite(peak)
    for i in np.flatnonzero(ok):
        p_s = rows["p0_fe"][i] if np.isfinite(rows["p0_fe"][i]) else rows["p0_hertz"][i]
        a_s = rows["a_fe"][i] if np.isfinite(rows["a_fe"][i]) else rows["a_hertz"][i]
        k_p, k_a = peak[i] / p_s, a[i] / a_s
        for name in SCALED_BY_P0:
            rows[name][i] *= k_p
        for name in SCALED_BY_A:
            rows[name][i] *= k_a
        rows["p0_fe"][i], rows["p0_fit"][i], rows["a_fe"][i] = peak[i], fit[i], a[i]
        rows["err_p0"][i] = peak[i] / rows["p0_hertz"][i] - 1.0
        rows["err_a"][i] = a[i] / rows["a_hertz"][i] - 1.0
        rows["model"][i] = f"{rows['model'][i] or 'hertz'}+ring"
        done[i] = True
    return done
