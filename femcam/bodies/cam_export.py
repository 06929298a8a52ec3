"""VTU of the complete cam disk (and its shaft) from a solved fully refined cam model.

Points in the contact frame of the angle (m; contact at the origin, cam below ``y = 0``, cam
centre ``model.centre``). Point data at the P2 nodes (``triangle6`` cells): ``displacement`` (m),
``sxx, syy, sxy`` (Pa), ``hoop`` (Pa, about the cam centre) and ``von_mises`` (Pa, plane strain
``szz = nu (sxx + syy)``). Cell data ``body``: 0 cam, 3 shaft.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..fe.elasticity import scalar_node_coordinates, stress_operator

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
    b = model.bodies[name]
    lam = np.concatenate([result.p, result.bore_p])
    f = model.loads[name] @ (lam if name == "cam" else result.bore_p)
    u = b.solve(f)
    s = stress_operator(b) @ u
    n = b.n_dofs // 2
    sxx, syy, sxy = s[:n], s[n:2 * n], s[2 * n:]
    xy = scalar_node_coordinates(b)
    th = np.arctan2(xy[1] - model.centre[1], xy[0] - model.centre[0])
    hoop = sxx * np.sin(th) ** 2 + syy * np.cos(th) ** 2 - 2 * sxy * np.sin(th) * np.cos(th)
    szz = b.material.nu * (sxx + syy) if model.plane == "strain" else np.zeros_like(sxx)
    vm = np.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2) + 3 * sxy**2)
    return {"xy": xy, "u": np.stack([u[0::2], u[1::2]]), "sxx": sxx, "syy": syy, "sxy": sxy,
            "hoop": hoop, "von_mises": vm, "cells": (b.basis.element_dofs[::2] // 2).T}


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

    pts, cells, ids = [], [], []
    keys = ("sxx", "syy", "sxy", "hoop", "von_mises")
    data = {k: [] for k in ("displacement",) + keys}
    off = 0
    for name in bodies:
        if name not in model.bodies:
            continue
        fl = cam_body_fields(model, result, name)
        n = fl["xy"].shape[1]
        pts.append(np.column_stack([fl["xy"].T, np.zeros(n)]))
        cells.append(fl["cells"] + off)
        ids.append(np.full(fl["cells"].shape[0], BODY_IDS[name]))
        data["displacement"].append(np.column_stack([fl["u"].T, np.zeros(n)]))
        for k in keys:
            data[k].append(fl[k])
        off += n
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    meshio.write(path, meshio.Mesh(np.concatenate(pts), [("triangle6", np.concatenate(cells))],
                                   point_data={k: np.concatenate(v) for k, v in data.items()},
                                   cell_data={"body": [np.concatenate(ids)]}))
    return path
