"""Planar linkages: the four-bar and the slider-crank (textbook chapter 2).

Conventions (``CONVENTIONS.md``): angles in radians, points as complex numbers
``x + 1j*y``, ground pivots ``A = 0`` and ``D = d``.
"""

from mech._errors import AssemblyError
from mech.planar._fourbar import FourBar, FourBarPose
from mech.planar._grashof import GrashofResult, grashof
from mech.planar._limit_positions import LimitPositions
from mech.planar._quick_return import extreme_angle, time_ratio
from mech.planar._slider_crank import SliderCrank, SliderCrankPose

__all__ = [
    "AssemblyError",
    "FourBar",
    "FourBarPose",
    "GrashofResult",
    "LimitPositions",
    "SliderCrank",
    "SliderCrankPose",
    "extreme_angle",
    "grashof",
    "time_ratio",
]
