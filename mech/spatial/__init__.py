"""Spatial linkages: coordinate transforms, H-D matrices, the RSSR four-bar, the universal
joint and open chains (textbook chapter 2, section 5).

Conventions (``CONVENTIONS.md``): angles in radians; a matrix ``R_ij`` or ``M_ij`` maps
coordinates in frame j to coordinates in frame i; arrays of parameters give stacks.
"""

from mech._exports import reexport
from mech.spatial import _chain, _hooke, _mobility, _rccc, _rssr, _transforms

__all__ = reexport(globals(), _chain, _hooke, _mobility, _rccc, _rssr, _transforms)
