"""Finite-element two-body contact (scikit-fem): plane elasticity per body, condensation onto
the contact vertices, active-set complementarity solve, stress recovery and VTU export.

>>> from femcam.fe import ContactModel, MeshOptions, SolverOptions, ContactResult  # doctest: +SKIP

Modules: ``elasticity`` (assembly, supports, factorisation), ``contact`` (consistent nodal
forces, compliances, LCP), ``recovery`` (stresses, half-width fit), ``passrange`` (the range of
``txz`` over one pass from the subsurface field), ``model`` (``ContactModel``,
``solve_contact``), ``result`` (``ContactResult`` with the stress maxima, the ``txz`` range and
both bodies' surface stresses), ``export`` (VTU through meshio), ``traction`` (partial slip),
``gap``, ``followers``, ``angles``, ``choice`` (exact gap, follower types, angle sets and the
model choice).
"""

from ..mesh import MeshOptions
from .model import ContactModel, SolverOptions, solve_contact
from .result import MAXIMA_KEYS, ContactResult, ShearRange, StressMax, SurfaceStress

__all__ = ["MAXIMA_KEYS", "ContactModel", "ContactResult", "MeshOptions", "ShearRange", "SolverOptions",
           "StressMax", "SurfaceStress", "solve_contact"]
