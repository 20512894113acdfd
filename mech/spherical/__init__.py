"""Spherical mechanisms: the spherical calculus, the spherical four-bar and its types, the
side-angle laws of spherical polygons, the transference principle and function generation
(the spherical monograph, chapters 1, 5, 6 and 7), and in ``path`` the eighth-order
coupler curve (chapter 2).

Conventions (``CONVENTIONS.md``): the sphere has unit radius, arcs are radians in (0, pi),
points are unit 3-vectors in arrays of shape ``(..., 3)``, and ``lon`` is 0 at the poles.
"""

from mech.spherical._circles import (
    Circle,
    Collinearity,
    Intersection,
    angle_between,
    bisector,
    circle_through,
    collinearity,
    distance_to_great_circle,
    great_circle_at,
    great_circle_through,
    intersect,
)
from mech.spherical._coordinates import distance, distance_lonlat, from_xyz, local_frame, to_xyz
from mech.spherical._dual import Dual, dual
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
from mech.spherical._rigid_body import (
    angle_at,
    inclination,
    point_at,
    rotate_about,
    rotation_matrix,
    tangent,
    triangle_point,
    turn,
    velocity,
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
from mech.spherical.path import CouplerOctic, coupler_octic, coupler_quartic, nine_parameters
from mech.spherical._transference import dual_fourbar_joints, dual_fourbar_output, rssr_from_transference
from mech.spherical._types import SphericalType, antipode_reduction, classify, inversions

__all__ = [
    "Circle",
    "Collinearity",
    "CouplerOctic",
    "Dual",
    "FunctionGenerator",
    "Intersection",
    "PolygonRelations",
    "SliderStroke",
    "SphericalFourBar",
    "SphericalFourBarPose",
    "SphericalPolygon",
    "SphericalType",
    "angle_at",
    "angle_between",
    "antipode_reduction",
    "arcs_from_coefficients",
    "bisector",
    "chain_components",
    "chebyshev_spacing",
    "circle_through",
    "classify",
    "close_polygon",
    "collinearity",
    "cosine_law",
    "coupler_octic",
    "coupler_quartic",
    "deltoid",
    "deltoid_input",
    "distance",
    "distance_lonlat",
    "distance_to_great_circle",
    "dual",
    "dual_fourbar_joints",
    "dual_fourbar_output",
    "freudenstein_coefficients",
    "from_xyz",
    "great_circle_at",
    "great_circle_through",
    "ground_frame",
    "inclination",
    "intersect",
    "inversions",
    "isogram",
    "isogram_output",
    "law_count",
    "least_squares",
    "local_frame",
    "nine_parameters",
    "open_chain_axes",
    "point_at",
    "polygon_relations",
    "precision_pairs",
    "rotate_about",
    "rotation_matrix",
    "rssr_from_transference",
    "sine_cosine_law",
    "sine_law",
    "slider_crank_stroke",
    "spherical_slider_crank",
    "tangent",
    "to_xyz",
    "triangle_point",
    "turn",
    "universal_joint",
    "velocity",
]
