"""Mechanical efficiency and self-locking (eqs. 2-21 to 2-29, F15, F32).

Efficiency in work, power, force and moment form; machines in series, in parallel and
mixed; the wedge press of example 2-11; the spreading wedge and the push rod of exercises
2-19 and 2-21; the eccentric clamp of Fig. 2-65. Formulas from the derivation pages
``deriv-efficiency`` and ``deriv-friction``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from mech._generated.efficiency import push_rod as _push_rod
from mech._generated.efficiency import spreading_wedge, wedge_press as _wedge_press
from mech._generated.friction import eccentric_clamp
from mech._geometry import plane_cross
from mech._validate import bool_flag, common_shape, finite_array, finite_result
from mech.planar.forces._friction import _nonnegative, _out, _positive, total_reaction

__all__ = [
    "WedgePress",
    "WedgePressForces",
    "efficiency",
    "efficiency_from_drive",
    "efficiency_from_resistance",
    "series_efficiency",
    "parallel_efficiency",
    "is_self_locking",
    "wedge_press",
    "wedge_press_forces",
    "spreading_wedge_force",
    "push_rod",
    "eccentric_clamp_max_angle",
    "eccentric_clamp_locks",
]


def efficiency(useful, driving):
    """Efficiency as useful over input work or power, eta = A_r / A_d = N_r / N_d (F24, 2-21).

    Parameters
    ----------
    useful : array_like
        Useful work (or average power) against the working resistance.
    driving : array_like
        Input work (or power), > 0.

    Returns
    -------
    eta : float or ndarray
        <= 0 means the machine cannot do the useful work: self-locking (F32).

    Raises
    ------
    ValueError
        If `driving` is not > 0.

    Notes
    -----
    :ref:`deriv-efficiency`. With the lost work A_f, eta = 1 - A_f / A_d.

    Examples
    --------
    >>> from mech.planar.forces._efficiency import efficiency
    >>> efficiency(80.0, 100.0)
    0.8
    """
    useful, driving = finite_array("useful", useful), _positive("driving", driving)
    with np.errstate(over="ignore"):
        eta = useful / driving
    return _out(finite_result(eta, "the efficiency", useful=useful, driving=driving))


def efficiency_from_drive(ideal, actual):
    """Efficiency as ideal over actual driving force (or moment), eta = P0 / P (2-24, F31).

    Parameters
    ----------
    ideal : array_like
        Driving force or moment needed without friction for the same resistance.
    actual : array_like
        The one needed with friction, > 0.

    Returns
    -------
    eta : float or ndarray

    Raises
    ------
    ValueError
        If `actual` is not > 0.

    Notes
    -----
    :ref:`deriv-efficiency`.

    Examples
    --------
    >>> from mech.planar.forces._efficiency import efficiency_from_drive
    >>> efficiency_from_drive(30.0, 40.0)
    0.75
    """
    ideal, actual = finite_array("ideal", ideal), _positive("actual", actual)
    with np.errstate(over="ignore"):
        eta = ideal / actual
    return _out(finite_result(eta, "the efficiency", ideal=ideal, actual=actual))


def efficiency_from_resistance(actual, ideal):
    """Efficiency as actual over ideal resistance, eta = Q / Q0 (2-24, F31).

    Parameters
    ----------
    actual : array_like
        Resistance (force or moment) overcome with friction by a given drive.
    ideal : array_like
        Resistance the same drive overcomes without friction, > 0.

    Returns
    -------
    eta : float or ndarray

    Raises
    ------
    ValueError
        If `ideal` is not > 0.

    Notes
    -----
    :ref:`deriv-efficiency`.

    Examples
    --------
    >>> from mech.planar.forces._efficiency import efficiency_from_resistance
    >>> efficiency_from_resistance(45.0, 50.0)
    0.9
    """
    actual, ideal = finite_array("actual", actual), _positive("ideal", ideal)
    with np.errstate(over="ignore"):
        eta = actual / ideal
    return _out(finite_result(eta, "the efficiency", actual=actual, ideal=ideal))


def series_efficiency(etas):
    """Efficiency of machines in series (串联): the product of their efficiencies.

    Parameters
    ----------
    etas : sequence of float
        Efficiencies of the machines, each in [0, 1].

    Returns
    -------
    eta : float

    Raises
    ------
    ValueError
        If the sequence is empty or an efficiency is outside [0, 1].

    Notes
    -----
    Each machine's output is the next one's input (:ref:`deriv-efficiency`). A mixed
    arrangement nests :func:`series_efficiency` and :func:`parallel_efficiency`.

    Examples
    --------
    >>> from mech.planar.forces._efficiency import series_efficiency
    >>> round(series_efficiency([0.95, 0.9, 0.8]), 4)
    0.684
    """
    e = _unit_interval("etas", etas)
    return float(np.prod(e))


def parallel_efficiency(etas, powers):
    """Efficiency of machines in parallel (并联): mean weighted by input power.

    Parameters
    ----------
    etas : sequence of float
        Efficiencies of the branches, each in [0, 1].
    powers : sequence of float
        Input power of each branch, >= 0, not all zero.

    Returns
    -------
    eta : float
        sum(eta_i N_i) / sum(N_i), between the worst and the best branch.

    Raises
    ------
    ValueError
        If the lengths differ, a power is negative or all are zero.

    Notes
    -----
    :ref:`deriv-efficiency`.

    Examples
    --------
    >>> from mech.planar.forces._efficiency import parallel_efficiency
    >>> round(parallel_efficiency([0.9, 0.6], [3.0, 1.0]), 4)
    0.825
    """
    e = _unit_interval("etas", etas)
    n = _nonnegative("powers", powers).ravel()
    if n.shape != e.shape:
        raise ValueError(f"Expected as many `powers` as `etas`, got lengths {n.size} and {e.size}")
    if not np.any(n > 0):
        raise ValueError("Expected some `powers` > 0, got all zero")
    return float(np.dot(e, n) / n.sum())


def _unit_interval(name, values):
    e = finite_array(name, values).ravel()
    if e.size == 0:
        raise ValueError(f"Expected at least one value in `{name}`, got none")
    bad = (e < 0) | (e > 1)
    if np.any(bad):
        raise ValueError(f"Expected every value of `{name}` in [0, 1], got {float(e[bad][0])!r}")
    return e


def is_self_locking(eta):
    """Self-locking test eta <= 0 (F32).

    Parameters
    ----------
    eta : array_like
        Efficiency in the direction of motion in question.

    Returns
    -------
    locked : bool or ndarray of bool

    Notes
    -----
    eta = 0: the input work just covers the losses (A_d = A_f): a moving machine idles, one
    at rest cannot start. eta < 0: it cannot move that way at all (:ref:`deriv-efficiency`).

    Examples
    --------
    >>> from mech.planar.forces._efficiency import is_self_locking
    >>> is_self_locking([-0.1, 0.0, 0.4]).tolist()
    [True, True, False]
    """
    return _out(finite_array("eta", eta) <= 0)


@dataclass(frozen=True)
class WedgePress:
    """Wedge press of example 2-11 at wedge angle lam and friction angle phi.

    ``forward_ratio`` P/Q pressing (2-25); ``reverse_ratio`` P/Q holding the release;
    ``efficiency`` (2-26) and ``reverse_efficiency`` (2-28); ``forward_moves`` (2-27:
    lam + 2 phi < 90 deg) and ``reverse_locks`` (2-29: lam <= 2 phi); ``lock_angle`` = 2 phi.
    """

    forward_ratio: object
    reverse_ratio: object
    efficiency: object
    reverse_efficiency: object
    forward_moves: object
    reverse_locks: object
    lock_angle: object


def wedge_press(lam, phi):
    """Wedge press (example 2-11): both strokes, efficiencies, self-locking (2-25 to 2-29).

    Parameters
    ----------
    lam : array_like
        Wedge angle of the horizontally driven wedge, radians, in (0, pi/2).
    phi : array_like
        Friction angle of all three sliding faces, radians, in [0, pi/4).

    Returns
    -------
    WedgePress

    Raises
    ------
    ValueError
        If an angle is out of range.

    Notes
    -----
    Derived from the free bodies of both wedges in :ref:`deriv-efficiency`: P = Q tan(lam
    + 2 phi) forward and P = Q tan(lam - 2 phi) on the release. The reverse efficiency
    crosses zero at lam = 2 phi. Where lam + 2 phi >= 90 deg the forward push is infinite or
    negative: ``forward_moves`` is False there.

    Examples
    --------
    >>> from mech.planar.forces._efficiency import wedge_press
    >>> w = wedge_press(np.radians(10), np.arctan(0.1))
    >>> round(float(w.efficiency), 6), round(float(w.reverse_efficiency), 6), bool(w.reverse_locks)
    (0.449444, -0.140701, True)
    """
    lam, phi = _positive("lam", lam), _nonnegative("phi", phi)
    if np.any(lam >= np.pi / 2):
        raise ValueError(f"Expected `lam` < pi/2, got {float(lam.max())!r}")
    if np.any(phi >= np.pi / 4):
        raise ValueError(f"Expected `phi` < pi/4, got {float(phi.max())!r}")
    moves = lam + 2 * phi < np.pi / 2
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        fwd, rev, eta, eta_rev = _wedge_press(lam, phi)
    finite_result(eta_rev, "the reverse efficiency", lam=lam, phi=phi)
    fwd = np.where(moves, fwd, np.inf)
    eta = np.where(moves, eta, 0.0)
    return WedgePress(_out(fwd), _out(rev), _out(eta), _out(eta_rev), _out(moves),
                      _out(lam <= 2 * phi), _out(2 * phi + 0 * lam))


@dataclass(frozen=True)
class WedgePressForces:
    """Forces on the two wedges of example 2-11 (Fig. 2-68), complex ``x + 1j*y``, in N.

    Wedge 2 slides on the horizontal base 1 under the push ``P``; wedge 3 slides in the
    vertical guide of the frame 1 (the guide on its +x side) and carries the load ``Q``
    (downwards). ``R12``: base on wedge 2; ``R32``: wedge 3 on wedge 2; ``R23 = -R32``;
    ``R13``: guide on wedge 3. Each wedge's forces add up to zero (the closed polygons of
    Fig. 2-68b): ``P + R12 + R32 = 0`` and ``Q + R23 + R13 = 0``.
    """

    P: object
    Q: object
    R12: object
    R32: object
    R23: object
    R13: object


def wedge_press_forces(Q, lam, phi, *, release=False):
    """Forces on the wedges of the wedge press (example 2-11, Fig. 2-68) under a load Q.

    Each total reaction is turned from its face's normal by the friction angle against the
    relative sliding (`total_reaction`); then the two equilibria, of wedge 3 (Q known) and
    of wedge 2, are solved for the magnitudes. The push comes out as ``P = Q tan(lam +
    2 phi)`` pressing and ``Q tan(lam - 2 phi)`` on the release (2-25), as `wedge_press`.

    Parameters
    ----------
    Q : array_like
        Load on the vertical wedge 3, N, > 0.
    lam : array_like
        Wedge angle of the horizontal wedge 2, radians, in (0, pi/2).
    phi : array_like
        Friction angle of the three sliding faces, radians, in [0, pi/4).
    release : bool, optional
        False (default): pressing, wedge 2 moves towards +x and lifts wedge 3. True: the
        load drives back, every friction force reverses, and ``P`` is the force that holds
        wedge 2 (negative: a pull is needed, the press locks).

    Returns
    -------
    WedgePressForces

    Raises
    ------
    ValueError
        If an argument is out of range, if pressing with ``lam + 2 phi >= pi/2`` (no
        push can move the press, 2-27), or on the release with ``lam <= phi`` (wedge 3 then
        leans on the far face of its guide, outside this model and outside (2-25)).

    Notes
    -----
    The face between the wedges falls towards +x at ``lam`` below the horizontal, so its
    normal into wedge 3 is ``sin(lam) + 1j*cos(lam)``; pressing moves wedge 2 at 1 and
    wedge 3 at ``1j*tan(lam)``. Derivation of the ratios: :ref:`deriv-efficiency`.

    Examples
    --------
    >>> from mech.planar.forces._efficiency import wedge_press_forces
    >>> f = wedge_press_forces(1000.0, np.radians(10), np.arctan(0.1))
    >>> round(f.P.real, 3), abs(f.P + f.R12 + f.R32) < 1e-9
    (392.322, True)
    """
    Q = _positive("Q", Q)
    lam, phi = _positive("lam", lam), _nonnegative("phi", phi)
    release = bool_flag("release", release)
    if np.any(lam >= np.pi / 2):
        raise ValueError(f"Expected `lam` < pi/2, got {float(lam.max())!r}")
    if np.any(phi >= np.pi / 4):
        raise ValueError(f"Expected `phi` < pi/4, got {float(phi.max())!r}")
    if not release and np.any(lam + 2 * phi >= np.pi / 2):
        bad = (lam + 2 * phi >= np.pi / 2)
        raise ValueError("Expected `lam` + 2 `phi` < pi/2 for pressing (2-27), got `lam` = "
                         f"{float(np.broadcast_to(lam, bad.shape)[bad].ravel()[0])!r}, `phi` = "
                         f"{float(np.broadcast_to(phi, bad.shape)[bad].ravel()[0])!r}")
    if release and np.any(lam <= phi):
        bad = lam <= phi
        raise ValueError("Expected `lam` > `phi` on the release (else wedge 3 bears on the other "
                         "face of its guide), got `lam` = "
                         f"{float(np.broadcast_to(lam, bad.shape)[bad].ravel()[0])!r}, `phi` = "
                         f"{float(np.broadcast_to(phi, bad.shape)[bad].ravel()[0])!r}")
    Q, lam, phi = np.broadcast_arrays(Q, lam, phi)
    mu = np.tan(phi)
    sense = -1.0 if release else 1.0
    v2 = sense * np.ones_like(lam)                           # wedge 2 along x
    v3 = sense * 1j * np.tan(lam)                            # wedge 3 along y
    n23 = np.sin(lam) + 1j * np.cos(lam)                     # normal of the face, into 3
    u12 = total_reaction(1j + 0 * lam, v2, mu)               # base on wedge 2
    u23 = total_reaction(n23, v3 - v2, mu)                   # wedge 2 on wedge 3
    u13 = total_reaction(-1 + 0 * lam, v3, mu)               # guide on wedge 3
    # per unit load: wedge 3, a u23 + b u13 = 1j; wedge 2, p + c u12 = a u23 (R32 = -a u23)
    a = plane_cross(1j, u13) / plane_cross(u23, u13)
    b = plane_cross(u23, 1j) / plane_cross(u23, u13)
    R23, R13 = a * u23, b * u13
    R12 = np.imag(R23) / np.imag(u12) * u12
    P = np.real(R23 - R12) + 0j
    with np.errstate(over="ignore", invalid="ignore"):
        forces = [Q * f for f in (P, -1j + 0 * P, R12, -R23, R23, R13)]
    for f in forces:
        finite_result(f, "every force", Q=Q, lam=lam, phi=phi)
    return WedgePressForces(*(_out(f) for f in forces))


def spreading_wedge_force(Q, theta, phi, base_friction=True):
    """Push on a symmetric wedge spreading two blocks, each against Q (exercise 2-19).

    With friction on the faces and under the blocks: P = 2 Q sin(theta + phi) cos(phi) /
    cos(theta + 2 phi); on the faces only: P = 2 Q tan(theta + phi); ideal 2 Q tan(theta).

    Parameters
    ----------
    Q : array_like
        Resistance on each block, > 0.
    theta : array_like
        Angle of each wedge face to the push, radians, in (0, pi/2).
    phi : array_like
        Friction angle of every sliding surface, radians, >= 0.
    base_friction : bool
        Whether the blocks slide on the frame with friction.

    Returns
    -------
    P : float or ndarray
        inf where the wedge jams (theta + 2 phi >= 90 deg, or theta + phi with no base).

    Raises
    ------
    ValueError
        If `Q` <= 0 or an angle is out of range.

    Notes
    -----
    :ref:`deriv-efficiency`. The efficiency is the ideal push over this one.

    Examples
    --------
    >>> from mech.planar.forces._efficiency import spreading_wedge_force
    >>> round(float(spreading_wedge_force(1000.0, np.radians(15), np.radians(12))), 2)
    1142.82
    """
    Q, theta, phi = _positive("Q", Q), _positive("theta", theta), _nonnegative("phi", phi)
    base_friction = bool_flag("base_friction", base_friction)
    if np.any(theta >= np.pi / 2):
        raise ValueError(f"Expected `theta` < pi/2, got {float(theta.max())!r}")
    with np.errstate(divide="ignore", invalid="ignore"):
        base, faces, _ = spreading_wedge(Q, theta, phi)
    ok = theta + (2 if base_friction else 1) * phi < np.pi / 2
    return _out(np.where(ok, base if base_friction else faces, np.inf))


def push_rod(mu, offset, length):
    """Push rod in a guide (exercise 2-21): efficiency and the shortest guide that works.

    A push along the rod at `offset` from its axis tilts it against the two ends of the
    guide: eta = 1 - 2 mu e / L, and the rod jams (self-locks) for L <= 2 mu e.

    Parameters
    ----------
    mu : array_like
        Coefficient of friction rod-guide, >= 0.
    offset : array_like
        Distance e of the push's line from the rod axis, >= 0.
    length : array_like
        Guide length L, > 0.

    Returns
    -------
    eta : float or ndarray
    L_min : float or ndarray
        2 mu e.

    Raises
    ------
    ValueError
        If a value is out of range.

    Notes
    -----
    :ref:`deriv-efficiency`; the rod's width cancels.

    Examples
    --------
    >>> from mech.planar.forces._efficiency import push_rod
    >>> eta, L_min = push_rod(0.2, 100.0, 80.0)
    >>> round(float(eta), 6), round(float(L_min), 6)
    (0.5, 40.0)
    """
    mu, e, L = _nonnegative("mu", mu), _nonnegative("offset", offset), _positive("length", length)
    with np.errstate(over="ignore", invalid="ignore"):
        eta, L_min = _push_rod(mu, e, L)
    finite_result(eta, "the efficiency", mu=mu, offset=e, length=L)
    return _out(np.asarray(eta)), _out(np.asarray(L_min + 0 * L))


def eccentric_clamp_max_angle(e, r_disc, rho_pin, phi):
    """Largest clamp angle at which the eccentric clamp holds by itself (Fig. 2-65, F15).

    alpha_max = phi + asin((r sin(phi) + rho) / e), r the **disc** radius and rho = mu0 r_pin
    the friction circle of the **pivot pin** (the textbook writes rho = mu0 r with the disc's
    r: corrected).

    Parameters
    ----------
    e : array_like
        Distance from the pivot centre to the disc centre, > 0.
    r_disc : array_like
        Disc radius, > 0.
    rho_pin : array_like
        Friction-circle radius of the pivot, >= 0 (:func:`~mech.planar.forces.friction_circle`).
    phi : array_like
        Friction angle disc-workpiece, radians, in [0, pi/2).

    Returns
    -------
    alpha_max : float or ndarray
        Radians; phi + pi/2 when r sin(phi) + rho >= e (it then holds at every angle).

    Raises
    ------
    ValueError
        If a length is out of range or `phi` is outside [0, pi/2).

    Notes
    -----
    Moment balance about the pivot in :ref:`deriv-friction`.

    Examples
    --------
    >>> from mech.planar.forces._efficiency import eccentric_clamp_max_angle
    >>> round(float(np.degrees(eccentric_clamp_max_angle(10.0, 40.0, 1.0, np.arctan(0.15)))), 3)
    52.428
    """
    e, r, rho, phi = _clamp_args(e, r_disc, rho_pin, phi)
    with np.errstate(over="ignore"):             # x beyond the float range is capped at 1
        x = (r * np.sin(phi) + rho) / e
    capped = np.minimum(x, 1.0)
    # rho + (capped - x) e without forming x e: the pin radius that makes x = capped
    _, alpha_max = eccentric_clamp(0.0, e, r, np.where(x <= 1.0, rho, e - r * np.sin(phi)), phi)
    # capped (r sin(phi) + rho >= e): asin(1) directly, as e - r sin(phi) loses a tiny e
    alpha_max = np.where(x >= 1.0, phi + np.pi / 2, alpha_max)
    return _out(alpha_max)


def eccentric_clamp_locks(alpha, e, r_disc, rho_pin, phi):
    """Whether the eccentric clamp holds the workpiece after release (F15).

    Locked iff e sin(alpha - phi) - r sin(phi) <= rho.

    Parameters
    ----------
    alpha : array_like
        Clamp angle, radians: at the disc centre, between the line to the pivot and the
        contact normal (0: pivot on the normal).
    e, r_disc, rho_pin, phi
        As :func:`eccentric_clamp_max_angle`.

    Returns
    -------
    locked : bool or ndarray of bool

    Raises
    ------
    ValueError
        As :func:`eccentric_clamp_max_angle`.

    Notes
    -----
    :ref:`deriv-friction`.

    Examples
    --------
    >>> from mech.planar.forces._efficiency import eccentric_clamp_locks
    >>> eccentric_clamp_locks(np.radians([40, 60]), 10.0, 40.0, 1.0, np.arctan(0.15)).tolist()
    [True, False]
    """
    e, r, rho, phi = _clamp_args(e, r_disc, rho_pin, phi)
    alpha = finite_array("alpha", alpha)
    common_shape(alpha=alpha, e=e, r_disc=r, rho_pin=rho, phi=phi)
    with np.errstate(invalid="ignore", over="ignore"):   # the largest angle (unused) NaN when x > 1
        margin, _ = eccentric_clamp(alpha, e, r, rho, phi)
    return _out(np.asarray(margin) >= 0)


def _clamp_args(e, r_disc, rho_pin, phi):
    phi = _nonnegative("phi", phi)
    if np.any(phi >= np.pi / 2):             # a friction angle atan(mu) is below pi/2
        raise ValueError(f"Expected `phi` in [0, pi/2), got {float(phi[phi >= np.pi / 2].ravel()[0])!r}")
    return (_positive("e", e), _positive("r_disc", r_disc), _nonnegative("rho_pin", rho_pin), phi)
