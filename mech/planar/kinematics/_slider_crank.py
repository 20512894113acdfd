"""The slider-crank, centred and offset: positions, rates, limits, transmission angle."""

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from mech import _backend
from mech._errors import AssemblyError
from mech._generated import slider_crank as _gen
from mech._validate import (
    bool_flag, branch_sign, common_shape, finite_array, motion_inputs, nonnegative_int, positive_length,
    real_number)
from mech._pose import _finite_sum, mask_singular_rates, Pose, quiet_overflow
from mech._scaling import DEAD_POINT_RTOL, length_scale

__all__ = ["SliderCrank", "SliderCrankPose", "SliderCrankLimits", "SliderCrankSeries"]


class SliderCrankPose(Pose):
    """Poses of a slider-crank at an array of crank angles (from `SliderCrank.solve`).

    Attributes
    ----------
    theta, valid : ndarray
        The crank angles, and False where the rod cannot reach the guide (NaN there).
    B, C : ndarray of complex
        Crank pin and slider pin, ``C = x + 1j*e``.
    x, phi : ndarray
        Slider position along the guide, and the rod angle of B->C in (-pi, pi].
    v, omega_coupler, vB : ndarray
        With ``order >= 1``: slider velocity dx/dt, rod angular velocity, velocity of B.
    acc, alpha_coupler, aB : ndarray
        With ``order >= 2``: slider acceleration, rod angular acceleration, acceleration
        of B.
    assembled : ndarray of bool
        True where the position exists. With ``order >= 1``, ``valid`` is False also where
        a solved rate is infinite or undetermined (a dead point; those rates are NaN
        there), while ``assembled`` stays True (the rule of `mech._pose.Pose`).
    """

    _ORDER_OF = {"v": 1, "omega_coupler": 1, "vB": 1,
                 "acc": 2, "alpha_coupler": 2, "aB": 2}


@dataclass(frozen=True)
class SliderCrankLimits:
    """Limit positions of a slider-crank whose crank turns fully (see `SliderCrank`).

    Attributes: ``theta_extended``, ``theta_folded`` (crank angles where crank and rod
    are collinear, extended and folded), ``x_extended``, ``x_folded`` (slider positions
    there), ``stroke`` H, ``extreme_angle`` theta_0 and ``time_ratio`` K.
    """

    theta_extended: float
    theta_folded: float
    x_extended: float
    x_folded: float
    stroke: float
    extreme_angle: float
    time_ratio: float


class SliderCrankSeries(NamedTuple):
    """Two-term series (2-10) of a centred slider-crank (from `SliderCrank.approximate`)."""

    x: np.ndarray
    v: np.ndarray
    acc: np.ndarray
    cos_phi: np.ndarray


# fields that scale with the unit of length, and the rates found from the loop equations
_LINEAR = frozenset({"x", "B", "C", "v", "vB", "acc", "aB"})
_SOLVED_RATES = ("omega_coupler", "v", "alpha_coupler", "acc")
# the fields of each order, in the kernels' order; the complex ones; rows of the work array
_FIELDS = ("x", "phi", "B", "C", "omega_coupler", "v", "vB", "alpha_coupler", "acc", "aB")
_FIELD_COUNT = {0: 4, 1: 7, 2: 10}
_COMPLEX = frozenset({"B", "C", "vB", "aB"})
_WORK_ROWS = max(_gen.WORK_ROWS[name] for name in (
    "slider_crank_position", "slider_crank_velocity", "slider_crank_acceleration"))


def _float(value):
    return float(value) if np.ndim(value) == 0 else value


class SliderCrank:
    """A slider-crank: crank a about A = 0, rod b, slider pin on the line y = e.

    The crank pin is ``B = a exp(i theta)``; the slider pin ``C = x + 1j*e`` runs on
    the guide y = e at distance b from B (loop closure F44, Fig. 2-52). ``e = 0`` is the
    centred slider-crank (对心曲柄滑块机构), ``e != 0`` the offset one (偏置).

    Parameters
    ----------
    a, b : float
        Crank AB and connecting rod BC, in any one length unit.
    e : float, optional
        Offset of the guide line (signed: the guide is y = e).
    branch : {1, -1}, optional
        Assembly branch: +1 puts C to the right of B (``cos(phi) > 0``), -1 to the left.

    Raises
    ------
    ValueError
        If `a` or `b` is not positive and finite, `e` is not finite, `branch` is not
        +1 or -1, or the rod cannot reach the guide at any crank angle
        (``b < |e| - a``).

    Notes
    -----
    Formulas from :ref:`deriv-slider-crank`. The position is
    ``x = a cos(theta) + branch * sqrt((b - s)(b + s))`` with ``s = e - a sin(theta)``,
    free of cancellation up to the dead points. The crank turns fully when
    ``b >= a + |e|``; otherwise it rocks between two dead points (``|s| = b``), where the
    branches meet, the rod is perpendicular to the guide and the rates are infinite;
    beyond them the pose is NaN with ``valid == False``. The formulas run on the lengths
    divided by a power of two near the longest (`mech._scaling`), so any finite positive
    lengths give the same angles, and lengths and linear rates scale exactly with them.

    Examples
    --------
    >>> from mech.planar import SliderCrank
    >>> mechanism = SliderCrank(30, 100, 20)          # example 2-3
    >>> round(float(mechanism.solve(0.0).x), 4)
    127.9796
    >>> round(mechanism.stroke(), 4)
    61.3703
    """

    def __init__(self, a, b, e=0.0, *, branch=1):
        self._a = positive_length("a", a)
        self._b = positive_length("b", b)
        self._e = real_number("e", e)
        self._branch = branch_sign(branch)
        self._scale = length_scale(self._a, self._b, self._e)
        # the generated formulas see lengths of order one only (see mech._scaling)
        self._unit = (self._a / self._scale, self._b / self._scale, self._e / self._scale)
        a_, b_, e_ = self._unit
        tol = DEAD_POINT_RTOL * (a_ + b_ + abs(e_))
        # |a sin(theta) - e| <= a + |e|: a crank that clears the dead points by more than
        # the tolerance (twice, for rounding) never meets one
        self._may_meet_dead_point = a_ + abs(e_) >= b_ - 2.0 * tol
        # the rod just reaching the guide (at one dead point) is allowed in any unit of length
        if b_ < abs(e_) - a_ - tol:
            raise ValueError(
                f"Expected `b` >= |e| - a = {abs(self._e) - self._a!r} so that the rod reaches "
                f"the guide, got {self._b!r}"
            )

    a = property(lambda self: self._a, doc="Crank length AB.")
    b = property(lambda self: self._b, doc="Connecting-rod length BC.")
    e = property(lambda self: self._e, doc="Offset (the guide is the line y = e).")
    branch = property(lambda self: self._branch, doc="Assembly branch, +1 or -1.")

    @property
    def crank_turns(self):
        """True if the crank turns fully, ``b >= a + |e|``."""
        a, b, e = self._unit
        return b >= a + abs(e)

    def __repr__(self):
        return f"SliderCrank(a={self._a!r}, b={self._b!r}, e={self._e!r}, branch={self._branch})"

    def solve(self, theta, order=0, omega=1.0, alpha=0.0, strict=False):
        """Solve the loop for the slider and rod at crank angles `theta`.

        Position (F44): ``x = a cos(theta) + branch * sqrt(b^2 - (e - a sin(theta))^2)``
        and ``phi = atan2(e - a sin(theta), x - a cos(theta))``; the rates are the time
        derivatives of the loop equations (derivation :ref:`deriv-slider-crank`).

        Parameters
        ----------
        theta : array_like, shape (...)
            Crank angle of A->B from +x, counter-clockwise, radians.
        order : {0, 1, 2}, optional
            0: positions; 1: also velocities; 2: also accelerations.
        omega, alpha : array_like, optional
            Crank angular velocity (rad/s) and acceleration (rad/s^2); they broadcast
            with `theta`.
        strict : bool, optional
            Raise instead of returning NaN where the linkage cannot be assembled.

        Returns
        -------
        SliderCrankPose
            Fields ``B, C, x, phi, valid`` of the broadcast shape; with ``order >= 1``
            also ``v, omega_coupler, vB``; with ``order >= 2`` also
            ``acc, alpha_coupler, aB``. Nothing above `order` is computed.

        Raises
        ------
        AssemblyError
            With ``strict=True``, naming the first crank angle where
            ``|a sin(theta) - e| > b``.
        ValueError
            If `order` is not 0, 1 or 2 or an input is not finite.

        Notes
        -----
        At a dead point of a rocking crank (``|a sin(theta) - e| = b``) the position
        exists and is exact, so ``assembled`` is True (and ``strict`` does not raise), but
        the velocity equations are singular: the rates are infinite (undetermined when
        ``omega = 0``). With ``order >= 1``, ``valid`` is False there and ``v,
        omega_coupler, acc, alpha_coupler`` are NaN; ``vB`` and ``aB``, set by the crank
        alone, stay finite. Near a dead point the rates are finite and grow like the
        inverse square root of the distance to it.

        Examples
        --------
        >>> import numpy as np
        >>> from mech.planar import SliderCrank
        >>> pose = SliderCrank(1.0, 4.0).solve(np.pi / 2, order=2)
        >>> round(float(pose.x), 12), round(float(pose.v), 12), round(float(pose.acc), 6)
        (3.872983346207, -1.0, 0.258199)
        >>> SliderCrank(1.0, 4.0).solve(np.linspace(0, np.pi, 7)).x.shape
        (7,)
        """
        strict = bool_flag("strict", strict)
        order, shape, inputs = motion_inputs("theta", theta, order, omega, alpha)
        flat = [x.reshape(-1) for x in inputs]
        size = flat[0].size
        names = _FIELDS[: _FIELD_COUNT[order]]
        out = {name: np.empty(size, dtype=complex if name in _COMPLEX else float) for name in names}
        out["valid"] = np.empty(size, dtype=bool)
        # numba: fused loops over NUMBA_BLOCK points at a time; NumPy: cache-sized blocks,
        # temporaries in one reused work array, then each block masked, scaled and checked
        # while it is in cache
        numba = _backend.use_numba(size)
        step = _backend.NUMBA_BLOCK if numba else _backend.BLOCK
        finite = True
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            for start in range(0, max(size, 1), step):
                block = slice(start, start + step)
                views = {k: v[block] for k, v in out.items()}
                self._solve_block([x[block] for x in flat], order, views, numba)
                finite = finite and all(_finite_sum(views[k]) for k in names)
        valid = out["valid"]
        if strict and not np.all(valid):
            first = float(flat[0][~valid][0])
            raise AssemblyError(
                f"Cannot assemble {self!r} at theta = {first!r}: the rod cannot reach the guide "
                f"there (|a sin(theta) - e| > b)"
            )
        fields = {name: value.reshape(shape)[()] for name, value in out.items()}
        fields["theta"] = flat[0].reshape(shape).copy()[()]
        if order >= 1:
            if finite:                    # no dead point, no rate beyond the float range
                fields["assembled"] = fields["valid"].copy() if shape else fields["valid"]
            else:
                mask_singular_rates(fields, _SOLVED_RATES[: 2 * order])
        return SliderCrankPose(order, fields, finite)

    def _solve_block(self, inputs, order, out, numba):
        """Solve one block of flat inputs into the views in `out` (in the caller's error state)."""
        a_, b_, e_ = args = self._unit
        theta, branch = inputs[0], self._branch
        x, phi, B, C = (out[k] for k in ("x", "phi", "B", "C"))
        outs = [(x, phi, B.real, B.imag, C.real, C.imag)]
        if order >= 1:
            outs.append((out["omega_coupler"], out["v"], out["vB"].real, out["vB"].imag))
        if order >= 2:
            outs.append((out["alpha_coupler"], out["acc"], out["aB"].real, out["aB"].imag))
        stages = ("slider_crank_position", "slider_crank_velocity", "slider_crank_acceleration")
        if numba:
            kernels = _backend.numba_kernels("slider_crank")
            for k in range(order + 1):
                getattr(kernels, f"{stages[k]}_kernel")(*args, theta, branch, *inputs[1:k + 1], *outs[k])
        else:
            work = _backend.workspace("slider_crank", _WORK_ROWS, theta.shape[0])
            for k in range(order + 1):
                getattr(_gen, f"{stages[k]}_into")(*args, theta, branch, *inputs[1:k + 1], outs[k],
                                                   work[:_gen.WORK_ROWS[stages[k]]])
        # the generated root is NaN exactly where the rod cannot reach the guide
        valid = out["valid"]
        np.equal(x, x, out=valid)
        if self._may_meet_dead_point:
            # within DEAD_POINT_RTOL of a dead point (|s| = b) the input is the dead point:
            # C below B; the rates found from the loop equations are infinite there (NaN)
            s = a_ * np.sin(theta) - e_
            dead = np.abs(np.abs(s) - b_) <= DEAD_POINT_RTOL * (a_ + b_ + abs(e_))
            if dead.any():
                snap = dead & ~valid
                x[snap] = a_ * np.cos(theta[snap])
                phi[snap] = -np.sign(s[snap]) * (np.pi / 2)
                C.real[snap] = x[snap]
                valid |= snap
                for name in _SOLVED_RATES[: 2 * order]:
                    out[name][dead] = np.nan
        if not valid.all():
            for name in out:
                if name not in ("valid", "B", "vB", "aB"):
                    out[name][~valid] = np.nan + 1j * np.nan if name in _COMPLEX else np.nan
        if self._scale != 1.0:
            for name in _LINEAR.intersection(out):
                target = out[name].view(float) if name in _COMPLEX else out[name]
                np.multiply(target, self._scale, out=target)

    def _require_turning(self, what):
        if not self.crank_turns:
            raise ValueError(
                f"Expected a crank that turns fully for {what}, b >= a + |e| = "
                f"{self._a + abs(self._e)!r}, got b = {self._b!r}"
            )

    def limit_positions(self):
        """Limit positions of the slider, with stroke, extreme angle and time ratio.

        The slider stops where crank and rod are collinear: extended (C at distance
        b + a from A) and folded (b - a). Stroke and extreme angle follow F31
        (example 2-3) in cancellation-free form; K follows eq. (2-9).

        Returns
        -------
        SliderCrankLimits
            ``theta_extended, theta_folded`` in (-pi, pi], ``x_extended, x_folded``,
            ``stroke``, ``extreme_angle`` in [0, pi/2) and ``time_ratio``.

        Raises
        ------
        ValueError
            If the crank does not turn fully (``b < a + |e|``).

        Notes
        -----
        Derived in :ref:`deriv-slider-crank`. With the crank turning counter-clockwise,
        the crank turns ``pi + extreme_angle`` from the extended to the folded position
        when ``branch * e > 0`` (the slider's slow stroke is then towards A).

        Examples
        --------
        >>> import numpy as np
        >>> from mech.planar import SliderCrank
        >>> lim = SliderCrank(30, 100, 20).limit_positions()     # example 2-3
        >>> round(float(np.degrees(lim.extreme_angle)), 5), round(lim.stroke, 4)
        (7.75167, 61.3703)
        """
        from mech.planar.structure._quick_return import time_ratio

        self._require_turning("limit positions")
        out = [float(v) for v in _gen.slider_crank_limits(*self._unit, self._branch)]
        for k in (2, 3, 4):               # x_extended, x_folded, stroke are lengths
            out[k] *= self._scale
        return SliderCrankLimits(*out, time_ratio=float(time_ratio(out[-1])))

    def stroke(self):
        """Stroke H of the slider (F22, F31): ``4ab / (r_+ + r_-)`` = 2a when e = 0.

        Raises ValueError unless the crank turns fully (``b >= a + |e|``). See
        `limit_positions` and :ref:`deriv-slider-crank`.

        >>> from mech.planar import SliderCrank
        >>> SliderCrank(30, 100).stroke()
        60.0
        """
        self._require_turning("the stroke")
        return float(_gen.slider_crank_limits(*self._unit, self._branch)[4]) * self._scale

    def extreme_angle(self):
        """Extreme angle theta_0 (极位夹角, F31): ``asin(|e|/(b-a)) - asin(|e|/(b+a))``.

        Evaluated as ``atan2(|e| H, r_+ r_- + e^2)`` (:ref:`deriv-slider-crank`).
        Raises ValueError unless the crank turns fully.

        >>> import numpy as np
        >>> from mech.planar import SliderCrank
        >>> round(float(np.degrees(SliderCrank(30, 100, 20).extreme_angle())), 5)
        7.75167
        """
        self._require_turning("the extreme angle")
        return float(_gen.slider_crank_limits(*self._unit, self._branch)[5])

    def time_ratio(self):
        """Time ratio K = (pi + theta_0) / (pi - theta_0) of eq. (2-9).

        >>> from mech.planar import SliderCrank
        >>> round(SliderCrank(30, 100, 20).time_ratio(), 5)
        1.09001
        """
        from mech.planar.structure._quick_return import time_ratio

        return float(time_ratio(self.extreme_angle()))

    def transmission_angle(self, theta):
        """Transmission angle gamma (传动角) in [0, pi/2] at crank angles `theta`.

        gamma is the acute angle between the rod and the normal to the guide, so
        ``cos(gamma) = |a sin(theta) - e| / b`` (F56; the pressure angle is
        pi/2 - gamma). NaN where the linkage cannot be assembled.
        Derivation: :ref:`deriv-slider-crank`.

        >>> import numpy as np
        >>> from mech.planar import SliderCrank
        >>> round(float(np.degrees(SliderCrank(30, 100, 20).transmission_angle(-np.pi / 2))), 9)
        60.0
        """
        theta = finite_array("theta", theta)
        with np.errstate(invalid="ignore"):
            return _float(_gen.slider_crank_transmission(*self._unit, theta))

    def min_transmission_angle(self):
        """Minimum transmission angle and the crank angle where it occurs (F57).

        ``cos(gamma_min) = (a + |e|) / b``, reached with the crank perpendicular to the
        guide and pointing away from it: ``theta_at = -pi/2`` for ``e >= 0`` (also
        +pi/2 when e = 0), ``+pi/2`` for ``e < 0``. Raises ValueError unless the crank
        turns fully. Derivation: :ref:`deriv-slider-crank`.

        >>> import numpy as np
        >>> from mech.planar import SliderCrank
        >>> g, th = SliderCrank(30, 100, 20).min_transmission_angle()
        >>> round(float(np.degrees(g)), 9), round(float(np.degrees(th)), 9)
        (60.0, -90.0)
        """
        self._require_turning("the minimum transmission angle")
        gamma_min = float(_gen.slider_crank_min_transmission(*self._unit))
        return gamma_min, (np.pi / 2 if self._e < 0 else -np.pi / 2)

    @quiet_overflow
    def approximate(self, theta, omega=1.0):
        """The textbook's two-term series (2-10) for a centred slider-crank.

        ``x = a (cos t + 1/lam - lam/4 + lam/4 cos 2t)``, ``v = -a w (sin t + lam/2 sin 2t)``,
        ``acc = -a w^2 (cos t + lam cos 2t)`` with ``lam = a / b`` and a constant crank
        speed `omega`; branch +1. The error grows as lam^3 (about ``lam^3/8`` in x/a and
        ``lam^3/2`` in acc/(a w^2)): see the table in :ref:`deriv-slider-crank`.

        Returns
        -------
        SliderCrankSeries
            ``(x, v, acc, cos_phi)`` of the broadcast shape of `theta` and `omega`.

        Raises
        ------
        ValueError
            If the slider-crank is offset (``e != 0``) or on branch -1.

        Examples
        --------
        >>> from mech.planar import SliderCrank
        >>> float(SliderCrank(1.0, 4.0).approximate(0.0).x)
        5.0
        """
        if self._e != 0.0 or self._branch != 1:
            raise ValueError(
                f"Expected a centred slider-crank on branch +1 for the series (2-10), got "
                f"e = {self._e!r}, branch = {self._branch}"
            )
        theta = finite_array("theta", theta)
        omega = finite_array("omega", omega)
        common_shape(theta=theta, omega=omega)
        a, b, _ = self._unit
        x, v, acc, cos_phi = _gen.slider_crank_series(a, a / b, theta, omega)
        shape = np.broadcast_shapes(theta.shape, omega.shape)
        out = (x * self._scale, v * self._scale, acc * self._scale, cos_phi)
        return SliderCrankSeries(*(np.array(np.broadcast_to(v, shape))[()] for v in out))
