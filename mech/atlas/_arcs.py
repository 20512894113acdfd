"""Open and partial targets: match an arc against parts of the closed curves of an atlas.

An open arc, such as the path of a coupler point over half a turn of the crank, has a
signature of its own (the arc run forward and back, `curve_signature` with
``closed=False``), but that signature is not comparable with the signature of a whole
closed curve. So the search compares it with the signatures of *parts* of the atlas's
curves: every closed curve is cut into sub-arcs that cover a fraction `span` of its curve
parameter, starting at `starts` equally spaced places. Those sub-arc signatures are computed
once per atlas and kept with it. The alignment stage then frees both ends of the sub-arc:
a pattern search on its start and end parameters, at each step fitting the best similarity
(place, turn and scale) of the sub-arc onto the target at equal arc-length steps, for both
directions of travel.
"""

import numpy as np

from mech.atlas._sampling import coupler_points
from mech.atlas._signature import _close_arc, _resample_rows, normal_form

__all__ = []

#: Curve points per sub-arc when the alignment evaluates it (before arc-length resampling).
_POINTS = 160
#: Rows of an atlas cut into sub-arcs at a time (bounds the memory).
_ROWS = 256
#: Halvings of the pattern search on the ends of a sub-arc.
_LEVELS = 12
#: Largest number of rounds of moves at one step length of the pattern search.
_ROUNDS = 4
#: Signature entries of a sub-arc of no length (real signatures have entries in [-1, 1]).
_FAR = 1e3


def arc_signatures(atlas, span, starts):
    """Signatures of the sub-arcs of every atlas curve, shape (rows, starts, 4K); cached on the atlas.

    Kept in float32 (entries lie in [-1, 1]; their rounding, below 1e-7, is far under the
    noise of any drawn or measured target), half the memory of float64: about 82 MB for
    10^4 curves at the default 64 starts and 8 harmonics (41 MB at 32 starts). The
    distances are taken in float64.

    Sub-arc ``j`` of a curve covers the curve parameter ``u`` from about ``2 pi j / starts``
    (half a grid step later) to that plus ``2 pi span``, drawn from the curve at ``grid``
    equal steps of ``u``.
    """
    cache = atlas._arc_cache
    key = (float(span), int(starts))
    if key in cache:
        return cache[key]
    n = atlas.samples
    grid = starts * max(1, int(np.ceil(2 * n / starts)))          # a multiple of `starts`
    length = int(round(span * grid)) + 1
    # half a step off the dead centres of a rocking input (u = pi/2, 3 pi/2), where a pose
    # computed from rounded lengths may fail to assemble
    u = 2 * np.pi * (np.arange(grid) + 0.5) / grid
    index = (np.arange(starts)[:, None] * (grid // starts) + np.arange(length)[None, :]) % grid
    out = np.empty((len(atlas), starts, 4 * atlas.harmonics), dtype=np.float32)
    for lo in range(0, len(atlas), _ROWS):
        rows = np.arange(lo, min(lo + _ROWS, len(atlas)))
        curves = coupler_points(atlas.linkages.take(rows).columns(), u[None, :])
        arcs = curves[:, index].reshape(-1, length)
        # a sub-arc of no length (the coupler point still while the curve parameter runs,
        # as at a dead centre) has no shape: it gets a signature far from any other
        still = ~(np.max(np.abs(arcs - arcs[:, :1]), axis=1) > 0.0)
        arcs = np.where(still[:, None], np.arange(length)[None, :], arcs)
        sig = normal_form(_close_arc(_resample_rows(arcs, n // 2 + 1, False)), atlas.harmonics).signature
        sig[still] = _FAR
        out[rows] = sig.reshape(rows.size, starts, -1)
    norms = np.sum(np.square(out, dtype=np.float64), axis=2)
    cache[key] = (out, norms)
    return cache[key]


def _arc_fit(t, cols, u0, u1, m):
    """Fit sub-arcs [u0, u1] (rows) of the curves `cols` onto the open target `t` (m,) at m
    equal arc-length steps. Returns (RMS error, w, centroid, points) per row."""
    s = np.linspace(0.0, 1.0, _POINTS)
    z = coupler_points(cols, u0[:, None] + (u1 - u0)[:, None] * s[None, :])
    bad = ~np.all(np.isfinite(z), axis=1)
    z = np.where(bad[:, None], 0.0, z)
    span = np.max(np.abs(z - z[:, :1]), axis=1)
    z = np.where((span > 0.0)[:, None], z, s[None, :])          # a degenerate arc: any line
    z = _resample_rows(z, m, False)
    centroid = z.mean(axis=1)
    a = z - centroid[:, None]
    tc = t - t.mean()
    w = np.einsum("ij,j->i", a.conj(), tc) / np.sum(np.abs(a) ** 2, axis=1)
    err = np.sqrt(np.mean(np.abs(tc[None, :] - w[:, None] * a) ** 2, axis=1))
    return np.where(bad | ~(span > 0.0), np.inf, err), w, centroid, z


def align_arcs(t, linkages, u0, u1, step, levels=_LEVELS):
    """Best sub-arc [u0, u1] and direction of each linkage's curve for the open target `t`.

    A pattern search from the given ends (arrays over rows): moves of either end, of
    both together or of both apart, by `step` halved `levels` times, for the target run
    both ways.
    Returns (error, w, centroid, points, u0, u1, direction) per row, for the better way.
    """
    m = t.shape[0]
    rows = len(linkages)
    cols = {k: np.concatenate([v, v]) for k, v in linkages.columns().items()}
    targets = (t, t[::-1])
    U0, U1 = np.concatenate([u0, u0]), np.concatenate([u1, u1])

    def errors(a, b):
        e = np.empty(2 * rows)
        for d in (0, 1):
            part = slice(d * rows, (d + 1) * rows)
            sub = {k: v[part] for k, v in cols.items()}
            e[part] = _arc_fit(targets[d], sub, a[part], b[part], m)[0]
        return e

    # the search moves the ends in arc length (fractions of the closed curve's length), not
    # in u: where the coupler point is slow, a step in u barely moves an end, where it is
    # fast the same step moves it far, and the valley of the error then runs obliquely
    # between the moves, where the search stalls
    table, cumulative = _length_tables(cols)
    X0, X1 = _to_length(cumulative, U0), _to_length(cumulative, U1)
    step = step / (2 * np.pi)

    def errors_at(x0, x1):
        return errors(_to_u(table, x0), _to_u(table, x1))

    err = errors_at(X0, X1)
    for _ in range(levels):
        # at each step length, keep moving while a move helps (up to `_ROUNDS` rounds)
        for _ in range(_ROUNDS):
            moved = False
            for du0, du1 in ((1, 1), (-1, -1), (1, 0), (-1, 0), (0, 1), (0, -1), (-1, 1), (1, -1)):
                a, b = X0 + du0 * step, X1 + du1 * step
                ok = (b - a > 1e-6) & (b - a <= 1.0)
                e = np.where(ok, errors_at(a, b), np.inf)
                better = e < err
                moved = moved or bool(better.any())
                X0, X1, err = np.where(better, a, X0), np.where(better, b, X1), np.where(better, e, err)
            if not moved:
                break
        step = step * 0.5
    U0, U1 = _to_u(table, X0), _to_u(table, X1)
    pick = err[:rows] <= err[rows:]
    out = []
    for d in (0, 1):
        part = slice(d * rows, (d + 1) * rows)
        sub = {k: v[part] for k, v in cols.items()}
        out.append(_arc_fit(targets[d], sub, U0[part], U1[part], m))
    e, w, centroid, z = (np.where(pick if x0.ndim == 1 else pick[:, None], x0, x1) for x0, x1 in zip(*out))
    direction = np.where(pick, 1, -1)
    # the reversed target was fitted with its points reversed: turn the points back
    z = np.where(pick[:, None], z, z[:, ::-1])
    return e, w, centroid, z, np.where(pick, U0[:rows], U0[rows:]), np.where(pick, U1[:rows], U1[rows:]), direction


#: Steps of the tables between the curve parameter u and arc length.
_TABLE = 1024


def _length_tables(cols):
    """Per row: u at equal steps of arc length, and arc length at equal steps of u.

    Both tables have ``_TABLE + 1`` entries over one cycle (arc length as a fraction of the
    closed curve's length); a curve of no length gets arc length proportional to u.
    """
    u = 2 * np.pi * np.arange(_TABLE + 1) / _TABLE
    z = coupler_points(cols, u[None, :])
    step = np.abs(np.diff(z, axis=1))
    step = np.where(np.isfinite(step), step, 0.0)
    total = step.sum(axis=1)
    step = np.where((total > 0.0)[:, None], step, 1.0)
    cumulative = np.concatenate([np.zeros((z.shape[0], 1)), np.cumsum(step, axis=1)], axis=1)
    cumulative /= cumulative[:, -1:]
    grid = np.linspace(0.0, 1.0, _TABLE + 1)
    table = np.stack([np.interp(grid, c, u) for c in cumulative])
    return table, cumulative


def _lookup(table, x, scale):
    """Piecewise-linear periodic lookup of `table` rows at `x` (in cycles), plus `scale` per cycle."""
    turns = np.floor(x)
    f = (x - turns) * _TABLE
    j = np.minimum(f.astype(int), _TABLE - 1)
    r = np.arange(table.shape[0])
    low, high = table[r, j], table[r, j + 1]
    return turns * scale + low + (f - j) * (high - low)


def _to_u(table, x):
    return _lookup(table, x, 2 * np.pi)


def _to_length(cumulative, u):
    return _lookup(cumulative, u / (2 * np.pi), 1.0)
