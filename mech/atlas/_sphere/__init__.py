"""The spherical atlas: sampled spherical four-bars, their rotation-invariant signatures, the
stored atlas, its search (closed curves and open arcs) and refinement.

The public names are re-exported by `mech.atlas`; the modules here are internal.
"""
