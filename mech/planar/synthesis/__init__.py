"""Synthesis of planar linkages (textbook chapter 2, section 4): design a linkage for a task.

Every result here is a linkage that the analysis classes of `mech.planar` can move, with
the placement and the input angles that reproduce the task, so a design is checked by
analysing it.
"""

from mech.planar.synthesis._displacement import displacement_matrix, pole
from mech.planar.synthesis._function_generation import (
    FunctionGenerator,
    FunctionMap,
    chebyshev_spacing,
    freudenstein_coefficients,
    least_squares,
    lengths_from_coefficients,
    precision_pairs,
)
from mech.planar.synthesis._guidance import (
    BurmesterCurve,
    BurmesterPoints,
    Dyad,
    burmester,
    circle_point_curve,
    dyad_for_centre_point,
    dyad_for_circle_point,
)
from mech.planar.synthesis._guidance_fourbar import (
    CentricSliderCrank,
    GuidanceFourBar,
    GuidanceSynthesis,
    centric_slider_cranks,
    guidance_fourbars,
)
from mech.planar.synthesis._optimisation import DesignModel, OptimisationResult, grid_search, scipy_minimize
from mech.planar.synthesis._optimisation_examples import (
    PATH_VARIABLES,
    CouplerPathDesign,
    SteeringTrapezoid,
    path_synthesis_model,
    steering_trapezoid_model,
)
from mech.planar.synthesis._optimisation_penalty import penalty_method
from mech.planar.synthesis._path import (
    PathFourBar,
    PathSynthesis,
    path_design,
    path_residuals,
    path_timed,
    path_untimed,
)
from mech.planar.synthesis._quick_return_design import (
    QuickReturnCheck,
    QuickReturnCrankRocker,
    QuickReturnGuideBar,
    QuickReturnSliderCrank,
    quick_return_crank_rocker,
    quick_return_guide_bar,
    quick_return_slider_crank,
    simulate_quick_return,
)
from mech.planar.synthesis._quick_return_search import QuickReturnFamily, crank_rocker_family, slider_crank_family
from mech.planar.synthesis._slider_guidance import (
    GuidanceSliderCrank,
    SliderCircle,
    SliderDyad,
    guidance_slider_crank,
    slider_dyad_for_point,
    slider_dyads,
    slider_point_circle,
)

__all__ = [
    # displacements (2-31)-(2-37) and rigid-body guidance
    "displacement_matrix", "pole", "Dyad", "dyad_for_circle_point", "dyad_for_centre_point",
    "BurmesterCurve", "circle_point_curve", "BurmesterPoints", "burmester",
    "GuidanceFourBar", "GuidanceSynthesis", "guidance_fourbars",
    "SliderDyad", "slider_dyad_for_point", "SliderCircle", "slider_point_circle", "slider_dyads",
    "GuidanceSliderCrank", "guidance_slider_crank", "CentricSliderCrank", "centric_slider_cranks",
    # function generation (2-43)-(2-45)
    "FunctionGenerator", "FunctionMap", "chebyshev_spacing", "freudenstein_coefficients",
    "least_squares", "lengths_from_coefficients", "precision_pairs",
    # path generation by precision points (2-53)-(2-56), examples 2-21 and 2-22
    "PathFourBar", "PathSynthesis", "path_design", "path_residuals", "path_timed", "path_untimed",
    # quick-return design (2-46)-(2-52), examples 2-17 to 2-20
    "QuickReturnCheck", "QuickReturnCrankRocker", "QuickReturnFamily", "QuickReturnGuideBar",
    "QuickReturnSliderCrank", "crank_rocker_family", "quick_return_crank_rocker",
    "quick_return_guide_bar", "quick_return_slider_crank", "simulate_quick_return",
    "slider_crank_family",
    # optimisation design, examples 2-23 and 2-24
    "DesignModel", "OptimisationResult", "grid_search", "penalty_method", "scipy_minimize",
    "PATH_VARIABLES", "CouplerPathDesign", "SteeringTrapezoid", "path_synthesis_model",
    "steering_trapezoid_model",
]
