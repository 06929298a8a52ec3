"""The docs figures are drawn from the current sources (docs/figures.py).

Every PNG of docs/img/ has an entry with its producer, and the fingerprint of its sources (scene
files, producer script, and the plotted numbers or the analytic curve they are drawn against,
recomputed cheaply here) equals the one recorded when it was drawn (docs/figures.json). When
this fails: redraw the figure with the command the message names, then run
``python docs/figures.py --record``.
"""

from __future__ import annotations

import importlib.util
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
_spec = importlib.util.spec_from_file_location("docs_figures", ROOT / "docs" / "figures.py")
figures = importlib.util.module_from_spec(_spec)
sys.modules[_spec.name] = figures  # dataclasses look their module up
_spec.loader.exec_module(figures)


def test_every_figure_has_a_producer_and_every_entry_a_figure():
    on_disk = {p.name for p in (ROOT / "docs" / "img").glob("*.png")}
    listed = [f.name for f in figures.FIGURES]
    assert len(listed) == len(set(listed)), "a figure is listed twice in docs/figures.py"
    missing = sorted(on_disk - set(listed))
    assert not missing, f"figures without a producer in docs/figures.py: {missing}"
    assert not set(listed) - on_disk, f"listed but not in docs/img: {sorted(set(listed) - on_disk)}"


def test_figure_sources_unchanged_since_drawn():
    recorded = json.loads((ROOT / "docs" / "figures.json").read_text(encoding="utf-8"))
    now = figures.current()
    stale = {f.name: f.producer for f in figures.FIGURES if recorded.get(f.name) != now[f.name]}
    assert not stale, ("the sources of these figures changed since they were drawn; redraw them, "
                       f"then run python docs/figures.py --record: {stale}")


def test_figures_page_is_generated_from_the_record():
    recorded = json.loads((ROOT / "docs" / "figures.json").read_text(encoding="utf-8"))
    assert (ROOT / "docs" / "figures.md").read_text(encoding="utf-8") == figures.page(recorded), \
        "docs/figures.md is not the generated page: run python docs/figures.py --record"
