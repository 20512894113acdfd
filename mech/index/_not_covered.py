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
    ("chapter", "4"): "rigid-body guidance by spherical six-bars: not yet derived",
    ("fig", "2-2"): "drawing symbols of the basic mechanisms; " + _SCHEMATIC,
    ("fig", "2-3"): "the wedge mechanism; " + _SCHEMATIC,
    ("fig", "2-6"): "link lengths against type; " + _DRAWABLE,
    ("fig", "2-9"): "forces after swapping slider and guide; " + _SCHEMATIC,
    ("fig", "2-12"): "the R-P-P-P and four-prismatic chains; " + _SCHEMATIC,
    ("fig", "2-13"): "a motion-adding mechanism; " + _ART,
    ("fig", "2-21"): "the single and double universal joint as machine parts; the "
                     "universal-joint page draws the kinematics instead (Figs. 2-122, 2-123)",
    ("fig", "2-24"): "rotation to intermittent motion; " + _DRAWABLE,
    ("fig", "2-25"): "steering linkage and treadle drives; " + _ART,
    ("fig", "2-27"): "two function generators for y = lg x, link ratios only in the drawing; "
                     + _DRAWABLE,
    ("fig", "2-28"): "a mixer and a rail transfer; " + _ART,
    ("fig", "2-33"): "feeders with constant orientation; " + _ART,
    ("fig", "2-34"): "an engine hood and a feeder; " + _ART,
    ("fig", "2-35"): "straight-line guidance of a mixer motor; " + _ART,
    ("fig", "2-42"): "instant centres of lower pairs; " + _DRAWABLE,
    ("fig", "2-43"): "the instant centre of a higher pair; " + _DRAWABLE,
    ("fig", "2-48"): "the cam of example 2-7 (its profile is not given); the instant-centre "
                     "page computes the example without the cam drawing",
    ("fig", "2-63"): "journals as machine parts; " + _ART,
    ("fig", "2-67"): "the weight-and-pulley machine of the efficiency definition; " + _SCHEMATIC,
    ("fig", "2-68"): "the wedge press free bodies and force polygons; " + _DRAWABLE,
    ("fig", "2-71"): "hand-lever shears; " + _ART,
    ("fig", "2-73"): "the guide-bar with a constant transmission angle; " + _DRAWABLE,
    ("fig", "2-83"): "the slotting-machine guide-bar; " + _DRAWABLE,
    ("fig", "2-84"): "a flying shear; " + _ART,
    ("fig", "2-85"): "a slider with its pin off the guide; " + _DRAWABLE,
    ("fig", "2-115"): "spatial pairs; " + _ART,
    ("fig", "2-116"): "robot structures; " + _ART,
    ("fig", "2-124"): "an industrial robot; " + _ART,
}
