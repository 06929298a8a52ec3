"""``--angles-deg`` takes degrees; a range spanning 2 pi or pi (6.28, 3.14) is almost surely
radians typed into a degree flag: the command still runs what was asked (a 6.28 deg span is a
legal range) but says so on stderr, once, in one line. Reference: 2 pi = 6.2832, pi = 3.1416;
the hint fires within 1 % of them and never for a span of whole degrees used in practice
(1, 5, 10, 90, 180, 360)."""

from __future__ import annotations

import math

import pytest

from femcam import _validate
from femcam.cli import main

EXAMPLE = "examples/seed002_assess.toml"


@pytest.mark.parametrize("spec", ["0:6.28:0.1", "0:6.2832:0.01", "1:7.28:0.5", "0:3.14:0.1",
                                  f"0:{2 * math.pi!r}:0.1"])
def test_a_two_pi_or_pi_span_is_named(spec):
    hint = _validate.radians_hint("--angles-deg", spec)
    assert spec in hint and "degrees" in hint and "0:360:" in hint


@pytest.mark.parametrize("spec", ["0:360:1", "0:180:1", "0:90:5", "0:10:0.1", "0:6:0.1",
                                  "0:6.5:0.1", "0:1:0.01", "bad", "0:6.28"])
def test_spans_in_degrees_and_bad_specs_get_no_hint(spec):
    assert _validate.radians_hint("--angles-deg", spec) == ""


def test_the_cli_says_it_once_on_stderr_and_runs(tmp_path, capsys):
    out = tmp_path / "o"
    rc = main(["run", EXAMPLE, "--angles-deg", "0:6.28:0.1", "--out", str(out)])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 0
    notes = [line for line in err if "radians" in line]
    assert len(notes) == 1 and notes[0].startswith("femcam run: note: --angles-deg = '0:6.28:0.1'")
    assert out.exists()


def test_the_sweep_says_it_too(tmp_path, capsys):
    rc = main(["sweep", "examples/seed002_study_model.toml", "--angles-deg", "0:3.14:0.5",
               "--method", "hertz", "--no-plots", "--vtk-every", "0", "--progress", "off",
               "--workers", "1", "--out", str(tmp_path / "s")])
    err = capsys.readouterr().err
    assert rc == 0
    assert err.count("femcam sweep: note: --angles-deg = '0:3.14:0.5' spans 3.14 deg = pi") == 1
