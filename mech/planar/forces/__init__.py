"""Forces in planar linkages (textbook §2.3).

Friction in lower pairs (F1 to F22, eqs. 2-19 and 2-20), mechanical efficiency and
self-locking (eqs. 2-21 to 2-29), screw pairs and the screw jack (F47, F48), pressure and
transmission angles (eq. 2-30, F49 to F59), force gain and dead points (§2.3, part II), and
static force analysis of a solved linkage with and without friction (F60 onwards).
"""

from mech._exports import reexport
from mech.planar.forces import _efficiency, _force_gain, _friction, _pressure_angle, _screw, _statics, _transmission

__all__ = reexport(globals(), _efficiency, _force_gain, _friction, _pressure_angle, _screw, _statics, _transmission)
