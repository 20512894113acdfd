"""Quick-return design (textbook section 4, III: §2.4 III, eqs. 2-46 to 2-52, Ex. 2-17 to 2-20).

The time ratio K fixes the extreme angle theta = pi (K - 1)/(K + 1). A crank-rocker with
rocker c and swing phi, or an offset slider-crank with stroke H, then has one free
parameter, the angle alpha = angle AOC1 on the circle that sees the output's two limit
positions C1, C2 under theta (page ``deriv-quick-return-design``). This module builds
the design for a given alpha (or for a given crank, coupler or offset, which fix alpha),
and designs the oscillating guide-bar from K and its frame. The searches over alpha (the
largest minimum transmission angle, or every design that keeps it above a permitted
value) are in ``_quick_return_search``.

Every design is returned as the analysis class that moves it (`FourBar`, `SliderCrank`,
`GuideBar`); its ``check()`` simulates one full crank turn with that class and MEASURES
the time ratio, the swing or stroke and the minimum transmission angle, independently of
the formulas that built it (`simulate_quick_return`, below).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from mech._generated.quick_return_design import (
    qr_alpha_from_lengths,
    qr_alpha_from_offset,
    qr_crank_rocker,
    qr_crank_rocker_cos_gamma,
    qr_crank_rocker_k1,
    qr_slider_crank,
)
from mech._geometry import acute_angle_from_cosine as _acute
from mech._scaling import length_scale
from mech._validate import InputTypeError, branch_sign, nonnegative_int, positive_length, real_number
from mech.planar.kinematics._fourbar import FourBar
from mech.planar.kinematics._guide_bar import GuideBar
from mech.planar.structure._quick_return import extreme_angle as _extreme_angle
from mech.planar.kinematics._slider_crank import SliderCrank

__all__ = [
    "QuickReturnCrankRocker",
    "QuickReturnSliderCrank",
    "QuickReturnGuideBar",
    "quick_return_crank_rocker",
    "quick_return_slider_crank",
    "quick_return_guide_bar",
    "QuickReturnCheck",
    "simulate_quick_return",
]


def _optimize():
    """SciPy's optimize module, imported on first use so that importing mech stays light."""
    from scipy import optimize

    return optimize

_TWO_PI = 2.0 * math.pi


# ----------------------------------------------------------------------------- input checks
def _theta(time_ratio):
    K = real_number("time_ratio", time_ratio)
    if not K > 1.0:
        raise ValueError(f"Expected `time_ratio` > 1 for a quick return, got {K!r}")
    theta = float(_extreme_angle(K))
    if not theta < math.pi:     # K beyond about 1e16 rounds the extreme angle to pi
        raise ValueError(f"Expected `time_ratio` whose extreme angle pi (K - 1)/(K + 1) is below pi, got {K!r}")
    return K, theta


def _slider_theta(time_ratio):
    K, theta = _theta(time_ratio)
    if not theta < math.pi / 2:
        raise ValueError(f"Expected `time_ratio` < 3 for an offset slider-crank (extreme angle < pi/2), got {K!r}")
    return K, theta


def _angle_in(name, value, low, high):
    x = real_number(name, value)
    if not low < x < high:
        raise ValueError(f"Expected `{name}` in ({low!r}, {high!r}), got {x!r}")
    return x


def _one_of(**given):
    named = [k for k, v in given.items() if v is not None]
    if len(named) != 1:
        raise ValueError(f"Expected exactly one of {', '.join(f'`{k}`' for k in given)}, got {len(named)}: {named}")
    return named[0], given[named[0]]


# ----------------------------------------------------------------------------- simulation
@dataclass(frozen=True)
class QuickReturnCheck:
    """What one simulated crank turn of a quick-return design measured.

    Attributes
    ----------
    time_ratio : float
        K = (crank angle of the slow stroke) / (crank angle of the fast stroke), measured.
    extreme_angle : float
        The crank angle between the two limit positions minus pi, in absolute value (rad).
    output_range : float
        The swing of the rocker or guide (rad), or the stroke of the slider (length).
    min_transmission_angle : float
        The smallest transmission angle over the turn (rad), from the simulated positions.
    theta_limits : tuple of float
        The crank angles in [0, 2 pi) where the output stops (first: its smallest value).
    output_limits : tuple of float
        The output's smallest and largest values (rocker or guide angle, slider x).
    samples : int
        The number of crank angles sampled before the limit positions and the minimum
        were refined.
    """

    time_ratio: float
    extreme_angle: float
    output_range: float
    min_transmission_angle: float
    theta_limits: tuple
    output_limits: tuple
    samples: int


def _stops(rate, t, xtol):
    """Crank angles in [0, 2 pi) where `rate` changes sign along the sampled turn `t`."""
    r = rate(t)
    nxt = np.roll(r, -1)
    idx = np.flatnonzero(np.sign(r) != np.sign(nxt))
    roots = []
    for i in idx:
        lo, hi = t[i], t[i] + (t[1] - t[0])
        try:
            roots.append(_optimize().brentq(lambda u: float(rate(np.array([u]))[0]), lo, hi, xtol=xtol) % _TWO_PI)
        except ValueError:
            # the rate at 2 pi is not the rate at 0: a change-point linkage, which the analysis
            # continues through its change point instead of repeating its motion every turn
            raise ValueError(f"Expected `linkage` whose output repeats every crank turn, got one whose output "
                             f"rate jumps between crank angles {lo!r} and {hi!r} (a change-point linkage, "
                             "s + l = p + q?)") from None
    return roots


def _simulate(position, rate, gamma, samples, xtol, angular=True):
    """Measure K, the extreme angle, the output range and gamma_min over one crank turn.

    ``position(t)``, ``rate(t)`` and ``gamma(t)`` are the output coordinate, its rate and
    the transmission angle, all from the analysis class, at crank angles ``t``.
    """
    samples = nonnegative_int("samples", samples, 10**7)
    if samples < 16:
        raise ValueError(f"Expected `samples` >= 16, got {samples!r}")
    xtol = positive_length("xtol", xtol)
    t = np.linspace(0.0, _TWO_PI, samples, endpoint=False)
    stops = _stops(rate, t, xtol)
    if len(stops) != 2:
        raise ValueError(f"Expected an output with two limit positions per turn, got {len(stops)}")
    out = position(np.array(stops))
    span = out[1] - out[0]
    if angular:
        # a rocker or guide angle may cross the cut at +-pi between its stops
        span = float(np.angle(np.exp(1j * span)))
    low, high = (0, 1) if span > 0 else (1, 0)
    forward = (stops[high] - stops[low]) % _TWO_PI       # crank turn from the low to the high stop
    strokes = sorted((forward, _TWO_PI - forward))
    g = gamma(t)
    k = int(np.argmin(g))
    step = t[1] - t[0]
    refined = _optimize().minimize_scalar(lambda u: float(gamma(np.array([u]))[0]), bounds=(t[k] - step, t[k] + step),
                              method="bounded", options={"xatol": xtol})
    return QuickReturnCheck(
        time_ratio=strokes[1] / strokes[0],
        extreme_angle=abs(forward - math.pi),
        output_range=abs(float(span)),
        min_transmission_angle=float(min(refined.fun, g[k])),
        theta_limits=(float(stops[low]), float(stops[high])),
        output_limits=(float(out[low]), float(out[high])),
        samples=samples,
    )


def simulate_quick_return(linkage, *, samples=2048, xtol=1e-13):
    """Simulate one crank turn of a `FourBar`, `SliderCrank` or `GuideBar`; measure its quick return.

    The output (rocker angle psi, slider position x, guide angle psi) stops where its rate
    from ``linkage.solve(t, order=1)`` changes sign: those crank angles are found by
    Brent's method from `samples` equally spaced crank angles, and K, the extreme angle
    and the swing or stroke follow from them. The transmission angle is computed from the
    simulated pin positions (angle BCD of a four-bar; rod against the guide's normal of a
    slider-crank; pi/2 for the guide-bar, whose block pushes the guide along its normal)
    and its smallest value refined by a bounded scalar minimisation.

    Parameters
    ----------
    linkage : FourBar, SliderCrank or GuideBar
        A linkage whose input crank turns fully.
    samples : int, optional
        Crank angles sampled over the turn (>= 16).
    xtol : float, optional
        Absolute tolerance (rad) of the refinements.

    Returns
    -------
    QuickReturnCheck

    Raises
    ------
    ValueError
        If the output does not stop exactly twice per turn.

    Examples
    --------
    >>> from mech.planar import FourBar
    >>> from mech.planar.synthesis import simulate_quick_return
    >>> round(simulate_quick_return(FourBar(10, 40, 30, 35)).time_ratio, 5)     # example 2-1
    1.22404
    """
    # FourBar on this branch loses its angles for lengths near 1e-300 (NaN with valid True):
    # simulate a copy scaled by a power of two, which changes no angle and no rounding
    if isinstance(linkage, FourBar):
        scale = length_scale(linkage.a, linkage.b, linkage.c, linkage.d)
        linkage = FourBar(linkage.a / scale, linkage.b / scale, linkage.c / scale, linkage.d / scale,
                          branch=linkage.branch)
        d = linkage.d

        def gamma(t):
            p = linkage.solve(t)
            # angle BCD from the simulated pins, not from the cosine law (2-48)
            cos_bcd = np.real((p.B - p.C) * np.conj(d - p.C)) / (np.abs(p.B - p.C) * np.abs(d - p.C))
            return _acute(cos_bcd)

        return _simulate(lambda t: linkage.solve(t).psi, lambda t: linkage.solve(t, order=1).omega_output,
                         gamma, samples, xtol)
    if isinstance(linkage, SliderCrank):
        scale = length_scale(linkage.a, linkage.b, linkage.e)
        linkage = SliderCrank(linkage.a / scale, linkage.b / scale, linkage.e / scale, branch=linkage.branch)
        b = linkage.b

        def gamma(t):
            p = linkage.solve(t)
            # acute angle between the rod and the normal of the guide, from the pins
            return _acute(np.imag(p.C - p.B) / b)

        check = _simulate(lambda t: linkage.solve(t).x, lambda t: linkage.solve(t, order=1).v, gamma,
                          samples, xtol, angular=False)
        return replace(check, output_range=check.output_range * scale,
                       output_limits=tuple(x * scale for x in check.output_limits))
    if isinstance(linkage, GuideBar):
        return _simulate(lambda t: linkage.solve(t).psi, lambda t: linkage.solve(t, order=1).omega_guide,
                         lambda t: np.full(np.shape(t), np.pi / 2), samples, xtol)
    raise InputTypeError(f"Expected `linkage` to be a FourBar, SliderCrank or GuideBar, got {linkage!r}")


# ----------------------------------------------------------------------------- crank-rocker
@dataclass(frozen=True)
class QuickReturnCrankRocker:
    """A crank-rocker designed for a time ratio, a rocker and its swing, (2-46).

    Attributes
    ----------
    fourbar : FourBar
        The linkage in the standard frame (A = 0, D = d on +x) on the branch that passes
        through the designed limit positions.
    lengths : tuple of float
        ``(a, b, c, d)``: crank AB, coupler BC, rocker CD, frame AD.
    time_ratio, extreme_angle, swing : float
        The task: K, theta = pi (K - 1)/(K + 1) and the rocker swing phi (rad).
    alpha : float
        The free parameter, angle AOC1 in (0, pi - theta) (rad); 0 when K = 1.
    side : int
        +1: D on the side of A of the chord C1C2 (the textbook's Fig. 2-101); -1: the
        other side.
    min_transmission_angle : float
        gamma_min from (2-48) and its companion at the extended position (rad).
    theta_extended, theta_folded : float
        Crank angles (standard frame) at the limit positions with AC2 = b + a and
        AC1 = b - a.
    psi_extended, psi_folded : float
        Rocker angles (of D->C) there.
    placement : tuple
        ``(origin, rotation)``: a point z of the standard frame is at
        ``origin + exp(1j*rotation) * z`` in the design frame of page
        ``deriv-quick-return-design`` (circle centre O at 0, chord C1C2 parallel to x; for
        K = 1, the chord's midpoint at 0 and C1C2 along +x).
    """

    fourbar: FourBar
    lengths: tuple
    time_ratio: float
    extreme_angle: float
    swing: float
    alpha: float
    side: int
    min_transmission_angle: float
    theta_extended: float
    theta_folded: float
    psi_extended: float
    psi_folded: float
    placement: tuple

    def check(self, *, samples=2048, xtol=1e-13):
        """Simulate one crank turn with `FourBar` and measure K, the swing and gamma_min.

        Parameters
        ----------
        samples : int, optional
            Crank angles sampled over the turn before the rocker's stops (sign changes of
            its angular velocity) are refined by Brent's method and the smallest
            transmission angle by a bounded scalar minimisation.
        xtol : float, optional
            Absolute tolerance (rad) of those refinements.

        Returns
        -------
        QuickReturnCheck
        """
        return simulate_quick_return(self.fourbar, samples=samples, xtol=xtol)


def _crank_rocker_unit(theta, swing, alpha, side):
    """(2-46) with c = 1 for arrays of alpha: lengths, gamma_min, whether the crank revolves, and
    the points A, D, C1, C2 measured from the midpoint M of C1C2 (bounded as K -> 1)."""
    # a swing below about 1e-308 divides 0 by 0 (sin(swing/2)**2 underflows): NaN, not a crank-rocker
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        R, H, a, b, d, ax, ay = qr_crank_rocker(theta, 1.0, swing, alpha, side)
    # a coupler b = 0 (a swing below the float range) gives NaN: not a crank-rocker
    with np.errstate(invalid="ignore", divide="ignore"):
        k0, kpi = qr_crank_rocker_cos_gamma(a, b, 1.0, d)
    # the crank revolves when it passes both positions along the frame line
    revolves = (np.abs(k0) <= 1.0) & (np.abs(kpi) <= 1.0) & (a > 0.0) & (b > a)
    # and C1, C2 must be positions of one assembly branch (C on one side of B->D at both);
    # (2-46) alone does not ensure it, e.g. for a small swing with a large K
    A = ax + 1j * ay
    D = -1j * side * np.cos(swing / 2)
    C1, C2 = -np.sin(swing / 2) + 0j, np.sin(swing / 2) + 0j
    with np.errstate(invalid="ignore", divide="ignore"):
        B2 = A + a * (C2 - A) / np.abs(C2 - A)
        B1 = A - a * (C1 - A) / np.abs(C1 - A)
    side2 = np.imag(np.conj(D - B2) * (C2 - B2))
    side1 = np.imag(np.conj(D - B1) * (C1 - B1))
    revolves = revolves & (side1 * side2 > 0.0)
    # near alpha_max the design tends to a change-point linkage (s + l = p + q): within the
    # tolerance of `grashof`, FourBar continues it smoothly through the change point, off the
    # crank-rocker's periodic motion, and the design cannot be checked by simulation
    with np.errstate(invalid="ignore"):
        links = np.sort(np.stack(np.broadcast_arrays(a, b, np.ones_like(a), d)), axis=0)
        slack = links[1] + links[2] - links[0] - links[3]
    revolves = revolves & ~(np.abs(slack) <= 1e-12 * np.sum(links, axis=0))
    gamma = np.where(revolves, np.minimum(_acute(k0), _acute(kpi)), -1.0)
    return R, H, a, b, d, gamma, revolves, (A, D, C1, C2)


def _check_scaled(unit, scale, name):
    """Raise naming `name` (the caller's length `scale`) if a link ``unit * scale`` underflows to 0.0."""
    for x in unit:
        if x != 0.0 and x * scale == 0.0:
            raise ValueError(
                f"Expected `{name}` at least 2**-1074 / {float(abs(x))!r} so that every link of the design "
                f"(the shortest {float(abs(x))!r} times `{name}`) is longer than 0.0, got {scale!r}"
            )


def _build_crank_rocker(K, theta, c, swing, alpha, side):
    R, H, a, b, d, gamma, revolves, points = _crank_rocker_unit(theta, swing, alpha, side)
    if not revolves:
        raise ValueError(
            f"Expected `alpha` for which the design is a crank-rocker (the crank passes both positions "
            f"along the frame, both limit positions on one branch, not a change-point linkage), got {alpha!r}"
        )
    A, D, C1, C2 = (complex(v) for v in points)
    design = _placed_crank_rocker(K, theta, c, swing, alpha, side, (float(a), float(b), float(d), float(gamma)),
                                  A, D, C1, C2)
    # placement in the design frame of the derivation: O = 0, the midpoint M at (0, R cos(theta))
    origin, rotation = design.placement
    return replace(design, placement=(origin + 1j * float(R) * math.cos(theta) * c, rotation))


def _build_crank_rocker_k1(c, swing, coupler, side):
    """K = 1 (Fig. 2-100): A on the line C1C2 at `coupler` from its midpoint, the limit of (2-46)."""
    b = positive_length("coupler", coupler) / c
    a, d = (float(v) for v in qr_crank_rocker_k1(1.0, swing, b))
    k0, kpi = qr_crank_rocker_cos_gamma(a, b, 1.0, d)
    if not (b > a and abs(k0) <= 1.0 and abs(kpi) <= 1.0):
        raise ValueError(f"Expected `coupler` > c sin(swing/2) = {a * c!r} for which the crank revolves, "
                         f"got {coupler!r}")
    gamma = min(float(_acute(k0)), float(_acute(kpi)))
    # design frame for K = 1, in units of c: the chord's midpoint at 0, C1C2 along +x
    C1, C2 = complex(-a, 0.0), complex(a, 0.0)
    D = complex(0.0, -side * math.cos(swing / 2))
    return _placed_crank_rocker(1.0, 0.0, c, swing, 0.0, side, (a, b, d, gamma), complex(-b, 0.0), D, C1, C2)


def _placed_crank_rocker(K, theta, c, swing, alpha, side, unit, A, D, C1, C2):
    a, b, d, gamma = unit
    _check_scaled((a, b, d), c, "rocker")
    u = (D - A) / abs(D - A)
    C1s, C2s = (C1 - A) / u, (C2 - A) / u
    B2 = a * C2s / abs(C2s)
    branch = 1 if ((d - B2).conjugate() * (C2s - B2)).imag > 0 else -1
    fb = FourBar(a * c, b * c, c, d * c, branch=branch)
    return QuickReturnCrankRocker(
        fourbar=fb, lengths=(a * c, b * c, c, d * c), time_ratio=K, extreme_angle=theta, swing=swing,
        alpha=alpha, side=side, min_transmission_angle=gamma,
        theta_extended=float(np.angle(C2s)) % _TWO_PI, theta_folded=float(np.angle(-C1s)) % _TWO_PI,
        psi_extended=float(np.angle(C2s - d)), psi_folded=float(np.angle(C1s - d)),
        placement=(complex(A * c), float(np.angle(u))),
    )


def quick_return_crank_rocker(time_ratio, rocker, swing, *, alpha=None, crank=None, coupler=None, side=1):
    """The crank-rocker with time ratio K, rocker `rocker` swinging through `swing`, (2-46).

    Give exactly one of `alpha` (the textbook's free parameter), `crank` (example 2-17) or
    `coupler` (example 2-18). K = 1 (no quick return, Fig. 2-100) takes `coupler` only.

    Parameters
    ----------
    time_ratio : float
        K >= 1.
    rocker : float
        Rocker length c > 0.
    swing : float
        Rocker swing phi in (0, pi), radians.
    alpha : float, optional
        Angle AOC1, radians: in (0, pi - theta) for (2-46), but only the part of that range
        given in the Notes makes a working crank-rocker.
    crank : float, optional
        Crank length a in (0, c sin(phi/2)).
    coupler : float, optional
        Coupler length b in (c sin(phi/2), c sin(phi/2) / sin(theta/2)).
    side : {1, -1}, optional
        +1: frame pivot D on the side of A of the chord C1C2 (Fig. 2-101, the textbook's
        only family); -1: on the other side, a second family with the same crank and
        coupler and another frame.

    Returns
    -------
    QuickReturnCrankRocker

    Raises
    ------
    ValueError
        If an input is out of its range or the design is not a crank-rocker.

    Notes
    -----
    Derived in :ref:`deriv-quick-return-design`. The design is computed with c = 1 and
    scaled, so any finite positive rocker length gives the same angles. Not every alpha
    of (0, pi - theta) gives a crank-rocker that does the task: the crank must pass both
    positions along the frame line, and the extended and folded limit positions must lie
    on one assembly branch (C on the same side of B->D at both); (2-46) does not ensure
    the latter, and such an alpha raises ValueError. The alphas that work form the
    interval (0, alpha_max), alpha_max = min(pi - theta, pi - phi, pi - 2 theta + phi) for
    ``side=1`` and pi - 2 theta - phi for ``side=-1`` (none when that is <= 0): found by
    sampling and tested on random tasks whose interval is wider than 0.02 rad, not derived.
    Near alpha_max the design tends to a change-point linkage; within the tolerance of
    `mech.planar.grashof` (s + l = p + q to 1e-12 of the perimeter) it is rejected too,
    since `FourBar` then continues through the change point instead of rocking back. For K = 2 and phi = 30 deg, ``side=1`` keeps 3/4 of
    (0, pi - theta) and ``side=-1`` 1/4; `crank_rocker_family` finds the interval of any
    task. The returned `FourBar` is on the branch of both limit positions. A crank (or
    coupler) fixes alpha uniquely through ``a = 2R cos((theta + alpha)/2) sin(theta/2)``
    (or the line for b of (2-46)), both monotonic on (0, pi - theta).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import quick_return_crank_rocker
    >>> q = quick_return_crank_rocker(1.3, 100.0, np.radians(40.0), crank=31.4)   # §2.4 III, after (2-47)
    >>> round(float(np.degrees(q.alpha)), 2), [round(x, 2) for x in q.lengths]
    (28.5, [31.4, 73.67, 100.0, 95.98])
    >>> round(q.check().time_ratio, 9)
    1.3
    >>> [round(x, 4) for x in quick_return_crank_rocker(1.0, 100.0, np.radians(40.0), coupler=90.0).lengths]
    [34.202, 90.0, 100.0, 130.1162]
    """
    if real_number("time_ratio", time_ratio) == 1.0:
        c = positive_length("rocker", rocker)
        swing = _angle_in("swing", swing, 0.0, math.pi)
        side = branch_sign(side, "side")
        if alpha is not None or crank is not None or coupler is None:
            raise ValueError("Expected `coupler` alone for `time_ratio` = 1 (the crank is c sin(swing/2) and "
                             f"alpha is 0), got alpha={alpha!r}, crank={crank!r}, coupler={coupler!r}")
        return _build_crank_rocker_k1(c, swing, coupler, side)
    K, theta = _theta(time_ratio)
    c = positive_length("rocker", rocker)
    swing = _angle_in("swing", swing, 0.0, math.pi)
    side = branch_sign(side, "side")
    which, value = _one_of(alpha=alpha, crank=crank, coupler=coupler)
    if which == "alpha":
        al = _angle_in("alpha", value, 0.0, math.pi - theta)
    else:
        x = positive_length(which, value) / c
        # one of the two inverses is out of its domain: its NaN is not used
        with np.errstate(invalid="ignore"):
            al_a, al_b = (float(v) for v in np.nan_to_num(
                np.asarray(qr_alpha_from_lengths(theta, 1.0, swing, min(x, 1e6)), dtype=float), nan=-1.0))
        al = al_a if which == "crank" else al_b
        if not 0.0 < al < math.pi - theta:
            raise ValueError(f"Expected `{which}` that fits the swing and K (0 < alpha < pi - theta), got {value!r}")
    return _build_crank_rocker(K, theta, c, swing, al, side)


# ----------------------------------------------------------------------------- slider-crank
@dataclass(frozen=True)
class QuickReturnSliderCrank:
    """An offset slider-crank designed for a time ratio and a stroke, (2-51).

    Attributes
    ----------
    slider_crank : SliderCrank
        The linkage in its standard frame (A = 0, guide y = e > 0, slider to the right).
    lengths : tuple of float
        ``(a, b, e)``: crank, connecting rod, offset.
    time_ratio, extreme_angle, stroke : float
        The task: K, theta and the stroke H.
    alpha : float
        The free parameter, angle AOC1 in (0, pi - theta).
    min_transmission_angle : float
        gamma_min with cos(gamma_min) = (a + e)/b, (2-52) (rad).
    theta_extended, theta_folded : float
        Crank angles at the far (x = sqrt((a+b)^2 - e^2)) and near limit positions.
    """

    slider_crank: SliderCrank
    lengths: tuple
    time_ratio: float
    extreme_angle: float
    stroke: float
    alpha: float
    min_transmission_angle: float
    theta_extended: float
    theta_folded: float

    def check(self, *, samples=2048, xtol=1e-13):
        """Simulate one crank turn with `SliderCrank`: measure K, the stroke and gamma_min.

        Same keywords as `QuickReturnCrankRocker.check`.
        """
        return simulate_quick_return(self.slider_crank, samples=samples, xtol=xtol)


def _slider_unit(theta, alpha):
    R, a, b, e = qr_slider_crank(theta, 1.0, alpha)
    # C1 must lie beyond the foot of A on the guide, or the folded position is on the other
    # branch: sin(theta + alpha) > sin(theta), that is alpha < pi - 2 theta
    valid = (b > a + np.abs(e)) & (np.sin(theta + alpha) > np.sin(theta))
    gamma = np.where(valid, _acute((a + e) / b), -1.0)
    return R, a, b, e, gamma


def _build_slider(K, theta, H, alpha):
    R, a, b, e, gamma = (float(v) for v in _slider_unit(theta, alpha))
    if gamma < 0.0:
        raise ValueError(
            f"Expected `alpha` < pi - 2 theta = {math.pi - 2 * theta!r} so that both limit positions lie on "
            f"one branch, got {alpha!r}"
        )
    _check_scaled((a, b, e), H, "stroke")
    sc = SliderCrank(a * H, b * H, e * H)
    return QuickReturnSliderCrank(
        slider_crank=sc, lengths=(a * H, b * H, e * H), time_ratio=K, extreme_angle=theta, stroke=H,
        alpha=alpha, min_transmission_angle=gamma,
        theta_extended=math.asin(e / (a + b)) % _TWO_PI, theta_folded=(math.pi + math.asin(e / (b - a))) % _TWO_PI,
    )


def quick_return_slider_crank(time_ratio, stroke, *, alpha=None, offset=None):
    """The offset slider-crank with time ratio K and stroke H, (2-51).

    Give exactly one of `alpha` (angle AOC1 in (0, pi - 2 theta)) or `offset` (example
    2-19: e in (0, H / tan(theta)), one design).

    Returns
    -------
    QuickReturnSliderCrank

    Notes
    -----
    Derived in :ref:`deriv-quick-return-design`. Computed with H = 1 and scaled. The
    textbook lets alpha run over (0, pi - theta), but for alpha >= pi - 2 theta the near
    limit position C1 lies behind the foot of A on the guide and the slider would have to
    change branch between its two limit positions: such an alpha raises ValueError. On
    (0, pi - 2 theta) the crank revolves (b > a + e).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import quick_return_slider_crank
    >>> q = quick_return_slider_crank(1.25, 100.0, alpha=np.radians(25.0))   # §2.4 III, after (2-52)
    >>> [round(x, 3) for x in q.lengths], round(float(np.degrees(q.min_transmission_angle)), 3)
    ([46.907, 110.189, 34.002], 42.755)
    >>> round(q.check().output_range, 9)
    100.0
    """
    K, theta = _slider_theta(time_ratio)
    H = positive_length("stroke", stroke)
    which, value = _one_of(alpha=alpha, offset=offset)
    if which == "alpha":
        al = _angle_in("alpha", value, 0.0, math.pi - 2.0 * theta)
    else:
        e = positive_length("offset", value) / H
        top = 1.0 / math.tan(theta)
        if not e < top:
            raise ValueError(f"Expected `offset` < H / tan(theta) = {top * H!r}, got {value!r}")
        if e < 2.0**-30 * math.tan(theta):
            # arccos(cos(theta) - 2 e sin(theta)) - theta cancels for a small offset: its series
            # 2 e - 2 e**2 cot(theta) + O(e**3), the next term below 2**-60 relative
            al = 2.0 * e - 2.0 * e * e / math.tan(theta)
        else:
            al = float(qr_alpha_from_offset(theta, 1.0, e))
        if float(_slider_unit(theta, al)[-1]) < 0.0:
            raise ValueError(
                f"Expected `offset` large enough relative to `stroke` ({H!r}) that the angle alpha it "
                f"gives ({al!r}) puts both limit positions on one branch in floating point, got {value!r}"
            )
    return _build_slider(K, theta, H, al)


# ----------------------------------------------------------------------------- guide-bar
@dataclass(frozen=True)
class QuickReturnGuideBar:
    """An oscillating guide-bar designed for a time ratio and a frame (Ex. 2-20).

    Attributes
    ----------
    guide_bar : GuideBar
        The linkage: crank a = d sin(theta/2) about A = 0, guide pivot at D = d.
    time_ratio, extreme_angle : float
        K and theta; the guide swings through theta.
    frame, crank : float
        d and a.
    min_guide_length : float
        The guide must reach the crank pin at its farthest, ``d + a`` (§2.4 III).
    """

    guide_bar: GuideBar
    time_ratio: float
    extreme_angle: float
    frame: float
    crank: float
    min_guide_length: float

    def check(self, *, samples=2048, xtol=1e-13):
        """Simulate one crank turn with `GuideBar`: measure K and the swing of the guide.

        Same keywords as `QuickReturnCrankRocker.check`; see `simulate_quick_return`.
        """
        return simulate_quick_return(self.guide_bar, samples=samples, xtol=xtol)


def quick_return_guide_bar(time_ratio, frame):
    """The oscillating guide-bar with time ratio K and frame AD = `frame` (Ex. 2-20).

    The guide's limit positions are tangent to the crank circle, so the crank is
    perpendicular to the guide there, the swing equals the extreme angle theta and
    ``a = d sin(theta / 2)`` (§2.4 III).

    Examples
    --------
    >>> from mech.planar.synthesis import quick_return_guide_bar
    >>> q = quick_return_guide_bar(2.0, 300.0)
    >>> round(q.crank, 9), round(q.check().time_ratio, 9)
    (150.0, 2.0)
    """
    K, theta = _theta(time_ratio)
    d = positive_length("frame", frame)
    try:
        gb = GuideBar.from_swing(d, theta)
    except ValueError:          # the crank d sin(theta / 2) rounds to d for K beyond about 1e8
        raise ValueError(f"Expected `time_ratio` whose crank d sin(theta / 2) is shorter than `frame` = {d!r}, "
                         f"got {K!r}") from None
    return QuickReturnGuideBar(gb, K, theta, d, gb.a, d + gb.a)
