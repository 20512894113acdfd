"""Function generation with the planar four-bar (textbook section 4, II: F85 to F94, Ex. 2-16).

Freudenstein's equation of page ``deriv-function-generation``,

    K1 cos(psi) - K2 cos(theta) + K3 = cos(theta - psi),

is linear in K1 = d/a, K2 = d/c, K3 = (a^2 - b^2 + c^2 + d^2)/(2ac). Three precision pairs
are one 3x3 solve, more pairs a least-squares fit; every design is then handed to
`mech.planar.FourBar` and simulated over its input range, which alone decides whether it
meets its pairs, on which branch, and whether one branch covers the range.
"""


import numpy as np

from mech._generated.function_generation import fg_output_terms, fg_row
from mech._geometry import wrap_angle as _wrap
from mech._spacing import chebyshev_spacing
from mech._task import distinct_pairs
from mech._validate import angle, bool_flag, function_pairs, naming, positive_length, real_number
from mech.planar.synthesis._function_generator import (
    FunctionGenerator,
    FunctionMap,
    _common,
    freudenstein_coefficients,
    lengths_from_coefficients,
)

__all__ = [
    "FunctionGenerator",
    "FunctionMap",
    "freudenstein_coefficients",
    "lengths_from_coefficients",
    "chebyshev_spacing",
    "precision_pairs",
    "least_squares",
]


def _from_signed(signed, theta0, psi0, x, y, **options):
    """The FunctionGenerator of signed lengths: flip negative links, branch from the first pair."""
    a, b, c, d = signed
    theta0 = theta0 + np.pi * (a < 0)
    psi0 = psi0 + np.pi * (c < 0)
    a, c = abs(a), abs(c)
    first = int(np.argmin(x))
    B = a / d * np.exp(1j * (theta0 + x[first]))          # in units of d: no overflow
    C = 1.0 + c / d * np.exp(1j * (psi0 + y[first]))
    cross = ((1.0 - B).conjugate() * (C - B)).imag
    branch = 1 if cross >= 0 else -1
    return FunctionGenerator((a, b, c, d), float(_wrap(theta0)), float(_wrap(psi0)), branch, x, y, **options)


def _matrix(theta, psi):
    """[G | h] of Freudenstein's rows, shape (..., n, 4)."""
    return np.stack(np.broadcast_arrays(*fg_row(theta, psi)), axis=-1)


def _half_turn_roots(f):
    """Roots u in [0, pi) of f(u) = alpha cos^2 u + beta cos u sin u + gamma sin^2 u, evaluated
    through `f` (broadcast over leading axes); shape (..., 2), NaN where there are none.

    f = P + Q cos 2u + R sin 2u, so the roots are 2u = atan2(R, Q) +- arccos(-P / hypot(Q, R)).
    """
    f0, f1, f2 = f(0.0), f(np.pi / 4), f(np.pi / 2)
    P, Q, R = 0.5 * (f0 + f2), 0.5 * (f0 - f2), f1 - 0.5 * (f0 + f2)
    amp = np.hypot(Q, R)
    with np.errstate(invalid="ignore", divide="ignore"):
        ratio = -P / amp
    ok = np.abs(ratio) <= 1.0
    spread = np.arccos(np.where(ok, ratio, 0.0))
    centre = np.arctan2(R, Q)
    roots = np.stack([centre + spread, centre - spread], axis=-1) / 2.0
    return np.where(ok[..., None], np.mod(roots, np.pi), np.nan)


def _check_fixed(x, y, theta0, psi0):
    """Raise if det [G | h] of the first four pairs is at rounding level for every free start
    angle: then the pairs do not fix them (y = x, for one, is met by every parallelogram),
    or not in double precision (pairs too close together)."""
    u = np.linspace(0.0, np.pi, 37)
    t = u[:, None] if theta0 is None else np.full((1, 1), theta0)
    q = u[None, :] if psi0 is None else np.full((1, 1), psi0)
    t, q = np.broadcast_arrays(t, q)
    M = _matrix(t[..., None] + x[:4], q[..., None] + y[:4])
    # the entries are cosines: |det| <= 16 (Hadamard), computed with an error of about
    # 4 * 16 * eps; below that level the sign of det, and so every root, is noise
    largest = float(np.max(np.abs(np.linalg.det(M))))
    if largest <= 64 * np.finfo(float).eps:
        raise ValueError(f"Expected pairs that fix the free start angle(s), got det [G | h] at rounding "
                         f"level ({largest:.1e}) for every start angle: the pairs are met at any start "
                         f"angle (as y = x by any parallelogram) or lie too close together (x = {x}, y = {y})")


def _start_angles(x, y, theta0, psi0):
    """Every (theta0, psi0) in [0, pi)^2 (or with the given angle) at which the pairs are
    consistent: det [G | h] = 0 for four pairs (and for pairs 1, 2, 3, 5 with five)."""
    if theta0 is not None and psi0 is not None:
        return [(theta0, psi0)]
    if psi0 is None and theta0 is not None:
        roots = _half_turn_roots(lambda u: np.linalg.det(_matrix(theta0 + x, u + y)))
        return [(theta0, float(u)) for u in roots[np.isfinite(roots)]]
    if theta0 is None and psi0 is not None:
        roots = _half_turn_roots(lambda u: np.linalg.det(_matrix(u + x, psi0 + y)))
        return [(float(u), psi0) for u in roots[np.isfinite(roots)]]
    first, second = np.array([0, 1, 2, 3]), np.array([0, 1, 2, 4])

    def det(idx, t, u):
        t, u = np.broadcast_arrays(np.asarray(t, dtype=float), np.asarray(u, dtype=float))
        with np.errstate(invalid="ignore"):            # NaN u: theta0 where the curve has no point
            return np.linalg.det(_matrix(t[..., None] + x[idx], u[..., None] + y[idx]))

    def branch_roots(t):
        return _half_turn_roots(lambda u: det(first, t, u))

    # psi0 on the curve det(first) = 0 is a continuous function of theta0 on each of its two
    # roots (mod pi, and the determinants have period pi in both angles); a sign change of
    # det(second) along it brackets a start-angle pair
    grid = np.linspace(0.0, np.pi, 721)
    traced = branch_roots(grid)
    found = []
    for j in (0, 1):
        u = traced[:, j]
        g = det(second, grid, u)
        for i in np.flatnonzero(np.isfinite(g[:-1]) & np.isfinite(g[1:]) & (np.sign(g[:-1]) != np.sign(g[1:]))):
            lo, hi, glo = grid[i], grid[i + 1], g[i]
            for _ in range(60):                            # bisection: g changes sign on [lo, hi]
                mid = 0.5 * (lo + hi)
                umid = branch_roots(mid)[j]
                gmid = det(second, mid, umid)
                if not np.isfinite(gmid):
                    break
                if np.sign(gmid) == np.sign(glo):
                    lo, glo = mid, gmid
                else:
                    hi = mid
            t = 0.5 * (lo + hi)
            found.append((float(t), float(branch_roots(t)[j])))
    # a solution on the short arc where the two roots join (a fold of the curve, between
    # two samples): det(second) has opposite signs on the two roots at the sample next to it
    exists = np.all(np.isfinite(traced), axis=1)
    edges = exists & ~(np.r_[False, exists[:-1]] & np.r_[exists[1:], False])
    for i in np.flatnonzero(edges):
        g0, g1 = det(second, grid[i], traced[i, 0]), det(second, grid[i], traced[i, 1])
        if np.sign(g0) != np.sign(g1):
            u0, u1 = traced[i]
            middle = u0 + 0.5 * (np.mod(u1 - u0 + np.pi / 2, np.pi) - np.pi / 2)
            found.append(_newton2(lambda z: np.array([det(first, z[0], z[1]), det(second, z[0], z[1])]),
                                  (grid[i], middle)))
    return found


def _newton2(F, z, steps=40):
    """Newton's method on two equations in two unknowns (central-difference Jacobian)."""
    z = np.array(z, dtype=float)
    h = 1e-7
    for _ in range(steps):
        f = F(z)
        J = np.column_stack([(F(z + h * e) - F(z - h * e)) / (2 * h) for e in np.eye(2)])
        try:
            step = np.linalg.solve(J, -f)
        except np.linalg.LinAlgError:
            break
        z = z + step
        if np.max(np.abs(step)) <= 4 * np.finfo(float).eps * (1.0 + np.max(np.abs(z))):
            break
    return float(z[0]), float(z[1])


def precision_pairs(x, y, *, theta0=None, psi0=None, d=1.0, target=None, x_range=None, samples=721,
                    tol=1e-9):
    """Four-bars whose output meets y at x exactly: psi0 + y_i = psi(theta0 + x_i).

    Freudenstein's equation (3) at each precision pair (精确点): three pairs with both start
    angles given (one linear 3x3 solve (5)), four pairs with one start angle unknown (the
    two roots of a quadratic in its cosine and sine), five pairs with both unknown (the
    textbook's F88; continuation of one quadratic, bisection on a second). Each linkage is
    then simulated by `FourBar` through the pairs and over the input range.

    Parameters
    ----------
    x, y : array_like, shape (n,)
        Input and output rotations from the start angles, radians; 3 <= n <= 5.
    theta0, psi0 : float or None
        Start angles of the input link (A->B) and output link (D->C), radians; both for
        n = 3, one for n = 4, none for n = 5.
    d : float, optional
        Ground length AD, > 0 (the free scale).
    target : callable, optional
        Target output rotation y(x), e.g. a `FunctionMap`; used for the structural error
        over the range and the reversal check.
    x_range : (float, float), optional
        Input rotations to cover (default: the target's span, else the pairs' span).
    samples : int, optional
        Input rotations sampled over `x_range` by the coverage check.
    tol : float, optional
        Largest ``|structural error|`` (radians) at the pairs for them to count as met; for
        free start angles also the relative residual of (3) for a root to count, the
        relative size of K1, K2 below which a root is a link of unbounded length.

    Returns
    -------
    designs : tuple of FunctionGenerator
        Every real linkage found (one for n = 3), those that cover the range first, then
        by largest error at the pairs; `defect` and `covers_range` tell them apart.

    Raises
    ------
    ValueError
        For bad pairs, a wrong number of start angles, or no real linkage (b^2 <= 0, a link
        of infinite length, a singular system).

    Notes
    -----
    Page ``deriv-function-generation``, eqs. (3) to (5); the textbook reaches the same
    linkages by inversion, (2-43) to (2-45). A negative length from (4) is realised by
    turning that link by pi, so `theta0` or `psi0` of a result may differ by pi from the
    arguments; for the same reason unknown start angles are searched in [0, pi) only.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import precision_pairs
    >>> x = np.radians([0.0, 30.0, 60.0]); y = np.radians([0.0, 20.0, 35.0])
    >>> g, = precision_pairs(x, y, theta0=np.radians(60.0), psi0=np.radians(30.0), d=100.0)
    >>> g.pair_error < 1e-12
    True
    """
    x, y = function_pairs(x, y, 3)
    distinct_pairs(x, y)
    n = x.size
    theta0 = None if theta0 is None else angle("theta0", theta0)
    psi0 = None if psi0 is None else angle("psi0", psi0)
    given = (theta0 is not None) + (psi0 is not None)
    if n > 5:
        raise ValueError(f"Expected at most 5 precision pairs (use least_squares for more) in `x` and `y`, got {n}")
    if given != {3: 2, 4: 1, 5: 0}[n]:
        raise ValueError(f"Expected {({3: 2, 4: 1, 5: 0}[n])} of `theta0`, `psi0` given for {n} pairs, got {given}")
    d = positive_length("d", d)
    x_range = _common(target, x_range, samples, tol)
    if n > 3:
        _check_fixed(x, y, theta0, psi0)
    designs, problems = [], []
    for t0, p0 in _start_angles(x, y, theta0, psi0):
        if not (np.isfinite(t0) and np.isfinite(p0)):
            continue                                       # Newton's method did not converge
        M = _matrix(t0 + x, p0 + y)
        try:
            k = np.linalg.solve(M[:, :3], M[:, 3]) if n == 3 else np.linalg.lstsq(M[:, :3], M[:, 3], rcond=None)[0]
        except np.linalg.LinAlgError as err:
            problems.append(str(err))
            continue
        if np.max(np.abs(M[:, :3] @ k - M[:, 3])) > tol * (1.0 + np.max(np.abs(k))):
            # a root where [G | h] is singular without the pairs being consistent
            problems.append(f"start angles ({t0!r}, {p0!r}) do not satisfy every pair")
            continue
        if n > 3 and min(abs(k[0]), abs(k[1])) <= tol * np.max(np.abs(k)):
            # a root at infinity: K1 or K2 zero to rounding is a link of unbounded length
            problems.append(f"start angles ({t0!r}, {p0!r}) give a link of unbounded length")
            continue
        try:
            signed = lengths_from_coefficients(*k, d=d)
            design = _from_signed(signed, t0, p0, x, y, x_range=x_range, target=target, samples=samples, tol=tol)
        except ValueError as err:
            problems.append(str(err))
            continue
        if any(np.allclose(design.lengths, g.lengths, rtol=tol) and abs(_wrap(design.theta0 - g.theta0)) <= tol
               for g in designs):
            continue                                       # found twice (a fold and a crossing)
        designs.append(design)
    if not designs:
        detail = f": {problems[0]}" if problems else ""
        listed, shown = naming(x=x, y=y, theta0=theta0, psi0=psi0)
        raise ValueError(f"Expected {listed} that admit a real four-bar through the {n} precision pairs, "
                         f"got {shown}{detail}")
    return tuple(sorted(designs, key=lambda g: (not g.covers_range, g.defect == "branch", g.pair_error)))


def _psi_model(p, d, theta, branch):
    """Output angle of (6) for lengths p = (a, b, c) (ratios to d) and a penalty where not assembled."""
    beta, kappa = fg_output_terms(p[0], p[1], p[2], 1.0, theta)
    clipped = np.clip(kappa, -1.0, 1.0)
    psi = beta + branch * np.arctan2(np.sqrt((1.0 - clipped) * (1.0 + clipped)), clipped)
    return psi, np.sqrt(np.maximum(np.abs(kappa) - 1.0, 0.0))


def least_squares(x, y, *, theta0, psi0, d=1.0, kind="structural", fit_start=False, start=None,
                  target=None, x_range=None, samples=721, tol=1e-9):
    """Four-bar fitted to the pairs (x, y) in the least-squares sense.

    ``kind="equation"`` minimises the residual of Freudenstein's equation (3) over the pairs
    (one linear solve; biased: the residual is not the output error). ``kind="structural"``
    minimises the structural error (7), psi(theta0 + x) - psi0 - y, over the length ratios
    (and the start angles with `fit_start`), by SciPy's nonlinear least squares, starting
    from `start` or from the linear fit.

    Parameters
    ----------
    x, y : array_like, shape (n,)
        Input and output rotations, radians; n >= 3 (n >= 5 with `fit_start`).
    theta0, psi0 : float
        Start angles (fixed, or the first guess with `fit_start`).
    d : float, optional
        Ground length, > 0.
    kind : {"structural", "equation"}
    fit_start : bool
        Let the structural fit move theta0 and psi0 too.
    start : FunctionGenerator, optional
        First design of the structural fit (its branch is kept).
    target, x_range, samples, tol
        As in `precision_pairs`.

    Returns
    -------
    FunctionGenerator
        With its `defect` and `covers_range`; `pair_error` is the fit's largest residual.

    Raises
    ------
    ValueError
        For bad pairs or options, or if the linear fit gives no real linkage.

    Notes
    -----
    Page ``deriv-function-generation``, section "More pairs: least squares". With three
    pairs both kinds give the exact `precision_pairs` design. SciPy is imported only by the
    structural fit.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import least_squares
    >>> from mech.planar.synthesis import FunctionMap
    >>> m = FunctionMap(np.log10, (1.0, 10.0), np.radians(100.0), -np.radians(60.0))
    >>> X, Y = m.rotations(np.linspace(1.0, 10.0, 31))
    >>> fit = least_squares(X, Y, theta0=np.radians(40.0), psi0=np.radians(245.0), d=100.0, target=m)
    >>> fit.covers_range, round(fit.errors()[0] / abs(m.output_scale), 4)     # max error in y
    (True, 0.01)
    """
    x, y = function_pairs(x, y, 3)
    distinct_pairs(x, y, exact=False)
    theta0, psi0 = angle("theta0", theta0), angle("psi0", psi0)
    d = positive_length("d", d)
    fit_start = bool_flag("fit_start", fit_start)
    if not (isinstance(kind, str) and kind in ("structural", "equation")):
        raise ValueError(f"Expected `kind` 'structural' or 'equation', got {kind!r}")
    if fit_start and x.size < 5:
        raise ValueError(f"Expected at least 5 pairs in `x` and `y` for `fit_start` = True, got {x.size}")
    if start is not None and not isinstance(start, FunctionGenerator):
        raise ValueError(f"Expected `start` to be a FunctionGenerator or None, got {start!r}")
    x_range = _common(target, x_range, samples, tol)
    options = dict(x_range=x_range, target=target, samples=samples, tol=np.inf)
    if start is None:
        G = np.stack(np.broadcast_arrays(*fg_row(theta0 + x, psi0 + y)), axis=-1)
        k = np.linalg.lstsq(G[:, :3], G[:, 3], rcond=None)[0]
        first = _from_signed(lengths_from_coefficients(*k, d=d), theta0, psi0, x, y, **options)
        # the pairs are not met exactly: keep the branch that follows them better
        twins = [FunctionGenerator(first.lengths, first.theta0, first.psi0, br, x, y, **options) for br in (1, -1)]
        scores = [np.sum(np.nan_to_num(np.abs(g.structural_error(x, y)), nan=np.pi)) for g in twins]
        start = twins[int(np.argmin(scores))]
    if kind == "equation":
        return FunctionGenerator(start.lengths, start.theta0, start.psi0, start.branch, x, y, **options)
    from scipy.optimize import least_squares as scipy_least_squares

    branch = start.branch
    scale = start.lengths[3]

    def residual(p):
        t0, p0 = (p[3], p[4]) if fit_start else (start.theta0, start.psi0)
        psi, stalled = _psi_model(np.exp(p[:3]), 1.0, t0 + x, branch)
        return np.r_[_wrap(psi - p0 - y), stalled]

    p = np.r_[np.log(np.array(start.lengths[:3]) / scale), (start.theta0, start.psi0) if fit_start else ()]
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        p = scipy_least_squares(residual, p, method="trf", x_scale=1.0, xtol=1e-15, ftol=1e-15, gtol=1e-15).x
    t0, p0 = (p[3], p[4]) if fit_start else (start.theta0, start.psi0)
    lengths = np.r_[np.exp(p[:3]) * d, d]
    try:
        return FunctionGenerator(lengths, t0, p0, branch, x, y, **options)
    except ValueError:
        # the fit wandered onto lengths that do not make a four-bar: keep its start
        return FunctionGenerator(start.lengths, start.theta0, start.psi0, branch, x, y, **options)
