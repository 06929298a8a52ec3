r"""Model families: which angles share one FE model, and the verification of that reuse.

2D linear elasticity is invariant under a uniform scaling of the geometry; from angle to angle
only the gap shape and the load change. So angles are grouped into families that share one
:class:`femcam.fe.ContactModel` (mesh + factorisation + condensation) and every worker process
keeps the models it built (:class:`femcam.sweep.cache.ModelCache`).

The concept is in two modules, re-exported here (the import path of the whole concept):

- :mod:`femcam.sweep.plan`: the first guess (:func:`plan_families`: greedy clusters in the
  Hertz half-width ``a`` and in ``Rr/rho``, spans from :func:`family_spans`);
- :mod:`femcam.sweep.verify`: :func:`verify_families` checks every family's **reuse error**
  ``p0(family model) / p0(fresh model) - 1`` against the tolerance with models built fresh
  for its worst angles (:func:`check_angles`) and splits the families that exceed it.

The reuse error is a discretisation effect (two discretisations of the same problem that place
the contact edge differently relative to the nodes), of the order of the FE error itself
(~0.2 % at ``a_over_h = 10``). A tolerance far below it forces nearly one model per angle;
:data:`TOLERANCE_FLOOR` is the smallest accepted value; refine the mesh (``a_over_h``) to make
both errors smaller. Interior angles are not checked one by one: the benchmark measures the
error at independent angles (``benchmarks/bench_sweep.py``).
"""

from __future__ import annotations

from .options import TOLERANCE_FLOOR
from .plan import curvature_ratio, family_spans, hertz_half_width, plan_families
from .verify import (
    ESTIMATE_MARGIN,
    MAX_SCAN,
    N_CHECKS,
    FamilyRecord,
    check_angles,
    verify_families,
)

__all__ = ["ESTIMATE_MARGIN", "MAX_SCAN", "N_CHECKS", "TOLERANCE_FLOOR", "FamilyRecord",
           "check_angles", "curvature_ratio", "family_spans", "hertz_half_width", "plan_families",
           "verify_families"]
