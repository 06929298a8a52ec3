"""One-way layers (docs/architecture.md): no import cycle, no import against the layer order, and
function-level imports only for the heavy optional packages.

The reference is the layer order written once in docs/architecture.md (the line starting with
``layers:``); the imports are read from the source with :mod:`ast` (lazy, function-level imports
included), so the test needs no femcam import.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PKG = ROOT / "femcam"

#: third-party packages that may be imported inside functions (each with a one-line reason on
#: the line): heavy, optional, or native libraries that ``import femcam`` must not load
LAZY_OK = {"gmsh", "pyvista", "matplotlib", "dask",
           # meshio: ~0.4-0.6 s to import (its format plugins); only the .vtu/.msh writers need it
           "meshio",
           # rich: the progress bar, drawn only when stderr is a terminal (femcam._progress)
           "rich",
           # scipy submodules beyond linalg/sparse, imported where a path needs them: signal
           # (~0.5-0.7 s), optimize/special/fft/spatial/integrate (0.08-0.12 s together, not
           # needed by README command 1; docs/architecture.md)
           "scipy",
           # skfem: ~0.03-0.09 s on top of scipy (0.3-0.6 s alone), but ``import femcam`` stays
           # numpy/scipy only (tests/test_imports.py): loaded when an FE body is assembled
           "skfem",
           # pandas: optional (the [test] extra), only the to_dataframe() methods of results use it
           "pandas"}


def layer_order() -> list[str]:
    text = (ROOT / "docs" / "architecture.md").read_text(encoding="utf-8")
    m = re.search(r"^\s*layers:\s*(.+)$", text, re.M)
    assert m, "docs/architecture.md must state the layer order on a line 'layers: a -> b -> ...'"
    return [u.strip() for u in m.group(1).split("->")]


def module_name(f: Path) -> str:
    parts = list(f.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts)


MODULES = {module_name(f): f for f in sorted(PKG.rglob("*.py"))}


def unit(mod: str) -> str:
    """Layer unit of a module: ``femcam`` for the root package, else its first sub-package."""
    parts = mod.split(".")
    return "femcam" if len(parts) == 1 else parts[1]


def _resolve(mod: str, f: Path, node: ast.ImportFrom) -> list[str]:
    pkg = mod.split(".") if f.name == "__init__.py" else mod.split(".")[:-1]
    base = (pkg[: len(pkg) - node.level + 1] if node.level else []) + \
        (node.module.split(".") if node.module else [])
    out = []
    for a in node.names:
        full = ".".join([*base, a.name])
        out.append(full if full in MODULES else ".".join(base))
    return out


def imports(mod: str):
    """``(target, lineno, lazy, top-level package)`` of every import in module ``mod``."""
    f = MODULES[mod]
    tree = ast.parse(f.read_text(encoding="utf-8"))
    found = []

    def visit(node, in_function):
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.If) and "TYPE_CHECKING" in ast.unparse(child.test):
                continue
            lazy = in_function or isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))
            if isinstance(child, ast.ImportFrom):
                if child.level:
                    targets = _resolve(mod, f, child)
                else:
                    targets = [child.module + "." + a.name if f"{child.module}.{a.name}" in MODULES
                               else child.module for a in child.names]
                found.extend((t, child.lineno, lazy) for t in targets)
            elif isinstance(child, ast.Import):
                found.extend((a.name, child.lineno, lazy) for a in child.names)
            visit(child, lazy)

    visit(tree, False)
    return found


def graph() -> dict[str, set[str]]:
    g = {}
    for mod in MODULES:
        g[mod] = {t for t, _, _ in imports(mod) if t.split(".")[0] == "femcam" and t != mod}
    return g


def back_edges(g: dict[str, set[str]], order: list[str]) -> list[str]:
    """Imports from a module to a module of a later layer (lazy imports count)."""
    rank = {u: i for i, u in enumerate(order)}
    bad = []
    for mod, targets in g.items():
        for t in targets:
            a, b = unit(mod), unit(t)
            if a != b and rank[b] > rank[a]:
                bad.append(f"{mod} -> {t} ({a} is below {b})")
    return sorted(bad)


def cycles(g: dict[str, set[str]]) -> list[str]:
    """Import cycles of the module graph ``g`` (depth-first search, one per back edge)."""
    state, stack, found = {}, [], []

    def dfs(m):
        state[m] = 1
        stack.append(m)
        for t in sorted(g.get(m, ())):
            if state.get(t) == 1:
                found.append(" -> ".join([*stack[stack.index(t):], t]))
            elif t not in state:
                dfs(t)
        stack.pop()
        state[m] = 2

    for m in sorted(g):
        if m not in state:
            dfs(m)
    return found


def test_layer_order_names_every_package():
    order = layer_order()
    units = {unit(m) for m in MODULES}
    assert units <= set(order), f"not in the layer order of docs/architecture.md: {units - set(order)}"
    assert len(order) == len(set(order))


def test_no_import_against_the_layer_order():
    bad = back_edges(graph(), layer_order())
    assert not bad, "imports against the layer order:\n" + "\n".join(bad)


def test_no_import_cycle():
    found = cycles(graph())
    assert not found, "import cycles:\n" + "\n".join(found)


def test_function_level_imports_only_for_heavy_optional_packages():
    bad = []
    for mod, f in MODULES.items():
        rel = f.relative_to(ROOT).as_posix()
        lines = f.read_text(encoding="utf-8").splitlines()
        lazy = [(t, n) for t, n, is_lazy in imports(mod) if is_lazy]
        for t, n in lazy:
            root = t.split(".")[0]
            if root not in LAZY_OK:
                bad.append(f"{rel}:{n}: {t} (function-level import)")
        by_root = {}
        for t, n in lazy:
            by_root.setdefault(t.split(".")[0], []).append(n)
        for root, ns in by_root.items():
            if root in LAZY_OK and not any("#" in lines[n - 1] for n in ns):
                bad.append(f"{rel}:{ns[0]}: lazy import of {root} without a one-line reason comment")
    assert not bad, "\n".join(bad)


def test_the_checks_catch_a_cycle_and_a_back_edge():
    """The checkers on a graph written here: sweep -> io -> sweep is a cycle, and io -> sweep
    runs against an order that puts io below sweep."""
    g = {"femcam.sweep.run": {"femcam.io"}, "femcam.io": {"femcam.sweep.result"},
         "femcam.sweep.result": {"femcam.sweep.run"}}
    assert cycles(g) == ["femcam.io -> femcam.sweep.result -> femcam.sweep.run -> femcam.io"]
    assert back_edges(g, ["io", "sweep"]) == ["femcam.io -> femcam.sweep.result (io is below sweep)"]
    assert cycles({"femcam.a": {"femcam.b"}, "femcam.b": set()}) == []


def test_no_follower_dispatch_outside_the_follower_classes():
    """Issue 24 item 2: callers read the follower protocol (``rolls``, ``draws_circle``,
    ``flat_face``, ``needs_tip``, ``oscillating``, ``contact_radius``; docs/architecture.md)
    instead of ``isinstance(..., *Follower)`` or a ``kind`` string (tests/style_numbers.py)."""
    import sys

    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from style_numbers import follower_dispatch

    assert follower_dispatch(ROOT) == []


def test_columns_declared_with_the_column_type():
    """Issue 24 item 4: a table column is declared as a ``femcam._columns.Column``, not as a
    bare ``(si, csv, factor)`` tuple (tests/style_numbers.py, docs/architecture.md)."""
    import sys

    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from style_numbers import bare_columns

    assert bare_columns(ROOT) == []


def test_chunk_table_written_by_attribute():
    """Issue 24 item 4: the sweep's chunk table is typed (``femcam.sweep.chunk.ChunkRows``):
    no ``rows["..."] = ...`` / ``rows[name][i] = ...`` write is left in ``femcam/sweep``
    (tests/style_numbers.py, docs/architecture.md)."""
    import sys

    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from style_numbers import chunk_table_writes

    assert chunk_table_writes(ROOT) == []


def test_physics_packages_take_records_not_the_scene():
    """Issue 24 item 1: the physics packages (every layer below the sweep but the scene, the
    edge adapter) take the scene's typed records (``ContactPair``, ``ContactCase``,
    ``FiniteCase``, ``CamDiskCase``, ``BodyLayers``, ``SceneState``, ...), never the ``Scene``
    (tests/style_numbers.py, docs/architecture.md)."""
    import sys

    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from style_numbers import physics_scene_files

    assert physics_scene_files(ROOT) == []
