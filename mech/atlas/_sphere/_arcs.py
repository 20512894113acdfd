"""Open arcs on the sphere (say half a turn of the crank), for `query_sphere`.

Every closed curve of the atlas is cut into sub-arcs covering a fraction `span` of its curve
parameter at `starts` places, with the signature of each sub-arc run there and back (cached
on the atlas); the best rows then get their sub-arc's two ends freed by a pattern search on
arc length, and are re-ranked by the real RMS distance after the best rotation, for both
directions of travel.
"""

import numpy as np

from mech.atlas._sphere._sampling import sphere_points
from mech.atlas._sphere._fit import _kabsch, _match, _radius, _rotation_gain
from mech.atlas._sphere._signature import _interpolate, _resample_open, _signature_rows, _there_and_back

__all__ = ["arc_signatures", "query_arc"]

#: Rows of an atlas cut into sub-arcs at a time.
_ROWS = 256
#: Steps of the arc-length table of a closed curve used to place sub-arcs.
_TABLE = 1024
#: Rows given a coarse alignment of an open arc, per entry of the short list; rows given the
#: fine alignment after it.
_ARC_WIDER, _ARC_FINE = 1, 16
#: Starts tried per row in the coarse alignment of an open arc.
_ARC_TRIES = 3
#: Halvings of the pattern search on the ends of a sub-arc (coarse, then fine).
_ARC_COARSE, _ARC_LEVELS = 3, 8


def arc_signatures(atlas, span, starts):
    """Signatures of the sub-arcs of every atlas curve, shape (rows, starts, 3 (K + 1)), cached.

    Sub-arc ``j`` covers the curve parameter from ``2 pi (j + 1/2) / grid`` (grid a multiple
    of `starts`) over ``2 pi span``; float32 (entries are at most 1).
    """
    cache = atlas._arc_cache
    key = (float(span), int(starts))
    if key in cache:
        return cache[key]
    n = atlas.samples
    grid = starts * max(1, int(np.ceil(n / starts)))
    length = int(round(span * grid)) + 1
    u = 2 * np.pi * (np.arange(grid) + 0.5) / grid
    index = (np.arange(starts)[:, None] * (grid // starts) + np.arange(length)[None, :]) % grid
    out = np.empty((len(atlas), starts, 3 * (atlas.harmonics + 1)), dtype=np.float32)
    for lo in range(0, len(atlas), _ROWS):
        rows = np.arange(lo, min(lo + _ROWS, len(atlas)))
        curves = sphere_points(atlas.linkages.take(rows).columns(), u[None, :])
        arcs = curves[:, index].reshape(-1, length, 3)
        sig = _signature_rows(_there_and_back(_resample_open(arcs, n // 2 + 1)), atlas.harmonics)
        out[rows] = sig.reshape(rows.size, starts, -1)
    cache[key] = out
    return out


class _Tables:
    """Closed curves of some rows as polylines of `_TABLE` steps of the curve parameter, with
    the arc-length fraction at each vertex: sub-arcs are read off them by arc length.

    The vertices sit half a step off ``u = k pi / 2`` (where a rocking input is at a limit
    position, which rounding may put just out of reach).
    """

    def __init__(self, cols):
        self.u = 2 * np.pi * (np.arange(_TABLE + 1) + 0.5) / _TABLE
        z = sphere_points(cols, self.u[None, :])
        self.bad = ~np.all(np.isfinite(z), axis=(1, 2))
        self.z = np.where(self.bad[:, None, None], np.array([0.0, 0.0, 1.0]), z)
        seg = np.linalg.norm(np.diff(self.z, axis=1), axis=2)
        cum = np.concatenate([np.zeros((seg.shape[0], 1)), np.cumsum(seg, axis=1)], axis=1)
        total = cum[:, -1:]
        self.cum = np.where(total > 0.0, cum / np.where(total > 0.0, total, 1.0), np.linspace(0.0, 1.0, _TABLE + 1))
        # the curves again at equal steps of length (closed: the first point repeated last)
        even = _interpolate(self.z, np.broadcast_to(np.arange(_TABLE) / _TABLE, (self.z.shape[0], _TABLE)))
        self.even = np.concatenate([even, even[:, :1]], axis=1)

    def length_at(self, u):
        """Arc-length fraction (in cycles, unwrapped) at curve parameters u (rows,)."""
        v = u - self.u[0]
        turns = np.floor(v / (2 * np.pi))
        return turns + np.array([np.interp(w, self.u - self.u[0], c) for w, c in zip(v - 2 * np.pi * turns, self.cum)])

    def u_at(self, x):
        """Curve parameter (unwrapped) at arc-length fractions x (rows,)."""
        turns = np.floor(x)
        return 2 * np.pi * turns + np.array([np.interp(v, c, self.u) for v, c in zip(x - turns, self.cum)])

    def arcs(self, rows, x0, x1, m):
        """m points at equal steps of length from x0 to x1 on the given rows, (rows, m, 3)."""
        frac = np.mod(x0[:, None] + (x1 - x0)[:, None] * np.linspace(0.0, 1.0, m)[None, :], 1.0)
        x = frac * _TABLE
        j = np.minimum(x.astype(int), _TABLE - 1)
        w = (x - j)[..., None]
        r = rows[:, None]
        return (1.0 - w) * self.even[r, j] + w * self.even[r, j + 1]


def _arc_errors(tables, rows, targets, x0, x1, rotations=False):
    """RMS error after the best rotation of each sub-arc onto its target (one per row); with
    `rotations`, also the rotations (by SVD) and the points."""
    pts = tables.arcs(rows, x0, x1, targets.shape[1])
    if rotations:
        err, rot = _kabsch(pts, targets)
        return np.where(tables.bad[rows], np.inf, err), rot, pts
    H = np.einsum("rjp,rjq->rpq", pts, targets)
    norms = np.sum(pts**2, axis=(1, 2)) + np.sum(targets**2, axis=(1, 2))
    sq = norms - 2.0 * _rotation_gain(H, norms / 2)
    return np.where(tables.bad[rows], np.inf, np.sqrt(np.maximum(sq, 0.0) / targets.shape[1]))


def _align_arcs(tables, t, x0, x1, step, levels, rounds=4):
    """Pattern search on the ends (arc-length fractions) of each row's sub-arc, target both ways."""
    rows = x0.size
    idx = np.concatenate([np.arange(rows), np.arange(rows)])
    targets = np.concatenate([np.broadcast_to(t, (rows,) + t.shape), np.broadcast_to(t[::-1], (rows,) + t.shape)])
    X0, X1 = np.concatenate([x0, x0]), np.concatenate([x1, x1])
    err = _arc_errors(tables, idx, targets, X0, X1)
    for _ in range(levels):
        for _ in range(rounds):
            moved = False
            for d0, d1 in ((1, 1), (-1, -1), (1, 0), (-1, 0), (0, 1), (0, -1), (-1, 1), (1, -1)):
                a, b = X0 + d0 * step, X1 + d1 * step
                ok = (b - a > 1e-6) & (b - a <= 1.0)
                e = np.where(ok, _arc_errors(tables, idx, targets, a, b), np.inf)
                better = e < err
                moved = moved or bool(better.any())
                X0, X1, err = np.where(better, a, X0), np.where(better, b, X1), np.where(better, e, err)
            if not moved:
                break
        step *= 0.5
    pick = err[:rows] <= err[rows:]
    sel = np.where(pick, np.arange(rows), np.arange(rows) + rows)
    e, rot, pts = _arc_errors(tables, idx[sel], targets[sel], X0[sel], X1[sel], rotations=True)
    # the reversed target was fitted point for point reversed: turn the points back
    pts = np.where(pick[:, None, None], pts, pts[:, ::-1])
    return e, rot, pts, X0[sel], X1[sel], np.where(pick, 1, -1)


def query_arc(atlas, x, k, shortlist, span, starts):
    """The `k` best `SphereMatch` records for the open arc `x` (checked unit points, (m, 3))."""
    n = atlas.samples
    t = _resample_open(x[None], n // 2 + 1)[0]
    sig = _signature_rows(_there_and_back(t[None]), atlas.harmonics)[0]
    sigs = arc_signatures(atlas, span, starts)
    dist = np.sqrt(np.sum((sigs.astype(np.float64) - sig) ** 2, axis=2))
    where = np.argmin(dist, axis=1)
    best = dist[np.arange(len(atlas)), where]
    m = min(_ARC_WIDER * shortlist, len(atlas))
    short = np.argpartition(best, m - 1)[:m] if m < len(atlas) else np.arange(len(atlas))
    grid = starts * max(1, int(np.ceil(n / starts)))
    # each row from its two best starts that are local minima over the starts (a rocking
    # input's curve has look-alike parts, mirrored in the input angle, that trap one start)
    d = dist[short]
    local = (d <= np.roll(d, 1, axis=1)) & (d <= np.roll(d, -1, axis=1))
    order = np.argsort(np.where(local, d, np.inf), axis=1, kind="stable")[:, :min(_ARC_TRIES, starts)]
    tried = np.isfinite(np.take_along_axis(np.where(local, d, np.inf), order, axis=1))
    tried[:, 0] = True
    row = np.repeat(np.arange(short.size), order.shape[1])[tried.ravel()]
    u0 = 2 * np.pi * (order.ravel()[tried.ravel()] / starts + 0.5 / grid)
    tables = _Tables(atlas.linkages.take(short[row]).columns())
    x0 = tables.length_at(u0)
    x1 = tables.length_at(u0 + 2 * np.pi * span)
    step = 0.5 / starts
    err, _, _, x0, x1, _ = _align_arcs(tables, t, x0, x1, step, _ARC_COARSE)
    # the better try of each row
    first = np.lexsort((err, row))
    first = first[np.r_[True, row[first][1:] != row[first][:-1]]]
    short, err, x0, x1 = short[row[first]], err[first], x0[first], x1[first]
    keep = np.argsort(err, kind="stable")[:min(max(2 * k, _ARC_FINE), m)]
    short, x0, x1 = short[keep], x0[keep], x1[keep]
    tables = _Tables(atlas.linkages.take(short).columns())
    err, rot, pts, x0, x1, direction = _align_arcs(tables, t, x0, x1, step / 2**_ARC_COARSE, _ARC_LEVELS, rounds=2)
    u0, u1 = tables.u_at(x0), tables.u_at(x1)
    radius = _radius(t)
    rows = atlas.linkages.take(short)
    return [_match(rank, int(short[j]), rows.take([j]), rot[j], direction[j], err[j], radius, best[short[j]],
                   pts[j] @ rot[j].T, arc=(float(u0[j]), float(u1[j])))
            for rank, j in enumerate(np.argsort(err, kind="stable")[:k])]
