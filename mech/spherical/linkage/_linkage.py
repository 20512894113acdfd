"""A spherical linkage of one degree of freedom: a crank, then spherical RRR dyads.

The formulas come from ``derivations/spherical/linkage.md`` through
``mech._generated.spherical_linkage``; this module orders the steps, carries the points,
angular velocities and accelerations from one step to the next, and reports failures.
"""

from __future__ import annotations

import numpy as np

from mech._errors import AssemblyError, InputTypeError
from mech._generated import spherical_linkage as _g
from mech._pose import Pose
from mech._scaling import DEAD_POINT_RTOL
from mech._validate import arc as _arc, bool_flag, branch_sign, motion_inputs, real_number, real_tuple, unit_vector

# ``GROUND`` is the name a pivot on the frame is given; callers write the string "ground"
__all__ = ["SphericalLinkage", "SphericalLinkagePose"]

GROUND = "ground"

#: A dyad's radicand (4) within this of zero at a local minimum counts as a change point.
_CHANGE_TOL = 1e-12
#: Inputs per block of a solve: a six-bar's temporaries over a block stay in cache.
_BLOCK = 16384


def _xyz(v):
    return v[..., 0], v[..., 1], v[..., 2]


def _stack(*c):
    return np.stack(np.broadcast_arrays(*c), axis=-1)


def _pair(name, value):
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise InputTypeError(f"Expected `{name}` to be a pair, got {value!r}")
    return tuple(value)


class SphericalLinkagePose(Pose):
    """Poses of a `SphericalLinkage` at an array of input angles (`SphericalLinkage.solve`).

    Attributes
    ----------
    theta, valid, assembled : ndarray, shape (...)
        Input angle; True where every solved field is finite; True where the positions
        exist (they differ only at dead points, where a dyad's rates are unbounded).
    points : dict of str -> ndarray, shape (..., 3)
        Every named point (ground points broadcast), NaN where it cannot assemble.
    velocities, accelerations : dict of str -> ndarray, shape (..., 3)
        Velocities and accelerations of every point; with ``order >= 1`` and ``>= 2``.
    angular_velocities, angular_accelerations : dict of str -> ndarray, shape (..., 3)
        Angular velocity and acceleration vectors of every link (the ground's are zero).
    """

    _ORDER_OF = {"velocities": 1, "angular_velocities": 1, "accelerations": 2, "angular_accelerations": 2}


class SphericalLinkage:
    """A spherical linkage (球面连杆机构) built as a crank followed by spherical RRR dyads.

    Build it with the chained methods (each returns a new linkage), then call `solve`.
    Points are unit vectors named by strings; links are named by strings; the frame is
    ``"ground"``. Every moving link has a frame: an origin point and the great circle
    towards a second point of it, set by the step that creates it, and `point` attaches a
    point at an arc and an angle there (eq. (1) of :ref:`deriv-spherical-linkage`).

    Parameters
    ----------
    ground : mapping of str to array_like (3,), optional
        Named fixed points (unit vectors).

    Notes
    -----
    Derivation: :ref:`deriv-spherical-linkage`. Each dyad is solved in closed form from
    the one equation A cos x + B sin x = C, eqs. (2)-(4), with an explicit ``branch``:
    +1 puts the joint to the left of the directed great circle pins[0] -> pins[1] seen
    from outside (``det[P1, P2, J] > 0``), the convention of `SphericalFourBar`, and a
    solution never jumps from one branch to the other.

    *Change points.* Where a dyad's two branches meet and part again (its radicand (4)
    touches zero: the spherical isogram at theta = 0 and pi, any four-bar with
    s + l = p + q), the motion continues smoothly onto the other sign, as in
    `SphericalFourBar`: the sign at input theta is ``branch`` times -1 for each change
    point in (0, theta] (for theta < 0, in (theta, 0]), so ``branch`` names the mode just
    after theta = 0 and every input is solved on its own. The change points are found once
    per linkage by sampling each dyad's radicand over the period of its pins (2048 samples
    per turn; two change points closer than a sample are missed), refining the minimum, and
    locating the zero of the signed root to rounding; a linkage with an odd number of them
    per turn has a period of two turns. Within four samples of a change point, where the
    dyad's equations lose digits (the rates are 0/0 at the point), every result is the
    polynomial through 16 solutions of the same mode further away, so the meeting pose is
    solved, rates included (tested against `SphericalFourBar`: positions to 1e-13,
    velocities 1e-10, accelerations 1e-8).

    *Dead points.* Where a dyad's branches meet without parting (a limit position of the
    input, the radicand crossing zero) the pose is assembled but its rates are unbounded:
    where ``|det[P1, P2, J]| <= 2**-46`` the rates from that dyad on are NaN (``valid``
    False, ``assembled`` True), never a huge finite number. Rates come from differentiating
    the closure, eqs. (5)-(8): each link's angular velocity and acceleration vector, then
    ``v = w x P`` and ``a = dw x P + w x (w x P)`` for its points.

    Examples
    --------
    The spherical four-bar (0.3, 0.9, 0.7, 1.0) as a crank and one dyad:

    >>> import numpy as np
    >>> from mech.spherical import SphericalLinkage
    >>> lk = (SphericalLinkage({"A": (0, 0, 1), "D": (np.sin(1.0), 0, np.cos(1.0))})
    ...       .crank("AB", pivot="A", tip="B", arc=0.3, reference="D")
    ...       .rrr(("BC", "DC"), pins=("B", "D"), joint="C", arcs=(0.9, 0.7)))
    >>> pose = lk.solve([0.0, np.pi / 2], order=2)
    >>> np.round(np.arccos(np.sum(pose.points["C"] * pose.points["D"], axis=-1)), 12).tolist()
    [0.7, 0.7]
    >>> pose.accelerations["C"].shape
    (2, 3)
    """

    def __init__(self, ground=None):
        self._steps = ()
        self._points = {}
        self._links = {GROUND: None}
        self._driver = None
        if ground is not None and not hasattr(ground, "items"):
            raise InputTypeError(f"Expected `ground` to be a mapping of point names to unit vectors, got {ground!r}")
        for name, v in dict(ground or {}).items():
            self._add_point(name, GROUND, "ground")
            self._steps += (("ground", name, unit_vector(f"ground[{name!r}]", v)),)

    # ------------------------------------------------------------------ building
    def _copy(self):
        new = object.__new__(SphericalLinkage)
        new._steps = self._steps
        new._points = dict(self._points)
        new._links = dict(self._links)
        new._driver = self._driver
        return new

    def _add_point(self, name, link, arg):
        if not isinstance(name, str) or not name:
            raise ValueError(f"Expected `{arg}` to be a point name (a non-empty str), got {name!r}")
        if name in self._points:
            raise ValueError(f"Expected `{arg}` to be a new point name, got {name!r}, which is already defined")
        self._points[name] = link

    def _add_link(self, name, frame, arg):
        if not isinstance(name, str) or not name:
            raise ValueError(f"Expected `{arg}` to be a link name (a non-empty str), got {name!r}")
        if name in self._links:
            raise ValueError(f"Expected `{arg}` to be a new link name, got {name!r}, which is already defined")
        self._links[name] = frame

    def _need_point(self, name, arg):
        if not isinstance(name, str) or name not in self._points:
            known = ", ".join(sorted(self._points)) or "none"
            raise ValueError(f"Expected `{arg}` to be a known point, got {name!r} (known points: {known})")

    def _need_link(self, name, arg):
        if not isinstance(name, str) or name not in self._links:
            known = ", ".join(sorted(self._links))
            raise ValueError(f"Expected `{arg}` to be a known link, got {name!r} (known links: {known})")

    @property
    def points(self):
        """Names of the points, in the order they are defined."""
        return tuple(self._points)

    @property
    def links(self):
        """Names of the links (the ground first)."""
        return tuple(self._links)

    @property
    def change_points(self):
        """``(period, points)``: the period of the motion in theta (2 pi, or 4 pi after an odd
        number of change points per turn) and, per dyad in order, its change points in
        [0, period) (see the class notes); found on first use."""
        period, points = self._change_points()
        return period, tuple(p.copy() for p in points)

    @property
    def members(self):
        """The points of every link, a mapping from link name to point names (frame points first).

        A link with three or more points is a ternary (or higher) link.
        """
        out = {link: [] if frame is None else list(frame) for link, frame in self._links.items()}
        for name, link in self._points.items():
            if name not in out[link]:
                out[link].append(name)
        return {link: tuple(names) for link, names in out.items()}

    def ground(self, name, at):
        """Add a fixed point `name` at the unit vector `at`."""
        new = self._copy()
        new._add_point(name, GROUND, "name")
        new._steps += (("ground", name, unit_vector("at", at)),)
        return new

    def point(self, name, *, link, at):
        """Attach a point to a moving `link` at ``at = (r, gamma)`` in its frame.

        The point is at arc `r` from the frame's origin O, at the angle `gamma`
        counter-clockwise (seen from outside) from the great circle O -> X, eq. (1).
        """
        new = self._copy()
        new._need_link(link, "link")
        if link == GROUND:
            raise ValueError("Expected `link` to be a moving link (add ground points with `ground`), got 'ground'")
        r, g = real_tuple("at", at, 2)
        new._add_point(name, link, "name")
        new._steps += (("point", name, link, r, g),)
        return new

    def crank(self, link, *, pivot, tip, arc, reference):
        """The input crank: `link` turns about the fixed point `pivot`, its `tip` at `arc`.

        The input angle theta is the angle at `pivot` from the great circle towards the
        fixed point `reference` to the great circle towards `tip`, counter-clockwise seen
        from outside; the link's frame is ``pivot -> tip``.
        """
        new = self._copy()
        if new._driver is not None:
            raise ValueError(f"Expected one crank (the linkage has one degree of freedom), got a second: {link!r}")
        new._need_point(pivot, "pivot")
        new._need_point(reference, "reference")
        for arg, p in (("pivot", pivot), ("reference", reference)):
            if new._points[p] != GROUND:
                raise ValueError(f"Expected `{arg}` to be a ground point, got {p!r} (on link {new._points[p]!r})")
        if pivot == reference:
            raise ValueError(f"Expected `reference` to differ from `pivot`, got {reference!r} for both")
        a = _arc("arc", arc)
        new._add_link(link, (pivot, tip), "link")
        new._add_point(tip, link, "tip")
        new._driver = link
        new._steps += (("crank", link, pivot, tip, a, reference),)
        return new

    def rrr(self, links, *, pins, joint, arcs, branch=1):
        """A spherical RRR dyad, eqs. (2)-(8): two links pinned at known `pins`, met at `joint`.

        ``arcs = (b1, b2)`` are the arcs pins[0]-joint and pins[1]-joint. ``branch=+1``
        puts `joint` to the left of the great circle pins[0] -> pins[1] seen from outside.
        Frames: link 0 is ``pins[0] -> joint``, link 1 is ``pins[1] -> joint``.
        """
        new = self._copy()
        l1, l2 = _pair("links", links)
        p1, p2 = _pair("pins", pins)
        new._need_point(p1, "pins[0]")
        new._need_point(p2, "pins[1]")
        if p1 == p2:
            raise ValueError(f"Expected two different `pins`, got {pins!r}")
        b1, b2 = (_arc("arcs", v) for v in _pair("arcs", arcs))
        sign = branch_sign(branch)
        new._add_link(l1, (p1, joint), "links[0]")
        new._add_link(l2, (p2, joint), "links[1]")
        new._add_point(joint, l1, "joint")
        new._steps += (("rrr", (l1, l2), (p1, p2), joint, (b1, b2), sign),)
        return new

    def __repr__(self):
        return f"SphericalLinkage(points={list(self._points)}, links={list(self._links)[1:]})"

    # ------------------------------------------------------------------ solving
    def solve(self, theta, order=0, omega=1.0, alpha=0.0, strict=False):
        """Solve every point of the linkage at the input angles `theta`.

        Parameters
        ----------
        theta : array_like, shape (...)
            Input angle of the crank, radians.
        order : {0, 1, 2}, optional
            Highest time derivative to compute.
        omega, alpha : array_like, optional
            The crank's angular velocity and acceleration, broadcast against `theta`.
        strict : bool, optional
            Raise `AssemblyError` instead of returning NaN where it cannot assemble.

        Returns
        -------
        SphericalLinkagePose
            ``theta, valid, assembled, points``; with ``order >= 1`` also ``velocities``
            and ``angular_velocities``; with ``order >= 2`` also ``accelerations`` and
            ``angular_accelerations``.

        Raises
        ------
        AssemblyError
            With ``strict=True``, naming the first input angle that cannot be assembled.
        ValueError
            For a linkage without a crank, a non-finite input or an `order` outside 0..2.

        Examples
        --------
        >>> import numpy as np
        >>> from mech.spherical import stephenson1
        >>> lk = stephenson1(0.3, 0.9, 0.7, 1.0, E=(0.2, 0.8), F=(0.3, -1.0), arcs=(0.8, 0.7), coupler=(0.4, 0.5))
        >>> pose = lk.solve(np.linspace(0.0, 1.0, 3), order=2)
        >>> pose.valid.tolist(), pose.accelerations["P"].shape
        ([True, True, True], (3, 3))
        """
        strict = bool_flag("strict", strict)
        if self._driver is None:
            raise ValueError("Expected a linkage with a crank before `solve`, got none (call `crank` first)")
        order, shape, inputs = motion_inputs("theta", theta, order, omega, alpha)
        th = inputs[0].reshape(-1)
        om = inputs[1].reshape(-1) if order >= 1 else None
        al = inputs[2].reshape(-1) if order >= 2 else None
        P, V, Acc, W, DW = self._blocks(th, om, al, order)
        assembled = np.all([np.isfinite(v).all(axis=-1) for v in P.values()], axis=0)
        valid = assembled.copy()
        for group in ((V, W) if order == 1 else (V, W, Acc, DW) if order == 2 else ()):
            for v in group.values():
                valid &= np.isfinite(v).all(axis=-1)
        if strict and not assembled.all():
            bad = float(th[np.argmin(assembled)])
            raise AssemblyError(f"Cannot assemble {self!r} at theta = {bad!r}")
        nan = np.where(assembled[:, None], 0.0, np.nan)
        ok = np.where(valid[:, None], 0.0, np.nan)

        def shaped(d, mask):
            return {k: (v + mask).reshape(shape + (3,)) for k, v in d.items()}

        fields = {"theta": inputs[0].copy(), "valid": valid.reshape(shape), "assembled": assembled.reshape(shape),
                  "points": shaped(P, nan)}
        if order >= 1:
            fields["velocities"] = shaped(V, ok)
            fields["angular_velocities"] = shaped({k: W[k] for k in self._links}, ok)
        if order >= 2:
            fields["accelerations"] = shaped(Acc, ok)
            fields["angular_accelerations"] = shaped({k: DW[k] for k in self._links}, ok)
        return SphericalLinkagePose(order, fields)

    def _blocks(self, th, om, al, order):
        """`_flat` and `_across_changes` over blocks of `_BLOCK` inputs, gathered.

        Each pose's results depend on its own inputs only, so a block gives the same bits
        as the whole array; solved whole, the hundred temporaries of a six-bar's rates
        over 10^6 inputs left the cache and the cost per pose grew with N.
        """
        n = th.size
        if n <= _BLOCK:
            fields = self._flat(th, om, al, order)
            self._across_changes(th, om, al, order, fields)
            return fields
        parts = []
        for start in range(0, n, _BLOCK):
            part = slice(start, start + _BLOCK)
            cut = [None if x is None else x[part] for x in (th, om, al)]
            fields = self._flat(*cut, order)
            self._across_changes(*cut, order, fields)
            parts.append(fields)
        return tuple({k: np.concatenate([p[i][k] for p in parts]) for k in parts[0][i]} for i in range(5))

    def _flat(self, th, om, al, order):
        """Points, velocities, accelerations and link rates at the flat inputs `th`."""
        n = th.size
        P, V, Acc, W, DW = {}, {}, {}, {GROUND: np.zeros((n, 3))}, {GROUND: np.zeros((n, 3))}
        zero = np.zeros((n, 3))
        changes = self._change_points()
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            k = 0
            for step in self._steps:
                kind = step[0]
                if kind == "ground":
                    _, name, v = step
                    P[name] = np.broadcast_to(v, (n, 3)).copy()
                    V[name], Acc[name] = zero, zero
                    continue
                if kind == "crank":
                    _, link, pivot, tip, a, ref = step
                    P[tip] = _stack(*_g.spherical_link_point(*_xyz(P[pivot]), *_xyz(P[ref]), a, th))
                    if order >= 1:
                        W[link] = om[:, None] * P[pivot]
                    if order >= 2:
                        DW[link] = al[:, None] * P[pivot]
                    self._rates(P, V, Acc, W, DW, tip, link, order)
                elif kind == "point":
                    _, name, link, r, g = step
                    o, x = self._links[link]
                    P[name] = _stack(*_g.spherical_link_point(*_xyz(P[o]), *_xyz(P[x]), r, g))
                    self._rates(P, V, Acc, W, DW, name, link, order)
                else:
                    _, (l1, l2), (p1, p2), j, (b1, b2), sign = step
                    P[j] = self._joint(P, step, th, changes, k)
                    k += 1
                    if order >= 1:
                        # a dead point (J on the great circle P1P2, det = 0): rates unbounded
                        det = np.einsum("ij,ij->i", np.cross(P[p1], P[p2]), P[j])
                        dead = np.where(np.abs(det) <= DEAD_POINT_RTOL, np.nan, 0.0)[:, None]
                        out = _g.spherical_dyad_velocity(*_xyz(P[p1]), *_xyz(V[p1]), *_xyz(P[p2]), *_xyz(V[p2]),
                                                         *_xyz(P[j]))
                        W[l1], W[l2] = _stack(*out[:3]) + dead, _stack(*out[3:]) + dead
                    if order >= 2:
                        out = _g.spherical_dyad_acceleration(*_xyz(P[p1]), *_xyz(Acc[p1]), *_xyz(P[p2]),
                                                             *_xyz(Acc[p2]), *_xyz(P[j]), *_xyz(W[l1]), *_xyz(W[l2]))
                        DW[l1], DW[l2] = _stack(*out[:3]), _stack(*out[3:])
                    self._rates(P, V, Acc, W, DW, j, l1, order)
        return P, V, Acc, W, DW

    def _across_changes(self, th, om, al, order, fields):
        """Replace the results within four samples of a change point by interpolation.

        There the dyad's equations lose digits (its rates are 0/0 at the point itself);
        each result is the degree-15 polynomial through 16 solutions on the same mode
        further away (8 on each side), rates scaled by omega and alpha as they enter.
        """
        period, points = self._change_points()
        cps = np.unique(np.concatenate(points)) if points else np.empty(0)
        if not cps.size:
            return
        w = 4 * 2 * np.pi / 2048
        d = np.mod(th, period)[:, None] - cps[None, :]
        d = np.mod(d + period / 2, period) - period / 2
        nearest = np.argmin(np.abs(d), axis=1)
        dist = d[np.arange(th.size), nearest]
        near = np.abs(dist) < w
        if not near.any():
            return
        centre = th - dist
        nodes_x = np.concatenate((-(w + 0.5 * w * np.arange(8))[::-1], w + 0.5 * w * np.arange(8)))
        P, V, Acc, W, DW = fields
        for c in np.unique(np.round(centre[near], 12)):
            idx = np.flatnonzero(near & (np.abs(centre - c) < 1e-9))
            t0 = centre[idx[0]]
            nodes = t0 + nodes_x
            ones, zeros = np.ones(16), np.zeros(16)
            r1 = self._flat(nodes, ones, zeros, order)
            r2 = self._flat(nodes, zeros, ones, order) if order >= 2 else None
            x = (th[idx] - t0) / w

            def fit(values):
                coef = np.polynomial.polynomial.polyfit(nodes_x / w, values, 15)
                return np.polynomial.polynomial.polyval(x, coef).T

            for name in P:
                P[name] = np.array(P[name], dtype=float)
                P[name][idx] = fit(r1[0][name])
            if order >= 1:
                for d_out, d_in in ((V, r1[1]), (W, r1[3])):
                    for name in d_out:
                        d_out[name] = np.array(d_out[name], dtype=float)
                        d_out[name][idx] = fit(d_in[name]) * om[idx, None]
            if order >= 2:
                for d_out, i in ((Acc, 2), (DW, 4)):
                    for name in d_out:
                        d_out[name] = np.array(d_out[name], dtype=float)
                        d_out[name][idx] = (fit(r1[i][name]) * om[idx, None] ** 2 + fit(r2[i][name]) * al[idx, None])

    # ------------------------------------------------------------------ change points
    @staticmethod
    def _radicand(P, step):
        _, _, (p1, p2), _, (b1, b2), _ = step
        return _g.spherical_dyad_radicand(*_xyz(P[p1]), *_xyz(P[p2]), b1, b2)

    @staticmethod
    def _joint(P, step, th, changes, k):
        """The joint of the k-th dyad, its sign flipped once per change point passed."""
        _, _, (p1, p2), _, (b1, b2), sign = step
        rho = _g.spherical_dyad_radicand(*_xyz(P[p1]), *_xyz(P[p2]), b1, b2)
        sigma = np.full(th.shape, float(sign))
        period, points = changes
        if k < len(points) and points[k].size:
            phase = np.mod(th, period)
            passed = np.searchsorted(points[k], phase, side="right") - np.searchsorted(points[k], 0.0, side="right")
            sigma = np.where(passed % 2 == 1, -sigma, sigma)
            # where the branches meet the radicand is zero up to rounding
            rho = np.where(rho >= -_CHANGE_TOL, np.maximum(rho, 0.0), rho)
        return _stack(*_g.spherical_dyad_position(*_xyz(P[p1]), *_xyz(P[p2]), b1, b2, sigma, rho))

    def _radicand_of(self, th, changes, upto):
        """The radicand of dyad `upto` at the inputs `th`, upstream dyads on their modes."""
        n = th.size
        P = {}
        k = 0
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            for step in self._steps:
                kind = step[0]
                if kind == "ground":
                    P[step[1]] = np.broadcast_to(step[2], (n, 3)).copy()
                elif kind == "crank":
                    _, link, pivot, tip, a, ref = step
                    P[tip] = _stack(*_g.spherical_link_point(*_xyz(P[pivot]), *_xyz(P[ref]), a, th))
                elif kind == "point":
                    _, name, link, r, g = step
                    o, x = self._links[link]
                    P[name] = _stack(*_g.spherical_link_point(*_xyz(P[o]), *_xyz(P[x]), r, g))
                else:
                    if k == upto:
                        return self._radicand(P, step)
                    P[step[3]] = self._joint(P, step, th, changes, k)
                    k += 1
        raise AssertionError("no such dyad")

    def _change_points(self):
        """Input angles where a dyad's branches meet and part again, found once per linkage.

        Returns ``(period, points)``: the period of the whole motion (2 pi times a power of
        two) and, per dyad, the sorted change points in [0, period). Each dyad's radicand
        is sampled (2048 samples per turn) with the dyads before it on their modes; a local
        minimum that stays non-negative and reaches zero within `_CHANGE_TOL` (refined by
        golden-section search) is a change point. An odd count per turn doubles the period.
        """
        cached = self.__dict__.get("_changes")
        if cached is not None:
            return cached
        n_dyads = sum(1 for s in self._steps if s[0] == "rrr")
        period, points = 2 * np.pi, []
        golden = (np.sqrt(5.0) - 1.0) / 2.0
        for k in range(n_dyads):
            m = int(round(2048 * period / (2 * np.pi)))
            grid = np.arange(m) * (period / m)
            rho = self._radicand_of(grid, (period, points), k)
            # the radicand scales with the arcs (about their fourth power on a small cap):
            # a change point is a zero relative to its own size over the turn, so a small
            # linkage whose branches never meet is not given change points
            size = float(np.nanmax(np.abs(rho))) if np.any(np.isfinite(rho)) else 1.0
            size = size if size > 0.0 else 1.0
            left, right = np.roll(rho, 1), np.roll(rho, -1)
            candidates = np.flatnonzero((rho <= left) & (rho <= right) & (left > 0) & (right > 0)
                                        & (rho >= -_CHANGE_TOL * size) & (rho < 1e-2 * size))
            found = []
            for i in candidates:
                lo, hi = grid[i] - period / m, grid[i] + period / m
                f = lambda t: float(self._radicand_of(np.array([t]), (period, points), k)[0])  # noqa: E731
                x1, x2 = hi - golden * (hi - lo), lo + golden * (hi - lo)
                f1, f2 = f(x1), f(x2)
                for _ in range(80):
                    if f1 <= f2:
                        hi, x2, f2 = x2, x1, f1
                        x1 = hi - golden * (hi - lo)
                        f1 = f(x1)
                    else:
                        lo, x1, f1 = x1, x2, f2
                        x2 = lo + golden * (hi - lo)
                        f2 = f(x2)
                t, v = (x1, f1) if f1 <= f2 else (x2, f2)
                if abs(v) <= _CHANGE_TOL * size:
                    # the minimum of rho is flat (rho ~ c (t - t0)^2); the signed root
                    # +-sqrt(rho) is smooth through t0, so fit it across and take its zero
                    x = np.array([-3.0, -2.0, -1.0, 1.0, 2.0, 3.0]) * 1e-3
                    r = self._radicand_of(t + x, (period, points), k)
                    y = np.sign(x) * np.sqrt(np.maximum(r, 0.0))
                    c = np.polyfit(x, y, 5)
                    z = 0.0
                    for _ in range(8):
                        z -= np.polyval(c, z) / np.polyval(np.polyder(c), z)
                    t = t + z if abs(z) < 1e-3 else t
                    t = float(np.mod(t, period))
                    # a change point at theta = 0 (within its location's precision) is at 0:
                    # `branch` names the mode just after it
                    found.append(0.0 if min(t, period - t) < 1e-9 else t)
            if len(found) % 2 == 1:
                points = [np.concatenate((c, c + period)) for c in points]
                found = found + [t + period for t in found]
                period *= 2
            points.append(np.sort(np.array(found, dtype=float)))
        self.__dict__["_changes"] = (period, points)
        return self._changes

    @staticmethod
    def _rates(P, V, Acc, W, DW, name, link, order):
        if order >= 1:
            V[name] = np.cross(W[link], P[name])
        if order >= 2:
            Acc[name] = np.cross(DW[link], P[name]) + np.cross(W[link], V[name])

    def coupler_curve(self, theta, point="P", order=0, omega=1.0, alpha=0.0):
        """The path of `point` with the input angle as parameter (monograph §2.4).

        Returns ``(P, valid)`` for ``order=0``, ``(P, v, valid)`` for ``order=1`` and
        ``(P, v, a, valid)`` for ``order=2``: arrays of shape ``theta.shape + (3,)``
        (NaN where it cannot assemble) and the mask. See `solve` for the arguments.

        Examples
        --------
        >>> import numpy as np
        >>> from mech.spherical import watt1
        >>> lk = watt1(0.3, 0.9, 0.7, 1.0, E=(0.5, 0.6), F=(0.4, 0.9), arcs=(0.7, 0.8), coupler=(0.3, 0.4))
        >>> P, valid = lk.coupler_curve(np.linspace(0, 2 * np.pi, 7))
        >>> P.shape, bool(valid.all())
        ((7, 3), True)
        """
        if not isinstance(point, str) or point not in self._points:
            raise ValueError(f"Expected `point` to be a known point, got {point!r} (known points: {', '.join(self._points)})")
        pose = self.solve(theta, order=order, omega=omega, alpha=alpha)
        out = [pose.points[point]]
        if order >= 1:
            out.append(pose.velocities[point])
        if order >= 2:
            out.append(pose.accelerations[point])
        return (*out, pose.valid)
