"""Cam optimisation: minimise a worst-angle objective (peak p0, von Mises, tau1, acceleration,
cam size, Archard wear) over base radius, roller radius, rise angle and the free interior
ordinates of a Bezier rise, subject to pressure-angle, undercut/curvature and lift-off limits;
SLSQP on the analytic chain, the optimum checked by the FE (docs/optimise.md).
"""

from .chain import CONSTRAINT_UNITS, OBJECTIVE_UNITS, OBJECTIVES
from .compare import COMPARE_COLUMNS, STANDARD_LAWS, compare_laws
from .design import BezierRise, Design, Variable
from .result import FECheck, OptimiseResult, StartRecord
from .solve import optimise

__all__ = ["optimise", "OptimiseResult", "StartRecord", "FECheck", "Variable", "BezierRise", "Design",
           "compare_laws", "COMPARE_COLUMNS", "STANDARD_LAWS",
           "OBJECTIVES", "OBJECTIVE_UNITS", "CONSTRAINT_UNITS"]
