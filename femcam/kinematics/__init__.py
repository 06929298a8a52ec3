"""Kinematics: normalised motion laws and cam programs (rise / dwell / fall), SVAJ, junctions.

>>> from math import pi
>>> from femcam.kinematics import law, rise, dwell, fall, CamProgram
>>> prog = CamProgram([rise(pi / 2, 0.01, "poly345"), dwell(pi / 2),
...                    fall(pi / 2, 0.01, "cycloidal"), dwell(pi / 2)])
>>> round(float(prog.derivatives(pi / 4).s), 6)  # half-way up the 3-4-5 rise
0.005

Only numpy and scipy are imported.
"""

from .laws import LAW_NAMES, LawEnds, MotionLaw, bernstein, law
from .program import (
    SVAJ,
    CamProgram,
    Derivatives,
    Junction,
    Segment,
    dwell,
    fall,
    junction_report,
    rise,
)

__all__ = [
    "LAW_NAMES",
    "LawEnds",
    "MotionLaw",
    "bernstein",
    "law",
    "SVAJ",
    "CamProgram",
    "Derivatives",
    "Junction",
    "Segment",
    "dwell",
    "fall",
    "junction_report",
    "rise",
]
