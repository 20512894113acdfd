"""The immutable result record shared by every `solve` of the package."""

import numpy as np

__all__ = ["Pose"]


class Pose:
    """Immutable bundle of solved fields.

    Subclasses list the fields above order 0 in ``_ORDER_OF`` (reading one that was not
    solved raises an `AttributeError` naming the order needed) and the fields computed on
    first read in ``_DERIVED`` (``_derive(name)`` computes them; the result is kept).
    """

    _ORDER_OF = {}
    _DERIVED = ()

    def __init__(self, order, fields):
        object.__setattr__(self, "order", order)
        object.__setattr__(self, "_fields", fields)

    def __getattr__(self, name):
        fields = self.__dict__.get("_fields", {})
        if name in fields:
            return fields[name]
        if name in self._DERIVED:
            fields[name] = value = self._derive(name)
            return value
        if name in self._ORDER_OF:
            raise AttributeError(
                f"`{name}` needs solve(..., order={self._ORDER_OF[name]}) or higher; "
                f"this pose was solved with order={self.order}"
            )
        raise AttributeError(f"{type(self).__name__} has no attribute {name!r}")

    def _derive(self, name):
        raise NotImplementedError(name)

    def __setattr__(self, name, value):
        raise AttributeError(f"{type(self).__name__} is immutable")

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._fields) | set(self._DERIVED))

    def __repr__(self):
        valid = np.asarray(self._fields["valid"])
        return (f"{type(self).__name__}(order={self.order}, shape={valid.shape}, "
                f"valid={int(valid.sum())}/{valid.size})")
