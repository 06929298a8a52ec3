"""femcam: finite-element contact-stress analysis of cam-follower mechanisms.

The pipeline, in module order: materials -> kinematics -> profile -> loads -> hertz ->
mesh -> fe -> sweep -> wear -> io / viz / cli. SI units and radians throughout the library;
degrees, rpm, mm and MPa appear only at the edges (CLI, scene files, plot labels).

``import femcam`` needs numpy/scipy only: gmsh and pyvista are imported inside the functions
that use them.
"""

# first: on the command line, Ctrl-C / SIGTERM during the imports below is one line and exit
# 130 / 143, not a traceback (importing femcam._interrupt installs its handler when this process
# is the command line; stdlib only, and nothing for a program that imports femcam)
from . import _interrupt  # noqa: F401, I001

import importlib  # noqa: E402  (femcam.sweep on first use: __getattr__ below)

__version__ = "0.1.0"

from . import sweep
from .errors import (
    ConvergenceError,
    FemcamError,
    HertzValidityError,
    InputError,
    LiftOffError,
    PhysicsError,
    SceneError,
    UndercutError,
    WorkerLostError,
)
from .materials import STEEL, Material, effective_modulus

# ``femcam.sweep`` is the sweep function, not the package of the same name: the (light) package
# is imported above, so that importing it later cannot rebind the name, and the binding that
# import made is removed here; ``__getattr__`` below gives the function on first use. The
# package's modules are imported by name (``from femcam.sweep.table import COLUMNS``).
del sweep

__all__ = [
    "__version__",
    "ConvergenceError",
    "FemcamError",
    "HertzValidityError",
    "InputError",
    "LiftOffError",
    "PhysicsError",
    "SceneError",
    "UndercutError",
    "WorkerLostError",
    "Material",
    "STEEL",
    "effective_modulus",
    "RunOptions",
    "Scene",
    "SweepOptions",
    "SweepResult",
    "load_scene",
    "sweep",
]


#: the top-level names that load their package on first use: name -> module
_LAZY = {"sweep": "femcam.sweep.run", "SweepOptions": "femcam.sweep.options",
         "RunOptions": "femcam.sweep.options",
         "SweepResult": "femcam.sweep.result", "load_scene": "femcam.scene",
         "Scene": "femcam.scene"}


def __getattr__(name):
    """``sweep``, ``SweepOptions``, ``RunOptions``, ``SweepResult``, ``load_scene``, ``Scene`` on
    first use:
    ``import femcam`` and ``femcam --version`` stay free of scipy's solvers and the scene
    machinery (PEP 562)."""
    if name not in _LAZY:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(_LAZY[name]), name)
    globals()[name] = value
    return value
