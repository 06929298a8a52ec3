"""The arrays of a solved contact scene as VTU point data (both bodies in one mesh), written by
:func:`femcam.io.write_fe_vtu`.

Points are in the FE contact frame (m): ``x`` along the common tangent, ``y`` from the cam into
the roller. P2 models are written as quadratic ``triangle6`` cells (skfem's local P2 node order
-- vertices, then edges 01, 12, 20 -- is VTK's), P1 models as ``triangle``. Point data:
``displacement_m`` (3 components), ``stress_Pa`` (the tensor in the FE frame, 6 components
XX, YY, ZZ, XY, YZ, XZ: sx, sz, sy, +-txz, 0, 0; :func:`stress_tensor`), ``tau1_Pa``,
``von_mises_Pa``, ``depth_m`` (m below each body's surface) and ``contact_pressure_Pa`` (Pa,
the P1 interpolant of the nodal pressure at the vertex and midside nodes of the fine-zone contact
curve, 0 elsewhere), ``err_est_stress_Pa`` (the recovery (ZZ) indicator of the stress error,
:mod:`femcam.fe.estimate`), ``contact_traction_Pa`` (the tangential traction on each body along x in
the contact frame, ``q`` on the cam and ``-q`` on the roller, same interpolation). Cell data
``body``: 0 cam, 1 roller.
"""

from __future__ import annotations

import numpy as np

from .estimate import zz_indicator
from .recovery import surface_nodes

FIELDS = ("sx", "sz", "txz", "sy", "tau1", "von_mises")

#: names of the arrays in the .vtu files (units in the names): scene_arrays key -> VTU name
VTK_NAMES = {"displacement": "displacement_m", "stress": "stress_Pa", "tau1": "tau1_Pa",
             "von_mises": "von_mises_Pa", "depth": "depth_m",
             "contact_pressure": "contact_pressure_Pa", "contact_traction": "contact_traction_Pa",
             "wear_rate": "wear_rate_m_s", "err_est_stress": "err_est_stress_Pa"}


def stress_tensor(sx, sz, sy, txz, sign: float):
    """The stress tensor in the FE frame as one VTK array (n, 6), order XX, YY, ZZ, XY, YZ, XZ.

    ``sx, sz, txz`` are in the body's Johnson frame (``z`` depth), ``sy`` out of plane; the FE
    frame has ``y`` from the cam into the roller, so ``XY = sign * txz`` with ``sign = -1`` for
    the cam (below, ``y = -z``) and ``+1`` for the roller (:func:`femcam.fe.recovery.johnson_frame`).

    Parameters
    ----------
    sx, sz, sy, txz : array_like of float, shape (n,)
        Stresses in the body's Johnson frame [Pa] (``sy`` out of plane).
    sign : float
        ``-1`` for the cam, ``+1`` for the roller.

    Returns
    -------
    ndarray of float, shape (n, 6)
        ``XX, YY, ZZ, XY, YZ, XZ`` in the FE frame [Pa].
    """
    zero = np.zeros_like(np.asarray(sx, float))
    return np.column_stack([sx, sz, sy, sign * np.asarray(txz, float), zero, zero])


def vtk_point_data(data: dict) -> dict:
    """Point data as written to .vtu: the stress tensor as one array ``stress_Pa`` (replacing
    ``sx, sz, txz, sy``) and every name with its unit (:data:`VTK_NAMES`).

    Parameters
    ----------
    data : dict of str to ndarray
        Point data of :func:`scene_arrays` (SI units, unit-free names).

    Returns
    -------
    dict of str to ndarray
        The same arrays under their VTU names, without ``sx, sz, txz, sy``.
    """
    return {VTK_NAMES.get(k, k): v for k, v in data.items() if k not in ("sx", "sz", "txz", "sy")}


def scene_arrays(result, model=None):
    """Mesh and point data of both bodies, ready for :func:`femcam.io.write_vtu`.

    Parameters
    ----------
    result : ContactResult
        A solved contact.
    model : ContactModel, optional
        The solving model, needed for an unpickled ``result``.

    Returns
    -------
    points : ndarray of float, shape (n, 3)
        Node coordinates in the FE contact frame [m] (``z = 0``), cam nodes first.
    cells : ndarray of int, shape (n_el, k)
        Node indices per triangle (``k = 6`` for P2, 3 for P1).
    cell_type : str
        ``"triangle6"`` or ``"triangle"``.
    point_data : dict of str to ndarray
        Per node: ``sx, sz, txz, sy, tau1, von_mises`` [Pa], ``stress`` (n, 6) [Pa],
        ``displacement`` (n, 3) [m], ``depth`` [m], ``contact_pressure`` and
        ``contact_traction`` [Pa], ``err_est_stress`` [Pa] (the recovery indicator of
        :func:`femcam.fe.estimate.zz_indicator`).
    body_id : ndarray of int, shape (n_el,)
        0 for cam cells, 1 for roller cells.
    """

    model = result.model_or(model)
    keys = (*FIELDS, "displacement", "depth", "contact_pressure", "contact_traction", "stress",
            "err_est_stress")
    pts, cells, data, body_id = [], [], {k: [] for k in keys}, []
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
        data["stress"].append(stress_tensor(fld["sx"], fld["sz"], fld["sy"], fld["txz"],
                                            -1.0 if name == "cam" else 1.0))
        data["displacement"].append(np.column_stack([u.T, np.zeros(n)]))
        data["depth"].append(fld["z"])
        # recovery (ZZ) indicator, Pa
        data["err_est_stress"].append(zz_indicator(b, u, model.field_gradients(name)))
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
