"""Writers: result tables (CSV with a provenance header, NPZ), VTU fields, PVD series, and the
atomic file writes every other writer (the sweep's chunk store included) goes through.

This module knows no sweep: a table is a dict of arrays written through a column list
``[(internal SI name, CSV column name, factor SI -> CSV unit), ...]`` that the caller owns
(:data:`femcam.sweep.result.COLUMNS` for a sweep), so the writers sit below the sweep in the
layer order (docs/architecture.md).

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
import importlib.metadata
import json
import os
import platform
import shlex
import sys
import tempfile
import zipfile
from collections.abc import Callable, Sequence
from pathlib import Path
from xml.sax.saxutils import escape, quoteattr

import numpy as np

from . import _validate
from .fe.export import scene_arrays, stress_tensor, vtk_point_data
from .hertz import LineContact

#: one column of a written table: (internal SI name, CSV column name, factor SI -> CSV unit)
Column = tuple[str, str, float]


# ---------------------------------------------------------------------------------------------
# atomic writes
# ---------------------------------------------------------------------------------------------
def _umask() -> int:
    """The process umask, read without changing it where possible (Linux /proc), else by the
    classic set-and-restore."""
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    old = os.umask(0o022)
    os.umask(old)
    return old


def atomic_write_bytes(path, write: Callable) -> None:
    """Call ``write(fileobj)`` on a temp file next to ``path``, fsync, then rename over ``path``.

    Parameters
    ----------
    path : str or Path
        Destination file; a reader sees either the old file or the whole new one.
    write : callable
        ``write(f)`` writes the content to the binary file object ``f``.

    Notes
    -----
    The file gets the mode an ordinary ``open(path, "w")`` would give (``0o666 & ~umask``), not
    mkstemp's private 0600.
    """
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=path.name + ".", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as f:
            write(f)
            f.flush()
            os.fsync(f.fileno())
        os.chmod(tmp, 0o666 & ~_umask())
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def atomic_write_text(path, text: str) -> None:
    """Write ``text`` to ``path`` atomically (:func:`atomic_write_bytes`).

    Parameters
    ----------
    path : str or Path
        Destination file.
    text : str
        Content, written as UTF-8.
    """
    atomic_write_bytes(Path(path), lambda f: f.write(text.encode("utf-8")))


# ---------------------------------------------------------------------------------------------
# provenance
# ---------------------------------------------------------------------------------------------
def versions() -> dict[str, str]:
    """Versions of femcam and the libraries that shape the numbers.

    Returns
    -------
    dict[str, str]
        ``{"femcam", "python", "numpy", "scipy", "scikit-fem", "gmsh", "meshio"}`` -> version.
    """
    # the package's own version: femcam/__init__.py is always imported before this submodule
    # (a lookup, not an import: the root package sits above every layer)
    out = {"femcam": sys.modules[__package__].__version__, "python": platform.python_version()}
    for mod, name in (("numpy", "numpy"), ("scipy", "scipy"), ("skfem", "scikit-fem"),
                      ("gmsh", "gmsh"), ("meshio", "meshio")):
        try:
            if mod in sys.modules:
                out[name] = str(getattr(sys.modules[mod], "__version__", "?"))
            else:  # the installed version without importing it (meshio: ~0.05 s for nothing)
                out[name] = importlib.metadata.version(name)
        except Exception:  # pragma: no cover - optional/missing
            out[name] = "not installed"
    return out


def provenance(*, scene_path=None, scene_hash=None, command=None, options=None,
               **extra) -> dict:
    """The provenance record written at the top of every output file.

    Parameters
    ----------
    scene_path, scene_hash : str, optional
        Scene file and its SHA-256.
    command : str, optional
        The command line (default: ``sys.argv``).
    options : dict, optional
        JSON-able options of the run.
    **extra
        Further JSON-able entries, e.g. ``families``, ``wear`` (``None`` values are dropped).

    Returns
    -------
    dict
        Versions, UTC date, machine, and the entries above.
    """
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
    for key in ("options", "families", "wear", "extras"):
        if key in prov:
            lines.append(f"{key}: " + json.dumps(prov[key], sort_keys=True))
    return ["# " + s.replace("\n", " ").replace("\r", " ") for s in lines]


_CSV_TEXT = str.maketrans({",": ";", "#": "No.", '"': "'", "\n": " ", "\r": " "})


#: an empty text field as written to the CSV: ``numpy.genfromtxt(..., dtype=None)`` reads a
#: column of empty fields as bool, a column with ``-`` as text (:func:`read_csv` maps it back)
CSV_EMPTY = "-"


def csv_text(value) -> str:
    """A text field as written to the CSV: no ``,``, ``#``, quotes or line breaks; an empty
    field is :data:`CSV_EMPTY`.

    Parameters
    ----------
    value : object
        The field value (converted with ``str``).

    Returns
    -------
    str
        The CSV-safe text.

    >>> csv_text('a, "b" #1'), csv_text("")
    ("a; 'b' No.1", '-')
    """
    return str(value).translate(_CSV_TEXT) or CSV_EMPTY


def write_csv(path, table: dict, prov: dict | None = None, *, columns: Sequence[Column],
              text_columns: Sequence[str] = ()) -> Path:
    """Write a table as CSV (unit-suffixed columns, provenance header); atomic.

    Parameters
    ----------
    path : str or Path
        Output file.
    table : dict[str, ndarray]
        One array per column, SI units, all of one length n.
    prov : dict, optional
        Provenance (:func:`provenance`), written as ``# key: value`` lines.
    columns : sequence of (name, csv_name, factor)
        Numeric columns in CSV order; ``csv = SI * factor``.
    text_columns : sequence of str
        String columns written after the numeric ones (:func:`csv_text`).

    Returns
    -------
    Path
        ``path``.
    """
    path = Path(path)
    names = [c[1] for c in columns] + list(text_columns)
    head = [",".join(names)] + _header_lines(prov or {})  # line 1: genfromtxt(names=True)

    def write(f):  # in blocks of rows: memory independent of n
        f.write(("\n".join(head) + "\n").encode())
        for rows in _row_blocks(table):
            cols = [np.asarray(rows[k], dtype=float) * fac for k, _, fac in columns]
            text = [[csv_text(v) for v in np.asarray(rows[k]).astype(str)] for k in text_columns]
            f.write("".join(",".join([f"{c[i]:.10g}" for c in cols] + [t[i] for t in text]) + "\n"
                            for i in range(len(rows["theta"]))).encode())

    atomic_write_bytes(path, write)
    return path


def _row_blocks(table, block: int = 2000):
    """The table in blocks of rows (dicts of arrays): its own chunks if it has them (a table
    kept on disk, :class:`femcam.sweep.store.StoredTable`), else slices of ``block`` rows."""
    chunks = getattr(table, "chunks", None)
    if chunks is not None:
        yield from chunks()
        return
    n = len(table["theta"])
    for a in range(0, n, block):
        yield {k: v[a:a + block] for k, v in table.items()}


def read_csv(path) -> tuple[dict, dict]:
    """Read a CSV written by :func:`write_csv`.

    Parameters
    ----------
    path : str or Path
        A file written by :func:`write_csv`.

    Returns
    -------
    columns : dict[str, ndarray]
        Numeric columns (float, CSV units) and text columns (str): a column is text when one of
        its values is not a number.
    header : dict[str, str]
        The ``# key: value`` provenance lines.
    """
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
        try:
            cols[name] = np.array(vals, dtype=float)
        except ValueError:
            cols[name] = np.array(["" if v == CSV_EMPTY else v for v in vals], dtype=str)
    return cols, header


def write_npz(path, table: dict, prov: dict | None = None, *, numeric: Sequence[str],
              text_columns: Sequence[str] = (), integer_columns: Sequence[str] = (),
              scene_toml: str = "", scene_repr: str = "", extra: dict | None = None) -> Path:
    """The table in SI units (internal names) plus provenance and scene text; atomic.

    Parameters
    ----------
    path : str or Path
        Output ``.npz``.
    table : dict[str, ndarray]
        One array per column (SI).
    prov : dict, optional
        Provenance, stored as the JSON string ``provenance_json``.
    numeric, text_columns : sequence of str
        Names of the float and the string columns to store.
    integer_columns : sequence of str
        Those of ``numeric`` stored as int64 (counts, ids), with -1 where the table has NaN.
    scene_toml, scene_repr : str
        The scene file's text and the parsed scene's ``repr``.
    extra : dict[str, ndarray], optional
        More arrays stored as they are (e.g. the plots' data, so a reloaded sweep re-plots).

    Returns
    -------
    Path
        ``path``.
    """
    ints = set(integer_columns)

    def arrays():  # one column at a time (a table kept on disk reads each column on access)
        for k in numeric:
            if k in table:
                v = np.asarray(table[k], dtype=float)
                # counts and ids: int64, -1 where undefined (NaN)
                yield k, (np.where(np.isfinite(v), v, -1).astype(np.int64) if k in ints else v)
        for k in text_columns:
            yield k, np.asarray(table[k]).astype(str)
        yield "provenance_json", np.array(json.dumps(prov or {}, sort_keys=True))
        yield "scene_toml", np.array(str(scene_toml))
        yield "scene_repr", np.array(str(scene_repr))
        yield from ((k, np.asarray(v)) for k, v in (extra or {}).items())

    path = Path(path)
    atomic_write_bytes(path, lambda f: _savez_stream(f, arrays()))
    return path


def _savez_stream(f, items) -> None:
    """``numpy.savez_compressed`` of ``(name, array)`` pairs written one by one (the same
    ``.npz`` format: a deflated zip of ``name.npy`` members), so only one array is in memory."""
    with zipfile.ZipFile(f, mode="w", compression=zipfile.ZIP_DEFLATED, allowZip64=True) as zf:
        for name, arr in items:
            with zf.open(name + ".npy", "w", force_zip64=True) as member:
                np.lib.format.write_array(member, arr, allow_pickle=False)


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
