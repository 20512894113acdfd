"""The package's one input layer: checks that raise ``"Expected X, got Y"`` naming the argument.

Every public function sends its numeric arguments through these checks. They accept real
numbers only: Python ints and floats, NumPy integer and floating scalars and arrays, and
sequences of those. They reject, naming the argument and showing the value:

- complex numbers and complex arrays (casting would silently drop the imaginary part);
- booleans (``True`` is not a length), strings, bytes, ``None`` and other objects;
- NaN and infinities (unless a caller explicitly allows them);
- a wrong shape where a shape is fixed.

Planar points are complex by the package's convention: `planar_point` and `planar_points`
accept real and complex numbers but reject the rest as above (NaN or infinity in either
part included). Integers (`integer`, `nonnegative_int`), flags (`bool_flag`), the branch
sign (`branch_sign`) and string options (`option`) accept exactly their type: ``True`` is
not 1, ``1`` is not ``True`` and ``2.0`` is not an integer. Objects and names (a solved
linkage, a point name) are checked by `instance` and `known_name`.

A wrong *type* raises :class:`mech.InputTypeError`, which is both a ``TypeError`` and a
``ValueError``; a wrong *value* raises ``ValueError``. So ``except ValueError`` catches every
bad input, and ``except TypeError`` catches exactly the wrong types.
"""

import math
import numbers

import numpy as np

from mech._errors import InputTypeError

__all__ = [
    "positive_length",
    "real_number",
    "real_array",
    "finite_array",
    "arc",
    "arc_array",
    "branch_sign",
    "nonnegative_int",
    "motion_inputs",
    "vector3",
    "unit_vector",
    "proper_rotation",
    "bool_flag",
    "instance",
    "integer",
    "known_name",
    "nonnegative_number",
    "option",
    "real_tuple",
    "planar_point",
    "planar_points",
    "function_pairs",
    "common_shape",
    "finite_result",
    "naming",
]


def _show(value):
    """A short, safe text of ``value`` for an error message."""
    if isinstance(value, np.ma.MaskedArray):
        text = str(value)         # masked entries show as --
        return text if len(text) <= 80 else text[:77] + "..."
    if isinstance(value, (list, tuple)):
        # the user's own entries (``False``, ``2j``), not NumPy's conversion of them
        text = repr(value)
        return text if len(text) <= 80 else text[:77] + "..."
    try:
        arr = np.asarray(value)
    except Exception:  # pragma: no cover - objects that refuse even to be wrapped
        return repr(value)[:80]
    if arr.dtype.kind in "biufc" and arr.ndim == 0:
        return repr(arr.item())
    if arr.dtype.kind in "biufc":
        return np.array2string(arr, threshold=6)
    text = repr(value)
    return text if len(text) <= 80 else text[:77] + "..."


def _kind_name(arr):
    return {"b": "boolean", "c": "complex", "U": "string", "S": "bytes", "O": "object",
            "M": "datetime", "m": "timedelta", "V": "structured"}.get(arr.dtype.kind, str(arr.dtype))


#: The largest count of samples or points a public function accepts: an array beyond it
#: would not fit comfortably in memory, and NumPy's own error would not name the argument.
MAX_COUNT = 10**7

_NONE_BAD = object()

#: NumPy registers `timedelta64` as an integer type (and so a ``numbers.Real``), and
#: ``int(np.datetime64(...))`` works: neither is a number of the package.
_TIME = (np.datetime64, np.timedelta64)


def _is_int(value):
    """True for Python and NumPy integers; not booleans, not NumPy's time types."""
    return isinstance(value, (int, np.integer)) and not isinstance(value, (bool, np.bool_, *_TIME))


def _scalar_int(value):
    """A 0-d integer array as the integer it holds (NumPy itself takes one as a count:
    ``np.zeros(np.array(3))``, ``range(np.array(3))``); any other value unchanged."""
    if (isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind in "iu"
            and not np.ma.is_masked(value)):
        return value.item()
    return value


def _int_text(value):
    """The value for an integer's error message; a 0-d array is said to be one, so that
    ``np.array(2.0)`` does not read as the float ``2.0``."""
    if isinstance(value, np.ndarray) and value.ndim == 0:
        return f"a 0-d array {_show(value)}"
    return _show(value)


def _has_masked(value):
    """True if ``value``, or an array inside nested lists and tuples, has a masked entry."""
    if isinstance(value, np.ma.MaskedArray):
        return bool(np.ma.is_masked(value))
    if isinstance(value, (list, tuple)):
        return any(_has_masked(item) for item in value)
    return False


def _masked(name, value):
    """Reject masked entries (NumPy would read the arbitrary data under the mask)."""
    if _has_masked(value):
        raise ValueError(f"Expected `{name}` without masked entries, got {_show(value)}")
    return np.ma.getdata(value) if isinstance(value, np.ma.MaskedArray) else value


def _first_bad_object(arr, allowed=numbers.Real):
    for item in arr.ravel():
        if isinstance(item, (bool, np.bool_, *_TIME)) or not isinstance(item, allowed):
            return item
    return _NONE_BAD


def _first_bool(value):
    """The first boolean inside nested lists and tuples (NumPy would turn it into 1.0)."""
    if isinstance(value, (bool, np.bool_)):
        return value
    # a boolean array inside a list would otherwise become 1.0 and 0.0 with its neighbours
    if isinstance(value, np.ndarray) and value.dtype.kind == "b" and value.size:
        return value.ravel()[0]
    if isinstance(value, (list, tuple)):
        for item in value:
            found = _first_bool(item)
            if found is not _NONE_BAD:
                return found
    return _NONE_BAD


def _first_bad_leaf(value, allowed):
    """The first entry of nested lists and tuples that is not an ``allowed`` number."""
    if isinstance(value, (list, tuple)):
        for item in value:
            found = _first_bad_leaf(item, allowed)
            if found is not _NONE_BAD:
                return found
        return _NONE_BAD
    if isinstance(value, np.ndarray) and value.dtype.kind in "iufc":
        return _NONE_BAD
    if isinstance(value, (bool, np.bool_, *_TIME)) or not isinstance(value, allowed):
        return value
    return _NONE_BAD


def _unreadable(name, value, exc, what, allowed):
    """The error for a value NumPy cannot read as an array (ragged lists, odd objects)."""
    bad = _first_bad_leaf(value, allowed)
    shown = f"{bad!r} in {_show(value)}" if bad is not _NONE_BAD else f"{_show(value)} ({exc})"
    return InputTypeError(f"Expected `{name}` to be {what}, got {shown}")


def _first_text(arr, value):
    """The value shown for a string array: its first string that is not a number, in context."""
    if arr.dtype.kind not in "US" or arr.ndim == 0:
        return _show(value)
    for item in np.asarray(value, dtype=object).ravel():
        if isinstance(item, (str, bytes)):
            return f"{item!r} in {_show(value)}"
    return _show(value)


def _first_complex(arr):
    flat = arr.ravel()
    nonreal = np.flatnonzero(flat.imag != 0)
    return complex(flat[nonreal[0]] if nonreal.size else flat[0]) if flat.size else None


def real_array(name, value, *, finite=True):
    """Return ``value`` as a float array after checking that it holds real numbers only.

    Rejects booleans, complex numbers, strings, ``None`` and other objects with an
    :class:`~mech.InputTypeError`, and (with ``finite=True``) NaN and infinities with a
    ``ValueError``; every message names the argument ``name`` and shows the bad value.
    """
    if type(value) is float:
        # a plain number (the default rates of a solve): no array to inspect
        if not finite or math.isfinite(value):
            return np.asarray(value, dtype=float)
    if type(value) is np.ndarray and value.dtype == np.float64:
        # the common case, an array of floats: one summation decides (NaN or an infinity
        # makes the sum non-finite; a finite sum that overflows takes the full check)
        if not finite or math.isfinite(np.add.reduce(value, axis=None)):
            return value
    if value is None or isinstance(value, (str, bytes, bool, np.bool_, complex, np.complexfloating, *_TIME)):
        raise InputTypeError(f"Expected `{name}` to be a real number, got {value!r}")
    value = _masked(name, value)
    try:
        arr = np.asarray(value)
    except Exception as exc:
        raise _unreadable(name, value, exc, "real numbers", numbers.Real) from None
    kind = arr.dtype.kind
    bad = _first_bool(value)
    if bad is not _NONE_BAD:
        raise InputTypeError(f"Expected `{name}` to be real numbers, got {bad!r} in {_show(value)}")
    if kind == "c":
        raise InputTypeError(
            f"Expected `{name}` to be real numbers, got a complex value {_first_complex(arr)!r} in {_show(value)}"
        )
    if kind == "O":
        bad = _first_bad_object(arr)
        if bad is not _NONE_BAD:
            raise InputTypeError(f"Expected `{name}` to be real numbers, got {bad!r} in {_show(value)}")
        try:
            arr = arr.astype(float)
        except (TypeError, ValueError, OverflowError):
            raise InputTypeError(f"Expected `{name}` to be real numbers, got {_show(value)}") from None
    elif kind not in "iuf":
        raise InputTypeError(
            f"Expected `{name}` to be real numbers, got a {_kind_name(arr)} value {_first_text(arr, value)}"
        )
    arr = np.asarray(arr, dtype=float)
    if finite and not np.all(np.isfinite(arr)):
        bad = float(arr[~np.isfinite(arr)].ravel()[0])
        raise ValueError(f"Expected finite `{name}`, got {bad!r}")
    return arr


def finite_array(name, value):
    """Return ``value`` as a float array after checking that it holds finite real numbers."""
    return real_array(name, value, finite=True)


def _scalar(name, value):
    arr = real_array(name, value, finite=False)
    if arr.ndim != 0:
        raise ValueError(f"Expected `{name}` to be a single number, got shape {arr.shape}: {_show(value)}")
    return float(arr)


def real_number(name, value):
    """Return ``value`` as a float after checking that it is one finite real number."""
    x = _scalar(name, value)
    if not np.isfinite(x):
        raise ValueError(f"Expected finite `{name}`, got {x!r}")
    return x


#: The largest angle (radians) `angle` accepts: from 2**52 on, float64 has no fractional
#: radians (its spacing is 1 rad or more), so such an angle fixes no direction.
MAX_ANGLE = 2.0**52


def angle(name, value):
    """Return ``value`` as a float after checking that it is a finite angle, |value| < 2**52 rad.

    A larger angle has no digits below one radian: it names no direction, and the result
    of the computation it enters would depend on rounding. Refusing it here, by name, keeps
    it from reaching (and tripping) checks on other arguments.
    """
    x = real_number(name, value)
    if not abs(x) < MAX_ANGLE:
        raise ValueError(f"Expected `{name}` to be an angle below 2**52 ~ 4.5e15 rad in size (beyond it float64 "
                         f"has no fractional radians), got {x!r}")
    return x


def positive_length(name, value):
    """Return ``value`` as a float after checking that it is finite and > 0."""
    x = _scalar(name, value)
    if not (np.isfinite(x) and x > 0.0):
        raise ValueError(f"Expected `{name}` > 0, got {x!r}")
    return x


def nonnegative_number(name, value):
    """Return ``value`` as a float after checking that it is finite and >= 0 (a tolerance)."""
    x = _scalar(name, value)
    if not (np.isfinite(x) and x >= 0.0):
        raise ValueError(f"Expected `{name}` >= 0, got {x!r}")
    return x


def real_tuple(name, value, size):
    """Return ``value`` as a tuple of ``size`` finite floats, e.g. a coupler point ``(p, q)``."""
    arr = finite_array(name, value)
    if arr.shape != (size,):
        raise ValueError(f"Expected `{name}` to be {size} numbers, got shape {arr.shape}: {_show(value)}")
    return tuple(float(x) for x in arr)


def arc(name, value):
    """Return ``value`` as a float after checking that it is an arc in (0, pi) (a sphere)."""
    x = real_number(name, value)
    if not 0.0 < x < np.pi:
        raise ValueError(f"Expected `{name}` in (0, pi), got {x!r}")
    return x


def arc_array(name, value):
    """Return ``value`` as a float array after checking that every entry is in (0, pi)."""
    arr = finite_array(name, value)
    bad = (arr <= 0.0) | (arr >= np.pi)
    if np.any(bad):
        raise ValueError(f"Expected `{name}` in (0, pi), got {float(arr[bad].ravel()[0])!r}")
    return arr


def vector3(name, value):
    """Return ``value`` as a float array of shape ``(..., 3)`` with finite entries."""
    arr = finite_array(name, value)
    if arr.ndim == 0 or arr.shape[-1] != 3:
        raise ValueError(f"Expected `{name}` of shape (..., 3), got shape {arr.shape}")
    return arr


def unit_vector(name, value, tol=1e-9):
    """Return ``value``, a 3-vector of length 1 within `tol`, divided by its length.

    The division removes the rounding of a vector typed in to a few digits; a length
    further than `tol` from 1 raises ValueError naming the argument and its length.
    """
    v = np.asarray(real_tuple(name, value, 3), dtype=float)
    n = float(np.linalg.norm(v))
    if not abs(n - 1.0) <= tol:
        raise ValueError(f"Expected `{name}` to be a unit vector, got {value!r} (norm {n!r})")
    return v / n


def proper_rotation(name, value, tol=1e-9):
    """Return ``value`` as a 3x3 float array after checking it is a proper rotation.

    ``R.T @ R = I`` and ``det R = +1`` within `tol`, entry by entry; a reflection, a scaled
    or a sheared matrix raises ValueError naming the argument and showing the matrix.
    """
    R = finite_array(name, value)
    if R.shape != (3, 3):
        raise ValueError(f"Expected `{name}` to be a 3x3 rotation matrix, got shape {R.shape}")
    # entries of a rotation are at most 1 in size: test that first, so that R.T @ R
    # cannot overflow
    if np.max(np.abs(R)) > 1.0 + tol or np.max(np.abs(R.T @ R - np.eye(3))) > tol or np.linalg.det(R) <= 0.0:
        raise ValueError(f"Expected `{name}` to be a proper rotation (R.T @ R = I, det R = +1), "
                         f"got {np.array2string(R, precision=6)}")
    return R


def branch_sign(value, name="branch"):
    """Return ``value`` as the int +1 or -1."""
    if isinstance(value, (bool, np.bool_, *_TIME)) or not isinstance(value, (numbers.Integral, numbers.Real)):
        raise InputTypeError(f"Expected `{name}` to be +1 or -1, got {value!r}")
    if value not in (1, -1):
        raise ValueError(f"Expected `{name}` to be +1 or -1, got {value!r}")
    return int(value)


def nonnegative_int(name, value, maximum):
    """Return ``value`` as an int in ``[0, maximum]`` (a 0-d integer array counts as its integer)."""
    value = _scalar_int(value)
    if not _is_int(value):
        raise InputTypeError(f"Expected `{name}` to be an integer in [0, {maximum}], got {_int_text(value)}")
    if not 0 <= value <= maximum:
        raise ValueError(f"Expected `{name}` to be an integer in [0, {maximum}], got {value!r}")
    return int(value)


def bool_flag(name, value):
    """Return ``value`` as a bool after checking that it is ``True`` or ``False``."""
    if not isinstance(value, (bool, np.bool_)):
        raise InputTypeError(f"Expected `{name}` to be True or False, got {value!r}")
    return bool(value)


def integer(name, value, *, minimum=None, maximum=None):
    """Return ``value`` as an int after checking its type and the bounds given.

    Accepts Python and NumPy integers only, and a 0-d integer array as the integer it holds
    (as NumPy does for a count: ``np.zeros(np.array(3))``): booleans, floats (even ``2.0``),
    strings and other objects raise :class:`~mech.InputTypeError`; a value out of bounds
    raises ``ValueError``.
    """
    value = _scalar_int(value)
    bounds = {(None, None): "", (None, maximum): f" <= {maximum}", (minimum, None): f" >= {minimum}"}.get(
        (minimum, maximum), f" in [{minimum}, {maximum}]")
    if not _is_int(value):
        raise InputTypeError(f"Expected `{name}` to be an integer{bounds}, got {_int_text(value)}")
    if (minimum is not None and value < minimum) or (maximum is not None and value > maximum):
        raise ValueError(f"Expected `{name}` to be an integer{bounds}, got {value!r}")
    return int(value)


def option(name, value, allowed):
    """Return ``value`` after checking that it is one of the strings ``allowed``."""
    if not isinstance(value, str) or value not in allowed:
        choices = ", ".join(repr(a) for a in allowed)
        raise ValueError(f"Expected `{name}` to be one of {choices}, got {_show(value)}")
    return value


def instance(name, value, cls):
    """Return ``value`` after checking that it is a ``cls`` (e.g. a solved linkage)."""
    if not isinstance(value, cls):
        raise InputTypeError(f"Expected `{name}` to be a {cls.__name__}, got {_show(value)}")
    return value


def known_name(name, value, names):
    """Return ``value`` after checking that it is one of ``names`` (point or link names)."""
    try:
        hash(value)              # an unhashable value (a list, an array) is no name
        # ``True == 1``: a flag is no name even where a link is labelled 1
        known = not isinstance(value, (bool, np.bool_)) and value in names
    except (TypeError, ValueError):
        known = False
    if not known:
        listed = ", ".join(repr(n) for n in names)
        raise ValueError(f"Expected `{name}` among {listed}, got {_show(value)}")
    return value


def planar_points(name, value):
    """Return ``value`` as a complex array of finite planar points ``x + 1j*y``.

    Planar points are complex by the package's convention, so real and complex numbers are
    both accepted; booleans, strings, ``None``, other objects, NaN and infinities (in
    either part) are rejected by name.
    """
    if value is None or isinstance(value, (str, bytes, bool, np.bool_, *_TIME)):
        raise InputTypeError(f"Expected `{name}` to be a point x + 1j*y, got {value!r}")
    value = _masked(name, value)
    try:
        arr = np.asarray(value)
    except Exception as exc:
        raise _unreadable(name, value, exc, "points x + 1j*y", numbers.Complex) from None
    bad = _first_bool(value)
    if bad is not _NONE_BAD:
        raise InputTypeError(f"Expected `{name}` to be points x + 1j*y, got {bad!r} in {_show(value)}")
    if arr.dtype.kind == "O":
        bad = _first_bad_object(arr, numbers.Complex)
        if bad is not _NONE_BAD or arr.ndim == 0:
            bad = value if bad is _NONE_BAD else bad
            raise InputTypeError(f"Expected `{name}` to be points x + 1j*y, got {bad!r} in {_show(value)}")
        try:
            arr = arr.astype(complex)
        except (TypeError, ValueError, OverflowError):       # an int beyond the float range
            raise InputTypeError(f"Expected `{name}` to be points x + 1j*y, got {_show(value)}") from None
    elif arr.dtype.kind not in "iufc":
        raise InputTypeError(
            f"Expected `{name}` to be points x + 1j*y, got a {_kind_name(arr)} value {_first_text(arr, value)}"
        )
    arr = np.asarray(arr, dtype=complex)
    finite = np.isfinite(arr)
    if not np.all(finite):
        raise ValueError(f"Expected finite `{name}`, got {arr[~finite].ravel()[0]!r}")
    return arr


def planar_point(name, value):
    """Return ``value`` as one finite planar point, a Python complex (see `planar_points`)."""
    arr = planar_points(name, value)
    if arr.ndim != 0:
        raise ValueError(f"Expected `{name}` to be a single point, got shape {arr.shape}: {_show(value)}")
    return complex(arr)


def motion_inputs(name, angle, order, omega, alpha):
    """Check a driver's angle and the rates an order needs; broadcast them together.

    Returns ``(order, shape, arrays)``: the checked order (0, 1 or 2), the common shape and
    the broadcast read-only arrays ``[angle]``, ``[angle, omega]`` or
    ``[angle, omega, alpha]`` (the rates a lower order does not need are not checked).
    """
    order = nonnegative_int("order", order, 2)
    inputs = [finite_array(name, angle)]
    if order >= 1:
        inputs.append(finite_array("omega", omega))
    if order >= 2:
        inputs.append(finite_array("alpha", alpha))
    shape = inputs[0].shape
    if any(x.shape != shape for x in inputs[1:]):
        shape = common_shape(**dict(zip((name, "omega", "alpha"), inputs)))
    return order, shape, [_read_only(x, shape) for x in inputs]


def _read_only(x, shape):
    """``x`` broadcast to `shape` as a read-only view (a plain view when no broadcast is needed)."""
    if x.shape != shape:
        return np.broadcast_to(x, shape)
    view = x.view()
    view.flags.writeable = False
    return view


def common_shape(**arrays):
    """The broadcast shape of the named arrays; a ValueError naming each shape if none."""
    shapes = {np.shape(x) for x in arrays.values()}
    shapes.discard(())
    if len(shapes) <= 1:
        # one array and scalars (a solve's inputs and its default rates): nothing to broadcast
        return shapes.pop() if shapes else ()
    try:
        return np.broadcast_shapes(*shapes)
    except ValueError:
        shapes = ", ".join(f"`{n}` {np.shape(x)}" for n, x in arrays.items())
        raise ValueError(f"Expected shapes that broadcast together, got {shapes}") from None


def function_pairs(x, y, minimum):
    """Check the pairs ``(x, y)`` of a function to generate: 1-D, one length, distinct `x`.

    Returns the two float arrays; raises ValueError naming `x` or `y` when they are not
    finite, not 1-D arrays of one length, fewer than `minimum`, or `x` repeats a value.
    """
    x, y = finite_array("x", x), finite_array("y", y)
    if x.ndim != 1 or y.shape != x.shape:
        raise ValueError(f"Expected `x` and `y` as 1-D arrays of one length, got shapes {x.shape} and {y.shape}")
    if x.size < minimum:
        raise ValueError(f"Expected at least {minimum} pairs in `x` and `y`, got {x.size}")
    if np.unique(x).size != x.size:
        raise ValueError(f"Expected distinct `x` values, got {x}")
    return x, y


def naming(**given):
    """The givens as "`a`, `b` and `c`" and "a=1.0, b=2.0, c=3.0" for an error message."""
    names = [f"`{k}`" for k in given]
    listed = names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]
    return listed, ", ".join(f"{k}={_show(v)}" for k, v in given.items())


def finite_result(value, what, **given):
    """`value` if every entry is finite; else a ValueError naming the givens and values.

    For results whose true value lies beyond the float range (an overflow), computed under
    ``np.errstate`` so that no RuntimeWarning escapes: "Expected `a` and `b` so that
    <what> is finite, got a=..., b=...".
    """
    if np.all(np.isfinite(value)):
        return value
    listed, shown = naming(**given)
    raise ValueError(f"Expected {listed} so that {what} is finite, got {shown}")
