"""The ``femcam`` command ends with ``os._exit`` once its output is out (femcam.cli._exit_process,
issue 27): every file complete, stdout flushed, the exit code kept. References: the same sweep
run in this process through the API (no fast exit), and the documented exit codes."""

from __future__ import annotations

import csv
import os
import subprocess
import sys
from pathlib import Path

import pytest

from femcam.scene import load_scene
from femcam.sweep import RunOptions, SweepOptions, parse_angles_deg, sweep

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "examples" / "seed002_study_model.toml"
ENV = {**os.environ, "PYTHONPATH": str(ROOT)}


def _rows(path: Path) -> list[dict]:
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return [{k: v for k, v in r.items() if "time" not in k} for r in rows]


@pytest.mark.slow
def test_command_line_files_and_stdout_are_complete(tmp_path):
    """A Hertz sweep with a VTK series and plots through ``python -m femcam`` (piped stdout):
    exit 0, the summary printed to its last line, and the CSV, the .pvd's files and the reports
    equal to an in-process run's."""
    args = ["--angles-deg", "0:360:45", "--method", "hertz", "--vtk-every", "1"]
    p = subprocess.run([sys.executable, "-m", "femcam", "sweep", str(SCENE), "--out",
                        str(tmp_path / "cli"), *args], capture_output=True, text=True, env=ENV,
                       cwd=ROOT, timeout=300)
    assert p.returncode == 0, p.stderr
    assert p.stdout.startswith("femcam sweep: 8 angles")
    assert p.stdout.rstrip().endswith(str(tmp_path / "cli" / "report.html"))  # last path line
    api = sweep(load_scene(SCENE),
                SweepOptions(angles=parse_angles_deg("0:360:45"), method="hertz", vtk_every=1),
                RunOptions(out=tmp_path / "api", progress=False))
    assert _rows(tmp_path / "cli" / "sweep.csv") == _rows(tmp_path / "api" / "sweep.csv")
    for sub in ("vtk", "plots"):
        cli = sorted(x.name for x in (tmp_path / "cli" / sub).iterdir())
        assert cli == sorted(x.name for x in (tmp_path / "api" / sub).iterdir()) and cli
    for name in ("sweep.pvd", "report.md", "report.html"):
        assert (tmp_path / "cli" / name).read_text().endswith("\n"), name
    assert set(api.paths) <= {line.split(":")[0].strip() for line in p.stdout.splitlines()[1:]}


def test_command_line_error_keeps_exit_code_1(tmp_path):
    """An error still ends with exit code 1 and its one line on stderr."""
    p = subprocess.run([sys.executable, "-m", "femcam", "check", str(tmp_path / "missing.toml")],
                       capture_output=True, text=True, env=ENV, cwd=ROOT, timeout=120)
    assert p.returncode == 1
    assert p.stderr.count("\n") == 1 and "missing.toml" in p.stderr
