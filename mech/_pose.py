"""The immutable result record shared by every `solve` of the package."""

import numpy as np

__all__ = ["Pose", "mask_singular_rates"]


class Pose:
    """Immutable bundle of solved fields.

    Subclasses list the fields above order 0 in ``_ORDER_OF`` (reading one that was not
    solved raises an `AttributeError` naming the order needed) and the fields computed on
    first read in ``_DERIVED`` (``_derive(name)`` computes them; the result is kept).

    The masks: ``valid`` concerns the positions (order 0): False exactly where the linkage
    cannot be assembled, and every position field is NaN there. A pose solved with
    ``order >= 1`` may also carry ``rates_valid`` (see `mask_singular_rates`): False where
    the pose assembles but its velocity equations are singular (a dead point, where the
    rates are infinite or undetermined); the rates that depend on those equations are NaN
    there. So no field is ever NaN where its own mask is True.
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


def mask_singular_rates(fields, names):
    """Add the mask ``rates_valid`` to solved `fields` and NaN the rates where it is False.

    ``rates_valid`` is True where ``valid`` is True and every field in `names` is finite;
    those fields (the rates found by solving the singular velocity equations, not those
    fixed by the input link alone) are set to NaN where it is False, so that an infinite
    rate of a dead point reads as NaN under a False mask. Fields must already have the
    shape of ``valid``, optionally with trailing axes (vectors), which are reduced.
    """
    valid = np.asarray(fields["valid"])
    ok = valid.copy()
    values = {name: np.asarray(fields[name]) for name in names}
    for value in values.values():
        finite = np.isfinite(value)
        ok &= finite.reshape(valid.shape + (-1,)).all(axis=-1)
    for name, value in values.items():
        keep = ok.reshape(ok.shape + (1,) * (value.ndim - ok.ndim))
        nan = np.nan + 1j * np.nan if np.iscomplexobj(value) else np.nan
        fields[name] = np.where(keep, value, nan)[()]
    fields["rates_valid"] = ok[()]
    return fields
