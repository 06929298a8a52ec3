"""Read only regular files, of bounded size: a FIFO would block for ever, ``/dev/zero`` never
ends, a directory or a device is not an input. One error line names the file and why.

The file is opened with ``O_NONBLOCK`` (opening a FIFO with no writer then returns at once
instead of waiting), its type and size are checked with ``fstat`` on the open descriptor (no
race between the check and the read), and at most ``max_bytes + 1`` bytes are read (a file
that grows while read is refused too).
"""

from __future__ import annotations

import errno
import os
import stat

from .errors import InputError

#: the kind of a non-regular file, for the message
_KINDS = ((stat.S_ISDIR, "a directory"), (stat.S_ISFIFO, "a FIFO (named pipe)"),
          (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
          (stat.S_ISSOCK, "a socket"))


def check_regular(path, what: str, max_bytes: int, error=InputError) -> int:
    """Refuse ``path`` unless it is a regular file of at most ``max_bytes`` (not read).

    Parameters
    ----------
    path : str or os.PathLike
        The file.
    what : str
        How the message names it.
    max_bytes : int
        Largest accepted size (bytes).
    error : type, optional
        The exception class raised (default :class:`~femcam.errors.InputError`).

    Returns
    -------
    int
        Its size (bytes).

    Raises
    ------
    InputError
        (or ``error``) as :func:`read_regular`.
    """
    fd = _open(path, what, error)
    try:
        return _check(fd, path, what, max_bytes, error)
    finally:
        os.close(fd)


def _open(path, what, error) -> int:
    try:
        return os.open(path, os.O_RDONLY | os.O_NONBLOCK)
    except FileNotFoundError:
        raise error(f"{what} {path}: not found") from None
    except OSError as exc:  # permission denied, a path under a file, a loop of links
        raise error(f"{what} {path}: cannot be read ({exc.strerror or exc})") from None


def _check(fd, path, what, max_bytes, error) -> int:
    st = os.fstat(fd)
    for test, kind in _KINDS:
        if test(st.st_mode):
            if kind == "a directory":
                hint = "; give a .toml file" if "scene" in what else ""
                raise error(f"{what} {path}: is a directory{hint}")
            raise error(f"{what} {path}: is {kind}, not a regular file")
    if st.st_size > max_bytes:
        raise error(f"{what} {path}: {st.st_size:,} bytes, above the cap of {max_bytes:,} bytes")
    return st.st_size


def read_regular(path, what: str, max_bytes: int, error=InputError) -> bytes:
    """The bytes of the regular file ``path``, refused if it is anything else or too large.

    Parameters
    ----------
    path : str or os.PathLike
        The file.
    what : str
        How the message names it (``"scene file"``, ``"--sweep (sweep.npz)"``).
    max_bytes : int
        Largest accepted size (bytes).
    error : type, optional
        The exception class raised (default :class:`~femcam.errors.InputError`).

    Returns
    -------
    bytes
        The content.

    Raises
    ------
    InputError
        (or ``error``) ``"<what> <path>: <why>"``: not found, a directory (or FIFO, device,
        socket), unreadable, or larger than ``max_bytes``.
    """
    fd = _open(path, what, error)
    try:
        _check(fd, path, what, max_bytes, error)
        os.set_blocking(fd, True)
        chunks, n = [], 0
        while n <= max_bytes:
            b = os.read(fd, min(1 << 20, max_bytes + 1 - n))
            if not b:
                break
            chunks.append(b)
            n += len(b)
        if n > max_bytes:
            raise error(f"{what} {path}: more than {max_bytes:,} bytes, above the cap")
        return b"".join(chunks)
    except OSError as exc:
        raise error(f"{what} {path}: cannot be read ({exc.strerror or exc})") from None
    finally:
        os.close(fd)


def os_error_line(exc: OSError) -> str:
    """The reason and the path(s) of an ``OSError`` on one line.

    Parameters
    ----------
    exc : OSError
        The error (``strerror``, ``filename``, ``filename2``).

    Returns
    -------
    str
        e.g. ``"No space left on device: 'DIR/sweep.csv'"`` (with a hint on a full disk).
    """
    why = exc.strerror or str(exc) or type(exc).__name__
    if exc.errno == errno.ENOSPC:
        why += " (free some space, then rerun; a sweep can continue with --resume)"
    names = [repr(str(f)) for f in (exc.filename, exc.filename2) if f is not None]
    return f"{why}: {' -> '.join(names)}" if names else why
