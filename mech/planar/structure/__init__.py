"""Structure and types of the four-bar (textbook §2.1 and the start of §2.2).

What the link lengths alone decide: the Grashof classification and the kinds of motion of
the chain (eqs. 2-1 to 2-8), the limit positions, swing and extreme angle of the
crank-rocker, and the time ratio K of quick return (eq. 2-9). The book covers these in the
part "Structure and types of four-bars" and the first pages of "Kinematics".
"""

from mech.planar.structure._grashof import GrashofResult, KindInterval, grashof, kind_intervals
from mech.planar.structure._limit_positions import LimitPositions, limit_positions
from mech.planar.structure._quick_return import extreme_angle, time_ratio

__all__ = [
    "GrashofResult",
    "KindInterval",
    "LimitPositions",
    "extreme_angle",
    "grashof",
    "kind_intervals",
    "limit_positions",
    "time_ratio",
]
