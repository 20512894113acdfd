"""Signatures of curves on the sphere, the same for every rotation of the sphere, start and direction.

A closed curve on the unit sphere is resampled at equal steps of its length (the polyline
through its points, whose length no rotation changes), turned into the frame of the principal
axes of its second-moment matrix ``M = mean(x x^T)``, and described by the moduli of the
discrete Fourier coefficients of its three coordinates in that frame. The derivation page
:ref:`deriv-sphere-signature` proves why this is the same for every rotation of the sphere,
start and direction, and where it is ill-conditioned (two equal principal moments).
An open arc gets the signature of the closed curve that runs along it and back.
"""

import numpy as np

from mech._validate import _show, bool_flag, integer, real_array
from mech.atlas._planar._signature import HARMONICS, SAMPLES

__all__ = ["sphere_signature"]


def _sphere_curves(points, name="points"):
    x = real_array(name, points)
    if x.ndim < 2 or x.shape[-1] != 3 or x.shape[-2] < 3:
        raise ValueError(f"Expected `{name}` of shape (..., m, 3) with m >= 3, got shape {x.shape}")
    # each point is a direction: divided first by the power of two of its largest
    # component, so its norm neither overflows (1e300) nor underflows (1e-300)
    biggest = np.max(np.abs(x), axis=-1)
    if not np.all(biggest > 0.0):
        raise ValueError(f"Expected `{name}` without zero vectors, got {_show(points)}")
    x = x / np.ldexp(1.0, np.frexp(biggest)[1] - 1)[..., None]
    return x / np.linalg.norm(x, axis=-1)[..., None]


def _interpolate(z, frac):
    """Points of polylines z (rows, M + 1, 3) at fractions `frac` (rows, n) of their length, vectorised."""
    rows, m1 = z.shape[:2]
    seg = np.linalg.norm(np.diff(z, axis=1), axis=2)
    cum = np.concatenate([np.zeros((rows, 1)), np.cumsum(seg, axis=1)], axis=1)
    total = cum[:, -1:]
    # a polyline of no length: its vertices at equal fractions
    cum = np.where(total > 0.0, cum / np.where(total > 0.0, total, 1.0), np.linspace(0.0, 1.0, m1)[None, :])
    # one searchsorted for all rows: row r is shifted to [2 r, 2 r + 1]
    shift = 2.0 * np.arange(rows)[:, None]
    j = np.searchsorted((cum + shift).ravel(), (frac + shift).ravel(), side="right").reshape(frac.shape) - 1
    j = np.clip(j - (m1 * np.arange(rows))[:, None], 0, m1 - 2)
    lo = np.take_along_axis(cum, j, axis=1)
    width = np.take_along_axis(cum, j + 1, axis=1) - lo
    t = np.divide(frac - lo, width, out=np.zeros_like(width), where=width > 0.0)
    r = np.arange(rows)[:, None]
    return z[r, j] + t[..., None] * (z[r, j + 1] - z[r, j])


def _resample_closed(x, n):
    """Points at n equal steps of length along closed polylines x (rows, m, 3), from the first."""
    z = np.concatenate([x, x[:, :1]], axis=1)
    return _interpolate(z, np.broadcast_to(np.arange(n)[None, :] / n, (x.shape[0], n)))


def _signature_rows(y, harmonics):
    """Signatures of resampled curves y (rows, N, 3): principal frame, then |DFT| moduli."""
    m = np.einsum("rni,rnj->rij", y, y) / y.shape[1]
    _, vectors = np.linalg.eigh(m)                               # ascending moments
    frame = np.einsum("rni,rij->rnj", y, vectors)
    c = np.abs(np.fft.rfft(frame, axis=1))[:, :harmonics + 1, :] / y.shape[1]
    return np.transpose(c, (0, 2, 1)).reshape(y.shape[0], -1)


def sphere_signature(points, *, harmonics=HARMONICS, samples=SAMPLES, resampled=False, closed=True):
    """Signature of a curve on the sphere: the same for every rotation, start and direction.

    Parameters
    ----------
    points : array_like, shape (..., m, 3)
        Points along closed curves (or open arcs), in order (nonzero vectors; they are
        scaled to unit length).
    harmonics : int, optional
        Harmonics K kept per coordinate; the signature has 3 (K + 1) numbers.
    samples : int, optional
        Equal steps of length the curve is resampled to, more than 2K.
    resampled : bool, optional
        True if `points` are already at equal steps (of length, or of a parameter): they
        are used as given and `samples` is ignored.
    closed : bool, optional
        False for open arcs: the signature is that of the closed curve running along the
        arc and back (``samples`` points in all), comparable only with other open arcs.

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
    closed = bool_flag("closed", closed)
    x = _sphere_curves(points)
    lead = x.shape[:-2]
    y = x.reshape(-1, *x.shape[-2:])
    if not closed:
        y = _there_and_back(y if resampled else _resample_open(y, samples // 2 + 1))
        if y.shape[1] <= 2 * harmonics:
            raise ValueError(f"Expected more than {harmonics + 1} points in `points`, got {x.shape[-2]}")
        return _signature_rows(y, harmonics).reshape(*lead, -1)
    if resampled:
        if y.shape[1] <= 2 * harmonics:
            raise ValueError(f"Expected more than 2 * harmonics = {2 * harmonics} points in `points`, "
                             f"got {y.shape[1]}")
    else:
        y = _resample_closed(y, samples)
    return _signature_rows(y, harmonics).reshape(*lead, -1)


def _resample_open(x, n):
    """Points at n equal steps of length along open polylines x (rows, m, 3), both ends kept."""
    return _interpolate(x, np.broadcast_to(np.linspace(0.0, 1.0, n)[None, :], (x.shape[0], n)))


def _there_and_back(y):
    """The closed curve along open arcs y (rows, n, 3) at equal steps and back: (rows, 2n - 2, 3)."""
    return np.concatenate([y, y[:, -2:0:-1]], axis=1)


def arc_signature_rows(x, harmonics, samples):
    """Signatures of open arcs x (rows, m, 3): the closed there-and-back curve of the arc
    resampled at ``samples // 2 + 1`` equal steps (so ``samples`` points in all)."""
    return _signature_rows(_there_and_back(_resample_open(x, samples // 2 + 1)), harmonics)
