"""Bad input and faulty disks on the command line: one line ``femcam <cmd>: error: ...``, exit
1 (or 2 for argparse usage), never a traceback.

References are the inputs themselves: each test builds the bad path/flag and checks that the
message names it (flag, value, unit or path) and that stderr holds no ``Traceback``.
"""

import errno
import math
from pathlib import Path

import pytest

from femcam.cli import main
from femcam.errors import UndercutError
from femcam.profile.geometry import _fmt_intervals_deg

STUDY_PATH = Path(__file__).resolve().parents[1] / "examples" / "seed002_study_model.toml"

SCENE = str(STUDY_PATH)
#: (subcommand, arguments before the scene/--out) of every subcommand that reads a scene
WITH_SCENE = {"run": ["run"], "sweep": ["sweep"], "wear": ["wear", "map"], "synth": ["synth"],
              "dynamics": ["dynamics"], "assess": ["assess"]}


def _one_line(capsys, cmd: str) -> str:
    err = capsys.readouterr().err.strip()
    assert "Traceback" not in err
    assert err.startswith(f"femcam {cmd}: error: ")
    assert len(err.splitlines()) == 1, err
    return err


@pytest.mark.parametrize("cmd", list(WITH_SCENE))
def test_scene_path_is_a_directory(cmd, tmp_path, capsys):
    assert main([*WITH_SCENE[cmd], str(tmp_path), "--out", str(tmp_path / "o")]) == 1
    assert f"scene file {tmp_path}: is a directory" in _one_line(capsys, cmd)


@pytest.mark.parametrize("cmd", list(WITH_SCENE))
def test_binary_scene(cmd, tmp_path, capsys):
    bad = tmp_path / "scene.toml"
    bad.write_bytes(b"\x89PNG\r\n\x1a\n\x00\xff")
    assert main([*WITH_SCENE[cmd], str(bad), "--out", str(tmp_path / "o")]) == 1
    assert f"scene file {bad}: not a UTF-8 text file (byte 0" in _one_line(capsys, cmd)


def test_latin1_scene_names_the_byte(tmp_path, capsys):
    bad = tmp_path / "scene.toml"
    bad.write_bytes('name = "caf\u00e9"\n'.encode("latin-1"))  # e-acute is 0xe9 in Latin-1
    assert main(["run", str(bad)]) == 1
    pos = len(b'name = "caf')  # the offset of the 0xe9 byte
    assert f"(byte {pos}: b'\\xe9')" in _one_line(capsys, "run")


@pytest.mark.parametrize("cmd", list(WITH_SCENE))
@pytest.mark.parametrize("under", [False, True])
def test_out_is_a_file_or_under_one(cmd, under, tmp_path, capsys):
    f = tmp_path / "afile"
    f.write_text("x")
    out = f / "sub" if under else f
    args = [*WITH_SCENE[cmd], SCENE, "--out", str(out)]
    if cmd == "synth":  # synth takes a knife-edge case; the --out check comes first
        args = ["synth", "--case", "seed003", "--out", str(out)]
    if cmd == "dynamics":  # needs a scene with an elastic train
        args[1] = str(STUDY_PATH.with_name("seed002_dynamic.toml"))
    if cmd == "sweep":
        args += ["--method", "hertz"]
    assert main(args) == 1
    what = f"is under the file {f}" if under else "is an existing file"
    assert f"--out = '{out}': {what}, not a directory" in _one_line(capsys, cmd)


def test_wear_seed000_csv_under_a_file(tmp_path, capsys):
    f = tmp_path / "afile"
    f.write_text("x")
    assert main(["wear", "seed000", "--csv", str(f / "t.csv")]) == 1
    err = _one_line(capsys, "wear")
    assert f"--csv (its directory) = '{f}': is an existing file, not a directory" in err


def test_unwritable_directory_is_refused(tmp_path, capsys, monkeypatch):
    # the tests run as root, for whom chmod 0o500 does not stop writes: os.access is what the
    # check asks, so it is made to answer "not writable" for the output directory
    import femcam.cli._common as common
    ro = tmp_path / "ro"
    ro.mkdir()
    real = common.os.access
    monkeypatch.setattr(common.os, "access", lambda p, m: False if str(p) == str(ro) else real(p, m))
    want = f"--out = '{ro}': directory {ro} is not writable"   # one wording for every command
    for cmd, args in (("run", ["--no-plots"]), ("sweep", ["--method", "hertz"]),
                      ("assess", ["--no-plots"]), ("wear", ["--no-plots"])):
        assert main([*WITH_SCENE[cmd], SCENE, "--out", str(ro), *args]) == 1
        assert _one_line(capsys, cmd) == f"femcam {cmd}: error: {want}"
    assert main(["sweep", SCENE, "--out", str(ro / "new"), "--method", "hertz"]) == 1
    assert f"directory {ro} is not writable" in _one_line(capsys, "sweep")


def test_full_disk_is_one_line(tmp_path, capsys, monkeypatch):
    """ENOSPC while writing the CSV (simulated: the writer raises OSError(ENOSPC))."""
    import femcam.cli.run as run

    def full(path, *a, **k):
        raise OSError(errno.ENOSPC, "No space left on device", str(path))

    monkeypatch.setattr(run, "write_csv", full)
    out = tmp_path / "o"
    assert main(["run", SCENE, "--out", str(out), "--no-plots"]) == 1
    err = _one_line(capsys, "run")
    assert "No space left on device (free some space, then rerun" in err
    assert f"'{out / 'analytic.csv'}'" in err


def _full_vtu_writer(monkeypatch):
    """The VTU writer (femcam.io.vtk's one-pass writer, and meshio's for other cells) hits a
    full disk: a partial file, then ENOSPC."""
    import femcam.io.vtk as vtk
    meshio = pytest.importorskip("meshio")

    def full(path, *a, **k):
        open(path, "wb").write(b"<VTKFile")  # a partial file, as a full disk leaves it
        raise OSError(errno.ENOSPC, "No space left on device", str(path))

    monkeypatch.setattr(meshio, "write", full)
    monkeypatch.setattr(vtk, "_write_parts", full)


def test_full_disk_in_vtu_writer_is_one_line(tmp_path, capsys, monkeypatch):
    """ENOSPC inside the VTU writer while a sweep writes its VTU files: one line, exit 1."""
    _full_vtu_writer(monkeypatch)
    out = tmp_path / "o"
    rc = main(["sweep", SCENE, "--out", str(out), "--method", "hertz", "--angles-deg", "0:20:10",
               "--vtk-every", "1", "--no-plots", "--workers", "1", "--progress", "off"])
    assert rc == 1
    assert "No space left on device" in _one_line(capsys, "sweep")


def test_full_disk_leaves_no_part_file(tmp_path, monkeypatch):
    _full_vtu_writer(monkeypatch)
    out = tmp_path / "o"
    main(["sweep", SCENE, "--out", str(out), "--method", "hertz", "--angles-deg", "0:20:10",
          "--vtk-every", "1", "--no-plots", "--workers", "1", "--progress", "off"])
    assert not [p for p in out.rglob("*") if p.name.endswith((".part.vtu", ".tmp"))]


@pytest.mark.parametrize("flag, value, why", [
    ("--print-every-deg", "0", "must be in [0.001, 360]"),
    ("--print-every-deg", "-1", "must be in [0.001, 360]"),
    ("--print-every-deg", "nan", "must be finite"), ("--phi-limit-deg", "nan", "must be finite"),
    ("--phi-limit-deg", "-5", "must be in (0, 90)"), ("--phi-limit-deg", "95", "must be in (0, 90)")])
def test_run_flags_are_checked(flag, value, why, tmp_path, capsys):
    assert main(["run", SCENE, "--out", str(tmp_path), "--no-plots", flag, value]) == 1
    err = _one_line(capsys, "run")
    assert f"{flag} = {float(value):g} deg: {why}" in err
    assert not (tmp_path / "analytic.csv").exists()  # refused before any work


@pytest.mark.slow  # over 1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_long_lists_are_capped(capsys, tmp_path):
    # 50 intervals: the message lists 20 of them and counts the rest
    iv = [(math.radians(i), math.radians(i + 0.5)) for i in range(50)]
    text = _fmt_intervals_deg(iv)
    assert text.count(" deg") == 20 and text.endswith(", ... and 30 more")
    # a scene of 1800 alternating rise/fall segments of 0.2 deg is undercut at ~3600 angles
    src = STUDY_PATH.read_text()
    i, j = src.index("[[program.segment]]"), src.index("[follower]")
    segs = "".join(f'[[program.segment]]\nkind = "{"rise" if k % 2 == 0 else "fall"}"\n'
                   "beta_deg = 0.2\nlift_mm = 0.01\n" for k in range(1800))
    big = tmp_path / "big.toml"
    big.write_text(src[:i] + segs + src[j:])
    assert main(["run", str(big), "--out", str(tmp_path / "o"), "--no-plots"]) == 1
    err = _one_line(capsys, "run")
    assert len(err) < 1500 and ", ... and " in err
    assert err.count("] deg") == 20


def test_many_scene_problems_are_capped(tmp_path):
    from femcam.errors import SceneError
    from femcam.scene import MAX_PROBLEMS, load_scene
    src = STUDY_PATH.read_text()
    bad = tmp_path / "bad.toml"
    # 30 misspelt keys in [follower]
    bogus = "".join(f"bogus{k} = 1\n" for k in range(30))
    bad.write_text(src.replace("[follower]\n", "[follower]\n" + bogus))
    with pytest.raises(SceneError) as ei:
        load_scene(bad)
    lines = str(ei.value).splitlines()
    assert lines[0].endswith(": 30 problems")
    assert len(lines) == 1 + MAX_PROBLEMS + 1 and lines[-1].strip() == "... and 10 more"
    assert UndercutError  # the undercut message of the test above is an UndercutError


def _parsers():
    """Every (sub)parser of the femcam CLI, by its prog name."""
    import argparse

    from femcam.cli import build_parser
    todo, seen = [build_parser()], {}
    while todo:
        p = todo.pop()
        seen[p.prog] = p
        for a in p._actions:
            if isinstance(a, argparse._SubParsersAction):
                todo += list(a.choices.values())
    return seen


def test_help_is_plain_text_and_complete():
    import re
    parsers = _parsers()
    assert {"femcam wear map", "femcam wear seed000", "femcam synth", "femcam sweep"} <= set(parsers)
    for prog, p in parsers.items():
        text = p.format_help()
        assert "``" not in text and not re.search(r":[a-z]+:`", text), prog  # no RST markup
        if prog != "femcam":
            assert p.description, f"{prog} has no description"
        for a in p._actions:
            if a.help is not None and a.help != "==SUPPRESS==" and a.dest not in ("help", "command"):
                assert a.help.strip(), f"{prog} {a.option_strings or a.dest}"
            elif a.help is None and a.dest not in ("help", "command", "wear_command"):
                raise AssertionError(f"{prog}: {a.option_strings or a.dest} has no help text")


def test_synth_help_shows_defaults_and_law_names():
    text = _parsers()["femcam synth"].format_help()
    for s in ("default 180", "default 1e6", "default 1)", "default 50", "poly345", "bezier7"):
        assert s in " ".join(text.split()), s


DYNAMIC = STUDY_PATH.parent / "seed002_dynamic.toml"  # a one_dof train: dynamics has work to do


@pytest.mark.parametrize("cmd, argv, want", [
    ("dynamics", ["--rpm-sweep", "100:6000"], "--rpm-sweep = '100:6000': must be START:STOP:STEP"),
    ("wear", ["map", "--laws", "bezier5,bez7"],
     "--laws = 'bez7': unknown motion law (did you mean 'bezier7'?)"),
    ("sweep", ["--law", "bezeir9"], "--law = 'bezeir9': unknown motion law (did you mean 'bezier9'?)"),
])
def test_bad_flag_refused_before_any_work(cmd, argv, want, tmp_path, capsys):
    """A bad --rpm-sweep / --laws / --law is refused before anything is computed or written:
    the output directory is not even created; the message names the flag and a did-you-mean."""
    out = tmp_path / "o"
    head, tail = ([argv[0]], argv[1:]) if cmd == "wear" else ([], argv)
    scene = DYNAMIC if cmd == "dynamics" else STUDY_PATH
    assert main([cmd, *head, str(scene), "--out", str(out), *tail]) == 1
    assert want in _one_line(capsys, cmd)
    assert not out.exists()


def test_run_law_did_you_mean(capsys):
    assert main(["run", SCENE, "--law", "bezeir9"]) == 1
    err = _one_line(capsys, "run")
    assert "--law = 'bezeir9': unknown motion law (did you mean 'bezier9'?)" in err
    assert "valid names: " in err and "bezier9" in err


def test_sweep_help_states_each_scene_default_once():
    """The defaults a scene can override are written once (``femcam.cli.sweep.SETTINGS``) and
    shown in --help; the expected values are typed from docs/sweep.md's settings table."""
    text = " ".join(_parsers()["femcam sweep"].format_help().split())
    for s in ("(default: [sweep] angles_deg, else 0:360:1)", "(default: [fe] a_over_h, else 10)",
              "(default: [fe] tolerance, else 0.002; >= 0.0001)", "(default: [sweep] chunk_size, else 30)",
              "(default: [sweep] vtk_every, else 10; 1 = every angle; 0 = none)",
              "(default: [sweep] method, else fe)", "(default: [sweep] plots, else yes)"):
        assert s in text, s


def test_subcommands_share_scene_out_and_law_flags():
    """SCENE.toml and --out (femcam.cli._common.add_scene_out) and --law read the same way in
    every subcommand that has them; --law lists the laws named alone (not bezier/polynomial)."""
    parsers = _parsers()
    for prog in ("femcam run", "femcam sweep", "femcam assess", "femcam dynamics", "femcam wear map"):
        p = parsers[prog]
        args = p.parse_args(["scene.toml", "--out", "d"])
        assert (args.scene, args.out) == ("scene.toml", "d"), prog
    assert parsers["femcam run"].parse_args(["scene.toml"]).out is None  # run picks its own DIR
    for prog in ("femcam run", "femcam sweep"):
        law = next(a for a in parsers[prog]._actions if "--law" in a.option_strings)
        assert "cycloidal" in law.help and "poly345" in law.help, prog
        assert "bezier," not in law.help and "polynomial" not in law.help, prog


@pytest.mark.parametrize("flag, value, expected", [
    # ranges typed from docs/sweep.md's settings table (a_over_h 2..400, tolerance 1e-4..0.5) and
    # from the meaning of the counts (at least 1 angle a chunk; 0 = no VTK)
    ("--a-over-h", "1", "--a-over-h = 1 (elements per contact half-width, a/h): must be in [2, 400]; "
                         "10 (default)"),
    ("--a-over-h", "inf", "--a-over-h = inf (elements per contact half-width, a/h): must be finite"),
    ("--tolerance", "1e-05", "--tolerance = 1e-05 (relative p0 reuse error): must be >= 0.0001: "),
    ("--tolerance", "0.9", "--tolerance = 0.9 (relative p0 reuse error): must be in [0.0001, 0.5]"),
    ("--chunk-size", "0", "--chunk-size = 0 angles: must be a whole number >= 1"),
    ("--vtk-every", "-1", "--vtk-every = -1 angles: must be a whole number >= 0; 0 = no VTK"),
])
def test_sweep_flag_ranges_name_the_flag(flag, value, expected, tmp_path, capsys):
    """The sweep flags are checked by the scene schema's one range check, in the flag's words
    (a scene key it mentions, a_over_h, appears as --a-over-h)."""
    assert main(["sweep", SCENE, "--out", str(tmp_path / "o"), flag, value]) == 1
    err = _one_line(capsys, "sweep")
    assert expected in err
    assert "a_over_h" not in err


@pytest.mark.slow  # over 1 s; the default suite keeps its budget (CI runs it in the slow pass)
def test_broken_pipe_ends_quietly():
    """``femcam wear seed000 --all-laws | head``: the reader closes the pipe before femcam
    writes; femcam ends with Python's EPIPE code 1 and writes nothing on stderr (reference: the
    Python documentation's SIGPIPE recipe)."""
    import os
    import subprocess
    import sys

    root = Path(__file__).resolve().parents[1]
    env = {**os.environ, "PYTHONPATH": str(root)}
    p = subprocess.Popen([sys.executable, "-m", "femcam", "wear", "seed000", "--all-laws"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, cwd=root)
    p.stdout.close()          # the reader is gone before the first line
    err = p.stderr.read().decode()
    assert p.wait(timeout=60) == 1
    assert err == ""


@pytest.mark.parametrize("argv, want", [
    (["wear", "map", SCENE, "--cycles", "-3"], "--cycles = -3 revolutions: must be in (0, 1e+12] "
     "(1e12 revolutions is 3,000 years at 600 rpm)"),
    (["synth", "--case", "seed003", "--elements", "0"],
     "--elements = 0 elements around the cam: must be a whole number in [3, 20000] "
     "(femcam.synthesis.options.MAX_ELEMENTS: time and memory)"),
    (["synth", "--case", "seed003", "--k", "-1"], "--k = -1 (penalty constant, dimensionless): must be "
     "in (0, 1e+14] (the studies span 1e2-1e10; beyond 1e14 the tangent is singular in double precision)"),
    (["synth", "--case", "seed003", "--mu", "0"],
     "--mu = 0 (stabilisation parameter, dimensionless): must be in (0, 1e+14] (the studies span "
     "1e2-1e10; beyond 1e14 the tangent is singular in double precision)"),
])
def test_bad_flag_is_named_before_any_output(argv, want, tmp_path, capsys):
    out = tmp_path / "o"
    assert main([*argv, "--out", str(out)]) == 1
    cap = capsys.readouterr()
    assert cap.out == ""                       # nothing printed before the refusal
    assert cap.err.strip() == f"femcam {argv[0]}: error: {want}"
    assert not out.exists()


@pytest.mark.parametrize("argv, hint", [
    (["sweep", SCENE, "--method", "hertz"],
     "pass --resume to continue the sweep in it, --overwrite to replace its results, "
     "or choose another --out"),
    (["wear", "map", SCENE, "--no-plots"], "pass --overwrite to replace its files, or choose another --out"),
    (["dynamics", str(STUDY_PATH.parent / "seed002_dynamic.toml"), "--no-plots"],
     "pass --overwrite to replace its files, or choose another --out"),
])
def test_non_empty_out_is_refused_in_flag_words(argv, hint, tmp_path, capsys):
    """The sweep's rule for a non-empty --out, worded with the CLI flags (no Python argument)."""
    (tmp_path / "old.csv").write_text("x")
    assert main([*argv, "--out", str(tmp_path)]) == 1
    err = _one_line(capsys, argv[0])
    assert err == f"femcam {argv[0]}: error: --out = '{tmp_path}': the directory is not empty; {hint}"
    assert "=True" not in err and (tmp_path / "old.csv").read_text() == "x"


def test_wear_map_row_is_the_scene_law_and_all_laws_help_matches_output(tmp_path, capsys):
    """The scene's law is ``bezier5`` (examples/seed002_study_model.toml, [program] law); the
    --all-laws help names exactly the laws the table prints (bezier/polynomial need control
    points, so neither appears in either)."""
    from femcam.cli import build_parser
    from femcam.kinematics import LAW_NAMES

    assert main(["wear", "map", SCENE, "--out", str(tmp_path / "o"), "--no-plots", "--step-deg", "10",
                 "--cycles", "1"]) == 0
    rows = [ln.split() for ln in capsys.readouterr().out.splitlines()]
    assert ["bezier5"] in [r[:1] for r in rows] and ["scene"] not in [r[:1] for r in rows]
    summ = (tmp_path / "o" / "wear_summary.csv").read_text().splitlines()
    assert summ[1].split(",")[0] == "bezier5"
    sub = build_parser()._subparsers._group_actions[0].choices["wear"]
    seed = sub._subparsers._group_actions[0].choices["seed000"]
    text = " ".join(seed.format_help().split())
    assert main(["wear", "seed000", "--all-laws"]) == 0
    table = capsys.readouterr().out
    named = [n for n in LAW_NAMES if n not in ("bezier", "polynomial")]
    assert f"({', '.join(named)})" in text      # the help's list: exactly the 10 named laws
    lines = table.splitlines()
    first = lines.index(next(ln for ln in lines if ln.startswith("Motion Type")))
    block = lines[first + 1:lines.index("", first)]
    assert len(block) == len(named) == 10        # the table: one row per named law
