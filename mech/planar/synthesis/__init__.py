"""Synthesis of planar linkages (textbook chapter 2, section 4): design a linkage for a task.

Every result here is a linkage that the analysis classes of `mech.planar` can move, with
the placement and the input angles that reproduce the task, so a design is checked by
analysing it.
"""

from mech.planar.synthesis._function_generation import (
    FunctionGenerator,
    FunctionMap,
    chebyshev_spacing,
    freudenstein_coefficients,
    least_squares,
    lengths_from_coefficients,
    precision_pairs,
)

__all__ = [
    "FunctionGenerator",
    "FunctionMap",
    "chebyshev_spacing",
    "freudenstein_coefficients",
    "least_squares",
    "lengths_from_coefficients",
    "precision_pairs",
]
