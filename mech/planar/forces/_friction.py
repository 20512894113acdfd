"""Friction in lower pairs: sliding, V-groove, curved contact, journals, thrust faces.

Textbook chapter 2, §3.1 (F1 to F22, eqs. 2-19 and 2-20). Formulas come from the
derivation page ``deriv-friction`` through ``mech._generated.friction``.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from mech._generated.friction import (
    equivalent_mu,
    incline_push,
    mill_max_thickness,
    thrust_moment,
    two_force_tilt,
)
from mech._validate import (bool_flag, common_shape, finite_array, finite_result, nonnegative_number, option, planar_points,
                            positive_length)

__all__ = [
    "FRICTION_TABLE_2_2",
    "InclineForces",
    "friction_angle",
    "total_reaction",
    "slider_state",
    "incline_forces",
    "vgroove_mu",
    "curved_contact_mu",
    "journal_mu",
    "friction_circle",
    "journal_state",
    "two_force_tilt_angle",
    "thrust_friction_moment",
    "collar_friction_radius",
    "rolling_mill_max_thickness",
]

#: Table 2-2 of the textbook (§2.3, part I): coefficients of friction of flat
#: contacts by material pair, as printed. Each entry is ``(static dry, static lubricated,
#: kinetic dry, kinetic lubricated)``; each value a ``(low, high)`` range (equal ends for a
#: single number) or ``None`` where the table leaves the cell empty.
FRICTION_TABLE_2_2 = {
    "steel-steel": ((0.15, 0.15), (0.10, 0.12), (0.10, 0.10), (0.05, 0.10)),
    "steel-cast iron": ((0.2, 0.3), None, (0.16, 0.18), (0.05, 0.15)),
    "steel-bronze": (None, (0.10, 0.15), (0.15, 0.18), (0.07, 0.07)),
    "cast iron-cast iron": (None, (0.15, 0.16), (0.15, 0.15), (0.07, 0.12)),
    "cast iron-bronze": ((0.28, 0.28), (0.16, 0.16), (0.15, 0.21), (0.07, 0.15)),
    "bronze-bronze": (None, None, (0.15, 0.20), (0.04, 0.10)),
    "leather-cast iron or steel": (None, None, (0.30, 0.50), (0.12, 0.15)),
    "rubber-cast iron": (None, None, (0.8, 0.8), (0.5, 0.5)),
}

_STATES = np.array(["decelerates or stays at rest", "keeps its state", "accelerates"])


def _nonnegative(name, value):
    arr = finite_array(name, value)
    if np.any(arr < 0):
        raise ValueError(f"Expected `{name}` >= 0, got {float(arr[arr < 0].ravel()[0])!r}")
    return arr


def _positive(name, value):
    arr = finite_array(name, value)
    if np.any(arr <= 0):
        raise ValueError(f"Expected `{name}` > 0, got {float(arr[arr <= 0].ravel()[0])!r}")
    return arr


def _out(x):
    """A Python scalar for 0-d results, the array otherwise."""
    return np.asarray(x).item() if np.ndim(x) == 0 else x


def friction_angle(mu):
    """Friction angle phi = atan(mu) (F2).

    Parameters
    ----------
    mu : array_like
        Coefficient of friction, >= 0.

    Returns
    -------
    phi : float or ndarray
        Friction angle (摩擦角), radians, in [0, pi/2).

    Raises
    ------
    ValueError
        If `mu` is negative or not finite.

    Notes
    -----
    The total reaction (总反力) of a sliding pair leans by phi from the normal, against the
    relative motion (:ref:`deriv-friction`).

    Examples
    --------
    >>> from mech.planar.forces._friction import friction_angle
    >>> round(float(np.degrees(friction_angle(0.1))), 5)
    5.71059
    """
    return _out(np.arctan(_nonnegative("mu", mu)))


def total_reaction(normal, velocity, mu, normal_force=None):
    """Total reaction on a sliding body: its direction, or the force itself (F2).

    Parameters
    ----------
    normal : array_like, complex
        Normal of the contact pointing into the body that receives the reaction.
    velocity : array_like, complex
        Velocity of that body relative to the other one.
    mu : array_like
        Coefficient of friction, >= 0.
    normal_force : array_like, optional
        Magnitude N >= 0 of the normal force. If given, the reaction itself is returned,
        N n + mu N (against the sliding), of magnitude N sqrt(1 + mu^2) = N / cos(phi).

    Returns
    -------
    reaction : complex or ndarray
        Unit vector of the total reaction (or the force, with `normal_force`): the normal
        turned by atan(mu) against the tangential part of `velocity`. NaN where the body
        does not slide (the reaction can then lie anywhere inside the friction cone).

    Raises
    ------
    ValueError
        If `normal` is zero or `mu` is negative.

    Notes
    -----
    The reaction makes 90 deg + phi with the relative velocity, so it always resists
    (:ref:`deriv-friction`).

    Examples
    --------
    >>> from mech.planar.forces._friction import total_reaction
    >>> d = total_reaction(1j, 1.0, 0.1)       # block sliding right on a floor
    >>> round(float(np.degrees(np.angle(d))), 4)
    95.7106
    >>> total_reaction(1j, 1.0, 0.1, normal_force=50.0)
    (-5+50j)
    """
    n = planar_points("normal", normal)
    velocity = planar_points("velocity", velocity)
    if np.any(n == 0):
        raise ValueError("Expected a nonzero `normal`, got 0j")
    mu = _nonnegative("mu", mu)
    n = n / np.abs(n)
    t = -1j * n                                                  # the tangent, n turned -90 deg
    vt = np.real(velocity * np.conj(t))
    sense = np.where(vt > 0, 1.0, np.where(vt < 0, -1.0, np.nan))
    if normal_force is None:
        return _out((n - sense * mu * t) / np.hypot(1.0, mu))
    return _out(_nonnegative("normal_force", normal_force) * (n - sense * mu * t))


def slider_state(alpha, phi):
    """Motion of a slider under a push at alpha from the guide's normal (F3).

    Parameters
    ----------
    alpha : array_like
        Angle between the push and the normal of the guide, radians, in [0, pi/2].
    phi : array_like
        Friction angle, radians, >= 0.

    Returns
    -------
    state : str or ndarray of str
        "accelerates" (alpha > phi), "keeps its state" (alpha == phi: uniform motion or
        rest), "decelerates or stays at rest" (alpha < phi: self-locking whatever the push).

    Raises
    ------
    ValueError
        If an angle is negative or not finite.

    Notes
    -----
    The push lies inside the friction cone exactly when alpha < phi (:ref:`deriv-friction`).

    Examples
    --------
    >>> from mech.planar.forces._friction import slider_state
    >>> slider_state([0.05, 0.2], 0.1).tolist()
    ['decelerates or stays at rest', 'accelerates']
    """
    alpha, phi = _nonnegative("alpha", alpha), _nonnegative("phi", phi)
    common_shape(alpha=alpha, phi=phi)
    return _out(_STATES[(np.sign(alpha - phi) + 1).astype(int)])


class InclineForces(NamedTuple):
    """Pushes for uniform motion of a block on an inclined plane."""

    raising: float
    """Push that moves the block up at uniform speed."""
    lowering: float
    """Push that holds a uniform slide down; <= 0 means the block holds itself."""


def incline_forces(Q, incline, mu, push_angle=None):
    """Push on a block on an inclined plane, raising and lowering (F1 to F3).

    P_up = Q sin(lambda + phi) / cos(beta - phi) and P_down = Q sin(lambda - phi) /
    cos(beta + phi), with phi = atan(mu) and beta the push's angle above the plane.

    Parameters
    ----------
    Q : array_like
        Weight of the block, > 0.
    incline : array_like
        Inclination lambda of the plane, radians.
    mu : array_like
        Coefficient of friction, >= 0.
    push_angle : array_like, optional
        Angle beta of the push above the plane's rising direction, radians. Default: a
        horizontal push, beta = -lambda (then P = Q tan(lambda +- phi), the screw's form).

    Returns
    -------
    InclineForces
        ``raising`` and ``lowering`` pushes.

    Raises
    ------
    ValueError
        If `Q` is not > 0 or `mu` is negative.

    Notes
    -----
    Derived by components and by the friction angle in :ref:`deriv-friction`. A raising
    push that comes out negative or infinite means that direction of push cannot move the
    block (it lies beyond the friction cone's edge).

    Examples
    --------
    >>> from mech.planar.forces._friction import incline_forces
    >>> f = incline_forces(100.0, np.radians(30), 0.2)
    >>> round(float(f.raising), 3), round(float(f.lowering), 3)
    (87.883, 33.829)
    """
    Q, lam = _positive("Q", Q), finite_array("incline", incline)
    phi = np.arctan(_nonnegative("mu", mu))
    beta = -lam if push_angle is None else finite_array("push_angle", push_angle)
    up, down = incline_push(Q, lam, beta, phi)
    return InclineForces(_out(up), _out(down))


def vgroove_mu(mu, half_angle):
    """Equivalent coefficient of a V-groove, mu / sin(theta) (F6).

    Parameters
    ----------
    mu : array_like
        Coefficient of flat contact, >= 0.
    half_angle : array_like
        Half theta of the groove's included angle 2 theta, radians, in (0, pi/2].

    Returns
    -------
    mu_v : float or ndarray
        Equivalent coefficient (当量摩擦系数): friction = mu_v times the load.

    Raises
    ------
    ValueError
        If `mu` < 0 or `half_angle` is outside (0, pi/2].

    Notes
    -----
    Two flanks each carry N with vertical part N sin(theta) (:ref:`deriv-friction`).

    Examples
    --------
    >>> from mech.planar.forces._friction import vgroove_mu
    >>> round(float(vgroove_mu(0.1, np.radians(30))), 6)
    0.2
    """
    theta = _positive("half_angle", half_angle)
    if np.any(theta > np.pi / 2):
        raise ValueError(f"Expected `half_angle` <= pi/2, got {float(theta.max())!r}")
    mu = _nonnegative("mu", mu)
    with np.errstate(over="ignore"):
        value = equivalent_mu(mu, theta)[0]
    return _out(finite_result(value, "the equivalent coefficient", mu=mu, half_angle=theta))


def curved_contact_mu(mu, k):
    """Equivalent coefficient of a cylindrical contact, mu0 = k mu (F8).

    Parameters
    ----------
    mu : array_like
        Coefficient of flat contact, >= 0.
    k : array_like
        Contact factor in [1, pi/2]: 1 for line contact, 4/pi for a worn (uniform wear)
        fit, pi/2 for uniform pressure over a half circle.

    Returns
    -------
    mu0 : float or ndarray

    Raises
    ------
    ValueError
        If `k` is outside [1, pi/2] (no pressure law on a half circle gives it).

    Notes
    -----
    k is the integral of the pressure over that of its load-direction part
    (:ref:`deriv-friction`); the text quotes the measured range 1 to 1.57.

    Examples
    --------
    >>> from mech.planar.forces._friction import curved_contact_mu
    >>> round(float(curved_contact_mu(0.1, 1.2)), 6)
    0.12
    """
    k = finite_array("k", k)
    if np.any((k < 1.0) | (k > np.pi / 2)):
        bad = float(k[(k < 1.0) | (k > np.pi / 2)].ravel()[0])
        raise ValueError(f"Expected `k` in [1, pi/2], got {bad!r}")
    return _out(_nonnegative("mu", mu) * k)


def journal_mu(mu, condition="run-in"):
    """Equivalent coefficient of a radial journal (F9).

    Parameters
    ----------
    mu : array_like
        Coefficient of flat contact, >= 0.
    condition : {"run-in", "new", "line"}
        "new": tight, not yet run in, uniform pressure: pi/2 mu (the text's 1.57 mu);
        "run-in": loose and worn in, uniform wear: 4/pi mu (1.27 mu); "line": a loose
        pin on one line of contact: mu.

    Returns
    -------
    mu0 : float or ndarray

    Raises
    ------
    ValueError
        If `mu` < 0 or `condition` is unknown.

    Notes
    -----
    Both factors come from integrating the pressure over the half circle
    (:ref:`deriv-friction`).

    Examples
    --------
    >>> from mech.planar.forces._friction import journal_mu
    >>> round(float(journal_mu(0.1, "new")), 5), round(float(journal_mu(0.1)), 5)
    (0.15708, 0.12732)
    """
    mu = _nonnegative("mu", mu)
    _, new, run_in = equivalent_mu(mu, np.pi / 2)
    table = {"new": new, "run-in": run_in, "line": mu}
    option("condition", condition, tuple(table))
    return _out(np.asarray(table[condition], dtype=float))


def friction_circle(mu0, r):
    """Radius of the friction circle, rho = mu0 r (2-19).

    Parameters
    ----------
    mu0 : array_like
        Equivalent coefficient of the journal (see :func:`journal_mu`), >= 0.
    r : array_like
        Journal (pin) radius, > 0.

    Returns
    -------
    rho : float or ndarray
        The total reaction on the journal is tangent to the circle of this radius.

    Raises
    ------
    ValueError
        If `mu0` < 0 or `r` <= 0.

    Notes
    -----
    :ref:`deriv-friction`. In the eccentric clamp r is the pivot pin's radius, not the
    disc's (errata).

    Examples
    --------
    >>> from mech.planar.forces._friction import friction_circle
    >>> round(float(friction_circle(0.2, 12.5)), 6)
    2.5
    """
    return _out(_nonnegative("mu0", mu0) * _positive("r", r))


def journal_state(h, rho):
    """Motion of a journal whose load line passes at h from its centre (F13).

    Parameters
    ----------
    h : array_like
        Distance of the resultant load's line from the journal centre, >= 0.
    rho : array_like
        Friction-circle radius, >= 0.

    Returns
    -------
    state : str or ndarray of str
        "accelerates" (h > rho), "keeps its state" (h == rho), "decelerates or stays at
        rest" (h < rho: a journal at rest cannot be started, whatever the load).

    Raises
    ------
    ValueError
        If `h` or `rho` is negative.

    Notes
    -----
    The load drives with Q h against the friction moment Q rho (:ref:`deriv-friction`).

    Examples
    --------
    >>> from mech.planar.forces._friction import journal_state
    >>> journal_state([1.0, 2.5, 3.0], 2.5).tolist()
    ['decelerates or stays at rest', 'keeps its state', 'accelerates']
    """
    h, rho = _nonnegative("h", h), _nonnegative("rho", rho)
    common_shape(h=h, rho=rho)
    return _out(_STATES[(np.sign(h - rho) + 1).astype(int)])


def two_force_tilt_angle(length, rho_a, rho_b, cross=True):
    """Tilt from AB of the force line of a two-force member through two friction circles.

    Parameters
    ----------
    length : float
        Pin distance AB, > 0.
    rho_a, rho_b : float
        Friction-circle radii at A and B, >= 0.
    cross : bool
        True for the cross (internal) tangent (the link turns in opposite senses relative
        to its two neighbours), False for the direct tangent (equal senses).

    Returns
    -------
    tilt : float
        asin((rho_a + rho_b)/l) or asin(``|rho_a - rho_b|``/l), radians.

    Raises
    ------
    ValueError
        If a cross tangent is asked for with rho_a + rho_b >= l (the circles overlap and no
        cross tangent exists; for equal circles, rho >= l/2).

    Notes
    -----
    :ref:`deriv-friction`. Which side of AB the line passes follows from the senses of the
    relative rotations; this function gives only the tilt.

    Examples
    --------
    >>> from mech.planar.forces._friction import two_force_tilt_angle
    >>> round(float(np.degrees(two_force_tilt_angle(100.0, 2.5, 2.5))), 4)
    2.866
    """
    l = positive_length("length", length)
    cross = bool_flag("cross", cross)
    ra, rb = (nonnegative_number(n, v) for n, v in (("rho_a", rho_a), ("rho_b", rho_b)))
    if cross and ra + rb >= l:
        raise ValueError(
            f"Expected `rho_a` + `rho_b` < `length` for a cross tangent, got "
            f"rho_a + rho_b = {ra + rb!r} >= length = {l!r}"
        )
    if not cross and abs(ra - rb) >= l:
        raise ValueError(f"Expected |`rho_a` - `rho_b`| < `length`, got {abs(ra - rb)!r} >= {l!r}")
    tilt_cross, tilt_direct = two_force_tilt(l, ra, rb)
    return float(tilt_cross if cross else tilt_direct)


def thrust_friction_moment(Q, mu, r_out, r_in=0.0, *, condition="new", cone_half_angle=np.pi / 2):
    """Friction moment of a flat or conical thrust face (2-20, F22).

    New face (uniform pressure): M = 2/3 mu Q (R^2 + R r + r^2)/(R + r) / sin(alpha);
    run-in face (uniform wear, p s = const): M = mu Q (R + r) / 2 / sin(alpha).

    Parameters
    ----------
    Q : array_like
        Axial load, > 0.
    mu : array_like
        Coefficient of friction, >= 0.
    r_out, r_in : array_like
        Outer radius R > 0 and inner radius r in [0, R) of the contact (radii measured
        from the axis, for a cone too). r_in = 0 is a solid face.
    condition : {"new", "run-in"}
        Pressure law.
    cone_half_angle : array_like
        Angle alpha between the cone's generator and its axis, in (0, pi/2]; pi/2 (the
        default) is a flat face.

    Returns
    -------
    M : float or ndarray

    Raises
    ------
    ValueError
        If a radius is out of range, `mu` < 0, or the condition is unknown.

    Notes
    -----
    Derived by integrating over rings in :ref:`deriv-friction`; the form used has no 0/0
    when r -> R.

    Examples
    --------
    >>> from mech.planar.forces._friction import thrust_friction_moment
    >>> round(float(thrust_friction_moment(1.0, 0.3, 100.0, 50.0, condition="run-in")), 6)
    22.5
    """
    Q, mu, R = _positive("Q", Q), _nonnegative("mu", mu), _positive("r_out", r_out)
    r = _nonnegative("r_in", r_in)
    if np.any(r >= R):
        raise ValueError(f"Expected `r_in` < `r_out`, got r_in = {float(np.max(r))!r} >= r_out = {float(np.min(R))!r}")
    alpha = _positive("cone_half_angle", cone_half_angle)
    if np.any(alpha > np.pi / 2):
        raise ValueError(f"Expected `cone_half_angle` <= pi/2, got {float(alpha.max())!r}")
    new = option("condition", condition, ("new", "run-in")) == "new"
    # the radius factor at unit load, friction and outer radius (no overflow of R**2), then
    # scaled: M = mu Q R f
    with np.errstate(over="ignore", invalid="ignore"):
        f = thrust_moment(1.0, 1.0, 1.0, r / R, alpha)[0 if new else 1]
        load = mu * Q
        moment = np.where(load == 0.0, 0.0, load * (R * f))
    return _out(finite_result(moment, "the friction moment", Q=Q, mu=mu, r_out=R, cone_half_angle=alpha))


def collar_friction_radius(r_out, r_in=0.0, condition="new"):
    """Friction radius r_c of a flat annular collar: M = mu Q r_c.

    Parameters
    ----------
    r_out, r_in : array_like
        Outer and inner radius of the collar face.
    condition : {"new", "run-in"}
        Uniform pressure: 2/3 (R^3 - r^3)/(R^2 - r^2); uniform wear: (R + r)/2.

    Returns
    -------
    r_c : float or ndarray

    Raises
    ------
    ValueError
        As :func:`thrust_friction_moment`.

    Notes
    -----
    :ref:`deriv-friction`; used for the collar of a screw jack.

    Examples
    --------
    >>> from mech.planar.forces._friction import collar_friction_radius
    >>> round(float(collar_friction_radius(25.0, 21.0)), 4), float(collar_friction_radius(25.0, 21.0, "run-in"))
    (23.058, 23.0)
    """
    return thrust_friction_moment(1.0, 1.0, r_out, r_in, condition=condition)


def rolling_mill_max_thickness(diameter, gap, mu):
    """Thickest strip two equal rolls draw in by friction alone (exercise 2-20).

    h_max = a + D (1 - cos(phi)), phi = atan(mu): the bite angle may not exceed the
    friction angle.

    Parameters
    ----------
    diameter : array_like
        Roll diameter D, > 0.
    gap : array_like
        Gap a between the rolls, >= 0.
    mu : array_like
        Coefficient of friction between roll and strip, >= 0.

    Returns
    -------
    h_max : float or ndarray

    Raises
    ------
    ValueError
        If `diameter` <= 0, or `gap` or `mu` negative.

    Notes
    -----
    :ref:`deriv-friction`, written as a + D mu^2 / (s (1 + s)), s = sqrt(1 + mu^2), with no
    cancellation for small mu.

    Examples
    --------
    >>> from mech.planar.forces._friction import rolling_mill_max_thickness
    >>> round(float(rolling_mill_max_thickness(1200.0, 25.0, 0.3)), 4)
    75.6085
    """
    D, a, mu = _positive("diameter", diameter), _nonnegative("gap", gap), _nonnegative("mu", mu)
    # mu**2 / (s (1 + s)) = 1 - 1/s rounds to 1 for mu >= 1e150: cap mu there (mu**2 finite)
    with np.errstate(over="ignore"):
        h = mill_max_thickness(D, a, np.minimum(mu, 1e150))
    return _out(finite_result(h, "the thickness", diameter=D, gap=a))
