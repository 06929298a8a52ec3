"""The settings of a sweep and where each one came from: one copy for the API and the CLI.

``femcam.sweep(scene, SweepOptions(...))`` and ``femcam sweep SCENE`` resolve their settings
here, so that the two compute the same rows. Precedence, setting by setting: a value given (a
field of :class:`femcam.sweep.options.SweepOptions` that is not None, or a command-line flag)
wins; else the scene's ``[fe]`` / ``[sweep]`` key (:class:`femcam.scene.study.StudySettings`);
else femcam's default (:data:`SETTINGS`, the one place each default is written; ``femcam sweep
--help`` shows them).

``rtol`` (scene ``[fe] rtol_pct``, in percent) chooses the mesh, so it excludes ``a_over_h``:
both given is refused, and so are both scene keys; one given beats the scene's other key; the
scene's ``rtol_pct`` is for its FE runs and is dropped under method ``hertz``
(:func:`femcam.sweep.rtol.rtol_settings` then sets the reuse tolerance ``<= rtol / 2``).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from .. import _validate
from .options import rtol_quantities
from .rtol import rtol_settings

__all__ = ["SETTINGS", "SweepSettings", "resolve_settings"]

#: parameter -> (scene table, scene key, default in the scene key's unit); ``angles`` is given
#: in rad (an array) or as ``angles_deg`` ("start:stop:step", deg), ``rtol`` as a fraction
#: (the scene's ``rtol_pct`` in percent); ``rtol``'s default None: ``a_over_h`` decides
SETTINGS = {"angles": ("sweep", "angles_deg", "0:360:1"), "a_over_h": ("fe", "a_over_h", 10.0),
            "tolerance": ("fe", "tolerance", 2e-3), "chunk_size": ("sweep", "chunk_size", 30),
            "vtk_every": ("sweep", "vtk_every", 10), "method": ("sweep", "method", "fe"),
            "plots": ("sweep", "plots", True), "rtol": ("fe", "rtol_pct", None),
            "rtol_on": ("fe", "rtol_on", ("p0",))}

#: a field of :class:`femcam.scene.study.StudySettings` -> its parameter here (the same name
#: but the angles, given by the scene as their spec)
_FIELD = {"angles_deg": "angles"}
#: the unit of each parameter in messages
_UNITS = {"a_over_h": "(elements per contact half-width)", "rtol": "(relative p0 error)"}


@dataclass(frozen=True, kw_only=True)
class SweepSettings:
    """The resolved settings of one sweep and the source of each.

    Parameters
    ----------
    angles : ndarray, shape (n,)
        Cam angles [rad].
    angles_deg : str or None
        Their ``start:stop:step`` spec [deg] (None: the angles were given as an array).
    method : str
        ``"fe"``, ``"hertz"`` or ``"auto"``.
    a_over_h : float
        Elements per contact half-width [-] (with ``rtol``: the pilot's, then chosen by the
        sweep, :mod:`femcam.sweep.rtol`).
    tolerance : float
        Reuse tolerance [-] (at most ``rtol / 2`` with ``rtol``).
    rtol : float or None
        Requested relative p0 error [-].
    chunk_size, vtk_every : int
        Angles per chunk; a ``.vtu`` every k angles (with an output directory).
    plots : bool
        Write the PNG plots (with an output directory).
    rtol_on : tuple of str
        The quantities ``rtol`` bounds (:data:`femcam.sweep.options.RTOL_ON`).
    sources : dict
        Parameter -> ``"argument"`` (an option or flag), ``"scene"`` or ``"default"``.
    from_scene : tuple of str
        ``[table] key = value`` of each setting taken from the scene, in :data:`SETTINGS` order.
    """

    angles: np.ndarray
    angles_deg: str | None
    method: str
    a_over_h: float
    tolerance: float
    rtol: float | None
    chunk_size: int
    vtk_every: int
    plots: bool
    rtol_on: tuple = ("p0",)
    sources: dict = field(default_factory=dict)
    from_scene: tuple = ()

    def to_dict(self) -> dict:
        """The settings (JSON-able) and their sources, as recorded in the provenance.

        Returns
        -------
        dict
            ``{"values": {name: value}, "sources": {name: source}}``; angles as their spec
            [deg] or their count, ``rtol`` a fraction.
        """
        values = {"angles_deg": self.angles_deg if self.angles_deg is not None
                  else f"{self.angles.size} angles given", "method": self.method,
                  "a_over_h": self.a_over_h, "tolerance": self.tolerance, "rtol": self.rtol,
                  "chunk_size": self.chunk_size, "vtk_every": self.vtk_every, "plots": self.plots,
                  "rtol_on": list(self.rtol_on)}
        return {"values": values, "sources": dict(self.sources)}


def _shown(v) -> str:
    """A scene value as written in TOML."""
    if isinstance(v, bool):
        return str(v).lower()
    return f'"{v}"' if isinstance(v, str) else f"{v:g}"


def resolve_settings(scene, given: Mapping, names: Mapping | None = None) -> SweepSettings:
    """The settings of a sweep: given > scene ``[fe]``/``[sweep]`` > default (:data:`SETTINGS`).

    Parameters
    ----------
    scene : femcam.scene.Scene
        The scene (its ``study``: :class:`femcam.scene.study.StudySettings`).
    given : mapping
        Parameter -> value as given, None (or absent) where not given: the keys of
        :data:`SETTINGS` (``angles`` in rad, ``rtol`` a fraction) and ``angles_deg``
        (``"start:stop:step"`` in deg, the CLI's flag; used when ``angles`` is None).
    names : mapping, optional
        Parameter -> ``(name, factor, unit)`` for messages about given values (the CLI's flags,
        e.g. ``{"rtol": ("--rtol-pct", 100, "%")}``); default the parameter's own name.

    Returns
    -------
    SweepSettings

    Raises
    ------
    InputError
        ``rtol`` given with ``a_over_h``, both in the scene, ``rtol`` with method ``hertz``, an
        angle spec that is not ``start:stop:step``, or no angles.

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> from femcam.scene.study import StudySettings
    >>> scene = SimpleNamespace(study=StudySettings(a_over_h=20.0))
    >>> s = resolve_settings(scene, {"method": "hertz"})
    >>> s.a_over_h, s.method, s.sources["a_over_h"], s.sources["method"], s.sources["tolerance"]
    (20.0, 'hertz', 'scene', 'argument', 'default')
    """
    study = getattr(scene, "study", None)
    fixed = study.given() if study is not None else {}   # field -> value (SI, rtol a fraction)
    fixed = {_FIELD.get(p, p): v for p, v in fixed.items()}
    given = {k: v for k, v in given.items() if v is not None}
    if "angles_deg" in given and "angles" not in given:
        given["angles"] = str(given.pop("angles_deg"))
    given.pop("angles_deg", None)

    def name(p):
        return (names or {}).get(p, (p, 1, _UNITS.get(p, "")))

    _mesh_keys(fixed, given, name)
    values, sources, used = {}, {}, []
    for p, (table, key, default) in SETTINGS.items():
        if p in given:
            values[p], sources[p] = given[p], "argument"
        elif p in fixed:
            values[p], sources[p] = fixed[p], "scene"
            used.append(f"[{table}] {key} = {_shown(fixed[p] * 100 if p == 'rtol' else fixed[p])}")
        else:
            values[p], sources[p] = default, "default"
    if sources["rtol"] == "scene" and values["method"] == "hertz":   # the scene's rtol is for its FE runs
        values["rtol"], sources["rtol"] = None, "default"
        used.pop()
    spec = values["angles"] if isinstance(values["angles"], str) else None
    label = {"argument": name("angles_deg")[0], "scene": "[sweep] angles_deg"}.get(sources["angles"],
                                                                                  "angles_deg")
    angles = _angles(values["angles"], label)
    a_over_h = values["a_over_h"] if sources["a_over_h"] != "default" or values["rtol"] is None else None
    tolerance = values["tolerance"] if sources["tolerance"] != "default" else None
    a_over_h, tolerance, rtol = rtol_settings(a_over_h, values["rtol"], values["method"], tolerance)
    rtol_on = rtol_quantities(values["rtol_on"], {"argument": name("rtol_on")[0],
                                                  "scene": "[fe] rtol_on"}.get(sources["rtol_on"], "rtol_on"))
    return SweepSettings(rtol_on=rtol_on, angles=angles, angles_deg=spec, method=values["method"],
                         a_over_h=a_over_h, tolerance=tolerance,
                         rtol=rtol, chunk_size=values["chunk_size"], vtk_every=values["vtk_every"],
                         plots=bool(values["plots"]), sources=sources, from_scene=tuple(used))


def _mesh_keys(fe: dict, given: dict, name) -> None:
    """``rtol`` against ``a_over_h``: both given, or both in the scene, refused; one given drops
    the scene's other key from ``fe`` (the scene's settings, in place)."""
    if "rtol" in given and "a_over_h" in given:
        (nr, fr, ur), (na, fa, _) = name("rtol"), name("a_over_h")
        r = _validate.number("rtol", given["rtol"], _UNITS["rtol"]) * fr
        a = _validate.number("a_over_h", given["a_over_h"], _UNITS["a_over_h"]) * fa
        raise _validate.fail(nr, r, ur, f"cannot be given with {na} = {a:g}: {nr} chooses the mesh "
                             "(a_over_h); give one")
    if "rtol" in given or "a_over_h" in given:
        fe.pop("a_over_h" if "rtol" in given else "rtol", None)  # one given beats the other key
    if "rtol" in fe and "a_over_h" in fe:
        raise _validate.fail("[fe] rtol_pct", fe["rtol"] * 100, "%", "cannot be given with "
                             "[fe] a_over_h in the same scene: rtol_pct chooses the mesh; give one of "
                             "them (or override one: a_over_h / rtol, --a-over-h / --rtol-pct)")


def _angles(value, label: str) -> np.ndarray:
    """Cam angles [rad] from a ``start:stop:step`` spec [deg] or an array [rad]."""
    if isinstance(value, str):
        return _validate.angles_deg(label, value)
    angles = _validate.finite_array("angles", value, "rad").ravel()
    if angles.size == 0:
        raise _validate.fail("angles", "[]", "rad", "must contain at least one angle")
    return angles
