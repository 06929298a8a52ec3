"""Tribology formulas of a lubricated line contact: EHL film, flash temperature, shakedown and
contact fatigue, lubricant table, wear coefficient by lubrication regime (numpy/scipy only)."""

from .fatigue import first_yield_limit, orthogonal_shear_range, shakedown_limit, sn_cycles
from .film import (
    REGIME_NAMES,
    composite_roughness,
    dimensionless_groups,
    film_thickness,
    lubrication_regime,
)
from .flash import effusivity, flash_temperature, peclet, scuffing_safety
from .lubricants import OILS, Lubricant, lubricant
from .regime import greenwood_tripp, wear_coefficient

__all__ = [
    "OILS", "REGIME_NAMES", "Lubricant", "composite_roughness", "dimensionless_groups", "effusivity",
    "film_thickness", "first_yield_limit", "flash_temperature", "greenwood_tripp", "lubricant",
    "lubrication_regime", "orthogonal_shear_range", "peclet", "scuffing_safety", "shakedown_limit",
    "sn_cycles", "wear_coefficient",
]
