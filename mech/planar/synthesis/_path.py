"""Path generation by precision points: a four-bar whose coupler point meets given points.

Two problems of the textbook's section 4.4: the points alone (Ex. 2-21, solved numerically
from many starts) and the points with the crank angle at each (Ex. 2-22, solved in closed
form as two five-pose Burmester problems). Every design is proved by analysis with
`mech.planar.FourBar`.
"""

from dataclasses import dataclass

import numpy as np

from mech._generated.path_generation import path_dyad_coefficients, path_dyad_residual
from mech._task import distinct_poses
from mech._validate import finite_array, nonnegative_int, planar_points, positive_length, real_array
from mech.planar.kinematics._fourbar import FourBar
from mech.planar.structure._grashof import grashof
from mech.planar.synthesis._displacement import complex_array
from mech.planar.synthesis._guidance import burmester
from mech.planar.synthesis._guidance_fourbar import _motion

__all__ = ["PathFourBar", "PathSynthesis", "path_design", "path_residuals", "path_timed", "path_untimed"]


@dataclass(frozen=True)
class PathFourBar:
    """A four-bar whose coupler point is meant to pass through path points, analysed.

    Attributes
    ----------
    linkage : FourBar
        The four-bar in its standard frame (A = 0, D on +x), coupler point P set.
    origin, angle : complex, float
        Placement: a standard-frame point ``w`` is at ``origin + exp(1j*angle)*w`` in the
        task's ground frame (``origin`` is the fixed pivot A).
    A, B1, C1, D : complex
        The pivots in the task's ground frame, drawn at the first path point.
    points : ndarray of complex, shape (n,)
        The path points.
    theta_input : ndarray, shape (n,)
        Input angle (standard frame) at which the coupler point reaches each point.
    coupler_rotation : ndarray, shape (n,)
        Rotation of the coupler from the first point, radians (0 first).
    residual : float
        Largest design-equation residual (2-53), (2-54), relative to the squared longest link.
    point_error : float
        Largest distance, relative to the longest link, between the analysed coupler point
        at `theta_input` and the path point.
    direction : int
        +1 (-1) if the input, turning counter-clockwise (clockwise) by less than a turn,
        meets the points in order with the linkage assembled all the way; 0 if neither.
    in_order : bool
        ``direction != 0``.
    passes : bool
        ``in_order`` and ``point_error <= rtol``.
    kind : str
        Grashof type.
    gamma_at_points : ndarray, shape (n,)
        Transmission angle at each point, radians.
    gamma_min : float
        Smallest transmission angle from the first point to the last when `in_order`,
        else over the points only.
    """

    linkage: FourBar
    origin: complex
    angle: float
    A: complex
    B1: complex
    C1: complex
    D: complex
    points: np.ndarray
    theta_input: np.ndarray
    coupler_rotation: np.ndarray
    residual: float
    point_error: float
    direction: int
    in_order: bool
    passes: bool
    kind: str
    gamma_at_points: np.ndarray
    gamma_min: float

    def to_ground(self, w):
        """Map standard-frame points (complex) to the task's ground frame."""
        return self._place(planar_points("w", w))

    def coupler_point(self, theta_input):
        """The coupler point in the task frame at standard-frame input angles (NaN if unassembled)."""
        # placed unchecked: the NaN of an unassembled pose is a result, not a bad input
        return self._place(self.linkage.solve(finite_array("theta_input", theta_input)).P)

    def _place(self, w):
        return self.origin + np.exp(1j * self.angle) * w


@dataclass(frozen=True)
class PathSynthesis:
    """The four-bars found for a path task (returned by `path_timed` and `path_untimed`).

    Attributes
    ----------
    candidates : tuple of PathFourBar
        Every distinct real solution of the design equations, analysed.
    passing : tuple of PathFourBar
        The candidates that pass every check (`PathFourBar.passes`).
    n_starts : int
        Starts tried (0 for the closed-form `path_timed`).
    """

    candidates: tuple
    passing: tuple
    n_starts: int


def _points(points, counts):
    points = complex_array("points", points)
    if points.ndim != 1 or points.size not in counts:
        allowed = " or ".join(str(c) for c in counts)
        raise ValueError(f"Expected `points` of shape (n,) with n = {allowed}, got shape {points.shape}")
    return points


def _pivot(name, value):
    value = complex_array(name, value)
    if value.shape != ():
        raise ValueError(f"Expected `{name}` a single point, got shape {value.shape}")
    return complex(value)


def _design_residual(A, B1, C1, D, points, rot):
    """Largest (2-53)/(2-54) residual, relative to the squared longest distance involved."""
    scale = max(abs(B1 - A), abs(C1 - B1), abs(C1 - D), abs(D - A), np.ptp(points.real), np.ptp(points.imag))
    z = [(v - points[0]) / scale for v in (A, B1, C1, D)]
    p = (points - points[0]) / scale
    out = 0.0
    for fixed, moving in ((z[0], z[1]), (z[3], z[2])):
        F = path_dyad_residual(fixed.real, fixed.imag, moving.real, moving.imag, 0.0, 0.0, p.real, p.imag, rot)[0]
        out = max(out, float(np.max(np.abs(F))))
    return out


def _analyse(A, B1, C1, D, points, theta_ground, rot, rtol):
    """Hand the linkage to `FourBar`, placed, and check it meets the points in order."""
    lengths = (abs(B1 - A), abs(C1 - B1), abs(C1 - D), abs(D - A))
    unit = max(lengths)
    scaled = tuple(x / unit for x in lengths)
    angle = float(np.angle(D - A))
    turn = np.exp(-1j * angle)
    b, c, p1 = turn * (B1 - A) / unit, turn * (C1 - A) / unit, turn * (points[0] - A) / unit
    side = np.imag(np.conj(scaled[3] - b) * (c - b))
    branch = 1 if side >= 0.0 else -1
    body = (p1 - b) * np.exp(-1j * np.angle(c - b))
    try:
        model = FourBar(*scaled, branch=branch, coupler=(float(body.real), float(body.imag)))
    except ValueError:
        # one link at least as long as the other three together: not a linkage
        return None
    theta_in = np.angle(np.exp(1j * (np.asarray(theta_ground, dtype=float) - angle)))
    pose = model.solve(theta_in)
    target = turn * (points - A) / unit
    with np.errstate(invalid="ignore"):
        error = np.max(np.abs(pose.P - target))
    point_error = float(error) if np.all(pose.valid) else float("inf")
    direction, critical = _motion(model, theta_in)
    gamma_at = np.asarray(model.transmission_angle(theta_in), dtype=float)
    gamma_min = float(np.min(model.transmission_angle(critical))) if direction else float(np.min(gamma_at))
    linkage = FourBar(*lengths, branch=branch, coupler=(float(body.real * unit), float(body.imag * unit)))
    return PathFourBar(
        linkage=linkage, origin=complex(A), angle=angle, A=complex(A), B1=complex(B1), C1=complex(C1),
        D=complex(D), points=points, theta_input=theta_in, coupler_rotation=np.asarray(rot, dtype=float),
        residual=_design_residual(A, B1, C1, D, points, np.asarray(rot, dtype=float)),
        point_error=point_error, direction=int(direction), in_order=bool(direction != 0),
        passes=bool(direction != 0 and point_error <= rtol), kind=grashof(*lengths).kind,
        gamma_at_points=gamma_at, gamma_min=gamma_min,
    )


def _locate(A, B1, C1, D, points):
    """Coupler rotation at each point: B on both circles (crank and coupler), C must then fit."""
    rho, r = abs(B1 - A), abs(B1 - points[0])
    g = points - A
    dist = np.abs(g)
    with np.errstate(invalid="ignore", divide="ignore"):
        along = (dist**2 + rho**2 - r**2) / (2.0 * dist)
        across = np.sqrt(np.maximum(rho**2 - along**2, 0.0))
    best_err, best_rot = np.full(points.shape, np.inf), np.zeros(points.shape)
    for sign in (1.0, -1.0):
        with np.errstate(invalid="ignore", divide="ignore"):
            B = A + (g / dist) * (along + 1j * sign * across)
            rot = np.angle((B - points) / (B1 - points[0]))
            C = points + np.exp(1j * rot) * (C1 - points[0])
            err = np.abs(np.abs(C - D) - abs(C1 - D))
        err = np.where(np.isfinite(err), err, np.inf)
        best_rot = np.where(err < best_err, rot, best_rot)
        best_err = np.minimum(err, best_err)
    return best_rot


def path_design(A, B1, C1, D, points, *, rtol=1e-9):
    """Analyse a drawn four-bar as a path generator for `points`.

    The linkage is drawn at the first point: its coupler point is ``points[0]``. For every
    other point the crank and coupler angles that bring the coupler point there are found
    (two circle intersections for B, then C must keep its crank length), and the placed
    `FourBar` is solved at those input angles.

    Parameters
    ----------
    A, B1, C1, D : complex
        Fixed pivots A, D and moving pivots B, C at the first point, ground frame.
    points : array_like of complex, shape (n,)
        Path points, n >= 2.
    rtol : float, optional
        Largest accepted point error, relative to the longest link.

    Returns
    -------
    PathFourBar

    Raises
    ------
    ValueError
        For bad points or pivots, or pivots that make no four-bar.

    Notes
    -----
    The branch is the one drawn (C's side of B->D at the first point); a point the
    coupler point reaches only on the other branch shows as a large ``point_error``. An
    unreachable point gets the input angle that brings the crank nearest to it.

    Examples
    --------
    >>> from mech.planar.synthesis import path_design
    >>> P = [13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 32.95 + 99.62j,
    ...      44.74 + 113.95j, 58.62 + 127.98j, 66.27 + 215.07j]
    >>> book = path_design(0j, -95.524 + 80.407j, 76.791 + 170.535j, 174.194 + 18.575j, P)
    >>> bool(book.point_error * 194.46 < 0.06)       # example 2-21 as printed: within 0.06 mm
    True
    """
    points = _points(points, range(2, 10**6))
    A, B1, C1, D = (_pivot(n, v) for n, v in zip(("A", "B1", "C1", "D"), (A, B1, C1, D)))
    rtol = positive_length("rtol", rtol)
    for name, (u, v) in (("B1", (B1, A)), ("C1", (C1, B1)), ("D", (D, C1)), ("A", (A, D))):
        if u == v:
            raise ValueError(f"Expected `{name}` distinct from its neighbouring pivot, got {u}")
    # the rotations are angles: found in units of the task's size, so that squares of
    # lengths near the float range neither overflow nor underflow
    size = max(abs(A), abs(B1), abs(C1), abs(D), float(np.max(np.abs(points))))
    rot = _locate(A / size, B1 / size, C1 / size, D / size, points / size)
    B = points + np.exp(1j * rot) * (B1 - points[0])
    design = _analyse(A, B1, C1, D, points, np.angle(B - A), rot, rtol)
    if design is None:
        lengths = (abs(B1 - A), abs(C1 - B1), abs(C1 - D), abs(D - A))
        raise ValueError(f"Expected pivots that make a four-bar, got link lengths {lengths}")
    return design


def path_residuals(design, points, crank_angles):
    """Coupler-point errors of a four-bar at given crank angles (for approximate synthesis).

    Parameters
    ----------
    design : PathFourBar or sequence of 5 complex
        A result of this module, or ``(A, B1, C1, D, P1)``: the pivots drawn at a first
        position and the coupler point there, ground frame. The assembly branch is the one
        drawn.
    points : array_like of complex, shape (n,)
        Target points.
    crank_angles : array_like, shape (n,)
        Ground-frame angle of A->B at each target, radians.

    Returns
    -------
    ndarray of complex, shape (n,)
        Analysed coupler point minus target (NaN where the linkage cannot be assembled).

    Raises
    ------
    ValueError
        For bad input, or a `design` that makes no four-bar.

    Notes
    -----
    This is the error vector (F32) of the textbook's optimisation (section 4.5): the
    coupler point comes from `FourBar` on the drawn branch, so an optimiser that uses it
    sees exactly what analysis will see.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import path_residuals
    >>> book = (-5.46 + 1.17j, 0.74 + 1.54j, 16.9 + 15.29j, 9.34 - 20.54j, 12.42 + 0j)   # Ex. 2-22
    >>> P = [12.42, 7.98 + 1.89j, 0.76 + 1.47j, 1.30 - 0.85j, 8.83 + 0.3j]
    >>> alpha = np.radians([4.2, 64.87, 145.82, 219.24, 303.45]) + np.angle(0.74 + 1.54j - (-5.46 + 1.17j)) - np.radians(4.2)
    >>> bool(np.max(np.abs(path_residuals(book, P, alpha))) < 0.1)
    True
    """
    if isinstance(design, PathFourBar):
        A, B1, C1, D, P1 = design.A, design.B1, design.C1, design.D, design.points[0]
    else:
        parts = complex_array("design", design)
        if parts.shape != (5,):
            raise ValueError(f"Expected `design` of 5 complex (A, B1, C1, D, P1), got shape {parts.shape}")
        A, B1, C1, D, P1 = (complex(v) for v in parts)
    points = complex_array("points", points)
    crank_angles = real_array("crank_angles", crank_angles)
    if points.ndim != 1 or crank_angles.shape != points.shape:
        raise ValueError(
            f"Expected `points` and `crank_angles` of one shape (n,), got {points.shape} and {crank_angles.shape}"
        )
    for name, (u, v) in (("B1", (B1, A)), ("C1", (C1, B1)), ("D", (D, C1)), ("A", (A, D))):
        if u == v:
            raise ValueError(f"Expected `design` with `{name}` distinct from its neighbouring pivot, got {u}")
    first = _analyse(A, B1, C1, D, np.array([P1]), np.array([np.angle(B1 - A)]), np.zeros(1), 1.0)
    if first is None:
        lengths = (abs(B1 - A), abs(C1 - B1), abs(C1 - D), abs(D - A))
        raise ValueError(f"Expected a `design` that makes a four-bar, got link lengths {lengths}")
    return first.coupler_point(crank_angles - first.angle) - points


def path_timed(points, crank_angles, *, rtol=1e-9, imag_tol=1e-7):
    """Every four-bar whose coupler point meets five points at five given crank angles.

    With the crank angles given, the crank is a guidance dyad of the inverted pose set
    ``(crank_angles + pi, points)`` (its coupler side keeps the length PB, (2-56)): a five-pose
    Burmester problem. Each real crank fixes the coupler's rotations, and the output dyad
    is a Burmester dyad of the coupler poses; the crank itself is one of those and is left
    out.

    Parameters
    ----------
    points : array_like of complex, shape (5,)
        Path points.
    crank_angles : array_like, shape (5,)
        Crank angle at each point, radians; only differences matter (the textbook's
        alpha_i1 = alpha_i - alpha_1).
    rtol : float, optional
        Largest accepted point error, relative to the longest link.
    imag_tol : float, optional
        Passed to `burmester`: how small an imaginary part counts as real.

    Returns
    -------
    PathSynthesis

    Notes
    -----
    The solution is closed form (two quartics), so every real design is found. The
    reported ``theta_input`` are the designed crank's own angles; they differ from
    `crank_angles` by one constant. Derivation: :ref:`deriv-path-generation`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import path_timed
    >>> P = [12.42, 7.98 + 1.89j, 0.76 + 1.47j, 1.30 - 0.85j, 8.83 + 0.3j]     # example 2-22
    >>> found = path_timed(P, np.radians([4.2, 64.87, 145.82, 219.24, 303.45]))
    >>> sorted(round(abs(k.B1 - k.A), 4) for k in found.candidates)
    [3.9001, 6.2168]
    """
    points = _points(points, (5,))
    crank_angles = real_array("crank_angles", crank_angles)
    if crank_angles.shape != (5,):
        raise ValueError(f"Expected `crank_angles` of shape (5,), got shape {crank_angles.shape}")
    rtol = positive_length("rtol", rtol)
    imag_tol = positive_length("imag_tol", imag_tol)
    if np.all(points == points[0]):
        # `burmester` would divide by the zero size of the pose set
        raise ValueError(f"Expected `points` not all equal, got {points}")
    # a point met twice at one crank angle (or a whole turn later) is one task pose
    distinct_poses(crank_angles, points, names=("crank_angles", "points"))
    found = []
    for crank in burmester(crank_angles + np.pi, points, imag_tol=imag_tol).dyads:
        A = complex(crank.centre_point)
        B = A + np.exp(1j * crank_angles) * crank.circle_point
        beta = np.angle(points - B)
        size = max(abs(B[0] - A), abs(points[0] - B[0]))
        try:
            outs = burmester(beta, points, imag_tol=imag_tol).dyads
        except ValueError:
            continue            # the coupler's poses repeat or are dependent: no output dyad
        for out in outs:
            D = complex(out.centre_point)
            C = np.exp(1j * beta) * out.circle_point + points
            # the crank reappears among the coupler's dyads; it is not a second link
            if abs(D - A) <= imag_tol * size and abs(C[0] - B[0]) <= imag_tol * size:
                continue
            rot = np.angle(np.exp(1j * (beta - beta[0])))
            found.append(_analyse(A, complex(B[0]), complex(C[0]), D, points, np.angle(B - A), rot, rtol))
    found = [k for k in found if k is not None]
    return PathSynthesis(tuple(found), tuple(k for k in found if k.passes), 0)


def _untimed_system(p, fixed_A, fixed_D):
    """Residuals and Jacobian of (2-53), (2-54) in the normalised unknowns."""
    n = p.size
    pr, pi = p.real, p.imag

    def unpack(x):
        k = 0
        A = fixed_A
        if A is None:
            A, k = complex(x[0], x[1]), 2
        D = fixed_D
        if D is None:
            D, k = complex(x[k], x[k + 1]), k + 2
        B1, C1 = complex(x[k], x[k + 1]), complex(x[k + 2], x[k + 3])
        return A, B1, C1, D, k, x[k + 4:]

    def fun_jac(x):
        A, B1, C1, D, k, t = unpack(x)
        m = n - 1
        F = np.empty(2 * m)
        J = np.zeros((2 * m, x.size))
        col_A = 0 if fixed_A is None else None
        col_D = (2 if fixed_A is None else 0) if fixed_D is None else None
        for row0, (fix, mov, col_f, col_m) in enumerate(((A, B1, col_A, k), (D, C1, col_D, k + 2))):
            out = path_dyad_residual(fix.real, fix.imag, mov.real, mov.imag, pr[0], pi[0], pr[1:], pi[1:], t)
            rows = np.arange(m) * 2 + row0
            F[rows] = out[0]
            if col_f is not None:
                J[rows, col_f], J[rows, col_f + 1] = out[1], out[2]
            J[rows, col_m], J[rows, col_m + 1] = out[3], out[4]
            J[rows, k + 4 + np.arange(m)] = out[5]
        return F, J

    return unpack, fun_jac


def _cramer_rotations(A, B1, C1, D, p):
    """Starting rotations from (2-53), (2-54) by Cramer's rule (F20)."""
    a = path_dyad_coefficients(A.real, A.imag, B1.real, B1.imag, p[0].real, p[0].imag, p[1:].real, p[1:].imag)
    b = path_dyad_coefficients(D.real, D.imag, C1.real, C1.imag, p[0].real, p[0].imag, p[1:].real, p[1:].imag)
    s = a[2] * b[1] - a[1] * b[2]
    c = a[0] * b[2] - a[2] * b[0]
    # the common factor 1/det only scales (s, c); its sign matters
    det = a[0] * b[1] - a[1] * b[0]
    return np.arctan2(s * np.sign(det + (det == 0)), c * np.sign(det + (det == 0)))


def path_untimed(points, *, A=None, D=None, initial=(), starts=100, seed=0, max_steps=100, tol=1e-10,
                 distinct_tol=1e-6, rtol=1e-9):
    """Four-bars whose coupler point meets 9 - 2k points in order (k fixed pivots), found numerically.

    The unknowns are the pivots A, B1, C1, D not given and the coupler rotations theta_i1;
    the equations are the crank constraints (2-53), (2-54) at every point after the first.
    With no pivot fixed, nine points make the system square; fixing A (as the textbook does
    in Ex. 2-21) leaves seven, fixing A and D five. The system is solved by Levenberg-
    Marquardt from `initial` and from `starts` random starts (rotations from Cramer's
    rule), and every distinct root is analysed with `FourBar`.

    Parameters
    ----------
    points : array_like of complex, shape (n,)
        Path points; n = 9, 7 or 5 for 0, 1 or 2 fixed pivots.
    A, D : complex, optional
        Fixed pivots, ground frame.
    initial : sequence of (A, B1, C1, D), optional
        Starting guesses (complex, ground frame; fixed pivots override theirs).
    starts : int, optional
        Number of random starts.
    seed : int, optional
        Seed of the random starts.
    max_steps : int, optional
        Largest number of residual evaluations of one start (a start that has not
        converged by then is dropped).
    tol : float, optional
        Largest residual of a root (the equations are normalised by the points' size).
    distinct_tol : float, optional
        Roots whose pivots agree within this (relative to the points' size) are one; a
        link shorter than this is degenerate and left out.
    rtol : float, optional
        Largest accepted point error in the analysis, relative to the longest link.

    Returns
    -------
    PathSynthesis
        ``candidates`` sorted by residual; ``passing``.

    Notes
    -----
    A numerical search can miss roots; more starts find more. Each candidate's residual is
    reported, and its analysis does not depend on how it was found. The data are moved to
    their centroid and scaled by their size, so the unit of length does not matter.
    Derivation: :ref:`deriv-path-generation`.

    Examples
    --------
    >>> from mech.planar.synthesis import path_untimed
    >>> P = [13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 32.95 + 99.62j,
    ...      44.74 + 113.95j, 58.62 + 127.98j, 66.27 + 215.07j]
    >>> found = path_untimed(P, A=0j, initial=[(0j, -82.5 + 70.7j, 89.7 + 158.2j, 190.4 + 1j)], starts=0)
    >>> k = found.candidates[0]                        # example 2-21
    >>> [round(v, 3) for v in (k.B1.real, k.B1.imag, k.D.real, k.D.imag)]
    [-95.524, 80.407, 174.194, 18.575]
    """
    from scipy.optimize import least_squares as scipy_least_squares  # lazily: mech stays light

    points = _points(points, (5, 7, 9))
    fixed = {"A": None if A is None else _pivot("A", A), "D": None if D is None else _pivot("D", D)}
    n_fixed = sum(v is not None for v in fixed.values())
    if points.size != 9 - 2 * n_fixed:
        raise ValueError(
            f"Expected {9 - 2 * n_fixed} points with {n_fixed} fixed pivot(s) (a square system), got {points.size}"
        )
    starts = nonnegative_int("starts", starts, 10**6)
    seed = nonnegative_int("seed", seed, 2**63 - 1)
    max_steps = nonnegative_int("max_steps", max_steps, 10**6)
    if max_steps == 0:
        raise ValueError("Expected `max_steps` >= 1, got 0")
    tol = positive_length("tol", tol)
    distinct_tol = positive_length("distinct_tol", distinct_tol)
    rtol = positive_length("rtol", rtol)
    centre = complex(np.mean(points))
    size = float(np.max(np.abs(points - centre)))
    if not np.isfinite(size) or size == 0.0:
        raise ValueError(f"Expected distinct finite `points`, got {points}")
    p = (points - centre) / size
    norm = {k: None if v is None else (v - centre) / size for k, v in fixed.items()}
    unpack, fun_jac = _untimed_system(p, norm["A"], norm["D"])

    guesses = []
    for g in initial:
        g = complex_array("initial", g)
        if g.shape != (4,):
            raise ValueError(f"Expected each `initial` guess as (A, B1, C1, D), got shape {g.shape}")
        guesses.append((g - centre) / size)
    rng = np.random.default_rng(seed)
    for _ in range(starts):
        guesses.append(2.0 * (rng.uniform(-1, 1, 4) + 1j * rng.uniform(-1, 1, 4)))

    roots = []
    for g in guesses:
        Ag = g[0] if norm["A"] is None else norm["A"]
        Dg = g[3] if norm["D"] is None else norm["D"]
        # a guess (or fixed pivot) far beyond the task's size may overflow: no start there
        with np.errstate(all="ignore"):
            t0 = _cramer_rotations(Ag, g[1], g[2], Dg, p)
        if not np.all(np.isfinite(t0)):
            continue
        free = [v for v, f in ((Ag, norm["A"]), (Dg, norm["D"])) if f is None] + [g[1], g[2]]
        x0 = np.concatenate([np.ravel([[v.real, v.imag] for v in free]), t0])
        with np.errstate(all="ignore"):
            sol = scipy_least_squares(lambda x: fun_jac(x)[0], x0, jac=lambda x: fun_jac(x)[1], method="lm",
                                xtol=1e-15, ftol=1e-15, gtol=1e-15, max_nfev=max_steps)
        if not np.all(np.isfinite(sol.x)):
            continue
        res = float(np.max(np.abs(fun_jac(sol.x)[0])))
        Ar, B1r, C1r, Dr, _, t = unpack(sol.x)
        piv = np.array([Ar, B1r, C1r, Dr])
        links = np.abs(piv - np.roll(piv, 1))
        if not res <= tol or np.min(links) <= distinct_tol or np.max(np.abs(piv)) > 1.0 / distinct_tol:
            continue
        if any(np.max(np.abs(piv - q)) <= distinct_tol for q, _, _ in roots):
            continue
        roots.append((piv, np.angle(np.exp(1j * t)), res))

    found = []
    for piv, t, _ in sorted(roots, key=lambda r: r[2]):
        Ag, B1g, C1g, Dg = (complex(centre + size * v) for v in piv)
        rot = np.concatenate([[0.0], t])
        B = points + np.exp(1j * rot) * (B1g - points[0])
        found.append(_analyse(Ag, B1g, C1g, Dg, points, np.angle(B - Ag), rot, rtol))
    found = [k for k in found if k is not None]
    return PathSynthesis(tuple(found), tuple(k for k in found if k.passes), len(guesses))
