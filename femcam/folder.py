"""What a results folder holds, and its plots redrawn from its saved data.

:func:`folder_info` recognises the folder by the file its command writes (``sweep.npz``:
``femcam sweep``; ``assessment.csv``: ``assess``; ``dynamics.csv`` / ``rpm_sweep.csv``:
``dynamics``; ``wear_summary.csv``: ``wear map``; ``study.csv``: ``study``; ``optimum.json``:
``optimise``; ``analytic.csv``: ``run``) and, for a sweep, reads it back with
:meth:`femcam.sweep.SweepResult.load`: scene, physics hash, angles, the worst values with their
angle and unit, refused parts. :func:`replot` redraws a sweep's plots from ``sweep.npz``.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .errors import InputError
from .sweep import SweepResult
from .viz.sweep import plot_sweep

#: the file each command writes, in the order they are recognised
MARKERS = (("sweep.npz", "sweep"), ("assessment.csv", "assess"), ("optimum.json", "optimise"),
           ("study.csv", "study"), ("wear_summary.csv", "wear map"), ("dynamics.csv", "dynamics"),
           ("rpm_sweep.csv", "dynamics"), ("analytic.csv", "run"))

#: the worst values a sweep's summary reports: (column, label, scale to the unit, unit)
WORST = (("Fc", "contact force", 1.0, "N"), ("p0_hertz", "p0 Hertz", 1e-6, "MPa"),
         ("p0_fe", "p0 FE", 1e-6, "MPa"), ("vm_max", "von Mises", 1e-6, "MPa"),
         ("tau1_max", "max shear", 1e-6, "MPa"), ("phi", "pressure angle", 180 / math.pi, "deg"))


@dataclass(frozen=True)
class FolderInfo:
    """What :func:`folder_info` found.

    Attributes
    ----------
    command : str
        The command that wrote the folder.
    files : list of (str, int)
        Relative path and size [bytes] of every file.
    scene, physics_hash : str
        Scene name and physics hash (a sweep; ``""`` otherwise).
    angles : tuple
        ``(count, first, last, step)`` [deg] (a sweep; empty otherwise).
    worst : list of (str, float, str, float)
        ``(label, value, unit, angle in deg)`` per quantity (a sweep).
    refused : list of str
        Parts of the scene the sweep refused.
    """

    command: str
    files: list
    scene: str = ""
    physics_hash: str = ""
    angles: tuple = ()
    worst: list = field(default_factory=list)
    refused: list = field(default_factory=list)

    def lines(self) -> list:
        """The information as text lines.

        Returns
        -------
        list of str
            Command, scene, angles, worst values (with unit and angle), refused parts, files.
        """
        out = [f"written by: femcam {self.command}"]
        if self.scene:
            out.append(f"scene: {self.scene} (physics sha256 {self.physics_hash[:12]})")
        if self.angles:
            n, a, b, step = self.angles
            out.append(f"angles: {n}, {a:g} to {b:g} deg" + (f", step {step:g} deg" if step else ""))
        for label, v, unit, ang in self.worst:
            out.append(f"worst {label}: {v:.4g} {unit} at {ang:g} deg")
        out += [f"refused: {r}" for r in self.refused]
        total = sum(s for _, s in self.files)
        out.append(f"files: {len(self.files)} ({total / 1e6:.3g} MB)")
        out += [f"  {name}  {size:,} B" for name, size in self.files if "/" not in name]
        dirs = sorted({name.split("/", 1)[0] for name, _ in self.files if "/" in name})
        for d in dirs:
            inside = [s for name, s in self.files if name.startswith(d + "/")]
            out.append(f"  {d}/  {len(inside)} files, {sum(inside):,} B")
        return out


def _files(d: Path) -> list:
    return [(p.relative_to(d).as_posix(), p.stat().st_size) for p in sorted(d.rglob("*")) if p.is_file()]


def folder_info(directory) -> FolderInfo:
    """What a femcam results folder holds.

    Parameters
    ----------
    directory : str or os.PathLike
        The folder (a command's ``--out``).

    Returns
    -------
    FolderInfo
        Command, files and, for a sweep, scene, angles, worst values and refused parts.

    Raises
    ------
    InputError
        ``directory`` is not a directory or holds none of the files of :data:`MARKERS`.
    """
    d = Path(directory)
    if not d.is_dir():
        raise InputError(f"DIR = {str(d)!r}: not a directory")
    command = next((c for f, c in MARKERS if (d / f).is_file()), None)
    if command is None:
        raise InputError(f"DIR = {str(d)!r}: not a femcam results folder (none of "
                         f"{', '.join(f for f, _ in MARKERS)})")
    if command != "sweep":
        return FolderInfo(command=command, files=_files(d))
    r = SweepResult.load(d)
    theta = np.degrees(r.theta)
    step = np.unique(np.round(np.diff(theta), 9))
    worst = []
    for col, label, scale, unit in WORST:
        if col not in r.table:
            continue
        v = np.where(r.ok, np.abs(np.asarray(r.table[col], float)), np.nan)
        if np.any(np.isfinite(v)):
            i = int(np.nanargmax(v))
            worst.append((label, float(v[i] * scale), unit, float(theta[i])))
    prov = r.provenance
    return FolderInfo(command="sweep", files=_files(d), scene=_scene_name(d, prov),
                      physics_hash=str(prov.get("scene_physics_sha256", "")),
                      angles=(int(theta.size), float(theta[0]), float(theta[-1]),
                              float(step[0]) if step.size == 1 else 0.0),
                      worst=worst, refused=[f"{k}: {v}" for k, v in r.refused])


def _scene_name(d: Path, prov: dict) -> str:
    """``name (file)``: the name in the folder's ``scene.toml`` and the scene file swept."""
    name = ""
    if (d / "scene.toml").is_file():
        m = re.search(r'^name\s*=\s*"([^"]*)"', (d / "scene.toml").read_text(encoding="utf-8"), re.M)
        name = m.group(1) if m else ""
    src = str(prov.get("scene", ""))
    return f"{name} ({src})" if name and src else name or src


def replot(directory) -> dict:
    """Redraw a sweep's plots into ``DIR/plots`` from ``DIR/sweep.npz`` (no solve).

    Plots are derived data: existing PNGs of the same names are replaced.

    Parameters
    ----------
    directory : str or os.PathLike
        A sweep's output folder.

    Returns
    -------
    dict
        Plot name -> path.

    Raises
    ------
    InputError
        Not a sweep's folder (another command's folder names its command).
    """
    info_command = folder_info(directory).command
    if info_command != "sweep":
        raise InputError(f"DIR = {str(directory)!r}: written by femcam {info_command}; only a "
                         "sweep's plots can be redrawn (rerun the command to redraw the others)")
    return plot_sweep(SweepResult.load(directory), Path(directory))
