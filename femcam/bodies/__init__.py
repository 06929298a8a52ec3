"""The real bodies: the roller as a ring on its pin or needles (FE, scikit-fem + gmsh).

>>> from femcam.bodies import RollerBearing, RingModel, solve_ring  # doctest: +SKIP

Modules: ``geometry`` (:class:`RollerBearing`, needle load-deflection, geometry checks),
``mesh`` (gmsh ring annulus and pin disk), ``contact`` (curved contact operators, the
multi-contact active-set solve), ``model`` (:class:`RingModel`: build once), ``solve``
(:func:`solve_ring`, :class:`RingResult`), ``rows`` (:func:`ring_rows`, sweep-facing).
"""

from .geometry import SUPPORTS, RollerBearing, bearing_problems, needle_approach
from .model import RingMeshOptions, RingModel
from .rows import CSV_COLUMNS, build_for, ring_rows, to_csv_columns
from .solve import RingResult, solve_ring

__all__ = ["CSV_COLUMNS", "SUPPORTS", "RingMeshOptions", "RingModel", "RingResult", "RollerBearing",
           "bearing_problems", "build_for", "needle_approach", "ring_rows", "solve_ring",
           "to_csv_columns"]
