"""The records a planar linkage is built from and solved into: guides, slides, steps, intervals.

Shared by the builder (`mech.planar.kinematics._linkage`), the step solvers
(``_linkage_groups``), the block and mode machinery and the solution, none of which this
module imports.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from mech._errors import InputTypeError
from mech._validate import planar_point, real_number

__all__ = ["AssemblyInterval", "Guide", "Slide"]

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
