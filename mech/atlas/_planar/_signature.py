"""Shape signatures of planar curves: normalised Fourier descriptors of the arc-length curve.

The normalisation is derived, and its invariances proved, on the page
``derivations/atlas/shape_signature.md`` (label ``deriv-shape-signature``); the normalising
angles come from the generated module ``mech._generated.shape_signature``.
"""

import os
from dataclasses import dataclass

import numpy as np

from mech._generated.shape_signature import signature_angles
from mech._validate import _show, bool_flag, integer, planar_points

__all__ = ["curve_signature", "read_points", "resample"]

#: Default number of equal arc-length steps a curve is resampled to.
SAMPLES = 128
#: Default number of harmonics kept on each side (a signature has 4 * HARMONICS numbers).
HARMONICS = 8
_MAX_SAMPLES = 1 << 16


def _row_scales(flat):
    """Per row, the power of two 2**k with 2**k <= max |x|, |y| < 2**(k + 1) (1 for a zero row).

    Dividing a curve by it is exact (a power of two) and puts its largest coordinate in
    [1, 2): no square, sum of squares or cumulative arc length then overflows, and none
    underflows for want of size, whatever the unit (1e-300 to 1e308)."""
    biggest = np.maximum(np.max(np.abs(flat.real), axis=1), np.max(np.abs(flat.imag), axis=1))
    return np.where(biggest > 0.0, np.ldexp(1.0, np.frexp(biggest)[1] - 1), 1.0)


def _curves(points, closed, name="points", scaled=False):
    """Check a curve or a stack of curves; return them as a 2-D complex array and the lead shape.

    With `scaled`, each row comes divided by its `_row_scales` and the scales (rows,) come
    third: the caller works on curves of size about 1 and multiplies lengths back.
    """
    z = planar_points(name, points)
    least = 3 if closed else 2
    if z.ndim == 0 or z.shape[-1] < least:
        raise ValueError(f"Expected `{name}` of shape (..., m) with m >= {least}, got shape {z.shape}: {_show(points)}")
    lead = z.shape[:-1]
    flat = z.reshape(-1, z.shape[-1])
    given, scale = flat, _row_scales(flat)
    # part by part: a complex division by a subnormal scale overflows (Smith's algorithm)
    flat = np.empty_like(given)
    flat.real, flat.imag = given.real / scale[:, None], given.imag / scale[:, None]
    span = np.max(np.abs(flat - flat[:, :1]), axis=1)
    if not np.all(span > 0.0):
        row = int(np.flatnonzero(~(span > 0.0))[0])
        where = f" (curve {row})" if lead else ""
        raise ValueError(f"Expected `{name}` that are not all equal{where}, got {_show(given[row])}")
    return (flat, lead, scale) if scaled else (given, lead)


def _samples(samples, *, even=False, harmonics=None):
    samples = integer("samples", samples, minimum=4, maximum=_MAX_SAMPLES)
    if even and samples % 2:
        raise ValueError(f"Expected an even `samples` for an open arc, got {samples}")
    if harmonics is not None and samples <= 2 * harmonics:
        raise ValueError(f"Expected `samples` > 2 * harmonics = {2 * harmonics}, got {samples}")
    return samples


_CHUNK = 64


def _resample_rows(z, n, closed, offset=None):
    """Points at `n` equal arc-length steps along each row of `z` (rows checked already).

    A closed row may start `offset[i]` of its length after its first point. Rows are done
    `_CHUNK` at a time with one `searchsorted`: row r of a chunk is shifted by 2 r, so the
    rows' normalised arc lengths in [0, 1] line up in one sorted array (the shift costs at
    most 2 * _CHUNK ulps of a fraction).
    """
    if closed:
        z = np.concatenate([z, z[:, :1]], axis=1)
    seg = np.abs(np.diff(z, axis=1))
    cum = np.concatenate([np.zeros((z.shape[0], 1)), np.cumsum(seg, axis=1)], axis=1)
    u = cum / cum[:, -1:]
    m = z.shape[1]
    fractions = np.arange(n) / (n if closed else n - 1)
    f = np.broadcast_to(fractions, (z.shape[0], n)) if offset is None else \
        (fractions[None, :] + np.asarray(offset)[:, None]) % 1.0
    out = np.empty((z.shape[0], n), dtype=complex)
    for lo in range(0, z.shape[0], _CHUNK):
        rows = slice(lo, lo + _CHUNK)
        shift = 2.0 * np.arange(u[rows].shape[0])[:, None]
        flat = (u[rows] + shift).ravel()
        j = np.searchsorted(flat, (f[rows] + shift).ravel(), side="right") - 1
        j = j.reshape(-1, n) - (m * np.arange(u[rows].shape[0]))[:, None]
        j = np.clip(j, 0, m - 2)
        ur, zr = u[rows], z[rows]
        u0, u1 = np.take_along_axis(ur, j, 1), np.take_along_axis(ur, j + 1, 1)
        z0, z1 = np.take_along_axis(zr, j, 1), np.take_along_axis(zr, j + 1, 1)
        width = u1 - u0
        t = np.divide(f[rows] - u0, width, out=np.zeros_like(width), where=width > 0.0)
        out[rows] = z0 + t * (z1 - z0)
    return out


def resample(points, samples=SAMPLES, *, closed=True):
    """Resample a polyline at equal steps of arc length.

    The polyline through `points` (closed back to its first point when `closed`) is cut into
    `samples` pieces of equal length, measured along it; the first point is kept.

    Parameters
    ----------
    points : array_like, complex, shape (..., m)
        Points ``x + 1j*y`` in order along the curve; leading axes hold several curves.
    samples : int, optional
        Number of points returned, at least 4.
    closed : bool, optional
        True for a closed curve (the last step returns towards the first point, which is not
        repeated); False for an open arc (both ends are kept).

    Returns
    -------
    ndarray of complex, shape (..., samples)

    Raises
    ------
    ValueError
        If `points` are not finite planar points, fewer than 3 (closed) or 2 (open), or all
        equal; if `samples` is not an integer in [4, 65536].

    Notes
    -----
    Straight segments between the given points, so resampling commutes exactly with moves,
    turns and scaling, and a closed curve run backwards from the same first point gives
    the same points in reverse order (see :ref:`deriv-shape-signature`).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.atlas import resample
    >>> square = [0, 1, 1 + 1j, 1j]
    >>> np.round(resample(square, 8), 12)
    array([0. +0.j , 0.5+0.j , 1. +0.j , 1. +0.5j, 1. +1.j , 0.5+1.j , 0. +1.j , 0. +0.5j])
    >>> resample([[0, 2], [0, 4j]], 5, closed=False)[1]
    array([0.+0.j, 0.+1.j, 0.+2.j, 0.+3.j, 0.+4.j])
    """
    closed = bool_flag("closed", closed)
    z, lead, scale = _curves(points, closed, scaled=True)
    samples = _samples(samples)
    return (_resample_rows(z, samples, closed) * scale[:, None]).reshape(*lead, samples)


def _close_arc(z):
    """An open arc at N/2 + 1 equal steps, run forward and back: a closed curve of N points."""
    return np.concatenate([z, z[:, -2:0:-1]], axis=1)


@dataclass(frozen=True)
class NormalForm:
    """The four normalisations of curves sampled at equal arc-length steps (internal).

    ``candidates`` has shape (rows, 4, 4K): direction +1 with the two angle branches, then
    direction -1 with both; ``alpha`` and ``direction`` have shape (rows, 4); ``centroid``
    and ``scale`` shape (rows,). ``chosen`` (rows,) is the index of the signature.
    """

    candidates: np.ndarray
    alpha: np.ndarray
    direction: np.ndarray
    centroid: np.ndarray
    scale: np.ndarray
    chosen: np.ndarray

    @property
    def signature(self):
        return self.candidates[np.arange(self.chosen.size), self.chosen]


def _key_weights(size):
    return 1.0 / (1.0 + np.arange(size))


def normal_form(z, harmonics, base=1):
    """Normalise rows of equally spaced samples `z` (rows, N); see the derivation page.

    `base` is the harmonic made real and positive: 1 (the signature), or 2 for open arcs
    whose first harmonic is small (the window signatures normalised on c_2). On c_2 the
    start shift is defined modulo pi, so each direction has four branches, eight in all.
    """
    n = z.shape[1]
    C = np.fft.fft(z, axis=1) / n
    # the norm of the harmonics, scaled by the largest so no square overflows (a curve of size 1e300)
    A = np.abs(C[:, 1:])
    top = np.max(A, axis=1)
    scale = top * np.sqrt(np.sum((A / np.where(top > 0.0, top, 1.0)[:, None]) ** 2, axis=1))
    k = np.arange(1, harmonics + 1)
    pos, neg = C[:, k], C[:, -k]
    cands, alphas, directions = [], [], []
    # the branches (alpha + j pi, sigma + l pi / base) move alpha +- base sigma by (j +- l) pi:
    # every l = j (mod 2) below 2 base gives a solution (two for base 1, four for base 2)
    branches = ((0, 0), (1, 1)) if base == 1 else ((0, 0), (1, 1), (0, 2), (1, 3))
    for d, (bp, bn) in ((1, (pos, neg)), (-1, (neg, pos))):
        c_p, c_n = bp[:, base - 1], bn[:, base - 1]
        alpha, sigma = signature_angles(c_p.real, c_p.imag, c_n.real, c_n.imag)
        # signature_angles solves alpha + sigma = -arg c_p; on c_base the shift is sigma / base
        sigma = sigma / base
        for j, l in branches:
            al, sg = (alpha + j * np.pi)[:, None], (sigma + l * np.pi / base)[:, None]
            hp = bp * np.exp(1j * (al + k * sg)) / scale[:, None]
            hn = bn * np.exp(1j * (al - k * sg)) / scale[:, None]
            both = np.concatenate([hp, hn], axis=1)
            cands.append(np.stack([both.real, both.imag], axis=-1).reshape(z.shape[0], 4 * harmonics))
            alphas.append(alpha + j * np.pi)
            directions.append(np.full(z.shape[0], d))
    cands = np.stack(cands, axis=1)
    chosen = np.argmax(np.einsum("ijk,k->ij", cands, _key_weights(4 * harmonics)), axis=1)
    return NormalForm(cands, np.stack(alphas, axis=1), np.stack(directions, axis=1), C[:, 0], scale, chosen)


def curve_signature(points, *, closed=True, harmonics=HARMONICS, samples=SAMPLES, resampled=False):
    """Shape signature of a curve: the same for every placement, size, start and direction.

    The curve is resampled at `samples` equal arc-length steps, its discrete Fourier
    coefficients ``c_k`` are divided by the RMS radius S, and turned and restarted so that
    ``c_1`` and ``c_-1`` are real and positive; of the four normalisations (two directions, two branches
    of the angles) the one with the largest fixed linear key is returned. An open arc is run
    forward and back to make it closed.

    Parameters
    ----------
    points : array_like, complex, shape (..., m)
        Points ``x + 1j*y`` along the curve, in order; leading axes hold several curves.
    closed : bool, optional
        True for a closed curve, False for an open arc.
    harmonics : int, optional
        Harmonics kept on each side, K >= 1; the signature has 4K numbers.
    samples : int, optional
        Arc-length samples N (even for an open arc), N > 2K.
    resampled : bool, optional
        True if `points` are already at equal arc-length steps (or equal steps of the
        parameter of a band-limited curve): they are used as given and `samples` is ignored.

    Returns
    -------
    ndarray, shape (..., 4 * harmonics)
        ``Re c_1, Im c_1, ..., Re c_K, Im c_K, Re c_-1, ..., Im c_-K``, normalised.

    Raises
    ------
    ValueError
        For points that are not finite, too few or all equal, or bad options (named).

    Notes
    -----
    Derived, with the proof of each invariance, in :ref:`deriv-shape-signature`. The
    normalisation is ill-conditioned when ``c_1`` or ``c_-1`` is small against S (a first-harmonic
    ellipse that is nearly a circle); `query` therefore compares all four normalisations of
    a target and then aligns candidates exactly.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.atlas import curve_signature
    >>> t = np.linspace(0, 2 * np.pi, 200, endpoint=False)
    >>> egg = np.cos(t) + 0.6j * np.sin(t) + 0.2 * np.exp(2j * t)
    >>> s = curve_signature(egg)
    >>> s.shape
    (32,)
    >>> backwards = np.roll(egg[::-1], 1)              # the same first point, run backwards
    >>> moved = 3 - 1j + 2.5 * np.exp(0.7j) * backwards
    >>> bool(np.allclose(curve_signature(moved), s, atol=1e-12))
    True
    >>> curve_signature(np.stack([egg, moved]), harmonics=4).shape
    (2, 16)
    """
    closed = bool_flag("closed", closed)
    resampled = bool_flag("resampled", resampled)
    harmonics = integer("harmonics", harmonics, minimum=1, maximum=_MAX_SAMPLES // 4)
    z, lead, _ = _curves(points, closed, scaled=True)      # the signature does not depend on the size
    if resampled:
        if not closed:
            z = _close_arc(z)
        if z.shape[1] <= 2 * harmonics:
            raise ValueError(f"Expected more than 2 * harmonics = {2 * harmonics} points in `points`, "
                             f"got {z.shape[1]}")
    else:
        samples = _samples(samples, even=not closed, harmonics=harmonics)
        z = _resample_rows(z, samples, True) if closed else _close_arc(_resample_rows(z, samples // 2 + 1, False))
    return normal_form(z, harmonics).signature.reshape(*lead, 4 * harmonics)


def read_points(path):
    """Read a curve from a CSV file of ``x, y`` rows (a header line is allowed).

    Parameters
    ----------
    path : str or os.PathLike
        The file: one point per line, two numbers separated by a comma; a first line that
        is not numeric (a header) is skipped; lines starting with ``#`` are comments.

    Returns
    -------
    ndarray of complex, shape (m,)
        The points ``x + 1j*y`` in the order of the file.

    Raises
    ------
    ValueError
        If the file cannot be read, a row does not hold two finite numbers, or there are
        fewer than 2 rows.

    Examples
    --------
    >>> import os, tempfile
    >>> from mech.atlas import read_points
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     path = os.path.join(tmp, "target.csv")
    ...     with open(path, "w") as f:
    ...         _ = f.write("x,y\\n0,0\\n1,0\\n1,1\\n")
    ...     read_points(path)
    array([0.+0.j, 1.+0.j, 1.+1.j])
    """
    if not isinstance(path, (str, os.PathLike)) or isinstance(path, bytes):
        raise TypeError(f"Expected `path` to be a file name, got {_show(path)}")
    try:
        with open(path, encoding="utf-8") as f:
            lines = [ln.strip() for ln in f if ln.strip() and not ln.lstrip().startswith("#")]
    except OSError as exc:
        raise ValueError(f"Expected `path` to name a readable CSV file, got {str(path)!r} ({exc})") from None
    rows = []
    for number, line in enumerate(lines):
        cells = [c.strip() for c in line.split(",")]
        try:
            values = [float(c) for c in cells]
        except ValueError:
            if number == 0:
                continue                      # a header
            raise ValueError(f"Expected `path` rows of two numbers x, y, got {line!r}") from None
        if len(values) != 2 or not all(np.isfinite(values)):
            raise ValueError(f"Expected `path` rows of two finite numbers x, y, got {line!r}")
        rows.append(complex(*values))
    if len(rows) < 2:
        raise ValueError(f"Expected at least 2 points in `path`, got {len(rows)} in {str(path)!r}")
    return np.array(rows)
