"""Four-bars with two prismatic pairs (Table 2-1, Fig. 2-11): trammel, sine, tangent, Oldham."""

import numpy as np

from mech._errors import AssemblyError
from mech._generated import special_mechanisms as _gen
from mech._validate import bool_flag, finite_array, positive_length, real_tuple
from mech._pose import mask_singular_rates, Pose, quiet_overflow
from mech.planar.special._special import _finish, _inputs

__all__ = [
    "EllipticTrammel",
    "TrammelPose",
    "ScotchYoke",
    "ScotchYokePose",
    "TangentMechanism",
    "TangentPose",
    "OldhamCoupling",
    "OldhamPose",
]


def _rates_mask(order, fields, pose_class):
    """Mark dead points over every rate of the pose (the rule of `mech._pose.Pose`)."""
    if order >= 1:
        mask_singular_rates(fields, [k for k in pose_class._ORDER_OF if k in fields])
    return fields


class TrammelPose(Pose):
    """Poses of an elliptic trammel (from `EllipticTrammel.solve`).

    Attributes
    ----------
    theta, valid : ndarray
        Crank angles of O->M; `valid` is all True.
    B, C, M, P, I : ndarray of complex
        Slider on the x guide, slider on the y guide, midpoint of BC (the crank pin),
        coupler point and instant centre of the coupler.
    phi : ndarray
        Angle of B->C, ``pi - theta``.
    vB, vC, vP, omega_coupler : ndarray
        With ``order >= 1``; ``omega_coupler = -omega``.
    aB, aC, aP, alpha_coupler : ndarray
        With ``order >= 2``.
    assembled : ndarray of bool
        True where the position exists. With ``order >= 1``, ``valid`` is False also where
        a solved rate is infinite or undetermined (a dead point; those rates are NaN
        there), while ``assembled`` stays True (the rule of `mech._pose.Pose`).
    """

    _ORDER_OF = {"vB": 1, "vC": 1, "vP": 1, "omega_coupler": 1,
                 "aB": 2, "aC": 2, "aP": 2, "alpha_coupler": 2}


class EllipticTrammel:
    """The double slider with perpendicular guides (双滑块机构, 椭圆仪, Fig. 2-11a).

    The coupler BC of length `L` has B on the x axis and C on the y axis; a crank OM of
    length L/2 drives its midpoint, ``M = (L/2) exp(i theta)``, so that
    ``B = L cos(theta)``, ``C = i L sin(theta)`` and the coupler angle is
    ``phi = pi - theta``. A coupler point ``P = B + (p + i q) exp(i phi)`` traces an ellipse
    about O (F17, F54).

    Parameters
    ----------
    L : float
        Coupler length BC.
    point : (float, float), optional
        Coupler point (p, q): p along B->C, q to its left.

    Raises
    ------
    ValueError
        If `L` is not positive and finite or the point is not finite.

    Notes
    -----
    Derived in :ref:`deriv-special-mechanisms`. The instant centre is ``I = L exp(i theta)``:
    the fixed centrode is the circle of radius L about O, the moving centrode the circle
    of diameter L about M. The motion is a circle of radius L/2 rolling inside one of
    radius L (Fig. 2-60). With ``L = 2a`` it is the isosceles slider-crank of Fig. 2-22c
    (crank = rod = a, stroke 4a), see `from_crank`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.special._double_slider import EllipticTrammel
    >>> trammel = EllipticTrammel(2.0, point=(0.5, 0.0))
    >>> pose = trammel.solve(np.pi / 2)
    >>> np.round(complex(pose.P), 12), trammel.path_axes()
    (np.complex128(0.5j), (1.5, 0.5))
    """

    def __init__(self, L, *, point=(0.0, 0.0)):
        self._L = positive_length("L", L)
        self._p, self._q = real_tuple("point", point, 2)

    @classmethod
    def from_crank(cls, a, *, point=(0.0, 0.0)):
        """The isosceles slider-crank (等腰对心式曲柄滑块机构): crank = rod = `a`, L = 2a.

        Its slider is B, its auxiliary pin (Fig. 2-22c) is C; the stroke of B is 4a.

        >>> from mech.planar.special._double_slider import EllipticTrammel
        >>> EllipticTrammel.from_crank(1.5).stroke()
        6.0
        """
        return cls(2.0 * positive_length("a", a), point=point)

    L = property(lambda self: self._L, doc="Coupler length BC.")
    point = property(lambda self: (self._p, self._q), doc="Coupler point (p, q).")

    def __repr__(self):
        return f"EllipticTrammel(L={self._L!r}, point=({self._p!r}, {self._q!r}))"

    @quiet_overflow
    def solve(self, theta, order=0, omega=1.0, alpha=0.0, strict=False):
        """Positions (and rates) of the sliders, the midpoint and the coupler point.

        Parameters
        ----------
        theta : array_like, shape (...)
            Angle of the crank O->M from +x, counter-clockwise, radians.
        order : {0, 1, 2}, optional
            0: positions; 1: also velocities; 2: also accelerations.
        omega, alpha : array_like, optional
            Crank angular velocity and acceleration; they broadcast with `theta`.
        strict : bool, optional
            Accepted for the common API; the trammel assembles at every angle.

        Returns
        -------
        TrammelPose
            ``B, C, M, P, I, phi, valid``; with ``order >= 1`` also ``vB, vC, vP,
            omega_coupler``; with ``order >= 2`` also ``aB, aC, aP, alpha_coupler``.

        Raises
        ------
        ValueError
            If `order` is not 0, 1 or 2 or an input is not finite.

        Examples
        --------
        >>> from mech.planar.special._double_slider import EllipticTrammel
        >>> pose = EllipticTrammel(2.0).solve(0.0, order=2, omega=3.0)
        >>> complex(pose.B), complex(pose.aB), float(pose.omega_coupler)
        ((2+0j), (-18+0j), -3.0)
        """
        strict = bool_flag("strict", strict)
        order, theta, omega, alpha = _inputs(order, theta, omega, alpha)
        args = (self._L, self._p, self._q, theta)
        B, C, M, P, phi, I = _gen.trammel_position(*args)
        fields = {"theta": theta, "valid": np.ones(np.shape(theta), dtype=bool),
                  "B": B, "C": C, "M": M, "P": P, "phi": phi, "I": I}
        if order >= 1:
            fields.update(zip(("vB", "vC", "vP", "omega_coupler"), _gen.trammel_velocity(*args, omega)))
        if order >= 2:
            fields.update(zip(("aB", "aC", "aP", "alpha_coupler"),
                              _gen.trammel_acceleration(*args, omega, alpha)))
        return TrammelPose(order, _rates_mask(order, _finish(fields), TrammelPose))

    def path_axes(self):
        """Semi-axes (major, minor) of the ellipse traced by the coupler point.

        With ``r = |P - M|`` measured on the coupler, they are ``L/2 + r`` and
        ``|L/2 - r|``: a circle for the midpoint, a segment of length 2L for B and C.
        """
        r = float(np.hypot(self._p - self._L / 2, self._q))
        return self._L / 2 + r, abs(self._L / 2 - r)

    def stroke(self):
        """Stroke of each slider, 2L (4a for the isosceles slider-crank, F22)."""
        return 2.0 * self._L


class ScotchYokePose(Pose):
    """Poses of a sine mechanism (from `ScotchYoke.solve`): ``theta, valid, x, B``;
    ``v`` with ``order >= 1``; ``acc`` with ``order >= 2``."""

    _ORDER_OF = {"v": 1, "acc": 2}


class ScotchYoke:
    """The sine mechanism (正弦机构, 十字滑块曲柄机构, Scotch yoke, Fig. 2-11b).

    The crank pin ``B = a exp(i theta)`` slides in a slot of the yoke perpendicular to the
    yoke's guide (the x axis), so the yoke is at ``x = a cos(theta)`` (F51; the text's
    ``h = L sin(alpha)`` with alpha measured from the slot). It is the slider-crank with
    an infinitely long rod, the limit lambda -> 0 of (2-10).

    Parameters
    ----------
    a : float
        Crank length.

    Raises
    ------
    ValueError
        If `a` is not positive and finite.

    Notes
    -----
    Derived in :ref:`deriv-special-mechanisms`: ``v = -a omega sin(theta)``,
    ``acc = -a omega^2 cos(theta) - a alpha sin(theta)``; stroke 2a, no quick return.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.special._double_slider import ScotchYoke
    >>> pose = ScotchYoke(2.0).solve(np.pi / 2, order=1)
    >>> round(float(pose.x), 12), float(pose.v)
    (0.0, -2.0)
    """

    def __init__(self, a):
        self._a = positive_length("a", a)

    a = property(lambda self: self._a, doc="Crank length.")

    def __repr__(self):
        return f"ScotchYoke(a={self._a!r})"

    @quiet_overflow
    def solve(self, theta, order=0, omega=1.0, alpha=0.0, strict=False):
        """Yoke position ``x``, crank pin ``B`` and (with `order`) ``v``, ``acc``.

        Same arguments as `EllipticTrammel.solve`; returns a `ScotchYokePose`.
        """
        strict = bool_flag("strict", strict)
        order, theta, omega, alpha = _inputs(order, theta, omega, alpha)
        x, B = _gen.scotch_yoke_position(self._a, theta)
        fields = {"theta": theta, "valid": np.ones(np.shape(theta), dtype=bool), "x": x, "B": B}
        if order >= 1:
            fields["v"] = _gen.scotch_yoke_velocity(self._a, theta, omega)
        if order >= 2:
            fields["acc"] = _gen.scotch_yoke_acceleration(self._a, theta, omega, alpha)
        return ScotchYokePose(order, _rates_mask(order, _finish(fields), ScotchYokePose))

    def stroke(self):
        """Stroke 2a (F22)."""
        return 2.0 * self._a


class TangentPose(Pose):
    """Poses of a tangent mechanism (from `TangentMechanism.solve`): ``theta, valid, h, S``;
    ``v`` with ``order >= 1`` (where a rate overflows, ``valid`` is False, ``assembled``
    True and the rates NaN); ``acc`` with ``order >= 2``."""

    _ORDER_OF = {"v": 1, "acc": 2}


class TangentMechanism:
    """The tangent mechanism (正切机构, Fig. 2-11d): ``h = L tan(theta)`` (F17).

    A bar turns about O = 0 by theta and carries a slider that also runs on the fixed
    guide x = L; the slider is at ``S = L + i h``.

    Parameters
    ----------
    L : float
        Distance from the bar's pivot to the guide.

    Raises
    ------
    ValueError
        If `L` is not positive and finite.

    Notes
    -----
    The bar meets the guide unless it is parallel to it, ``cos(theta) = 0``; only there
    is the pose NaN with ``valid == False``. All outputs are linear in `L`, so angles do not
    depend on the unit of length; a slide beyond the largest float reads ``inf``.
    Derivation: :ref:`deriv-special-mechanisms`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.special._double_slider import TangentMechanism
    >>> pose = TangentMechanism(2.0).solve(np.pi / 4, order=1)
    >>> round(float(pose.h), 12), round(float(pose.v), 12)
    (2.0, 4.0)
    """

    def __init__(self, L):
        self._L = positive_length("L", L)

    L = property(lambda self: self._L, doc="Distance from the pivot to the guide.")

    def __repr__(self):
        return f"TangentMechanism(L={self._L!r})"

    @quiet_overflow
    def solve(self, theta, order=0, omega=1.0, alpha=0.0, strict=False):
        """Output ``h``, slider ``S`` and (with `order`) ``v``, ``acc``.

        Same arguments as `EllipticTrammel.solve`; with ``strict=True`` raises
        `AssemblyError` naming the first angle with ``cos(theta) == 0``.
        """
        strict = bool_flag("strict", strict)
        order, theta, omega, alpha = _inputs(order, theta, omega, alpha)
        valid = np.cos(theta) != 0.0
        if strict and not np.all(valid):
            first = float(theta[~valid].ravel()[0])
            raise AssemblyError(f"Cannot assemble {self!r} at theta = {first!r}: the bar is parallel to the guide")
        # near cos(theta) = 0 a huge L makes h overflow to inf: the true slide is beyond
        # the floating-point range, so inf is its correctly rounded value
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            h = _gen.tangent_position(self._L, theta)
            fields = {"theta": theta, "valid": valid, "h": h, "S": self._L + 1j * h}
            if order >= 1:
                fields["v"] = _gen.tangent_velocity(self._L, theta, omega)
            if order >= 2:
                fields["acc"] = _gen.tangent_acceleration(self._L, theta, omega, alpha)
        fields = _finish(fields)
        for name in ("h", "S", "v", "acc"):
            if name in fields:
                nan = np.nan + 1j * np.nan if name == "S" else np.nan
                fields[name] = np.where(fields["valid"], fields[name], nan)[()]
        return TangentPose(order, _rates_mask(order, fields, TangentPose))


class OldhamPose(Pose):
    """Poses of an Oldham coupling (from `OldhamCoupling.solve`).

    Attributes
    ----------
    theta, valid : ndarray
        Angle of the input shaft (and of its tongue); `valid` is all True.
    S : ndarray of complex
        Centre of the cross-slider, on the circle with diameter O1 O3.
    orbit : ndarray
        Angle of S seen from that circle's centre, ``2 theta`` (the text's phi_2).
    s1, s3 : ndarray
        Slides of S along the input and output tongues, ``e0 cos(theta)``, ``e0 sin(theta)``.
    phi_slider, phi_output : ndarray
        Orientation of the cross-slider and angle of the output shaft: both ``theta``.
    vS, omega_orbit, omega_slider, omega_output : ndarray
        With ``order >= 1``: ``omega_orbit = 2 omega``, the others ``omega``.
    aS, alpha_orbit, alpha_slider, alpha_output : ndarray
        With ``order >= 2``.
    assembled : ndarray of bool
        True where the position exists. With ``order >= 1``, ``valid`` is False also where
        a solved rate is infinite or undetermined (a dead point; those rates are NaN
        there), while ``assembled`` stays True (the rule of `mech._pose.Pose`).
    """

    _ORDER_OF = {"vS": 1, "omega_orbit": 1, "omega_slider": 1, "omega_output": 1,
                 "aS": 2, "alpha_orbit": 2, "alpha_slider": 2, "alpha_output": 2}


class OldhamCoupling:
    """The Oldham coupling (双转块机构, 十字滑块联轴器, Figs. 2-11c, 2-57).

    Parallel shafts turn about O1 = 0 and O3 = e0; a cross-slider with two slots at right
    angles engages a tongue on each. Both shafts and the cross-slider turn through the
    same angle theta; the cross-slider's centre runs on the circle of diameter e0 at twice
    the shaft speed (F49).

    Parameters
    ----------
    e0 : float
        Offset between the shaft axes.

    Raises
    ------
    ValueError
        If `e0` is not positive and finite.

    Notes
    -----
    The text (§2.2 I and III) says the cross-slider turns at twice the input speed; it
    turns at the input speed, and only its centre orbits at 2 omega, which causes the
    rotating inertia force ``m (e0/2) (2 omega)^2`` (`inertia_force`). Derivation and
    proof: :ref:`deriv-special-mechanisms`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.special._double_slider import OldhamCoupling
    >>> pose = OldhamCoupling(0.1).solve(np.pi / 4, order=1, omega=10.0)
    >>> round(complex(pose.S).real, 12), float(pose.omega_orbit), float(pose.omega_slider)
    (0.05, 20.0, 10.0)
    >>> OldhamCoupling(0.1).inertia_force(2.0, 10.0)
    40.0
    """

    def __init__(self, e0):
        self._e0 = positive_length("e0", e0)

    e0 = property(lambda self: self._e0, doc="Offset between the shaft axes.")

    def __repr__(self):
        return f"OldhamCoupling(e0={self._e0!r})"

    @quiet_overflow
    def solve(self, theta, order=0, omega=1.0, alpha=0.0, strict=False):
        """Cross-slider centre and orientation, output shaft, and their rates.

        Same arguments as `EllipticTrammel.solve`; returns an `OldhamPose`.
        """
        strict = bool_flag("strict", strict)
        order, theta, omega, alpha = _inputs(order, theta, omega, alpha)
        S, orbit, s1, s3 = _gen.oldham_position(self._e0, theta)
        fields = {"theta": theta, "valid": np.ones(np.shape(theta), dtype=bool), "S": S, "orbit": orbit,
                  "s1": s1, "s3": s3, "phi_slider": theta, "phi_output": theta}
        if order >= 1:
            vS, w_orbit = _gen.oldham_velocity(self._e0, theta, omega)
            fields.update(vS=vS, omega_orbit=w_orbit, omega_slider=omega, omega_output=omega)
        if order >= 2:
            aS, a_orbit = _gen.oldham_acceleration(self._e0, theta, omega, alpha)
            fields.update(aS=aS, alpha_orbit=a_orbit, alpha_slider=alpha, alpha_output=alpha)
        return OldhamPose(order, _rates_mask(order, _finish(fields), OldhamPose))

    @quiet_overflow
    def inertia_force(self, m, omega):
        """Magnitude of the cross-slider's rotating inertia force, ``m (e0/2)(2 omega)^2``.

        For a constant shaft speed `omega`; `m` is the cross-slider's mass.
        """
        m = positive_length("m", m)
        omega = finite_array("omega", omega)
        force = _gen.oldham_inertia_force(m, self._e0, omega)
        return float(force) if np.ndim(force) == 0 else force
