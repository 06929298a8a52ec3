"""Full fields of a solved ring model, as the arrays :func:`femcam.io.write_ring_vtu` writes.

The ring, the pin (if elastic) and the cam body are written in the roller frame (m; ring
centre ``(0, Ro)``). Point data at the P2 nodes (``triangle6`` cells): ``displacement`` (m),
``sxx, syy, sxy`` (Pa), ``hoop`` (Pa, the hoop stress about the roller centre; the cam's is
the same projection, for a single colour map) and ``von_mises`` (Pa, plane strain ``szz =
nu (sxx + syy)``). Cell data ``body``: 0 cam, 1 ring, 2 pin.
"""

from __future__ import annotations

import numpy as np

from ..fe.elasticity import scalar_node_coordinates, stress_operator

BODY_IDS = {"cam": 0, "ring": 1, "pin": 2}


def nodal_fields(body, f, centre, plane: str, S=None) -> dict:
    """Nodal displacement and stresses of one elastic body under the nodal forces ``f``.

    Parameters
    ----------
    body : femcam.fe.elasticity.Body
        The clamped, factorised body.
    f : ndarray, shape (n_dofs,)
        Nodal forces per unit thickness [N/m].
    centre : tuple of float
        The point the hoop direction is taken about, (x, y) in the body's frame [m].
    plane : {"strain", "stress"}
        Plane condition (sets ``szz`` in the von Mises stress).
    S : scipy.sparse matrix or None, optional
        The body's stress operator [Pa/m] if already built; None: built here.

    Returns
    -------
    dict
        ``xy`` (2, n) node coordinates [m]; ``u`` (2, n) displacement [m]; ``sxx``, ``syy``,
        ``sxy``, ``hoop`` (about ``centre``), ``von_mises`` (n,) [Pa]; ``cells`` (n_cells, 6)
        int node indices of the ``triangle6`` cells.
    """
    u = body.solve(f)
    s = (stress_operator(body) if S is None else S) @ u
    n = body.n_dofs // 2
    sxx, syy, sxy = s[:n], s[n:2 * n], s[2 * n:]
    xy = scalar_node_coordinates(body)
    th = np.arctan2(xy[1] - centre[1], xy[0] - centre[0])
    hoop = sxx * np.sin(th) ** 2 + syy * np.cos(th) ** 2 - 2 * sxy * np.sin(th) * np.cos(th)
    szz = body.material.nu * (sxx + syy) if plane == "strain" else np.zeros_like(sxx)
    vm = np.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2) + 3 * sxy**2)
    return {"xy": xy, "u": np.stack([u[0::2], u[1::2]]), "sxx": sxx, "syy": syy, "sxy": sxy,
            "hoop": hoop, "von_mises": vm, "cells": (body.basis.element_dofs[::2] // 2).T}


def stack_bodies(fields: dict, body_ids: dict):
    """Several bodies' nodal fields as one point cloud with ``triangle6`` cells.

    Parameters
    ----------
    fields : dict of str to dict
        Body name -> :func:`nodal_fields` output, in the order to write.
    body_ids : dict of str to int
        The integer id written per cell for each body name.

    Returns
    -------
    points : ndarray, shape (n, 3)
        Node coordinates [m] (z = 0).
    cells : ndarray of int, shape (nel, 6)
        ``triangle6`` node indices.
    point_data : dict of str to ndarray
        ``displacement`` (n, 3) [m]; ``sxx``, ``syy``, ``sxy``, ``hoop``, ``von_mises`` (n,) [Pa].
    body_ids : ndarray of int, shape (nel,)
        Body id of each cell.
    """
    keys = ("sxx", "syy", "sxy", "hoop", "von_mises")
    pts, cells, ids = [], [], []
    data = {k: [] for k in ("displacement",) + keys}
    off = 0
    for name, fl in fields.items():
        n = fl["xy"].shape[1]
        pts.append(np.column_stack([fl["xy"].T, np.zeros(n)]))
        cells.append(fl["cells"] + off)
        ids.append(np.full(fl["cells"].shape[0], body_ids[name]))
        data["displacement"].append(np.column_stack([fl["u"].T, np.zeros(n)]))
        for k in keys:
            data[k].append(fl[k])
        off += n
    return (np.concatenate(pts), np.concatenate(cells), {k: np.concatenate(v) for k, v in data.items()},
            np.concatenate(ids))


def body_fields(model, result, name: str) -> dict:
    """Nodal fields of body ``name`` (see module docstring) for a :class:`RingResult`.

    Parameters
    ----------
    model : RingModel
        The solved ring model (:class:`~femcam.bodies.model.RingModel`).
    result : RingResult
        Its solution for one load case.
    name : {"ring", "pin", "cam"}
        The body (``"pin"`` only with an elastic pin).

    Returns
    -------
    dict
        ``xy`` (2, n) node coordinates in the roller frame [m]; ``u`` (2, n) displacement [m];
        ``sxx``, ``syy``, ``sxy``, ``hoop`` (about the roller centre), ``von_mises`` (n,) [Pa];
        ``cells`` (n_cells, 6) int node indices of the ``triangle6`` cells.
    """
    b = model.bodies[name]
    basic = np.concatenate([result.p, result.bore_p])
    if name == "cam":
        f = model.loads["cam"] @ result.p
    else:
        f = model.loads[name] @ (basic if name == "ring" else result.bore_p)
    return nodal_fields(b, f, (0.0, model.bearing.Ro), model.plane)


def ring_arrays(model, result, bodies=("ring", "pin", "cam")):
    """The chosen bodies as one point cloud with ``triangle6`` cells (for the VTU export).

    Parameters
    ----------
    model : RingModel
        The solved ring model.
    result : RingResult
        Its solution for one load case.
    bodies : tuple of str, optional
        The bodies, of ``"ring"``, ``"pin"``, ``"cam"`` (a missing one is skipped).

    Returns
    -------
    points : ndarray, shape (n, 3)
        Node coordinates in the roller frame [m] (z = 0).
    cells : ndarray of int, shape (nel, 6)
        ``triangle6`` node indices.
    point_data : dict of str to ndarray
        ``displacement`` (n, 3) [m]; ``sxx``, ``syy``, ``sxy``, ``hoop``, ``von_mises`` (n,) [Pa].
    body_ids : ndarray of int, shape (nel,)
        Body of each cell (:data:`BODY_IDS`: 0 cam, 1 ring, 2 pin).
    """
    fields = {name: body_fields(model, result, name) for name in bodies if name in model.bodies}
    return stack_bodies(fields, BODY_IDS)
