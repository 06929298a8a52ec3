"""``femcam wear seed000 --csv``: an empty path, a directory and an unwritable location are each
refused with one line naming the flag, before the table is computed (issue 29 review, item 7).
"""

from __future__ import annotations

import os

import pytest

from femcam.cli import main


def _one_line(capsys) -> str:
    cap = capsys.readouterr()
    lines = cap.err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in cap.err, cap.err
    assert "Seed 000 recomputed" not in cap.out          # refused before the work
    return lines[0]


def test_an_empty_csv_path_is_refused(capsys):
    assert main(["wear", "seed000", "--csv", ""]) == 1
    assert "--csv = '': must name a file (it is empty)" in _one_line(capsys)


def test_a_directory_is_refused_naming_the_flag(tmp_path, capsys):
    assert main(["wear", "seed000", "--csv", str(tmp_path)]) == 1
    line = _one_line(capsys)
    assert f"--csv = '{tmp_path}': is a directory" in line and ".tmp" not in line


@pytest.mark.skipif(os.name != "posix" or os.geteuid() == 0, reason="root writes anywhere")
def test_an_unwritable_directory_is_refused(tmp_path, capsys):
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    try:
        assert main(["wear", "seed000", "--csv", str(ro / "t.csv")]) == 1
        assert "--csv (its directory)" in _one_line(capsys)
    finally:
        ro.chmod(0o700)


def test_a_file_path_is_written(tmp_path, capsys):
    assert main(["wear", "seed000", "--csv", str(tmp_path / "t.csv")]) == 0
    assert (tmp_path / "t.csv").is_file()
