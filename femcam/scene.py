"""Scene files: one TOML file describes a whole cam-follower case, with units in the key names.

``load_scene(path) -> Scene`` reads the file, checks every key and converts to SI; a bad file
raises one :class:`~femcam.errors.SceneError` that lists each problem with its dotted key
(``program.segment[1].beta_deg``), the value found and the expected unit. ``Scene.analyse``
runs the analytic chain (kinematics -> profile -> loads) at given cam angles.

Schema (all keys; ``?`` = optional; see ``docs/profile.md`` for the full table)::

    name, description?, source?
    [operating]        rpm | omega_rad_s
    [program]          law?  (default law of rise/fall segments), control_points?
    [[program.segment]] kind = "rise"|"dwell"|"fall", beta_deg, lift_mm (rise/fall),
                        law? | control_points?
    [follower]         type = "roller"|"knife_edge"|"flat_faced", base_radius_mm,
                       roller_radius_mm (roller), offset_mm?, face_width_mm
    [dynamics]         mass_kg, spring_N_per_m, preload_N, damping_N_s_per_m | damping_ratio
    [materials.cam], [materials.roller] (alias [materials.follower]):
                       E_GPa, nu, hardness_MPa?, name?
    [contact]?         friction?, plane? = "strain"|"stress", sliding? = "+x"|"-x"
    [fe]?, [wear]?     passed through unchanged (dicts) to the FE/sweep and wear layers

Only numpy/scipy and the standard library (``tomllib``) are imported.
"""

from __future__ import annotations

import dataclasses
import difflib
import math
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import numpy as np

from .errors import InputError, SceneError, UndercutError
from .kinematics import CamProgram, dwell, fall, law, rise
from .loads import FollowerDynamics, LoadResult, contact_force
from .materials import Material
from .profile import CamProfile, bool_intervals, cam_profile, make_follower

try:  # Python >= 3.11
    import tomllib
except ModuleNotFoundError:  # pragma: no cover - Python 3.10
    import tomli as tomllib


# --------------------------------------------------------------------------------------------
# schema: key -> (unit shown to the user, SI factor, check, required)
# check: "pos" > 0, "nonneg" >= 0, "num" any finite, "nu" in (-1, 0.5), "str", "list"
# --------------------------------------------------------------------------------------------
#: angles of the dense undercut check of Scene.analyse over one revolution (0.05 deg apart)
UNDERCUT_CHECK_N = 7200


def _dense_theta() -> np.ndarray:
    """The ``UNDERCUT_CHECK_N`` angles (rad) of the dense undercut check."""
    return np.linspace(0.0, 2.0 * math.pi, UNDERCUT_CHECK_N, endpoint=False)


_TOP = {"name": ("", None, "str", True), "description": ("", None, "str", False),
        "source": ("", None, "str", False)}
_TABLES = ("operating", "program", "follower", "dynamics", "materials", "contact", "fe", "wear")
_OPERATING = {"rpm": ("rpm", 2.0 * math.pi / 60.0, "pos", False),
              "omega_rad_s": ("rad/s", 1.0, "pos", False)}
_PROGRAM = {"law": ("", None, "str", False), "control_points": ("", None, "list", False),
            "segment": ("", None, "seglist", True)}
_SEGMENT = {"kind": ("", None, "str", True), "beta_deg": ("deg", math.pi / 180.0, "pos", True),
            "lift_mm": ("mm", 1e-3, "pos", False), "law": ("", None, "str", False),
            "control_points": ("", None, "list", False)}
_FOLLOWER = {"type": ("", None, "str", True), "base_radius_mm": ("mm", 1e-3, "pos", True),
             "roller_radius_mm": ("mm", 1e-3, "pos", False), "offset_mm": ("mm", 1e-3, "num", False),
             "face_width_mm": ("mm", 1e-3, "pos", True)}
_DYNAMICS = {"mass_kg": ("kg", 1.0, "nonneg", True), "spring_N_per_m": ("N/m", 1.0, "nonneg", True),
             "preload_N": ("N", 1.0, "nonneg", True),
             "damping_N_s_per_m": ("N s/m", 1.0, "nonneg", False),
             "damping_ratio": ("(dimensionless)", 1.0, "nonneg", False)}
_MATERIAL = {"E_GPa": ("GPa", 1e9, "pos", True), "nu": ("(dimensionless)", 1.0, "nu", True),
             "hardness_MPa": ("MPa", 1e6, "pos", False), "name": ("", None, "str", False)}
_CONTACT = {"friction": ("(dimensionless)", 1.0, "nonneg", False), "plane": ("", None, "str", False),
            "sliding": ("", None, "str", False)}
_CHOICES = {"kind": ("rise", "dwell", "fall"), "type": ("roller", "knife_edge", "flat_faced"),
            "plane": ("strain", "stress"), "sliding": ("+x", "-x"),
            "hardness_law": ("exponential", "linear")}
# --- coated and case-hardened bodies (femcam.layers): [materials.<body>.coating|case] ---------
_COATING = {"thickness_um": ("um", 1e-6, "pos", True), "E_GPa": ("GPa", 1e9, "pos", True),
            "nu": ("(dimensionless)", 1.0, "nu", True), "name": ("", None, "str", False),
            "interface_shear_strength_MPa": ("MPa", 1e6, "pos", False),
            "hardness_MPa": ("MPa", 1e6, "pos", False)}
_CASE = {"depth_mm": ("mm", 1e-3, "pos", True), "hardness_law": ("", None, "str", False),
         "surface_hardness_HV": ("HV", 9.80665e6, "pos", False),
         "core_hardness_HV": ("HV", 9.80665e6, "pos", False),
         "surface_yield_MPa": ("MPa", 1e6, "pos", False), "core_yield_MPa": ("MPa", 1e6, "pos", False)}


def _layers(ck, raw: dict) -> dict:
    """``{body: {"coating": {...}, "case": {...}}}`` (SI, checked) from [materials.<body>.*]."""
    out = {}
    mraw = raw.get("materials", {}) if isinstance(raw.get("materials", {}), dict) else {}
    for alias, tabs in mraw.items():
        body = "roller" if alias == "follower" else alias
        for t, spec in (("coating", _COATING), ("case", _CASE)):
            if isinstance(tabs, dict) and t in tabs:
                out.setdefault(body, {})[t] = ck.table(tabs[t], f"materials.{alias}.{t}", spec)
        case = out.get(body, {}).get("case", {})
        pairs = [("surface_hardness_HV", "core_hardness_HV"), ("surface_yield_MPa", "core_yield_MPa")]
        given = [p for p in pairs if any(k in case for k in p)]
        if case and (len(given) != 1 or not all(k in case for k in given[0])):
            ck.add(f"materials.{alias}.case", "give surface_hardness_HV and core_hardness_HV, or "
                   "surface_yield_MPa and core_yield_MPa (one complete pair)")
    return out
# --- end of the layers block -------------------------------------------------------------------


def _fmt(v) -> str:
    return repr(v) if isinstance(v, str) else str(v).lower() if isinstance(v, bool) else f"{v}"


class _Checker:
    """Collects every problem of a scene file, then raises one SceneError."""

    def __init__(self, path: str):
        self.path = path
        self.problems: list[str] = []

    def add(self, key: str, msg: str) -> None:
        # "key = value unit: condition" (like femcam._validate), or "key: message"
        self.problems.append(f"{key} {msg}" if msg.startswith("= ") else f"{key}: {msg}")

    def table(self, raw, key: str, spec: dict, *, extra: tuple = ()) -> dict:
        """Check one table: types, ranges, unknown and missing keys. Returns SI values."""
        out = {}
        if not isinstance(raw, dict):
            self.add(key, f"= {_fmt(raw)}: must be a table [{key}]")
            return out
        for k, v in raw.items():
            dk = f"{key}.{k}" if key else k
            if k in extra:
                continue
            if k not in spec:
                self.add(dk, f"= {_fmt(v)}: unknown key{self._hint(k, spec)}")
                continue
            unit, factor, check, _ = spec[k]
            val = self.value(dk, k, v, unit, factor, check)
            if val is not None:
                out[k] = val
        for k, (unit, _, _, required) in spec.items():
            if required and k not in raw:
                u = f" (unit: {unit})" if unit else ""
                self.add(f"{key}.{k}" if key else k, f"missing required key{u}")
        return out

    @staticmethod
    def _hint(k: str, spec: dict) -> str:
        pref = [n for n in spec if n.startswith(k + "_")]
        near = pref or difflib.get_close_matches(k, list(spec), n=1, cutoff=0.6)
        if not near:
            return f"; valid keys: {', '.join(spec)}"
        unit = spec[near[0]][0]
        why = " (units go in the key name)" if pref else ""
        return f"; did you mean {near[0]!r}{' in ' + unit if unit else ''}?{why}"

    def value(self, dk, k, v, unit, factor, check):
        """One value checked by ``check`` and converted to SI with ``factor`` (None: a problem
        was added)."""
        if check == "str":
            if not isinstance(v, str):
                self.add(dk, f"= {_fmt(v)}: must be a string")
                return None
            if k in _CHOICES and v not in _CHOICES[k]:
                self.add(dk, f"= {v!r}: must be one of {', '.join(map(repr, _CHOICES[k]))}")
                return None
            return v
        if check == "list":
            ok = isinstance(v, list) and all(isinstance(x, int | float) and not isinstance(x, bool)
                                             for x in v)
            if not ok:
                self.add(dk, f"= {_fmt(v)}: must be a list of numbers")
                return None
            return [float(x) for x in v]
        if check == "seglist":
            return v  # handled by the caller
        return self._number(dk, v, unit, factor, check)

    def _number(self, dk, v, unit, factor, check):
        u = f" {unit}" if unit else ""
        if isinstance(v, bool) or not isinstance(v, int | float):
            self.add(dk, f"= {_fmt(v)}: must be a number in{u or ' (dimensionless)'}")
            return None
        x = float(v)
        bad = None
        if not math.isfinite(x):
            bad = "must be finite"
        elif check == "pos" and x <= 0:
            bad = "must be > 0"
        elif check == "nonneg" and x < 0:
            bad = "must be >= 0"
        elif check == "nu" and not (-1.0 < x < 0.5):
            bad = "Poisson's ratio must be in (-1, 0.5)"
        if bad:
            self.add(dk, f"= {_fmt(v)}{u}: {bad}")
            return None
        return x * factor

    def raise_if_any(self):
        if self.problems:
            n = len(self.problems)
            head = f"scene file {self.path}: {n} problem{'s' if n > 1 else ''}"
            raise SceneError(head + "\n  " + "\n  ".join(self.problems))


# --------------------------------------------------------------------------------------------
# scene
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class SceneState:
    """The analytic chain at cam angles ``theta`` (rad); SI units throughout."""

    theta: np.ndarray
    s: np.ndarray
    v: np.ndarray
    a: np.ndarray
    j: np.ndarray
    s1: np.ndarray
    s2: np.ndarray
    phi: np.ndarray
    rho: np.ndarray
    Fc: np.ndarray
    liftoff: np.ndarray
    contact_x: np.ndarray
    contact_y: np.ndarray
    profile: CamProfile
    loads: LoadResult
    undercut_intervals: list = field(default_factory=list)

    @property
    def undercut(self) -> np.ndarray:
        """Undercut flags at the analysed angles ``theta`` (see ``undercut_intervals`` for the
        whole revolution)."""
        return self.profile.undercut


@dataclass(frozen=True)
class Scene:
    """A cam-follower case in SI units (built by :func:`load_scene`).

    ``length`` is the axial contact length (face width / cam thickness, m); ``cam`` and
    ``roller`` are the cam and follower materials; ``fe`` and ``wear`` are the optional
    pass-through tables, ``raw`` the parsed TOML.
    """

    name: str
    program: CamProgram
    follower: object
    dynamics: FollowerDynamics
    omega: float
    cam: Material
    roller: Material
    length: float
    mu: float = 0.0
    plane: str = "strain"
    sliding: str | None = None
    description: str = ""
    source: str = ""
    fe: dict = field(default_factory=dict)
    wear: dict = field(default_factory=dict)
    #: coatings and cases per body (SI, checked; femcam.layers.scene_layers builds them)
    layers: dict = field(default_factory=dict)
    source_path: str = ""
    raw: dict = field(default_factory=dict, repr=False)

    @property
    def rpm(self) -> float:
        return self.omega * 60.0 / (2.0 * math.pi)

    @cached_property
    def _dense_undercut(self) -> tuple:
        """``(flags, message)`` of the dense undercut check on :func:`_dense_theta` (``message``:
        the :class:`~femcam.errors.UndercutError` text of :func:`~femcam.profile.cam_profile`,
        or None). Computed once per scene (the scene is immutable), not per :meth:`analyse`
        call (the sweep analyses chunk by chunk)."""
        dense = _dense_theta()
        dd = self.program.derivatives(dense)
        try:
            return cam_profile(self.follower, dense, dd.s, dd.s1, dd.s2).undercut, None
        except UndercutError as exc:
            flags = cam_profile(self.follower, dense, dd.s, dd.s1, dd.s2, allow_undercut=True).undercut
            return flags, str(exc)

    def undercut_check(self, theta=None, undercut=None) -> list:
        """Undercut intervals ``[(start, end), ...]`` (rad, in [0, 2 pi)) of the whole cam.

        The profile is checked on a dense grid of ``UNDERCUT_CHECK_N`` angles over one
        revolution (0.05 deg apart; computed once per scene) merged with ``theta`` (taken mod
        2 pi; ``undercut``, if given, are its already computed flags), so a narrow undercut band
        between coarse analysis angles is still found. Vectorised.
        """
        dense, flags = _dense_theta(), self._dense_undercut[0]
        if theta is None:
            return bool_intervals(dense, flags)
        extra = np.mod(np.ravel(np.asarray(theta, float)), 2.0 * math.pi)
        if undercut is None:
            de = self.program.derivatives(extra)
            undercut = cam_profile(self.follower, extra, de.s, de.s1, de.s2,
                                   allow_undercut=True).undercut
        undercut = np.ravel(np.asarray(undercut, bool))
        if undercut.size != extra.size:
            raise InputError(f"undercut has {undercut.size} flags: must have one per theta "
                             f"({extra.size} angles)")
        th = np.concatenate([dense, extra])
        order = np.argsort(th, kind="stable")
        return bool_intervals(th[order], np.concatenate([flags, undercut])[order])

    def analyse(self, theta, *, allow_undercut: bool = False) -> SceneState:
        """Kinematics, profile and contact force at cam angles ``theta`` (rad), vectorised.

        Undercut is a property of the whole cam, so besides ``theta`` the profile is checked on a
        dense grid over one revolution (:meth:`undercut_check`). Raises
        :class:`~femcam.errors.UndercutError` (with the angle ranges in degrees) for an
        undercut cam unless ``allow_undercut=True``; the intervals found are
        ``SceneState.undercut_intervals`` (rad, in [0, 2 pi)).
        """
        d = self.program.derivatives(theta)
        w = self.omega
        v, a, j = w * d.s1, w**2 * d.s2, w**3 * d.s3
        p = cam_profile(self.follower, d.theta, d.s, d.s1, d.s2, allow_undercut=allow_undercut)
        intervals = self.undercut_check(d.theta, p.undercut)
        if intervals and not allow_undercut:
            # cam_profile passed on theta, so the dense grid found it (and holds the message)
            raise UndercutError(f"{self._dense_undercut[1]} (found by the dense check on "
                                f"{UNDERCUT_CHECK_N} angles over one revolution; the analysed "
                                "angles miss it)")
        r = contact_force(self.dynamics, d.theta, d.s, v, a, p.phi)
        return SceneState(theta=np.asarray(d.theta, float), s=d.s, v=v, a=a, j=j, s1=d.s1, s2=d.s2,
                          phi=p.phi, rho=p.rho, Fc=r.Fc, liftoff=r.liftoff, contact_x=p.contact_x,
                          contact_y=p.contact_y, profile=p, loads=r, undercut_intervals=intervals)

    def with_law(self, name: str, **params) -> Scene:
        """The same scene with every rise/fall segment using motion law ``name``."""
        lw = law(name, **params)
        segs = [s if s.law is None else dataclasses.replace(s, law=lw) for s in self.program.segments]
        return dataclasses.replace(self, program=CamProgram(segs))


def _law_from(ck: _Checker, key: str, tab: dict, default):
    if "law" in tab and "control_points" in tab:
        ck.add(key, "give either law or control_points, not both")
        return None
    if "control_points" in tab:
        try:
            return law("bezier", control_points=tab["control_points"])
        except InputError as exc:
            ck.add(f"{key}.control_points", str(exc))
            return None
    if "law" in tab:
        try:
            return law(tab["law"])
        except InputError as exc:
            ck.add(f"{key}.law", str(exc))
            return None
    return default


def load_scene(path) -> Scene:
    """Read a scene TOML file (units in key names) and convert it to SI.

    Parameters
    ----------
    path : str or Path
        The scene file.

    Returns
    -------
    Scene

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
    dyn = _dynamics(ck, raw)
    mats = _materials(ck, raw)
    layers = _layers(ck, raw)
    # contact and pass-through tables
    co = ck.table(raw.get("contact", {}), "contact", _CONTACT)
    for t in ("fe", "wear"):
        if t in raw and not isinstance(raw[t], dict):
            ck.add(t, f"= {_fmt(raw[t])}: must be a table [{t}]")
    ck.raise_if_any()

    return Scene(name=top["name"], description=top.get("description", ""), source=top.get("source", ""),
                 program=program, follower=follower, dynamics=dyn, omega=omega, cam=mats["cam"],
                 roller=mats["roller"], length=fo["face_width_mm"], mu=co.get("friction", 0.0),
                 plane=co.get("plane", "strain"), sliding=co.get("sliding"), fe=dict(raw.get("fe", {})),
                 wear=dict(raw.get("wear", {})), layers=layers, source_path=str(path), raw=raw)


def _read_toml(path: Path) -> dict:
    try:
        with open(path, "rb") as fh:
            return tomllib.load(fh)
    except FileNotFoundError:
        raise SceneError(f"scene file {path}: not found") from None
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
        given = [k for k in _OPERATING if k in raw["operating"]]
        if len(given) != 1:
            ck.add("operating", "give exactly one of rpm (rpm) or omega_rad_s (rad/s); "
                   f"got {given or 'none'}")
    return op.get("rpm", op.get("omega_rad_s"))


def _program(ck: _Checker, raw: dict) -> CamProgram | None:
    """The cam program from [program] and its [[program.segment]] tables."""
    g = raw.get("program", {})
    prog_tab = ck.table(g, "program", _PROGRAM)
    default_law = _law_from(ck, "program", prog_tab, None)
    segments = []
    closure = []  # same betas and lifts, a placeholder law where the law is bad: closure check
    segs_raw = g.get("segment", []) if isinstance(g, dict) else []
    if "program" in raw and not (isinstance(segs_raw, list) and segs_raw):
        ck.add("program.segment", "must be an array of tables [[program.segment]] with at least one segment")
        segs_raw = []
    prog_law = isinstance(g, dict) and ("law" in g or "control_points" in g)
    for i, sr in enumerate(segs_raw):
        _segment(ck, f"program.segment[{i}]", sr, default_law, prog_law, segments, closure)
    program = None
    if closure and len(closure) == len(segs_raw):
        # closure (sum of beta = 360 deg, rises = falls) depends on betas and lifts only, so it is
        # reported even when other keys (a law, another table) have problems too
        try:
            program = CamProgram(closure)
        except InputError as exc:
            ck.add("program.segment", str(exc))
        else:
            program = CamProgram(segments) if len(segments) == len(segs_raw) else None
    return program


def _segment(ck: _Checker, key: str, sr, default_law, prog_law: bool, segments: list,
             closure: list) -> None:
    """One [[program.segment]]: appended to ``segments`` (if valid) and ``closure``."""
    sg = ck.table(sr, key, _SEGMENT)
    kind = sg.get("kind")
    if kind is None or "beta_deg" not in sg:
        return
    if kind == "dwell":
        for k in ("lift_mm", "law", "control_points"):
            if k in sg:
                ck.add(f"{key}.{k}", f"= {_fmt(sr[k])}: a dwell takes only kind and beta_deg")
        segments.append(dwell(sg["beta_deg"]))
        closure.append(segments[-1])
        return
    if "lift_mm" not in sg:
        if isinstance(sr, dict) and "lift_mm" not in sr:
            ck.add(f"{key}.lift_mm", f"missing required key for a {kind} (unit: mm)")
        return
    make = rise if kind == "rise" else fall
    lw = _law_from(ck, key, sg, default_law)
    closure.append(make(sg["beta_deg"], sg["lift_mm"], lw or "cycloidal"))
    if lw is None:
        if "law" not in sg and "control_points" not in sg and not prog_law:  # else reported
            ck.add(f"{key}.law", "missing: give law (e.g. 'cycloidal') or control_points, "
                   "here or in [program]")
        return
    segments.append(make(sg["beta_deg"], sg["lift_mm"], lw))


def _follower(ck: _Checker, raw: dict):
    """``(checked [follower] table in SI, follower or None)``."""
    g = raw.get("follower", {})
    fo = ck.table(g, "follower", _FOLLOWER)
    ftype = fo.get("type")
    follower = None
    if ftype == "roller" and "roller_radius_mm" not in g:
        ck.add("follower.roller_radius_mm", "missing required key for a roller follower (unit: mm)")
    elif ftype in ("knife_edge", "flat_faced") and "roller_radius_mm" in g:
        ck.add("follower.roller_radius_mm", f"= {_fmt(g['roller_radius_mm'])}: "
               f"a {ftype} follower has no roller")
    elif ftype and isinstance(g, dict) and set(g) <= set(fo) and "base_radius_mm" in fo:
        try:
            follower = make_follower(ftype, Rb=fo["base_radius_mm"], Rr=fo.get("roller_radius_mm", 0.0),
                                     e=fo.get("offset_mm", 0.0))
        except InputError:  # only the offset can fail here: |e| < prime radius
            Rr_m = fo.get("roller_radius_mm", 0.0) if ftype == "roller" else 0.0
            Rp_mm = (fo["base_radius_mm"] + Rr_m) * 1e3
            ck.add("follower.offset_mm", f"= {_fmt(g['offset_mm'])} mm: must satisfy "
                   f"|offset| < prime-circle radius {Rp_mm:g} mm")
    return fo, follower


def _dynamics(ck: _Checker, raw: dict) -> FollowerDynamics | None:
    """The follower dynamics from [dynamics] (exactly one of the two damping keys)."""
    g = raw.get("dynamics", {})
    dy = ck.table(g, "dynamics", _DYNAMICS)
    if not (isinstance(g, dict) and "dynamics" in raw):
        return None
    given = [k for k in ("damping_N_s_per_m", "damping_ratio") if k in g]
    if len(given) != 1:
        ck.add("dynamics", "give exactly one of damping_N_s_per_m (N s/m) or damping_ratio "
               f"(dimensionless); got {given or 'none'}")
        return None
    if not all(k in dy for k in ("mass_kg", "spring_N_per_m", "preload_N", given[0])):
        return None
    try:
        return FollowerDynamics(m=dy["mass_kg"], k=dy["spring_N_per_m"], Fpl=dy["preload_N"],
                                c=dy.get("damping_N_s_per_m"), zeta=dy.get("damping_ratio"))
    except InputError:  # only a damping ratio with c_c = 2 sqrt(k m) = 0 fails here
        ck.add("dynamics.damping_ratio",
               f"= {_fmt(g['damping_ratio'])} (dimensionless): the critical "
               f"damping c_c = 2 sqrt(k m) = 2 sqrt({dy['spring_N_per_m']:g} N/m * "
               f"{dy['mass_kg']:g} kg) = 0 N s/m, so a ratio cannot set the damping; give "
               "damping_N_s_per_m (N s/m) instead")
        return None


def _materials(ck: _Checker, raw: dict) -> dict:
    """``{"cam": Material, "roller": Material}`` from [materials.*] (roller alias follower)."""
    mats = {}
    mraw = raw.get("materials", {})
    if not isinstance(mraw, dict):
        if "materials" in raw:
            ck.add("materials", f"= {_fmt(mraw)}: must be a table")
        return mats
    for k in mraw:
        if k not in ("cam", "roller", "follower"):
            ck.add(f"materials.{k}", "unknown material table; use [materials.cam] and "
                   "[materials.roller] (or [materials.follower])")
    if "roller" in mraw and "follower" in mraw:
        ck.add("materials", "give [materials.roller] or its alias [materials.follower], not both")
    for k, alias in (("cam", "cam"), ("roller", "roller"), ("roller", "follower")):
        if alias in mraw:
            m = ck.table(mraw[alias], f"materials.{alias}", _MATERIAL, extra=("coating", "case"))
            if "E_GPa" in m and "nu" in m:
                mats[k] = Material(E=m["E_GPa"], nu=m["nu"], name=m.get("name", alias),
                                   hardness=m.get("hardness_MPa"))
    if "materials" in raw:
        for k in ("cam", "roller"):
            if k not in mraw and not (k == "roller" and "follower" in mraw):
                ck.add(f"materials.{k}", "missing required table (keys E_GPa, nu)")
    return mats
