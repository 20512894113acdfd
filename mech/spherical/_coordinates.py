"""Coordinates on the unit sphere: longitude and latitude, the local frame, the arc between
two points (the spherical monograph, §§1.1 and 1.2).

Conventions (``CONVENTIONS.md``): ``to_xyz(lon, lat) = (cos lat cos lon, cos lat sin lon,
sin lat)``, lon = 0 at the poles; the local frame at P has x along the meridian toward
decreasing latitude and y east, so that x cross y = P (outward).
"""

import numpy as np

from mech._generated.spherical_calculus import sph_distance_lonlat, sph_local_frame, sph_to_xyz
from mech._validate import common_shape, finite_array

__all__ = ["to_xyz", "from_xyz", "local_frame", "distance", "distance_lonlat"]

_EPS = np.finfo(float).eps


def _norm(v):
    """Euclidean norm over the last axis, free of overflow and underflow.

    Each row is divided by its largest absolute component before squaring (as `hypot`
    does), so rows of size 1e-300 or 1e300 keep full relative accuracy; zero rows give 0.
    """
    v = np.asarray(v, dtype=float)
    big = np.max(np.abs(v), axis=-1)
    safe = np.where(big > 0.0, big, 1.0)
    w = v / safe[..., None]
    return big * np.sqrt(np.sum(w * w, axis=-1))


def unit_vectors(name, value):
    """Return ``value`` as a float array of shape (..., 3) with finite, non-zero rows.

    Rows whose norm is 1 to within a few rounding errors are used as given (dividing by a
    norm of 1 +- 1e-16 would move the point sideways by a rounding error, which matters for
    arcs of 1e-8); other rows are scaled to unit length. Each row is first divided by its
    largest absolute component, so any finite non-zero row (1e-300 or 1e300 in size) gives
    a unit vector; only an exactly zero row is rejected.
    """
    arr = finite_array(name, value)
    if arr.ndim == 0 or arr.shape[-1] != 3:
        raise ValueError(f"Expected `{name}` of shape (..., 3), got shape {arr.shape}")
    big = np.max(np.abs(arr), axis=-1)
    if np.any(big == 0.0):
        index = np.argwhere(np.atleast_1d(big == 0.0))[0]
        raise ValueError(f"Expected non-zero vectors in `{name}`, got the zero vector at index {tuple(index)}")
    scaled = arr / big[..., None]
    size = np.sqrt(np.sum(scaled * scaled, axis=-1))          # in [1, sqrt(3)]
    # a unit row has big in [1/sqrt(3), 1], where big * size cannot overflow
    near_unit = (big <= 1.0) & (np.abs(np.minimum(big, 1.0) * size - 1.0) <= 8 * _EPS)
    return np.where(near_unit[..., None], arr, scaled / size[..., None])


def _stack(*components):
    """Stack broadcast components along a new last axis."""
    return np.stack(np.broadcast_arrays(*components), axis=-1)


def _cross_accurate(p, q):
    """p x q, formed as (p - q) x q or (p + q) x q so that it keeps its relative accuracy
    for nearly equal and nearly antipodal unit vectors (derivation, eq. 4)."""
    dot = np.sum(p * q, axis=-1)[..., None]
    return np.where(dot >= 0.0, np.cross(p - q, q), np.cross(p + q, q))


def to_xyz(lon, lat):
    """Unit vector of the point with longitude `lon` and latitude `lat`.

    ``to_xyz(lon, lat) = (cos lat cos lon, cos lat sin lon, sin lat)``, eq. (1) of the
    spherical calculus (monograph §1.1).

    Parameters
    ----------
    lon, lat : array_like
        Longitude (经度, theta) and latitude (纬度, phi), radians; they broadcast.

    Returns
    -------
    ndarray, shape (..., 3)
        The points.

    Raises
    ------
    ValueError
        If an angle is not finite.

    Notes
    -----
    Derived on page :ref:`deriv-spherical-calculus`. Any `lat` is accepted (the formula is
    periodic); `from_xyz` returns the canonical pair with lat in [-pi/2, pi/2].

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._coordinates import to_xyz
    >>> to_xyz(0.0, np.pi / 2).round(12) + 0.0
    array([0., 0., 1.])
    >>> to_xyz([0.0, np.pi / 2], 0.0).round(12) + 0.0
    array([[1., 0., 0.],
           [0., 1., 0.]])
    """
    lon = finite_array("lon", lon)
    lat = finite_array("lat", lat)
    common_shape(lon=lon, lat=lat)
    return _stack(*sph_to_xyz(lon, lat))


def from_xyz(v):
    """Longitude and latitude of the direction `v` (the inverse of `to_xyz`).

    lat = atan2(z, sqrt(x^2 + y^2)), accurate near the poles, and lon = atan2(y, x), set to 0
    exactly where x = y = 0 (the monograph's rule at the poles), eq. (2).

    Parameters
    ----------
    v : array_like, shape (..., 3)
        Non-zero vectors (they need not have unit length).

    Returns
    -------
    lon : ndarray, shape (...)
        Longitude in (-pi, pi].
    lat : ndarray, shape (...)
        Latitude in [-pi/2, pi/2].

    Raises
    ------
    ValueError
        If `v` has the wrong shape, a non-finite entry, or a zero row.

    Notes
    -----
    Derived on page :ref:`deriv-spherical-calculus`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._coordinates import from_xyz, to_xyz
    >>> lon, lat = from_xyz(to_xyz(0.5, -0.25))
    >>> float(lon), float(lat)
    (0.5, -0.25)
    >>> from_xyz([[0.0, 0.0, 2.0], [0.0, -1.0, 0.0]])
    (array([ 0.        , -1.57079633]), array([1.57079633, 0.        ]))
    """
    v = unit_vectors("v", v)
    x, y, z = v[..., 0], v[..., 1], v[..., 2]
    rho = np.hypot(x, y)
    lon = np.where(rho > 0.0, np.arctan2(y, x), 0.0)
    return lon, np.arctan2(z, rho)


def local_frame(p):
    """The local frame (e_x, e_y) at the point `p`.

    e_x = (sin lat cos lon, sin lat sin lon, -cos lat) runs along the meridian toward
    decreasing latitude, e_y = (-sin lon, cos lon, 0) runs east, and e_x x e_y = p. At the
    north pole (lon = 0) they are the global x and y axes.

    Parameters
    ----------
    p : array_like, shape (..., 3)
        Points (non-zero vectors; scaled to unit length).

    Returns
    -------
    ex, ey : ndarray, shape (..., 3)
        The two unit tangents.

    Raises
    ------
    ValueError
        If `p` has the wrong shape, a non-finite entry, or a zero row.

    Notes
    -----
    The inclination (倾角) of a direction at `p` is its angle from e_x, counter-clockwise
    seen from outside. Near the north pole the frame is the planar polar frame (e_r,
    e_theta) of the point. Derived on page :ref:`deriv-spherical-calculus`.

    Examples
    --------
    >>> from mech.spherical._coordinates import local_frame
    >>> ex, ey = local_frame([0.0, 0.0, 1.0])
    >>> ex, ey
    (array([1., 0., 0.]), array([0., 1., 0.]))
    >>> ex, ey = local_frame([[1.0, 0.0, 0.0]])
    >>> ex, ey
    (array([[ 0.,  0., -1.]]), array([[0., 1., 0.]]))
    """
    p = unit_vectors("p", p)
    x, y, z = p[..., 0], p[..., 1], p[..., 2]
    rho = np.hypot(x, y)
    positive = rho > 0.0
    safe = np.where(positive, rho, 1.0)
    clon = np.where(positive, x / safe, 1.0)
    slon = np.where(positive, y / safe, 0.0)
    parts = sph_local_frame(clon, slon, rho, z)
    zero = np.zeros_like(z)
    ex = _stack(*(c + zero for c in parts[:3]))  # + 0.0 turns -0.0 into 0.0
    ey = _stack(parts[3] + zero, parts[4] + zero, zero)
    return ex, ey


def distance(p, q):
    """Arc between the points `p` and `q`: the angle they subtend at the centre.

    d = atan2(``|p x q|``, p . q) with p x q formed as (p - q) x q (or (p + q) x q when
    p . q < 0), eq. (4) of the spherical calculus: accurate to a few rounding errors,
    relative to the arc, for arcs near 0 and near pi, where arccos(p . q) loses half the
    digits.

    Parameters
    ----------
    p, q : array_like, shape (..., 3)
        Points; non-zero vectors are accepted (the arc is between their directions).

    Returns
    -------
    ndarray, shape (...)
        The arc in [0, pi].

    Raises
    ------
    ValueError
        If an argument has the wrong shape, a non-finite entry, or a zero row.

    Notes
    -----
    The law-of-cosines form cos d = sin lat1 sin lat2 + cos lat1 cos lat2 cos(lon1 - lon2)
    is equal in theory; `distance_lonlat` evaluates it without cancellation. Derived on page
    :ref:`deriv-spherical-calculus`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._coordinates import distance
    >>> float(distance([0, 0, 1], [1, 0, 0]))
    1.5707963267948966
    >>> distance([0.0, 0.0, 1.0], [[0.0, 0.6, 0.8], [0.0, 0.0, -1.0]])
    array([0.64350111, 3.14159265])
    >>> p = np.array([0.0, 0.0, 1.0]); q = np.array([1e-9, 0.0, 1.0])
    >>> float(distance(p, q)), float(np.arccos(p @ q / np.linalg.norm(q)))
    (1e-09, 0.0)
    """
    p = unit_vectors("p", p)
    q = unit_vectors("q", q)
    p, q = np.broadcast_arrays(p, q)
    c = _cross_accurate(p, q)
    return np.arctan2(_norm(c), np.sum(p * q, axis=-1))


def distance_lonlat(lon1, lat1, lon2, lat2):
    """Arc between two points given by their coordinates, accurate near 0 and pi.

    The law of cosines cos d = sin lat1 sin lat2 + cos lat1 cos lat2 cos(lon2 - lon1) in the
    cancellation-free form (5) of the spherical calculus: d = atan2(sqrt(S1^2 + S2^2), C).

    Parameters
    ----------
    lon1, lat1, lon2, lat2 : array_like
        Longitudes and latitudes of the two points, radians; they broadcast.

    Returns
    -------
    ndarray
        The arc in [0, pi].

    Raises
    ------
    ValueError
        If an angle is not finite.

    Notes
    -----
    Derived on page :ref:`deriv-spherical-calculus`; agrees with `distance` of the
    points' `to_xyz`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._coordinates import distance_lonlat
    >>> round(float(distance_lonlat(0.0, 0.0, np.pi / 2, 0.0)), 12)
    1.570796326795
    >>> distance_lonlat(0.0, 0.0, [1e-9, np.pi], 0.0)
    array([1.00000000e-09, 3.14159265e+00])
    """
    args = [finite_array(n, v) for n, v in
            (("lon1", lon1), ("lat1", lat1), ("lon2", lon2), ("lat2", lat2))]
    common_shape(**dict(zip(("lon1", "lat1", "lon2", "lat2"), args)))
    return np.asarray(sph_distance_lonlat(*args))
