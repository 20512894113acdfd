"""Rigid-body guidance on the sphere (the spherical monograph, chapter 3): displacements and
poles, spherical cranks and sliders for two to five orientations, the Burmester cubics and
points, and the four-bars they make, each checked by analysis with `SphericalFourBar`.

Every name is re-exported from `mech.spherical`.
"""

from mech.spherical.guidance._burmester import (
    SphericalBurmesterCurve,
    SphericalBurmesterPoints,
    burmester,
    circle_point_curve,
    slider_dyads,
    slider_point_curve,
)
from mech.spherical.guidance._dyads import (
    SphericalDyad,
    dyad_for_centre_point,
    dyad_for_circle_point,
    slider_dyad_for_point,
)
from mech.spherical.guidance._fourbar import SphericalGuidanceFourBar, guidance_fourbars, guidance_slider_crank
from mech.spherical.guidance._optimal import (
    SphericalGuidanceMotion,
    SphericalOptimalGuidance,
    guidance_motion,
    optimal_guidance,
)
from mech.spherical.guidance._sixbar import SphericalGuidanceSixBar, guidance_watt2, sixbar_orientations
from mech.spherical.guidance._sixbar_optimal import SphericalOptimalSixBar, optimal_guidance_watt2
from mech.spherical.guidance._sixbar_optimal_exact import optimal_guidance_sixbar
from mech.spherical.guidance._stephenson3_optimal import SphericalOptimalStephenson3, optimal_guidance_stephenson3
from mech.spherical.guidance._stephenson3 import SphericalGuidanceStephenson3, guidance_stephenson3
from mech.spherical.guidance._sixbar_exact import (
    SphericalExactSixBar, guidance_stephenson1, guidance_stephenson2, guidance_watt1)
from mech.spherical.guidance._orientations import (
    crank_residual,
    planar_orientations,
    pole_triangle,
    relative_rotation,
    rotation_pole,
    slider_residual,
)

__all__ = [
    "relative_rotation", "rotation_pole", "pole_triangle", "crank_residual", "slider_residual", "planar_orientations",
    "SphericalDyad", "dyad_for_circle_point", "dyad_for_centre_point", "slider_dyad_for_point",
    "SphericalBurmesterCurve", "SphericalBurmesterPoints", "circle_point_curve", "slider_point_curve", "burmester", "slider_dyads",
    "SphericalGuidanceFourBar", "guidance_fourbars", "guidance_slider_crank",
    "SphericalGuidanceMotion", "SphericalOptimalGuidance", "guidance_motion", "optimal_guidance",
    "SphericalGuidanceSixBar", "guidance_watt2", "sixbar_orientations", "SphericalOptimalSixBar", "optimal_guidance_watt2",
    "optimal_guidance_sixbar", "SphericalOptimalStephenson3", "optimal_guidance_stephenson3",
    "SphericalGuidanceStephenson3", "guidance_stephenson3",
    "SphericalExactSixBar", "guidance_stephenson1", "guidance_stephenson2", "guidance_watt1",
]
