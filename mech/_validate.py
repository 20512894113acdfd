"""Input checks that raise ``ValueError("Expected X, got Y")`` naming the argument."""

import numpy as np

__all__ = ["positive_length", "real_number", "finite_array", "arc", "arc_array", "branch_sign", "nonnegative_int", "motion_inputs"]


def _show(value):
    arr = np.asarray(value)
    return repr(arr.item()) if arr.ndim == 0 else np.array2string(arr, threshold=6)


def positive_length(name, value):
    """Return ``value`` as a float after checking that it is finite and > 0."""
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"Expected `{name}` to be a real number, got {value!r}") from None
    if not np.isfinite(x) or x <= 0.0:
        raise ValueError(f"Expected `{name}` > 0, got {x!r}")
    return x


def real_number(name, value):
    """Return ``value`` as a float after checking that it is a finite real number."""
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"Expected `{name}` to be a real number, got {value!r}") from None
    if not np.isfinite(x):
        raise ValueError(f"Expected finite `{name}`, got {x!r}")
    return x


def finite_array(name, value):
    """Return ``value`` as a float array after checking that every entry is finite."""
    arr = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(arr)):
        bad = float(arr[~np.isfinite(arr)].ravel()[0])
        raise ValueError(f"Expected finite `{name}`, got {bad!r}")
    return arr


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


def branch_sign(value, name="branch"):
    """Return ``value`` as the int +1 or -1."""
    if value not in (1, -1) or isinstance(value, bool):
        raise ValueError(f"Expected `{name}` to be +1 or -1, got {value!r}")
    return int(value)


def nonnegative_int(name, value, maximum):
    """Return ``value`` as an int in ``[0, maximum]``."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not 0 <= value <= maximum:
        raise ValueError(f"Expected `{name}` to be an integer in [0, {maximum}], got {value!r}")
    return int(value)


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
    shape = np.broadcast_shapes(*(x.shape for x in inputs))
    return order, shape, [np.broadcast_to(x, shape) for x in inputs]
