"""The two optimisation designs of the textbook: the steering trapezoid (Example 2-23) and
approximate path synthesis of a coupler point through n points (Example 2-24).

Each has a model factory (a `DesignModel` for the solvers of ``_optimisation``) and a design
class that builds the linkage as a `mech.planar.FourBar` and proves it by analysis: the
angles or coupler points are recomputed by `FourBar.solve`, not taken from the objective.
"""

from dataclasses import dataclass

import numpy as np

from mech._generated.path_optimisation import path_coupler_point
from mech._generated.steering_trapezoid import steering_beta, steering_ideal
from mech._geometry import wrap_angle as _wrap
from mech._validate import _show, finite_array, nonnegative_int, planar_points, positive_length, real_number
from mech.planar.kinematics._fourbar import FourBar
from mech.planar.structure._grashof import grashof
from mech.planar.synthesis._optimisation import DesignModel

__all__ = ["SteeringTrapezoid", "steering_trapezoid_model", "CouplerPathDesign", "path_synthesis_model",
           "PATH_VARIABLES"]

#: Design variables of Example 2-24, in order (the text's nine plus the crank's start angle).
PATH_VARIABLES = ("l1", "l2", "l3", "l4", "l5", "xA", "yA", "alpha", "phi4", "theta0")


def _trapezoid_weights(steps):
    w = np.ones(steps + 1)
    w[[0, -1]] = 0.5
    return w


def steering_trapezoid_model(a=1480.0, h=2960.0, *, theta_max=np.radians(30.0), steps=20,
                             arm_range=(0.1, 0.4), clearance=0.6):
    """The optimisation model of the steering trapezoid, Example 2-23 (eqs. 2-57, F44-F49).

    Variables ``x = [l1, phi0]``: arm length and arm angle to the axle (l3 = l1, l4 = a,
    l2 = a - 2 l1 cos(phi0)). Objective: the integral of (beta' - beta)^2 over
    0 <= theta <= theta_max (radians), by the trapezoidal rule with ``steps`` steps.
    Constraints (F49, corrected units): g1 = arm_range[0] a - l1, g2 = l1 - arm_range[1] a,
    g3 = arctan(2 clearance h / a) - phi0, g4 = phi0 - pi/2, all <= 0; they are the box too.

    Parameters
    ----------
    a, h : float
        Kingpin track and wheelbase (any one unit), > 0.
    theta_max : float
        Steering range of the driving arm, radians, in (0, pi/2).
    steps : int
        Trapezoidal steps (the text: 20).
    arm_range : (float, float)
        Bounds of l1 / a (the text: 0.1 and 0.4).
    clearance : float
        The arms' lines must meet at least ``clearance * h`` behind the axle (the text: 0.6).

    Returns
    -------
    DesignModel
        A design that cannot be assembled over the range has objective inf.

    Notes
    -----
    The closure is derived on page ``deriv-steering-trapezoid``; beta uses the corrected
    constant C. The text calls the objective an RMS error; it is an integral square error.

    Examples
    --------
    Example 2-23 at the text's optimum (l1 = 148 mm, phi0 = 1.226 rad):

    >>> from mech.planar.synthesis import steering_trapezoid_model
    >>> model = steering_trapezoid_model()
    >>> float(model.f([148.0, 1.226]))
    2.563...e-05
    """
    a, h = positive_length("a", a), positive_length("h", h)
    if not np.isfinite(a / h) or a / h == 0.0:
        raise ValueError(f"Expected `a` / `h` within the float range, got a = {a!r}, h = {h!r}")
    theta_max = real_number("theta_max", theta_max)
    if not 0.0 < theta_max < np.pi / 2:
        raise ValueError(f"Expected `theta_max` in (0, pi/2), got {theta_max}")
    steps = nonnegative_int("steps", steps, 10**6)
    if steps < 1:
        raise ValueError(f"Expected `steps` >= 1, got {steps}")
    bounds = finite_array("arm_range", arm_range)
    if bounds.shape != (2,):
        raise ValueError(f"Expected `arm_range` of two numbers (low, high), got shape {bounds.shape}: {arm_range!r}")
    lo, hi = bounds
    if not 0.0 < lo < hi < 0.5:
        raise ValueError(f"Expected `arm_range` with 0 < low < high < 0.5, got {arm_range!r}")
    clearance = real_number("clearance", clearance)
    if not clearance >= 0.0:
        raise ValueError(f"Expected `clearance` >= 0, got {clearance}")
    phi_lo = float(np.arctan2(2.0 * clearance * h, a))
    if not phi_lo < np.pi / 2:      # 2 clearance h / a so large that the arctan rounds to pi/2
        raise ValueError(
            f"Expected `clearance`, `h` and `a` whose lower bound arctan(2 clearance h / a) of phi0 is "
            f"below pi/2 in floating point, got clearance={clearance!r}, h={h!r}, a={a!r}"
        )
    theta = np.linspace(0.0, theta_max, steps + 1)
    weight = _trapezoid_weights(steps) * (theta_max / steps)
    ideal = steering_ideal(theta, a / h)

    def objective(x):
        lam, phi0 = x[..., 0:1] / a, x[..., 1:2]
        with np.errstate(all="ignore"):
            beta = _wrap(steering_beta(lam, phi0, theta, -1.0))
            value = np.sum(weight * (ideal - beta) ** 2, axis=-1)
        return np.where(np.isfinite(value), value, np.inf)

    def inequality(x):
        l1, phi0 = x[..., 0], x[..., 1]
        return np.stack([lo * a - l1, l1 - hi * a, phi_lo - phi0, phi0 - np.pi / 2], axis=-1)

    return DesignModel(objective, [(lo * a, hi * a), (phi_lo, np.pi / 2)], inequality=inequality,
                       names=("l1", "phi0"))


@dataclass(frozen=True)
class SteeringProof:
    """A steering trapezoid analysed over its range (see `SteeringTrapezoid.prove`)."""

    theta: np.ndarray             # driving-arm rotations
    beta: np.ndarray              # driven-arm rotations by FourBar.solve
    beta_ideal: np.ndarray        # Ackermann rotations
    model_difference: float       # max |beta(analysis) - beta(closure of the model)|
    objective: float              # trapezoidal integral of (beta' - beta)^2 from the analysis
    max_error: float              # max |beta' - beta|, radians
    min_transmission_angle: float  # over the range, radians
    valid: bool                   # assembled at every sample


class SteeringTrapezoid:
    """An isosceles steering trapezoid ABCD (Example 2-23) as a `FourBar`.

    A = 0 and D = a are the kingpins; AB = CD = l1 lean inwards at phi0 to the axle;
    BC = l2 = a - 2 l1 cos(phi0). The driving arm AB turns by theta and CD by beta.

    Parameters
    ----------
    l1 : float
        Arm length, > 0.
    phi0 : float
        Arm angle to the axle, radians, in (0, pi/2].
    a, h : float
        Track and wheelbase, > 0 (h sets the ideal relation only).

    Attributes
    ----------
    fourbar : FourBar
        ``FourBar(l1, l2, l1, a, branch=1)`` in the standard frame (the placement is the
        identity: A = 0, D = a on +x); its input angle is ``phi0 + theta`` and its output
        angle ``psi = pi - phi0 + beta``.

    Raises
    ------
    ValueError
        If a length is not positive or l2 <= 0.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import SteeringTrapezoid
    >>> proof = SteeringTrapezoid(148.0, 1.2263).prove()
    >>> round(float(np.degrees(proof.beta[-1])), 3), bool(proof.valid)
    (40.279, True)
    """

    def __init__(self, l1, phi0, a=1480.0, h=2960.0):
        self.l1, self.a, self.h = positive_length("l1", l1), positive_length("a", a), positive_length("h", h)
        self.phi0 = real_number("phi0", phi0)
        if not 0.0 < self.phi0 <= np.pi / 2:
            raise ValueError(f"Expected `phi0` in (0, pi/2], got {self.phi0}")
        self.l2 = self.a - 2.0 * self.l1 * np.cos(self.phi0)
        if not self.l2 > 0.0:
            raise ValueError(f"Expected `l1` < a / (2 cos(phi0)) so that the tie rod is longer than 0, "
                             f"got l1 = {self.l1}, phi0 = {self.phi0}, a = {self.a}")
        try:
            # C is to the left of B->D in the drawn trapezoid: branch +1 (see the derivation page)
            self.fourbar = FourBar(self.l1, self.l2, self.l1, self.a, branch=1)
        except ValueError as exc:     # its message names the four-bar's `b` or `d`, derived here
            raise ValueError(
                f"Expected `l1`, `phi0` and `a` whose trapezoid (arms l1, tie rod a - 2 l1 cos(phi0) = "
                f"{self.l2!r}, track a) closes in floating point, got l1={l1!r}, phi0={phi0!r}, a={a!r} ({exc})"
            ) from exc

    def __repr__(self):
        return f"SteeringTrapezoid(l1={self.l1!r}, phi0={self.phi0!r}, a={self.a!r}, h={self.h!r})"

    def beta(self, theta):
        """Driven-arm rotation by the closure of the model (generated code)."""
        theta = finite_array("theta", theta)
        with np.errstate(all="ignore"):
            return _wrap(steering_beta(self.l1 / self.a, self.phi0, theta, -1.0))

    def beta_ideal(self, theta):
        """The ideal (Ackermann) rotation, F44."""
        return steering_ideal(finite_array("theta", theta), self.a / self.h)

    def prove(self, theta_max=np.radians(30.0), steps=20):
        """Analyse the trapezoid with `FourBar.solve` over 0 <= theta <= theta_max."""
        theta_max = real_number("theta_max", theta_max)
        steps = nonnegative_int("steps", steps, 10**7)
        if steps < 1 or not 0.0 < theta_max < np.pi / 2:
            raise ValueError(f"Expected `steps` >= 1 and `theta_max` in (0, pi/2), got {steps}, {theta_max}")
        theta = np.linspace(0.0, theta_max, steps + 1)
        sol = self.fourbar.solve(self.phi0 + theta)
        beta = _wrap(sol.psi - np.pi + self.phi0)
        ideal = self.beta_ideal(theta)
        weight = _trapezoid_weights(steps) * (theta_max / steps)
        with np.errstate(invalid="ignore"):
            gamma = self.fourbar.transmission_angle(self.phi0 + theta)
        return SteeringProof(theta, beta, ideal, float(np.max(np.abs(beta - self.beta(theta)))),
                             float(np.sum(weight * (ideal - beta) ** 2)), float(np.max(np.abs(ideal - beta))),
                             float(np.min(gamma)), bool(np.all(sol.valid)))


def _points(points):
    arr = planar_points("points", points)
    if arr.ndim != 1 or arr.size < 3:
        raise ValueError(f"Expected `points` as a 1-D array of at least 3 complex numbers, got {_show(points)}")
    return arr


def _coupler_model(x, n):
    """Coupler points of (2-58) for designs x (..., 10) at n equal crank steps: shape (..., n)."""
    l1, l2, l3, l4, l5, xa, ya, alpha, phi4, theta0 = (x[..., i:i + 1] for i in range(10))
    # in units of the longest link: no overflow or underflow in the squares at any scale
    s = np.maximum(np.maximum(l1, l2), np.maximum(l3, l4))
    phi1 = theta0 + 2.0 * np.pi * np.arange(n) / n
    # the point relative to A, by the generated model (derivation page deriv-path-optimisation)
    xp, yp = path_coupler_point(l1 / s, l2 / s, l3 / s, l4 / s, l5 / s, 0.0, 0.0, alpha, phi4, phi1)
    return xa + 1j * ya + s * (xp + 1j * yp)


def path_synthesis_model(points, *, gamma_min=np.radians(30.0), bounds=None):
    """The optimisation model of approximate path synthesis, Example 2-24 (eq. 2-58, F52, F53).

    A four-bar's coupler point P passes near the n given points, reached at n equal steps
    of the crank, 2 pi / n apart. Variables (`PATH_VARIABLES`): l1..l4 (crank, coupler,
    rocker, ground), l5 and alpha (P at l5 from B, alpha from B->C), the crank pivot
    (xA, yA), the ground angle phi4 and the crank angle theta0 at the first point.
    Objective: the sum of the distances ``|P_i' - P_i|`` (the text's F33; not an RMS error).
    Constraints (F53): crank l1 (Grashof, g1..g3), l1 > 0 (g4), transmission angle at
    least ``gamma_min`` at both crank-frame alignments (g5, g6, radians).

    Parameters
    ----------
    points : array_like, shape (n,), complex
        Target points x + iy, in the order the coupler point should meet them.
    gamma_min : float
        Smallest allowed transmission angle, radians, in [0, pi/2).
    bounds : array_like, shape (10, 2), optional
        Default: lengths in [0.01 R, 4 R], the pivot within 4 R of the points' centroid,
        angles in [-pi, pi], with R the largest distance of a point from the centroid.

    Returns
    -------
    DesignModel

    Notes
    -----
    The text leaves the crank's start angle unstated; here it is the variable theta0 (the
    printed optimum fits its ten points only with theta0 near 92 degrees). The coupler
    angle is phi4 + alpha + delta with delta = angle CBD - beta: the assembly with C to
    the left of B->D, `FourBar` branch +1. The model is generated from the derivation page
    ``deriv-path-optimisation`` (eq. 2-58, in atan2 form: accurate also where the triangle
    BCD is nearly flat). A design that cannot be assembled at a step has objective inf.

    Examples
    --------
    >>> from mech.planar.synthesis import path_synthesis_model
    >>> model = path_synthesis_model([1 + 1j, 2 + 1.5j, 3 + 1j])
    >>> model.n, model.names[-1]
    (10, 'theta0')
    """
    pts = _points(points)
    gamma_min = real_number("gamma_min", gamma_min)
    if not 0.0 <= gamma_min < np.pi / 2:
        raise ValueError(f"Expected `gamma_min` in [0, pi/2), got {gamma_min}")
    n = pts.size
    if bounds is None:
        c = pts.mean()
        R = float(np.max(np.abs(pts - c)))
        if not R > 0.0:
            raise ValueError(f"Expected `points` that are not all equal, got {points!r}")
        bounds = [(0.01 * R, 4 * R)] * 5 + [(c.real - 4 * R, c.real + 4 * R), (c.imag - 4 * R, c.imag + 4 * R)] \
            + [(-np.pi, np.pi)] * 3

    def objective(x):
        with np.errstate(all="ignore"):
            value = np.sum(np.abs(_coupler_model(x, n) - pts), axis=-1)
        return np.where(np.isfinite(value), value, np.inf)

    def inequality(x):
        l1, l2, l3, l4 = (x[..., i] for i in range(4))
        s = np.maximum(np.maximum(l1, l2), np.maximum(l3, l4))
        with np.errstate(all="ignore"):
            l1, l2, l3, l4 = l1 / s, l2 / s, l3 / s, l4 / s     # the cosines from ratios (no overflow)
            g5 = gamma_min - np.arccos((l2**2 + l3**2 - (l4 - l1) ** 2) / (2 * l2 * l3))
            g6 = gamma_min - (np.pi - np.arccos((l2**2 + l3**2 - (l4 + l1) ** 2) / (2 * l2 * l3)))
        return np.stack([s * (l1 + l4 - l2 - l3), s * (l1 + l3 - l2 - l4), s * (l1 + l2 - l3 - l4), -s * l1, g5, g6],
                        axis=-1)

    return DesignModel(objective, bounds, inequality=inequality, names=PATH_VARIABLES)


@dataclass(frozen=True)
class PathProof:
    """A path-synthesis design analysed with `FourBar.solve` (see `CouplerPathDesign.prove`)."""

    P: np.ndarray                  # coupler point at the n crank steps, ground frame
    distances: np.ndarray          # |P_i - target_i|
    objective: float               # their sum, by analysis
    curve_distances: np.ndarray    # distance of each target from the whole coupler curve
    min_transmission_angle: float  # over a full crank turn, radians
    kind: str                      # Grashof type ("crank-rocker" wanted)
    valid: bool                    # assembled at every step


class CouplerPathDesign:
    """A four-bar whose coupler point approximates a path (Example 2-24), as a `FourBar`.

    Parameters
    ----------
    x : array_like, shape (10,)
        Design in the order of `PATH_VARIABLES`.
    points : array_like, shape (n,), complex
        The target points.

    Attributes
    ----------
    fourbar : FourBar
        ``FourBar(l1, l2, l3, l4, branch=1, coupler=(l5 cos(alpha), l5 sin(alpha)))`` in the
        standard frame.
    origin, rotation : complex, float
        Placement: a standard-frame point z is at ``origin + exp(1j*rotation) * z``
        (origin = xA + i yA, rotation = phi4).
    theta : ndarray, shape (n,)
        Input angles at the targets: theta0 + 2 pi k / n.

    Examples
    --------
    The design printed in the text, with start angle 92.09 degrees:

    >>> import numpy as np
    >>> from mech.planar.synthesis import CouplerPathDesign
    >>> P = [9.5+8.26j, 9+8.87j, 7.96+9.51j, 5.65+9.94j, 4.36+9.7j, 3.24+9j, 3.26+8.36j,
    ...      4.79+8.11j, 6.58+8j, 9.12+7.89j]
    >>> x = [1.678, 5.819, 5.407, 7.03, 7.973, 2.066, 2.249, np.radians(79.016),
    ...      np.radians(-70.29), np.radians(92.09)]
    >>> round(CouplerPathDesign(x, P).prove().objective, 4)
    1.89
    """

    def __init__(self, x, points):
        x = finite_array("x", x)
        if x.shape != (10,):
            raise ValueError(f"Expected `x` of shape (10,) in the order {PATH_VARIABLES}, got shape {x.shape}")
        self.x = x
        self.points = _points(points)
        l1, l2, l3, l4, l5, xa, ya, alpha, phi4, theta0 = (float(v) for v in x)
        self.fourbar = FourBar(l1, l2, l3, l4, branch=1, coupler=(l5 * np.cos(alpha), l5 * np.sin(alpha)))
        self.origin, self.rotation = complex(xa, ya), phi4
        self.theta = theta0 + 2.0 * np.pi * np.arange(self.points.size) / self.points.size

    def __repr__(self):
        return "CouplerPathDesign(" + ", ".join(f"{k}={v:.6g}" for k, v in zip(PATH_VARIABLES, self.x)) + ")"

    def place(self, z):
        """Standard-frame points z in the task's ground frame."""
        return self.origin + np.exp(1j * self.rotation) * planar_points("z", z)

    def prove(self, samples=7200):
        """Solve the four-bar at the targets' crank angles and over a full turn (``samples`` poses)."""
        samples = nonnegative_int("samples", samples, 10**8)
        if samples < 3:
            raise ValueError(f"Expected `samples` >= 3, got {samples}")
        sol = self.fourbar.solve(self.theta)
        P = self.place(sol.P)
        d = np.abs(P - self.points)
        turn = self.fourbar.solve(np.linspace(0.0, 2.0 * np.pi, samples, endpoint=False))
        curve = self.place(turn.P[turn.valid])
        nearest = np.min(np.abs(curve[:, None] - self.points[None, :]), axis=0) if curve.size else \
            np.full(self.points.size, np.inf)
        return PathProof(P, d, float(np.sum(d)), nearest, float(self.fourbar.min_transmission_angle()[0]),
                         grashof(*self.x[:4]).kind, bool(np.all(sol.valid)))
