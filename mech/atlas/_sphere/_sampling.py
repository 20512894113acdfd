"""A design space of spherical four-bars, sampled in bulk: type, input range, branch, transmission.

Each sample is a `mech.spherical.SphericalFourBar` with arcs a, b, c, d drawn uniformly in a
range of arcs and a coupler point at arc ``r`` from B and angle ``gamma`` from the great
circle B->C. Nothing is normalised: on the sphere the size of a linkage is part of the shape
of its coupler curve. For each sample the input range comes in closed form from the arc BD
(as `SphericalFourBar.assembly_range` finds it): a full turn when the crank revolves,
otherwise the rocking range between the two limit positions of the input, where B, C and D
lie on one great circle. As in the planar atlas (`mech.atlas.sample_fourbars`), the closed
coupler curve of a rocking input runs over the range on one assembly branch and back on the
other, through the limit positions where the two branches meet.
"""

from dataclasses import dataclass

import numpy as np

from mech._generated.spherical_fourbar import spherical_fourbar_limit_theta, spherical_fourbar_position
from mech._generated.spherical_types import spherical_type_slacks
from mech._validate import _show, branch_sign, integer, nonnegative_number, real_tuple
from mech.atlas._records import _MAX_SEED, _Samples
from mech.atlas._planar._sampling import KINDS

__all__ = ["SphereSamples", "sample_sphere_fourbars"]

#: Default range of the four arcs of a sampled spherical four-bar, radians.
ARCS = (0.15, 1.4)
#: Default range of the coupler point's arc r from B, radians.
COUPLER_ARC = (0.1, 1.2)


@dataclass(frozen=True)
class SphereSamples(_Samples):
    """Spherical four-bars, one entry per sample (arrays of shape (n,)).

    Attributes
    ----------
    a, b, c, d : ndarray
        Arcs AB (input), BC (coupler), CD (output) and AD (ground), radians.
    r, gamma : ndarray
        Coupler point: at arc `r` from B, at angle `gamma` from the great circle B->C.
    branch : ndarray of int
        Assembly branch (+1 where ``det[B, D, C] > 0``) of a full-turn input; for a rocking
        input, the branch the closed curve starts on, and the sign of the input range when
        the linkage has two.
    kind : ndarray of str
        Type by `mech.spherical.classify` (planar words).
    full_turn : ndarray of bool
        True if the crank turns fully.
    theta_lo, theta_hi : ndarray
        The input range, radians (0 and 2 pi for a full turn).
    gamma_min : ndarray
        Smallest transmission angle (at C, between the great circles C->B and C->D, folded
        into [0, pi/2]) over the input range; 0 for a rocking input, which stops where B, C
        and D lie on one great circle.
    movable : ndarray of bool
        False if the linkage cannot be assembled at two different input angles.
    usable : ndarray of bool
        `movable`, not a change-point linkage, and `gamma_min` at least the limit asked of
        `sample_sphere_fourbars`.
    """

    a: np.ndarray
    b: np.ndarray
    c: np.ndarray
    d: np.ndarray
    r: np.ndarray
    gamma: np.ndarray
    branch: np.ndarray
    kind: np.ndarray
    full_turn: np.ndarray
    theta_lo: np.ndarray
    theta_hi: np.ndarray
    gamma_min: np.ndarray
    movable: np.ndarray
    usable: np.ndarray

    def fourbar(self, i, frame=None):
        """Sample `i` as a `mech.spherical.SphericalFourBar` (placed by `frame`, a rotation)."""
        from mech.spherical import SphericalFourBar

        i = integer("i", i, minimum=-len(self), maximum=len(self) - 1)
        return SphericalFourBar(self.a[i], self.b[i], self.c[i], self.d[i], branch=int(self.branch[i]),
                                coupler=(float(self.r[i]), float(self.gamma[i])), frame=frame)

    def curves(self, samples=256):
        """Closed coupler curves of every sample, shape (n, samples, 3).

        A full-turn input at ``theta = 2 pi (j + 1/2) / samples`` on its branch; a rocking
        input at ``theta = mid + half * sin(u)``, ``u = 2 pi (j + 1/2) / samples``, on
        ``branch * sign(cos u)`` (over the range on one branch and back on the other).

        Examples
        --------
        >>> from mech.atlas import sample_sphere_fourbars
        >>> sample_sphere_fourbars(3, seed=1).curves(64).shape
        (3, 64, 3)
        """
        samples = integer("samples", samples, minimum=4, maximum=1 << 16)
        return sphere_curves(self.columns(), samples)


def sphere_curves(cols, samples):
    """Closed coupler curves (n, samples, 3) of the columns of `SphereSamples`."""
    return sphere_points(cols, 2 * np.pi * (np.arange(samples) + 0.5) / samples)


def sphere_points(cols, u):
    """Coupler points (n, m, 3) at curve parameters `u` (broadcast against (n, 1)).

    ``u`` runs over [0, 2 pi) once around each closed curve: the input angle for a full
    turn, ``theta = mid + half * sin(u)`` on ``branch * sign(cos u)`` for a rocking input.
    """
    a, b, c, d, r, gamma = (np.asarray(cols[k], dtype=float)[:, None] for k in ("a", "b", "c", "d", "r", "gamma"))
    branch = np.asarray(cols["branch"])[:, None]
    full = np.asarray(cols["full_turn"])[:, None]
    lo, hi = np.asarray(cols["theta_lo"])[:, None], np.asarray(cols["theta_hi"])[:, None]
    theta = np.where(full, u, 0.5 * (lo + hi) + 0.5 * (hi - lo) * np.sin(u))
    side = np.where(full, branch, branch * np.where(np.cos(u) >= 0.0, 1, -1))
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        *_, px, py, pz = spherical_fourbar_position(a, b, c, d, r, gamma, theta, -side)
    return np.stack([px, py, pz], axis=-1)


def input_ranges(a, b, c, d, branch):
    """Input range of each linkage: (full_turn, lo, hi, movable), vectorised.

    The arc g = BD runs from |a - d| (theta = 0) to min(a + d, 2 pi - a - d) (theta = pi);
    the linkage assembles while g lies in [|b - c|, min(b + c, 2 pi - b - c)], the limit
    positions from eq. (6) of :ref:`deriv-spherical-fourbar` (``spherical_fourbar_limit_theta``).
    """
    g_lo, g_hi = np.abs(a - d), np.minimum(a + d, 2 * np.pi - a - d)
    w_lo, w_hi = np.abs(b - c), np.minimum(b + c, 2 * np.pi - b - c)
    lo, hi = np.maximum(g_lo, w_lo), np.minimum(g_hi, w_hi)
    movable = lo < hi
    with np.errstate(invalid="ignore"):
        t_lo = np.where(w_lo <= g_lo, 0.0, spherical_fourbar_limit_theta(a, d, np.clip(lo, g_lo, g_hi)))
        t_hi = np.where(w_hi >= g_hi, np.pi, spherical_fourbar_limit_theta(a, d, np.clip(hi, g_lo, g_hi)))
    movable &= t_lo < t_hi
    full = movable & (t_lo == 0.0) & (t_hi == np.pi)
    # one interval around 0 ([-t_hi, t_hi]), one around pi ([t_lo, 2 pi - t_lo]), or two
    # mirror intervals [t_lo, t_hi] and [-t_hi, -t_lo]: the branch sign picks one
    first = branch > 0
    lo_out = np.where(t_lo == 0.0, -t_hi, np.where(t_hi == np.pi, t_lo, np.where(first, t_lo, -t_hi)))
    hi_out = np.where(t_lo == 0.0, t_hi, np.where(t_hi == np.pi, 2 * np.pi - t_lo, np.where(first, t_hi, -t_lo)))
    return full, np.where(full, 0.0, lo_out), np.where(full, 2 * np.pi, hi_out), movable


def transmission_min(b, c, g_ends):
    """Smallest transmission angle at C over arcs BD in `g_ends` (a tuple of arrays), in [0, pi/2].

    The spherical law of cosines in the triangle BCD: ``cos g = cos b cos c + sin b sin c cos mu``;
    mu is monotonic in g, so its extremes lie at the ends of the range of g.
    """
    out = np.full(np.shape(b), np.pi / 2)
    for g in g_ends:
        with np.errstate(invalid="ignore", divide="ignore"):
            mu = np.arccos(np.clip((np.cos(g) - np.cos(b) * np.cos(c)) / (np.sin(b) * np.sin(c)), -1.0, 1.0))
        out = np.fmin(out, np.minimum(mu, np.pi - mu))
    return out


def kinds(a, b, c, d):
    """Types and change-point flags by the sign table of :ref:`deriv-spherical-types`.

    Vectorised for rows whose four arcs are at most pi/2 (no antipode move is needed; the
    table is `mech.spherical.classify`'s); other rows call `classify` itself.
    """
    from mech.spherical._types import classify

    s_ab, s_ac, s_ad, s_n = (np.sign(x) for x in spherical_type_slacks(a, b, c, d))
    turns_a = (s_ab * s_ac >= 0) & (s_ad * s_n >= 0)
    turns_d = (s_ac * s_ad <= 0) & (s_ab * s_n <= 0)
    turns_b = (s_ac * s_ad >= 0) & (s_ab * s_n >= 0)
    turns_c = (s_ab * s_ac <= 0) & (s_ad * s_n <= 0)
    code = np.where(turns_a & turns_d, 2, np.where(turns_a, 0, np.where(turns_d, 1, 3)))
    code = np.where(turns_a | turns_b | turns_c | turns_d, code, 4)
    out = np.asarray(KINDS)[code]
    change = (s_ab == 0) | (s_ac == 0) | (s_ad == 0) | (s_n == 0)
    for i in np.flatnonzero(np.maximum.reduce([a, b, c, d]) > np.pi / 2):
        try:
            t = classify(a[i], b[i], c[i], d[i])
        except ValueError:                   # cannot be assembled: `input_ranges` says so too
            continue
        out[i], change[i] = t.kind, t.change_point
    return out, change


def describe_sphere(a, b, c, d, r, gamma, branch, min_transmission=0.0):
    """The `SphereSamples` record of given spherical four-bars (arrays of one shape (n,))."""
    a, b, c, d, r, gamma = (np.asarray(x, dtype=float) for x in (a, b, c, d, r, gamma))
    branch = np.asarray(branch, dtype=np.int8)
    full, lo, hi, movable = input_ranges(a, b, c, d, branch)
    kind, change = kinds(a, b, c, d)
    g_ends = (np.abs(a - d), np.minimum(a + d, 2 * np.pi - a - d))
    gamma_min = np.where(full, transmission_min(b, c, g_ends), 0.0)
    usable = movable & ~change & (gamma_min >= min_transmission)
    return SphereSamples(a, b, c, d, r, gamma, branch, kind, full, lo, hi, gamma_min, movable, usable)


def _pair(name, value, top=np.pi):
    lo, hi = real_tuple(name, value, 2)
    if not 0.0 < lo < hi < top:
        raise ValueError(f"Expected `{name}` with 0 < low < high < pi, got {_show(value)}")
    return lo, hi


def sample_sphere_fourbars(n, *, seed=0, arcs=ARCS, coupler_arc=COUPLER_ARC, branch=None, min_transmission=0.0):
    """Draw spherical four-bars, with their type, input range and minimum transmission angle.

    Arcs a, b, c, d uniform in `arcs`; the coupler point at arc ``r`` uniform in
    `coupler_arc` from B and angle ``gamma`` uniform in [-pi, pi); branch +1 or -1 with equal
    chance (or the one given). Cranks that turn fully and rocking inputs are both kept;
    samples that cannot move are flagged (`movable`), and so are change-point linkages and
    those whose minimum transmission angle is below `min_transmission` (`usable`).

    Parameters
    ----------
    n : int
        Number of samples, in [0, 10**7].
    seed : int, optional
        Seed of ``numpy.random.default_rng``, in [0, 2**63 - 1].
    arcs, coupler_arc : (float, float), optional
        Ranges of the four arcs and of r, radians, 0 < low < high < pi.
    branch : {1, -1}, optional
        Draw one branch only.
    min_transmission : float, optional
        Radians in [0, pi/2]; any value above 0 keeps only cranks that turn fully.

    Returns
    -------
    SphereSamples
        All `n` samples; ``samples.take(samples.usable)`` selects the usable ones.

    Notes
    -----
    Types by the slack table of :ref:`deriv-spherical-types` (`mech.spherical.classify`),
    limit positions by eq. (6) and positions by eqs. (1)-(10) of
    :ref:`deriv-spherical-fourbar`, all vectorised over samples.

    Examples
    --------
    >>> from mech.atlas import sample_sphere_fourbars
    >>> s = sample_sphere_fourbars(1000, seed=3)
    >>> bool((s.full_turn == ((s.kind == "crank-rocker") | (s.kind == "double-crank"))).all())
    True
    >>> bool(s.full_turn.any() and (~s.full_turn & s.usable).any())    # rocking inputs kept too
    True
    """
    n = integer("n", n, minimum=0, maximum=10**7)
    seed = integer("seed", seed, minimum=0, maximum=_MAX_SEED)
    lo, hi = _pair("arcs", arcs)
    r0, r1 = _pair("coupler_arc", coupler_arc)
    if branch is not None:
        branch = branch_sign(branch)
    min_transmission = nonnegative_number("min_transmission", min_transmission)
    if min_transmission > np.pi / 2:
        raise ValueError(f"Expected `min_transmission` in [0, pi/2], got {min_transmission!r}")
    rng = np.random.default_rng(seed)
    a, b, c, d = rng.uniform(lo, hi, size=(4, n))
    r, gamma = rng.uniform(r0, r1, size=n), rng.uniform(-np.pi, np.pi, size=n)
    signs = rng.choice(np.array([-1, 1], dtype=np.int8), size=n)
    if branch is not None:
        signs[:] = branch
    return describe_sphere(a, b, c, d, r, gamma, signs, min_transmission)
