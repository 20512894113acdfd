"""The records a planar linkage is built from and solved into: guides, slides, steps, intervals, solutions.

Shared by the builder (`mech.planar.kinematics._linkage`), the step solvers
(``_linkage_groups``) and the block and mode machinery, none of which this module imports.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from types import MappingProxyType

import numpy as np

from mech._errors import InputTypeError
from mech._validate import known_name, planar_point, real_number
from mech.planar.kinematics._instant_centres import instant_centres, prismatic, revolute

__all__ = ["AssemblyInterval", "Guide", "LinkageSolution", "Slide"]

GROUND = "ground"


def _for(arg):
    return "" if arg is None else f" for `{arg}`"


def _two(name, value):
    """Unpack a pair of names (links, pins, guides) given as a tuple or list."""
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise InputTypeError(f"Expected `{name}` to be a pair, got {value!r}")
    return tuple(value)


def _looks_numeric(text):
    """True for a string such as "10" that would name a driver but reads as a number."""
    try:
        float(text)
    except ValueError:
        return False
    return True


@dataclass(frozen=True)
class Guide:
    """A straight guide fixed in a link: through a point of it, at an angle to the link.

    ``through`` is a point name, or local coordinates (complex) in the link's frame;
    ``angle`` is measured from the link's x axis (for the ground: from +x).
    """

    link: str
    through: object = 0j
    angle: float = 0.0

    def __post_init__(self):
        if not isinstance(self.through, str) or _looks_numeric(self.through):
            object.__setattr__(self, "through", planar_point("through", self.through))
        object.__setattr__(self, "angle", real_number("angle", self.angle))


@dataclass(frozen=True)
class Slide:
    """Relative motion in one sliding pair: the moving link along the guiding link.

    ``s`` is the position along the guide, ``v`` and ``a`` its first and second time
    derivatives (the relative sliding velocity and acceleration, along ``direction``),
    ``coriolis`` the Coriolis acceleration 2 omega x v_rel (complex), where
    omega is the angular velocity of the guiding link.
    """

    s: np.ndarray
    direction: np.ndarray
    v: np.ndarray = None
    a: np.ndarray = None
    coriolis: np.ndarray = None


@dataclass(frozen=True)
class AssemblyInterval:
    """A closed interval of one driver's input where the linkage assembles."""

    start: float
    end: float


@dataclass(frozen=True)
class _Step:
    kind: str
    label: str
    links: tuple
    data: tuple          # (key, value) pairs, so the step stays hashable and immutable

    def get(self, key):
        return dict(self.data)[key]


def _re_im(z):
    return np.real(z), np.imag(z)


def _cx(x, y):
    return x + 1j * y


# step data that hold lengths (or guides through fixed points); the rest are angles, signs, names
_LENGTH_KEYS = frozenset({"at", "length", "lengths", "offset", "guide", "guides"})


def _magnitudes(value, planar=False):
    """The length magnitudes held by one item of step data (a Guide, a number, a tuple).

    A point gives its two coordinates, or with ``planar=True`` its distance from the origin.
    """
    if isinstance(value, Guide):
        return [] if isinstance(value.through, str) else _magnitudes(complex(value.through), planar)
    if isinstance(value, tuple):
        return [m for v in value for m in _magnitudes(v, planar)]
    if isinstance(value, complex):
        return [math.hypot(value.real, value.imag)] if planar else [abs(value.real), abs(value.imag)]
    if isinstance(value, float):
        return [abs(value)]
    return []           # a driver's name in place of a length


def _in_unit(value, unit):
    """Divide the lengths in one item of step data by `unit` (angles and names unchanged)."""
    if isinstance(value, Guide):
        if isinstance(value.through, str):
            return value
        return replace(value, through=complex(value.through) / unit)
    if isinstance(value, tuple):
        return tuple(_in_unit(v, unit) for v in value)
    if isinstance(value, (complex, float)) and not isinstance(value, bool):
        return value / unit
    return value


class LinkageSolution:
    """The solved linkage over an array of inputs (immutable).

    Attributes
    ----------
    points, velocities, accelerations : mapping of str to complex ndarray
        Every named point; velocities need ``order >= 1``, accelerations ``order >= 2``.
    angles, omegas, alphas : mapping of str to float ndarray
        Every moving link's angle (of its frame's x axis, in (-pi, pi]; use
        ``numpy.unwrap`` along the input for a continuous angle), angular velocity and
        angular acceleration.
    slides : mapping of (str, str) to Slide
        Every sliding pair, keyed by (moving link, guiding link).
    valid : bool ndarray
        Where every group assembles.
    failures : mapping of str to bool ndarray
        For each driver and group, where it is the first to fail.
    """

    def __init__(self, linkage, order, state, failures):
        shape = state.shape
        def full(x):
            # an array of the full shape already (the compiled loop's rows) is kept as it is
            return x if type(x) is np.ndarray and x.shape == shape else np.broadcast_to(np.asarray(x), shape)

        self.linkage, self.order, self.valid = linkage, order, state.valid
        self.points = MappingProxyType({k: full(v) for k, v in state.P.items()})
        self.velocities = MappingProxyType({k: full(v) for k, v in state.V.items()})
        self.accelerations = MappingProxyType({k: full(v) for k, v in state.A.items()})
        links = [k for k in linkage.links if k != GROUND]
        later = getattr(state, "dirs_later", None)
        # the compiled loop leaves the directions to a second pass, made on first use
        self._dirs_now = None if later is not None else {k: full(state.dir[k]) for k in links}
        self._dirs_later = None if later is None else (lambda: {k: full(v) for k, v in later().items()})
        self.omegas = MappingProxyType({k: full(state.W[k]) for k in links if k in state.W})
        self.alphas = MappingProxyType({k: full(state.AL[k]) for k in links if k in state.AL})
        self.slides = MappingProxyType(dict(state.slides))
        self.failures = MappingProxyType(failures)

    @property
    def _dirs(self):
        if self._dirs_now is None:
            object.__setattr__(self, "_dirs_now", self._dirs_later())
        return self._dirs_now

    @property
    def angles(self):
        """Angle of every moving link's frame, by atan2, in (-pi, pi]."""
        return MappingProxyType({k: np.angle(d) for k, d in self._dirs.items()})

    def instant_centres(self):
        """All n(n-1)/2 instant centres of the linkage at every pose, by Kennedy's theorem.

        The direct centres come from the pairs (a revolute pair at its joint, a sliding
        pair at infinity across its guide); the rest follow from the three-centre theorem
        (`mech.planar.instant_centres`, derivation :ref:`deriv-instant-centres`).

        Returns
        -------
        InstantCentres
            Indexed by pairs of link names, the ground being ``"ground"``. A centre that
            the positions do not fix (its Kennedy lines coincide at a pose) is NaN there,
            with its mask ``defined`` False.

        Raises
        ------
        ValueError
            If a pose was not assembled (its centres do not exist).
        """
        if not np.all(self.valid):
            first = np.unravel_index(np.flatnonzero(~self.valid)[0], self.valid.shape)
            raise ValueError(f"Expected every pose to be assembled, got an invalid pose at index "
                             f"{tuple(int(i) for i in first)}; solve the valid inputs only")
        direct = {}
        for kind, i, j, where in self.linkage._direct_pairs():
            key = (i, j)
            if (j, i) in direct or key in direct:
                continue          # a compound hinge: one pair per two links is enough
            if kind == "R":
                direct[key] = revolute(self.points[where])
            else:
                direct[key] = prismatic(self.slides[where].direction)
        return instant_centres(self.linkage.links, direct, undefined="nan")

    def direction(self, link):
        """Unit complex direction of ``link``'s frame x axis (no trigonometry)."""
        known_name("link", link, tuple(self._dirs))
        return self._dirs[link]

    def __setattr__(self, name, value):
        if name in self.__dict__:
            raise AttributeError("LinkageSolution is immutable")
        object.__setattr__(self, name, value)

    def __repr__(self):
        return (f"LinkageSolution(order={self.order}, shape={self.valid.shape}, "
                f"valid={int(self.valid.sum())}/{self.valid.size})")
