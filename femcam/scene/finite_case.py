"""A roller's finite-length contact as the physics packages take it (:class:`FiniteCase`):
the records :func:`femcam.halfspace.strip_for` reads and the design revolution of a logarithmic
crown, so that femcam.halfspace and femcam.wear.axial never see the whole
:class:`~femcam.scene.Scene`.

:func:`finite_case` is the adapter: it checks that the follower is a roller and, for a
logarithmic crown, analyses the scene over one revolution (:data:`DESIGN_N` angles) for the
design load. The contact at the cam angles themselves is the caller's ``Scene.analyse(theta)``
(or a :class:`~femcam.scene.case.ContactCase`'s state).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import _validate
from ..errors import InputError
from ..halfspace.rows import has_finite_length, strip_for
from ..halfspace.strip import FiniteLengthContact
from .finite import FiniteLength
from .pair import ContactPair
from .state import Scene, SceneState

#: uniform angles over one revolution whose largest contact force designs a logarithmic crown
DESIGN_N = 720


@dataclass(frozen=True, kw_only=True)
class FiniteCase:
    """A roller's finite-length contact (keyword-only; built by :func:`finite_case`), SI units.

    Parameters
    ----------
    finite : femcam.scene.FiniteLength or None
        The finite-length keys (m, rad; ``Scene.finite_length``); None without a face width (a
        straight roller as wide as the cam).
    pair : femcam.scene.ContactPair
        Materials (Pa), contact length (m), plane, friction.
    Rr : float
        Roller radius (m).
    design : femcam.scene.SceneState or None
        The scene on :data:`DESIGN_N` uniform angles over one revolution (rad), whose largest
        contact force designs a logarithmic crown; None for any other crown.
    """

    finite: FiniteLength | None
    pair: ContactPair
    Rr: float
    design: SceneState | None = None

    def __post_init__(self):
        _validate.optional(_validate.instance, "finite", self.finite, FiniteLength,
                           "a femcam.scene.FiniteLength or None")
        _validate.instance("pair", self.pair, ContactPair, "a femcam.scene.ContactPair")
        object.__setattr__(self, "Rr", _validate.positive("Rr", self.Rr, "m"))
        _validate.optional(_validate.instance, "design", self.design, SceneState,
                           "a femcam.scene.SceneState or None")

    @property
    def applies(self) -> bool:
        """True when the scene asks for the finite-length contact
        (:func:`femcam.halfspace.has_finite_length` of ``finite`` and the contact length)."""
        return has_finite_length(self.finite, self.pair.length)

    def strip(self, *, nx: int = 64, ny: int = 128, tol: float = 1e-5) -> FiniteLengthContact:
        """The half-space strip of the roller (:func:`femcam.halfspace.strip_for`).

        Parameters
        ----------
        nx, ny : int
            Cells across the contact (rolling direction) and along the axis [-].
        tol : float
            Relative pressure-change tolerance of the conjugate gradients [-].

        Returns
        -------
        femcam.halfspace.FiniteLengthContact
            The strip; a logarithmic crown designed for the largest contact force [N] of
            ``design`` at its relative radius [m].
        """
        d = self.design
        return strip_for(self.finite, self.pair, self.Rr, Fc=None if d is None else d.Fc,
                         rho=None if d is None else d.rho, nx=nx, ny=ny, tol=tol)


def finite_case(scene: Scene) -> FiniteCase:
    """The :class:`FiniteCase` of a roller scene.

    Parameters
    ----------
    scene : femcam.scene.Scene
        A scene with a roller follower (its ``finite_length``, ``pair`` and roller radius, m).

    Returns
    -------
    FiniteCase
        The records; ``design`` analysed on :data:`DESIGN_N` angles (rad) for a logarithmic
        crown.

    Raises
    ------
    InputError
        If the follower is not a roller (``Rr`` not > 0).
    """
    _validate.record("scene", scene, "a femcam.scene.Scene", "follower", "analyse", "finite_length")
    Rr = getattr(scene.follower, "Rr", 0.0)
    if not Rr > 0.0:
        raise InputError(f"follower = {type(scene.follower).__name__}: the finite-length half-space "
                         "contact needs a roller follower (a knife edge or flat face is not a line contact "
                         "of two cylinders)")
    fl = scene.finite_length
    design = None
    if fl is not None and fl.roller_profile().crown == "logarithmic":
        design = scene.analyse(np.linspace(0.0, 2.0 * math.pi, DESIGN_N, endpoint=False))
    return FiniteCase(finite=fl, pair=scene.pair, Rr=Rr, design=design)
