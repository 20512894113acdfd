"""Independent reference for spherical linkages: rotation chains solved with mpmath.

Every point is built by Rodrigues rotations about the joint axes (not by the closed form
of the dyad), each dyad's angle is found by ``mpmath.findroot`` on its arc condition,
started from the float solution, and rates are derivatives in theta by ``mpmath.diff``.
"""

import mpmath

DPS = 50


def _v(x):
    return mpmath.matrix([mpmath.mpf(float(c)) for c in x])


def _dot(p, q):
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]


def _cross(p, q):
    return mpmath.matrix([p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]])


def _unit(p):
    return p / mpmath.sqrt(_dot(p, p))


def rotate(axis, angle, p):
    """Rodrigues: `p` turned by `angle` about the unit `axis` (right hand)."""
    c, s = mpmath.cos(angle), mpmath.sin(angle)
    return p * c + _cross(axis, p) * s + axis * (_dot(axis, p) * (1 - c))


def toward(o, x, r):
    """The point at arc r from o on the great circle towards x."""
    u = _unit(x - o * _dot(o, x))
    return rotate(_unit(_cross(o, u)), r, o)


def chain(linkage, theta, guesses):
    """All points of `linkage` at `theta` (mpf), dyad angles started from `guesses`."""
    pts = {}
    frames = dict(linkage._links)
    for step in linkage._steps:
        kind = step[0]
        if kind == "ground":
            pts[step[1]] = _unit(_v(step[2]))
        elif kind == "crank":
            _, link, pivot, tip, a, ref = step
            pts[tip] = rotate(pts[pivot], theta, toward(pts[pivot], pts[ref], mpmath.mpf(a)))
        elif kind == "point":
            _, name, link, r, g = step
            o, x = frames[link]
            pts[name] = rotate(pts[o], mpmath.mpf(g), toward(pts[o], pts[x], mpmath.mpf(r)))
        else:
            _, links, (p1, p2), j, (b1, b2), sign = step
            start = toward(pts[p1], pts[p2], mpmath.mpf(b1))
            c2 = mpmath.cos(mpmath.mpf(b2))
            x = mpmath.findroot(lambda t: _dot(rotate(pts[p1], t, start), pts[p2]) - c2, guesses[j],
                                tol=mpmath.mpf(10) ** (-2 * DPS + 10))
            pts[j] = rotate(pts[p1], x, start)
    return pts


def dyad_guesses(linkage, pose_points):
    """Float starting angles of each dyad: the joint's angle at pins[0] from the great circle to pins[1]."""
    import numpy as np

    out = {}
    for step in linkage._steps:
        if step[0] == "rrr":
            _, links, (p1, p2), j, arcs, sign = step
            P1, P2, J = (np.asarray(pose_points[k], dtype=float) for k in (p1, p2, j))
            u = P2 - (P1 @ P2) * P1
            u /= np.linalg.norm(u)
            w = np.cross(P1, u)
            t = J - (P1 @ J) * P1
            out[j] = mpmath.mpf(float(np.arctan2(t @ w, t @ u)))
    return out


def reference(linkage, theta, omega, alpha, pose_points):
    """Positions, velocities and accelerations of every point at 50 digits."""
    with mpmath.workdps(DPS + 10):
        guesses = dyad_guesses(linkage, pose_points)
        th = mpmath.mpf(float(theta))
        cache = {}

        def f(t):
            key = (mpmath.mp.prec, t)
            if key not in cache:
                cache[key] = chain(linkage, t, guesses)
            return cache[key]

        P = f(th)
        out = {}
        for name in P:
            d1 = [mpmath.diff(lambda t: f(t)[name][i], th, 1) for i in range(3)]
            d2 = [mpmath.diff(lambda t: f(t)[name][i], th, 2) for i in range(3)]
            om, al = mpmath.mpf(float(omega)), mpmath.mpf(float(alpha))
            out[name] = ([P[name][i] for i in range(3)], [d * om for d in d1],
                         [d2[i] * om * om + d1[i] * al for i in range(3)])
        return out
