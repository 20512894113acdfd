"""Function generation with the spherical four-bar (the spherical monograph, chapter 6).

The spherical Freudenstein equation of page ``deriv-spherical-function-generation``,

    k1 cos(theta) cos(psi) + sin(theta) sin(psi) = k2 cos(psi) - k3 cos(theta) + k4,

is linear in four coefficients of the arcs; precision pairs and least squares are linear
algebra on its rows, and every design is checked by simulating the linkage.
"""

import numpy as np

from mech._generated.one_equation import abc_discriminant, abc_solve, spherical_fourbar_abc
from mech._generated.spherical_function_generation import sfg_arcs, sfg_coefficients, sfg_row
from mech._geometry import wrap_angle
from mech._spacing import chebyshev_spacing
from mech._task import distinct_pairs
from mech._validate import (arc as _arc, bool_flag, common_shape, finite_array, finite_result, function_pairs,
                            naming, option, real_number)

__all__ = [
    "FunctionGenerator",
    "freudenstein_coefficients",
    "arcs_from_coefficients",
    "chebyshev_spacing",
    "precision_pairs",
    "least_squares",
]

_DENSE = 721          # samples of the input range for the limit-position check


def _simulate(arcs, theta, branch):
    """Output angle on `branch` (NaN where not assembled) and the discriminant."""
    A, B, C = spherical_fourbar_abc(*arcs, theta)
    disc = abc_discriminant(A, B, C)
    ok = disc >= 0.0
    psi = abc_solve(A, B, C, np.sqrt(np.where(ok, disc, 0.0)), -branch)
    return np.where(ok, psi, np.nan), disc


def _rows(theta, psi):
    g1, g2, g3, g4, h = sfg_row(theta, psi)
    G = np.stack(np.broadcast_arrays(g1, g2, g3, g4), axis=-1)
    return G, np.broadcast_to(h, G.shape[:-1])


def freudenstein_coefficients(a, b, c, d):
    """Coefficients k1..k4 of the spherical Freudenstein equation of a four-bar.

    k1 = cos d, k2 = sin d cot a, k3 = sin d cot c and
    k4 = (cos b - cos a cos c cos d) / (sin a sin c), eq. (2) of the derivation, so that
    k1 cos(theta) cos(psi) + sin(theta) sin(psi) = k2 cos(psi) - k3 cos(theta) + k4.

    Parameters
    ----------
    a, b, c, d : float
        Arcs AB (input), BC (coupler), CD (output), AD (ground), radians in (0, pi).

    Returns
    -------
    k : ndarray, shape (4,)

    Raises
    ------
    ValueError
        If an arc is not in (0, pi).

    Notes
    -----
    Derived on page ``deriv-spherical-function-generation``, eqs. (2) and (4): k4 uses
    versines, so it stays accurate for short arcs, where k2, k3, k4 tend to Freudenstein's
    planar K1 = d/a, K2 = d/c, K3 = (a^2 - b^2 + c^2 + d^2)/(2ac) and k1 to 1.

    Examples
    --------
    >>> from mech.spherical._function_generation import freudenstein_coefficients
    >>> k = freudenstein_coefficients(0.4, 0.9, 0.7, 1.0)
    >>> [round(float(v), 6) for v in k]
    [0.540302, 1.990266, 0.99903, 0.960597]
    """
    arcs = [_arc(n, v) for n, v in zip("abcd", (a, b, c, d))]
    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):   # checked below
        k = np.array(sfg_coefficients(*arcs), dtype=float)
    return finite_result(k, "each of the coefficients k1..k4", a=arcs[0], b=arcs[1], c=arcs[2], d=arcs[3])


def arcs_from_coefficients(k1, k2, k3, k4):
    """Arcs (a, b, c, d) of the spherical four-bar with the coefficients k1..k4.

    Inverts `freudenstein_coefficients` by eq. (5) of the derivation.

    Parameters
    ----------
    k1, k2, k3, k4 : float
        The coefficients of the spherical Freudenstein equation.

    Returns
    -------
    arcs : ndarray, shape (4,)
        a, b, c, d in (0, pi).

    Raises
    ------
    ValueError
        If no real linkage has these coefficients: ``|k1| >= 1`` (no ground arc) or
        ``|cos b| >= 1`` (no coupler arc), condition (6).

    Notes
    -----
    Page ``deriv-spherical-function-generation``, eqs. (5), (6).

    Examples
    --------
    >>> from mech.spherical._function_generation import arcs_from_coefficients, freudenstein_coefficients
    >>> k = freudenstein_coefficients(0.4, 0.9, 0.7, 1.0)
    >>> [round(float(v), 12) for v in arcs_from_coefficients(*k)]
    [0.4, 0.9, 0.7, 1.0]
    """
    k = [real_number(f"k{i + 1}", v) for i, v in enumerate((k1, k2, k3, k4))]
    if not abs(k[0]) < 1.0:
        raise ValueError(f"Expected |`k1`| < 1 (k1 = cos d), got {k[0]!r}")
    with np.errstate(invalid="ignore", over="ignore"):
        # NumPy floats: on Python floats a square beyond the float range raises OverflowError
        a, b, c, d, cos_b = sfg_arcs(*(np.float64(v) for v in k))
    beyond = ValueError(f"Expected `k1` .. `k4` of a linkage whose arcs are within the float range, got "
                        f"{[float(v) for v in k]!r}")
    if not np.isfinite(cos_b):
        raise beyond
    if not abs(cos_b) < 1.0:
        raise ValueError(f"Expected `k1` .. `k4` with |cos b| < 1 for a real coupler arc, got k1={k[0]!r}, "
                         f"k2={k[1]!r}, k3={k[2]!r}, k4={k[3]!r} (cos b = {float(cos_b)!r})")
    if not np.all(np.isfinite([a, b, c, d])):
        raise beyond
    return np.array([a, b, c, d], dtype=float)


class FunctionGenerator:
    """A spherical four-bar designed to generate y = f(x): psi - psi0 = f(theta - theta0).

    Returned by `precision_pairs` and `least_squares`; immutable. Attributes: `arcs`
    (a, b, c, d), `theta0`, `psi0`, `branch` (+1 when det[B, D, C] > 0 along the design
    range), `coefficients` (k1..k4), `x`, `y` (the pairs of the synthesis), `defect`
    (None, "branch": the pairs lie on different branches, or "limit": a limit position
    lies inside the input range) and `reference` (the samples (x, y) behind `max_error`
    and `rms_error`).
    """

    __slots__ = ("arcs", "theta0", "psi0", "branch", "coefficients", "x", "y", "defect", "reference")

    def __init__(self, arcs, theta0, psi0, branch, x, y, defect=None, reference=None):
        values = dict(arcs=tuple(float(v) for v in arcs), theta0=float(theta0), psi0=float(psi0),
                      branch=int(branch), x=np.array(x, dtype=float), y=np.array(y, dtype=float),
                      defect=defect)
        values["coefficients"] = np.array(sfg_coefficients(*values["arcs"]), dtype=float)
        ref = (values["x"], values["y"]) if reference is None else reference
        values["reference"] = tuple(np.array(r, dtype=float) for r in ref)
        for name, value in values.items():
            if isinstance(value, np.ndarray):
                value.flags.writeable = False
            object.__setattr__(self, name, value)

    def __setattr__(self, name, value):
        raise AttributeError("FunctionGenerator is immutable")

    def __repr__(self):
        arcs = ", ".join(f"{v:.6f}" for v in self.arcs)
        return (f"FunctionGenerator(arcs=({arcs}), theta0={self.theta0:.6f}, psi0={self.psi0:.6f}, "
                f"branch={self.branch:+d}, defect={self.defect!r})")

    @property
    def fourbar(self):
        """The linkage as a `SphericalFourBar` (default placement, A at the north pole)."""
        from mech.spherical._fourbar import SphericalFourBar

        return SphericalFourBar(*self.arcs, branch=self.branch)

    def output(self, x):
        """Generated output rotation psi(theta0 + x) - psi0, wrapped to (-pi, pi]; NaN
        where the linkage does not assemble."""
        psi, _ = _simulate(self.arcs, self.theta0 + finite_array("x", x), self.branch)
        return wrap_angle(psi - self.psi0)

    def structural_error(self, x, y):
        """Structural error psi_sim(theta0 + x) - (psi0 + y), wrapped to (-pi, pi], eq. (7)."""
        x, y = finite_array("x", x), finite_array("y", y)
        common_shape(x=x, y=y)
        psi, _ = _simulate(self.arcs, self.theta0 + x, self.branch)
        return wrap_angle(psi - self.psi0 - y)

    def points(self, x):
        """Joint points A, B, C, D (unit vectors, shape (..., 3) each) at input rotations `x`,
        default placement (A the north pole, D = (sin d, 0, cos d))."""
        x = finite_array("x", x)
        a, _, c, d = self.arcs
        theta = self.theta0 + x
        psi, _ = _simulate(self.arcs, theta, self.branch)
        A = np.broadcast_to([0.0, 0.0, 1.0], x.shape + (3,))
        D = np.broadcast_to([np.sin(d), 0.0, np.cos(d)], x.shape + (3,))
        B = np.stack([np.sin(a) * np.cos(theta), np.sin(a) * np.sin(theta), np.full_like(theta, np.cos(a))], -1)
        C = (np.cos(c) * D + np.sin(c) * np.stack([np.cos(psi) * np.cos(d), np.sin(psi),
                                                    -np.cos(psi) * np.sin(d)], -1))
        return A, B, C, D

    @property
    def max_error(self):
        """Largest ``|structural error|`` over `reference`."""
        return float(np.max(np.abs(self.structural_error(*self.reference))))

    @property
    def rms_error(self):
        """Root mean square of the structural error over `reference`."""
        return float(np.sqrt(np.mean(self.structural_error(*self.reference) ** 2)))


def _diagnose(arcs, theta0, psi0, x, y, span=None):
    """Branch of the first pair (in x order) and the defect (None, "branch", "limit"); the
    limit-position check covers the range of `span` (default `x`)."""
    order = np.argsort(x)
    theta, psi = theta0 + x[order], psi0 + y[order]
    A, B, C = spherical_fourbar_abc(*arcs, theta)
    branches = np.where(A * np.sin(psi) - B * np.cos(psi) > 0, -1, 1)     # branch +1 is sigma = -1
    if np.any(branches != branches[0]):
        return int(branches[0]), "branch"
    span = x if span is None else span
    dense = theta0 + np.linspace(np.min(span), np.max(span), _DENSE)
    _, disc = _simulate(arcs, dense, int(branches[0]))
    return int(branches[0]), (None if np.all(disc > 0.0) else "limit")


def _cubic_roots(f):
    """Roots in [0, pi) of f(u) = alpha c^3 + beta c^2 s + gamma c s^2 + delta s^3 (c, s = cos u, sin u)."""
    offset = 0.3                              # keeps a root at u = pi/2 away from tan's pole
    v = np.arange(4) * np.pi / 4
    c, s = np.cos(v), np.sin(v)
    V = np.stack([c**3, c**2 * s, c * s**2, s**3], axis=-1)
    coeffs = np.linalg.solve(V, f(offset + v))
    scale = np.max(np.abs(coeffs))
    if scale == 0.0:
        return np.empty(0)
    t = np.roots(coeffs[::-1] / scale)
    t = t[np.abs(t.imag) <= 1e-7 * (1.0 + np.abs(t))].real
    u = offset + np.arctan(t)
    for _ in range(3):                        # polish by Newton, central-difference slope
        h = 1e-6
        slope = (f(u + h) - f(u - h)) / (2 * h)
        u = u - np.where(slope != 0.0, f(u) / np.where(slope != 0.0, slope, 1.0), 0.0)
    return np.sort(np.mod(u, np.pi))


def _det(theta0, psi0, x, y):
    """det [G | h] of five pairs, broadcast over theta0 and psi0."""
    theta0, psi0 = np.broadcast_arrays(np.asarray(theta0, dtype=float), np.asarray(psi0, dtype=float))
    G, h = _rows(theta0[..., None] + x, psi0[..., None] + y)
    return np.linalg.det(np.concatenate([G, h[..., None]], axis=-1))


def _newton2(F, z):
    z = np.array(z, dtype=float)
    for _ in range(30):
        f = F(z)
        J = np.empty((2, 2))
        for j in range(2):
            dz = np.zeros(2)
            dz[j] = 1e-7
            J[:, j] = (F(z + dz) - F(z - dz)) / 2e-7
        try:
            step = np.linalg.solve(J, -f)
        except np.linalg.LinAlgError:
            break
        z += step
        if np.max(np.abs(step)) < 1e-14:
            break
    return z


def _start_candidates(x, y, theta0, psi0):
    """Every (theta0, psi0) for which the pairs are consistent, start angles as given."""
    if theta0 is not None and psi0 is not None:
        return [(theta0, psi0)]
    if psi0 is None and theta0 is not None:
        return [(theta0, u) for u in _cubic_roots(lambda u: _det(theta0, u, x[:5], y[:5]))]
    if theta0 is None and psi0 is not None:
        return [(u, psi0) for u in _cubic_roots(lambda u: _det(u, psi0, x[:5], y[:5]))]
    first = (x[:5], y[:5])
    second = (np.r_[x[:4], x[5]], np.r_[y[:4], y[5]])
    grid = np.linspace(0.0, np.pi, 181)
    traced = [_cubic_roots(lambda u, t=t: _det(t, u, *first)) for t in grid]
    found = []
    for i in range(grid.size - 1):
        for r in traced[i]:
            nxt = traced[i + 1]
            if nxt.size == 0:
                continue
            gap = np.mod(nxt - r + np.pi / 2, np.pi) - np.pi / 2
            j = np.argmin(np.abs(gap))
            if abs(gap[j]) > 0.1:
                continue
            if np.sign(_det(grid[i], r, *second)) != np.sign(_det(grid[i + 1], r + gap[j], *second)):
                found.append(_newton2(lambda z: np.array([_det(z[0], z[1], *first), _det(z[0], z[1], *second)]),
                                      (0.5 * (grid[i] + grid[i + 1]), r + 0.5 * gap[j])))
    return [tuple(z) for z in found]


def precision_pairs(x, y, *, theta0=None, psi0=None, d=None, keep_defective=False, reference=None):
    """Spherical four-bars whose output meets y at x exactly: psi0 + y_i = psi(theta0 + x_i).

    Solves the spherical Freudenstein equation (3) at each precision pair (精确点): three
    pairs with the start angles and the ground arc `d` given (one free arc), four pairs
    with the start angles given (linear), five with one start angle unknown (the roots of
    one cubic), six with both unknown (continuation of one cubic plus Newton).

    Parameters
    ----------
    x, y : array_like, shape (n,)
        Input and output rotations from the start positions, radians; 3 <= n <= 6.
    theta0, psi0 : float, optional
        Start angles; None makes one unknown (n = 5) or both (n = 6).
    d : float, optional
        The ground arc, required for n = 3 (and only then).
    keep_defective : bool
        Also return linkages with a branch or limit-position defect.
    reference : (array_like, array_like), optional
        Dense samples (x, y) of the function for `max_error` and `rms_error`.

    Returns
    -------
    designs : tuple of FunctionGenerator
        Every real linkage found, best `rms_error` first (one for n = 3 and 4); the twin
        with C (or B, for a free theta0) at its antipode is not repeated.

    Raises
    ------
    ValueError
        For a wrong number of pairs or start angles, or if no real linkage without defect
        passes through the pairs (an arc outside (0, pi), or every solution defective).

    Notes
    -----
    Page ``deriv-spherical-function-generation``. Each returned linkage was simulated
    (the solver of ``deriv-one-equation``) through every pair on one branch.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._function_generation import precision_pairs
    >>> x = np.radians([10.0, 30.0, 50.0, 70.0]); y = 0.5 * np.sin(x)
    >>> g, = precision_pairs(x, y, theta0=np.radians(40.0), psi0=np.radians(80.0))
    >>> float(np.max(np.abs(g.structural_error(x, y)))) < 1e-12
    True
    """
    x, y = function_pairs(x, y, 3)
    distinct_pairs(x, y)
    n = x.size
    theta0 = None if theta0 is None else real_number("theta0", theta0)
    psi0 = None if psi0 is None else real_number("psi0", psi0)
    keep_defective = bool_flag("keep_defective", keep_defective)
    unknown_starts = (theta0 is None) + (psi0 is None)
    if n > 6:
        raise ValueError(f"Expected at most 6 precision pairs (use least_squares for more) in `x` and `y`, got {n}")
    if (n == 3) != (d is not None):
        raise ValueError(f"Expected the ground arc `d` exactly for 3 pairs, got {n} pairs and d = {d!r}")
    needed = {3: 0, 4: 0, 5: 1, 6: 2}[n]
    if unknown_starts != needed:
        raise ValueError(f"Expected {2 - needed} of `theta0`, `psi0` given for {n} pairs, got {2 - unknown_starts}")
    k1 = None if d is None else np.cos(_arc("d", d))
    span = x if reference is None else np.r_[x, finite_array("reference x", reference[0])]
    designs, seen = [], []
    for t0, p0 in _start_candidates(x, y, theta0, psi0):
        G, h = _rows(t0 + x, p0 + y)
        try:
            if k1 is None:
                k = np.linalg.lstsq(G, h, rcond=None)[0]
            else:
                k = np.r_[k1, np.linalg.solve(G[:, 1:], h - k1 * G[:, 0])]
        except np.linalg.LinAlgError:
            continue
        if np.max(np.abs(G @ k - h)) > 1e-8 * (1.0 + np.max(np.abs(k))):
            continue                          # spurious root of the determinant(s)
        if psi0 is None and k[2] < 0:         # the twin with C at its antipode
            p0, k = p0 + np.pi, k * np.array([1, 1, -1, -1])
        if theta0 is None and k[1] < 0:       # the twin with B at its antipode
            t0, k = t0 + np.pi, k * np.array([1, -1, 1, -1])
        t0 = t0 if theta0 is not None else float(wrap_angle(t0))
        p0 = p0 if psi0 is not None else float(wrap_angle(p0))
        if any(abs(wrap_angle(t0 - s)) < 1e-7 and abs(wrap_angle(p0 - q)) < 1e-7 for s, q in seen):
            continue
        seen.append((t0, p0))
        try:
            arcs = arcs_from_coefficients(*k)
        except ValueError:
            continue
        branch, defect = _diagnose(arcs, t0, p0, x, y, span)
        design = FunctionGenerator(arcs, t0, p0, branch, x, y, defect, reference)
        if defect is None and np.max(np.abs(design.structural_error(x, y))) > 1e-8:
            continue                          # does not meet the pairs: not a solution
        if defect is None or keep_defective:
            designs.append(design)
    if not designs:
        listed, shown = naming(x=x, y=y, theta0=theta0, psi0=psi0)
        raise ValueError(f"Expected {listed} that admit a real spherical four-bar without branch or limit "
                         f"defect through the {n} pairs, got {shown} ({len(seen)} candidate start angle(s) "
                         "examined)")
    return tuple(sorted(designs, key=lambda g: (g.defect is not None, g.rms_error)))


def least_squares(x, y, theta0, psi0, *, kind="structural", fit_start=False, start=None, reference=None):
    """Spherical four-bar fitted to more pairs than unknowns, in the least-squares sense.

    ``kind="equation"`` minimises the residual of the spherical Freudenstein equation (3)
    over the pairs (one linear solve; biased, the residual is not the output error).
    ``kind="structural"`` minimises the structural error (结构误差) (7),
    psi_sim(theta0 + x) - psi0 - y, by nonlinear least squares (SciPy), starting from
    `start` or from the linear fit; it never ends worse than its start.

    Parameters
    ----------
    x, y : array_like, shape (n,)
        Input and output rotations, radians; n >= 4.
    theta0, psi0 : float
        Start angles (fixed, or the initial guess when `fit_start`).
    kind : {"structural", "equation"}
    fit_start : bool
        Let the structural fit move theta0 and psi0 too.
    start : FunctionGenerator, optional
        Initial design of the structural fit (its branch is kept).
    reference : (array_like, array_like), optional
        Samples for `max_error` and `rms_error` (default: the pairs).

    Returns
    -------
    design : FunctionGenerator

    Raises
    ------
    ValueError
        For bad pairs or `kind`, if the linear fit gives no real linkage, or if the result
        passes a limit position inside the input range.

    Notes
    -----
    Page ``deriv-spherical-function-generation``. SciPy is imported only by the
    structural fit.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical._function_generation import least_squares
    >>> x = np.linspace(0.0, np.radians(60.0), 31); y = 0.5 * np.sin(x)
    >>> fit = least_squares(x, y, np.radians(40.0), np.radians(80.0))
    >>> fit.max_error < 1e-3
    True
    """
    x, y = function_pairs(x, y, 4)
    distinct_pairs(x, y, exact=False)
    theta0, psi0 = real_number("theta0", theta0), real_number("psi0", psi0)
    kind = option("kind", kind, ("structural", "equation"))
    fit_start = bool_flag("fit_start", fit_start)
    if start is None:
        G, h = _rows(theta0 + x, psi0 + y)
        k = np.linalg.lstsq(G, h, rcond=None)[0]
        try:
            arcs = arcs_from_coefficients(*k)
        except ValueError as exc:      # its message names the coefficients `k1`.., derived here
            raise ValueError(
                f"Expected `x`, `y`, `theta0` and `psi0` whose least-squares fit of equation (3) is a real "
                f"spherical four-bar (or a `start`), got theta0={theta0!r}, psi0={psi0!r} for x={x!r}, "
                f"y={y!r} ({exc})"
            ) from exc
        candidates = [FunctionGenerator(arcs, theta0, psi0, b, x, y) for b in (1, -1)]
        errors = [np.nan_to_num(np.abs(g.structural_error(x, y)), nan=np.pi).sum() for g in candidates]
        start = candidates[int(np.argmin(errors))]
    branch = start.branch
    if kind == "structural":
        from scipy.optimize import least_squares as scipy_least_squares

        def residual(p):
            arcs = p[:4]
            t0, p0 = (p[4], p[5]) if fit_start else (start.theta0, start.psi0)
            psi, disc = _simulate(arcs, t0 + x, branch)
            stalled = np.sqrt(np.maximum(-disc, 0.0))
            A, B, C = spherical_fourbar_abc(*arcs, t0 + x)
            at_limit = abc_solve(A, B, C, 0.0, -branch)
            return np.r_[wrap_angle(np.where(np.isnan(psi), at_limit, psi) - p0 - y), stalled]

        p = np.r_[start.arcs, (start.theta0, start.psi0) if fit_start else ()]
        low = np.r_[np.full(4, 1e-6), (-np.inf, -np.inf) if fit_start else ()]
        high = np.r_[np.full(4, np.pi - 1e-6), (np.inf, np.inf) if fit_start else ()]
        p = scipy_least_squares(residual, np.clip(p, low, high), bounds=(low, high), x_scale="jac",
                                xtol=1e-14, ftol=1e-14, gtol=1e-14).x
        t0, p0 = (p[4], p[5]) if fit_start else (start.theta0, start.psi0)
        start = FunctionGenerator(p[:4], t0, p0, branch, x, y)
    _, defect = _diagnose(start.arcs, start.theta0, start.psi0, np.r_[x.min(), x.max()],
                          np.r_[0.0, 0.0] + start.output(np.r_[x.min(), x.max()]))
    if defect is not None:
        raise ValueError(f"Expected a fit without a limit position in the input range, got defect {defect!r}")
    return FunctionGenerator(start.arcs, start.theta0, start.psi0, branch, x, y, None, reference)
