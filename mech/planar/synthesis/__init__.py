"""Synthesis of planar linkages (textbook chapter 2, section 4): design a linkage for a task.

Every result here is a linkage that the analysis classes of `mech.planar` can move, with
the placement and the input angles that reproduce the task, so a design is checked by
analysing it.

The modules by task: displacements and rigid-body guidance (2-31)-(2-37) with revolute and
slider dyads; function generation (2-43)-(2-45); quick-return design (2-46)-(2-52), examples
2-17 to 2-20; path generation by precision points (2-53)-(2-56), examples 2-21 and 2-22; and
design by optimisation, examples 2-23 and 2-24.
"""

from mech._exports import reexport
from mech.planar.synthesis import (
    _displacement,
    _function_generation,
    _guidance,
    _guidance_fourbar,
    _optimisation,
    _optimisation_examples,
    _optimisation_penalty,
    _path,
    _quick_return_design,
    _quick_return_search,
    _slider_guidance,
)

__all__ = reexport(globals(), _displacement, _guidance, _guidance_fourbar, _slider_guidance, _function_generation,
                   _quick_return_design, _quick_return_search, _path, _optimisation, _optimisation_penalty,
                   _optimisation_examples)

del reexport  # a helper, not a name of this package
