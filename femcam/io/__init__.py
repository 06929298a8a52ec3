"""Writers: result tables (plain CSV with a sidecar JSON, NPZ), VTU fields, PVD series, gmsh
meshes, and the atomic file writes they all go through. Every file femcam writes is written here
(``tests/test_writers.py`` fails on a writer elsewhere): the lower layers hand over arrays.

This package knows no sweep: a table is a dict of arrays written through a column list
``[(internal SI name, CSV column name, factor SI -> CSV unit), ...]`` that the caller owns
(:data:`femcam.sweep.table.COLUMNS` for a sweep), so the writers sit below the sweep in the
layer order (docs/architecture.md).

* CSV (:func:`write_csv`, :func:`write_table`): line 1 holds the column names, whose names carry
  the unit (``theta_deg``, ``p0_fe_MPa``, ...); then one row per line, nothing else, so
  ``pandas.read_csv(path)`` and ``numpy.genfromtxt(path, delimiter=",", names=True, dtype=None,
  encoding="utf-8")`` read it as it is. Text fields never contain ``,``, ``#``, quotes or line
  breaks (replaced by ``;``, ``No.``, ``'`` and spaces; the NPZ keeps the exact text).
* Sidecar JSON (:func:`meta_path`: ``X.csv`` -> ``X.csv-metadata.json``): the provenance
  (femcam/gmsh/scikit-fem/numpy versions, scene file and SHA-256, command line, date, machine,
  options, model families, wear, ...), the column names and datatypes and the row count; one
  layout for every CSV.
* NPZ: the same table in SI (the internal column names) plus ``provenance_json``,
  ``scene_toml`` (the scene file's text, "" if the scene was built in code) and ``scene_repr``
  (the parsed scene as the sweep used it, e.g. after ``--law``).
* PVD: a ParaView collection; each ``DataSet`` is one ``.vtu`` whose ``timestep`` is the cam
  angle in degrees, so ParaView and pyvista play the sweep as an animation.
"""

from .atomic import TEMP_SUFFIX, atomic_write_bytes, atomic_write_path, atomic_write_text
from .fields import (
    write_cam_vtu,
    write_fe_vtu,
    write_global_cam_vtu,
    write_hertz_vtu,
    write_msh,
    write_ring_vtu,
)
from .provenance import header_dict, provenance, versions
from .tables import (
    CSV_EMPTY,
    META_SUFFIX,
    Column,
    csv_text,
    meta_path,
    read_csv,
    read_meta,
    write_arrays,
    write_csv,
    write_npz,
    write_rows,
    write_table,
)
from .vtk import vtu_name, write_pvd, write_vtu

__all__ = ["CSV_EMPTY", "META_SUFFIX", "TEMP_SUFFIX", "Column", "atomic_write_bytes",
           "atomic_write_path", "atomic_write_text", "csv_text", "header_dict", "meta_path",
           "provenance", "read_csv", "read_meta", "versions", "vtu_name", "write_arrays",
           "write_cam_vtu", "write_csv", "write_fe_vtu", "write_global_cam_vtu", "write_hertz_vtu",
           "write_msh", "write_npz", "write_pvd", "write_ring_vtu", "write_rows", "write_table",
           "write_vtu"]
