"""Stephenson-1 path synthesis on the sphere (monograph §2.5, with the six-bar of §2.4.1).

The design variables are the fifteen parameters of `stephenson1` placed by `ground_frame`;
the residuals are the distances from the coupler point that the parametric form (§2.4.1)
gives at each prescribed input angle to its prescribed point, as for the four-bar in
``_synthesis``. Two things are added for a six-bar:

* an assembly constraint: on a dense sweep of the input between the first and the last
  prescribed angle, the sine of each dyad's transmission angle (the angle at its joint)
  must stay above ``sin(min_transmission)``. Without it, a fit to noisy points may pass
  a dead point between two prescribed angles: every point is reached, but the linkage
  cannot move from one to the next by turning its crank;
* a fast batch evaluation of the chain (crank, dyad B-C-D, points E and F, dyad E-G-F,
  point P) straight from the generated formulas, for many parameter vectors at once, so
  that the central-difference Jacobian costs one vectorised call. The designed linkage is
  then rebuilt as a `SphericalLinkage` and verified by `path_verify`.

SciPy is imported when a synthesis runs, never at ``import mech``.
"""

import time

import numpy as np

from mech._generated import spherical_linkage as _g
from mech._validate import branch_sign, finite_array, option, real_number
from mech.spherical.path._synthesis import (_FIFTEEN, _bounds, _design, _residual_vectors, _stephenson, _task,
                                            _tol, path_verify)

__all__ = ["path_stephenson1"]

_SWEEP = 64                                   # samples of the assembly constraint
_STEP = 1e-7                                  # relative step of the central differences
_NFEV = 500                                   # residual evaluations of a full refinement
_SCREEN, _KEEP = 30, 3                        # with more starts: a short run each, keep 3
_STALL = (20, 1e-3)                           # stop after 20 iterations that gain < 1e-3 of the cost


def _xyz(v):
    return v[..., 0], v[..., 1], v[..., 2]


def _stack(*c):
    return np.stack(np.broadcast_arrays(*c), axis=-1)


def _chain(X, th, branches):
    """Coupler points and transmission sines of Stephenson-1 six-bars, in a batch.

    ``X`` has shape (k, 15) (parameters in the order of ``_FIFTEEN``), ``th`` shape (m,).
    Returns ``P`` of shape (k, m, 3) (NaN where a dyad does not assemble) and ``s`` of
    shape (k, m, 2): for each dyad ``sign(rho) sqrt(|rho|) / (sin b1 sin b2)``, which is
    the sine of the transmission angle where the dyad assembles (``sqrt(rho)`` is
    ``det[P1, P2, J]``, eq. (4) of the linkage derivation) and negative where it does not.
    The branch signs are held fixed: no change point is crossed (the constraint keeps
    every radicand away from zero).
    """
    col = [X[:, j][:, None] for j in range(15)]
    lon, lat, heading, a, b, c, d, er, eg, fr, fg, e, f, r, gamma = col
    cl, sl, co, so = np.cos(lat), np.sin(lat), np.cos(lon), np.sin(lon)
    ch, sh = np.cos(heading)[..., None], np.sin(heading)[..., None]
    A = _stack(cl * co, cl * so, sl)                         # ground_frame, column 3
    xd = ch * _stack(sl * co, sl * so, -cl) + sh * _stack(-so, co, 0.0 * lon)
    D = np.sin(d)[..., None] * xd + np.cos(d)[..., None] * A
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        B = _stack(*_g.spherical_link_point(*_xyz(A), *_xyz(D), a, th))
        rho1 = _g.spherical_dyad_radicand(*_xyz(B), *_xyz(D), b, c)
        C = _stack(*_g.spherical_dyad_position(*_xyz(B), *_xyz(D), b, c, branches[0], rho1))
        E = _stack(*_g.spherical_link_point(*_xyz(A), *_xyz(B), er, eg))
        F = _stack(*_g.spherical_link_point(*_xyz(D), *_xyz(C), fr, fg))
        rho2 = _g.spherical_dyad_radicand(*_xyz(E), *_xyz(F), e, f)
        G = _stack(*_g.spherical_dyad_position(*_xyz(E), *_xyz(F), e, f, branches[1], rho2))
        P = _stack(*_g.spherical_link_point(*_xyz(E), *_xyz(G), r, gamma))
        s1 = np.sign(rho1) * np.sqrt(np.abs(rho1)) / (np.sin(b) * np.sin(c))
        s2 = np.sign(rho2) * np.sqrt(np.abs(rho2)) / (np.sin(e) * np.sin(f))
    return P, np.stack(np.broadcast_arrays(s1, s2), axis=-1)


def _starts(start):
    x = finite_array("start", start)
    if x.shape == (15,):
        x = x[None]
    if x.ndim != 2 or x.shape[1] != 15 or x.shape[0] < 1:
        raise ValueError(f"Expected `start` of shape (15,) or (k, 15), got shape {x.shape}")
    return x


def _min_transmission(value):
    if value is None:
        return None
    mu = real_number("min_transmission", value)
    if not 0.0 <= mu < np.pi / 2:
        raise ValueError(f"Expected `min_transmission` in [0, pi/2), got {mu!r}")
    return mu


def _matching_branches(x, branches, th, P):
    """The branch signs under which `SphericalLinkage.solve` gives the batch result `P`.

    The analysis flips a dyad's sign at every change point it passes after theta = 0; a
    change point before the first prescribed angle would make it disagree with the fixed
    signs of the search. Returns the first of the four sign pairs that agrees (or the
    search's own pair if none does, and the verification then reports the difference).
    """
    pairs = [branches] + [(s1, s2) for s1 in (1, -1) for s2 in (1, -1) if (s1, s2) != branches]
    for pair in pairs:
        Pa = _stephenson(x, pair).solve(th).points["P"]
        if np.all(np.isfinite(Pa)) and np.max(np.abs(Pa - P)) < 1e-9:
            return pair
    return branches


def path_stephenson1(points, theta, start, *, metric="arc", branches=(1, 1), tol=1e-3,
                     min_transmission=np.radians(30.0)):
    """Synthesise a Stephenson-1 spherical six-bar path generator with prescribed input angles.

    Minimises ``sum_i dist(P(x, theta_i), Q_i)^2`` over the fifteen parameters ``x = (lon,
    lat, heading, a, b, c, d, E_r, E_gamma, F_r, F_gamma, e, f, r, gamma)`` of
    `stephenson1` placed by `ground_frame` (monograph §§2.4.1, 2.5), subject to both dyads
    keeping a transmission angle of at least `min_transmission` on a sweep of 64 inputs
    from ``theta[0]`` to ``theta[-1]`` (a penalty), and verifies the result by analysis
    with `SphericalLinkage` (`path_verify`).

    Parameters
    ----------
    points : array_like, shape (n, 3)
        Prescribed points, unit vectors.
    theta : array_like, shape (n,)
        Prescribed crank angles, strictly monotonic within one turn, radians.
    start : array_like, shape (15,) or (k, 15)
        Starting parameters in the order above (E and F as ``(r, gamma)`` on the crank and
        the rocker, ``e, f`` the arcs EG and FG, ``r, gamma`` the coupler point on EG).
        With k starts (k > 3), each is first run for 30 residual evaluations, the three
        with the smallest cost are refined, and the best verified design is returned (the
        one that passes with the smallest RMS error, else the smallest RMS error in order).
    metric : {"arc", "chord"}, optional
    branches : (int, int), optional
        Branches of the dyads B-C-D and E-G-F, kept throughout.
    tol : float, optional
        Arc error allowed for `SphericalPathDesign.passes`, radians.
    min_transmission : float or None, optional
        Smallest transmission angle of either dyad allowed between the first and the
        last prescribed input, radians in [0, pi/2) (default 30 degrees, as the planar
        `path_synthesis_model`); 0 asks only that the linkage assembles there, None
        drops the constraint (the points alone).

    Returns
    -------
    SphericalPathDesign
        ``evaluations`` counts residual evaluations of one linkage, the batched Jacobian
        included (30 per Jacobian); ``seconds`` covers all starts.

    Notes
    -----
    The residuals and the assembly constraint come from a batch evaluation of the
    parametric six-bar (the generated formulas of :ref:`deriv-spherical-linkage`), and
    the Jacobian from central differences over all fifteen parameters in one call; the
    result is rebuilt with `stephenson1` and verified with `path_verify` (sweep of 2001
    inputs). The constraint is what makes the points be met in order on noisy data: see
    :ref:`book-spherical-path-synthesis`.

    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import path_stephenson1
    >>> from mech.spherical.path._synthesis import _stephenson
    >>> x = np.array([0.2, 1.1, 0.3, 0.3, 0.9, 0.7, 1.0, 0.2, 0.8, 0.3, -1.0, 0.8, 0.7, 0.4, 0.5])
    >>> th = np.linspace(0.0, 1.6, 7)
    >>> Q = _stephenson(x, (1, 1)).solve(th).points["P"]
    >>> d = path_stephenson1(Q, th, x + 0.02)
    >>> bool(d.passes), d.max_error < 1e-6
    (True, True)
    """
    Q, th = _task(points, theta)
    starts = _starts(start)
    metric = option("metric", metric, ("arc", "chord"))
    if not isinstance(branches, (tuple, list)) or len(branches) != 2:
        raise ValueError(f"Expected `branches` to be two signs (+1 or -1), got {branches!r}")
    branches = tuple(branch_sign(v, "branches") for v in branches)
    tol = _tol(tol)
    mu = _min_transmission(min_transmission)
    floor = None if mu is None else np.sin(mu)
    from scipy.optimize import least_squares

    lo, hi = _bounds(_FIFTEEN)
    n = th.size
    inputs = th if floor is None else np.concatenate((th, np.linspace(th[0], th[-1], _SWEEP)))

    def residuals(X):
        P, s = _chain(X, inputs, branches)
        e = _residual_vectors(P[:, :n], Q, metric).reshape(len(X), -1)
        if floor is None:
            return e
        short = np.nan_to_num(np.maximum(0.0, floor - s[:, n:]), nan=0.0).reshape(len(X), -1)
        return np.concatenate((e, short), axis=1)

    def jac(x):
        h = _STEP * np.maximum(1.0, np.abs(x))
        R = residuals(np.concatenate((x + np.diag(h), x - np.diag(h))))
        return ((R[:15] - R[15:]) / (2.0 * h[:, None])).T

    def refine(x0, max_nfev):
        costs = []

        def stalled(intermediate_result):
            # a noisy fit creeps along a flat valley of the fifteen parameters: stop when
            # the cost fell by less than 1e-3 of itself over the last 20 iterations
            costs.append(intermediate_result.cost)
            if len(costs) > _STALL[0] and costs[-1 - _STALL[0]] - costs[-1] < _STALL[1] * costs[-1]:
                raise StopIteration

        sol = least_squares(lambda x: residuals(x[None])[0], np.clip(x0, lo + 1e-12, hi - 1e-12), jac=jac,
                            bounds=(lo, hi), xtol=1e-10, ftol=1e-9, gtol=1e-12, max_nfev=max_nfev,
                            callback=stalled)
        return sol, sol.nfev + 30 * sol.njev

    t0 = time.perf_counter()
    evaluations = 0
    if len(starts) > _KEEP:
        # screen: a short run from every start, then refine the most promising ones
        screened = []
        for x0 in starts:
            sol, used = refine(x0, _SCREEN)
            evaluations += used
            screened.append((sol.cost, sol.x))
        starts = [x for _, x in sorted(screened, key=lambda item: item[0])[:_KEEP]]
    best = None
    for x0 in starts:
        sol, used = refine(x0, _NFEV)
        evaluations += used
        P = _chain(sol.x[None], th, branches)[0][0]
        linkage = _stephenson(sol.x, _matching_branches(sol.x, branches, th, P))
        v = path_verify(linkage, Q, th, tol)
        key = (not v["passes"], not v["in_order"], v["rms_error"])
        if best is None or key < best[0]:
            best = (key, sol.x, linkage)
    seconds = time.perf_counter() - t0
    return _design(best[2], "stephenson1", "distance", best[1], _FIFTEEN, Q, th, tol, seconds, evaluations)
