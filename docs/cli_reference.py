"""Write the subcommand reference of docs/cli.md from femcam's argparse parser.

Run ``python docs/cli_reference.py`` after a flag or a subcommand changes: it replaces the text
between the ``<!-- cli-reference -->`` markers of docs/cli.md with the ``--help`` of every
subcommand, so the page is generated, never hand-copied.
"""

from __future__ import annotations

import argparse
import os
import re
from pathlib import Path

PAGE = Path(__file__).resolve().parent / "cli.md"
BEGIN, END = "<!-- cli-reference -->", "<!-- /cli-reference -->"


def _subparsers(parser: argparse.ArgumentParser, prefix: str = "femcam"):
    """(command line, parser) of every subcommand, depth first."""
    for action in parser._actions:  # argparse keeps its sub-parsers here only
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield f"{prefix} {name}", sub
                yield from _subparsers(sub, f"{prefix} {name}")


def reference() -> str:
    """Markdown: one section per subcommand with its ``--help`` text."""
    os.environ["COLUMNS"] = "100"  # argparse wraps to the terminal width: fix it
    from femcam.cli import build_parser

    parts = []
    for cmd, sub in _subparsers(build_parser()):
        parts.append(f"### `{cmd}`\n\n```text\n{sub.format_help().rstrip()}\n```\n")
    return "\n".join(parts)


def main() -> None:
    text = PAGE.read_text(encoding="utf-8")
    new = f"{BEGIN}\n\n{reference()}\n{END}"
    text = re.sub(re.escape(BEGIN) + ".*?" + re.escape(END), lambda _: new, text, flags=re.S)
    PAGE.write_text(text, encoding="utf-8")


if __name__ == "__main__":
    main()
