"""Reading a scene file: the TOML, the top-level keys and tables (with a did-you-mean for a
misspelt table), ``[operating]``, and :func:`load_scene`, which runs every table group's check
and raises one :class:`~femcam.errors.SceneError` listing all problems.
"""

from __future__ import annotations

import difflib
from pathlib import Path

from .._files import read_regular
from ..errors import SceneError
from .bodies import _check_bodies
from .checker import _Checker
from .contact import _contact, _tribology
from .cross import cross_key_problems
from .dynamics import _dynamics
from .follower import _finite_length, _follower, arm_fold, arm_program, arm_self_locking
from .layers import _layers
from .materials import _materials
from .origin import freeze
from .program import _program
from .schema import _OPERATING, _TABLES, _TOP
from .state import Scene
from .study import _study
from .wear import _scene_wear, wear_settings

try:  # Python >= 3.11
    import tomllib
except ModuleNotFoundError:  # pragma: no cover - Python 3.10
    import tomli as tomllib


#: largest scene file read (bytes): the example scenes are 1-5 kB; a scene of 10,000 control
#: points is ~0.3 MB
MAX_SCENE_BYTES = 4_000_000


def load_scene(path) -> Scene:
    """Read a scene TOML file (units in key names) and convert it to SI.

    Parameters
    ----------
    path : str or Path
        The scene file.

    Returns
    -------
    Scene
        The case in SI units (m, rad, rad/s, N, Pa, kg).

    Raises
    ------
    SceneError
        Listing every problem (dotted key, value, expected unit) if the file is malformed.
    """
    path = Path(path)
    raw = _read_toml(path)
    ck = _Checker(str(path))
    top = _top_level(ck, raw)
    omega = _operating(ck, raw)
    program = _program(ck, raw)
    fo, follower = _follower(ck, raw)
    arm_fold(ck, program, follower)
    dyn, train, steps_per_rev = _dynamics(ck, raw, follower)
    mats = _materials(ck, raw)
    tribo = _tribology(ck, raw, mats)
    finite = _finite_length(ck, raw, fo, fo.get("type"))
    bodies = _check_bodies(ck, raw, fo, mats)
    layers = _layers(ck, raw)
    co = _contact(ck, raw)
    arm_self_locking(ck, program, follower, co.get("friction"))
    study = _study(ck, raw)
    wear = _scene_wear(ck, raw, mats)
    cross_key_problems(ck, raw)
    ck.raise_if_any()
    program = arm_program(program, follower)  # an arm's lifts (rad) -> roller-centre arc travel (m)

    return Scene(name=top["name"], description=top.get("description", ""), source=top.get("source", ""),
                 program=program, follower=follower, dynamics=dyn, omega=omega, cam=mats["cam"],
                 roller=mats["roller"], length=fo["face_width_mm"], mu=co.get("friction", 0.0),
                 plane=co.get("plane", "strain"), sliding=co.get("sliding"), study=study,
                 wear=wear_settings(wear), source_path=str(path), origin=freeze(raw), train=train,
                 tribology=tribo, finite_length=finite, bodies=bodies, layers=layers,
                 steps_per_rev=steps_per_rev, tip_radius=fo.get("tip_radius_mm"),
                 face_length=fo.get("face_length_mm"))


def _read_toml(path: Path) -> dict:
    """The parsed TOML of ``path``; a missing, binary, malformed or huge file, a directory, a
    FIFO or a device is a SceneError (only a regular file of at most MAX_SCENE_BYTES is read)."""
    data = read_regular(path, "scene file", MAX_SCENE_BYTES, SceneError)
    try:
        return tomllib.loads(data.decode("utf-8"))
    except UnicodeDecodeError as exc:  # a binary file, or text not saved as UTF-8
        raise SceneError(f"scene file {path}: not a UTF-8 text file (byte {exc.start}: "
                         f"{exc.object[exc.start:exc.start + 1]!r}); TOML must be UTF-8") from None
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(f"scene file {path}: not valid TOML: {exc}") from None


def _top_level(ck: _Checker, raw: dict) -> dict:
    """Unknown and missing tables; the top-level keys (name, description, source)."""
    for k, v in raw.items():  # a table that is not one of ours: "[contactt]"
        if k not in _TABLES and k not in _TOP and isinstance(v, dict):
            near = difflib.get_close_matches(k, _TABLES, n=1, cutoff=0.6)
            hint = (f"; did you mean [{near[0]}]?" if near
                    else f"; valid tables: {', '.join(f'[{n}]' for n in _TABLES)}")
            ck.add(k, f"unknown table [{k}]{hint}")
    top = ck.table({k: v for k, v in raw.items()
                    if k not in _TABLES and (k in _TOP or not isinstance(v, dict))}, "", _TOP)
    for t in ("operating", "program", "follower", "dynamics", "materials"):
        if t not in raw:
            ck.add(t, f"missing required table [{t}]")
    return top


def _operating(ck: _Checker, raw: dict):
    """The operating speed omega (rad/s), from exactly one of rpm and omega_rad_s."""
    op = ck.table(raw.get("operating", {}), "operating", _OPERATING)
    if "operating" in raw and isinstance(raw["operating"], dict):
        given = [k for k in ("rpm", "omega_rad_s") if k in raw["operating"]]
        if len(given) != 1:
            ck.add("operating", "give exactly one of rpm (rpm) or omega_rad_s (rad/s); "
                   f"got {given or 'none'}")
    return op.get("rpm", op.get("omega_rad_s"))

