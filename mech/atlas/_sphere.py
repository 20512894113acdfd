"""An atlas of spherical four-bars: signatures that ignore rotations of the sphere (issue 13).

A closed curve on the unit sphere is resampled at equal steps of its length (the polyline
through its points, whose length no rotation changes), turned into the frame of the principal
axes of its second-moment matrix ``M = mean(x x^T)``, and described by the moduli of the
discrete Fourier coefficients of its three coordinates in that frame. The derivation page
:ref:`deriv-sphere-signature` proves why this is the same for every rotation of the sphere,
start and direction, and where it is ill-conditioned (two equal principal moments).
The search ranks an atlas by these signatures, then aligns a short list exactly: for every
start and both directions, the best rotation (the SVD solution of the orthogonal Procrustes
problem), with all starts at once through FFT cross-correlations.
"""

from dataclasses import dataclass

import numpy as np

from mech._validate import _show, bool_flag, integer, real_array, real_tuple
from mech.atlas._build import block_seed
from mech.atlas._signature import HARMONICS, SAMPLES

__all__ = ["SphereAtlas", "SphereMatch", "build_sphere_atlas", "query_sphere", "sphere_signature"]

#: Default range of the four arcs of a sampled spherical four-bar, radians.
ARCS = (0.15, 1.4)
#: Default range of the coupler point's arc r from B, radians.
COUPLER_ARC = (0.1, 1.2)
#: Sub-steps of the start tried by the exact alignment of `query_sphere`.
_PHASES = 4


def _sphere_curves(points, name="points"):
    x = real_array(name, points)
    if x.ndim < 2 or x.shape[-1] != 3 or x.shape[-2] < 3:
        raise ValueError(f"Expected `{name}` of shape (..., m, 3) with m >= 3, got shape {x.shape}")
    norm = np.linalg.norm(x, axis=-1)
    if not np.all(norm > 0.0):
        raise ValueError(f"Expected `{name}` without zero vectors, got {_show(points)}")
    return x / norm[..., None]


def _resample_closed(x, n):
    """Points at n equal steps of length along closed polylines x (rows, m, 3)."""
    z = np.concatenate([x, x[:, :1]], axis=1)
    seg = np.linalg.norm(np.diff(z, axis=1), axis=2)
    cum = np.concatenate([np.zeros((z.shape[0], 1)), np.cumsum(seg, axis=1)], axis=1)
    total = cum[:, -1:]
    f = np.arange(n)[None, :] / n * total
    out = np.empty((x.shape[0], n, 3))
    for r in range(x.shape[0]):
        j = np.clip(np.searchsorted(cum[r], f[r], side="right") - 1, 0, z.shape[1] - 2)
        width = cum[r, j + 1] - cum[r, j]
        t = np.divide(f[r] - cum[r, j], width, out=np.zeros_like(width), where=width > 0.0)
        out[r] = z[r, j] + t[:, None] * (z[r, j + 1] - z[r, j])
    return out


def _signature_rows(y, harmonics):
    """Signatures of resampled curves y (rows, N, 3): principal frame, then |DFT| moduli."""
    m = np.einsum("rni,rnj->rij", y, y) / y.shape[1]
    _, vectors = np.linalg.eigh(m)                               # ascending moments
    frame = np.einsum("rni,rij->rnj", y, vectors)
    c = np.abs(np.fft.rfft(frame, axis=1))[:, :harmonics + 1, :] / y.shape[1]
    return np.transpose(c, (0, 2, 1)).reshape(y.shape[0], -1)


def sphere_signature(points, *, harmonics=HARMONICS, samples=SAMPLES, resampled=False):
    """Signature of a closed curve on the sphere: the same for every rotation, start and direction.

    Parameters
    ----------
    points : array_like, shape (..., m, 3)
        Points along closed curves, in order (nonzero vectors; they are scaled to unit length).
    harmonics : int, optional
        Harmonics K kept per coordinate; the signature has 3 (K + 1) numbers.
    samples : int, optional
        Equal steps of length the curve is resampled to, more than 2K.
    resampled : bool, optional
        True if `points` are already at equal steps (of length, or of a parameter): they
        are used as given and `samples` is ignored.

    Returns
    -------
    ndarray, shape (..., 3 * (harmonics + 1))
        ``|c_0|, ..., |c_K|`` of the coordinate along the principal axis of the smallest
        moment, then of the middle one, then of the largest.

    Notes
    -----
    Derived in :ref:`deriv-sphere-signature`. Ill-conditioned when two principal moments
    are nearly equal (a curve with a symmetry axis, such as a small circle); the search
    then relies on its exact alignment stage. The size of a curve on the sphere is part of
    its shape: nothing is scaled.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.atlas import sphere_signature
    >>> t = np.linspace(0, 2 * np.pi, 200, endpoint=False)
    >>> x = np.stack([0.5 * np.cos(t), 0.3 * np.sin(t) + 0.1 * np.sin(2 * t), np.ones_like(t)], axis=1)
    >>> s = sphere_signature(x, resampled=True)                     # equal steps of t, used as given
    >>> q, _ = np.linalg.qr(np.random.default_rng(1).normal(size=(3, 3)))
    >>> turned = np.roll(x[::-1], 17, axis=0) @ q.T                   # rotated, restarted, reversed
    >>> bool(np.allclose(sphere_signature(turned, resampled=True), s, atol=1e-12)), s.shape
    (True, (27,))
    """
    harmonics = integer("harmonics", harmonics, minimum=1, maximum=1 << 12)
    samples = integer("samples", samples, minimum=4, maximum=1 << 16)
    if samples <= 2 * harmonics:
        raise ValueError(f"Expected `samples` > 2 * harmonics = {2 * harmonics}, got {samples}")
    resampled = bool_flag("resampled", resampled)
    x = _sphere_curves(points)
    lead = x.shape[:-2]
    y = x.reshape(-1, *x.shape[-2:])
    if resampled:
        if y.shape[1] <= 2 * harmonics:
            raise ValueError(f"Expected more than 2 * harmonics = {2 * harmonics} points in `points`, "
                             f"got {y.shape[1]}")
    else:
        y = _resample_closed(y, samples)
    return _signature_rows(y, harmonics).reshape(*lead, -1)


@dataclass(frozen=True)
class SphereAtlas:
    """Spherical four-bars whose cranks turn fully, with the signatures of their coupler curves.

    Attributes
    ----------
    arcs : ndarray, shape (n, 4)
        Arcs a, b, c, d (radians) of each `mech.spherical.SphericalFourBar`.
    coupler : ndarray, shape (n, 2)
        Coupler point ``(r, gamma)``.
    branch : ndarray of int, shape (n,)
    kind : ndarray of str, shape (n,)
        Type by `mech.spherical.classify` ("crank-rocker" or "double-crank").
    signatures : ndarray, shape (n, 3 (K + 1))
    settings : dict
        ``harmonics``, ``samples``, ``seed``, ``arcs`` and ``coupler_arc`` ranges.
    """

    arcs: np.ndarray
    coupler: np.ndarray
    branch: np.ndarray
    kind: np.ndarray
    signatures: np.ndarray
    settings: dict

    def __len__(self):
        return int(self.arcs.shape[0])

    def fourbar(self, i):
        """Row `i` as a `mech.spherical.SphericalFourBar` in its standard frame."""
        from mech.spherical import SphericalFourBar

        i = integer("i", i, minimum=-len(self), maximum=len(self) - 1)
        return SphericalFourBar(*self.arcs[i], branch=int(self.branch[i]), coupler=tuple(self.coupler[i]))

    def curves(self, index, samples=None):
        """Coupler curves of rows `index` (row numbers), shape (rows, samples, 3), crank angle
        ``2 pi (j + 1/2) / samples``."""
        samples = int(self.settings["samples"]) if samples is None else integer("samples", samples, minimum=4)
        index = np.atleast_1d(np.asarray(index))
        theta = 2 * np.pi * (np.arange(samples) + 0.5) / samples
        return np.stack([self.fourbar(int(i)).solve(theta).P for i in index])


def build_sphere_atlas(n, *, seed=0, harmonics=HARMONICS, samples=SAMPLES, arcs=ARCS, coupler_arc=COUPLER_ARC):
    """Sample `n` spherical four-bars whose crank turns fully, with their curve signatures.

    Arcs a, b, c, d uniform in `arcs`, the coupler point at arc ``r`` uniform in
    `coupler_arc` from B and angle ``gamma`` uniform in [-pi, pi), branch +1 or -1;
    `mech.spherical.classify` keeps the crank-rockers and double-cranks whose every pose
    over a turn assembles. Draws in blocks of 256 with seeds from ``(seed, block)``.

    Examples
    --------
    >>> from mech.atlas import build_sphere_atlas
    >>> atlas = build_sphere_atlas(20, seed=1)
    >>> len(atlas), atlas.signatures.shape
    (20, (20, 27))
    """
    from mech.spherical import SphericalFourBar, classify

    n = integer("n", n, minimum=1, maximum=10**6)
    seed = integer("seed", seed, minimum=0)
    harmonics = integer("harmonics", harmonics, minimum=1, maximum=1 << 12)
    samples = integer("samples", samples, minimum=4, maximum=1 << 16)
    if samples <= 2 * harmonics:
        raise ValueError(f"Expected `samples` > 2 * harmonics = {2 * harmonics}, got {samples}")
    lo, hi = real_tuple("arcs", arcs, 2)
    if not 0.0 < lo < hi < np.pi:
        raise ValueError(f"Expected `arcs` with 0 < low < high < pi, got {_show(arcs)}")
    r0, r1 = real_tuple("coupler_arc", coupler_arc, 2)
    if not 0.0 < r0 < r1 < np.pi:
        raise ValueError(f"Expected `coupler_arc` with 0 < low < high < pi, got {_show(coupler_arc)}")
    theta = 2 * np.pi * (np.arange(samples) + 0.5) / samples
    rows, curves, block = [], [], 0
    while len(rows) < n:
        rng = np.random.default_rng(block_seed(seed, block))
        drawn = zip(rng.uniform(lo, hi, size=(256, 4)), rng.uniform(r0, r1, 256), rng.uniform(-np.pi, np.pi, 256),
                    rng.choice([-1, 1], 256))
        for (a, b, c, d), r, gamma, branch in drawn:
            if len(rows) == n:
                break
            try:
                kind = classify(a, b, c, d).kind
            except ValueError:                     # cannot be assembled at all
                continue
            if kind not in ("crank-rocker", "double-crank"):
                continue
            pose = SphericalFourBar(a, b, c, d, branch=int(branch), coupler=(r, gamma)).solve(theta)
            if np.all(pose.valid):
                rows.append((a, b, c, d, r, gamma, int(branch), kind))
                curves.append(pose.P)
        block += 1
    cols = list(zip(*rows))
    sig = _signature_rows(_resample_closed(np.stack(curves), samples), harmonics)
    settings = {"harmonics": harmonics, "samples": samples, "seed": seed, "arcs": [lo, hi],
                "coupler_arc": [r0, r1]}
    return SphereAtlas(np.array(cols[:4]).T, np.array(cols[4:6]).T, np.array(cols[6], dtype=np.int8),
                       np.array(cols[7]), sig, settings)


@dataclass(frozen=True)
class SphereMatch:
    """One spherical four-bar found by `query_sphere`.

    Attributes
    ----------
    rank, index : int
        Rank (0 best) and row in the atlas.
    fourbar : SphericalFourBar
        The linkage in its standard frame.
    rotation : ndarray, shape (3, 3)
        The rotation that carries its curve onto the target: ``target ~ curve @ rotation.T``.
    direction : int
        +1 if the target runs with the crank angle, -1 against it.
    error : float
        RMS distance (chord, about the arc in radians) between the target and the turned
        curve at equal steps of length, best aligned over quarter steps of the start (so an
        exact copy shows up to an eighth of a step of start offset).
    kind : str
    curve : ndarray, shape (samples, 3)
        The turned coupler curve, aligned with the target's resampled points.
    """

    rank: int
    index: int
    fourbar: object
    rotation: np.ndarray
    direction: int
    error: float
    kind: str
    curve: np.ndarray


def _kabsch_all_starts(a, t):
    """For curves a (rows, N, 3) and target t (N, 3): the best rotation at every cyclic start.

    Returns (squared error sum, rotation) of the best start per row, and the start.
    """
    n = t.shape[0]
    A, T = np.fft.fft(a, axis=1), np.fft.fft(t, axis=0)
    # H[r, s, p, q] = sum_j a[r, j + s, p] t[j, q]
    H = np.fft.ifft(A[:, :, :, None] * np.conj(T)[None, :, None, :], axis=1).real
    u, sigma, vt = np.linalg.svd(H)
    sign = np.sign(np.linalg.det(np.einsum("rsij,rsjk->rsik", u, vt)))
    sigma = sigma.copy()
    sigma[..., 2] *= sign
    sq = np.sum(a**2, axis=(1, 2))[:, None] + np.sum(t**2) - 2 * np.sum(sigma, axis=2)
    s = np.argmin(sq, axis=1)
    r = np.arange(a.shape[0])
    fix = np.ones((a.shape[0], 3))
    fix[:, 2] = sign[r, s]
    # the rotation R with R a_{j+s} ~ t_j: R = V diag(1, 1, det) U^T
    rot = np.einsum("rji,rj,rkj->rik", vt[r, s], fix, u[r, s])
    return sq[r, s], rot, s


def query_sphere(atlas, target, *, k=5, shortlist=64, resampled=False):
    """Find the spherical four-bars of an atlas whose coupler curves best match a closed target.

    Parameters
    ----------
    atlas : SphereAtlas
    target : array_like, shape (m, 3)
        Points along a closed curve on the sphere, any rotation, start and direction.
    k, shortlist : int, optional
        Matches returned, and entries aligned exactly after the signature stage.
    resampled : bool, optional
        True if `target` is already at equal steps of length (used as given).

    Returns
    -------
    list of SphereMatch
        Best first, by the RMS distance after the best rotation, start and direction.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.atlas import build_sphere_atlas, query_sphere
    >>> atlas = build_sphere_atlas(100, seed=2)
    >>> q, _ = np.linalg.qr(np.random.default_rng(3).normal(size=(3, 3)))
    >>> target = np.roll(atlas.curves(7)[0], 30, axis=0)[::-1] @ q.T
    >>> best = query_sphere(atlas, target, k=2)[0]
    >>> best.index, best.error < 1e-2
    (7, True)
    """
    if not isinstance(atlas, SphereAtlas):
        raise TypeError(f"Expected `atlas` to be a SphereAtlas, got {_show(atlas)}")
    k = integer("k", k, minimum=1, maximum=10**4)
    shortlist = integer("shortlist", shortlist, minimum=1, maximum=10**5)
    resampled = bool_flag("resampled", resampled)
    if k > shortlist:
        raise ValueError(f"Expected `k` <= shortlist = {shortlist}, got {k}")
    x = _sphere_curves(target, "target")
    if x.ndim != 2:
        raise ValueError(f"Expected one curve in `target`, got shape {x.shape}")
    n, harmonics = int(atlas.settings["samples"]), int(atlas.settings["harmonics"])
    t = x if resampled else _resample_closed(x[None], n)[0]
    sig = _signature_rows(t[None], harmonics)[0]
    dist = np.sqrt(np.sum((atlas.signatures - sig) ** 2, axis=1))
    m = min(shortlist, len(atlas))
    short = np.argpartition(dist, m - 1)[:m] if m < len(atlas) else np.arange(len(atlas))
    # candidates at _PHASES times the target's steps: each phase is the curve started a
    # fraction of a step later, so the start is found to 1/_PHASES of a step
    fine = _resample_closed(atlas.curves(short, 4 * t.shape[0]), _PHASES * t.shape[0])
    best = []
    for direction in (1, -1):
        for phase in range(_PHASES):
            a = fine[:, phase::_PHASES] if direction == 1 else fine[:, ::-1][:, phase::_PHASES]
            sq, rot, s = _kabsch_all_starts(a, t)
            if len(best) <= (direction < 0):
                best.append((sq, rot, s, a))
                continue
            old = best[-1]
            better = sq < old[0]
            best[-1] = (np.where(better, sq, old[0]), np.where(better[:, None, None], rot, old[1]),
                        np.where(better, s, old[2]), np.where(better[:, None, None], a, old[3]))
    pick = best[0][0] <= best[1][0]
    out = []
    for j in np.argsort(np.where(pick, best[0][0], best[1][0]), kind="stable")[:k]:
        sq, rot, s, a = best[0 if pick[j] else 1]
        turned = np.roll(a[j], -s[j], axis=0) @ rot[j].T
        err = float(np.sqrt(max(sq[j], 0.0) / t.shape[0]))
        out.append(SphereMatch(len(out), int(short[j]), atlas.fourbar(int(short[j])), rot[j], 1 if pick[j] else -1,
                               err, str(atlas.kind[short[j]]), turned))
    return out
