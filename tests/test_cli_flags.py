"""Command-line nonsense is refused with one line before any work: every numeric flag of every
subcommand (found by walking the argparse parser, so a flag added later is covered), empty
names, the one ``--out`` policy, and input files that are not regular files.

The reference is each flag's stated range (femcam.cli._flags.Range, shown in ``--help``) and
the one-line rule ``femcam <command>: error: <flag> = <value> <unit>: <why>``.
"""

import argparse
import os
from pathlib import Path

import pytest

from femcam.cli import build_parser, main
from femcam.cli._flags import NumberAction

EX = Path(__file__).resolve().parents[1] / "examples"
SCENE = str(EX / "seed002_study_model.toml")
DYN = str(EX / "seed002_dynamic.toml")

#: the smallest valid command of each subcommand path (the flag under test is appended)
BASE = {("run",): ["run", SCENE], ("sweep",): ["sweep", SCENE], ("wear", "map"): ["wear", "map", SCENE],
        ("synth",): ["synth", "--case", "seed003"], ("dynamics",): ["dynamics", DYN],
        ("assess",): ["assess", SCENE],
        ("optimise",): ["optimise", SCENE, "--vary", "base_radius_mm=15:40", "--no-fe"],
        ("study",): ["study", SCENE, "--vary", "follower.base_radius_mm=10,12", "--no-plots"]}


def _walk(parser, path=()):
    """(subcommand path, action) of every option of every (sub)parser."""
    for a in parser._actions:
        if isinstance(a, argparse._SubParsersAction):
            for name, sp in a.choices.items():
                yield from _walk(sp, (*path, name))
        elif a.option_strings:
            yield path, a


ACTIONS = list(_walk(build_parser()))
NUMERIC = [(p, a) for p, a in ACTIONS if isinstance(a, NumberAction)]
#: every subcommand path that writes an --out directory (the generated cases need its BASE command)
COMMANDS = sorted({p for p, a in ACTIONS if "--out" in a.option_strings})


def _base(path):
    """The BASE command of ``path``, or a failure naming what to add (not a KeyError)."""
    if path not in BASE:
        pytest.fail(f"femcam {' '.join(path)}: no smallest valid command in BASE (tests/test_cli_flags.py); "
                    "add one so its flags and --out policy are checked")
    return BASE[path]


def test_every_subcommand_has_a_base_command():
    """A new subcommand is covered by the generated cases without anyone remembering to."""
    missing = [" ".join(p) for p in COMMANDS if p not in BASE]
    assert not missing, f"subcommands without a smallest valid command in BASE: {missing}"
    missing = sorted({p[0] for p in COMMANDS} - set(SCENE_AT) - NO_SCENE)
    assert not missing, f"subcommands without an entry in SCENE_AT (or NO_SCENE): {missing}"


def _one_line(capsys, cmd):
    cap = capsys.readouterr()
    err = cap.err.strip()
    assert "Traceback" not in err
    assert len(err.splitlines()) == 1, err
    assert err.startswith(f"femcam {cmd}: error: "), err
    return err, cap.out


def test_every_numeric_flag_has_a_range():
    """No flag parses a number with a bare ``type=int/float`` (which takes nan, inf and 1e30);
    each one is a NumberAction with a stated range, shown in --help."""
    bare = [(p, a.option_strings[-1]) for p, a in ACTIONS if a.type in (int, float)]
    assert bare == [], f"numeric flags without a stated range (use femcam.cli._flags.add_number): {bare}"
    assert len(NUMERIC) >= 15      # the flags known today (run 2, sweep 5, wear 4, synth 5, dynamics 1)
    for p, a in NUMERIC:
        _base(p)
        assert a.help == argparse.SUPPRESS or "range " in a.help, (p, a.option_strings)


def _nonsense(a):
    values = ["nan", "inf", "-inf", "-1", "1e30", "abc", ""]
    if a.range.lo > 0 or a.range.lo_open:
        values.append("0")
    if a.range.whole:
        values.append("2.5")
    return values


CASES = [(p, a.option_strings[-1], v) for p, a in NUMERIC for v in _nonsense(a)]
PATHS = sorted(set(BASE) | set(COMMANDS))


@pytest.mark.parametrize("path, flag, value", CASES, ids=[f"{' '.join(p)} {f}={v}" for p, f, v in CASES])
def test_numeric_flag_nonsense_is_one_line(path, flag, value, tmp_path, capsys):
    out = tmp_path / "o"
    assert main([*_base(path), "--out", str(out), f"{flag}={value}"]) == 1
    err, stdout = _one_line(capsys, path[0])
    assert f"{flag} = " in err
    assert stdout == "" and not out.exists()       # refused before any work


@pytest.mark.parametrize("argv, want", [
    (["run", SCENE, "--law", ""], "--law = '': unknown motion law"),
    (["sweep", SCENE, "--law", ""], "--law = '': unknown motion law"),
    (["wear", "map", SCENE, "--laws", ""], "--laws = '': unknown motion law"),
    (["wear", "map", SCENE, "--cycles", "1e30"], "--cycles = 1e+30 revolutions: must be in (0, 1e+12]"),
    (["wear", "map", SCENE, "--step-deg", "1e-7"], "--step-deg = 1e-07 deg: must be in [0.01, 10]"),
    (["run", SCENE, "--print-every-deg", "1e-9"], "--print-every-deg = 1e-09 deg: must be in [0.001, 360]"),
    (["synth", "--case", "seed003", "--base-radius-mm", "1e9"],
     "--base-radius-mm = 1e+09 mm: must be in (0, 1000] or auto"),
    (["synth", "--case", "seed003", "--elements", "1e9"],
     "--elements = 1e+09 elements around the cam: must be a whole number in [3, 20000]"),
])
def test_issue_flag_cases(argv, want, tmp_path, capsys):
    """The CLI cases of issue 29, each one line naming the flag, value, unit and range."""
    assert main([*argv, "--out", str(tmp_path / "o")]) == 1
    err, _ = _one_line(capsys, argv[0])
    assert want in err


@pytest.mark.parametrize("path", PATHS)
def test_empty_out_is_refused(path, capsys):
    """``--out ""`` named the current directory (Path("") is ".")."""
    assert main([*_base(path), "--out", ""]) == 1
    err, _ = _one_line(capsys, path[0])
    assert "--out = '': must name a directory" in err


@pytest.mark.parametrize("path", PATHS)
def test_non_empty_out_needs_overwrite(path, tmp_path, capsys):
    """One --out policy: a non-empty directory is refused unless --overwrite (run, assess and
    synth overwrote it silently)."""
    (tmp_path / "keep.txt").write_text("x")
    assert main([*_base(path), "--out", str(tmp_path)]) == 1
    err, _ = _one_line(capsys, path[0])
    assert "the directory is not empty; pass" in err and "--overwrite" in err
    assert (tmp_path / "keep.txt").read_text() == "x"
    assert any(a.option_strings == ["--overwrite"] for p, a in ACTIONS if p == path)


def test_overwrite_replaces(tmp_path, capsys):
    (tmp_path / "keep.txt").write_text("x")
    assert main(["run", SCENE, "--out", str(tmp_path), "--angles-deg", "0:360:30", "--no-plots",
                 "--overwrite"]) == 0
    assert (tmp_path / "analytic.csv").is_file()


def _fifo(tmp_path):
    p = tmp_path / "scene.toml"
    os.mkfifo(p)
    return str(p)


def _huge(tmp_path):
    p = tmp_path / "huge.toml"
    with open(p, "wb") as fh:
        fh.truncate(5_000_000)   # sparse: above MAX_SCENE_BYTES (4 MB) without writing it
    return str(p)


SCENE_AT = {"run": lambda s: ["run", s], "sweep": lambda s: ["sweep", s],
            "wear": lambda s: ["wear", "map", s], "synth": lambda s: ["synth", s],
            "dynamics": lambda s: ["dynamics", s], "assess": lambda s: ["assess", s],
            "optimise": lambda s: ["optimise", s, "--vary", "base_radius_mm=15:40", "--no-fe"],
            "study": lambda s: ["study", s, "--vary", "follower.base_radius_mm=10,12", "--no-plots"]}
#: subcommands that read no scene file (none today)
NO_SCENE: set = set()


@pytest.mark.parametrize("cmd", list(SCENE_AT))
@pytest.mark.parametrize("kind, make, want", [
    ("fifo", _fifo, "is a FIFO (named pipe), not a regular file"),
    ("dev-zero", lambda t: "/dev/zero", "is a character device, not a regular file"),
    ("huge", _huge, "5,000,000 bytes, above the cap of 4,000,000 bytes"),
])
def test_scene_must_be_a_regular_file(cmd, kind, make, want, tmp_path, capsys):
    """A FIFO blocked for ever and /dev/zero gave a traceback; a huge file is not read."""
    path = make(tmp_path)
    assert main([*SCENE_AT[cmd](path), "--out", str(tmp_path / "o")]) == 1
    err, _ = _one_line(capsys, cmd)
    assert f"scene file {path}: {want}" in err


@pytest.mark.parametrize("kind", ["fifo", "garbage", "dev-null-link"])
def test_assess_sweep_folder_files(kind, tmp_path, capsys):
    """``assess --sweep DIR``: a FIFO sweep.npz is not opened, a corrupt one is one line."""
    d = tmp_path / "sw"
    d.mkdir()
    f = d / "sweep.npz"
    if kind == "fifo":
        os.mkfifo(f)
    elif kind == "garbage":
        f.write_bytes(b"not an npz\n")
    else:
        f.symlink_to("/dev/null")
    assert main(["assess", SCENE, "--out", str(tmp_path / "o"), "--sweep", str(d)]) == 1
    err, _ = _one_line(capsys, "assess")
    assert f"sweep folder = {d}" in err     # the library's reader (femcam.assess.sweep_table) says it


def test_resume_store_manifest_fifo_does_not_block(tmp_path):
    """A resume store whose manifest is a FIFO blocked for ever on read. It is not read (only
    regular files are): like an unreadable manifest it counts as none, the sweep starts fresh
    and writes a regular manifest in its place."""
    from femcam.sweep.store import MANIFEST

    chunks = tmp_path / "o" / "chunks"
    chunks.mkdir(parents=True)
    os.mkfifo(chunks / MANIFEST)
    assert main(["sweep", SCENE, "--out", str(tmp_path / "o"), "--method", "hertz", "--angles-deg",
                 "0:10:5", "--no-plots", "--resume"]) == 0
    assert (chunks / MANIFEST).is_file()
