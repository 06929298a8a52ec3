"""``femcam run`` in-process on every shipped example: CSV columns and values, PNG plots, errors."""

import math

try:  # Python >= 3.11
    import tomllib
except ModuleNotFoundError:  # pragma: no cover - Python 3.10
    import tomli as tomllib
from pathlib import Path

import numpy as np
import pytest

from femcam.cli import main

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
SCENES = sorted(EXAMPLES.glob("*.toml"))
PNGS = ("svaj", "phi", "rho", "fc", "cam")


def read_csv(path):
    """Columns of a femcam CSV (``#`` provenance lines, then a header row) as float arrays."""
    lines = [ln for ln in Path(path).read_text().splitlines() if not ln.startswith("#")]
    names = lines[0].split(",")
    vals = np.array([[float(x) for x in ln.split(",")] for ln in lines[1:]])
    return {n: vals[:, k] for k, n in enumerate(names)}


SEED_SCENES = {"seed000_rise", "seed002_study_model", "seed003_knife_edge"}


def test_the_seed_scenes_ship():
    assert SEED_SCENES <= {p.stem for p in SCENES}


def _omega_from_file(path) -> float:
    """omega (rad/s) read from the TOML with the standard library: rpm * 2 pi / 60 or omega_rad_s."""
    op = tomllib.loads(Path(path).read_text())["operating"]
    return op["rpm"] * 2 * math.pi / 60 if "rpm" in op else op["omega_rad_s"]


@pytest.mark.slow  # ~1 s; the default suite keeps its budget (CI runs it in the slow pass)
@pytest.mark.parametrize("scene", SCENES, ids=lambda p: p.stem)
def test_run_writes_csv_and_pngs(scene, tmp_path, capsys):
    out = tmp_path / "out"
    # the PNGs (~1 s per scene) are checked on the three seed scenes; the variants run without
    plots = scene.stem in SEED_SCENES
    assert main(["run", str(scene), "--out", str(out), "--angles-deg", "0:360:2"]
                + ([] if plots else ["--no-plots"])) == 0
    text = capsys.readouterr().out
    assert "Summary:" in text and "max |phi|" in text and "Junctions" in text
    d = read_csv(out / "analytic.csv")
    for col in ("theta_deg", "s_mm", "v_m_s", "a_m_s2", "j_m_s3", "phi_deg", "rho_mm", "Fc_N"):
        assert col in d
    np.testing.assert_allclose(d["theta_deg"], np.arange(0, 360, 2.0))
    # independent identity: v = ds/dt = omega ds/dtheta, checked by finite differences of s_mm
    w = _omega_from_file(scene)
    dsdth = np.gradient(d["s_mm"] * 1e-3, np.radians(d["theta_deg"]))
    vmax = np.max(np.abs(d["v_m_s"]))
    assert np.median(np.abs(dsdth * w - d["v_m_s"])) < 0.02 * vmax
    for name in PNGS if plots else ():
        png = out / f"{name}.png"
        assert png.stat().st_size > 5000 and png.read_bytes()[:4] == b"\x89PNG"


def test_run_law_override_and_no_plots(tmp_path, capsys):
    out = tmp_path / "o"
    rc = main(["run", str(EXAMPLES / "seed002_study_model.toml"), "--out", str(out), "--law", "bezier9",
               "--no-plots", "--angles-deg", "0:360:0.25"])
    assert rc == 0
    d = read_csv(out / "analytic.csv")
    # eq. 24 by hand at mid-rise of bezier9 (u = 1/2): s = L/2, s' = L/beta * 630/256
    i = int(np.argmin(np.abs(d["theta_deg"] - 50.0)))
    s1 = 0.01 / math.radians(100) * 630 / 2**8
    assert d["phi_deg"][i] == pytest.approx(math.degrees(math.atan(s1 / (0.005 + 0.02))), abs=1e-6)
    assert not list(out.glob("*.png"))
    assert "rise(bezier9)" in capsys.readouterr().out


def test_run_bad_input_gives_clear_error(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    text = (EXAMPLES / "seed002_study_model.toml").read_text()
    bad.write_text(text.replace("mass_kg = 0.2", "mass_kg = -1"))
    assert main(["run", str(bad), "--out", str(tmp_path / "x")]) == 1
    err = capsys.readouterr().err
    assert "dynamics.mass_kg = -1 kg: must be >= 0" in err
    assert main(["run", str(EXAMPLES / "seed000_rise.toml"), "--angles-deg", "0:360"]) == 1
    assert "--angles-deg = '0:360' deg: must be start:stop:step" in capsys.readouterr().err


def test_run_prints_junction_jumps_in_si_and_no_negative_zero(tmp_path, capsys):
    assert main(["run", str(EXAMPLES / "seed003_knife_edge.toml"), "--out", str(tmp_path / "o"),
                 "--no-plots", "--angles-deg", "0:360:1"]) == 0
    text = capsys.readouterr().out
    # 3-4-5 rise (h = 3 mm, beta = 120 deg) into a dwell at 300 rpm: jerk j = 60 h w^3/beta^3 at the
    # rise end, 0 on the dwell -> jump -60 h w^3/beta^3 (m/s^3), by hand
    w, h, beta = 10 * math.pi, 0.003, math.radians(120)
    jump = -60 * h * w**3 / beta**3
    assert f"omega = {w:.6g} rad/s" in text
    assert f"j = {jump:+.4g} m/s^3" in text and "m/s^2" in text and "v = +0 m/s" in text
    assert f"{jump:+.4g}" == "-607.5"
    summary = (tmp_path / "o" / "summary.txt").read_text()
    assert f"j = {jump:+.4g} m/s^3" in summary
    # the seed 000 table has exact zeros that used to print as "-0"
    assert main(["run", str(EXAMPLES / "seed000_rise.toml"), "--out", str(tmp_path / "z"),
                 "--no-plots"]) == 0
    tokens = capsys.readouterr().out.split()
    assert "-0" not in tokens


def test_run_reports_narrow_undercut_missed_by_coarse_angles(tmp_path, capsys):
    # seed 002's cam with Rb = 2.5 mm under a 20 mm roller: undercut only near 75.2-77.2 deg and
    # 202.8-204.8 deg (pitch radius of curvature < Rr; see tests/test_scene.py), between 10-deg angles
    text = (EXAMPLES / "seed002_study_model.toml").read_text()
    text = text.replace("roller_radius_mm = 10.0", "roller_radius_mm = 20.0").replace(
        "base_radius_mm = 10.0", "base_radius_mm = 2.5")
    scene = tmp_path / "narrow.toml"
    scene.write_text(text)
    args = ["run", str(scene), "--out", str(tmp_path / "o"), "--no-plots", "--angles-deg", "0:360:10"]
    assert main(args) == 1
    assert "undercut" in capsys.readouterr().err
    assert main([*args, "--allow-undercut"]) == 0
    out = capsys.readouterr()
    line = next(ln for ln in out.out.splitlines() if ln.strip().startswith("undercut"))
    assert "75." in line and "77." in line and "202." in line and "204." in line
    assert "WARNING" in out.err
