"""Writers: sweep tables (CSV with a provenance header, NPZ), VTU fields and PVD series.

* CSV: the first line is the header row, whose column names carry the unit (``theta_deg``,
  ``p0_fe_MPa``, ...); then ``# key: value`` comment lines (femcam/gmsh/scikit-fem/numpy
  versions, scene file and SHA-256, command line, date, options, model families, wear); then
  one row per cam angle. Text fields never contain ``,``, ``#``, quotes or line breaks (they
  are replaced by ``;``, ``No.``, ``'`` and spaces; the NPZ keeps the exact text), so
  ``numpy.genfromtxt(path, delimiter=",", names=True, dtype=None, encoding="utf-8")`` and
  ``pandas.read_csv(path, comment="#")`` read it directly, as does :func:`read_csv`.
* NPZ: the same table in SI (the internal column names) plus ``provenance_json``,
  ``scene_toml`` (the scene file's text, "" if the scene was built in code) and ``scene_repr``
  (the parsed scene as the sweep used it, e.g. after ``--law``).
* PVD: a ParaView collection; each ``DataSet`` is one ``.vtu`` whose ``timestep`` is the cam
  angle in degrees, so ParaView and pyvista play the sweep as an animation.
"""

from __future__ import annotations

import csv
import datetime as _dt
import hashlib
import importlib
import io as _io
import json
import platform
import shlex
import sys
from pathlib import Path
from xml.sax.saxutils import quoteattr

import numpy as np

from .sweep.result import COLUMNS, NUMERIC, TEXT_COLUMNS
from .sweep.store import _atomic_write_bytes, atomic_write_text


def file_hash(path) -> str:
    """SHA-256 of a file's bytes."""
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def versions() -> dict[str, str]:
    """Versions of femcam and the libraries that shape the numbers (imported lazily)."""
    from . import __version__

    out = {"femcam": __version__, "python": platform.python_version()}
    for mod, name in (("numpy", "numpy"), ("scipy", "scipy"), ("skfem", "scikit-fem"),
                      ("gmsh", "gmsh"), ("meshio", "meshio")):
        try:
            out[name] = str(getattr(importlib.import_module(mod), "__version__", "?"))
        except Exception:  # pragma: no cover - optional/missing
            out[name] = "not installed"
    return out


def provenance(*, scene_path=None, scene_hash=None, command=None, options=None,
               **extra) -> dict:
    """The provenance record written at the top of every output file (``extra``: further
    JSON-able entries, e.g. ``families``, ``wear``)."""
    rec = {"versions": versions(),
           "date": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"),
           "machine": f"{platform.machine()} {platform.system()} {platform.release()}"}
    if scene_path is not None:
        rec["scene"] = str(scene_path)
    if scene_hash is not None:
        rec["scene_sha256"] = scene_hash
    rec["command"] = command if command is not None else shlex.join(sys.argv)
    if options is not None:
        rec["options"] = options
    rec.update({k: v for k, v in extra.items() if v is not None})
    return rec


def _header_lines(prov: dict) -> list[str]:
    lines = ["femcam sweep results (units in the column names)"]
    v = prov.get("versions", {})
    lines.append("versions: " + ", ".join(f"{k} {val}" for k, val in v.items()))
    for key in ("scene", "scene_sha256", "scene_copy", "command", "date", "machine"):
        if key in prov:
            lines.append(f"{key}: {prov[key]}")
    for key in ("options", "families", "wear"):
        if key in prov:
            lines.append(f"{key}: " + json.dumps(prov[key], sort_keys=True))
    return ["# " + s.replace("\n", " ").replace("\r", " ") for s in lines]


_CSV_TEXT = str.maketrans({",": ";", "#": "No.", '"': "'", "\n": " ", "\r": " "})


def csv_text(value) -> str:
    """A text field as written to the CSV: no ``,``, ``#``, quotes or line breaks."""
    return str(value).translate(_CSV_TEXT)


def write_csv(path, table: dict, prov: dict | None = None) -> Path:
    """Write a sweep table as CSV (unit-suffixed columns, provenance header); atomic."""
    path = Path(path)
    buf = _io.StringIO()
    names = [c[1] for c in COLUMNS] + list(TEXT_COLUMNS)
    buf.write(",".join(names) + "\n")  # first line: numpy.genfromtxt(names=True) reads it
    for line in _header_lines(prov or {}):
        buf.write(line + "\n")
    n = len(table["theta"])
    cols = [np.asarray(table[k], dtype=float) * f for k, _, f in COLUMNS]
    text = [[csv_text(v) for v in np.asarray(table[k]).astype(str)] for k in TEXT_COLUMNS]
    for i in range(n):
        buf.write(",".join([f"{c[i]:.10g}" for c in cols] + [t[i] for t in text]) + "\n")
    atomic_write_text(path, buf.getvalue())
    return path


def read_csv(path) -> tuple[dict, dict]:
    """Read a CSV written by :func:`write_csv`: ``(columns in CSV units, header dict)``."""
    header, rows = {}, []
    with open(path, newline="") as f:
        lines = f.read().splitlines()
    body = []
    for line in lines:
        if line.startswith("# "):
            k, _, v = line[2:].partition(": ")
            header[k] = v
        else:
            body.append(line)
    reader = csv.reader(body)
    names = next(reader)
    rows = list(reader)
    cols = {}
    for j, name in enumerate(names):
        vals = [r[j] for r in rows]
        if name in TEXT_COLUMNS:
            cols[name] = np.array(vals, dtype=str)
        else:
            cols[name] = np.array(vals, dtype=float)
    return cols, header


def write_npz(path, table: dict, prov: dict | None = None, *, scene_toml: str = "",
              scene_repr: str = "") -> Path:
    """The table in SI units (internal names) + ``provenance_json``, ``scene_toml`` (the scene
    file's text) and ``scene_repr``; atomic."""
    arrays = {k: np.asarray(table[k], dtype=float) for k in NUMERIC if k in table}
    for k in TEXT_COLUMNS:
        arrays[k] = np.asarray(table[k]).astype(str)
    arrays["provenance_json"] = np.array(json.dumps(prov or {}, sort_keys=True))
    arrays["scene_toml"] = np.array(str(scene_toml))
    arrays["scene_repr"] = np.array(str(scene_repr))
    path = Path(path)
    _atomic_write_bytes(path, lambda f: np.savez_compressed(f, **arrays))
    return path


def write_pvd(path, entries) -> Path:
    """A ParaView collection: ``entries = [(timestep, vtu path), ...]``.

    ``timestep`` is the cam angle in degrees; vtu paths are written relative to the pvd.
    """
    path = Path(path)
    out = ['<?xml version="1.0"?>',
           '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">',
           "  <Collection>"]
    for t, vtu in sorted(entries, key=lambda e: float(e[0])):
        rel = Path(vtu).resolve().relative_to(path.parent.resolve()).as_posix() \
            if Path(vtu).is_absolute() else Path(vtu).as_posix()
        out.append(f'    <DataSet timestep="{float(t):.10g}" group="" part="0" '
                   f"file={quoteattr(rel)}/>")
    out += ["  </Collection>", "</VTKFile>", ""]
    atomic_write_text(path, "\n".join(out))
    return path


def write_vtu(path, points, cells, point_data: dict, field_data: dict | None = None,
              cell_data: dict | None = None) -> Path:
    """A mesh with point (and cell) data as ``.vtu`` through meshio (atomic write).

    ``points`` (n, 2) or (n, 3) in m; ``cells`` = ``[("triangle", conn), ...]``;
    ``field_data`` = ``{name: float or 1D array}``: VTK FieldData (one value per file, e.g. the
    cam angle), which meshio's VTU writer drops, so it is inserted into the XML here (pyvista
    ``mesh.field_data`` and ParaView read it).
    """
    import meshio

    pts = np.asarray(points, dtype=float)
    if pts.shape[1] == 2:
        pts = np.column_stack([pts, np.zeros(len(pts))])
    mesh = meshio.Mesh(pts, cells, point_data={k: np.asarray(v) for k, v in point_data.items()},
                       cell_data=cell_data or {})
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(path.stem + ".part.vtu")
    meshio.write(tmp, mesh, file_format="vtu", binary=True)
    if field_data:
        _insert_field_data(tmp, field_data)
    tmp.replace(path)
    return path


def _insert_field_data(path: Path, field_data: dict) -> None:
    """Add a ``<FieldData>`` block (ASCII Float64 arrays) to a VTU written by meshio."""
    from xml.sax.saxutils import escape

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
