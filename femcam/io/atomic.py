"""Atomic file writes: every file femcam writes (tables, VTU, the sweep's chunk store) is
written to a temp file next to its destination (``<name>.<random>.tmp``, :data:`TEMP_SUFFIX`) and
renamed over it, so a reader sees either the old file or the whole new one."""

from __future__ import annotations

import os
import tempfile
from collections.abc import Callable
from pathlib import Path

#: the suffix of the temp file an atomic write renames over its destination
TEMP_SUFFIX = ".tmp"


def _umask() -> int:
    """The process umask, read without changing it where possible (Linux /proc), else by the
    classic set-and-restore."""
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    old = os.umask(0o022)
    os.umask(old)
    return old


def atomic_write_bytes(path, write: Callable) -> None:
    """Call ``write(fileobj)`` on a temp file next to ``path``, fsync, then rename over ``path``.

    Parameters
    ----------
    path : str or Path
        Destination file; a reader sees either the old file or the whole new one.
    write : callable
        ``write(f)`` writes the content to the binary file object ``f``.

    Notes
    -----
    The file gets the mode an ordinary ``open(path, "w")`` would give (``0o666 & ~umask``), not
    mkstemp's private 0600.
    """
    def write_file(tmp):
        with open(tmp, "wb") as f:
            write(f)
            f.flush()
            os.fsync(f.fileno())

    atomic_write_path(path, write_file)


def atomic_write_path(path, write: Callable) -> None:
    """Call ``write(tmp)`` with the path of a temp file next to ``path``, then rename it over
    ``path`` (for writers that take a file name, not a file object: meshio).

    Parameters
    ----------
    path : str or Path
        Destination file, in an existing folder. A reader sees either the old file or the
        whole new one; on any error (a full disk, Ctrl-C) the temp file is removed.
    write : callable
        ``write(tmp)`` writes the whole content to the file ``tmp`` (a ``Path`` ending in
        :data:`TEMP_SUFFIX`).

    Notes
    -----
    The file gets the mode an ordinary ``open(path, "w")`` would give (``0o666 & ~umask``), not
    mkstemp's private 0600.
    """
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=path.name + ".", suffix=TEMP_SUFFIX, dir=path.parent)
    os.close(fd)
    try:
        write(Path(tmp))
        os.chmod(tmp, 0o666 & ~_umask())
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def atomic_write_text(path, text: str) -> None:
    """Write ``text`` to ``path`` atomically (:func:`atomic_write_bytes`).

    Parameters
    ----------
    path : str or Path
        Destination file.
    text : str
        Content, written as UTF-8.
    """
    atomic_write_bytes(Path(path), lambda f: f.write(text.encode("utf-8")))

