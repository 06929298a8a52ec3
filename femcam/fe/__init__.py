"""Finite-element two-body contact (scikit-fem): plane elasticity per body, condensation onto
the contact vertices, active-set complementarity solve, stress recovery and VTU export.

>>> from femcam.fe import ContactModel, MeshOptions, SolverOptions, ContactResult  # doctest: +SKIP

Modules: ``elasticity`` (assembly, supports, factorisation), ``contact`` (consistent nodal
forces, compliances, LCP), ``recovery`` (stresses, half-width fit), ``model`` (``ContactModel``,
``ContactResult``, ``solve_contact``), ``export`` (VTU through meshio).
"""

from ..mesh import MeshOptions
from .model import ContactModel, ContactResult, SolverOptions, StressMax, solve_contact

__all__ = ["ContactModel", "ContactResult", "MeshOptions", "SolverOptions", "StressMax", "solve_contact"]
