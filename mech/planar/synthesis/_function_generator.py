"""Freudenstein's coefficients and the result objects of planar function generation.

`FunctionMap` maps a function y = f(x) onto link rotations (the textbook's F93);
`FunctionGenerator` holds a designed four-bar and proves it by simulating it with
`mech.planar.FourBar`: whether it meets its pairs, on which branch, and whether one branch
covers the input range. The synthesis itself is in ``_function_generation``.
"""

import numpy as np

from mech._generated.function_generation import fg_coefficients, fg_lengths
from mech._geometry import wrap_angle as _wrap
from mech._validate import (MAX_COUNT, angle, branch_sign, finite_array, function_pairs, integer, positive_length,
                            real_array, real_number, common_shape)
from mech.planar.kinematics._fourbar import FourBar

__all__ = ["FunctionGenerator", "FunctionMap", "freudenstein_coefficients", "lengths_from_coefficients"]


def _interval(name, value):
    """Two finite numbers (low, high) from `value`."""
    arr = finite_array(name, value)
    if arr.shape != (2,):
        raise ValueError(f"Expected `{name}` as a pair (low, high), got shape {arr.shape}: {value!r}")
    return float(arr[0]), float(arr[1])


def _call(f, name, x, arg="x"):
    """f(x) as a finite float array; a user function's complex, NaN or infinite values are
    reported under `name` and the argument `arg` that gave x, not warned about or carried
    into the design."""
    try:
        with np.errstate(all="ignore"):
            value = f(x)
    except Exception as err:                       # a user function: report, do not mask as ours
        raise ValueError(f"Expected `f` to evaluate at {x!r}, got {type(err).__name__}: {err}") from err
    try:
        return finite_array(name, value)
    except ValueError as exc:                      # and where: the caller's argument, as given
        v = np.broadcast_to(np.asarray(value), np.shape(x)) if np.ndim(value) <= np.ndim(x) else None
        at = x if v is None or np.ndim(x) == 0 else np.asarray(x)[~np.isfinite(np.real(v))].ravel()[:1]
        at = float(np.ravel(at)[0]) if np.size(at) else at
        raise type(exc)(f"{exc}, at `{arg}` = {at!r}") from exc      # InputTypeError stays one


def freudenstein_coefficients(a, b, c, d):
    """Freudenstein's coefficients K1, K2, K3 of a four-bar, eq. (3) of the derivation.

    K1 = d/a, K2 = d/c, K3 = (a^2 - b^2 + c^2 + d^2)/(2ac), so that at every assembled pose
    K1 cos(psi) - K2 cos(theta) + K3 = cos(theta - psi) (angles of CONVENTIONS.md: theta
    of A->B, psi of D->C).

    Parameters
    ----------
    a, b, c, d : float
        Input link AB, coupler BC, output link CD, ground AD, > 0, any one unit.

    Returns
    -------
    k : ndarray, shape (3,)

    Raises
    ------
    ValueError
        If a length is not positive and finite.

    Notes
    -----
    Page ``deriv-function-generation``, eqs. (2), (3). The coefficients are ratios, so they
    do not depend on the unit of length.

    Examples
    --------
    >>> from mech.planar.synthesis import freudenstein_coefficients
    >>> freudenstein_coefficients(10, 40, 30, 35).round(6)
    array([3.5     , 1.166667, 1.041667])
    """
    lengths = np.array([positive_length(n, v) for n, v in zip("abcd", (a, b, c, d))])
    # ratios to the longest link: the same numbers at any scale, no overflow in a^2
    with np.errstate(all="ignore"):
        k = np.array(fg_coefficients(*(lengths / lengths.max())), dtype=float)
    if not np.all(np.isfinite(k)):
        a, b, c, d = (float(v) for v in lengths)
        raise ValueError(f"Expected `a`, `b`, `c` and `d` whose ratios give finite coefficients, got a={a!r}, "
                         f"b={b!r}, c={c!r}, d={d!r} (K = {tuple(float(v) for v in k)})")
    return k


def lengths_from_coefficients(k1, k2, k3, d=1.0):
    """Signed lengths (a, b, c, d) of the four-bar with Freudenstein coefficients K1..K3.

    a = d/K1, c = d/K2, b^2 = a^2 + c^2 + d^2 - 2ac K3, eq. (4) of the derivation. A
    negative a (or c) is the link of length ``|a|`` turned by pi: B = ``|a|`` exp(i(theta + pi)).

    Parameters
    ----------
    k1, k2, k3 : float
        The coefficients.
    d : float, optional
        The ground length (the free scale), > 0.

    Returns
    -------
    lengths : ndarray, shape (4,)
        a and c signed, b > 0, d.

    Raises
    ------
    ValueError
        If K1 or K2 is zero (a link of infinite length) or b^2 <= 0 (no real coupler).

    Notes
    -----
    Page ``deriv-function-generation``, eq. (4).

    Examples
    --------
    >>> from mech.planar.synthesis import lengths_from_coefficients
    >>> lengths_from_coefficients(3.5, 35 / 30, 625 / 600, d=35).round(9)
    array([10., 40., 30., 35.])
    """
    k = [real_number(f"k{i + 1}", v) for i, v in enumerate((k1, k2, k3))]
    d = positive_length("d", d)
    for i in (0, 1):
        if k[i] == 0.0:
            raise ValueError(f"Expected `k{i + 1}` != 0 (a finite link length), got {k[i]!r}")
    with np.errstate(all="ignore"):
        a, c, b_sq = (float(v) for v in fg_lengths(*np.array(k), np.float64(1.0)))
    if not (np.isfinite(a) and np.isfinite(c) and np.isfinite(b_sq)):
        raise ValueError(f"Expected `k1`, `k2` and `k3` giving finite lengths, got k1={k[0]!r}, k2={k[1]!r}, "
                         f"k3={k[2]!r}")
    if not b_sq > 0.0:
        raise ValueError(f"Expected `k1`, `k2` and `k3` with b^2 > 0 for a real coupler, got k1={k[0]!r}, "
                         f"k2={k[1]!r}, k3={k[2]!r} (b^2 = {b_sq * d * d!r})")
    with np.errstate(over="ignore"):
        out = np.array([a, np.sqrt(b_sq), c, 1.0]) * d
    if not np.all(np.isfinite(out)):
        raise ValueError(f"Expected `k1`, `k2`, `k3` and `d` giving finite lengths, got k1={k[0]!r}, "
                         f"k2={k[1]!r}, k3={k[2]!r}, d={d!r} (lengths {tuple(float(v) for v in out)})")
    return out


class FunctionMap:
    """The linear map (F93) between a function y = f(x) on [x_start, x_end] and link rotations.

    Input rotation X = theta_range (x - x_start)/(x_end - x_start); output rotation
    Y = psi_range (f(x) - f(x_start))/(f(x_end) - f(x_start)). Calling the map with input
    rotations returns the target output rotations, so it serves as the `target` of
    `precision_pairs` and `least_squares`.

    Parameters
    ----------
    f : callable
        The function, vectorised over NumPy arrays.
    x_range : (float, float)
        x_start, x_end, distinct.
    theta_range, psi_range : float
        Rotations of the input and output links over the range, radians, nonzero; negative
        turns that link clockwise.

    Raises
    ------
    ValueError
        If `f` is not callable, or wherever it is evaluated (the ends of the range when
        built, the arguments asked later) it raises or returns complex, NaN or infinite
        values: the message names ``f(x)`` (at an end of the range, e.g. ``f(1.0)``) and shows the value.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.planar.synthesis import FunctionMap
    >>> m = FunctionMap(np.log10, (1.0, 10.0), np.radians(100.0), np.radians(60.0))
    >>> float(np.degrees(m(np.radians(50.0))).round(6))       # y at x = 5.5, in degrees
    44.422
    """

    def __init__(self, f, x_range, theta_range, psi_range):
        if not callable(f):
            raise ValueError(f"Expected `f` to be callable, got {f!r}")
        x0, x1 = _interval("x_range", x_range)
        if x0 == x1:
            raise ValueError(f"Expected distinct ends of `x_range`, got {x_range!r}")
        self.f, self.x_start, self.x_end = f, x0, x1
        self.theta_range = real_number("theta_range", theta_range)
        self.psi_range = real_number("psi_range", psi_range)
        for name in ("theta_range", "psi_range"):
            if getattr(self, name) == 0.0:
                raise ValueError(f"Expected `{name}` != 0, got 0.0")
        self.y_start, self.y_end = (real_number(f"f({v!r})", _call(f, f"f({v!r})", np.float64(v), "x_range"))
                                   for v in (x0, x1))
        if self.y_start == self.y_end:
            raise ValueError(f"Expected f(x_start) != f(x_end), got {self.y_start!r} for both")

    @property
    def span(self):
        """The input rotation interval (low, high)."""
        return (min(0.0, self.theta_range), max(0.0, self.theta_range))

    @property
    def output_scale(self):
        """Output rotation per unit of y; an angle error divided by it is an error in y."""
        return self.psi_range / (self.y_end - self.y_start)

    def input_rotation(self, x):
        """Input rotation X at function arguments `x` (F93)."""
        return self.theta_range * (finite_array("x", x) - self.x_start) / (self.x_end - self.x_start)

    def input_value(self, X):
        """Function argument x at input rotations `X`."""
        return self.x_start + (self.x_end - self.x_start) * finite_array("X", X) / self.theta_range

    def output_rotation(self, y):
        """Output rotation Y at function values `y` (F93)."""
        return self.output_scale * (finite_array("y", y) - self.y_start)

    def output_value(self, Y):
        """y at output rotations `Y`; NaN passes through (a linkage that did not assemble)."""
        Y = real_array("Y", Y, finite=False)
        if np.any(np.isinf(Y)):
            raise ValueError(f"Expected `Y` finite or NaN, got {float(Y[np.isinf(Y)].ravel()[0])!r}")
        return self.y_start + Y / self.output_scale

    def rotations(self, x):
        """Rotations (X, Y) of the links at function arguments `x`."""
        x = finite_array("x", x)
        return self.input_rotation(x), self.output_rotation(_call(self.f, "f(x)", x))

    def __call__(self, X):
        return self.output_rotation(_call(self.f, "f(x)", self.input_value(X), "X"))

    def __repr__(self):
        return (f"FunctionMap({getattr(self.f, '__name__', self.f)!s}, x_range=({self.x_start!r}, "
                f"{self.x_end!r}), theta_range={self.theta_range!r}, psi_range={self.psi_range!r})")


class FunctionGenerator:
    """A four-bar designed to generate psi - psi0 = y(theta - theta0), checked by `FourBar`.

    Returned by `precision_pairs` and `least_squares`; read-only. Every number below comes
    from simulating `fourbar` (not from the design equations).

    Parameters
    ----------
    lengths : (float, float, float, float)
        a, b, c, d, > 0.
    theta0, psi0 : float
        Start angles (FourBar convention), radians.
    branch : {1, -1}
    x, y : array_like, shape (n,)
        Input and output rotations of the pairs, radians.
    x_range, target, samples, tol
        As in `precision_pairs` (``tol=np.inf`` skips the check at the pairs).

    Attributes
    ----------
    fourbar : FourBar
        The linkage, standard frame (A = 0, D = d on +x), on the branch of the first pair.
    placement : (complex, float)
        Translation and rotation mapping the standard frame onto the task's ground frame:
        ``(0j, 0.0)``, function generation poses its task in the standard frame.
    lengths : tuple of float
        a, b, c, d (positive).
    theta0, psi0 : float
        Start angles in the FourBar's convention (a negative Freudenstein length shifted
        its link's start angle by pi).
    branch : int
    x, y : ndarray, shape (n,)
        The pairs of the synthesis (input and output rotations, radians).
    input_angles : ndarray, shape (n,)
        theta0 + x: the FourBar input angles that reproduce the pairs.
    x_range : (float, float)
        The input rotations the design must cover.
    target : callable or None
        Target output rotation as a function of the input rotation.
    defect : str or None
        None when one branch covers `x_range`; "branch" if the pairs are not all met on
        one branch, "limit" if the linkage cannot be assembled somewhere in the range (a
        limit position of the input inside it), "reversal" if the output turns back while
        the target does not.
    pair_error : float
        Largest ``|structural error|`` at the pairs.
    min_transmission_angle : (float, float)
        Smallest transmission angle over the sampled range and the input rotation x there.
    monotone : bool
        Whether the output turns one way only over the sampled range.
    coefficients : ndarray, shape (3,)
        Freudenstein's K1, K2, K3 of `lengths` (for the FourBar's angles).
    covers_range : bool
        ``defect is None``.

    Notes
    -----
    Page ``deriv-function-generation``. The range is checked at `samples` input rotations
    (a limit position between two samples whose excursion is shorter than the spacing
    could be missed). Angles are simulated on the linkage scaled to its longest link, so
    any length scale works; `fourbar` itself has the given lengths.
    """

    def __init__(self, lengths, theta0, psi0, branch, x, y, *, x_range=None, target=None,
                 samples=721, tol=1e-9):
        values = finite_array("lengths", lengths)
        if values.shape != (4,):
            raise ValueError(f"Expected `lengths` (a, b, c, d), got shape {values.shape}: {lengths!r}")
        a, b, c, d = (positive_length(n, v) for n, v in zip("abcd", values))
        self.lengths = (a, b, c, d)
        self.theta0, self.psi0 = angle("theta0", theta0), angle("psi0", psi0)
        self.branch = branch_sign(branch)
        self.x, self.y = function_pairs(x, y, 1)
        x_range = _common(target, x_range, samples, tol)
        self.fourbar = FourBar(a, b, c, d, branch=self.branch)
        self.placement = (0j, 0.0)
        # angles depend on length ratios only: simulate the linkage scaled to its longest
        # link, so that no length scale can overflow or underflow inside the solver
        m = max(self.lengths)
        try:
            self._unit = FourBar(a / m, b / m, c / m, d / m, branch=self.branch)
        except (OverflowError, ZeroDivisionError, FloatingPointError):
            raise ValueError(f"Expected link-length ratios within the floating-point range, got lengths "
                             f"{self.lengths}") from None
        self.coefficients = freudenstein_coefficients(a, b, c, d)
        self.input_angles = self.theta0 + self.x
        lo, hi = (np.min(self.x), np.max(self.x)) if x_range is None else x_range
        self.x_range = (float(lo), float(hi))
        self.target = target
        self._diagnose(samples, tol)
        for arr in (self.x, self.y, self.input_angles, self.coefficients):
            arr.flags.writeable = False

    def _diagnose(self, samples, tol):
        err = self.structural_error(self.x, self.y)
        self.pair_error = float(np.max(np.nan_to_num(np.abs(err), nan=np.inf)))
        dense = np.linspace(*self.x_range, samples)
        pose = self._unit.solve(self.theta0 + dense, order=1)
        gamma = self._unit.transmission_angle(self.theta0 + dense)
        i = int(np.nanargmin(gamma)) if np.any(pose.valid) else 0
        self.min_transmission_angle = (float(gamma[i]), float(dense[i]))
        self.monotone = bool(np.all(pose.valid) and (np.all(pose.omega_output > 0)
                                                      or np.all(pose.omega_output < 0)))
        if not self.pair_error <= tol:
            self.defect = "branch"
        elif not np.all(pose.valid):
            self.defect = "limit"
        else:
            self.defect = None
            if self.target is not None:
                step = np.diff(self._target(dense))
                target_monotone = np.all(step > 0) or np.all(step < 0)
                turn = np.sign(np.mean(step)) * pose.omega_output
                if target_monotone and not np.all(turn > 0):
                    self.defect = "reversal"
        self.covers_range = self.defect is None

    def __setattr__(self, name, value):
        if name in getattr(self, "__dict__", {}) and "covers_range" in self.__dict__:
            raise AttributeError("FunctionGenerator is read-only")
        object.__setattr__(self, name, value)

    def __repr__(self):
        lengths = ", ".join(f"{v:.6g}" for v in self.lengths)
        return (f"FunctionGenerator(lengths=({lengths}), theta0={self.theta0:.6f}, psi0={self.psi0:.6f}, "
                f"branch={self.branch:+d}, defect={self.defect!r})")

    def solve(self, x, order=0):
        """The FourBar's poses at input rotations `x` (angles theta0 + x)."""
        return self.fourbar.solve(self.theta0 + finite_array("x", x), order=order)

    def _psi(self, x):
        return self._unit.solve(self.theta0 + finite_array("x", x)).psi

    def output(self, x):
        """Generated output rotation psi(theta0 + x) - psi0, wrapped to (-pi, pi]; NaN where the
        linkage does not assemble."""
        return _wrap(self._psi(x) - self.psi0)

    def structural_error(self, x, y=None):
        """Structural error psi(theta0 + x) - (psi0 + y), wrapped to (-pi, pi], eq. (7); with `y`
        omitted the target's output rotation at `x` is used."""
        x = finite_array("x", x)
        if y is None:
            if self.target is None:
                raise ValueError("Expected `y` (this design has no `target`), got None")
            y = self._target(x)
        y = finite_array("y", y)
        common_shape(x=x, y=y)
        return _wrap(self._psi(x) - self.psi0 - y)

    def _target(self, x):
        """The target's output rotations at `x`, checked: finite, one per input."""
        try:
            with np.errstate(all="ignore"):
                y = self.target(x)
        except Exception as err:                   # a user function: report, do not mask as ours
            raise ValueError(f"Expected `target` to evaluate at the input rotations, got "
                             f"{type(err).__name__}: {err}") from err
        y = finite_array("target(x)", y)
        if y.shape != np.shape(x):
            raise ValueError(f"Expected `target(x)` of shape {np.shape(x)}, got shape {y.shape}")
        return y

    def errors(self, samples=721):
        """(max ``|structural error|``, RMS) over `samples` input rotations spanning `x_range`."""
        samples = integer("samples", samples, minimum=2, maximum=MAX_COUNT)
        x = np.linspace(*self.x_range, samples)
        e = self.structural_error(x) if self.target is not None else self.structural_error(self.x, self.y)
        return float(np.max(np.abs(e))), float(np.sqrt(np.mean(e**2)))


def _common(target, x_range, samples, tol):
    if target is not None and not callable(target):
        raise ValueError(f"Expected `target` to be callable or None, got {target!r}")
    if x_range is None and isinstance(target, FunctionMap):
        x_range = target.span
    if x_range is not None:
        lo, hi = _interval("x_range", x_range)
        if not lo < hi:
            raise ValueError(f"Expected `x_range` = (low, high) with low < high, got {x_range!r}")
        x_range = (lo, hi)
    samples = integer("samples", samples, minimum=2, maximum=MAX_COUNT)
    t = real_array("tol", tol, finite=False)
    if t.ndim != 0 or not t > 0.0:                  # +inf is allowed: no check at the pairs
        raise ValueError(f"Expected `tol` > 0, got {tol!r}")
    return x_range
