"""The physics content of a scene as a hash: what a result computed from the scene depends on.

A sweep records :func:`physics_hash` of the scene it swept (``provenance["scene_physics_sha256"]``
and, per part, ``provenance["scene_physics_parts"]``); the assessment of a scene refuses a sweep
folder whose hash differs (:func:`femcam.assess.sweep_table`). The hash is taken over the parsed
scene (SI values), not the file: comments, whitespace, key order, units written differently
(``E_GPa = 210`` or ``210.0``), the free text (``name``, ``description``, ``source``, material
names) and the study settings of ``[fe]`` and ``[sweep]`` (how finely or over which angles it is
computed, not what is computed) leave it unchanged; any physical value changes it.

:class:`SceneDigest` (built by :func:`scene_digest`) is what a check against a recorded result
needs of a scene: its name, file and per-part hashes, so that the check takes the record, not the
scene.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
from dataclasses import dataclass

import numpy as np

from .. import _validate

#: fields that do not change what is computed: free text, the file, the TOML as written (its
#: physics is in the typed fields), study settings
NOT_PHYSICS = {"Scene": ("name", "description", "source", "source_path", "origin", "study",
                          "overrides"),
               "Material": ("name",)}


def _canon(x):
    """A JSON-able, deterministic form of ``x`` (floats by ``repr``: exact)."""
    if dataclasses.is_dataclass(x) and not isinstance(x, type):
        skip = NOT_PHYSICS.get(type(x).__name__, ())
        return {"__type__": type(x).__name__,
                **{f.name: _canon(getattr(x, f.name)) for f in dataclasses.fields(x) if f.name not in skip}}
    if isinstance(x, dict):
        return {str(k): _canon(v) for k, v in x.items()}
    if isinstance(x, list | tuple):
        return [_canon(v) for v in x]
    if isinstance(x, np.ndarray):
        return [_canon(v) for v in x.tolist()]
    if isinstance(x, bool | str) or x is None:
        return x
    if isinstance(x, int | np.integer):
        return int(x)
    if isinstance(x, float | np.floating):
        return repr(float(x))
    name = getattr(x, "name", None)   # e.g. a MotionLaw: its name is what the scene chose
    if isinstance(name, str):
        return {"__type__": type(x).__name__, "name": name}
    return {"__type__": type(x).__name__, **{k: _canon(v) for k, v in sorted(vars(x).items())
                                             if not callable(v)}}


def _sha256(x) -> str:
    """Hex SHA-256 of the canonical JSON of ``x`` (keys sorted)."""
    return hashlib.sha256(json.dumps(x, sort_keys=True).encode()).hexdigest()


def physics_parts(scene) -> dict[str, str]:
    """SHA-256 of each physics field of ``scene`` (``program``, ``follower``, ``cam``, ...).

    Parameters
    ----------
    scene : femcam.scene.Scene
        A loaded scene.

    Returns
    -------
    dict[str, str]
        Field name -> hex digest of its canonical JSON form (the fields of
        :data:`NOT_PHYSICS` left out).
    """
    c = _canon(scene)
    return {k: _sha256(v) for k, v in c.items() if k != "__type__"}


def physics_hash(scene) -> str:
    """SHA-256 of the physics content of ``scene`` (module docstring).

    Parameters
    ----------
    scene : femcam.scene.Scene
        A loaded scene.

    Returns
    -------
    str
        Hex digest; equal for two scenes that differ only in comments, layout, free text or
        study settings.
    """
    return _sha256(physics_parts(scene))


def differing_parts(a: dict[str, str], b: dict[str, str]) -> list[str]:
    """The fields whose hashes differ between two :func:`physics_parts` records.

    Parameters
    ----------
    a, b : dict[str, str]
        Two records of :func:`physics_parts`.

    Returns
    -------
    list of str
        Field names, sorted (a field present in one record only counts as differing).

    >>> differing_parts({"program": "1", "follower": "2"}, {"program": "1", "follower": "3"})
    ['follower']
    """
    return sorted(k for k in set(a) | set(b) if a.get(k) != b.get(k))


@dataclass(frozen=True, kw_only=True)
class SceneDigest:
    """A scene's physics hashes with its name and file (built by :func:`scene_digest`).

    Parameters
    ----------
    name : str
        The scene's name.
    source_path : str
        The scene file ("" for a scene built in code).
    parts : dict[str, str]
        :func:`physics_parts` of the scene: field name -> hex digest.
    """

    name: str
    source_path: str
    parts: dict

    def __post_init__(self):
        _validate.instance("parts", self.parts, dict, "a dict of field name -> sha256 hex digest")

    @property
    def sha256(self) -> str:
        """:func:`physics_hash` of the scene (hex digest)."""
        return _sha256(self.parts)


def scene_digest(scene) -> SceneDigest:
    """The :class:`SceneDigest` of ``scene``.

    Parameters
    ----------
    scene : femcam.scene.Scene
        A loaded scene.

    Returns
    -------
    SceneDigest
        Its name, file and :func:`physics_parts`.
    """
    return SceneDigest(name=scene.name, source_path=scene.source_path or "", parts=physics_parts(scene))
