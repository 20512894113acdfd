"""Spatial linkages: coordinate transforms, H-D matrices, the RSSR four-bar, the universal
joint and open chains (textbook chapter 2, section 5).

Conventions (``CONVENTIONS.md``): angles in radians; a matrix ``R_ij`` or ``M_ij`` maps
coordinates in frame j to coordinates in frame i; arrays of parameters give stacks.
"""

from mech.spatial._hooke import DoubleJointPose, DoubleUniversalJoint, hooke_acceleration, hooke_output, hooke_ratio
from mech.spatial._mobility import PAIR_FREEDOMS, mobility
from mech.spatial._rssr import RSSR, AssemblyRange, RSSRPose

__all__ = [
    "AssemblyRange",
    "DoubleJointPose",
    "DoubleUniversalJoint",
    "PAIR_FREEDOMS",
    "RSSR",
    "RSSRPose",
    "hooke_acceleration",
    "hooke_output",
    "hooke_ratio",
    "mobility",
]
