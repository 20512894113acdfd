"""Searching quick-return designs, and the textbook's tables 2-3, 2-4 and 2-5.

Every design is measured by `simulate_quick_return` (``_quick_return_design``). The
families search the free angle alpha of the crank-rocker and the slider-crank (Ex. 2-17,
2-18) for the largest smallest transmission angle, or for every design that keeps it above
a permitted value; the tables are regenerated from those searches.

The printed tables (Tables 2-3 to 2-5, §2.4, part III) are kept here as data so that the book
page and the tests compare the same numbers; `table_errata` lists the printed entries
that differ from the regenerated ones by more than their rounding allows. The designs
themselves are built in ``_quick_return_design`` (page ``deriv-quick-return-design``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from mech._validate import branch_sign, finite_array, integer, nonnegative_int, positive_length, real_number
from mech.planar.structure._quick_return import extreme_angle
from mech.planar.synthesis._quick_return_design import (
    _angle_in,
    _build_crank_rocker,
    _build_slider,
    _crank_rocker_unit,
    _optimize,
    _slider_theta,
    _slider_unit,
    _theta,
    quick_return_crank_rocker,
    quick_return_slider_crank,
)

# The searches are the package's public names. The tables (``TABLE_K``, the ``PRINTED_TABLE_*``
# data and the functions that regenerate and compare them) serve the book page and the tests,
# which import them from this module: listing them here would re-export them as
# `mech.planar.synthesis` names.
__all__ = ["QuickReturnFamily", "crank_rocker_family", "slider_crank_family"]


# ----------------------------------------------------------------------------- searches over alpha
@dataclass(frozen=True)
class QuickReturnFamily:
    """Every design of one kind for a task, over the free parameter alpha.

    Attributes
    ----------
    intervals : tuple of (float, float)
        Open intervals of alpha (rad) whose designs have ``gamma_min >= min_transmission``
        (empty if there is none).
    best : QuickReturnCrankRocker or QuickReturnSliderCrank
        The design with the largest gamma_min over (0, pi - theta).
    min_transmission : float
        The permitted transmission angle [gamma] the intervals keep.
    design : callable
        ``design(alpha)`` builds the design at any alpha.
    """

    intervals: tuple
    best: object
    min_transmission: float
    design: Callable

    def designs(self, n=5):
        """``n`` designs spread over each interval (its ends excluded)."""
        n = nonnegative_int("n", n, 10**6)
        return [self.design(lo + (hi - lo) * (k + 1) / (n + 1)) for lo, hi in self.intervals for k in range(n)]


def _search(gamma_of, top, min_transmission, samples, xtol):
    """alpha maximising gamma_of on (0, top) and the intervals where gamma_of >= min_transmission."""
    alpha = np.linspace(0.0, top, samples + 2)[1:-1]
    g = gamma_of(alpha)
    k = int(np.argmax(g))
    step = alpha[1] - alpha[0]
    res = _optimize().minimize_scalar(lambda u: -float(gamma_of(np.array([u]))[0]),
                          bounds=(max(alpha[k] - step, 0.5 * alpha[0]), min(alpha[k] + step, top - 0.5 * alpha[0])),
                          method="bounded", options={"xatol": xtol})
    best = float(res.x) if -res.fun >= g[k] else float(alpha[k])
    f = lambda u: float(gamma_of(np.array([u]))[0]) - min_transmission  # noqa: E731
    above = g >= min_transmission
    ends = [0.0] if above[0] else []
    for i in np.flatnonzero(above[1:] != above[:-1]):
        ends.append(_optimize().brentq(f, alpha[i], alpha[i + 1], xtol=xtol))
    if above[-1]:
        ends.append(top)
    return best, tuple((float(lo), float(hi)) for lo, hi in zip(ends[0::2], ends[1::2]))


def crank_rocker_family(time_ratio, rocker, swing, *, min_transmission=0.0, side=1, samples=2001, xtol=1e-12):
    """Every quick-return crank-rocker for K, c and phi, and the best by gamma_min (Table 2-3).

    Parameters
    ----------
    time_ratio, rocker, swing, side
        As for `quick_return_crank_rocker`.
    min_transmission : float, optional
        The permitted transmission angle [gamma] in [0, pi/2) (rad).
    samples : int, optional
        Values of alpha (at least 2) sampled on (0, pi - theta) before the crossings of [gamma] are
        refined by Brent's method and the best alpha by a bounded scalar search.
    xtol : float, optional
        Absolute tolerance (rad) on alpha of those refinements.

    Returns
    -------
    QuickReturnFamily

    Notes
    -----
    gamma_min(alpha) comes from (2-48) and its companion at the extended position
    (§2.4 III); alpha where the linkage is not a crank-rocker doing the task (see
    `quick_return_crank_rocker`) count as below [gamma]. The
    sampling must resolve each interval: an interval narrower than (pi - theta)/samples
    can be missed.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import crank_rocker_family
    >>> f = crank_rocker_family(1.25, 500.0, np.radians(40.0), min_transmission=np.radians(40.0))
    >>> [tuple(round(float(np.degrees(x)), 4) for x in iv) for iv in f.intervals]   # §2.4 III, after (2-48)
    [(14.4487, 45.2267)]
    """
    K, theta = _theta(time_ratio)
    c = positive_length("rocker", rocker)
    swing = _angle_in("swing", swing, 0.0, math.pi)
    side = branch_sign(side, "side")
    gmin = real_number("min_transmission", min_transmission)
    if not 0.0 <= gmin < math.pi / 2:
        raise ValueError(f"Expected `min_transmission` in [0, pi/2), got {gmin!r}")
    samples = integer("samples", samples, minimum=2, maximum=10**7)
    xtol = positive_length("xtol", xtol)

    def gamma_of(al):
        with np.errstate(invalid="ignore"):
            return _crank_rocker_unit(theta, swing, al, side)[5]

    best, intervals = _search(gamma_of, math.pi - theta, gmin, samples, xtol)
    if gamma_of(np.array([best]))[0] < 0.0:
        raise ValueError(f"Expected `time_ratio`, `swing` and `side` that admit a crank-rocker, got "
                         f"time_ratio={time_ratio!r}, swing={swing!r}, side={side!r}")
    return QuickReturnFamily(intervals, _build_crank_rocker(K, theta, c, swing, best, side), gmin,
                             lambda al: quick_return_crank_rocker(K, c, swing, alpha=al, side=side))


def slider_crank_family(time_ratio, stroke, *, min_transmission=0.0, samples=2001, xtol=1e-12):
    """Every quick-return offset slider-crank for K and H, and the best by gamma_min (Table 2-5).

    Keywords as for `crank_rocker_family`; gamma_min(alpha) from (2-52).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import slider_crank_family
    >>> f = slider_crank_family(1.25, 100.0)
    >>> round(float(np.degrees(f.best.alpha)), 3), round(float(np.degrees(f.best.min_transmission_angle)), 4)
    (27.035, 42.8078)
    """
    K, theta = _slider_theta(time_ratio)
    H = positive_length("stroke", stroke)
    gmin = real_number("min_transmission", min_transmission)
    if not 0.0 <= gmin < math.pi / 2:
        raise ValueError(f"Expected `min_transmission` in [0, pi/2), got {gmin!r}")
    samples = integer("samples", samples, minimum=2, maximum=10**7)
    xtol = positive_length("xtol", xtol)

    def gamma_of(al):
        return _slider_unit(theta, al)[4]

    best, intervals = _search(gamma_of, math.pi - 2.0 * theta, gmin, samples, xtol)
    return QuickReturnFamily(intervals, _build_slider(K, theta, H, best), gmin,
                             lambda al: quick_return_slider_crank(K, H, alpha=al))


#: The time ratios of the three tables.
TABLE_K = (1.05, 1.10, 1.15, 1.20, 1.25, 1.30, 1.35, 1.40, 1.45)
#: The rocker swings (degrees) of table 2-3.
TABLE_2_3_SWINGS_DEG = (10, 20, 30, 40, 50, 60, 70, 80)

_NAN = float("nan")
#: Table 2-3 as printed (§2.4 III): {swing in degrees: {row: 9 values}}; gamma in degrees.
#: The a/c row of 10° prints only seven numbers (the last two are lost): NaN here.
PRINTED_TABLE_2_3 = {
    10: {"a/c": (0.086, 0.084, 0.083, 0.082, 0.081, 0.080, 0.079, _NAN, _NAN),
         "b/c": (0.438, 0.319, 0.263, 0.230, 0.206, 0.190, 0.177, 0.166, 0.157),
         "d/c": (1.011, 0.966, 0.952, 0.947, 0.945, 0.945, 0.945, 0.947, 0.948),
         "gamma": (67.51, 59.41, 53.36, 48.43, 44.24, 40.59, 37.36, 34.45, 31.82)},
    20: {"a/c": (0.171, 0.168, 0.165, 0.163, 0.160, 0.158, 0.157, 0.155, 0.154),
         "b/c": (0.812, 0.616, 0.517, 0.459, 0.417, 0.385, 0.359, 0.338, 0.321),
         "d/c": (1.164, 1.025, 0.969, 0.939, 0.923, 0.914, 0.909, 0.907, 0.906),
         "gamma": (65.5, 58.43, 53.04, 48.59, 44.76, 41.39, 38.37, 35.65, 33.17)},
    30: {"a/c": (0.255, 0.251, 0.247, 0.243, 0.240, 0.236, 0.233, 0.231, 0.228),
         "b/c": (1.115, 0.866, 0.748, 0.669, 0.613, 0.571, 0.537, 0.509, 0.485),
         "d/c": (1.356, 1.139, 1.040, 0.982, 0.945, 0.920, 0.903, 0.891, 0.884),
         "gamma": (62.41, 56.26, 51.55, 47.63, 44.24, 41.24, 38.53, 36.07, 33.81)},
    40: {"a/c": (0.338, 0.333, 0.328, 0.323, 0.318, 0.314, 0.310, 0.306, 0.302),
         "b/c": (1.366, 1.077, 0.936, 0.848, 0.786, 0.738, 0.699, 0.666, 0.639),
         "d/c": (1.542, 1.268, 1.136, 1.055, 1.000, 0.960, 0.929, 0.907, 0.889),
         "gamma": (58.76, 53.33, 49.19, 45.77, 42.81, 40.18, 37.81, 35.65, 33.65)},
    50: {"a/c": (0.419, 0.413, 0.408, 0.402, 0.396, 0.391, 0.386, 0.381, 0.376),
         "b/c": (1.579, 1.254, 1.099, 1.001, 0.933, 0.881, 0.838, 0.804, 0.775),
         "d/c": (1.712, 1.392, 1.237, 1.140, 1.071, 1.091, 0.979, 0.947, 0.921),
         "gamma": (54.8, 49.93, 46.27, 43.26, 40.67, 38.39, 36.33, 34.45, 32.72)},
    60: {"a/c": (0.496, 0.490, 0.484, 0.478, 0.472, 0.466, 0.461, 0.455, 0.450),
         "b/c": (1.755, 1.401, 1.234, 1.130, 1.057, 1.001, 0.958, 0.921, 0.891),
         "d/c": (1.858, 1.503, 1.331, 1.222, 1.145, 1.086, 1.039, 1.000, 0.968),
         "gamma": (50.64, 46.25, 42.98, 40.32, 38.04, 36.04, 34.26, 32.63, 31.14)},
    70: {"a/c": (0.569, 0.564, 0.558, 0.552, 0.545, 0.539, 0.533, 0.527, 0.522),
         "b/c": (1.901, 1.524, 1.347, 1.237, 1.160, 1.102, 1.056, 1.020, 0.988),
         "d/c": (1.980, 1.599, 1.415, 1.297, 1.214, 1.150, 1.098, 1.056, 1.021),
         "gamma": (46.36, 42.38, 39.45, 37.07, 35.07, 33.32, 31.76, 30.35, 29.07)},
    80: {"a/c": (0.639, 0.633, 0.627, 0.621, 0.615, 0.609, 0.603, 0.547, 0.591),
         "b/c": (2.015, 1.622, 1.437, 1.323, 1.244, 1.185, 1.138, 1.100, 1.068),
         "d/c": (2.076, 1.676, 1.483, 1.361, 1.274, 1.207, 1.154, 1.109, 1.072),
         "gamma": (42.0, 38.38, 35.74, 33.63, 31.85, 30.32, 28.96, 27.74, 26.64)},
}
#: Table 2-4 as printed (§2.4 III): phi = theta and (gamma_min)_max, degrees.
PRINTED_TABLE_2_4 = {
    "theta": (4.37, 8.57, 12.56, 16.36, 20.0, 23.48, 26.81, 30.0, 33.06),
    "gamma": (67.85, 59.42, 53.4, 48.66, 44.76, 41.44, 38.58, 36.07, 33.85),
}
#: Table 2-5 as printed (§2.4 III); gamma in degrees.
PRINTED_TABLE_2_5 = {
    "a/H": (0.491, 0.483, 0.476, 0.470, 0.466, 0.461, 0.458, 0.455, 0.453),
    "b/H": (2.527, 1.796, 1.471, 1.279, 1.149, 1.054, 0.980, 0.921, 0.873),
    "e/H": (0.470, 0.446, 0.421, 0.398, 0.378, 0.358, 0.338, 0.321, 0.304),
    "gamma": (67.64, 58.85, 52.4, 47.2, 42.81, 39.0, 35.64, 32.63, 29.92),
}


def crank_rocker_table(time_ratios=TABLE_K, swings_deg=TABLE_2_3_SWINGS_DEG):
    """Table 2-3 regenerated: the crank-rockers with the largest gamma_min, c = 1.

    Returns
    -------
    dict
        ``{swing_deg: {"a/c": array, "b/c": ..., "d/c": ..., "gamma": degrees, "alpha":
        degrees}}`` over `time_ratios`, each design found by `crank_rocker_family`.

    Examples
    --------
    >>> from mech.planar.synthesis._quick_return_search import crank_rocker_table
    >>> row = crank_rocker_table((1.3,), (30,))[30]
    >>> [round(float(row[k][0]), 3) for k in ("a/c", "b/c", "d/c")], round(float(row["gamma"][0]), 2)
    ([0.236, 0.571, 0.92], 41.24)
    """
    K = finite_array("time_ratios", time_ratios).ravel()
    swings = finite_array("swings_deg", swings_deg).ravel()
    out = {}
    for s in swings:
        best = [crank_rocker_family(k, 1.0, math.radians(s)).best for k in K]
        key = int(s) if float(s).is_integer() else float(s)
        out[key] = {
            "a/c": np.array([q.lengths[0] for q in best]),
            "b/c": np.array([q.lengths[1] for q in best]),
            "d/c": np.array([q.lengths[3] for q in best]),
            "gamma": np.degrees([q.min_transmission_angle for q in best]),
            "alpha": np.degrees([q.alpha for q in best]),
        }
    return out


def crank_rocker_best_table(time_ratios=TABLE_K):
    """Table 2-4 regenerated: for each K, swing phi = theta and the best gamma_min (degrees).

    Examples
    --------
    >>> from mech.planar.synthesis._quick_return_search import crank_rocker_best_table
    >>> t = crank_rocker_best_table((1.05,))
    >>> round(float(t["theta"][0]), 4), round(float(t["gamma"][0]), 4)
    (4.3902, 67.8531)
    """
    K = finite_array("time_ratios", time_ratios).ravel()
    theta = np.array([float(extreme_angle(k)) for k in K])
    gamma = [crank_rocker_family(k, 1.0, t).best.min_transmission_angle for k, t in zip(K, theta)]
    return {"theta": np.degrees(theta), "gamma": np.degrees(gamma)}


def slider_crank_table(time_ratios=TABLE_K):
    """Table 2-5 regenerated: the offset slider-cranks with the largest gamma_min, H = 1.

    Examples
    --------
    >>> from mech.planar.synthesis._quick_return_search import slider_crank_table
    >>> t = slider_crank_table((1.15,))
    >>> [round(float(t[k][0]), 3) for k in ("a/H", "b/H", "e/H")], round(float(t["gamma"][0]), 2)
    ([0.476, 1.471, 0.421], 52.4)
    """
    K = finite_array("time_ratios", time_ratios).ravel()
    best = [slider_crank_family(k, 1.0).best for k in K]
    return {
        "a/H": np.array([q.lengths[0] for q in best]),
        "b/H": np.array([q.lengths[1] for q in best]),
        "e/H": np.array([q.lengths[2] for q in best]),
        "gamma": np.degrees([q.min_transmission_angle for q in best]),
        "alpha": np.degrees([q.alpha for q in best]),
    }


def table_errata(printed, computed, *, ratio_tol=0.005, angle_tol=0.01):
    """Printed entries that differ from the regenerated ones beyond their rounding.

    Parameters
    ----------
    printed, computed : dict
        One table (or one swing's block of table 2-3): row name to values.
    ratio_tol : float, optional
        Largest accepted difference of a length ratio. The printed ratios have three
        decimals, and the optimum over alpha is flat, so the textbook's own solver moved
        some ratios by up to 0.003 without changing gamma; larger differences are errors.
    angle_tol : float, optional
        Largest accepted difference of an angle in degrees (printed with two decimals).

    Returns
    -------
    list of (row, index, printed, computed)
        The wrong entries; a NaN printed entry (lost in the text) is listed too.

    Examples
    --------
    >>> from mech.planar.synthesis._quick_return_search import (PRINTED_TABLE_2_4,
    ...     crank_rocker_best_table, table_errata)
    >>> [(r, i, p, round(float(c), 2)) for r, i, p, c in table_errata(PRINTED_TABLE_2_4, crank_rocker_best_table())]
    [('theta', 0, 4.37, 4.39)]
    """
    ratio_tol = positive_length("ratio_tol", ratio_tol)
    angle_tol = positive_length("angle_tol", angle_tol)
    wrong = []
    for row, values in printed.items():
        tol = angle_tol if row in ("gamma", "theta") else ratio_tol
        for i, (p, c) in enumerate(zip(values, computed[row])):
            if not abs(p - c) <= tol:
                wrong.append((row, i, p, float(c)))
    return wrong
