"""Synthesis of planar linkages (textbook chapter 2, section 4): design a linkage for a task.

Every result here is a linkage that the analysis classes of `mech.planar` can move, with
the placement and the input angles that reproduce the task, so a design is checked by
analysing it.
"""

__all__ = []

from mech.planar.synthesis._displacement import displacement_matrix, pole
from mech.planar.synthesis._guidance import (
    BurmesterPoints,
    Dyad,
    burmester,
    dyad_for_centre_point,
    dyad_for_circle_point,
)
from mech.planar.synthesis._guidance_curve import BurmesterCurve, circle_point_curve
from mech.planar.synthesis._guidance_fourbar import GuidanceFourBar, GuidanceSynthesis, guidance_fourbars

__all__ += ["GuidanceFourBar", "GuidanceSynthesis", "guidance_fourbars",
            "displacement_matrix", "pole", "Dyad", "BurmesterPoints", "burmester",
            "dyad_for_circle_point", "dyad_for_centre_point", "BurmesterCurve", "circle_point_curve"]
