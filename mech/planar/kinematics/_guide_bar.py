"""The crank and oscillating guide-bar (摆动导杆机构) of example 2-2."""

import numpy as np

from mech import _backend
from mech._generated import slider_crank as _gen
from mech._validate import motion_inputs, positive_length
from mech._pose import _finite_sum, mask_singular_rates, Pose, quiet_overflow
from mech._scaling import length_scale

__all__ = ["GuideBar", "GuideBarPose"]


# fields that scale with the unit of length
_LINEAR = frozenset({"rho", "B", "v_slide", "vB", "a_slide", "aB"})
_SOLVED_RATES = ("omega_guide", "v_slide", "alpha_guide", "a_slide")
# the fields of each order, in the kernels' order; the complex ones; rows of the work array
_FIELDS = ("psi", "rho", "B", "omega_guide", "v_slide", "vB", "alpha_guide", "a_slide", "aB")
_FIELD_COUNT = {0: 3, 1: 6, 2: 9}
_COMPLEX = frozenset({"B", "vB", "aB"})
_WORK_ROWS = max(_gen.WORK_ROWS[name] for name in (
    "guide_bar_position", "guide_bar_velocity", "guide_bar_acceleration"))


class GuideBarPose(Pose):
    """Poses of an oscillating guide-bar at an array of crank angles (`GuideBar.solve`).

    Attributes
    ----------
    theta, valid : ndarray
        The crank angles; `valid` is all True (the mechanism always assembles).
    B : ndarray of complex
        Crank pin, the centre of the block that slides on the guide.
    psi, rho : ndarray
        Guide angle (of D->B, in (pi/2, 3pi/2)) and the block's distance DB.
    omega_guide, v_slide, vB : ndarray
        With ``order >= 1``: d psi/dt, d rho/dt and the velocity of B.
    alpha_guide, a_slide, aB : ndarray
        With ``order >= 2``: the second derivatives and the acceleration of B.
    assembled : ndarray of bool
        True where the position exists. With ``order >= 1``, ``valid`` is False also where
        a solved rate is infinite or undetermined (a dead point; those rates are NaN
        there), while ``assembled`` stays True (the rule of `mech._pose.Pose`).
    """

    _ORDER_OF = {"omega_guide": 1, "v_slide": 1, "vB": 1,
                 "alpha_guide": 2, "a_slide": 2, "aB": 2}


class GuideBar:
    """A crank AB and an oscillating guide bar pivoted at D, with A = 0 and D = d.

    The block pinned to the crank at ``B = a exp(i theta)`` slides on the guide bar
    through D. This is the centred slider-crank chain with its crank made the frame
    (F16); the guide oscillates when ``a < d`` (Fig. 2-39, example 2-2).

    Parameters
    ----------
    a : float
        Crank length AB.
    d : float
        Frame length AD, the distance between the crank centre and the guide pivot.

    Raises
    ------
    ValueError
        If a length is not positive and finite or if ``a >= d`` (then the guide
        rotates fully: a rotating guide-bar, not covered here).

    Notes
    -----
    Formulas from :ref:`deriv-slider-crank` (section on the guide-bar). At the guide's
    limit positions the crank is perpendicular to the guide, so the extreme angle equals
    the swing (F23) and ``sin(swing / 2) = a / d``. The formulas run on the lengths
    divided by a power of two near `d` (`mech._scaling`): angles do not depend on the
    unit of length, and lengths and linear rates scale exactly with it.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar import GuideBar
    >>> mechanism = GuideBar.from_swing(300.0, np.radians(60.0))    # example 2-2
    >>> round(mechanism.a, 9), round(mechanism.time_ratio(), 9), round(mechanism.min_guide_length(), 9)
    (150.0, 2.0, 450.0)
    """

    def __init__(self, a, d):
        self._a = positive_length("a", a)
        self._d = positive_length("d", d)
        if self._a >= self._d:
            raise ValueError(
                f"Expected `a` < `d` = {self._d!r} for an oscillating guide, got {self._a!r}"
            )
        self._scale = length_scale(self._a, self._d)
        # the generated formulas see lengths of order one only (see mech._scaling)
        self._unit = (self._a / self._scale, self._d / self._scale)

    a = property(lambda self: self._a, doc="Crank length AB.")
    d = property(lambda self: self._d, doc="Frame length AD.")

    def __repr__(self):
        return f"GuideBar(a={self._a!r}, d={self._d!r})"

    @classmethod
    def from_swing(cls, d, swing):
        """Guide-bar with frame `d` whose guide swings through `swing` radians.

        ``a = d sin(swing / 2)`` (F30), for ``0 < swing < pi``.

        >>> import numpy as np
        >>> from mech.planar import GuideBar
        >>> round(GuideBar.from_swing(300.0, np.radians(60.0)).a, 9)
        150.0
        """
        d = positive_length("d", d)
        swing = positive_length("swing", swing)
        if swing >= np.pi:
            raise ValueError(f"Expected `swing` < pi, got {swing!r}")
        a = float(_gen.guide_bar_crank(d, swing))
        if a == 0.0:
            raise ValueError(f"Expected `d` and `swing` with a crank d sin(swing / 2) longer than 0.0, "
                             f"got d={d!r}, swing={swing!r}")
        return cls(a, d)

    @quiet_overflow
    def solve(self, theta, order=0, omega=1.0, alpha=0.0):
        """Guide angle, block distance and their rates at crank angles `theta`.

        ``psi = pi - atan2(a sin(theta), d - a cos(theta))`` and
        ``rho^2 = (d - a)^2 + 4 a d sin^2(theta / 2)``; the rates are their time
        derivatives (:ref:`deriv-slider-crank`).

        Parameters
        ----------
        theta : array_like, shape (...)
            Crank angle of A->B from +x (towards D), counter-clockwise, radians.
        order : {0, 1, 2}, optional
            0: positions; 1: also velocities; 2: also accelerations.
        omega, alpha : array_like, optional
            Crank angular velocity and acceleration; they broadcast with `theta`.

        Returns
        -------
        GuideBarPose
            ``B, psi, rho, valid``; with ``order >= 1`` also ``omega_guide, v_slide, vB``;
            with ``order >= 2`` also ``alpha_guide, a_slide, aB``.

        Raises
        ------
        ValueError
            If `order` is not 0, 1 or 2 or an input is not finite.

        Examples
        --------
        >>> import numpy as np
        >>> from mech.planar import GuideBar
        >>> pose = GuideBar(150.0, 300.0).solve(np.pi / 3, order=1)
        >>> round(float(np.degrees(pose.psi)), 9), round(float(pose.omega_guide), 12)
        (150.0, 0.0)
        """
        order, shape, inputs = motion_inputs("theta", theta, order, omega, alpha)
        flat = [x.reshape(-1) for x in inputs]
        size = flat[0].size
        names = _FIELDS[: _FIELD_COUNT[order]]
        out = {name: np.empty(size, dtype=complex if name in _COMPLEX else float) for name in names}
        # numba: fused loops over NUMBA_BLOCK points at a time; NumPy: cache-sized blocks,
        # temporaries in one reused work array; each block scaled and checked in cache
        numba = _backend.use_numba(size)
        step = _backend.NUMBA_BLOCK if numba else _backend.BLOCK
        finite = True
        for start in range(0, max(size, 1), step):
            block = slice(start, start + step)
            views = {k: v[block] for k, v in out.items()}
            self._solve_block([x[block] for x in flat], order, views, numba)
            finite = finite and all(_finite_sum(views[k]) for k in names)
        fields = {name: value.reshape(shape)[()] for name, value in out.items()}
        fields["theta"] = flat[0].reshape(shape).copy()[()]
        fields["valid"] = np.ones(shape, dtype=bool)[()]      # the guide-bar always assembles
        if order >= 1:
            if finite:                    # no dead point, no rate beyond the float range
                fields["assembled"] = np.ones(shape, dtype=bool)[()]
            else:
                mask_singular_rates(fields, _SOLVED_RATES[: 2 * order])
        return GuideBarPose(order, fields, finite)

    def _solve_block(self, inputs, order, out, numba):
        """Solve one block of flat inputs into the views in `out` (in the caller's error state)."""
        theta = inputs[0]
        outs = [(out["psi"], out["rho"], out["B"].real, out["B"].imag)]
        if order >= 1:
            outs.append((out["omega_guide"], out["v_slide"], out["vB"].real, out["vB"].imag))
        if order >= 2:
            outs.append((out["alpha_guide"], out["a_slide"], out["aB"].real, out["aB"].imag))
        stages = ("guide_bar_position", "guide_bar_velocity", "guide_bar_acceleration")
        if numba:
            kernels = _backend.numba_kernels("slider_crank")
            for k in range(order + 1):
                getattr(kernels, f"{stages[k]}_kernel")(*self._unit, theta, *inputs[1:k + 1], *outs[k])
        else:
            work = _backend.workspace("guide_bar", _WORK_ROWS, theta.shape[0])
            for k in range(order + 1):
                getattr(_gen, f"{stages[k]}_into")(*self._unit, theta, *inputs[1:k + 1], outs[k],
                                                   work[:_gen.WORK_ROWS[stages[k]]])
        if self._scale != 1.0:
            for name in _LINEAR.intersection(out):
                target = out[name].view(float) if name in _COMPLEX else out[name]
                np.multiply(target, self._scale, out=target)

    def swing(self):
        """Swing of the guide bar, ``2 asin(a / d)`` (F23, in atan2 form).

        >>> import numpy as np
        >>> from mech.planar import GuideBar
        >>> round(float(np.degrees(GuideBar(150.0, 300.0).swing())), 9)
        60.0
        """
        return float(_gen.guide_bar_swing(*self._unit)[0])

    def extreme_angle(self):
        """Extreme angle (极位夹角) of the crank; it equals the swing (F23).

        >>> import numpy as np
        >>> from mech.planar import GuideBar
        >>> round(float(np.degrees(GuideBar(150.0, 300.0).extreme_angle())), 9)
        60.0
        """
        return self.swing()

    def time_ratio(self):
        """Time ratio K = (pi + swing) / (pi - swing) of eq. (2-9).

        >>> from mech.planar import GuideBar
        >>> round(GuideBar(150.0, 300.0).time_ratio(), 9)
        2.0
        """
        from mech.planar.structure._quick_return import time_ratio

        return float(time_ratio(self.extreme_angle()))

    def min_guide_length(self):
        """Shortest guide that keeps the block on it: the largest DB, ``d + a`` (F30).

        >>> from mech.planar import GuideBar
        >>> GuideBar(150.0, 300.0).min_guide_length()
        450.0
        """
        return float(_gen.guide_bar_swing(*self._unit)[1]) * self._scale
