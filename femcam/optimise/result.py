"""Result records of :func:`femcam.optimise.optimise`: the optimum, each start, the FE check.
Frozen, keyword-only and picklable (no solver handles inside).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

__all__ = ["OptimiseResult", "StartRecord", "FECheck"]


@dataclass(frozen=True, kw_only=True)
class StartRecord:
    """One SLSQP start: where it began and ended (SI), and how.

    Parameters
    ----------
    x0, x : tuple of float
        Start and end design (SI, in the order of ``OptimiseResult.names``).
    value : float
        Objective at ``x`` on the grid (unit of ``OptimiseResult.unit``).
    feasible, converged : bool
        Every constraint margin >= -FEAS_TOL; SLSQP's success flag.
    iterations : int
        SLSQP iterations.
    message : str
        SLSQP's message.
    """

    x0: tuple
    x: tuple
    value: float
    feasible: bool
    converged: bool
    iterations: int
    message: str


@dataclass(frozen=True, kw_only=True)
class FECheck:
    """The FE check of an optimum: :func:`femcam.sweep.sweep` at angles around the worst one.

    Parameters
    ----------
    theta : tuple of float
        Cam angles (rad).
    p0_hertz, p0_fe : tuple of float
        Hertz and FE peak pressure (Pa; NaN where the FE row failed).
    rel_diff : float
        Largest ``|p0_fe / p0_hertz - 1|`` over the angles (-).
    status : tuple of str
        Sweep row statuses.
    message : str
        Summary, or why the FE could not answer.
    """

    theta: tuple
    p0_hertz: tuple
    p0_fe: tuple
    rel_diff: float
    status: tuple
    message: str

    @property
    def ok(self) -> bool:
        """True when the FE answered at every angle (``status`` all ``ok``, a finite FE ``p0``)."""
        return bool(self.status) and all(s == "ok" for s in self.status) and bool(
            np.all(np.isfinite(np.asarray(self.p0_fe, float))))


@dataclass(frozen=True, kw_only=True)
class OptimiseResult:
    """The optimum and how it was obtained (SI; pickles; like scipy's ``OptimizeResult``).

    Parameters
    ----------
    objective, unit : str
        Objective name and its SI unit.
    value : float
        Objective at the optimum on the fine grid (the worst angle; ``unit``).
    start_value : float
        Objective at the first start on the fine grid (``unit``).
    names : tuple of str
        Design variables.
    x : tuple of float
        Optimal design (SI).
    control_points : tuple of float or None
        All Bezier ordinates of the optimal rise (None if none varied).
    program : femcam.kinematics.CamProgram
        Optimal cam program.
    follower : object
        Optimal follower.
    constraints : dict
        ``{name: {"limit": SI, "value": worst SI value, "margin": smallest margin (-)}}``;
        ``value`` is max ``|phi|`` (rad), min convex ``rho`` (m) or min ``Fc/Fpl`` at the
        lift-off speed.
    theta_worst : float
        Angle of the objective's maximum (rad).
    optimiser : str
        ``"SLSQP"`` (scipy), epigraph form, central-difference gradients.
    iterations, nfev : int
        SLSQP iterations of all runs for the best start; analytic-chain evaluations in total.
    converged : bool
        SLSQP succeeded, all margins >= -FEAS_TOL and the exchange gap is within GAP_TOL.
    message : str
        What happened, in words.
    starts : tuple of StartRecord
        Every start.
    spread : float
        Largest relative difference of the converged feasible starts' values from the best (-).
    exchange_rounds : int
        Exchange refinements of the angle grid.
    grid_gap : float
        Relative excess of the fine-grid maximum over the grid maximum at the optimum (-).
    fe : FECheck or None
        FE verification (None if not asked).
    """

    objective: str
    unit: str
    value: float
    start_value: float
    names: tuple
    x: tuple
    control_points: tuple | None
    program: object
    follower: object
    constraints: dict
    theta_worst: float
    optimiser: str
    iterations: int
    nfev: int
    converged: bool
    message: str
    starts: tuple
    spread: float
    exchange_rounds: int
    grid_gap: float
    fe: FECheck | None = None

    def design(self) -> dict:
        """The optimal design by name.

        Returns
        -------
        dict
            ``{variable: optimal value (SI)}``.
        """
        return dict(zip(self.names, self.x, strict=True))

    def apply(self, scene):
        """The optimal variant of ``scene`` (its program and follower replaced).

        Parameters
        ----------
        scene : femcam.scene.Scene
            The scene that was optimised.

        Returns
        -------
        femcam.scene.Scene
        """
        return dataclasses.replace(scene, program=self.program, follower=self.follower)
