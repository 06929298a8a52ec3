"""VTU of the complete cam disk (and its shaft): from a solved fully refined cam model
(:func:`write_cam_vtu`), or from the global model at one cam angle (:func:`write_global_cam_vtu`,
what ``femcam sweep`` writes beside its own VTUs).

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
from pathlib import Path

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


def write_cam_vtu(model, result, path, bodies=("cam", "shaft")) -> Path:
    """Write the cam disk (and the shaft, if elastic) to a ``.vtu`` file.

    Parameters
    ----------
    model : CamDiskModel
        The solved fully refined model.
    result : CamDiskResult
        Its solution for one load case.
    path : str or os.PathLike
        The ``.vtu`` file; its folder is created.
    bodies : tuple of str, optional
        The bodies to write, of ``"cam"`` and ``"shaft"`` (a missing one is skipped).

    Returns
    -------
    pathlib.Path
        The written file.
    """
    import meshio  # optional heavy dependency of the export only

    fields = {name: cam_body_fields(model, result, name) for name in bodies if name in model.bodies}
    pts, cells, data, ids = stack_bodies(fields, BODY_IDS)
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    meshio.write(path, meshio.Mesh(pts, [("triangle6", cells)], point_data=data,
                                   cell_data={"body": [ids]}))
    return path


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


def write_global_cam_vtu(model, C, n, F: float, path, *, theta: float = math.nan) -> Path:
    """Write the global model's cam at one contact to ``path`` (.vtu; module docstring).

    Parameters
    ----------
    model : CamGlobalModel
    C, n : array_like, shape (2,)
        Contact point (m) and outward unit cam normal, cam frame.
    F : float
        Contact force (N, > 0).
    path : str or Path
        Output ``.vtu``.
    theta : float
        The cam angle (rad), recorded as field data ``theta_deg``.

    Returns
    -------
    Path
    """
    import meshio  # optional heavy dependency of the export only

    fl = global_cam_fields(model, C, n, F)
    nn = fl["xy"].shape[1]
    mpa = {f"{k}_MPa": fl[k] * 1e-6 for k in ("sxx", "syy", "sxy", "hoop", "von_mises")}
    data = {"displacement_um": np.column_stack([fl["u"].T * 1e6, np.zeros(nn)]), **mpa,
            "bore_hoop_MPa": fl["bore_hoop"] * 1e-6, "bore_pressure_MPa": fl["bore_p"] * 1e-6}
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    meshio.write(path, meshio.Mesh(np.column_stack([fl["xy"].T, np.zeros(nn)]), [("triangle6", fl["cells"])],
                                   point_data=data,
                                   field_data={"theta_deg": np.array([math.degrees(theta)]),
                                               "Fc_N": np.array([float(F)])}))
    return path
