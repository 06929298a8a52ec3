"""Shared pytest configuration for femcam.

Rendering is headless: matplotlib uses Agg and pyvista renders off-screen.
"""

import os

os.environ.setdefault("MPLBACKEND", "Agg")
os.environ.setdefault("PYVISTA_OFF_SCREEN", "true")
