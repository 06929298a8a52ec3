"""The FE models of a process: one per model family, their solved load cases, and the p0 of
the fresh check models (:class:`ModelCache`), plus how a model is built (:func:`build_model`).
"""

from __future__ import annotations

import math
import threading
import time
from collections import OrderedDict
from contextlib import ExitStack, contextmanager

from .. import _validate
from .._threads import Background
from ..errors import FemcamError
from ..fe import ContactModel, ContactResult, SolverOptions
from ..layers import Coating, build_coated_model
from ..materials import effective_modulus
from ..mesh import MeshOptions
from ..mesh.session import gmsh_kept
from .diskcache import DiskCache, content_key, finite_p0, restore_model, strip_model
from .options import ContactParams, ResolvedOptions

#: fresh checks: one load case, only its p0 read: no stress operators, and a stress window of
#: the surface nodes only (eval_depth 0; the contact solve does not use the window, so p0 is the
#: same bit for bit, and the build ~10 % cheaper)
_FRESH_SOLVER = SolverOptions(stress_operators="per_solve", eval_depth=0.0)


def _key(cp, rho_ref, a_ref, options):
    return (cp.Rr, cp.length, repr(cp.cam), repr(cp.roller), cp.plane, float(rho_ref),
            float(a_ref), options.a_over_h, cp.coat_body, cp.coat_thickness, cp.coat_E, cp.coat_nu)


class ModelCache:
    """The FE models of a process, their solved load cases and the fresh-model check results.

    Thread-safe: Dask runs tasks in worker threads of one process; every change of the tables
    holds one lock, the builds of :meth:`model_for` another (a key is built once), and gmsh
    (not thread-safe) is used under :data:`femcam.mesh.GMSH_LOCK`. Builds may run ahead in a
    background thread (:meth:`building_in_background`, :meth:`prefetch_model`,
    :meth:`prefetch_fresh`): the sweep's family phase uses both cores that way.

    Parameters
    ----------
    max_models : int
        Models kept (least recently used dropped first).
    disk : femcam.sweep.diskcache.DiskCache, optional
        The persistent cache consulted before a family model or a fresh check is built (and
        given what is built); None: none (:func:`femcam.sweep.sweep` attaches one per call).

    Attributes
    ----------
    stats : dict
        ``{"built": int, "build_time": float (s), "loaded": int, "checks_built": int,
        "checks_loaded": int}``: models built by this cache and loaded from ``disk``, fresh
        checks computed and loaded (diagnostics).
    """

    def __init__(self, max_models: int = 64, disk: DiskCache | None = None):
        self.max_models = _validate.integer("max_models", max_models, 1, "models")
        self.disk = disk
        self._models: OrderedDict = OrderedDict()
        #: ``id(model) -> {(F, rho, mu, sliding): ContactResult}`` (lives as long as its model)
        self._results: dict[int, dict] = {}
        #: p0 of fresh check models (a repeated sweep in one process does not rebuild them)
        self._fresh_p0: OrderedDict = OrderedDict()
        self.stats = {"built": 0, "build_time": 0.0, "loaded": 0, "checks_built": 0,
                      "checks_loaded": 0}
        self._lock = threading.RLock()
        self._build_lock = threading.RLock()
        #: builds started ahead (:meth:`building_in_background`; none outside it)
        self.background = Background(0)
        self._kept, self._kept_entered = None, False   # gmsh kept initialised meanwhile

    def model_for(self, cp: ContactParams, rho_ref: float, a_ref: float,
                  options: ResolvedOptions) -> ContactModel:
        """The FE model of a family (references ``rho_ref``, ``a_ref`` in m), cached or built now.

        Parameters
        ----------
        cp : ContactParams
            The scene's follower radius and face width (m), materials, plane (part of the key).
        rho_ref, a_ref : float
            Reference cam radius and half-width (m) the mesh is built for.
        options : ResolvedOptions
            ``a_over_h`` (elements per contact half-width) of the mesh.

        Returns
        -------
        femcam.fe.ContactModel
            The model of this key: the cached one (now the most recently used), or one built
            now by :func:`build_model` and counted in :attr:`stats`.
        """
        return self._get_or_build(_key(cp, rho_ref, a_ref, options),
                                  lambda: build_model(cp, rho_ref, a_ref, options), memo=True,
                                  disk_key=lambda: _disk_key("family_model", cp, rho_ref, a_ref, options))

    def _get_or_build(self, key: tuple, build, memo: bool = False, disk_key=None):
        """The model under ``key`` (LRU: most recently used last), else from :attr:`disk` under
        ``disk_key()`` (counted as loaded), else ``build()`` now or taken from the background
        build :meth:`prefetch_model` started (counted in :attr:`stats`, and stored); ``memo``:
        keep its solved load cases (:meth:`solve`). The tables' lock is not held while a model
        is built (a background build and the solves of the caller go on side by side); builds
        asked for here are serialised, so threads sharing the cache (Dask) build a key once."""
        with self._lock:
            m = self._lookup(key)
        if m is not None:
            return m
        with self._build_lock:
            with self._lock:
                m = self._lookup(key)
            if m is not None:
                return m
            m, dt = self.background.take(("model", key), lambda: self._load_or_build(build, disk_key))
        with self._lock:
            self.stats["loaded" if dt is None else "built"] += 1
            self.stats["build_time"] += dt or 0.0
            self._models[key] = m
            if memo:
                self._results[id(m)] = {}
            while len(self._models) > self.max_models:
                _, old = self._models.popitem(last=False)
                self._results.pop(id(old), None)
            return m

    def _lookup(self, key: tuple):
        """The model under ``key`` (now the most recently used) or None; hold :attr:`_lock`."""
        m = self._models.get(key)
        if m is not None:
            self._models.move_to_end(key)
        return m

    def _load_or_build(self, build, disk_key) -> tuple:
        """``(model, build time in s)`` built now and stored, or ``(model, None)`` loaded from
        :attr:`disk`."""
        dk = disk_key() if (disk_key is not None and self.disk is not None) else None
        m = self.disk.get(dk) if dk is not None else None
        if isinstance(m, ContactModel):
            return restore_model(m), None
        t0 = time.perf_counter()
        m = build()
        dt = time.perf_counter() - t0
        if dk is not None:  # pickled and hashed in the background when a thread is on
            disk = self.disk
            self.background.defer(lambda: disk.put(dk, strip_model(m)))
        return m, dt

    def prefetch_model(self, cp: ContactParams, rho_ref: float, a_ref: float,
                       options: ResolvedOptions) -> None:
        """Start building (or loading) the model :meth:`model_for` will be asked for, in the
        background thread of :meth:`building_in_background` (nothing outside it).

        Parameters
        ----------
        cp : ContactParams
            The contact parameters.
        rho_ref, a_ref : float
            Reference cam radius and half-width (m).
        options : ResolvedOptions
            ``a_over_h``.
        """
        key = _key(cp, rho_ref, a_ref, options)
        with self._lock:
            if key in self._models:
                return
        dk = _disk_key("family_model", cp, rho_ref, a_ref, options) if self.disk is not None else None
        self.submit_build(("model", key), lambda: self._load_or_build(
            lambda: build_model(cp, rho_ref, a_ref, options), lambda: dk), dk)

    def submit_build(self, key, job, disk_key: str | None = None) -> None:
        """Queue ``job`` (a build) in the background under ``key``, unless :attr:`disk` holds
        its entry ``disk_key`` (loading it where it is wanted costs milliseconds). gmsh is
        initialised for the background builds here, in the submitting (main) thread, on the
        first build queued (:func:`femcam.mesh.session.gmsh_kept`): a run that only loads
        from the disk cache never imports gmsh.

        Parameters
        ----------
        key : hashable
            The job's key (``background.take(key, ...)`` takes its result).
        job : callable
            ``job()`` builds (or loads) and returns the result.
        disk_key : str, optional
            Its entry in :attr:`disk` (None: not stored, always queued).
        """
        if not self.background.threads:
            return
        if disk_key is not None and self.disk is not None and self.disk.has(disk_key):
            return
        if self._kept is not None and not self._kept_entered:
            self._kept.enter_context(gmsh_kept())
            self._kept_entered = True
        self.background.submit(key, job)

    @contextmanager
    def building_in_background(self, threads: int = 1):
        """Let :meth:`prefetch_model`, :meth:`prefetch_fresh` and :meth:`submit_build` run
        builds in ``threads`` background threads while the caller works (0: none; from the first
        build queued on, gmsh stays initialised, :func:`femcam.mesh.session.gmsh_kept`). On
        exit the builds not started are dropped and a running one is waited for.

        Parameters
        ----------
        threads : int
            Background threads (0 or 1 on the 2-core machines femcam is measured on).

        Yields
        ------
        femcam._threads.Background
            The background jobs (also :attr:`background` meanwhile).
        """
        if threads < 1:
            yield self.background
            return
        with ExitStack() as kept, Background(threads) as bg:  # bg closes first, then gmsh
            old, self.background = self.background, bg
            self._kept, self._kept_entered = kept, False
            try:
                yield bg
            finally:
                self.background, self._kept = old, None

    def solve(self, model: ContactModel, F: float, rho: float, mu: float, sliding: int,
              check: bool = True, Q: float | None = None, rolling: int = 0) -> ContactResult:
        """``model.solve(...)``, remembered for models in this cache.

        The family verification solves every angle of a family with its model; the chunks
        computed in this process (serial sweeps, and forked workers, which inherit the cache)
        then take those results instead of solving again. A result is a deterministic function
        of the model and the load case, so this changes no number.

        Parameters
        ----------
        model : femcam.fe.ContactModel
            A model of this cache (results of other models are not remembered).
        F : float
            Contact force (N).
        rho : float
            Cam radius of curvature (m).
        mu : float
            Friction coefficient (dimensionless).
        sliding : int
            Direction of the friction traction on the cam: +1 (+x) or -1 (-x).
        check : bool
            Refuse load cases the model does not cover.
        Q : float, optional
            Tangential force on the cam (N): Coulomb partial slip (``ContactModel.solve``).
        rolling : int
            With ``Q``: rolling direction (0, +1, -1).

        Returns
        -------
        femcam.fe.ContactResult
        """
        key = (float(F), float(rho), float(mu), int(sliding), None if Q is None else float(Q), int(rolling))
        with self._lock:
            memo = self._results.get(id(model))
            if memo is not None and key in memo:
                return memo[key]
        r = model.solve(F=float(F), rho=float(rho), mu=mu, sliding=sliding, check=check, Q=Q,
                        rolling=rolling if Q is not None else 0)
        with self._lock:
            if memo is not None and id(model) in self._results:
                memo[key] = r
        return r

    def fresh_p0(self, cp: ContactParams, rho: float, a: float, options: ResolvedOptions,
                 F: float, load: tuple = (None, None, 0)) -> float:
        """FE p0 of a model built fresh for one load case (remembered per load case).

        Parameters
        ----------
        cp : ContactParams
            Follower radius and face width (m), materials, plane, friction ``mu``.
        rho, a : float
            The load case's cam radius and Hertz half-width (m): the fresh mesh is graded to them.
        options : ResolvedOptions
            ``a_over_h`` (elements per contact half-width) of the fresh mesh.
        F : float
            Contact force (N).
        load : tuple
            ``(sliding, Q, rolling)`` of the load case (:func:`femcam.sweep.realcam.traction_args`);
            ``sliding`` None: ``cp.sliding``.

        Returns
        -------
        float
            p0 (Pa); NaN if the fresh model cannot be built or solved.
        """
        key, job = self._fresh_job(cp, rho, a, options, F, load)
        with self._lock:
            p0 = self._fresh_p0.get(key)
        if p0 is not None:
            return p0
        p0, how = self.background.take(("fresh", key), job)
        if how is None:
            return p0
        with self._lock:
            self.stats["checks_built" if how == "built" else "checks_loaded"] += 1
            self._fresh_p0[key] = p0
            while len(self._fresh_p0) > 1024:
                self._fresh_p0.popitem(last=False)
        return p0

    def prefetch_fresh(self, cp: ContactParams, rho: float, a: float, options: ResolvedOptions,
                       F: float, load: tuple = (None, None, 0)) -> None:
        """Start the fresh check :meth:`fresh_p0` will be asked for (same arguments) in the
        background (nothing outside :meth:`building_in_background`).

        Parameters
        ----------
        cp : ContactParams
            Follower radius and face width (m), materials, plane, friction ``mu``.
        rho, a : float
            The load case's cam radius and Hertz half-width (m).
        options : ResolvedOptions
            ``a_over_h`` of the fresh mesh.
        F : float
            Contact force (N).
        load : tuple
            ``(sliding, Q, rolling)`` of the load case.
        """
        key, job = self._fresh_job(cp, rho, a, options, F, load)
        with self._lock:
            if key in self._fresh_p0:
                return
        self.submit_build(("fresh", key), job, job.disk_key)

    def _fresh_job(self, cp, rho, a, options, F, load) -> tuple:
        """The memo key of a fresh check and the function computing ``(p0, how)``: ``how``
        ``"loaded"`` (from :attr:`disk`), ``"built"`` or None (p0 NaN: the fresh model could
        not be built or solved; not remembered)."""
        sliding, Q, rolling = load
        sliding = cp.sliding if sliding is None else sliding
        key = (_key(cp, rho, a, options), F, cp.mu, sliding, Q, rolling)

        def job():
            solver, dk = _FRESH_SOLVER, job.disk_key
            p0 = self.disk.get(dk) if dk is not None else None
            if finite_p0(p0):
                return p0, "loaded"
            try:
                fresh = build_model(cp, rho, a, options, solver)
                p0 = float(fresh.solve(F=F, rho=rho, mu=cp.mu, sliding=sliding, check=False, Q=Q,
                                       rolling=rolling if Q is not None else 0).p0_nodal)
            except (FemcamError, ValueError, ArithmeticError):
                return math.nan, None
            if dk is not None and finite_p0(p0):
                self.disk.put(dk, p0)
            return p0, "built"

        job.disk_key = (_disk_key("fresh_p0", cp, rho, a, options, _FRESH_SOLVER, (F, sliding, Q, rolling))
                        if self.disk is not None else None)
        return key, job

    def real_cam(self, key: tuple, build):
        """A real-cam model of the models table (flat-faced sweeps; LRU as the family models).

        Parameters
        ----------
        key : tuple
            ``("real_cam", ...)``: what the model is built from.
        build : callable
            ``build() -> femcam.fe.choice.RealCam``, called on a miss.

        Returns
        -------
        femcam.fe.choice.RealCam
            Cached, or built now (counted in :attr:`stats`).
        """
        return self._get_or_build(key, build)

    def forget(self, cp: ContactParams, rho_ref: float, a_ref: float, options: ResolvedOptions) -> None:
        """Drop the model of references ``(rho_ref, a_ref)`` and its solved cases.

        Parameters
        ----------
        cp : ContactParams
            The contact parameters the model was built for.
        rho_ref, a_ref : float
            Its reference cam radius and half-width (m).
        options : ResolvedOptions
            Its ``a_over_h``.
        """
        with self._lock:
            m = self._models.pop(_key(cp, rho_ref, a_ref, options), None)
            if m is not None:
                self._results.pop(id(m), None)

    def clear(self) -> None:
        """Forget every model and fresh-model check result."""
        with self._lock:
            self._models.clear()
            self._results.clear()
            self._fresh_p0.clear()


_PROCESS_CACHE = ModelCache()


def default_cache() -> ModelCache:
    """This process's :class:`ModelCache`.

    One per process, not one per :func:`femcam.sweep.sweep` call: worker processes receive
    their tasks pickled (a cache of factorised models cannot travel with them), so a worker
    keeps the models it builds across chunks, and forked workers inherit the models and
    results the parent's verification built.

    Returns
    -------
    ModelCache
    """
    return _PROCESS_CACHE


def build_model(cp: ContactParams, rho_ref: float, a_ref: float, options: ResolvedOptions,
                solver: SolverOptions | None = None, mesh: MeshOptions | None = None) -> ContactModel:
    """A fresh :class:`femcam.fe.ContactModel` (mesh + factorisation).

    Parameters
    ----------
    cp : ContactParams
    rho_ref, a_ref : float
        Reference cam radius and half-width (m).
    options : ResolvedOptions
        ``a_over_h``.
    solver : SolverOptions, optional
        Default ``SolverOptions()`` (stress operators precomputed: a family model solved at
        many angles); ``stress_operators="per_solve"`` for a one-off model (same p0 to ~1e-12).
    mesh : MeshOptions, optional
        Replaces the mesh of :func:`model_args` (the coarse level of a two-level estimate,
        :func:`femcam.sweep.estimate.coarse_mesh`; such a model is not cached).

    Returns
    -------
    femcam.fe.ContactModel
        With ``cp.coat_body`` set: the coated model (:func:`femcam.layers.build_coated_model`,
        the coating band in the contact FE), its fine zone widened by :func:`coated_zone_factor`.
    """
    args = model_args(cp, rho_ref, a_ref, options, solver)
    if mesh is not None:
        args["mesh"] = mesh
    if cp.coat_body is None:
        return ContactModel.build(**args)
    return build_coated_model(**args, body=cp.coat_body,
                              coating=Coating(thickness=cp.coat_thickness, material=cp.coating))


def coated_zone_factor(cp: ContactParams) -> float:
    r"""How much wider than the homogeneous model's the coated model's fine zone is: the ratio of
    the Hertz half-widths with the coating's and the substrate's constants on the coated body,
    when the coating is softer (1 otherwise).

    The families are planned, and :meth:`~femcam.fe.ContactModel.covers` checks, with the Hertz
    half-width of the substrates (``cp.E_star``); a soft coating thicker than the contact widens
    the contact up to that of a body of the coating material, ``a ~ 1 / sqrt(E*)`` (Johnson 1985
    eq. 4.43), so the zone the contact may load grows by this factor.

    .. math:: f = \max\left(1, \sqrt{E^*_{substrate} / E^*_{coating}}\right)

    Parameters
    ----------
    cp : ContactParams
        With ``coat_body``, ``coat_E`` [Pa], ``coat_nu`` [-].

    Returns
    -------
    float
        ``f >= 1`` [-] (1 for an uncoated ``cp``).
    """
    if cp.coat_body is None:
        return 1.0
    coat = cp.coating
    as_coat = {"cam": (coat, cp.roller), "roller": (cp.cam, coat)}[cp.coat_body]
    return max(1.0, math.sqrt(cp.E_star / effective_modulus(*as_coat, cp.plane)))


def model_args(cp: ContactParams, rho_ref: float, a_ref: float, options: ResolvedOptions,
               solver: SolverOptions | None = None) -> dict:
    """The keyword arguments of :meth:`femcam.fe.ContactModel.build` for a sweep's model (the
    one place they are chosen: :func:`build_model` builds with them, the persistent cache keys
    on them, :mod:`femcam.sweep.diskcache`).

    Parameters
    ----------
    cp : ContactParams
        The contact (radii, materials, length, plane, coating).
    rho_ref, a_ref : float
        Reference cam radius and half-width (m).
    options : ResolvedOptions
        ``a_over_h``.
    solver : SolverOptions, optional
        Default ``SolverOptions()``.

    Returns
    -------
    dict
        ``Rr, rho_ref, cam, roller, length, a_ref`` (m, materials), ``mesh`` (the fine zone widened
        by :func:`coated_zone_factor` for a coated ``cp``), ``solver``, ``plane``.
    """
    mesh = MeshOptions(a_over_h=options.a_over_h)
    if cp.coat_body is not None:   # a soft coating widens the contact: widen the fine zone
        mesh = MeshOptions(a_over_h=options.a_over_h,
                           fine_half_width=mesh.fine_half_width * coated_zone_factor(cp))
    return dict(Rr=cp.Rr, rho_ref=rho_ref, cam=cp.cam, roller=cp.roller, length=cp.length,
                a_ref=a_ref, mesh=mesh, solver=solver or SolverOptions(), plane=cp.plane)


def _disk_key(kind: str, cp, rho_ref, a_ref, options, solver=None, load=()) -> str | None:
    """The persistent key of a model (or a fresh check with its ``load`` case): every field of
    ``cp`` and every build argument (None: not keyable, so not stored)."""
    try:
        return content_key(kind, cp, model_args(cp, float(rho_ref), float(a_ref), options, solver),
                           load)
    except TypeError:
        return None
