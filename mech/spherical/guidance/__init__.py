"""Rigid-body guidance on the sphere (the spherical monograph, chapter 3): displacements and
poles, spherical cranks and sliders for two to five orientations, the Burmester cubics and
points, and the four-bars they make, each checked by analysis with `SphericalFourBar`.

Every name is re-exported from `mech.spherical`.
"""

from mech._exports import reexport
from mech.spherical.guidance import (
    _burmester,
    _dyads,
    _fourbar,
    _optimal,
    _orientations,
    _sixbar,
    _sixbar_exact,
    _sixbar_optimal,
    _sixbar_optimal_exact,
    _stephenson3,
    _stephenson3_optimal,
)

__all__ = reexport(globals(), _orientations, _dyads, _burmester, _fourbar, _optimal, _sixbar, _sixbar_optimal,
                   _sixbar_optimal_exact, _stephenson3, _stephenson3_optimal, _sixbar_exact)

del reexport  # a helper, not a name of this package
