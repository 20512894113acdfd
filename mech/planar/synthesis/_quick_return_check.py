"""Checking a quick-return design: turn its crank once and measure what the formulas promised.

`simulate_quick_return` turns the crank of a `FourBar`, `SliderCrank` or `GuideBar` once
and MEASURES its time ratio, swing or stroke and smallest transmission angle, independently
of the formulas of eqs. (2-46) to (2-52) that built it. The designs of
``_quick_return_design`` call it from their ``check()``; the searches and tables of
``_quick_return_search`` build on both.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from mech._geometry import acute_angle_from_cosine as _acute
from mech._scaling import length_scale
from mech._validate import InputTypeError, nonnegative_int, positive_length
from mech.planar.kinematics._fourbar import FourBar
from mech.planar.kinematics._guide_bar import GuideBar
from mech.planar.kinematics._slider_crank import SliderCrank

__all__ = ["QuickReturnCheck", "simulate_quick_return"]


def _optimize():
    """SciPy's optimize module, imported on first use so that importing mech stays light."""
    from scipy import optimize

    return optimize

_TWO_PI = 2.0 * math.pi


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
