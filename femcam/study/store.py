"""The study's record store: one small JSON file per content hash in ``DIR/variants/``,
written atomically by the client as results arrive (:func:`femcam.io.atomic_write_text`).

Content-addressed, so a record is valid for any study that meets the same variant with the same
evaluation options: a killed study resumes from the records on disk, and a variant met twice is
computed once. Workers never write here; their results return to the client.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from ..errors import InputError
from ..io import atomic_write_text

#: the store's directory inside the output directory
STORE_DIR = "variants"


class RecordStore:
    """Records by content hash, on disk under ``root`` or in memory (``root=None``).

    Parameters
    ----------
    root : str or Path or None
        The output directory (records under ``root/variants``); None: memory only.
    resume : bool
        Keep records already in ``root`` (the default for a content-addressed store).
    overwrite : bool
        Delete the records of an earlier study first.
    """

    def __init__(self, root=None, *, resume: bool = True, overwrite: bool = False):
        self.mem: dict = {}
        self.dir = None if root is None else Path(root) / STORE_DIR
        if self.dir is None:
            return
        if Path(root).exists() and not Path(root).is_dir():
            raise InputError(f"out = {root}: exists and is not a directory")
        Path(root).mkdir(parents=True, exist_ok=True)
        if self.dir.exists() and any(self.dir.iterdir()):
            if overwrite:
                shutil.rmtree(self.dir)
            elif not resume:
                raise InputError(f"out = {root}: holds a study's records ({self.dir}); resume it "
                                 "(--resume) or start afresh (--overwrite)")
        self.dir.mkdir(parents=True, exist_ok=True)
        for tmp in self.dir.glob("*.tmp"):  # leftovers of a killed write
            tmp.unlink(missing_ok=True)

    def _path(self, key: str) -> Path:
        return self.dir / f"{key}.json"

    def get(self, key: str) -> dict | None:
        """The stored record of ``key``.

        Parameters
        ----------
        key : str
            Content hash (optionally with a suffix, e.g. ``-fe``).

        Returns
        -------
        dict or None
            The record, or None when none is stored (or it is unreadable).
        """
        if key in self.mem or self.dir is None:
            return self.mem.get(key)
        try:
            rec = json.loads(self._path(key).read_text())
        except (OSError, ValueError):
            return None
        self.mem[key] = rec
        return rec

    def put(self, key: str, rec: dict) -> None:
        """Store ``rec`` under ``key`` (atomic on disk).

        Parameters
        ----------
        key : str
            Content hash.
        rec : dict
            JSON-able record (NaN allowed).
        """
        self.mem[key] = rec
        if self.dir is not None:
            atomic_write_text(self._path(key), json.dumps(rec, sort_keys=True))
