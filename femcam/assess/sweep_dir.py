"""A finished sweep folder as the table of an assessment, checked to be a sweep of the same scene.

An assessment fed by a sweep (``femcam assess SCENE.toml --sweep DIR``,
``assess(contact_case(scene, theta), table=sweep_table(DIR, scene_digest(scene)))``) combines
the scene's tribology with the sweep's contact; a sweep of another scene (another roller, another
program) would mix two mechanisms in one report. :func:`sweep_table` therefore compares the
physics hashes of the scene (its :class:`~femcam.scene.digest.SceneDigest`, from
:func:`femcam.scene.digest.scene_digest`: comments, layout and free text do not count) with the
ones the sweep recorded, and refuses with one line naming both scenes. A folder whose
``sweep.npz`` cannot be read (partial, truncated, not a sweep) is refused with one line too.
"""

from __future__ import annotations

import json
import re
import zipfile
import zlib
from pathlib import Path

import numpy as np

from .. import _validate
from .._files import check_regular
from ..errors import FemcamError, InputError
from ..scene import load_scene
from ..scene.digest import SceneDigest, differing_parts, physics_parts

#: what reading a damaged ``sweep.npz`` raises (numpy, zipfile, zlib, json)
#: largest sweep.npz read (bytes): 360,000 angles of ~150 columns are ~0.4 GB
MAX_SWEEP_BYTES = 2_000_000_000
_READ_ERRORS = (OSError, ValueError, KeyError, EOFError, zipfile.BadZipFile, zlib.error)


def _read(directory: Path) -> tuple[dict, dict]:
    """``(arrays, provenance)`` of ``directory/sweep.npz``; one-line refusals."""
    f = directory / "sweep.npz"
    if not f.is_file():
        what = "" if directory.is_dir() else " (not a directory)"
        raise InputError(f"sweep folder = {directory}: no sweep.npz there{what} (run femcam sweep "
                         f"SCENE.toml --out {directory} first; an interrupted sweep finishes with --resume)")
    check_regular(f, f"sweep folder = {directory}:", MAX_SWEEP_BYTES)   # never a FIFO or a device
    try:
        with np.load(f, allow_pickle=False) as z:
            arrays = {k: np.asarray(z[k]) for k in z.files}
        prov = json.loads(str(arrays["provenance_json"]))
    except _READ_ERRORS as exc:
        reason = f"{type(exc).__name__}: {exc}".splitlines()[0]
        raise InputError(f"sweep folder = {directory}: sweep.npz cannot be read ({reason}): a corrupted or "
                         f"partial results folder; sweep again (femcam sweep SCENE.toml --out {directory} "
                         "--overwrite)") from None
    theta = arrays.get("theta")
    if theta is None or theta.ndim != 1 or not isinstance(prov, dict):
        raise InputError(f"sweep folder = {directory}: sweep.npz has no per-angle table (no 1-D theta "
                         "column): not a femcam sweep's results; sweep again")
    return arrays, prov


def _their_name(arrays: dict) -> str:
    """The swept scene's name from the stored ``repr`` (``"?"`` when absent)."""
    m = re.match(r"Scene\(name='([^']*)'", str(arrays.get("scene_repr", "")))
    return m.group(1) if m else "?"


def _their_parts(directory: Path, prov: dict) -> dict | None:
    """The physics parts the sweep recorded; for a sweep made before they were recorded, those
    of its copy ``DIR/scene.toml`` (None when neither exists or the copy does not load)."""
    parts = prov.get("scene_physics_parts")
    if isinstance(parts, dict):
        return parts
    copy = directory / "scene.toml"
    if not copy.is_file():
        return None
    try:
        return physics_parts(load_scene(copy))
    except FemcamError:
        return None


def sweep_table(directory, digest: SceneDigest) -> dict[str, np.ndarray]:
    """The per-angle columns of the finished sweep in ``directory`` (SI, the sweep's names:
    ``theta``, ``a_fe``, ``p0_fe``, ...), after checking that it is a sweep of the scene whose
    physics hashes are ``digest``.

    Parameters
    ----------
    directory : str or Path
        A finished sweep's output folder (``DIR/sweep.npz``).
    digest : femcam.scene.digest.SceneDigest
        The physics hashes, name and file of the scene to assess
        (:func:`femcam.scene.digest.scene_digest`).

    Returns
    -------
    dict[str, ndarray]
        Every column of one value per angle (shape (n,); numeric or text).

    Raises
    ------
    InputError
        Not a folder, no ``sweep.npz``, a ``sweep.npz`` that cannot be read (corrupted or
        partial), or a sweep of another scene: the physics hash it recorded differs from
        ``digest`` (the line names both scenes and the fields that differ, and how to fix it).
    """
    me = _validate.instance("digest", digest, SceneDigest, "a femcam.scene.digest.SceneDigest "
                            "(femcam.scene.digest.scene_digest(scene))")
    d = Path(directory)
    arrays, prov = _read(d)
    mine = me.parts
    theirs = _their_parts(d, prov)
    if theirs is None:
        raise InputError(f"sweep folder = {d}: it records no scene (no scene_physics_sha256, no scene.toml), "
                         f"so it cannot be checked against scene {me.name!r}; sweep this scene again")
    diff = differing_parts(mine, theirs)
    if diff:
        got = str(prov.get("scene_physics_sha256", ""))[:12] or "(from its scene.toml)"
        raise InputError(
            f"sweep folder = {d}: it was swept from scene {_their_name(arrays)!r} "
            f"({prov.get('scene', '?')}), not from scene {me.name!r} "
            f"({me.source_path or 'built in code'}): they differ in "
            f"{', '.join(diff)} (physics sha256 {got} vs {me.sha256[:12]}); sweep this scene "
            f"(femcam sweep {me.source_path or 'SCENE.toml'} --out NEW_DIR) or assess the folder's own "
            f"scene ({d / 'scene.toml'})")
    n = arrays["theta"].size
    _check_columns(d, arrays, n)
    return {k: v for k, v in arrays.items() if v.ndim == 1 and v.size == n}


#: per-angle columns an assessment reads: required (every sweep writes them, NaN where the FE did
#: not answer) and optional (a sweep written before femcam computed them)
REQUIRED_COLUMNS = ("a_fe", "p0_fe")
OPTIONAL_COLUMNS = ("tau1_max", "txz_range_max")


def _check_columns(d: Path, arrays: dict, n: int) -> None:
    """Refuse a damaged table: a required column missing, or a column the assessment reads that
    is not one number per angle (a table cut or edited by hand would otherwise be dropped and
    every row fall back to Hertz with no word)."""
    for k in REQUIRED_COLUMNS:
        if k not in arrays:
            raise InputError(f"sweep folder = {d}: sweep.npz has no column {k} (every femcam sweep "
                             "writes it): a damaged or edited results folder; sweep again "
                             f"(femcam sweep SCENE.toml --out {d} --overwrite)")
    for k in (*REQUIRED_COLUMNS, *OPTIONAL_COLUMNS):
        v = arrays.get(k)
        if v is None:
            continue
        if v.ndim != 1 or v.size != n or v.dtype.kind not in "fiu":
            raise InputError(f"sweep folder = {d}: sweep.npz column {k} has shape {v.shape} "
                             f"({v.dtype}), not one number per angle ({n} angles in theta): a damaged "
                             f"or edited results folder; sweep again (femcam sweep SCENE.toml --out {d} "
                             "--overwrite)")
