"""Optimal design of Stephenson-1, Stephenson-2 and Watt-1 guidance six-bars for more
orientations than the exact designs take (the spherical monograph, chapter 4, with the
optimal-design model of §1.9; the Watt-2's own optimiser is `optimal_guidance_watt2`).

The design variables are the seven joints A, B, C, D, E, F, G of the assembly at the first
orientation (two tangent coordinates each) and the guided body's axes relative to the frame
of EG (a rotation vector): 17 numbers. Each candidate is built as the linkage that
`guidance_stephenson1` and its siblings build from their joints; the search moves them
through a closed-form batch of the chain (crank, dyad B-C-D, the links that carry E and F,
dyad E-G-F), and the result is analysed by `SphericalLinkage` at every prescribed input. A dead-point guard keeps both dyads' joints at least 0.05 (sine of the arc) from the
great circles of their pins on 64 inputs between the first and the last. SciPy is
imported when a design runs.
"""

import numpy as np

from mech._geometry import cross3 as _cross
from mech._validate import InputTypeError, _show, finite_array
from mech.spherical._rigid_body import angle_at
from mech.spherical.guidance._fourbar import _rotation_gap
from mech.spherical.guidance._optimal import _point, _tangents
from mech.spherical.guidance._sixbar import _frame
from mech.spherical.guidance._sixbar_exact import SphericalExactSixBar, _linkage_of
from mech.spherical.guidance._sixbar_optimal import (_FD_STEP, _GUARD, _HEIGHT, _MAX_NFEV, _TOL,
                                                      SphericalOptimalSixBar, _heights, _joint, _optimal_task,
                                                      _rotvec, _turn)

__all__ = ["optimal_guidance_sixbar"]

_NAMES = ("A", "B", "C", "D", "E", "F", "G")
#: the residual of an orientation the candidate cannot reach (Frobenius entries lie in [-2, 2])
_UNREACHED = 2.0
#: the links that carry E and F (as `guidance_stephenson1` and its siblings build them)
_CARRY = {"stephenson1": ("rocker", "crank"), "stephenson2": ("coupler", "ground"), "watt1": ("coupler", "rocker")}


def _frames(p, q):
    """[p, t, p x t] with t the unit tangent at p toward q (batched `_frame`)."""
    t = q - np.sum(p * q, axis=-1, keepdims=True) * p
    t = t / np.linalg.norm(t, axis=-1, keepdims=True)
    return np.stack([p, t, _cross(p, t)], axis=-1)


def _chain(kind, pts, branches, turn):
    """Frames of EG and the dyads' `_heights` after the crank turns by `turn` from the
    assembly `pts`, in closed form (the same eqs. (5) as the Watt-2 optimiser); the points
    may be batches of shape (k, 1, 3), then the frames have shape (k, m, 3, 3)."""
    A, B0, C0, D, E0, F0, G0 = (pts[k] for k in _NAMES)

    def dot(p, q):
        return np.sum(p * q, axis=-1)

    B = _turn(B0, A, turn)
    Ds = np.broadcast_to(D, B.shape)
    C = _joint(B, Ds, dot(B0, C0), dot(D, C0), branches[0])
    u, w = _cross(D, C0), _cross(D, C)
    rocker = np.arctan2(dot(_cross(u, w), D), dot(w, u))
    coupler = _frames(B, C) @ np.swapaxes(_frames(B0, C0), -1, -2)     # the coupler's rotation

    def carried(P0, link):
        if link == "crank":
            return _turn(P0, A, turn)
        if link == "rocker":
            return _turn(P0, D, rocker)
        if link == "coupler":
            return np.einsum("...ij,...j->...i", coupler, np.broadcast_to(P0, B.shape))
        return np.broadcast_to(P0, B.shape)

    on_e, on_f = _CARRY[kind]
    E, F = carried(E0, on_e), carried(F0, on_f)
    G = _joint(E, F, dot(E0, G0), dot(F0, G0), branches[1])
    with np.errstate(invalid="ignore"):
        return _frames(E, G), np.stack([_heights(B, Ds, C), _heights(E, F, G)])


def optimal_guidance_sixbar(R, theta, start, *, rtol=1e-2, sweep=721):
    """The Stephenson-1, Stephenson-2 or Watt-1 six-bar nearest (least squares in
    orientation) to n > 5 orientations with prescribed input angles.

    Starting from an exact design of five of the orientations (`guidance_stephenson1`,
    `guidance_stephenson2` or `guidance_watt1`; the type is the start's), minimises
    ``sum_j |F_j body - R_j|^2`` (Frobenius) with ``F_j`` the frame of the guided link EG
    at the prescribed input, eq. (6) of :ref:`deriv-spherical-guidance-sixbar`, over the
    joints of the assembly and the body's axes, subject to eq. (6a): on 64 inputs from the
    first prescribed angle to the last each dyad's joint stays 0.05 (sine of the arc) or
    more from the great circle through its pins. Levenberg-Marquardt with forward
    differences; every candidate is analysed by `SphericalLinkage`.

    Parameters
    ----------
    R : array_like, shape (n, 3, 3)
        Orientations of the guided body, n >= 5.
    theta : array_like, shape (n,)
        Prescribed input angles, strictly increasing, spanning less than a turn.
    start : SphericalExactSixBar or SphericalOptimalSixBar
        A starting design of the same task (the type is taken from it).
    rtol : float, optional
        The result ``passes`` when its largest orientation error is at most `rtol`
        (radians) and it assembles at every input between the first and the last.
    sweep : int, optional
        Inputs sampled for that order check.

    Returns
    -------
    SphericalOptimalSixBar
        With ``kind`` the start's type; ``nfev`` counts residual evaluations of the
        optimiser (its finite-difference Jacobians not included).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import guidance_watt1, optimal_guidance_sixbar, sixbar_orientations, watt1
    >>> lk = watt1(0.3, 0.9, 0.7, 1.0, E=(0.5, 0.6), F=(0.4, 0.9), arcs=(0.7, 0.8), coupler=(0.3, 0.4))
    >>> theta = np.linspace(0.0, 1.4, 8)
    >>> R = sixbar_orientations(lk, theta)
    >>> R[3] = R[3] @ np.array([[1, 0, 0], [0, np.cos(0.01), -np.sin(0.01)], [0, np.sin(0.01), np.cos(0.01)]])
    >>> five = [0, 2, 4, 5, 7]
    >>> start = min((d for d in guidance_watt1(R[five], theta[five], [0.3, -0.2, 0.93]) if d.passes),
    ...             key=lambda d: d.pose_error)
    >>> best = optimal_guidance_sixbar(R, theta, start)
    >>> best.kind, best.passes, bool(best.pose_error < 0.01)
    ('watt1', True, True)
    """
    R, theta, rtol, sweep = _optimal_task(R, theta, rtol, sweep)
    n = R.shape[0]
    kind = getattr(start, "kind", None)
    if not isinstance(start, (SphericalExactSixBar, SphericalOptimalSixBar)) or kind not in (
            "stephenson1", "stephenson2", "watt1"):
        raise InputTypeError(f"Expected `start` to be a Stephenson-1, Stephenson-2 or Watt-1 design "
                             f"(SphericalExactSixBar or SphericalOptimalSixBar), got {_show(start)}")
    from scipy.optimize import least_squares

    # the start's joints at the first prescribed orientation, and its body axes
    first = start.linkage.solve(start.input_offset + theta[:1]).points
    P0 = {k: np.asarray(first[k][0], dtype=float) for k in _NAMES}
    body0 = _frame(P0["E"], P0["G"]).T @ start.guided_orientations(theta[:1])[0]
    branches = tuple(s[-1] for s in start.linkage._steps if s[0] == "rrr")
    T = {k: _tangents(P0[k]) for k in _NAMES}
    guard = np.linspace(theta[0], theta[-1], _GUARD)
    inputs = np.concatenate((theta, guard))

    def unpack(x):
        P = {k: _point(P0[k], T[k], x[2 * i:2 * i + 2]) for i, k in enumerate(_NAMES)}
        return P, body0 @ _rotvec(x[14:17])

    def model(x):
        P, body = unpack(x)
        lk = _linkage_of(kind, P, branches)
        return lk, body, float(angle_at(P["A"], P["D"], P["B"])) - float(theta[0])

    def residuals(X):
        """The residuals of the designs X (shape (k, 17)) at once, shape (k, 9 n + 2 _GUARD)."""
        k = X.shape[0]
        pts = {key: _point(P0[key], T[key], X[:, 2 * i:2 * i + 2])[:, None, :] for i, key in enumerate(_NAMES)}
        bodies = np.stack([body0 @ _rotvec(x[14:17]) for x in X])
        # the crank turns from the assembly's own angle at A: the inputs relative to theta[0]
        frames, h = _chain(kind, pts, branches, inputs - theta[0])
        gap = np.nan_to_num(frames[:, :n] @ bodies[:, None] - R[None], nan=_UNREACHED)
        keep = np.maximum(0.0, _HEIGHT - np.nan_to_num(h[:, :, n:], nan=-1.0)).transpose(1, 0, 2)
        return np.concatenate((gap.reshape(k, -1), keep.reshape(k, -1)), axis=1)

    def residual(x):
        return residuals(x[None])[0]

    def jacobian(x):
        # forward differences, all 17 columns in one batched evaluation
        step = _FD_STEP * np.maximum(1.0, np.abs(x))
        F = residuals(np.vstack((x, x + np.diag(step))))
        return (F[1:] - F[0]).T / step

    sol = least_squares(residual, np.zeros(17), jac=jacobian, method="lm", xtol=_TOL, ftol=_TOL, gtol=_TOL,
                        max_nfev=_MAX_NFEV)
    lk, body, offset = model(sol.x)
    P, _ = unpack(sol.x)
    pose = lk.solve(theta + offset)
    with np.errstate(invalid="ignore"):
        got = _frame(pose.points["E"], pose.points["G"]) @ body
    errors = _rotation_gap(got, R)
    errors = np.where(np.isfinite(errors), errors, np.pi)
    in_order = bool(lk.solve(np.linspace(theta[0], theta[-1], sweep) + offset).assembled.all())
    return SphericalOptimalSixBar(lk, float(offset), P, body, errors, float(np.sqrt(np.mean(errors ** 2))),
                                  float(errors.max()), in_order, in_order and float(errors.max()) <= rtol,
                                  int(sol.nfev), bool(sol.status > 0), kind)
