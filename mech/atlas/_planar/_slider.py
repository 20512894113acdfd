"""A normalised design space of the offset slider-crank with a coupler point (issue 13, item 2).

Every sample is a slider-crank in the convention of `mech.planar.SliderCrank`: crank
``a = 1`` about A = 0 (a coupler curve's shape does not depend on the unit of length), rod
``b`` from the crank pin ``B = a exp(i theta)`` to the slider pin C on the guide line
``y = e``, and a coupler point on the rod, ``P = B + (p + i q) exp(i phi)`` with ``phi`` the
direction of B->C (the convention of `mech.planar.FourBar`'s coupler point). The rod is
drawn log-uniformly, the offset uniformly, and ``(p, q) = b (u, v)`` with ``(u, v)``
uniform in a box.

Loop closure (F44, :ref:`deriv-slider-crank`): with ``s = e - a sin(theta)``,
``C - B = branch * sqrt(b^2 - s^2) + i s``. The pose exists while ``|s| <= b``, so the
crank turns fully when ``b >= a + |e|``; otherwise it rocks between dead centres
(``|s| = b``: the rod perpendicular to the guide), where the two branches meet. The
transmission angle ``mu`` is the angle between the rod and the normal to the guide,
``cos(mu) = |s| / b``; over a full turn ``|s|`` is largest, ``a + |e|``, with the crank
perpendicular to the guide and pointing away from it, so
``mu_min = acos((a + |e|) / b)`` (F57).
"""

from dataclasses import dataclass

import numpy as np

from mech._validate import _show, branch_sign, integer, nonnegative_number
from mech.atlas._records import _MAX_SEED, _box, _check_sizes, _Samples
from mech.planar.kinematics._slider_crank import SliderCrank

__all__ = ["SliderCrankSamples", "sample_slider_cranks"]

SLIDER_KINDS = ("crank-slider", "rocker-slider")

#: Default ranges of the slider-crank design space (ratios to the crank a = 1).
RODS = (0.3, 5.0)
OFFSETS = (-2.0, 2.0)
SLIDER_COUPLER = (-1.0, 2.0, -1.5, 1.5)


@dataclass(frozen=True)
class SliderCrankSamples(_Samples):
    """Slider-cranks of the normalised design space, one entry per sample (arrays of shape (n,)).

    Attributes
    ----------
    a, b, e : ndarray
        Crank, rod and offset of the guide line ``y = e`` (``a = 1`` for sampled linkages).
    p, q : ndarray
        Coupler point on the rod, ``P = B + (p + 1j*q) * exp(1j*phi)``.
    branch : ndarray of int
        Assembly branch (+1: the slider pin C to the right of B, as in
        `mech.planar.SliderCrank`) of a full-turn crank; for a rocking crank the branch the
        closed curve starts on, and the choice of input range when there are two.
    kind : ndarray of str
        "crank-slider" when the crank turns fully, "rocker-slider" when it rocks.
    full_turn : ndarray of bool
        True if ``b >= a + |e|``.
    theta_lo, theta_hi : ndarray
        The input range, radians (``0`` and ``2 pi`` for a full turn).
    gamma_min : ndarray
        Smallest transmission angle, ``acos((a + |e|) / b)`` for a full turn, 0 for a
        rocking crank (it stops at dead centres).
    movable : ndarray of bool
        False if the rod cannot reach the guide at any crank angle (``|e| >= a + b``).
    usable : ndarray of bool
        `movable`, and `gamma_min` at least the limit asked of `sample_slider_cranks`.
    """

    a: np.ndarray
    b: np.ndarray
    e: np.ndarray
    p: np.ndarray
    q: np.ndarray
    branch: np.ndarray
    kind: np.ndarray
    full_turn: np.ndarray
    theta_lo: np.ndarray
    theta_hi: np.ndarray
    gamma_min: np.ndarray
    movable: np.ndarray
    usable: np.ndarray

    def slider_crank(self, i):
        """Sample `i` as a `mech.planar.SliderCrank` (the coupler point is ``(p[i], q[i])``)."""
        i = integer("i", i, minimum=-len(self), maximum=len(self) - 1)
        return SliderCrank(self.a[i], self.b[i], self.e[i], branch=int(self.branch[i]))

    def curves(self, samples=256):
        """Closed coupler curves of every sample, shape (n, samples), complex.

        Stepped like `FourBarSamples.curves`: a full turn at ``theta = 2 pi (j + 1/2) /
        samples``, a rocking crank at ``theta = mid + half * sin(u)`` on
        ``branch * sign(cos u)``.

        Examples
        --------
        >>> from mech.atlas import sample_slider_cranks
        >>> sample_slider_cranks(3, seed=1).curves(64).shape
        (3, 64)
        """
        samples = integer("samples", samples, minimum=4, maximum=1 << 16)
        return slider_points(self.columns(), 2 * np.pi * (np.arange(samples) + 0.5) / samples)


def slider_ranges(a, b, e, branch):
    """Input range of each slider-crank: (full_turn, lo, hi, movable), vectorised.

    The pose exists where ``sin(theta)`` lies in ``[(e - b)/a, (e + b)/a]``.
    """
    with np.errstate(invalid="ignore", divide="ignore"):
        low, high = (e - b) / a, (e + b) / a
        full = (low <= -1.0) & (high >= 1.0)
        movable = (low < 1.0) & (high > -1.0)
        sl, sh = np.arcsin(np.clip(low, -1.0, 1.0)), np.arcsin(np.clip(high, -1.0, 1.0))
    only_high = (low <= -1.0) & (high < 1.0)       # sin(theta) <= high: around -pi/2
    only_low = (low > -1.0) & (high >= 1.0)        # sin(theta) >= low: around +pi/2
    # both limits: two mirror intervals [sl, sh] and [pi - sh, pi - sl]; the branch picks one
    lo = np.where(only_high, np.pi - sh, np.where(only_low, sl, np.where(branch > 0, sl, np.pi - sh)))
    hi = np.where(only_high, 2 * np.pi + sh, np.where(only_low, np.pi - sl, np.where(branch > 0, sh, np.pi - sl)))
    lo = np.where(full, 0.0, np.where(movable, lo, np.nan))
    hi = np.where(full, 2 * np.pi, np.where(movable, hi, np.nan))
    return full, lo, hi, movable


def slider_points(cols, u):
    """Coupler points at curve parameters `u` (broadcast against (n, 1)) of the closed curves.

    ``C - B = side * sqrt((b - s)(b + s)) + i s`` with ``s = e - a sin(theta)`` (F44), and
    ``P = B + (p + i q) (C - B) / b``.
    """
    a, b, e, p, q = (np.asarray(cols[k], dtype=float)[:, None] for k in "abepq")
    branch = np.asarray(cols["branch"])[:, None]
    full = np.asarray(cols["full_turn"])[:, None]
    lo, hi = np.asarray(cols["theta_lo"])[:, None], np.asarray(cols["theta_hi"])[:, None]
    theta = np.where(full, u, 0.5 * (lo + hi) + 0.5 * (hi - lo) * np.sin(u))
    side = np.where(full, branch, branch * np.where(np.cos(u) >= 0.0, 1, -1))
    s = e - a * np.sin(theta)
    radicand = (b - s) * (b + s)
    # rounding at a dead centre of a rocking crank (|s| = b there) may leave a tiny negative
    radicand = np.where(radicand < 0.0, np.where(radicand > -1e-12 * b * b, 0.0, np.nan), radicand)
    with np.errstate(invalid="ignore"):
        rod = side * np.sqrt(radicand) + 1j * s
        return a * np.exp(1j * theta) + (p + 1j * q) * rod / b


def describe_sliders(a, b, e, p, q, branch):
    """The `SliderCrankSamples` record of given slider-cranks (arrays of one shape (n,))."""
    a, b, e, p, q = (np.asarray(x, dtype=float) for x in (a, b, e, p, q))
    branch = np.asarray(branch, dtype=np.int8)
    full, lo, hi, movable = slider_ranges(a, b, e, branch)
    with np.errstate(invalid="ignore"):
        gamma = np.where(full, np.arccos(np.clip((a + np.abs(e)) / b, 0.0, 1.0)), 0.0)
    kind = np.asarray(SLIDER_KINDS)[np.where(full, 0, 1)]
    return SliderCrankSamples(a, b, e, p, q, branch, kind, full, lo, hi, gamma, movable, movable)


def sample_slider_cranks(n, *, seed=0, rods=RODS, offsets=OFFSETS, coupler=SLIDER_COUPLER, branch=None,
                         min_transmission=0.0):
    """Draw slider-cranks from the normalised design space, with their type and input range.

    Crank ``a = 1``; rod ``b`` log-uniform in `rods`; offset ``e`` of the guide ``y = e``
    uniform in `offsets`; coupler point ``(p, q) = b * (u, v)`` with ``u, v`` uniform in
    `coupler`; branch +1 or -1 with equal chance (or the one given). The crank turns fully
    when ``b >= a + |e|`` (kind "crank-slider"), with minimum transmission angle
    ``acos((a + |e|) / b)`` (F57); otherwise it rocks ("rocker-slider") over the range where
    ``|e - a sin(theta)| <= b``.

    Parameters
    ----------
    n : int
        Number of samples, in [0, 10**7].
    seed : int, optional
        Seed of ``numpy.random.default_rng``, in [0, 2**63 - 1]; the same seed gives the same samples.
    rods : (float, float), optional
        Range of the rod b as a ratio to the crank, 0 < low < high <= 1e150.
    offsets : (float, float), optional
        Range of the offset e as a ratio to the crank, low < high, each at most 1e150 in size.
    coupler : (float, float, float, float), optional
        ``(u_low, u_high, v_low, v_high)``: the coupler point in units of the rod b.
    branch : {1, -1}, optional
        Draw one branch only.
    min_transmission : float, optional
        Samples whose `gamma_min` is below it (radians, in [0, pi/2]) are flagged not
        `usable`; any value above 0 keeps only cranks that turn fully.

    Returns
    -------
    SliderCrankSamples
        All `n` samples; select the usable ones with ``samples.take(samples.usable)``.

    Examples
    --------
    >>> from mech.atlas import sample_slider_cranks
    >>> s = sample_slider_cranks(1000, seed=3)
    >>> len(s), float(s.a.max())
    (1000, 1.0)
    >>> bool((s.full_turn == (s.b >= 1 + abs(s.e))).all())
    True
    """
    n = integer("n", n, minimum=0, maximum=10**7)
    seed = integer("seed", seed, minimum=0, maximum=_MAX_SEED)
    low, high = _box("rods", rods, 2)
    if not low > 0.0:
        raise ValueError(f"Expected `rods` > 0, got {_show(rods)}")
    e0, e1 = _box("offsets", offsets, 2)
    u0, u1, v0, v1 = _box("coupler", coupler, 4)
    _check_sizes(("rods", rods, high), ("offsets", offsets, max(abs(e0), abs(e1))),
                 ("coupler", coupler, high * max(abs(u0), abs(u1), abs(v0), abs(v1))))
    if branch is not None:
        branch = branch_sign(branch)
    min_transmission = nonnegative_number("min_transmission", min_transmission)
    if min_transmission > np.pi / 2:
        raise ValueError(f"Expected `min_transmission` in [0, pi/2], got {min_transmission!r}")
    rng = np.random.default_rng(seed)
    b = np.exp(rng.uniform(np.log(low), np.log(high), size=n))
    e = rng.uniform(e0, e1, size=n)
    u, v = rng.uniform(u0, u1, size=n), rng.uniform(v0, v1, size=n)
    signs = rng.choice(np.array([-1, 1], dtype=np.int8), size=n)
    if branch is not None:
        signs[:] = branch
    out = describe_sliders(np.ones(n), b, e, b * u, b * v, signs)
    usable = out.movable & (out.gamma_min >= min_transmission)
    return SliderCrankSamples(**{**out.columns(), "usable": usable})


def check_mechanism(mechanism):
    """Check a mechanism name: "four-bar" or "slider-crank"."""
    if not isinstance(mechanism, str) or mechanism not in ("four-bar", "slider-crank"):
        raise ValueError(f"Expected `mechanism` to be 'four-bar' or 'slider-crank', got {_show(mechanism)}")
    return mechanism
