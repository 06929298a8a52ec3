"""One gmsh session at a time: :data:`GMSH_LOCK` and :func:`gmsh_session` (the only place gmsh
is imported; used by the contact mesh and by :mod:`femcam.bodies`), and :func:`gmsh_kept` (gmsh
initialised once for the background model builds of a sweep)."""

from __future__ import annotations

import signal
import threading
from contextlib import contextmanager

from ..errors import FemcamError

#: Held around every use of gmsh (initialise, mesh, finalise): gmsh keeps one global state per
#: process and is not thread-safe (Dask runs several tasks in threads of one worker process).
GMSH_LOCK = threading.RLock()


@contextmanager
def gmsh_session(what: str):
    """An initialised gmsh, held under :data:`GMSH_LOCK`.

    gmsh is initialised here only if it is not already, and finalised on exit if it was
    initialised here.

    Parameters
    ----------
    what : str
        What is meshed, for the error message (e.g. ``"the contact region"``).

    Yields
    ------
    module
        The ``gmsh`` module, terminal output off.

    Raises
    ------
    FemcamError
        ``"gmsh failed to mesh <what>: ..."`` for any gmsh failure (gmsh raises plain
        ``Exception``); a :class:`FemcamError` raised inside passes unchanged.
    """
    import gmsh  # lazy: gmsh is a large native library, loaded only to build meshes

    with GMSH_LOCK:  # gmsh is one global, non-thread-safe state per process
        init_here = not gmsh.isInitialized()
        if init_here:
            _initialize(gmsh)
        elif _KEPT:
            # a gmsh kept open by gmsh_kept carries the options of the last mesh into the next
            # (the meshes then depended on the build order): every session starts from the
            # defaults, as a freshly initialised gmsh does (same nodes, bit for bit)
            gmsh.option.restoreDefaults()
        try:
            gmsh.option.setNumber("General.Terminal", 0)
            gmsh.option.setNumber("General.Verbosity", 1)
            yield gmsh
        except FemcamError:
            raise
        except Exception as exc:  # gmsh raises plain Exception
            raise FemcamError(f"gmsh failed to mesh {what}: {exc}") from None
        finally:
            if init_here:
                gmsh.finalize()


#: open :func:`gmsh_kept` contexts that initialised gmsh
_KEPT = 0


def _initialize(gmsh) -> None:
    """``gmsh.initialize`` with Python's signal handlers kept."""
    # interruptible=False: gmsh would install its own SIGINT handler (which ends the process
    # silently on Ctrl-C, and which Python allows only in the main thread, while Dask runs
    # tasks in worker threads); Python's KeyboardInterrupt stays in charge
    kept = _python_handlers()
    gmsh.initialize(["-nopopup"], readConfigFiles=False, interruptible=False)
    _reinstall(kept)  # gmsh resets SIGTERM to its default (the process dies silently)


@contextmanager
def gmsh_kept():
    """gmsh initialised for a phase of many meshes, from the thread that enters (the main one).

    A :func:`gmsh_session` opened meanwhile, in any thread, neither initialises nor finalises
    gmsh: ``gmsh.initialize`` resets the process's SIGTERM handler, which Python can install
    again only from the main thread, so meshes built in background threads
    (:class:`femcam._threads.Background`) need gmsh initialised before. Each session then
    starts from gmsh's default options (:func:`gmsh_session`). Nothing is done when gmsh is
    initialised already (by the caller's own code).

    Yields
    ------
    None
    """
    global _KEPT
    import gmsh  # lazy: gmsh is a large native library, loaded only to build meshes

    with GMSH_LOCK:
        own = not gmsh.isInitialized()
        if own:
            _initialize(gmsh)
            _KEPT += 1
    try:
        yield
    finally:
        if own:
            with GMSH_LOCK:
                _KEPT -= 1
                gmsh.finalize()


def _python_handlers() -> dict:
    """The Python handlers of SIGINT and SIGTERM ({} off the main thread, where Python can
    install none)."""
    if threading.current_thread() is not threading.main_thread():
        return {}
    return {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}


def _reinstall(handlers: dict) -> None:
    """Install ``handlers`` again: ``gmsh.initialize`` replaces the C-level SIGTERM handler, so
    the command line's one-line exit 143 (femcam._interrupt) would be lost."""
    for s, h in handlers.items():
        if h is not None:
            signal.signal(s, h)
