"""The planar atlas: four-bars and slider-cranks, their shape signatures, the stored atlas,
its search (closed curves and open arcs), constrained refinement and multistart synthesis.

The public names are re-exported by `mech.atlas`; the modules here are internal.
"""
