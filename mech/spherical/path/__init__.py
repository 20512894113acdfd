"""Path generation with spherical four-bars (the monograph's chapter 2): the eighth-order
implicit coupler curve in its nine parameters (§2.1), with the quartic that cuts it from
the sphere and its longitude-latitude form, and a scaled form of the octic that keeps its
digits for small linkages. The parametric coupler curve, with velocities
and accelerations of the coupler point (§2.3), is `mech.spherical.SphericalFourBar.solve`. Path synthesis by
optimisation (§2.5): `path_fourbar` and the six-bars' `path_stephenson1`, `path_stephenson2`,
`path_watt1`, `path_watt2`, verified by `path_verify`. The implicit
coupler curves of the Stephenson and Watt six-bars (§2.2, §2.7 to §2.9): `sixbar_curve`.
"""

from mech.spherical.path._octic import CouplerOctic, coupler_octic, coupler_quartic, nine_parameters
from mech.spherical.path._sixbar_curve import SIXBAR_CURVE_ORDERS, sixbar_curve
from mech.spherical.path._sixpath import path_stephenson1, path_stephenson2, path_watt1, path_watt2
from mech.spherical.path._synthesis import SphericalPathDesign, path_fourbar, path_verify

__all__ = ["CouplerOctic", "SIXBAR_CURVE_ORDERS", "SphericalPathDesign", "coupler_octic", "coupler_quartic",
           "nine_parameters", "path_fourbar", "path_stephenson1", "path_stephenson2", "path_verify", "path_watt1",
           "path_watt2", "sixbar_curve"]
