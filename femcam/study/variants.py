"""A variant's scene: the base scene file's mapping with the varied keys set, written back as
TOML and read by the public loader (:func:`femcam.scene.load_scene`), so every variant passes
the same checks as a scene file; keyed by a content hash.

Why through a file: the loader reads files; building variants through it (rather than copying
its checks here) keeps one set of scene rules. The TOML is written by the client into a
temporary directory and removed at once; workers receive the loaded :class:`Scene` and write
nothing.

A segment angle (``program.segment.I.beta_deg``) changes the program's 360 deg: the difference
is taken out of the first dwell after the varied segment (cyclically) that is not itself varied;
a variant whose dwell would vanish is refused by the loader (recorded, not dropped).
"""

from __future__ import annotations

import copy
import dataclasses
import difflib
import hashlib
import json
import math
import re
import tempfile
from pathlib import Path

from ..errors import InputError, SceneError
from ..io import atomic_write_text
from ..scene import load_scene

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")
_BETA = re.compile(r"^program\.segment\.(\d+)\.beta_deg$")


def _paths(node, prefix: str = "") -> list:
    """Every dotted path of a parsed TOML mapping (list entries by index)."""
    out = []
    items = node.items() if isinstance(node, dict) else enumerate(node) if isinstance(node, list) else ()
    for k, v in items:
        p = f"{prefix}{k}"
        out.append(p)
        if isinstance(v, (dict, list)):
            out.extend(_paths(v, p + "."))
    return out


def check_key(raw: dict, key: str) -> None:
    """Check that ``key``'s parent table (or list) exists in the scene mapping ``raw``.

    A leaf key the scene does not set yet is allowed here (``follower.offset_mm``); the loader
    checks its name and value (did-you-mean) when the variants are built.

    Parameters
    ----------
    raw : dict
        The parsed scene file.
    key : str
        Dotted key.

    Raises
    ------
    InputError
        A parent that does not exist, with a did-you-mean from the scene's own keys.
    """
    parts = key.split(".")
    node, walked = raw, []
    for p in parts[:-1]:
        nxt = _child(node, p)
        if nxt is None or not isinstance(nxt, (dict, list)):
            near = difflib.get_close_matches(key, _paths(raw), n=1, cutoff=0.6)
            hint = (f"; did you mean {near[0]}?" if near
                    else f"; {'.'.join(walked + [p])} is not a table of the scene")
            raise InputError(f"vary: unknown scene key {key}{hint}")
        node, walked = nxt, walked + [p]
    if isinstance(node, list) and _child(node, parts[-1]) is None:
        raise InputError(f"vary: unknown scene key {key}: {'.'.join(walked)} has {len(node)} entries "
                         f"(index 0..{len(node) - 1})")
    if isinstance(node, dict) and parts[-1] not in node:
        near = difflib.get_close_matches(parts[-1], [k for k in node if not isinstance(node[k], dict)],
                                         n=1, cutoff=0.75)
        if near:  # a near miss of an existing key is a typo, not a new key
            raise InputError(f"vary: unknown scene key {key}; did you mean {'.'.join(walked + near)}?")


def _child(node, p: str):
    if isinstance(node, dict):
        return node.get(p)
    if isinstance(node, list) and p.isdigit() and int(p) < len(node):
        return node[int(p)]
    return None


def apply(raw: dict, values: dict) -> dict:
    """The scene mapping with the varied keys set (a deep copy; module docstring for angles).

    Parameters
    ----------
    raw : dict
        The parsed base scene file.
    values : dict
        ``{dotted key: value}`` in the scene file's units; None removes the key.

    Returns
    -------
    dict
        The variant's mapping.
    """
    new = copy.deepcopy(raw)
    for key, val in values.items():
        *parents, leaf = key.split(".")
        node = new
        for p in parents:
            node = _child(node, p)
        if isinstance(node, list):
            node[int(leaf)] = val
        elif val is None:  # "null": the variant has no such key
            node.pop(leaf, None)
        else:
            node[leaf] = val
    varied = {int(m.group(1)) for k in values if (m := _BETA.match(k))}
    segs = new.get("program", {}).get("segment", [])
    if varied and isinstance(segs, list):
        total = sum(float(s.get("beta_deg", 0.0)) for s in segs if isinstance(s, dict))
        n = len(segs)
        for j in ((min(varied) + d) % n for d in range(1, n + 1)):
            if j not in varied and isinstance(segs[j], dict) and segs[j].get("kind") == "dwell":
                segs[j]["beta_deg"] = float(f"{float(segs[j]['beta_deg']) + 360.0 - total:.12g}")
                break
    return new


def content_hash(raw: dict, options: dict) -> str:
    """SHA-256 of a variant: its scene mapping and the evaluation options (canonical JSON,
    integers as floats).

    Parameters
    ----------
    raw : dict
        The variant's scene mapping (its ``name``/``description``/``source`` text excluded).
    options : dict
        JSON-able evaluation options.

    Returns
    -------
    str
        Hex digest.
    """
    body = {k: v for k, v in raw.items() if k not in ("name", "description", "source")}
    text = json.dumps({"scene": _canonical(body), "options": options}, sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()


def _canonical(v):
    """Numbers as floats (``10`` mm and ``10.0`` mm are one variant), recursively."""
    if isinstance(v, dict):
        return {k: _canonical(x) for k, x in v.items()}
    if isinstance(v, list):
        return [_canonical(x) for x in v]
    if isinstance(v, int) and not isinstance(v, bool):
        return float(v)
    return v


def _value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return repr(v) if math.isfinite(v) else ("nan" if v != v else ("inf" if v > 0 else "-inf"))
    if isinstance(v, str):
        return json.dumps(v)  # a JSON string is a TOML basic string
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_key(k)} = {_value(x)}" for k, x in v.items()) + "}"
    return json.dumps(str(v))


def _key(k) -> str:
    return k if _BARE.match(str(k)) else json.dumps(str(k))


def _aot(v) -> bool:
    return isinstance(v, list) and bool(v) and all(isinstance(x, dict) for x in v)


def to_toml(raw: dict) -> str:
    """A parsed TOML mapping written back as TOML text (scene files: tables, arrays of tables,
    strings, numbers, booleans, lists).

    Parameters
    ----------
    raw : dict
        The mapping (as :mod:`tomllib` returns it).

    Returns
    -------
    str
        TOML that :mod:`tomllib` parses back to ``raw``.

    >>> import tomllib
    >>> raw = {"name": "x", "a": {"b": 1.5, "c": [{"k": "rise"}]}}
    >>> tomllib.loads(to_toml(raw)) == raw
    True
    """
    lines = []

    def table(path: list, d: dict) -> None:
        scalars = [(k, v) for k, v in d.items() if not isinstance(v, dict) and not _aot(v)]
        if path and (scalars or not any(isinstance(v, dict) or _aot(v) for v in d.values())):
            lines.append(f"[{'.'.join(_key(p) for p in path)}]")
        lines.extend(f"{_key(k)} = {_value(v)}" for k, v in scalars)
        for k, v in d.items():
            if isinstance(v, dict):
                table(path + [k], v)
        for k, v in d.items():
            if _aot(v):
                for item in v:
                    lines.append(f"[[{'.'.join(_key(p) for p in path + [k])}]]")
                    lines.extend(f"{_key(a)} = {_value(b)}" for a, b in item.items())

    table([], raw)
    return "\n".join(lines) + "\n"


def build_scene(raw: dict, *, source_path: str = "", label: str = "variant", tmpdir=None):
    """Load a variant's mapping with the public scene loader (all scene checks).

    Parameters
    ----------
    raw : dict
        The variant's scene mapping.
    source_path : str
        The base scene file (kept as the scene's ``source_path``).
    label : str
        Names the variant in a loader message instead of the temporary file.
    tmpdir : str or Path, optional
        A directory of the client for the temporary TOML (reused across variants: a study
        makes one); default: a fresh temporary directory.

    Returns
    -------
    femcam.scene.Scene
        The variant in SI.

    Raises
    ------
    SceneError
        The loader's message (every problem, dotted key, value and unit) for this variant.
    """
    if tmpdir is None:
        with tempfile.TemporaryDirectory(prefix="femcam-study-") as tmp:
            return build_scene(raw, source_path=source_path, label=label, tmpdir=tmp)
    path = Path(tmpdir) / "variant.toml"
    atomic_write_text(path, to_toml(raw))
    try:
        scene = load_scene(path)
    except SceneError as exc:
        raise SceneError(str(exc).replace(str(path), label)) from None
    finally:
        path.unlink(missing_ok=True)
    return dataclasses.replace(scene, source_path=str(source_path))
