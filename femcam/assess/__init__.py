"""Will it fail? Per-angle assessment of a lubricated cam-follower contact (film thickness and
lambda, flash temperature and scuffing, yield, shakedown, subsurface and surface fatigue, wear
coefficient of the lubrication regime), from a scene and optionally a sweep table."""

from .core import (
    COLUMNS,
    WORST,
    Assessment,
    assess,
    assess_rows,
    csv_columns,
    wear_factor,
    worst_angles,
)
from .inputs import AssessInputs, assessment_inputs
from .sweep_dir import sweep_table

__all__ = ["COLUMNS", "WORST", "AssessInputs", "Assessment", "assess", "assess_rows", "assessment_inputs",
           "csv_columns", "sweep_table", "wear_factor", "worst_angles"]
