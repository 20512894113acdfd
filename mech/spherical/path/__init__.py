"""Path generation with spherical four-bars (the monograph's chapter 2): the eighth-order
implicit coupler curve in its nine parameters (§2.1), with the quartic that cuts it from
the sphere and its longitude-latitude form, and a scaled form of the octic that keeps its
digits for small linkages. The parametric coupler curve, with velocities
and accelerations of the coupler point (§2.3), is `mech.spherical.SphericalFourBar.solve`. Path synthesis by
optimisation (§2.5): `path_fourbar` and the six-bars' `path_stephenson1`, `path_stephenson2`,
`path_watt1`, `path_watt2`, verified by `path_verify`. The implicit
coupler curves of the Stephenson and Watt six-bars (§2.2, §2.7 to §2.9): `sixbar_curve`.
"""

from mech._exports import reexport
from mech.spherical.path import _octic, _sixbar_curve, _sixpath, _synthesis

# ``_octic_small`` is the octic's scaled form, used through `coupler_octic`; it adds no name
__all__ = reexport(globals(), _octic, _sixbar_curve, _sixpath, _synthesis)

del reexport  # a helper, not a name of this package
