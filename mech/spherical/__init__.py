"""Spherical mechanisms: the spherical calculus, the spherical four-bar and its types, the
side-angle laws of spherical polygons, the transference principle, function generation,
rigid-body guidance, a general spherical linkage solver with the Stephenson and Watt
six-bars, and in ``path`` the eighth-order coupler curve (the spherical monograph, chapters
1, 2 (§§2.1, 2.3, 2.4), 3, 5, 6 and 7).

Conventions (``CONVENTIONS.md``): the sphere has unit radius, arcs are radians in (0, pi),
points are unit 3-vectors in arrays of shape ``(..., 3)``, and ``lon`` is 0 at the poles.
"""

from mech._exports import reexport
from mech.spherical import (
    _circles,
    _coordinates,
    _dual,
    _fourbar,
    _function_generation,
    _minimax,
    _polygons,
    _rigid_body,
    _special,
    _transference,
    _types,
    guidance,
    linkage,
    path,
)

# every public name of the base modules and of the three subpackages (``_fourbar_branch`` is the
# four-bar's change-point helper and adds no name)
__all__ = reexport(globals(), _circles, _coordinates, _dual, _fourbar, _function_generation, _minimax, _polygons,
                   _rigid_body, _special, _transference, _types, guidance, linkage, path)

del reexport  # a helper, not a name of this package
