"""Spherical mechanisms: the spherical calculus, the spherical four-bar and its types, the
side-angle laws of spherical polygons, the transference principle and function generation
(the spherical monograph, chapters 1, 5, 6 and 7).

Conventions (``CONVENTIONS.md``): the sphere has unit radius, arcs are radians in (0, pi),
points are unit 3-vectors in arrays of shape ``(..., 3)``, and ``lon`` is 0 at the poles.
"""

from mech.spherical._fourbar import SphericalFourBar, SphericalFourBarPose, ground_frame

__all__ = [
    "SphericalFourBar",
    "SphericalFourBarPose",
    "ground_frame",
]
