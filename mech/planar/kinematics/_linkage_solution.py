"""The solution of a planar linkage: every point, link angle and rate, and the instant centres."""

from __future__ import annotations

from types import MappingProxyType

import numpy as np

from mech._validate import known_name
from mech.planar.kinematics._instant_centres import instant_centres, prismatic, revolute
from mech.planar.kinematics._linkage_records import GROUND

__all__ = ["LinkageSolution"]


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
        full = lambda x: np.broadcast_to(np.asarray(x), shape)
        self.linkage, self.order, self.valid = linkage, order, state.valid
        self.points = MappingProxyType({k: full(v) for k, v in state.P.items()})
        self.velocities = MappingProxyType({k: full(v) for k, v in state.V.items()})
        self.accelerations = MappingProxyType({k: full(v) for k, v in state.A.items()})
        links = [k for k in linkage.links if k != GROUND]
        self._dirs = {k: full(state.dir[k]) for k in links}
        self.omegas = MappingProxyType({k: full(state.W[k]) for k in links if k in state.W})
        self.alphas = MappingProxyType({k: full(state.AL[k]) for k in links if k in state.AL})
        self.slides = MappingProxyType(dict(state.slides))
        self.failures = MappingProxyType(failures)

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
