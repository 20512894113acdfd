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
    BurmesterPoints,
    Dyad,
    burmester,
    dyad_for_centre_point,
    dyad_for_circle_point,
)
from mech.planar.synthesis._guidance_curve import BurmesterCurve, circle_point_curve
from mech.planar.synthesis._guidance_fourbar import GuidanceFourBar, GuidanceSynthesis, guidance_fourbars

__all__ = [
    # displacements (2-31)-(2-37) and rigid-body guidance
    "displacement_matrix", "pole", "Dyad", "dyad_for_circle_point", "dyad_for_centre_point",
    "BurmesterCurve", "circle_point_curve", "BurmesterPoints", "burmester",
    "GuidanceFourBar", "GuidanceSynthesis", "guidance_fourbars",
    # function generation (2-43)-(2-45)
    "FunctionGenerator", "FunctionMap", "chebyshev_spacing", "freudenstein_coefficients",
    "least_squares", "lengths_from_coefficients", "precision_pairs",
]

from mech.planar.synthesis._path import (  # noqa: E402
    PathFourBar,
    PathSynthesis,
    path_design,
    path_residuals,
    path_timed,
    path_untimed,
)

__all__ += [
    # path generation by precision points (2-53)-(2-56)
    "PathFourBar", "PathSynthesis", "path_design", "path_residuals", "path_timed", "path_untimed",
]
