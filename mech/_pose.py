"""The immutable result records shared by the solvers: `Pose` (every `solve`) and `AssemblyRange`."""

import functools
import math
from dataclasses import dataclass

import numpy as np

from mech._validate import finite_array

__all__ = ["AssemblyRange", "Pose", "mask_singular_rates", "quiet_overflow"]


class Pose:
    """Immutable bundle of solved fields.

    Subclasses list the fields above order 0 in ``_ORDER_OF`` (reading one that was not
    solved raises an `AttributeError` naming the order needed) and the fields computed on
    first read in ``_DERIVED`` (``_derive(name)`` computes them; the result is kept).

    The masks (the package's promise, page "What the package promises"):

    - ``valid``: True exactly where every field that was solved holds a number. It is
      False where the linkage cannot be assembled (every field is NaN there) and, for a
      pose solved with ``order >= 1``, also at a dead point, where the pose assembles but
      its velocity equations are singular, so the rates are infinite or undetermined
      (those rates are NaN there; see `mask_singular_rates`). No field is ever NaN where
      ``valid`` is True.
    - ``assembled``: True where the position exists, whatever the order. It differs from
      ``valid`` only at dead points, where the positions are solved and finite.
    """

    _ORDER_OF = {}
    _DERIVED = ()

    def __init__(self, order, fields, finite=False):
        # finite=True: the solver has already checked that every solved field is finite
        # (block by block, while the block was in cache), so the promise holds as it is
        object.__setattr__(self, "order", order)
        object.__setattr__(self, "_fields", fields if finite else _keep_promise(fields))

    def __getattr__(self, name):
        fields = self.__dict__.get("_fields", {})
        if name in fields:
            return fields[name]
        if name == "assembled" and "valid" in fields:
            return fields["valid"]
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


def quiet_overflow(solve):
    """Run `solve` with NumPy's overflow warnings off: a rate beyond the float range (an
    angular velocity of 1e200 squared) becomes inf, and 0 times it NaN, which `Pose` then
    masks like a dead point's rate (``valid`` False, NaN). Only for solvers returning a
    `Pose` (the mask is the warning), or whose formulas cannot make 0 times inf."""

    @functools.wraps(solve)
    def quiet(*args, **kwargs):
        with np.errstate(over="ignore", invalid="ignore"):
            return solve(*args, **kwargs)

    return quiet


def _all_finite(value):
    """True if no element of a float or complex array is NaN or infinite (no temporaries).

    One pass: the sum of the elements is finite only if every element is (NaN or inf in,
    NaN or inf out). A finite array whose sum overflows is reported False; the caller then
    takes its exact, slower route, so the answer is never wrong, only slower.
    """
    with np.errstate(invalid="ignore", over="ignore"):
        return _finite_sum(value)


def _finite_sum(value):
    """`_all_finite` without its error state: for callers that have set their own."""
    if value.size == 0:
        return True
    if value.dtype.kind == "c":
        if value.ndim > 0 and value.flags.c_contiguous:
            return math.isfinite(np.add.reduce(value.view(value.real.dtype), axis=None))
        return math.isfinite(np.add.reduce(value.real, axis=None)) and math.isfinite(
            np.add.reduce(value.imag, axis=None))
    return math.isfinite(np.add.reduce(value, axis=None))


def _keep_promise(fields):
    """Make ``valid`` False wherever a solved field is not finite, whatever the cause.

    The solvers mark the poses that cannot be assembled and the dead points themselves;
    this last check catches what no formula flags: a value beyond the float range (a rate
    of 1e8 near a dead point times a length of 1e300, an angular velocity of 1e200 times a
    crank of 1e200). There the field is set to NaN and ``assembled`` keeps the incoming
    mask, as at a dead point. Fields are the shape of ``valid``, maybe with trailing axes.
    """
    valid = fields.get("valid")
    if valid is None or np.asarray(valid).dtype != bool:
        return fields
    valid = np.asarray(valid)
    solved = [np.asarray(v) for n, v in fields.items() if n not in ("valid", "assembled", "theta")]
    solved = [v for v in solved if v.dtype.kind in "fc" and v.shape[: valid.ndim] == valid.shape]
    if all(_all_finite(v) for v in solved):
        return fields                       # the common case: two reductions per field, no copy
    ok = valid.copy()
    checked = {}
    for name, value in fields.items():
        if name in ("valid", "assembled", "theta"):
            continue
        value = np.asarray(value)
        if value.dtype.kind not in "fc" or value.shape[: valid.ndim] != valid.shape:
            continue
        with np.errstate(invalid="ignore"):
            finite = np.isfinite(value)
        checked[name] = (value, finite)
        ok &= finite.all(axis=tuple(range(valid.ndim, finite.ndim)))
    if np.array_equal(ok, valid):
        return fields
    fields = dict(fields)
    for name, (value, finite) in checked.items():
        if not finite.all():
            nan = np.nan + 1j * np.nan if np.iscomplexobj(value) else np.nan
            fields[name] = np.where(finite, value, nan)[()]
    fields.setdefault("assembled", valid[()])
    fields["valid"] = ok[()]
    return fields


def mask_singular_rates(fields, names):
    """Mark dead points in solved `fields`: ``valid`` False there, ``assembled`` kept.

    ``assembled`` takes the incoming ``valid`` (the positions exist). The new ``valid`` is
    True where ``assembled`` is True and every field in `names` is finite; those fields
    (the rates found by solving the singular velocity equations, not those fixed by the
    input link alone) are set to NaN where it is False, so that an infinite rate of a dead
    point reads as NaN under a False mask. Fields must already have the shape of
    ``valid``, optionally with trailing axes (vectors), which are reduced.
    """
    valid = np.asarray(fields["valid"])
    ok = valid.copy()
    values = {name: np.asarray(fields[name]) for name in names}
    for value in values.values():
        finite = np.isfinite(value)
        ok &= finite.all(axis=tuple(range(valid.ndim, finite.ndim)))
    for name, value in values.items():
        keep = ok.reshape(ok.shape + (1,) * (value.ndim - ok.ndim))
        nan = np.nan + 1j * np.nan if np.iscomplexobj(value) else np.nan
        fields[name] = np.where(keep, value, nan)[()]
    fields["assembled"] = valid[()]
    fields["valid"] = ok[()]
    return fields


@dataclass(frozen=True)
class AssemblyRange:
    """Input angles where a linkage assembles (`RSSR.assembly_range`, `SphericalFourBar.assembly_range`).

    Attributes
    ----------
    intervals : ndarray, shape (k, 2)
        Closed intervals ``[start, end]`` of crank angle, counter-clockwise from start to
        end, with ``start`` in [-pi, pi) and ``end > start`` (``end`` may exceed pi). At
        each end A**2 + B**2 = C**2: a limit position, where the two branches meet.
        Empty when the crank turns fully or never assembles.
    full_turn : bool
        True when the linkage assembles at every crank angle.
    """

    intervals: np.ndarray
    full_turn: bool

    def contains(self, phi01):
        """True where the crank angle `phi01` lies in the range."""
        phi01 = finite_array("phi01", phi01)
        if self.full_turn:
            return np.ones(phi01.shape, dtype=bool)
        inside = np.zeros(phi01.shape, dtype=bool)
        for start, end in self.intervals:
            inside |= np.mod(phi01 - start, 2 * np.pi) <= end - start
        return inside
