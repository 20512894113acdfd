"""Path generation with spherical four-bars (the monograph's chapter 2): the eighth-order
implicit coupler curve in its nine parameters (§2.1), with the quartic that cuts it from
the sphere and its longitude-latitude form. The parametric coupler curve, with velocities
and accelerations of the coupler point (§2.3), is `mech.spherical.SphericalFourBar.solve`.
"""

from mech.spherical.path._octic import CouplerOctic, coupler_octic, coupler_quartic, nine_parameters

__all__ = ["CouplerOctic", "coupler_octic", "coupler_quartic", "nine_parameters"]
