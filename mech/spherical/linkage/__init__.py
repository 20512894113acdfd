"""A general spherical linkage solver (a crank, then spherical RRR dyads) and the
Stephenson-1, Stephenson-2, Watt-1 and Watt-2 six-bars on the sphere (monograph §2.4)."""

from mech._exports import reexport
from mech.spherical.linkage import _linkage, _sixbars, _stephenson3

__all__ = reexport(globals(), _linkage, _sixbars, _stephenson3)

del reexport  # a helper, not a name of this package
