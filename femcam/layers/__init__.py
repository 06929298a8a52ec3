"""Coated and case-hardened bodies: coating and case definitions, interface stresses along the
coating-substrate boundary and the case-core margin (docs/layers.md)."""

from .case import CASE_LAWS, Case, CaseMargin, case_margin, shear_strength_from_hardness
from .coating import CoatedMaterial, Coating, build_coated_model
from .from_scene import scene_layer_rows, scene_layers
from .interface import (
    LAYER_COLUMNS,
    SWEEP_COLUMNS,
    InterfaceStress,
    interface_stress,
    layer_rows,
    result_layer_row,
)

__all__ = ["CASE_LAWS", "LAYER_COLUMNS", "SWEEP_COLUMNS", "Case", "CaseMargin", "CoatedMaterial", "Coating",
           "InterfaceStress", "build_coated_model", "case_margin", "interface_stress", "layer_rows",
           "result_layer_row", "scene_layer_rows", "scene_layers", "shear_strength_from_hardness"]
