"""VTK output: ``.vtu`` fields through meshio (atomic), ParaView ``.pvd`` collections, and the
VTU of one solved cam angle (FE result or analytic Hertz field, plus wear)."""

from __future__ import annotations

import os
from pathlib import Path
from xml.sax.saxutils import escape, quoteattr

import numpy as np

from .. import _validate
from ..fe.export import scene_arrays, stress_tensor, vtk_point_data
from ..hertz import LineContact
from .atomic import atomic_write_text


def write_pvd(path, entries) -> Path:
    """A ParaView collection.

    Parameters
    ----------
    path : str or Path
        Output ``.pvd``.
    entries : iterable of (float, path)
        ``(timestep, vtu path)``; the timestep is the cam angle in degrees; vtu paths are
        written relative to the pvd.

    Returns
    -------
    Path
        ``path``.
    """
    path = Path(path)
    out = ['<?xml version="1.0"?>',
           '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">',
           "  <Collection>"]
    for t, vtu in sorted(entries, key=lambda e: float(e[0])):
        # relative to the .pvd (ParaView's convention), whatever the form (relative to the
        # working directory, or absolute) of the paths given
        rel = Path(os.path.relpath(Path(vtu).resolve(), path.parent.resolve())).as_posix()
        out.append(f'    <DataSet timestep="{float(t):.10g}" group="" part="0" '
                   f"file={quoteattr(rel)}/>")
    out += ["  </Collection>", "</VTKFile>", ""]
    atomic_write_text(path, "\n".join(out))
    return path


def write_vtu(path, points, cells, point_data: dict, field_data: dict | None = None,
              cell_data: dict | None = None) -> Path:
    """A mesh with point (and cell) data as ``.vtu`` through meshio (atomic write).

    Parameters
    ----------
    path : str or Path
        Output ``.vtu``.
    points : ndarray, shape (n, 2) or (n, 3)
        Node coordinates (m).
    cells : list of (str, ndarray)
        ``[("triangle", conn (nel, 3)), ...]``.
    point_data : dict[str, ndarray]
        Arrays of length n.
    field_data : dict[str, float or 1D array], optional
        VTK FieldData (one value per file, e.g. the cam angle), which meshio's VTU writer drops,
        so it is inserted into the XML here (pyvista ``mesh.field_data`` and ParaView read it).
    cell_data : dict[str, list of ndarray], optional
        meshio cell data.

    Returns
    -------
    Path
        ``path``.
    """
    import meshio  # lazy: meshio pulls in its many format plugins; only VTU writing needs it

    pts = np.asarray(points, dtype=float)
    if pts.shape[1] == 2:
        pts = np.column_stack([pts, np.zeros(len(pts))])
    mesh = meshio.Mesh(pts, cells, point_data={k: np.asarray(v) for k, v in point_data.items()},
                       cell_data=cell_data or {})
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(path.stem + ".part.vtu")
    try:
        # compression=None: zlib took 29 of 32 ms per file (measured), for files read once
        meshio.write(tmp, mesh, file_format="vtu", binary=True, compression=None)
        if field_data:
            _insert_field_data(tmp, field_data)
        tmp.replace(path)
    except BaseException:  # a full disk, Ctrl-C: no half-written .part.vtu is left behind
        tmp.unlink(missing_ok=True)
        raise
    return path


def _insert_field_data(path: Path, field_data: dict) -> None:
    """Add a ``<FieldData>`` block (ASCII Float64 arrays) to a VTU written by meshio."""
    arrays = []
    for name, val in field_data.items():
        v = np.atleast_1d(np.asarray(val, dtype=float)).ravel()
        txt = " ".join(repr(float(x)) for x in v)
        arrays.append(f'<DataArray type="Float64" Name={quoteattr(str(name))} '
                      f'NumberOfTuples="{v.size}" format="ascii">{escape(txt)}</DataArray>')
    block = "<FieldData>\n" + "\n".join(arrays) + "\n</FieldData>\n"
    data = path.read_bytes()
    tag = b"<UnstructuredGrid>"
    k = data.find(tag)
    if k < 0:  # pragma: no cover - not a meshio VTU
        return
    k += len(tag)
    path.write_bytes(data[:k] + b"\n" + block.encode() + data[k:])


# ---------------------------------------------------------------------------------------------
# VTU of one solved angle (sweep): FE result or analytic Hertz field, plus wear
# ---------------------------------------------------------------------------------------------
def vtu_name(theta: float) -> str:
    """File name of the ``.vtu`` of one cam angle: ``angle_<deg>deg.vtu``.

    Parameters
    ----------
    theta : float
        Cam angle [rad].

    Returns
    -------
    str
        The file name, the angle in degrees with 3 decimals (``angle_0090.000deg.vtu``).

    >>> vtu_name(np.pi / 2)
    'angle_0090.000deg.vtu'
    """
    return f"angle_{np.degrees(_validate.number('theta', theta, 'rad')):08.3f}deg.vtu"


def _field_data(wear: dict | None) -> dict:
    if not wear:
        return {}
    return {"theta_deg": wear["theta_deg"], "Fc_N": wear["Fc"], "wear_k_m3_per_N_m": wear["k"],
            "v_slip_m_s": wear["v_slip"], "V_cam_m_s": wear["V_cam"],
            "wear_depth_per_rev_m": wear["wear_depth_per_rev"]}


def write_fe_vtu(path, r, wear: dict | None = None) -> Path:
    """Both bodies of a solved angle (:func:`femcam.fe.export.scene_arrays`) plus wear.

    Parameters
    ----------
    path : str or Path
        Output ``.vtu``.
    r : femcam.fe.ContactResult
        The solved load case.
    wear : dict, optional
        ``{"k" (m^3/(N m)), "v_slip" (m/s), "V_cam" (m/s), "wear_depth_per_rev" (m),
        "theta_deg" (deg), "Fc" (N)}``. Adds the point data ``wear_rate_m_s``: Archard's local
        rate ``k p v_slip`` on the contact surfaces (``p`` = the FE nodal contact pressure), 0
        elsewhere, and the field data ``theta_deg``, ``Fc_N``, ``wear_k_m3_per_N_m``,
        ``v_slip_m_s``, ``V_cam_m_s``, ``wear_depth_per_rev_m``.

    Returns
    -------
    Path
        ``path``.
    """
    points, cells, cell_type, point_data, body = scene_arrays(r)
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
