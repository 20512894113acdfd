"""Fitting spherical coupler curves onto a target by a rotation of the sphere, and the match record.

The closed-curve search (`mech.atlas._sphere._search`) and the open-arc search
(`mech.atlas._sphere._arcs`) both turn curves onto the target with the rotations of this
module (Kabsch's SVD solution of the orthogonal Procrustes problem, and Theobald's
quaternion bound for many candidate starts at once) and report their results as
`SphereMatch` records.
"""

from dataclasses import dataclass

import numpy as np

__all__ = ["SphereMatch"]


@dataclass(frozen=True)
class SphereMatch:
    """One spherical four-bar found by `query_sphere` (or refined by `refine_sphere`).

    Attributes
    ----------
    rank, index : int
        Rank (0 best) and row in the atlas (the row a refinement started from).
    fourbar : SphericalFourBar
        The linkage in its standard frame (A at the north pole, D on the x-z plane).
    rotation : ndarray, shape (3, 3)
        The rotation of the sphere that carries its curve onto the target:
        ``target ~ curve @ rotation.T``.
    direction : int
        +1 if the target runs with the curve parameter, -1 against it.
    error : float
        RMS distance (chord, about the arc in radians) between the target and the turned
        curve at equal steps of length, best aligned.
    kind : str
        Type by `mech.spherical.classify`.
    curve : ndarray, shape (m, 3)
        The turned coupler curve (or sub-arc), point for point against the target's
        resampled points.
    placed : SphericalFourBar
        The same linkage placed on the target: ``frame=rotation``, so that its coupler
        point traces the target.
    relative_error : float
        `error` over the RMS distance of the target's points from their mean.
    distance : float
        Distance of the signatures (the first stage's ranking).
    gamma_min : float
        Smallest transmission angle over the input range, radians (0 for a rocking input).
    full_turn : bool
        True if the crank turns fully.
    theta_range : (float, float)
        The input range, radians.
    refined : bool
        True for a result of `refine_sphere`.
    arc : (float, float) or None
        For an open target, the curve parameter u at the two ends of the matching part of
        the closed curve (the input angle for a crank that turns fully).
    """

    rank: int
    index: int
    fourbar: object
    rotation: np.ndarray
    direction: int
    error: float
    kind: str
    curve: np.ndarray
    placed: object = None
    relative_error: float = float("nan")
    distance: float = float("nan")
    gamma_min: float = float("nan")
    full_turn: bool = True
    theta_range: tuple = (0.0, 2 * np.pi)
    refined: bool = False
    arc: tuple = None


def _rotation_gain(H, bound, steps=24):
    """``max over proper rotations R of trace(R H)`` for 3x3 matrices H (..., 3, 3).

    The largest eigenvalue of Horn's quaternion matrix K of H, as a root of its characteristic
    polynomial ``l^4 + c2 l^2 + c1 l + c0`` (``c2 = -2 |H|^2``, ``c1 = -8 det H``,
    ``c0 = det K``) found by Newton's method from `bound`, an upper bound such as
    ``(|a|^2 + |t|^2) / 2`` (Theobald's QCP method): no SVD per matrix.
    """
    Sxx, Sxy, Sxz = H[..., 0, 0], H[..., 0, 1], H[..., 0, 2]
    Syx, Syy, Syz = H[..., 1, 0], H[..., 1, 1], H[..., 1, 2]
    Szx, Szy, Szz = H[..., 2, 0], H[..., 2, 1], H[..., 2, 2]
    K = np.stack([
        np.stack([Sxx + Syy + Szz, Syz - Szy, Szx - Sxz, Sxy - Syx], axis=-1),
        np.stack([Syz - Szy, Sxx - Syy - Szz, Sxy + Syx, Szx + Sxz], axis=-1),
        np.stack([Szx - Sxz, Sxy + Syx, -Sxx + Syy - Szz, Syz + Szy], axis=-1),
        np.stack([Sxy - Syx, Szx + Sxz, Syz + Szy, -Sxx - Syy + Szz], axis=-1)], axis=-2)
    c2 = -2.0 * np.sum(H**2, axis=(-2, -1))
    c1 = -8.0 * np.linalg.det(H)
    c0 = np.linalg.det(K)
    lam = np.array(bound, dtype=float, copy=True)
    for _ in range(steps):
        l2 = lam * lam
        p = (l2 + c2) * l2 + c1 * lam + c0
        dp = 4.0 * l2 * lam + 2.0 * c2 * lam + c1
        lam = lam - np.divide(p, dp, out=np.zeros_like(p), where=dp != 0.0)
    return lam


def _kabsch_all_starts(a, t):
    """For curves a (rows, N, 3) and target t (N, 3): the best rotation at every cyclic start.

    Returns (squared error sum, rotation, start) of the best start per row.
    """
    A, T = np.fft.fft(a, axis=1), np.fft.fft(t, axis=0)
    # H[r, s, p, q] = sum_j a[r, j + s, p] t[j, q]
    H = np.fft.ifft(A[:, :, :, None] * np.conj(T)[None, :, None, :], axis=1).real
    norms = np.sum(a**2, axis=(1, 2))[:, None] + np.sum(t**2)
    gain = _rotation_gain(H, np.broadcast_to(norms / 2, H.shape[:2]))
    s = np.argmin(norms - 2 * gain, axis=1)
    r = np.arange(a.shape[0])
    # the rotation at the chosen start, and its error, from the SVD (Kabsch)
    u, sigma, vt = np.linalg.svd(H[r, s])
    sign = np.sign(np.linalg.det(np.einsum("rij,rjk->rik", u, vt)))
    fix = np.ones((a.shape[0], 3))
    fix[:, 2] = sign
    # the rotation R with R a_{j+s} ~ t_j: R = V diag(1, 1, det) U^T
    rot = np.einsum("rji,rj,rkj->rik", vt, fix, u)
    return norms[:, 0] - 2 * np.sum(sigma * fix, axis=1), rot, s


def _kabsch(a, t):
    """Best rotation of each row of points a (rows, m, 3) onto t (rows or 1, m, 3): (RMS, R)."""
    H = np.einsum("rjp,rjq->rpq", a, np.broadcast_to(t, a.shape))
    u, sigma, vt = np.linalg.svd(H)
    sign = np.sign(np.linalg.det(np.einsum("rij,rjk->rik", u, vt)))
    sigma = sigma.copy()
    sigma[:, 2] *= sign
    fix = np.ones((a.shape[0], 3))
    fix[:, 2] = sign
    rot = np.einsum("rji,rj,rkj->rik", vt, fix, u)
    sq = np.sum(a**2, axis=(1, 2)) + np.sum(np.broadcast_to(t, a.shape) ** 2, axis=(1, 2)) - 2 * np.sum(sigma, axis=1)
    return np.sqrt(np.maximum(sq, 0.0) / a.shape[1]), rot


def _radius(t):
    return float(np.sqrt(np.mean(np.sum((t - t.mean(axis=0)) ** 2, axis=1))))


def _match(rank, index, row, rot, direction, err, radius, distance, curve, refined=False, arc=None):
    """The `SphereMatch` of one linkage (a one-row SphereSamples) turned by `rot`."""
    rot = np.asarray(rot, dtype=float)
    # a rotation from an SVD is orthogonal to rounding; make it exactly proper for `frame`
    u, _, vt = np.linalg.svd(rot)
    rot = u @ vt
    return SphereMatch(rank, index, row.fourbar(0), rot, int(direction), float(err), str(row.kind[0]), curve,
                       row.fourbar(0, frame=rot), float(err / radius), float(distance), float(row.gamma_min[0]),
                       bool(row.full_turn[0]), (float(row.theta_lo[0]), float(row.theta_hi[0])), refined, arc)
