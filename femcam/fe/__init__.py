"""Finite-element two-body contact (scikit-fem): plane elasticity per body, condensation onto
the contact vertices, active-set complementarity solve, stress recovery and VTU export.

>>> from femcam.fe import ContactModel, MeshOptions, SolverOptions, ContactResult  # doctest: +SKIP

Modules: ``elasticity`` (assembly, supports, factorisation), ``contact`` (consistent nodal
forces, compliances, LCP), ``recovery`` (stresses, half-width fit), ``model`` (``ContactModel``,
``ContactResult`` with the stress maxima and both bodies' surface stresses, ``solve_contact``),
``export`` (VTU through meshio).
"""

from ..mesh import MeshOptions
from .model import (
    MAXIMA_KEYS,
    ContactModel,
    ContactResult,
    SolverOptions,
    StressMax,
    SurfaceStress,
    solve_contact,
)

__all__ = ["MAXIMA_KEYS", "ContactModel", "ContactResult", "MeshOptions", "SolverOptions", "StressMax",
           "SurfaceStress", "solve_contact"]
