"""Shared pytest configuration for femcam.

Rendering is headless: matplotlib uses Agg and pyvista renders off-screen.

The persistent model cache (:mod:`femcam.sweep.diskcache`) of every test, and of every
subprocess a test starts, is a fresh directory of this session (``FEMCAM_CACHE_DIR``, removed at
exit): the suite never reads or fills the user's cache, and no run starts warm from an earlier
one.

Session fixtures shared by the test files: the seed 002 study model scene (loaded once: its
dense undercut check and the sweep's family models, kept in the process's
:func:`femcam.sweep.default_cache`, then serve every file that sweeps it).
"""

import atexit
import os
import shutil
import tempfile
from pathlib import Path

import pytest

from femcam.scene import load_scene

ROOT = Path(__file__).resolve().parents[1]
STUDY_PATH = ROOT / "examples" / "seed002_study_model.toml"

_CACHE_DIR = tempfile.mkdtemp(prefix="femcam-test-cache-")
os.environ["FEMCAM_CACHE_DIR"] = _CACHE_DIR
atexit.register(shutil.rmtree, _CACHE_DIR, ignore_errors=True)

os.environ.setdefault("MPLBACKEND", "Agg")
os.environ.setdefault("PYVISTA_OFF_SCREEN", "true")


@pytest.fixture(scope="session")
def study_scene():
    """The seed 002 study model (examples/seed002_study_model.toml), loaded once per session."""
    return load_scene(STUDY_PATH)
