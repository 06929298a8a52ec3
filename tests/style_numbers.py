"""The style numbers of docs/architecture.md ("Style numbers"), counted from the source with
:mod:`ast` (no femcam import). Run ``python tests/style_numbers.py`` from the repository root
(or ``python tests/style_numbers.py /path/to/another/checkout`` for the "before" column);
``tests/test_writers.py`` holds the writer count at zero.

Counts:

* writers outside ``femcam/io`` (:func:`test_writers.writers_outside_io`);
* compat aliases: re-export lines marked ``noqa: F401`` outside ``__init__.py``, modules that
  only re-export (no function or class of their own), ``from x import _name as _name``
  re-exports, properties documented as an ``Alias of``, the callable-module trick
  (``__class__`` of a module replaced) and scene keys documented as a deprecated alias;
* follower dispatch sites outside the follower classes: ``isinstance(..., <X>Follower)`` (a
  class name ending in ``Follower``: not ``FollowerDynamics``, a load record) and comparisons of
  a ``kind`` with a follower kind string (``.kind == "roller"``) or of anything with a follower
  class name (``type(f).__name__ == "RollerFollower"``), outside
  ``femcam/profile/geometry.py``, ``femcam/profile/oscillating.py`` and ``femcam/profile/pad.py``;
* files with a function that takes the scene (a parameter named ``scene`` or ``sc``, or
  annotated ``Scene``);
* the sweep package: module count and import depth (the longest chain of module-level imports
  between its modules);
* column declarations as bare tuples (:func:`bare_columns`): a tuple literal ``(si, csv,
  factor)`` or a dict value ``csv: (csv, factor)`` whose CSV name ends in a unit of
  ``femcam._columns.UNITS`` and whose factor is a number expression, and a comprehension that
  builds ``(name, csv, f)`` triples; declarations are :class:`femcam._columns.Column`;
* string-keyed chunk-table writes (:func:`chunk_table_writes`): in ``femcam/sweep/``, an
  assignment (plain or augmented, also one element of a tuple target) to a subscript of the name
  ``rows`` (``rows["p0_fe"][i] = ...``, ``rows[name] = ...``); the chunk table is
  :class:`femcam.sweep.chunk.ChunkRows`, written by attribute.
"""

from __future__ import annotations

import ast
import re
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
FOLLOWER_HOMES = ("femcam/profile/geometry.py", "femcam/profile/oscillating.py", "femcam/profile/pad.py")


def _files(root: Path):
    for f in sorted((root / "femcam").rglob("*.py")):
        yield f.relative_to(root).as_posix(), f.read_text(encoding="utf-8")


def _only_re_exports(tree: ast.Module) -> bool:
    """A module whose body is relative imports and assignments only (no code of its own)."""
    body = [n for n in tree.body if not isinstance(n, ast.Expr)]
    return bool(body) and all(isinstance(n, ast.ImportFrom | ast.Import | ast.Assign) for n in body) \
        and any(isinstance(n, ast.ImportFrom) and n.level for n in body)


def _alias_nodes(tree: ast.Module) -> list[tuple[int, str]]:
    """``from x import _name as _name`` re-exports and properties documented ``Alias of``."""
    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            out += [(node.lineno, f"private re-export {a.name}") for a in node.names
                    if a.asname and a.asname == a.name and a.name.startswith("_")]
        if isinstance(node, ast.FunctionDef) and any(
                isinstance(d, ast.Name) and d.id == "property" for d in node.decorator_list) \
                and (ast.get_docstring(node) or "").startswith("Alias of"):
            out.append((node.lineno, f"alias property {node.name}"))
    return out


def compat_aliases(root: Path) -> list[str]:
    """The compat aliases and re-exports (module docstring), as ``path:line what``."""
    out = []
    for rel, text in _files(root):
        tree = ast.parse(text)
        for i, line in enumerate(text.splitlines(), 1):
            if "noqa: F401" in line and not rel.endswith("__init__.py") and "import" in line:
                out.append(f"{rel}:{i} re-export")
            if re.search(r"__class__\s*=", line) and "sys.modules" in line:
                out.append(f"{rel}:{i} callable module")
            if re.search(r"DEPRECATED alias", line):
                out.append(f"{rel}:{i} deprecated scene key")
        if not rel.endswith("__init__.py") and _only_re_exports(tree):
            out.append(f"{rel}:1 re-export module")
        out += [f"{rel}:{n} {what}" for n, what in _alias_nodes(tree)]
    return out


#: the follower kinds (``kind`` of the follower classes)
KINDS = {"roller", "knife_edge", "flat_faced", "oscillating_roller", "oscillating_pad"}


def _names_a_kind(node: ast.Compare) -> bool:
    """A comparison of something with a follower kind string (``f.kind == "roller"``,
    ``kind in ("roller", "oscillating_roller")``) or a follower class name
    (``type(f).__name__ == "RollerFollower"``)."""
    consts = [c for c in ast.walk(node) if isinstance(c, ast.Constant) and isinstance(c.value, str)]
    if any(re.fullmatch(r"\w+Follower", c.value) for c in consts):  # type(f).__name__ == "RollerFollower"
        return True
    return any(c.value in KINDS for c in consts) and "kind" in ast.unparse(node)


def follower_dispatch(root: Path) -> list[str]:
    """isinstance/kind-string follower dispatch sites outside the follower classes."""
    out = []
    for rel, text in _files(root):
        if rel in FOLLOWER_HOMES:
            continue
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) \
                    and node.func.id == "isinstance" and len(node.args) == 2 \
                    and re.search(r"Follower\b", ast.unparse(node.args[1])):
                out.append(f"{rel}:{node.lineno} isinstance")
            if isinstance(node, ast.Compare) and _names_a_kind(node):
                out.append(f"{rel}:{node.lineno} kind")
    return out


def scene_files(root: Path) -> list[str]:
    """Files with a function taking the scene (parameter ``scene``/``sc`` or annotated Scene)."""
    out = []
    for rel, text in _files(root):
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
                args = node.args.posonlyargs + node.args.args + node.args.kwonlyargs
                if any(a.arg in ("scene", "sc") or (a.annotation is not None and "Scene" ==
                       ast.unparse(a.annotation).split(".")[-1]) for a in args):
                    out.append(rel)
                    break
    return out


#: the packages below the sweep that compute physics (the layer order of docs/architecture.md
#: below ``sweep``, without ``scene``, the edge adapter that builds the records they take)
PHYSICS = ("materials", "kinematics", "profile", "loads", "dynamics", "halfspace", "hertz",
           "tribology", "mesh", "fe", "layers", "bodies", "wear", "assess", "synthesis", "io", "viz")


def physics_scene_files(root: Path) -> list[str]:
    """Files of the physics packages (:data:`PHYSICS`) with a function taking the scene (issue
    24 item 1: they take the scene's typed records, never ``Scene``)."""
    return [rel for rel in scene_files(root)
            if Path(rel).parts[1].removesuffix(".py") in PHYSICS]


def sweep_package(root: Path) -> tuple[int, int]:
    """``(modules, import depth)`` of ``femcam/sweep``: depth = the longest chain of
    module-level imports between its modules (1 for a module importing no sibling)."""
    pkg = root / "femcam" / "sweep"
    mods = {f.stem: f for f in pkg.glob("*.py")}
    deps = {}
    for name, f in mods.items():
        d = set()
        for node in ast.parse(f.read_text(encoding="utf-8")).body:
            if isinstance(node, ast.ImportFrom) and node.level == 1:
                if node.module:
                    d.add(node.module.split(".")[0])
                else:
                    d.update(a.name for a in node.names)
        deps[name] = {m for m in d if m in mods and m != name}
    memo: dict[str, int] = {}

    def depth(m, seen=()):
        if m not in memo:
            memo[m] = 1 + max((depth(t, (*seen, m)) for t in deps[m] if t not in seen), default=0)
        return memo[m]

    return len(mods), max(depth(m) for m in mods)


#: unit suffixes of CSV names (femcam/_columns.py ``UNITS``; repeated here: no femcam import)
UNITS = ("mm3_per_N_m", "per_rev_nm", "m_per_rev", "N_per_mm", "m_per_s2", "m_per_s", "mPa_s",
         "m_s2", "m_s3", "m_s", "cycles", "MPa", "deg", "pct", "mm", "um", "nm", "ms", "N", "K", "C")


def _csv_name(node) -> bool:
    return isinstance(node, ast.Constant) and isinstance(node.value, str) \
        and re.fullmatch(r"[A-Za-z]\w*", node.value) is not None \
        and any(node.value.endswith("_" + u) for u in UNITS)


def _number(node) -> bool:
    if isinstance(node, ast.Constant):
        return isinstance(node.value, int | float) and not isinstance(node.value, bool)
    if isinstance(node, ast.Name):  # a constant or a factor variable, not a class (CamelCase)
        return not (node.id[0].isupper() and not node.id.isupper())
    return isinstance(node, ast.BinOp | ast.UnaryOp | ast.Attribute)


def bare_columns(root: Path) -> list[str]:
    """Column declarations as bare tuples (module docstring), as ``path:line what``."""
    out = []
    for rel, text in _files(root):
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, ast.Tuple) and len(node.elts) == 3 \
                    and isinstance(node.elts[0], ast.Constant | ast.JoinedStr) \
                    and _csv_name(node.elts[1]) and _number(node.elts[2]):
                out.append(f"{rel}:{node.lineno} (si, csv, factor)")
            if isinstance(node, ast.Dict):
                out += [f"{rel}:{v.lineno} key: (csv, factor)" for v in node.values
                        if isinstance(v, ast.Tuple) and len(v.elts) == 2 and _csv_name(v.elts[0])
                        and _number(v.elts[1])]
            if isinstance(node, ast.GeneratorExp | ast.ListComp) and isinstance(node.elt, ast.Tuple) \
                    and len(node.elt.elts) == 3 and isinstance(node.elt.elts[2], ast.Name) \
                    and "csv" in ast.unparse(node.elt.elts[1]):
                out.append(f"{rel}:{node.lineno} built (name, csv, f)")
    return out


def _subscript_of_rows(node) -> bool:
    """``rows[...]`` or ``rows[...][...]`` (any depth of subscripts on the name ``rows``)."""
    if not isinstance(node, ast.Subscript):
        return False
    while isinstance(node, ast.Subscript):
        node = node.value
    return isinstance(node, ast.Name) and node.id == "rows"


def _binds_other_rows(fn) -> bool:
    """A function whose ``rows`` is its own dict or list (``rows: dict[str, int] = {}``)."""
    for node in ast.walk(fn):
        if isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name) \
                and node.target.id == "rows":
            return True
        if isinstance(node, ast.Assign) and isinstance(node.value, ast.Dict | ast.List | ast.DictComp) \
                and any(isinstance(t, ast.Name) and t.id == "rows" for t in node.targets):
            return True
    return False


def chunk_table_writes(root: Path) -> list[str]:
    """String-keyed chunk-table writes in ``femcam/sweep`` (module docstring), as ``path:line``;
    a function whose ``rows`` is a dict or list of its own is not counted."""
    out = set()
    for rel, text in _files(root):
        if not rel.startswith("femcam/sweep/"):
            continue
        for fn in ast.walk(ast.parse(text)):
            if not isinstance(fn, ast.FunctionDef) or _binds_other_rows(fn):
                continue
            for node in ast.walk(fn):
                targets = node.targets if isinstance(node, ast.Assign) else \
                    [node.target] if isinstance(node, ast.AugAssign) else []
                for t in targets:
                    for e in t.elts if isinstance(t, ast.Tuple) else [t]:
                        if _subscript_of_rows(e):
                            out.add(f"{rel}:{e.lineno}:{e.col_offset} rows[...] write")
    return sorted(out)


def writers(root: Path) -> list[str]:
    """Writer calls outside femcam/io (:mod:`test_writers`)."""
    sys.path.insert(0, str(HERE))
    from test_writers import writers_outside_io

    return writers_outside_io(root)


def numbers(root: Path) -> dict[str, int]:
    """Every count of the module docstring for the checkout at ``root``."""
    n_mod, depth = sweep_package(root)
    return {"writers outside io": len(writers(root)),
            "compat aliases and re-exports": len(compat_aliases(root)),
            "follower dispatch sites outside the follower classes": len(follower_dispatch(root)),
            "files with a function taking the scene": len(set(scene_files(root))),
            "physics-package files taking the scene": len(set(physics_scene_files(root))),
            "sweep package modules": n_mod, "sweep import depth": depth,
            "column declarations as bare tuples": len(bare_columns(root)),
            "string-keyed chunk-table writes": len(chunk_table_writes(root))}


if __name__ == "__main__":
    root = Path(sys.argv[1]) if len(sys.argv) > 1 else HERE.parent
    for k, v in numbers(root).items():
        print(f"{k}: {v}")
    if "-v" in sys.argv:
        for line in (compat_aliases(root) + follower_dispatch(root) + writers(root) + bare_columns(root)
                     + chunk_table_writes(root)):
            print("  ", line)
