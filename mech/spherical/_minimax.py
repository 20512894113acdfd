"""Best (minimax, Chebyshev) approximation for spherical function generation, by a Remez
exchange on the structural error (the spherical monograph, §1.8; chapter 6).

Interpolation (`precision_pairs`) meets the function at chosen points, least squares
(`least_squares`) minimises the sum of squared errors; the minimax design minimises the
largest structural error over the samples. For four free arcs its error equioscillates at
five samples: it reaches its largest magnitude there with alternating signs. The Remez
exchange solves for the arcs that make the error alternate with equal magnitude on a
reference set of five samples, moves the reference to the extrema of the new error, and
repeats until the largest error equals the levelled one.
"""

import numpy as np

from mech._validate import function_pairs, integer, naming, nonnegative_number, real_number
from mech._geometry import wrap_angle
from mech.spherical._function_generation import FunctionGenerator, _diagnose, _simulate, least_squares

__all__ = ["minimax"]

_UNKNOWNS = 4       # the four arcs; the start angles stay fixed


def _extrema(e):
    """Indices of the alternating extrema of the samples `e`: local extrema of |e| (ends
    included), same-sign neighbours merged to their largest."""
    n = e.size
    keep = [0]
    for i in range(1, n - 1):
        if (e[i] - e[i - 1]) * (e[i + 1] - e[i]) <= 0.0 and e[i] != e[i - 1]:
            keep.append(i)
    keep.append(n - 1)
    merged = []
    for i in keep:
        if merged and np.sign(e[i]) == np.sign(e[merged[-1]]):
            if abs(e[i]) > abs(e[merged[-1]]):
                merged[-1] = i
        else:
            merged.append(i)
    return merged


def _exchange(e, m):
    """A reference of `m` alternating extrema that holds the largest |e|."""
    ext = _extrema(e)
    top = int(np.argmax(np.abs(e)))
    while len(ext) > m:
        if abs(e[ext[0]]) < abs(e[ext[-1]]) and ext[0] != top:
            ext.pop(0)
        elif ext[-1] != top:
            ext.pop()
        else:
            ext.pop(0)
    return np.array(ext)


def minimax(x, y, theta0, psi0, *, start=None, tol=1e-10, max_iter=40):
    """Spherical four-bar whose largest structural error over the samples is least (§1.8).

    Parameters
    ----------
    x, y : array_like, shape (n,)
        Input and output rotations sampling the function, radians, n >= 5; the error is
        levelled over these samples, so sample densely.
    theta0, psi0 : float
        Start angles (fixed).
    start : FunctionGenerator, optional
        Initial design (its branch is kept). Default: the structural `least_squares` fit.
    tol : float, optional
        Stop when the largest error exceeds the levelled error by at most this fraction.
    max_iter : int, optional
        Largest number of exchanges.

    Returns
    -------
    design : FunctionGenerator
        With ``x``, ``y`` and ``reference`` the samples; ``design.max_error`` is the
        levelled error.

    Raises
    ------
    ValueError
        For bad samples, if the exchange does not converge in `max_iter` steps, or if
        the result passes a limit position inside the input range.

    Notes
    -----
    Eq. (9) of ``deriv-spherical-function-generation``: on the reference x_0 < ... < x_4
    the arcs and the level E solve e(x_i) = (-1)^i E (five equations, SciPy's least squares
    as a Newton solver). SciPy is imported lazily.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import least_squares, minimax
    >>> x = np.linspace(0.0, np.radians(60.0), 301); y = 0.5 * np.sin(x)
    >>> best = minimax(x, y, np.radians(40.0), np.radians(80.0))
    >>> fit = least_squares(x, y, np.radians(40.0), np.radians(80.0))
    >>> best.max_error < fit.max_error
    True
    """
    x, y = function_pairs(x, y, _UNKNOWNS + 1)
    theta0, psi0 = real_number("theta0", theta0), real_number("psi0", psi0)
    tol = nonnegative_number("tol", tol)
    max_iter = integer("max_iter", max_iter, minimum=1)
    order = np.argsort(x)
    x, y = x[order], y[order]
    if start is None:
        start = least_squares(x, y, theta0, psi0)
    elif not isinstance(start, FunctionGenerator):
        raise TypeError(f"Expected `start` to be a FunctionGenerator, got {start!r}")
    from scipy.optimize import least_squares as solve

    branch, m = start.branch, _UNKNOWNS + 1
    signs = (-1.0) ** np.arange(m)

    def error(arcs, where=slice(None)):
        psi, disc = _simulate(arcs, theta0 + x[where], branch)
        return wrap_angle(np.where(np.isnan(psi), np.pi, psi) - psi0 - y[where])

    def reference(e):
        ref = _exchange(e, m)
        if ref.size < m:
            listed, shown = naming(x=x, y=y, theta0=theta0, psi0=psi0)
            raise ValueError(f"Expected {listed} whose structural error alternates at {m} samples (a reference "
                             f"for the exchange), got {shown} with {ref.size} alternating extrema")
        return ref

    arcs = np.array(start.arcs)
    e = error(arcs)
    ref = reference(e)
    level = float(np.mean(signs * e[ref]))
    for _ in range(max_iter):
        def levelled(p, ref=ref):
            return error(p[:4], ref) - signs * p[4]
        p = solve(levelled, np.r_[arcs, level], bounds=(np.r_[np.full(4, 1e-6), -np.inf],
                                                        np.r_[np.full(4, np.pi - 1e-6), np.inf]),
                  xtol=1e-15, ftol=1e-15, gtol=1e-15).x
        arcs, level = p[:4], float(p[4])
        e = error(arcs)
        if np.max(np.abs(e)) <= abs(level) * (1.0 + tol):
            break
        ref = reference(e)
    else:
        raise ValueError(f"Expected the exchange to level the error within `max_iter`={max_iter} steps, got "
                         f"max error {np.max(np.abs(e))!r} against level {abs(level)!r}")
    _, defect = _diagnose(arcs, theta0, psi0, x[[0, -1]], e[[0, -1]] + y[[0, -1]])
    if defect is not None:
        raise ValueError(f"Expected a minimax design without a limit position in the input range, got defect "
                         f"{defect!r}")
    return FunctionGenerator(arcs, theta0, psi0, branch, x, y, None, (x, y))
