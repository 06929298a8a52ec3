"""Starting a scene: check one without running it, write a commented template, copy the
shipped example scenes.

* :func:`check_scene`: load and validate a scene file (every key, unit and stated range,
  :mod:`femcam.scene.ranges`) and the whole cam (undercut, pressure angle, radius of
  curvature, lift-off of the follower train); no FE.
* :func:`scene_template`: a scene file whose every key carries a comment with its unit, its
  range and the range's source, generated from :data:`femcam.scene.ranges.RANGES` and the
  schema (the comments cannot drift from what the loader accepts).
* :func:`example_scenes` / :func:`copy_examples`: the example scenes, package data of the
  installed wheel (``femcam/_examples``) or the repository's ``examples/`` in a source tree.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

import numpy as np

try:  # Python >= 3.11
    import tomllib
except ModuleNotFoundError:  # pragma: no cover - Python 3.10
    import tomli as tomllib

from . import _validate
from .io import atomic_write_text
from .kinematics import LAW_NAMES
from .scene import load_scene
from .scene import schema as _schema
from .scene.ranges import RANGES, group_of, span
from .sweep.settings import resolve_settings

#: the example the template is made from (a roller follower, every common table)
TEMPLATE_BASE = "seed002_study_model.toml"

#: the pressure-angle limit the summary compares with (``femcam run --phi-limit-deg`` default)
PHI_LIMIT_DEG = 30.0

#: cam angles of the check's analytic pass [deg] (the undercut and pressure-angle checks of the
#: scene use their own dense grids)
CHECK_STEP_DEG = 0.5


@dataclass(frozen=True)
class SceneCheck:
    """What :func:`check_scene` found (SI units, radians).

    Attributes
    ----------
    name, follower : str
        Scene name and follower type.
    n_segments : int
        Segments of the cam program.
    phi_max, phi_max_theta : float
        Largest pressure angle over the whole cam and its cam angle [rad].
    rho_min, rho_min_theta : float
        Smallest radius of curvature of the cam's pitch curve on the check grid and its angle
        [m] (negative: concave).
    undercut : list of (float, float)
        Undercut intervals [rad] (empty: none).
    liftoff : int or None
        Check angles where the follower leaves the cam (None: rigid model without dynamics).
    """

    name: str
    follower: str
    n_segments: int
    phi_max: float
    phi_max_theta: float
    rho_min: float
    rho_min_theta: float
    undercut: list
    liftoff: int | None

    @property
    def ok(self) -> bool:
        """No undercut and no lift-off."""
        return not self.undercut and not self.liftoff

    def lines(self) -> list:
        """The summary as text lines.

        Returns
        -------
        list of str
            Name, follower, segments, pressure angle, radius of curvature (deg, mm), undercut
            and lift-off.
        """
        deg = math.degrees
        out = [f"{self.name}: {self.follower} follower, {self.n_segments} segments",
               f"  max pressure angle {deg(self.phi_max):.2f} deg at {deg(self.phi_max_theta):.2f} deg "
               f"({'within' if deg(self.phi_max) <= PHI_LIMIT_DEG else 'EXCEEDS'} the usual limit of "
               f"{PHI_LIMIT_DEG:g} deg for a translating roller)",
               f"  min radius of curvature {self.rho_min * 1e3:.3f} mm at {deg(self.rho_min_theta):.2f} deg"]
        out.append("  undercut: " + (", ".join(f"{deg(a):.2f}-{deg(b):.2f} deg" for a, b in self.undercut)
                                     or "none"))
        if self.liftoff is not None:
            out.append(f"  lift-off: {self.liftoff} of {int(360 / CHECK_STEP_DEG)} check angles"
                       if self.liftoff else "  lift-off: none")
        return out


def check_scene(path) -> SceneCheck:
    """Load and validate a scene file and check the whole cam (no FE).

    Parameters
    ----------
    path : str or os.PathLike
        The scene file.

    Returns
    -------
    SceneCheck
        The summary; :attr:`SceneCheck.ok` is False on undercut or lift-off.

    Raises
    ------
    SceneError
        Every problem of the file (dotted key, value, unit, range).
    InputError
        ``[fe]``/``[sweep]`` settings the sweep refuses together (``rtol_pct`` with ``a_over_h``).
    """
    sc = load_scene(path)
    resolve_settings(sc, {})   # the [fe]/[sweep] settings as the sweep reads them (conflicts refused)
    theta = np.radians(np.arange(0.0, 360.0, CHECK_STEP_DEG))
    st = sc.analyse(theta, allow_undercut=True)
    phi, phi_theta = sc.max_pressure_angle
    rho = np.asarray(st.rho, float)
    i = int(np.nanargmin(np.abs(rho)))
    lift = None if sc.train is None and sc.dynamics is None else int(np.count_nonzero(st.liftoff))
    return SceneCheck(name=sc.name, follower=str(getattr(sc.follower, "kind", "?")),
                      n_segments=len(sc.program.segments), phi_max=phi, phi_max_theta=phi_theta,
                      rho_min=float(rho[i]), rho_min_theta=float(theta[i]),
                      undercut=[(float(a), float(b)) for a, b in sc.undercut_check()], liftoff=lift)


def examples_dir() -> Path:
    """The directory of the shipped example scenes.

    Returns
    -------
    pathlib.Path
        ``femcam/_examples`` of an installed wheel, else the repository's ``examples/``.
    """
    packaged = resources.files("femcam") / "_examples"
    if packaged.is_dir():
        return Path(str(packaged))
    return Path(__file__).resolve().parents[1] / "examples"


def example_scenes() -> dict:
    """``{file name: description}`` of every example scene.

    Returns
    -------
    dict
        Sorted by file name; the description is the scene's ``description`` key (first line).
    """
    out = {}
    for f in sorted(examples_dir().glob("*.toml")):
        desc = tomllib.loads(f.read_text(encoding="utf-8")).get("description", "")
        out[f.name] = " ".join(desc.split())
    return out


def copy_examples(dest, *, overwrite: bool = False) -> list:
    """Copy the example scenes into ``dest``.

    Parameters
    ----------
    dest : str or os.PathLike
        Directory (created; must be empty unless ``overwrite``).
    overwrite : bool
        Write into a non-empty directory, replacing files of the same names.

    Returns
    -------
    list of pathlib.Path
        The files written.

    Raises
    ------
    InputError
        ``dest`` is not empty (without ``overwrite``) or is a file.
    """
    dest = Path(dest)
    if dest.exists() and not dest.is_dir():
        raise _validate.fail("DIR", str(dest), "", "is an existing file, not a directory")
    if dest.is_dir() and any(dest.iterdir()) and not overwrite:
        raise _validate.fail("DIR", str(dest), "", "the directory is not empty; pass --overwrite "
                             "to replace its files, or choose another DIR")
    dest.mkdir(parents=True, exist_ok=True)
    written = []
    for f in sorted(examples_dir().glob("*.toml")):
        atomic_write_text(dest / f.name, f.read_text(encoding="utf-8"))
        written.append(dest / f.name)
    return written


#: the template's own top-level values (the example's are replaced)
_TOP_VALUES = {"name": '"my_cam"', "description": '"a roller follower on a rise-dwell-fall-dwell cam"',
               "source": '"femcam init template"'}

_KEY = re.compile(r"^(\s*)([A-Za-z0-9_]+)(\s*=\s*)(.*)$")
_HEADER = re.compile(r"^\s*\[\[?\s*([A-Za-z0-9_.]+)\s*\]\]?")


def _schema_of(table: str) -> dict:
    """``{key: (unit, factor, check, required)}`` of a table of the scene schema."""
    tables = {"": _schema._TOP, "operating": _schema._OPERATING, "program": _schema._PROGRAM,
              "program.segment": _schema._SEGMENT, "follower": _schema._FOLLOWER,
              "contact": _schema._CONTACT, "dynamics": _schema._DYNAMICS}
    if table.startswith("materials."):
        return _schema._MATERIAL
    return tables.get(table, {})


def key_comment(table: str, key: str) -> str:
    """The template's comment of one key: unit, required or optional, stated range and source.

    Parameters
    ----------
    table : str
        Dotted table (``""`` for the top level, ``"program.segment"``, ``"materials.cam"``).
    key : str
        The key.

    Returns
    -------
    str
        e.g. ``"mm, required; range (0, 1000] (handbook: ...)"``; ``""`` for an unknown key.
    """
    spec = _schema_of(table).get(key)
    if spec is None:
        return ""
    unit, _, check, required = spec
    parts = [unit] if unit else []
    parts.append("required" if required else "optional")
    text = ", ".join(parts)
    if key in _schema._CHOICES and check == "str":
        text += "; one of " + ", ".join(_schema._CHOICES[key])
    if key == "law":
        text += "; a motion law: " + ", ".join(LAW_NAMES) + " (or control_points, a Bezier law)"
    r = RANGES.get(group_of(table), {}).get(key)
    if r is not None:
        text += f"; range {span(r, check)} ({r.source})"
    return text


def scene_template() -> str:
    """A scene file whose every key carries its unit, range and source as a comment.

    Made from the example :data:`TEMPLATE_BASE` (its values; its own comments replaced by
    the generated ones), so the template loads with :func:`femcam.scene.load_scene`.

    Returns
    -------
    str
        The TOML text.
    """
    base = (examples_dir() / TEMPLATE_BASE).read_text(encoding="utf-8")
    out = ["# femcam scene template: every value is in the unit written in its key name",
           "# (mm, deg, rpm, GPa, N/m, ...); femcam converts to SI. Each comment gives the unit,",
           "# whether the key is required, its accepted range and where the range comes from.",
           "# Check the file with `femcam check SCENE.toml`; see docs/scene.md for every key.", ""]
    table, in_string = "", False
    for line in base.splitlines():
        if in_string:  # inside the example's multi-line description: dropped
            in_string = '"""' not in line
            continue
        if line.lstrip().startswith("#"):
            continue  # the example's own comments: replaced by the generated ones
        h = _HEADER.match(line)
        if h:
            table = h.group(1)
            out.append(line.split("#", 1)[0].rstrip())
            continue
        m = _KEY.match(line)
        if not m:
            out.append(line)
            continue
        value = m.group(4)
        if value.startswith('"""'):  # the example's description: the template's own instead
            in_string = value.count('"""') == 1
            out.append(f'description = {_TOP_VALUES["description"]}  # optional')
            continue
        comment = key_comment(table, m.group(2))
        value = _TOP_VALUES.get(m.group(2), value) if not table else value
        value = _strip_comment(value)
        new = f"{m.group(1)}{m.group(2)}{m.group(3)}{value}"
        out.append(f"{new:<40}# {comment}" if comment else new)
    return "\n".join(out) + "\n"


def _strip_comment(value: str) -> str:
    """A TOML value without its trailing ``# comment`` (a ``#`` inside a string stays)."""
    quote = ""
    for i, ch in enumerate(value):
        if quote:
            quote = "" if ch == quote else quote
        elif ch in "\"'":
            quote = ch
        elif ch == "#":
            return value[:i].rstrip()
    return value.rstrip()
