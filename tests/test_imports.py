"""The analytic chain must import without gmsh, pyvista or matplotlib (docs/architecture.md)."""

import subprocess
import sys

import pytest

ANALYTIC = ["femcam", "femcam.materials", "femcam.kinematics", "femcam.profile", "femcam.loads",
            "femcam.hertz", "femcam.scene", "femcam.wear"]
HEAVY = ["gmsh", "pyvista", "vtk", "matplotlib", "skfem", "dask"]


@pytest.mark.parametrize("module", ANALYTIC)
def test_analytic_module_imports_without_heavy_dependencies(module):
    code = (
        "import importlib, sys\n"
        f"importlib.import_module({module!r})\n"
        f"print(','.join(m for m in {HEAVY!r} if m in sys.modules))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "", f"{module} pulled in {out.stdout.strip()}"


#: what README command 1 (``femcam sweep``) must not load before it needs it: the scipy
#: submodules beyond linalg/sparse (scipy.optimize alone took 0.3-0.5 s when a scene module
#: imported it at the top) and the writers' and plots' libraries (loaded when they write)
SWEEP_LAZY = ["scipy.optimize", "scipy.signal", "scipy.special", "scipy.spatial", "scipy.fft",
              "scipy.integrate", "meshio", "matplotlib", "gmsh", "skfem", "pyvista"]


def test_sweep_command_imports_stay_lean():
    code = ("import sys\nimport femcam.cli.sweep\n"
            f"print(','.join(m for m in {SWEEP_LAZY!r} if m in sys.modules))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "", f"femcam.cli.sweep pulled in {out.stdout.strip()}"
