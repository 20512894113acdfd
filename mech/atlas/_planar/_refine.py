"""Refinement of an atlas match by constrained optimisation on the real curve error (issue 28).

The variables are the link ratios and coupler point of the four-bar (ground d = 1) and where
along its curve the target starts: ``x = (log a, log b, log c, u, v, s)`` for a closed target,
coupler point ``(p, q) = b (u, v)``, `s` the start as a fraction of the curve's length; for
an open arc, ``x = (log a, log b, log c, u, v, s_0, s_1)``, the two ends of the sub-arc in
fractions of the length. Given `x`, the best similarity (place, turn, scale) of the curve onto
the target is a linear least-squares problem solved in closed form, so the objective, the
relative RMS error squared, is a smooth function of `x` evaluated for many `x` at once
(vectorised over rows). SLSQP (SciPy) minimises it under the `Constraints`: the transmission
inequalities (C2) of `mech.atlas._planar._constraints`, the bound on the link ratio as linear
inequalities on the logarithms, and the pivot box on the placed pivots; its gradient is a
forward difference of all coordinates in one vectorised evaluation.
"""

import numpy as np

from mech._validate import instance, integer
from mech.atlas._planar._constraints import Constraints, motor_at_crank, transmission_margins
from mech.atlas._planar._sampling import coupler_curves, describe
from mech.atlas._planar._search import Match, PlacedLinkage, _align, _fit, _match, _rescaled
from mech.atlas._planar._signature import _curves, _resample_rows, _samples

__all__ = ["refine"]

_DENSE = 4
#: Points per cycle of the arc-length tables of an open refinement (the final fit uses _TABLE).
_OPEN_TABLE = 1024
#: Forward-difference step of the gradient (the objective is smooth to well below it).
_STEP = 1e-7
#: Margins kept inside the constraints, so that the result passes the check after SLSQP's
#: last, slightly inexact, step: radians of transmission angle, log of the link ratio.
_MU_MARGIN = 1e-5
_RATIO_MARGIN = 1e-6
#: The objective where a linkage does not assemble (SLSQP needs a finite number).
_BIG = 1e6
#: SLSQP's stopping tolerance on the objective, the squared error over the start's (1 at the start).
_FTOL = 1e-9
_PAIRS = [(i, j) for i in range(4) for j in range(4) if i != j]


def _unit(fourbar):
    f = fourbar
    return (f.a / f.d, f.b / f.d, f.c / f.d, 1.0, f.coupler[0] / f.d, f.coupler[1] / f.d, f.branch)


def _rows(X, branch):
    a, b, c = np.exp(X[:, 0]), np.exp(X[:, 1]), np.exp(X[:, 2])
    return describe(a, b, c, np.ones_like(a), b * X[:, 3], b * X[:, 4], np.full(a.shape, branch))


def _columns(X, branch):
    """The columns `coupler_points` reads, and the movable rows, for rows of x (the inner loop:
    `describe` without the Grashof type and transmission angle, which it does not need)."""
    from mech.atlas._planar._sampling import _input_ranges

    a, b, c = np.exp(X[:, 0]), np.exp(X[:, 1]), np.exp(X[:, 2])
    one = np.ones_like(a)
    signs = np.full(a.shape, branch, dtype=np.int8)
    full, lo, hi, movable = _input_ranges(a, b, c, one, signs)
    cols = {"a": a, "b": b, "c": c, "d": one, "p": b * X[:, 3], "q": b * X[:, 4], "branch": signs,
            "full_turn": full, "theta_lo": lo, "theta_hi": hi}
    return cols, movable


def _closed_evaluator(t, branch, direction, dense_samples):
    """Relative RMS error and placed pivots (A, D) for rows of x = (log a, log b, log c, u, v, s)."""
    centre = t.mean()

    def evaluate(X):
        X = np.atleast_2d(X)
        rel, piv = np.full(X.shape[0], np.nan), np.full((X.shape[0], 2), np.nan + 0j)
        cols, movable = _columns(X, branch)
        ok = np.flatnonzero(movable)
        if ok.size:
            dense = coupler_curves({k: v[ok] for k, v in cols.items()}, dense_samples)
            fine = np.all(np.isfinite(dense), axis=1)
            ok, dense = ok[fine], dense[fine]
        if ok.size:
            err, w, centroid, radius, _ = _fit(t, dense, np.full(ok.size, direction), X[ok, 5] % 1.0)
            rel[ok] = err / radius
            origin = centre - w * centroid
            piv[ok, 0], piv[ok, 1] = origin, origin + w
        return rel, piv

    return evaluate


def _open_evaluator(t, branch, direction, size):
    """Relative RMS error and placed pivots for rows of x = (log a, log b, log c, u, v, s_0, s_1)."""
    from mech.atlas._planar._arcs import _fit_tables, curve_tables

    centre = t.mean()
    tc = t - centre
    target = tc if direction == 1 else tc[::-1]
    radius = np.sqrt(np.mean(np.abs(tc) ** 2))

    def evaluate(X):
        X = np.atleast_2d(X)
        rel, piv = np.full(X.shape[0], np.nan), np.full((X.shape[0], 2), np.nan + 0j)
        cols, movable = _columns(X, branch)
        ok = np.flatnonzero(movable & (X[:, 6] - X[:, 5] > 1e-6) & (X[:, 6] - X[:, 5] <= 1.0))
        if ok.size:
            _, table, _, fine = curve_tables({k: v[ok] for k, v in cols.items()}, size, with_u=False)
            e, w, centroid, _ = _fit_tables(np.broadcast_to(target, (ok.size, t.size)), table, np.arange(ok.size),
                                            X[ok, 5], X[ok, 6])
            good = fine & np.isfinite(e)
            ok, w, centroid = ok[good], w[good], centroid[good]
            rel[ok] = e[good] / radius
            origin = centre - w * centroid
            piv[ok, 0], piv[ok, 1] = origin, origin + w
        return rel, piv

    return evaluate


def _minimise(evaluate, x0, lower, upper, constraints, box, iterations, linear=()):
    """SLSQP on the relative error squared from `x0` within bounds, under `constraints` (the
    box in the scaled target frame) and extra linear inequalities ``A x <= b``. Returns x."""
    from scipy.optimize import minimize

    n = x0.size
    memo, around = {}, {}

    def at(x):
        key = x.tobytes()
        if key not in memo:
            rel, piv = evaluate(x[None, :])
            memo[key] = rel[0], piv[0]
        return memo[key]

    def batch(x):
        key = x.tobytes()
        if key not in around:
            rel, piv = evaluate(x[None, :] + np.vstack([np.zeros(n), _STEP * np.eye(n)]))
            memo[key] = rel[0], piv[0]
            around.clear()
            around[key] = rel, piv
        return around[key]

    scale = at(x0)[0]
    scale = scale if np.isfinite(scale) and scale > 0.0 else 1.0

    def value(rel):
        return np.where(np.isfinite(rel), (rel / scale) ** 2, _BIG)

    def f(x):
        return float(value(at(x)[0]))

    def grad(x):
        v = value(batch(x)[0])
        return (v[1:] - v[0]) / _STEP

    cons = []
    for A, b in linear:
        cons.append({"type": "ineq", "fun": lambda x, A=A, b=b: b - A @ x, "jac": lambda x, A=A: -A})
    if constraints.driven:
        mu = max(constraints.min_transmission, 1e-3) + _MU_MARGIN
        cons.append({"type": "ineq",
                     "fun": lambda x: np.array(transmission_margins(*np.exp(x[:3]), 1.0, mu))})
    if constraints.max_ratio is not None:
        A = np.zeros((len(_PAIRS), n))
        for k, (i, j) in enumerate(_PAIRS):
            if i < 3:
                A[k, i] += 1.0
            if j < 3:
                A[k, j] -= 1.0
        bound = np.log(constraints.max_ratio) - _RATIO_MARGIN
        cons.append({"type": "ineq", "fun": lambda x: bound - A @ x, "jac": lambda x: -A})
    if box is not None:
        x_lo, x_hi, y_lo, y_hi = box
        shrink = _RATIO_MARGIN * max(x_hi - x_lo, y_hi - y_lo)

        def inside(piv):
            g = np.stack([piv.real - x_lo, x_hi - piv.real, piv.imag - y_lo, y_hi - piv.imag], axis=-1) - shrink
            return np.where(np.isfinite(g), g, -1.0).reshape(*piv.shape[:-1], -1)

        cons.append({"type": "ineq", "fun": lambda x: inside(at(x)[1]),
                     "jac": lambda x: (lambda g: (g[1:] - g[0]).T / _STEP)(inside(batch(x)[1]))})
    result = minimize(f, x0, jac=grad, method="SLSQP", bounds=list(zip(lower, upper)), constraints=cons,
                      options={"maxiter": iterations, "ftol": _FTOL})
    return np.asarray(result.x, dtype=float)


def _start_of(t, dense):
    """Direction and start (fraction of the length) of one dense curve best aligned with `t`."""
    n = t.shape[0]
    direction, start = _align(t, _resample_rows(dense, n, True))
    err = _fit(t, dense, direction, start)[0]
    step = 0.5 / n
    for _ in range(6):
        for trial in (start - step, start + step):
            e = _fit(t, dense, direction, trial % 1.0)[0]
            better = e < err
            start, err = np.where(better, trial % 1.0, start), np.where(better, e, err)
        step *= 0.5
    return int(direction[0]), float(start[0])


def _placed_ok(match, constraints):
    """True if the placed four-bar of `match` satisfies `constraints` (the check of every result)."""
    return not constraints.violations(match.linkage.fourbar, match.linkage.pivots)


def _refine_closed(unit, t, s, constraints, samples, iterations, rank, index, distance):
    """Refine one start (a unit-ground linkage tuple) on the closed, scaled target `t`.

    Returns (start match, refined match or None), both placed on the target at its scale `s`
    (with the motor at the crank when `constraints` ask for a driven input)."""
    if constraints.driven:
        unit, _ = motor_at_crank(*unit)
    a, b, c, _, p, q, branch = unit
    row = describe([a], [b], [c], [1.0], [p], [q], [branch])
    if not row.movable[0]:
        return None, None
    dense = coupler_curves(row.columns(), _DENSE * samples)
    if not np.all(np.isfinite(dense)):
        return None, None
    direction, start = _start_of(t, dense)
    evaluate = _closed_evaluator(t, branch, direction, _DENSE * samples)
    x0 = np.array([np.log(a), np.log(b), np.log(c), p / b, q / b, start])
    width = np.array([1.5, 1.5, 1.5, 1.0, 1.0, 0.5])
    box = None if constraints.pivot_box is None else tuple(v / s for v in constraints.pivot_box)
    x = _minimise(evaluate, x0, x0 - width, x0 + width, constraints, box, iterations)
    out = []
    for y, refined in ((x0, False), (x, True)):
        r = _rows(y[None, :], branch)
        if not r.movable[0]:
            out.append(None)
            continue
        d = coupler_curves(r.columns(), _DENSE * samples)
        err, w, centroid, radius, z = _fit(t, d, np.array([direction]), np.array([y[5] % 1.0]))
        if not np.isfinite(err[0]):
            out.append(None)
            continue
        out.append(_rescaled(_match(rank, index, r, t, w[0], centroid[0], err[0], radius, direction, distance,
                                    z[0], refined=refined), s))
    return tuple(out)


def _open_start(match, unit, relabelled, size):
    """Direction and the two ends (fractions of the length) of the sub-arc of `unit`'s curve
    that the open `match` covers, from its placed points (nearest points of the table)."""
    from mech.atlas._planar._arcs import curve_tables

    a, b, c, d, p, q, branch = unit
    row = describe([a], [b], [c], [d], [p], [q], [branch])
    _, table, _, fine = curve_tables(row.columns(), size, with_u=False)
    f = match.linkage.fourbar
    z = (match.curve - match.linkage.origin) * np.exp(-1j * match.linkage.rotation) / f.d
    if relabelled:
        z = 1.0 - z
    mid = z.size // 2
    j = [int(np.argmin(np.abs(table[0] - z[i]))) for i in (0, mid, z.size - 1)]
    if (j[1] - j[0]) % size <= (j[2] - j[0]) % size:
        return 1, j[0] / size, j[0] / size + max((j[2] - j[0]) % size, 1) / size
    return -1, j[2] / size, j[2] / size + max((j[0] - j[2]) % size, 1) / size


def _refine_open(match, t, s, constraints, iterations):
    """Refine an open match on the scaled open target `t` as an open arc (its ends free)."""
    from mech.atlas._planar._arcs import _TABLE, _fit_tables, _lerp, curve_tables

    unit = _unit(match.linkage.fourbar)
    relabelled = False
    if constraints.driven:
        unit, relabelled = motor_at_crank(*unit)
    a, b, c, _, p, q, branch = unit
    direction, s0, s1 = _open_start(match, unit, relabelled, _OPEN_TABLE)
    evaluate = _open_evaluator(t, branch, direction, _OPEN_TABLE)
    x0 = np.array([np.log(a), np.log(b), np.log(c), p / b, q / b, s0, s1])
    width = np.array([1.5, 1.5, 1.5, 1.0, 1.0, 0.5, 0.5])
    # the sub-arc keeps a length and at most one cycle: s_0 - s_1 <= -1e-4, s_1 - s_0 <= 1
    linear = [(np.array([[0, 0, 0, 0, 0, 1.0, -1.0], [0, 0, 0, 0, 0, -1.0, 1.0]]), np.array([-1e-4, 1.0]))]
    box = None if constraints.pivot_box is None else tuple(v / s for v in constraints.pivot_box)
    x = _minimise(evaluate, x0, x0 - width, x0 + width, constraints, box, iterations, linear)
    r = _rows(x[None, :], branch)
    if not r.movable[0]:
        return None
    _, table, u_at, fine = curve_tables(r.columns(), _TABLE)
    tc = t - t.mean()
    target = (tc if direction == 1 else tc[::-1])[None, :]
    e, w, centroid, z = _fit_tables(target, table, np.array([0]), x[5:6], x[6:7])
    if not (fine[0] and np.isfinite(e[0])):
        return None
    z = z if direction == 1 else z[:, ::-1]
    u0, u1 = (_lerp(u_at, np.array([[v]]), 2 * np.pi)[0, 0] for v in x[5:7])
    radius = np.sqrt(np.mean(np.abs(tc) ** 2))
    return _rescaled(_match(match.rank, match.index, r, t, w[0], centroid[0], e[0], radius, direction,
                            match.distance, z[0], refined=True, arc=(float(u0), float(u1))), s)


def refine(match, target, *, samples=128, iterations=100, constraints=None):
    """Refine a match by constrained optimisation on the real curve error (the path synthesis of chapter 2).

    Starting from the matched linkage, the crank, coupler and rocker (as ratios to the ground),
    the coupler point and the start of the target along the curve (for an open arc, both ends
    of the sub-arc) are moved by SLSQP to reduce the RMS distance between the target and the
    coupler curve, best placed (translation, turn, scale in closed form) at every step, while
    keeping the `constraints`.

    Parameters
    ----------
    match : Match
        A result of `query` (its branch and direction are kept). A match of an open arc
        (``match.arc`` set) is refined as an open arc: the ends of its sub-arc move too.
    target : array_like, complex, shape (m,)
        The target given to `query` (closed, or the open arc).
    samples : int, optional
        Equal arc-length steps at which a closed curve is compared (an open arc: half of
        them, plus one, as in `query`).
    iterations : int, optional
        Largest number of SLSQP iterations.
    constraints : Constraints, optional
        What the result must satisfy (default: nothing). With a driven input asked for, a
        rocker-crank start is first relabelled with the motor at its fully turning link
        (`Constraints`).

    Returns
    -------
    Match
        With ``refined=True``, the refined linkage placed on the target, with its error,
        type, minimum transmission angle and cognates, if it satisfies `constraints` and has
        a smaller error than the start; otherwise the starting match unchanged (which need
        not satisfy `constraints`: `find_linkages` checks every result). An open match stays
        open (``arc`` set, the refined sub-arc covering the whole target).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.atlas import build_atlas, query, refine
    >>> from mech.planar import FourBar
    >>> t = np.linspace(0, 2 * np.pi, 400, endpoint=False)
    >>> target = FourBar(1.0, 2.7, 2.4, 3.1, coupler=(1.5, 0.8)).solve(t).P   # not in the atlas
    >>> first = query(build_atlas(2000, seed=3), target, k=1)[0]
    >>> better = refine(first, target)
    >>> better.refined, better.relative_error < first.relative_error
    (True, True)
    """
    instance("match", match, Match)
    if not isinstance(match.linkage, PlacedLinkage):
        raise ValueError(f"Expected `match` of a four-bar (refine does not move slider-cranks), got a match "
                         f"of a {match.linkage.name}")
    samples = _samples(samples, harmonics=1, even=match.arc is not None)
    iterations = integer("iterations", iterations, minimum=1, maximum=10**6)
    constraints = Constraints.none() if constraints is None else constraints
    instance("constraints", constraints, Constraints)
    closed = match.arc is None
    z, lead, scale = _curves(target, closed, "target", scaled=True)
    if lead not in ((), (1,)):
        raise ValueError(f"Expected one curve in `target`, got shape {np.shape(target)}")
    # the search runs on the target divided by a power of two, as in `query`
    s = float(scale[0])
    if not closed:
        t = _resample_rows(z, samples // 2 + 1, False)[0]
        better = _refine_open(match, t, s, constraints, iterations)
    else:
        t = _resample_rows(z, samples, True)[0]
        _, better = _refine_closed(_unit(match.linkage.fourbar), t, s, constraints, samples, iterations,
                                   match.rank, match.index, match.distance)
    if better is None or not better.relative_error < match.relative_error or not _placed_ok(better, constraints):
        return match
    return better
