"""Mesh output: ``.vtu`` fields and gmsh ``.msh`` meshes through meshio (atomic), ParaView
``.pvd`` collections. The fields of a solved body (FE contact, Hertz, ring, cam disk) are in
:mod:`femcam.io.fields`; they are written through :func:`write_vtu`."""

from __future__ import annotations

import os
from pathlib import Path
from xml.sax.saxutils import escape, quoteattr

import numpy as np

from .. import _validate
from .atomic import atomic_write_path, atomic_write_text


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
        Output ``.vtu``; its folder is created.
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
    pts = np.asarray(points, dtype=float)
    if pts.shape[1] == 2:
        pts = np.column_stack([pts, np.zeros(len(pts))])
    mesh = _mesh(pts, cells, point_data={k: np.asarray(v) for k, v in point_data.items()},
                 cell_data=cell_data or {})

    def write(tmp):
        # compression=None: files read once; zlib would be most of the write time
        # (docs/performance.md)
        _meshio().write(tmp, mesh, file_format="vtu", binary=True, compression=None)
        if field_data:
            _insert_field_data(tmp, field_data)

    return _write_mesh(path, write)


def write_gmsh(path, points, cells, cell_data: dict, field_data: dict) -> Path:
    """A mesh as a gmsh 2.2 ASCII ``.msh`` file through meshio (atomic write).

    Parameters
    ----------
    path : str or os.PathLike
        Output file; must end in ``.msh``. Parent folders are created.
    points : ndarray, shape (n, 3)
        Node coordinates (m).
    cells : list of (str, ndarray)
        ``[("triangle", conn (nel, 3)), ("line", conn (nel, 2)), ...]``.
    cell_data : dict[str, list of ndarray]
        ``gmsh:physical`` and ``gmsh:geometrical`` tags, one array per cell block.
    field_data : dict[str, ndarray]
        The physical names: ``name -> [tag, dim]``.

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    InputError
        ``path`` is not a path ending in ``.msh``.
    """
    if not isinstance(path, str | os.PathLike):
        raise _validate.fail("path", path, "", "must be a file path (str or os.PathLike) ending in .msh")
    if Path(path).suffix.lower() != ".msh":
        raise _validate.fail("path", str(path), "", "must end in .msh (gmsh 2.2 ASCII mesh)")
    mesh = _mesh(points, cells, cell_data=cell_data, field_data=field_data)
    return _write_mesh(path, lambda tmp: _meshio().write(tmp, mesh, file_format="gmsh22",
                                                           binary=False))


def _meshio():
    import meshio  # lazy: meshio loads its many format plugins; only the mesh writers need it

    return meshio


def _mesh(points, cells, **data):
    return _meshio().Mesh(points, cells, **data)


def _write_mesh(path, write) -> Path:
    """``write(tmp)`` into a temp file renamed over ``path`` (:func:`atomic_write_path`); the
    folder is created."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    atomic_write_path(path, write)
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
