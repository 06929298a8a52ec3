"""The fields of a solved body as ``.vtu`` files and the contact mesh as ``.msh``, all through
:func:`femcam.io.write_vtu` / :func:`femcam.io.write_msh` (atomic; one meshio call site).

The lower layers hand over arrays (:func:`femcam.fe.export.scene_arrays`,
:func:`femcam.bodies.export.ring_arrays`, :func:`femcam.bodies.cam_export.cam_arrays`,
:func:`femcam.bodies.cam_export.global_cam_arrays`, ``ContactMesh.msh_arrays``); the files are
written here.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .. import _validate
from ..bodies.cam_export import cam_arrays, global_cam_arrays
from ..bodies.export import ring_arrays
from ..fe.export import scene_arrays, stress_tensor, vtk_point_data
from ..hertz import LineContact
from ..mesh import ContactMesh
from .vtk import write_gmsh, write_vtu


def _field_data(wear: dict | None) -> dict:
    if not wear:
        return {}
    return {"theta_deg": wear["theta_deg"], "Fc_N": wear["Fc"], "wear_k_m3_per_N_m": wear["k"],
            "v_slip_m_s": wear["v_slip"], "V_cam_m_s": wear["V_cam"],
            "wear_depth_per_rev_m": wear["wear_depth_per_rev"]}


def write_fe_vtu(path, r, wear: dict | None = None, *, model=None) -> Path:
    """Both bodies of a solved contact (:func:`femcam.fe.export.scene_arrays`), plus wear.

    Points in the FE contact frame (m); point data ``displacement_m``, ``stress_Pa`` (6
    components XX, YY, ZZ, XY, YZ, XZ), ``tau1_Pa``, ``von_mises_Pa``, ``depth_m``,
    ``contact_pressure_Pa``, ``contact_traction_Pa`` (:mod:`femcam.fe.export`); cell data
    ``body`` (0 cam, 1 roller).

    Parameters
    ----------
    path : str or Path
        Output ``.vtu``; its folder is created.
    r : femcam.fe.ContactResult
        The solved load case.
    wear : dict, optional
        ``{"k" (m^3/(N m)), "v_slip" (m/s), "V_cam" (m/s), "wear_depth_per_rev" (m),
        "theta_deg" (deg), "Fc" (N)}``. Adds the point data ``wear_rate_m_s``: Archard's local
        rate ``k p v_slip`` on the contact surfaces (``p`` = the FE nodal contact pressure), 0
        elsewhere, and the field data ``theta_deg``, ``Fc_N``, ``wear_k_m3_per_N_m``,
        ``v_slip_m_s``, ``V_cam_m_s``, ``wear_depth_per_rev_m``.
    model : femcam.fe.ContactModel, optional
        The solving model, needed for an unpickled ``r``.

    Returns
    -------
    Path
        ``path``.
    """
    points, cells, cell_type, point_data, body = scene_arrays(r, model)
    if wear:
        point_data = dict(point_data, wear_rate=wear["k"] * np.asarray(point_data["contact_pressure"])
                          * wear["v_slip"])
    return write_vtu(path, points, [(cell_type, cells)], vtk_point_data(point_data),
                     field_data=_field_data(wear),
                     cell_data={"body": [body]})


def write_hertz_vtu(path, hc: LineContact, n: int = 41, wear: dict | None = None) -> Path:
    """The analytic Hertz field in the cam on a structured grid ``|x| <= 3a``, ``0 <= z <= 3a``.

    Parameters
    ----------
    path : str or Path
        Output ``.vtu``.
    hc : femcam.hertz.LineContact
        One (scalar) load case.
    n : int
        Grid points in depth (``2 n - 1`` along x).
    wear : dict, optional
        As in :func:`write_fe_vtu`; adds ``wear_rate_m_s = k p v_slip`` on the surface row.

    Returns
    -------
    Path
        ``path``. Point data ``stress_Pa`` (6 components XX, YY, ZZ, XY, YZ, XZ:
        ``sx, sz, sy, -txz, 0, 0``), ``tau1_Pa``, ``von_mises_Pa``, ``contact_pressure_Pa``; the cam
        lies below the surface (``y = -z``).
    """
    n = _validate.integer("n", n, 2, "grid points")
    a = float(hc.a)
    xs = np.linspace(-3 * a, 3 * a, 2 * n - 1)
    zs = np.linspace(0.0, 3 * a, n)
    X, Z = np.meshgrid(xs, zs)
    sf = hc.stress(X.ravel(), Z.ravel())
    ids = np.arange(X.size).reshape(Z.shape)
    quads = np.column_stack([ids[:-1, :-1].ravel(), ids[:-1, 1:].ravel(), ids[1:, 1:].ravel(),
                             ids[1:, :-1].ravel()])
    pts = np.column_stack([X.ravel(), -Z.ravel()])  # cam below the surface: y = -z
    data = {"stress": stress_tensor(sf.sx, sf.sz, sf.sy, sf.txz, -1.0), "tau1": sf.tau1,
            "von_mises": sf.von_mises}
    p = np.where(Z == 0.0, hc.pressure(X), 0.0).ravel()
    data["contact_pressure"] = p
    if wear:
        data["wear_rate"] = wear["k"] * p * wear["v_slip"]
    return write_vtu(path, pts, [("quad", quads)],
                     vtk_point_data({k: np.asarray(v, float) for k, v in data.items()}),
                     field_data=_field_data(wear))


def write_ring_vtu(path, model, result, bodies=("ring", "pin", "cam")) -> Path:
    """The bodies of a solved ring model (:func:`femcam.bodies.export.ring_arrays`) as ``.vtu``.

    Points in the roller frame (m; ring centre ``(0, Ro)``); point data at the P2 nodes
    (``triangle6`` cells): ``displacement`` (m), ``sxx, syy, sxy``, ``hoop``, ``von_mises``
    (Pa); cell data ``body``: 0 cam, 1 ring, 2 pin.

    Parameters
    ----------
    path : str or os.PathLike
        The ``.vtu`` file; its folder is created.
    model : femcam.bodies.RingModel
        The solved ring model.
    result : femcam.bodies.RingResult
        Its solution for one load case.
    bodies : tuple of str, optional
        The bodies, of ``"ring"``, ``"pin"``, ``"cam"`` (a missing one is skipped).

    Returns
    -------
    pathlib.Path
        The written file.
    """
    pts, cells, data, ids = ring_arrays(model, result, bodies)
    return write_vtu(path, pts, [("triangle6", cells)], data, cell_data={"body": [ids]})


def write_cam_vtu(path, model, result, bodies=("cam", "shaft")) -> Path:
    """The cam disk (and the shaft, if elastic) of a solved fully refined model as ``.vtu``
    (:func:`femcam.bodies.cam_export.cam_arrays`; cell data ``body``: 0 cam, 3 shaft).

    Parameters
    ----------
    path : str or os.PathLike
        The ``.vtu`` file; its folder is created.
    model : femcam.bodies.CamDiskModel
        The solved fully refined model.
    result : femcam.bodies.CamDiskResult
        Its solution for one load case.
    bodies : tuple of str, optional
        The bodies to write, of ``"cam"`` and ``"shaft"`` (a missing one is skipped).

    Returns
    -------
    pathlib.Path
        The written file.
    """
    pts, cells, data, ids = cam_arrays(model, result, bodies)
    return write_vtu(path, pts, [("triangle6", cells)], data, cell_data={"body": [ids]})


def write_global_cam_vtu(path, model, C, n, F: float, *, theta: float | None = None) -> Path:
    """The global model's cam at one contact as ``.vtu``
    (:func:`femcam.bodies.cam_export.global_cam_arrays`: point data with the unit in the name,
    field data ``theta_deg`` and ``Fc_N``).

    Parameters
    ----------
    path : str or os.PathLike
        Output ``.vtu``; its folder is created.
    model : femcam.bodies.CamGlobalModel
        The global cam-disk model.
    C, n : array_like, shape (2,)
        Contact point (m) and outward unit cam normal, cam frame.
    F : float
        Contact force (N, > 0).
    theta : float, optional
        The cam angle (rad), recorded as field data ``theta_deg`` (NaN if not given).

    Returns
    -------
    pathlib.Path
        The written file.
    """
    F = _validate.positive("F", F, "N")
    theta = _validate.optional(_validate.number, "theta", theta, "rad")
    pts, cells, data, field = global_cam_arrays(model, C, n, F,
                                                theta=float("nan") if theta is None else theta)
    return write_vtu(path, pts, [("triangle6", cells)], data, field_data=field)


def write_msh(path, mesh) -> Path:
    """Both bodies of a contact mesh as a gmsh 2.2 ASCII ``.msh`` file (``ContactMesh.msh_arrays``:
    nodes in m, the physical names ``roller_contact, cam_contact, roller_fixed, cam_fixed,
    roller, cam``).

    Parameters
    ----------
    path : str or os.PathLike
        Output file; must end in ``.msh``. Parent folders are created.
    mesh : femcam.mesh.ContactMesh
        The contact mesh (``ContactModel.mesh``).

    Returns
    -------
    pathlib.Path
        The path written.

    Raises
    ------
    InputError
        ``path`` is not a path ending in ``.msh``, or ``mesh`` is not a contact mesh.
    """
    _validate.instance("mesh", mesh, ContactMesh, "a femcam.mesh.ContactMesh")
    return write_gmsh(path, *mesh.msh_arrays())
