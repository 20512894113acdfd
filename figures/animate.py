"""Moving and turnable figures for the book: one call turns solved poses into a player.

`animate` draws a planar linkage pose by pose (play/pause, a slider for the input, the
coupler curve traced as it moves, an optional second assembly branch, marked dead or
limit positions); `view3d` draws points, links, great arcs and curves in space, in an
orthographic view the reader turns by dragging, optionally moving too. `animate_linkage`
and `great_circle` are shortcuts for a `mech.planar.Linkage` and for the sphere.

Every pose is computed by `mech` in the notebook; the browser draws them (and a live
figure, ``live=`` from `figures.live`, re-solves its linkage in the page). The output is
an `IPython.display.HTML` object holding an inline SVG, the poses as compact JSON and a
small script of our own (``figures/mech_anim.js``, inlined; a recording fetches no file, so
it works offline and as a plain notebook; a live figure imports its kernels from the book's
own ``_static`` folder, and stays a recording in a plain notebook).

Contract with the browser test of the book: an animation is ``<div class="mech-anim"
data-frame="K">`` with an ``<svg>``, a ``<button class="mech-play">`` and an ``<input
type="range" class="mech-slider">``; ``data-frame`` is the frame drawn, and the slider's
value (after an ``input`` event) is that frame. A turnable view is ``<div
class="mech-view3d" data-yaw=".." data-pitch="..">`` with an ``<svg>``; dragging on the
svg changes both attributes (degrees) and redraws. A moving 3-D view has both classes.

Weight, measured on the crank-rocker (10, 40, 30, 35) with a coupler point, 180 poses
(the table is on the book's page *How to read this book*): Matplotlib's
``FuncAnimation.to_jshtml`` (one PNG per pose, 5 x 4 in) stores 2441 kB at 72 dpi and
3655 kB at 100 dpi, and took about 13 s to render; this module stores 18.4 kB (6.8 kB of
data, the poses rounded to 4 significant digits on an integer grid and the input values;
9.6 kB of script (with the placing of labels that never collide and the hooks of live
figures), 1.6 kB of style). A live figure (``live=``, `figures.live`) adds its controls
and loads the kernels it needs as shared ES modules. Plotly would add its own script of about 3.5 MB to every page that uses it.
"""

import html
import json
import math
from pathlib import Path

import numpy as np

__all__ = ["animate", "animate_linkage", "view3d", "great_circle", "insert_frames"]

_JS = Path(__file__).with_name("mech_anim.js")

_CSS = """<style>
.mech-fig{margin:.4em 0 1.2em;font:13px/1.4 sans-serif}
.mech-fig svg{width:100%;height:auto;display:block;touch-action:none;background:#fff;border:1px solid #e4e4e4}
.mech-view3d svg{cursor:grab}
.mech-title{font-weight:600;margin:0 0 .25em}
.mech-fig path,.mech-fig circle,.mech-fig rect{vector-effect:non-scaling-stroke}
.mech-bar{display:flex;flex-wrap:wrap;gap:.5em;align-items:center;margin-top:.3em}
.mech-bar .mech-slider{flex:1 1 10em}
.mech-bar button{font:inherit;padding:.1em .6em}
.mf-link{fill:none;stroke:#222;stroke-width:2.2;stroke-linejoin:round;stroke-linecap:round}
.mf-plate{fill:#ddd;fill-opacity:.8}
.mf-ghost.mf-plate,.mf-marked.mf-plate{fill:none}
.mf-ghost{fill:none;stroke:#c0392b;stroke-width:1.6;stroke-dasharray:6 3}
.mf-marked{fill:none;stroke:#8e44ad;stroke-width:1.1;stroke-dasharray:2 3}
.mf-marktext{fill:#8e44ad}
.mf-path-all{fill:none;stroke:#9cc3e6;stroke-width:1.2}
.mf-path{fill:none;stroke:#d35400;stroke-width:2}
.mf-guide{fill:none;stroke:#888;stroke-width:1;stroke-dasharray:7 4}
.mf-ground{fill:#fff;stroke:#222;stroke-width:1.1}
.mf-block{fill:#fff;stroke:#222;stroke-width:1.5}
.mf-joint{fill:#fff;stroke:#222;stroke-width:1.3}
.mf-label,.mf-label3,.mf-marktext{font-family:sans-serif}
.mf-back{stroke-dasharray:3 3;opacity:.4}
.mf-outline{fill:#f4f7fb;stroke:#999;stroke-width:1}
.mf-grid{fill:none;stroke:#bbb;stroke-width:.7}
.mf-axis{fill:none;stroke:#555;stroke-width:1;stroke-dasharray:8 3 2 3}
.mf-curve{fill:none;stroke:#2e86c1;stroke-width:1.5}
.mf-fixed{fill:none;stroke:#000;stroke-width:3}
</style>"""

#: Styles a still curve of `view3d` can take (CSS classes above).
STYLES = ("grid", "axis", "curve", "fixed", "link", "path")


def _script():
    """The player script without its comment lines (they are for readers of the file)."""
    lines = (ln.strip() for ln in _JS.read_text(encoding="utf-8").splitlines())
    return "\n".join(ln for ln in lines if ln and not ln.startswith("//"))


def _grid_step(span):
    """A power of ten that puts `span` on 1000..9999 grid steps: 4 significant digits."""
    if not (np.isfinite(span) and span > 0):
        raise ValueError(f"Expected a figure of finite, positive size, got span {span!r}")
    return 10.0 ** (math.floor(math.log10(span)) - 3)


def _ints(values, step):
    """Round to the grid; NaN (no pose there) becomes None."""
    k = np.round(np.asarray(values, dtype=float) / step)
    return [None if not np.isfinite(v) else int(v) for v in k.ravel()]


def _json(data):
    text = json.dumps(data, separators=(",", ":"), allow_nan=False)
    return text.replace("</", "<\\/")


def _frames(points, name):
    """Per-name arrays: complex (n,) for a moving point or a scalar for a fixed one."""
    if not isinstance(points, dict) or not points:
        raise TypeError(f"Expected `{name}` a non-empty dict of point name -> coordinates, got {points!r}")
    return {str(k): np.asarray(v) for k, v in points.items()}


def _n_frames(arrays, name):
    ns = {a.shape[0] for a in arrays.values() if a.ndim >= 1 and a.shape[0] > 1}
    if len(ns) > 1:
        raise ValueError(f"Expected every moving point of `{name}` to have the same number of poses, got {sorted(ns)}")
    return ns.pop() if ns else 1


def _inputs(inputs, n):
    if inputs is None:
        return list(range(n))
    vals = np.asarray(inputs, dtype=float).ravel()
    if vals.size != n:
        raise ValueError(f"Expected `inputs` with one value per pose ({n}), got {vals.size}")
    return [round(float(v), 1) for v in vals]


def _controls(n, label, marks):
    jumps = "".join(f'<button type="button" class="mech-mark" data-to="{int(m[0])}">'
                    f"{html.escape(str(m[1]))}</button>" for m in marks)
    return ('<div class="mech-bar"><button type="button" class="mech-play">\u25B6 play</button>'
            f'<input type="range" class="mech-slider" min="0" max="{n - 1}" step="1" value="0" '
            f'aria-label="{html.escape(label)}"><span class="mech-value"></span>{jumps}</div>')


def _wrap(classes, attrs, svg, controls, data, title="", live=None):
    heading = f'<div class="mech-title">{html.escape(title)}</div>' if title else ""
    if live is not None:  # controls of a live figure, in their first state (figures/live.py)
        from figures.live import controls as live_controls

        data["live"] = live
        controls += live_controls(live)
    return (f'{_CSS}<div class="mech-fig {classes}" {attrs}>{heading}{svg}{controls}'
            f'<script type="application/json" class="mech-data">{_json(data)}</script></div>'
            f"<script>{_script()}</script>")


def _display(text):
    from IPython.display import HTML

    return HTML(text)


def animate(points, links, *, trace=(), ground=(), blocks=(), lines=(), branches=None, marks=(),
            inputs=None, input_label="\u03b8 (deg)", labels=True, fps=30, width=560, caption="", title="",
            live=None):
    """Animate a planar linkage from its solved poses.

    Parameters
    ----------
    points : dict of str -> complex array_like, shape (n,) or ()
        Joint and point positions ``x + 1j*y`` per frame; a scalar is a fixed point. NaN
        (a pose that does not assemble) hides the links through that point in that frame.
    links : sequence of sequences of str
        Each link as the names of the points it carries (two: a bar; three or more: a
        plate, drawn filled).
    trace : sequence of str
        Points whose path is drawn (faint, whole) and traced up to the current frame.
    ground : sequence of str
        Points drawn as fixed pivots (a triangle).
    blocks : sequence of str or (str, str)
        Points drawn as sliding blocks: a level box, or with a second point name a box
        along the line to it. Points whose name starts with ``_`` are helpers (such a
        direction) and are not drawn.
    lines : sequence of sequences of complex
        Still polylines (guides), drawn dashed.
    branches : dict of str -> complex array_like, optional
        The same points on the other assembly branch, drawn red dashed, moving together.
    marks : sequence of (int, str, str) or (int, str)
        ``(frame, text, point)``: that pose is drawn still (dotted) and labelled at
        `point` (dead or limit positions), with a button that jumps to it;
        ``(frame, text)``: the button only.
    inputs : array_like, shape (n,), optional
        The input value shown for each frame (e.g. the crank angle in degrees).
    input_label : str
    labels : bool
        Write the point names.
    fps : float
        Frames per second when playing.
    width : int
        Largest width in CSS pixels.
    caption : str
        Text for screen readers (``aria-label`` of the SVG).
    title : str
        A visible title above the figure (which linkage it is, when a page shows several).
    live : dict, optional
        From `figures.live` (``fourbar``, ``slider_crank``, ``guide_bar``, ``linkage``,
        ``none``): the reader may change the linkage in the page, which recomputes it with
        the JavaScript kernels.

    Returns
    -------
    IPython.display.HTML
        ``.data`` is the HTML text; the poses are rounded to 4 significant digits of the
        figure's size.

    Examples
    --------
    >>> import numpy as np
    >>> t = np.linspace(0, 2 * np.pi, 5)
    >>> out = animate({"A": 0, "B": np.exp(1j * t)}, [("A", "B")], ground=["A"])
    >>> 'class="mech-fig mech-anim" data-frame="0"' in out.data
    True
    """
    P = _frames(points, "points")
    n = _n_frames(P, "points")
    names = list(P)
    index = {k: i for i, k in enumerate(names)}

    def idx(seq, what):
        bad = [s for s in seq if s not in index]
        if bad:
            raise ValueError(f"Expected `{what}` to name points of `points` ({names}), got {bad}")
        return [index[s] for s in seq]

    link_idx = [idx(list(l), "links") for l in links]
    G = _frames(branches, "branches") if branches is not None else None
    if G is not None:
        idx(list(G), "branches")
        if _n_frames(G, "branches") not in (1, n):
            raise ValueError(f"Expected `branches` with {n} poses, got {_n_frames(G, 'branches')}")
    lines = [np.asarray(l, dtype=complex).ravel() for l in lines]
    everything = [np.ravel(v) for k, v in P.items() if not k.startswith("_")] + lines + ([np.ravel(v) for v in G.values()] if G else [])
    z = np.concatenate([np.asarray(v, dtype=complex) for v in everything])
    z = z[np.isfinite(z)]
    if z.size == 0:
        raise ValueError("Expected `points` with at least one finite pose, got only NaN")
    lo, hi = complex(z.real.min(), z.imag.min()), complex(z.real.max(), z.imag.max())
    span = max(hi.real - lo.real, hi.imag - lo.imag, 1e-300) * 1.12
    step = _grid_step(span)

    def enc(v):  # x, -y (SVG's y points down), flat per frame
        v = np.asarray(v, dtype=complex).ravel()
        if v.size == 1:  # a fixed point: once
            return _ints([v[0].real, -v[0].imag], step)
        return _ints(np.c_[v.real, -v.imag], step)

    marks = [(int(m[0]), str(m[1]), idx([m[2]], "marks")[0] if len(m) > 2 else None) for m in marks]
    for f, _, _ in marks:
        if not 0 <= f < n:
            raise ValueError(f"Expected `marks` frames in [0, {n - 1}], got {f}")
    data = {
        "kind": "2d", "grid": step, "n": n, "fps": float(fps), "label": input_label, "inputs": _inputs(inputs, n),
        "names": names, "P": [enc(P[k]) for k in names], "links": link_idx,
        "trace": idx(list(trace), "trace"), "ground": idx(list(ground), "ground"),
        "blocks": [idx([b], "blocks") + [-1] if isinstance(b, str) else idx(list(b), "blocks") for b in blocks], "lines": [[ _ints([c.real, -c.imag], step) for c in l] for l in lines],
        "ghost": [enc(G[k]) if k in G else enc(P[k]) if P[k].size == 1 else [None, None] for k in names] if G else None,
        "marks": [list(m) for m in marks], "labels": bool(labels),
    }
    x0, y0 = _ints([lo.real - 0.08 * span, -hi.imag - 0.08 * span], step)
    w, h = math.ceil((hi.real - lo.real + 0.26 * span) / step), math.ceil((hi.imag - lo.imag + 0.16 * span) / step)
    data["unit"] = round(0.018 * max(w, h), 1)
    font = round(0.034 * max(w, h), 1)
    svg = (f'<svg viewBox="{x0} {y0} {w} {h}" style="max-width:{int(width)}px;font-size:{font}px" role="img" '
           f'aria-label="{html.escape(caption)}"></svg>')
    return _display(_wrap("mech-anim", 'data-frame="0"', svg, _controls(n, input_label, marks), data, title, live))


def animate_linkage(linkage, solution, *, trace=(), inputs=None, **options):
    """`animate` a `mech.planar.Linkage` from its `solve` result: links, pivots, blocks and
    the fixed guides of blocks come from the linkage itself.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar import watt_six_bar
    >>> lk = watt_six_bar()
    >>> out = animate_linkage(lk, lk.solve(np.radians(np.arange(0, 360, 60))), trace=["E"])
    >>> out.data.count('class="mech-slider"')
    1
    """
    from mech.planar.special._library import sketch

    sk = sketch(linkage)
    pts = {k: np.asarray(v) for k, v in solution.points.items()}
    for name in sk["ground"]:
        pts[name] = complex(np.ravel(pts[name])[0])
    allz = np.concatenate([np.ravel(v) for v in pts.values()])
    allz = allz[np.isfinite(allz)]
    reach = max(np.ptp(allz.real), np.ptp(allz.imag), 1e-300) / 10
    blocks = []
    for name, link in sk["blocks"]:  # a helper point along the block's link sets its direction
        pts["_" + name] = pts[name] + reach * np.asarray(solution.direction(link))
        blocks.append((name, "_" + name))
    guides = []
    for name, _ in sk["guides"]:  # a block on the frame: a dashed line along its path
        path = np.asarray(pts[name]).ravel()
        path = path[np.isfinite(path)]
        ends = path[[np.argmin(path.real + path.imag), np.argmax(path.real + path.imag)]]
        guides.append(ends + np.array([-0.15, 0.15]) * (ends[1] - ends[0]))
    return animate(pts, list(sk["links"].values()), trace=trace, ground=sk["ground"],
                   blocks=blocks, lines=guides, inputs=inputs, **options)


def insert_frames(values, extra):
    """Sort the `extra` input values (e.g. limit positions) into `values`.

    Returns the new sorted input array and the frame index of each extra value, so that
    a marked pose is drawn exactly, not at the nearest grid step.

    Examples
    --------
    >>> t, at = insert_frames([0.0, 1.0, 2.0], [1.5, 0.5])
    >>> t.tolist(), at
    ([0.0, 0.5, 1.0, 1.5, 2.0], [3, 1])
    """
    values = np.asarray(values, dtype=float).ravel()
    extra = np.asarray(extra, dtype=float).ravel()
    if not (np.isfinite(values).all() and np.isfinite(extra).all()):
        raise ValueError(f"Expected finite `values` and `extra`, got {values!r} and {extra!r}")
    order = np.argsort(np.r_[values, extra], kind="stable")
    where = np.empty_like(order)
    where[order] = np.arange(order.size)
    return np.r_[values, extra][order], [int(i) for i in where[values.size:]]


def great_circle(pole, n=97):
    """Points of the great circle with unit normal `pole`, shape (n, 3) (closed)."""
    pole = np.asarray(pole, dtype=float)
    norm = np.linalg.norm(pole)
    if pole.shape != (3,) or not np.isfinite(norm) or norm == 0:
        raise ValueError(f"Expected `pole` a non-zero 3-vector, got {pole!r}")
    pole = pole / norm
    helper = np.array([1.0, 0.0, 0.0]) if abs(pole[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = np.cross(pole, helper)
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(pole, e1)
    t = np.linspace(0.0, 2 * np.pi, n)[:, None]
    return np.cos(t) * e1 + np.sin(t) * e2


def view3d(points=None, links=(), *, arcs=(), still=(), sphere=False, trace=(), inputs=None,
           input_label="\u03b8 (deg)", labels=True, yaw=30.0, pitch=20.0, fps=20, width=460, caption="", title="",
           live=None):
    """A 3-D figure the reader turns by dragging; moving when its points have several poses.

    Parameters
    ----------
    points : dict of str -> array_like, shape (n, 3) or (3,), optional
        Points per frame (a single 3-vector is a fixed point); NaN hides a pose.
    links : sequence of (str, str)
        Straight segments between named points.
    arcs : sequence of (str, str)
        Great-circle arcs between named unit vectors (links of a spherical linkage).
    still : sequence of (array_like (m, 3), str)
        Still polylines with a style from `STYLES`: "grid", "axis", "curve", "fixed",
        "link", "path".
    sphere : bool
        Draw the unit sphere's outline and draw what lies behind it faint and dashed.
    trace : sequence of str
        Moving points whose path is drawn and traced up to the current frame.
    inputs, input_label, labels, fps, width, caption, title
        As in `animate`.
    yaw, pitch : float
        The initial view, degrees: turn about the z axis, then tilt towards the reader.
    live : dict, optional
        From `figures.live` (``spherical_fourbar``, ``spherical_linkage``, ``hooke``, ``rssr``,
        ``open_chain``, ``stephenson3``, ``great_circles``, ``none``), as in `animate`.

    Returns
    -------
    IPython.display.HTML

    Examples
    --------
    >>> out = view3d(still=[(great_circle([0, 0, 1]), "grid")], sphere=True)
    >>> 'class="mech-fig mech-view3d"' in out.data and 'class="mech-play"' not in out.data
    True
    """
    P = {} if points is None else {str(k): np.asarray(v, dtype=float) for k, v in points.items()}
    for k, v in P.items():
        if v.shape[-1:] != (3,) or v.ndim > 2:
            raise ValueError(f"Expected `points[{k!r}]` of shape (n, 3) or (3,), got {v.shape}")
    ns = {v.shape[0] for v in P.values() if v.ndim == 2 and v.shape[0] > 1}
    if len(ns) > 1:
        raise ValueError(f"Expected every moving point of `points` to have the same number of poses, got {sorted(ns)}")
    n = ns.pop() if ns else 1
    names = list(P)
    index = {k: i for i, k in enumerate(names)}
    bad = [s for pair in list(links) + list(arcs) + [[t] for t in trace] for s in pair if s not in index]
    if bad:
        raise ValueError(f"Expected `links`, `arcs` and `trace` to name points of `points` ({names}), got {bad}")
    still = [(np.asarray(c, dtype=float).reshape(-1, 3), s) for c, s in still]
    for _, s in still:
        if s not in STYLES:
            raise ValueError(f"Expected a `still` style in {STYLES}, got {s!r}")
    allpts = [v.reshape(-1, 3) for v in P.values()] + [c for c, _ in still]
    if not allpts:
        raise ValueError("Expected `points` or `still` to hold something to draw, got neither")
    xyz = np.concatenate(allpts)
    xyz = xyz[np.isfinite(xyz).all(axis=1)]
    centre = np.zeros(3) if sphere else (xyz.min(axis=0) + xyz.max(axis=0)) / 2
    R = max(float(np.max(np.linalg.norm(xyz - centre, axis=1), initial=0.0)), 1.0 if sphere else 1e-300) * 1.08
    step = _grid_step(R)

    def enc(v):
        return _ints(np.asarray(v, dtype=float) - centre, step)

    data = {
        "kind": "3d", "n": n, "fps": float(fps), "label": input_label, "inputs": _inputs(inputs, n),
        "names": names, "P": [enc(P[k]) for k in names], "step": step, "R": R, "c0": [float(c) for c in centre],
        "links": [[index[a], index[b], 0] for a, b in links] + [[index[a], index[b], 1] for a, b in arcs],
        "trace": [index[t] for t in trace], "sphere": bool(sphere), "labels": bool(labels),
        "still": [{"p": enc(c), "c": f"mf-{s}"} for c, s in still],
    }
    svg = (f'<svg viewBox="-1040 -1040 2080 2080" style="max-width:{int(width)}px;font-size:62px" '
           f'role="img" aria-label="{html.escape(caption)}"></svg>')
    moving = n > 1
    attrs = f'data-yaw="{float(yaw):.1f}" data-pitch="{float(pitch):.1f}"' + (' data-frame="0"' if moving else "")
    return _display(_wrap("mech-view3d mech-anim" if moving else "mech-view3d", attrs, svg,
                          _controls(n, input_label, ()) if moving else "", data, title, live))
