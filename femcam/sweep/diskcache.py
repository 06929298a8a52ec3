"""The persistent model cache: family models and fresh-check results on disk, by content hash.

A sweep builds one FE model per family (gmsh mesh, assembly, factorisation, condensation onto
the contact DOFs, stress operators of the window) and a few fresh "check" models for the reuse
verification (:mod:`femcam.sweep.verify`). A repeated run of the same scene, a resumed run or a
design-study variant with the same bodies would build them all again. This module stores them.

What is stored (sizes and load/build times: docs/sweep.md and docs/performance.md)
----------------------------------------------------------------------------------
* a family model without its factorised bodies (:func:`strip_model`): the meshes, the condensed
  compliances ``An, At, Ctt, Ctn``, the load operators and the stress operators of the window
  (loading one is about a hundred times faster than building it). A SuperLU factor cannot be
  pickled: a loaded model's bodies (:class:`LazyBodies`) are made from the stored meshes, with
  the mesh and basis only, and assembled and factorised again (bit-identical to the original
  ones) only when a load that was not stored needs a back-solve;
* the displacements of the full fields a sweep writes (its ``.vtu`` files): one entry per body
  and load vector, keyed by the body (mesh, material, element, factor options) and the load
  vector's bytes (:class:`StoredBody`, :func:`store_fields`; 67 KB per body of the study
  model at ``--a-over-h 10``, 4.8 MB for the 36 files of README command 1). A run that writes
  the same ``.vtu`` again reads them back and factorises no body: its fields are the cold
  run's, bit for bit;
* the p0 of each fresh check model (a float: the check models themselves are never reused).

Key
---
SHA-256 of a canonical text (:func:`canonical`) of everything the entry depends on: every field
of :class:`~femcam.sweep.options.ContactParams` (walked generically, nested dataclasses such as
materials and coatings included, so fields added later are keyed without a change here), the
arguments of :meth:`femcam.fe.ContactModel.build` (mesh and solver options, all fields), the load
case of a check, the femcam version, the Python, numpy, scipy, scikit-fem, gmsh and meshio
versions, and a hash of the source of the modules that shape a model (``femcam.fe``,
``femcam.mesh``, ``femcam.layers``, ``femcam.materials``, ``femcam.hertz``, this module and
:mod:`~femcam.sweep.cache`: an edited checkout never loads a model of older code).

Safety
------
An entry is written to a temporary file in the same directory and moved in place with
``os.replace``, so readers never see half a file and two processes writing one key leave one
whole entry. Each entry carries a magic, its payload length and the payload's SHA-256: a corrupt
or truncated entry is removed, rebuilt and said in one line. Size is bounded (default
:data:`DEFAULT_MAX_BYTES`, ``$FEMCAM_CACHE_MAX_MB``): the least recently used entries (file
modification time, touched on every hit) are removed after a write. A directory that cannot be
written (read-only, full disk) never stops a sweep: the models are built and it is said once.
Entries are pickles: the directory (created mode 0700) must be one only its user writes.
"""

from __future__ import annotations

import dataclasses
import functools
import hashlib
import importlib.metadata
import math
import os
import pickle
import platform
import struct
import sys
import tempfile
import threading
import time
from pathlib import Path

import numpy as np

from .. import _validate
from ..fe import ContactModel
from ..fe.elasticity import assemble_body, mesh_body

#: environment variable naming the cache directory
ENV_DIR = "FEMCAM_CACHE_DIR"
#: environment variable with the size bound in MB
ENV_MAX_MB = "FEMCAM_CACHE_MAX_MB"
#: default size bound (bytes): ~75 family models of the study model at a_over_h = 10
DEFAULT_MAX_BYTES = 1 << 30
#: first bytes of every entry (a new layout changes it and the directory name)
MAGIC = b"FEMCAMC1"
_HEADER = struct.Struct("<8sQ32s")  # magic, payload length, SHA-256 of the payload
#: the entries live in this subdirectory of the cache directory
LAYOUT = "models-v1"
#: modules whose source shapes a stored model (part of every key)
_SOURCES = ("fe", "mesh", "layers", "materials.py", "hertz", "sweep/cache.py", "sweep/diskcache.py")


def default_dir() -> Path:
    """The cache directory: ``$FEMCAM_CACHE_DIR``, else ``$XDG_CACHE_HOME/femcam``, else
    ``~/.cache/femcam``.

    Returns
    -------
    pathlib.Path
        The directory (not created here).
    """
    env = os.environ.get(ENV_DIR)
    if env:
        return Path(env).expanduser()
    xdg = os.environ.get("XDG_CACHE_HOME")
    return (Path(xdg).expanduser() if xdg else Path.home() / ".cache") / "femcam"


def canonical(obj) -> str:
    """A canonical text of a key part: dataclasses field by field (with their class name),
    floats exactly (``float.hex``), arrays by dtype, shape and content hash.

    Parameters
    ----------
    obj : object
        Numbers, strings, None, tuples/lists, dicts, numpy arrays, dataclasses of these.

    Returns
    -------
    str
        Equal texts for equal values; a different text for any changed field.

    Raises
    ------
    TypeError
        An object of another kind (it cannot be keyed safely: the caller builds instead).
    """
    if obj is None or isinstance(obj, (bool, str)):
        return repr(obj)
    if isinstance(obj, (int, np.integer)):
        return f"i{int(obj)}"
    if isinstance(obj, (float, np.floating)):
        return f"f{float(obj).hex()}"
    if isinstance(obj, np.ndarray):
        return f"a{obj.dtype.str}{obj.shape}{hashlib.sha256(np.ascontiguousarray(obj).tobytes()).hexdigest()}"
    if isinstance(obj, (tuple, list)):
        return "[" + ",".join(canonical(x) for x in obj) + "]"
    if isinstance(obj, dict):
        return "{" + ",".join(f"{canonical(k)}:{canonical(obj[k])}" for k in sorted(obj, key=repr)) + "}"
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        body = ",".join(f"{f.name}={canonical(getattr(obj, f.name))}" for f in dataclasses.fields(obj))
        return f"{type(obj).__module__}.{type(obj).__qualname__}({body})"
    raise TypeError(f"cannot key a {type(obj).__name__}")


@functools.lru_cache(maxsize=1)
def _library_versions() -> str:
    out = [platform.python_version()]
    for name in ("numpy", "scipy", "scikit-fem", "gmsh", "meshio"):
        try:
            out.append(f"{name}={importlib.metadata.version(name)}")
        except importlib.metadata.PackageNotFoundError:
            out.append(f"{name}=none")
    return ";".join(out)


@functools.lru_cache(maxsize=1)
def _source_hash() -> str:
    root = Path(__file__).resolve().parents[1]
    h = hashlib.sha256()
    for part in _SOURCES:
        p = root / part
        for f in sorted(p.rglob("*.py")) if p.is_dir() else [p]:
            h.update(str(f.relative_to(root)).encode())
            h.update(f.read_bytes())
    return h.hexdigest()


def content_key(kind: str, *parts) -> str:
    """The key of an entry: SHA-256 of ``kind``, the canonical ``parts`` and the versions.

    Parameters
    ----------
    kind : str
        What is stored (``"family_model"``, ``"fresh_p0"``).
    *parts : object
        What the entry depends on (:func:`canonical`).

    Returns
    -------
    str
        64 hex digits.

    Raises
    ------
    TypeError
        A part that cannot be keyed.
    """
    femcam_version = getattr(sys.modules.get("femcam"), "__version__", "?")
    text = "|".join([kind, f"femcam={femcam_version}", _library_versions(), _source_hash(),
                     *(canonical(p) for p in parts)])
    return hashlib.sha256(text.encode()).hexdigest()


#: attributes of a :class:`~femcam.fe.elasticity.Body` that need its stiffness and factor (the
#: others come from the mesh alone, :func:`~femcam.fe.elasticity.mesh_body`)
_FACTORED = frozenset({"K", "free", "lu", "perm", "last", "t_assembly", "t_factor", "solve_apply",
                       "schur_solve", "schur_inverse"})


class StoredBody:
    """One body of a model whose full-field displacements go through the disk cache.

    A ``.vtu`` needs the displacements of both bodies under the solved contact loads, a
    back-solve with the body's factor; a model loaded from the cache has no factor (a SuperLU
    factor cannot be stored). :meth:`solve` of one load vector stores the displacements under
    the key of the body and the load (:func:`content_key` of the mesh, material, plane,
    element, factor options and the load vector's bytes), so a run of the same scene reads them
    back and never assembles or factorises the body: the mesh, basis and Lamé parameters
    (:func:`~femcam.fe.elasticity.mesh_body`) are all the stresses, the error indicator and the
    coordinates of a ``.vtu`` need. Any other load, or any use of the factor (``K``, ``lu``,
    :meth:`~femcam.fe.elasticity.Body.solve_apply`, ...), assembles and factorises the body
    from the stored mesh once, bit-identical to the original (same code, same inputs).

    Attribute access is forwarded to that body (the mesh-only one until the factor is needed).

    Parameters
    ----------
    spec : tuple
        ``(geometry, material, plane, element, ordering, contact_last)`` of
        :func:`~femcam.fe.elasticity.assemble_body`.
    body : femcam.fe.elasticity.Body, optional
        The factorised body, when it exists already (a model built in this process).
    disk : DiskCache, optional
        Where the displacements are read and stored (None: never).
    """

    def __init__(self, spec: tuple, body=None, disk: DiskCache | None = None):
        self._spec = spec
        self._full = body
        self._mesh_only = None
        self._key = None
        self._lock = threading.Lock()
        self.disk = disk

    @classmethod
    def of(cls, body, solver, disk: DiskCache | None = None) -> StoredBody:
        """A factorised body whose displacements are stored.

        Parameters
        ----------
        body : femcam.fe.elasticity.Body
            The factorised body.
        solver : femcam.fe.SolverOptions
            The options its model was built with (:func:`_factor_args`).
        disk : DiskCache, optional
            Where its displacements are stored.

        Returns
        -------
        StoredBody
        """
        spec = (body.geometry, body.material, body.plane, body.element, *_factor_args(solver))
        return cls(spec, body, disk)

    def __getattr__(self, name):  # called only for names not set on the proxy itself
        if name.startswith("__") or name in ("_spec", "_full", "_mesh_only", "_key", "_lock"):
            raise AttributeError(name)
        if self._full is None and name not in _FACTORED:
            return getattr(self.mesh_only(), name)
        return getattr(self.factorised(), name)

    def __repr__(self) -> str:
        return f"StoredBody({self._spec[0].name}, factorised={self._full is not None})"

    def mesh_only(self):
        """The body without its factor (built on first use).

        Returns
        -------
        femcam.fe.elasticity.Body
        """
        if self._full is not None:
            return self._full
        with self._lock:
            if self._mesh_only is None:
                geometry, material, plane, element, _, _ = self._spec
                self._mesh_only = mesh_body(geometry, material, plane=plane, element=element)
            return self._mesh_only

    def factorised(self):
        """The assembled, factorised body (built from the stored mesh on first use).

        Returns
        -------
        femcam.fe.elasticity.Body
        """
        with self._lock:
            if self._full is None:
                geometry, material, plane, element, ordering, contact_last = self._spec
                self._full = assemble_body(geometry, material, plane=plane, element=element,
                                           ordering=ordering, contact_last=contact_last)
                self._mesh_only = None
            return self._full

    def _disp_key(self, f: np.ndarray) -> str | None:
        if self._key is None:
            try:
                self._key = canonical(self._spec)
            except TypeError:  # a part that cannot be keyed: never stored
                self._key = ""
        return content_key("body_displacement", self._key, f) if self._key else None

    def solve(self, f) -> np.ndarray:
        """Displacements for nodal forces ``f`` (:meth:`femcam.fe.elasticity.Body.solve`):
        read from the disk cache for one stored load vector, else solved (and stored).

        Parameters
        ----------
        f : ndarray of float, shape (n_dofs,) or (n_dofs, k)
            Nodal forces [N per unit thickness].

        Returns
        -------
        ndarray of float, same shape as ``f``
            Nodal displacements [m].
        """
        f = np.asarray(f, dtype=float)
        disk = self.disk
        key = self._disp_key(f) if (f.ndim == 1 and disk is not None and disk.enabled) else None
        if key is None:
            return self.factorised().solve(f)
        if self._full is None:
            u = disk.get(key)
            if isinstance(u, np.ndarray) and u.dtype == f.dtype and u.shape == f.shape:
                return u
        u = self.factorised().solve(f)
        if not disk.has(key):
            disk.put(key, u)
        return u


def _factor_args(solver) -> tuple[str, bool]:
    """``(ordering, contact_last)`` of :func:`~femcam.fe.elasticity.assemble_body` for a body of
    a model built with ``solver`` (as :meth:`femcam.fe.ContactModel.build` builds it: contact
    DOFs last for ``per_solve`` models)."""
    return solver.ordering, solver.stress_operators == "per_solve"


class LazyBodies(dict):
    """The ``bodies`` of a model loaded from the cache: a :class:`StoredBody` per body, made on
    first use (mesh and basis; assembled and factorised again from the stored mesh only when
    the factor is needed).

    Parameters
    ----------
    model : femcam.fe.ContactModel
        The loaded model (its ``mesh``, materials, plane, element and solver options).

    Attributes
    ----------
    disk : DiskCache or None
        Where the bodies' displacements are read and stored (:func:`store_fields`).
    """

    def __init__(self, model: ContactModel):
        super().__init__()
        self._spec = (model.mesh, {"cam": model.cam, "roller": model.roller}, model.plane,
                      model.element, model.options)
        self._lock = threading.Lock()
        self.disk = None

    def __missing__(self, name: str):
        mesh, materials, plane, element, solver = self._spec
        if name not in materials:
            raise KeyError(name)
        with self._lock:
            if name not in self:
                self[name] = StoredBody((getattr(mesh, name), materials[name], plane, element,
                                         *_factor_args(solver)), disk=self.disk)
            return dict.__getitem__(self, name)

    def __reduce__(self):  # pickles as a plain empty dict (no SuperLU factors)
        return (dict, ())


def store_fields(model: ContactModel, disk: DiskCache | None) -> None:
    """Route the full-field back-solves of ``model`` (its ``.vtu`` files) through ``disk``
    (:class:`StoredBody`): a model built here stores them, a model loaded from the cache
    reads them. Idempotent; ``model.bodies`` is changed in place.

    Parameters
    ----------
    model : femcam.fe.ContactModel
        A family model.
    disk : DiskCache or None
        The sweep's cache (None or disabled: nothing changes).
    """
    if disk is None or not disk.enabled or not isinstance(model, ContactModel):
        return
    bodies = model.bodies
    if isinstance(bodies, LazyBodies):
        bodies.disk = disk
        for b in bodies.values():
            b.disk = disk
        return
    for name, b in list(bodies.items()):
        if isinstance(b, StoredBody):
            b.disk = disk
        elif b is not None:
            bodies[name] = StoredBody.of(b, model.options, disk)


def strip_model(model: ContactModel) -> ContactModel:
    """The model without its factorised bodies and cached field operators (what is stored).

    Parameters
    ----------
    model : femcam.fe.ContactModel
        A built model.

    Returns
    -------
    femcam.fe.ContactModel
        The same arrays; ``bodies`` empty.
    """
    return dataclasses.replace(model, bodies={}, _field_ops={})


def restore_model(model: ContactModel) -> ContactModel:
    """A stripped model with :class:`LazyBodies` (bodies rebuilt on first use).

    Parameters
    ----------
    model : femcam.fe.ContactModel
        A model from :func:`strip_model` (after a pickle round trip).

    Returns
    -------
    femcam.fe.ContactModel
        The model, ready to solve and to give full fields.
    """
    out = dataclasses.replace(model, bodies={}, _field_ops={})
    object.__setattr__(out, "bodies", LazyBodies(out))
    return out


def _env_max_bytes() -> int:
    """``$FEMCAM_CACHE_MAX_MB`` in bytes, or :data:`DEFAULT_MAX_BYTES` when unset."""
    env = os.environ.get(ENV_MAX_MB, "").strip()
    if not env:
        return DEFAULT_MAX_BYTES
    try:
        mb = float(env)
    except ValueError:
        raise _validate.fail(ENV_MAX_MB, env, "MB", "must be a number of megabytes >= 0") from None
    return int(_validate.nonnegative(ENV_MAX_MB, mb, "MB") * 1e6)


def _say(line: str) -> None:
    print(f"femcam: model cache: {line}", file=sys.stderr)


class DiskCache:
    """Entries on disk by content key (module docstring: layout, safety, size bound).

    Parameters
    ----------
    directory : str or Path, optional
        The cache directory (default :func:`default_dir`).
    enabled : bool
        False: every ``get`` misses and nothing is written (``--no-cache``).
    writable : bool
        False: read only (Dask workers read what the client stored and write nothing).
    max_bytes : int, optional
        Size bound (bytes, >= 0; default ``$FEMCAM_CACHE_MAX_MB`` MB or
        :data:`DEFAULT_MAX_BYTES`).

    Attributes
    ----------
    stats : dict
        ``hits``, ``misses``, ``writes``, ``corrupt``, ``evicted`` (counts).
    """

    def __init__(self, directory=None, *, enabled: bool = True, writable: bool = True,
                 max_bytes: int | None = None):
        self.root = Path(directory).expanduser() if directory is not None else default_dir()
        if not isinstance(enabled, bool):
            raise _validate.fail("model_cache", enabled, "", "must be True or False")
        self.enabled = enabled
        self.writable = bool(writable)
        if max_bytes is None:
            max_bytes = _env_max_bytes()
        self.max_bytes = _validate.integer("max_bytes", max_bytes, 0, "bytes")
        self.stats = {"hits": 0, "misses": 0, "writes": 0, "corrupt": 0, "evicted": 0}
        self._failed_write = False

    @property
    def directory(self) -> Path:
        """Where the entries are (``root/models-v1``)."""
        return self.root / LAYOUT

    def spec(self) -> tuple:
        """``(directory, enabled, writable, max_bytes)``: picklable, for worker processes.

        Returns
        -------
        tuple
            What :meth:`from_spec` takes.
        """
        return (str(self.root), self.enabled, self.writable, self.max_bytes)

    @classmethod
    def from_spec(cls, spec: tuple) -> DiskCache:
        """The cache of :meth:`spec`.

        Parameters
        ----------
        spec : tuple
            ``(directory, enabled, writable, max_bytes)``.

        Returns
        -------
        DiskCache
        """
        root, enabled, writable, max_bytes = spec
        return cls(root, enabled=enabled, writable=writable, max_bytes=max_bytes)

    def path(self, key: str) -> Path:
        """The file of an entry.

        Parameters
        ----------
        key : str
            :func:`content_key`.

        Returns
        -------
        pathlib.Path
        """
        return self.directory / f"{key}.pkl"

    def has(self, key: str) -> bool:
        """Whether an entry is stored under ``key`` (not checked: :meth:`get` checks it).

        Parameters
        ----------
        key : str
            :func:`content_key`.

        Returns
        -------
        bool
            False for a disabled cache.
        """
        return self.enabled and self.path(key).is_file()

    def get(self, key: str):
        """The stored object, or None (a miss, a disabled cache, or a corrupt entry: removed,
        said in one line).

        Parameters
        ----------
        key : str
            :func:`content_key`.

        Returns
        -------
        object or None
        """
        if not self.enabled:
            return None
        p = self.path(key)
        try:
            data = p.read_bytes()
        except OSError:
            self.stats["misses"] += 1
            return None
        obj = self._decode(data)
        if obj is None:
            self.stats["corrupt"] += 1
            self.stats["misses"] += 1
            _say(f"entry {p.name} is corrupt or incomplete ({len(data)} bytes); removed, rebuilding")
            try:
                p.unlink()
            except OSError:
                pass
            return None
        self.stats["hits"] += 1
        try:
            os.utime(p)  # least recently used = oldest modification time
        except OSError:
            pass
        return obj

    @staticmethod
    def _decode(data: bytes):
        if len(data) < _HEADER.size:
            return None
        magic, n, digest = _HEADER.unpack_from(data)
        payload = memoryview(data)[_HEADER.size:]
        if magic != MAGIC or n != len(payload) or hashlib.sha256(payload).digest() != digest:
            return None
        try:
            return pickle.loads(payload)
        except Exception:  # noqa: BLE001 - any unpickling failure is a corrupt entry
            return None

    def put(self, key: str, obj) -> bool:
        """Store ``obj`` under ``key`` (atomic; then the size bound).

        Parameters
        ----------
        key : str
            :func:`content_key`.
        obj : object
            A picklable object.

        Returns
        -------
        bool
            Whether it was written (False: disabled, read only, or the directory cannot be
            written, said once).
        """
        if not (self.enabled and self.writable) or self._failed_write:
            return False
        try:
            payload = pickle.dumps(obj, protocol=5)
        except (pickle.PicklingError, TypeError, AttributeError) as exc:  # a field added later
            self._failed_write = True
            _say(f"cannot store a {type(obj).__name__} ({exc}); building without storing")
            return False
        if len(payload) + _HEADER.size > self.max_bytes:
            return False
        head = _HEADER.pack(MAGIC, len(payload), hashlib.sha256(payload).digest())
        tmp = None
        try:
            self.directory.mkdir(parents=True, exist_ok=True, mode=0o700)
            fd, tmp = tempfile.mkstemp(dir=self.directory, prefix=".tmp-", suffix=".part")
            with os.fdopen(fd, "wb") as f:
                f.write(head)
                f.write(payload)
            os.replace(tmp, self.path(key))
        except OSError as exc:
            if tmp is not None:
                try:
                    os.unlink(tmp)
                except OSError:
                    pass
            self._failed_write = True
            _say(f"cannot write to {self.root} (--cache-dir or FEMCAM_CACHE_DIR: {exc.strerror or exc}); "
                 "building without storing")
            return False
        self.stats["writes"] += 1
        self._evict()
        return True

    def _evict(self) -> None:
        """Remove the least recently used entries above the bound, and temporary files older
        than an hour (a writer killed mid-write)."""
        entries, total, now = [], 0, time.time()
        try:
            with os.scandir(self.directory) as it:
                for e in it:
                    st = e.stat()
                    if e.name.startswith(".tmp-"):
                        if now - st.st_mtime > 3600:
                            os.unlink(e.path)
                        continue
                    entries.append((st.st_mtime, st.st_size, e.path))
                    total += st.st_size
            entries.sort()
            for _, size, path in entries:
                if total <= self.max_bytes:
                    break
                os.unlink(path)
                total -= size
                self.stats["evicted"] += 1
        except OSError:  # another process removed it first, or the disk went away
            pass


def usage_line(reused: int, built: int, checks_reused: int, checks_built: int,
               disk: DiskCache | None) -> str:
    """The sweep summary's line on the model cache.

    Parameters
    ----------
    reused, built : int
        Family models loaded from the cache and built in this sweep.
    checks_reused, checks_built : int
        Fresh-check p0 values loaded and computed.
    disk : DiskCache or None
        The cache (None or disabled: ``--no-cache``).

    Returns
    -------
    str
        E.g. ``"FE models: 2 reused from cache (/home/u/.cache/femcam), 0 built; fresh checks:
        2 reused, 0 built"``.
    """
    checks = f"; fresh checks: {checks_reused} reused, {checks_built} built"
    if disk is None or not disk.enabled:
        return f"FE models: {built} built, model cache off (--no-cache)" + checks
    ro = "" if disk.writable and not disk._failed_write else ", not writable"
    return f"FE models: {reused} reused from cache ({disk.root}{ro}), {built} built" + checks


def usage(stats: dict, before: dict, disk: DiskCache) -> dict:
    """What one sweep took from the cache and built (its provenance ``options.model_cache``).

    Parameters
    ----------
    stats, before : dict
        :attr:`femcam.sweep.cache.ModelCache.stats` after and before the sweep.
    disk : DiskCache
        The sweep's cache.

    Returns
    -------
    dict
        ``directory``, ``enabled``, ``loaded``, ``built``, ``checks_loaded``, ``checks_built``
        (counts) and ``line`` (:func:`usage_line`).
    """
    used = {k: stats[k] - before[k] for k in ("loaded", "built", "checks_loaded", "checks_built")}
    return {"directory": str(disk.root), "enabled": disk.enabled, **used,
            "line": usage_line(used["loaded"], used["built"], used["checks_loaded"],
                               used["checks_built"], disk)}


def attach(cache, spec: tuple | None) -> None:
    """Give a process's :class:`~femcam.sweep.cache.ModelCache` the disk cache of ``spec`` (a
    worker process running a chunk; unchanged when it already has it).

    Parameters
    ----------
    cache : femcam.sweep.cache.ModelCache
        The process's model cache.
    spec : tuple or None
        :meth:`DiskCache.spec` of the sweep (None: leave as is).
    """
    if spec is None:
        return
    if cache.disk is None or cache.disk.spec() != tuple(spec):
        cache.disk = DiskCache.from_spec(spec)


def read_only(spec: tuple | None) -> tuple | None:
    """The read-only variant of a :meth:`DiskCache.spec` (Dask workers).

    Parameters
    ----------
    spec : tuple or None
        ``(directory, enabled, writable, max_bytes)``.

    Returns
    -------
    tuple or None
        The same with ``writable`` False.
    """
    return None if spec is None else (spec[0], spec[1], False, spec[3])


def finite_p0(p0) -> bool:
    """Whether a fresh-check p0 is worth storing (a NaN is a failed build: not stored).

    Parameters
    ----------
    p0 : float
        Peak pressure (Pa).

    Returns
    -------
    bool
    """
    return isinstance(p0, float) and math.isfinite(p0)
