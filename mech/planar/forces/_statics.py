"""Static force analysis of a solved planar linkage, with and without friction.

The group formulas come from ``derivations/planar/statics.md`` through
``mech._generated.statics``. This module walks the groups of a `Linkage` in the reverse
of their solving order (the group farthest from the driver first, F60), carries the
reactions of each solved group onto the links it hangs on, and ends at the drivers with
the balancing moment or force. Friction (friction circles in revolute pairs, friction
angles in sliding pairs, senses from the solved velocities) enters as couples and forces
whose sizes depend on the reactions; that nonlinear system is solved by Newton's method.
"""

from __future__ import annotations

from types import MappingProxyType

import numpy as np

from mech._errors import AssemblyError, InputTypeError
from mech._generated import statics as _g
from mech._geometry import plane_cross
from mech._validate import common_shape, finite_array, instance, integer, nonnegative_number, planar_points
from mech.planar.kinematics._linkage import LinkageSolution

__all__ = ["StaticForces", "static_forces", "as_linkage"]

GROUND = "ground"


def _re_im(z):
    return np.real(z), np.imag(z)


# ----------------------------------------------------------------------------- conversion
def as_linkage(mechanism):
    """The `Linkage` equivalent of a `FourBar` or a `SliderCrank`, for `static_forces`.

    A four-bar becomes ground points A = 0 and D = d, the crank ``"crank"`` (A->B), and an
    RRR group ``("coupler", "rocker")`` with joint C on the same branch; a nonzero coupler
    point is added as point ``"P"`` of the coupler. A slider-crank becomes the crank and an
    RRP group ``("rod", "slider")`` whose block C runs on the ground line y = e.

    Examples
    --------
    >>> from mech.planar import FourBar
    >>> lk = as_linkage(FourBar(1, 3, 2.5, 3))
    >>> lk.groups
    ('crank crank', 'RRR coupler-rocker')
    """
    from mech.planar.kinematics._fourbar import FourBar
    from mech.planar.kinematics._linkage import Guide, Linkage
    from mech.planar.kinematics._slider_crank import SliderCrank

    if isinstance(mechanism, FourBar):
        lk = (Linkage({"A": 0.0, "D": mechanism.d})
              .crank("crank", pivot="A", tip="B", length=mechanism.a)
              .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(mechanism.b, mechanism.c),
                   branch=mechanism.branch))
        p, q = mechanism.coupler
        if p or q:
            lk = lk.point("P", link="coupler", at=complex(p, q))
        return lk
    if isinstance(mechanism, SliderCrank):
        return (Linkage({"A": 0.0})
                .crank("crank", pivot="A", tip="B", length=mechanism.a)
                .rrp(("rod", "slider"), pin="B", guide=Guide(GROUND, complex(0.0, mechanism.e), 0.0),
                     joint="C", length=mechanism.b, branch=mechanism.branch))
    raise InputTypeError(f"Expected `mechanism` to be a FourBar or a SliderCrank, got {type(mechanism).__name__}")


# ----------------------------------------------------------------------------- the pairs
class _Pair:
    """One pair: the reaction is the force on ``links[1]`` from ``links[0]``."""

    __slots__ = ("kind", "links", "name", "at", "e", "rate", "slide")

    def __init__(self, kind, links, name, at, e=None, rate=None, slide=None):
        self.kind, self.links, self.name, self.at, self.e, self.rate, self.slide = (
            kind, links, name, at, e, rate, slide)


def _omega(sol, link):
    return 0.0 if link == GROUND else sol.omegas[link]


def _pairs(sol):
    """Every pair of the linkage with its place, guide direction and relative rate."""
    lk, P = sol.linkage, sol.points
    owner = lk._points
    rated = sol.order >= 1
    out = []

    def rev(i, j, pin):
        rate = _omega(sol, j) - _omega(sol, i) if rated else None
        out.append(_Pair("R", (i, j), pin, P[pin], rate=rate))

    def pri(guiding, moving, at, name):
        sl = sol.slides[(moving, guiding)]
        out.append(_Pair("P", (guiding, moving), name, at, e=sl.direction,
                         rate=sl.v if rated else None, slide=(moving, guiding)))

    for st in lk._steps:
        k, L = st.kind, st.links
        if k == "crank":
            rev(owner[st.get("pivot")], L[0], st.get("pivot"))
        elif k == "slider":
            pri(L[1], L[0], P[st.get("point")], st.get("point"))
        elif k == "rrr":
            (p1, p2), j = st.get("pins"), st.get("joint")
            rev(owner[p1], L[0], p1), rev(owner[p2], L[1], p2), rev(L[0], L[1], j)
        elif k == "rrp":
            p1, g, j = st.get("pin"), st.get("guide"), st.get("joint")
            rev(owner[p1], L[0], p1), rev(L[0], L[1], j), pri(g.link, L[1], P[j], j)
        elif k == "rpr":
            p1, p2 = st.get("pins")
            rev(owner[p1], L[0], p1), rev(owner[p2], L[1], p2), pri(L[0], L[1], P[p2], p2)
        elif k == "prp":
            (g1, g2), j = st.get("guides"), st.get("joint")
            pri(g1.link, L[0], P[j], j), pri(g2.link, L[1], P[j], j), rev(L[0], L[1], j)
        elif k == "rpp":
            p1, g, pt = st.get("pin"), st.get("guide"), st.get("point")
            rev(owner[p1], L[0], p1), pri(L[1], L[0], P[p1], p1), pri(g.link, L[1], P[pt], pt)
    return out


# ----------------------------------------------------------------------------- linear statics
class _Loads:
    """Resultant force and moment about the origin on every moving link."""

    def __init__(self, shape):
        self.F, self.M, self.shape = {}, {}, shape

    def force(self, link, f, at):
        if link == GROUND:
            return
        self.F[link] = self.F.get(link, 0.0) + f
        self.M[link] = self.M.get(link, 0.0) + plane_cross(at, f)

    def couple(self, link, m):
        if link != GROUND:
            self.M[link] = self.M.get(link, 0.0) + m

    def get(self, link, about):
        """Resultant force and its moment about the point ``about``."""
        F = self.F.get(link, 0.0) + np.zeros(self.shape)
        return F, self.M.get(link, 0.0) - plane_cross(about, F)


def _linear(sol, loads):
    """Frictionless statics for the given loads: pair forces, couples and efforts.

    Returns ``(force, couple, effort)``: dicts keyed by the pair's links (force on the
    later link from the earlier), by the same keys for sliding pairs, and by driver.
    """
    lk, P, owner = sol.linkage, sol.points, sol.linkage._points
    force, couple, effort = {}, {}, {}
    n_of = lambda e: 1j * e
    for st in reversed(lk._steps):
        k, L = st.kind, st.links
        if k in ("ground", "point"):
            continue
        if k == "crank":
            pivot = st.get("pivot")
            o = owner[pivot]
            F, M = loads.get(L[0], P[pivot])
            force[(o, L[0])], effort[st.get("driver")] = -F, -M
            loads.force(o, F, P[pivot])
            loads.couple(o, M)
        elif k == "slider":
            g, pt = L[1], P[st.get("point")]
            e = sol.slides[(L[0], g)].direction
            F, M = loads.get(L[0], pt)
            Fb, N, C = _g.slider_reactions(*_re_im(e), *_re_im(F), M)
            force[(g, L[0])], couple[(g, L[0])], effort[st.get("driver")] = N * n_of(e), C, Fb
            loads.force(g, -(N * n_of(e) + Fb * e), pt)
            loads.couple(g, -C)
        elif k == "rrr":
            (p1, p2), J = st.get("pins"), P[st.get("joint")]
            F1, M1 = loads.get(L[0], J)
            F2, M2 = loads.get(L[1], J)
            r = _g.rrr_reactions(*_re_im(J - P[p1]), *_re_im(J - P[p2]), *_re_im(F1), M1, *_re_im(F2), M2)
            R1, R2, RJ = r[0] + 1j * r[1], r[2] + 1j * r[3], r[4] + 1j * r[5]
            force[(owner[p1], L[0])], force[(owner[p2], L[1])], force[(L[0], L[1])] = R1, R2, RJ
            loads.force(owner[p1], -R1, P[p1])
            loads.force(owner[p2], -R2, P[p2])
        elif k == "rrp":
            p1, g, J = st.get("pin"), st.get("guide").link, P[st.get("joint")]
            e = sol.slides[(L[1], g)].direction
            F1, M1 = loads.get(L[0], J)
            F2, M2 = loads.get(L[1], J)
            R1x, R1y, RJx, RJy, N, C = _g.rrp_reactions(*_re_im(J - P[p1]), *_re_im(e), *_re_im(F1), M1,
                                                        *_re_im(F2), M2)
            R1 = R1x + 1j * R1y
            force[(owner[p1], L[0])], force[(L[0], L[1])] = R1, RJx + 1j * RJy
            force[(g, L[1])], couple[(g, L[1])] = N * n_of(e), C
            loads.force(owner[p1], -R1, P[p1])
            loads.force(g, -N * n_of(e), J)
            loads.couple(g, -C)
        elif k == "rpr":
            p1, p2 = st.get("pins")
            e = sol.slides[(L[1], L[0])].direction
            F1, M1 = loads.get(L[0], P[p1])
            F2, M2 = loads.get(L[1], P[p2])
            R1x, R1y, R2x, R2y, N, C = _g.rpr_reactions(*_re_im(P[p2] - P[p1]), *_re_im(e), *_re_im(F1), M1,
                                                        *_re_im(F2), M2)
            R1, R2 = R1x + 1j * R1y, R2x + 1j * R2y
            force[(owner[p1], L[0])], force[(owner[p2], L[1])] = R1, R2
            force[(L[0], L[1])], couple[(L[0], L[1])] = N * n_of(e), C
            loads.force(owner[p1], -R1, P[p1])
            loads.force(owner[p2], -R2, P[p2])
        elif k == "prp":
            (g1, g2), J = st.get("guides"), P[st.get("joint")]
            e1 = sol.slides[(L[0], g1.link)].direction
            e2 = sol.slides[(L[1], g2.link)].direction
            F1, M1 = loads.get(L[0], J)
            F2, M2 = loads.get(L[1], J)
            N1, C1, N2, C2, RJx, RJy = _g.prp_reactions(*_re_im(e1), *_re_im(e2), *_re_im(F1), M1, *_re_im(F2), M2)
            force[(g1.link, L[0])], couple[(g1.link, L[0])] = N1 * n_of(e1), C1
            force[(g2.link, L[1])], couple[(g2.link, L[1])] = N2 * n_of(e2), C2
            force[(L[0], L[1])] = RJx + 1j * RJy
            loads.force(g1.link, -N1 * n_of(e1), J)
            loads.couple(g1.link, -C1)
            loads.force(g2.link, -N2 * n_of(e2), J)
            loads.couple(g2.link, -C2)
        elif k == "rpp":
            p1, g, J = st.get("pin"), st.get("guide").link, P[st.get("point")]
            e = sol.slides[(L[1], g)].direction
            w = sol.slides[(L[0], L[1])].direction
            F1, M1 = loads.get(L[0], P[p1])
            F2, M2 = loads.get(L[1], J)
            R1x, R1y, Ni, Ci, No, Co = _g.rpp_reactions(*_re_im(P[p1] - J), *_re_im(e), *_re_im(w), *_re_im(F1),
                                                        M1, *_re_im(F2), M2)
            R1 = R1x + 1j * R1y
            force[(owner[p1], L[0])] = R1
            force[(L[1], L[0])], couple[(L[1], L[0])] = Ni * n_of(w), Ci
            force[(g, L[1])], couple[(g, L[1])] = No * n_of(e), Co
            loads.force(owner[p1], -R1, P[p1])
            loads.force(g, -No * n_of(e), J)
            loads.couple(g, -Co)
        else:  # pragma: no cover - every step kind of Linkage is handled above
            raise ValueError(f"Expected a known step kind, got {k!r}")
    return force, couple, effort


# ----------------------------------------------------------------------------- the result
class StaticForces:
    """Pair reactions and balancing efforts of a linkage at an array of poses (immutable).

    Attributes
    ----------
    reactions : mapping of (str, str) to complex ndarray
        The total reaction on link ``j`` from link ``i`` under the key ``(i, j)`` (the
        textbook's R_ij), for every pair, under both orders of the key
        (``reactions[j, i] == -reactions[i, j]``). For a sliding pair it is the normal
        force plus the friction force.
    lines : mapping of (str, str) to complex ndarray
        A point of the line of action of each reaction: for a revolute pair the foot of
        the perpendicular from the pin (on the friction circle when there is friction);
        for a sliding pair the point of the guide line where the normal force acts.
    efforts : mapping of str to float ndarray
        The balancing moment of each crank driver and the balancing force (along its
        guide) of each slider driver: the effort the driver must exert.
    frictionless : mapping of str to float ndarray
        The efforts without friction, for the same loads.
    efficiency : float ndarray
        Instantaneous efficiency: frictionless over actual driving power (1 without
        friction); NaN where the linkage self-locks.
    self_locking : bool ndarray
        Where no finite driving effort moves the linkage in the sense of its solved
        velocities (the required effort is infinite or of the wrong sign).
    """

    def __init__(self, reactions, lines, efforts, frictionless, efficiency, self_locking):
        self.reactions = MappingProxyType(reactions)
        self.lines = MappingProxyType(lines)
        self.efforts = MappingProxyType(efforts)
        self.frictionless = MappingProxyType(frictionless)
        self.efficiency = efficiency
        self.self_locking = self_locking

    @property
    def balancing(self):
        """The effort of the only driver (ValueError if there are several)."""
        if len(self.efforts) != 1:
            raise ValueError(f"Expected one driver, got {list(self.efforts)}; use `efforts[name]`")
        return next(iter(self.efforts.values()))

    def __setattr__(self, name, value):
        if name in self.__dict__:
            raise AttributeError("StaticForces is immutable")
        object.__setattr__(self, name, value)

    def __repr__(self):
        return f"StaticForces(drivers={list(self.efforts)}, pairs={len(self.reactions) // 2})"


# ----------------------------------------------------------------------------- inputs
def _fits(name, value, shape):
    """A load must broadcast to the solution's shape (one value per solved pose, or one for all)."""
    if common_shape(**{name: value, "solution": np.empty(shape)}) != shape:
        raise ValueError(f"Expected `{name}` of a shape that broadcasts to the solution's {shape}, "
                         f"got shape {np.shape(value)}")


def _load_table(sol, forces, couples):
    lk = sol.linkage
    pts, links = lk._points, set(lk.links)
    if forces is not None and (isinstance(forces, (str, bytes)) or not hasattr(forces, "__iter__")):
        raise InputTypeError(f"Expected `forces` to be a mapping of points to forces, got {forces!r}")
    items = forces.items() if hasattr(forces, "items") else (forces or ())
    out_f = []
    for key, f in items:
        point, link = (key, None) if isinstance(key, str) else tuple(key)
        lk._need_point(point)
        link = pts[point] if link is None else link
        lk._need_link(link)
        f = planar_points(f"forces[{point!r}]", f)
        _fits(f"forces[{point!r}]", f, sol.valid.shape)
        out_f.append((link, point, f))
    out_c = []
    if couples is not None and not hasattr(couples, "items"):
        raise InputTypeError(f"Expected `couples` to be a mapping of links to couples, got {couples!r}")
    for link, m in dict(couples or {}).items():
        lk._need_link(link)
        m = finite_array(f"couples[{link!r}]", m)
        _fits(f"couples[{link!r}]", m, sol.valid.shape)
        out_c.append((link, m))
    if any(link == GROUND for link, _, _ in out_f) or any(link == GROUND for link, _ in out_c):
        raise ValueError("Expected `forces` and `couples` on moving links, got a load on 'ground'")
    return out_f, out_c


def _coefficients(pairs, value, kind, what):
    """Per-pair coefficient from a float or a mapping (pin name / (moving, guiding) key)."""
    names = {p.name if kind == "R" else p.slide for p in pairs if p.kind == kind}
    if hasattr(value, "items"):
        unknown = [k for k in value if k not in names]
        if unknown:
            raise ValueError(f"Expected `{what}` keys among {sorted(names, key=str)}, got {unknown[0]!r}")
        table = dict(value)
    else:
        v = nonnegative_number(what, value)     # checked even where no pair of this kind exists
        table = {n: v for n in names}
    out = {}
    for k, v in table.items():
        out[k] = nonnegative_number(f"{what}[{k!r}]", v)
    return [out.get(p.name if kind == "R" else p.slide, 0.0) if p.kind == kind else 0.0 for p in pairs]


def _check_two_force_members(sol, pairs, rho, loaded):
    """A loaded-free link with two pins only: the friction circles must fit between the pins."""
    by_link = {}
    for p, r in zip(pairs, rho):
        for link in p.links:
            by_link.setdefault(link, []).append((p, r))
    drivers = {st.links[0] for st in sol.linkage._steps if st.kind in ("crank", "slider")}
    for link, items in by_link.items():
        if link == GROUND or link in loaded or link in drivers or len(items) != 2:
            continue
        if any(p.kind != "R" for p, _ in items) or not any(r > 0 for _, r in items):
            continue
        (pa, ra), (pb, rb) = items
        span = float(np.min(np.abs(pa.at - pb.at)))
        if ra + rb >= span:
            raise ValueError(
                f"Expected `rho` with the friction circles of the two-force member {link!r} fitting between "
                f"its pins (rho_{pa.name} + rho_{pb.name} < |{pa.name}{pb.name}| = {span!r}), got "
                f"rho_{pa.name}={ra!r}, rho_{pb.name}={rb!r}: the cross tangent does not exist")


def _check_valid(sol):
    if not np.all(sol.valid):
        idx = tuple(int(i) for i in np.unravel_index(np.flatnonzero(~sol.valid)[0], sol.valid.shape))
        raise AssemblyError(f"Expected every pose to be assembled, got a pose that cannot be assembled at "
                            f"index {idx}; solve only inputs where the linkage assembles")


# ----------------------------------------------------------------------------- the solver
def static_forces(solution, forces=None, couples=None, *, rho=0.0, mu=0.0, tol=1e-12, max_iter=60):
    """Pair reactions and the balancing effort of a solved linkage under static loads.

    Equilibrium of every link with the given loads (inertia neglected), solved one class
    II group at a time from the last group back to the drivers (F60). Without friction
    each revolute pair transmits a force through its pin and each sliding pair a force
    normal to its guide. With friction the reaction of a revolute pair is tangent to its
    friction circle of radius ``rho`` (eq. 2-19), on the side that opposes the relative
    rotation, and that of a sliding pair is tilted by the friction angle atan(``mu``)
    against the relative sliding (F2); the senses come from the solved velocities.

    Parameters
    ----------
    solution : LinkageSolution
        ``Linkage.solve(...)`` at the poses wanted; ``order >= 1`` when there is friction
        (the velocities give the senses of the relative motions). Use `as_linkage` for a
        `FourBar` or a `SliderCrank`.
    forces : mapping or iterable of pairs, optional
        Applied forces (complex, broadcast against the poses) keyed by point name, acting
        on the link that first carries the point (at a joint: the group's first link), or
        by ``(point, link)``, e.g. ``("C", "slider")`` for a load on a slider's block.
    couples : mapping of str to float, optional
        Applied couples (counter-clockwise positive) keyed by link.
    rho : float or mapping of str to float
        Friction-circle radius of every revolute pair, or per pin name.
    mu : float or mapping of (str, str) to float
        Friction coefficient of every sliding pair, or per ``(moving, guiding)`` link pair.
    tol, max_iter : float, int
        Newton's method on the reaction magnitudes stops at a relative step ``tol``.

    Returns
    -------
    StaticForces

    Raises
    ------
    ValueError
        For unknown points or links, non-finite loads, a negative ``rho`` or ``mu``,
        friction circles that do not fit on a two-force member, or friction with an
        ``order=0`` solution.
    mech.AssemblyError
        If a pose of ``solution`` is not assembled.

    Notes
    -----
    Derivation: :ref:`deriv-statics`; book page :ref:`book-forces-static-forces`.
    Without friction the balancing effort equals the virtual-work one,
    M_b omega + sum(F . v) + sum(M omega) = 0. With friction the result's `self_locking`
    flag marks poses that no finite effort can drive: the book finds the boundary of
    Example 2-14 (the double slider) with it and compares it with the closed form.

    Examples
    --------
    A four-bar with a force on its rocker at C; the balancing moment on the crank:

    >>> from mech.planar import FourBar
    >>> sol = as_linkage(FourBar(1, 3, 2.5, 3)).solve(0.5, order=1)
    >>> sf = static_forces(sol, {"C": -10})
    >>> round(float(sf.balancing), 6)
    3.305175
    >>> power = sf.balancing * 1.0 + (-10 * sol.velocities["C"].conj()).real
    >>> abs(float(power)) < 1e-12
    True
    """
    sol = solution
    instance("solution", solution, LinkageSolution)
    tol = nonnegative_number("tol", tol)
    max_iter = integer("max_iter", max_iter, minimum=1)
    _check_valid(sol)
    shape = sol.valid.shape
    pairs = _pairs(sol)
    keys = [p.links for p in pairs]
    if len(set(keys)) != len(keys):
        raise ValueError("Expected at most one pair between two links, got a repeated pair")
    if any(isinstance(st.get("lengths"), tuple) and any(isinstance(x, str) for x in st.get("lengths"))
           for st in sol.linkage._steps if st.kind == "rrr"):
        raise ValueError("Expected crank or slider drivers, got a length actuator (not supported)")
    f_list, c_list = _load_table(sol, forces, couples)
    coeff = [r + m for r, m in zip(_coefficients(pairs, rho, "R", "rho"), _coefficients(pairs, mu, "P", "mu"))]
    _check_two_force_members(sol, pairs, [c if p.kind == "R" else 0.0 for p, c in zip(pairs, coeff)],
                             {link for link, _, _ in f_list} | {link for link, _ in c_list})
    rough = [k for k, c in enumerate(coeff) if c > 0]
    if rough and sol.order < 1:
        raise ValueError("Expected `solution` with order >= 1 (velocities give the senses of friction) for "
                         f"`rho` = {rho!r} and `mu` = {mu!r}, got order 0")

    def loads(s=None):
        L = _Loads(shape)
        for link, point, f in f_list:
            L.force(link, f, sol.points[point])
        for link, m in c_list:
            L.couple(link, m)
        for k, sk in zip(rough, () if s is None else s):
            p = pairs[k]
            i, j = p.links
            sg = np.sign(p.rate) * coeff[k]
            if p.kind == "R":
                L.couple(j, -sg * sk)
                L.couple(i, sg * sk)
            else:
                f = -sg * sk * p.e
                L.force(j, f, p.at)
                L.force(i, -f, p.at)
        return L

    force0, couple0, effort0 = _linear(sol, loads())
    ok = np.ones(shape, dtype=bool)
    force, couple, effort = force0, couple0, effort0
    if rough:
        s, ok = _newton(sol, pairs, rough, force0, loads, shape, tol, max_iter)
        force, couple, effort = _linear(sol, loads(list(s)))
    return _assemble(sol, pairs, rough, coeff, force, couple, effort, effort0, ok)


def _newton(sol, pairs, rough, force0, loads, shape, tol, max_iter):
    """Solve s_k = |R_k(s)| for the reaction magnitudes at the rough pairs."""
    K = len(rough)
    n = int(np.prod(shape, dtype=int))
    key = [pairs[k].links for k in rough]
    R0 = np.stack([np.broadcast_to(force0[kk], shape).reshape(n) for kk in key])
    base = _linear(sol, loads([np.zeros(shape)] * K))[0]       # friction at zero: R0 again
    A = np.empty((K, K, n), dtype=complex)
    for col in range(K):
        unit = [np.zeros(shape)] * K
        unit[col] = np.ones(shape)
        f = _linear(sol, loads(unit))[0]
        for row, kk in enumerate(key):
            A[row, col] = (np.broadcast_to(f[kk], shape) - np.broadcast_to(base[kk], shape)).reshape(n)
    s = np.abs(R0)
    done = np.zeros(n, dtype=bool)
    prev = np.full(n, np.inf)
    eye = np.eye(K)
    # Each Newton step solves the equilibrium with the reactions' directions frozen at the
    # current iterate: (I - Re(conj(u) A)) s_new = Re(conj(u) R0), u = R / |R|.
    for it in range(max_iter):
        R = R0 + np.einsum("kln,ln->kn", A, s)
        absR = np.abs(R)
        g = absR - s
        safe = np.where(absR > 0, absR, 1.0)
        J = np.real(np.conj(R)[:, None, :] * A) / safe[:, None, :] - eye[:, :, None]
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            step = np.linalg.solve(np.moveaxis(J, -1, 0) + 0.0, -g.T[..., None])[..., 0].T
        step = np.where(np.isfinite(step), step, np.nan)
        s = np.where(done, s, s + step)
        size = np.max(np.abs(step) / (1.0 + np.abs(s)), axis=0)
        # converged, or stalled at the rounding floor of an ill-conditioned pose
        stalled = (it >= 2) & (size >= 0.5 * prev) & (size <= 1e-7)
        done = done | (((size <= tol) | stalled) & np.all(np.isfinite(s), axis=0))
        prev = np.where(done, prev, size)
        if np.all(done | ~np.all(np.isfinite(s), axis=0)):
            break
    R = R0 + np.einsum("kln,ln->kn", A, np.where(np.isfinite(s), s, 0.0))
    resid = np.abs(np.abs(R) - s)
    ok = done & np.all(resid <= 1e-9 * (1.0 + np.abs(s)), axis=0) & np.all(s >= 0, axis=0)
    s = np.where(ok, s, np.nan)
    return [s[k].reshape(shape) for k in range(K)], ok.reshape(shape)


def _driver_rates(sol):
    out = {}
    owner = sol.linkage._points
    for st in sol.linkage._steps:
        if st.kind == "crank":
            out[st.get("driver")] = _omega(sol, st.links[0]) - _omega(sol, owner[st.get("pivot")])
        elif st.kind == "slider":
            out[st.get("driver")] = sol.slides[(st.links[0], st.links[1])].v
    return out


def _assemble(sol, pairs, rough, coeff, force, couple, effort, effort0, ok):
    shape = sol.valid.shape
    full = lambda x: np.broadcast_to(np.asarray(x), shape).copy()
    reactions, lines = {}, {}
    for k, p in enumerate(pairs):
        i, j = p.links
        R = full(force[p.links])
        if p.kind == "R":
            c = 0.0
            if k in rough:
                c = -np.sign(p.rate) * coeff[k] * np.abs(R)
            # -c i R / |R|^2 as (c / |R|) times the unit vector R / |R|: no |R|^2 to overflow
            absR = np.abs(R)
            safe = np.where(absR > 0, absR, 1.0)
            # the unit vector part by part: a complex division by a subnormal |R| overflows
            unit = np.real(R) / safe + 1j * (np.imag(R) / safe)
            off = np.where(absR > 0, -(c / safe) * 1j * unit, 0.0)
            line = p.at + off
        else:
            N = np.real(R / (1j * p.e))
            C = full(couple[p.links])
            line = p.at + np.where(N != 0, C / np.where(N != 0, N, 1.0), 0.0) * p.e
            if k in rough:
                R = R - np.sign(p.rate) * coeff[k] * np.abs(N) * p.e
        reactions[(i, j)], reactions[(j, i)] = R, -R
        lines[(i, j)] = lines[(j, i)] = full(line)
    efforts = {d: np.where(ok, full(v), np.nan) for d, v in effort.items()}
    frictionless = {d: full(v) for d, v in effort0.items()}
    if sol.order >= 1:
        rates = _driver_rates(sol)
        p0 = sum(frictionless[d] * rates[d] for d in efforts)
        p1 = sum(efforts[d] * rates[d] for d in efforts)
        locked = ~ok | ((p0 > 0) & ~(p1 > 0))
        with np.errstate(invalid="ignore", divide="ignore"):
            eta = np.where(~locked & (p0 > 0), p0 / np.where(p1 != 0, p1, 1.0), np.nan)
        if not rough:
            eta = np.where(p0 > 0, 1.0, np.nan)
    else:
        locked = ~ok
        eta = np.full(shape, np.nan)
    for d in efforts:
        efforts[d] = np.where(locked, np.nan, efforts[d])
    return StaticForces(reactions, lines, efforts, frictionless, eta, locked)
