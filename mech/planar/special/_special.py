"""Inversions of the slider-crank chain beyond the slider-crank and the oscillating guide-bar.

The rotating guide-bar (转动导杆机构) and the oscillating or turning block (摇块, 转块) of
Table 2-1. The fixed block (定块) is the slider-crank ``SliderCrank(b, a)`` with the
roles of crank and rod exchanged; see :ref:`deriv-special-mechanisms`.
"""

import numpy as np

from mech._generated import special_mechanisms as _gen
from mech._validate import bool_flag, common_shape, finite_array, nonnegative_int, positive_length
from mech.planar.kinematics._guide_bar import GuideBar
from mech._pose import mask_singular_rates, Pose, quiet_overflow
from mech._scaling import length_scale

__all__ = ["RotatingGuideBar", "RotatingGuideBarPose", "SwingingBlock"]


def _finish(fields):
    """Broadcast every field to one shape and return plain arrays (scalars for 0-d)."""
    shape = np.broadcast_shapes(*(np.shape(f) for f in fields.values()))
    return {k: np.array(np.broadcast_to(v, shape))[()] for k, v in fields.items()}


def _inputs(order, theta, omega, alpha):
    order = nonnegative_int("order", order, 2)
    theta = finite_array("theta", theta)
    omega = finite_array("omega", omega) if order >= 1 else omega
    alpha = finite_array("alpha", alpha) if order >= 2 else alpha
    common_shape(**dict(list({"theta": theta, "omega": omega, "alpha": alpha}.items())[: order + 1]))
    return order, theta, omega, alpha


# fields of the guide-bar poses that scale with the unit of length
_LINEAR = frozenset({"rho", "B", "v_slide", "vB", "a_slide", "aB"})


class RotatingGuideBarPose(Pose):
    """Poses of a rotating guide-bar (from `RotatingGuideBar.solve`).

    Attributes
    ----------
    theta, valid : ndarray
        The crank angles; `valid` is all True (the mechanism always assembles).
    B : ndarray of complex
        Crank pin, the centre of the block that slides on the guide.
    psi, rho : ndarray
        Guide angle, continuous in theta, and the block's position along the guide:
        ``B - d = rho * exp(1j * psi)``. For ``a > d`` rho = DB > 0; for ``a == d`` it is
        signed and passes through zero when the block crosses the pivot.
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


class RotatingGuideBar:
    """A crank AB and a guide bar through D that turns fully (转动导杆机构), a >= d.

    The block pinned to the crank at ``B = a exp(i theta)`` slides on the guide through
    the pivot D = d, as in `GuideBar`, but with the crank at least as long as the frame
    the guide turns fully (F16, Table 2-1; the shaper of Fig. 2-20f).

    Parameters
    ----------
    a : float
        Crank length AB, ``a >= d``.
    d : float
        Frame length AD.

    Raises
    ------
    ValueError
        If a length is not positive and finite or ``a < d`` (use `GuideBar`).

    Notes
    -----
    Formulas from :ref:`deriv-special-mechanisms`. For ``a > d``,
    ``psi = theta + atan2(d sin(theta), a - d cos(theta))``, continuous, with
    ``psi(theta + 2 pi) = psi(theta) + 2 pi``. For ``a == d`` (Fig. 2-58) the guide turns
    at exactly half the crank speed, ``psi = pi/2 + theta/2`` (F50, phi1 = 2 phi3), and the
    block passes through D at ``theta = 0 (mod 2 pi)``; the two cases are chosen by the
    exact comparison ``a == d``. The formulas run on the lengths divided by a power of two
    near `a` (`mech._scaling`): angles do not depend on the unit of length, and lengths
    and linear rates scale exactly with it.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.special._special import RotatingGuideBar
    >>> pose = RotatingGuideBar(1.0, 1.0).solve(np.pi / 2, order=1)   # crank = frame
    >>> round(float(np.degrees(pose.psi)), 12), float(pose.omega_guide)
    (135.0, 0.5)
    >>> RotatingGuideBar(2.0, 1.0).solve(np.linspace(0, 2 * np.pi, 5)).psi.round(6)
    array([0.      , 2.034444, 3.141593, 4.248741, 6.283185])
    """

    def __init__(self, a, d):
        self._a = positive_length("a", a)
        self._d = positive_length("d", d)
        if self._a < self._d:
            raise ValueError(f"Expected `a` >= `d` = {self._d!r} for a rotating guide, got {self._a!r}")
        self._scale = length_scale(self._a, self._d)
        # the generated formulas see lengths of order one only (see mech._scaling)
        self._unit = (self._a / self._scale, self._d / self._scale)

    a = property(lambda self: self._a, doc="Crank length AB.")
    d = property(lambda self: self._d, doc="Frame length AD.")

    def __repr__(self):
        return f"RotatingGuideBar(a={self._a!r}, d={self._d!r})"

    @quiet_overflow
    def solve(self, theta, order=0, omega=1.0, alpha=0.0, strict=False):
        """Guide angle, block position and their rates at crank angles `theta`.

        Parameters
        ----------
        theta : array_like, shape (...)
            Crank angle of A->B from +x (towards D), counter-clockwise, radians.
        order : {0, 1, 2}, optional
            0: positions; 1: also velocities; 2: also accelerations.
        omega, alpha : array_like, optional
            Crank angular velocity and acceleration; they broadcast with `theta`.
        strict : bool, optional
            Accepted for the common API; the mechanism assembles at every angle.

        Returns
        -------
        RotatingGuideBarPose
            ``B, psi, rho, valid``; with ``order >= 1`` also ``omega_guide, v_slide, vB``;
            with ``order >= 2`` also ``alpha_guide, a_slide, aB``.

        Raises
        ------
        ValueError
            If `order` is not 0, 1 or 2 or an input is not finite.

        Examples
        --------
        >>> from mech.planar.special._special import RotatingGuideBar
        >>> pose = RotatingGuideBar(2.0, 1.0).solve(0.0, order=2)
        >>> float(pose.psi), float(pose.rho), float(pose.omega_guide)
        (0.0, 1.0, 2.0)
        """
        strict = bool_flag("strict", strict)
        order, theta, omega, alpha = _inputs(order, theta, omega, alpha)
        a, d = self._unit
        equal = a == d
        if equal:
            psi, rho, B = _gen.equal_guide_bar_position(a, theta)
        else:
            psi, rho, B = _gen.rotating_guide_bar_position(a, d, theta)
        fields = {"theta": theta, "valid": np.ones(np.shape(theta), dtype=bool), "psi": psi, "rho": rho, "B": B}
        if order >= 1:
            if equal:
                wg, vs, vB = _gen.equal_guide_bar_velocity(a, theta, omega)
            else:
                wg, vs, vB = _gen.rotating_guide_bar_velocity(a, d, theta, omega)
            fields.update(omega_guide=wg, v_slide=vs, vB=vB)
        if order >= 2:
            if equal:
                ag, as_, aB = _gen.equal_guide_bar_acceleration(a, theta, omega, alpha)
            else:
                ag, as_, aB = _gen.rotating_guide_bar_acceleration(a, d, theta, omega, alpha)
            fields.update(alpha_guide=ag, a_slide=as_, aB=aB)
        fields = _finish(fields)
        with np.errstate(over="ignore"):      # a rate near a dead point may overflow: masked below
            fields.update((k, v * self._scale) for k, v in fields.items() if k in _LINEAR)
        if order >= 1:
            mask_singular_rates(fields, ("omega_guide", "v_slide", "alpha_guide", "a_slide")[: 2 * order])
        return RotatingGuideBarPose(order, fields)

    def guide_turns_per_crank_turn(self):
        """Turns of the guide per crank turn: 1 for ``a > d``, 1/2 for ``a == d`` (F50).

        >>> from mech.planar.special._special import RotatingGuideBar
        >>> RotatingGuideBar(1.0, 1.0).guide_turns_per_crank_turn()
        0.5
        """
        return 0.5 if self._a == self._d else 1.0


class SwingingBlock:
    """The block mechanism (摇块 / 转块, Fig. 2-8): the coupler of the slider-crank chain fixed.

    The crank a turns about the origin; the block is pivoted on the frame at D = d, and a
    rod pinned to the crank at ``B = a exp(i theta)`` slides through it. The rod lies on
    the line B-D, so the block turns with the guide angle of the guide-bar with the same
    crank and frame (exchanging slot and slider changes no relative motion, F16): it
    oscillates (摇块) when ``a < d`` and turns fully (转块) when ``a >= d``.

    Parameters
    ----------
    a : float
        Crank length.
    d : float
        Frame length, from the crank centre to the block's pivot.

    Raises
    ------
    ValueError
        If a length is not positive and finite.

    Notes
    -----
    `solve` returns the pose of `GuideBar` (``a < d``) or `RotatingGuideBar` (``a >= d``):
    ``psi`` is the block's angle (of D->B) and ``rho`` the rod length between the crank pin
    and the block, e.g. the length of the hydraulic cylinder of a tipping lorry
    (Fig. 2-10). See :ref:`deriv-special-mechanisms`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.special._special import SwingingBlock
    >>> block = SwingingBlock(1.0, 2.0)
    >>> block.kind, round(float(np.degrees(block.swing())), 9)
    ('oscillating', 60.0)
    >>> SwingingBlock(2.0, 1.0).kind
    'turning'
    """

    def __init__(self, a, d):
        self._a = positive_length("a", a)
        self._d = positive_length("d", d)
        self._inner = GuideBar(self._a, self._d) if self._a < self._d else RotatingGuideBar(self._a, self._d)

    a = property(lambda self: self._a, doc="Crank length.")
    d = property(lambda self: self._d, doc="Frame length, crank centre to block pivot.")

    @property
    def kind(self):
        """``"oscillating"`` (摇块, ``a < d``) or ``"turning"`` (转块, ``a >= d``)."""
        return "oscillating" if self._a < self._d else "turning"

    def __repr__(self):
        return f"SwingingBlock(a={self._a!r}, d={self._d!r})"

    @quiet_overflow
    def solve(self, theta, order=0, omega=1.0, alpha=0.0, strict=False):
        """Block angle ``psi``, rod length ``rho`` and their rates (see `GuideBar.solve`).

        >>> import numpy as np
        >>> from mech.planar.special._special import SwingingBlock
        >>> float(SwingingBlock(1.0, 2.0).solve(np.pi).rho)
        3.0
        """
        strict = bool_flag("strict", strict)
        if isinstance(self._inner, GuideBar):
            return self._inner.solve(theta, order=order, omega=omega, alpha=alpha)
        return self._inner.solve(theta, order=order, omega=omega, alpha=alpha, strict=strict)

    def swing(self):
        """Swing of an oscillating block, ``2 asin(a / d)``; ValueError if it turns.

        >>> import numpy as np
        >>> from mech.planar.special._special import SwingingBlock
        >>> round(float(np.degrees(SwingingBlock(1.0, 2.0).swing())), 9)
        60.0
        """
        if self.kind != "oscillating":
            raise ValueError(f"Expected `a` < `d` = {self._d!r} for a swing, got {self._a!r}")
        return self._inner.swing()
