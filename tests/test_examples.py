"""Every gallery script in ``examples/`` runs to the end (STYLE: examples are tests).

The scripts carry their own physics checks (``assert`` against the reference each one talks
about: Hertz, the half-space, the rigid train, ...), so a clean run is the test. Each runs in
this process with the Agg backend the way sphinx-gallery runs it (from ``examples/``, without
``__file__``), with a temporary output directory (``FEMCAM_EXAMPLE_OUT``); the test checks that
nothing is written into ``examples/``. New scripts are
found by globbing and run with the slow tests until they are measured and listed in ``FAST``.
"""

from __future__ import annotations

import ast
import importlib
from pathlib import Path

import matplotlib
import pytest

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
SCRIPTS = sorted(EXAMPLES.glob("plot_*.py"))
#: scripts that run in about a second or less in a warm test process (the default suite's share
#: stays at a few seconds); every other script runs with ``-m slow``
FAST = {"plot_01_hertz.py", "plot_02_fe_contact.py", "plot_06_crowned_roller.py", "plot_09_assessment.py"}


def test_the_gallery_has_its_scripts_and_header():
    assert len(SCRIPTS) >= 1
    header = (EXAMPLES / "GALLERY_HEADER.rst").read_text(encoding="utf-8")
    assert header.splitlines()[0].strip() == "Gallery"


@pytest.mark.parametrize("path", [
    pytest.param(p, id=p.name, marks=() if p.name in FAST else pytest.mark.slow) for p in SCRIPTS])
def test_example_runs(path, tmp_path, monkeypatch, capsys):
    text = path.read_text(encoding="utf-8")
    title = text.split('"""')[1].strip().splitlines()
    assert len(title) > 2 and set(title[1]) == {"="}, "a module docstring with an RST title"
    assert "# %%" in text, "sphinx-gallery cells"
    # as sphinx-gallery runs it: from its own folder, without ``__file__``
    monkeypatch.chdir(EXAMPLES)
    monkeypatch.setenv("FEMCAM_EXAMPLE_OUT", str(tmp_path))
    monkeypatch.setattr(plt, "show", lambda *a, **k: None)
    plt.close("all")
    before = sorted(EXAMPLES.rglob("*"))
    try:
        exec(compile(text, str(path), "exec"), {"__name__": "__main__"})  # noqa: S102
        assert plt.get_fignums(), f"{path.name} draws at least one figure"
    finally:
        plt.close("all")
    assert capsys.readouterr().out.strip(), f"{path.name} prints its key numbers"
    assert sorted(EXAMPLES.rglob("*")) == before, "examples write nothing into the repository"


@pytest.mark.parametrize("path", SCRIPTS, ids=[p.name for p in SCRIPTS])
def test_example_uses_the_public_api(path):
    """Every name an example imports from femcam is in that module's ``__all__``."""
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("femcam"):
            public = getattr(importlib.import_module(node.module), "__all__", None)
            if public is not None:
                missing = [a.name for a in node.names if a.name not in public]
                assert not missing, f"{path.name}: {missing} not in {node.module}.__all__"
