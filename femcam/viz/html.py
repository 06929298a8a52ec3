"""Self-contained HTML pages (standard library only): inline style, PNG images embedded as
base64 ``data:`` URIs, tables, and a page from a report's Markdown.

A page built here loads nothing from the network and needs no file beside it except the ones it
links to, so it can be sent on its own: :func:`femcam.sweep.report.report_html` builds the
sweep's ``report.html`` from these parts, and :func:`markdown_page` turns a Markdown report
(``femcam assess``'s ``report.md``) into one page with its images embedded.
"""

from __future__ import annotations

import base64
import html
import re
from pathlib import Path

__all__ = ["CSS", "html_table", "markdown_page", "page_html", "png_data_uri"]

#: the pages' style (inline, no external font or sheet)
CSS = """body{font-family:system-ui,sans-serif;max-width:62rem;margin:1.5rem auto;padding:0 1rem;
color:#222;line-height:1.4}h1{margin-bottom:.2rem}h2{border-bottom:1px solid #ccc;margin-top:2rem}
table{border-collapse:collapse;margin:.5rem 0}td,th{border:1px solid #ccc;padding:.2rem .5rem;
text-align:left;vertical-align:top}td.num{text-align:right;font-variant-numeric:tabular-nums}
pre{background:#f6f6f6;padding:.6rem;overflow-x:auto;font-size:.85rem}
.refused{border:3px solid #b00;background:#fee;padding:.6rem 1rem;margin:1rem 0}
.refused h2{border:0;margin:0;color:#b00}.omits{background:#fff7e0;padding:.4rem 1rem}
figure{margin:1rem 0}figure img{max-width:100%;border:1px solid #ddd}figcaption{font-size:.9rem}
.muted{color:#666;font-size:.9rem}"""

_e = html.escape


def page_html(title: str, body: str) -> str:
    """A complete HTML document with the inline style.

    Parameters
    ----------
    title : str
        The page title (escaped here).
    body : str
        The body's HTML (already escaped).

    Returns
    -------
    str
        ``<!DOCTYPE html>`` ... ``</html>``, UTF-8.
    """
    return ("<!DOCTYPE html>\n<html lang=en><head><meta charset=utf-8>"
            f"<title>{_e(title)}</title><style>{CSS}</style></head><body>{body}</body></html>\n")


def html_table(head, rows, num=(), attrs: str = "") -> str:
    """An HTML table.

    Parameters
    ----------
    head : sequence of str
        Column titles (escaped here).
    rows : sequence of sequence of str
        Cells, already escaped HTML.
    num : collection of int, optional
        Columns to right-align (numbers).
    attrs : str, optional
        Attributes of the ``<table>`` tag, e.g. ``"id=worst"``.

    Returns
    -------
    str
        The ``<table>`` element.
    """
    h = "".join(f"<th>{_e(c)}</th>" for c in head)
    body = "".join("<tr>" + "".join(f"<td{' class=num' if j in num else ''}>{c}</td>"
                                    for j, c in enumerate(r)) + "</tr>" for r in rows)
    return f"<table{' ' + attrs if attrs else ''}><thead><tr>{h}</tr></thead><tbody>{body}</tbody></table>"


def png_data_uri(path) -> str:
    """A PNG file as a ``data:image/png;base64,...`` URI (the image travels inside the page).

    Parameters
    ----------
    path : str or Path
        The PNG file.

    Returns
    -------
    str
        The URI.
    """
    return "data:image/png;base64," + base64.b64encode(Path(path).read_bytes()).decode("ascii")


def _inline(text: str) -> str:
    """Escaped text with Markdown's ```code``` and ``**bold**`` spans as HTML."""
    out = _e(text)
    out = re.sub(r"`([^`]+)`", r"<code>\1</code>", out)
    return re.sub(r"\*\*([^*]+)\*\*", r"<b>\1</b>", out)


def _image(alt: str, src: str, base: Path) -> str:
    path = base / src
    if src.lower().endswith(".png") and path.is_file() and not re.match(r"^[a-z]+:", src):
        return (f"<figure><img src=\"{png_data_uri(path)}\" alt=\"{_e(alt)}\"><figcaption>{_e(alt)} "
                f"<span class=muted>({_e(src)})</span></figcaption></figure>")
    return f"<p>{_e(alt)} ({_e(src)}: not found)</p>"


def markdown_page(text: str, base, title: str = "") -> str:
    """One self-contained page from a report's Markdown: headings, paragraphs, lists, tables,
    ``code`` and ``**bold**`` spans, and images (``![alt](plots/x.png)``) embedded from ``base``.

    Only that subset is read (what femcam's reports write); anything else is shown as text.

    Parameters
    ----------
    text : str
        The Markdown.
    base : str or Path
        The directory image paths are relative to (the report's folder).
    title : str, optional
        The page title (default: the first heading).

    Returns
    -------
    str
        The HTML document (:func:`page_html`).
    """
    base, out, para, table, items = Path(base), [], [], [], []

    def flush():
        if para:
            out.append(f"<p>{_inline(' '.join(para))}</p>")
        if items:
            out.append("<ul>" + "".join(f"<li>{_inline(t)}</li>" for t in items) + "</ul>")
        if table:
            cells = [[c.strip() for c in re.split(r"(?<!\\)\|", r.strip().strip("|"))] for r in table]
            rows = [[_inline(c.replace("\\|", "|")) for c in r] for r in cells[1:]
                    if not all(set(c) <= set("-: ") for c in r)]
            out.append(html_table([c.replace("\\|", "|") for c in cells[0]], rows))
        para.clear(), table.clear(), items.clear()

    for line in text.splitlines():
        s = line.strip()
        img = re.fullmatch(r"!\[([^\]]*)\]\(([^)]+)\)", s)
        if not s or img or s.startswith("#") or (s.startswith("|") != bool(table)) \
                or (s.startswith("- ") != bool(items)):
            flush()
        if not s:
            continue
        if img:
            out.append(_image(img.group(1), img.group(2), base))
        elif s.startswith("#"):
            level = min(len(s) - len(s.lstrip("#")), 6)
            title = title or s.lstrip("# ")
            out.append(f"<h{level}>{_inline(s.lstrip('# '))}</h{level}>")
        elif s.startswith("|"):
            table.append(s)
        elif s.startswith("- "):
            items.append(s[2:])
        else:
            para.append(s)
    flush()
    return page_html(title or "femcam report", "".join(out))
