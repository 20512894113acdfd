"""Planar linkages: the four-bar, the slider-crank and the guide-bar (textbook chapter 2).

Conventions (``CONVENTIONS.md``): angles in radians, points as complex numbers
``x + 1j*y``, ground pivots ``A = 0`` and ``D = d``.
"""

from mech._errors import AssemblyError
from mech.planar._atlas import CouplerDashes, coupler_dashes
from mech.planar._centrodes import CentrodeSegment, CouplerCentrodes, coupler_centrodes
from mech.planar._cognates import Cognate, CognatePose, Cognates, TenBarPose, cognates
from mech.planar._instant_centres import (
    Centre,
    InstantCentres,
    LinkVelocities,
    centre_count,
    centre_velocities,
    higher_pair,
    instant_centres,
    omega_ratio,
    prismatic,
    revolute,
)
from mech.planar._triad import TriadPose, TriadSixBar
from mech.planar._double_slider import (
    EllipticTrammel,
    OldhamCoupling,
    OldhamPose,
    ScotchYoke,
    ScotchYokePose,
    TangentMechanism,
    TangentPose,
    TrammelPose,
)
from mech.planar._fourbar import FourBar, FourBarPose
from mech.planar._grashof import GrashofResult, KindInterval, grashof, kind_intervals
from mech.planar._guide_bar import GuideBar, GuideBarPose
from mech.planar._library import (
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
from mech.planar._limit_positions import LimitPositions, limit_positions
from mech.planar._linkage import AssemblyInterval, Guide, Linkage, LinkageSolution, Slide
from mech.planar._polygons import (
    Equation,
    Image,
    Polygon,
    RelativeMotion,
    Term,
    acceleration_image,
    acceleration_polygon,
    coincident_motion,
    relative_motion,
    velocity_image,
    velocity_polygon,
)
from mech.planar._quick_return import extreme_angle, time_ratio
from mech.planar._slider_crank import SliderCrank, SliderCrankLimits, SliderCrankPose, SliderCrankSeries
from mech.planar._special import RotatingGuideBar, RotatingGuideBarPose, SwingingBlock
from mech.planar._transmission import min_transmission_angle, transmission_angle

__all__ = [
    "AssemblyError",
    "AssemblyInterval",
    "Centre",
    "CentrodeSegment",
    "Cognate",
    "CognatePose",
    "Cognates",
    "CouplerCentrodes",
    "CouplerDashes",
    "EllipticTrammel",
    "Equation",
    "FourBar",
    "FourBarPose",
    "GrashofResult",
    "Guide",
    "GuideBar",
    "GuideBarPose",
    "Image",
    "InstantCentres",
    "JANSEN_HOLY_NUMBERS",
    "KindInterval",
    "LimitPositions",
    "Linkage",
    "LinkageSolution",
    "LinkVelocities",
    "OldhamCoupling",
    "OldhamPose",
    "Polygon",
    "RelativeMotion",
    "RotatingGuideBar",
    "RotatingGuideBarPose",
    "ScotchYoke",
    "ScotchYokePose",
    "Slide",
    "SliderCrank",
    "SliderCrankLimits",
    "SliderCrankPose",
    "SliderCrankSeries",
    "Stroke",
    "SwingingBlock",
    "TangentMechanism",
    "TangentPose",
    "TenBarPose",
    "Term",
    "TrammelPose",
    "TriadPose",
    "TriadSixBar",
    "acceleration_image",
    "acceleration_polygon",
    "centre_count",
    "centre_velocities",
    "cognates",
    "coincident_motion",
    "coupler_centrodes",
    "coupler_dashes",
    "extreme_angle",
    "grashof",
    "higher_pair",
    "instant_centres",
    "jansen_linkage",
    "kind_intervals",
    "limit_positions",
    "min_transmission_angle",
    "omega_ratio",
    "prismatic",
    "quick_return_crank_rocker",
    "quick_return_guide_bar",
    "quick_return_slider_crank",
    "ram_stroke",
    "relative_motion",
    "revolute",
    "shaper_stephenson",
    "shaper_watt",
    "step_ratio",
    "stephenson_six_bar",
    "time_ratio",
    "transmission_angle",
    "velocity_image",
    "velocity_polygon",
    "watt_six_bar",
]
