"""The README's Python examples, and those of the docs pages marked for it, run as written
(STYLE: README code blocks are tests).

Every ```python block of README.md runs; in ``docs/*.md`` the blocks preceded by
``<!-- docs-test -->`` run (the worked examples of each stage's guide). A block preceded by
``<!-- readme-test: slow -->`` or ``<!-- docs-test: slow -->`` (an FE model build or a sweep of
several seconds) runs with the slow tests.
"""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]


def _blocks():
    """(id, code, slow) of every tested python block."""
    found = []
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    for i, (slow, code) in enumerate(re.findall(
            r"(<!-- readme-test: slow -->\s*)?```python\n(.*?)```", readme, re.S)):
        found.append((f"README.md:{i}", code, bool(slow)))
    for md in sorted((ROOT / "docs").glob("*.md")):
        text = md.read_text(encoding="utf-8")
        for i, (slow, code) in enumerate(re.findall(
                r"<!-- docs-test(: slow)? -->\s*```python\n(.*?)```", text, re.S)):
            found.append((f"docs/{md.name}:{i}", code, bool(slow)))
    return found


_FOUND = _blocks()
BLOCKS = {name: code for name, code, _ in _FOUND}
PARAMS = [pytest.param(name, marks=pytest.mark.slow, id=name) if slow else pytest.param(name, id=name)
          for name, _, slow in _FOUND]


def test_readme_has_python_examples():
    assert any(name.startswith("README.md") for name in BLOCKS)


def test_docs_keep_the_moved_examples():
    """The worked examples of the stage guides stay tested (nine blocks, two of them slow)."""
    docs = [name for name in BLOCKS if name.startswith("docs/")]
    assert len(docs) >= 9, docs


@pytest.mark.parametrize("name", PARAMS)
def test_readme_python_block_runs(name, tmp_path, monkeypatch, capsys):
    shutil.copytree(ROOT / "examples", tmp_path / "examples")
    monkeypatch.chdir(tmp_path)
    ns: dict = {}
    exec(compile(BLOCKS[name], f"{name} python block", "exec"), ns)  # noqa: S102
    out = capsys.readouterr().out
    if "write_fe_vtu" in BLOCKS[name]:
        # the tour block: FE p0 and a against Hertz at the worst angle, and a VTU file
        p0_err, a_err = (float(v) for v in out.split()[:2])
        assert abs(p0_err) < 3e-3, "FE p0 vs Hertz (docs/fe.md target 0.3 %)"
        assert abs(a_err) < 1e-2, "FE a vs Hertz (docs/fe.md target 1 %)"
        assert (tmp_path / "worst.vtu").stat().st_size > 10_000
        assert np.isfinite(ns["r"].tau1_max.value)
    if "pv.get_reader" in BLOCKS[name]:
        # the tour's ParaView series: one step per angle, a stress field at 60 deg
        assert len(ns["reader"].time_values) == 12
        assert float(ns["mesh"]["von_mises_Pa"].max()) > 1e8
