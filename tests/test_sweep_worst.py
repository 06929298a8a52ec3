"""The sweep's summary and report.md name each extra provider's worst value (femcam.sweep.worst).

Reference: the CSV column's own extreme, read here with the csv module (the printed number is
rounded to 4 significant figures, hence the 5e-4 relative tolerance).
"""

from __future__ import annotations

import csv
import re
from pathlib import Path

import pytest

from femcam.cli import main

ROOT = Path(__file__).resolve().parents[1]


def _csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return rows


def _worst(rows, col):
    ok = [r for r in rows if r["status"] == "ok" and r[col] not in ("", "nan")]
    best = max(ok, key=lambda r: float(r[col]))
    return float(best[col]), float(best["theta_deg"]), best


@pytest.mark.parametrize("scene, pattern, col, unit", [
    ("seed002_crowned.toml", r"finite length: axial peak ([\d.]+) MPa at ([\d.]+) deg",
     "p_axial_peak_MPa", 1.0),
    pytest.param("seed002_needle_roller.toml",
                 r"roller support: bore hoop stress ([\d.]+) MPa at ([\d.]+) deg",
                 "bore_hoop_max_MPa", 1.0, marks=pytest.mark.slow),   # the ring model: ~2 s
    pytest.param("seed002_needle_roller.toml", r"worst needle load ([\d.]+) N at ([\d.]+) deg",
                 "needle_Qmax_on_N", 1.0, marks=pytest.mark.slow),
])
def test_summary_and_report_print_the_providers_worst_value(tmp_path, capsys, scene, pattern, col, unit):
    out = tmp_path / "o"
    assert main(["sweep", str(ROOT / "examples" / scene), "--out", str(out), "--method", "hertz",
                 "--angles-deg", "0:144:24", "--no-plots", "--vtk-every", "0"]) == 0
    printed = capsys.readouterr().out
    value, theta_deg, row = _worst(_csv(out / "sweep.csv"), col)
    for text in (printed, (out / "report.md").read_text()):
        m = re.search(pattern, text)
        assert m, text
        assert float(m.group(1)) == pytest.approx(value * unit, rel=5e-4)
        assert float(m.group(2)) == pytest.approx(theta_deg, abs=0.05)
    if col == "p_axial_peak_MPa":   # the 2D Hertz p0 at the same angle is quoted beside it
        m = re.search(r"\(2D Hertz at the mean load there ([\d.]+) MPa\): the 2D p0 above is not "
                      r"the peak", printed)
        assert m and float(m.group(1)) == pytest.approx(float(row["p0_hertz_MPa"]), abs=0.5)
