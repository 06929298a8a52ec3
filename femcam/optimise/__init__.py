"""Cam optimisation: minimise a worst-angle objective (peak p0, von Mises, tau1, acceleration,
cam size, Archard wear) over base radius, roller radius, rise angle and the free interior
ordinates of a Bezier rise, subject to pressure-angle, undercut/curvature and lift-off limits;
SLSQP on the analytic chain, the optimum checked by the FE (docs/optimise.md).
"""

from .chain import CONSTRAINT_UNITS, OBJECTIVE_UNITS, OBJECTIVES
from .design import BezierRise, Design, Variable
from .solve import FECheck, OptimiseResult, StartRecord, optimise

__all__ = ["optimise", "OptimiseResult", "StartRecord", "FECheck", "Variable", "BezierRise", "Design",
           "OBJECTIVES", "OBJECTIVE_UNITS", "CONSTRAINT_UNITS"]
