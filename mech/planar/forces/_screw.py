"""Screw pairs and the screw jack: torques, efficiencies and self-locking (F47, F48).

The thread is an inclined plane wrapped on the mean diameter; a jack adds the friction of
its collar. Formulas from the derivation page ``deriv-efficiency`` through
``mech._generated.efficiency``; the collar radius from ``deriv-friction``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from mech._generated.efficiency import screw_geometry, screw_jack as _screw_jack
from mech._validate import (
    finite_array, finite_result, integer, nonnegative_number, option, positive_length, real_number, real_tuple,
)
from mech.planar.forces._friction import _nonnegative, _out, _positive, collar_friction_radius

__all__ = ["ScrewJack", "ScrewResult", "lead_angle", "thread_friction_angle", "screw_efficiency"]


def lead_angle(pitch, d2, starts=1):
    """Lead (helix) angle at the mean diameter, tan(lambda) = z p / (pi d2) (F47).

    Parameters
    ----------
    pitch : array_like
        Thread pitch p, > 0.
    d2 : array_like
        Mean (pitch) **diameter**, > 0 (the textbook's d = (r_in + r_out)/2 is a radius:
        use d2 = (d_in + d_out)/2).
    starts : int
        Number of starts z >= 1; the lead is z p.

    Returns
    -------
    lam : float or ndarray
        Lead angle, radians.

    Raises
    ------
    ValueError
        If `pitch` or `d2` is not > 0 or `starts` is not a positive integer.

    Notes
    -----
    :ref:`deriv-efficiency`.

    Examples
    --------
    >>> from mech.planar.forces._screw import lead_angle
    >>> round(float(np.degrees(lead_angle(4.0, 22.0))), 4)
    3.3123
    """
    starts = integer("starts", starts, minimum=1, maximum=10**6)
    p, d = _positive("pitch", pitch), _positive("d2", d2)
    with np.errstate(over="ignore"):        # a lead beyond the float range gives pi/2
        return _out(screw_geometry(starts * p, d, 0.0, 0.0)[0])


def thread_friction_angle(mu, flank_angle=0.0):
    """Friction angle of a thread, phi_v = atan(mu / cos(beta)).

    Parameters
    ----------
    mu : array_like
        Coefficient of friction, >= 0.
    flank_angle : array_like
        Flank angle beta between the flank and the plane normal to the axis, in
        [0, pi/2): 0 for a square thread, 30 deg for a metric V thread, 15 deg for a
        trapezoidal (ACME-like) thread.

    Returns
    -------
    phi_v : float or ndarray
        Radians.

    Raises
    ------
    ValueError
        If `mu` < 0 or `flank_angle` is outside [0, pi/2).

    Notes
    -----
    Like a V-groove of half angle 90 deg - beta (:ref:`deriv-efficiency`), neglecting the
    lead angle's tilt of the flank normal (the usual approximation).

    Examples
    --------
    >>> from mech.planar.forces._screw import thread_friction_angle
    >>> round(float(np.degrees(thread_friction_angle(0.1, np.radians(30)))), 4)
    6.5868
    """
    mu, beta = _nonnegative("mu", mu), _nonnegative("flank_angle", flank_angle)
    if np.any(beta >= np.pi / 2):
        raise ValueError(f"Expected `flank_angle` < pi/2, got {float(beta.max())!r}")
    return _out(screw_geometry(1.0, 1.0, mu, beta)[1])


@dataclass(frozen=True)
class ScrewResult:
    """Torques and efficiencies of a screw (jack) under the axial load Q.

    ``raise_torque``: torque to lift at uniform speed. ``hold_torque``: torque the load
    exerts on the screw while it descends at uniform speed (<= 0: the screw holds the load
    by itself, and its magnitude is the torque needed to lower it). ``efficiency``,
    ``reverse_efficiency``: ideal over actual torque raising; actual over ideal lowering.
    ``lock_angle``: the largest self-locking lead angle. ``self_locking``: bool.
    """

    raise_torque: object
    hold_torque: object
    efficiency: object
    reverse_efficiency: object
    lock_angle: object
    self_locking: object


def screw_efficiency(Q, d2, lam, phi_v, mu_c=0.0, r_c=0.0):
    """Screw with collar friction: torques, efficiencies, self-locking (F48 corrected).

    M_raise = Q (d2/2 tan(lambda + phi_v) + mu_c r_c), M_hold = Q (d2/2 tan(lambda - phi_v)
    - mu_c r_c), eta = tan(lambda) / (tan(lambda + phi_v) + 2 mu_c r_c / d2), and the
    screw self-locks iff lambda <= phi_v + atan(2 mu_c r_c / d2) (lambda <= phi_v for the
    thread alone; the textbook's lambda <= 2 phi is wrong).

    Parameters
    ----------
    Q : array_like
        Axial load, > 0.
    d2 : array_like
        Mean diameter of the thread, > 0.
    lam : array_like
        Lead angle, radians, in (0, pi/2) (:func:`lead_angle`).
    phi_v : array_like
        Thread friction angle, radians, >= 0 (:func:`thread_friction_angle`).
    mu_c, r_c : array_like
        Collar coefficient and friction radius (:func:`collar_friction_radius`); 0 for no
        collar friction.

    Returns
    -------
    ScrewResult

    Raises
    ------
    ValueError
        If a length or load is not > 0, or an angle is out of range.

    Notes
    -----
    :ref:`deriv-efficiency`; the reverse efficiency crosses zero exactly at `lock_angle`.

    Examples
    --------
    >>> from mech.planar.forces._screw import screw_efficiency
    >>> s = screw_efficiency(1.0, 22.0, np.arctan(4 / (22 * np.pi)), np.arctan(0.1))
    >>> round(float(s.efficiency), 4), bool(s.self_locking)
    (0.3644, True)
    """
    Q, d2 = _positive("Q", Q), _positive("d2", d2)
    lam = _positive("lam", lam)
    if np.any(lam >= np.pi / 2):
        raise ValueError(f"Expected `lam` < pi/2, got {float(lam.max())!r}")
    phi_v = _nonnegative("phi_v", phi_v)
    mu_c, r_c = _nonnegative("mu_c", mu_c), _nonnegative("r_c", r_c)
    # a collar term 2 mu_c r_c / d2 beyond the float range is infinite: eta = 0, locked
    with np.errstate(over="ignore", invalid="ignore"):
        up, hold, eta, eta_rev, lock = _screw_jack(Q, d2, lam, phi_v, mu_c, r_c)
    for value, what in ((up, "the raising torque"), (hold, "the holding torque"), (eta, "the efficiency"),
                        (eta_rev, "the reverse efficiency")):
        finite_result(value, what, Q=Q, d2=d2, lam=lam, phi_v=phi_v, mu_c=mu_c, r_c=r_c)
    return ScrewResult(_out(up), _out(hold), _out(eta), _out(eta_rev), _out(lock), _out(np.asarray(hold) <= 0))


@dataclass(frozen=True)
class ScrewJack:
    """A screw jack: thread plus collar (Fig. 2-69, exercise 2-24).

    Parameters
    ----------
    d2 : float
        Mean thread diameter, > 0.
    pitch : float
        Pitch, > 0.
    mu : float
        Thread friction coefficient, >= 0.
    starts : int
        Number of starts (1 unless stated).
    flank_angle : float
        0 for a square thread (radians).
    collar : tuple (D, d0) or None
        Outer and inner **diameter** of the collar face; None for no collar friction.
    mu_collar : float or None
        Collar coefficient (default: `mu`).
    collar_condition : {"new", "run-in"}
        Pressure law on the collar.

    Notes
    -----
    :ref:`deriv-efficiency`. Examples: exercise 2-24 on :ref:`book-forces-exercises`.

    Examples
    --------
    >>> from mech.planar.forces._screw import ScrewJack
    >>> jack = ScrewJack(22.0, 4.0, 0.1, collar=(50.0, 42.0), collar_condition="run-in")
    >>> r = jack.solve(1.0)
    >>> round(float(r.efficiency), 4), round(30000.0 / float(r.raise_torque), 1)
    (0.1573, 7413.4)
    """

    d2: float
    pitch: float
    mu: float
    starts: int = 1
    flank_angle: float = 0.0
    collar: tuple = None
    mu_collar: float = None
    collar_condition: str = "new"

    def __post_init__(self):
        for name in ("d2", "pitch"):
            object.__setattr__(self, name, positive_length(name, getattr(self, name)))
        object.__setattr__(self, "mu", nonnegative_number("mu", self.mu))
        object.__setattr__(self, "starts", integer("starts", self.starts, minimum=1, maximum=10**6))
        object.__setattr__(self, "flank_angle", real_number("flank_angle", self.flank_angle))
        if self.collar is not None:
            outer, inner = real_tuple("collar", self.collar, 2)
            if not outer > inner >= 0.0:
                raise ValueError(f"Expected `collar` = (D, d0) with D > d0 >= 0, got {self.collar!r}")
            object.__setattr__(self, "collar", (outer, inner))
        if self.mu_collar is not None:
            object.__setattr__(self, "mu_collar", nonnegative_number("mu_collar", self.mu_collar))
        option("collar_condition", self.collar_condition, ("new", "run-in"))

    @property
    def lead_angle(self):
        """Lead angle at the mean diameter, radians."""
        return lead_angle(self.pitch, self.d2, self.starts)

    @property
    def friction_angle(self):
        """Thread friction angle phi_v, radians."""
        return thread_friction_angle(self.mu, self.flank_angle)

    @property
    def collar_radius(self):
        """Friction radius of the collar (0 without a collar)."""
        if self.collar is None:
            return 0.0
        D, d0 = self.collar
        return float(collar_friction_radius(D / 2, d0 / 2, self.collar_condition))

    def solve(self, Q=1.0):
        """Torques and efficiencies under the load Q (see :func:`screw_efficiency`)."""
        mu_c = self.mu if self.mu_collar is None else self.mu_collar
        mu_c = 0.0 if self.collar is None else float(finite_array("mu_collar", mu_c))
        return screw_efficiency(Q, self.d2, self.lead_angle, self.friction_angle, mu_c, self.collar_radius)
