"""The planar revolute four-bar: positions, velocities and accelerations."""

import math
from typing import NamedTuple

import numpy as np

from mech import _backend
from mech._errors import AssemblyError
from mech._generated import coupler_speed as _speed
from mech._generated import fourbar_position as _gen
from mech._validate import bool_flag, branch_sign, finite_array, motion_inputs, nonnegative_number, real_tuple
from mech._pose import Pose, _finite_sum
from mech._scaling import DEAD_POINT_RTOL
from mech.planar.kinematics._fourbar_change import change_point_rates, kite_pose
from mech.planar.structure._lengths import assembly_gaps, dead_points_near, fourbar_lengths
from mech.planar.structure._limit_positions import limit_positions

__all__ = ["FourBar", "FourBarPose", "fourbar_inputs"]


# rows of the reused work array of a block (NumPy backend): the position kernel's, then S,
# then the rate kernels'
_POSITION_ROWS = max(_gen.WORK_ROWS["fourbar_position"], _gen.WORK_ROWS["fourbar_position_signed"])
_RATE_ROWS = max(_gen.WORK_ROWS["fourbar_velocity"], _gen.WORK_ROWS["fourbar_acceleration"])
_WORK_ROWS = _POSITION_ROWS + 1 + _RATE_ROWS
# scaling a point of the scaled linkage (|x| < 4) by 2**e, 0 <= e <= this, neither
# overflows nor loses a bit: it scales back exactly
_EXACT_EXPONENT = 1000
_FIELDS = ("B", "C", "P", "omega_coupler", "omega_output", "vB", "vC", "vP",
           "alpha_coupler", "alpha_output", "aB", "aC", "aP")
_FIELD_COUNT = {0: 3, 1: 8, 2: 13}
_COMPLEX = {"B", "C", "P", "vB", "vC", "vP", "aB", "aC", "aP"}

#: The transmission-angle functions of `mech.planar.forces`, which builds on this module and
#: registers them (`register_transmission`): importing any part of `mech.planar` runs the
#: package's ``__init__``, which imports the forces subpackage, so they are here before use.
_TRANSMISSION = {}


def register_transmission(**functions):
    """Set the functions behind `FourBar.transmission_angle` and `FourBar.min_transmission_angle`."""
    _TRANSMISSION.update(functions)


class FourBarInputs(NamedTuple):
    """The plain inputs of the generated four-bar kernels (`fourbar_inputs`)."""

    lengths: tuple        # a, b, c, d divided by 2**exponent: the longest in [1/2, 1)
    exponent: int         # multiply points and linear rates by 2**exponent (exact)
    coupler: tuple        # (p, q) as given, checked
    unit_coupler: tuple   # (p, q) divided by 2**exponent
    rtol: float           # the change-point tolerance used for `gaps`
    gaps: tuple           # g2, g3, g4 of the scaled lengths, 0.0 within rtol (a + b + c + d)
    m23: int              # 1 if g2 or g3 is zero (the sign flip of sin(theta/2)), else 0
    m4: int               # 1 if g4 is zero (the sign flip of cos(theta/2)), else 0
    kite: bool            # a = d and b = c: the crank pin passes through D


def fourbar_inputs(a, b, c, d, coupler=(0.0, 0.0), rtol=1e-12):
    """Check a four-bar given in any unit and return the inputs its generated kernels take.

    The kernels of ``mech._generated.fourbar_position`` are formulas of plain numbers (the
    contract in ``derivations/README.md``): they take lengths of order one, the assembly
    gaps and the change-point flags, and know nothing of units or tolerances. This helper
    is the one place that makes those numbers: the lengths (and coupler point) divided by
    the power of two that brings the longest link into [1/2, 1) (`fourbar_lengths`), the
    gaps zeroed within ``rtol`` (a + b + c + d) (`assembly_gaps`), the flags ``m23`` and
    ``m4`` of `fourbar_position_signed` and whether the linkage is a kite. Points the
    kernels return are multiplied by ``2**exponent`` to come back to the caller's unit.

    Raises ValueError naming the argument and the value: a length that is not positive and
    finite or not shorter than the other three together, a coupler ``b`` below 2**-1022
    times the longest link, a coupler point that is not two finite numbers, a negative
    ``rtol``.

    Examples
    --------
    >>> from mech.planar.kinematics._fourbar import fourbar_inputs
    >>> k = fourbar_inputs(10, 40, 30, 35)
    >>> k.lengths, k.exponent, k.m23, k.m4
    ((0.15625, 0.625, 0.46875, 0.546875), 6, 0, 0)
    >>> fourbar_inputs(20, 50, 40, 10).m23         # 10 + 50 = 20 + 40: a change point
    1
    """
    lengths, exponent = fourbar_lengths(a, b, c, d)
    if lengths[1] < 2.0**-1022:
        # the coupler's direction is C - B divided by b: lost once b underflows
        raise ValueError(f"Expected `b` at least 2**-1022 times the longest link, got {float(b)!r} "
                         f"with the longest {max(float(a), float(b), float(c), float(d))!r}")
    p, q = coupler = real_tuple("coupler", coupler, 2)
    rtol = nonnegative_number("rtol", rtol)
    gaps = assembly_gaps(*lengths, rtol)
    zero = [g == 0.0 for g in gaps]
    # one sign flip even when both are zero: then the diagonal B->D itself reverses
    return FourBarInputs(lengths, exponent, coupler, (math.ldexp(p, -exponent), math.ldexp(q, -exponent)),
                         rtol, gaps, int(zero[0] or zero[1]), int(zero[2]), zero[0] and zero[1])


def _unscale(z, exponent, copy=True):
    """A complex array times ``2**exponent``, rounded once (exact unless subnormal).

    A point beyond the float range (links near 1e308) becomes inf, as IEEE arithmetic
    would give it; the angles, read from the scaled points, stay exact. With
    ``copy=False`` the array is scaled in place (and returned).
    """
    if exponent == 0 and not copy:
        return z
    out = np.empty_like(z) if copy else z
    with np.errstate(over="ignore"):
        if -1000 <= exponent <= 1000 and z.ndim > 0 and z.flags.c_contiguous:
            # a product by a normal power of two rounds once, as ldexp: one pass over both parts
            np.multiply(z.view(float), 2.0**exponent, out=out.view(float))
        else:
            np.ldexp(z.real, exponent, out=out.real)
            np.ldexp(z.imag, exponent, out=out.imag)
    return out


def _store(out, name, x, y):
    """Write the real and imaginary parts of one complex field of a block."""
    target = out[name]
    target.real = x
    target.imag = y


class FourBarPose(Pose):
    """Poses of a four-bar at an array of input angles (returned by `FourBar.solve`).

    Attributes
    ----------
    theta, valid : ndarray
        The input angles, and False where the linkage cannot be assembled (NaN there).
    B, C, P : ndarray of complex
        Crank pin, rocker pin and coupler point.
    phi, psi : ndarray
        Angles of B->C and D->C in (-pi, pi], computed by atan2 when first read.
    omega_coupler, omega_output, vB, vC, vP : ndarray
        Present when solved with ``order >= 1``.
    alpha_coupler, alpha_output, aB, aC, aP : ndarray
        Present when solved with ``order >= 2``.
    """

    _ORDER_OF = {
        "omega_coupler": 1, "omega_output": 1, "vB": 1, "vC": 1, "vP": 1,
        "alpha_coupler": 2, "alpha_output": 2, "aB": 2, "aC": 2, "aP": 2,
    }
    _DERIVED = ("phi", "psi")

    def __init__(self, unit, order, fields, finite=False):
        super().__init__(order, fields, finite)
        # B, C and d in the scaled lengths: the angles read from them keep every bit
        # even where the points in the user's unit are subnormal
        object.__setattr__(self, "_unit", unit)

    def _derive(self, name):
        B, C, d, exponent = self._unit
        if exponent:
            # B and C were scaled in place by 2**exponent, 0 < exponent <= _EXACT_EXPONENT:
            # scaling back is exact, so the angles keep every bit in any unit of length
            B, C = (_unscale(z, -exponent) for z in (B, C))
        return np.angle(C - (B if name == "phi" else d))[()]


class FourBar:
    """A planar revolute four-bar ABCD with ground pivots A = 0 and D = d.

    Parameters
    ----------
    a, b, c, d : float
        Crank AB, coupler BC, rocker CD and ground AD, in any one length unit.
    branch : {1, -1}, optional
        Assembly branch: +1 puts C to the left of the directed line B->D.
    coupler : (float, float), optional
        Coupler point ``(p, q)``: ``P = B + (p + 1j*q) * exp(1j*phi)``.
    rtol : float, optional
        Relative tolerance (of a + b + c + d) within which the linkage counts as a
        change-point linkage, s + l = p + q.

    Raises
    ------
    ValueError
        If a length is not positive and finite, if one link is at least as long as the
        other three together (the message names it), or if `branch` is not +1 or -1.

    Notes
    -----
    Positions come from the loop-closure equation in atan2 form with a factored,
    half-angle area term (derivation page :ref:`deriv-fourbar-position`), so they stay
    accurate up to the limit positions.

    *Branch rule.* At a change point (s + l = p + q) the two branches meet, all four
    joints in line, and the solution continues smoothly onto the other side of B->D (a
    parallelogram stays a parallelogram, an anti-parallelogram stays anti). `branch`
    names the branch by the side of C for input angles just above 0, where the
    branches differ; as sin(theta/2) has period 4 pi, a linkage whose branch changes
    sides once per turn comes back to its starting side after two turns. At the meeting
    point the rates are their limits along the branch, found from factored formulas
    (module `mech.planar.kinematics._fourbar_change`), so they are finite and continuous.

    *Degenerate pose.* The kite a = d, b = c (the rhombus included) has its crank pin B
    on the pivot D at theta = 0. The pose is assembled there: C is the limit along the
    branch, C = B + branch * b, and the rates are limits too. Only where the triangle
    BCD cannot close is a pose invalid (NaN); a valid pose never has a NaN field.

    *Scaling.* The lengths are divided internally by a power of two that brings the
    longest link into [1/2, 1), so any finite positive lengths work (1e-300 to 1e300),
    angles do not depend on the unit, and points scale exactly with the lengths (a
    point beyond the float range, with links near 1e308, is inf).

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar import FourBar
    >>> linkage = FourBar(10, 40, 30, 35)           # example 2-1
    >>> pose = linkage.solve(np.pi / 2)
    >>> round(float(abs(pose.C - pose.B)), 12), round(float(abs(pose.C - 35)), 12)
    (40.0, 30.0)
    >>> linkage.solve(np.linspace(0, np.pi, 5), order=1).omega_output.shape
    (5,)
    """

    def __init__(self, a, b, c, d, *, branch=1, coupler=(0.0, 0.0), rtol=1e-12):
        inputs = fourbar_inputs(a, b, c, d, coupler, rtol)
        (a_, b_, c_, d_), self._exponent = inputs.lengths, inputs.exponent
        self._a, self._b, self._c, self._d = (float(v) for v in (a, b, c, d))
        self._branch = branch_sign(branch)
        self._coupler = inputs.coupler
        self._rtol = inputs.rtol
        self._unit = (*inputs.lengths, *inputs.unit_coupler)
        self._gaps, self._m23, self._m4, self._kite = inputs.gaps, inputs.m23, inputs.m4, inputs.kite
        # |BD| sweeps [|d - a|, d + a]: a dead point (|BD| = b + c or |b - c|, gap not zero)
        # is within reach only if its gap is below the tolerance (twice, for rounding)
        tol = 2.0 * DEAD_POINT_RTOL * (a_ + b_ + c_ + d_)
        close_gap = self._gaps[0] if c_ > b_ else self._gaps[1]  # as in dead_points_near
        self._may_meet_dead_point = (self._gaps[2] != 0.0 and self._gaps[2] <= tol) or (
            close_gap != 0.0 and close_gap <= tol)
        # positions alone may take the numba kernel that scales and masks in one pass
        # (`_solve_fused`): no kite, no dead point to snap, points that scale back exactly
        self._fused = not self._kite and not self._may_meet_dead_point and (
            0 <= self._exponent <= _EXACT_EXPONENT)
        flags = (self._m23, self._m4) if self.change_point else ()
        self._fused_tail = (self._branch, *self._gaps, *flags)

    a = property(lambda self: self._a, doc="Crank length AB.")
    b = property(lambda self: self._b, doc="Coupler length BC.")
    c = property(lambda self: self._c, doc="Rocker length CD.")
    d = property(lambda self: self._d, doc="Ground length AD.")
    branch = property(lambda self: self._branch, doc="Assembly branch, +1 or -1.")
    coupler = property(lambda self: self._coupler, doc="Coupler point (p, q).")

    @property
    def change_point(self):
        """True if two branches of the linkage meet (s + l = p + q within `rtol`)."""
        return self._m23 + self._m4 > 0

    def __repr__(self):
        return (f"FourBar({self._a!r}, {self._b!r}, {self._c!r}, {self._d!r}, "
                f"branch={self._branch}, coupler={self._coupler!r})")

    def solve(self, theta, order=0, omega=1.0, alpha=0.0, strict=False):
        """Solve the loop-closure equation at the input angles `theta`.

        Positions by the atan2 form of the loop-closure equation, eqs. (2-11), (2-12);
        rates by differentiating it once (``order=1``) or twice (``order=2``).

        Parameters
        ----------
        theta : array_like, shape (...)
            Crank angle of A->B from +x, counter-clockwise, radians.
        order : {0, 1, 2}, optional
            Highest time derivative to compute; nothing above it is computed.
        omega, alpha : array_like, optional
            Angular velocity and acceleration of the crank, broadcast against `theta`.
        strict : bool, optional
            Raise `AssemblyError` instead of returning NaN where it cannot assemble.

        Returns
        -------
        FourBarPose
            ``B, C, P`` (complex), ``phi, psi``, ``valid``; with ``order >= 1`` also
            ``omega_coupler, omega_output, vB, vC, vP``; with ``order >= 2`` also
            ``alpha_coupler, alpha_output, aB, aC, aP``.

        Raises
        ------
        AssemblyError
            With ``strict=True``, naming the first input angle that cannot be assembled.
        ValueError
            For a non-finite `theta`, `omega` or `alpha`, or an `order` outside 0..2.

        Notes
        -----
        See :ref:`deriv-fourbar-position` for the derivation and the branch convention.

        Examples
        --------
        >>> from mech.planar import FourBar
        >>> pose = FourBar(10, 40, 30, 35, coupler=(20, 10)).solve([0.0, 1.0], order=2)
        >>> pose.valid.tolist(), pose.aP.shape
        ([True, True], (2,))
        """
        strict = bool_flag("strict", strict)
        if (type(order) is int and order == 0 and self._fused and type(theta) is np.ndarray
                and theta.dtype == np.float64 and _backend.use_numba(theta.size)):
            # positions of an array of floats: the fused kernel's own finiteness check
            # covers theta too (a NaN or infinite angle makes its outputs NaN)
            return self._solve_fused(theta, strict)
        order, shape, inputs = motion_inputs("theta", theta, order, omega, alpha)
        flat = [x.reshape(-1) for x in inputs]
        size = flat[0].size
        names = _FIELDS[: _FIELD_COUNT[order]]
        # the complex fields are the rows of one array: each block is scaled and checked by
        # one call each, and the solve makes one allocation for them
        complex_fields = [name for name in names if name in _COMPLEX]
        points = np.empty((len(complex_fields), size), dtype=complex)
        rows = iter(points)
        out = {name: next(rows) if name in _COMPLEX else np.empty(size) for name in names}
        out["valid"] = np.empty(size, dtype=bool)
        real_fields = [name for name in names if name not in _COMPLEX]
        # numba: fused loops over blocks of NUMBA_BLOCK points; NumPy: blocks that fit in
        # cache, every temporary in one reused work array (no allocation per block)
        numba = _backend.use_numba(size) and not self._kite
        step = _backend.NUMBA_BLOCK if numba else _backend.BLOCK
        # B and C in the scaled lengths are kept for the angles phi and psi (FourBarPose):
        # as they are, or (exponent in 0 .. _EXACT_EXPONENT) as the points in the user's
        # unit, which scale back exactly: then every field is scaled in place, block by
        # block while the block is in cache, and checked finite there (Pose's promise)
        exact = 0 <= self._exponent <= _EXACT_EXPONENT
        finite, scale = True, 2.0**self._exponent
        # over: 1 / |BD|^2 where B all but meets D (theta ~ 1e-160 with a = d) cannot
        # assemble, and a point beyond the float range (links near 1e308) becomes inf
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            for start in range(0, max(size, 1), step):
                block = slice(start, start + step)
                views = {k: v[block] for k, v in out.items()}
                self._solve_block([x[block] for x in flat], order, views, numba)
                parts = points[:, block].view(float)     # real and imaginary parts of a block
                if exact and self._exponent:
                    # a product by a normal power of two rounds once, as ldexp
                    np.multiply(parts, scale, out=parts)
                finite = finite and _finite_sum(parts) and all(_finite_sum(views[k]) for k in real_fields)
        valid = out["valid"]
        if strict and not np.all(valid):
            bad = float(flat[0][~valid][0])
            raise AssemblyError(f"Cannot assemble {self!r} at theta = {bad!r}")
        unit = (out["B"].reshape(shape), out["C"].reshape(shape), self._unit[3], self._exponent if exact else 0)
        if not exact:
            for name in complex_fields:
                out[name] = _unscale(out[name], self._exponent, copy=name in ("B", "C"))
            finite = False
        fields = {name: value.reshape(shape)[()] for name, value in out.items()}
        fields["theta"] = np.broadcast_to(theta, shape)[()]
        return FourBarPose(unit, order, fields, finite)

    def _solve_fused(self, theta, strict):
        """Positions by the numba kernel that scales, checks and masks in its one pass.

        For a linkage without kites and dead points in reach, whose points scale back
        exactly (`_fused`), and `theta` a float64 array, not yet checked: the same bits as
        `_solve_block` followed by the scaling. Where the kernel reports a field that is not
        finite, `theta` is checked first (ValueError for NaN or an infinity, as `solve`
        raises for every other input), then the fields of the valid poses.
        """
        shape, flat = theta.shape, theta.reshape(-1)
        size = flat.shape[0]
        points = np.empty((3, size), dtype=complex)
        B, C, P = points
        valid = np.empty(size, dtype=bool)
        step = _backend.NUMBA_BLOCK
        S = _backend.workspace("fourbar_numba", 1, min(size, step))[0]
        kernel, args, scales = self._fused_call
        outs = (B.real, B.imag, C.real, C.imag, P.real, P.imag)
        finite, checked = True, False
        for start in range(0, size, step):
            stop = min(start + step, size)
            s, v = S[: stop - start], valid[start:stop]
            blocks = outs if size <= step else [x[start:stop] for x in outs]
            if not kernel(*args, flat[start:stop], *self._fused_tail, scales, *blocks, s, v):
                if not checked:
                    finite_array("theta", theta)            # raises for NaN or an infinity
                    checked = True
                # a field is NaN or infinite somewhere: where the pose does not exist (S is
                # NaN, so `valid` is False), which is as promised; anywhere else (a point
                # beyond the float range) `Pose` checks every field
                finite = finite and all(_finite_sum(x[v]) for x in blocks)
        if strict and not valid.all():
            bad = float(flat[~valid][0])
            raise AssemblyError(f"Cannot assemble {self!r} at theta = {bad!r}")
        if len(shape) != 1:
            B, C, P, valid = (x.reshape(shape) for x in (B, C, P, valid))
        view = theta.view()                         # read-only, as `motion_inputs` gives it
        view.flags.writeable = False
        fields = {"B": B[()], "C": C[()], "P": P[()], "valid": valid[()], "theta": view[()]}
        return FourBarPose((B, C, self._unit[3], self._exponent), 0, fields, finite)

    @property
    def _fused_call(self):
        """The fused kernel, its scalar arguments before theta, and the scales of its outputs."""
        call = self.__dict__.get("_fused_cache")
        if call is None:
            name = "fourbar_position_signed" if self.change_point else "fourbar_position"
            kernel = getattr(_backend.numba_kernels("fourbar_position"), f"{name}_fused_kernel")
            scale = 2.0**self._exponent
            call = self._fused_cache = (kernel, self._unit, (scale,) * 6 + (1.0,))
        return call

    def _solve_block(self, inputs, order, out, numba=False):
        """Solve one block of flat inputs, writing into the views in `out`."""
        a, b, c, d, p, q = self._unit
        branch, theta = self._branch, inputs[0]
        n = theta.shape[0]
        # in the error state of the caller (`solve`)
        if self._kite:
            B, C, P, S, ratios = kite_pose(a, b, self._gaps[2], self._m4, p, q, theta, branch)
            out["B"][...], out["C"][...], out["P"][...] = B, C, P
            position = None
        else:
            name = "fourbar_position_signed" if self.change_point else "fourbar_position"
            flags = (self._m23, self._m4) if self.change_point else ()
            args = (a, b, c, d, p, q, theta, branch, *self._gaps, *flags)
            B, C, P = out["B"], out["C"], out["P"]
            if numba:
                S = _backend.workspace("fourbar_numba", 1, n)[0]
                kernel = getattr(_backend.numba_kernels("fourbar_position"), f"{name}_kernel")
                kernel(*args, B.real, B.imag, C.real, C.imag, P.real, P.imag, S)
            else:
                work = _backend.workspace("fourbar", _WORK_ROWS, n)
                S = work[_POSITION_ROWS]
                getattr(_gen, f"{name}_into")(*args, (B.real, B.imag, C.real, C.imag, P.real, P.imag, S),
                                              work[:_gen.WORK_ROWS[name]])
            position = (B.real, B.imag, C.real, C.imag, S)
        np.equal(S, S, out=out["valid"])             # False where S is NaN
        if order >= 1 and (self._kite or self.change_point):
            self._change_point_rates(inputs, order, out, ratios if self._kite else None)
        elif order >= 1:
            self._rates(inputs, order, out, position, numba)
        self._dead_points(theta, order, out)

    def _dead_points(self, theta, order, out):
        """Inputs within `DEAD_POINT_RTOL` of a dead point are the dead point (`dead_points_near`).

        There the pose is the dead point's (C on the line BD) and the rates are NaN
        (infinite there), so `valid` agrees in every unit of length: True for positions,
        False with rates, and `assembled` True.
        """
        if not self._may_meet_dead_point:
            return
        a, b, c, d, p, q = self._unit
        near_far, near_close, k = dead_points_near(a, b, c, d, theta, self._gaps)
        near = near_far | near_close
        if not near.any():
            return
        snap = near & ~out["valid"]
        if snap.any():
            B = a * np.exp(1j * theta[snap])
            sign = np.where(near_far[snap] | (b >= c), 1.0, -1.0)
            C = B + sign * b * (d - B) / k[snap]
            out["B"][snap], out["C"][snap] = B, C
            out["P"][snap] = B + (p + 1j * q) * (C - B) / b
            out["valid"][snap] = True
        for name in ("omega_coupler", "omega_output", "vC", "vP", "alpha_coupler", "alpha_output", "aC", "aP"):
            if name in out:
                out[name][near] = np.nan + 1j * np.nan if name in _COMPLEX else np.nan

    def _rates(self, inputs, order, out, position, numba=False):
        """Rates of a linkage without change points, by the generated velocity loop."""
        a, b, c, d, p, q = self._unit
        omega, branch = inputs[1], self._branch
        w2, w3, vB, vC, vP = (out[k] for k in ("omega_coupler", "omega_output", "vB", "vC", "vP"))
        args = (b, d, p, q, *position, branch, omega)
        outs = (w2, w3, vB.real, vB.imag, vC.real, vC.imag, vP.real, vP.imag)
        if numba:
            kernels = _backend.numba_kernels("fourbar_position")
            kernels.fourbar_velocity_kernel(*args, *outs)
        else:
            # the rows after S in the block's work array (S is an input here)
            work = _backend.workspace("fourbar", _WORK_ROWS, w2.shape[0])[_POSITION_ROWS + 1:]
            _gen.fourbar_velocity_into(*args, outs, work[:_gen.WORK_ROWS["fourbar_velocity"]])
        if order < 2:
            return
        a2, a3, aB, aC, aP = (out[k] for k in ("alpha_coupler", "alpha_output", "aB", "aC", "aP"))
        args = (*args, inputs[2], w2, w3)
        outs = (a2, a3, aB.real, aB.imag, aC.real, aC.imag, aP.real, aP.imag)
        if numba:
            kernels.fourbar_acceleration_kernel(*args, *outs)
        else:
            _gen.fourbar_acceleration_into(*args, outs, work[:_gen.WORK_ROWS["fourbar_acceleration"]])

    def _change_point_rates(self, inputs, order, out, ratios):
        """Rates of a change-point linkage as limits along the branch (`_fourbar_change`)."""
        a, b, c, d, p, q = self._unit
        if ratios is None:
            ratios = change_point_rates(a, b, c, d, inputs[0], self._branch, self._gaps,
                                        self._m23, self._m4)
        (g2, dg2), (g3, dg3) = ratios
        omega = inputs[1]
        B, C, P = out["B"], out["C"], out["P"]
        w2, w3 = g2 * omega, g3 * omega
        out["omega_coupler"][...] = w2
        out["omega_output"][...] = w3
        out["vB"][...] = 1j * omega * B
        out["vC"][...] = 1j * w3 * (C - d)
        out["vP"][...] = 1j * omega * B + 1j * w2 * (P - B)
        if order < 2:
            return
        alpha = inputs[2]
        omega2 = omega * omega
        a2, a3 = g2 * alpha + dg2 * omega2, g3 * alpha + dg3 * omega2
        out["alpha_coupler"][...] = a2
        out["alpha_output"][...] = a3
        aB = (1j * alpha - omega2) * B
        out["aB"][...] = aB
        out["aC"][...] = (1j * a3 - w3 * w3) * (C - d)
        out["aP"][...] = aB + (1j * a2 - w2 * w2) * (P - B)

    def limit_positions(self):
        """Limit positions of a crank-rocker: see `mech.planar.LimitPositions`.

        Returns the crank and rocker angles at the extended and folded limit positions,
        the swing, the extreme angle and the time ratio K (2-9) of this branch.

        Examples
        --------
        >>> from mech.planar import FourBar
        >>> lp = FourBar(10, 40, 30, 35).limit_positions()     # example 2-1
        >>> round(float(np.degrees(lp.swing)), 4), round(float(lp.time_ratio), 5)
        (45.9719, 1.22404)
        """
        return limit_positions(self._a, self._b, self._c, self._d, branch=self._branch)

    def transmission_angle(self, theta):
        """Transmission angle gamma in [0, pi/2] at crank angles `theta`, eq. (2-30).

        Examples
        --------
        >>> from mech.planar import FourBar
        >>> round(float(np.degrees(FourBar(30, 70, 60, 80).transmission_angle(0.0))), 4)
        44.4153
        """
        return _TRANSMISSION["transmission_angle"](self._a, self._b, self._c, self._d, theta)

    def min_transmission_angle(self):
        """The smallest transmission angle and the crank angle where it occurs, ``(gamma_min, theta_at)``.

        Examples
        --------
        >>> from mech.planar import FourBar
        >>> gamma_min, theta_at = FourBar(30, 70, 60, 80).min_transmission_angle()
        >>> round(float(np.degrees(gamma_min)), 4)
        44.4153
        """
        return _TRANSMISSION["min_transmission_angle"](self._a, self._b, self._c, self._d)

    def coupler_point_speed(self, theta, omega=1.0):
        """Speed of the coupler point P, ``|dP/dt|``, at the crank angles `theta` (F25).

        The closed form of :ref:`deriv-coupler-speed`: the length of
        ``v_P = v_B + 1j * omega_coupler * (P - B)`` as ``hypot`` of its components, with
        the coupler's angle and rate from `solve`, so it holds through change points and
        the kite's degenerate pose. The speed is the one an atlas page shows by the
        spacing of its dashes (`mech.planar.coupler_dashes`).

        Parameters
        ----------
        theta : array_like
            Crank angle of A->B from +x, counter-clockwise, radians.
        omega : array_like, optional
            Angular velocity of the crank, broadcast against `theta`.

        Returns
        -------
        ndarray
            The speed in the unit of the lengths per unit of time; NaN where the linkage
            cannot be assembled, inf only where the speed is beyond the float range.

        Raises
        ------
        ValueError
            For a non-finite `theta` or `omega` (the message names it).

        Examples
        --------
        >>> from mech.planar import FourBar
        >>> linkage = FourBar(10, 40, 30, 35, coupler=(20, 10))
        >>> round(float(linkage.coupler_point_speed(0.5, omega=2.0)), 6)
        12.183321
        >>> FourBar(10, 30, 10, 30).coupler_point_speed([0.5, 2.0]).tolist()   # a parallelogram
        [10.0, 10.0]
        """
        pose = self.solve(theta, order=1, omega=omega)
        a, _, _, _, p, q = self._unit
        with np.errstate(over="ignore"):
            # the kernel takes the lengths scaled by 2**-exponent (linear in them): scale back, exactly
            speed = _speed.coupler_point_speed(a, p, q, pose.theta, pose.phi, np.asarray(omega, dtype=float),
                                               pose.omega_coupler)
            return np.ldexp(speed, self._exponent)[()]
