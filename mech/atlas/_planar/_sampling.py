"""A normalised design space of the planar four-bar, sampled in bulk (issue 13, item 2).

Every sample is a `mech.planar.FourBar` with ground ``d = 1`` (a coupler curve's shape does
not depend on the unit of length), crank, coupler and rocker drawn log-uniformly from a
range of ratios to the ground, and a coupler point ``(p, q) = b * (u, v)`` with ``(u, v)``
uniform in a box. For each sample the input range is found in closed form: a full turn when
the crank revolves, otherwise the rocking range between the two dead-centre positions of
the input, where coupler and rocker lie in line. The closed coupler curve of a rocking
input runs over the range on one assembly branch and back on the other.
"""

from dataclasses import dataclass

import numpy as np

from mech._generated.fourbar_position import fourbar_assembly_gaps, fourbar_position
from mech._generated.grashof import grashof_margins
from mech._generated.transmission_angle import fourbar_crank_angle_at_diagonal, fourbar_transmission
from mech._validate import _show, branch_sign, integer, nonnegative_number
from mech.atlas._records import _MAX_RATIO, _MAX_SEED, _box, _check_sizes, _Samples  # noqa: F401
from mech.atlas._planar._slider import slider_points
from mech.planar.kinematics._fourbar import FourBar

__all__ = ["FourBarSamples", "sample_fourbars"]

KINDS = ("crank-rocker", "rocker-crank", "double-crank", "double-rocker", "triple-rocker")

#: Default ranges of the normalised design space (ratios to the ground d = 1, and (u, v)).
LENGTHS = (0.2, 5.0)
COUPLER = (-1.0, 2.0, -1.5, 1.5)
@dataclass(frozen=True)
class FourBarSamples(_Samples):
    """Four-bars of the normalised design space, one entry per sample (arrays of shape (n,)).

    Attributes
    ----------
    a, b, c, d : ndarray
        Crank, coupler, rocker and ground lengths (``d = 1`` for sampled linkages).
    p, q : ndarray
        Coupler point in the `FourBar` convention, ``P = B + (p + 1j*q) * exp(1j*phi)``.
    branch : ndarray of int
        Assembly branch (+1 or -1) of a full-turn input; for a rocking input, the branch the
        closed curve starts on, and the sign of the input range when the linkage has two
        (one per circuit).
    kind : ndarray of str
        Grashof type, as `mech.planar.grashof` names it.
    full_turn : ndarray of bool
        True if the crank turns fully (the input range is the whole turn).
    theta_lo, theta_hi : ndarray
        The input range, radians (``0`` and ``2 pi`` for a full turn).
    gamma_min : ndarray
        Smallest transmission angle over the input range, radians (0 for a rocking input,
        which stops at dead centres where coupler and rocker are in line).
    movable : ndarray of bool
        False if the linkage cannot be assembled at any input angle.
    usable : ndarray of bool
        `movable`, and `gamma_min` at least the limit asked of `sample_fourbars`.
    """

    a: np.ndarray
    b: np.ndarray
    c: np.ndarray
    d: np.ndarray
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

    def fourbar(self, i):
        """Sample `i` as a `mech.planar.FourBar`."""
        i = integer("i", i, minimum=-len(self), maximum=len(self) - 1)
        return FourBar(self.a[i], self.b[i], self.c[i], self.d[i], branch=int(self.branch[i]),
                       coupler=(self.p[i], self.q[i]))

    def curves(self, samples=256):
        """Closed coupler curves of every sample, shape (n, samples), complex.

        A full-turn input is sampled at ``theta = 2 pi (j + 1/2) / samples`` on its branch; a
        rocking input at ``theta = mid + half * sin(u)``, ``u = 2 pi (j + 1/2) / samples``, on
        ``branch * sign(cos u)``: the curve goes over the range on one branch and back on
        the other, smoothly through the dead centres. NaN where a pose does not assemble
        (an unmovable sample).

        Examples
        --------
        >>> from mech.atlas import sample_fourbars
        >>> sample_fourbars(3, seed=1).curves(64).shape
        (3, 64)
        """
        samples = integer("samples", samples, minimum=4, maximum=1 << 16)
        return coupler_curves(self.columns(), samples)




def _input_ranges(a, b, c, d, branch):
    """Input range of each linkage: (full_turn, lo, hi, movable), vectorised."""
    near, far = np.abs(d - a), d + a                       # BD at theta = 0 and pi
    stretched, folded = b + c, np.abs(b - c)
    with np.errstate(invalid="ignore"):
        theta_u = fourbar_crank_angle_at_diagonal(a, d, np.clip(stretched, near, far))
        theta_l = fourbar_crank_angle_at_diagonal(a, d, np.clip(folded, near, far))
    upper = np.where(stretched >= far, np.pi, theta_u)     # |theta| <= upper from BD <= b + c
    lower = np.where(folded <= near, 0.0, theta_l)         # |theta| >= lower from BD >= |b - c|
    movable = (stretched >= near) & (folded <= far) & (lower < upper)
    full = movable & (lower == 0.0) & (upper == np.pi)
    # one interval around 0 ([-upper, upper]), one around pi ([lower, 2 pi - lower]), or two
    # mirror intervals [lower, upper] and [-upper, -lower]: the branch sign picks one
    lo = np.where(lower == 0.0, -upper, np.where(upper == np.pi, lower, np.where(branch > 0, lower, -upper)))
    hi = np.where(lower == 0.0, upper, np.where(upper == np.pi, 2 * np.pi - lower,
                                                 np.where(branch > 0, upper, -lower)))
    lo = np.where(full, 0.0, lo)
    hi = np.where(full, 2 * np.pi, hi)
    return full, lo, hi, movable


def _kinds(a, b, c, d):
    s_ab, s_ac, s_ad = (np.sign(m) for m in grashof_margins(a, b, c, d))
    turns_a = (s_ad >= 0) & (s_ab * s_ac >= 0)
    turns_d = (s_ab <= 0) & (s_ac * s_ad <= 0)
    grashof = s_ab * s_ac * s_ad >= 0
    code = np.where(~grashof, 4, np.where(turns_a & turns_d, 2, np.where(turns_a, 0, np.where(turns_d, 1, 3))))
    return np.asarray(KINDS)[code]


def coupler_curves(cols, samples):
    """Closed coupler curves (n, samples) for columns a, b, c, d, p, q, branch, full_turn, theta_lo/hi."""
    return coupler_points(cols, 2 * np.pi * (np.arange(samples) + 0.5) / samples)


def coupler_points(cols, u):
    """Coupler points at curve parameters `u` (broadcast against (n, 1)) of the closed curves.

    ``u`` runs over [0, 2 pi) once around each closed curve: the input angle for a full
    turn, ``theta = mid + half * sin(u)`` on ``branch * sign(cos u)`` for a rocking input.
    Columns with an offset ``e`` are slider-cranks (`mech.atlas._planar._slider.slider_points`).
    """
    if "e" in cols:
        return slider_points(cols, u)
    a, b, c, d, p, q = (np.asarray(cols[k], dtype=float)[:, None] for k in "abcdpq")
    branch = np.asarray(cols["branch"])[:, None]
    full = np.asarray(cols["full_turn"])[:, None]
    lo, hi = np.asarray(cols["theta_lo"])[:, None], np.asarray(cols["theta_hi"])[:, None]
    theta = np.where(full, u, 0.5 * (lo + hi) + 0.5 * (hi - lo) * np.sin(u))
    side = np.where(full, branch, branch * np.where(np.cos(u) >= 0.0, 1, -1))
    gaps = fourbar_assembly_gaps(a, b, c, d)
    with np.errstate(invalid="ignore", divide="ignore"):
        *_, px, py, _ = fourbar_position(a, b, c, d, p, q, theta, side, *gaps)
    return px + 1j * py


def describe(a, b, c, d, p, q, branch):
    """The `FourBarSamples` record of given linkages (arrays of one shape (n,))."""
    a, b, c, d, p, q = (np.asarray(x, dtype=float) for x in (a, b, c, d, p, q))
    branch = np.asarray(branch, dtype=np.int8)
    full, lo, hi, movable = _input_ranges(a, b, c, d, branch)
    with np.errstate(invalid="ignore"):
        _, g0 = fourbar_transmission(a, b, c, d, 0.0)
        _, g1 = fourbar_transmission(a, b, c, d, np.pi)
    gamma = np.where(full, np.fmin(g0, g1), 0.0)
    return FourBarSamples(a, b, c, d, p, q, branch, _kinds(a, b, c, d), full, lo, hi, gamma, movable, movable)


def sample_fourbars(n, *, seed=0, lengths=LENGTHS, coupler=COUPLER, branch=None, min_transmission=0.0):
    """Draw four-bars from the normalised design space, with their type and input range.

    Ground ``d = 1``; crank ``a``, coupler ``b`` and rocker ``c`` log-uniform in `lengths`;
    coupler point ``(p, q) = b * (u, v)`` with ``u, v`` uniform in `coupler`; branch +1 or -1
    with equal chance (or the one given). Each sample carries its Grashof type, input range
    (full turn or rocking), minimum transmission angle over that range and a `movable` flag.

    Parameters
    ----------
    n : int
        Number of samples, in [0, 10**7].
    seed : int, optional
        Seed of ``numpy.random.default_rng``, in [0, 2**63 - 1]; the same seed gives the same samples.
    lengths : (float, float), optional
        Range of a, b, c as ratios to the ground, 0 < low < high <= 1e150.
    coupler : (float, float, float, float), optional
        ``(u_low, u_high, v_low, v_high)``: the coupler point in units of the coupler b
        (``b * max |u|, |v|`` at most 1e150).
    branch : {1, -1}, optional
        Draw one branch only.
    min_transmission : float, optional
        Samples whose `gamma_min` is below it (radians, in [0, pi/2]) are flagged not `usable`.

    Returns
    -------
    FourBarSamples
        All `n` samples; select the usable ones with ``samples.take(samples.usable)``.

    Notes
    -----
    The dead-centre input angles come from the generated
    ``fourbar_crank_angle_at_diagonal`` (derivation :ref:`deriv-transmission-angle`), the
    type from ``grashof_margins`` (:ref:`deriv-grashof`), positions from
    ``fourbar_position`` (:ref:`deriv-fourbar-position`), all vectorised over samples.

    Examples
    --------
    >>> from mech.atlas import sample_fourbars
    >>> s = sample_fourbars(1000, seed=3)
    >>> len(s), float(s.d.max())
    (1000, 1.0)
    >>> bool((s.full_turn == ((s.kind == "crank-rocker") | (s.kind == "double-crank"))).all())
    True
    """
    n = integer("n", n, minimum=0, maximum=10**7)
    seed = integer("seed", seed, minimum=0, maximum=_MAX_SEED)
    low, high = _box("lengths", lengths, 2)
    if not low > 0.0:
        raise ValueError(f"Expected `lengths` > 0, got {_show(lengths)}")
    u0, u1, v0, v1 = _box("coupler", coupler, 4)
    _check_sizes(("lengths", lengths, high), ("coupler", coupler, high * max(abs(u0), abs(u1), abs(v0), abs(v1))))
    if branch is not None:
        branch = branch_sign(branch)
    min_transmission = nonnegative_number("min_transmission", min_transmission)
    if min_transmission > np.pi / 2:
        raise ValueError(f"Expected `min_transmission` in [0, pi/2], got {min_transmission!r}")
    rng = np.random.default_rng(seed)
    a, b, c = np.exp(rng.uniform(np.log(low), np.log(high), size=(3, n)))
    u, v = rng.uniform(u0, u1, size=n), rng.uniform(v0, v1, size=n)
    signs = rng.choice(np.array([-1, 1], dtype=np.int8), size=n)
    if branch is not None:
        signs[:] = branch
    out = describe(a, b, c, np.ones(n), b * u, b * v, signs)
    usable = out.movable & (out.gamma_min >= min_transmission)
    return FourBarSamples(**{**out.columns(), "usable": usable})
