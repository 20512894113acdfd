"""Kinematic analysis of planar linkages (textbook §2.2, parts I and II).

Positions, velocities and accelerations: the revolute four-bar (with its change points),
the slider-crank and the oscillating guide-bar of the analytical method; any linkage of
revolute and sliding pairs built from a driver and class II Assur groups, with its assembly
modes through change points; the class III triad of example 2-6; instant centres by the
three-centre theorem (F32 to F37); and the relative-motion method's velocity and
acceleration polygons and images (F38 to F43).
"""

from mech.planar.kinematics._fourbar import FourBar, FourBarPose
from mech.planar.kinematics._guide_bar import GuideBar, GuideBarPose
from mech.planar.kinematics._instant_centres import (
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
from mech.planar.kinematics._linkage import AssemblyInterval, Guide, Linkage, LinkageSolution, Slide
from mech.planar.kinematics._polygons import (
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
from mech.planar.kinematics._slider_crank import (
    SliderCrank,
    SliderCrankLimits,
    SliderCrankPose,
    SliderCrankSeries,
)
from mech.planar.kinematics._triad import TriadPose, TriadSixBar

__all__ = [
    "AssemblyInterval",
    "Centre",
    "Equation",
    "FourBar",
    "FourBarPose",
    "Guide",
    "GuideBar",
    "GuideBarPose",
    "Image",
    "InstantCentres",
    "LinkVelocities",
    "Linkage",
    "LinkageSolution",
    "Polygon",
    "RelativeMotion",
    "Slide",
    "SliderCrank",
    "SliderCrankLimits",
    "SliderCrankPose",
    "SliderCrankSeries",
    "Term",
    "TriadPose",
    "TriadSixBar",
    "acceleration_image",
    "acceleration_polygon",
    "centre_count",
    "centre_velocities",
    "coincident_motion",
    "higher_pair",
    "instant_centres",
    "omega_ratio",
    "prismatic",
    "relative_motion",
    "revolute",
    "velocity_image",
    "velocity_polygon",
]
