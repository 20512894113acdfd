"""Six-bar path synthesis on the sphere (monograph §2.5, with the six-bars of §2.4).

The Stephenson-1, Stephenson-2, Watt-1 and Watt-2 six-bars share one parametrisation: the
four-bar ABCD, the joints E and F on the links that carry them (the table of
``mech.spherical.linkage._sixbars``), the arcs EG and FG, and the coupler point on EG. The
design variables are these fifteen parameters placed by `ground_frame`;
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
from mech._validate import MAX_ANGLE, branch_sign, finite_array, option, real_number
from mech.spherical.path._synthesis import (_FIFTEEN, _bounds, _design, _residual_vectors, _sixbar, _task, _tol,
                                            path_verify)

__all__ = ["path_stephenson1", "path_stephenson2", "path_watt1", "path_watt2"]

#: The link that carries E and the one that carries F, as (origin, toward) of the link's
#: frame; "ground" for a third fixed pivot F given in the ground frame (A toward D).
_CARRIERS = {"stephenson1": (("A", "B"), ("D", "C")), "stephenson2": (("B", "C"), "ground"),
             "watt1": (("B", "C"), ("D", "C")), "watt2": (("D", "C"), "ground")}

_SWEEP = 64                                   # samples of the assembly constraint
_STEP = 1e-7                                  # relative step of the central differences
_NFEV = 500                                   # residual evaluations of a full refinement
_SCREEN, _KEEP = 30, 3                        # with more starts: a short run each, keep 3
_STALL = (20, 1e-3)                           # stop after 20 iterations that gain < 1e-3 of the cost


def _xyz(v):
    return v[..., 0], v[..., 1], v[..., 2]


def _stack(*c):
    return np.stack(np.broadcast_arrays(*c), axis=-1)


def _chain(X, th, branches, kind="stephenson1"):
    """Coupler points and transmission sines of six-bars of type `kind`, in a batch.

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
        joints = {"A": A, "B": B, "C": C, "D": D}
        on_e, on_f = _CARRIERS[kind]
        E = _stack(*_g.spherical_link_point(*_xyz(joints[on_e[0]]), *_xyz(joints[on_e[1]]), er, eg))
        if on_f == "ground":
            # the ground frame's columns: x toward D, y = A x (x), z = A (as `ground_frame`)
            yd = np.cross(A, xd)
            sr = np.sin(fr)[..., None]
            F = sr * np.cos(fg)[..., None] * xd + sr * np.sin(fg)[..., None] * yd + np.cos(fr)[..., None] * A
            F = np.broadcast_to(F, B.shape)
        else:
            F = _stack(*_g.spherical_link_point(*_xyz(joints[on_f[0]]), *_xyz(joints[on_f[1]]), fr, fg))
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
    # its entries are angles and arcs: beyond 2**52 rad float64 names no direction
    if x.size and not np.max(np.abs(x)) < MAX_ANGLE:
        raise ValueError(f"Expected `start` of angles below 2**52 ~ 4.5e15 rad in size, got an entry "
                         f"{float(x.flat[np.argmax(np.abs(x))])!r}")
    return x


def _min_transmission(value):
    if value is None:
        return None
    mu = real_number("min_transmission", value)
    if not 0.0 <= mu < np.pi / 2:
        raise ValueError(f"Expected `min_transmission` in [0, pi/2), got {mu!r}")
    return mu


def _matching_branches(x, branches, th, P, kind="stephenson1"):
    """The branch signs under which `SphericalLinkage.solve` gives the batch result `P`.

    The analysis flips a dyad's sign at every change point it passes after theta = 0; a
    change point before the first prescribed angle would make it disagree with the fixed
    signs of the search. Returns the first of the four sign pairs that agrees (or the
    search's own pair if none does, and the verification then reports the difference).
    """
    pairs = [branches] + [(s1, s2) for s1 in (1, -1) for s2 in (1, -1) if (s1, s2) != branches]
    for pair in pairs:
        Pa = _sixbar(kind, x, pair).solve(th).points["P"]
        if np.all(np.isfinite(Pa)) and np.max(np.abs(Pa - P)) < 1e-9:
            return pair
    return branches


def _path_sixbar(kind, points, theta, start, metric, branches, tol, min_transmission):
    """`path_stephenson1` and its siblings: the search for the six-bar type `kind`."""
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
        P, s = _chain(X, inputs, branches, kind)
        e = _residual_vectors(P[:, :n], Q, metric).reshape(len(X), -1)
        if floor is None:
            return e
        short = np.nan_to_num(np.maximum(0.0, floor - s[:, n:]), nan=0.0).reshape(len(X), -1)
        return np.concatenate((e, short), axis=1)

    # Watt-2: the input four-bar ABCD acts on the rest only through the rocker's turn about
    # D, so turning ABCD about D (the frame, E's angle and F's coordinates together) moves
    # no coupler point; the heading is held at its start value to remove that direction
    # (derivation page, "Counting precision points").
    free = np.ones(15, dtype=bool)
    if kind == "watt2":
        free[2] = False
    k = int(free.sum())

    def full(v, base):
        x = base.copy()
        x[free] = v
        return x

    def refine(x0, max_nfev):
        costs = []

        def stalled(intermediate_result):
            # a noisy fit creeps along a flat valley of the fifteen parameters: stop when
            # the cost fell by less than 1e-3 of itself over the last 20 iterations
            costs.append(intermediate_result.cost)
            if len(costs) > _STALL[0] and costs[-1 - _STALL[0]] - costs[-1] < _STALL[1] * costs[-1]:
                raise StopIteration

        base = np.clip(x0, lo + 1e-12, hi - 1e-12)

        def fun(v):
            return residuals(full(v, base)[None])[0]

        def jac(v):
            x = full(v, base)
            h = (_STEP * np.maximum(1.0, np.abs(x)))[free]
            step = np.zeros((k, 15))
            step[:, free] = np.diag(h)
            R = residuals(np.concatenate((x + step, x - step)))
            return ((R[:k] - R[k:]) / (2.0 * h[:, None])).T

        # SciPy's bounded trust region converges slowly on these ill-conditioned fits (an
        # exact Stephenson-2 fit stalls at 1e-7 rad where Levenberg-Marquardt reaches 1e-15
        # in a tenth of the evaluations), and the optimum lies inside the bounds as a rule:
        # the bounded search (with its stall test) runs only when it does not
        options = dict(jac=jac, xtol=1e-10, ftol=1e-9, gtol=1e-12, max_nfev=max_nfev)
        sol = least_squares(fun, base[free], method="lm", **options)
        used = sol.nfev + 2 * k * sol.njev
        if not np.all((lo[free] < sol.x) & (sol.x < hi[free])):
            sol = least_squares(fun, base[free], bounds=(lo[free], hi[free]), callback=stalled, **options)
            used += sol.nfev + 2 * k * sol.njev
        sol.x = full(sol.x, base)
        return sol, used

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
        P = _chain(sol.x[None], th, branches, kind)[0][0]
        linkage = _sixbar(kind, sol.x, _matching_branches(sol.x, branches, th, P, kind))
        v = path_verify(linkage, Q, th, tol)
        key = (not v["passes"], not v["in_order"], v["rms_error"])
        if best is None or key < best[0]:
            best = (key, sol.x, linkage)
    seconds = time.perf_counter() - t0
    return _design(best[2], kind, "distance", best[1], _FIFTEEN, Q, th, tol, seconds, evaluations)


_DOC = """Synthesise a {name} spherical six-bar path generator with prescribed input angles.

    Minimises ``sum_i dist(P(x, theta_i), Q_i)^2`` over the fifteen parameters ``x = (lon,
    lat, heading, a, b, c, d, E_r, E_gamma, F_r, F_gamma, e, f, r, gamma)`` of
    `{kind}` placed by `ground_frame` (monograph §§{section}, 2.5), subject to both dyads
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
        Starting parameters in the order above (E and F as ``(r, gamma)`` on {carriers}, ``e, f`` the arcs EG and FG, ``r, gamma`` the coupler point on EG).
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
    result is rebuilt with `{kind}` and verified with `path_verify` (sweep of 2001
    inputs). The constraint is what makes the points be met in order on noisy data: see
    :ref:`book-spherical-path-synthesis`.

{examples}"""


def path_stephenson1(points, theta, start, *, metric="arc", branches=(1, 1), tol=1e-3,
                     min_transmission=np.radians(30.0)):
    return _path_sixbar("stephenson1", points, theta, start, metric, branches, tol, min_transmission)


def path_stephenson2(points, theta, start, *, metric="arc", branches=(1, 1), tol=1e-3,
                     min_transmission=np.radians(30.0)):
    return _path_sixbar("stephenson2", points, theta, start, metric, branches, tol, min_transmission)


def path_watt1(points, theta, start, *, metric="arc", branches=(1, 1), tol=1e-3,
               min_transmission=np.radians(30.0)):
    return _path_sixbar("watt1", points, theta, start, metric, branches, tol, min_transmission)


def path_watt2(points, theta, start, *, metric="arc", branches=(1, 1), tol=1e-3,
               min_transmission=np.radians(30.0)):
    return _path_sixbar("watt2", points, theta, start, metric, branches, tol, min_transmission)


def _fill(template, **fields):
    # str.format would trip on the literal braces of the option sets in the docstring
    for key, value in fields.items():
        template = template.replace("{" + key + "}", value)
    return template


_EXAMPLE = """    Examples
    --------
    >>> import numpy as np
    >>> from mech.spherical import {function}
    >>> from mech.spherical.path._synthesis import _sixbar
    >>> x = np.array({x})
    >>> th = np.linspace({th})
    >>> Q = _sixbar("{kind}", x, (1, 1)).solve(th).points["P"]
    >>> d = {function}(Q, th, x + 0.02)
    >>> bool(d.passes), d.max_error < 1e-6
    (True, True)
"""

#: a six-bar of each type that assembles on 0 <= theta <= 5.8 with both transmission
#: angles above 30 degrees (the examples and the tests start near it)
KNOWN = {
    "stephenson1": [0.2, 1.1, 0.3, 0.3, 0.9, 0.7, 1.0, 0.2, 0.8, 0.3, -1.0, 0.8, 0.7, 0.4, 0.5],
    "stephenson2": [0.2, 1.1, 0.3, 0.3, 0.9, 0.7, 1.0, 0.4, 0.7, 1.2, 0.5, 0.7, 0.6, 0.3, -0.4],
    "watt1": [0.2, 1.1, 0.3, 0.3, 0.9, 0.7, 1.0, 0.5, 0.6, 0.4, 0.9, 0.7, 0.8, 0.3, 0.4],
    "watt2": [0.2, 1.1, 0.3, 0.3, 0.9, 0.7, 1.0, 0.3, 0.5, 1.4, 0.4, 0.6, 0.5, 0.3, 0.4],
}
for _f, _name, _section, _carriers in (
        (path_stephenson1, "Stephenson-1", "2.4.1", "the crank and the rocker"),
        (path_stephenson2, "Stephenson-2", "2.4.2", "the coupler and the ground (F fixed)"),
        (path_watt1, "Watt-1", "2.4.3", "the coupler and the rocker"),
        (path_watt2, "Watt-2", "2.4.4", "the rocker and the ground (F fixed)")):
    _kind = _f.__name__[5:]
    _f.__doc__ = _fill(_DOC, name=_name, kind=_kind, section=_section, carriers=_carriers,
                       examples=_fill(_EXAMPLE, function=_f.__name__, kind=_kind,
                                      x="[" + ", ".join(str(v) for v in KNOWN[_kind]) + "]",
                                      th="0.0, 5.8, 16" if _kind == "watt2" else "0.0, 3.2, 12"))
