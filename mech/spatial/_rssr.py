"""The spatial RSSR four-bar of (2-69) to (2-71): positions, rates, assembly range."""

import numpy as np

from mech import _backend
from mech._errors import AssemblyError
from mech._generated import one_equation as _abc
from mech._generated import rssr as _gen
from mech._validate import (
    bool_flag, branch_sign, finite_array, motion_inputs, nonnegative_number, positive_length, real_number,
    real_tuple,
)
from mech._pose import _keep_promise, AssemblyRange, mask_singular_rates, Pose
from mech._scaling import DEAD_POINT_RTOL, length_scale
from mech.spatial._rssr_change import change_points

__all__ = ["RSSR", "RSSRPose", "AssemblyRange"]


# smallest l1 l3 / D**2 (D: the largest dimension) for which A, B, C of (2-71) and their
# squares are finite floats
_MIN_L1_L3 = 2.0 ** -500
# fields that scale with the unit of length, and the rates found from the loop equation
_LINEAR = frozenset({"B", "C", "P", "vB", "vC", "aB", "aC"})
_SOLVED_RATES = ("omega_output", "vC", "alpha_output", "aC")
#: Crank angles per block of a large solve: the block's temporaries (a few dozen arrays of
#: this length) stay in cache, and Python's cost per block vanishes (measured with
#: benchmarks/bench_speed_linkage.py).
_BLOCK = 16384
#: The smallest solve that the backend ``"auto"`` hands to the compiled loop
#: (`mech.spatial._rssr_compiled`), as for the planar `Linkage`: at 10^3 angles the NumPy
#: path cost 6 times a plain compiled loop (benchmarks/bench_compiled.py), the loop far less.
_COMPILED_MIN_SIZE = 512


def _stack(*components):
    return np.stack(np.broadcast_arrays(*components), axis=-1)


class RSSRPose(Pose):
    """Poses of an RSSR four-bar at an array of crank angles (returned by `RSSR.solve`).

    Attributes
    ----------
    phi01, phi03, valid : ndarray
        Crank angle, rocker angle in (-pi, pi] (NaN where the linkage cannot be
        assembled) and the mask of assembled poses.
    B, C, P : ndarray, shape (..., 3)
        Crank pin, rocker pin and coupler point in the ground frame O-x0y0z0.
    omega_output, vB, vC : ndarray
        d phi03/dt and the pin velocities; present when solved with ``order >= 1``.
    alpha_output, aB, aC : ndarray
        d2 phi03/dt2 and the pin accelerations; present when solved with ``order >= 2``.
    assembled : ndarray of bool
        True where the position exists. With ``order >= 1``, ``valid`` is False also where
        a solved rate is infinite or undetermined (a dead point; those rates are NaN
        there), while ``assembled`` stays True (the rule of `mech._pose.Pose`).
    """

    _ORDER_OF = {"omega_output": 1, "vB": 1, "vC": 1,
                 "alpha_output": 2, "aB": 2, "aC": 2}


class RSSR:
    """The spatial RSSR four-bar of Fig. 2-121 (crank AB, coupler BC, rocker DC).

    Parameters
    ----------
    l1, l2, l3 : float
        Crank AB, coupler BC and rocker DC lengths.
    s0, s3 : float
        Offsets S_0 of the crank pivot A along z0 and S_3 of the rocker pivot D along z3.
    h0 : float
        h_0, the common perpendicular of the two axes, from O on the crank axis to O_K on
        the rocker axis, along x0 (signed, as in the textbook).
    lam : float
        lambda_30, the twist of the rocker axis z3 from z0 about x0, radians.
    branch : {1, -1}, optional
        Assembly mode: +1 takes the + sign of the root in (2-71),
        phi03 = 2 atan((A + sqrt(A**2 + B**2 - C**2)) / (B - C)) with A, B, C of the
        textbook (C corrected). Geometrically, +1 when z3 . ((C - D) x (B - C)) > 0. For a
        change-point linkage, the sign at the smallest non-negative crank angle where the
        two branches differ (see Notes).
    coupler : (float, float, float), optional
        Coupler point ``(p, q, u)``: ``P = B + p e1 + q e2 + u e3`` with ``e1`` along B->C,
        ``e3`` along ``e1 x z3`` and ``e2 = e3 x e1`` (the coupler's idle spin about BC
        fixed by the rocker axis).
    rtol : float, optional
        A double zero of A**2 + B**2 - C**2 within ``rtol`` times the size of its Fourier
        coefficients of zero is a change point (the branches meet there).

    Raises
    ------
    ValueError
        If a length is not positive and finite, an offset or `lam` is not finite, or
        `branch` is not +1 or -1.

    Notes
    -----
    Derivation, the corrected C of (2-71) and the branch geometry: :ref:`deriv-rssr`; the
    shared atan2 solver: :ref:`deriv-one-equation`. Along a branch the rocker angle is
    continuous in phi01 (modulo 2 pi) wherever the linkage assembles. The two branches meet
    at the ends of `assembly_range`; a crank that rocks between them passes from one
    branch to the other there, so a motion through a limit position is followed by
    switching `branch`.

    *Branch rule.* At a change point (`change_angles`: a double zero of the discriminant,
    where the branches meet and cross, as in the planar parallelogram and kite) the
    solution continues smoothly: the root of (2-71) is taken with its sign, which changes
    there (module `mech.spatial._rssr_change`), and `branch` names the sign at the smallest
    non-negative crank angle where the two branches differ, the rule of `FourBar` and
    `SphericalFourBar`. Rates there are the limits along the branch, finite and
    continuous; where the crank pin crosses the rocker axis (A = B = C = 0, the spatial
    kite) the pose is the limit along the branch too. As sin(phi01/2) has period 4 pi, a
    linkage with an odd number of change points per turn returns on the other branch.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spatial._rssr import RSSR
    >>> rssr = RSSR(1.0, 4.0, 2.0, 0.5, 0.8, 3.0, np.radians(60))
    >>> pose = rssr.solve(np.radians([0, 90, 180]))
    >>> np.round(np.linalg.norm(pose.C - pose.B, axis=-1), 12)
    array([4., 4., 4.])
    >>> rssr.assembly_range().full_turn
    True

    A change point: the planar kite (1, 2, 2, 1) continues through phi01 = 0.

    >>> pose = RSSR(1, 2, 2, 0, 0, 1, 0).solve([-1e-9, 1e-9], order=1)
    >>> pose.omega_output.round(12).tolist()
    [0.75, 0.75]
    """

    def __init__(self, l1, l2, l3, s0, s3, h0, lam, *, branch=1, coupler=(0.0, 0.0, 0.0), rtol=1e-12):
        self._l1, self._l2, self._l3 = (positive_length(n, v) for n, v in (("l1", l1), ("l2", l2), ("l3", l3)))
        self._s0, self._s3, self._h0, self._lam = (
            real_number(n, v) for n, v in (("s0", s0), ("s3", s3), ("h0", h0), ("lam", lam)))
        self._branch = branch_sign(branch)
        self._coupler = real_tuple("coupler", coupler, 3)
        self._scale = length_scale(self._l1, self._l2, self._l3, self._s0, self._s3, self._h0)
        # the generated formulas see lengths of order one only (see mech._scaling)
        self._unit = tuple(x / self._scale for x in
                           (self._l1, self._l2, self._l3, self._s0, self._s3, self._h0)) + (self._lam,)
        self._unit_coupler = tuple(x / self._scale for x in self._coupler)
        # (2-71) is divided by l1 l3: with both far below the other dimensions its
        # coefficients, and their squares, would overflow
        l1, _, l3 = self._unit[:3]
        if l1 * l3 < _MIN_L1_L3:
            largest = max(abs(x) for x in (self._l1, self._l2, self._l3, self._s0, self._s3, self._h0))
            raise ValueError(
                f"Expected `l1` * `l3` >= 2**-500 * {largest!r}**2 (the largest length or offset, "
                f"squared) so that the coefficients of (2-71) stay finite, got `l1` = {self._l1!r}, "
                f"`l3` = {self._l3!r}"
            )
        self._rtol = nonnegative_number("rtol", rtol)
        # double zeros of the discriminant, where the branches meet (None if there are none)
        self._change = change_points(self._unit, self._rtol)

    l1 = property(lambda self: self._l1, doc="Crank length AB.")
    l2 = property(lambda self: self._l2, doc="Coupler length BC.")
    l3 = property(lambda self: self._l3, doc="Rocker length DC.")
    s0 = property(lambda self: self._s0, doc="Offset S_0 of A along z0.")
    s3 = property(lambda self: self._s3, doc="Offset S_3 of D along z3.")
    h0 = property(lambda self: self._h0, doc="Common perpendicular h_0 along x0.")
    lam = property(lambda self: self._lam, doc="Twist lambda_30 of the rocker axis.")
    branch = property(lambda self: self._branch, doc="Assembly mode, +1 or -1.")
    coupler = property(lambda self: self._coupler, doc="Coupler point (p, q, u).")
    rtol = property(lambda self: self._rtol, doc="Relative tolerance of a change point.")

    @property
    def change_point(self):
        """True if the two branches meet at some crank angle (a double zero of A^2 + B^2 - C^2)."""
        return self._change is not None

    def change_angles(self):
        """The crank angles in [0, 2 pi) where the two branches meet (empty without any).

        Examples
        --------
        >>> from mech.spatial._rssr import RSSR
        >>> RSSR(1.0, 2.0, 2.0, 0.0, 0.0, 1.0, 0.0).change_angles().tolist()
        [0.0]
        """
        if self._change is None:
            return np.empty(0)
        return np.array(self._change.crank_angles())

    def _dims(self):
        """The dimensions with every length divided by the power of two `_scale`."""
        return self._unit

    def __repr__(self):
        return (f"RSSR({self._l1!r}, {self._l2!r}, {self._l3!r}, {self._s0!r}, {self._s3!r}, "
                f"{self._h0!r}, {self._lam!r}, branch={self._branch}, coupler={self._coupler!r}, rtol={self._rtol!r})")

    def _coefficients(self, phi01):
        """A, B, C of A cos(phi03) + B sin(phi03) = C and the discriminant A^2 + B^2 - C^2."""
        dims = self._dims()
        A, B, C = _gen.rssr_abc(*dims, phi01)
        _, rho, r2 = _gen.rssr_reach(*dims, phi01)
        factored = _gen.rssr_discriminant(dims[0], dims[2], rho, np.sqrt(np.maximum(r2, 0.0)))
        disc = np.where(r2 >= 0.0, factored, _abc.abc_discriminant(A, B, C))
        return A, B, C, disc

    def coefficients(self, phi01):
        """The textbook's A, B, C of (2-71), A sin(phi03) + B cos(phi03) + C = 0, C corrected.

        The printed C has the wrong sign on its last term, S0 S3 cos(lam) / (l1 l3);
        this is the derived one (:ref:`deriv-rssr`).

        Examples
        --------
        >>> from mech.spatial._rssr import RSSR
        >>> [round(float(x), 6) for x in RSSR(1.0, 4.0, 2.0, 0.5, 0.8, 3.0, 0.0).coefficients(0.0)]
        [0.0, 2.0, -1.9775]
        """
        A, B, C = _gen.rssr_abc(*self._dims(), finite_array("phi01", phi01))
        return B[()], A[()], np.negative(C)[()]

    def points(self, phi01, phi03):
        """The pins B (2-69) and C (2-70), shape (..., 3), at given crank and rocker angles.

        Examples
        --------
        >>> from mech.spatial._rssr import RSSR
        >>> B, C = RSSR(1.0, 4.0, 2.0, 0.5, 0.8, 3.0, 0.0).points(0.0, 0.0)
        >>> B.tolist(), C.tolist()
        ([1.0, 0.0, 0.5], [5.0, 0.0, 0.8])
        """
        l1, _, l3, s0, s3, h0, lam = self._dims()
        Bx, By, Bz, Cx, Cy, Cz = _gen.rssr_points(l1, l3, s0, s3, h0, lam, finite_array("phi01", phi01),
                                                  finite_array("phi03", phi03))
        return _stack(Bx, By, Bz) * self._scale, _stack(Cx, Cy, Cz) * self._scale

    def discriminant(self, phi01):
        """A**2 + B**2 - C**2 of (2-71) at crank angles `phi01`: >= 0 where it assembles.

        Evaluated as a product of triangle factors (:ref:`deriv-rssr`), accurate near the
        limit positions.

        Examples
        --------
        >>> from mech.spatial._rssr import RSSR
        >>> bool(RSSR(1.0, 4.0, 2.0, 0.5, 0.8, 3.0, 1.0).discriminant(0.0) > 0)
        True
        """
        return self._coefficients(finite_array("phi01", phi01))[3][()]

    def solve(self, phi01, order=0, omega=1.0, alpha=0.0, strict=False):
        """Solve (2-71) for the rocker angle at the crank angles `phi01`.

        The root of A cos(phi03) + B sin(phi03) = C in atan2 form (no pole where the
        textbook's half-angle form divides by B - C), with (2-69), (2-70) for the pins;
        rates by differentiating (2-71) once (``order=1``) or twice (``order=2``).

        Parameters
        ----------
        phi01 : array_like, shape (...)
            Crank angle from x0 to x1 about z0, radians.
        order : {0, 1, 2}, optional
            Highest time derivative to compute; nothing above it is computed.
        omega, alpha : array_like, optional
            Angular velocity and acceleration of the crank, broadcast against `phi01`.
        strict : bool, optional
            Raise `AssemblyError` instead of returning NaN where it cannot assemble.

        Returns
        -------
        RSSRPose
            ``phi01, phi03, B, C, P, valid``; with ``order >= 1`` also
            ``omega_output, vB, vC``; with ``order >= 2`` also ``alpha_output, aB, aC``.

        Raises
        ------
        AssemblyError
            With ``strict=True``, naming the first crank angle that cannot be assembled.
        ValueError
            For a non-finite `phi01`, `omega` or `alpha`, or an `order` outside 0..2.

        Notes
        -----
        See :ref:`deriv-rssr`. Rates are unbounded at the limit positions
        (A^2 + B^2 = C^2): the pose is assembled there (``assembled`` is True and
        ``strict`` does not raise), but with ``order >= 1`` ``valid`` is False and the
        rates of the rocker and its pin are NaN (the crank pin's stay finite). The
        formulas run on the lengths and offsets divided by a power of two near the
        largest (`mech._scaling`): angles do not depend on the unit of length, and points
        and linear rates scale exactly with it. More than 16384 crank angles are solved in
        blocks of that many, with the same results. With numba installed, the backend
        ``"auto"`` (from 512 angles) or ``"numba"`` solves a linkage without change points in
        one compiled loop (`mech.spatial._rssr_compiled`), within a few ulp of NumPy.

        Examples
        --------
        >>> from mech.spatial._rssr import RSSR
        >>> pose = RSSR(1.0, 4.0, 2.0, 0.5, 0.8, 3.0, 1.0).solve([0.0, 1.0], order=2)
        >>> pose.valid.tolist(), pose.aC.shape
        ([True, True], (2, 3))
        """
        strict = bool_flag("strict", strict)
        order, shape, (phi01, *rates) = motion_inputs("phi01", phi01, order, omega, alpha)
        if self._change is None and _backend.use_numba(phi01.size, _COMPILED_MIN_SIZE):
            fields, spoiled = self._compiled_fields(phi01, rates, order, strict)
            return RSSRPose(order, fields, finite=not spoiled)
        if phi01.size <= _BLOCK:
            return RSSRPose(order, self._solve_fields(phi01, rates, order, strict))
        # cache-sized blocks, each solved and checked whole, copied into outputs allocated
        # once: no temporary outlives its block (every result depends on its own input only)
        flat = [x.reshape(-1) for x in (phi01, *rates)]
        size, out, masked = phi01.size, {}, False
        for start in range(0, size, _BLOCK):
            part = slice(start, start + _BLOCK)
            fields = _keep_promise(self._solve_fields(flat[0][part], [x[part] for x in flat[1:]], order, strict))
            del fields["phi01"]
            masked = masked or "assembled" in fields
            fields.setdefault("assembled", fields["valid"])
            for name, value in fields.items():
                if name not in out:
                    out[name] = np.empty((size,) + value.shape[1:], dtype=value.dtype)
                out[name][part] = value
        if not masked:
            del out["assembled"]            # equal to `valid`, as one solve over all inputs reports it
        fields = {"phi01": phi01[()], **{name: value.reshape(shape + value.shape[1:]) for name, value in out.items()}}
        return RSSRPose(order, fields, finite=True)

    def _compiled_fields(self, phi01, rates, order, strict):
        """The fields of `solve` by the compiled loop (`_rssr_compiled`): no change points."""
        from mech.spatial import _rssr_compiled     # imports numba: only when a solve uses it

        fields, spoiled = _rssr_compiled.solve_fields(self, phi01, rates, order)
        if strict and not np.all(fields["valid"]):
            bad = float(np.asarray(phi01)[~np.asarray(fields["valid"])].ravel()[0])
            raise AssemblyError(f"Cannot assemble {self!r} at phi01 = {bad!r}")
        if order >= 1:
            mask_singular_rates(fields, _SOLVED_RATES[: 2 * order])
        return fields, spoiled

    def _solve_fields(self, phi01, rates, order, strict):
        """The fields of `solve` at crank angles `phi01` (any shape), rates and masks done."""
        l1, l2, l3, s0, s3, h0, lam = dims = self._dims()
        sigma = self._branch
        if self._change is not None:
            # the root taken with its sign through the change points (_rssr_change)
            with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
                jet, valid, dead = self._change.solve(phi01, sigma, order)
            if strict and not np.all(valid):
                bad = float(phi01[~valid].ravel()[0])
                raise AssemblyError(f"Cannot assemble {self!r} at phi01 = {bad!r}")
            phi03 = np.where(valid, np.angle(np.exp(1j * jet.v)), np.nan)
        else:
            A, B, C, disc = self._coefficients(phi01)
            # within rounding (DEAD_POINT_RTOL) of a limit position the input is the limit
            # position: it assembles in every unit of length, with infinite (NaN) rates
            dead = np.abs(disc) <= DEAD_POINT_RTOL * (A * A + B * B + C * C)
            disc = np.where(dead & (disc < 0.0), 0.0, disc)
            valid = disc >= 0.0
            if strict and not np.all(valid):
                bad = float(phi01[~valid].ravel()[0])
                raise AssemblyError(f"Cannot assemble {self!r} at phi01 = {bad!r}")
            root = np.sqrt(np.where(valid, disc, 0.0))
            phi03 = np.where(valid, _abc.abc_solve(A, B, C, root, sigma), np.nan)
        Bx, By, Bz, Cx, Cy, Cz = _gen.rssr_points(l1, l3, s0, s3, h0, lam, phi01, phi03)
        fields = {"phi01": phi01[()], "phi03": phi03[()], "valid": valid[()],
                  "B": _stack(Bx, By, Bz), "C": _stack(Cx, Cy, Cz)}
        p, q, u = self._unit_coupler
        if q == 0.0 and u == 0.0:
            fields["P"] = fields["B"] + (p / l2) * (fields["C"] - fields["B"])
        else:
            with np.errstate(invalid="ignore", divide="ignore"):
                fields["P"] = _stack(*_gen.rssr_coupler_point(Bx, By, Bz, Cx, Cy, Cz, l2, lam, p, q, u))
        # at a limit position the root vanishes and the rates are infinite: they are
        # masked below by mask_singular_rates
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            if order >= 1:
                omega = rates[0]
                if self._change is not None:
                    w3 = np.where(valid & ~dead, jet.d1 * omega, np.nan)
                else:
                    dA, dB, dC, ddA, ddB, ddC = _gen.rssr_abc_rates(*dims, phi01, omega,
                                                                    rates[1] if order >= 2 else 0.0)
                    w3 = np.where(valid & ~dead, _abc.abc_rate(dA, dB, dC, phi03, root, sigma), np.nan)
                fields["omega_output"] = w3[()]
                fields["vB"], fields["vC"] = (_stack(*v) for v in np.split(
                    np.array(np.broadcast_arrays(*_gen.rssr_velocity(l1, l3, lam, phi01, phi03, omega, w3))), 2))
            if order >= 2:
                alpha = rates[1]
                if self._change is not None:
                    a3 = np.where(valid & ~dead, jet.d2 * omega * omega + jet.d1 * alpha, np.nan)
                else:
                    a3 = np.where(valid & ~dead,
                                  _abc.abc_accel(C, dA, dB, ddA, ddB, ddC, phi03, w3, root, sigma), np.nan)
                fields["alpha_output"] = a3[()]
                fields["aB"], fields["aC"] = (_stack(*v) for v in np.split(np.array(np.broadcast_arrays(
                    *_gen.rssr_acceleration(l1, l3, lam, phi01, phi03, omega, w3, alpha, a3))), 2))
        with np.errstate(over="ignore"):      # a rate beyond the float range: masked below
            for name in _LINEAR.intersection(fields):
                fields[name] = fields[name] * self._scale
        if order >= 1:
            mask_singular_rates(fields, _SOLVED_RATES[: 2 * order])
        return fields

    def assembly_range(self):
        """The crank angles where the linkage assembles, and its limit positions.

        The discriminant A^2 + B^2 - C^2 of (2-71) is a trigonometric polynomial of degree 2
        in phi01: its coefficients come from 8 equally spaced samples, its zeros from the
        quartic in z = exp(1j phi01), refined by bisection on the accurate discriminant.

        Returns
        -------
        AssemblyRange
            ``intervals`` (limit positions at the ends) and ``full_turn``.

        Examples
        --------
        >>> import numpy as np
        >>> from mech.spatial._rssr import RSSR
        >>> rng = RSSR(2.0, 2.5, 1.5, 0.3, -0.4, 1.5, 0.8).assembly_range()
        >>> rng.full_turn, rng.intervals.shape
        (False, (1, 2))
        """
        samples = self._coefficients(np.arange(8) * (np.pi / 4))[3]
        fourier = np.fft.fft(samples) / 8                  # c_k at index k (mod 8)
        poly = [fourier[k % 8] for k in (2, 1, 0, -1, -2)]  # highest power of z first
        if abs(poly[0]) <= 1e-14 * np.max(np.abs(poly)):
            zeros = np.array([])
        else:
            zs = np.roots(poly)
            zeros = np.sort(np.angle(zs[np.abs(np.abs(zs) - 1.0) < 1e-6]))
        disc = lambda x: float(self._coefficients(np.asarray(x, dtype=float))[3])
        zeros = np.array([self._refine(disc, z) for z in zeros])
        if zeros.size == 0:
            return AssemblyRange(np.empty((0, 2)), bool(disc(0.0) >= 0.0))
        ends = np.append(zeros, zeros[0] + 2 * np.pi)
        intervals = [(s, e) for s, e in zip(ends[:-1], ends[1:]) if e > s and disc(0.5 * (s + e)) > 0.0]
        merged = []
        for s, e in intervals:                      # join intervals that meet at a double zero
            if merged and abs(s - merged[-1][1]) < 1e-9:
                merged[-1] = (merged[-1][0], e)
            else:
                merged.append((s, e))
        if len(merged) > 1 and abs(merged[-1][1] - 2 * np.pi - merged[0][0]) < 1e-9:
            merged[0] = (merged[-1][0], merged[0][1] + 2 * np.pi)
            merged.pop()
        if not merged:                              # it assembles at isolated angles at most
            return AssemblyRange(np.empty((0, 2)), False)
        if len(merged) == 1 and merged[0][1] - merged[0][0] > 2 * np.pi - 1e-9:
            return AssemblyRange(np.empty((0, 2)), True)
        out = np.array([(s - 2 * np.pi * np.floor((s + np.pi) / (2 * np.pi)), 0.0) for s, _ in merged])
        out[:, 1] = out[:, 0] + np.array([e - s for s, e in merged])
        return AssemblyRange(out, False)

    @staticmethod
    def _refine(disc, x, width=1e-5):
        """Bisect a sign change of `disc` within `width` of `x`; return `x` if none."""
        lo, hi = x - width, x + width
        f_lo, f_hi = disc(lo), disc(hi)
        if f_lo * f_hi > 0.0:
            return x
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            f_mid = disc(mid)
            if f_mid == 0.0:
                return mid
            if (f_mid > 0.0) == (f_lo > 0.0):
                lo, f_lo = mid, f_mid
            else:
                hi = mid
        return 0.5 * (lo + hi)
