"""The arrays of the complete cam disk (and its shaft) as VTU point data: from a solved fully
refined cam model (:func:`cam_arrays`), or from the global model at one cam angle
(:func:`global_cam_arrays`, what ``femcam sweep`` writes beside its own VTUs); written by
:func:`femcam.io.write_cam_vtu` and :func:`femcam.io.write_global_cam_vtu`.

Fully refined model: points in the contact frame of the angle (m; contact at the origin, cam below
``y = 0``, cam centre ``model.centre``). Point data at the P2 nodes (``triangle6`` cells):
``displacement`` (m), ``sxx, syy, sxy`` (Pa), ``hoop`` (Pa, about the cam centre) and
``von_mises`` (Pa, plane strain ``szz = nu (sxx + syy)``). Cell data ``body``: 0 cam, 3 shaft.

Global model: points in the cam frame (m, cam centre at the origin: the body turns with the cam,
the contact moves round it from angle to angle); point data with the unit in the name:
``displacement_um``, ``sxx_MPa``, ``syy_MPa``, ``sxy_MPa``, ``hoop_MPa``, ``von_mises_MPa`` and, at
the bore vertices only (NaN elsewhere), ``bore_hoop_MPa`` and ``bore_pressure_MPa`` (the shaft
contact). Field data ``theta_deg``, ``Fc_N``. The loads are those of the sweep's row (the contact
force split between its two outline stations, the drive torque, the solved bore pressures), so
the largest ``bore_hoop_MPa`` is the row's ``cam_bore_hoop_max_MPa``. The contact zone itself is
coarse here (the global model has no fine zone): its stresses are the local body's, in the
sweep's own VTU.
"""

from __future__ import annotations

import math

import numpy as np

from ..fe.elasticity import stress_operator
from .cam_rows import solve_global
from .export import nodal_fields, stack_bodies

BODY_IDS = {"cam": 0, "shaft": 3}


def cam_body_fields(model, result, name: str) -> dict:
    """Nodal fields of ``"cam"`` or ``"shaft"`` for a :class:`~femcam.bodies.cam_solve.CamDiskResult`.

    Parameters
    ----------
    model : CamDiskModel
        The solved fully refined model (:class:`~femcam.bodies.cam_model.CamDiskModel`).
    result : CamDiskResult
        Its solution for one load case.
    name : {"cam", "shaft"}
        The body (``"shaft"`` only with an elastic shaft).

    Returns
    -------
    dict
        ``xy`` (2, n) node coordinates in the contact frame [m]; ``u`` (2, n) displacement [m];
        ``sxx``, ``syy``, ``sxy``, ``hoop`` (about the cam centre), ``von_mises`` (n,) [Pa];
        ``cells`` (n_cells, 6) int node indices of the ``triangle6`` cells.
    """
    lam = np.concatenate([result.p, result.bore_p])
    f = model.loads[name] @ (lam if name == "cam" else result.bore_p)
    return nodal_fields(model.bodies[name], f, model.centre, model.plane)


def cam_arrays(model, result, bodies=("cam", "shaft")):
    """The cam disk (and the shaft, if elastic) as one point cloud with ``triangle6`` cells.

    Parameters
    ----------
    model : CamDiskModel
        The solved fully refined model.
    result : CamDiskResult
        Its solution for one load case.
    bodies : tuple of str, optional
        The bodies, of ``"cam"`` and ``"shaft"`` (a missing one is skipped).

    Returns
    -------
    points : ndarray, shape (n, 3)
        Node coordinates in the contact frame [m] (z = 0).
    cells : ndarray of int, shape (nel, 6)
        ``triangle6`` node indices.
    point_data : dict of str to ndarray
        ``displacement`` (n, 3) [m]; ``sxx``, ``syy``, ``sxy``, ``hoop``, ``von_mises`` (n,) [Pa].
    body_ids : ndarray of int, shape (nel,)
        Body of each cell (:data:`BODY_IDS`: 0 cam, 3 shaft).
    """
    fields = {name: cam_body_fields(model, result, name) for name in bodies if name in model.bodies}
    return stack_bodies(fields, BODY_IDS)


def global_cam_fields(model, C, n, F: float) -> dict:
    """Nodal fields of the global model's cam at one contact (the superposition of its unit
    station loads, drive torque and bore hats, as one back-substitution).

    Parameters
    ----------
    model : CamGlobalModel
    C, n : array_like, shape (2,)
        Contact point (m) and outward unit cam normal, cam frame.
    F : float
        Contact force (N, > 0) over ``model.length``.

    Returns
    -------
    dict
        As the fully refined model's fields (SI) plus ``bore_hoop``, ``bore_p`` (Pa; NaN off
        the bore vertices) and ``hoop_max`` (Pa, the row's ``solve_global`` value).
    """
    C = np.asarray(C, float).reshape(2, 1)
    n = np.asarray(n, float).reshape(2, 1)
    r = solve_global(model, C, n, np.array([float(F)]))
    L = model.load_weights(C, -(float(F) / model.length) * n)[0]
    cam = model.bodies["cam"]
    f = model.loads["bore"] @ r["bore_p"][0] + L[-1] * model.loads["torque"]
    f[cam.basis.nodal_dofs[0, model.station_nodes]] += L[0:-1:2]
    f[cam.basis.nodal_dofs[1, model.station_nodes]] += L[1:-1:2]
    if "stress" not in model.cache:
        model.cache["stress"] = stress_operator(cam)
    fl = nodal_fields(cam, f, (0.0, 0.0), model.plane, model.cache["stress"])
    nn = fl["xy"].shape[1]
    fl["bore_hoop"] = np.full(nn, np.nan)
    fl["bore_hoop"][model.bore_nodes] = fl["hoop"][model.bore_nodes]
    fl["bore_p"] = np.full(nn, np.nan)
    fl["bore_p"][model.bore_nodes] = r["bore_p"][0]
    fl["hoop_max"] = float(r["hoop_max"][0])
    return fl


def global_cam_arrays(model, C, n, F: float, *, theta: float = math.nan):
    """The global model's cam at one contact as VTU arrays, units in the names (module docstring).

    Parameters
    ----------
    model : CamGlobalModel
    C, n : array_like, shape (2,)
        Contact point (m) and outward unit cam normal, cam frame.
    F : float
        Contact force (N, > 0).
    theta : float
        The cam angle (rad), returned as field data ``theta_deg``.

    Returns
    -------
    points : ndarray, shape (n_nodes, 3)
        Node coordinates in the cam frame [m] (z = 0).
    cells : ndarray of int, shape (nel, 6)
        ``triangle6`` node indices.
    point_data : dict of str to ndarray
        ``displacement_um`` (n_nodes, 3) [um]; ``sxx_MPa``, ``syy_MPa``, ``sxy_MPa``, ``hoop_MPa``,
        ``von_mises_MPa``, ``bore_hoop_MPa``, ``bore_pressure_MPa`` (NaN off the bore) [MPa].
    field_data : dict of str to float
        ``theta_deg`` [deg] and ``Fc_N`` [N].
    """
    fl = global_cam_fields(model, C, n, F)
    nn = fl["xy"].shape[1]
    mpa = {f"{k}_MPa": fl[k] * 1e-6 for k in ("sxx", "syy", "sxy", "hoop", "von_mises")}
    data = {"displacement_um": np.column_stack([fl["u"].T * 1e6, np.zeros(nn)]), **mpa,
            "bore_hoop_MPa": fl["bore_hoop"] * 1e-6, "bore_pressure_MPa": fl["bore_p"] * 1e-6}
    return (np.column_stack([fl["xy"].T, np.zeros(nn)]), fl["cells"], data,
            {"theta_deg": math.degrees(theta), "Fc_N": float(F)})
