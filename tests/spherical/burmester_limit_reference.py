"""Independent high-precision count of the real Burmester dyads of five orientations, in a
chart scaled to the task (for sets near the planar limit).

Nothing here uses ``mech``. The float64 orientations are taken exactly into mpmath and each replaced by
the rotation nearest it (its polar factor, `_rotation`). The
body axis runs over the affine chart ``z = c + h (t1 a + t2 b)``, where c is the mean of
the poles of the relative turns (taken to the body at orientation 1), h the spread of those
poles, and (a, b) a random pair completing a frame; so all six solutions have coordinates of
order one even when the orientations differ by arcs of 1e-8 (a chart of unit size would put
them all within 1e-8 of one point, where a root of one cubic is easily taken for another).
The minors ``det[(R_p-R_1)z, (R_q-R_1)z, (R_r-R_1)z]`` and the one with the fourth for R_r
(p, q the two displacements that differ most) are cubics in (t1, t2); their Sylvester resultant in t2 (sampled and interpolated) has degree 9
in t1. Each root, with the root of the first cubic in t2 that the second shares, is polished
by Newton's method on the two cubics; the three points where the first two rows are
parallel do not make the third and fourth minors vanish and are dropped. What is left are
the six solutions; a solution is real when its coordinates are real to a third of the
working digits. Double roots count twice (the multiplicity of a root of the resultant).
"""

import mpmath as mp
import numpy as np


def _interp(fun, nodes):
    V = mp.matrix([[t ** k for k in range(len(nodes))] for t in nodes])
    return list(mp.lu_solve(V, mp.matrix([fun(t) for t in nodes])))


def _sylvester(f, g):
    m, n = len(f) - 1, len(g) - 1
    S = mp.zeros(m + n, m + n)
    for r in range(n):
        for k, c in enumerate(reversed(f)):
            S[r, r + k] = c
    for r in range(m):
        for k, c in enumerate(reversed(g)):
            S[n + r, r + k] = c
    return mp.det(S)


def _rotation(Rk):
    """The rotation nearest the float64 matrix (its polar factor), at the working precision.

    A float64 rotation is a rotation rounded: it is orthogonal only to about 1e-16, and near
    the planar limit that rounding is as large as the task (the turns and translations at arc
    s enter the equations at s**2); the nearest rotation is what the matrix stands for.
    Newton's iteration X <- (X + X^-T) / 2 converges quadratically from so close.
    """
    X = mp.matrix([[mp.mpf(float(v)) for v in row] for row in Rk])
    for _ in range(8):
        X = (X + mp.inverse(X).T) / 2
    return X


def _chart(R, seed):
    """(c, a, b, h) as floats: the cap's centre in the body, a random frame, the cap's size."""
    R = np.asarray(R, dtype=float)
    axes = []
    for j in range(1, 5):
        D = R[j] @ R[0].T
        s = np.array([D[2, 1] - D[1, 2], D[0, 2] - D[2, 0], D[1, 0] - D[0, 1]])
        if np.linalg.norm(s) < 1e-6:                     # near a half turn: no planar limit here
            return None
        axes.append(s / np.linalg.norm(s))
    axes = np.array(axes)
    axes *= np.where(axes @ axes[0] < 0, -1.0, 1.0)[:, None]
    c = axes.sum(axis=0)
    c = R[0].T @ (c / np.linalg.norm(c))
    h = max(np.linalg.norm(p - q) for p in axes for q in axes)
    rng = np.random.default_rng(seed)
    c = c + h * 0.3 * rng.normal(size=3)                 # off the centre, for a generic chart
    c /= np.linalg.norm(c)
    a = rng.normal(size=3)
    a -= (a @ c) * c
    a /= np.linalg.norm(a)
    return c, a, np.cross(c, a), h


def real_count_scaled_mp(R, seed=0, dps=60):
    """The number of real solutions (double roots counted twice) and of all solutions found."""
    chart = _chart(R, seed)
    if chart is None or chart[3] > 0.2:
        rng = np.random.default_rng(seed)
        Q = np.linalg.qr(rng.normal(size=(3, 3)))[0]
        chart = (Q[:, 0], Q[:, 1], Q[:, 2], 1.0)
    with mp.workdps(dps):
        Rm = [_rotation(Rk) for Rk in np.asarray(R)]
        K = [Rm[j] - Rm[0] for j in range(1, 5)]
        # the two displacements that differ most share both cubics (two that nearly agree
        # would make every point nearly one where their rows are parallel)
        pairs = [(i, j) for i in range(4) for j in range(i + 1, 4)]
        p, q = max(pairs, key=lambda ij: mp.mnorm(K[ij[0]] - K[ij[1]], 1))
        K = [K[p], K[q]] + [K[m] for m in range(4) if m not in (p, q)]
        c, a, b = (mp.matrix([mp.mpf(float(v)) for v in vec]) for vec in chart[:3])
        h = mp.mpf(float(chart[3]))

        Kl = [[[Kk[i, k] for k in range(3)] for i in range(3)] for Kk in K]
        cl, al, bl = ([v[i] for i in range(3)] for v in (c, a, b))

        def rows(t1, t2):
            z = [cl[i] + (al[i] * t1 + bl[i] * t2) * h for i in range(3)]
            return [[Kk[i][0] * z[0] + Kk[i][1] * z[1] + Kk[i][2] * z[2] for i in range(3)] for Kk in Kl]

        def minor(r, i, j, k):
            p, q, s = r[i], r[j], r[k]
            return (p[0] * (q[1] * s[2] - q[2] * s[1]) - p[1] * (q[0] * s[2] - q[2] * s[0])
                    + p[2] * (q[0] * s[1] - q[1] * s[0]))

        def norm(v):
            return mp.sqrt(sum(abs(x) ** 2 for x in v))

        nodes = [mp.mpf(k) for k in (-1.5, -0.5, 0.5, 1.5)]

        def cubics(t1):
            return (_interp(lambda t2: minor(rows(t1, t2), 0, 1, 2), nodes),
                    _interp(lambda t2: minor(rows(t1, t2), 0, 1, 3), nodes))

        res = _interp(lambda t1: _sylvester(*cubics(t1)), [mp.mpf(k) / 2 for k in range(-5, 5)])
        top = max(abs(r) for r in res)
        while len(res) > 1 and abs(res[-1]) < mp.mpf(10) ** (10 - dps) * top:
            res = res[:-1]
        n_real = n_all = 0
        for t1 in mp.polyroots(res[::-1], maxsteps=4000, extraprec=4 * dps):
            f, g = cubics(t1)
            t2 = min(mp.polyroots(f[::-1], maxsteps=2000, extraprec=4 * dps), key=lambda t: abs(mp.polyval(g[::-1], t)))
            try:
                t1, t2 = mp.findroot(lambda x, y: [minor(rows(x, y), 0, 1, 2), minor(rows(x, y), 0, 1, 3)],
                                     (t1, t2), tol=mp.mpf(10) ** (15 - dps), verify=False)
            except (ZeroDivisionError, ValueError):
                pass                                      # a double root: keep the resultant's
            r = rows(t1, t2)
            size = norm(r[0]) * norm(r[1])
            if size == 0:
                continue
            cross = [r[0][1] * r[1][2] - r[0][2] * r[1][1], r[0][2] * r[1][0] - r[0][0] * r[1][2],
                     r[0][0] * r[1][1] - r[0][1] * r[1][0]]
            parallel = norm(cross) / size
            off = max(abs(minor(r, i, 2, 3)) / (norm(r[i]) * norm(r[2]) * norm(r[3])) for i in (0, 1))
            if parallel <= off or off > mp.mpf(10) ** (-dps // 4) * max(1, abs(t1), abs(t2)) ** 2:
                continue                                  # the first two rows parallel: not a solution
            n_all += 1
            if max(abs(mp.im(t1)), abs(mp.im(t2))) <= mp.mpf(10) ** (-dps // 3) * max(1, abs(t1), abs(t2)):
                n_real += 1
        return n_real, n_all
