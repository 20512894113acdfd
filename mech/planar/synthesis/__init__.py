"""Synthesis of planar linkages (textbook chapter 2, section 4): design a linkage for a task.

Every result here is a linkage that the analysis classes of `mech.planar` can move, with
the placement and the input angles that reproduce the task, so a design is checked by
analysing it.
"""

__all__ = []
