"""Live figures of linkages built step by step: any planar `mech.planar.Linkage` (six-bars,
shapers, Jansen's leg), any `mech.spherical.SphericalLinkage` (the spherical six-bars), the
RSSR and the open chain of example 2-25.

Each builder returns a description for ``live=`` of `figures.animate` (as `figures.live`
does for the four-bar): the linkage's steps and dimensions, the fields the page shows, and
the first read-out. In the page, ``book/_static/mech/live_chains.js`` solves the same
steps with the generated kernels (``assur_groups.js``, ``spherical_linkage.js``,
``rssr.js``, ``one_equation.js``, ``open_chains.js``). Each group keeps the assembly mode
it was built with (the page does not follow a mode through a change point of the crank's
turn, as `Linkage.solve` does); the branch switch flips every group at once.

The read-out is computed here with `mech` (NumPy) and in the page with the kernels, in the
same words and to the same digits.
"""

import math

import numpy as np

__all__ = ["linkage", "spherical_linkage", "rssr", "open_chain", "great_circles", "stephenson3"]

CURVE_POINTS = 720


def _deg(x):
    return f"{math.degrees(x):.1f}".replace("-", "\u2212") + "\u00b0"


def _angles(theta):
    from figures.live import _angles as angles

    return angles(theta)


def _pair(z):
    z = complex(z)
    return [z.real, z.imag]


def _field(key, label, value, lo, hi, step):
    return [key, label, float(value), float(lo), float(hi), float(step)]


def _fold(mu):
    return np.minimum(mu, np.pi - mu)


def _turn_words(ok, n):
    count = int(np.count_nonzero(ok))
    kind = "the crank turns fully" if count == n else "the crank does not turn fully"
    return kind, f"assembles at {count} of {n} crank angles"


def linkage(lk, theta):
    """A live planar `mech.planar.Linkage` driven by one crank (ground, crank, point, RRR,
    RRP and RPR steps); `theta` the crank angle of each frame.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar import watt_six_bar
    >>> spec = linkage(watt_six_bar(), np.radians([0.0, 90.0]))
    >>> spec["type"], [f[1] for f in spec["fields"]]
    ('linkage', ['AB', 'BC', 'DC', 'EG', 'FG'])
    """
    steps, fields = [], []
    for s in lk._steps:
        data = dict(s.data)
        if s.kind == "ground":
            steps.append({"k": "ground", "name": s.label, "at": _pair(data["at"])})
        elif s.kind == "point":
            steps.append({"k": "point", "name": s.label, "link": s.links[0], "at": _pair(data["at"])})
        elif s.kind == "crank":
            key = f"L{len(fields)}"
            fields.append((key, data["pivot"] + data["tip"], data["length"]))
            steps.append({"k": "crank", "link": s.links[0], "pivot": data["pivot"], "tip": data["tip"], "len": key})
        elif s.kind == "rrr":
            (p1, p2), j = data["pins"], data["joint"]
            keys = [f"L{len(fields)}", f"L{len(fields) + 1}"]
            fields += [(keys[0], p1 + j, data["lengths"][0]), (keys[1], p2 + j, data["lengths"][1])]
            steps.append({"k": "rrr", "links": list(s.links), "pins": [p1, p2], "joint": j, "lens": keys,
                          "branch": int(data["branch"])})
        elif s.kind == "rrp":
            g = data["guide"]
            if isinstance(g.through, str):
                raise ValueError(f"Expected a guide through local coordinates in a live linkage, got {g!r}")
            key = f"L{len(fields)}"
            fields.append((key, data["pin"] + data["joint"], data["length"]))
            steps.append({"k": "rrp", "links": list(s.links), "pin": data["pin"], "joint": data["joint"], "len": key,
                          "guide": {"link": g.link, "through": _pair(g.through), "angle": float(g.angle)},
                          "branch": int(data["branch"])})
        elif s.kind == "rpr":
            steps.append({"k": "rpr", "links": list(s.links), "pins": list(data["pins"]),
                          "offset": float(data["offset"]), "branch": int(data["branch"])})
        else:
            raise ValueError(f"Expected ground, point, crank, RRR, RRP or RPR steps in a live linkage, got {s.kind!r}")
    if [s["k"] for s in steps].count("crank") != 1 or len(lk._drivers) != 1:
        raise ValueError(f"Expected a linkage driven by one crank, got drivers {lk._drivers!r}")
    longest = max(abs(v) for _, _, v in fields)
    spec = {"type": "linkage", "theta": _angles(theta), "steps": steps, "branch": 1, "curve": CURVE_POINTS,
            "fields": [_field(k, label, v, 0.0, 2 * longest, longest / 400) for k, label, v in fields]}
    spec["first"] = _linkage_readout(lk, steps)
    return spec


def _linkage_readout(lk, steps):
    t = 2 * np.pi * np.arange(CURVE_POINTS) / CURVE_POINTS
    P = lk.solve(t).points
    ok = np.all([np.isfinite(np.asarray(v) + np.zeros(t.shape)) for v in P.values()], axis=0)
    kind, limits = _turn_words(ok, CURVE_POINTS)
    least, joints = np.inf, []
    for s in steps:
        if s["k"] == "rrr":
            J, P1, P2 = (np.asarray(P[n]) + np.zeros(t.shape) for n in (s["joint"], *s["pins"]))
            u, v = P1 - J, P2 - J
            mu = _fold(np.arctan2(np.abs((np.conj(u) * v).imag), (np.conj(u) * v).real))
            least = min(least, float(np.min(mu[ok]))) if ok.any() else least
            joints.append(s["joint"])
    gamma = (f"smallest transmission angle {_deg(least)} (joints {', '.join(joints)}; over {CURVE_POINTS} poses)"
             if joints and np.isfinite(least) else "no RRR group: no transmission angle")
    return {"kind": kind, "limits": limits, "transmission": gamma}


def spherical_linkage(lk, theta, *, title="spherical linkage"):
    """A live `mech.spherical.SphericalLinkage` (a crank, points and RRR dyads); `theta`
    the input angle of each frame. Arcs are shown in degrees.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import watt1
    >>> lk = watt1(0.3, 0.9, 0.7, 1.0, E=(0.5, 0.6), F=(0.4, 0.9), arcs=(0.7, 0.8), coupler=(0.3, 0.4))
    >>> spec = spherical_linkage(lk, [0.0])
    >>> spec["type"], spec["first"]["kind"]
    ('sphlinkage', 'the crank turns fully')
    """
    steps, fields = [], []
    for s in lk._steps:
        if s[0] == "ground":
            steps.append({"k": "ground", "name": s[1], "at": [float(v) for v in s[2]]})
        elif s[0] == "crank":
            _, link, pivot, tip, a, ref = s
            key = f"L{len(fields)}"
            fields.append((key, f"{pivot}{tip} (\u00b0)", a))
            steps.append({"k": "crank", "link": link, "pivot": pivot, "tip": tip, "arc": key, "ref": ref})
        elif s[0] == "point":
            _, name, link, r, g = s
            steps.append({"k": "point", "name": name, "link": link, "r": float(r), "g": float(g)})
        else:
            _, (l1, l2), (p1, p2), j, (b1, b2), sign = s
            keys = [f"L{len(fields)}", f"L{len(fields) + 1}"]
            fields += [(keys[0], f"{p1}{j} (\u00b0)", b1), (keys[1], f"{p2}{j} (\u00b0)", b2)]
            steps.append({"k": "rrr", "links": [l1, l2], "pins": [p1, p2], "joint": j, "arcs": keys,
                          "branch": int(sign)})
    spec = {"type": "sphlinkage", "theta": _angles(theta), "steps": steps, "branch": 1, "curve": CURVE_POINTS,
            "title": str(title),
            "fields": [_field(k, label, math.degrees(v), 0.0, 180.0, 0.1) for k, label, v in fields]}
    spec["first"] = _spherical_readout(lk, steps)
    return spec


def _tangent(at, to):
    return to - np.sum(at * to, axis=-1, keepdims=True) * at


def _spherical_readout(lk, steps):
    t = 2 * np.pi * np.arange(CURVE_POINTS) / CURVE_POINTS
    pose = lk.solve(t)
    P = {k: np.asarray(v) + np.zeros(t.shape + (3,)) for k, v in pose.points.items()}
    ok = np.all([np.isfinite(v).all(axis=-1) for v in P.values()], axis=0)
    kind, limits = _turn_words(ok, CURVE_POINTS)
    least, joints = np.inf, []
    for s in steps:
        if s["k"] == "rrr":
            J, P1, P2 = (P[n] for n in (s["joint"], *s["pins"]))
            u, v = _tangent(J, P1), _tangent(J, P2)
            mu = _fold(np.arctan2(np.linalg.norm(np.cross(u, v), axis=-1), np.sum(u * v, axis=-1)))
            if ok.any():
                least = min(least, float(np.min(mu[ok])))
            joints.append(s["joint"])
    gamma = f"smallest transmission angle {_deg(least)} (joints {', '.join(joints)}; over {CURVE_POINTS} poses)"
    return {"kind": kind, "limits": limits, "transmission": gamma}


_RSSR_KEYS = ("l1", "l2", "l3", "s0", "s3", "h0", "lam")


def rssr(dims, theta, *, branch=1):
    """A live RSSR of dimensions `dims` (``l1, l2, l3, s0, s3, h0, lam`` as
    `mech.spatial.RSSR`), drawn with both assembly modes (C on `branch`, C' on the other),
    in the view of ``book/spatial/rssr.md``. `theta`: the crank angle of each frame.

    Examples
    --------
    >>> import numpy as np
    >>> spec = rssr(dict(l1=1.0, l2=4.0, l3=2.0, s0=0.5, s3=0.8, h0=3.0, lam=np.radians(60.0)), [0.0])
    >>> spec["first"]["kind"]
    'the crank turns fully'
    """
    from mech.spatial import RSSR

    dims = {k: float(dims[k]) for k in _RSSR_KEYS}
    L = RSSR(**dims, branch=branch)
    longest = max(abs(dims[k]) for k in _RSSR_KEYS[:-1])
    labels = {"l1": "crank l1", "l2": "coupler l2", "l3": "rocker l3", "s0": "S0", "s3": "S3", "h0": "h0"}
    fields = [_field(k, labels[k], dims[k], 0.0 if k[0] in "lh" else -2 * longest, 2 * longest, longest / 400)
              for k in _RSSR_KEYS[:-1]]
    fields.append(_field("lam", "twist \u03bb (\u00b0)", math.degrees(dims["lam"]), -180.0, 180.0, 0.1))
    t = 2 * np.pi * np.arange(CURVE_POINTS) / CURVE_POINTS
    pose = L.solve(t)
    ok = np.asarray(pose.valid) & np.isfinite(pose.C).all(axis=-1)
    kind, limits = _turn_words(ok, CURVE_POINTS)
    z3 = np.array([0.0, np.sin(dims["lam"]), np.cos(dims["lam"])])
    bc = pose.C - pose.B
    D = np.array([dims["h0"], dims["s3"] * np.sin(dims["lam"]), dims["s3"] * np.cos(dims["lam"])])
    along = np.cross(z3, pose.C - D)      # C's direction of motion about the rocker axis
    mu = np.arctan2(np.linalg.norm(np.cross(bc, along), axis=-1), np.abs(np.sum(bc * along, axis=-1)))
    least = float(np.min(np.pi / 2 - mu[ok])) if ok.any() else np.nan
    return {"type": "rssr", "theta": _angles(theta), "dims": dims, "branch": int(branch), "curve": CURVE_POINTS,
            "fields": fields, "first": {"kind": kind, "limits": limits,
                                        "transmission": f"smallest transmission angle {_deg(least)} at C"}}


def open_chain(s0, p, sweep):
    """A live open chain RRPR of example 2-25 (base height `s0`, gripper point `p` out along
    z4) moving through `sweep`, shape (n, 4): the joint values of each frame. The fields set
    S0, p and a shift of the slide S2 over the whole sweep.

    Examples
    --------
    >>> import numpy as np
    >>> spec = open_chain(0.4, 0.08, np.zeros((2, 4)) + [0.0, 1.0, 0.25, 0.0])
    >>> spec["first"]["limits"]
    'reach |AP| from 0.3553 to 0.3553'
    """
    from mech.spatial import example_2_25_reach

    q = np.asarray(sweep, dtype=float)
    if q.ndim != 2 or q.shape[1] != 4 or not np.isfinite(q).all():
        raise ValueError(f"Expected `sweep` finite joint values of shape (n, 4), got shape {q.shape}")
    reach = example_2_25_reach(q[:, 1], q[:, 2], s0, p)
    fields = [_field("s0", "S0", s0, 0.0, 4 * s0, s0 / 400), _field("p", "p", p, 0.0, 4 * s0, s0 / 400),
              _field("shift", "shift of S2", 0.0, -2 * s0, 2 * s0, s0 / 400)]
    return {"type": "chain", "q": [[round(float(v), 9) for v in row] for row in q], "s0": float(s0), "p": float(p),
            "shift": 0.0, "branch": 1, "fields": fields,
            "first": {"kind": "open chain RRPR: no loop to close, every pose exists",
                      "limits": f"reach |AP| from {reach.min():.4f} to {reach.max():.4f}",
                      "transmission": "the gripper turns with \u03c6\u2083\u2084"}}


def great_circles(A, B, C):
    """A live view of the triangle ABC on the unit sphere with the great circles AB and BC,
    their poles N1, N2 and their common points X and -X (as ``book/spherical/calculus.md``
    draws it); the fields set the longitude and latitude of A, B and C in degrees.

    Examples
    --------
    >>> great_circles([1, 0, 0], [0, 1, 0], [0, 0, 1])["first"]["limits"]
    'angle between the circles at X 90.0°'
    """
    from mech.spherical import distance, great_circle_through, intersect

    pts = {k: np.asarray(v, dtype=float) / np.linalg.norm(v) for k, v in zip("ABC", (A, B, C))}
    fields = []
    for k, p in pts.items():
        fields.append(_field(f"{k}lon", f"{k} longitude (\u00b0)", math.degrees(math.atan2(p[1], p[0])), -180, 180, 0.1))
        fields.append(_field(f"{k}lat", f"{k} latitude (\u00b0)", math.degrees(math.atan2(p[2], math.hypot(p[0], p[1]))),
                             -90, 90, 0.1))
    n1, n2 = great_circle_through(pts["A"], pts["B"]).pole, great_circle_through(pts["B"], pts["C"]).pole
    x = intersect(n1, n2)
    arcs = ", ".join(f"{p}{q} {_deg(float(distance(pts[p], pts[q])))}" for p, q in ("AB", "BC", "CA"))
    return {"type": "circles", "branch": 1, "fields": fields,
            "first": {"kind": "the great circles AB and BC meet at X and \u2212X",
                      "limits": f"angle between the circles at X {_deg(float(x.angle))}", "transmission": f"arcs {arcs}"}}


def stephenson3(lk, theta):
    """A live Stephenson-3 spherical six-bar (`mech.spherical.SphericalStephenson3`) at the
    input angles `theta`: the page moves its guided link CGH from the assembled pose, as
    `solve` does, with the fields setting the arcs BC, EG and DH.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import stephenson3 as build
    >>> lk = build(0.35, 0.9, 0.8, 1.1, E=(0.5, 0.7), arcs=(0.9, 0.6), H=(0.55, -0.6), coupler=(0.3, 0.4), mu=0.8)
    >>> stephenson3(lk, np.linspace(0.0, 1.0, 5))["first"]["limits"]
    'assembled at 5 of 5 frames'
    """
    theta = np.asarray(theta, dtype=float).ravel()
    points = {k: [float(x) for x in v] for k, v in lk.assembly.items()}
    arcs = {k: lk.arcs[k] for k in ("BC", "EG", "DH")}
    fields = [_field(k, f"{k} (\u00b0)", math.degrees(v), 0.0, 180.0, 0.1) for k, v in arcs.items()]
    count = int(np.count_nonzero(lk.solve(theta).valid))
    return {"type": "stephenson3", "theta": _angles(theta), "points": points, "theta0": float(lk.theta0),
            "branch": 1, "fields": fields, "curve": CURVE_POINTS,
            "first": {"kind": "Stephenson-3: the guided link CGH hangs from the crank by BC and EG and from D by DH",
                      "limits": f"assembled at {count} of {theta.size} frames",
                      "transmission": "arcs " + ", ".join(f"{k} {_deg(v)}" for k, v in arcs.items())}}
