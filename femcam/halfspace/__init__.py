"""Finite-length contact on the elastic half-space: influence coefficients (Love 1929), DC-FFT
(Liu, Wang & Liu 2000), the conjugate-gradient contact solver (Polonsky & Keer 1999), roller
crowns (circular, logarithmic after Lundberg 1939 and Johns & Gohar 1981) and the per-angle
cam-roller strip (see ``docs/halfspace.md``)."""

from .influence import cell_influence, dcfft_kernel
from .solver import ContactSolution, HalfSpace

__all__ = ["ContactSolution", "HalfSpace", "cell_influence", "dcfft_kernel"]
