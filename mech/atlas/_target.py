"""Target curves from the files a designer has: a CSV of points or a path drawn in an SVG editor.

An SVG path is read with svgelements (transforms applied), sampled uniformly by arc length
and turned into the book's frame: SVG's y axis points down, the book's up, so y is negated.
Whether the target is closed is read from the path: a closing ``Z`` or an end that comes
back to the start.
"""

import os

import numpy as np

from mech._errors import InputTypeError
from mech._validate import _show, integer
from mech.atlas._planar._signature import read_points

__all__ = ["read_svg", "read_target"]

#: points per path segment before the arc-length resampling
_DENSE = 512


def _file(path):
    if not isinstance(path, (str, os.PathLike)) or isinstance(path, bytes):
        raise InputTypeError(f"Expected `path` to be a file name, got {_show(path)}")
    return os.fspath(path)


def read_svg(path, *, samples=256, element=None):
    """Read a target curve from a path (or any shape) in an SVG file.

    Parameters
    ----------
    path : str or os.PathLike
        The SVG file, as saved by a vector editor (Inkscape, Illustrator, a browser...).
    samples : int, optional
        Number of points returned, equally spaced along the curve's length (default 256).
    element : str, optional
        The ``id`` of the shape to read. Without it the file must hold exactly one path
        (or, with no path, exactly one other shape: a polygon, an ellipse...).

    Returns
    -------
    points : ndarray of complex, shape (samples,)
        ``x + 1j*y`` with y pointing up (SVG's y negated), in the units of the root
        ``viewBox`` (the drawing's own units) after every transform inside it; a closed
        curve does not repeat its first point.
    closed : bool
        Whether the path closes (a ``Z`` command, or its end within 1e-9 of its size of
        its start).

    Raises
    ------
    ValueError
        If the file cannot be read, holds no shape or several (without `element`), the
        shape has several separate strokes, or has no length.
    ImportError
        If svgelements is not installed.

    Examples
    --------
    >>> import os, tempfile
    >>> from mech.atlas import read_svg
    >>> svg = '<svg xmlns="http://www.w3.org/2000/svg"><path d="M 0 0 H 10 V 10 H 0 Z"/></svg>'
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     name = os.path.join(tmp, "target.svg")
    ...     with open(name, "w") as f:
    ...         _ = f.write(svg)
    ...     points, closed = read_svg(name, samples=8)
    >>> closed, points[:4].round(9).tolist()
    (True, [0j, (5+0j), (10+0j), (10-5j)])
    """
    name = _file(path)
    samples = integer("samples", samples, minimum=3, maximum=10**7)
    if element is not None and not isinstance(element, str):
        raise InputTypeError(f"Expected `element` to be the id of an SVG shape (a str), got {_show(element)}")
    try:
        from svgelements import SVG, Close, Matrix, Move, Path, Shape
    except ImportError:
        raise ImportError("reading an SVG target needs svgelements (pip install 'mech[export]')") from None
    try:
        svg = SVG.parse(name, reify=True)
    except (OSError, SyntaxError, ValueError) as exc:
        raise ValueError(f"Expected `path` to name a readable SVG file, got {name!r} ({exc})") from None
    shapes = [e for e in svg.elements() if isinstance(e, Shape)]
    if element is not None:
        chosen = [e for e in shapes if e.id == element]
        if not chosen:
            ids = ", ".join(repr(e.id) for e in shapes if e.id) or "none"
            raise ValueError(f"Expected `element` to be the id of a shape in {name!r}, got {element!r} (ids: {ids})")
    else:
        paths = [e for e in shapes if isinstance(e, Path)]
        chosen = paths if paths else shapes
        if len(chosen) != 1:
            ids = ", ".join(repr(e.id) for e in chosen if e.id) or "none"
            raise ValueError(f"Expected one path in {name!r} (or pick one with `element`), got {len(chosen)} (ids: {ids})")
    shape = Path(chosen[0])
    strokes = [list(sub) for sub in shape.as_subpaths()]
    strokes = [s for s in strokes if any(not isinstance(seg, Move) for seg in s)]
    if len(strokes) != 1:
        raise ValueError(f"Expected the shape of `path` {name!r} to be one stroke, got {len(strokes)} separate strokes")
    pieces, closed = [], False
    t = np.linspace(0.0, 1.0, _DENSE)
    for seg in strokes[0]:
        if isinstance(seg, Move) or seg.start is None:
            continue
        closed = closed or isinstance(seg, Close)
        xy = np.asarray(seg.npoint(t), dtype=float)
        pieces.append(xy[:, 0] - 1j * xy[:, 1])
    z = np.concatenate(pieces)
    # svgelements maps the root's viewBox onto its width and height (pixels); undo that, so
    # the points are in the drawing's own units (Inkscape's document units, say millimetres)
    fit = getattr(svg, "viewbox_transform", None)
    if fit:
        m = ~Matrix(fit)
        x, y = z.real, -z.imag
        z = (m.a * x + m.c * y + m.e) - 1j * (m.b * x + m.d * y + m.f)
    size = float(np.ptp(z.real) + np.ptp(z.imag))
    if not size > 0.0:
        raise ValueError(f"Expected the shape of `path` {name!r} to have a non-zero length, got a single point")
    closed = closed or abs(z[-1] - z[0]) <= 1e-9 * size
    if closed and abs(z[-1] - z[0]) > 0.0:
        z = np.append(z, z[0])
    s = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(z)))])
    at = np.linspace(0.0, s[-1], samples, endpoint=not closed) if not closed else s[-1] * np.arange(samples) / samples
    return np.interp(at, s, z.real) + 1j * np.interp(at, s, z.imag), bool(closed)


def read_target(path, *, samples=256):
    """Read a target curve from a CSV (``x, y`` rows) or an SVG file, chosen by the file's suffix.

    Parameters
    ----------
    path : str or os.PathLike
        ``*.svg``: the one path of the drawing (`read_svg`); anything else: a CSV read by
        `read_points`.
    samples : int, optional
        Points taken along an SVG path (a CSV's points are returned as they are).

    Returns
    -------
    points : ndarray of complex
    closed : bool or None
        From the SVG path; None for a CSV, which does not say.

    Examples
    --------
    >>> import os, tempfile
    >>> from mech.atlas import read_target
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     name = os.path.join(tmp, "arc.csv")
    ...     with open(name, "w") as f:
    ...         _ = f.write("0,0\\n1,1\\n2,0\\n")
    ...     read_target(name)
    (array([0.+0.j, 1.+1.j, 2.+0.j]), None)
    """
    name = _file(path)
    samples = integer("samples", samples, minimum=3, maximum=10**7)
    if name.lower().endswith(".svg"):
        return read_svg(name, samples=samples)
    return read_points(name), None
