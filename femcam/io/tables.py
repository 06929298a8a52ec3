"""Tables: CSV (one header line, then the rows; the provenance in a sidecar JSON) and NPZ."""

from __future__ import annotations

import csv
import json
import zipfile
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from .._columns import Column
from ..errors import InputError
from .atomic import atomic_write_bytes
from .provenance import header_dict

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


#: the sidecar of ``X.csv`` is ``X.csv-metadata.json`` (the default metadata location of the W3C
#: "CSV on the Web" recommendation, so CSVW tools find it too)
META_SUFFIX = "-metadata.json"


def meta_path(path) -> Path:
    """The sidecar JSON of a CSV: ``sweep.csv`` -> ``sweep.csv-metadata.json``.

    Parameters
    ----------
    path : str or Path
        The CSV file.

    Returns
    -------
    Path
        The sidecar next to it.

    >>> meta_path("out/sweep.csv").as_posix()
    'out/sweep.csv-metadata.json'
    """
    path = Path(path)
    return path.with_name(path.name + META_SUFFIX)


def _datatype(a: np.ndarray) -> str:
    return "number" if a.dtype.kind in "biuf" else "string"


def _fields(a) -> list[str]:
    """One column as CSV fields: numbers with 10 significant digits (``nan`` where undefined),
    booleans as 0/1, integers as integers, text through :func:`csv_text`."""
    a = np.asarray(a)
    if a.dtype.kind == "O":
        try:
            a = a.astype(float)
        except (TypeError, ValueError):
            a = a.astype(str)
    if a.dtype.kind in "biu":
        return [str(int(x)) for x in a]
    if a.dtype.kind == "f":
        return [f"{x:.10g}" for x in a]
    return [csv_text(x) for x in a.astype(str)]


def _write_table(path, names: list[str], blocks, prov: dict | None, title: str) -> Path:
    """The one CSV writer: line 1 the column names, then the rows (``blocks`` yields lists of
    arrays, one per name), then the sidecar JSON (:func:`meta_path`); both atomic."""
    path = Path(path)
    kinds, n = {}, [0]

    def write(f):
        f.write((",".join(names) + "\n").encode())
        for cols in blocks:
            for name, c in zip(names, cols, strict=True):
                kinds.setdefault(name, _datatype(np.asarray(c)))
            fields = [_fields(c) for c in cols]
            rows = len(fields[0]) if fields else 0
            n[0] += rows
            f.write("".join(",".join(col[i] for col in fields) + "\n" for i in range(rows)).encode())

    atomic_write_bytes(path, write)
    meta = {"@context": "http://www.w3.org/ns/csvw", "url": path.name, "dc:title": title,
            "tableSchema": {"columns": [{"name": k, "datatype": kinds.get(k, "string")}
                                        for k in names]},
            "rows": n[0], "provenance": prov or {}}
    text = json.dumps(meta, indent=1, default=str, allow_nan=True)
    atomic_write_bytes(meta_path(path), lambda f: f.write((text + "\n").encode()))
    return path


def write_table(path, columns: dict, prov: dict | None = None, *, title: str = "") -> Path:
    """Write a table as a plain CSV (one header line, then the rows) plus its sidecar JSON.

    Every CSV femcam writes goes through here or :func:`write_csv`: ``pandas.read_csv(path)``,
    ``numpy.genfromtxt(path, delimiter=",", names=True, dtype=None, encoding="utf-8")`` and
    :func:`read_csv` read it as it is; the provenance is in ``path`` + ``-metadata.json``
    (:func:`meta_path`, :func:`read_meta`).

    Parameters
    ----------
    path : str or Path
        Output ``.csv``.
    columns : dict[str, array_like]
        Column name (unit in the name, e.g. ``Fc_N``) -> values already in that unit, all of one
        length. Floats are written with 10 significant digits, integers and booleans (as 0/1)
        exactly, anything else as text (:func:`csv_text`).
    prov : dict, optional
        Provenance (:func:`femcam.io.provenance` plus any JSON-able entries of the table).
    title : str
        What the table is (one line), stored as the sidecar's ``dc:title``.

    Returns
    -------
    Path
        ``path``.
    """
    names = list(columns)
    return _write_table(path, names, iter([[columns[k] for k in names]]), prov, title)


def write_rows(path, header: Sequence[str], rows, prov: dict | None = None, *,
               title: str = "", text: Sequence[str] = ()) -> Path:
    """:func:`write_table` of a table given as rows (``header`` and one list per row).

    A column whose fields all read as numbers (an empty field counts as NaN) is written as
    numbers, any other (and those named in ``text``) as text.

    Parameters
    ----------
    path : str or Path
        Output ``.csv``.
    header : sequence of str
        Column names, units in the names.
    rows : iterable of sequence
        One sequence of values (numbers or text) per row, in ``header`` order.
    prov : dict, optional
        Provenance for the sidecar JSON.
    title : str
        The sidecar's ``dc:title``.
    text : sequence of str
        Columns always written as text (an empty field is :data:`CSV_EMPTY`).

    Returns
    -------
    Path
        ``path``.
    """
    rows = [list(r) for r in rows]
    cols = {}
    for j, name in enumerate(header):
        vals = [r[j] for r in rows]
        try:
            if name in text:
                raise ValueError(name)
            cols[name] = np.array([np.nan if v == "" else float(v) for v in vals], dtype=float)
        except (TypeError, ValueError):
            cols[name] = np.array([str(v) for v in vals], dtype=str)
    return write_table(path, cols, prov, title=title)


def write_csv(path, table: dict, prov: dict | None = None, *, columns: Sequence[Column],
              text_columns: Sequence[str] = (), title: str = "") -> Path:
    """Write an SI table as CSV through a column list (unit-suffixed names) plus the sidecar JSON.

    Parameters
    ----------
    path : str or Path
        Output file.
    table : dict[str, ndarray]
        One array per column, SI units, all of one length n (a table kept on disk is written
        chunk by chunk).
    prov : dict, optional
        Provenance (:func:`femcam.io.provenance`), written to the sidecar (:func:`meta_path`).
    columns : sequence of femcam._columns.Column
        Numeric columns in CSV order; ``csv = SI * factor``.
    text_columns : sequence of str
        String columns written after the numeric ones (:func:`csv_text`).
    title : str
        The sidecar's ``dc:title``.

    Returns
    -------
    Path
        ``path``.
    """
    names = [c.csv for c in columns] + list(text_columns)

    def blocks():  # in blocks of rows: memory independent of n
        for rows in _row_blocks(table):
            yield ([np.asarray(rows[c.si], dtype=float) * c.factor for c in columns]
                   + [np.asarray(rows[k]).astype(str) for k in text_columns])

    return _write_table(path, names, blocks(), prov, title)


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


def read_meta(path) -> dict:
    """The sidecar JSON of a CSV written by femcam.

    Parameters
    ----------
    path : str or Path
        The CSV (or its sidecar).

    Returns
    -------
    dict
        ``url``, ``dc:title``, ``tableSchema`` (column names and datatypes), ``rows`` and
        ``provenance``.

    Raises
    ------
    InputError
        No sidecar (a CSV from an older femcam keeps its provenance in ``#`` lines instead:
        :func:`read_csv` reads those).
    """
    path = Path(path)
    meta = path if path.name.endswith(META_SUFFIX) else meta_path(path)
    if not meta.is_file():
        raise InputError(f"path = {path}: no sidecar {meta.name} (a CSV written by an older femcam "
                         "has its provenance in '#' lines, read by femcam.io.read_csv)")
    return json.loads(meta.read_text(encoding="utf-8"))


def read_csv(path) -> tuple[dict, dict]:
    """Read a CSV written by femcam (:func:`write_csv`, :func:`write_table`).

    Parameters
    ----------
    path : str or Path
        The CSV. Its provenance comes from the sidecar JSON (:func:`meta_path`); a CSV written
        by an older femcam, with ``# key: value`` lines after (or before) the header line and no
        sidecar, is read too.

    Returns
    -------
    columns : dict[str, ndarray]
        Numeric columns (float, CSV units) and text columns (str): a column is text when one of
        its values is not a number.
    header : dict[str, str]
        The provenance, one text line per entry (:func:`femcam.io.provenance.header_dict`),
        plus ``title``.
    """
    header = {}
    with open(path, newline="", encoding="utf-8") as f:
        lines = f.read().splitlines()
    body = []
    for line in lines:
        if line.startswith("# "):   # an older femcam's provenance lines
            k, _, v = line[2:].partition(": ")
            header[k] = v
        else:
            body.append(line)
    if meta_path(path).is_file():
        meta = read_meta(path)
        header = {"title": str(meta.get("dc:title", "")), **header_dict(meta.get("provenance", {}))}
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


def write_arrays(path, arrays: dict) -> Path:
    """Named arrays as one uncompressed ``.npz`` (``numpy.savez``), atomic.

    Parameters
    ----------
    path : str or Path
        Output ``.npz``.
    arrays : dict[str, ndarray]
        Name -> array (no object arrays: read back with ``allow_pickle=False``).

    Returns
    -------
    Path
        ``path``.
    """
    path = Path(path)
    atomic_write_bytes(path, lambda f: np.savez(f, **arrays))
    return path


def _savez_stream(f, items) -> None:
    """``numpy.savez_compressed`` of ``(name, array)`` pairs written one by one (the same
    ``.npz`` format: a deflated zip of ``name.npy`` members), so only one array is in memory."""
    with zipfile.ZipFile(f, mode="w", compression=zipfile.ZIP_DEFLATED, allowZip64=True) as zf:
        for name, arr in items:
            with zf.open(name + ".npy", "w", force_zip64=True) as member:
                np.lib.format.write_array(member, arr, allow_pickle=False)

