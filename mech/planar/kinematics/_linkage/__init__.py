"""The general planar linkage solver: a driver and class II Assur groups of revolute and
sliding pairs, solved in order, with assembly modes through change points.

- ``_records``: the records a linkage is built from and solved into (guides, slides, the
  solution, assembly intervals);
- ``_groups``: the Assur groups' steps over whole arrays of inputs;
- ``_modes``: each group's assembly mode from its change points, and the bridges across them;
- ``_blocks``: a large solve cut into blocks that fit the cache;
- ``_compiled``: the same rules in one compiled loop per topology (numba, when installed);
- ``_solver``: `Linkage` itself, which chooses among them.
"""

from mech._exports import reexport
from mech.planar.kinematics._linkage import _solver

__all__ = reexport(globals(), _solver)
