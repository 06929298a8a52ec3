"""One writer layer (docs/architecture.md, "Style numbers"): every file femcam writes (CSV, NPZ,
VTU, MSH, JSON, text) goes through :mod:`femcam.io`; a writer anywhere else fails this test.

The calls are read from the source with :mod:`ast` (no femcam import): ``meshio.write``,
``numpy.save*``/``savetxt``/``tofile``, ``Path.write_text``/``write_bytes``, ``json.dump``/
``pickle.dump`` to a file, ``csv.writer``, pandas ``to_csv``/``to_parquet``, ``open`` with a
write/append/create mode and ``os.open`` with a write flag. Plots (``savefig``, pyvista
``screenshot``) are drawn by :mod:`femcam.viz` and are not table/mesh writers.
"""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PKG = ROOT / "femcam"

#: writer methods/functions by attribute name (``obj.<name>(...)``)
WRITER_ATTRS = {"write_text", "write_bytes", "savez", "savez_compressed", "save", "savetxt",
                "tofile", "to_csv", "to_parquet", "writer", "dump"}

#: the writer calls allowed outside femcam/io, each with its reason:
#: (module path, text in the call's source) -> why
ALLOWED = {
    ("femcam/cli/__init__.py", "os.devnull"): "the sink of --quiet and of a closed stdout, no file",
    ("femcam/sweep/store.py", "os.open(self.path, os.O_RDWR | os.O_CREAT"):
        "the output folder's lock file (flock), no result",
}


def _call_name(node: ast.Call) -> str | None:
    """The writer a call is, or None."""
    f = node.func
    if isinstance(f, ast.Name) and f.id == "open":
        mode = node.args[1] if len(node.args) > 1 else next(
            (k.value for k in node.keywords if k.arg == "mode"), None)
        if isinstance(mode, ast.Constant) and isinstance(mode.value, str) \
                and set(mode.value) & set("wax+"):
            return "open"
        return None
    if not isinstance(f, ast.Attribute):
        return None
    base = f.value.id if isinstance(f.value, ast.Name) else ""
    if f.attr == "write" and base == "meshio":
        return "meshio.write"
    if f.attr == "open" and base == "os":
        flags = ast.unparse(node.args[1]) if len(node.args) > 1 else ""
        return "os.open" if any(w in flags for w in ("O_WRONLY", "O_RDWR", "O_CREAT")) else None
    if f.attr in ("dump", "writer") and base not in ("json", "pickle", "csv"):
        return None   # e.g. a stream's own method of that name
    if f.attr == "save" and base not in ("np", "numpy"):
        return None   # e.g. viz._mpl.save (a plot)
    return f"{base}.{f.attr}" if f.attr in WRITER_ATTRS else None


def writers_outside_io(root: Path = ROOT) -> list[str]:
    """Every writer call outside ``femcam/io`` not in :data:`ALLOWED`, as ``path:line call``.

    Parameters
    ----------
    root : Path
        The repository root.

    Returns
    -------
    list of str
        One entry per call.
    """
    out = []
    for f in sorted((root / "femcam").rglob("*.py")):
        rel = f.relative_to(root).as_posix()
        if rel.startswith("femcam/io/"):
            continue
        for node in ast.walk(ast.parse(f.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Call) and (name := _call_name(node)):
                text = ast.unparse(node)
                if not any(rel == r and t in text for r, t in ALLOWED):
                    out.append(f"{rel}:{node.lineno} {name}")
    return out


def test_no_writer_outside_io():
    found = writers_outside_io()
    assert not found, ("files are written through femcam.io only (atomic, one provenance layout, "
                       "one write_vtu); found:\n" + "\n".join(found))


def test_the_scan_finds_writers(tmp_path):
    """The scan itself: each kind of writer in a module outside io is found, io is exempt."""
    (tmp_path / "femcam" / "io").mkdir(parents=True)
    (tmp_path / "femcam" / "fe").mkdir()
    src = ("import json, meshio, numpy as np, os\n"
           "def f(p, m, a, fo):\n"
           "    meshio.write(p, m)\n"
           "    np.savez(p, a=a)\n"
           "    p.write_text('x')\n"
           "    open(p, 'w')\n"
           "    open(p, mode='ab')\n"
           "    json.dump({}, fo)\n"
           "    os.open(p, os.O_WRONLY | os.O_CREAT)\n"
           "    open(p)\n"                      # reading: not a writer
           "    json.dumps({})\n")              # text, not a file: not a writer
    (tmp_path / "femcam" / "fe" / "bad.py").write_text(src)
    (tmp_path / "femcam" / "io" / "ok.py").write_text(src)
    found = writers_outside_io(tmp_path)
    assert [s.split()[1] for s in found] == ["meshio.write", "np.savez", "p.write_text", "open",
                                             "open", "json.dump", "os.open"], found
    assert all(s.startswith("femcam/fe/bad.py:") for s in found)


def test_no_compat_alias_comes_back():
    """The style numbers' alias count (tests/style_numbers.py, docs/architecture.md): no re-export
    kept for an old import path, no alias property, no callable module, no deprecated scene key
    (``[wear] tip_radius_mm`` is refused with the key to use)."""
    import sys

    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from style_numbers import compat_aliases

    left = compat_aliases(ROOT)
    assert not left, left


def test_a_failed_vtu_write_leaves_the_old_file_and_no_temp_file(tmp_path):
    """Atomic (temp file + os.replace): a meshio error mid-write keeps the previous file byte
    for byte and removes the temp file; the file read back has the points and data written."""
    import meshio
    import numpy as np
    import pytest

    from femcam.io import TEMP_SUFFIX, write_vtu

    pts = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    path = write_vtu(tmp_path / "sub" / "t.vtu", pts, [("triangle", np.array([[0, 1, 2]]))],
                     {"p_Pa": np.array([1.0, 2.0, 3.0])}, field_data={"theta_deg": 12.5})
    before = path.read_bytes()
    m = meshio.read(path)
    np.testing.assert_array_equal(m.points[:, :2], pts)
    np.testing.assert_array_equal(m.point_data["p_Pa"], [1.0, 2.0, 3.0])
    with pytest.raises(Exception):  # noqa: B017, PT011 - meshio's own error for a bad cell block
        write_vtu(path, pts, [("triangle", np.array([[0, 1]]))], {"p_Pa": np.zeros(3)})
    assert path.read_bytes() == before
    assert not [p for p in path.parent.iterdir() if p.name.endswith(TEMP_SUFFIX)]


def test_vtu_bytes_are_meshios_plus_the_field_data(tmp_path, monkeypatch):
    """write_vtu writes in one pass the file meshio's binary uncompressed VTU writer writes
    (reference: meshio itself, then the field data inserted), apart from the comment line
    naming the writer; a cell block meshio would refuse still goes to meshio."""
    import numpy as np

    from femcam.io import vtk

    rng = np.random.default_rng(7)
    pts = rng.random((9, 2))
    cells = [("triangle6", np.arange(6, dtype=np.int32).reshape(1, 6)),
             ("triangle", np.array([[6, 7, 8], [0, 7, 8]], dtype=np.int32))]
    pdata = {"u_m": rng.random((9, 3)), "p_Pa": rng.random(9), "flag": np.arange(9)}
    cdata = {"body": [np.array([0]), np.array([1, 1])]}
    fdata = {"theta_deg": 12.5, "v": [1.0, 2.0]}
    new = vtk.write_vtu(tmp_path / "new.vtu", pts, cells, pdata, field_data=fdata, cell_data=cdata)
    monkeypatch.setattr(vtk, "_vtu_parts", lambda *a: None)   # meshio's writer
    ref = vtk.write_vtu(tmp_path / "ref.vtu", pts, cells, pdata, field_data=fdata, cell_data=cdata)
    a, b = new.read_bytes().split(b"\n"), ref.read_bytes().split(b"\n")
    assert len(a) == len(b) and b"meshio" in b[2]
    assert [i for i, (x, y) in enumerate(zip(a, b, strict=True)) if x != y] == [2]
