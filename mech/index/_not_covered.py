"""Catalogued numbers that nothing in the repository covers yet, each with its reason.

This is the only hand-kept part of the index, and it lists only gaps: a number that gains a
derivation, a page or a function is found by harvesting and no longer needs its entry (the
index then reports the entry as stale, so it can be deleted). An equation counts as covered
only when a derivation notebook declares it, because the derivation is the source of truth
for a formula; every other number counts as covered when a derivation, a book page or a
public function declares it.
"""

__all__ = ["NOT_COVERED"]

_DRAWABLE = "drawable from the text's data or from chosen data; not yet redrawn on a page"
_ART = "a machine drawing, photograph or sketch of a device; nothing to compute"
_SCHEMATIC = "an explanatory sketch without data; not redrawn"

#: (kind, number) -> why it is not covered yet.
NOT_COVERED = {
    ("fig", "2-2"): "drawing symbols of the basic mechanisms; " + _SCHEMATIC,
    ("fig", "2-3"): "the wedge mechanism; " + _SCHEMATIC,
    ("fig", "2-9"): "forces after swapping slider and guide; " + _SCHEMATIC,
    ("fig", "2-13"): "a motion-adding mechanism; " + _ART,
    ("fig", "2-21"): "the single and double universal joint as machine parts; the "
                     "universal-joint page draws the kinematics instead (Figs. 2-122, 2-123)",
    ("fig", "2-25"): "steering linkage and treadle drives; " + _ART,
    ("fig", "2-28"): "a mixer and a rail transfer; " + _ART,
    ("fig", "2-33"): "feeders with constant orientation; " + _ART,
    ("fig", "2-34"): "an engine hood and a feeder; " + _ART,
    ("fig", "2-35"): "straight-line guidance of a mixer motor; " + _ART,
    ("fig", "2-63"): "journals as machine parts; " + _ART,
    ("fig", "2-67"): "the weight-and-pulley machine of the efficiency definition; " + _SCHEMATIC,
    ("fig", "2-71"): "hand-lever shears; " + _ART,
    ("fig", "2-84"): "a flying shear; " + _ART,
    ("fig", "2-115"): "spatial pairs; " + _ART,
    ("fig", "2-116"): "robot structures; " + _ART,
    ("fig", "2-124"): "an industrial robot; " + _ART,
}
