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
from pathlib import Path

import numpy as np

from ..errors import InputError
from ..io import atomic_write_bytes, atomic_write_text
from .result import NUMERIC, TEXT_COLUMNS, extra_keys

MANIFEST = "manifest.json"
PLAN = "plan.json"
FORMAT_VERSION = 3  # 2: wear and build-time columns, plan.json; 3: extra provider columns


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

    ``key`` is a JSON-able dict (scene hash, angle hash, method, options) that identifies the
    sweep; ``bounds`` are the chunk boundaries ``[(start, stop), ...]`` in row indices.
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
                old = json.loads(mpath.read_text())
            except (OSError, ValueError):
                old = None
            if old is not None and old != json.loads(json.dumps(self._manifest(), sort_keys=True)):
                diff = sorted(k for k in set(old.get("key", {})) | set(self.key)
                              if old.get("key", {}).get(k) != self.key.get(k))
                if old.get("bounds") != self.bounds:
                    diff.append("chunk bounds")
                raise InputError(
                    f"resume = True: {mpath} belongs to a different sweep (differs in: "
                    f"{', '.join(diff) or 'format'}); rerun without --resume or use another --out")
            if old is not None:
                return {i for i in range(len(self.bounds)) if self._readable(i)}
        # fresh sweep: drop old chunks and plan, write the manifest
        for p in self.root.glob("chunk_*.npz"):
            p.unlink()
        (self.root / PLAN).unlink(missing_ok=True)
        atomic_write_text(mpath, json.dumps(self._manifest(), indent=1, sort_keys=True))
        return set()

    # -- the verified family plan ----------------------------------------------------
    def save_plan(self, plan: dict) -> None:
        """Store the verified family plan (JSON): a resume reuses it instead of re-verifying,
        so the resumed chunks use exactly the same models. ``plan``: JSON-able dict."""
        atomic_write_text(self.root / PLAN, json.dumps(plan, sort_keys=True))

    def load_plan(self) -> dict | None:
        """The stored family plan, or None (none stored, or unreadable)."""
        try:
            return json.loads((self.root / PLAN).read_text())
        except (OSError, ValueError):
            return None

    # -- chunks -------------------------------------------------------------------------
    def path(self, i: int) -> Path:
        """File of chunk ``i``."""
        return self.root / f"chunk_{i:05d}.npz"

    def _readable(self, i: int) -> bool:
        p = self.path(i)
        if not p.exists():
            return False
        try:
            rows = self.load(i)
        except Exception:  # truncated/corrupt file (should not happen with atomic writes)
            return False
        start, stop = self.bounds[i]
        return rows["theta"].shape == (stop - start,)

    def write(self, i: int, rows: dict) -> Path:
        """Write chunk ``i`` (rows: its table) atomically; returns the file written."""
        arrays = {name: np.asarray(rows[name], dtype=float) for name in NUMERIC}
        for name in TEXT_COLUMNS:
            arrays[name] = np.asarray(rows[name]).astype(str)
        for name in extra_keys(rows):  # extra column providers: numbers as float, text as str
            v = np.asarray(rows[name])
            arrays[name] = v.astype(str) if v.dtype.kind in "OUS" else v.astype(float)
        p = self.path(i)
        atomic_write_bytes(p, lambda f: np.savez(f, **arrays))
        return p

    def load(self, i: int) -> dict:
        """The table of chunk ``i`` (dict of arrays)."""
        with np.load(self.path(i), allow_pickle=False) as z:
            return {name: z[name] for name in z.files}
