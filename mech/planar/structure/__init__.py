"""Structure and types of the four-bar (textbook §2.1 and the start of §2.2).

What the link lengths alone decide: the Grashof classification and the kinds of motion of
the chain (eqs. 2-1 to 2-8), the limit positions, swing and extreme angle of the
crank-rocker, and the time ratio K of quick return (eq. 2-9). The book covers these in the
part "Structure and types of four-bars" and the first pages of "Kinematics".
"""

from mech._exports import reexport
from mech.planar.structure import _grashof, _limit_positions, _quick_return

__all__ = reexport(globals(), _grashof, _limit_positions, _quick_return)
