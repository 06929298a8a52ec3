"""Finite-length contact on the elastic half-space: influence coefficients (Love 1929), DC-FFT
(Liu, Wang & Liu 2000), the conjugate-gradient contact solver (Polonsky & Keer 1999), roller
crowns (circular, logarithmic after Lundberg 1939 and Johns & Gohar 1981) and the per-angle
cam-roller strip (see ``docs/halfspace.md``). numpy/scipy only."""

from .crown import CROWNS, RollerProfile, circular_drop, edge_drop, log_drop
from .influence import cell_influence, dcfft_kernel
from .rows import COLUMNS, anchor_angles, finite_length_rows, has_finite_length, strip_for, to_csv_columns
from .solver import ContactSolution, HalfSpace
from .strip import FiniteLengthContact, StripResult

__all__ = ["COLUMNS", "CROWNS", "ContactSolution", "FiniteLengthContact", "HalfSpace", "RollerProfile",
           "StripResult", "anchor_angles", "cell_influence", "circular_drop", "dcfft_kernel", "edge_drop",
           "finite_length_rows", "has_finite_length", "log_drop", "strip_for", "to_csv_columns"]
