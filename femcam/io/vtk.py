"""Mesh output: ``.vtu`` fields (in the layout of meshio's VTU writer, written here in one
pass) and gmsh ``.msh`` meshes through meshio (atomic), ParaView ``.pvd`` collections. The fields
of a solved body (FE contact, Hertz, ring, cam disk) are in :mod:`femcam.io.fields`; they are
written through :func:`write_vtu`."""

from __future__ import annotations

import base64
import os
import sys
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
    """A mesh with point (and cell) data as ``.vtu`` (atomic write).

    The file is the one meshio's VTU writer writes (``binary=True``, no compression: inline
    base64 arrays with a UInt32 byte count, meshio's element and attribute order) with a
    ``<FieldData>`` block, which meshio's writer drops. It is written here in one pass (the
    arrays encoded in memory, one write), about three times faster than meshio plus a second
    pass for the field data, which matters for a sweep's series of ``.vtu`` files; cell types
    or dtypes outside :data:`VTK_CELL_TYPES` / :data:`VTU_TYPES` go through meshio.

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
        VTK FieldData (one value per file, e.g. the cam angle), written as ASCII Float64 arrays
        (pyvista ``mesh.field_data`` and ParaView read it).
    cell_data : dict[str, list of ndarray], optional
        Arrays per cell block, as meshio takes them.

    Returns
    -------
    Path
        ``path``.
    """
    pts = np.asarray(points, dtype=float)
    if pts.shape[1] == 2:
        pts = np.column_stack([pts, np.zeros(len(pts))])
    pdata = {k: np.asarray(v) for k, v in point_data.items()}
    cdata = {k: [np.asarray(a) for a in v] for k, v in (cell_data or {}).items()}
    blocks = [(t, np.asarray(c)) for t, c in cells]
    parts = _vtu_parts(pts, blocks, pdata, cdata, field_data)
    if parts is not None:
        def write(tmp):
            _write_parts(tmp, parts)
    else:  # a cell type or dtype the direct writer does not know: meshio's writer
        mesh = _mesh(pts, cells, point_data=pdata, cell_data=cell_data or {})

        def write(tmp):
            # compression=None: files read once; zlib would be most of the write time
            # (docs/performance.md)
            _meshio().write(tmp, mesh, file_format="vtu", binary=True, compression=None)
            if field_data:
                _insert_field_data(tmp, field_data)

    return _write_mesh(path, write)


#: numpy dtype -> VTU ``DataArray`` type (meshio's table)
VTU_TYPES = {np.dtype(t): name for t, name in (
    (np.float32, "Float32"), (np.float64, "Float64"), (np.int8, "Int8"), (np.int16, "Int16"),
    (np.int32, "Int32"), (np.int64, "Int64"), (np.uint8, "UInt8"), (np.uint16, "UInt16"),
    (np.uint32, "UInt32"), (np.uint64, "UInt64"))}
#: meshio cell type -> (VTK cell type id, nodes per cell), for the cells femcam writes (same
#: node order in meshio and VTK)
VTK_CELL_TYPES = {"vertex": (1, 1), "line": (3, 2), "triangle": (5, 3), "quad": (9, 4),
                  "tetra": (10, 4), "hexahedron": (12, 8), "line3": (21, 3), "triangle6": (22, 6),
                  "quad8": (23, 8), "tetra10": (24, 10), "quad9": (28, 9)}


def _vtu_parts(points, blocks, point_data, cell_data, field_data) -> list | None:
    """The bytes of a ``.vtu`` (the layout of meshio's binary, uncompressed VTU writer, plus
    the field data) as a list of parts, or None for an unsupported cell type or dtype."""
    if not blocks or any(t not in VTK_CELL_TYPES or c.ndim != 2 or c.shape[1] != VTK_CELL_TYPES[t][1]
                         for t, c in blocks):
        return None
    arrays = [points, *point_data.values(), *(a for v in cell_data.values() for a in v)]
    if any(a.dtype.newbyteorder("=") not in VTU_TYPES for a in arrays):
        return None
    if any(len(a) != len(points) for a in point_data.values()) or any(
            len(v) != len(blocks) or any(len(a) != len(c) for a, (_, c) in zip(v, blocks, strict=False))
            for v in cell_data.values()):
        return None  # meshio's writer says what does not fit
    conn = np.concatenate([c.ravel() for _, c in blocks])
    offsets = [c.shape[1] * np.arange(1, c.shape[0] + 1, dtype=conn.dtype) for _, c in blocks]
    for k in range(1, len(offsets)):
        offsets[k] += offsets[k - 1][-1]
    types = np.concatenate([np.full(len(c), VTK_CELL_TYPES[t][0]) for t, c in blocks])
    out = [b'<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="0.1" byte_order="',
           (b"LittleEndian" if sys.byteorder == "little" else b"BigEndian"),
           b'">\n<!--This file was written by femcam in the layout of meshio\'s VTU writer-->\n'
           b"<UnstructuredGrid>\n"]
    if field_data:
        out += [_field_data_block(field_data), b"\n"]
    out.append(f'<Piece NumberOfPoints="{len(points)}" NumberOfCells="{len(types)}">\n<Points>\n'
               .encode())
    out += _data_array("Points", points)
    out.append(b"</Points>\n<Cells>\n")
    for name, a in (("connectivity", conn), ("offsets", np.concatenate(offsets)), ("types", types)):
        out += _data_array(name, a)
    out.append(b"</Cells>\n")
    for tag, data in (("PointData", point_data),
                      ("CellData", {k: np.concatenate(v) for k, v in cell_data.items()})):
        if data:
            out.append(f"<{tag}>\n".encode())
            for name, a in data.items():
                out += _data_array(name, a)
            out.append(f"</{tag}>\n".encode())
    out.append(b"</Piece>\n</UnstructuredGrid>\n</VTKFile>\n")
    return out


def _write_parts(path, parts: list) -> None:
    """Write the byte strings ``parts`` to the file ``path``, one after the other."""
    with open(path, "wb") as f:
        f.writelines(parts)


def _data_array(name: str, a: np.ndarray) -> list:
    """One binary ``DataArray``: base64 of a UInt32 byte count and the native-order bytes."""
    a = a.astype(a.dtype.newbyteorder("="), copy=False)
    raw = a.tobytes()
    comps = f' NumberOfComponents="{a.shape[1]}"' if a.ndim == 2 else ""
    return [f'<DataArray type="{VTU_TYPES[a.dtype]}" Name="{name}"{comps} format="binary">\n'.encode(),
            base64.b64encode(np.array(len(raw), dtype=np.uint32).tobytes() + raw),
            b"\n</DataArray>\n"]


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


def _field_data_block(field_data: dict) -> bytes:
    """A ``<FieldData>`` block (ASCII Float64 arrays, one per name)."""
    arrays = []
    for name, val in field_data.items():
        v = np.atleast_1d(np.asarray(val, dtype=float)).ravel()
        txt = " ".join(repr(float(x)) for x in v)
        arrays.append(f'<DataArray type="Float64" Name={quoteattr(str(name))} '
                      f'NumberOfTuples="{v.size}" format="ascii">{escape(txt)}</DataArray>')
    return ("<FieldData>\n" + "\n".join(arrays) + "\n</FieldData>\n").encode()


def _insert_field_data(path: Path, field_data: dict) -> None:
    """Add a ``<FieldData>`` block to a VTU written by meshio."""
    data = path.read_bytes()
    tag = b"<UnstructuredGrid>"
    k = data.find(tag)
    if k < 0:  # pragma: no cover - not a meshio VTU
        return
    k += len(tag)
    path.write_bytes(data[:k] + b"\n" + _field_data_block(field_data) + data[k:])


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
