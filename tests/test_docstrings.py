"""Every public function and class of femcam carries a numpydoc docstring.

The rule (STYLE.md, numpydoc): a public function or method (no leading underscore, in a module
whose name has none either) has a docstring; if it takes arguments besides ``self``/``cls`` the
docstring has a ``Parameters`` section, and if it returns a value (a ``return <expr>`` in its
body, or a return annotation other than ``None``) a ``Returns`` or ``Yields`` section. A public
class whose constructor takes arguments (a dataclass with fields, or an ``__init__`` with
parameters) has a ``Parameters`` or ``Attributes`` section. Properties need a docstring only.

``PENDING`` lists packages still being brought up to the rule (one entry a paragraph, so
parallel branches can each delete their own); it is empty: every package follows the rule.
"""

from __future__ import annotations

import ast
import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[1] / "femcam"

PENDING: set[str] = set()


def _has(doc: str, *sections: str) -> bool:
    return any(re.search(rf"^{name}\n-{{3,}}", doc, re.MULTILINE) for name in sections)


def _is_pending(rel: str) -> bool:
    return any(rel == p or rel.startswith(p + "/") or rel.startswith(p + ".")
               or rel.startswith(p + "_") for p in PENDING)


def _returns_value(fn: ast.FunctionDef) -> bool:
    if fn.returns is not None:
        return ast.unparse(fn.returns) not in ("None", "NoReturn")
    for node in ast.walk(fn):
        if isinstance(node, (ast.Yield, ast.YieldFrom)):
            return True
        if isinstance(node, ast.Return) and node.value is not None:
            return True
    return False


def _decorators(node) -> set[str]:
    return {ast.unparse(d).split("(")[0].split(".")[-1] for d in node.decorator_list}


def _function_problems(fn: ast.FunctionDef, where: str) -> list[str]:
    doc = ast.get_docstring(fn)
    if _decorators(fn) & {"property", "cached_property", "setter"}:
        return [] if doc else [f"{where}: no docstring"]
    if not doc:
        return [f"{where}: no docstring"]
    out = []
    args = [a.arg for a in fn.args.posonlyargs + fn.args.args + fn.args.kwonlyargs
            if a.arg not in ("self", "cls")]
    if fn.args.vararg:
        args.append(fn.args.vararg.arg)
    if fn.args.kwarg:
        args.append(fn.args.kwarg.arg)
    if args and not _has(doc, "Parameters"):
        out.append(f"{where}: no Parameters section")
    if _returns_value(fn) and not _has(doc, "Returns", "Yields"):
        out.append(f"{where}: no Returns section")
    return out


def _class_takes_arguments(cls: ast.ClassDef) -> bool:
    if "dataclass" in _decorators(cls):
        return any(isinstance(n, ast.AnnAssign) and "ClassVar" not in ast.unparse(n.annotation)
                   for n in cls.body)
    for n in cls.body:
        if isinstance(n, ast.FunctionDef) and n.name == "__init__":
            return len(n.args.args) > 1 or bool(n.args.kwonlyargs)
    return False


def _class_problems(cls: ast.ClassDef, where: str) -> list[str]:
    doc = ast.get_docstring(cls)
    if not doc:
        return [f"{where}: no docstring"]
    if _class_takes_arguments(cls) and not _has(doc, "Parameters", "Attributes"):
        return [f"{where}: no Parameters/Attributes section"]
    return []


def _module_problems(path: pathlib.Path, rel: str) -> list[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    out = []
    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and not node.name.startswith("_"):
            out += _function_problems(node, f"{rel}:{node.lineno} {node.name}")
        elif isinstance(node, ast.ClassDef) and not node.name.startswith("_"):
            out += _class_problems(node, f"{rel}:{node.lineno} {node.name}")
            for m in node.body:
                if isinstance(m, ast.FunctionDef) and not m.name.startswith("_"):
                    out += _function_problems(m, f"{rel}:{m.lineno} {node.name}.{m.name}")
    return out


def _public_modules():
    for path in sorted(ROOT.rglob("*.py")):
        rel = path.relative_to(ROOT.parent).as_posix()
        if any(part.startswith("_") and part != "__init__.py" for part in path.relative_to(ROOT).parts):
            continue
        yield path, rel


def test_every_public_function_and_class_has_numpydoc_sections():
    problems = []
    for path, rel in _public_modules():
        if not _is_pending(rel):
            problems += _module_problems(path, rel)
    assert not problems, f"{len(problems)} docstring problems:\n" + "\n".join(problems)


def test_the_rule_catches_a_missing_section():
    src = 'def f(x):\n    """Do f. Parameters are x; Returns x."""\n    return x\n'
    fn = ast.parse(src).body[0]
    assert _function_problems(fn, "f") == ["f: no Parameters section", "f: no Returns section"]
    good = ('def f(x):\n    """Do f.\n\n    Parameters\n    ----------\n    x : float\n'
            '        Load [N].\n\n    Returns\n    -------\n    float\n        Load [N].\n    """\n'
            '    return x\n')
    assert _function_problems(ast.parse(good).body[0], "f") == []
