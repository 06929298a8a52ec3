"""femcam's exceptions.

Every error a user can trigger is one of these, never a traceback from deep inside numpy,
gmsh or scipy:

* :class:`InputError` (a :class:`ValueError`): a bad parameter. The message names the parameter,
  its value and its unit, e.g. ``beta = -0.5 rad: must be > 0``.
* :class:`SceneError`: a bad scene file; names the TOML key, the value and the expected unit.
* :class:`PhysicsError`: the input is well-formed but the physics cannot answer it
  (subclasses say why: Hertz validity, undercut cam, follower lift-off).
* :class:`ConvergenceError`: a nonlinear or contact solve did not converge; carries the
  residual history so the caller can see how it failed.
* :class:`WorkerLostError`: a worker process of a parallel sweep ended without its result
  (killed by the system or a signal); the message says what was saved and how to resume.
"""

from __future__ import annotations


class FemcamError(Exception):
    """Base class of all femcam errors."""


class InputError(FemcamError, ValueError):
    """A parameter has a bad value (message names parameter, value and unit)."""


class SceneError(InputError):
    """A scene file is malformed (message names key, value and expected unit)."""


class PhysicsError(FemcamError):
    """The question is well-formed but the model cannot answer it; the message says why."""


class HertzValidityError(PhysicsError):
    """Hertz line-contact theory does not apply (conformal/concave contact, R_eff <= 0)."""


class UndercutError(PhysicsError):
    """The cam profile is undercut or has a cusp (radius of curvature changes sign badly)."""


class LiftOffError(PhysicsError):
    """The follower leaves the cam (contact force <= 0)."""


class ConvergenceError(FemcamError):
    """An iterative solve failed; ``history`` holds the residual history.

    Parameters
    ----------
    message : str
        What failed and why (shown to the user).
    history : iterable of float, optional
        Residuals of the iterations (units of the solver's residual), kept as the list
        ``history`` (empty when None).
    """

    def __init__(self, message: str, history=None):
        super().__init__(message)
        self.history = list(history) if history is not None else []


class WorkerLostError(FemcamError):
    """A worker process of a parallel run ended without returning its result (the out-of-memory
    killer, ``kill -9``, a crash in a native library); the message says what was saved."""
