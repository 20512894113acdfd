"""The implicit coupler curve of the spherical four-bar (monograph chapter 2, §2.1).

The homogeneous octic ``F`` (the cone over the curve and its antipodal image), the quartic
``Q`` that cuts the curve from the unit sphere, and the nine parameters that place a
linkage anywhere on the sphere. Formulas: ``mech._generated.spherical_coupler_curve``,
derived in ``derivations/spherical/coupler_curve.md``.
"""

import numpy as np

from mech._generated import spherical_coupler_curve as _gen
from mech._validate import finite_array, instance, option, real_number
from mech.spherical._fourbar import SphericalFourBar, register_coupler_polynomial
from mech.spherical.path import _octic_small

__all__ = ["CouplerOctic", "coupler_octic", "coupler_quartic", "nine_parameters"]

_BLOCK = 1 << 14          # points per call of the generated code (cache-sized temporaries)
_NAMES = ("lon", "lat", "heading", "a", "b", "c", "d", "r", "gamma")
_FORMS = ("auto", "direct", "scaled")
#: The smallest linkage `coupler_octic` evaluates: F is of order size**12 near the linkage
#: (its gradient size**11), which below 2**-80 leaves the normal range of float64.
_SMALLEST = 2.0**-80


def nine_parameters(linkage):
    """The nine parameters ``(lon, lat, heading, a, b, c, d, r, gamma)`` of a four-bar.

    ``lon, lat`` place the input pivot A, `heading` is the inclination of the great
    circle A->D at A (see `mech.spherical.ground_frame`), then the four arcs and the
    coupler point ``(r, gamma)`` (monograph §2.1).

    Parameters
    ----------
    linkage : SphericalFourBar

    Returns
    -------
    ndarray, shape (9,)

    Examples
    --------
    >>> from mech.spherical import SphericalFourBar, ground_frame
    >>> from mech.spherical.path import nine_parameters
    >>> m = SphericalFourBar(0.5, 1.1, 0.9, 1.2, coupler=(0.6, 0.8), frame=ground_frame(0.3, 0.2, 1.0))
    >>> nine_parameters(m).round(6).tolist()
    [0.3, 0.2, 1.0, 0.5, 1.1, 0.9, 1.2, 0.6, 0.8]
    """
    instance("linkage", linkage, SphericalFourBar)
    R = np.eye(3) if linkage.frame is None else linkage.frame
    A = R[:, 2]
    lat = float(np.arctan2(A[2], np.hypot(A[0], A[1])))
    lon = float(np.arctan2(A[1], A[0])) if np.hypot(A[0], A[1]) > 0.0 else 0.0
    cl, sl, co, so = np.cos(lat), np.sin(lat), np.cos(lon), np.sin(lon)
    xl = np.array([sl * co, sl * so, -cl])
    yl = np.array([-so, co, 0.0])
    heading = float(np.arctan2(R[:, 0] @ yl, R[:, 0] @ xl))
    return np.array([lon, lat, heading, linkage.a, linkage.b, linkage.c, linkage.d, *linkage.coupler])


def _frame_of(linkage):
    """The placement rotation of a SphericalFourBar as it stores it (exact for frame=None)."""
    return np.eye(3) if linkage.frame is None else np.array(linkage.frame, dtype=float)


def _parameters(linkage):
    """Validated parameters, shape (..., 9), from an array or a SphericalFourBar."""
    if isinstance(linkage, SphericalFourBar):
        return nine_parameters(linkage)
    p = finite_array("linkage", linkage)
    if p.ndim == 0 or p.shape[-1] != 9:
        raise ValueError(f"Expected `linkage` of shape (..., 9) (lon, lat, heading, a, b, c, d, r, gamma), "
                         f"got shape {p.shape}")
    arcs = p[..., 3:7]
    if np.any((arcs <= 0.0) | (arcs >= np.pi)):
        bad = float(arcs[(arcs <= 0.0) | (arcs >= np.pi)].ravel()[0])
        raise ValueError(f"Expected the arcs a, b, c, d of `linkage` in (0, pi), got {bad!r}")
    if np.any(np.abs(p[..., 1]) > np.pi / 2):
        bad = float(p[..., 1][np.abs(p[..., 1]) > np.pi / 2].ravel()[0])
        raise ValueError(f"Expected the latitude of `linkage` in [-pi/2, pi/2], got {bad!r}")
    if np.any((p[..., 7] < 0.0) | (p[..., 7] > np.pi)):
        bad = float(p[..., 7][(p[..., 7] < 0.0) | (p[..., 7] > np.pi)].ravel()[0])
        raise ValueError(f"Expected the coupler arc r of `linkage` in [0, pi], got {bad!r}")
    return p


def _evaluate(function, degree, linkage, points, *, form="direct", frame=None, small=0.0):
    """Evaluate a generated curve function at unit directions, then scale by |x|**degree.

    For the octic, `form` chooses the direct eq. (4) or the scaled eqs. (7)-(9) per point
    (see `coupler_octic`); `frame` is the placement rotation, (3, 3) or (..., 3, 3).
    """
    p = _parameters(linkage)
    x = finite_array("points", points)
    if x.ndim == 0 or x.shape[-1] != 3:
        raise ValueError(f"Expected `points` of shape (..., 3), got shape {x.shape}")
    shape = np.broadcast_shapes(x.shape[:-1], p.shape[:-1])
    big = np.max(np.abs(x), axis=-1)
    if not np.all(big > 0.0):
        # the origin is on every cone: it is no point of a curve on the sphere
        raise ValueError(f"Expected non-zero `points` (directions from the sphere's centre), got {x[big == 0.0][0]!r}")
    if degree == 8 and np.any(_octic_small.linkage_size(p) < _SMALLEST):
        size = float(np.min(_octic_small.linkage_size(p)))
        raise ValueError(f"Expected `linkage` of size (its largest arc among a, b, c, d, r) at least 2**-80 "
                         f"~ {_SMALLEST:.3g} rad (below it the octic, of order size**12, underflows), got {size!r}")
    # divided by the largest component first, so that |x| neither overflows nor underflows
    u = x / big[..., None]
    n = np.sqrt(np.sum(u * u, axis=-1))
    u = u / n[..., None]
    norm = big * n
    u = np.broadcast_to(u, shape + (3,)).reshape(-1, 3)
    flat_p = np.broadcast_to(p, shape + (9,)).reshape(-1, 9)
    one_linkage = p.ndim == 1
    value = np.empty(u.shape[0])
    grad = np.empty((u.shape[0], 3))
    scaled = np.zeros(u.shape[0], dtype=bool)
    if form == "scaled" or (form == "auto" and np.any(_octic_small.linkage_size(p) <= small)):
        R = _octic_small.frames(p) if frame is None else frame
        flat_R = np.broadcast_to(R, shape + (3, 3)).reshape(-1, 3, 3)
        cosine = np.einsum("ni,ni->n", u, flat_R[:, :, 2])           # cos of the arc from A to the point
        size = _octic_small.linkage_size(flat_p)
        # the scaled form on the half of the sphere centred at A (u . A > 0), for linkages
        # no larger than `small` ("auto") or for all ("scaled")
        scaled = (cosine > 0.0) & ((size <= small) | (form == "scaled"))
    direct = np.flatnonzero(~scaled) if np.any(scaled) else slice(None)
    u_direct, p_direct = u[direct], (p if one_linkage else flat_p[direct])
    for s in range(0, u_direct.shape[0], _BLOCK):
        blk = slice(s, s + _BLOCK)
        args = p if one_linkage else p_direct[blk].T
        out = function(*np.ascontiguousarray(u_direct[blk].T), *args)
        rows = direct[blk] if np.any(scaled) else blk
        value[rows] = out[0]
        grad[rows] = np.stack(np.broadcast_arrays(*out[1:]), axis=-1)
    if np.any(scaled):
        one_R = np.ndim(R) == 2
        value[scaled], grad[scaled] = _octic_small.octic_small(
            p if one_linkage and one_R else flat_p[scaled], R if one_linkage and one_R else flat_R[scaled],
            u[scaled], block=_BLOCK)
    value, grad = value.reshape(shape), grad.reshape(shape + (3,))
    if degree is None:                               # the quartic: at the direction, on the sphere
        return value, grad
    norm = np.broadcast_to(norm, shape)
    with np.errstate(over="ignore", under="ignore"):
        value = value * norm**degree
        grad = grad * (norm ** (degree - 1))[..., None]
    if not (np.all(np.isfinite(value)) and np.all(np.isfinite(grad))):
        bad = float(norm[~np.isfinite(value) | ~np.all(np.isfinite(grad), axis=-1)].ravel()[0])
        raise ValueError(f"Expected `points` small enough for a finite octic (|x|**8), got a point of length {bad!r}")
    return value, grad


def coupler_octic(linkage, points, *, form="auto", small=0.1):
    """The eighth-order coupler curve F(x) = 0 of a spherical four-bar, and its gradient.

    F is the homogeneous octic of eq. (4) of the derivation (monograph §2.1): it vanishes
    on the cone through the sphere's centre over the coupler curve and over its antipodal
    image. On the unit sphere ``F(x) = Q(x) Q(-x)`` with `coupler_quartic`'s Q.

    Parameters
    ----------
    linkage : array_like, shape (..., 9), or SphericalFourBar
        ``(lon, lat, heading, a, b, c, d, r, gamma)``: placement of A and of the direction
        A->D (`mech.spherical.ground_frame`), the arcs AB, BC, CD, AD in (0, pi) and the
        coupler point (`SphericalFourBar`'s ``coupler``). Many linkages broadcast.
    points : array_like, shape (..., 3)
        Points (any non-zero vectors: F is homogeneous of degree 8), radians-free.
    form : {"auto", "direct", "scaled"}, optional
        "direct" evaluates eq. (4); "scaled" evaluates eqs. (7)-(9), the form without
        cancellation for small linkages, at the points on the half of the sphere centred at
        A (the rest directly); "auto" (default) does the same for linkages whose size, the
        largest of a, b, c, d and r, is at most `small`.
    small : float, optional
        The largest linkage size (radians) that "auto" evaluates in the scaled form.

    Returns
    -------
    value : ndarray, shape (...)
        F at the points; the leading shapes of `linkage` and `points` broadcast.
    gradient : ndarray, shape (..., 3)
        dF/dx. ``|value| / |gradient|`` is the distance to the cone, to first order.

    Raises
    ------
    ValueError
        If an input is not finite, has the wrong shape, an arc is outside (0, pi), `form`
        is unknown, `small` < 0, a point is the zero vector or so long that ``|x|**8``
        overflows, or the linkage is smaller than 2**-80 rad (F, of order size**12, would
        underflow).

    Notes
    -----
    Derivations: :ref:`deriv-spherical-coupler-curve`, eqs. (1)-(4), and
    :ref:`deriv-spherical-coupler-small`, eqs. (7)-(9). The orientation of the coupler
    triangle is kept by the sign of gamma: the mirrored triangle ``(r, -gamma)`` traces a
    different curve. For a linkage of size eps, F is of order eps**12 near it; the direct
    form, built from terms of order one, then keeps only about 1e-16 / eps**2 of relative
    accuracy (1e-8 at eps = 1e-4), while the scaled form divides the powers of eps out
    symbolically and keeps about 1e-15 down to eps = 1e-8 and beyond (measured on
    :ref:`book-spherical-planar-limit`); it costs about five times as much per point. For
    a `SphericalFourBar` its own frame is used as stored (exact for ``frame=None``); from
    nine parameters the frame is rounded, which moves A by about 1e-16, a relative change
    of about 1e-16 / eps in a linkage of size eps.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import SphericalFourBar
    >>> from mech.spherical.path import coupler_octic
    >>> m = SphericalFourBar(0.5, 1.1, 0.9, 1.2, coupler=(0.6, 0.8))
    >>> P = m.solve(np.linspace(0, 2 * np.pi, 5)).P
    >>> value, gradient = coupler_octic(m, P)
    >>> bool(np.all(np.abs(value) < 1e-12 * np.linalg.norm(gradient, axis=-1)))
    True
    >>> coupler_octic([0.0, 1.5707963, 0.0, 0.5, 1.1, 0.9, 1.2, 0.6, 0.8], np.ones((2, 4, 3)))[1].shape
    (2, 4, 3)

    A linkage a millionth of the sphere's radius across, evaluated both ways:

    >>> tiny = SphericalFourBar(1e-6, 3.5e-6, 3e-6, 3.2e-6, coupler=(1.7e-6, 0.49))
    >>> x = [1.3e-6, 2.1e-6, 1.0]
    >>> scaled, _ = coupler_octic(tiny, x)
    >>> direct, _ = coupler_octic(tiny, x, form="direct")
    >>> float(scaled / 1e-6**12)              # near the planar limit ell S / (16 r**2)
    -3465.00...
    >>> bool(abs(direct / scaled - 1) > 1e-4)  # the direct form has lost digits here
    True
    """
    form = option("form", form, _FORMS)
    small = real_number("small", small)
    if small < 0.0:
        raise ValueError(f"Expected `small` >= 0, got {small!r}")
    frame = None
    if isinstance(linkage, SphericalFourBar):
        frame = _frame_of(linkage)
    return _evaluate(_gen.spherical_coupler_octic, 8, linkage, points, form=form, frame=frame, small=small)


def coupler_quartic(linkage, points):
    """The quartic surface Q(x) = 0 that cuts the coupler curve from the unit sphere.

    Eq. (3) of the derivation (monograph §2.1): ``Q = |N|**2 - Delta**2`` from Cramer's
    rule on the linear system (2) for the pin B. Q is not homogeneous: it means the curve
    only on the unit sphere, so each point is taken as a direction and Q is evaluated at
    ``x / |x|`` (the same value for a point given in any unit of length). No surface of
    lower degree cuts the curve from the sphere. The longitude-latitude form is
    ``Q(to_xyz(lon, lat))``.

    Parameters
    ----------
    linkage : array_like, shape (..., 9), or SphericalFourBar
        As in `coupler_octic`.
    points : array_like, shape (..., 3)
        Non-zero vectors, taken as directions (points on the unit sphere).

    Returns
    -------
    value : ndarray, shape (...)
        Q at ``x / |x|``.
    gradient : ndarray, shape (..., 3)
        The gradient of Q at ``x / |x|``.

    Raises
    ------
    ValueError
        If an input is not finite or has the wrong shape, an arc is outside (0, pi), or a
        point is the zero vector.

    Notes
    -----
    Derivation: :ref:`deriv-spherical-coupler-curve`, eqs. (2), (3).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import SphericalFourBar, to_xyz
    >>> from mech.spherical.path import coupler_quartic
    >>> m = SphericalFourBar(0.5, 1.1, 0.9, 1.2, coupler=(0.6, 0.8))
    >>> value, _ = coupler_quartic(m, m.solve(1.0).P)
    >>> abs(float(value)) < 1e-14
    True
    """
    return _evaluate(_gen.spherical_coupler_quartic, None, linkage, points)


@register_coupler_polynomial
class CouplerOctic:
    """The implicit coupler curve of one `SphericalFourBar` (from
    `SphericalFourBar.coupler_curve_polynomial`).

    Calling it evaluates the octic F (value, gradient) as `coupler_octic` does, in the
    linkage's own frame (with the same `form` and `small` options); `quartic` evaluates Q, `lonlat` the longitude-latitude form ``Q(to_xyz(lon, lat))``; `params` are
    the nine parameters. Other forms: the parametric curve is `SphericalFourBar.solve`
    (P, vP, aP over the input angle).

    Examples
    --------
    >>> from mech.spherical import SphericalFourBar
    >>> curve = SphericalFourBar(0.5, 1.1, 0.9, 1.2, coupler=(0.6, 0.8)).coupler_curve_polynomial()
    >>> curve.degree, curve.params.shape
    (8, (9,))
    """

    degree = 8

    def __init__(self, linkage):
        self._params = nine_parameters(linkage)
        self._frame = _frame_of(linkage)

    params = property(lambda self: self._params.copy(), doc="(lon, lat, heading, a, b, c, d, r, gamma).")

    def __call__(self, points, *, form="auto", small=0.1):
        """F and its gradient at `points`, shape (..., 3) (see `coupler_octic`, also for
        `form` and `small`), in the linkage's own frame."""
        form = option("form", form, _FORMS)
        small = real_number("small", small)
        if small < 0.0:
            raise ValueError(f"Expected `small` >= 0, got {small!r}")
        return _evaluate(_gen.spherical_coupler_octic, 8, self._params, points, form=form, frame=self._frame,
                         small=small)

    def quartic(self, points):
        """Q and its gradient at `points`, shape (..., 3) (see `coupler_quartic`)."""
        return coupler_quartic(self._params, points)

    def lonlat(self, lon, lat):
        """The longitude-latitude form: Q at ``to_xyz(lon, lat)`` (zero on the curve)."""
        from mech.spherical._coordinates import to_xyz

        return coupler_quartic(self._params, to_xyz(lon, lat))[0]

    def __repr__(self):
        return f"CouplerOctic(params={np.round(self._params, 12).tolist()})"
