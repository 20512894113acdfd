"""Exercises 2-30, 2-31 and 2-32 of chapter 2: quick-return design from the time ratio K.

Each solution lists every design that fits the givens, builds it with
`mech.planar.synthesis` (or by the geometry of the limit positions), and proves it by
simulating one full crank turn with `FourBar` or `GuideBar`: the time ratio, the swing or
stroke and the minimum transmission (or pressure) angle in the results are MEASURED by
that simulation, not taken from the design formulas. A design whose simulation does not
reproduce the task is dropped. The solutions are shown on the book page
``book-synthesis-quick-return``; the theory on ``deriv-quick-return-design``.

Examples
--------
>>> from mech.exercises.chapter2_quick_return import EXERCISE_2_30
>>> s = EXERCISE_2_30.solve()
>>> round(float(s["(1) l_BC, D on the side of A"].value), 3), round(float(s["(1) l_AD, D on the side of A"].value), 3)
(176.014, 278.717)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from mech._validate import integer, naming, option, positive_length, real_number
from mech.exercises._core import Exercise, Parameter, Part, Result, Solution
from mech.planar import FourBar, GuideBar, extreme_angle, grashof
from mech.planar.synthesis import crank_rocker_family, quick_return_crank_rocker, simulate_quick_return

__all__ = [
    "EXERCISE_2_30",
    "EXERCISE_2_31",
    "EXERCISE_2_32",
    "designs_2_30",
    "designs_2_31",
    "Shaper",
    "shaper_2_32",
]


def _optimize():
    """SciPy's optimize module, imported on first use so that importing mech stays light."""
    from scipy import optimize

    return optimize

_DEG = math.pi / 180.0
#: Relative tolerance on the simulated time ratio and swing of an accepted design, and the
#: absolute tolerance (rad) on its rocker angle at the given limit position.
_RTOL = 1e-9
_SIDES = {1: "D on the side of A", -1: "D across the chord"}


def _measured(linkage):
    return simulate_quick_return(linkage)


def _agrees(measured, wanted):
    return abs(measured - wanted) <= _RTOL * abs(wanted)


def _time_ratio(p):
    """The exercise's `K`, checked under its own name (the library calls it `time_ratio`)."""
    K = real_number("K", p["K"])
    if not K >= 1.0:
        raise ValueError(f"Expected `K` >= 1, got {K!r}")
    return K


# ----------------------------------------------------------------------------- 2-30
def designs_2_30(p, given):
    """The crank-rockers of exercise 2-30 with the crank (``given="a"``) or coupler (``"b"``) given.

    Returns a list of ``(side, design, check)`` for both sides of the chord C1C2 (see
    `quick_return_crank_rocker`) whose simulation reproduces K and the swing; a side with
    no crank-rocker is left out.

    Examples
    --------
    >>> from mech.exercises.chapter2_quick_return import EXERCISE_2_30, designs_2_30
    >>> [side for side, _, _ in designs_2_30(EXERCISE_2_30.defaults, "a")]
    [1, -1]
    """
    K = _time_ratio(p)
    c = positive_length("l_CD", p["l_CD"])
    swing = positive_length("psi", p["psi"]) * _DEG
    # the given link is checked here, under its exercise name: a bad value must not read as
    # "no crank-rocker on this side" in the loop below
    if option("given", given, ("a", "b")) == "a":
        keyword = {"crank": positive_length("l_AB", p["l_AB"])}
    else:
        keyword = {"coupler": positive_length("l_BC", p["l_BC"])}
    out = []
    for side in (1, -1):
        try:
            q = quick_return_crank_rocker(K, c, swing, side=side, **keyword)
        except ValueError:
            continue
        check = _measured(q.fourbar)
        if _agrees(check.time_ratio, K) and _agrees(check.output_range, swing):
            out.append((side, q, check))
    return out


_STATEMENT_2_30 = (
    "Design a crank-rocker ABCD with rocker CD = {l_CD} mm, swing psi = {psi}° between the "
    "rocker's limit positions and time ratio K = {K}. (1) With the crank AB = {l_AB} mm find "
    "the coupler BC and the frame AD, and check whether the minimum transmission angle is "
    "acceptable ([gamma] = {gamma_allowed}° assumed). (2) With the coupler BC = {l_BC} mm find "
    "the crank AB and the frame AD."
)


def _design_results(tag, side, q, check, gamma_allowed):
    a, b, c, d = q.lengths
    name = _SIDES[side]
    return (
        Result(f"{tag} l_AB, {name}", a, "mm", "given" if tag == "(1)" else "from alpha, (2-46) third line"),
        Result(f"{tag} l_BC, {name}", b, "mm", "given" if tag == "(2)" else "from alpha, (2-46) fourth line"),
        Result(f"{tag} l_AD, {name}", d, "mm", "(2-46) fifth line" if side == 1 else "|A - D|, D across the chord"),
        Result(f"{tag} alpha, {name}", q.alpha, "rad", "angle AOC1 fixed by the given length"),
        Result(f"{tag} K simulated, {name}", check.time_ratio, "", "one crank turn of `FourBar`"),
        Result(f"{tag} swing simulated, {name}", check.output_range, "rad", "rocker stops of the simulation"),
        Result(f"{tag} gamma_min simulated, {name}", check.min_transmission_angle, "rad",
               "smallest angle BCD (or its supplement) over the turn"),
        Result(f"{tag} gamma_min >= [gamma], {name}", bool(check.min_transmission_angle >= gamma_allowed),
               "", f"[gamma] = {math.degrees(gamma_allowed):g}°"),
    )


def _solve_2_30(p):
    gamma_allowed = real_number("gamma_allowed", p["gamma_allowed"])
    if not 0.0 <= gamma_allowed < 90.0:
        raise ValueError(f"Expected `gamma_allowed` in [0, 90) degrees, got {gamma_allowed!r}")
    gamma_allowed *= _DEG
    parts = []
    for tag, given, title in (("(1)", "a", "Part 1: crank given"), ("(2)", "b", "Part 2: coupler given")):
        found = designs_2_30(p, given)
        if not found:
            listed, shown = naming(**dict(p))
            raise ValueError(f"Expected {listed} that admit a crank-rocker in part {tag}, got {shown}")
        results = tuple(r for side, q, check in found for r in _design_results(tag, side, q, check, gamma_allowed))
        parts.append(Part(title, results, (
            "Both sides of the chord C1C2 for the pivot D give a crank-rocker with the given "
            "length; the textbook's Fig. 2-101 draws only D on the side of A.",)))
    fam = crank_rocker_family(p["K"], p["l_CD"], p["psi"] * _DEG, min_transmission=gamma_allowed)
    best = fam.best
    check = _measured(best.fourbar)
    parts.append(Part("For comparison: the largest gamma_min for this K, c and psi", (
        Result("best l_AB", best.lengths[0], "mm", "alpha maximising gamma_min, `crank_rocker_family`"),
        Result("best l_BC", best.lengths[1], "mm"),
        Result("best l_AD", best.lengths[3], "mm"),
        Result("best gamma_min simulated", check.min_transmission_angle, "rad", "one crank turn of `FourBar`"),
        Result("alpha ranges with gamma_min >= [gamma]", ", ".join(
            f"({math.degrees(lo):.3f}°, {math.degrees(hi):.3f}°)" for lo, hi in fam.intervals) or "none", "",
            "D on the side of A"),
    )))
    conventions = (
        "theta = 180° (K - 1)/(K + 1); A lies on the circle that sees the rocker's limit "
        "positions C1 C2 under theta; AC2 = b + a (extended), AC1 = b - a (folded).",
        "The exercise states no permitted transmission angle: [gamma] = 40° is assumed, the "
        "chapter's example value (§2.4 III, after (2-48)).",
        "The textbook also asks for a graphical solution; the analytical one (2-46) gives "
        "the same linkage exactly.",
    )
    return Solution("2-30", EXERCISE_2_30.title, dict(p), conventions, tuple(parts))


def _sample_2_30(rng):
    c = float(rng.integers(100, 400))
    psi = float(rng.integers(20, 60))
    K = float(rng.choice([1.1, 1.15, 1.2, 1.25, 1.3, 1.35, 1.4]))
    top = c * math.sin(psi * _DEG / 2)
    return {"l_CD": c, "psi": psi, "K": K, "l_AB": float(round(top * rng.uniform(0.3, 0.95))),
            "l_BC": float(round(top * rng.uniform(1.1, 1.8))), "gamma_allowed": 40.0}


EXERCISE_2_30 = Exercise(
    number="2-30",
    title="A quick-return crank-rocker from K, the rocker and its swing",
    tag="N",
    statement=_STATEMENT_2_30,
    parameters=(
        Parameter("l_CD", 290.0, "mm", "rocker"),
        Parameter("psi", 32.0, "°", "rocker swing"),
        Parameter("K", 1.25, "", "time ratio"),
        Parameter("l_AB", 75.0, "mm", "crank, part 1"),
        Parameter("l_BC", 100.0, "mm", "coupler, part 2"),
        Parameter("gamma_allowed", 40.0, "°", "permitted transmission angle (assumed)"),
    ),
    solver=_solve_2_30,
    sampler=_sample_2_30,
)


# ----------------------------------------------------------------------------- 2-31
def designs_2_31(p):
    """Every crank-rocker of exercise 2-31, as ``(limit, fourbar, check)``.

    The frame is A = 0, D = (AD, 0); the given limit position has C above the frame with
    the interior angle CDA = phi. The other limit position C' lies on the rocker's circle
    on one of the two rays from A at the angle theta from AC; the longer of AC, AC' is
    b + a (extended), the shorter b - a (folded). A candidate is kept when its simulation
    has time ratio K and a rocker stop at the given position. ``limit`` names the given
    position: ``"extended"`` or ``"folded"``.

    Examples
    --------
    >>> from mech.exercises.chapter2_quick_return import EXERCISE_2_31, designs_2_31
    >>> [(limit, round(fb.a, 3), round(fb.b, 3)) for limit, fb, _ in designs_2_31(EXERCISE_2_31.defaults)]
    [('extended', 26.916, 32.58), ('folded', 38.671, 98.167)]
    """
    c = positive_length("l_CD", p["l_CD"])
    d = positive_length("l_AD", p["l_AD"])
    K = _time_ratio(p)
    theta = float(extreme_angle(K))
    psi_given = math.pi - positive_length("phi", p["phi"]) * _DEG
    C = d + c * np.exp(1j * psi_given)
    out = []
    for turn in (1, -1):
        u = C / abs(C) * np.exp(1j * turn * theta)
        # in units of max(c, d), so that no square leaves the float range
        unit = max(c, d)
        half = d / unit * u.real
        disc = half**2 - (d / unit) ** 2 + (c / unit) ** 2
        for t in {(half + math.sqrt(disc)) * unit, (half - math.sqrt(disc)) * unit} if disc >= 0 else ():
            if t <= 0:
                continue
            long_, short = max(abs(C), t), min(abs(C), t)
            a, b = (long_ - short) / 2, (long_ + short) / 2
            if not a > 0.0:             # the two diagonals agree to rounding: no crank
                continue
            if not grashof(a, b, c, d).kind == "crank-rocker":
                continue
            limit = "extended" if abs(C) > t else "folded"
            B = a * C / abs(C) * (1 if limit == "extended" else -1)
            branch = 1 if ((d - B).conjugate() * (C - B)).imag > 0 else -1
            fb = FourBar(a, b, c, d, branch=branch)
            check = _measured(fb)
            stops = np.array(check.output_limits)
            if _agrees(check.time_ratio, K) and np.min(np.abs(np.angle(np.exp(1j * (stops - psi_given))))) <= _RTOL:
                out.append((limit, fb, check))
    return sorted(out, key=lambda x: x[1].a)


_STATEMENT_2_31 = (
    "A hinged four-bar has the rocker CD = {l_CD} mm, the time ratio K = {K} and the frame "
    "AD = {l_AD} mm; one limit position of the rocker makes the angle phi = {phi}° with the "
    "frame. Find the crank AB and the coupler BC."
)


def _solve_2_31(p):
    found = designs_2_31(p)
    if not found:
        listed, shown = naming(**dict(p))
        raise ValueError(f"Expected {listed} that admit a crank-rocker, got {shown}")
    results = []
    for k, (limit, fb, check) in enumerate(found, 1):
        results += [
            Result(f"design {k}: the given position is", limit, "",
                   "A, B, C in line: stretched out (b + a) or folded (b - a)"),
            Result(f"design {k}: l_AB", fb.a, "mm", "(AC_long - AC_short) / 2"),
            Result(f"design {k}: l_BC", fb.b, "mm", "(AC_long + AC_short) / 2"),
            Result(f"design {k}: K simulated", check.time_ratio, "", "one crank turn of `FourBar`"),
            Result(f"design {k}: swing simulated", check.output_range, "rad"),
            Result(f"design {k}: gamma_min simulated", check.min_transmission_angle, "rad"),
        ]
    assumptions = (
        "A = (0, 0), D = (AD, 0); phi is the interior angle CDA at the given limit position, "
        "with C above the frame (a mirror image gives the same lengths).",
        "The text does not say which limit position makes phi: both are tried, with the other "
        "limit position on either side of AC; every crank-rocker that the simulation confirms "
        "is listed.",
    )
    conventions = (
        "theta = 180° (K - 1)/(K + 1); at the two limit positions A, B, C are in line, so "
        "A sees the two positions of C under theta.",
    )
    part = Part("Every crank-rocker that fits", tuple(results), (
        "Measuring phi from the extension of AD beyond D instead would put C at phi above "
        "the frame line on the far side of D and give other lengths.",))
    return Solution("2-31", EXERCISE_2_31.title, dict(p), conventions, (part,), assumptions=assumptions)


def _sample_2_31(rng):
    return {"l_CD": float(rng.integers(50, 120)), "K": float(rng.choice([1.2, 1.3, 1.4, 1.5, 1.6])),
            "l_AD": float(rng.integers(60, 150)), "phi": float(rng.integers(30, 80))}


EXERCISE_2_31 = Exercise(
    number="2-31",
    title="A quick-return crank-rocker from K, the frame and one limit position",
    tag="A",
    statement=_STATEMENT_2_31,
    parameters=(
        Parameter("l_CD", 75.0, "mm", "rocker"),
        Parameter("K", 1.5, "", "time ratio"),
        Parameter("l_AD", 80.0, "mm", "frame"),
        Parameter("phi", 45.0, "°", "angle of one limit position with the frame"),
    ),
    solver=_solve_2_31,
    sampler=_sample_2_31,
)


# ----------------------------------------------------------------------------- 2-32
@dataclass(frozen=True)
class Shaper:
    """A shaper drive: crank AB, oscillating guide CD pivoted at C, link DE, ram E.

    The crank turns about A = 0; the guide pivot C is at (AC, 0); the guide's end D is at
    ``C + l_CD exp(1j*psi)`` with psi the guide angle of `GuideBar` (pointing back past A);
    the ram's pin E runs on the line x = x_ram, perpendicular to the frame line, above D.
    """

    guide_bar: GuideBar
    l_CD: float
    l_DE: float
    x_ram: float

    def ram(self, theta, order=0):
        """Ram position y_E (and its velocity with ``order=1``, unit crank speed) at `theta`."""
        y, *rate = self._ram_below_link(theta, order)
        return y + self.l_DE if order == 0 else (y + self.l_DE, *rate)

    def _ram_below_link(self, theta, order):
        """y_E - l_DE, which keeps the ram's motion however long DE is (y_E alone loses it
        once l_DE / H is near 1e16), and with ``order=1`` the ram's velocity."""
        pose = self.guide_bar.solve(theta, order=order)
        D = self.guide_bar.d + self.l_CD * np.exp(1j * pose.psi)
        dx = self.x_ram - D.real
        r = dx / self.l_DE
        height = self.l_DE * np.sqrt((1.0 - r) * (1.0 + r))   # |E - D| = l_DE, no square overflows
        below = D.imag - dx * r / (1.0 + np.sqrt((1.0 - r) * (1.0 + r)))   # D.imag + height - l_DE
        if order == 0:
            return (below,)
        vD = 1j * self.l_CD * pose.omega_guide * np.exp(1j * pose.psi)
        # E moves along y only and keeps |E - D|: Re(conj(w) (vE - vD)) = 0, w = dx + i height
        return below, (dx * vD.real + height * vD.imag) / height

    def pressure_angle(self, theta):
        """Angle between the link DE (the force on the ram) and the ram's path, at `theta`."""
        pose = self.guide_bar.solve(theta)
        D = self.guide_bar.d + self.l_CD * np.exp(1j * pose.psi)
        return np.arcsin(np.abs(self.x_ram - D.real) / self.l_DE)

    def measure(self, samples=4096, xtol=1e-13):
        """Simulate one crank turn: (K, stroke, largest pressure angle), all measured."""
        samples = integer("samples", samples, minimum=16, maximum=10**7)
        xtol = positive_length("xtol", xtol)
        t = np.linspace(0.0, 2 * math.pi, samples, endpoint=False)
        v = self._ram_below_link(t, 1)[1]
        idx = np.flatnonzero(np.sign(v) != np.sign(np.roll(v, -1)))
        step = t[1] - t[0]
        stops = [_optimize().brentq(lambda u: float(self._ram_below_link(np.array([u]), 1)[1][0]), t[i], t[i] + step,
                                    xtol=xtol) for i in idx]
        if len(stops) != 2:
            raise ValueError(f"Expected a ram with two limit positions per turn at `samples` = {samples} and "
                             f"`xtol` = {xtol!r}, got {len(stops)}")
        y = self._ram_below_link(np.array(stops), 0)[0]
        forward = (stops[int(np.argmax(y))] - stops[int(np.argmin(y))]) % (2 * math.pi)
        K = max(forward, 2 * math.pi - forward) / min(forward, 2 * math.pi - forward)
        worst = float(np.max(self.pressure_angle(t)))
        return K, float(np.ptp(y)), worst


def shaper_2_32(p):
    """The shaper of exercise 2-32 for the givens `p`.

    Swing of the guide = theta; frame AC = l_AB / sin(theta/2); guide CD = H / (2 sin(theta/2))
    so that the chord of D's arc is the stroke; the ram's path halves the sagitta of that arc,
    which makes the largest pressure angle as small as possible.

    Examples
    --------
    >>> from mech.exercises.chapter2_quick_return import EXERCISE_2_32, shaper_2_32
    >>> s = shaper_2_32(EXERCISE_2_32.defaults)
    >>> round(s.guide_bar.d, 9), round(s.l_CD, 9), round(s.guide_bar.d - s.x_ram, 3)
    (150.0, 300.0, 279.904)
    """
    a = positive_length("l_AB", p["l_AB"])
    l_DE = positive_length("l_DE", p["l_DE"])
    H = positive_length("H", p["H"])
    theta = float(extreme_angle(_time_ratio(p)))
    if not 0.0 < theta < math.pi:     # K beyond about 1e16 rounds the extreme angle to pi
        raise ValueError(f"Expected `K` > 1 with an extreme angle pi (K - 1)/(K + 1) below pi, got {p['K']!r}")
    AC = a / math.sin(theta / 2)
    l_CD = H / (2 * math.sin(theta / 2))
    sagitta = l_CD * (1 - math.cos(theta / 2))
    if not sagitta / 2 < l_DE:
        raise ValueError(f"Expected `l_DE` > half the sagitta of the arc of D ({sagitta / 2!r}, from `H` = {H!r} "
                         f"and `K` = {p['K']!r}), got {l_DE!r}")
    if not l_CD > AC + a:
        raise ValueError(f"Expected `H`, `l_AB` and `K` that make the guide CD = {l_CD!r} longer than AC + AB = "
                         f"{AC + a!r}, got H={H!r}, l_AB={a!r}, K={p['K']!r}")
    return Shaper(GuideBar(a, AC), l_CD, l_DE, AC - l_CD * (1 + math.cos(theta / 2)) / 2)


_STATEMENT_2_32 = (
    "The main drive of a shaper has the crank AB = {l_AB} mm and the link DE = {l_DE} mm; the "
    "time ratio is K = {K} and the stroke of the ram is H = {H} mm. The ram should have a small "
    "pressure angle over the whole stroke. Design the mechanism."
)


def _solve_2_32(p):
    s = shaper_2_32(p)
    K, stroke, worst = s.measure()
    gb_check = simulate_quick_return(s.guide_bar)
    assumptions = (
        "Crank AB about A drives the guide bar CD, pivoted at C on the frame line through A, "
        "through a block at B; the guide's end D drives the ram E through the link DE; the "
        "ram moves perpendicular to the frame line AC.",
        "'Small pressure angle' is read as the smallest possible largest pressure angle: the "
        "ram's path halves the sagitta of the arc of D.",
    )
    conventions = (
        "theta = 180° (K - 1)/(K + 1); the guide's limit positions are tangent to the crank "
        "circle, so its swing is theta and AC = AB / sin(theta/2) (example 2-20).",
    )
    part1 = Part("Dimensions", (
        Result("l_AC", s.guide_bar.d, "mm", "AB / sin(theta/2)"),
        Result("l_CD", s.l_CD, "mm", "H / (2 sin(theta/2)): the chord of D's arc is the stroke"),
        Result("distance of the ram's path from C", s.guide_bar.d - s.x_ram, "mm",
               "l_CD (1 + cos(theta/2)) / 2"),
    ))
    part2 = Part("Check by simulating one crank turn", (
        Result("K simulated (ram)", K, "", "ram stops from `GuideBar` and the dyad DE"),
        Result("stroke simulated", stroke, "mm"),
        Result("largest pressure angle of the ram", worst, "rad", "angle of DE to the ram's path"),
        Result("swing of the guide simulated", gb_check.output_range, "rad", "`GuideBar`"),
    ))
    return Solution("2-32", EXERCISE_2_32.title, dict(p), conventions, (part1, part2), assumptions=assumptions)


def _sample_2_32(rng):
    return {"l_AB": float(rng.integers(50, 100)), "l_DE": float(rng.integers(80, 150)),
            "K": float(rng.choice([1.4, 1.6, 1.8, 2.0, 2.2])), "H": float(rng.integers(200, 400))}


EXERCISE_2_32 = Exercise(
    number="2-32",
    title="A shaper drive: oscillating guide-bar and ram from K and the stroke",
    tag="A",
    statement=_STATEMENT_2_32,
    parameters=(
        Parameter("l_AB", 75.0, "mm", "crank"),
        Parameter("l_DE", 100.0, "mm", "link from the guide to the ram"),
        Parameter("K", 2.0, "", "time ratio"),
        Parameter("H", 300.0, "mm", "stroke of the ram"),
    ),
    solver=_solve_2_32,
    sampler=_sample_2_32,
)
