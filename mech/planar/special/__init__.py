"""Special mechanisms and ready-made linkages (textbook §2.2, Table 2-1, Fig. 2-11).

The inversions of the slider-crank chain beyond the slider-crank and the oscillating
guide-bar (rotating guide-bar, swinging and turning block), the four-bars with two
prismatic pairs (elliptic trammel, Scotch yoke, tangent mechanism, Oldham coupling), and a
library of named linkages: Stephenson and Watt six-bars, shapers, quick-return linkages
and Jansen's leg.
"""

from mech.planar.special._double_slider import (
    EllipticTrammel,
    OldhamCoupling,
    OldhamPose,
    ScotchYoke,
    ScotchYokePose,
    TangentMechanism,
    TangentPose,
    TrammelPose,
)
from mech.planar.special._library import (
    JANSEN_HOLY_NUMBERS,
    Stroke,
    jansen_linkage,
    quick_return_crank_rocker,
    quick_return_guide_bar,
    quick_return_slider_crank,
    ram_stroke,
    shaper_stephenson,
    shaper_watt,
    step_ratio,
    stephenson_six_bar,
    watt_six_bar,
)
from mech.planar.special._special import RotatingGuideBar, RotatingGuideBarPose, SwingingBlock

__all__ = [
    "EllipticTrammel",
    "JANSEN_HOLY_NUMBERS",
    "OldhamCoupling",
    "OldhamPose",
    "RotatingGuideBar",
    "RotatingGuideBarPose",
    "ScotchYoke",
    "ScotchYokePose",
    "Stroke",
    "SwingingBlock",
    "TangentMechanism",
    "TangentPose",
    "TrammelPose",
    "jansen_linkage",
    "quick_return_crank_rocker",
    "quick_return_guide_bar",
    "quick_return_slider_crank",
    "ram_stroke",
    "shaper_stephenson",
    "shaper_watt",
    "step_ratio",
    "stephenson_six_bar",
    "watt_six_bar",
]
