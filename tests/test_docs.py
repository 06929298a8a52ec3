"""The docs site (docs/conf.py) publishes every page and every public package, and the examples
written on its pages run as printed.

The full Sphinx build (warnings as errors, the gallery executed) runs in CI (.ci/run); these checks
are the cheap part of it:

* every ``docs/*.md`` page is in a toctree of the index, by name (Sphinx would also warn about
  a page in no toctree, but only in the full build);
* the API reference (``API_PACKAGES`` of ``docs/conf.py``, read from the layer order of
  docs/architecture.md) holds every public subpackage of femcam, all but the command line
  (``NOT_IN_API``, with its reason);
* the ``pycon`` blocks of the pages are doctests: they run, a page's blocks in one namespace from
  the top as a reader types them, with the expected output checked (the docstrings' doctests run
  through ``--doctest-modules``; ``python`` blocks marked ``<!-- docs-test -->`` run, without an
  output check, in tests/test_readme.py).
"""

from __future__ import annotations

import doctest
import pkgutil
import re
import runpy
import shutil
from pathlib import Path

import pytest

import femcam

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"


def _toctree_entries(page: Path) -> list[str]:
    text = page.read_text(encoding="utf-8")
    entries = []
    for block in re.findall(r"^```\{toctree\}\n(.*?)^```", text, re.S | re.M):
        entries += [ln.strip() for ln in block.splitlines() if ln.strip() and not ln.startswith(":")]
    return entries


def test_every_page_is_in_the_index_toctree():
    entries = _toctree_entries(DOCS / "index.md")
    assert entries, "docs/index.md has no toctree"
    pages = sorted(p.stem for p in DOCS.glob("*.md") if p.stem != "index")
    missing = [p for p in pages if p not in entries]
    assert not missing, (f"docs pages in no toctree of docs/index.md: {missing}; add each where it "
                         "belongs (Using femcam, User guide or Reference)")
    named = [e for e in entries if not e.startswith("gallery/")]
    assert not [e for e in named if not (DOCS / f"{e}.md").is_file()], "toctree names a missing page"
    assert len(set(entries)) == len(entries), "a page is listed twice"
    assert "gallery/index" in entries, "the gallery is not in the index's toctree"


def test_api_reference_lists_every_public_package():
    conf = runpy.run_path(str(DOCS / "conf.py"))  # imports femcam's packages, not Sphinx
    listed = conf["API_PACKAGES"]
    public = {f"femcam.{m.name}" for m in pkgutil.iter_modules(femcam.__path__)
              if not m.name.startswith("_") and m.name not in conf["NOT_IN_API"]}
    assert sorted(listed) == sorted(public | {"femcam"}), (
        f"the API reference (docs/conf.py API_PACKAGES) vs femcam's public packages: missing "
        f"{sorted(public - set(listed))}, unknown {sorted(set(listed) - public - {'femcam'})}")
    assert listed[0] == "femcam" and len(set(listed)) == len(listed)
    # a name re-exported by several packages is documented once, where it is defined
    elsewhere = conf["autosummary_context"]["elsewhere"]
    assert ("MeshOptions", ":py:obj:`femcam.mesh.MeshOptions`") in elsewhere["femcam.fe"]
    assert "femcam" in (DOCS / "api.md").read_text(encoding="utf-8")


def _pycon_pages() -> list[Path]:
    return [p for p in sorted(DOCS.glob("*.md")) if "```pycon" in p.read_text(encoding="utf-8")]


def test_some_pages_carry_doctests():
    assert len(_pycon_pages()) >= 2


@pytest.mark.parametrize("page", _pycon_pages(), ids=lambda p: p.name)
def test_page_examples_run_as_printed(page, tmp_path, monkeypatch):
    shutil.copytree(ROOT / "examples", tmp_path / "examples")  # pages load examples/*.toml
    monkeypatch.chdir(tmp_path)
    text = page.read_text(encoding="utf-8")
    parser = doctest.DocTestParser()
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    globs: dict = {}
    report: list[str] = []
    for m in re.finditer(r"^```pycon\n(.*?)^```", text, re.S | re.M):
        line = text.count("\n", 0, m.start()) + 1
        test = parser.get_doctest(m.group(1), globs, f"{page.name}:{line}", str(page), line)
        runner.run(test, out=report.append, clear_globs=False)
    assert runner.failures == 0, "".join(report)
