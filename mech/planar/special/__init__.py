"""Special mechanisms and ready-made linkages (textbook §2.2, Table 2-1, Fig. 2-11).

The inversions of the slider-crank chain beyond the slider-crank and the oscillating
guide-bar (rotating guide-bar, swinging and turning block), the four-bars with two
prismatic pairs (elliptic trammel, Scotch yoke, tangent mechanism, Oldham coupling), and a
library of named linkages: Stephenson and Watt six-bars, shapers, quick-return linkages
and Jansen's leg.
"""

from mech._exports import reexport
from mech.planar.special import _double_slider, _library, _special

__all__ = reexport(globals(), _double_slider, _library, _special)
