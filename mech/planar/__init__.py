"""Planar linkages: the four-bar, the slider-crank and the guide-bar (textbook chapter 2).

Conventions (``CONVENTIONS.md``): angles in radians, points as complex numbers
``x + 1j*y``, ground pivots ``A = 0`` and ``D = d``.

The modules are grouped by the chapter's sections, one subpackage each: ``structure``
(Grashof types, limit positions, quick return), ``kinematics`` (the four-bar, the
slider-crank, the guide-bar, any ``Linkage``, the triad, instant centres, velocity and
acceleration polygons), ``coupler`` (coupler-curve atlas, centrodes, cognates), ``forces``
(friction, efficiency, screws, pressure and transmission angles, force gain, statics),
``special`` (inversions of the slider-crank chain, double sliders, ready-made linkages) and
``synthesis``. Every public name of the first five is re-exported here, so
``mech.planar.FourBar`` and ``mech.planar.kinematics.FourBar`` are the same object.
"""

from mech._errors import AssemblyError
from mech._exports import reexport
from mech.planar import coupler, forces, kinematics, special, structure

# every public name of the five analysis subjects; ``synthesis`` keeps its own namespace
__all__ = ["AssemblyError", *reexport(globals(), structure, kinematics, coupler, forces, special)]
