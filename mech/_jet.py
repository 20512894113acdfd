"""Truncated Taylor series in one variable (value and up to two derivatives) for exact rates.

Shared by the closed forms that continue a linkage through its change points
(`mech.spherical._fourbar_branch`, `mech.spatial._rssr_change`): a position written as a
smooth closed form in the input angle gives its rates as exact derivatives, with no
division by the root that vanishes where two branches meet.
"""

import numpy as np

__all__ = ["Jet", "jet_atan2"]


class Jet:
    """A function of theta with its first `n` derivatives (n <= 2), for exact rates."""

    __slots__ = ("v", "d1", "d2", "n")
    __array_ufunc__ = None               # NumPy scalars defer to the reflected operators

    def __init__(self, v, d1=None, d2=None, n=0):
        self.v, self.d1, self.d2, self.n = v, d1, d2, n

    @classmethod
    def const(cls, x, like):
        zero = np.zeros_like(like.v)
        x = x + zero
        return cls(x, zero if like.n >= 1 else None, zero if like.n >= 2 else None, like.n)

    def _lift(self, other):
        return other if isinstance(other, Jet) else Jet.const(other, self)

    def __add__(self, other):
        o = self._lift(other)
        return Jet(self.v + o.v, _opt(self.d1, o.d1, np.add), _opt(self.d2, o.d2, np.add), self.n)

    __radd__ = __add__

    def __neg__(self):
        return Jet(-self.v, None if self.d1 is None else -self.d1, None if self.d2 is None else -self.d2, self.n)

    def __sub__(self, other):
        return self + (-self._lift(other))

    def __rsub__(self, other):
        return self._lift(other) + (-self)

    def __mul__(self, other):
        if not isinstance(other, Jet):
            return Jet(self.v * other, None if self.d1 is None else self.d1 * other,
                        None if self.d2 is None else self.d2 * other, self.n)
        d1 = d2 = None
        if self.n >= 1:
            d1 = self.d1 * other.v + self.v * other.d1
        if self.n >= 2:
            d2 = self.d2 * other.v + 2 * self.d1 * other.d1 + self.v * other.d2
        return Jet(self.v * other.v, d1, d2, self.n)

    __rmul__ = __mul__

    def __truediv__(self, other):
        if not isinstance(other, Jet):
            return self * (1.0 / other)
        q = self.v / other.v
        d1 = d2 = None
        if self.n >= 1:
            d1 = (self.d1 - q * other.d1) / other.v
        if self.n >= 2:
            d2 = (self.d2 - 2 * d1 * other.d1 - q * other.d2) / other.v
        return Jet(q, d1, d2, self.n)

    def __rtruediv__(self, other):
        return Jet.const(other, self) / self

    def _chain(self, f0, f1, f2):
        """f(self) from f and its derivatives f1, f2 evaluated at self.v."""
        d1 = d2 = None
        if self.n >= 1:
            d1 = f1 * self.d1
        if self.n >= 2:
            d2 = f1 * self.d2 + f2 * self.d1 * self.d1
        return Jet(f0, d1, d2, self.n)

    def sin(self):
        s, c = np.sin(self.v), np.cos(self.v)
        return self._chain(s, c, -s)

    def cos(self):
        s, c = np.sin(self.v), np.cos(self.v)
        return self._chain(c, -s, -c)

    def sqrt(self):
        r = np.sqrt(self.v)
        return self._chain(r, 0.5 / r, -0.25 / (r * self.v))

    def where(self, mask, other):
        """This jet where `mask` is False, `other` where it is True."""
        o = self._lift(other)
        return Jet(np.where(mask, o.v, self.v), _opt(self.d1, o.d1, lambda x, y: np.where(mask, y, x)),
                    _opt(self.d2, o.d2, lambda x, y: np.where(mask, y, x)), self.n)


def _opt(x, y, op):
    return None if x is None else op(x, y)


def jet_atan2(y, x):
    """atan2 of two jets; both are scaled by their larger size first, so that tiny arcs
    (the planar limit) neither underflow nor lose digits in x^2 + y^2."""
    big = np.maximum(np.abs(y.v), np.abs(x.v))
    scale = 1.0 / np.where(big > 0.0, big, 1.0)
    y, x = y * scale, x * scale
    value = np.arctan2(y.v, x.v)
    d1 = d2 = None
    if y.n >= 1:
        den = x.v * x.v + y.v * y.v
        num = x.v * y.d1 - y.v * x.d1
        d1 = num / den
        if y.n >= 2:
            dnum = x.v * y.d2 - y.v * x.d2
            dden = 2 * (x.v * x.d1 + y.v * y.d1)
            d2 = (dnum - d1 * dden) / den
    return Jet(value, d1, d2, y.n)
