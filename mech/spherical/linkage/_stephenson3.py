"""The Stephenson-3 spherical six-bar (monograph chapter 4): the inversion of the Stephenson
chain that fixes a binary link of its two-link path, solved by continuation of a triad.

The Stephenson chain has two ternary links that are not adjacent, joined by three paths: two
of one binary link each and one of two binary links. Fixing a binary link of a one-link path
gives the Stephenson-1 (`stephenson1`), fixing a ternary link the Stephenson-2
(`stephenson2`); fixing a binary link of the two-link path gives the Stephenson-3, built
here. Its ground AD holds two pivots:

- the input crank ABE (ternary) turns about A;
- the binary link DH turns about D;
- the floating ternary link CGH (the guided link) is pinned to the crank through the binary
  links BC and EG and to DH at H.

The crank fixes B and E; the links BC, EG, DH and CGH then form a triad (a class-III group):
no dyad can be solved first, so `SphericalLinkage` (a crank and RRR dyads) cannot move it.
The orientation Q of CGH is found from the three constant arcs

    (B . C) = cos b,    (E . G) = cos e,    (D . H) = cos c,    C, G, H = Q C0, Q G0, Q H0,

by Newton's method on Q (eq. (13) of :ref:`deriv-spherical-guidance-sixbar`), continued in
small steps from the assembly, so a solution stays on the assembly's branch and never jumps.
"""

from __future__ import annotations

import numpy as np

from mech._errors import AssemblyError, InputTypeError
from mech._validate import _show, bool_flag, finite_array, unit_vector
from mech.spherical.linkage._linkage import SphericalLinkagePose

__all__ = ["SphericalStephenson3"]

_NAMES = ("A", "D", "B", "E", "C", "G", "H")
#: largest step of the continuation in the input angle, radians
_STEP = 0.05
#: the closure is solved to this (cosines of the arcs)
_CLOSE = 1e-15
#: crank turns searched for the period of a branch that does not stop at a dead point
_TURNS = 4


def _cx(a, b):
    """Cross product of two 3-vectors (np.cross is slow on single vectors)."""
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


def _rodrigues(axis, angle):
    k = np.asarray(axis, float)
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) + np.sin(angle) * K + (1.0 - np.cos(angle)) * (K @ K)


def _expmap(w):
    t = float(np.linalg.norm(w))
    return np.eye(3) if t == 0.0 else _rodrigues(w / t, t)


def _signed_angle(a, b, c):
    u, w = _cx(a, b), _cx(a, c)
    return float(np.arctan2(np.dot(a, _cx(u, w)), np.dot(u, w)))


class SphericalStephenson3:
    """The Stephenson-3 spherical six-bar, moved from one assembled pose.

    Parameters
    ----------
    points : mapping of str to array_like (3,)
        Unit vectors of the joints in one assembled pose: the ground pivots A (input) and D,
        the crank's joints B and E (the crank ABE turns about A), and the joints C, G, H of
        the guided link CGH (BC, EG and DH are binary links). The arcs of every link are
        read from them.
    coupler : array_like (3,), optional
        A point P of the guided link in the same pose (default: none).

    Attributes
    ----------
    theta0 : float
        Input angle of the given pose: the angle at A from the great circle A -> D to
        A -> B, counter-clockwise seen from outside.
    arcs : dict of str -> float
        AB, AE, BE, BC, EG, DH, CG, CH, GH and AD, radians.

    Notes
    -----
    Derivation: :ref:`deriv-spherical-guidance-sixbar`, eqs. (13)-(14). `solve` continues the
    motion from `theta0` to each input in steps of at most 0.05 rad, predicting the guided
    link's turn from the rate equation (14) and correcting it with Newton's method on the
    three arc conditions (13) (a 3 x 3 solve per step, to 1e-15 in the cosines). The branch
    is the assembly's: the determinant of (14) keeps its sign along it; where it would
    change sign the triad is at a dead point (two assemblies meet, the input cannot pass),
    and every input beyond it is NaN (``valid`` False), never the other assembly. A branch
    with no dead point is followed until it is back at the assembly (its period, a whole
    number of crank turns up to four) and inputs further away are reduced by the period;
    one that does not return within four turns is NaN beyond them.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import stephenson3
    >>> lk = stephenson3(0.35, 0.9, 0.8, 1.1, E=(0.5, 0.7), arcs=(0.9, 0.6), H=(0.55, -0.6),
    ...                  coupler=(0.3, 0.4), mu=0.8)
    >>> pose = lk.solve(np.linspace(0.0, 1.0, 5))
    >>> bool(pose.valid.all()), lk.closure(pose) < 1e-12
    (True, True)
    """

    def __init__(self, points, *, coupler=None):
        if not hasattr(points, "items"):
            raise InputTypeError(f"Expected `points` to be a mapping of the joints A, D, B, E, C, G, H, got {points!r}")
        missing = [k for k in _NAMES if k not in points]
        if missing:
            raise ValueError(f"Expected `points` with the joints A, D, B, E, C, G, H, got {sorted(points)!r} "
                             f"(missing {', '.join(missing)})")
        p = {k: unit_vector(f"points[{k!r}]", points[k]) for k in _NAMES}
        if coupler is not None:
            p["P"] = unit_vector("coupler", coupler)
        for a, b in (("A", "B"), ("A", "D"), ("B", "C"), ("E", "G"), ("D", "H"), ("C", "G"), ("A", "E"),
                     ("B", "E")):
            if np.linalg.norm(np.cross(p[a], p[b])) < 1e-9:
                raise ValueError(f"Expected `points` {a} and {b} apart and not antipodal (a link of zero or "
                                 f"half-turn arc), got {a} = {p[a].tolist()!r}, {b} = {p[b].tolist()!r}")
        self._p = p
        self.theta0 = _signed_angle(p["A"], p["D"], p["B"])
        arc = lambda a, b: float(np.arctan2(np.linalg.norm(np.cross(p[a], p[b])), np.dot(p[a], p[b])))  # noqa: E731
        self.arcs = {a + b: arc(a, b) for a, b in (("A", "B"), ("A", "E"), ("B", "E"), ("B", "C"), ("E", "G"),
                                                   ("D", "H"), ("C", "G"), ("C", "H"), ("G", "H"), ("A", "D"))}
        self._cos = np.array([p["B"] @ p["C"], p["E"] @ p["G"], p["D"] @ p["H"]])
        self._sign = np.sign(np.linalg.det(self._jacobian(np.eye(3), 0.0)))

    @property
    def points(self):
        """Names of the points (ground A, D; crank B, E; guided link C, G, H; and P)."""
        return tuple(self._p)

    @property
    def assembly(self):
        """The joints of the given pose (at `theta0`): point name -> unit vector (a copy)."""
        return {k: v.copy() for k, v in self._p.items()}

    @property
    def members(self):
        """The points of every link, a mapping from link name to a tuple of point names."""
        guided = ("C", "G", "H", "P") if "P" in self._p else ("C", "G", "H")
        return {"ground": ("A", "D"), "ABE": ("A", "B", "E"), "BC": ("B", "C"), "EG": ("E", "G"),
                "DH": ("D", "H"), "CGH": guided}

    def __repr__(self):
        return f"SphericalStephenson3(arcs={ {k: round(v, 6) for k, v in self.arcs.items()} })"

    # ------------------------------------------------------------------ the triad
    def _crank(self, turn):
        """B and E after the crank turns by `turn` about A (Rodrigues on the two vectors)."""
        cached = self.__dict__.get("_last_turn")
        if cached is not None and cached[0] == turn:
            return cached[1]
        A, c, s = self._p["A"], np.cos(turn), np.sin(turn)
        out = tuple(p * c + _cx(A, p) * s + A * ((A @ p) * (1.0 - c)) for p in (self._p["B"], self._p["E"]))
        self.__dict__["_last_turn"] = (turn, out)
        return out

    def _residual(self, Q, turn):
        B, E = self._crank(turn)
        p = self._p
        return np.array([B @ (Q @ p["C"]), E @ (Q @ p["G"]), p["D"] @ (Q @ p["H"])]) - self._cos

    def _jacobian(self, Q, turn):
        """Rows d/dw of the three closures for Q -> exp(w) Q: (Q y) x X, eq. (14)."""
        B, E = self._crank(turn)
        p = self._p
        return np.array([_cx(Q @ p["C"], B), _cx(Q @ p["G"], E), _cx(Q @ p["H"], p["D"])])

    def _theta_rate(self, Q, turn):
        """d/dtheta of the closures at fixed Q: the crank turns about A."""
        B, E = self._crank(turn)
        A, p = self._p["A"], self._p
        return np.array([_cx(A, B) @ (Q @ p["C"]), _cx(A, E) @ (Q @ p["G"]), 0.0])

    def _correct(self, Q, turn):
        for _ in range(12):
            r = self._residual(Q, turn)
            if np.max(np.abs(r)) <= _CLOSE:
                break
            J = self._jacobian(Q, turn)
            try:
                w = np.linalg.solve(J, -r)
            except np.linalg.LinAlgError:
                return None
            step = np.linalg.norm(w)
            if step > 0.3:
                return None
            Q = _expmap(w) @ Q
            if step < 1e-15:
                break
        if np.max(np.abs(self._residual(Q, turn))) > 1e-12:
            return None
        if np.sign(np.linalg.det(self._jacobian(Q, turn))) != self._sign:
            return None
        return Q

    def _march(self, turns):
        """Guided-link rotations Q at the sorted crank turns (one direction from 0)."""
        out = []
        Q, t = np.eye(3), 0.0
        for target in turns:
            while Q is not None and t != target:
                h = float(np.clip(target - t, -_STEP, _STEP))
                while True:
                    w = -np.linalg.solve(self._jacobian(Q, t), self._theta_rate(Q, t))
                    Qn = self._correct(_expmap(w * h) @ Q, t + h)
                    if Qn is not None:
                        Q, t = Qn, t + h
                        break
                    h /= 2.0
                    if abs(h) < 1e-7:
                        Q = None
                        break
            out.append(None if Q is None else Q.copy())
        return out

    def _period(self):
        """The turn of the crank after which the branch is back at the assembly (2 pi k for
        the first k <= _TURNS that closes), or None (a dead point first, or no return)."""
        if "_period_found" not in self.__dict__:
            found = None
            marks = 2.0 * np.pi * np.arange(1, _TURNS + 1)
            for k, Q in enumerate(self._march(marks)):
                if Q is None:
                    break
                if np.abs(Q - np.eye(3)).max() < 1e-9:
                    found = float(marks[k])
                    break
            self.__dict__["_period_found"] = found
        return self.__dict__["_period_found"]

    def rotations(self, theta):
        """Rotation Q of the guided link CGH from the given pose at input angles `theta`.

        Parameters
        ----------
        theta : array_like, shape (...)
            Input angles (as `theta0`), radians.

        Returns
        -------
        ndarray, shape (..., 3, 3)
            Q with ``C(theta) = Q @ C(theta0)`` and likewise for G, H and P; NaN beyond a
            dead point of the triad.

        Examples
        --------
        >>> import numpy as np
        >>> from mech.spherical import stephenson3
        >>> lk = stephenson3(0.35, 0.9, 0.8, 1.1, E=(0.5, 0.7), arcs=(0.9, 0.6), H=(0.55, -0.6),
        ...                  coupler=(0.3, 0.4), mu=0.8)
        >>> np.allclose(lk.rotations(lk.theta0), np.eye(3))
        True
        """
        theta = finite_array("theta", theta)
        return self._rotations(self._turns(theta)).reshape(theta.shape + (3, 3))

    def _turns(self, theta):
        """The crank's turns from the assembly, reduced by the period where one is needed."""
        flat = theta.reshape(-1) - self.theta0
        if np.any(np.abs(flat) > 2.0 * np.pi):
            period = self._period()
            if period is not None:
                flat = np.mod(flat, period)
            else:
                # not back at the assembly within _TURNS turns: no input that far is solved
                flat = np.where(np.abs(flat) > 2.0 * np.pi * _TURNS, np.nan, flat)
        return flat

    def _rotations(self, flat):
        Q = np.full((flat.size, 3, 3), np.nan)
        with np.errstate(all="ignore"):
            for side in (flat >= 0, flat < 0):          # NaN (beyond _TURNS turns) in neither
                idx = np.flatnonzero(side)
                order = idx[np.argsort(np.abs(flat[idx]))]
                for i, q in zip(order, self._march(flat[order])):
                    if q is not None:
                        Q[i] = q
        return Q

    def orientations(self, theta):
        """Orientation of the guided link CGH at the input angles `theta`.

        The frame ``[C, t, C x t]`` with t the unit tangent at C of the great circle C -> G
        (as `sixbar_orientations` for the link EG of the other six-bars); NaN beyond a dead
        point of the branch.

        Parameters
        ----------
        theta : array_like, shape (...)
            Input angles, radians.

        Returns
        -------
        ndarray, shape (..., 3, 3)

        Examples
        --------
        >>> import numpy as np
        >>> from mech.spherical import stephenson3
        >>> lk = stephenson3(0.35, 0.9, 0.8, 1.1, E=(0.5, 0.7), arcs=(0.9, 0.6), H=(0.55, -0.6),
        ...                  coupler=(0.3, 0.4), mu=0.8)
        >>> R = lk.orientations([0.0, 0.5])
        >>> bool(np.allclose(R[1].T @ R[1], np.eye(3))), round(float(np.linalg.det(R[0])), 12)
        (True, 1.0)
        """
        Q = self.rotations(theta)
        C, G = self._p["C"], self._p["G"]
        t = G - (C @ G) * C
        t = t / np.linalg.norm(t)
        return Q @ np.stack([C, t, _cx(C, t)], axis=-1)

    def solve(self, theta, strict=False):
        """Positions of every point at the input angles `theta` (order 0).

        Parameters
        ----------
        theta : array_like, shape (...)
            Input angles, radians (measured as `theta0`).
        strict : bool, optional
            Raise `AssemblyError` naming the first input beyond a dead point of the branch.

        Returns
        -------
        SphericalLinkagePose
            ``theta, valid, assembled, points`` (A, D, B, E, C, G, H and P).

        Examples
        --------
        >>> import numpy as np
        >>> from mech.spherical import stephenson3
        >>> lk = stephenson3(0.35, 0.9, 0.8, 1.1, E=(0.5, 0.7), arcs=(0.9, 0.6), H=(0.55, -0.6),
        ...                  coupler=(0.3, 0.4), mu=0.8)
        >>> lk.solve([0.0, 0.5]).points["H"].shape
        (2, 3)
        """
        strict = bool_flag("strict", strict)
        theta = finite_array("theta", theta)
        turn = self._turns(theta)
        Q = self._rotations(turn).reshape(theta.shape + (3, 3))
        ok = np.isfinite(Q).all(axis=(-2, -1))
        if strict and not ok.all():
            bad = float(theta.reshape(-1)[np.argmin(ok.reshape(-1))])
            raise AssemblyError(f"Cannot reach theta = {bad!r} from the assembly at theta0 = {self.theta0!r} "
                                f"on its branch of {self!r}")
        p = self._p
        K = np.stack([_rodrigues(p["A"], t) for t in np.nan_to_num(turn)]).reshape(theta.shape + (3, 3))
        nan = np.where(ok[..., None], 0.0, np.nan)
        pts = {k: np.broadcast_to(p[k], theta.shape + (3,)) + nan for k in ("A", "D")}
        for k in ("B", "E"):
            pts[k] = np.einsum("...ij,j->...i", K, p[k]) + nan
        for k in ("C", "G", "H", "P"):
            if k in p:
                pts[k] = np.einsum("...ij,j->...i", Q, p[k])
        return SphericalLinkagePose(0, {"theta": theta.copy(), "valid": ok, "assembled": ok, "points": pts})

    def closure(self, pose):
        """Largest error (radians) of the six link arcs over a `solve` result's valid poses.

        Examples
        --------
        >>> import numpy as np
        >>> from mech.spherical import stephenson3
        >>> lk = stephenson3(0.35, 0.9, 0.8, 1.1, E=(0.5, 0.7), arcs=(0.9, 0.6), H=(0.55, -0.6),
        ...                  coupler=(0.3, 0.4), mu=0.8)
        >>> lk.closure(lk.solve(np.linspace(-0.5, 0.5, 11))) < 1e-12
        True
        """
        if not isinstance(pose, SphericalLinkagePose):
            raise InputTypeError(f"Expected `pose` to be the result of `solve`, got {_show(pose)}")
        P = pose.points
        v = np.asarray(pose.valid)
        worst = 0.0
        for a, b in (("A", "B"), ("B", "C"), ("E", "G"), ("D", "H"), ("C", "G"), ("C", "H"), ("G", "H"),
                     ("A", "E"), ("B", "E")):
            x, y = P[a][v], P[b][v]
            got = np.arctan2(np.linalg.norm(np.cross(x, y), axis=-1), np.sum(x * y, axis=-1))
            if got.size:
                worst = max(worst, float(np.max(np.abs(got - self.arcs[a + b]))))
        return worst
