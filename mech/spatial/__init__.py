"""Spatial linkages: coordinate transforms, H-D matrices, the RSSR four-bar, the universal
joint and open chains (textbook chapter 2, section 5).

Conventions (``CONVENTIONS.md``): angles in radians; a matrix ``R_ij`` or ``M_ij`` maps
coordinates in frame j to coordinates in frame i; arrays of parameters give stacks.
"""

from mech.spatial._chain import ChainPose, Joint, OpenChain, example_2_25_manipulator, example_2_25_pose, example_2_25_reach
from mech.spatial._hooke import DoubleJointPose, DoubleUniversalJoint, hooke_acceleration, hooke_output, hooke_ratio
from mech.spatial._mobility import PAIR_FREEDOMS, mobility
from mech.spatial._rccc import RCCC, RCCCPose
from mech.spatial._rssr import RSSR, AssemblyRange, RSSRPose
from mech.spatial._transforms import hd, hd_inv, homogeneous, rot_x, rot_z

__all__ = [
    "AssemblyRange",
    "ChainPose",
    "DoubleJointPose",
    "DoubleUniversalJoint",
    "Joint",
    "OpenChain",
    "PAIR_FREEDOMS",
    "RCCC",
    "RCCCPose",
    "RSSR",
    "RSSRPose",
    "example_2_25_manipulator",
    "example_2_25_pose",
    "example_2_25_reach",
    "hd",
    "hd_inv",
    "homogeneous",
    "hooke_acceleration",
    "hooke_output",
    "hooke_ratio",
    "mobility",
    "rot_x",
    "rot_z",
]
