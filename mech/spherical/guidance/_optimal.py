"""Motion analysis of a spherical guidance four-bar and its optimal synthesis for more than
five orientations (the spherical monograph, §3.7), with the optimal-design model of §1.9.

Two objectives are offered. The orientation error (the rotation angle between the coupler
orientation the linkage reaches and the prescribed one) analyses the linkage at every step,
so the result has no branch or order defect by construction. The constant-length condition
fits each crank's design equation (the moving pivot stays at a constant arc from its centre
point) separately: two small problems, cheaper, but its residual is not the orientation
error, so its result is checked by analysis afterwards. SciPy is imported lazily.
"""

from dataclasses import dataclass

import numpy as np

from mech._geometry import unit_rows as _unit
from mech._validate import MAX_ANGLE, InputTypeError, _show, finite_array, nonnegative_number, option
from mech.spherical._fourbar import SphericalFourBar
from mech.spherical._types import classify
from mech.spherical.guidance._dyads import SphericalDyad, arc_between
from mech.spherical.guidance._fourbar import (SphericalGuidanceFourBar, _frame_of, _motion, _orientation,
                                              _rotation_gap, _transmission, guidance_fourbars)
from mech.spherical.guidance._orientations import orientation_set

__all__ = ["SphericalGuidanceMotion", "SphericalOptimalGuidance", "guidance_motion", "optimal_guidance"]


@dataclass(frozen=True)
class SphericalGuidanceMotion:
    """The motion of a guidance four-bar's coupler over input angles (`guidance_motion`).

    Attributes
    ----------
    theta_input : ndarray, shape (m,)
        Input angles at A (the linkage's convention).
    orientation : ndarray, shape (m, 3, 3)
        Coupler orientation R(theta): the rotation carrying the body axes of the circle
        points to the moving pivots B and C (NaN where the linkage does not assemble).
    B, C : ndarray, shape (m, 3)
        Moving pivots.
    valid : ndarray of bool, shape (m,)
        The linkage assembles.
    gamma : ndarray, shape (m,)
        Transmission angle at C, folded into [0, pi/2].
    """

    theta_input: np.ndarray
    orientation: np.ndarray
    B: np.ndarray
    C: np.ndarray
    valid: np.ndarray
    gamma: np.ndarray


@dataclass(frozen=True)
class SphericalOptimalGuidance:
    """Result of `optimal_guidance`.

    Attributes
    ----------
    design : SphericalGuidanceFourBar
        The linkage, checked by analysis: ``design.theta_input`` are the input angles that
        bring the coupler nearest to each orientation, ``design.pose_error`` the largest
        orientation error there (radians), ``design.in_order`` the branch and order check.
    objective : str
        ``"orientation"`` or ``"constant_length"``.
    errors : ndarray, shape (n,)
        Orientation error (radians) at each orientation, by analysis.
    rms_error : float
        Root mean square of `errors`.
    nfev : int
        Residual evaluations the optimiser used (both dyads for ``"constant_length"``).
    """

    design: SphericalGuidanceFourBar
    objective: str
    errors: np.ndarray
    rms_error: float
    nfev: int


def _tangents(p):
    """Two unit tangents at p, orthogonal to each other (shape (2, 3))."""
    seed = np.eye(3)[int(np.argmin(np.abs(p)))]
    e1 = _unit(np.cross(p, seed))
    return np.stack([e1, np.cross(p, e1)])


def _point(p0, T, uv):
    """Unit point near p0: normalise p0 + u e1 + v e2 (two coordinates per point)."""
    return _unit(p0 + uv @ T)


def _linkage(A, D, a, c, zB, zC, branch):
    """The placed SphericalFourBar of ground pivots A, D, crank arcs a, c and body points zB, zC."""
    b, d = float(arc_between(zB, zC)), float(arc_between(A, D))
    frame = _frame_of(A, D)[:, [1, 2, 0]]
    return SphericalFourBar(float(a), b, float(c), d, branch=branch, frame=frame), frame


def _gamma(B, C, D, valid):
    """Transmission angle where the linkage assembles, NaN elsewhere."""
    out = np.full(valid.shape, np.nan)
    if np.any(valid):
        out[valid] = _transmission(B[valid], C[valid], D)
    return out


def _check_design(name, value):
    if not isinstance(value, SphericalGuidanceFourBar):
        raise InputTypeError(f"Expected `{name}` to be a SphericalGuidanceFourBar, got {_show(value)}")
    return value


def guidance_motion(design, theta_input):
    """Motion analysis of a guidance four-bar: the coupler's orientation as a function of the
    input angle (§3.7).

    Parameters
    ----------
    design : SphericalGuidanceFourBar
        A linkage from `guidance_fourbars`, `guidance_slider_crank` or `optimal_guidance`.
    theta_input : array_like, shape (m,)
        Input angles at A, radians.

    Returns
    -------
    SphericalGuidanceMotion

    Raises
    ------
    ValueError
        For non-finite angles (`InputTypeError` when `design` is not a
        SphericalGuidanceFourBar).

    Notes
    -----
    The linkage is solved by `SphericalFourBar` on its branch; the coupler orientation is
    the rotation that carries the frame [zB, t, zB x t] of the body points (t the direction
    from zB toward zC) to the frame [B, t', B x t'] of the moving pivots, eq. (12) of
    :ref:`deriv-spherical-guidance`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import guidance_fourbars, guidance_motion, planar_orientations
    >>> P = [13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j, 66.27 + 215.07j]
    >>> R = planar_orientations(np.radians([0.0, 8.88, 22.1, 63.68, -3.0]), P, 1e-3)
    >>> best = guidance_fourbars(R).passing[0]
    >>> motion = guidance_motion(best, best.theta_input)
    >>> float(np.max(np.abs(motion.orientation - R))) < 1e-12
    True
    """
    design = _check_design("design", design)
    theta = np.atleast_1d(finite_array("theta_input", theta_input)).astype(float)
    pose = design.linkage.solve(theta)
    zB, zC = design.input_dyad.circle_point, design.output_dyad.circle_point
    orientation = _orientation(pose.B, pose.C, zB, zC)
    B, C, valid = np.asarray(pose.B), np.asarray(pose.C), np.asarray(pose.valid, bool)
    return SphericalGuidanceMotion(theta, orientation, B, C, valid, _gamma(B, C, design.linkage.D, valid))


def _best_angles(model, zB, zC, R, theta):
    """Per orientation, the input angle (near `theta`) where the coupler comes nearest to it."""
    from scipy.optimize import minimize_scalar

    out = np.array(theta, float)
    for j in range(R.shape[0]):
        def gap(t, j=j):
            pose = model.solve(np.array([t]))
            if not pose.valid[0]:
                return 4.0
            return float(_rotation_gap(_orientation(pose.B, pose.C, zB, zC), R[j])[0])
        found = minimize_scalar(gap, bracket=None, bounds=(theta[j] - 0.5, theta[j] + 0.5), method="bounded",
                                options={"xatol": 1e-13})
        if found.fun <= gap(theta[j]):
            out[j] = found.x
    return out


def _verified(R, A, D, a, c, zB, zC, branch, theta, rtol, refine):
    """A SphericalGuidanceFourBar for the linkage, checked by analysis at the input angles."""
    model, frame = _linkage(A, D, a, c, zB, zC, branch)
    if refine:
        theta = _best_angles(model, zB, zC, R, theta)
    theta = np.arctan2(np.sin(theta), np.cos(theta))
    pose = model.solve(theta)
    valid = np.asarray(pose.valid, bool)
    errors = np.full(R.shape[0], np.inf)
    if np.all(valid):
        errors = _rotation_gap(_orientation(pose.B, pose.C, zB, zC), R)
    direction, critical = _motion(model, theta) if np.all(valid) else (0, None)
    in_order = direction != 0
    gamma_at = _gamma(np.asarray(pose.B), np.asarray(pose.C), D, valid)
    if in_order:
        crit = model.solve(critical)
        gamma_min = float(min(np.min(_transmission(crit.B, crit.C, D)), np.min(gamma_at)))
    else:
        gamma_min = float(np.nanmin(gamma_at)) if np.any(valid) else float("nan")
    try:
        kind = classify(model.a, model.b, model.c, model.d).kind
    except ValueError:
        kind = "unknown"
    B1 = np.asarray(pose.B)[0] if valid[0] else R[0] @ zB
    C1 = np.asarray(pose.C)[0] if valid[0] else R[0] @ zC
    crank = SphericalDyad(zB, B1, A, float(a))
    rocker = SphericalDyad(zC, C1, D, float(c))
    pose_error = float(np.max(errors))
    design = SphericalGuidanceFourBar(
        linkage=model, frame=frame, input_dyad=crank, output_dyad=rocker, theta_input=theta,
        direction=direction, kind=kind, in_order=in_order, pose_error=pose_error,
        passes=bool(in_order and pose_error <= rtol), gamma_at_poses=gamma_at, gamma_min=gamma_min)
    return design, errors


def _start_from(R, start):
    """Pick a start: the given design, or the best passing Burmester four-bar of five spread
    orientations."""
    if start is not None:
        return _check_design("start", start)
    n = R.shape[0]
    pick = np.unique(np.round(np.linspace(0, n - 1, 5)).astype(int))
    found = guidance_fourbars(R[pick]).passing
    if not found:
        raise ValueError(f"Expected `R` whose five spread orientations {pick.tolist()} admit a Burmester four-bar "
                         "that passes its analysis (or a `start`), got none")
    def spread(g):       # constant-length residual of both dyads over all orientations
        total = 0.0
        for dyad in (g.input_dyad, g.output_dyad):
            cosines = np.einsum("i,nij,j->n", np.asarray(dyad.centre_point), R, np.asarray(dyad.circle_point))
            total += float(np.var(cosines))
        return total
    return min(found, key=spread)


def optimal_guidance(R, start=None, *, objective="orientation", theta_input=None, rtol=1e-2):
    """Optimal spherical four-bar through more orientations than five fix exactly (§3.7).

    Parameters
    ----------
    R : array_like, shape (n, 3, 3)
        Prescribed coupler orientations, n >= 5, in the order the linkage should meet them.
    start : SphericalGuidanceFourBar, optional
        Initial linkage (its branch is kept). Default: of the Burmester four-bars of five
        orientations spread over the task that pass their analysis, the one whose two
        cranks best keep constant length over all the orientations.
    objective : {"orientation", "constant_length"}
        ``"orientation"``: least squares of the orientation error ``|R(theta_j) - R_j|_F``
        (the linkage is analysed at every step; input angles free, or prescribed).
        ``"constant_length"``: least squares of the two cranks' design equations
        A . (R_j zB) = cos a and D . (R_j zC) = cos c, two independent problems.
    theta_input : array_like, shape (n,), optional
        Prescribed input rotations from the first orientation (``theta_input[0]`` is 0); the
        first input angle stays free. Only with ``objective="orientation"``.
    rtol : float, optional
        Orientation error (radians) within which `design.passes`.

    Returns
    -------
    SphericalOptimalGuidance
        With the linkage checked by analysis (`SphericalGuidanceFourBar`).

    Raises
    ------
    ValueError
        For bad orientations, fewer than five, a bad `objective`, `theta_input` with the
        constant-length objective, or no start found.

    Notes
    -----
    The design variables are the ground pivots A, D and the body points zB, zC (two
    tangent-plane coordinates each), the crank arcs a, c, and with the orientation
    objective the input angles; the optimiser is SciPy's trust-region reflective least
    squares. Eqs. (12)-(14) (the objectives (13) and (14)) of :ref:`deriv-spherical-guidance`.

    Examples
    --------
    Eight orientations turning about a slowly tilting axis (no four-bar meets them exactly):

    >>> import numpy as np
    >>> from mech.spherical import optimal_guidance, rotation_matrix
    >>> R = np.stack([rotation_matrix([0.1 * k, 0.05, 1.0], 0.25 * k) for k in range(8)])
    >>> fit = optimal_guidance(R)
    >>> fit.design.in_order, fit.design.pose_error < 0.05
    (True, True)
    """
    R = orientation_set("R", R, task=True)
    n = R.shape[0]
    if n < 5:
        raise ValueError(f"Expected at least five orientations in `R`, got {n}")
    objective = option("objective", objective, ("orientation", "constant_length"))
    rtol = nonnegative_number("rtol", rtol)
    if theta_input is not None:
        steps = finite_array("theta_input", theta_input)
        if steps.shape != (n,):
            raise ValueError(f"Expected `theta_input` of shape ({n},), got shape {steps.shape}")
        if not np.max(np.abs(steps)) < MAX_ANGLE:
            # beyond 2**52 rad float64 names no direction (and the search ran for minutes)
            raise ValueError(f"Expected `theta_input` of angles below 2**52 ~ 4.5e15 rad in size, got "
                             f"{_show(theta_input)}")
        if objective != "orientation":
            raise ValueError(f"Expected `theta_input` only with objective 'orientation', got {objective!r}")
    start = _start_from(R, start)
    from scipy.optimize import least_squares

    A0, D0 = np.asarray(start.input_dyad.centre_point, float), np.asarray(start.output_dyad.centre_point, float)
    zB0, zC0 = np.asarray(start.input_dyad.circle_point, float), np.asarray(start.output_dyad.circle_point, float)
    a0, c0 = float(start.input_dyad.arc), float(start.output_dyad.arc)
    branch = start.linkage.branch
    TA, TD, TB, TC = (_tangents(p) for p in (A0, D0, zB0, zC0))
    if objective == "constant_length":
        nfev = 0
        fitted = []
        for u0, z0, Tu, Tz, arc0 in ((A0, zB0, TA, TB, a0), (D0, zC0, TD, TC, c0)):
            def crank(p, u0=u0, z0=z0, Tu=Tu, Tz=Tz):
                u, z = _point(u0, Tu, p[0:2]), _point(z0, Tz, p[2:4])
                return np.einsum("i,nij,j->n", u, R, z) - np.cos(p[4])
            sol = least_squares(crank, np.r_[0.0, 0.0, 0.0, 0.0, arc0], x_scale="jac", xtol=1e-15, ftol=1e-15,
                                gtol=1e-15)
            nfev += sol.nfev
            u, z = _point(u0, Tu, sol.x[0:2]), _point(z0, Tz, sol.x[2:4])
            fitted.append((u, z, float(np.arccos(np.clip(np.cos(sol.x[4]), -1.0, 1.0)))))
        (A, zB, a), (D, zC, c) = fitted
        model, frame = _linkage(A, D, a, c, zB, zC, branch)
        local = np.einsum("nij,j->ni", R, zB) @ frame
        theta = np.arctan2(local[:, 1], local[:, 0])
        design, errors = _verified(R, A, D, a, c, zB, zC, branch, theta, rtol, refine=True)
        return SphericalOptimalGuidance(design, objective, errors, float(np.sqrt(np.mean(errors ** 2))), nfev)

    theta0 = np.unwrap(np.asarray(start.theta_input, float)) if start.theta_input.shape == (n,) else None
    if theta0 is None:
        local = np.einsum("nij,j->ni", R, zB0) @ start.frame
        theta0 = np.unwrap(np.arctan2(local[:, 1], local[:, 0]))
    prescribed = theta_input is not None
    angles0 = np.array([theta0[0]]) if prescribed else theta0

    def unpack(p):
        A, D = _point(A0, TA, p[0:2]), _point(D0, TD, p[2:4])
        zB, zC = _point(zB0, TB, p[4:6]), _point(zC0, TC, p[6:8])
        theta = p[10] + steps if prescribed else p[10:]
        return A, D, p[8], p[9], zB, zC, theta

    def residual(p):
        A, D, a, c, zB, zC, theta = unpack(p)
        try:
            model, _ = _linkage(A, D, a, c, zB, zC, branch)
        except ValueError:
            return np.full(9 * n, 2.0)
        pose = model.solve(theta)
        gap = _orientation(pose.B, pose.C, zB, zC) - R
        return np.nan_to_num(gap, nan=2.0).ravel()

    p0 = np.r_[np.zeros(8), a0, c0, angles0]
    low = np.r_[np.full(8, -np.inf), 1e-6, 1e-6, np.full(angles0.size, -np.inf)]
    high = np.r_[np.full(8, np.inf), np.pi - 1e-6, np.pi - 1e-6, np.full(angles0.size, np.inf)]
    sol = least_squares(residual, p0, bounds=(low, high), x_scale="jac", xtol=1e-15, ftol=1e-15, gtol=1e-15)
    A, D, a, c, zB, zC, theta = unpack(sol.x)
    design, errors = _verified(R, A, D, a, c, zB, zC, branch, theta, rtol, refine=False)
    return SphericalOptimalGuidance(design, objective, errors, float(np.sqrt(np.mean(errors ** 2))), int(sol.nfev))
