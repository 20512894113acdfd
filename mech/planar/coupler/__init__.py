"""Coupler curves of the four-bar (textbook §2.2, part II, Figs. 2-30 and 2-32).

The atlas pages that sample a coupler curve as dashes of equal crank rotation, the fixed
and moving centrodes of the coupler (example 2-4), and the three Roberts-Chebyshev
cognates that trace one coupler curve, and the implicit coupler sextic.
"""

from mech._exports import reexport
from mech.planar.coupler import _atlas, _centrodes, _cognates, _sextic

__all__ = reexport(globals(), _atlas, _centrodes, _cognates, _sextic)
