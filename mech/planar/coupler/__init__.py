"""Coupler curves of the four-bar (textbook §2.2, part II, Figs. 2-30 and 2-32).

The atlas pages that sample a coupler curve as dashes of equal crank rotation, the fixed
and moving centrodes of the coupler (example 2-4), and the three Roberts-Chebyshev
cognates that trace one coupler curve, and the implicit coupler sextic.
"""

from mech.planar.coupler._atlas import CouplerDashes, coupler_dashes
from mech.planar.coupler._centrodes import CentrodeSegment, CouplerCentrodes, coupler_centrodes
from mech.planar.coupler._cognates import Cognate, CognatePose, Cognates, TenBarPose, cognates
from mech.planar.coupler._sextic import coupler_sextic

__all__ = [
    "CentrodeSegment",
    "Cognate",
    "CognatePose",
    "Cognates",
    "CouplerCentrodes",
    "CouplerDashes",
    "TenBarPose",
    "cognates",
    "coupler_centrodes",
    "coupler_dashes",
    "coupler_sextic",
]
