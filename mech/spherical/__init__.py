"""Spherical mechanisms: the spherical calculus, the spherical four-bar and its types, the
side-angle laws of spherical polygons, the transference principle and function generation
(the spherical monograph, chapters 1, 5, 6 and 7).

Conventions (``CONVENTIONS.md``): the sphere has unit radius, arcs are radians in (0, pi),
points are unit 3-vectors in arrays of shape ``(..., 3)``, and ``lon`` is 0 at the poles.
"""

from mech.spherical._fourbar import SphericalFourBar, SphericalFourBarPose, ground_frame
from mech.spherical._function_generation import (
    FunctionGenerator,
    arcs_from_coefficients,
    chebyshev_spacing,
    freudenstein_coefficients,
    least_squares,
    precision_pairs,
)
from mech.spherical._polygons import (
    PolygonRelations,
    SphericalPolygon,
    chain_components,
    close_polygon,
    cosine_law,
    law_count,
    open_chain_axes,
    polygon_relations,
    sine_cosine_law,
    sine_law,
)
from mech.spherical._special import (
    SliderStroke,
    deltoid,
    deltoid_input,
    isogram,
    isogram_output,
    slider_crank_stroke,
    spherical_slider_crank,
    universal_joint,
)
from mech.spherical._types import SphericalType, antipode_reduction, classify, inversions

__all__ = [
    "FunctionGenerator",
    "PolygonRelations",
    "SliderStroke",
    "SphericalFourBar",
    "SphericalFourBarPose",
    "SphericalPolygon",
    "SphericalType",
    "antipode_reduction",
    "arcs_from_coefficients",
    "chain_components",
    "chebyshev_spacing",
    "classify",
    "close_polygon",
    "cosine_law",
    "deltoid",
    "deltoid_input",
    "freudenstein_coefficients",
    "ground_frame",
    "inversions",
    "isogram",
    "isogram_output",
    "law_count",
    "least_squares",
    "open_chain_axes",
    "polygon_relations",
    "precision_pairs",
    "sine_cosine_law",
    "sine_law",
    "slider_crank_stroke",
    "spherical_slider_crank",
    "universal_joint",
]
