"""Dual numbers x + eps y with eps**2 = 0 (对偶数), vectorised over NumPy arrays.

A dual number carries a real part and a dual part. Every analytic function extends to
dual numbers by f(x + eps y) = f(x) + eps y f'(x), so one evaluation gives a value and a
directional derivative. In the kinematics of spatial linkages a dual angle (对偶角)
``theta + eps s`` pairs an angle with a distance along the same axis: the transference
principle (转换原理) of :ref:`deriv-spherical-transference` runs the formulas of a
spherical linkage on dual angles to get the spatial linkage of the same topology.

`Dual` implements NumPy's ``__array_ufunc__`` for the ufuncs that the generated code of the
package uses (``np.cos``, ``np.sin``, ``np.arctan2``, ``np.sqrt``, ...), so a generated
function written for arrays runs unchanged on dual arguments.
"""

import numpy as np

from mech._validate import real_array

__all__ = ["Dual", "dual"]


def _part(value):
    return value.real_part if isinstance(value, Dual) else np.asarray(value, dtype=float)


def _dpart(value):
    return value.dual_part if isinstance(value, Dual) else np.zeros_like(np.asarray(value, dtype=float))


class Dual:
    """An immutable array of dual numbers ``real + eps * dual`` with ``eps**2 = 0``.

    Parameters
    ----------
    real, dual : array_like
        Real and dual parts; they broadcast against each other.

    Raises
    ------
    ValueError
        If a part is not finite or the shapes do not broadcast; `mech.InputTypeError` (also
        a ``TypeError``) if a part is complex, boolean, a string or another object.

    Notes
    -----
    Arithmetic (``+ - * / **`` with real exponents, unary ``-``) mixes freely with
    scalars and arrays. The NumPy functions ``cos, sin, tan, arctan, arctan2, sqrt, exp,
    log, absolute, square, hypot`` apply the rule f(x + eps y) = f(x) + eps y f'(x); any
    other ufunc raises ``TypeError``. Division needs a non-zero real part of the divisor
    (an exact zero gives inf/NaN, as for arrays); ``sqrt`` of a zero real part has an
    infinite dual part. Comparisons are not defined: compare ``.real_part``.
    The theory is on page :ref:`deriv-spherical-transference`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._dual import Dual
    >>> x = Dual(0.5, 1.0)                 # 0.5 + eps
    >>> y = np.sin(x)                      # sin(0.5) + eps cos(0.5)
    >>> round(float(y.real_part), 12), round(float(y.dual_part), 12)
    (0.479425538604, 0.87758256189)
    >>> (x * x).dual_part                  # d(x**2) = 2 x dx
    array(1.)
    >>> np.cos(Dual([np.pi / 6, np.pi / 2], [2.0, 2.0])).dual_part.round(12)
    array([-1., -2.])
    """

    __slots__ = ("_re", "_du")

    def __init__(self, real, dual=0.0):
        re, du = real_array("real", real), real_array("dual", dual)
        try:
            np.broadcast_shapes(re.shape, du.shape)
        except ValueError:
            raise ValueError(f"Expected `real` and `dual` shapes that broadcast together, "
                             f"got {re.shape} and {du.shape}") from None
        self._set(re, du)

    @classmethod
    def _raw(cls, real, dual=0.0):
        """A dual number from parts already known to be real arrays (NaN allowed): the
        arithmetic below builds its results with this, unchecked."""
        new = object.__new__(cls)
        new._set(np.asarray(real, dtype=float), np.asarray(dual, dtype=float))
        return new

    def _set(self, re, du):
        re, du = np.broadcast_arrays(re, du)
        re, du = re.copy(), du.copy()
        re.flags.writeable = False
        du.flags.writeable = False
        object.__setattr__(self, "_re", re)
        object.__setattr__(self, "_du", du)

    real_part = property(lambda self: self._re, doc="Real part (read-only array).")
    dual_part = property(lambda self: self._du, doc="Dual part (read-only array).")
    shape = property(lambda self: self._re.shape, doc="Broadcast shape of the two parts.")

    def __setattr__(self, name, value):
        raise AttributeError("Dual is immutable")

    def __repr__(self):
        return f"Dual({np.array2string(self._re)}, {np.array2string(self._du)})"

    def __getitem__(self, index):
        return Dual._raw(self._re[index], self._du[index])

    # arithmetic -------------------------------------------------------------------
    def __add__(self, other):
        return Dual._raw(self._re + _part(other), self._du + _dpart(other))

    __radd__ = __add__

    def __sub__(self, other):
        return Dual._raw(self._re - _part(other), self._du - _dpart(other))

    def __rsub__(self, other):
        return Dual._raw(_part(other) - self._re, _dpart(other) - self._du)

    def __mul__(self, other):
        o_re, o_du = _part(other), _dpart(other)
        return Dual._raw(self._re * o_re, self._re * o_du + self._du * o_re)

    __rmul__ = __mul__

    def __truediv__(self, other):
        o_re, o_du = _part(other), _dpart(other)
        return Dual._raw(self._re / o_re, (self._du * o_re - self._re * o_du) / (o_re * o_re))

    def __rtruediv__(self, other):
        return Dual._raw(other) / self

    def __neg__(self):
        return Dual._raw(-self._re, -self._du)

    def __pos__(self):
        return self

    def __pow__(self, exponent):
        if isinstance(exponent, Dual):
            raise TypeError("Expected a real exponent for a Dual power, got a Dual")
        p = np.asarray(exponent, dtype=float)
        return Dual._raw(self._re**p, p * self._re ** (p - 1.0) * self._du)

    # NumPy functions --------------------------------------------------------------
    def __array_ufunc__(self, ufunc, method, *inputs, **kwargs):
        if method != "__call__" or kwargs:
            return NotImplemented
        rule = _RULES.get(ufunc)
        if rule is None:
            raise TypeError(f"Expected a ufunc with a dual rule ({', '.join(sorted(u.__name__ for u in _RULES))}), "
                            f"got {ufunc.__name__}")
        return rule(*inputs)


def _unary(f, df):
    def rule(x):
        x = x if isinstance(x, Dual) else Dual._raw(x)
        return Dual._raw(f(x.real_part), df(x.real_part) * x.dual_part)
    return rule


def _atan2(y, x):
    y_re, y_du, x_re, x_du = _part(y), _dpart(y), _part(x), _dpart(x)
    return Dual._raw(np.arctan2(y_re, x_re), (x_re * y_du - y_re * x_du) / (x_re * x_re + y_re * y_re))


def _hypot(x, y):
    x_re, x_du, y_re, y_du = _part(x), _dpart(x), _part(y), _dpart(y)
    r = np.hypot(x_re, y_re)
    return Dual._raw(r, (x_re * x_du + y_re * y_du) / r)


_RULES = {
    np.add: lambda x, y: Dual._raw(_part(x), _dpart(x)) + y,
    np.subtract: lambda x, y: Dual._raw(_part(x), _dpart(x)) - y,
    np.multiply: lambda x, y: Dual._raw(_part(x), _dpart(x)) * y,
    np.true_divide: lambda x, y: Dual._raw(_part(x), _dpart(x)) / y,
    np.power: lambda x, p: Dual._raw(_part(x), _dpart(x)) ** p,
    np.negative: lambda x: -x,
    np.positive: lambda x: x,
    np.square: lambda x: x * x,
    np.cos: _unary(np.cos, lambda r: -np.sin(r)),
    np.sin: _unary(np.sin, np.cos),
    np.tan: _unary(np.tan, lambda r: 1.0 / np.cos(r) ** 2),
    np.arctan: _unary(np.arctan, lambda r: 1.0 / (1.0 + r * r)),
    np.exp: _unary(np.exp, np.exp),
    np.log: _unary(np.log, lambda r: 1.0 / r),
    np.sqrt: _unary(np.sqrt, lambda r: 0.5 / np.sqrt(r)),
    np.absolute: _unary(np.abs, np.sign),
    np.arctan2: _atan2,
    np.hypot: _hypot,
}


def dual(real, dual=0.0):
    """Return the dual number (or array) ``real + eps * dual``.

    Parameters
    ----------
    real, dual : array_like
        Real and dual parts, broadcast against each other.

    Returns
    -------
    Dual

    Notes
    -----
    A dual angle (对偶角) is ``dual(angle, distance)``: a twist with a link length, or a
    joint angle with a slide along the joint axis (:ref:`deriv-spherical-transference`).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._dual import dual
    >>> t = dual(np.pi / 3, 2.0)           # 60 degrees, 2 units along the axis
    >>> c = np.cos(t)
    >>> round(float(c.real_part), 12), round(float(c.dual_part), 12)
    (0.5, -1.732050807569)
    """
    return Dual(real, dual)
