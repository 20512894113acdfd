"""Assembly modes of a `Linkage` through change points.

A group with two assembly modes (RRR, RRP, RPR) has a radicand that is zero where its
modes meet. Where the radicand only *touches* zero along the motion (a change point:
a parallelogram four-bar at theta = 0, a slider-crank with a + |e| = b, ...), the motion
continues smoothly onto the other sign of the root, so the mode that continues the motion
changes there. For a linkage driven by one crank this module finds those input angles once
per linkage (sampling a turn, then bisecting on the rate of the group's distance), and
turns them into a local rule: the mode at an input angle is the chosen ``branch`` times
-1 for every change point passed between 0 and that angle.
"""

from __future__ import annotations

import math

import numpy as np

from mech.planar.kinematics._linkage._groups import guide_state
from mech.planar.kinematics._linkage._records import Slide

__all__ = []        # internal to the subpackage: nothing here is re-exported

# samples per crank turn when looking for the extremes of a group's distance; a change
# point is found whenever the extremes are further apart than two samples
_SAMPLES = 2048


class Schedule:
    """The change points of one group over one period of its inputs.

    ``period`` is the period of the group's pin motion (2 pi times a power of two),
    ``points`` the sorted input angles in [0, period) where its radicand touches zero, and
    ``width`` half the interval around each point within which a radicand that rounding
    made slightly negative counts as zero.
    """

    __slots__ = ("period", "points", "width")

    def __init__(self, period, points, width):
        self.period, self.points, self.width = period, np.asarray(points, dtype=float), width

    @property
    def sign_period(self):
        """Period of the mode: twice ``period`` when the group changes mode an odd number of times."""
        return self.period * (2 if len(self.points) % 2 else 1)

    def flips(self, theta):
        """Number of change points in (0, theta] (negative for theta < 0), as a float array."""
        P, tp = self.period, self.points
        turns = np.floor(theta / P)
        rest = theta - turns * P
        passed = np.searchsorted(tp, rest, side="right")
        at_zero = int(len(tp) > 0 and tp[0] <= 0.0)
        return turns * len(tp) + passed - at_zero

    def near(self, theta):
        """True where ``theta`` is within ``width`` of a change point (modulo the period)."""
        if len(self.points) == 0:
            return np.zeros(np.shape(theta), dtype=bool)
        P = self.period
        off = np.mod(np.asarray(theta)[..., None] - self.points + 0.5 * P, P) - 0.5 * P
        return np.any(np.abs(off) <= self.width, axis=-1)


def modes(schedules, steps, theta):
    """The mode of every two-mode group: ``label -> (sign, near)`` at the inputs ``theta``.

    ``sign`` is +1 or -1 (an array when the group has change points), ``near`` where a
    slightly negative radicand counts as zero (None when nowhere).
    """
    out = {}
    for step in steps:
        if step.kind not in ("rrr", "rrp", "rpr"):
            continue
        branch = step.get("branch")
        sch = schedules.get(step.label) if schedules else None
        if sch is None or len(sch.points) == 0 or theta is None:
            out[step.label] = (branch, None)
            continue
        odd = np.mod(sch.flips(theta), 2.0)
        out[step.label] = (branch * (1.0 - 2.0 * odd), sch.near(theta))
    return out


def _distance(step, st, guide_state):
    """The group's distance x, its rate along the input, and the bounds it must keep.

    RRR: x = |P2 - P1| between |r1 - r2| and r1 + r2; RRP: x = |h|, the distance of the pin
    from the guide, at most r1; RPR: x = |P2 - P1|, at least |offset|.
    """
    kind = step.kind
    if kind in ("rrr", "rpr"):
        p1, p2 = step.get("pins")
        g = st.P[p2] - st.P[p1]
        gv = st.V[p2] - st.V[p1]
        x = np.hypot(g.real, g.imag)
        dx = (g.real * gv.real + g.imag * gv.imag) / x
        if kind == "rrr":
            r1, r2 = step.get("lengths")
            return x, dx, abs(r1 - r2), r1 + r2
        return x, dx, abs(step.get("offset")), math.inf
    P1 = st.P[step.get("pin")]
    V1 = st.V[step.get("pin")]
    Q, e, vQ, _, wK, _ = guide_state(st, step.get("guide"))
    rel = np.conj(e) * (P1 - Q)
    h = rel.imag
    dh = (np.conj(e) * (V1 - vQ)).imag - wK * rel.real
    return np.abs(h), np.sign(h) * dh, -math.inf, step.get("length")


def find_schedule(linkage, steps, driver, rtol):
    """Change points of every two-mode group of a linkage driven by the one crank ``driver``.

    Returns ``label -> Schedule``. The search runs group by group in solving order, each
    with the modes of the groups before it already fixed, over the period of its pins.
    """
    schedules = {}
    period = 2 * math.pi
    for i, step in enumerate(steps):
        if step.kind not in ("rrr", "rrp", "rpr"):
            continue
        before = steps[:i]
        n = int(round(_SAMPLES * period / (2 * math.pi)))
        h = period / n

        def measure(theta, before=before, step=step):
            theta = np.asarray(theta, dtype=float)
            st = linkage._run(before, 1, theta.shape, {driver: theta}, {driver: np.ones_like(theta)},
                              {driver: np.zeros_like(theta)}, modes(schedules, before, theta))[0]
            with np.errstate(invalid="ignore", divide="ignore"):
                return _distance(step, st, guide_state)

        t = np.arange(n) * h
        x, _, lower, upper = measure(t)
        points = []
        if not np.nanmax(x, initial=-math.inf) - np.nanmin(x, initial=math.inf) > rtol:
            schedules[step.label] = Schedule(period, [], h)   # pins that keep their distance
            continue
        for bound, sense in ((lower, 1.0), (upper, -1.0)):
            if not math.isfinite(bound):
                continue
            y = sense * x                   # look for minima of y
            prev, nxt = np.roll(y, 1), np.roll(y, -1)
            cand = (y <= prev) & (y <= nxt) & np.isfinite(prev) & np.isfinite(nxt)
            # refine only the minima whose parabola through three samples comes near the
            # bound; the parabola's error is far below 100 second differences unless the
            # distance turns a hundred times faster than the sampling can resolve
            curv = prev + nxt - 2 * y
            with np.errstate(invalid="ignore", divide="ignore"):
                vertex = y - np.where(curv > 0, (nxt - prev) ** 2 / (8 * curv), 0.0)
            cand &= vertex - sense * bound <= 100 * np.abs(curv) + rtol
            cand = np.flatnonzero(cand)
            if cand.size == 0:
                continue
            lo, hi = t[cand] - h, t[cand] + h
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                if np.all((mid <= lo) | (mid >= hi)):
                    break
                _, dx, _, _ = measure(mid)
                slope = sense * dx
                lo = np.where(slope < 0, mid, lo)
                hi = np.where(slope > 0, mid, hi)
                flat = ~(slope != 0)        # zero or NaN: the extreme itself
                lo = np.where(flat, mid, lo)
                hi = np.where(flat, mid, hi)
            t0 = 0.5 * (lo + hi)
            x0 = measure(t0)[0]
            touch = np.abs(x0 - bound) <= rtol
            points.extend(np.mod(t0[touch], period).tolist())
        pts = _merge(np.asarray(points, dtype=float), period, h)
        schedules[step.label] = Schedule(period, pts, 1.5 * h)
        period = max(period, schedules[step.label].sign_period)
    return schedules


def _merge(points, period, spacing):
    """Sorted points in [0, period), one for each cluster closer than ``spacing``.

    Neighbouring samples on a flat extreme are refined to the same change point up to
    rounding; counting it twice would undo the change of mode.
    """
    pts = np.mod(points, period)
    pts = np.sort(np.where(pts < period, pts, 0.0))     # just below 0, rounded up to the period
    if pts.size == 0:
        return pts
    keep = np.concatenate(([True], np.diff(pts) > spacing))
    pts = pts[keep]
    if pts.size > 1 and pts[0] + period - pts[-1] <= spacing:
        pts = pts[:-1]
    return pts


# The bridge across a change point: poses closer than _HALF sample spacings to a change
# point take their values from a polynomial through _NODES solutions of the same mode,
# _NODES // 2 on each side, at Chebyshev points between _HALF and _REACH * _HALF spacings
# away, where the loop equations are well conditioned. For positions analytic along the
# motion the interpolation error falls like (reach / radius of convergence)**_NODES; the
# Lebesgue constant of these nodes over the gap is about 5. The bridge of a change point is
# accepted where its nodes assemble and it reproduces the direct solutions halfway to the
# change point to _AGREE (in the solving unit, about the longest length); otherwise (a limit
# position or a fast turn close to the change point) it is halved, up to _TRIES times.
_HALF = 4.0
_REACH = 4.0
_NODES = 16
_TRIES = 8
_AGREE = 1e-10


def _bridge_nodes(width):
    k = np.arange(_NODES // 2)
    side = width * (0.5 * (1 + _REACH) + 0.5 * (_REACH - 1) * np.cos(np.pi * (k + 0.5) / (_NODES // 2)))
    x = np.concatenate((-side[::-1], side))
    # barycentric weights of the nodes
    diff = x[:, None] - x[None, :]
    np.fill_diagonal(diff, 1.0)
    w = 1.0 / np.prod(diff / width, axis=1)
    return x, w


def bridge(linkage, steps, schedules, driver, state, theta, omega, alpha, failures):
    """Replace the state next to every change point by interpolation across it (in place).

    At a change point the rates of a group are 0/0 and its position is fixed only to the
    square root of the rounding error; the interpolation gives the smooth continuation
    to rounding instead, and the limit at the change point itself. A pose that the direct
    solution left unassembled becomes assembled only where the group of the change point
    was the one that failed (its pins met, or rounding pushed its radicand below zero).
    """
    shape, order = state.shape, state.order
    flat = np.broadcast_to(theta, shape).reshape(-1)
    todo = np.zeros(flat.shape, dtype=bool)
    tasks = []
    for label, sch in schedules.items():
        if len(sch.points) == 0:
            continue
        width = _HALF * sch.width / 1.5
        P = sch.period
        for t0 in sch.points:
            turns = np.round((flat - t0) / P)
            off = flat - (t0 + turns * P)
            inside = (np.abs(off) < width) & ~todo
            if not np.any(inside):
                continue
            todo |= inside
            tasks.append((label, t0, P, width, turns, off, inside))
    if not tasks:
        return
    tasks = [(label, t0, P, width / 2**k, turns, off, inside & (np.abs(off) < width / 2**k))
             for label, t0, P, width, turns, off, inside in tasks for k in range(_TRIES)]
    om = np.broadcast_to(omega, shape).reshape(-1)
    al = np.broadcast_to(alpha, shape).reshape(-1)
    fields = _fields(state)
    out = {key: np.array(np.broadcast_to(val, shape), dtype=complex if key[0] in _COMPLEX else float).reshape(-1)
           for key, val in fields.items()}
    valid = state.valid.reshape(-1).copy()
    done = np.zeros(flat.shape, dtype=bool)
    for label, t0, P, width, turns, off, inside in tasks:
        mended = np.broadcast_to(failures.get(label, False), shape).reshape(-1)
        idx = np.flatnonzero(inside & ~done)
        if idx.size == 0:
            continue
        bases, which = np.unique(turns[idx], return_inverse=True)
        x, w = _bridge_nodes(width)
        probe = np.array([-0.5, 0.5]) * width
        at = ((t0 + bases * P)[:, None] + np.concatenate((x, probe))[None, :]).reshape(-1)
        ns = linkage._run(steps, order, at.shape, {driver: at}, {driver: np.ones_like(at)},
                          {driver: np.zeros_like(at)}, modes(schedules, steps, at))[0]
        nvalid = ns.valid.reshape(len(bases), -1).all(axis=1)
        nf = {k: np.broadcast_to(v, at.shape).reshape(len(bases), -1) for k, v in _fields(ns).items()}
        # accept the bridge of a base where it reproduces the direct solutions halfway to
        # the change point; a solution that turns faster than the nodes resolve fails this
        cp = w[None, :] / (probe[:, None] - x[None, :])
        cp /= cp.sum(axis=1, keepdims=True)
        for key, vals in nf.items():
            if key[0] == "P":
                miss = np.abs(vals[:, : x.size] @ cp.T - vals[:, x.size:])
                nvalid &= np.max(miss, axis=1) <= _AGREE
        nf = {k: v[:, : x.size] for k, v in nf.items()}
        c = w[None, :] / (off[idx][:, None] - x[None, :])
        c /= c.sum(axis=1, keepdims=True)
        good = nvalid[which] & ~done[idx]
        sel = idx[good]
        done[sel] = True
        cg = c[good]
        bg = which[good]

        def interp(key):
            return np.sum(cg * nf[key][bg], axis=1)

        for key in out:
            kind = key[0]
            if kind in ("P", "dir", "s", "sdir"):
                v = interp(key)
                if kind in ("dir", "sdir"):
                    v = v / np.abs(v)
            elif kind in ("V", "W", "sv"):
                v = om[sel] * interp(key)
            elif kind in ("A", "AL", "sa"):
                first = {"A": "V", "AL": "W", "sa": "sv"}[kind]
                v = om[sel] ** 2 * interp(key) + al[sel] * interp((first,) + key[1:])
            else:                                   # Coriolis terms: products of two rates
                v = om[sel] ** 2 * interp(key)
            out[key][sel] = v
        valid[sel] |= mended[sel]
    _store_fields(state, {k: v.reshape(shape) for k, v in out.items()})
    state.valid = valid.reshape(shape)


_COMPLEX = frozenset({"P", "V", "A", "dir", "sdir", "cor"})


def _fields(st):
    """Every array of a state, keyed by (kind, name)."""
    out = {}
    for kind, table in (("P", st.P), ("V", st.V), ("A", st.A), ("W", st.W), ("AL", st.AL)):
        for k, v in table.items():
            if v is not None:
                out[(kind, k)] = v
    for k, v in st.dir.items():
        if k != "ground":
            out[("dir", k)] = v
    for key, sl in st.slides.items():
        for kind, v in (("s", sl.s), ("sdir", sl.direction), ("sv", sl.v), ("sa", sl.a), ("cor", sl.coriolis)):
            if v is not None:
                out[(kind, key)] = v
    return out


def _store_fields(st, values):
    for (kind, k), v in values.items():
        if kind in ("P", "V", "A", "W", "AL"):
            getattr(st, kind)[k] = v
        elif kind == "dir":
            st.dir[k] = v
    for key, sl in list(st.slides.items()):
        parts = [values.get((kind, key), old) for kind, old in
                 (("s", sl.s), ("sdir", sl.direction), ("sv", sl.v), ("sa", sl.a), ("cor", sl.coriolis))]
        st.slides[key] = Slide(*parts)
