"""Optimal design of a Watt-2 guidance six-bar for more than five orientations with
prescribed input angles (the spherical monograph, chapter 4, with the model of §1.9).

The objective is the orientation error of `optimal_guidance`: the linkage is analysed by
`SphericalLinkage` at every prescribed input angle and the guided link's orientation is
compared with the task's, so the result has no branch or order defect by construction.
The start is an exact design of five of the orientations (`guidance_watt2`). SciPy is
imported lazily.
"""

from dataclasses import dataclass

import numpy as np

from mech._geometry import cross3 as _cross
from mech._validate import InputTypeError, _show, finite_array, integer, nonnegative_number
from mech.spherical._rigid_body import angle_at
from mech.spherical.guidance._fourbar import _rotation_gap
from mech.spherical.guidance._optimal import _point, _tangents
from mech.spherical.guidance._orientations import orientation_set
from mech.spherical.guidance._sixbar import SphericalGuidanceSixBar, _build, _frame
from mech.spherical.linkage._linkage import SphericalLinkage

__all__ = ["SphericalOptimalSixBar", "optimal_guidance_watt2"]

_NAMES = ("A", "D", "F", "B", "C", "E", "G")
#: the dyads' joints are kept this far (sin of the arc) from the great circle of their pins
_HEIGHT = 0.05
#: inputs between the first and last prescribed angle where that is enforced
_GUARD = 64
#: the optimiser's cap of residual evaluations (finite differences included)
_MAX_NFEV = 4000
#: the optimiser stops when a step changes the cost or the variables by less than this (relative)
_TOL = 1e-8
#: relative step of the forward differences (about the square root of the machine epsilon)
_FD_STEP = 1.5e-8


@dataclass(frozen=True)
class SphericalOptimalSixBar:
    """Result of `optimal_guidance_watt2` and `optimal_guidance_sixbar`.

    Attributes
    ----------
    linkage : SphericalLinkage
        The six-bar (points as in `SphericalGuidanceSixBar`); the guided link is EG.
    input_offset : float
        The linkage's input angle is ``theta_j + input_offset`` at orientation j.
    points : dict of str -> ndarray, shape (3,)
        A, B, C, D, E, F, G in the assembly the linkage was built from.
    body : ndarray, shape (3, 3)
        The guided body's axes in the frame of EG: the orientation reached is
        ``F(theta) @ body`` with F the frame of `sixbar_orientations`.
    errors : ndarray, shape (n,)
        Orientation error (radians) at each prescribed input angle, by analysis.
    rms_error, pose_error : float
        Root mean square and largest of `errors`.
    in_order : bool
        The linkage assembles at every input from the first prescribed angle to the last.
    passes : bool
        ``in_order`` and ``pose_error <= rtol``.
    nfev : int
        Residual evaluations of the optimiser (not counting its forward-difference
        Jacobians, each one batched evaluation of the 17 designs it needs).
    converged : bool
        The optimiser stopped on its tolerance (a stationary point), not on its cap of
        evaluations.
    kind : str
        The six-bar's type: ``"watt2"``, or the start's type for `optimal_guidance_sixbar`.
    """

    linkage: SphericalLinkage
    input_offset: float
    points: dict
    body: np.ndarray
    errors: np.ndarray
    rms_error: float
    pose_error: float
    in_order: bool
    passes: bool
    nfev: int
    converged: bool = True
    kind: str = "watt2"

    def guided_orientations(self, theta):
        """Orientation R of the guided body (task frame) at task input angles `theta`."""
        theta = finite_array("theta", theta)
        pose = self.linkage.solve(theta + self.input_offset)
        with np.errstate(invalid="ignore"):
            return _frame(pose.points["E"], pose.points["G"]) @ self.body


def _rotvec(w):
    """Rotation matrix of the rotation vector w (Rodrigues)."""
    t = float(np.linalg.norm(w))
    if t == 0.0:
        return np.eye(3)
    k = w / t
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) + np.sin(t) * K + (1.0 - np.cos(t)) * (K @ K)


def _joint(P1, P2, c1, c2, sign):
    """The point J with J.P1 = c1, J.P2 = c2 on the side `sign` of P1 -> P2, eq. (5)."""
    g = np.sum(P1 * P2, axis=-1)
    n = _cross(P1, P2)
    nn = np.sum(n * n, axis=-1)
    al = (c1 - g * c2) / nn
    be = (c2 - g * c1) / nn
    inside = 1.0 - (al * al + be * be + 2.0 * al * be * g)
    with np.errstate(invalid="ignore"):
        ga = sign * np.sqrt(inside / nn)
    return al[..., None] * P1 + be[..., None] * P2 + ga[..., None] * n


def _turn(p, axis, angle):
    """Rodrigues: p turned by `angle` about the unit `axis`, counter-clockwise (broadcast)."""
    c, s = np.cos(angle)[..., None], np.sin(angle)[..., None]
    return p * c + _cross(axis, p) * s + axis * np.sum(axis * p, axis=-1, keepdims=True) * (1.0 - c)


def _heights(P1, P2, J):
    """sin of the arc from the joint J to the great circle through its pins P1, P2 (0 at a
    dead point of the dyad, where its two assemblies meet)."""
    n = _cross(P1, P2)
    return np.abs(np.sum(n * J, axis=-1)) / np.linalg.norm(n, axis=-1)


def _guided_frames(pts, branches, turn, heights=False):
    """Frames of EG after the crank turns by `turn` from the assembly `pts` (closed form);
    with ``heights=True`` also the dyads' `_heights` at every turn. The points may be
    batches of shape (k, 1, 3) (k designs at once, for the Jacobian): then the frames have
    shape (k, m, 3, 3)."""
    A, D, F, B0, C0, E0, G0 = (pts[k] for k in _NAMES)

    def dot(p, q):
        return np.sum(p * q, axis=-1)

    B = _turn(B0, A, turn)
    Ds = np.broadcast_to(D, B.shape)
    C = _joint(B, Ds, dot(B0, C0), dot(D, C0), branches[0])
    u, w = _cross(D, C0), _cross(D, C)                       # the rocker's turn about D
    E = _turn(E0, D, np.arctan2(dot(_cross(u, w), D), dot(w, u)))
    Fs = np.broadcast_to(F, E.shape)
    G = _joint(E, Fs, dot(E0, G0), dot(F, G0), branches[1])
    with np.errstate(invalid="ignore"):
        t = G - np.sum(E * G, axis=-1, keepdims=True) * E
        t = t / np.linalg.norm(t, axis=-1, keepdims=True)
        frames = np.stack([E, t, _cross(E, t)], axis=-1)             # _frame(E, G)
        if not heights:
            return frames
        return frames, np.stack([_heights(B, Ds, C), _heights(E, Fs, G)])


def _optimal_task(R, theta, rtol, sweep):
    """The checks every optimal six-bar design makes of its task: at least five distinct
    orientations, one input angle each, strictly increasing within a turn; `rtol` >= 0 and
    `sweep` >= 2. Returns them as arrays and numbers."""
    R = orientation_set("R", R, task=True)
    n = R.shape[0]
    if n < 5:
        raise ValueError(f"Expected at least 5 orientations in `R`, got {n}")
    theta = finite_array("theta", theta)
    if theta.shape != (n,):
        raise ValueError(f"Expected `theta` of shape ({n},) (one input angle per orientation), got shape {theta.shape}")
    if not (np.all(np.diff(theta) > 0) and theta[-1] - theta[0] < 2.0 * np.pi):
        raise ValueError(f"Expected `theta` strictly increasing and spanning less than a turn, got {theta.tolist()!r}")
    return R, theta, nonnegative_number("rtol", rtol), integer("sweep", sweep, minimum=2)


def optimal_guidance_watt2(R, theta, start, *, rtol=1e-2, sweep=721):
    """The Watt-2 six-bar nearest (least squares in orientation) to n > 5 orientations.

    Variables (the optimal-design model of §1.9): the seven joints A, D, F, B, C, E, G of
    the assembly the linkage is built from (two tangent coordinates each, but A only along
    the great circle A -> D: turning the loop A-B-C about D changes nothing) and the body's
    axes relative to the frame of EG (a rotation vector): 16 numbers; the crank turns by
    the start's amount from that assembly to the first orientation (moving the assembly
    covers a change of the input offset). Objective: the sum over the orientations of
    ``|F_j body - R_j|^2`` (Frobenius) with F_j the frame of EG at the prescribed input,
    eq. (6) of :ref:`deriv-spherical-guidance-sixbar`, solved in closed form on the
    start's branches (eq. (5)); where it cannot assemble the residual is the largest
    possible. Constraint, eq. (6a): on 64 inputs from the first prescribed angle to the
    last each dyad's joint stays at least 0.05 (sine of the arc) from the great circle
    through its pins, so the optimum keeps clear of dead points and stays in order.
    Minimised by `scipy.optimize.least_squares` (Levenberg-Marquardt with forward
    differences) to a stationary point (`converged`); the errors returned are measured
    again with `SphericalLinkage`.

    Parameters
    ----------
    R : array_like, shape (n, 3, 3)
        Orientations of the guided body, n >= 5.
    theta : array_like, shape (n,)
        Prescribed input angles, strictly increasing, spanning less than a turn.
    start : SphericalGuidanceSixBar or SphericalOptimalSixBar
        A starting design, for example `guidance_watt2` of five of the orientations.
    rtol : float, optional
        The stated error: the result ``passes`` when its largest orientation error is at
        most `rtol` (radians) and it is in order; it is returned either way.
    sweep : int, optional
        Inputs sampled from the first prescribed angle to the last for the order check.

    Returns
    -------
    SphericalOptimalSixBar

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import guidance_watt2, optimal_guidance_watt2, sixbar_orientations, watt2
    >>> lk = watt2(0.3, 0.9, 0.7, 1.0, E=(0.3, 0.5), F=(1.4, 0.4), arcs=(0.6, 0.5), coupler=(0.3, 0.4))
    >>> theta = np.linspace(0.2, 2.6, 8)
    >>> R = sixbar_orientations(lk, theta)
    >>> R[3] = R[3] @ np.array([[1, 0, 0], [0, np.cos(0.01), -np.sin(0.01)], [0, np.sin(0.01), np.cos(0.01)]])
    >>> five = [0, 2, 4, 5, 7]
    >>> start = [d for d in guidance_watt2(R[five], theta[five], [0.3, -0.2, 0.93]) if d.passes][0]
    >>> best = optimal_guidance_watt2(R, theta, start)
    >>> best.passes, bool(best.pose_error < 0.01)
    (True, True)
    """
    R, theta, rtol, sweep = _optimal_task(R, theta, rtol, sweep)
    if not isinstance(start, (SphericalGuidanceSixBar, SphericalOptimalSixBar)):
        raise InputTypeError(f"Expected `start` to be a SphericalGuidanceSixBar or SphericalOptimalSixBar, "
                             f"got {_show(start)}")
    n = R.shape[0]
    from scipy.optimize import least_squares

    P0 = {k: np.asarray(v, float) for k, v in start.points.items()}
    p0 = start.linkage.solve(start.input_offset + theta[:1]).points
    F0 = _frame(p0["E"][0], p0["G"][0])
    if isinstance(start, SphericalOptimalSixBar):
        body0 = start.body
    else:
        body0 = F0.T @ start.guided_orientations(theta[:1])[0]
    branches = tuple(s[-1] for s in start.linkage._steps if s[0] == "rrr")
    T = {k: _tangents(P0[k]) for k in _NAMES}
    # turning the loop A-B-C about D leaves the motion unchanged (the input is measured from
    # A -> D, the rocker's turn relative to C): A moves along the great circle A -> D only
    tA = P0["D"] - np.dot(P0["A"], P0["D"]) * P0["A"]
    T["A"] = np.stack([tA / np.linalg.norm(tA), np.zeros(3)])
    # the input offset is carried as a shift from the assembly's own angle at A
    shift0 = float(start.input_offset) - (float(angle_at(P0["A"], P0["D"], P0["B"])) - float(theta[0]))
    guard = np.linspace(theta[0], theta[-1], _GUARD) - theta[0] + shift0

    def unpack(x):
        xa = np.concatenate(([x[0], 0.0], x[1:13]))
        pts = {k: _point(P0[k], T[k], xa[2 * i:2 * i + 2]) for i, k in enumerate(_NAMES)}
        body = body0 @ _rotvec(x[13:16])
        return pts, body, shift0

    def model(x):
        pts, body, shift = unpack(x)
        lk, built = _build(pts["A"], pts["D"], pts["F"], pts["B"], pts["C"], pts["E"], pts["G"], branches)
        return lk, body, built - float(theta[0]) + shift

    turns = np.concatenate((theta - theta[0] + shift0, guard))

    def residuals(X):
        """The residuals of the designs X (shape (k, 16)) at once, shape (k, 9 n + 2 _GUARD)."""
        k = X.shape[0]
        xa = np.concatenate((X[:, :1], np.zeros((k, 1)), X[:, 1:13]), axis=1)
        pts = {key: _point(P0[key], T[key], xa[:, 2 * i:2 * i + 2])[:, None, :] for i, key in enumerate(_NAMES)}
        bodies = np.stack([body0 @ _rotvec(x[13:16]) for x in X])
        # the closed-form poses, eq. (5), for speed; the result is checked by SphericalLinkage
        frames, h = _guided_frames(pts, branches, turns, heights=True)
        gap = frames[:, :n] @ bodies[:, None] - R[None]
        # the constraint (eq. (6a)): every dyad stays clear of its dead point between the first
        # and the last input, so the optimum keeps one branch in order
        keep = np.maximum(0.0, _HEIGHT - np.nan_to_num(h[:, :, n:], nan=-1.0)).transpose(1, 0, 2)
        return np.concatenate((np.nan_to_num(gap, nan=2.0).reshape(k, -1), keep.reshape(k, -1)), axis=1)

    def residual(x):
        return residuals(x[None])[0]

    def jacobian(x):
        # forward differences, all 16 columns in one batched evaluation
        step = _FD_STEP * np.maximum(1.0, np.abs(x))
        F = residuals(np.vstack((x, x + np.diag(step))))
        return (F[1:] - F[0]).T / step

    # Levenberg-Marquardt on unit-scaled variables (all are angles of the order of the
    # design's own)
    sol = least_squares(residual, np.zeros(16), jac=jacobian, method="lm", xtol=_TOL, ftol=_TOL, gtol=_TOL,
                        max_nfev=_MAX_NFEV)
    lk, body, offset = model(sol.x)
    pts, _, _ = unpack(sol.x)
    pose = lk.solve(theta + offset)
    with np.errstate(invalid="ignore"):
        got = _frame(pose.points["E"], pose.points["G"]) @ body
    errors = _rotation_gap(got, R)
    errors = np.where(np.isfinite(errors), errors, np.pi)
    in_order = bool(lk.solve(np.linspace(theta[0], theta[-1], sweep) + offset).assembled.all())
    return SphericalOptimalSixBar(lk, float(offset), pts, body, errors, float(np.sqrt(np.mean(errors ** 2))),
                                  float(errors.max()), in_order, in_order and float(errors.max()) <= rtol,
                                  int(sol.nfev), bool(sol.status > 0))
