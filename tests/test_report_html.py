"""``report.html``: one self-contained page a designer can send (docs/sweep.md, "The report").

The page is parsed with the standard library's ``html.parser`` and checked against the files
the run wrote: every image is one of ``plots/*.png`` (decoded from its ``data:`` URI, byte for
byte), every number of the worst-values table is the ``sweep.npz`` column at the stated angle to
the printed precision and is that column's extreme over the ``ok`` rows, every link resolves to
a file in the folder and nothing points outside it. A Hertz sweep of 8 angles with plots keeps
the default tests cheap; the FE validation figures are checked on a coarse FE sweep (slow).
"""

from __future__ import annotations

import base64
import dataclasses
import html
import math
import re
from html.parser import HTMLParser
from pathlib import Path

import numpy as np
import pytest

from femcam.sweep import RunOptions, SweepOptions, SweepResult, sweep
from femcam.sweep.report import report_html, scene_inputs
from femcam.sweep.table import COLUMNS
from femcam.sweep.worst import ITEMS, PEAKS
from femcam.viz.html import markdown_page, png_data_uri

EXAMPLE = "examples/seed002_study_model.toml"
PNG = b"\x89PNG\r\n\x1a\n"


class Page(HTMLParser):
    """The parts of the page the tests read: images, links, the worst-values table, text."""

    def __init__(self, text):
        super().__init__()
        self.imgs, self.links, self.attrs, self.worst, self.text = [], [], [], [], []
        self.first = None           # (tag, attrs) of the first element in <body>
        self._body = self._in_worst = False
        self._row = self._cell = None
        self.feed(text)

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.attrs.append((tag, a))
        if self._body and self.first is None:
            self.first = (tag, a)
        self._body |= tag == "body"
        if tag == "img":
            self.imgs.append(a)
        if tag == "a":
            self.links.append(a.get("href", ""))
        if tag == "table" and a.get("id") == "worst":
            self._in_worst = True
        if self._in_worst and tag == "tr" and "data-column" in a:
            self._row = {"column": a["data-column"], "cells": []}
        if self._row is not None and tag == "td":
            self._cell = []

    def handle_endtag(self, tag):
        if tag == "td" and self._cell is not None:
            self._row["cells"].append("".join(self._cell).strip())
            self._cell = None
        if tag == "tr" and self._row is not None:
            self.worst.append(self._row)
            self._row = None
        if tag == "table":
            self._in_worst = False

    def handle_data(self, data):
        self.text.append(data)
        if self._cell is not None:
            self._cell.append(data)


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    out = tmp_path_factory.mktemp("report")
    r = sweep(EXAMPLE,
              SweepOptions(angles=np.radians(np.arange(0.0, 360.0, 45.0)),  method="hertz",  plots=True,
                           vtk_every=4),
              RunOptions(workers=1, out=out, progress=False, scene_path=EXAMPLE))
    return r, out, Page((out / "report.html").read_text(encoding="utf-8"))


def _npz(out):
    with np.load(out / "sweep.npz", allow_pickle=False) as z:
        return {k: z[k] for k in z.files}


def test_written_beside_report_md_and_said_in_the_paths(run):
    r, out, _ = run
    assert r.paths["report_html"] == str(out / "report.html")
    assert SweepResult.load(out).paths["report_html"] == str(out / "report.html")
    assert "report.html" in (out / "report.md").read_text()


def test_every_plot_the_run_wrote_is_embedded_once(run):
    _, out, page = run
    files = {p.name: p.read_bytes() for p in (out / "plots").glob("*.png")}
    assert len(files) >= 4, files.keys()                              # the run made its plots
    found = []
    for img in page.imgs:
        src = img["src"]
        assert src.startswith("data:image/png;base64,"), src[:40]
        data = base64.b64decode(src.split(",", 1)[1], validate=True)
        assert data[:8] == PNG
        match = [n for n, b in files.items() if len(b) == len(data) and b == data]
        assert len(match) == 1, f"image {img.get('alt')} is none of the plot files"
        found.append(match[0])
    assert sorted(found) == sorted(files), "one <img> per plot file"


def _check_worst(out, page):
    """Every row of the worst-values table against ``sweep.npz``: the value at the printed
    angle to the printed precision, that angle the column's extreme over the ok rows, the depth."""
    z = _npz(out)
    ok = z["status"].astype(str) == "ok"
    theta_deg = np.degrees(z["theta"])
    # column -> (factor SI -> unit shown, which extreme, depth column)
    spec = {c: (f, how, "") for _, items in ITEMS.values() for c, _, _, f, how in items}
    factor = {c.si: c.factor for c in COLUMNS}
    spec.update({c: (factor[c], how, d) for c, _, _, how, d in PEAKS})
    for row in page.worst:
        col, (_, value, unit, angle, dep, csv, _, note) = row["column"], row["cells"]
        f, how, depth = spec[col]
        v = np.asarray(z[col], float) * f
        # the printed angle names one ok row, where the column has the printed value
        at = np.flatnonzero(ok & (np.round(theta_deg, 3) == float(angle)))
        assert at.size == 1, f"{col}: no single ok row at {angle} deg"
        i = at[0]
        assert value == f"{v[i]:.4g}", f"{col}: printed {value}, sweep.npz has {v[i]:.6g} at {angle} deg"
        # and that row is the column's extreme over the ok rows
        key = np.abs(v) if how == "absmax" else (-v if how == "min" else v)
        assert key[i] == np.nanmax(np.where(ok, key, np.nan)), f"{col}: {angle} deg is not the worst angle"
        assert dep == (f"{z[depth][i] * 1e6:.4g}" if depth else "-"), f"{col}: depth {dep} um"
        # an FE surface value of the contact edge's singularity is said where it is shown
        assert bool(note) == (f"surf_edge_dominated:{col}" in str(z["flags"][i]).split(";")), (col, note)
        if col in factor:    # the unit is the CSV column's (its name ends with it)
            assert csv.endswith("_" + unit.replace("µm", "um").replace("/", "_")), (csv, unit)
    return {r["column"] for r in page.worst}


def test_worst_values_are_the_npz_columns_at_the_stated_angle(run):
    _, out, page = run
    shown = _check_worst(out, page)
    for must in ("Fc", "phi", "p0_hertz", "vm_max", "tau1_max", "txz_range_max", "surf_sz_min",
                 "wear_depth"):
        assert must in shown, f"{must} is not in the worst-values table"


@pytest.mark.slow
@pytest.mark.parametrize("example, provider", [("seed002_coated.toml", "layers"),
                                               ("seed002_assess.toml", None)])
def test_provider_worst_values_match_the_npz(tmp_path, example, provider):
    out = tmp_path / "out"
    sweep(f"examples/{example}",
          SweepOptions(angles=np.radians([0.0, 90.0, 180.0, 270.0]),  method="hertz",  plots=False,
                       vtk_every=0),
          RunOptions(workers=1, out=out, progress=False))
    text = (out / "report.html").read_text(encoding="utf-8")
    page = Page(text)
    shown = _check_worst(out, page)
    if provider:
        assert {c for c, *_ in ITEMS[provider][1]} & shown, f"no {provider} row"
        for line in SweepResult.load(out).provenance["extras"]["headline"]:   # what it omits
            assert html.escape(line) in text
    else:        # the assessment's worst angle per criterion, from the npz columns
        z = _npz(out)
        ok = z["status"].astype(str) == "ok"
        rows = re.findall(r"<tr><td>([^<]+)</td><td class=num>([^<]+)</td><td>[^<]*</td><td class=num>"
                          r"([^<]+)</td><td><code>(assess_\w+)</code>", text)
        assert len(rows) >= 5, rows
        for crit, value, angle, col in rows:
            v = np.where(ok, z[col], np.nan)
            i = int(np.nanargmin(v) if crit != "contact temperature" else np.nanargmax(v))
            assert (value, float(angle)) == (f"{v[i]:.4g}", round(np.degrees(z["theta"][i]), 3)), crit


def test_links_resolve_in_the_folder_and_nothing_points_outside(run):
    _, out, page = run
    assert {"sweep.pvd", "sweep.csv"} <= set(page.links)
    for href in page.links:
        assert (out / href).is_file(), href
        assert Path(href).name == href                                  # relative, in the folder
    for tag, attrs in page.attrs:
        for name, value in attrs.items():
            if name in ("href", "src", "action") or value and "url(" in value:
                assert not re.match(r"^(https?:|//|file:)", value or ""), (tag, name, value[:60])
    assert not [t for t, _ in page.attrs if t in ("link", "script", "iframe")]


def test_title_versions_command_and_scene(run):
    r, out, page = run
    text = " ".join(page.text)
    prov = SweepResult.load(out).provenance
    toml = (out / "scene.toml").read_text()
    name = re.search(r'^name = "(.*)"', toml, re.M).group(1)
    assert f"femcam sweep report: {name}" in text                      # <title>
    for lib in ("femcam", "gmsh", "scikit-fem", "numpy"):
        assert f"{lib} {prov['versions'][lib]}" in text, lib
    assert prov["command"] in text and prov["date"] in text
    assert toml.strip() in text                                        # the TOML in a <pre>
    inputs = scene_inputs(toml)
    assert ("follower.roller_radius", "10.0", "mm") in inputs and ("operating.rpm", "600.0", "rpm") in inputs
    cells = re.sub(r"\s+", " ", text)
    for key, value, unit in inputs:
        assert f"{key} {value} {unit}".strip() in cells, key          # one table row each


def test_report_md_shows_the_plots_by_their_folder_path_and_the_angles(run):
    _, out, page = run
    md = (out / "report.md").read_text()
    images = re.findall(r"!\[[^\]]*\]\(([^)]+)\)", md)
    assert sorted(images) == sorted(f"plots/{p.name}" for p in (out / "plots").glob("*.png"))
    for row in page.worst:                              # the same worst angle in both reports
        what, value, unit, angle = row["cells"][:4]
        assert f"| {what} | {value} | {unit.replace('µm', 'um')} | {angle} |" in md, what


def test_report_of_the_reloaded_sweep_is_the_same_page(run):
    _, out, _ = run
    assert report_html(SweepResult.load(out), out) == (out / "report.html").read_text(encoding="utf-8")


def test_only_the_plots_of_this_run_are_embedded(run):
    # a rerun with --overwrite --no-plots leaves the earlier PNGs in plots/: not this run's
    r, out, _ = run
    assert Page(report_html(r, out, plots=[])).imgs == []
    one = out / "plots" / "p0_vs_angle.png"
    assert [i["src"] for i in Page(report_html(r, out, plots=[one])).imgs] == [png_data_uri(one)]


def test_refused_part_is_the_first_thing_on_the_page(run):
    r, out, _ = run
    line = "bodies refused at 8 of 8 angle(s), its columns are NaN there: ConvergenceError: ..."
    ex = dict(r.provenance.get("extras", {}), refused=[{"part": "bodies", "reason": "x", "line": line}])
    page = Page(report_html(dataclasses.replace(r, provenance=dict(r.provenance, extras=ex)), out))
    assert page.first[0] == "div" and page.first[1].get("class") == "refused"
    text = " ".join(page.text)
    assert "Not a complete answer: 1 part(s) the scene asks for were refused" in text and line in text
    assert "Not a complete answer" not in " ".join(run[2].text)       # not on a complete answer


@pytest.mark.slow
def test_fe_validation_figures_match_the_npz(tmp_path):
    out = tmp_path / "fe"
    sweep(EXAMPLE,
          SweepOptions(angles=np.radians([60.0, 210.0, 300.0]),  method="fe",  a_over_h=4,  plots=True,
                       vtk_every=1),
          RunOptions(workers=1, out=out, progress=False, scene_path=EXAMPLE))
    z, page = _npz(out), Page((out / "report.html").read_text(encoding="utf-8"))
    text = " ".join(page.text)
    ok = z["status"].astype(str) == "ok"
    arc = ok & (z["model"].astype(str) != "fe_exact") & np.isfinite(z["err_p0"])
    assert f"max |p0_fe/p0_hertz - 1| {100 * np.max(np.abs(z['err_p0'][arc])):.3f} % over {arc.sum()}" in text
    models, counts = np.unique(z["model"].astype(str), return_counts=True)
    for m, n in zip(models, counts, strict=True):
        assert f"{m} {n}" in re.sub(r"\s+", " ", text), m                 # model and its count
    rows = {r["column"]: r["cells"] for r in page.worst}
    i = int(np.nanargmax(np.where(ok, z["p0_fe"], np.nan)))
    assert rows["p0_fe"][1] == f"{z['p0_fe'][i] * 1e-6:.4g}"
    assert float(rows["p0_fe"][3]) == round(math.degrees(z["theta"][i]), 3)
    assert len(page.imgs) == len(list((out / "plots").glob("*.png")))


def test_markdown_page_embeds_images_and_reads_tables(run):
    # the page `femcam assess` writes beside its report.md
    _, out, _ = run
    md = ("# The title\n\nSome `code` and **bold**.\n\n| a | b |\n|---|---|\n| 1 | x \\| y |\n\n"
          "- one\n- two\n\n![the p0 plot](plots/p0_vs_angle.png)\n")
    text = markdown_page(md, out)
    page = Page(text)
    assert [i["src"] for i in page.imgs] == [png_data_uri(out / "plots" / "p0_vs_angle.png")]
    assert "<title>The title</title>" in text and "<code>code</code>" in text and "<b>bold</b>" in text
    assert "<td>1</td><td>x | y</td>" in text and "<li>one</li><li>two</li>" in text


def test_a_hertz_sweep_says_it_has_no_error_estimate(run):
    _, out, _ = run
    text = (out / "report.html").read_text(encoding="utf-8")
    assert "<h2>Error estimates</h2><p>No error estimate" in text and "id=estimates" not in text
    assert "## Error estimates" not in (out / "report.md").read_text()


@pytest.mark.slow
def test_error_estimates_per_headline_quantity_match_the_npz(tmp_path):
    """rtol 0.5 %: each FE headline quantity's estimate at the row of its worst value and the
    largest over the ok rows, read from sweep.npz here (err_est_* relative -> percent, .3g), in
    report.html's table and report.md's; p0 says the requested rtol and that every row met it."""
    out = tmp_path / "est"
    sweep(EXAMPLE,
          SweepOptions(angles=np.radians([60.0, 150.0, 210.0, 300.0]),  rtol=0.005,  plots=False,
                       vtk_every=0),
          RunOptions(workers=1, out=out, progress=False, scene_path=EXAMPLE))
    z, text = _npz(out), (out / "report.html").read_text(encoding="utf-8")
    md = (out / "report.md").read_text()
    ok = z["status"].astype(str) == "ok"
    table = text.split("<table id=estimates>", 1)[1].split("</table>", 1)[0]
    cells = [re.findall(r"<td[^>]*>([^<]*)</td>", r) for r in table.split("<tr>")[2:]]
    got = {c[0]: c[1:] for c in cells}
    what = {c: w for c, w, *_ in PEAKS}
    for col, q in (("p0_fe", "p0"), ("a_fe", "a"), ("vm_max", "vm"), ("tau1_max", "tau1")):
        est = np.where(ok, z[f"err_est_{q}"], np.nan)
        i = int(np.nanargmax(np.where(ok, z[col], np.nan)))        # the quantity's worst row
        at, top = f"{100 * est[i]:.3g}", f"{100 * np.nanmax(est):.3g}"
        assert got[what[col]][:3] == [at, top, str(int(np.isfinite(est).sum()))], col
        assert f"| {what[col]} | {at} | {top} | {int(np.isfinite(est).sum())} |" in md, col
    p0 = np.where(ok, z["err_est_p0"], np.nan)
    assert np.nanmax(p0) <= 0.005
    assert got[what["p0_fe"]][3] == "0.5 %: met by every row" and "0.5 %: met by every row" in md
    # the mesh rtol chose for each family: the last cell of its row in the families table
    for f in SweepResult.load(out).families:
        row = re.search(rf"<tr><td[^>]*>{f['id']}</td><td class=num>{f['n_angles']}</td>.*?</tr>", text)
        assert row and row.group(0).endswith(f"<td class=num>{f['a_over_h']:g}</td></tr>"), f["id"]
