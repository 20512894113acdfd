"""Design constraints of the synthesis: a motor that turns fully, a transmission angle, sane proportions.

A four-bar found by the atlas traces the target, but a designer also asks that a motor can
drive it (its input link turns fully), that it never comes near a dead centre (a minimum
transmission angle), that its links are of sensible proportions (a bound on the ratio of the
longest to the shortest), and that its fixed pivots lie where there is room for them (a box).
`Constraints` holds these; the refinement keeps them, and every linkage `find_linkages`
returns satisfies them (`Constraints.violations` is the check).

With the motor at the crank ``a`` and ``BD`` the diagonal from the crank pin to the rocker
pivot, the transmission angle (between coupler and rocker) satisfies, by the law of cosines
in the triangle ``B C D``,

    cos(delta) = (b^2 + c^2 - BD^2) / (2 b c),   BD^2 = a^2 + d^2 - 2 a d cos(theta),   (C1)

and ``BD`` runs between ``|d - a|`` (theta = 0) and ``d + a`` (theta = pi) as the crank turns.
So the crank turns fully with a transmission angle of at least ``mu`` everywhere exactly
when (C1) lies in ``[-cos mu, cos mu]`` at both ends,

    g_0 = cos mu - (b^2 + c^2 - (d - a)^2) / (2 b c) >= 0,
    g_pi = (b^2 + c^2 - (d + a)^2) / (2 b c) + cos mu >= 0,                              (C2)

two smooth inequalities on the lengths (with ``mu = 0`` they say that the triangle B C D
closes at every crank angle: the crank turns fully).
"""

import math
from dataclasses import dataclass

import numpy as np

from mech._validate import _show, bool_flag, nonnegative_number, real_number

__all__ = ["Constraints"]

#: Transmission angle asked of a crank when none is (the limit mu -> 0 of (C2) is a dead centre).
_LEAST_ANGLE = 1e-3


@dataclass(frozen=True)
class Constraints:
    """What a linkage returned by the synthesis must satisfy.

    Attributes
    ----------
    crank : bool
        The input link (the crank ``a``, where the motor sits) turns fully. A linkage whose
        other side link turns fully (a rocker-crank) is relabelled so that the motor sits
        at that link (`motor_at_crank`).
    min_transmission : float
        Smallest transmission angle over the full turn, radians, in [0, pi/2) (default 30
        degrees); above zero it implies `crank` (a rocking input reaches a dead centre).
    max_ratio : float or None
        Largest ratio of the longest to the shortest of the four links (default 10);
        None for no bound.
    pivot_box : (float, float, float, float) or None
        ``(x_min, x_max, y_min, y_max)``: the box, in the target's units and frame, that
        both fixed pivots must lie in; None for anywhere.

    Examples
    --------
    >>> import math
    >>> from mech.atlas import Constraints
    >>> from mech.planar import FourBar
    >>> c = Constraints()
    >>> round(math.degrees(c.min_transmission)), c.max_ratio
    (30, 10.0)
    >>> c.violations(FourBar(10, 40, 30, 35))          # a crank-rocker, gamma_min 38.6 deg
    ()
    >>> c.violations(FourBar(32, 40, 35, 45))          # not Grashof: the crank rocks
    ('the input link does not turn fully',)
    """

    crank: bool = True
    min_transmission: float = math.radians(30.0)
    max_ratio: float = 10.0
    pivot_box: tuple = None

    def __post_init__(self):
        object.__setattr__(self, "crank", bool_flag("crank", self.crank))
        mu = nonnegative_number("min_transmission", self.min_transmission)
        if not mu < np.pi / 2:
            raise ValueError(f"Expected `min_transmission` in [0, pi/2), got {mu!r}")
        object.__setattr__(self, "min_transmission", mu)
        if self.max_ratio is not None:
            r = real_number("max_ratio", self.max_ratio)
            if not r >= 1.0:
                raise ValueError(f"Expected `max_ratio` >= 1 (or None), got {r!r}")
            object.__setattr__(self, "max_ratio", r)
        if self.pivot_box is not None:
            box = np.asarray(self.pivot_box, dtype=object)
            if box.shape != (4,):
                raise ValueError(f"Expected `pivot_box` to be (x_min, x_max, y_min, y_max), got {_show(self.pivot_box)}")
            x0, x1, y0, y1 = (real_number("pivot_box", v) for v in self.pivot_box)
            if not (x0 < x1 and y0 < y1):
                raise ValueError(f"Expected `pivot_box` with x_min < x_max and y_min < y_max, got "
                                 f"{(x0, x1, y0, y1)!r}")
            object.__setattr__(self, "pivot_box", (x0, x1, y0, y1))

    @classmethod
    def none(cls):
        """No constraint at all: any four-bar, rocking or not, of any proportions."""
        return cls(crank=False, min_transmission=0.0, max_ratio=None, pivot_box=None)

    @property
    def driven(self):
        """True if the input must turn fully (asked for, or implied by a transmission angle)."""
        return self.crank or self.min_transmission > 0.0

    def violations(self, fourbar, pivots=None, *, tol=1e-9):
        """The constraints a four-bar breaks, as a tuple of short phrases (empty if none).

        `fourbar` is a `mech.planar.FourBar` (its motor at the crank ``a``); `pivots` its two
        fixed pivots in the target's frame (complex), needed when `pivot_box` is set.
        """
        a, b, c, d = (float(x) for x in (fourbar.a, fourbar.b, fourbar.c, fourbar.d))
        # every test below compares ratios: in units of the longest link, no square overflows
        # or underflows (a linkage of 1e200 or 1e-200)
        longest = max(a, b, c, d)
        if longest > 0.0:
            a, b, c, d = a / longest, b / longest, c / longest, d / longest
        out = []
        if self.driven:
            g0, gpi = transmission_margins(a, b, c, d, 0.0)
            if not (g0 >= -tol and gpi >= -tol):
                out.append("the input link does not turn fully")
            elif self.min_transmission > 0.0:
                g0, gpi = transmission_margins(a, b, c, d, self.min_transmission)
                if not (g0 >= -tol and gpi >= -tol):
                    out.append(f"the transmission angle falls below {math.degrees(self.min_transmission):.6g} deg")
        if self.max_ratio is not None and not max(a, b, c, d) <= self.max_ratio * min(a, b, c, d) * (1 + tol):
            out.append(f"the longest link is more than {self.max_ratio:.6g} times the shortest")
        if self.pivot_box is not None:
            if pivots is None:
                raise ValueError("Expected `pivots` for a `pivot_box` constraint, got None")
            x0, x1, y0, y1 = self.pivot_box
            slack = tol * max(x1 - x0, y1 - y0)
            if not all(x0 - slack <= p.real <= x1 + slack and y0 - slack <= p.imag <= y1 + slack for p in pivots):
                out.append("a fixed pivot lies outside the box")
        return tuple(out)


def transmission_margins(a, b, c, d, mu):
    """(C2): ``(g_0, g_pi)``, both >= 0 when the crank `a` turns fully with a transmission
    angle of at least `mu` (arrays broadcast)."""
    two_bc = 2.0 * b * c
    cos_mu = np.cos(mu)
    return (cos_mu - (b * b + c * c - (d - a) ** 2) / two_bc,
            (b * b + c * c - (d + a) ** 2) / two_bc + cos_mu)


def motor_at_crank(a, b, c, d, p, q, branch):
    """The same linkage with the motor moved to the rocker pivot, if only the rocker turns fully.

    For a rocker-crank (``c`` turns fully, ``a`` rocks) returns the relabelled linkage: crank
    ``c``, coupler ``b``, rocker ``a``, ground ``d``, coupler point ``(b - p, -q)`` (the
    coupler seen from C towards B), the branch of its one circuit, and True; in its standard
    frame the new crank pivot is the old D, so the placement turns by pi about the ground's
    midpoint (``z' = d - z``). Any other linkage comes back as given, with False.
    """
    from mech.atlas._planar._sampling import _input_ranges
    from mech.planar.kinematics._fourbar import FourBar

    full_a = bool(_input_ranges(*(np.array([x]) for x in (a, b, c, d)), np.array([branch]))[0][0])
    full_c = bool(_input_ranges(*(np.array([x]) for x in (c, b, a, d)), np.array([branch]))[0][0])
    if full_a or not full_c:
        return (a, b, c, d, p, q, branch), False
    # the new branch: the side of the new C (the old B) of the line from the new B (old C) to
    # the new D (old A), read off one pose of the old linkage (a rotation keeps sides)
    full, lo, hi, _ = _input_ranges(*(np.array([x]) for x in (a, b, c, d)), np.array([branch]))
    pose = FourBar(a, b, c, d, branch=int(branch), coupler=(p, q)).solve(0.5 * (lo[0] + hi[0]))
    B, C = complex(pose.B), complex(pose.C)
    side = (np.conj(0.0 - C) * (B - C)).imag
    return (c, b, a, d, b - p, -q, 1 if side > 0 else -1), True
