"""The front door of the command line: ``femcam --version`` and ``femcam --help`` import none
of the heavy stack, and the subcommand list of ``--help`` matches the subcommands' own help."""

import subprocess
import sys

import pytest

from femcam.cli import SUBCOMMANDS, build_parser

#: ``femcam.sweep.run``, the sweep's orchestrator (and everything it imports); the package
#: ``femcam.sweep`` itself imports nothing until a name is used (``import femcam`` loads it)
HEAVY = ("gmsh", "skfem", "pyvista", "matplotlib", "scipy.sparse.linalg", "dask", "femcam.sweep.run",
         "femcam.sweep.pipeline")

PROBE = (
    "import sys\n"
    "from femcam.cli import main\n"
    "try:\n"
    "    main(sys.argv[1:])\n"
    "except SystemExit:\n"
    "    pass\n"
    f"print('HEAVY', ','.join(m for m in {HEAVY!r} if m in sys.modules))\n"
)


@pytest.mark.parametrize("flag", ["--version", "--help"])
def test_version_and_help_import_no_heavy_module(flag):
    out = subprocess.run([sys.executable, "-c", PROBE, flag], capture_output=True, text=True,
                         check=True).stdout
    assert out.splitlines()[-1] == "HEAVY ", out
    if flag == "--version":
        first = out.splitlines()[0]
        for name in ("femcam", "scikit-fem", "gmsh", "numpy"):
            assert f"{name} " in first, first


def test_listed_help_matches_each_subcommand():
    sub = next(a for a in build_parser()._actions if a.__class__.__name__ == "_SubParsersAction")
    shown = {c.dest: c.help for c in sub._choices_actions}
    assert shown == SUBCOMMANDS


EX = __import__("pathlib").Path(__file__).resolve().parents[1] / "examples"
SCENE = str(EX / "seed002_study_model.toml")


def test_sweep_off_a_terminal_prints_plain_progress_and_quiet_removes_it(tmp_path, capsys):
    from femcam import _progress
    from femcam.cli import main

    cmd = ["sweep", SCENE, "--method", "hertz", "--angles-deg", "0:30:10", "--no-plots",
           "--vtk-every", "0"]
    assert main(["-v", *cmd, "--out", str(tmp_path / "a")]) == 0
    cap = capsys.readouterr()
    assert "femcam: solves 4/4 angles (100 %)" in cap.err, cap.err
    assert "femcam sweep: 4 angles" in cap.out
    assert main([*cmd, "-q", "--out", str(tmp_path / "b")]) == 0
    cap = capsys.readouterr()
    assert cap.out == "" and "femcam: " not in cap.err, cap
    assert _progress.LEVEL is None          # the command line's level does not outlive it


def test_copied_scene_reproduces_a_law_override(tmp_path, capsys):
    """``--law`` is written into DIR/scene.toml: sweeping the copy gives the same rows."""
    import numpy as np

    from femcam.cli import main
    from femcam.sweep import SweepResult

    cmd = ["--method", "hertz", "--angles-deg", "0:360:30", "--no-plots", "--vtk-every", "0"]
    assert main(["sweep", SCENE, *cmd, "--law", "cycloidal", "--out", str(tmp_path / "a")]) == 0
    copy = (tmp_path / "a" / "scene.toml").read_text()
    assert 'law = "cycloidal"  # set on the command line (the file had: "bezier5")' in copy
    assert main(["sweep", str(tmp_path / "a" / "scene.toml"), *cmd, "--out", str(tmp_path / "b")]) == 0
    assert main(["sweep", SCENE, *cmd, "--out", str(tmp_path / "c")]) == 0
    capsys.readouterr()
    a, b, c = (SweepResult.load(tmp_path / d).table for d in "abc")
    for k in ("Fc", "p0_hertz"):
        np.testing.assert_array_equal(a[k], b[k], err_msg=k)
    assert not np.array_equal(a["Fc"], c["Fc"])   # the law matters: the test can fail


def test_check_init_examples(tmp_path, capsys):
    """check: OK summary, exit 0; init: a template that loads and passes check, refused twice;
    examples: copies every scene, --list names them, a non-empty DIR is refused."""
    from femcam.cli import main
    from femcam.scene import load_scene
    from femcam.start import example_scenes, key_comment

    assert main(["check", SCENE]) == 0
    out = capsys.readouterr().out
    assert "max pressure angle" in out and "min radius of curvature" in out and "OK" in out
    bad = tmp_path / "bad.toml"
    bad.write_text((EX / "seed002_study_model.toml").read_text().replace("rpm = 600.0", "rpm = -5.0"))
    assert main(["check", str(bad)]) == 1
    assert "operating.rpm" in capsys.readouterr().err

    path = tmp_path / "scene.toml"
    assert main(["init", str(path)]) == 0
    text = path.read_text()
    assert load_scene(path).name == "my_cam"
    assert f"# {key_comment('follower', 'base_radius_mm')}" in text   # generated, not hand-written
    assert main(["check", str(path)]) == 0
    assert main(["init", str(path)]) == 1
    assert "--overwrite" in capsys.readouterr().err
    assert main(["init", str(path), "--overwrite"]) == 0

    dest = tmp_path / "ex"
    assert main(["examples", str(dest)]) == 0
    assert sorted(p.name for p in dest.glob("*.toml")) == sorted(example_scenes())
    assert main(["examples", str(dest)]) == 1
    assert main(["examples", "--list"]) == 0
    assert "seed002_study_model.toml: " in capsys.readouterr().out


@pytest.mark.slow  # over 1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_info_and_plot_of_a_sweep_folder(tmp_path, capsys):
    from femcam.cli import main

    out = tmp_path / "s"
    assert main(["sweep", SCENE, "--method", "hertz", "--angles-deg", "0:360:30", "--vtk-every", "0",
                 "--out", str(out)]) == 0
    capsys.readouterr()
    assert main(["info", str(out)]) == 0
    text = capsys.readouterr().out
    assert "written by: femcam sweep" in text and "angles: 12, 0 to 330 deg, step 30 deg" in text
    assert "worst p0 Hertz: " in text and " MPa at " in text and "sweep.csv" in text
    for png in (out / "plots").glob("*.png"):
        png.unlink()
    assert main(["plot", str(out)]) == 0
    assert (out / "plots" / "p0_vs_angle.png").is_file()
    assert main(["plot", str(out)]) == 0            # plots are derived data: replaced
    assert main(["info", str(tmp_path)]) == 1
    err = capsys.readouterr().err.strip()
    assert err.startswith("femcam info: error: DIR = ") and len(err.splitlines()) == 1


def test_one_rule_for_start_stop_step_flags():
    """--angles-deg and --rpm-sweep: the stop is included when it falls on the grid; an angle
    range of whole turns drops its stop (the same cam position as its start)."""
    import numpy as np

    from femcam.cli._flags import RANGE_RULE
    from femcam.cli.dynamics import _rpm_range
    from femcam.sweep import parse_angles_deg

    assert np.degrees(parse_angles_deg("0:90:30")).round(9).tolist() == [0, 30, 60, 90]
    assert _rpm_range("4200:4600:200").tolist() == [4200, 4400, 4600]
    assert np.degrees(parse_angles_deg("0:100:30")).round(9).tolist() == [0, 30, 60, 90]
    assert _rpm_range("4200:4700:200").tolist() == [4200, 4400, 4600]
    full = np.degrees(parse_angles_deg("0:360:1"))
    assert full.size == 360 and full[-1] == 359          # 360 deg is 0 deg: not twice
    assert parse_angles_deg("-360:0:30").size == 12 and parse_angles_deg("0:720:90").size == 8
    for flag in ("--angles-deg", "--rpm-sweep"):
        sub = "sweep" if flag == "--angles-deg" else "dynamics"
        help_text = next(a.help for a in build_parser(sub)._subparsers._group_actions[0]
                         .choices[sub]._actions if flag in a.option_strings)
        assert RANGE_RULE in help_text, flag


def test_cli_page_reference_is_the_parser():
    """docs/cli.md's reference section is what docs/cli_reference.py generates from the parser
    (every subcommand, flag and range): regenerate it after a flag changes."""
    import re
    import runpy
    from pathlib import Path

    page = Path(__file__).resolve().parents[1] / "docs" / "cli.md"
    gen = runpy.run_path(str(page.parent / "cli_reference.py"))
    text = page.read_text(encoding="utf-8")
    m = re.search(re.escape(gen["BEGIN"]) + r"\n\n(.*)\n" + re.escape(gen["END"]), text, re.S)
    assert m and m.group(1) == gen["reference"](), "run python docs/cli_reference.py"


def test_example_scenes_are_package_data():
    """The wheel ships examples/ as femcam/_examples (pyproject force-include); at run time the
    installed copy is used, else the repository's examples/ (an editable install)."""
    from pathlib import Path

    try:
        import tomllib
    except ModuleNotFoundError:  # pragma: no cover - Python 3.10
        import tomli as tomllib

    from femcam.start import example_scenes, examples_dir

    root = Path(__file__).resolve().parents[1]
    cfg = tomllib.loads((root / "pyproject.toml").read_text())
    wheel = cfg["tool"]["hatch"]["build"]["targets"]["wheel"]
    assert wheel["force-include"]["examples"] == "femcam/_examples"
    assert (examples_dir() / "seed002_study_model.toml").is_file()
    assert len(example_scenes()) == len(list((root / "examples").glob("*.toml")))
