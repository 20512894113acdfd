"""Search a spherical atlas for the four-bars whose coupler curves look like a target on the sphere.

Closed targets: the signature stage ranks every entry by the distance of its signature to the
target's; the alignment stage takes a short list and finds, for every start and both
directions, the best rotation of the sphere (the SVD solution of the orthogonal Procrustes
problem, Kabsch's method), with all starts at once through FFT cross-correlations.

Open arcs are searched by `mech.atlas._sphere._arcs` (called from `query_sphere`).

`refine_sphere` improves a match by optimisation (SciPy's Nelder-Mead, imported when called)
of the four arcs and the coupler point on the real curve error; `find_sphere_linkages`
refines the best few matches and keeps the best.
"""

import dataclasses

import numpy as np

from mech._validate import _show, bool_flag, instance, integer, nonnegative_number, real_number
from mech.atlas._sphere._arcs import query_arc
from mech.atlas._sphere._fit import SphereMatch, _kabsch, _kabsch_all_starts, _match, _radius
from mech.atlas._sphere._sampling import describe_sphere, sphere_curves
from mech.atlas._sphere._signature import _resample_closed, _signature_rows, _sphere_curves
from mech.atlas._sphere._store import SphereAtlas, spectra

__all__ = ["find_sphere_linkages", "query_sphere", "refine_sphere"]

#: Sub-steps of the start tried by the exact alignment of a closed target.
_PHASES = 4
#: Fresh starts of the simplex of `refine_sphere` after the first search stops.
_RESTARTS = 3


def _closed_fits(curves, t, keep=None, levels=8):
    """Align closed curves (rows, M, 3, at equal steps of the curve parameter) with the target t.

    The curves are resampled at `_PHASES` N equal steps of length; every start on that grid
    and both directions are tried at once (FFT and `_rotation_gain`); then, for the best
    `keep` rows (all by default), the start is refined by bisection between grid points on
    the exact error. Returns (RMS error, rotation, direction, turned curve at the target's N
    points) per row.
    """
    n = t.shape[0]
    fine = _resample_closed(curves, _PHASES * n)
    best = None
    for direction in (1, -1):
        way = fine if direction == 1 else fine[:, ::-1]
        for phase in range(_PHASES):
            sq, _, s = _kabsch_all_starts(way[:, phase::_PHASES], t)
            cand = (sq, s * _PHASES + phase, np.full(sq.shape, direction))
            if best is None:
                best = cand
                continue
            better = sq < best[0]
            best = tuple(np.where(better, x, y) for x, y in zip(cand, best))
    sq, offset, direction = best
    ways = np.where((direction == 1)[:, None, None], fine, fine[:, ::-1])
    big = _PHASES * n
    start = offset / big
    steps = np.arange(n) / n

    def fit(rows, f):
        # between the resampled points by their index (they are at equal steps of length)
        x = np.mod(f[:, None] + steps[None, :], 1.0) * big
        j = np.minimum(x.astype(int), big - 1)
        w = (x - j)[..., None]
        r = rows[:, None]
        pts = (1.0 - w) * ways[r, j] + w * ways[r, (j + 1) % big]
        err, rot = _kabsch(pts, t[None])
        return err, rot, pts

    err = np.sqrt(np.maximum(sq, 0.0) / n)
    top = np.argsort(err, kind="stable")[:len(err) if keep is None else keep]
    step = 0.5 / (_PHASES * n)
    for _ in range(levels):
        for trial in (start[top] - step, start[top] + step):
            e = fit(top, trial)[0]
            better = e < err[top]
            start[top] = np.where(better, trial, start[top])
            err[top] = np.where(better, e, err[top])
        step *= 0.5
    err, rot, pts = fit(np.arange(len(err)), start)
    return err, rot, direction, np.einsum("rjp,rqp->rjq", pts, rot)


def _target(target, closed):
    x = _sphere_curves(target, "target")
    if x.ndim != 2:
        raise ValueError(f"Expected one curve in `target`, got shape {x.shape}")
    # a target of one point has no size to measure the error against; points that differ by a
    # few units of rounding after scaling to the sphere are one point
    if not np.max(np.linalg.norm(x - x[0], axis=1)) > 8.0 * np.finfo(float).eps:
        raise ValueError(f"Expected `target` that are not all equal (on the unit sphere), got {_show(target)}")
    return x


def query_sphere(atlas, target, *, k=5, shortlist=64, resampled=False, closed=True, span=0.5, starts=64):
    """Find the spherical four-bars of an atlas whose coupler curves best match a target on the sphere.

    Parameters
    ----------
    atlas : SphereAtlas
    target : array_like, shape (m, 3)
        Points along a closed curve (or an open arc) on the sphere, any rotation of the
        sphere, start and direction (nonzero vectors, scaled to unit length).
    k, shortlist : int, optional
        Matches returned, and entries aligned exactly after the signature stage.
    resampled : bool, optional
        True if a closed `target` is already at equal steps of length (used as given).
    closed : bool, optional
        False for an open arc, matched against parts of the atlas's closed curves.
    span : float, optional
        For an open arc: the fraction of a closed curve's parameter it is expected to
        cover, in (0, 1] (the alignment frees both ends).
    starts : int, optional
        For an open arc: sub-arcs per closed curve in the signature stage (their
        signatures are cached on the atlas: ``12 (K + 1) starts`` bytes per linkage, 69 MB
        for 10^4 linkages at the defaults). Fewer starts are quicker but may miss the row.

    Returns
    -------
    list of SphereMatch
        Best first, by the RMS distance after the best rotation, start and direction.

    Notes
    -----
    Signatures: :ref:`deriv-sphere-signature`. The rotation is Kabsch's SVD solution;
    mirror images have equal signatures but are told apart by it (it is proper).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.atlas import build_sphere_atlas, query_sphere
    >>> atlas = build_sphere_atlas(100, seed=2)
    >>> q, _ = np.linalg.qr(np.random.default_rng(3).normal(size=(3, 3)))
    >>> q *= np.linalg.det(q)                                           # a proper rotation
    >>> target = np.roll(atlas.curves(7, 300)[0], 30, axis=0)[::-1] @ q.T
    >>> best = query_sphere(atlas, target, k=2)[0]
    >>> best.index, best.error < 1e-3, bool(np.allclose(best.rotation, q, atol=1e-2))
    (7, True, True)
    """
    instance("atlas", atlas, SphereAtlas)
    k = integer("k", k, minimum=1, maximum=10**4)
    shortlist = integer("shortlist", shortlist, minimum=1, maximum=10**5)
    resampled = bool_flag("resampled", resampled)
    closed = bool_flag("closed", closed)
    span = real_number("span", span)
    if not 0.0 < span <= 1.0:
        raise ValueError(f"Expected `span` in (0, 1], got {span!r}")
    starts = integer("starts", starts, minimum=1, maximum=1024)
    if k > shortlist:
        raise ValueError(f"Expected `k` <= shortlist = {shortlist}, got {k}")
    x = _target(target, closed)
    if not closed:
        return query_arc(atlas, x, k, shortlist, span, starts)
    n, harmonics = atlas.samples, atlas.harmonics
    if resampled and x.shape[0] <= 2 * harmonics:
        raise ValueError(f"Expected more than {2 * harmonics} points in a resampled `target`, got {x.shape[0]}")
    t = x if resampled else _resample_closed(x[None], n)[0]
    sig = _signature_rows(t[None], harmonics)[0]
    dist = np.sqrt(np.sum((atlas.signatures - sig) ** 2, axis=1))
    m = min(shortlist, len(atlas))
    short = np.argpartition(dist, m - 1)[:m] if m < len(atlas) else np.arange(len(atlas))
    if m < len(atlas):
        # a few more by the rotation spectrum, which needs no principal frame: a curve with two
        # nearly equal moments has an unsteady frame, and noise can move its signature far
        power = np.sqrt(np.sum((atlas._spectra - spectra(sig)) ** 2, axis=1))
        extra = min(max(m // 4, 1), len(atlas) - m)
        power[short] = np.inf
        short = np.concatenate([short, np.argpartition(power, extra - 1)[:extra]])
    err, rot, direction, turned = _closed_fits(atlas.curves(short, 4 * t.shape[0]), t, keep=max(k, 8))
    radius = _radius(t)
    rows = atlas.linkages.take(short)
    return [_match(rank, int(short[j]), rows.take([j]), rot[j], direction[j], err[j], radius, dist[short[j]],
                   turned[j])
            for rank, j in enumerate(np.argsort(err, kind="stable")[:k])]


# ---------------------------------------------------------------------------- refinement
def _objective(t, branch, samples):
    def f(p):
        a, b, c, d, r, gamma = p
        if not (0.0 < min(a, b, c, d, r) and max(a, b, c, d, r) < np.pi):
            return np.inf
        row = describe_sphere([a], [b], [c], [d], [r], [gamma], [branch])
        if not row.usable[0]:
            return np.inf
        curve = sphere_curves(row.columns(), 4 * samples)
        if not np.all(np.isfinite(curve)):
            return np.inf
        return float(_closed_fits(curve, t, levels=4)[0][0])

    return f


def refine_sphere(match, target, *, samples=96, iterations=600):
    """Refine a closed-curve match by optimisation on the real curve error.

    The four arcs and the coupler point ``(r, gamma)`` of the matched linkage are moved by
    SciPy's Nelder-Mead search (imported when called) to reduce the RMS distance between
    the target and the coupler curve after the best rotation of the sphere, start and
    direction (computed afresh at every step); the branch is kept.

    Parameters
    ----------
    match : SphereMatch
        A result of `query_sphere` for a closed target.
    target : array_like, shape (m, 3)
        The closed target given to `query_sphere`.
    samples : int, optional
        Equal steps of length at which the curves are compared.
    iterations : int, optional
        Largest number of simplex iterations.

    Returns
    -------
    SphereMatch
        ``refined=True``, with the refined linkage (`fourbar`), its placement on the target
        (`placed`, ``frame=rotation``), its error, type and minimum transmission angle; the
        starting match if no better linkage was found.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.atlas import build_sphere_atlas, query_sphere, refine_sphere
    >>> from mech.spherical import SphericalFourBar
    >>> t = np.linspace(0, 2 * np.pi, 300, endpoint=False)
    >>> target = SphericalFourBar(0.4, 1.0, 0.8, 1.1, coupler=(0.5, 0.6)).solve(t).P    # not in the atlas
    >>> first = query_sphere(build_sphere_atlas(1000, seed=3), target, k=1)[0]
    >>> better = refine_sphere(first, target, iterations=200)
    >>> better.refined, better.error < first.error
    (True, True)
    """
    from scipy.optimize import minimize

    instance("match", match, SphereMatch)
    samples = integer("samples", samples, minimum=16, maximum=1 << 14)
    iterations = integer("iterations", iterations, minimum=1, maximum=10**6)
    x = _target(target, True)
    if match.arc is not None:
        raise ValueError(f"Expected `match` of a closed target (arc None), got arc = {match.arc!r}")
    t = _resample_closed(x[None], samples)[0]
    f = match.fourbar
    p0 = np.array([f.a, f.b, f.c, f.d, *f.coupler], dtype=float)
    objective = _objective(t, f.branch, samples)
    start = objective(p0)
    if not np.isfinite(start):
        return match
    # Nelder-Mead restarted with a fresh simplex from where it stopped, while that helps: a
    # collapsed simplex often stops short on this objective (it has ridges where the type
    # or the best start of the alignment changes)
    best_x, best_f, left, size = p0, start, iterations, 0.05
    for _ in range(_RESTARTS + 1):
        simplex = np.vstack([best_x, best_x + size * np.eye(6)])
        result = minimize(objective, best_x, method="Nelder-Mead",
                          options={"maxiter": left, "initial_simplex": simplex, "xatol": 1e-7, "fatol": 1e-10})
        left -= int(result.nit)
        improved = result.fun < best_f
        if improved:
            gain = (best_f - result.fun) / best_f
            best_x, best_f = result.x, float(result.fun)
        if left <= 0 or not improved or gain < 1e-2:
            break
        size *= 0.5
    if not best_f < start:
        return match
    a, b, c, d, r, gamma = best_x
    row = describe_sphere([a], [b], [c], [d], [r], [np.angle(np.exp(1j * gamma))], [f.branch])
    err, rot, direction, turned = _closed_fits(sphere_curves(row.columns(), 4 * samples), t)
    return _match(match.rank, match.index, row, rot[0], direction[0], err[0], _radius(t), match.distance,
                  turned[0], refined=True)


def find_sphere_linkages(atlas, target, *, starts=4, goal=None, samples=96, iterations=600):
    """Find spherical four-bars tracing a closed target: query an atlas, refine from several starts.

    The best `starts` matches of `query_sphere` are each refined by `refine_sphere` (until
    one reaches `goal`, a `relative_error`, if given); the refined matches are returned
    best first.

    Parameters
    ----------
    atlas : SphereAtlas
    target : array_like, shape (m, 3)
        A closed curve on the sphere.
    starts : int, optional
        Matches refined, in [1, 64].
    goal : float, optional
        Stop once a refined match has a `relative_error` at most this.
    samples, iterations : int, optional
        Passed to `refine_sphere`.

    Returns
    -------
    list of SphereMatch
        Refined matches, best first, ranked again from 0.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.atlas import build_sphere_atlas, find_sphere_linkages
    >>> from mech.spherical import SphericalFourBar
    >>> t = np.linspace(0, 2 * np.pi, 300, endpoint=False)
    >>> target = SphericalFourBar(0.4, 1.0, 0.8, 1.1, coupler=(0.5, 0.6)).solve(t).P
    >>> best = find_sphere_linkages(build_sphere_atlas(1000, seed=3), target, starts=2, iterations=200)[0]
    >>> best.rank, best.refined
    (0, True)
    """
    starts = integer("starts", starts, minimum=1, maximum=64)
    if goal is not None:
        goal = nonnegative_number("goal", goal)
    out = []
    for match in query_sphere(atlas, target, k=starts, shortlist=max(64, starts)):
        out.append(refine_sphere(match, target, samples=samples, iterations=iterations))
        if goal is not None and out[-1].relative_error <= goal:
            break
    out.sort(key=lambda m: m.error)
    return [dataclasses.replace(m, rank=r) for r, m in enumerate(out)]
