"""The options of a sweep, and the scene adapter: the few contact parameters it needs.

:class:`SweepOptions` says what a sweep computes (None: the scene's ``[fe]``/``[sweep]`` value,
else femcam's default, :mod:`femcam.sweep.settings`), :class:`RunOptions` how it runs (output
directory, workers, cache, progress); :class:`ResolvedOptions` are the numerical options after
that resolution, as the pipeline reads them. The accepted methods and ranges are the scene's
(:data:`METHODS`, :data:`TOLERANCE_FLOOR` and :func:`femcam.scene.schema.study_problem`, one
copy used by the ``[fe]``/``[sweep]`` tables and by both option records).
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace
from pathlib import Path

import numpy as np

from .. import _validate
from ..errors import InputError
from ..materials import Material, effective_modulus
from ..scene.schema import METHODS, RTOL_ON, STUDY_UNITS, STUDY_WHOLE, TOLERANCE_FLOOR, study_problem

#: accepted ``rtol`` (relative p0 error): 0.02 % (the reuse tolerance floor 1e-4 is half of it)
#: to 10 %
RTOL_RANGE = (2e-4, 0.1)

__all__ = ["METHODS", "RTOL_ON", "RTOL_RANGE", "TOLERANCE_FLOOR", "ContactParams", "ResolvedOptions",
           "RunOptions", "SweepOptions", "contact_params", "rtol_quantities"]


def _study_value(key: str, value):
    """A study setting checked by :func:`study_problem` (``int`` for the whole-number ones)."""
    unit = STUDY_UNITS[key]
    x = _validate.number(key, value, unit)
    problem = study_problem(key, x)
    if problem:
        raise _validate.fail(key, value, unit, problem)
    return int(x) if key in STUDY_WHOLE else x


def _flag(name: str, value) -> bool:
    """A boolean option: True or False (numbers and strings refused)."""
    if not isinstance(value, (bool, np.bool_)):
        raise _validate.fail(name, value, "", "must be True or False")
    return bool(value)


@dataclass(frozen=True, kw_only=True, eq=False)
class SweepOptions:
    """What a sweep computes; each option left at None takes the scene's ``[fe]`` / ``[sweep]``
    value, else femcam's default (:mod:`femcam.sweep.settings`, the rule ``femcam sweep`` applies
    to its flags: the two compute the same rows).

    Parameters
    ----------
    angles : array_like or None
        Cam angles [rad], at least one, finite; default the scene's ``[sweep] angles_deg``, else
        0, 1, ..., 359 deg.
    method : str or None
        ``"fe"`` (FE contact solve), ``"hertz"`` (analytic only) or ``"auto"`` (the cheapest of
        Hertz, FE arc gap, FE exact gap within ``tolerance`` per angle, :data:`METHODS`);
        default ``[sweep] method``, else ``"fe"``.
    a_over_h : float or None
        Elements per contact half-width, ``h = a / a_over_h`` [-], in [2, 400]; default ``[fe]
        a_over_h``, else 10 (refused together with ``rtol``).
    tolerance : float or None
        Bound on the model-reuse error ``|p0(family model) / p0(fresh model) - 1|`` [-], in
        [1e-4, 0.5]; default ``[fe] tolerance``, else 2e-3 (with ``rtol``: ``<= rtol / 2``).
    rtol : float or None
        Bound on every FE row's estimated relative error [-] (a fraction, in :data:`RTOL_RANGE`):
        the sweep chooses ``a_over_h`` (:mod:`femcam.sweep.rtol`); default ``[fe] rtol_pct`` /
        100 (dropped when ``a_over_h`` is given or the method is ``"hertz"``), else none.
    rtol_on : str or sequence of str or None
        The quantities ``rtol`` bounds: stems of the ``err_est_*`` columns (:data:`RTOL_ON`, e.g.
        ``("p0", "tau1")`` or ``"p0,tau1"``); default ``[fe] rtol_on``, else ``("p0",)``.
    chunk_size : int or None
        Angles per chunk (unit of parallel work and of the on-disk store) [angles], >= 1;
        default ``[sweep] chunk_size``, else 30.
    vtk_every : int or None
        With an output directory, a ``.vtu`` every k-th angle and ``sweep.pvd`` [angles] (0:
        none); default ``[sweep] vtk_every``, else 10.
    plots : bool or None
        With an output directory, write the PNG plots; default ``[sweep] plots``, else True.
    animate : bool or None
        With an output directory and VTK output, also write ``animation.gif`` (von Mises over
        cam angle); default False.

    Raises
    ------
    InputError
        A given value of the wrong kind or out of range, naming the option, value and unit.
    """

    angles: np.ndarray | None = None
    method: str | None = None
    a_over_h: float | None = None
    tolerance: float | None = None
    rtol: float | None = None
    rtol_on: tuple | None = None
    chunk_size: int | None = None
    vtk_every: int | None = None
    plots: bool | None = None
    animate: bool | None = None

    def __post_init__(self):
        if self.angles is not None:
            th = _validate.finite_array("angles", self.angles, "rad").ravel()
            if th.size == 0:
                raise _validate.fail("angles", "[]", "rad", "must contain at least one angle")
            th.flags.writeable = False
            object.__setattr__(self, "angles", th)
        if self.method is not None:
            _validate.choice("method", self.method, METHODS)
        for key in STUDY_UNITS:
            if getattr(self, key) is not None:
                object.__setattr__(self, key, _study_value(key, getattr(self, key)))
        if self.rtol is not None:
            object.__setattr__(self, "rtol", _validate.in_range("rtol", self.rtol, *RTOL_RANGE,
                                                                "(relative p0 error)"))
        if self.rtol_on is not None:
            object.__setattr__(self, "rtol_on", rtol_quantities(self.rtol_on))
        for key in ("plots", "animate"):
            if getattr(self, key) is not None:
                object.__setattr__(self, key, _flag(key, getattr(self, key)))

    def given(self) -> dict:
        """The options given (not None), as :func:`femcam.sweep.settings.resolve_settings` reads
        them.

        Returns
        -------
        dict
            Option name -> value (the fields' units; ``animate`` left out: no scene key).
        """
        return {f.name: getattr(self, f.name) for f in fields(self)
                if f.name != "animate" and getattr(self, f.name) is not None}


@dataclass(frozen=True, kw_only=True, eq=False)
class RunOptions:
    """How a sweep runs: where it writes, with how many processes, what it reuses and reports.
    None of these changes a computed row.

    Parameters
    ----------
    out : str or Path or None
        Output directory; None keeps everything in memory. Locked while the sweep runs; a
        non-empty directory is refused unless ``resume`` or ``overwrite``.
    resume : bool
        Continue a killed sweep in ``out`` (finished chunks loaded, the rest computed; each
        chunk checked against the manifest's scene hash).
    overwrite : bool
        Allow a fresh sweep into a non-empty ``out`` (its earlier results are replaced).
    workers : int or str
        Local worker processes [processes] for the chunks, or ``"auto"`` (default): processes
        only when the expected saving is worth it (:func:`femcam.sweep.auto_workers`); ignored
        with ``scheduler`` / ``client``. 1: the whole sweep in this process and thread (no
        worker pool, and no background thread building the family phase's models ahead, which
        ``"auto"`` uses while a core is idle and N >= 2 always: docs/sweep.md "Parallel
        runs").
    scheduler : str or None
        Dask scheduler address (``tcp://host:8786``).
    client : dask.distributed.Client or None
        A Dask ``Client`` (or ``LocalCluster``) to run the chunks on.
    progress : bool or None
        Progress on stderr (None: only when stderr is a terminal).
    chunk_delay_s : float
        Seconds [s] to sleep after each chunk, >= 0 (a test aid: "kill after k chunks" becomes
        deterministic).
    model_cache : bool
        Load family models and fresh checks from the persistent model cache and store what is
        built (False: ``--no-cache``; :mod:`femcam.sweep.diskcache`).
    cache_dir : str or Path or None
        The model cache's directory (default :func:`femcam.sweep.diskcache.default_dir`).
    command : str or None
        The command line recorded in the provenance.
    scene_path : str or Path or None
        The scene file, recorded and hashed (default the path given to
        :func:`femcam.sweep`, if any).

    Raises
    ------
    InputError
        A bad worker count, a negative delay, a non-boolean flag, a path that is not one, or
        ``resume`` without ``out``.
    """

    out: str | Path | None = None
    resume: bool = False
    overwrite: bool = False
    workers: int | str = "auto"
    scheduler: str | None = None
    client: object = None
    progress: bool | None = None
    chunk_delay_s: float = 0.0
    model_cache: bool = True
    cache_dir: str | Path | None = None
    command: str | None = None
    scene_path: str | Path | None = None

    def __post_init__(self):
        for key in ("resume", "overwrite", "model_cache"):
            object.__setattr__(self, key, _flag(key, getattr(self, key)))
        if self.progress is not None:
            object.__setattr__(self, "progress", _flag("progress", self.progress))
        object.__setattr__(self, "workers", _validate.workers("workers", self.workers))
        object.__setattr__(self, "chunk_delay_s",
                           _validate.nonnegative("chunk_delay_s", self.chunk_delay_s, "s"))
        for key in ("out", "cache_dir", "scene_path"):
            value = getattr(self, key)
            if value is not None and not (isinstance(value, (str, Path)) and str(value).strip()):
                raise _validate.fail(key, value, "", "must be a path (str or Path)")
        if self.out is not None:
            object.__setattr__(self, "out", Path(self.out))
        if self.resume and self.out is None:
            raise _validate.fail("resume", True, "", "needs an output directory (out)")


@dataclass(frozen=True, kw_only=True)
class ResolvedOptions:
    """The numerical options of a sweep after resolution (recorded in the manifest and the
    provenance; what the pipeline, the families and the model cache read).

    Parameters
    ----------
    method : str
        ``"fe"`` (default: the FE answers every contact angle, arc or exact gap), ``"hertz"``
        (analytic only) or ``"auto"`` (the cheapest model within the tolerance: Hertz, FE arc
        gap, FE exact gap) (:data:`METHODS`).
    a_over_h : float
        FE element size in the contact zone, ``h = a / a_over_h`` (``--a-over-h``;
        dimensionless), in :data:`femcam.scene.STUDY_RANGES` ([2, 400]).
    tolerance : float
        Bound on the reuse error ``|p0(family model) / p0(fresh model) - 1|`` (``--tolerance``),
        verified with fresh models at each family's worst-covered angles; families are split
        until it holds (:mod:`femcam.sweep.verify`). Dimensionless, in
        [:data:`TOLERANCE_FLOOR`, 0.5] ([1e-4, 0.5]).
    chunk_size : int
        Angles per chunk (unit of work and of the on-disk store), a whole number >= 1.
    vtk_every : int
        Write a ``.vtu`` every k-th angle (0: none), a whole number >= 0.
    rtol : float or None
        Requested bound on the estimated relative p0 error of every FE row (a fraction, in
        [:data:`RTOL_RANGE`]; ``--rtol-pct`` and ``[fe] rtol_pct`` give it in percent); the
        sweep then chooses ``a_over_h`` (:mod:`femcam.sweep.rtol`). None: ``a_over_h`` as given.
    rtol_on : tuple of str
        The quantities whose estimate ``rtol`` bounds (``--rtol-on``, ``[fe] rtol_on``): stems of
        the ``err_est_*`` columns in :data:`RTOL_ON`; default ``("p0",)``.

    Raises
    ------
    InputError
        An unknown method or a value out of range, naming the option, value and unit.
    """

    method: str = "fe"
    a_over_h: float = 10.0
    tolerance: float = 2e-3
    chunk_size: int = 30
    vtk_every: int = 0
    rtol: float | None = None
    rtol_on: tuple = ("p0",)

    def __post_init__(self):
        _validate.choice("method", self.method, METHODS)
        for key in STUDY_UNITS:
            object.__setattr__(self, key, _study_value(key, getattr(self, key)))
        if self.rtol is not None:
            object.__setattr__(self, "rtol", _validate.in_range("rtol", self.rtol, *RTOL_RANGE,
                                                                "(relative p0 error)"))
        object.__setattr__(self, "rtol_on", rtol_quantities(self.rtol_on))

    def for_family(self, a_over_h) -> ResolvedOptions:
        """These options with one model family's own ``a_over_h`` (``rtol`` chooses it per
        family, :mod:`femcam.sweep.rtol`; :class:`femcam.sweep.verify.FamilyRecord.a_over_h`).

        Parameters
        ----------
        a_over_h : float or None
            The family's elements per reference half-width [-]; None or NaN: unchanged.

        Returns
        -------
        ResolvedOptions
            ``self`` or a copy with ``a_over_h`` replaced (the model cache keys on it).
        """
        if a_over_h is None or a_over_h != a_over_h or float(a_over_h) == self.a_over_h:
            return self
        return replace(self, a_over_h=float(a_over_h))

    def to_dict(self) -> dict:
        """The options as a JSON-able dict (manifest key and provenance).

        Returns
        -------
        dict
            ``{"method", "a_over_h", "tolerance", "chunk_size", "vtk_every"}`` -> value (the
            fields' units), and ``"rtol"`` when it is set.
        """
        out = {"method": self.method, "a_over_h": self.a_over_h, "tolerance": self.tolerance,
               "chunk_size": self.chunk_size, "vtk_every": self.vtk_every}
        if self.rtol is not None:
            out["rtol"] = self.rtol
        if self.rtol_on != ("p0",):
            out["rtol_on"] = list(self.rtol_on)
        return out


def rtol_quantities(value, name: str = "rtol_on") -> tuple:
    """The quantities an ``rtol`` controls, checked: a list (or a comma-separated string) of
    names of :data:`RTOL_ON`, without repeats.

    Parameters
    ----------
    value : str or sequence of str
        ``"p0,vm"`` or ``["p0", "vm"]``.
    name : str
        The key or flag in messages (``rtol_on``, ``--rtol-on``, ``[fe] rtol_on``).

    Returns
    -------
    tuple of str
        The names in the given order.

    Raises
    ------
    InputError
        An empty list or a name outside :data:`RTOL_ON`, naming the key, the value and the
        accepted names.

    >>> rtol_quantities("p0, tau1")
    ('p0', 'tau1')
    """
    items = value.split(",") if isinstance(value, str) else list(value)
    names = tuple(dict.fromkeys(str(q).strip() for q in items if str(q).strip()))
    bad = [q for q in names if q not in RTOL_ON]
    if bad or not names:
        raise InputError(f"{name} = {value!r} (quantities): "
                         + (f"unknown {', '.join(map(repr, bad))}; " if bad else "empty; ")
                         + f"accepted: {', '.join(RTOL_ON)} (the stems of the err_est_*_pct columns)")
    return names


@dataclass(frozen=True)
class ContactParams:
    """The contact parameters of a roller-follower scene.

    Parameters
    ----------
    Rr : float
        Roller radius (m).
    length : float
        Face width (m).
    cam, roller : Material
        Materials.
    mu : float
        Friction coefficient.
    plane : str
        ``"strain"`` or ``"stress"``.
    sliding : int
        +1: friction traction on the cam in +x (scene ``"+x"``), -1: ``"-x"``; the default
        direction when no per-angle traction is given (:mod:`femcam.sweep.realcam`).
    kind : str
        Follower type: ``"roller"``, ``"knife_edge"`` (``Rr`` is the tip radius, the cam the one
        cut for it) or ``"flat_faced"`` (``Rr`` = inf).
    face_length : float or None
        Flat face length (m, ``[follower] face_length_mm``).
    coat_body : {"cam", "roller"} or None
        The body whose coating band is in the contact FE (``[materials.<body>.coating]``);
        None: homogeneous bodies. ``cam`` and ``roller`` stay the substrates, so Hertz
        (``E_star``) is the homogeneous reference.
    coat_thickness : float
        Coating thickness (m; 0 without a coating).
    coat_E : float
        Coating Young's modulus (Pa; 0 without a coating).
    coat_nu : float
        Coating Poisson's ratio (-; 0 without a coating).
    """

    Rr: float
    length: float
    cam: Material
    roller: Material
    mu: float
    plane: str
    sliding: int = 1
    kind: str = "roller"
    face_length: float | None = None
    coat_body: str | None = None
    coat_thickness: float = 0.0
    coat_E: float = 0.0
    coat_nu: float = 0.0

    @property
    def coating(self) -> Material | None:
        """The coating's elastic constants (``coat_E`` Pa, ``coat_nu``), None when uncoated."""
        if self.coat_body is None:
            return None
        return Material(E=self.coat_E, nu=self.coat_nu, name="coating")

    @property
    def E_star(self) -> float:
        """Effective modulus (Pa) of the pair in ``plane``."""
        return effective_modulus(self.cam, self.roller, self.plane)


def contact_params(scene) -> ContactParams:
    """Follower radius, face width, materials, mu, plane and sliding direction of a scene.

    Parameters
    ----------
    scene : femcam.scene.Scene
        Roller, knife-edge (with ``[follower] tip_radius_mm``) or flat-faced follower.

    Returns
    -------
    ContactParams
        With the scene's coating (``[materials.<body>.coating]``: one coated body per scene,
        the loader's rule) in ``coat_*``: the contact FE that answers the headline carries it.

    Raises
    ------
    InputError
        A knife edge without a tip radius (a sharp tip has no contact width), naming the key.
    """
    kind = scene.follower.kind
    sliding = -1 if str(scene.sliding or "+x").strip() == "-x" else 1
    tip = scene.tip_radius if scene.follower.needs_tip else None
    if scene.follower.needs_tip and tip is None:
        raise InputError("follower.type = knife_edge: a sharp tip has no contact width, so the "
                         "contact stresses are undefined; add the tip radius to the scene: "
                         "[follower] tip_radius_mm = ... (mm)")
    R = scene.follower.contact_radius(tip)  # Rr, the tip radius or inf (flat face)
    coat = {}
    for b in scene.layers:
        if (c := b.coating) is not None:
            coat = dict(coat_body=str(b.body), coat_thickness=float(c.thickness),
                        coat_E=float(c.E), coat_nu=float(c.nu))
    return ContactParams(R, float(scene.length), scene.cam, scene.roller, float(scene.mu),
                         str(scene.plane), sliding, kind=kind,
                         face_length=getattr(scene, "face_length", None), **coat)
