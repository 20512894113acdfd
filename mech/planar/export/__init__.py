"""A designed planar linkage as files a maker uses: JSON, an SVG drawing, a DXF for a laser cutter.

`design_of` reads any linkage or synthesis result (four-bars, slider-cranks, six-bar
`Linkage` objects, atlas matches) into a `Design`: its pins at one pose, its links, where
the motor goes and its smallest transmission angle. `write_json`, `write_svg` and
`write_dxf` write it; `read_json` reads it back. ezdxf is needed for the DXF only and is
imported when one is written.
"""

from mech._exports import reexport
from mech.planar.export import _design, _files

__all__ = reexport(globals(), _design, _files)

del reexport  # a helper, not a name of this package
