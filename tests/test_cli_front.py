"""The front door of the command line: ``femcam --version`` and ``femcam --help`` import none
of the heavy stack, and the subcommand list of ``--help`` matches the subcommands' own help."""

import subprocess
import sys

import pytest

from femcam.cli import SUBCOMMANDS, build_parser

HEAVY = ("gmsh", "skfem", "pyvista", "matplotlib", "scipy.sparse.linalg", "dask", "femcam.sweep")

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
