"""The real bodies: the roller as a ring on its pin or needles (FE, scikit-fem + gmsh).

>>> from femcam.bodies import RollerBearing, RingModel, solve_ring  # doctest: +SKIP

Modules: ``geometry`` (:class:`RollerBearing`, needle load-deflection, geometry checks),
``mesh`` (gmsh ring annulus and pin disk), ``contact`` (curved contact operators, the
multi-contact active-set solve), ``model`` (:class:`RingModel`: build once), ``solve``
(:func:`solve_ring`, :class:`RingResult`), ``rows`` (:func:`ring_rows`, sweep-facing).

The cam as a disk on its shaft (``[cam] bore_mm``): ``cam_geometry`` (:class:`CamDisk`),
``cam_mesh`` (gmsh), ``cam_model`` (:class:`CamDiskModel`, fully refined, one angle),
``cam_solve`` (:func:`solve_cam_disk`), ``cam_global`` (:class:`CamGlobalModel`, the whole
revolution), ``cam_rows`` (:func:`cam_disk_rows`, sweep-facing), ``cam_study``, ``cam_export``
(the arrays of the VTU files :mod:`femcam.io` writes).
"""

from .cam_geometry import CamDisk
from .cam_global import CamGlobalModel
from .cam_model import CamDiskModel, CamMeshOptions
from .cam_rows import CAM_CSV_COLUMNS, cam_disk_rows
from .cam_solve import CamDiskResult, solve_cam_disk
from .geometry import SUPPORTS, RollerBearing, bearing_problems, needle_approach
from .model import RingMeshOptions, RingModel
from .rows import CSV_COLUMNS, build_for, ring_rows, to_csv_columns
from .solve import RingResult, solve_ring

__all__ = ["CAM_CSV_COLUMNS", "CSV_COLUMNS", "SUPPORTS", "CamDisk", "CamDiskModel", "CamDiskResult",
           "CamGlobalModel", "CamMeshOptions", "RingMeshOptions", "RingModel", "RingResult", "RollerBearing",
           "bearing_problems", "build_for", "cam_disk_rows", "needle_approach", "ring_rows", "solve_cam_disk",
           "solve_ring", "to_csv_columns"]
