"""Provenance: the one record (versions, date, machine, scene, command, options, ...) that every
output file carries (the CSV's sidecar JSON, the NPZ's ``provenance_json``)."""

from __future__ import annotations

import datetime as _dt
import hashlib
import importlib.metadata
import json
import platform
import shlex
import sys
from pathlib import Path


def versions() -> dict[str, str]:
    """Versions of femcam and the libraries that shape the numbers.

    Returns
    -------
    dict[str, str]
        ``{"femcam", "python", "numpy", "scipy", "scikit-fem", "gmsh", "meshio"}`` -> version.
    """
    # the package's own version: femcam/__init__.py is always imported before this submodule
    # (a lookup, not an import: the root package sits above every layer)
    out = {"femcam": sys.modules["femcam"].__version__, "python": platform.python_version()}
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
    """The provenance record of every output file (a CSV's sidecar JSON, the NPZ).

    Parameters
    ----------
    scene_path, scene_hash : str, optional
        Scene file and its hash (a sweep's resume key); when the file exists its own SHA-256
        is recorded as ``scene_file_sha256``.
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
        if Path(scene_path).is_file():   # the file's own bytes (scene_sha256 may hash more)
            rec["scene_file_sha256"] = hashlib.sha256(Path(scene_path).read_bytes()).hexdigest()
    if scene_hash is not None:
        rec["scene_sha256"] = scene_hash
    rec["command"] = command if command is not None else shlex.join(sys.argv)
    if options is not None:
        rec["options"] = options
    rec.update({k: v for k, v in extra.items() if v is not None})
    return rec


def header_dict(prov: dict) -> dict[str, str]:
    """The provenance as one line of text per entry (the form :func:`femcam.io.read_csv` returns).

    Parameters
    ----------
    prov : dict
        A provenance record (:func:`provenance`).

    Returns
    -------
    dict[str, str]
        ``versions`` as ``"femcam 0.1, numpy 2.0, ..."``; nested entries (``options``,
        ``families``, ``wear``, ``extras``, ...) as JSON; the others as text.

    >>> header_dict({"versions": {"femcam": "1"}, "command": "femcam run", "options": {"b": 1}})
    {'versions': 'femcam 1', 'command': 'femcam run', 'options': '{"b": 1}'}
    """
    out = {}
    for key, val in prov.items():
        if key == "versions" and isinstance(val, dict):
            out[key] = ", ".join(f"{k} {v}" for k, v in val.items())
        elif isinstance(val, (dict, list, tuple)):
            out[key] = json.dumps(val, sort_keys=True, default=str)
        else:
            out[key] = str(val).replace("\n", " ").replace("\r", " ")
    return out
