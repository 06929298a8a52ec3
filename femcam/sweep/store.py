"""Chunked, atomic, resumable on-disk store of a sweep.

Layout of ``DIR/chunks/``::

    manifest.json        scene hash, angle hash, options, chunk boundaries
    plan.json            the verified model families (FE sweeps; reused on resume)
    chunk_00000.npz      rows of chunk 0 (written to a temporary file, then os.replace)
    ...

Why: a sweep of thousands of FE solves can be killed (ctrl-C, a cluster pre-emption, a full
disk). Each chunk is written atomically -- a reader sees either the whole chunk or none of it --
so ``resume`` loads every finished chunk and computes only the missing ones. The manifest makes
sure a resume continues *the same* sweep: a different scene, angle set or option refuses with a
message instead of silently mixing results.
"""

from __future__ import annotations

import hashlib
import json
import os
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from .._files import read_regular

try:
    import fcntl
except ImportError:  # pragma: no cover - Windows: no directory lock
    fcntl = None

from ..errors import InputError
from ..io import atomic_write_text, write_arrays
from .chunk import ChunkRows

MANIFEST = "manifest.json"
PLAN = "plan.json"
FORMAT_VERSION = 5  # 2: wear and build-time columns, plan.json; 3: scene hash in each chunk;
#                     4: extra provider columns (femcam.sweep.extras); 5: txz_range_* columns
LOCK = ".femcam.lock"
#: a sweep into an output directory with at least this many angles keeps its table on disk
#: (:class:`StoredTable`) instead of in memory
STREAM_ANGLES = 20_000
#: name of the scene hash stored in each chunk file (not a column)
CHUNK_SCENE_KEY = "_scene_sha256"

#: largest manifest / plan JSON read from a sweep's store (bytes); both are a few kB
MAX_JSON_BYTES = 50_000_000


def array_hash(arr) -> str:
    """SHA-256 of a float array's bytes (stable across runs and machines of one endianness).

    Parameters
    ----------
    arr : array_like
        Converted to little-endian float64.

    Returns
    -------
    str
        Hex digest.
    """
    a = np.ascontiguousarray(np.asarray(arr, dtype="<f8"))
    return hashlib.sha256(a.tobytes()).hexdigest()


class ChunkStore:
    """Chunks of a sweep in ``root`` (a directory), keyed by a manifest.

    Parameters
    ----------
    root : str or Path
        Directory of the chunk files (``DIR/chunks``).
    key : dict
        JSON-able record (scene hash, angle hash, method, options) that identifies the sweep.
    bounds : list of (int, int)
        Chunk boundaries ``[(start, stop), ...]`` in row indices.
    """

    def __init__(self, root, key: dict, bounds: list[tuple[int, int]]):
        self.root = Path(root)
        self.key = json.loads(json.dumps(key, sort_keys=True))
        self.bounds = [(int(a), int(b)) for a, b in bounds]

    # -- manifest -----------------------------------------------------------------------
    def _manifest(self) -> dict:
        return {"format": FORMAT_VERSION, "key": self.key, "bounds": self.bounds}

    def open(self, resume: bool) -> set[int]:
        """Prepare the directory; return the ids of chunks already finished (resume only).

        Without ``resume`` old chunks are deleted. With ``resume`` a manifest for a different
        sweep raises :class:`InputError` naming what differs.

        Parameters
        ----------
        resume : bool
            Keep the finished chunks of the same sweep.

        Returns
        -------
        set of int
            Finished chunk ids (empty without ``resume``).
        """
        self.root.mkdir(parents=True, exist_ok=True)
        mpath = self.root / MANIFEST
        for tmp in self.root.glob("*.tmp"):  # leftovers of a killed write
            tmp.unlink(missing_ok=True)
        if resume and mpath.exists():
            try:
                old = json.loads(read_regular(mpath, "sweep manifest", MAX_JSON_BYTES))  # no FIFO
            except (OSError, ValueError):
                old = None
            if old is not None and old != json.loads(json.dumps(self._manifest(), sort_keys=True)):
                diff = sorted(k for k in set(old.get("key", {})) | set(self.key)
                              if old.get("key", {}).get(k) != self.key.get(k))
                if old.get("bounds") != [list(b) for b in self.bounds]:  # JSON lists
                    diff.append("chunk bounds")
                raise InputError(
                    f"resume = True: {mpath} belongs to a different sweep (differs in: "
                    f"{', '.join(diff) or 'format'}); rerun without --resume or use another --out")
            if old is not None:
                done = {i for i in range(len(self.bounds)) if self._readable(i)}
                self._check_scene(done)
                return done
        # fresh sweep: drop old chunks and plan, write the manifest
        for p in self.root.glob("chunk_*.npz"):
            p.unlink()
        (self.root / PLAN).unlink(missing_ok=True)
        atomic_write_text(mpath, json.dumps(self._manifest(), indent=1, sort_keys=True))
        return set()

    def _check_scene(self, done) -> None:
        """Refuse finished chunks computed for another scene than the manifest's."""
        want = self.key.get("scene_sha256")
        for i in sorted(done):
            with np.load(self.path(i), allow_pickle=False) as z:
                got = str(z[CHUNK_SCENE_KEY]) if CHUNK_SCENE_KEY in z.files else "(none)"
            if want is not None and got != want:
                raise InputError(
                    f"resume = True: {self.path(i)} was computed for another scene (scene hash "
                    f"{got[:12]}, the manifest's is {want[:12]}); the directory holds two "
                    "sweeps' chunks: rerun without --resume (--overwrite) or use another --out")

    # -- the verified family plan ----------------------------------------------------
    def save_plan(self, plan: dict) -> None:
        """Store the verified family plan (JSON): a resume reuses it instead of re-verifying,
        so the resumed chunks use exactly the same models.

        Parameters
        ----------
        plan : dict
            JSON-able plan (families and their records).
        """
        atomic_write_text(self.root / PLAN, json.dumps(plan, sort_keys=True))

    def load_plan(self) -> dict | None:
        """The stored family plan.

        Returns
        -------
        dict or None
            The plan as saved by :meth:`save_plan`; None when none is stored or it is unreadable.
        """
        try:
            return json.loads(read_regular(self.root / PLAN, "sweep plan", MAX_JSON_BYTES))
        except (OSError, ValueError, InputError):  # (a FIFO or a huge file: not read)
            return None

    # -- chunks -------------------------------------------------------------------------
    def path(self, i: int) -> Path:
        """File of chunk ``i``.

        Parameters
        ----------
        i : int
            Chunk id.

        Returns
        -------
        Path
            ``root/chunk_<i:05d>.npz``.
        """
        return self.root / f"chunk_{i:05d}.npz"

    def _readable(self, i: int) -> bool:
        p = self.path(i)
        if not p.is_file():  # missing, or not a regular file (a FIFO would block np.load)
            return False
        try:
            rows = self.load(i)
        except Exception:  # truncated/corrupt file (should not happen with atomic writes)
            return False
        start, stop = self.bounds[i]
        return rows.theta.shape == (stop - start,)

    def write(self, i: int, rows: ChunkRows) -> Path:
        """Write chunk ``i`` atomically.

        Parameters
        ----------
        i : int
            Chunk id.
        rows : ChunkRows
            The chunk's table (SI numeric columns, text columns, extra provider columns).

        Returns
        -------
        Path
            The file written.
        """
        arrays = {}   # the chunk's columns in order: numbers as float, text as str
        for name, v in rows.items():
            v = np.asarray(v)
            arrays[name] = v.astype(str) if rows.is_text(name) else v.astype(float)
        if self.key.get("scene_sha256") is not None:
            arrays[CHUNK_SCENE_KEY] = np.array(str(self.key["scene_sha256"]))
        return write_arrays(self.path(i), arrays)

    def table(self) -> StoredTable:
        """The whole table, read from the chunk files on access.

        Returns
        -------
        StoredTable
            A read-only mapping column name -> array (SI).
        """
        return StoredTable(self)

    def load(self, i: int) -> ChunkRows:
        """The table of chunk ``i``.

        Parameters
        ----------
        i : int
            Chunk id.

        Returns
        -------
        ChunkRows
            The chunk's columns (SI numeric, text as ``str``).
        """
        with np.load(self.path(i), allow_pickle=False) as z:
            return ChunkRows.from_arrays({name: z[name] for name in z.files if name != CHUNK_SCENE_KEY})


class StoredTable(Mapping):
    """A sweep table read from its chunk files (:class:`ChunkStore`), not held in memory.

    ``table[name]`` reads that column from every chunk file (one column in memory, not kept:
    each access reads again); :meth:`chunks` yields the chunks' rows one at a time (the CSV
    writer streams them). A sweep into an output directory with at least
    :data:`STREAM_ANGLES` angles returns its table this way, so its memory does not grow with
    the table (0.3-0.5 kB per angle in memory otherwise).

    Parameters
    ----------
    store : ChunkStore
        A store whose chunks are all written.
    """

    def __init__(self, store: ChunkStore):
        self._paths = [store.path(i) for i in range(len(store.bounds))]
        with np.load(self._paths[0], allow_pickle=False) as z:
            self._keys = [k for k in z.files if k != CHUNK_SCENE_KEY]

    def __getitem__(self, name: str) -> np.ndarray:
        if name not in self._keys:
            raise KeyError(name)
        parts = []
        for p in self._paths:
            with np.load(p, allow_pickle=False) as z:
                parts.append(z[name])
        return np.concatenate(parts)

    def __iter__(self):
        return iter(self._keys)

    def __len__(self) -> int:
        return len(self._keys)

    def chunks(self):
        """The rows of each chunk in order, one chunk in memory at a time.

        Yields
        ------
        dict[str, ndarray]
            One chunk's columns (SI numeric, text as ``str``).
        """
        for p in self._paths:
            with np.load(p, allow_pickle=False) as z:
                yield {name: z[name] for name in self._keys}


class DirLock:
    """An exclusive OS lock on an output directory (``fcntl.flock`` on ``DIR/.femcam.lock``).

    A second writer into the same directory is refused with one line naming the holder's pid.
    The kernel releases the lock when the holder's file descriptor closes: on :meth:`release`,
    on exit, and on a kill (SIGKILL included), so a killed sweep never leaves a stale lock.
    Without ``fcntl`` (Windows) the lock is a no-op.

    Parameters
    ----------
    directory : str or Path
        The output directory (must exist).
    """

    def __init__(self, directory):
        self.path = Path(directory) / LOCK
        self._fd = None

    def acquire(self, flag: str = "out") -> DirLock:
        """Take the lock or raise :class:`InputError`.

        Parameters
        ----------
        flag : str
            The option named in the error message (e.g. ``"out"``).

        Returns
        -------
        DirLock
            ``self``, holding the lock.

        Raises
        ------
        InputError
            Another process holds the lock (its pid is named).
        """
        if fcntl is None:  # pragma: no cover - Windows
            return self
        fd = os.open(self.path, os.O_RDWR | os.O_CREAT, 0o644)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            holder = os.pread(fd, 64, 0).decode(errors="replace").strip() or "?"
            os.close(fd)
            raise InputError(f"{flag} = {self.path.parent}: another femcam sweep (pid {holder}) "
                             "is writing into this directory; wait for it to finish or use "
                             "another output directory") from None
        os.ftruncate(fd, 0)
        os.pwrite(fd, str(os.getpid()).encode(), 0)
        self._fd = fd
        return self

    def release(self) -> None:
        """Release the lock (idempotent)."""
        if self._fd is not None:
            os.close(self._fd)
            self._fd = None
