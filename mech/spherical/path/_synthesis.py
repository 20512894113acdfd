"""Spherical path synthesis by optimisation (monograph chapter 2, §2.5).

A spherical four-bar, or a Stephenson-1 six-bar, whose coupler point passes near prescribed
points ``Q_i`` on the unit sphere at prescribed input angles ``theta_i``. Two formulations:

* ``"distance"``: the design variables are the linkage's parameters (for the four-bar the
  nine of §2.1: placement ``lon, lat, heading``, arcs ``a, b, c, d``, coupler point
  ``r, gamma``); the residuals are the distances between the coupler point that the
  analysis (`SphericalFourBar.solve`, `SphericalLinkage.solve`) generates at ``theta_i``
  and ``Q_i``. Order and branch are right by construction: the analysis follows one
  branch.
* ``"constant-arc"`` (four-bar only): the joint C at every point is an extra unknown and
  the residuals say that the arcs BC, CD and the coupler triangle keep constant lengths
  when P is at ``Q_i``. Every residual is a dot product, but nothing ties C_i to one
  branch; the result is proved by the same analysis.

Derivation of the objective and its gradient: the section "Derivation: the objective and its
gradient (§2.5)" of ``book/spherical/path-synthesis.md``.
The six-bar (`path_stephenson1`) is in ``_sixpath``, which adds an assembly constraint
and a batch evaluation. SciPy is imported when a synthesis runs, never at ``import mech``.
"""

import time
from dataclasses import dataclass

import numpy as np

from mech._geometry import unit_rows
from mech._task import precision_points
from mech._validate import MAX_ANGLE, branch_sign, finite_array, option, real_array, real_number
from mech.spherical._fourbar import SphericalFourBar, ground_frame

__all__ = ["SphericalPathDesign", "path_fourbar", "path_verify"]

_TINY = 1e-3                                   # arcs kept in [_TINY, pi - _TINY]
_NINE = ("lon", "lat", "heading", "a", "b", "c", "d", "r", "gamma")
_FIFTEEN = ("lon", "lat", "heading", "a", "b", "c", "d", "E_r", "E_gamma", "F_r", "F_gamma",
              "e", "f", "r", "gamma")


@dataclass(frozen=True)
class SphericalPathDesign:
    """A synthesised spherical path generator, verified by analysis.

    Attributes
    ----------
    linkage : SphericalFourBar or SphericalLinkage
        The linkage, placed on the sphere; ``linkage.solve(theta)`` reproduces the task.
    kind : str
        ``"fourbar"`` or ``"stephenson1"``.
    formulation : str
        ``"distance"`` or ``"constant-arc"``.
    parameters : ndarray, shape (9,) or (15,)
        The linkage's parameters (names in `names`).
    names : tuple of str
    points : ndarray, shape (n, 3)
        The prescribed points.
    theta : ndarray, shape (n,)
        The prescribed input angles, radians.
    generated : ndarray, shape (n, 3)
        The coupler point found by analysis at `theta` (NaN where it does not assemble).
    errors : ndarray, shape (n,)
        Arc between each generated and prescribed point, radians (pi where unassembled).
    max_error, rms_error : float
        Largest and root-mean-square entry of `errors`.
    in_order : bool
        The input, swept from ``theta[0]`` to ``theta[-1]`` in 2000 steps, keeps the
        linkage assembled and moves the coupler point continuously (no step longer than
        20 times the mean step): the points are met in order on one branch.
    passes : bool
        ``in_order`` and ``max_error <= tol``.
    tol : float
        The error allowed by `passes`, radians.
    seconds : float
        Wall time of the optimisation.
    evaluations : int
        Residual evaluations spent.
    """

    linkage: object
    kind: str
    formulation: str
    parameters: np.ndarray
    names: tuple
    points: np.ndarray
    theta: np.ndarray
    generated: np.ndarray
    errors: np.ndarray
    max_error: float
    rms_error: float
    in_order: bool
    passes: bool
    tol: float
    seconds: float
    evaluations: int


def _task(points, theta, design=True):
    Q = real_array("points", points)
    if Q.ndim != 2 or Q.shape[1] != 3 or Q.shape[0] < 2:
        raise ValueError(f"Expected `points` of shape (n, 3) with n >= 2, got shape {Q.shape}")
    # |Q| after dividing by the largest component: no square under- or overflows (1e-300, 1e300)
    big = np.max(np.abs(Q), axis=1)
    norms = big * np.linalg.norm(Q / np.where(big > 0.0, big, 1.0)[:, None], axis=1)
    if np.any(np.abs(norms - 1.0) > 1e-9):
        bad = float(norms[np.argmax(np.abs(norms - 1.0))])
        raise ValueError(f"Expected `points` to be unit vectors, got a norm of {bad!r}")
    th = real_array("theta", theta)
    if th.shape != (Q.shape[0],):
        raise ValueError(f"Expected `theta` of shape ({Q.shape[0]},) (one input angle per point), "
                         f"got shape {th.shape}")
    Q = Q / norms[:, None]
    # a design task must also have points that move; a linkage may be checked against any
    precision_points(Q, th, one_point=design)
    return Q, th


def _start(start, size):
    x = finite_array("start", start)
    if x.shape != (size,):
        raise ValueError(f"Expected `start` of shape ({size},), got shape {x.shape}")
    # its entries are angles and arcs: beyond 2**52 rad float64 names no direction
    if x.size and not np.max(np.abs(x)) < MAX_ANGLE:
        raise ValueError(f"Expected `start` of angles below 2**52 ~ 4.5e15 rad in size, got an entry "
                         f"{float(x.flat[np.argmax(np.abs(x))])!r}")
    return x


def _tol(tol):
    tol = real_number("tol", tol)
    if not tol > 0.0:
        raise ValueError(f"Expected `tol` a positive number, got {tol!r}")
    return tol


def _bounds(names):
    lo = {"lon": -np.inf, "lat": -np.pi / 2, "heading": -np.inf, "r": 0.0, "gamma": -np.inf,
          "E_gamma": -np.inf, "F_gamma": -np.inf, "E_r": 0.0, "F_r": 0.0}
    hi = {"lon": np.inf, "lat": np.pi / 2, "heading": np.inf, "r": np.pi, "gamma": np.inf,
          "E_gamma": np.inf, "F_gamma": np.inf, "E_r": np.pi, "F_r": np.pi}
    return (np.array([lo.get(n, _TINY) for n in names]), np.array([hi.get(n, np.pi - _TINY) for n in names]))


def _fourbar(x, branch):
    return SphericalFourBar(*x[3:7], branch=branch, coupler=(x[7], x[8]), frame=ground_frame(*x[:3]))


def _sixbar(kind, x, branches):
    """The six-bar of type `kind` ("stephenson1", "stephenson2", "watt1", "watt2") with the
    fifteen parameters `x` in the order of ``_FIFTEEN``."""
    from mech.spherical import linkage

    build = getattr(linkage, kind)
    return build(*x[3:7], E=(x[7], x[8]), F=(x[9], x[10]), arcs=(x[11], x[12]),
                 coupler=(x[13], x[14]), branches=branches, frame=ground_frame(*x[:3]))


def _stephenson(x, branches):
    return _sixbar("stephenson1", x, branches)


def _coupler(linkage, theta):
    pose = linkage.solve(theta)
    return pose.P if isinstance(linkage, SphericalFourBar) else pose.points["P"]


def _residual_vectors(P, Q, metric):
    """Residual 3-vectors whose length is the chord (or the arc) from Q_i to P_i; an
    unassembled pose counts as the antipode of Q_i."""
    P = np.where(np.isfinite(P).all(axis=-1, keepdims=True), P, -Q)
    diff = P - Q
    if metric == "chord":
        return diff
    chord = np.linalg.norm(diff, axis=-1, keepdims=True)
    arc = 2.0 * np.arcsin(np.clip(chord / 2.0, 0.0, 1.0))
    scale = np.where(chord > 1e-300, arc / np.where(chord > 1e-300, chord, 1.0), 1.0)
    return diff * scale


def _arc_errors(P, Q):
    ok = np.isfinite(P).all(axis=-1)
    dots = np.clip(np.sum(np.where(ok[:, None], P, -Q) * Q, axis=-1), -1.0, 1.0)
    cross = np.linalg.norm(np.cross(np.where(ok[:, None], P, -Q), Q), axis=-1)
    return np.arctan2(cross, dots)


def path_verify(linkage, points, theta, tol=1e-3):
    """Verify a spherical path generator by analysis: error at each point, order, branch.

    Solves `linkage` at the prescribed input angles and measures the arc from each
    generated coupler point to its prescribed point; then sweeps the input from
    ``theta[0]`` to ``theta[-1]`` in 2000 steps and checks that the linkage stays assembled
    and the coupler point moves continuously, so that the points are met in the given order
    on the linkage's one branch (monograph §2.3: the parametric form has no branch or order
    defect).

    Parameters
    ----------
    linkage : SphericalFourBar or SphericalLinkage
        A linkage with a coupler point ``P``.
    points : array_like, shape (n, 3)
        Prescribed unit vectors.
    theta : array_like, shape (n,)
        Prescribed input angles, strictly monotonic within one turn, radians.
    tol : float, optional
        Largest arc allowed at a point for ``passes``, radians.

    Returns
    -------
    dict
        ``generated``, ``errors``, ``max_error``, ``rms_error``, ``in_order``, ``passes``.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import SphericalFourBar, path_verify
    >>> m = SphericalFourBar(0.5, 1.1, 0.9, 1.2, coupler=(0.6, 0.8))
    >>> th = np.linspace(0.0, 1.5, 5)
    >>> v = path_verify(m, m.solve(th).P, th)
    >>> bool(v["passes"]), float(v["max_error"]) < 1e-12
    (True, True)
    """
    from mech.spherical.linkage import SphericalLinkage

    if not isinstance(linkage, (SphericalFourBar, SphericalLinkage)):
        raise TypeError(f"Expected `linkage` a SphericalFourBar or SphericalLinkage, got {linkage!r}")
    Q, th = _task(points, theta, design=False)
    tol = _tol(tol)
    P = _coupler(linkage, th)
    errors = _arc_errors(P, Q)
    sweep = _coupler(linkage, np.linspace(th[0], th[-1], 2001))
    steps = np.linalg.norm(np.diff(sweep, axis=0), axis=-1)
    in_order = bool(np.isfinite(sweep).all() and steps.max() <= 20.0 * max(steps.mean(), 1e-300))
    return {"generated": P, "errors": errors, "max_error": float(errors.max()),
            "rms_error": float(np.sqrt(np.mean(errors ** 2))), "in_order": in_order,
            "passes": bool(in_order and errors.max() <= tol)}


def _design(linkage, kind, formulation, x, names, Q, th, tol, seconds, evaluations):
    v = path_verify(linkage, Q, th, tol)
    return SphericalPathDesign(linkage=linkage, kind=kind, formulation=formulation, parameters=x, names=names,
                               points=Q, theta=th, generated=v["generated"], errors=v["errors"],
                               max_error=v["max_error"], rms_error=v["rms_error"], in_order=v["in_order"],
                               passes=v["passes"], tol=tol, seconds=seconds, evaluations=evaluations)


def path_fourbar(points, theta, start, *, formulation="distance", metric="arc", branch=1, tol=1e-3):
    """Synthesise a spherical four-bar path generator with prescribed input angles.

    Minimises ``sum_i dist(P(x, theta_i), Q_i)^2`` over the nine parameters ``x = (lon,
    lat, heading, a, b, c, d, r, gamma)`` (monograph §2.5, with the parametric coupler point
    of §2.3), or solves the constant-arc equations (see the module notes), then verifies
    the result by analysis with `SphericalFourBar` (`path_verify`).

    Parameters
    ----------
    points : array_like, shape (n, 3)
        Prescribed points, unit vectors.
    theta : array_like, shape (n,)
        Prescribed input angles (from the great circle A->D, as in `SphericalFourBar`),
        strictly monotonic within one turn, radians.
    start : array_like, shape (9,)
        Starting parameters ``(lon, lat, heading, a, b, c, d, r, gamma)``.
    formulation : {"distance", "constant-arc"}, optional
    metric : {"arc", "chord"}, optional
        Distance used by the ``"distance"`` formulation.
    branch : {1, -1}, optional
        Assembly branch of the linkage (``"distance"``); the constant-arc result takes the
        branch of its first pose.
    tol : float, optional
        Arc error allowed for `SphericalPathDesign.passes`, radians.

    Returns
    -------
    SphericalPathDesign

    Raises
    ------
    ValueError
        For points off the unit sphere, input angles that are not monotonic, a `start` of
        the wrong shape.

    Notes
    -----
    The distance formulation calls the analysis at every evaluation, so the coupler point
    is always on the linkage's branch, in the order of the input angles. The constant-arc
    formulation is a polynomial system in dot products with ``3n + 11`` unknowns; its
    joints C_i may fall on either branch, and only the analysis afterwards can tell.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import SphericalFourBar, ground_frame, path_fourbar
    >>> x = np.array([0.3, 1.2, 0.4, 0.5, 1.1, 0.9, 1.2, 0.6, 0.8])
    >>> m = SphericalFourBar(*x[3:7], coupler=tuple(x[7:]), frame=ground_frame(*x[:3]))
    >>> th = np.linspace(0.2, 2.0, 6)
    >>> d = path_fourbar(m.solve(th).P, th, x + 0.05)
    >>> bool(d.passes), d.max_error < 1e-8
    (True, True)
    """
    Q, th = _task(points, theta)
    x0 = _start(start, 9)
    formulation = option("formulation", formulation, ("distance", "constant-arc"))
    metric = option("metric", metric, ("arc", "chord"))
    branch = branch_sign(branch)
    tol = _tol(tol)
    from scipy.optimize import least_squares

    lo, hi = _bounds(_NINE)
    x0 = np.clip(x0, lo + 1e-12, hi - 1e-12)
    t0 = time.perf_counter()
    if formulation == "distance":
        def fun(x):
            return _residual_vectors(_coupler(_fourbar(x, branch), th), Q, metric).ravel()

        sol = least_squares(fun, x0, bounds=(lo, hi), x_scale=1.0, xtol=1e-14, ftol=1e-14, gtol=1e-14,
                            max_nfev=1500)
        x, nfev = sol.x, sol.nfev
        linkage = _fourbar(x, branch)
    else:
        x, nfev, linkage = _constant_arc(Q, th, x0, branch, least_squares)
    seconds = time.perf_counter() - t0
    return _design(linkage, "fourbar", formulation, x, _NINE, Q, th, tol, seconds, nfev)


def _crank_points(A, D, a, th):
    """B_i at input angles th: eq. (2-1)-type crank point in the frame x toward D, y = A x x."""
    xd = unit_rows(D - (A @ D) * A)
    yd = np.cross(A, xd)
    return np.cos(a) * A + np.sin(a) * (np.cos(th)[:, None] * xd + np.sin(th)[:, None] * yd)


def _constant_arc(Q, th, x0, branch, least_squares):
    """Constant-arc formulation: unknowns A, D, a, C_1..C_n and the cosines of b, c, BP, CP."""
    n = len(th)
    m0 = _fourbar(x0, branch)
    pose = m0.solve(th)
    C0 = np.where(np.isfinite(pose.C), pose.C, Q)
    # cos of the arc C-P from the coupler triangle at the start
    P1, B1, Cs = pose.P[0], pose.B[0], pose.C[0]
    ce0 = float(P1 @ Cs) if np.isfinite(P1).all() else np.cos(x0[4])
    z0 = np.concatenate([m0.A, m0.D, [x0[3]], C0.ravel(), [np.cos(x0[4]), np.cos(x0[5]), np.cos(x0[7]), ce0]])

    def split(z):
        A, D, a = z[0:3], z[3:6], z[6]
        C = z[7:7 + 3 * n].reshape(n, 3)
        return A, D, a, C, z[7 + 3 * n:]

    def fun(z):
        A, D, a, C, (cb, cc, cr, ce) = split(z)
        B = _crank_points(A, D, a, th)
        return np.concatenate([[A @ A - 1.0, D @ D - 1.0], np.sum(C * C, axis=1) - 1.0,
                               np.sum(B * C, axis=1) - cb, C @ D - cc,
                               np.sum(Q * B, axis=1) - cr, np.sum(Q * C, axis=1) - ce])

    def jac(z):
        # every residual is a dot product: exact derivatives, except dB_i/d(A, D, a), taken
        # by central differences of the crank point (7 small vectorised calls)
        A, D, a, C, _ = split(z)
        g = z[:7]
        dB = np.empty((n, 3, 7))
        for k in range(7):
            h = 1e-7 * max(1.0, abs(g[k]))
            gp, gm = g.copy(), g.copy()
            gp[k] += h
            gm[k] -= h
            dB[:, :, k] = (_crank_points(gp[0:3], gp[3:6], gp[6], th) - _crank_points(gm[0:3], gm[3:6], gm[6], th)) / (2 * h)
        B = _crank_points(A, D, a, th)
        J = np.zeros((2 + 5 * n, 11 + 3 * n))
        J[0, 0:3], J[1, 3:6] = 2 * A, 2 * D
        cos = 7 + 3 * n
        for i in range(n):
            c = slice(7 + 3 * i, 10 + 3 * i)
            r = 2 + i + n * np.arange(5)
            J[r[0], c] = 2 * C[i]
            J[r[1], 0:7], J[r[1], c], J[r[1], cos] = C[i] @ dB[i], B[i], -1.0
            J[r[2], c], J[r[2], 3:6], J[r[2], cos + 1] = D, C[i], -1.0
            J[r[3], 0:7], J[r[3], cos + 2] = Q[i] @ dB[i], -1.0
            J[r[4], c], J[r[4], cos + 3] = Q[i], -1.0
        return J

    sol = least_squares(fun, z0, jac=jac, xtol=1e-15, ftol=1e-15, gtol=1e-15, max_nfev=1500)
    A, D, a, C, _ = split(sol.x)
    A, D, C = unit_rows(A), unit_rows(D), unit_rows(C)
    B = _crank_points(A, D, a, th)
    linkage, x = _from_joints(A, D, B[0], C[0], Q[0], th[0])
    return x, sol.nfev, linkage


def _from_joints(A, D, B, C, P, theta1):
    """The nine parameters (and the linkage) of a four-bar drawn at one pose."""
    arc = lambda u, v: float(np.arctan2(np.linalg.norm(np.cross(u, v)), u @ v))
    xd = unit_rows(D - (A @ D) * A)
    R = np.column_stack([xd, np.cross(A, xd), A])
    lat = float(np.arcsin(np.clip(A[2], -1.0, 1.0)))
    lon = float(np.arctan2(A[1], A[0]))
    xl = np.array([np.sin(lat) * np.cos(lon), np.sin(lat) * np.sin(lon), -np.cos(lat)])
    yl = np.array([-np.sin(lon), np.cos(lon), 0.0])
    heading = float(np.arctan2(xd @ yl, xd @ xl))
    tb = unit_rows(C - (B @ C) * B)                      # direction of B->C at B
    tp = unit_rows(P - (B @ P) * B)
    gamma = float(np.arctan2(np.cross(tb, tp) @ B, tb @ tp))
    branch = 1 if np.linalg.det(np.array([B, D, C])) > 0 else -1
    x = np.array([lon, lat, heading, arc(A, B), arc(B, C), arc(C, D), arc(A, D), arc(B, P), gamma])
    return SphericalFourBar(*x[3:7], branch=branch, coupler=(x[7], x[8]), frame=R), x
