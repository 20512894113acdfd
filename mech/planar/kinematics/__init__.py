"""Kinematic analysis of planar linkages (textbook §2.2, parts I and II).

Positions, velocities and accelerations: the revolute four-bar (with its change points),
the slider-crank and the oscillating guide-bar of the analytical method; any linkage of
revolute and sliding pairs built from a driver and class II Assur groups, with its assembly
modes through change points; the class III triad of example 2-6; instant centres by the
three-centre theorem (F32 to F37); and the relative-motion method's velocity and
acceleration polygons and images (F38 to F43).
"""

from mech._exports import reexport
from mech.planar.kinematics import _fourbar, _guide_bar, _instant_centres, _linkage, _polygons, _slider_crank, _triad

__all__ = reexport(globals(), _fourbar, _guide_bar, _instant_centres, _linkage, _polygons, _slider_crank, _triad)
