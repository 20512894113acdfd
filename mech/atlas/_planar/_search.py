"""Search an atlas for the four-bars whose coupler curves look like a target (issue 13, item 4).

Two stages. The signature stage ranks every atlas entry by the distance from its signature
to the nearest of the target's four normal forms (brute force on NumPy blocks). The
alignment stage takes a short list from it, rebuilds each curve, and finds the similarity,
start and direction that bring it closest to the target, by FFT cross-correlation over all
starts (band-limited interpolation between samples) and then bisection of the start on the
exact error; it ranks by the remaining RMS distance and places each linkage, and its two
Roberts-Chebyshev cognates, on the target. `refine` improves a match by optimisation.
"""

from dataclasses import dataclass, replace

import numpy as np

from mech._validate import bool_flag, instance, integer, planar_points, real_number
from mech.atlas._planar._signature import _close_arc, _curves, _resample_rows, normal_form
from mech.atlas._planar._store import Atlas
from mech.planar.kinematics._fourbar import FourBar

__all__ = ["Match", "PlacedLinkage", "PlacedSliderCrank", "query"]

_BLOCK = 1 << 15
#: The index is used when the short list is below this fraction (1/_ANN_SHARE) of the atlas.
_ANN_SHARE = 64
_UPSAMPLE = 16
_DENSE = 4
_REFINE = 8
#: An open arc: rows given a coarse alignment, per row of the short list, and its halvings.
_ARC_WIDER = 4
_ARC_COARSE = 4
#: An open arc whose |c_1| is below this fraction of its RMS radius is also compared with
#: the window signatures normalised on c_2.
_ARC_SMALL_FIRST = 0.25
#: Points per cycle of the curve tables of the coarse alignment.
_COARSE_TABLE = 512
_LEVELS = 6


class _Placed:
    """The similarity shared by PlacedLinkage and PlacedSliderCrank (fields `origin`, `rotation`)."""

    def place(self, z):
        """Map standard-frame points `z` into the target's frame: ``origin + exp(1j*rotation)*z``."""
        return self.origin + np.exp(1j * self.rotation) * planar_points("z", z)


@dataclass(frozen=True)
class PlacedLinkage(_Placed):
    """A four-bar in its standard frame and the similarity that places it on the target.

    Attributes
    ----------
    name : str
        "ABCD" for the match itself, "AEGK" and "DFHK" for its cognates (Fig. 2-32).
    fourbar : FourBar
        The linkage at the target's scale, in its standard frame (A = 0, D = d on +x).
    origin : complex
        Where the crank pivot A lies in the target's frame.
    rotation : float
        Angle of the ground line A->D in the target's frame, radians.
    """

    name: str
    fourbar: FourBar
    origin: complex
    rotation: float

    @property
    def pivots(self):
        """The two ground pivots A and D in the target's frame."""
        return self.origin, self.origin + np.exp(1j * self.rotation) * self.fourbar.d


@dataclass(frozen=True)
class PlacedSliderCrank(_Placed):
    """A slider-crank with a coupler point, in its standard frame, and the similarity that places it.

    Attributes
    ----------
    name : str
        "slider-crank" for the match itself, "cognate" for its Roberts cognate.
    slider : SliderCrank
        The linkage at the target's scale in its standard frame (crank pivot A = 0, guide
        the line y = e run in +x), as `mech.planar.SliderCrank`.
    coupler : (float, float)
        The coupler point ``(p, q)`` on the rod at the target's scale,
        ``P = B + (p + 1j*q) * exp(1j*phi)``.
    origin : complex
        Where the crank pivot A lies in the target's frame.
    rotation : float
        Angle of the guide's +x direction in the target's frame, radians.
    """

    name: str
    slider: object
    coupler: tuple
    origin: complex
    rotation: float

    @property
    def pivots(self):
        """The crank pivot A in the target's frame (one ground pivot)."""
        return (self.origin,)

    @property
    def guide(self):
        """The guide line in the target's frame as ``(point, direction)``; the foot of the
        perpendicular from A and a unit complex number along +x of the standard frame."""
        turn = np.exp(1j * self.rotation)
        return complex(self.origin + turn * 1j * self.slider.e), complex(turn)


@dataclass(frozen=True)
class Match:
    """One linkage found by `query`, placed on the target.

    Attributes
    ----------
    rank : int
        0 for the best match.
    index : int
        Its row in the atlas.
    linkage : PlacedLinkage or PlacedSliderCrank
        The match, scaled and placed so that its coupler curve lies on the target (a
        `PlacedSliderCrank` for an atlas of slider-cranks).
    cognates : tuple of PlacedLinkage
        Its two Roberts-Chebyshev cognates AEGK and DFHK, placed on the target (they trace
        the same curve); empty if the coupler point lies on a pin (no cognates). For a
        slider-crank, its one cognate slider-crank (Roberts' law), a `PlacedSliderCrank`
        named "cognate"; the four-bar's second cognate degenerates there.
    direction : int
        +1 if the target is run in the direction of the stored curve (input angle
        increasing along the curve as sampled), -1 if against it.
    error : float
        RMS distance between the target and the placed coupler curve, both at equal
        arc-length steps and best aligned, in the target's units.
    relative_error : float
        `error` over the RMS distance of the target from its centroid.
    distance : float
        Distance of the signatures (the first stage's ranking).
    kind : str
        Grashof type.
    gamma_min : float
        Smallest transmission angle over the input range, radians.
    full_turn : bool
        True if the crank turns fully; otherwise it rocks over `theta_range`.
    theta_range : (float, float)
        Input range, radians.
    curve : ndarray of complex, shape (samples,)
        The placed coupler curve at the atlas's equal arc-length steps (for drawing).
    refined : bool
        True for a match returned by `refine` (its linkage is no longer the atlas row
        `index`, from which the refinement started).
    arc : (float, float) or None
        For an open target, the part of the closed coupler curve that matches it, as the
        curve parameter u at its two ends (the input angle for a crank that turns fully;
        see `FourBarSamples.curves`), with `direction` telling which end the target starts
        at; None for a closed target.
    """

    rank: int
    index: int
    linkage: PlacedLinkage
    cognates: tuple
    direction: int
    error: float
    relative_error: float
    distance: float
    kind: str
    gamma_min: float
    full_turn: bool
    theta_range: tuple
    curve: np.ndarray
    refined: bool = False
    arc: tuple = None


def slider_cognate(placed):
    """The Roberts cognate of a placed slider-crank: one slider-crank tracing the same curve.

    With ``w = (p + i q) / b``, the coupler point is ``P = B + w (C - B)`` (standard frame).
    The parallelogram A, B, P, E gives a crank ``E = w (C - B)`` about A, and the point
    ``F = w C`` of the link EP runs on the line ``w (x + i e)``: the original guide turned
    by ``arg w`` and scaled by ``|w|``. In its own frame (turned by ``arg w``) the cognate
    has crank ``|w| b``, rod ``|w| a``, offset ``|w| e`` and coupler point
    ``a conj(w) / |w|`` on its rod EF; driven at the original rod's angle ``phi`` it puts
    its coupler point on P, pose by pose. Its rod turns with the original crank, so a
    cognate of a crank that turns fully rocks (``|w| a < |w| b + |w e|``) and changes
    assembly branch at its dead centres (branch ``sign(cos theta)``, theta the original
    crank angle); the second four-bar cognate degenerates (both pivots at infinity).

    Returns
    -------
    tuple of PlacedSliderCrank
        One cognate named "cognate", placed on the same target; empty if P lies on the
        crank pin B (``w = 0``).
    """
    from mech.planar.kinematics._slider_crank import SliderCrank

    sc = placed.slider
    w = complex(*placed.coupler) / sc.b
    m = abs(w)
    if m < 1e-12:
        return ()
    cog = SliderCrank(m * sc.b, m * sc.a, m * sc.e, branch=1)
    coupler = (float(sc.a * w.real / m), float(-sc.a * w.imag / m))
    return (PlacedSliderCrank("cognate", cog, coupler, placed.origin, float(placed.rotation + np.angle(w))),)


def _signature_distances(signatures, norms, candidates):
    """Smallest distance from each row of `signatures` to any of `candidates` (4, D)."""
    out = np.empty(signatures.shape[0])
    cc = np.sum(candidates**2, axis=1)
    for start in range(0, signatures.shape[0], _BLOCK):
        block = slice(start, start + _BLOCK)
        # einsum, not a BLAS product: a (rows, 32) x (32, 4) product is memory-bound, and
        # a threaded BLAS spends more on waking its threads than on the arithmetic
        d2 = norms[block, None] - 2.0 * np.einsum("ij,kj->ik", signatures[block], candidates) + cc[None, :]
        out[block] = np.min(d2, axis=1)
    return np.sqrt(np.maximum(out, 0.0))


def _align(target, curves):
    """Best start and direction of each curve against the target (all rows of N samples).

    By FFT cross-correlation over all starts, `_UPSAMPLE` per sample step (band-limited
    interpolation): returns the direction (+1, -1) and the start, as a fraction of the
    curve's length, that maximise the correlation, per row.
    """
    n = target.shape[0]
    T = np.fft.fft(target - target.mean())
    k = np.fft.fftfreq(n, 1.0 / n).astype(int)
    keep = np.abs(k) < n // 2 if n % 2 == 0 else np.ones(n, bool)
    best = []
    for direction in (1, -1):
        z = curves if direction == 1 else np.roll(curves[:, ::-1], 1, axis=1)
        a = z - z.mean(axis=1)[:, None]
        A = np.fft.fft(a, axis=1)
        X = np.zeros((a.shape[0], n * _UPSAMPLE), dtype=complex)
        X[:, k[keep] % (n * _UPSAMPLE)] = np.conj(A[:, keep]) * T[keep]
        r = np.abs(np.fft.fft(X, axis=1))            # |sum_j conj(a[j + s/U]) t[j]| over s
        s = np.argmax(r, axis=1)
        best.append((r[np.arange(a.shape[0]), s] / np.sqrt(np.sum(np.abs(a) ** 2, axis=1)), s))
    pick = best[0][0] >= best[1][0]
    direction = np.where(pick, 1, -1)
    start = np.where(pick, best[0][1], best[1][1]) / (n * _UPSAMPLE)
    return direction, start


def _fit(target, dense, direction, start):
    """Similarity of each dense curve, run in `direction` from `start`, onto the target.

    Returns (RMS error, w, centroid, RMS radius of the target, z) per row: target point j
    is nearest ``centroid(target) + w * (z_j - centroid)``, z_j the curve's j-th equal
    arc-length point from `start` (the rows of z).
    """
    n = target.shape[0]
    oriented = np.where(direction[:, None] == 1, dense, np.roll(dense[:, ::-1], 1, axis=1))
    z = _resample_rows(oriented, n, True, offset=start)
    centroid = z.mean(axis=1)
    a = z - centroid[:, None]
    t = target - target.mean()
    w = np.einsum("ij,j->i", a.conj(), t) / np.sum(np.abs(a) ** 2, axis=1)
    err = np.sqrt(np.mean(np.abs(t[None, :] - w[:, None] * a) ** 2, axis=1))
    return err, w, centroid, np.sqrt(np.mean(np.abs(t) ** 2)), z


def _scaled(a, b, c, d, p, q, branch, s):
    return FourBar(a * s, b * s, c * s, d * s, branch=branch, coupler=(p * s, q * s))


def _placed_cognates(fourbar, origin, w):
    from mech.planar.coupler._cognates import cognates

    try:
        trio = cognates(fourbar)
    except ValueError:                      # the coupler point on a pin: no cognates
        return ()
    out = []
    for cog in (trio.aegk, trio.dfhk):
        f = cog.fourbar
        out.append(PlacedLinkage(cog.name, _scaled(f.a, f.b, f.c, f.d, *f.coupler, f.branch, abs(w)),
                                 complex(origin + w * cog.origin), float(np.angle(w * cog.rotation))))
    return tuple(out)


def query(atlas, target, *, k=5, shortlist=64, resampled=False, closed=True, span=0.5, starts=64):
    """Find the four-bars of an atlas whose coupler curves best match a target curve or arc.

    Parameters
    ----------
    atlas : Atlas
        The atlas to search (`build_atlas`, `Atlas.from_parquet`).
    target : array_like, complex, shape (m,)
        Points ``x + 1j*y`` along a closed curve (m >= 3) or an open arc (m >= 2), in
        order; any placement, size, start and direction (read a CSV file with
        `read_points`).
    k : int, optional
        Number of matches returned, 1 <= k <= shortlist.
    shortlist : int, optional
        Entries taken from the signature stage to the exact alignment stage (for an open
        arc, four times as many get a coarse alignment first).
    resampled : bool, optional
        True if a closed `target` is already at equal arc-length steps (used as given).
    closed : bool, optional
        False for an open arc, matched against parts of the atlas's closed curves.
    span : float, optional
        For an open arc: the fraction of a closed curve's cycle (of its curve parameter,
        the input angle for a crank that turns fully) the arc is expected to cover, in
        (0, 1]; it places the sub-arcs of the signature stage, and the alignment frees it.
    starts : int, optional
        For an open arc: windows (sub-arcs) per closed curve in the signature stage. Their
        signatures, four harmonics per side in float16, are computed on the first open
        query and kept with the atlas: about ``40 * starts`` bytes per linkage with their
        squared norms and gaps, 26 MB for 10^4 linkages at the default (260 MB for 10^5).
        Fewer starts save memory but rank the right linkage lower.

    Returns
    -------
    list of Match
        Best first, by the RMS distance between the target and the placed coupler curve.

    Raises
    ------
    ValueError
        For a target that is not finite points, has fewer than 3 or all equal, whose
        matches would have lengths beyond the float range, or bad options (named).

    Notes
    -----
    The search runs on the target divided by the power of two of its largest coordinate
    and multiplies the lengths of the matches back, so a target in any unit of length
    (1e-300 to 1e300) gives the same rows and relative errors. The signature stage compares each atlas signature with all four normal forms of the
    target (:ref:`deriv-shape-signature`), so it needs no tie-break; the alignment stage
    then removes the normalisation's sensitivity (a nearly circular first harmonic) by
    aligning exactly. Matches are linkages of the atlas scaled, turned and moved; their
    cognates trace the same curve with other pivots. An open arc is compared with the
    signatures of windows of each closed curve (the arc run forward and back), through
    the distance to the segment between neighbouring windows' signatures, then aligned
    by a pattern search on the two ends of the sub-arc; its matches carry `arc`. When
    the arc's first harmonic is small (``|c_1|`` below a quarter of its RMS radius: an arc that
    folds back on itself), the normalisation on c_1 is ill-conditioned: such an arc is also
    compared with a second set of window signatures, normalised on c_2 (built on the first
    such query, as large as the first set), whose short list is aligned from two starts
    per row (:ref:`deriv-shape-signature`).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.atlas import build_atlas, query
    >>> atlas = build_atlas(300, seed=2)
    >>> curve = atlas.curves(17)[0]                     # a curve of the atlas, moved
    >>> target = 5 + 2j + 3 * np.exp(1j) * np.roll(curve, 40)[::-1]
    >>> best = query(atlas, target, k=3)[0]
    >>> best.index, best.relative_error < 1e-2
    (17, True)
    >>> len(best.cognates)
    2
    """
    instance("atlas", atlas, Atlas)
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
    z, lead, scale = _curves(target, closed, "target", scaled=True)
    if lead != (1,) and lead != ():
        raise ValueError(f"Expected one curve in `target`, got shape {np.shape(target)}")
    # the search runs on the target divided by a power of two (its largest coordinate in
    # [1, 2)); lengths of the matches are multiplied back, exactly, at the end
    if not closed:
        return [_rescaled(m, float(scale[0])) for m in _query_arc(atlas, z, k, shortlist, span, starts)]
    return [_rescaled(m, float(scale[0])) for m in _query_closed(atlas, z, k, shortlist, resampled)]


def _rescaled(match, s):
    """`match` with its lengths (linkages, placement, error, curve) multiplied by `s`."""
    if s == 1.0:
        return match
    placed = (match.linkage, *match.cognates)
    sizes = [max(abs(p.slider.a), abs(p.slider.b), abs(p.slider.e), *map(abs, p.coupler)) if hasattr(p, "slider")
             else max(p.fourbar.a, p.fourbar.b, p.fourbar.c, p.fourbar.d, *map(abs, p.fourbar.coupler)) for p in placed]
    if not np.isfinite(max(sizes) * s) or not np.isfinite(abs(match.linkage.origin) * s):
        raise ValueError(f"Expected `target` small enough that its matches fit in floating point, got a target "
                         f"whose match of rank {match.rank} has a link or pivot {max(sizes):.6g} * {s:.6g}, beyond "
                         f"{np.finfo(float).max:.6g}")
    return replace(match, linkage=_rescaled_linkage(match.linkage, s),
                   cognates=tuple(_rescaled_linkage(c, s) for c in match.cognates),
                   error=match.error * s, curve=match.curve * s)


def _rescaled_linkage(placed, s):
    if isinstance(placed, PlacedSliderCrank):
        from mech.planar.kinematics._slider_crank import SliderCrank

        sc = placed.slider
        return replace(placed, slider=SliderCrank(sc.a * s, sc.b * s, sc.e * s, branch=sc.branch),
                       coupler=(placed.coupler[0] * s, placed.coupler[1] * s), origin=placed.origin * s)
    f = placed.fourbar
    return replace(placed, fourbar=_scaled(f.a, f.b, f.c, f.d, *f.coupler, f.branch, s), origin=placed.origin * s)


def _query_closed(atlas, z, k, shortlist, resampled):
    """`query` for a closed target `z` (1, m) of size about 1."""
    n = atlas.samples
    if resampled:
        if z.shape[1] != n:
            raise ValueError(f"Expected {n} points in a resampled `target` (the atlas's samples), got {z.shape[1]}")
        t = z
    else:
        t = _resample_rows(z, n, True)
    form = normal_form(t, atlas.harmonics)
    m = min(shortlist, len(atlas))
    short = _nearest(atlas, form.candidates[0], m)
    dist = _signature_distances(atlas.signatures[short], atlas._norms[short], form.candidates[0])
    dense = atlas.curves(short, _DENSE * n)
    err, w, centroid, radius, curves, direction = _best_fits(t[0], dense, max(k, _REFINE))
    return [_match(rank, int(short[j]), atlas.linkages.take([short[j]]), t[0], w[j], centroid[j], err[j],
                   radius, direction[j], float(dist[j]), curves[j])
            for rank, j in enumerate(np.argsort(np.where(np.isnan(w), np.inf, err), kind="stable")[:k])]


def _nearest(atlas, candidates, m, exact=None):
    """Rows of the `m` signatures nearest any of the `candidates` (4, D), in no order.

    Through the atlas's approximate index when one is stored with it (`exact` None) and the
    short list is small beside the atlas; ``exact=True`` always streams every signature,
    ``exact=False`` always uses the index (the recall measurements).

    The four normal forms of a curve have the same norm, so the nearest of them to a row is
    the one with the largest dot product: ``d^2 = |s|^2 + |c|^2 - 2 max_k s . c_k``. The
    products run on a float32 copy of the signatures (half the memory to stream; entries
    in [-1, 1], so the rounding, below 1e-7, moves only ties within the short list, whose
    distances `query` recomputes in float64).
    """
    sig, norms = atlas._signatures32
    c = np.ascontiguousarray(candidates, dtype=np.float32)
    index = None if exact else atlas._ann
    if index is not None and (exact is False or m < len(atlas) // _ANN_SHARE):
        # the graph index gives the rows near any normal form; they are ranked exactly
        rows = index.search(c, m)
        if rows.size <= m:
            return rows
        score = norms[rows] - 2.0 * np.max(sig[rows] @ c.T, axis=1)
        return rows[np.argpartition(score, m - 1)[:m]]
    score = np.empty(len(atlas), dtype=np.float32)
    for start in range(0, len(atlas), _BLOCK):
        block = slice(start, start + _BLOCK)
        # einsum, not a BLAS product: a (rows, 32) x (32, 4) product is memory-bound, and
        # a threaded BLAS spends more on waking its threads than on the arithmetic
        np.subtract(norms[block], 2.0 * np.max(np.einsum("ij,kj->ik", sig[block], c), axis=1), out=score[block])
    if m >= len(atlas):
        return np.arange(len(atlas))
    return np.argpartition(score, m - 1)[:m]


def _query_arc(atlas, z, k, shortlist, span, starts):
    """`query` for an open arc `z` (1, m): window signatures, then alignment of both ends."""
    from mech.atlas._planar._arcs import align_arcs

    n = atlas.samples
    t = _resample_rows(z, n // 2 + 1, False)
    closed = _close_arc(t)
    # a window's signature is less sharp than a closed curve's (its normalisation rests on
    # the arc's first harmonic, which is often small): a longer list gets a coarse
    # alignment, the best `shortlist` of it the full one
    m = min(_ARC_WIDER * shortlist, len(atlas))
    c = np.abs(np.fft.fft(closed[0]) / closed.shape[1])
    small = min(c[1], c[-1]) < _ARC_SMALL_FIRST * np.sqrt(np.sum(c[1:] ** 2))
    short, u0, dist = _arc_shortlist(atlas, closed, 1, span, starts, m)
    if small:
        # a small first harmonic: the normalisation on it is ill-conditioned, so the windows
        # normalised on c_2 give a second list, each row from two starts; both lists are aligned
        more = _arc_shortlist(atlas, closed, 2, span, starts, m, True)
        short, u0, dist = (np.concatenate([x, y]) for x, y in zip((short, u0, dist), more))
    step = 0.5 / starts
    err, *_, u0, u1, _ = align_arcs(t[0], atlas.linkages.take(short), u0, u0 + 2 * np.pi * span, step,
                                    levels=_ARC_COARSE, size=_COARSE_TABLE)
    order = np.argsort(err, kind="stable")
    order = order[np.sort(np.unique(short[order], return_index=True)[1])]      # each row once, its best
    keep = order[:min(shortlist, m)]
    short, u0, u1, dist = short[keep], u0[keep], u1[keep], dist[keep]
    rows = atlas.linkages.take(short)
    err, w, centroid, points, u0, u1, direction = align_arcs(t[0], rows, u0, u1, step / 2**_ARC_COARSE)
    radius = np.sqrt(np.mean(np.abs(t[0] - t[0].mean()) ** 2))
    return [_match(rank, int(short[j]), rows.take([j]), t[0], w[j], centroid[j], err[j], radius, direction[j],
                   float(dist[j]), points[j], arc=(float(u0[j]), float(u1[j])))
            for rank, j in enumerate(np.argsort(err, kind="stable")[:k])]


def _arc_shortlist(atlas, closed, base, span, starts, m, second=False):
    """The `m` rows whose windows (normalised on harmonic `base`) lie nearest the open
    target run forward and back (`closed`, (1, N)); the start of the best-fitting window of
    each (with the fraction of a step towards the next) and the signature distance. With
    `second`, each row comes twice: from its best start and from its best start an eighth
    of a cycle or more away (`window_distances`)."""
    from mech.atlas._planar._arcs import _WINDOW_TABLE, _truncate, arc_signatures, window_distances

    form = normal_form(closed, atlas.harmonics, base)
    sigs, norms, gaps = arc_signatures(atlas, span, starts, base)
    best, where, frac, *other = window_distances(sigs, norms, gaps, _truncate(form.candidates[0], atlas.harmonics),
                                                 second)
    short = np.argpartition(best, m - 1)[:m] if m < len(atlas) else np.arange(len(atlas))
    u0 = 2 * np.pi * (where[short] + frac[short]) / starts + np.pi / _WINDOW_TABLE
    if second:
        where2, frac2 = other
        u0 = np.concatenate([u0, 2 * np.pi * (where2[short] + frac2[short]) / starts + np.pi / _WINDOW_TABLE])
        short = np.concatenate([short, short])
    return short, u0, best[short]


def _best_fits(t, dense, keep, levels=None):
    """Align every dense curve with the target `t` (N,): start and direction by FFT for all,
    then bisection on the exact error for the best `keep`. Returns arrays over all rows
    (error, w, centroid, radius, placed-frame samples, direction); rows past the best
    `keep` have the unrefined error and NaN placement."""
    n = t.shape[0]
    direction, start = _align(t, _resample_rows(dense, n, True))
    err = _fit(t, dense, direction, start)[0]
    # refine the start of the best few by bisection on the exact error (the FFT peak of a
    # curve that is not band-limited can be off by a fraction of a sample step)
    best = np.argsort(err, kind="stable")[:keep]
    step = 0.5 / n
    for _ in range(_LEVELS if levels is None else levels):
        for trial in (start[best] - step, start[best] + step):
            e = _fit(t, dense[best], direction[best], trial % 1.0)[0]
            better = e < err[best]
            start[best] = np.where(better, trial % 1.0, start[best])
            err[best] = np.where(better, e, err[best])
        step *= 0.5
    # the placement of the best few only (the others keep their unrefined error and no placement)
    e, wb, cb, radius, zb = _fit(t, dense[best], direction[best], start[best])
    err[best] = e
    w = np.full(err.shape, np.nan + 0j)
    centroid = np.full(err.shape, np.nan + 0j)
    curves = np.full((err.size, n), np.nan + 0j)
    w[best], centroid[best], curves[best] = wb, cb, zb
    return err, w, centroid, radius, curves, direction


def _match(rank, index, row, t, w, centroid, err, radius, direction, distance, curve, refined=False, arc=None):
    """The `Match` of one linkage (a one-row FourBarSamples or SliderCrankSamples) placed by
    ``z -> origin + w z``."""
    branch = int(row.branch[0])
    origin = t.mean() - w * centroid
    s = abs(w)
    if hasattr(row, "e"):
        from mech.planar.kinematics._slider_crank import SliderCrank

        a, b, e, p, q = (float(getattr(row, k)[0] * s) for k in "abepq")
        placed = PlacedSliderCrank("slider-crank", SliderCrank(a, b, e, branch=branch), (p, q), complex(origin),
                                   float(np.angle(w)))
        cognates = slider_cognate(placed)
    else:
        a, b, c, d, p, q = (float(getattr(row, k)[0]) for k in "abcdpq")
        unit = FourBar(a, b, c, d, branch=branch, coupler=(p, q))
        placed = PlacedLinkage("ABCD", _scaled(a, b, c, d, p, q, branch, s), complex(origin), float(np.angle(w)))
        cognates = _placed_cognates(unit, origin, w)
    return Match(rank, index, placed, cognates, int(direction), float(err), float(err / radius), distance,
                 str(row.kind[0]), float(row.gamma_min[0]), bool(row.full_turn[0]),
                 (float(row.theta_lo[0]), float(row.theta_hi[0])), origin + w * curve, refined, arc)
