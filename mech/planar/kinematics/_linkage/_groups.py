"""Solving a planar linkage step by step: the state carried between steps, and one function per step.

`Linkage.solve` runs its steps in building order through `STEPS`: a driver (crank or
slider), a point fixed on a link, or a class II Assur group (RRR, RRP, RPR, PRP, RPP) with
the formulas of ``mech._generated.assur_groups``. A group whose position takes a square
root snaps an input within rounding of a dead point onto it (`_snapped_root`), once for all
three such groups.
"""

from __future__ import annotations

import numpy as np

from mech._generated import assur_groups as _g
from mech._scaling import DEAD_POINT_RTOL
from mech.planar.kinematics._linkage._records import GROUND, Slide, _cx, _re_im

__all__ = []


class _State:
    """Mutable arrays filled step by step during one solve."""

    def __init__(self, order, shape):
        self.order, self.shape = order, shape
        self.P, self.V, self.A = {}, {}, {}
        self.dir, self.origin, self.W, self.AL = {"ground": 1.0 + 0j}, {"ground": None}, {}, {}
        self.slides = {}
        self.valid = np.ones(shape, dtype=bool)

    def drop_unfinished(self):
        """Count a pose as failed where any result is not finite (never NaN with valid True)."""
        for table in (self.P, self.V, self.A, self.W, self.AL):
            for v in table.values():
                if v is not None:
                    self.valid = self.valid & np.isfinite(v)
        for sl in self.slides.values():
            for v in (sl.s, sl.v, sl.a, sl.coriolis):
                if v is not None:
                    self.valid = self.valid & np.isfinite(v)

    def rescale(self, unit):
        """Multiply every length, linear rate and slide back from the solving unit."""
        if unit == 1.0:
            return
        with np.errstate(over="ignore", invalid="ignore"):      # NaN and inf where not assembled
            for table in (self.P, self.V, self.A):
                for k in table:
                    table[k] = table[k] * unit
            for key, sl in self.slides.items():
                self.slides[key] = Slide(*(x if x is None or i == 1 else x * unit
                                           for i, x in enumerate((sl.s, sl.direction, sl.v, sl.a, sl.coriolis))))

    def put_point(self, name, z, v, a):
        self.P[name] = z
        if self.order >= 1:
            self.V[name] = 0.0 if v is None else v
        if self.order >= 2:
            self.A[name] = 0.0 if a is None else a

    def put_link(self, link, origin, direction, w, a):
        if link == GROUND:
            return
        self.dir[link], self.origin[link] = direction, origin
        if self.order >= 1:
            self.W[link] = w
        if self.order >= 2:
            self.AL[link] = a

    def put_slide(self, moving, guiding, slide):
        self.slides[(moving, guiding)] = slide

    def rigid_v(self, origin, link, z):
        if origin is None:
            return 0.0
        return _cx(*_g.rigid_body_velocity(*_re_im(self.V[origin]), *_re_im(z - self.P[origin]), self.W[link]))

    def rigid_a(self, origin, link, z):
        if origin is None:
            return 0.0
        return _cx(*_g.rigid_body_acceleration(*_re_im(self.A[origin]), *_re_im(z - self.P[origin]),
                                               self.W[link], self.AL[link]))


def _dead_point(st, step, disc, dead):
    """A radicand within rounding of zero at a dead point counts as zero (the dead point).

    Not next to a change point (where the group's mode flips and the solution passes):
    there `_signed_root` handles it. Returns the radicand and the dead-point mask.
    """
    _, near = st.modes.get(step.label, (step.get("branch"), None))
    if near is not None:
        dead = dead & ~near
    return np.where(dead & (disc < 0), 0.0, disc), dead


def _signed_root(st, step, disc):
    """The root of a group's radicand with the sign of its mode, and where it assembles.

    The mode comes from `mech.planar.kinematics._linkage._modes.modes`; next to a change point a
    radicand that rounding made slightly negative counts as zero.
    """
    sign, near = st.modes.get(step.label, (step.get("branch"), None))
    if near is not None:
        disc = np.where(near & (disc < 0), 0.0, disc)
    return sign * np.sqrt(disc), disc >= 0

def _snapped_root(st, step, radicand, distance, limits, size):
    """The root of a group's radicand by `_signed_root`, with inputs at a dead point snapped onto it.

    A group is at a dead point where `distance` (a length of its pose) equals one of
    `limits`. Within ``DEAD_POINT_RTOL * size`` of that, and away from a change point, the
    input counts as the dead point, which assembles (`_dead_point`), whatever the rounding
    of a given unit of length. Returns ``(root, ok, dead)``: the signed root, where the group
    assembles, and the dead-point mask (the rates are infinite there).
    """
    tol = DEAD_POINT_RTOL * size
    dead = False
    for limit in limits:
        dead = dead | (np.abs(distance - limit) <= tol)
    radicand, dead = _dead_point(st, step, radicand, dead)
    root, ok = _signed_root(st, step, radicand)
    return root, ok, dead


def do_ground(step, st, q, w, al):
    st.put_point(step.label, step.get("at"), 0.0, 0.0)

def do_point(step, st, q, w, al):
    link = step.links[0]
    o = st.origin[link]
    d = st.dir[link]
    loc = step.get("at")
    z = _cx(*_g.rigid_body_position(*_re_im(st.P[o]), *_re_im(d), loc.real, loc.imag))
    v = a = None
    if st.order >= 1:
        v = st.rigid_v(o, link, z)
    if st.order >= 2:
        a = st.rigid_a(o, link, z)
    st.put_point(step.label, z, v, a)

def do_crank(step, st, q, w, al):
    link, pivot, tip, r = step.links[0], step.get("pivot"), step.get("tip"), step.get("length")
    name = step.get("driver")
    d = np.exp(1j * q[name])
    z = _cx(*_g.rigid_body_position(*_re_im(st.P[pivot]), *_re_im(d), r, 0.0))
    st.put_link(link, pivot, d, w[name] if st.order >= 1 else None, al[name] if st.order >= 2 else None)
    v = st.rigid_v(pivot, link, z) if st.order >= 1 else None
    a = st.rigid_a(pivot, link, z) if st.order >= 2 else None
    st.put_point(tip, z, v, a)

def guide_state(st, guide):
    """Point Q, unit direction e, and the rates of Q and of the guide's link."""
    link = guide.link
    d = st.dir[link]
    if isinstance(guide.through, str):
        Q = st.P[guide.through]
        vQ = st.V.get(guide.through)
        aQ = st.A.get(guide.through)
    else:
        Q = st.P[st.origin[link]] + complex(guide.through) * d if st.origin[link] else complex(guide.through)
        vQ = st.rigid_v(st.origin[link], link, Q) if st.order >= 1 and st.origin[link] else 0.0
        aQ = st.rigid_a(st.origin[link], link, Q) if st.order >= 2 and st.origin[link] else 0.0
    e = d * np.exp(1j * float(guide.angle))
    return Q, e, vQ, aQ, st.W.get(link, 0.0), st.AL.get(link, 0.0)

def do_slider(step, st, q, w, al):
    link, guide, pt, name = step.links[0], step.get("guide"), step.get("point"), step.get("driver")
    Q, e, vQ, aQ, wK, aK = guide_state(st, guide)
    s = q[name]
    z = Q + s * e
    v = a = None
    slide = Slide(s=np.broadcast_to(s, st.shape), direction=np.broadcast_to(e, st.shape))
    if st.order >= 1:
        v = _cx(*_g.slide_velocity(*_re_im(vQ), *_re_im(e), s, w[name], wK))
    if st.order >= 2:
        ax, ay, kx, ky = _g.slide_acceleration(*_re_im(aQ), *_re_im(e), s, w[name], al[name], wK, aK)
        a = ax + 1j * ay
        slide = Slide(slide.s, slide.direction, w[name], al[name], kx + 1j * ky)
    elif st.order >= 1:
        slide = Slide(slide.s, slide.direction, w[name])
    st.put_link(link, pt, e, wK if st.order >= 1 else None, aK if st.order >= 2 else None)
    st.put_point(pt, z, v, a)
    st.put_slide(link, guide.link, slide)

def _length(value, q, w, al, st):
    if isinstance(value, str):
        return q[value], w[value] if st.order >= 1 else 0.0, al[value] if st.order >= 2 else 0.0
    return value, 0.0, 0.0

def do_rrr(step, st, q, w, al):
    (l1, l2), (p1, p2), joint = step.links, step.get("pins"), step.get("joint")
    (r1, dr1, ddr1), (r2, dr2, ddr2) = (_length(x, q, w, al, st) for x in step.get("lengths"))
    P1, P2 = st.P[p1], st.P[p2]
    gx, gy = _re_im(P2 - P1)
    heron = _g.rrr_position(gx, gy, r1, r2, 1.0)[2]
    # dead points where |P2 - P1| = r1 + r2 or |r1 - r2|
    g = np.hypot(gx, gy)
    rho, ok, dead = _snapped_root(st, step, heron, g, (np.abs(r1) + np.abs(r2), np.abs(r1 - r2)),
                                  np.abs(r1) + np.abs(r2) + g)
    ux, uy = _g.rrr_position_root(gx, gy, r1, r2, rho)
    u1 = ux + 1j * uy
    P3 = P1 + u1
    u2 = P3 - P2
    W1 = W2 = A1 = A2 = v3 = a3 = None
    if st.order >= 1:
        W1, W2, vx, vy = _g.rrr_velocity(ux, uy, *_re_im(u2), r1, r2, *_re_im(st.V[p1]),
                                         *_re_im(st.V[p2]), dr1, dr2)
        v3 = vx + 1j * vy
    if st.order >= 2:
        A1, A2, ax, ay = _g.rrr_acceleration(ux, uy, *_re_im(u2), r1, r2, *_re_im(st.A[p1]),
                                             *_re_im(st.A[p2]), dr1, dr2, ddr1, ddr2, W1, W2)
        a3 = ax + 1j * ay
    if st.order >= 1 and np.any(dead):           # infinite at a dead point: NaN, failed
        W1, W2, v3 = (np.where(dead, np.nan, x) for x in (W1, W2, v3))
        if st.order >= 2:
            A1, A2, a3 = (np.where(dead, np.nan, x) for x in (A1, A2, a3))
    st.put_link(l1, p1, u1 / r1, W1, A1)
    st.put_link(l2, p2, u2 / r2, W2, A2)
    st.put_point(joint, P3, v3, a3)
    return ok & np.isfinite(ux) & np.isfinite(uy)

def do_rrp(step, st, q, w, al):
    (rod, block), p1, guide, joint, r1 = step.links, step.get("pin"), step.get("guide"), step.get("joint"), step.get("length")
    Q, e, vQ, aQ, wK, aK = guide_state(st, guide)
    P1 = st.P[p1]
    (gx, gy), (ex, ey) = _re_im(Q - P1), _re_im(e)
    radicand = _g.rrp_position(gx, gy, ex, ey, r1, 1.0)[3]
    # dead points where the pin's distance from the guide is r1
    across = ex * gy - ey * gx
    rho, ok, dead = _snapped_root(st, step, radicand, np.abs(across), (np.abs(r1),), np.abs(r1) + np.hypot(gx, gy))
    s, ux, uy = _g.rrp_position_root(gx, gy, ex, ey, rho)
    u1 = ux + 1j * uy
    P3 = P1 + u1
    W1 = A1 = v3 = a3 = None
    slide = Slide(s=s, direction=np.broadcast_to(e, np.shape(s)))
    if st.order >= 1:
        W1, ds = _g.rrp_velocity(ux, uy, *_re_im(e), r1, s, *_re_im(st.V[p1]), *_re_im(vQ), wK)
        W1, ds = (np.where(dead, np.nan, x) for x in (W1, ds))      # infinite at a dead point
        v3 = _cx(*_g.rigid_body_velocity(*_re_im(st.V[p1]), ux, uy, W1))
        slide = Slide(s, slide.direction, ds)
    if st.order >= 2:
        A1, dds = _g.rrp_acceleration(ux, uy, *_re_im(e), r1, s, *_re_im(st.A[p1]), *_re_im(aQ),
                                      wK, aK, W1, ds)
        a3 = _cx(*_g.rigid_body_acceleration(*_re_im(st.A[p1]), ux, uy, W1, A1))
        _, _, kx, ky = _g.slide_acceleration(*_re_im(aQ), *_re_im(e), s, ds, dds, wK, aK)
        slide = Slide(s, slide.direction, ds, dds, kx + 1j * ky)
    st.put_link(rod, p1, u1 / r1, W1, A1)
    st.put_link(block, joint, e, wK if st.order >= 1 else None, aK if st.order >= 2 else None)
    st.put_point(joint, P3, v3, a3)
    st.put_slide(block, guide.link, slide)
    return ok

def do_rpr(step, st, q, w, al):
    (gl, block), (p1, p2), e0 = step.links, step.get("pins"), step.get("offset")
    P1, P2 = st.P[p1], st.P[p2]
    gx, gy = _re_im(P2 - P1)
    radicand = _g.rpr_position(gx, gy, e0, 1.0)[3]
    # dead points where the pins' distance is |offset|
    g = np.hypot(gx, gy)
    s, ok, dead = _snapped_root(st, step, radicand, g, (abs(e0),), abs(e0) + g)
    wx, wy = _g.rpr_position_root(gx, gy, e0, s)
    d = wx + 1j * wy
    W = A = None
    slide = Slide(s=s, direction=d)
    if st.order >= 1:
        W, ds = _g.rpr_velocity(wx, wy, s, e0, *_re_im(st.V[p1]), *_re_im(st.V[p2]))
        W, ds = (np.where(dead, np.nan, x) for x in (W, ds))        # infinite at a dead point
        slide = Slide(s, d, ds)
    if st.order >= 2:
        A, dds, kx, ky = _g.rpr_acceleration(wx, wy, s, e0, *_re_im(st.A[p1]), *_re_im(st.A[p2]), W, ds)
        slide = Slide(s, d, ds, dds, kx + 1j * ky)
    st.put_link(gl, p1, d, W, A)
    st.put_link(block, p2, d, W, A)
    st.put_slide(block, gl, slide)
    return ok & np.isfinite(wx) & np.isfinite(wy)

def do_prp(step, st, q, w, al):
    (b1, b2), (g1, g2), joint = step.links, step.get("guides"), step.get("joint")
    Q1, e1, vQ1, aQ1, w1, a1 = guide_state(st, g1)
    Q2, e2, vQ2, aQ2, w2, a2 = guide_state(st, g2)
    s1, s2, det = _g.prp_position(*_re_im(Q2 - Q1), *_re_im(e1), *_re_im(e2))
    P3 = Q1 + s1 * e1
    sl1 = Slide(s=s1, direction=np.broadcast_to(e1, np.shape(s1)))
    sl2 = Slide(s=s2, direction=np.broadcast_to(e2, np.shape(s2)))
    v3 = a3 = None
    if st.order >= 1:
        ds1, ds2 = _g.prp_velocity(*_re_im(e1), *_re_im(e2), s1, s2, *_re_im(vQ1), *_re_im(vQ2), w1, w2)
        v3 = _cx(*_g.slide_velocity(*_re_im(vQ1), *_re_im(e1), s1, ds1, w1))
        sl1, sl2 = Slide(s1, sl1.direction, ds1), Slide(s2, sl2.direction, ds2)
    if st.order >= 2:
        dds1, dds2 = _g.prp_acceleration(*_re_im(e1), *_re_im(e2), s1, s2, *_re_im(aQ1), *_re_im(aQ2),
                                         w1, w2, a1, a2, ds1, ds2)
        ax, ay, k1x, k1y = _g.slide_acceleration(*_re_im(aQ1), *_re_im(e1), s1, ds1, dds1, w1, a1)
        a3 = ax + 1j * ay
        _, _, k2x, k2y = _g.slide_acceleration(*_re_im(aQ2), *_re_im(e2), s2, ds2, dds2, w2, a2)
        sl1 = Slide(s1, sl1.direction, ds1, dds1, k1x + 1j * k1y)
        sl2 = Slide(s2, sl2.direction, ds2, dds2, k2x + 1j * k2y)
    st.put_link(b1, joint, e1, w1 if st.order >= 1 else None, a1 if st.order >= 2 else None)
    st.put_link(b2, joint, e2, w2 if st.order >= 1 else None, a2 if st.order >= 2 else None)
    st.put_point(joint, P3, v3, a3)
    st.put_slide(b1, g1.link, sl1)
    st.put_slide(b2, g2.link, sl2)
    return np.abs(det) > 1e-12

def do_rpp(step, st, q, w, al):
    (pinned, sliding), p1, guide, gam, pt, e0 = (step.links, step.get("pin"), step.get("guide"),
                                                 step.get("angle"), step.get("point"), step.get("offset"))
    Q, e, vQ, aQ, wK, aK = guide_state(st, guide)
    wdir = e * np.exp(1j * gam)
    P1 = st.P[p1]
    s2, t, det = _g.rpp_position(*_re_im(P1 - Q), *_re_im(e), *_re_im(wdir), e0)
    J = Q + s2 * e
    slo = Slide(s=s2, direction=np.broadcast_to(e, np.shape(s2)))
    sli = Slide(s=t, direction=np.broadcast_to(wdir, np.shape(t)))
    vJ = aJ = None
    if st.order >= 1:
        ds2, dt = _g.rpp_velocity(*_re_im(e), *_re_im(wdir), s2, t, e0, *_re_im(st.V[p1]), *_re_im(vQ), wK)
        vJ = _cx(*_g.slide_velocity(*_re_im(vQ), *_re_im(e), s2, ds2, wK))
        slo, sli = Slide(s2, slo.direction, ds2), Slide(t, sli.direction, dt)
    if st.order >= 2:
        dds2, ddt, k2x, k2y, kix, kiy = _g.rpp_acceleration(
            *_re_im(e), *_re_im(wdir), s2, t, e0, *_re_im(st.A[p1]), *_re_im(aQ), wK, aK, ds2, dt)
        ax, ay, _, _ = _g.slide_acceleration(*_re_im(aQ), *_re_im(e), s2, ds2, dds2, wK, aK)
        aJ = ax + 1j * ay
        slo = Slide(s2, slo.direction, ds2, dds2, k2x + 1j * k2y)
        sli = Slide(t, sli.direction, dt, ddt, kix + 1j * kiy)
    rate = (wK if st.order >= 1 else None, aK if st.order >= 2 else None)
    st.put_link(sliding, pt, e, *rate)
    st.put_link(pinned, p1, wdir, *rate)
    st.put_point(pt, J, vJ, aJ)
    st.put_slide(sliding, guide.link, slo)
    st.put_slide(pinned, sliding, sli)
    return np.abs(det) > 1e-12

#: The function that solves each kind of step into the state; each returns its validity (or None).
STEPS = {"ground": do_ground, "point": do_point, "crank": do_crank, "slider": do_slider, "rrr": do_rrr,
         "rrp": do_rrp, "rpr": do_rpr, "prp": do_prp, "rpp": do_rpp}
