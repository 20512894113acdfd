"""Live figures: what a player needs to recompute its linkage in the reader's browser.

`figures.animate.animate` and `view3d` take ``live=`` one of the descriptions made here. The
page then shows controls under the drawing (a field and a slider per length and for the
coupler point, a branch switch; the pivots and the coupler point can be dragged) and, on
every change, recomputes the poses, the coupler curve, the linkage's type, its limit
positions and its smallest transmission angle with the generated JavaScript kernels
(``book/_static/kernels``, through the layer in ``book/_static/mech``; ``live.js`` wires
them to the player). The build writes the first state, controls and read-out included,
so the page is right before any script runs; the kernels load only on pages with a live
figure. The linkages built step by step (six-bars, Jansen's leg, the spherical six-bars,
the RSSR, the open chain, the Stephenson-3 triad) and the great-circle view are described
by `figures.live_chains`, re-exported here. `none` marks a figure whose linkage has no
kernel in the page, and says so.

The read-out is written by `readout` here and by ``live.js`` in the page, in the same words
and to the same digits.
"""

import html
import math

import numpy as np

__all__ = ["fourbar", "slider_crank", "guide_bar", "hooke", "spherical_fourbar", "linkage", "spherical_linkage", "rssr",
           "open_chain", "great_circles", "stephenson3", "none", "readout", "controls"]

CURVE_POINTS = 720  # poses of the coupler curve drawn by a live figure


def _angles(theta):
    t = np.asarray(theta, dtype=float).ravel()
    if t.size == 0 or not np.isfinite(t).all():
        raise ValueError(f"Expected `theta` finite input angles, got {theta!r}")
    return [round(float(v), 7) for v in t]


def _branch(branch):
    if branch not in (1, -1) or isinstance(branch, bool):
        raise ValueError(f"Expected `branch` +1 or -1, got {branch!r}")
    return int(branch)


def fourbar(a, b, c, d, theta, *, branch=1, couplers=None, origin=0j, angle=0.0, names="ABCD", ghost=False):
    """A live planar four-bar ABCD: A at `origin`, D at ``origin + d exp(i angle)``.

    Parameters
    ----------
    a, b, c, d : float
        Crank AB, coupler BC, rocker CD and ground AD, as `mech.planar.FourBar`.
    theta : array_like
        The crank angle of each frame of the player, radians from A->D.
    branch : {1, -1}
    couplers : dict of str -> (float, float), optional
        Coupler points by their name in the player: ``(p, q)`` as FourBar's `coupler`.
    origin : complex
    angle : float
        Direction of A->D in the drawing, radians.
    names : sequence of 4 str
        The player's names of A, B, C and D.
    ghost : bool
        The player draws the other branch too (``animate(branches=...)``).

    Examples
    --------
    >>> spec = fourbar(10, 40, 30, 35, [0.0, 1.0], couplers={"P": (20, 10)})
    >>> spec["type"], readout(spec)["kind"]
    ('fourbar', 'crank-rocker')
    """
    from mech.planar import FourBar

    FourBar(a, b, c, d, branch=branch)  # the same checks as the page: a clear error here
    couplers = {} if couplers is None else {str(k): [float(v[0]), float(v[1])] for k, v in couplers.items()}
    if len(names) != 4:
        raise ValueError(f"Expected `names` of A, B, C and D, got {names!r}")
    origin = complex(origin)
    return {"type": "fourbar", "a": float(a), "b": float(b), "c": float(c), "d": float(d),
            "branch": _branch(branch), "theta": _angles(theta), "couplers": couplers,
            "origin": [origin.real, origin.imag], "angle": float(angle), "names": list(names),
            "ghost": bool(ghost), "curve": CURVE_POINTS}


def slider_crank(a, b, e, theta, *, branch=1, names="ABC"):
    """A live slider-crank: crank AB about A = 0, rod BC, slider C on the line y = e.

    Examples
    --------
    >>> readout(slider_crank(30, 100, 20, [0.0]))["kind"]
    'crank-slider (the crank turns fully)'
    """
    from mech.planar import SliderCrank

    SliderCrank(a, b, e, branch=branch)
    return {"type": "slidercrank", "a": float(a), "b": float(b), "e": float(e), "branch": _branch(branch),
            "theta": _angles(theta), "names": list(names), "curve": CURVE_POINTS}


def guide_bar(a, d, theta, *, reach=1.1, names="ABDE"):
    """A live guide-bar: crank AB about A = 0, the block B sliding on the guide through
    D = (d, 0); the guide drawn to E at `reach` times its shortest length a + d.

    Examples
    --------
    >>> readout(guide_bar(150, 300, [0.0]))["limits"]
    'limit positions: swing 60.0°, K = 2.000'
    """
    from mech.planar import GuideBar

    GuideBar(a, d)
    return {"type": "guidebar", "a": float(a), "d": float(d), "theta": _angles(theta), "names": list(names),
            "reach": float(reach), "branch": 1}


def hooke(alpha, theta, *, arm=0.45, shaft=1.75):
    """A live Hooke's joint (universal joint) of shaft angle `alpha`, in the view of
    ``book/spatial/universal-joint.md``: input yoke at ``-arm`` on the z axis, output shaft
    ``shaft`` long along (0, sin alpha, cos alpha), the output yoke at ``arm`` on it.

    Examples
    --------
    >>> readout(hooke(0.5, [0.0]))["limits"]
    'speed ratio ω₃/ω₁ from 0.878 to 1.139'
    """
    from mech.spatial import hooke_output

    hooke_output(0.0, alpha)
    return {"type": "hooke", "alpha": float(alpha), "theta": _angles(theta), "arm": float(arm), "shaft": float(shaft),
            "branch": 1}


def spherical_fourbar(linkage, theta, *, names="ABCDP", curve=False):
    """A live spherical four-bar from a `mech.spherical.SphericalFourBar`.

    `theta`: the input angle of each frame (one angle for a still view). `names`: the
    view's names of A, B, C, D and the coupler point (four names: no coupler point).
    `curve`: draw the coupler curve in a view that does not trace it.

    Examples
    --------
    >>> from mech.spherical import SphericalFourBar
    >>> readout(spherical_fourbar(SphericalFourBar(0.3, 0.9, 0.7, 1.0), [0.0]))["kind"]
    'crank-rocker'
    """
    frame = linkage.frame
    return {"type": "sphfourbar", "a": linkage.a, "b": linkage.b, "c": linkage.c, "d": linkage.d,
            "branch": int(linkage.branch), "coupler": [float(v) for v in linkage.coupler],
            "frame": None if frame is None else np.asarray(frame).tolist(), "theta": _angles(theta),
            "names": list(names), "curve": CURVE_POINTS, "drawCurve": bool(curve)}


from figures.live_chains import great_circles, linkage, open_chain, rssr, spherical_linkage, stephenson3  # noqa: E402


def none(what):
    """A figure that stays a recording because the page cannot solve `what` yet (six-bars,
    Jansen's linkage, ...: no hand-written layer composes their kernels in the page); the
    figure says so under its controls.

    Examples
    --------
    >>> none("six-bar linkages")["why"]
    'Recorded poses: the page cannot solve six-bar linkages yet, so this figure cannot be changed here.'
    """
    return {"type": "none", "why": f"Recorded poses: the page cannot solve {what} yet, so this figure cannot be "
                                   "changed here."}


def _deg(x):
    return f"{math.degrees(x):.1f}".replace("-", "\u2212") + "\u00b0"


def readout(spec):
    """The read-out of a live figure: {"kind", "limits", "transmission"} as the page writes it."""
    kind = spec["type"]
    if "first" in spec:  # figures.live_chains: computed with the linkage itself
        return dict(spec["first"])
    if kind == "fourbar":
        from mech.planar import FourBar, grashof

        L = FourBar(spec["a"], spec["b"], spec["c"], spec["d"], branch=spec["branch"])
        g = grashof(L.a, L.b, L.c, L.d).kind
        if g == "crank-rocker":
            lim = L.limit_positions()
            limits = (f"limit positions \u03b8 = {_deg(lim.theta_extended)}, {_deg(lim.theta_folded)} "
                      f"(swing {_deg(lim.swing)}, K = {lim.time_ratio:.3f})")
        else:
            limits = "limit positions: none of a crank-rocker"
        gamma, at = L.min_transmission_angle()
        return {"kind": g, "limits": limits, "transmission": f"smallest transmission angle {_deg(gamma)} at \u03b8 = {_deg(at)}"}
    if kind == "slidercrank":
        from mech.planar import SliderCrank

        S = SliderCrank(spec["a"], spec["b"], spec["e"], branch=spec["branch"])
        if not S.crank_turns:
            return {"kind": "rocker-slider (the crank rocks)", "limits": "limit positions: the crank's own",
                    "transmission": "smallest transmission angle 0.0\u00b0"}
        lim = S.limit_positions()
        return {"kind": "crank-slider (the crank turns fully)",
                "limits": (f"limit positions \u03b8 = {_deg(lim.theta_extended)}, {_deg(lim.theta_folded)} "
                           f"(stroke {lim.stroke:.2f}, K = {lim.time_ratio:.3f})"),
                "transmission": f"smallest transmission angle {_deg(S.min_transmission_angle()[0])}"}
    if kind == "guidebar":
        from mech.planar import GuideBar

        G = GuideBar(spec["a"], spec["d"])
        right = "transmission angle 90.0\u00b0 throughout (the block pushes at right angles to the guide)"
        return {"kind": "oscillating guide-bar (the guide swings)",
                "limits": f"limit positions: swing {_deg(G.swing())}, K = {G.time_ratio():.3f}", "transmission": right}
    if kind == "hooke":
        from mech.spatial import hooke_output, hooke_ratio

        alpha, t1 = spec["alpha"], np.asarray(spec["theta"])
        lo, hi = float(hooke_ratio(np.pi / 2, alpha)), float(hooke_ratio(0.0, alpha))
        lead = float(np.max(np.abs(hooke_output(t1, alpha) - t1)))
        return {"kind": f"Hooke's joint, shafts at {_deg(alpha)}",
                "limits": f"speed ratio \u03c9\u2083/\u03c9\u2081 from {lo:.3f} to {hi:.3f}",
                "transmission": f"the output leads or lags by up to {_deg(lead)}"}
    if kind == "sphfourbar":
        from mech.spherical import SphericalFourBar, classify

        L = SphericalFourBar(spec["a"], spec["b"], spec["c"], spec["d"], branch=spec["branch"],
                             coupler=spec["coupler"], frame=spec["frame"])
        rng = L.assembly_range()
        if rng.full_turn:
            limits = "the input turns fully"
        else:
            limits = "input between " + ", ".join(f"{_deg(lo)} and {_deg(hi)}" for lo, hi in rng.intervals)
        # the smallest angle at C between the arcs to B and D, over the drawn curve's poses
        pose = L.solve(_curve_angles(rng, spec["curve"]))
        gamma = _sphere_transmission(pose.B, pose.C, L.D)
        return {"kind": classify(L.a, L.b, L.c, L.d).kind, "limits": limits,
                "transmission": f"smallest transmission angle {_deg(gamma)} (over {spec['curve']} poses)"}
    raise ValueError(f"Expected a live figure of type fourbar, slidercrank or sphfourbar, got {kind!r}")


def _curve_angles(rng, n):
    """The input angles of the drawn curve, as live.js samples them."""
    if rng.full_turn:
        return -np.pi + 2 * np.pi * np.arange(n) / (n - 1)
    total = sum(hi - lo for lo, hi in rng.intervals) or 1.0
    out = []
    for lo, hi in rng.intervals:
        count = max(2, round(n * (hi - lo) / total))
        inset = 1e-10 * (hi - lo)
        out.append(lo + inset + (hi - lo - 2 * inset) * np.arange(count) / (count - 1))
    return np.concatenate(out)


def _sphere_transmission(B, C, D):
    tb = B - np.sum(C * B, axis=-1, keepdims=True) * C
    td = D - np.sum(C * D, axis=-1, keepdims=True) * C
    mu = np.arctan2(np.linalg.norm(np.cross(tb, td), axis=-1), np.sum(tb * td, axis=-1))
    mu = np.minimum(mu, np.pi - mu)
    return float(np.nanmin(mu))


# The style of the controls, written only with a live figure.
_CSS = ("<style>.mech-live{margin-top:.3em}"
        ".mech-live-fields{display:flex;flex-wrap:wrap;gap:.2em .9em;align-items:center}"
        ".mech-live-field input[type=number]{width:5.5em;font:inherit}"
        ".mech-live-field input[type=range]{width:6.5em;vertical-align:middle}"
        ".mech-live-msg{color:#a00}.mech-live-none{color:#555;font-style:italic}"
        ".mf-handle{fill:#e67e22;fill-opacity:.2;stroke:#e67e22;stroke-width:1.2;cursor:move}</style>")

_FIELDS = {
    "fourbar": [("a", "crank a"), ("b", "coupler b"), ("c", "rocker c"), ("d", "ground d"), ("p", "coupler p"), ("q", "coupler q")],
    "slidercrank": [("a", "crank a"), ("b", "rod b"), ("e", "offset e")],
    "guidebar": [("a", "crank a"), ("d", "ground d")],
    "hooke": [("alpha", "shaft angle \u03b1 (\u00b0)")],
    "sphfourbar": [("a", "a (\u00b0)"), ("b", "b (\u00b0)"), ("c", "c (\u00b0)"), ("d", "d (\u00b0)"),
                   ("r", "coupler r (\u00b0)"), ("g", "coupler \u03b3 (\u00b0)")],
}


def _values(spec):
    kind = spec["type"]
    if kind == "fourbar":
        p, q = next(iter(spec["couplers"].values()), (0.0, 0.0))
        longest = max(spec["a"], spec["b"], spec["c"], spec["d"])
        values = {"a": spec["a"], "b": spec["b"], "c": spec["c"], "d": spec["d"], "p": p, "q": q}
        ranges = {k: (0.0, 2 * longest) for k in "abcd"} | {k: (-2 * longest, 2 * longest) for k in "pq"}
        if not spec["couplers"]:
            values.pop("p"), values.pop("q")
        return values, ranges, longest / 400
    if kind == "slidercrank":
        longest = max(spec["a"], spec["b"], abs(spec["e"]))
        return ({"a": spec["a"], "b": spec["b"], "e": spec["e"]},
                {"a": (0.0, 2 * longest), "b": (0.0, 2 * longest), "e": (-2 * longest, 2 * longest)}, longest / 400)
    if kind == "hooke":
        return {"alpha": math.degrees(spec["alpha"])}, {"alpha": (0.0, 89.0)}, 0.1
    if kind == "guidebar":
        longest = max(spec["a"], spec["d"])
        return {"a": spec["a"], "d": spec["d"]}, {"a": (0.0, 2 * longest), "d": (0.0, 2 * longest)}, longest / 400
    r, g = spec["coupler"]
    values = {k: math.degrees(spec[k]) for k in "abcd"} | {"r": math.degrees(r), "g": math.degrees(g)}
    return values, {k: (0.0, 180.0) for k in "abcdr"} | {"g": (-180.0, 180.0)}, 0.1


def controls(spec):
    """The HTML of a live figure's controls and read-out, in their first state."""
    if spec["type"] == "none":
        return f'{_CSS}<div class="mech-live mech-live-none">{html.escape(spec["why"])}</div>'
    if "fields" in spec:  # figures.live_chains: [key, label, value, lo, hi, step]
        fields = [(k, label) for k, label, *_ in spec["fields"]]
        values = {k: v for k, _, v, *_ in spec["fields"]}
        ranges = {k: (lo, hi) for k, _, _, lo, hi, _ in spec["fields"]}
        steps = {k: s for k, *_, s in spec["fields"]}
    else:
        values, ranges, step = _values(spec)
        fields, steps = _FIELDS[spec["type"]], {k: step for k in values}
    out = readout(spec)
    rows = []
    for key, label in fields:
        if key not in values:
            continue
        lo, hi = ranges[key]
        step = steps[key]
        v = f"{values[key]:.6g}"
        rows.append(f'<label class="mech-live-field">{html.escape(label)} '
                    f'<input type="number" data-k="{key}" value="{v}" step="any" size="6">'
                    f'<input type="range" data-k="{key}" min="{lo:.6g}" max="{hi:.6g}" step="{step:.3g}" value="{v}" '
                    f'aria-label="{html.escape(label)}"></label>')
    branch = ("" if spec["type"] in ("chain", "circles", "stephenson3") else
              f'<button type="button" class="mech-branch">branch {spec["branch"]:+d}</button>')
    text = (f'<span class="mech-live-type">{html.escape(out["kind"])}</span> \u00b7 '
            f'<span class="mech-live-limits">{html.escape(out["limits"])}</span> \u00b7 '
            f'<span class="mech-live-gamma">{html.escape(out["transmission"])}</span>')
    return (f'{_CSS}<div class="mech-live"><div class="mech-live-fields">{"".join(rows)}{branch}</div>'
            f'<div class="mech-live-out">{text}</div><div class="mech-live-msg" role="status"></div></div>')
