"""Open and partial targets: match an arc against parts of the closed curves of an atlas.

An open arc, such as the path of a coupler point over half a turn of the crank, has a
signature of its own (the arc run forward and back, `curve_signature` with
``closed=False``), but that signature is not comparable with the signature of a whole
closed curve. So the search compares it with the signatures of *windows*: every closed
curve is cut into sub-arcs that cover a fraction `span` of its curve parameter, starting
at `starts` equally spaced places.

Three choices keep this sharp, fast and small:

- a window's signature changes smoothly with its start, so the target is compared with
  the *segment* between the signatures of neighbouring windows, not only with its ends
  (the distance to a segment follows from the two end distances and the segment's length,
  so it costs one stored number per window). Between grid starts the error of the
  signature is then of second order in the grid step, not first;
- along a curve, each window keeps the one of its four normal forms that lies nearest the
  previous window's (any of the four represents the window, since the target is compared
  in all four of its own), so neighbouring windows lie on one smooth path;
- windows keep the first `ARC_HARMONICS` harmonics per side only, in float16: 2 bytes *
  4 * 4 harmonics * 65 windows = 2 kB per linkage, 2.6 kB with the float32 squared norms
  and segment lengths (26 MB for 10^4 linkages, 260 MB for 10^5; built in blocks of
  `_ROWS` linkages, so the build needs little more). Arcs whose first harmonic is small
  are also compared with a second set normalised on c_2 (`arc_signatures` with
  ``base=2``), built on the first such query: as large again, 52 MB for both sets at 10^4.

The alignment stage then frees both ends of the sub-arc: a pattern search on the arc
length at its two ends, each step fitting the best similarity (place, turn and scale) of the
sub-arc onto the target at equal arc-length steps, for both directions of travel. Every
trial reads the curve from a table of its points at equal steps of arc length (no
kinematics is solved inside the search).
"""

import numpy as np

from mech.atlas._planar._sampling import coupler_points
from mech.atlas._planar._signature import _close_arc, _resample_rows, normal_form

__all__ = []

#: Harmonics per side kept in the window signatures (the shortlist only needs a coarse shape).
ARC_HARMONICS = 4
#: Points per cycle of a curve's tables (at equal steps of u, and of arc length).
_TABLE = 2048
#: Points per cycle of the tables the window signatures are read from.
_WINDOW_TABLE = 1024
#: Rows of an atlas cut into windows at a time (bounds the memory).
_ROWS = 128
#: Rows compared with the target at a time in the signature stage.
_BLOCK = 4096
#: Halvings of the pattern search on the ends of a sub-arc.
_LEVELS = 12
#: Largest number of rounds of moves at one step length of the pattern search.
_ROUNDS = 4
#: Signature entries of a window of no length (real signatures have entries in [-1, 1]).
_FAR = 1e3


def _truncate(sig, harmonics, keep=ARC_HARMONICS):
    """The first `keep` harmonics per side of signatures with `harmonics` per side."""
    keep = min(keep, harmonics)
    return np.concatenate([sig[..., :2 * keep], sig[..., 2 * harmonics:2 * harmonics + 2 * keep]], axis=-1)


def curve_tables(cols, size=_TABLE, with_u=True):
    """Tables of closed curves: cumulative length at equal steps of u, points and u at equal
    steps of arc length.

    The curve parameter is sampled at ``u_g = 2 pi (g + 1/2) / size`` (half a step off the
    dead centres of a rocking input). Returns ``cum`` (rows, size + 1), the arc length from
    ``u_0`` to ``u_g`` as a fraction of the curve's length (``cum[:, size] = 1``); ``points``
    (rows, size), the curve at arc length ``h / size`` from ``u_0``; ``u_at`` (rows, size + 1),
    the curve parameter there (``u_at[:, size] = u_0 + 2 pi``); ``fine`` (rows,), False for
    a curve with a non-finite point or of no length.
    """
    u = 2 * np.pi * (np.arange(size) + 0.5) / size
    z = coupler_points(cols, u[None, :])
    fine = np.all(np.isfinite(z), axis=1)
    z = np.where(fine[:, None], z, 0.0)
    closed = np.concatenate([z, z[:, :1]], axis=1)
    step = np.abs(np.diff(closed, axis=1))
    total = step.sum(axis=1)
    fine &= total > 0.0
    step = np.where(fine[:, None], step, 1.0)
    cum = np.concatenate([np.zeros((z.shape[0], 1)), np.cumsum(step, axis=1)], axis=1)
    cum /= cum[:, -1:]
    points = _resample_rows(np.where(fine[:, None], z, np.exp(1j * u)[None, :]), size, True)
    grid = np.arange(size + 1) / size
    uu = np.concatenate([u, [u[0] + 2 * np.pi]])
    u_at = np.stack([np.interp(grid, c, uu) for c in cum]) if len(cum) and with_u else None
    return cum, points, u_at, fine


def _lerp(table, x, period, rows=None):
    """Periodic linear interpolation of rows of `table` (rows, size[+1]) at `x` (rows, m), in
    cycles; `period` is added per whole cycle (0 for points, 2 pi for u). Row i of `x` reads
    row ``rows[i]`` of the table (default: row i)."""
    width = table.shape[1]
    size = width if period == 0 else width - 1
    turns = np.floor(x)
    f = (x - turns) * size
    j = np.minimum(f.astype(np.int64), size - 1)
    base = ((np.arange(table.shape[0]) if rows is None else np.asarray(rows)) * width)[:, None]
    flat = table.reshape(-1)
    low = np.take(flat, base + j)
    high = np.take(flat, base + ((j + 1) % size if period == 0 else j + 1))
    out = low + (f - j) * (high - low)
    return out + turns * period if period else out


def _u_to_length(cum, u):
    """Arc length (cycles, from u_0) at curve parameters `u` (rows, m)."""
    size = cum.shape[1] - 1
    g = (u - np.pi / size) / (2 * np.pi)
    return _lerp(cum, g, 1.0)


def arc_signatures(atlas, span, starts, base=1):
    """Window signatures of every atlas curve; cached on the atlas.

    `base` is the harmonic the windows are normalised on (`normal_form`): 1, or 2 for the
    second set that `query` compares arcs with a small first harmonic against (built on
    the first such query; as large again).

    An atlas read from a folder (`Atlas.from_parquet`) keeps them there too, in
    ``arcs/arcs-<span>-<starts>[-<base>].npz`` beside the Parquet parts, with a digest of
    its rows: a new process loads them instead of building them again (2 to 7 minutes at
    10^5 linkages), and a changed atlas (a part appended) builds them anew.

    Returns ``(sigs, norms, gaps)``: ``sigs`` (rows, starts + 1, 4 * ARC_HARMONICS)
    float16, window ``j`` covering the curve parameter from ``u_0 + 2 pi j / starts`` to
    that plus ``2 pi span``, in the normal form nearest the previous window's (window
    ``starts`` is window 0 again, tracked round the cycle); ``norms`` (rows, starts + 1)
    float32, their squared norms; ``gaps`` (rows, starts) float32, the squared distance
    from window j's signature to window j + 1's (the segment's length).
    """
    cache = atlas._arc_cache
    key = (float(span), int(starts)) if base == 1 else (float(span), int(starts), int(base))
    if key in cache:
        return cache[key]
    from mech.atlas._planar._store import load_arc_index, save_arc_index

    stored = load_arc_index(atlas, key)
    if stored is not None:
        cache[key] = stored
        return stored
    n = atlas.samples
    points = n // 2 + 1
    size = _WINDOW_TABLE
    # window `starts` is window 0 again, in the normal form tracked from window starts - 1,
    # so the last segment closes the path without a jump between normal forms
    first = (np.arange(starts + 1) * size) // starts
    last = first + int(round(span * size))
    f = np.linspace(0.0, 1.0, points)
    width = 4 * min(ARC_HARMONICS, atlas.harmonics)
    windows = starts + 1
    sigs = np.empty((len(atlas), windows, width), dtype=np.float16)
    for lo in range(0, len(atlas), _ROWS):
        rows = np.arange(lo, min(lo + _ROWS, len(atlas)))
        cum, table, _, fine = curve_tables(atlas.linkages.take(rows).columns(), size, with_u=False)
        x0 = cum[:, first]
        x1 = np.where(last[None, :] <= size, cum[:, np.minimum(last, size)], 1.0 + cum[:, last % size])
        x = x0[:, :, None] + (x1 - x0)[:, :, None] * f[None, None, :]
        arcs = _lerp(table, x.reshape(rows.size, -1), 0).reshape(rows.size * windows, points)
        # a window of no length (the coupler point still while u runs, as at a dead centre)
        # has no shape: it gets a signature far from any other
        still = ~(np.max(np.abs(arcs - arcs[:, :1]), axis=1) > 0.0) | np.repeat(~fine, windows)
        arcs = np.where(still[:, None], np.arange(points)[None, :], arcs)
        # the first harmonics only (the normalisation uses all of them, so these are the
        # first entries of the full signature)
        form = normal_form(_close_arc(arcs), width // 4, base)
        cands = form.candidates.reshape(rows.size, windows, form.candidates.shape[1], width)
        out = np.empty((rows.size, windows, width))
        out[:, 0] = cands[np.arange(rows.size), 0, form.chosen.reshape(rows.size, windows)[:, 0]]
        for j in range(1, windows):
            pick = np.argmin(np.sum((cands[:, j] - out[:, j - 1, None, :]) ** 2, axis=2), axis=1)
            out[:, j] = cands[np.arange(rows.size), j, pick]
        out[still.reshape(rows.size, windows)] = _FAR
        sigs[rows] = out
    wide = sigs.astype(np.float32)
    norms = np.sum(wide * wide, axis=2)
    gaps = np.sum((wide[:, 1:] - wide[:, :-1]) ** 2, axis=2)
    cache[key] = (sigs, norms, gaps)
    save_arc_index(atlas, key, cache[key])
    return cache[key]


def window_distances(sigs, norms, gaps, candidates, second=False):
    """Per row: the least distance from any of the target's `candidates` (4 or 8, D) to the
    polyline through its window signatures, the window j of that segment and the fraction
    (0..1) along it towards window j + 1.

    With `second`, also the window and fraction of the best segment at least an eighth of
    the cycle away from the first (a second start for the alignment: a folded arc, traced
    out and back, can look alike from two starts, and the path of its windows' signatures
    bends sharply near the true one, so a grid segment may miss it by more than a wrong
    start's)."""
    rows, windows, width = sigs.shape
    c = np.asarray(candidates, dtype=np.float32)
    cc = np.sum(c.astype(np.float64) ** 2, axis=1).astype(np.float32)
    best = np.empty(rows)
    where = np.empty(rows, dtype=np.int64)
    frac = np.empty(rows)
    where2, frac2 = np.empty(rows, dtype=np.int64), np.empty(rows)
    steps = windows - 1
    apart = np.abs(np.arange(steps)[:, None] - np.arange(steps)[None, :])
    near = np.minimum(apart, steps - apart) < max(1, steps // 8)
    for lo in range(0, rows, _BLOCK):
        block = slice(lo, min(lo + _BLOCK, rows))
        s = sigs[block].astype(np.float32)
        b = s.shape[0]
        # einsum, not a BLAS product (memory-bound; a threaded BLAS only adds wake-ups)
        d2 = norms[block, :, None] - 2.0 * np.einsum("ijk,lk->ijl", s, c) + cc
        d2 = np.maximum(d2, 0.0)
        e2 = gaps[block, :, None]
        here = d2[:, :-1]
        half = 0.5 * (d2[:, 1:] - here - e2)                      # (S_j+1 - S_j) . (S_j - T)
        lam = np.clip(-half / np.maximum(e2, 1e-30), 0.0, 1.0)
        seg = here + lam * (2.0 * half + lam * e2)
        flat = seg.reshape(b, -1)
        k = np.argmin(flat, axis=1)
        best[block] = flat[np.arange(b), k]
        where[block] = k // seg.shape[2]
        frac[block] = lam.reshape(b, -1)[np.arange(b), k]
        if second:
            pick = np.argmin(seg, axis=2)                           # best candidate per segment
            per = np.take_along_axis(seg, pick[:, :, None], 2)[:, :, 0]
            per = np.where(near[where[block]], np.inf, per)
            j2 = np.argmin(per, axis=1)
            where2[block] = j2
            frac2[block] = lam[np.arange(b), j2, pick[np.arange(b), j2]]
    if second:
        return np.sqrt(np.maximum(best, 0.0)), where, frac, where2, frac2
    return np.sqrt(np.maximum(best, 0.0)), where, frac


def _fit_tables(targets, table, rows, x0, x1):
    """Fit arcs [x0, x1] (arc length in cycles) read from rows `rows` of `table` onto the
    centred targets `targets` (one per arc, m points each) at m equal steps.
    Returns (RMS error, w, centroid, points) per arc."""
    m = targets.shape[1]
    f = np.linspace(0.0, 1.0, m)
    z = _lerp(table, x0[:, None] + (x1 - x0)[:, None] * f[None, :], 0, rows)
    centroid = z.mean(axis=1)
    a = z - centroid[:, None]
    den = np.einsum("ij,ij->i", a.real, a.real) + np.einsum("ij,ij->i", a.imag, a.imag)
    w = np.einsum("ij,ij->i", a.conj(), targets) / np.where(den > 0.0, den, 1.0)
    r = targets - w[:, None] * a
    err = np.sqrt((np.einsum("ij,ij->i", r.real, r.real) + np.einsum("ij,ij->i", r.imag, r.imag)) / m)
    return np.where(den > 0.0, err, np.inf), w, centroid, z


#: The moves of the pattern search: either end, both together, both apart.
_MOVES = np.array([(1, 1), (-1, -1), (1, 0), (-1, 0), (0, 1), (0, -1), (-1, 1), (1, -1)], dtype=float)


def align_arcs(t, linkages, u0, u1, step, levels=_LEVELS, size=_TABLE):
    """Best sub-arc [u0, u1] and direction of each linkage's curve for the open target `t`.

    A pattern search from the given ends (arrays over rows): at each round every row takes
    the best of eight moves (either end, both together, both apart) by `step` (a fraction
    of the curve's length), if it helps; the step is halved `levels` times. Both directions
    of the target run side by side; every trial reads the curve from its table at equal
    arc-length steps (`size` per cycle), all rows and moves in one evaluation.
    Returns (error, w, centroid, points, u0, u1, direction) per row, for the better way.
    """
    rows = len(linkages)
    cum, table, u_at, fine = curve_tables(linkages.columns(), size)
    X0 = _u_to_length(cum, np.asarray(u0, float)[:, None])[:, 0]
    X1 = _u_to_length(cum, np.asarray(u1, float)[:, None])[:, 0]
    X1 = np.where(X1 <= X0, X1 + 1.0, X1)
    X0, X1 = np.concatenate([X0, X0]), np.concatenate([X1, X1])
    tc = t - t.mean()
    which = np.concatenate([np.arange(rows), np.arange(rows)])          # table row of each trial
    targets = np.concatenate([np.broadcast_to(tc, (rows, t.size)), np.broadcast_to(tc[::-1], (rows, t.size))])
    err = _fit_tables(targets, table, which, X0, X1)[0]
    moves = len(_MOVES)
    many_rows, many_targets = np.tile(which, moves), np.tile(targets, (moves, 1))
    for _ in range(levels):
        for _ in range(_ROUNDS):
            a = (X0[None, :] + _MOVES[:, :1] * step).ravel()
            b = (X1[None, :] + _MOVES[:, 1:] * step).ravel()
            ok = (b - a > 1e-6) & (b - a <= 1.0)
            e = np.where(ok, _fit_tables(many_targets, table, many_rows, a, b)[0], np.inf).reshape(moves, -1)
            k = np.argmin(e, axis=0)
            col = np.arange(e.shape[1])
            better = e[k, col] < err
            if not better.any():
                break
            X0 = np.where(better, a.reshape(moves, -1)[k, col], X0)
            X1 = np.where(better, b.reshape(moves, -1)[k, col], X1)
            err = np.where(better, e[k, col], err)
        step = step * 0.5
    e, w, centroid, z = _fit_tables(targets, table, which, X0, X1)
    pick = e[:rows] <= e[rows:]
    both = slice(0, rows), slice(rows, 2 * rows)
    e, w, centroid = (np.where(pick, x[both[0]], x[both[1]]) for x in (e, w, centroid))
    e = np.where(fine, e, np.inf)
    direction = np.where(pick, 1, -1)
    # the reversed target was fitted with its points reversed: turn the points back
    z = np.where(pick[:, None], z[both[0]], z[both[1]][:, ::-1])
    X0, X1 = np.where(pick, X0[both[0]], X0[both[1]]), np.where(pick, X1[both[0]], X1[both[1]])
    U0 = _lerp(u_at, X0[:, None], 2 * np.pi)[:, 0]
    U1 = _lerp(u_at, X1[:, None], 2 * np.pi)[:, 0]
    return e, w, centroid, z, U0, U1, direction
