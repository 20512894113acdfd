"""A `Design` written as JSON, as an SVG drawing and as a DXF of its links for a laser cutter.

Every link is cut as one closed outline: the convex hull of its pin centres grown by half
the link width, with round ends (a slot for a binary link, a rounded triangle for a
ternary one), and a hole of the stated diameter at each pin. In the DXF each link lies on
its own layer, named after the link, so that a cutter can take them one by one. ezdxf is
imported only when a DXF is written, so ``import mech`` never loads it.
"""

from __future__ import annotations

import json
import math
import os

import numpy as np

from mech._errors import InputTypeError
from mech._validate import _show, positive_length
from mech.planar.export._design import Design, _from_spec

__all__ = ["to_json", "from_json", "write_json", "read_json", "svg_text", "write_svg", "write_dxf"]

FORMAT = "mech design"
VERSION = 1

#: DXF $INSUNITS codes of the units a designer is likely to state
_INSUNITS = {"in": 1, "ft": 2, "mm": 4, "cm": 5, "m": 6}


def _xy(z):
    return [float(np.real(z)), float(np.imag(z))]


def _check_design(design):
    if not isinstance(design, Design):
        raise InputTypeError(f"Expected `design` to be a Design (from design_of), got {_show(design)}")
    return design


def _path_of(path):
    if not isinstance(path, (str, os.PathLike)) or isinstance(path, bytes):
        raise InputTypeError(f"Expected `path` to be a file name, got {_show(path)}")
    return path


# --------------------------------------------------------------------------------- JSON
def to_json(design, *, link_width=None, hole_diameter=None):
    """The design as a JSON text: type, dimensions, pivots, links, motor, transmission angle, units.

    Parameters
    ----------
    design : Design
    link_width, hole_diameter : float, optional
        Written under ``"cutting"`` when given (the values used for the DXF).

    Returns
    -------
    str

    Examples
    --------
    >>> from mech.planar import FourBar
    >>> from mech.planar.export import design_of, from_json, to_json
    >>> d = design_of(FourBar(30, 70, 60, 80, coupler=(20, 10)), units="mm")
    >>> from_json(to_json(d)) == d
    True
    """
    d = _check_design(design)
    out = {
        "format": FORMAT,
        "version": VERSION,
        "type": d.type,
        "kind": d.kind,
        "units": d.units,
        "dimensions": d.spec,
        "placement": {"origin": _xy(d.origin), "rotation": d.rotation},
        "input_angle": d.theta,
        "pivots": {k: _xy(v) for k, v in d.joints.items()},
        "fixed": list(d.fixed),
        "links": {k: list(v) for k, v in d.links.items()},
        "motor": {"joint": d.motor, "link": d.driven, "at": _xy(d.joints[d.motor]), "full_turn": d.full_turn},
        "transmission_angle": {"min": d.gamma_min, "min_degrees": math.degrees(d.gamma_min)},
        "guide": None if d.guide is None else {"through": _xy(d.guide[0]), "direction": _xy(d.guide[1])},
    }
    if link_width is not None or hole_diameter is not None:
        w, h = _cutting(d, link_width, hole_diameter)
        out["cutting"] = {"link_width": w, "hole_diameter": h}
    return json.dumps(out, indent=2)


def from_json(text):
    """The `Design` written by `to_json`, rebuilt from its dimensions and placement.

    Raises
    ------
    ValueError
        If the text is not a design written by `to_json`.
    """
    if not isinstance(text, str):
        raise InputTypeError(f"Expected `text` to be a JSON str, got {_show(text)}")
    try:
        data = json.loads(text)
        if data.get("format") != FORMAT:
            raise ValueError
        origin = complex(*data["placement"]["origin"])
        return _from_spec(data["type"], data["dimensions"], origin, float(data["placement"]["rotation"]),
                          float(data["input_angle"]), data["units"])
    except (ValueError, KeyError, TypeError, AttributeError):
        raise ValueError(f"Expected `text` to be a design written by to_json, got {text[:80]!r}") from None


def write_json(design, path, **cutting):
    """Write `to_json` of the design to `path`."""
    with open(_path_of(path), "w", encoding="utf-8") as f:
        f.write(to_json(design, **cutting) + "\n")


def read_json(path):
    """The `Design` in a file written by `write_json`."""
    with open(_path_of(path), encoding="utf-8") as f:
        return from_json(f.read())


# ----------------------------------------------------------------------------- outlines
def _cutting(d, link_width, hole_diameter):
    """The link width and the hole diameter: given, or from the design's size."""
    w = 0.08 * d.size if link_width is None else positive_length("link_width", link_width)
    h = 0.5 * w if hole_diameter is None else positive_length("hole_diameter", hole_diameter)
    if not h < w:
        raise ValueError(f"Expected `hole_diameter` smaller than the link width {w!r}, got {h!r}")
    return w, h


def _hull(z, tol):
    """Convex hull of points, counter-clockwise, without repeated or collinear points."""
    pts = sorted({(float(p.real), float(p.imag)) for p in z})
    if len(pts) == 1:
        return [complex(*pts[0])]

    def half(points):
        out = []
        for p in points:
            while len(out) >= 2:
                (ax, ay), (bx, by) = out[-2], out[-1]
                if (bx - ax) * (p[1] - ay) - (by - ay) * (p[0] - ax) > tol:
                    break
                out.pop()
            out.append(p)
        return out

    lower, upper = half(pts), half(pts[::-1])
    return [complex(*p) for p in lower[:-1] + upper[:-1]]


def _outline(pins, r, tol):
    """Vertices ``(point, bulge)`` of the closed outline at distance r around the pins.

    The bulge is ``tan(alpha/4)`` of the counter-clockwise arc that starts at the vertex
    (DXF's convention); 0 for a straight edge.
    """
    hull = _hull(pins, tol)
    if len(hull) == 1:
        c = hull[0]
        return [(c + r, 1.0), (c - r, 1.0)]
    n = len(hull)
    normals = [(hull[(k + 1) % n] - hull[k]) / abs(hull[(k + 1) % n] - hull[k]) * -1j for k in range(n)]
    out = []
    for k in range(n):
        before, after = normals[k - 1], normals[k]
        alpha = np.angle(after / before) % (2.0 * np.pi)
        out.append((hull[k] + r * before, math.tan(alpha / 4.0)))
        out.append((hull[k] + r * after, 0.0))
    return out


def _slider_block(c, u, w):
    """Corners of the slider block: 2w along the guide, w across."""
    v = 1j * u
    return [c - w * u - 0.5 * w * v, c + w * u - 0.5 * w * v, c + w * u + 0.5 * w * v, c - w * u + 0.5 * w * v]


def _guide_ends(d):
    """Ends of the drawn guide line: a design's size either side of the slider pin."""
    g, u = d.guide
    c = g + u * ((d.joints["C"] - g) / u).real
    return c - d.size * u, c + d.size * u


def _shapes(d, w):
    """``{link: (outline vertices with bulges, pin names)}`` for every link."""
    tol = 1e-12 * d.size
    out = {}
    for name, pins in d.links.items():
        if len(pins) == 1 and name != "frame" and d.guide is not None:
            out[name] = ([(z, 0.0) for z in _slider_block(d.joints[pins[0]], d.guide[1], w)], pins)
        else:
            out[name] = (_outline([d.joints[p] for p in pins], 0.5 * w, tol), pins)
    return out


# ---------------------------------------------------------------------------------- SVG
def svg_text(design, *, link_width=None, hole_diameter=None):
    """An SVG drawing of the design: links and holes, the fixed pivots, the motor, the coupler curve.

    The y axis points up in the design and down in SVG, so every y is negated. The coupler
    curve is the path with ``id="coupler-curve"`` (`mech.atlas.read_svg` reads it back).

    Returns
    -------
    str

    Examples
    --------
    >>> import xml.etree.ElementTree as ET
    >>> from mech.planar import FourBar
    >>> from mech.planar.export import design_of, svg_text
    >>> root = ET.fromstring(svg_text(design_of(FourBar(30, 70, 60, 80, coupler=(20, 10)))))
    >>> sorted(p.get("id") for p in root.iter("{http://www.w3.org/2000/svg}path") if p.get("id"))
    ['coupler-curve', 'link-coupler', 'link-crank', 'link-frame', 'link-rocker']
    """
    d = _check_design(design)
    w, h = _cutting(d, link_width, hole_diameter)
    fmt = lambda z: f"{z.real:.10g},{-z.imag:.10g}"
    shapes = _shapes(d, w)
    pts = [z for verts, _ in shapes.values() for z, _ in verts]
    if d.curve is not None and len(d.curve):
        pts += list(d.curve)
    pts = np.array(pts)
    pad = 0.1 * d.size
    x0, x1 = pts.real.min() - pad, pts.real.max() + pad
    y0, y1 = -pts.imag.max() - pad, -pts.imag.min() + pad
    stroke = d.size / 400
    units = d.units or "units"
    gamma = math.degrees(d.gamma_min)
    lines = [
        f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{x0:.10g} {y0:.10g} {x1 - x0:.10g} {y1 - y0:.10g}" '
        f'width="600" height="{600 * (y1 - y0) / (x1 - x0):.0f}">',
        f"<title>{d.type} ({d.kind}), motor at {d.motor}, minimum transmission angle {gamma:.1f} deg, "
        f"lengths in {units}</title>",
        f'<g id="links" fill="#dde7f0" fill-opacity="0.6" stroke="#234" stroke-width="{stroke:.6g}">',
    ]
    for name, (verts, _) in shapes.items():
        parts = [f"M {fmt(verts[0][0])}"]
        for k, (z, bulge) in enumerate(verts):
            nxt = verts[(k + 1) % len(verts)][0]
            if bulge:
                alpha = 4.0 * math.atan(bulge)
                radius = abs(nxt - z) / (2.0 * math.sin(alpha / 2.0))
                # counter-clockwise with y up is clockwise on screen: sweep flag 1
                parts.append(f"A {radius:.10g} {radius:.10g} 0 {int(alpha > math.pi)} 1 {fmt(nxt)}")
            else:
                parts.append(f"L {fmt(nxt)}")
        lines.append(f'<path id="link-{name}" d="{" ".join(parts)} Z"/>')
    lines.append("</g>")
    lines.append(f'<g id="holes" fill="white" stroke="#234" stroke-width="{stroke:.6g}">')
    for name, z in d.joints.items():
        lines.append(f'<circle id="pin-{name}" cx="{z.real:.10g}" cy="{-z.imag:.10g}" r="{0.5 * h:.10g}"/>')
    lines.append("</g>")
    if d.guide is not None:
        a, b = _guide_ends(d)
        lines.append(f'<path id="guide" d="M {fmt(a)} L {fmt(b)}" stroke="#888" stroke-dasharray="{4 * stroke:.6g}" '
                     f'stroke-width="{stroke:.6g}"/>')
    if d.curve is not None and len(d.curve):
        path = " L ".join(fmt(z) for z in d.curve)
        lines.append(f'<path id="coupler-curve" d="M {path}" fill="none" stroke="#c33" stroke-width="{2 * stroke:.6g}"/>')
    m = d.joints[d.motor]
    lines.append(f'<g id="motor"><circle cx="{m.real:.10g}" cy="{-m.imag:.10g}" r="{0.9 * w:.10g}" fill="none" '
                 f'stroke="#2a7" stroke-width="{2 * stroke:.6g}"/>')
    lines.append(f'<text x="{m.real + w:.10g}" y="{-m.imag - w:.10g}" font-size="{w:.6g}" fill="#2a7">motor</text></g>')
    for name in d.fixed:
        z = d.joints[name]
        tri = [z, z + w * complex(-0.6, -1.0), z + w * complex(0.6, -1.0)]
        lines.append(f'<path class="fixed-pivot" d="M {" L ".join(fmt(t) for t in tri)} Z" fill="#234"/>')
    lines.append("</svg>")
    return "\n".join(lines) + "\n"


def write_svg(design, path, **cutting):
    """Write `svg_text` of the design to `path`."""
    with open(_path_of(path), "w", encoding="utf-8") as f:
        f.write(svg_text(design, **cutting))


# ---------------------------------------------------------------------------------- DXF
def write_dxf(design, path, *, link_width=None, hole_diameter=None):
    """Write the links as a DXF for a laser cutter: one layer per link, outline and pin holes.

    Parameters
    ----------
    design : Design
    path : str or os.PathLike
    link_width : float, optional
        Width of every link (default 8 % of the design's size, its largest pin distance).
    hole_diameter : float, optional
        Diameter of the pin holes (default half the link width); must be below the width.

    Returns
    -------
    (float, float)
        The link width and the hole diameter used (also written into the DXF header as the
        custom properties ``link_width`` and ``hole_diameter``).

    Notes
    -----
    Each link is a closed ``LWPOLYLINE`` (straight edges and arcs given by their bulge) and a
    ``CIRCLE`` per pin, centred on the pin at the drawn pose, in the design's frame and
    units (``$INSUNITS`` set for mm, cm, m, in and ft). A slider block is a rectangle two
    widths long with one hole; the guide is a line on the layer ``guide``, not a part.

    Examples
    --------
    >>> import os, tempfile
    >>> import ezdxf
    >>> from mech.planar import FourBar
    >>> from mech.planar.export import design_of, write_dxf
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     _ = write_dxf(design_of(FourBar(30, 70, 60, 80)), os.path.join(tmp, "fb.dxf"), link_width=8, hole_diameter=4)
    ...     doc = ezdxf.readfile(os.path.join(tmp, "fb.dxf"))
    >>> sorted(layer.dxf.name for layer in doc.layers if layer.dxf.name not in ("0", "Defpoints"))
    ['coupler', 'crank', 'frame', 'rocker']
    """
    d = _check_design(design)
    w, h = _cutting(d, link_width, hole_diameter)
    path = _path_of(path)
    try:
        import ezdxf
    except ImportError:
        raise ImportError("writing a DXF needs ezdxf (pip install 'mech[export]')") from None
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = _INSUNITS.get(d.units, 0)
    doc.header.custom_vars.append("link_width", repr(w))
    doc.header.custom_vars.append("hole_diameter", repr(h))
    doc.header.custom_vars.append("units", d.units or "unstated")
    msp = doc.modelspace()
    for colour, (name, (verts, pins)) in enumerate(_shapes(d, w).items(), start=1):
        doc.layers.add(name, color=colour)
        msp.add_lwpolyline([(z.real, z.imag, b) for z, b in verts], format="xyb", close=True,
                           dxfattribs={"layer": name})
        for p in pins:
            z = d.joints[p]
            msp.add_circle((z.real, z.imag), 0.5 * h, dxfattribs={"layer": name})
    if d.guide is not None:
        doc.layers.add("guide", color=8)
        a, b = _guide_ends(d)
        msp.add_line((a.real, a.imag), (b.real, b.imag), dxfattribs={"layer": "guide"})
    doc.saveas(path)
    return w, h
