"""The crank and oscillating guide-bar (摆动导杆机构) of example 2-2."""

import numpy as np

from mech._generated import slider_crank as _gen
from mech._validate import common_shape, finite_array, nonnegative_int, positive_length
from mech._pose import mask_singular_rates, Pose, quiet_overflow
from mech._scaling import length_scale

__all__ = ["GuideBar", "GuideBarPose"]


# fields that scale with the unit of length
_LINEAR = frozenset({"rho", "B", "v_slide", "vB", "a_slide", "aB"})
_SOLVED_RATES = ("omega_guide", "v_slide", "alpha_guide", "a_slide")


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
        order = nonnegative_int("order", order, 2)
        theta = finite_array("theta", theta)
        psi, rho, B = _gen.guide_bar_position(*self._unit, theta)
        fields = {"theta": theta, "valid": np.ones(theta.shape, dtype=bool), "psi": psi, "rho": rho, "B": B}
        if order >= 1:
            omega = finite_array("omega", omega)
            common_shape(theta=theta, omega=omega)
            wg, vs, vB = _gen.guide_bar_velocity(*self._unit, theta, omega)
            fields.update(omega_guide=wg, v_slide=vs, vB=vB)
        if order >= 2:
            alpha = finite_array("alpha", alpha)
            common_shape(theta=theta, omega=omega, alpha=alpha)
            ag, as_, aB = _gen.guide_bar_acceleration(*self._unit, theta, omega, alpha)
            fields.update(alpha_guide=ag, a_slide=as_, aB=aB)
        shape = np.broadcast_shapes(*(np.shape(f) for f in fields.values()))
        fields = {k: np.array(np.broadcast_to(v, shape))[()] for k, v in fields.items()}
        with np.errstate(over="ignore"):      # a rate near a dead point may overflow: masked below
            fields.update((k, v * self._scale) for k, v in fields.items() if k in _LINEAR)
        if order >= 1:
            mask_singular_rates(fields, _SOLVED_RATES[: 2 * order])
        return GuideBarPose(order, fields)

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
