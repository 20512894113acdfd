"""Ready-made linkages: six-bars, shapers, quick-return linkages and Jansen's leg.

Each function returns a `mech.planar.Linkage` with documented default dimensions (the
textbook's figures carry no numbers, so the defaults are chosen here, as each docstring
says) and with the assembly mode of every group fixed so that the intended assembly runs
through a full turn of the crank. Helpers measure what the book shows: the steps of every
point over a turn (a jump shows up as one step far longer than the rest), the stroke and
time ratio of a ram, and the links each point belongs to (for drawing).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from mech._scaling import length_scale
from mech._validate import (
    instance, integer, known_name, MAX_COUNT, planar_point, positive_length, real_number,
)
from mech._errors import InputTypeError
from mech.planar.kinematics._linkage import Guide, Linkage

__all__ = [
    "watt_six_bar",
    "stephenson_six_bar",
    "shaper_watt",
    "shaper_stephenson",
    "quick_return_guide_bar",
    "quick_return_slider_crank",
    "quick_return_crank_rocker",
    "jansen_linkage",
    "JANSEN_HOLY_NUMBERS",
    "Stroke",
    "ram_stroke",
    "step_ratio",
]

#: Theo Jansen's published link lengths ("holy numbers") of one Strandbeest leg.
JANSEN_HOLY_NUMBERS = {
    "a": 38.0, "b": 41.5, "c": 39.3, "d": 40.1, "e": 55.8, "f": 39.4, "g": 36.7,
    "h": 65.7, "i": 49.0, "j": 50.0, "k": 61.9, "l": 7.8, "m": 15.0,
}


def _triangle(base, r1, r2, side, what):
    """Local coordinates of X with |OX| = r1, |PX| = r2, O = 0, P = base, X left if side > 0."""
    # squares of the sides divided by a power of two cannot overflow or underflow
    unit = length_scale(base, r1, r2)
    b, p, q = base / unit, r1 / unit, r2 / unit
    x = (b * b + p * p - q * q) / (2.0 * b)
    h2 = (p - x) * (p + x)
    if not h2 > 0.0:
        raise ValueError(f"Expected the sides of {what} to form a triangle, got {base!r}, {r1!r}, {r2!r}")
    return complex(x * unit, math.copysign(math.sqrt(h2) * unit, side))


def _lengths(**kw):
    return {k: positive_length(k, v) for k, v in kw.items()}


def _unit_at_angle(name, angle):
    """The unit vector at the checked angle ``angle``."""
    angle = real_number(name, angle)
    return complex(math.cos(angle), math.sin(angle))


# ----------------------------------------------------------------------------- six-bars
def watt_six_bar(*, crank=20.0, coupler=50.0, rocker=45.0, frame=50.0, lever=44.0,
                 lever_angle=math.radians(-150.0), pivot=68.0 - 9.0j, link5=24.0, output=18.0):
    """Watt six-bar of Fig. 2-15: two four-bars in series that enlarge the output swing.

    A Watt chain (Fig. 2-14a: the two ternary links jointed to each other) with a ternary
    link as the frame. The crank-rocker ``A B C D`` (A = 0, D = ``frame`` on +x) drives
    the ternary rocker ``C D E``, whose arm ``D E`` is the input of the second four-bar
    ``D E G F``; the output link ``F G`` swings about ``pivot``.

    Parameters
    ----------
    crank, coupler, rocker, frame : float
        AB, BC, CD and AD of the first four-bar (defaults 20, 50, 45, 50: a crank-rocker).
    lever, lever_angle : float
        Length of DE and its angle from D->C on the rocker, radians (44, -150 degrees).
    pivot : complex
        Output pivot F (default 68 - 9j).
    link5, output : float
        EG and FG (defaults 24 and 18).

    Returns
    -------
    Linkage
        Points A, D, F (ground), B, C, E, G; links crank, coupler, rocker, link5, output.

    Raises
    ------
    ValueError
        If a length is not positive.

    Notes
    -----
    The dimensions are chosen here (the textbook gives none): the rocker swings 58.4
    degrees, the output 109.6 degrees, and the second loop's transmission angle stays above
    67 degrees. Both groups are solved by `Linkage.rrr` (derivation: `deriv-assur-groups`).

    Examples
    --------
    >>> lk = watt_six_bar()
    >>> sol = lk.solve(np.linspace(0, 2 * np.pi, 361))
    >>> bool(sol.valid.all())
    True
    """
    L = _lengths(crank=crank, coupler=coupler, rocker=rocker, frame=frame, lever=lever,
                 link5=link5, output=output)
    return (Linkage({"A": 0.0, "D": L["frame"], "F": planar_point("pivot", pivot)})
            .crank("crank", pivot="A", tip="B", length=L["crank"])
            .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C",
                 lengths=(L["coupler"], L["rocker"]), branch=1)
            .point("E", link="rocker", at=L["lever"] * _unit_at_angle("lever_angle", lever_angle))
            .rrr(("link5", "output"), pins=("E", "F"), joint="G", lengths=(L["link5"], L["output"]), branch=-1))


def stephenson_six_bar(*, crank=20.0, coupler=50.0, rocker=45.0, frame=50.0, point=55.0 + 15.0j,
                       pivot=54.0 - 27.0j, link5=82.3, output=8.0):
    """Stephenson six-bar of Fig. 2-16: a coupler point drives a dyad, with a dwell.

    A Stephenson chain (Fig. 2-14b: the two ternary links not jointed to each other) with
    a ternary link as the frame. The crank-rocker ``A B C D`` carries the point E on its
    ternary coupler ``B C E``; the dyad ``E G`` (link 5) and ``G H`` (link 6, the output)
    hangs between E and the ground pivot H. While E runs along a nearly circular stretch of
    its coupler curve whose centre is G's dwell position and whose radius is EG, G and the
    output stand almost still.

    Parameters
    ----------
    crank, coupler, rocker, frame : float
        AB, BC, CD and AD of the four-bar (defaults 20, 50, 45, 50).
    point : complex
        E in the coupler's frame (origin B, x along B->C): default 55 + 15j.
    pivot : complex
        Output pivot H (default 54 - 27j).
    link5, output : float
        EG (default 82.3, the radius of the arc) and GH (default 8).

    Returns
    -------
    Linkage
        Points A, D, H (ground), B, C, E, G; links crank, coupler, rocker, link5, output.

    Raises
    ------
    ValueError
        If a length is not positive.

    Notes
    -----
    The dimensions are chosen here: E's curve between crank angles 230 and 350 degrees
    lies within 0.07 of a circle of radius 82.3 about 59.73 - 21.42j, and H puts G there.
    The output swings 20.7 degrees in all and stays within 0.91 degrees over those 120
    degrees of crank turn (the dwell). Derivation: `deriv-assur-groups`.

    Examples
    --------
    >>> sol = stephenson_six_bar().solve(np.linspace(0, 2 * np.pi, 361))
    >>> bool(sol.valid.all())
    True
    """
    L = _lengths(crank=crank, coupler=coupler, rocker=rocker, frame=frame, link5=link5, output=output)
    return (Linkage({"A": 0.0, "D": L["frame"], "H": planar_point("pivot", pivot)})
            .crank("crank", pivot="A", tip="B", length=L["crank"])
            .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C",
                 lengths=(L["coupler"], L["rocker"]), branch=1)
            .point("E", link="coupler", at=planar_point("point", point))
            .rrr(("link5", "output"), pins=("E", "H"), joint="G", lengths=(L["link5"], L["output"]), branch=1))


# ----------------------------------------------------------------------------- shapers
def _ram(lk, *, pin, height, rod, branch=1):
    """Append the rod ``pin -> F`` and the ram F sliding on the line y = height."""
    return lk.rrp(("rod", "ram"), pin=pin, guide=Guide("ground", complex(0.0, height), 0.0),
                  joint="F", length=rod, branch=branch)


def shaper_watt(*, crank=124.0, frame=400.0, bar=485.0, rod=120.0, height=None):
    """Shaper of Fig. 2-18a: a Watt chain with two sliding pairs (oscillating guide-bar).

    The crank ``A B`` (A = 0) carries a block at B that slides in the guide bar pivoted at
    D = -``frame`` j (below A); the bar's end E (at ``bar`` from D) drives the rod ``E F``
    and the ram F slides on the horizontal line y = ``height``. The two ternary links,
    the frame (A, D, the ram's guide) and the bar (D, the block's slot, E), share the
    joint D: a Watt chain with the joints at the block and at the ram made prismatic.

    Parameters
    ----------
    crank, frame, bar, rod : float
        AB, AD, DE and EF (defaults 124, 400, 485, 120: stroke about 300, K about 1.5).
    height : float, optional
        The ram's line; default the top of E's arc, ``bar - frame``.

    Returns
    -------
    Linkage
        Points A, D (ground), B, E, F; links crank, bar, block, rod, ram.

    Raises
    ------
    ValueError
        If a length is not positive, or ``crank >= frame`` (the bar would turn fully).

    Notes
    -----
    The dimensions are chosen here. The bar's swing and the extreme angle are both
    2 arcsin(crank / frame) (F23). Groups: RPR for the bar, RRP for the ram (derivation:
    `deriv-assur-groups`). See `ram_stroke` for the stroke and K.

    Examples
    --------
    >>> s = ram_stroke(shaper_watt())
    >>> round(s.length, 1), round(s.time_ratio, 3)
    (300.7, 1.502)
    """
    L = _lengths(crank=crank, frame=frame, bar=bar, rod=rod)
    if L["crank"] >= L["frame"]:
        raise ValueError(f"Expected `crank` < `frame` = {L['frame']!r}, got {L['crank']!r}")
    h = L["bar"] - L["frame"] if height is None else real_number("height", height)
    lk = (Linkage({"A": 0.0, "D": complex(0.0, -L["frame"])})
          .crank("crank", pivot="A", tip="B", length=L["crank"])
          .rpr(("bar", "block"), pins=("D", "B"), offset=0.0, branch=1)
          .point("E", link="bar", at=L["bar"]))
    return _ram(lk, pin="E", height=h, rod=L["rod"])


def shaper_stephenson(*, crank=120.0, frame=300.0, bar=600.0, rod=400.0, height=None):
    """Shaper of Fig. 2-18b: a Stephenson chain with two sliding pairs (oscillating block).

    The crank ``A B`` (A = 0) carries the guide bar pinned at B; the bar slides through a
    block that swings about D = ``frame`` j (above A), and its point E, at ``bar`` from B
    beyond D, drives the rod ``E F`` and the ram F on the line y = ``height``. The
    ternary links, the frame (A, D, the ram's guide) and the bar (B, the block's slot,
    E), share no joint: a Stephenson chain with the joints at the block and at the ram
    made prismatic.

    Parameters
    ----------
    crank, frame, bar, rod : float
        AB, AD, BE and EF (defaults 120, 300, 600, 400).
    height : float, optional
        The ram's line; default E's highest point, ``bar + crank``.

    Returns
    -------
    Linkage
        Points A, D (ground), B, E, F; links crank, bar, block, rod, ram.

    Raises
    ------
    ValueError
        If a length is not positive, ``crank >= frame`` or ``bar <= frame + crank``
        (E would reach the block).

    Notes
    -----
    The dimensions are chosen here. The bar swings through 2 arcsin(crank / frame).
    Groups: RPR for the bar, RRP for the ram (derivation: `deriv-assur-groups`).

    Examples
    --------
    >>> s = ram_stroke(shaper_stephenson())
    >>> round(s.length, 1), round(s.time_ratio, 3)
    (277.6, 2.375)
    """
    L = _lengths(crank=crank, frame=frame, bar=bar, rod=rod)
    if L["crank"] >= L["frame"]:
        raise ValueError(f"Expected `crank` < `frame` = {L['frame']!r}, got {L['crank']!r}")
    if L["bar"] <= L["frame"] + L["crank"]:
        raise ValueError(f"Expected `bar` > frame + crank = {L['frame'] + L['crank']!r}, got {L['bar']!r}")
    h = L["bar"] + L["crank"] if height is None else real_number("height", height)
    lk = (Linkage({"A": 0.0, "D": complex(0.0, L["frame"])})
          .crank("crank", pivot="A", tip="B", length=L["crank"])
          .rpr(("bar", "block"), pins=("B", "D"), offset=0.0, branch=1)
          .point("E", link="bar", at=L["bar"]))
    return _ram(lk, pin="E", height=h, rod=L["rod"])


# ----------------------------------------------------------------------------- quick return
def quick_return_guide_bar(*, crank=124.0, frame=400.0, bar=485.0, rod=120.0):
    """Quick-return candidate 1 of Fig. 2-36: crank, oscillating guide-bar, rod and ram.

    The same construction as `shaper_watt` (A = 0, bar pivot D below A, ram on the line
    through the top of E's arc), with dimensions chosen for a stroke of about 300 and a
    time ratio of about 1.5, like the other two candidates.

    Parameters
    ----------
    crank, frame, bar, rod : float
        AB, AD, DE and EF (defaults 124, 400, 485, 120).

    Returns
    -------
    Linkage
        As `shaper_watt`.

    Raises
    ------
    ValueError
        As `shaper_watt`.

    Notes
    -----
    The textbook's Fig. 2-36 is not described in words, so its three candidates are taken
    to be the classic three: this one, `quick_return_slider_crank` and
    `quick_return_crank_rocker`.

    Examples
    --------
    >>> s = ram_stroke(quick_return_guide_bar())
    >>> round(s.length), round(s.time_ratio, 2)
    (301, 1.5)
    """
    return shaper_watt(crank=crank, frame=frame, bar=bar, rod=rod)


def quick_return_slider_crank(*, crank=129.0, rod=280.0, offset=120.0):
    """Quick-return candidate 2 of Fig. 2-36: the offset slider-crank.

    Crank ``A B`` about A = 0 and rod ``B F`` to the ram F on the line y = ``offset``:
    `mech.planar.SliderCrank` (a, b, e) = (``crank``, ``rod``, ``offset``) built as a
    `Linkage` (a crank and an RRP group), so that it can be compared with the others.

    Parameters
    ----------
    crank, rod : float
        AB and BF (defaults 129 and 280).
    offset : float
        The ram's line y = offset (default 120).

    Returns
    -------
    Linkage
        Points A (ground), B, F; links crank, rod, ram.

    Raises
    ------
    ValueError
        If a length is not positive.

    Notes
    -----
    The dimensions are chosen here for a stroke of about 300 and K about 1.5; the crank
    turns fully when ``rod - crank > |offset|`` (F31).

    Examples
    --------
    >>> s = ram_stroke(quick_return_slider_crank())
    >>> round(s.length), round(s.time_ratio, 2)
    (299, 1.49)
    """
    L = _lengths(crank=crank, rod=rod)
    lk = Linkage({"A": 0.0}).crank("crank", pivot="A", tip="B", length=L["crank"])
    return _ram(lk, pin="B", height=real_number("offset", offset), rod=L["rod"])


def quick_return_crank_rocker(*, crank=60.0, coupler=120.0, rocker=180.0, frame=160.0,
                              lever=400.0, lever_angle=math.radians(-49.0), rod=150.0, height=None):
    """Quick-return candidate 3 of Fig. 2-36: a crank-rocker whose rocker drives a ram.

    The crank-rocker ``A B C D`` (A = 0, D = ``frame`` on +x) carries on its rocker the
    arm ``D E`` at ``lever_angle`` from D->C; the rod ``E F`` drives the ram F on the
    line y = ``height``.

    Parameters
    ----------
    crank, coupler, rocker, frame : float
        AB, BC, CD and AD (defaults 60, 120, 180, 160: K = 1.5, swing 44.4 degrees).
    lever, lever_angle : float
        DE and its angle from D->C, radians (defaults 400 and -49 degrees, which makes
        the arm upright in the middle of its swing).
    rod : float
        EF (default 150).
    height : float, optional
        The ram's line; default the top of E's arc, ``lever``.

    Returns
    -------
    Linkage
        Points A, D (ground), B, C, E, F; links crank, coupler, rocker, rod, ram.

    Raises
    ------
    ValueError
        If a length is not positive.

    Notes
    -----
    The dimensions are chosen here for a stroke of about 300 and K about 1.5.

    Examples
    --------
    >>> sol = quick_return_crank_rocker().solve(np.linspace(0, 2 * np.pi, 361))
    >>> bool(sol.valid.all())
    True
    """
    L = _lengths(crank=crank, coupler=coupler, rocker=rocker, frame=frame, lever=lever, rod=rod)
    h = L["lever"] if height is None else real_number("height", height)
    lk = (Linkage({"A": 0.0, "D": L["frame"]})
          .crank("crank", pivot="A", tip="B", length=L["crank"])
          .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C",
               lengths=(L["coupler"], L["rocker"]), branch=1)
          .point("E", link="rocker", at=L["lever"] * _unit_at_angle("lever_angle", lever_angle)))
    return _ram(lk, pin="E", height=h, rod=L["rod"])


# ----------------------------------------------------------------------------- Jansen
def jansen_linkage(**lengths):
    """One leg of Theo Jansen's Strandbeest, with his "holy numbers" by default.

    The crank ``O A`` (length m, O = 0) turns about O; the frame pivot is
    Z = -a - l j. Two RRR groups hang from A and Z: the upper joint B (AB = j, ZB = b)
    and the lower joint D (AD = k, ZD = c). The triangle ``Z B C`` (ZB = b, ZC = d,
    BC = e) is one link, the RRR group C-E-D (CE = f, DE = g) forms the knee E, and
    the triangle ``D E F`` (DE = g, DF = i, EF = h) carries the foot F.

    Parameters
    ----------
    **lengths : float
        Any of the thirteen lengths ``a`` to ``m`` to change (see `JANSEN_HOLY_NUMBERS`:
        a=38, b=41.5, c=39.3, d=40.1, e=55.8, f=39.4, g=36.7, h=65.7, i=49, j=50,
        k=61.9, l=7.8, m=15).

    Returns
    -------
    Linkage
        Points O, Z (ground), A, B, C, D, E, F (the foot); links crank, j, b, k, c, f, g.

    Raises
    ------
    ValueError
        If a name is unknown, a length is not positive, or a triangle cannot close.

    Notes
    -----
    The assembly modes are those of Jansen's leg: B above and D below the line A->Z, C
    outside (away from the crank), E and F outward and down. The foot's path has a nearly
    straight bottom (the stance), which the book measures. Derivation of the groups:
    `deriv-assur-groups`.

    Examples
    --------
    >>> sol = jansen_linkage().solve(np.linspace(0, 2 * np.pi, 361))
    >>> bool(sol.valid.all()), round(float(sol.points["F"].imag.min()), 1)
    (True, -91.8)
    """
    unknown = sorted(set(lengths) - set(JANSEN_HOLY_NUMBERS))
    if unknown:
        raise ValueError(f"Expected lengths among {sorted(JANSEN_HOLY_NUMBERS)}, got {unknown}")
    n = {k: positive_length(k, lengths.get(k, v)) for k, v in JANSEN_HOLY_NUMBERS.items()}
    return (Linkage({"O": 0.0, "Z": complex(-n["a"], -n["l"])})
            .crank("crank", pivot="O", tip="A", length=n["m"])
            .rrr(("j", "b"), pins=("A", "Z"), joint="B", lengths=(n["j"], n["b"]), branch=-1)
            .point("C", link="b", at=_triangle(n["b"], n["d"], n["e"], 1, "the link b-d-e"))
            .rrr(("k", "c"), pins=("A", "Z"), joint="D", lengths=(n["k"], n["c"]), branch=1)
            .rrr(("f", "g"), pins=("C", "D"), joint="E", lengths=(n["f"], n["g"]), branch=-1)
            .point("F", link="g", at=_triangle(n["g"], n["i"], n["h"], 1, "the link g-h-i")))


# ----------------------------------------------------------------------------- measuring
def step_ratio(solution, *, axis=-1):
    """Largest step over the median step of every moving point along a sampled motion.

    Parameters
    ----------
    solution : LinkageSolution
        Solved at inputs sampled uniformly along ``axis`` (e.g. 3600 crank angles).
    axis : int
        The axis of the samples.

    Returns
    -------
    dict of str to float
        For every point that moves, max ``|P[k+1] - P[k]|`` / median ``|P[k+1] - P[k]|``. A jump
        from one assembly mode to another gives a step of the order of a link length, far
        above the ratio of the largest to the median speed that a smooth motion gives.

    Examples
    --------
    >>> sol = jansen_linkage().solve(np.linspace(0, 2 * np.pi, 3601))
    >>> max(step_ratio(sol).values()) < 3
    True
    """
    if not hasattr(getattr(solution, "points", None), "items"):    # any solved linkage with points
        raise InputTypeError(f"Expected `solution` to be a LinkageSolution, got {solution!r}")
    axis = integer("axis", axis, minimum=-64, maximum=63)
    out = {}
    for name, z in solution.points.items():
        step = np.abs(np.diff(z, axis=axis))
        med = float(np.median(step))
        if med > 0.0:
            out[name] = float(np.max(step) / med)
    return out


@dataclass(frozen=True)
class Stroke:
    """Stroke of a point along a line over one crank turn (from `ram_stroke`).

    Attributes: ``length`` H; ``theta_min``, ``theta_max`` (crank angles in [0, 2 pi)
    where the point is at either end); ``forward`` (crank turn from the min end to the
    max end, the crank turning counter-clockwise), ``back`` (2 pi - forward); and
    ``time_ratio`` K = max(forward, back) / min(forward, back) of eq. (2-9).
    """

    length: float
    theta_min: float
    theta_max: float
    forward: float
    back: float
    time_ratio: float


def ram_stroke(linkage, point="F", *, direction=1.0 + 0.0j, samples=3600):
    """Stroke and time ratio K of ``point`` along ``direction`` over a crank turn.

    Parameters
    ----------
    linkage : Linkage
        With one crank as its driver.
    point : str
        The point to follow (default ``"F"``, the ram of the ready-made shapers).
    direction : complex
        The line along which the position is measured (default +x).
    samples : int
        Crank angles sampled; each end is then refined by bisection on the sign of the
        point's velocity along ``direction``, to rounding.

    Returns
    -------
    Stroke

    Raises
    ------
    ValueError
        If the linkage does not assemble over the whole turn.

    Examples
    --------
    >>> s = ram_stroke(quick_return_slider_crank())
    >>> round(s.length, 1), round(s.time_ratio, 3)
    (299.3, 1.492)
    """
    instance("linkage", linkage, Linkage)
    known_name("point", point, linkage.point_names)
    e = planar_point("direction", direction)
    if e == 0:
        raise ValueError(f"Expected a non-zero `direction`, got {direction!r}")
    e = e / abs(e)
    samples = integer("samples", samples, minimum=3, maximum=MAX_COUNT)
    th = 2.0 * math.pi * np.arange(samples) / samples
    sol = linkage.solve(th)
    if not np.all(sol.valid):
        bad = float(th[~sol.valid][0])
        raise ValueError(f"Expected a linkage that assembles over the whole turn, got a failure at {bad!r}")
    x = np.real(sol.points[point] * e.conjugate())
    n = len(th)
    step = 2.0 * math.pi / n

    def rate(t):
        return float(np.real(linkage.solve(np.array([t]), order=1).velocities[point][0] * e.conjugate()))

    def refine(k):
        lo, hi = th[k] - step, th[k] + step
        s_lo = rate(lo) > 0
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            if mid in (lo, hi):
                break
            if (rate(mid) > 0) == s_lo:
                lo = mid
            else:
                hi = mid
        t = 0.5 * (lo + hi)
        return float(t % (2.0 * math.pi)), float(np.real(linkage.solve(np.array([t])).points[point][0] * e.conjugate()))

    t_min, x_min = refine(int(np.argmin(x)))
    t_max, x_max = refine(int(np.argmax(x)))
    forward = float((t_max - t_min) % (2.0 * math.pi))
    back = 2.0 * math.pi - forward
    return Stroke(x_max - x_min, t_min, t_max, forward, back, max(forward, back) / min(forward, back))


# ----------------------------------------------------------------------------- drawing
def sketch(linkage):
    """Which points each link carries, and where its sliding blocks are, for drawing.

    Parameters
    ----------
    linkage : Linkage

    Returns
    -------
    dict
        ``"links"``: link name -> tuple of point names (in the order defined);
        ``"ground"``: names of the fixed points; ``"blocks"``: tuples
        ``(point, link)``, a block at the point, oriented along the link's frame;
        ``"guides"``: tuples ``(point, link)``, a fixed straight guide through the point,
        along the link's frame (for blocks sliding on the frame).

    Examples
    --------
    >>> sketch(shaper_watt())["links"]["bar"]
    ('D', 'B', 'E')
    """
    links, ground, blocks, guides = {}, [], [], []

    def add(link, *names):
        cur = links.setdefault(link, [])
        cur.extend(n for n in names if n not in cur)

    for step in linkage._steps:  # read-only walk over the solver's build steps
        kind, get = step.kind, step.get
        if kind == "ground":
            ground.append(step.label)
        elif kind == "point":
            add(step.links[0], step.label)
        elif kind == "crank":
            add(step.links[0], get("pivot"), get("tip"))
        elif kind == "rrr":
            (p1, p2), joint = get("pins"), get("joint")
            add(step.links[0], p1, joint)
            add(step.links[1], p2, joint)
        elif kind == "rrp":
            add(step.links[0], get("pin"), get("joint"))
            blocks.append((get("joint"), step.links[1]))
            if get("guide").link == "ground":
                guides.append((get("joint"), step.links[1]))
        elif kind == "rpr":
            p1, p2 = get("pins")
            add(step.links[0], p1, p2)
            blocks.append((p2, step.links[1]))
        elif kind in ("slider", "prp", "rpp"):
            pt = get("point") if kind != "prp" else get("joint")
            blocks.append((pt, step.links[0]))
    return {"links": {k: tuple(v) for k, v in links.items() if k != "ground"},
            "ground": tuple(ground), "blocks": tuple(blocks), "guides": tuple(guides)}
