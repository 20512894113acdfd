"""A designed linkage as a maker needs it: pins, links, the motor, the transmission angle.

`design_of` turns what a synthesis returns (a `FourBar`, a `SliderCrank`, a revolute
`Linkage` such as a six-bar, or any design record that carries one of them with its
placement: atlas matches, path, guidance, quick-return and function-generator designs)
into one `Design` record. The writers of ``_files`` draw and cut from that record only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from mech._errors import InputTypeError
from mech._validate import _show, planar_point, planar_points, real_number
from mech.planar.kinematics import FourBar, Guide, Linkage, SliderCrank
from mech.planar.structure import grashof

__all__ = ["Design", "design_of"]

#: input angles sampled when a range or a minimum is found numerically (a quarter degree)
_SAMPLES = 1441


def _fold(gamma):
    """An angle between two lines, folded into [0, pi/2]."""
    return np.minimum(gamma, np.pi - gamma)


def _triangle_angle(x, y, f):
    """The angle between sides x and y of a triangle whose third side is f (law of cosines),
    the sides divided by the longest first, so that no square overflows or underflows at any
    unit of length."""
    s = np.maximum(np.maximum(x, y), f)
    x, y, f = x / s, y / s, f / s
    return np.arccos(np.clip((x * x + y * y - f * f) / (2.0 * x * y), -1.0, 1.0))


def _default_theta(thetas, valid):
    """0 if the linkage assembles there, else the middle sample of its range."""
    idx = np.flatnonzero(valid)
    if idx.size == 0:
        raise ValueError("Expected `obj` to be a linkage that assembles at some input angle, got one that never does")
    return 0.0 if valid[0] else float(thetas[idx[idx.size // 2]])


@dataclass(frozen=True)
class Design:
    """A linkage ready to be drawn, cut and assembled (all lengths in the design's units).

    Attributes
    ----------
    type : str
        ``"four-bar"``, ``"slider-crank"``, ``"Watt six-bar"``, ``"Stephenson six-bar"`` or
        ``"slider-crank linkage"`` (a `Linkage` of a crank and an RRP group) or ``"linkage"``
        (another `Linkage` of revolute joints and sliders on fixed guides, driven by one crank).
    kind : str
        The four-bar's Grashof type (``grashof(a, b, c, d).kind``); for a slider-crank
        ``"crank"`` or ``"rocking crank"``; for a linkage ``"crank"`` or ``"rocking crank"``.
    spec : dict
        What rebuilds the analysis object: the lengths, branch and coupler point of a
        four-bar (``a, b, c, d, p, q, branch``), of a slider-crank (``a, b, e, p, q,
        branch``), or the building steps of a `Linkage`.
    origin, rotation : complex, float
        Placement: a point ``w`` of the standard frame lies at ``origin + exp(1j*rotation)*w``.
    theta : float
        The input angle (standard frame, radians) of the drawn pose.
    joints : dict of str to complex
        Every pin centre at the drawn pose, placed: ``A``, ``B``, ``C``, ``D`` and the coupler
        point ``P`` of a four-bar.
    links : dict of str to tuple of str
        Each rigid link and the pins it carries; ``"frame"`` carries the fixed pivots.
    motor : str
        The fixed pivot where the motor sits.
    driven : str
        The link the motor turns.
    full_turn : bool
        Whether the motor's link turns through full revolutions.
    gamma_min : float
        The smallest transmission angle over the motion the motor drives, radians.
    guide : (complex, complex) or None
        A point of a slider's guide and its unit direction, placed; None without a slider.
    units : str
        The unit of every length (the synthesis is unit-free; ``""`` when not stated).
    """

    type: str
    kind: str
    spec: dict
    origin: complex
    rotation: float
    theta: float
    joints: dict
    links: dict
    motor: str
    driven: str
    full_turn: bool
    gamma_min: float
    guide: tuple | None = None
    units: str = ""
    curve: np.ndarray = field(default=None, compare=False, repr=False)

    @property
    def fixed(self):
        """The fixed pivots (the pins of the frame)."""
        return self.links["frame"]

    @property
    def size(self):
        """The largest distance between two pins (the scale for drawings and tolerances)."""
        z = np.array(list(self.joints.values()))
        return float(np.max(np.abs(z[:, None] - z[None, :])))

    def linkage(self):
        """The analysis object again: `FourBar`, `SliderCrank` or `Linkage` (standard frame).

        Examples
        --------
        >>> from mech.planar import FourBar
        >>> from mech.planar.export import design_of
        >>> design_of(FourBar(30, 70, 60, 80, coupler=(20, 10))).linkage()
        FourBar(30.0, 70.0, 60.0, 80.0, branch=1, coupler=(20.0, 10.0))
        """
        s = self.spec
        if self.type == "four-bar":
            return FourBar(s["a"], s["b"], s["c"], s["d"], branch=s["branch"], coupler=(s["p"], s["q"]))
        if self.type == "slider-crank":
            return SliderCrank(s["a"], s["b"], s["e"], branch=s["branch"])
        return _rebuild(s["steps"])

    def place(self, w):
        """Standard-frame points (complex) in the design's frame."""
        return self.origin + np.exp(1j * self.rotation) * planar_points("w", w)


# ----------------------------------------------------------------------------- four-bar
def _fourbar_design(f, origin, rotation, theta, units):
    a, b, c, d = f.a, f.b, f.c, f.d
    g = grashof(a, b, c, d)
    # the motor goes to a fixed pivot whose link turns fully: A if it can, else D
    motor, full = ("A", True) if "A" in g.revolving else (("D", True) if "D" in g.revolving else ("A", False))
    if motor == "A":
        # the transmission angle is at C, between coupler and rocker; f = BD over the motion
        lo, hi = max(abs(d - a), abs(b - c)), min(d + a, b + c)
        gam = _fold(_triangle_angle(b, c, np.array([lo, hi])))
    else:
        # driven at D, the output is AB: the angle at B between coupler and AB; f = AC
        lo, hi = max(abs(d - c), abs(a - b)), min(d + c, a + b)
        gam = _fold(_triangle_angle(a, b, np.array([lo, hi])))
    # on a full turn the angle reaches both ends of its range; a rocking input stops at a
    # dead point of its own, so the range of f is still closed by the triangle inequalities
    gamma_min = float(np.min(gam))
    thetas = np.linspace(0.0, 2.0 * np.pi, _SAMPLES)
    curves = [f.solve(thetas)]
    if theta is None:
        theta = _default_theta(thetas, curves[0].valid)
    pose = f.solve(real_number("theta", theta))
    if not bool(pose.valid):
        raise ValueError(f"Expected `theta` at which the four-bar assembles, got {theta!r}")
    if motor == "D" or not full:
        # driven from D (or through dead centres), the curve takes both branches of A's angle
        other = FourBar(a, b, c, d, branch=-f.branch, coupler=f.coupler).solve(thetas[::-1])
        curve = np.concatenate([curves[0].P[curves[0].valid], other.P[other.valid]])
    else:
        curve = curves[0].P[curves[0].valid]
    place = lambda w: origin + np.exp(1j * rotation) * np.asarray(w)
    joints = {"A": place(0j), "B": place(complex(pose.B)), "C": place(complex(pose.C)), "D": place(complex(d)),
              "P": place(complex(pose.P))}
    p, q = f.coupler
    if motor == "D":
        # the link DC turns fully and carries the motor: it is the crank, AB the rocker
        links = {"frame": ("A", "D"), "crank": ("D", "C"), "coupler": ("B", "C", "P"), "rocker": ("A", "B")}
    else:
        links = {"frame": ("A", "D"), "crank": ("A", "B"), "coupler": ("B", "C", "P"), "rocker": ("D", "C")}
    if complex(p, q) in (0j, complex(f.b)):
        # the coupler point is the pin B or C itself: no hole of its own
        del joints["P"]
        links["coupler"] = ("B", "C")
    return Design("four-bar", g.kind, dict(a=a, b=b, c=c, d=d, p=float(p), q=float(q), branch=f.branch),
                  complex(origin), float(rotation), float(theta), joints, links, motor, "crank", full,
                  gamma_min, None, units, place(curve))


# ------------------------------------------------------------------------- slider-crank
def _slider_design(s, coupler, origin, rotation, theta, units):
    a, b, e = s.a, s.b, s.e
    full = bool(b >= a + abs(e))
    # cos(gamma) = |a sin(theta) - e| / b is largest with the crank across the guide (F57)
    gamma_min = float(math.acos(min(1.0, (a + abs(e)) / b)))
    thetas = np.linspace(0.0, 2.0 * np.pi, _SAMPLES)
    sol = s.solve(thetas)
    if theta is None:
        theta = _default_theta(thetas, sol.valid)
    pose = s.solve(real_number("theta", theta))
    if not bool(pose.valid):
        raise ValueError(f"Expected `theta` at which the slider-crank assembles, got {theta!r}")
    p, q = (0.0, 0.0) if coupler is None else (float(coupler[0]), float(coupler[1]))
    place = lambda w: origin + np.exp(1j * rotation) * np.asarray(w)
    B = a * np.exp(1j * theta)
    C = complex(float(pose.x), e)
    joints = {"A": place(0j), "B": place(B), "C": place(C)}
    links = {"frame": ("A",), "crank": ("A", "B"), "rod": ("B", "C"), "slider": ("C",)}
    P = B + complex(p, q) * (C - B) / b
    curve = np.exp(1j * thetas[sol.valid]) * a + complex(p, q) * (sol.x[sol.valid] + 1j * e - a * np.exp(1j * thetas[sol.valid])) / b
    if (p, q) != (0.0, 0.0) and abs(complex(p, q) - b) > 0.0:
        joints["P"] = place(P)
        links["rod"] = ("B", "C", "P")
    guide = (complex(place(complex(0.0, e))), complex(np.exp(1j * rotation)))
    return Design("slider-crank", "crank" if full else "rocking crank",
                  dict(a=a, b=b, e=e, p=p, q=q, branch=s.branch), complex(origin), float(rotation), float(theta),
                  joints, links, "A", "crank", full, gamma_min if full else 0.0, guide, units, place(curve))


# ----------------------------------------------------------------------------- Linkage
_BUILD = {
    "ground": lambda lk, st: lk.ground(st.label, st.get("at")),
    "point": lambda lk, st: lk.point(st.label, link=st.links[0], at=st.get("at")),
    "crank": lambda lk, st: lk.crank(st.links[0], pivot=st.get("pivot"), tip=st.get("tip"),
                                     length=st.get("length"), driver=st.get("driver")),
    "rrr": lambda lk, st: lk.rrr(st.links, pins=st.get("pins"), joint=st.get("joint"),
                                 lengths=st.get("lengths"), branch=st.get("branch")),
    "rrp": lambda lk, st: lk.rrp(st.links, pin=st.get("pin"), guide=st.get("guide"), joint=st.get("joint"),
                                 length=st.get("length"), branch=st.get("branch")),
}


class _StepView:
    """A step written as a plain dict (from JSON), read like the linkage's own steps."""

    def __init__(self, step):
        self.kind, self.label, self.links = step["kind"], step["label"], tuple(step["links"])
        self._data = step["data"]

    def get(self, key):
        v = self._data[key]
        if key == "at":
            return complex(*v)
        if key == "guide":
            through = v["through"] if isinstance(v["through"], str) else complex(*v["through"])
            return Guide(v["link"], through, v["angle"])
        return tuple(v) if isinstance(v, list) else v


def _rebuild(steps):
    lk = Linkage()
    for step in steps:
        lk = _BUILD[step["kind"]](lk, _StepView(step))
    return lk


def _steps_of(lk):
    """The linkage's building steps as plain dicts: points, one crank, RRR and RRP groups (fixed guides)."""
    out = []
    for st in lk._steps:
        if st.kind not in _BUILD:
            raise ValueError(f"Expected `obj` to be a linkage of RRR and RRP groups driven by one crank, got a step "
                             f"{st.label!r} ({st.kind}) that the export does not draw")
        data = {k: ([v.real, v.imag] if isinstance(v, complex) else list(v) if isinstance(v, tuple) else v)
                for k, v in st.data}
        if st.kind == "rrp":
            g = st.get("guide")
            if g.link != "ground":
                raise ValueError(f"Expected `obj` to have its sliders on guides fixed in the ground, got one in the link {g.link!r}")
            through = g.through if isinstance(g.through, str) else [g.through.real, g.through.imag]
            data["guide"] = {"link": g.link, "through": through, "angle": g.angle}
        if "at" in data and not isinstance(data["at"], list):
            data["at"] = [float(data["at"]), 0.0]
        out.append(dict(kind=st.kind, label=st.label, links=list(st.links), data=data))
    cranks = [s for s in out if s["kind"] == "crank"]
    if len(cranks) != 1 or len(lk.drivers) != 1:
        raise ValueError(f"Expected `obj` to be a linkage driven by one crank, got drivers {lk.drivers!r}")
    return out


def _chain_type(links):
    """Watt (the two ternary links share a pin) or Stephenson, for a six-bar of seven pins."""
    pins = {p for ps in links.values() for p in ps}
    ternary = [set(ps) for ps in links.values() if len(ps) >= 3]
    if len(links) != 6 or len(pins) < 7 or len(ternary) != 2:
        return "linkage"
    return "Watt six-bar" if ternary[0] & ternary[1] else "Stephenson six-bar"


def _linkage_design(lk, origin, rotation, theta, units):
    steps = _steps_of(lk)
    links = {"frame": []}
    crank = next(s for s in steps if s["kind"] == "crank")
    groups, sliders = [], []
    for s in steps:
        d = s["data"]
        if s["kind"] == "ground":
            links["frame"].append(s["label"])
        elif s["kind"] == "point":
            links.setdefault(s["links"][0], []).append(s["label"])
        elif s["kind"] == "crank":
            links[s["links"][0]] = [d["pivot"], d["tip"]]
        elif s["kind"] == "rrp":
            links[s["links"][0]] = [d["pin"], d["joint"]]
            links[s["links"][1]] = [d["joint"]]
            sliders.append((d["pin"], d["joint"], d["guide"]))
        else:
            links[s["links"][0]] = [d["pins"][0], d["joint"]]
            links[s["links"][1]] = [d["pins"][1], d["joint"]]
            groups.append((d["pins"][0], d["pins"][1], d["joint"]))
    # the frame carries only the fixed pivots that a link turns about
    used = {p for name, ps in links.items() if name != "frame" for p in ps}
    links["frame"] = [p for p in links["frame"] if p in used]
    links = {k: tuple(dict.fromkeys(v)) for k, v in links.items()}
    thetas = np.linspace(0.0, 2.0 * np.pi, _SAMPLES)
    sol = lk.solve(thetas)
    full = bool(sol.valid.all())
    gam = [np.pi / 2]
    for p0, p1, j in groups:
        u = sol.points[p0][sol.valid] - sol.points[j][sol.valid]
        v = sol.points[p1][sol.valid] - sol.points[j][sol.valid]
        gam.append(float(np.min(_fold(np.abs(np.angle(u * np.conj(v)))))) if u.size else 0.0)
    guide = None
    for pin, joint, g in sliders:
        # the rod against the normal to the guide: cos(gamma) = |sin(angle of rod to guide)|
        e = np.exp(1j * g["angle"])
        u = sol.points[joint][sol.valid] - sol.points[pin][sol.valid]
        gam.append(float(np.min(np.pi / 2 - _fold(np.abs(np.angle(u * np.conj(e)))))) if u.size else 0.0)
        through = g["through"]
        guide = (complex(*through) if isinstance(through, list) else through, complex(e))
    if theta is None:
        theta = _default_theta(thetas, sol.valid)
    pose = lk.solve(np.array([real_number("theta", theta)]))
    if not bool(pose.valid[0]):
        raise ValueError(f"Expected `theta` at which the linkage assembles, got {theta!r}")
    place = lambda w: origin + np.exp(1j * rotation) * np.asarray(w)
    joints = {name: place(complex(pose.points[name][0])) for ps in links.values() for name in ps}
    curve = place(sol.points["P"][sol.valid]) if "P" in sol.points else None
    if guide is not None:
        through = pose.points[guide[0]][0] if isinstance(guide[0], str) else guide[0]
        guide = (complex(place(complex(through))), complex(np.exp(1j * rotation) * guide[1]))
    kind = _chain_type(links) if guide is None else ("slider-crank linkage" if len(links) == 4 else "linkage")
    return Design(kind, "crank" if full else "rocking crank", dict(steps=steps), complex(origin),
                  float(rotation), float(theta), joints, links, crank["data"]["pivot"], crank["links"][0], full,
                  min(gam), guide, units, curve)


# --------------------------------------------------------------------------- the entry
def _placement(obj):
    """``(origin, rotation)`` of a design record: the fields the synthesis records use."""
    if hasattr(obj, "origin"):
        rot = getattr(obj, "rotation", getattr(obj, "angle", 0.0))
        return planar_point("origin", obj.origin), real_number("rotation", rot)
    if hasattr(obj, "placement"):
        o, r = obj.placement
        return planar_point("placement[0]", o), real_number("placement[1]", r)
    return 0j, 0.0


def design_of(obj, *, units="", theta=None):
    """The `Design` of a linkage or of a synthesis result, ready for `write_json`, `write_svg`, `write_dxf`.

    Parameters
    ----------
    obj : FourBar, SliderCrank, Linkage or a design record
        A linkage in its standard frame, or a record that holds one with its placement: an
        atlas `Match` (or its `PlacedLinkage`, `PlacedSliderCrank`), `PathFourBar`,
        `GuidanceFourBar`, `CentricSliderCrank`, `QuickReturnCrankRocker`,
        `QuickReturnSliderCrank`, `FunctionGenerator`, `CouplerPathDesign`,
        `GuidanceSliderCrank`, or a six-bar `Linkage` such as ``watt_six_bar()``.
    units : str, optional
        The unit of the lengths, written into the files (``"mm"``, ``"in"``...).
    theta : float, optional
        Input angle of the drawn pose (standard frame, radians); default 0 if the linkage
        assembles there, else an angle inside its range.

    Returns
    -------
    Design

    Raises
    ------
    TypeError
        If `obj` holds no linkage the export knows.
    ValueError
        If the linkage does not assemble at `theta`, or a `Linkage` has a sliding pair.

    Notes
    -----
    The motor goes to a fixed pivot whose link turns fully: A of a crank-rocker or a
    double-crank, D of a rocker-crank (the link DC is then the crank). The smallest
    transmission angle is exact for four-bars and slider-cranks: for a four-bar driven at
    A it is the folded angle at C between coupler and rocker, whose cosine
    ``(b^2 + c^2 - f^2)/(2 b c)`` is monotonic in the diagonal ``f = BD``; f runs over
    ``[max(|d - a|, |b - c|), min(d + a, b + c)]``, so the extreme values sit at the ends
    (eq. 2-30 and the rule F55 of the textbook); driven at D, the same holds at B with
    ``f = AC``. For a slider-crank ``cos(gamma_min) = (a + |e|)/b``
    (F57). For another `Linkage` it is the smallest folded angle at the joint of each
    RRR group over 1441 input angles of a turn.

    Examples
    --------
    >>> import math
    >>> from mech.planar import FourBar
    >>> from mech.planar.export import design_of
    >>> d = design_of(FourBar(30, 70, 60, 80, coupler=(20, 10)), units="mm")
    >>> d.type, d.kind, d.motor, d.full_turn, round(math.degrees(d.gamma_min), 4)
    ('four-bar', 'crank-rocker', 'A', True, 44.4153)
    """
    if not isinstance(units, str):
        raise InputTypeError(f"Expected `units` to be a str such as 'mm', got {_show(units)}")
    inner = getattr(obj, "linkage", None)
    if inner is not None and not callable(inner) and hasattr(obj, "cognates"):
        return design_of(inner, units=units, theta=theta)          # an atlas Match
    origin, rotation = _placement(obj)
    if isinstance(obj, FourBar):
        return _fourbar_design(obj, 0j, 0.0, theta, units)
    if isinstance(obj, SliderCrank):
        return _slider_design(obj, None, 0j, 0.0, theta, units)
    if isinstance(obj, Linkage):
        return _linkage_design(obj, 0j, 0.0, theta, units)
    for attr in ("fourbar", "linkage"):
        inner = getattr(obj, attr, None)
        if isinstance(inner, FourBar):
            return _fourbar_design(inner, origin, rotation, theta, units)
        if isinstance(inner, Linkage):
            return _linkage_design(inner, origin, rotation, theta, units)
    for attr in ("slider", "slider_crank"):
        inner = getattr(obj, attr, None)
        if isinstance(inner, SliderCrank):
            return _slider_design(inner, getattr(obj, "coupler", None), origin, rotation, theta, units)
    raise InputTypeError(f"Expected `obj` to be a FourBar, SliderCrank, Linkage or a synthesis result that holds one, "
                         f"got {_show(obj)}")


def _from_spec(type_, spec, origin, rotation, theta, units):
    """The `Design` of a linkage given by its type and `Design.spec` (what `from_json` reads)."""
    if type_ == "four-bar":
        f = FourBar(spec["a"], spec["b"], spec["c"], spec["d"], branch=spec["branch"], coupler=(spec["p"], spec["q"]))
        return _fourbar_design(f, origin, rotation, theta, units)
    if type_ == "slider-crank":
        s = SliderCrank(spec["a"], spec["b"], spec["e"], branch=spec["branch"])
        return _slider_design(s, (spec["p"], spec["q"]), origin, rotation, theta, units)
    return _linkage_design(_rebuild(spec["steps"]), origin, rotation, theta, units)
