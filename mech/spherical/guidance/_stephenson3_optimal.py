"""Optimal design of a Stephenson-3 guidance six-bar for more orientations than its exact
design takes (the spherical monograph, chapter 4, with the optimal-design model of §1.9).

The variables are the seven joints A, D, B, E, C, G, H of the assembly at the first
orientation (two tangent coordinates each) and the guided body's axes relative to that
assembly (a rotation vector): 17 numbers. The guided link CGH hangs from the crank ABE and
the ground by a triad, so its turn Q at each input is found by continuation from the
assembly, with Newton's method on the three arc conditions (13) and their rows (14) of
:ref:`deriv-spherical-guidance-sixbar`, for all finite-difference steps of a Jacobian at
once. Objective: ``sum_j |Q_j body - R_j|^2`` (Frobenius). Constraint: along the whole
motion from the first input to the last the determinant of (14), normalised by its rows,
keeps its sign and stays at least 0.05 in size, so the optimum has no dead point between
the orientations. The result is built as a `SphericalStephenson3` and its errors are
measured by that class's own continuation. SciPy is imported when a design runs.
"""

from dataclasses import dataclass

import numpy as np

from mech._geometry import cross3 as _cross
from mech._validate import InputTypeError, _show, finite_array
from mech.spherical.guidance._fourbar import _rotation_gap
from mech.spherical.guidance._optimal import _point, _tangents
from mech.spherical.guidance._sixbar_optimal import _FD_STEP, _MAX_NFEV, _TOL, _optimal_task, _rotvec, _turn
from mech.spherical.guidance._stephenson3 import SphericalGuidanceStephenson3
from mech.spherical.linkage._stephenson3 import SphericalStephenson3

__all__ = ["SphericalOptimalStephenson3", "optimal_guidance_stephenson3"]

_NAMES = ("A", "D", "B", "E", "C", "G", "H")
#: the normalised determinant of (14) kept at least this far from zero (a dead point)
_HEIGHT = 0.05
#: largest step of the continuation, radians of crank turn
_STEP = 0.05
#: Newton steps per continuation step (quadratic convergence from a 0.05 rad prediction)
_NEWTON = 5
#: the residual of an orientation the candidate cannot reach (Frobenius entries lie in [-2, 2])
_UNREACHED = 2.0


@dataclass(frozen=True)
class SphericalOptimalStephenson3:
    """Result of `optimal_guidance_stephenson3`.

    Attributes
    ----------
    linkage : SphericalStephenson3
        Assembled at the first orientation.
    input_offset : float
        The linkage's input angle is ``theta_j + input_offset`` at orientation j.
    first_orientation : ndarray, shape (3, 3)
        The guided body's orientation in the assembly: the orientation reached at input
        theta is ``linkage.rotations(theta + input_offset) @ first_orientation``.
    errors : ndarray, shape (n,)
        Orientation error (radians) at each prescribed input, by the analysis of
        `SphericalStephenson3`.
    rms_error, pose_error : float
        Root mean square and largest of `errors`.
    in_order : bool
        The analysis reaches every input from the first prescribed angle to the last.
    passes : bool
        ``in_order`` and ``pose_error <= rtol``.
    nfev : int
        Residual evaluations of the optimiser (its Jacobians not counted).
    converged : bool
        The optimiser stopped on its tolerance, not on its cap of evaluations.
    """

    linkage: SphericalStephenson3
    input_offset: float
    first_orientation: np.ndarray
    errors: np.ndarray
    rms_error: float
    pose_error: float
    in_order: bool
    passes: bool
    nfev: int
    converged: bool

    def guided_orientations(self, theta):
        """Orientation R of the guided body (task frame) at task input angles `theta`."""
        theta = finite_array("theta", theta)
        return self.linkage.rotations(theta + self.input_offset) @ self.first_orientation


def _solve3(J, r):
    """Batched 3 x 3 solves of J w = r by Cramer's rule (NaN where J is singular)."""
    c0, c1, c2 = _cross(J[..., 1, :], J[..., 2, :]), _cross(J[..., 2, :], J[..., 0, :]), _cross(J[..., 0, :], J[..., 1, :])
    det = np.sum(J[..., 0, :] * c0, axis=-1)
    adj = np.stack([c0, c1, c2], axis=-1)                   # adjugate: J^-1 = adj / det
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.einsum("...ij,...j->...i", adj, r) / det[..., None]


def _expmaps(w):
    """Rotation matrices of the rotation vectors w (batched Rodrigues)."""
    t = np.linalg.norm(w, axis=-1)
    k = w / np.where(t > 0, t, 1.0)[..., None]
    K = np.zeros(w.shape[:-1] + (3, 3))
    K[..., 0, 1], K[..., 0, 2], K[..., 1, 2] = -k[..., 2], k[..., 1], -k[..., 0]
    K[..., 1, 0], K[..., 2, 0], K[..., 2, 1] = k[..., 2], -k[..., 1], k[..., 0]
    s, c = np.sin(t)[..., None, None], (1.0 - np.cos(t))[..., None, None]
    return np.eye(3) + s * K + c * (K @ K)


def _march(pts, turns):
    """The guided link's turn Q at each crank turn of `turns` (increasing, from 0) and the
    normalised determinant of (14) there, for a batch of assemblies (points of shape
    (k, 3)); NaN from the first step where Newton fails or the determinant changes sign."""
    A, D, B0, E0, C0, G0, H0 = (pts[n] for n in _NAMES)
    k = A.shape[0]
    target = np.stack([np.sum(B0 * C0, -1), np.sum(E0 * G0, -1), np.sum(D * H0, -1)], -1)
    Q = np.broadcast_to(np.eye(3), (k, 3, 3)).copy()
    out = np.full((k, turns.size, 3, 3), np.nan)
    dets = np.full((k, turns.size), np.nan)
    sign0 = None
    alive = np.ones(k, dtype=bool)
    for i, t in enumerate(turns):
        tt = np.full(k, t)
        B, E = _turn(B0, A, tt), _turn(E0, A, tt)
        for _ in range(_NEWTON):
            C, G, H = (np.einsum("kij,kj->ki", Q, X) for X in (C0, G0, H0))
            r = np.stack([np.sum(B * C, -1), np.sum(E * G, -1), np.sum(D * H, -1)], -1) - target
            if not np.any(np.abs(r[alive]) > 1e-15):
                break
            J = np.stack([_cross(C, B), _cross(G, E), _cross(H, D)], axis=1)
            w = _solve3(J, -r)
            bad = ~np.isfinite(w).all(-1) | (np.linalg.norm(w, axis=-1) > 0.3)
            alive &= ~bad
            Q = np.where(alive[:, None, None], _expmaps(np.where(alive[:, None], w, 0.0)) @ Q, Q)
        C, G, H = (np.einsum("kij,kj->ki", Q, X) for X in (C0, G0, H0))
        r = np.stack([np.sum(B * C, -1), np.sum(E * G, -1), np.sum(D * H, -1)], -1) - target
        J = np.stack([_cross(C, B), _cross(G, E), _cross(H, D)], axis=1)
        det = np.linalg.det(J) / np.prod(np.linalg.norm(J, axis=-1), axis=-1)
        sign0 = np.sign(det) if sign0 is None else sign0
        alive &= (np.max(np.abs(r), axis=-1) < 1e-10) & (np.sign(det) == sign0)
        out[alive, i] = Q[alive]
        dets[alive, i] = np.abs(det[alive])
    return out, dets


def optimal_guidance_stephenson3(R, theta, start, *, rtol=1e-2, sweep=721):
    """The Stephenson-3 six-bar nearest (least squares in orientation) to n > 5 orientations
    with prescribed input angles.

    Parameters
    ----------
    R : array_like, shape (n, 3, 3)
        Orientations of the guided body, n >= 5.
    theta : array_like, shape (n,)
        Prescribed input angles, strictly increasing, spanning less than a turn.
    start : SphericalGuidanceStephenson3 or SphericalOptimalStephenson3
        A starting design, e.g. one of `guidance_stephenson3` (of five of the orientations,
        or its least-squares design of all of them).
    rtol : float, optional
        The result ``passes`` when its largest orientation error is at most `rtol` and it
        reaches every input from the first to the last.
    sweep : int, optional
        Inputs sampled for that check.

    Returns
    -------
    SphericalOptimalStephenson3

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import guidance_stephenson3, optimal_guidance_stephenson3, stephenson3
    >>> lk = stephenson3(0.35, 0.9, 0.8, 1.1, E=(0.5, 0.7), arcs=(0.9, 0.6), H=(0.55, -0.6),
    ...                  coupler=(0.3, 0.4), mu=0.8)
    >>> theta = np.linspace(0.0, 1.0, 8)
    >>> R = lk.orientations(theta)
    >>> R[3] = R[3] @ np.array([[1, 0, 0], [0, np.cos(0.01), -np.sin(0.01)], [0, np.sin(0.01), np.cos(0.01)]])
    >>> five = [0, 2, 4, 5, 7]
    >>> start = guidance_stephenson3(R[five], theta[five], lk.assembly["A"])[0]
    >>> best = optimal_guidance_stephenson3(R, theta, start)  # doctest: +SKIP
    >>> best.passes, bool(best.pose_error < 0.01)  # doctest: +SKIP
    (True, True)

    (The search takes tens of seconds, so the last two lines are run by the slow test
    ``tests/spherical/guidance/test_stephenson3_optimal.py``, not as a doctest.)
    """
    R, theta, rtol, sweep = _optimal_task(R, theta, rtol, sweep)
    n = R.shape[0]
    if not isinstance(start, (SphericalGuidanceStephenson3, SphericalOptimalStephenson3)):
        raise InputTypeError(f"Expected `start` to be a SphericalGuidanceStephenson3 or SphericalOptimalStephenson3, "
                             f"got {_show(start)}")
    from scipy.optimize import least_squares

    # the start's joints and body at the first prescribed input
    Q1 = start.linkage.rotations(theta[:1] + start.input_offset)[0]
    turn1 = float(theta[0] + start.input_offset - start.linkage.theta0)
    assembly = start.linkage.assembly
    P0 = {}
    for name in _NAMES:
        p = assembly[name]
        if name in ("B", "E"):
            p = _turn(p, assembly["A"], np.array(turn1))
        elif name in ("C", "G", "H"):
            p = Q1 @ p
        P0[name] = np.asarray(p, dtype=float)
    body0 = Q1 @ start.first_orientation
    T = {k: _tangents(P0[k]) for k in _NAMES}
    # the continuation grid: the prescribed turns and steps of at most _STEP between them
    rel = theta - theta[0]
    grid = np.unique(np.concatenate([rel] + [np.linspace(a, b, int(np.ceil((b - a) / _STEP)) + 1)
                                             for a, b in zip(rel[:-1], rel[1:])]))
    at = np.searchsorted(grid, rel)

    def residuals(X):
        k = X.shape[0]
        pts = {key: _point(P0[key], T[key], X[:, 2 * i:2 * i + 2]) for i, key in enumerate(_NAMES)}
        bodies = np.stack([body0 @ _rotvec(x[14:17]) for x in X])
        Q, det = _march(pts, grid)
        gap = np.nan_to_num(Q[:, at] @ bodies[:, None] - R[None], nan=_UNREACHED).reshape(k, -1)
        keep = np.maximum(0.0, _HEIGHT - np.nan_to_num(det, nan=-1.0))
        return np.concatenate((gap, keep), axis=1)

    def residual(x):
        return residuals(x[None])[0]

    def jacobian(x):
        step = _FD_STEP * np.maximum(1.0, np.abs(x))
        F = residuals(np.vstack((x, x + np.diag(step))))
        return (F[1:] - F[0]).T / step

    sol = least_squares(residual, np.zeros(17), jac=jacobian, method="lm", xtol=_TOL, ftol=_TOL, gtol=_TOL,
                        max_nfev=_MAX_NFEV)
    pts = {key: _point(P0[key], T[key], sol.x[2 * i:2 * i + 2]) for i, key in enumerate(_NAMES)}
    body = body0 @ _rotvec(sol.x[14:17])
    lk = SphericalStephenson3(pts)
    offset = lk.theta0 - float(theta[0])
    errors = _rotation_gap(lk.rotations(theta + offset) @ body, R)
    in_order = bool(np.all(np.isfinite(lk.rotations(np.linspace(theta[0], theta[-1], sweep) + offset))))
    errors = np.where(np.isfinite(errors), errors, np.pi)
    return SphericalOptimalStephenson3(lk, float(offset), body, errors, float(np.sqrt(np.mean(errors ** 2))),
                                       float(errors.max()), in_order, in_order and float(errors.max()) <= rtol,
                                       int(sol.nfev), bool(sol.status > 0))
