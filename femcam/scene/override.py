"""The scene file's text with the command line's overrides written into it, so that the copy
a sweep keeps (``DIR/scene.toml``) reproduces the run on its own.

The text is edited line by line (its comments stay): a key of a plain table (``[program]``,
``[sweep]``, ``[fe]``) is replaced where it is written and added under the table's header
otherwise (the table is appended when the file has none); a motion law replaces the ``law`` of
``[program]`` and of every ``[[program.segment]]`` and comments out their ``control_points``
(a law is given either by name or by control points).
"""

from __future__ import annotations

import re

_HEADER = re.compile(r"^\s*(\[\[?)\s*([A-Za-z0-9_.\-]+)\s*\]\]?\s*(#.*)?$")
#: the comment on every line written from the command line
NOTE = "set on the command line"
_KEY = re.compile(r"^\s*([A-Za-z0-9_\-]+)\s*=")


def toml_value(v) -> str:
    """``v`` as a TOML value (str, bool, int, float, list of those).

    Parameters
    ----------
    v : str or bool or int or float or list
        The value.

    Returns
    -------
    str
        Its TOML text, e.g. ``'"cycloidal"'``, ``'true'``, ``'0.002'``, ``'[0.0, 1.0]'``.
    """
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(v, list | tuple):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    return repr(float(v)) if isinstance(v, float) else str(int(v))


def _statements(lines: list) -> list:
    """``(table, is_array_table, key, first, last)`` per line group: a key's value may span
    lines (an array); ``key`` is None for headers, comments and blank lines."""
    out, table, arr, i = [], "", False, 0
    while i < len(lines):
        h = _HEADER.match(lines[i])
        if h:
            table, arr = h.group(2), h.group(1) == "[["
            out.append((table, arr, None, i, i))
            i += 1
            continue
        k = _KEY.match(lines[i])
        if not k:
            out.append((table, arr, None, i, i))
            i += 1
            continue
        j, depth = i, 0
        while True:  # an array value may span lines: up to its closing bracket
            depth += _brackets(lines[j])
            if depth <= 0 or j + 1 >= len(lines):
                break
            j += 1
        out.append((table, arr, k.group(1), i, j))
        i = j + 1
    return out


def _brackets(line: str) -> int:
    """Open minus closed square brackets of one line outside strings and comments."""
    n, quote = 0, ""
    for ch in line:
        if quote:
            quote = "" if ch == quote else quote
        elif ch in "\"'":
            quote = ch
        elif ch == "#":
            break
        elif ch == "[":
            n += 1
        elif ch == "]":
            n -= 1
    return n


def with_overrides(text: str, settings: dict, law: str | None = None,
                   control_points=None) -> str:
    """The scene text with ``settings`` and a motion law written into it.

    Parameters
    ----------
    text : str
        The scene file's text.
    settings : dict
        ``{(table, key): value}`` of plain tables, e.g. ``{("sweep", "method"): "hertz"}``.
    law : str, optional
        Motion law of every rise and fall (``[program] law`` and each segment's ``law``).
    control_points : sequence of float, optional
        With ``law="bezier"``: written as ``control_points`` instead of the law's name.

    Returns
    -------
    str
        The edited text (ends with a newline).
    """
    lines = text.splitlines()
    settings = dict(settings)
    if law is not None:
        key, value = ("control_points", list(control_points)) if control_points is not None \
            else ("law", law)
        settings[("program", key)] = value
    stmts = _statements(lines)
    edits = _edits(lines, stmts, settings, law, control_points)
    headers = {table: first for table, arr, key, first, _ in stmts if key is None and not arr
               and _HEADER.match(lines[first])}
    if "program" not in headers:  # every rise and fall names its own law (replaced above)
        settings = {tk: v for tk, v in settings.items() if tk[0] != "program"}
    out, i = [], 0
    while i < len(lines):
        if i in edits:
            last, new = edits[i]
            out.extend(new)
            i = last + 1
        else:
            out.append(lines[i])
            i += 1
        if i - 1 in headers.values():  # right under a table's header: its new keys
            table = next(t for t, f in headers.items() if f == i - 1)
            for (t, k) in [tk for tk in settings if tk[0] == table]:
                out.append(f"{k} = {toml_value(settings.pop((t, k)))}  # {NOTE}")
    for table in dict.fromkeys(t for t, _ in settings):  # tables the file does not have
        out += ["", f"[{table}]"] + [f"{k} = {toml_value(v)}  # {NOTE}"
                                     for (t, k), v in settings.items() if t == table]
    return "\n".join(out) + "\n"


def _edits(lines, stmts, settings, law, control_points) -> dict:
    """First line -> (last line, its replacement lines); the settings written are popped."""
    edits = {}
    for table, arr, key, first, last in stmts:
        if key is None:
            continue
        if law is not None and table in ("program", "program.segment") \
                and key in ("law", "control_points"):
            if table == "program.segment" and key == "law" and control_points is None:
                edits[first] = (last, [_replace(lines[first], toml_value(law), NOTE)])
                continue
            if table == "program.segment" or ("program", key) not in settings:
                edits[first] = (last, ["# " + ln for ln in lines[first:last + 1]])
                continue
        if not arr and (table, key) in settings:
            value = toml_value(settings.pop((table, key)))
            edits[first] = (last, [_replace(lines[first], value, NOTE)] if first == last
                            else [f"{key} = {value}  # {NOTE}"])
    return edits


def _replace(line: str, value: str, note: str) -> str:
    """``key = old  # comment`` -> ``key = value  # note (the file had: old)``."""
    key, rest = line.split("=", 1)
    old = rest.split("#", 1)[0].strip() if _brackets(rest.split("#", 1)[0]) == 0 else rest.strip()
    return f"{key.rstrip()} = {value}  # {note} (the file had: {old})"
