"""VTU export of a solved contact scene through meshio (both bodies in one file).

Points are in the FE contact frame (m): ``x`` along the common tangent, ``y`` from the cam into
the roller. P2 models are written as quadratic ``triangle6`` cells (skfem's local P2 node order
-- vertices, then edges 01, 12, 20 -- is VTK's), P1 models as ``triangle``. Point data:
``displacement`` (m, 3 components), ``sx, sz, txz, sy, tau1, von_mises`` (Pa, each body in its
own Johnson frame, see :mod:`femcam.fe.recovery`), ``depth`` (m) and ``contact_pressure`` (Pa,
the P1 interpolant of the nodal pressure at the vertex and midside nodes of the fine-zone contact
curve, 0 elsewhere), ``contact_traction`` (Pa, the tangential traction on each body along x in
the contact frame, ``q`` on the cam and ``-q`` on the roller, same interpolation). Cell data
``body``: 0 cam, 1 roller.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .recovery import surface_nodes

FIELDS = ("sx", "sz", "txz", "sy", "tau1", "von_mises")


def scene_arrays(result):
    """(points (n, 3), cells (nel, k), cell_type, point_data, body_id) for both bodies."""

    model = result.model
    pts, cells, data, body_id = [], [], {k: [] for k in (*FIELDS, "displacement", "depth",
                                                          "contact_pressure", "contact_traction")}, []
    offset = 0
    for i, name in enumerate(("cam", "roller")):
        b = model.bodies[name]
        u, fld = model.full_field(result, name)
        xy = fld["xy"]
        n = xy.shape[1]
        pts.append(np.column_stack([xy.T, np.zeros(n)]))
        conn = (b.basis.element_dofs[::2] // 2).T
        cells.append(conn + offset)
        for k in FIELDS:
            data[k].append(fld[k])
        data["displacement"].append(np.column_stack([u.T, np.zeros(n)]))
        data["depth"].append(fld["z"])
        # the fine-zone contact curve: vertices and P2 midside nodes (on the chords, so not
        # exactly at depth 0); the pressure is zero beyond it
        on = np.zeros(n, dtype=bool)
        on[surface_nodes(b)] = True
        cp = np.zeros(n)
        cp[on] = np.interp(xy[0, on], result.x, result.p)
        data["contact_pressure"].append(cp)
        q = result.q if result.q is not None else (result.sliding * result.mu) * result.p
        ct = np.zeros(n)
        ct[on] = (1.0 if name == "cam" else -1.0) * np.interp(xy[0, on], result.x, q)
        data["contact_traction"].append(ct)
        body_id.append(np.full(conn.shape[0], i))
        offset += n
    cell_type = "triangle6" if model.element == "P2" else "triangle"
    return (np.concatenate(pts), np.concatenate(cells), cell_type,
            {k: np.concatenate(v) for k, v in data.items()}, np.concatenate(body_id))


def write_vtu(result, path) -> Path:
    """Write ``result`` (a :class:`~femcam.fe.ContactResult`) to ``path`` (.vtu); returns the path."""
    import meshio  # lazy: meshio loads its many format plugins; only .vtu export needs it

    path = Path(path)
    if path.suffix != ".vtu":
        path = path.with_suffix(".vtu")
    points, cells, cell_type, point_data, body = scene_arrays(result)
    mesh = meshio.Mesh(points, [(cell_type, cells)], point_data=point_data,
                       cell_data={"body": [body]})
    path.parent.mkdir(parents=True, exist_ok=True)
    meshio.write(path, mesh, binary=True)
    return path
