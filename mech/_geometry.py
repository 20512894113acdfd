"""Small geometry helpers that several subjects share, each defined once.

Every function here takes NumPy arrays (or scalars) that the caller has already checked,
broadcasts like a ufunc, and never raises on a value: a degenerate input gives the documented
limit or NaN. Plane vectors are complex numbers ``x + 1j*y``; space vectors are arrays whose
last axis has length 3. Input checks (names, types, ranges) live in `mech._validate`.

The contracts, one per function:

- `wrap_angle`: an angle brought to (-pi, pi], the same direction (``atan2(sin, cos)``).
- `plane_cross`: the z component of the cross product of two plane vectors.
- `cross3`: the cross product of space vectors along the last axis.
- `cross_components`: the cross product of vectors given as three components of any ring
  (floats, arrays, dual numbers), as a tuple.
- `unit_rows`: space vectors scaled to length 1 along the last axis (NaN for a zero row).
- `acute_angle`: the angle in [0, pi/2] between the LINES of two plane vectors.
- `acute_angle_from_cosine`: the angle in [0, pi/2] whose cosine is ``|c|``.
"""

import numpy as np

from mech._generated.pressure_angle import acute_angle as _acute_angle_xy

__all__ = ["acute_angle", "acute_angle_from_cosine", "cross3", "cross_components", "plane_cross", "unit_rows", "wrap_angle"]


def wrap_angle(angle):
    """The angle in (-pi, pi] with the same direction as `angle` (radians).

    Computed as ``atan2(sin(angle), cos(angle))``, exact for angles already in range. The
    float nearest pi lies just below pi, so ``np.pi`` stays ``np.pi`` and ``-np.pi`` (just
    above -pi, inside the range) stays ``-np.pi``.

    Examples
    --------
    >>> from mech._geometry import wrap_angle
    >>> round(float(wrap_angle(3 * np.pi / 2)), 12), float(wrap_angle(np.pi))
    (-1.570796326795, 3.141592653589793)
    """
    angle = np.asarray(angle, dtype=float)
    return np.arctan2(np.sin(angle), np.cos(angle))


def plane_cross(u, w):
    """``u_x w_y - u_y w_x`` for plane vectors given as complex numbers ``x + 1j*y``.

    Positive when `w` lies counter-clockwise of `u` (within half a turn).

    Examples
    --------
    >>> from mech._geometry import plane_cross
    >>> float(plane_cross(2.0, 3j)), float(plane_cross(3j, 2.0))
    (6.0, -6.0)
    """
    return np.imag(np.conj(u) * w)


def cross3(a, b):
    """The cross product ``a x b`` of space vectors along the last axis (shape (..., 3)).

    Written out rather than `numpy.cross`, which costs more than the six products on the
    small stacks the solvers use; the stacks broadcast.

    Examples
    --------
    >>> from mech._geometry import cross3
    >>> cross3(np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0])).tolist()
    [0.0, 0.0, 1.0]
    """
    a, b = np.asarray(a), np.asarray(b)
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack((a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0), axis=-1)


def cross_components(u, v):
    """The cross product of vectors given as three components ``(x, y, z)``, as a tuple.

    The components may be floats, arrays or any numbers with ``*`` and ``-`` (dual numbers,
    `mech.spherical.Dual`): the formula uses nothing else.

    Examples
    --------
    >>> from mech._geometry import cross_components
    >>> cross_components((0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    (1.0, 0.0, 0.0)
    """
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def unit_rows(v):
    """Space vectors `v` (shape (..., 3)) divided by their lengths along the last axis.

    Each row is first scaled by a power of two that brings its largest component near 1
    (exact, so a row of normal size gives the same quotient as without it), so rows of
    size 1e-300 or 1e300 do not underflow or overflow in the squares. A zero row gives NaN,
    silently: the callers mark such rows as degenerate themselves. Complex rows are allowed.

    Examples
    --------
    >>> from mech._geometry import unit_rows
    >>> unit_rows(np.array([[3.0, 0.0, 4.0], [0.0, 0.0, 0.0]])).tolist()
    [[0.6, 0.0, 0.8], [nan, nan, nan]]
    """
    v = np.asarray(v)
    big = np.max(np.abs(v), axis=-1, keepdims=True)
    _, exponent = np.frexp(np.where(big > 0.0, big, 1.0))
    half = exponent // 2
    # two steps, so that neither power of two overflows for the smallest or largest rows
    with np.errstate(invalid="ignore", under="ignore"):
        scaled = v * np.ldexp(1.0, -half) * np.ldexp(1.0, half - exponent)
        n = np.linalg.norm(scaled, axis=-1, keepdims=True)
    with np.errstate(invalid="ignore", divide="ignore"):
        return scaled / n


def acute_angle(u, v):
    """The acute angle in [0, pi/2] between the lines of plane vectors `u` and `v` (complex).

    ``atan2(|u x v|, |u . v|)`` (F49, :ref:`deriv-pressure-angle`): accurate near 0 and
    pi/2 alike, and the lengths of `u` and `v` drop out. The angle between a force and
    a velocity (the pressure angle) and the one between a link and a guide are both this.

    Examples
    --------
    >>> from mech._geometry import acute_angle
    >>> round(float(np.degrees(acute_angle(1.0 + 1.0j, -2.0))), 9)
    45.0
    """
    u, v = np.asarray(u, dtype=complex), np.asarray(v, dtype=complex)
    return _acute_angle_xy(u.real, u.imag, v.real, v.imag)


def acute_angle_from_cosine(cos_angle):
    """The angle in [0, pi/2] whose cosine is ``|cos_angle|`` (clipped to 1).

    The transmission angle of a joint angle with this cosine, computed as
    ``pi/2 - asin(|c|)``.

    Examples
    --------
    >>> from mech._geometry import acute_angle_from_cosine
    >>> round(float(np.degrees(acute_angle_from_cosine(-0.5))), 9)
    60.0
    """
    return np.pi / 2 - np.arcsin(np.clip(np.abs(cos_angle), 0.0, 1.0))
