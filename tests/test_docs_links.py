"""The front door stays short and every relative link of the user-facing docs leads somewhere.

- README.md is at most 300 lines (a README of a few screens; the depth lives in docs/);
- every relative link and image of README.md and docs/*.md names an existing file or folder
  (anchors are not checked; links inside code and inside HTML comments do not count);
- the CLI page names every subcommand of the parser, and CITATION.cff carries femcam's version.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
MAX_README_LINES = 300


def test_readme_is_at_most_300_lines():
    n = len((ROOT / "README.md").read_text(encoding="utf-8").splitlines())
    assert n <= MAX_README_LINES, f"README.md has {n} lines; move the depth to a docs/ page"


def _links(text: str) -> list[str]:
    text = re.sub(r"<!--.*?-->", "", text, flags=re.S)        # comments: not rendered
    text = re.sub(r"^(```|~~~).*?^\1", "", text, flags=re.S | re.M)  # fenced code
    text = re.sub(r"`[^`\n]*`", "", text)                     # inline code
    return re.findall(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)", text)


@pytest.mark.parametrize("page", PAGES, ids=lambda p: str(p.relative_to(ROOT)))
def test_relative_links_resolve(page):
    bad = []
    for target in _links(page.read_text(encoding="utf-8")):
        if re.match(r"[a-z][a-z0-9+.-]*:", target, re.I) or target.startswith("#"):
            continue  # http(s), mailto, ... and same-page anchors
        path = target.split("#", 1)[0]
        if not (page.parent / path).exists():
            bad.append(target)
    assert not bad, f"{page.relative_to(ROOT)}: links to missing files: {bad}"


def test_cli_page_names_every_subcommand():
    from femcam.cli import build_parser

    text = (ROOT / "docs" / "cli.md").read_text(encoding="utf-8")
    sub = next(a for a in build_parser()._actions if a.__class__.__name__ == "_SubParsersAction")
    missing = [name for name in sub.choices if f"`femcam {name}" not in text]
    assert not missing, f"docs/cli.md does not document {missing}: run python docs/cli_reference.py"


def test_citation_version_is_the_package_version():
    import femcam

    text = (ROOT / "CITATION.cff").read_text(encoding="utf-8")
    assert re.search(r"^cff-version: 1\.2\.0$", text, re.M)
    assert re.search(rf"^version: {re.escape(femcam.__version__)}$", text, re.M), \
        "CITATION.cff version differs from femcam.__version__"
