"""Independent high-precision solution of the five-orientation Burmester problem.

Nothing here uses ``mech``. A resultant route, different from the package's: the rotations
are taken as exact rationals (every float is one), w = Q (x, y, 1) with a random integer
matrix Q, and SymPy forms exactly the two circle-point cubics det[K_2 w, K_3 w, K_4 w] and
det[K_2 w, K_3 w, K_5 w] and their resultant in x, a polynomial of degree 9 in y. Its roots
(``mpmath.polyroots`` at 60 digits) give the nine common points of the cubics; each is
polished by Newton's method on the pair at 50 digits, and the three where K_2 w and K_3 w
are parallel (which solve neither j = 4 nor j = 5 with a common u) are told apart from the
six Burmester points by the four residuals u . K_j w with u = K_2 w x K_3 w.
"""

import mpmath
import numpy as np
import sympy as sm

DPS = 50


def _common_points(M, seed, pair):
    """The common points w (at the working precision) of two exact cubics in w = Q (x, y, 1),
    Q a random integer matrix, and the matrices `M` as mpmath matrices.

    ``pair(w)`` gives the two 3 x 3 SymPy matrices whose determinants are the cubics; the
    roots of their resultant in x are polished by Newton's method on the pair. Call it
    inside ``mpmath.workdps(DPS + 10)``.
    """
    rng = np.random.default_rng(seed)
    Q = sm.Matrix(3, 3, [int(v) for v in rng.integers(-9, 10, size=9)])
    while Q.det() == 0:
        Q = sm.Matrix(3, 3, [int(v) for v in rng.integers(-9, 10, size=9)])
    x, y = sm.symbols("x y")
    F, G = (sm.expand(m.det()) for m in pair(Q * sm.Matrix([x, y, 1])))
    res = sm.Poly(sm.resultant(F, G, x), y)
    f_num = sm.lambdify((x, y), F, "mpmath")
    g_num = sm.lambdify((x, y), G, "mpmath")
    Fx = sm.Poly(F, x)
    coeffs = [mpmath.mpf(c.p) / mpmath.mpf(c.q) for c in map(sm.Rational, res.all_coeffs())]
    ys = mpmath.polyroots(coeffs, maxsteps=800, extraprec=800)
    Mm = [mpmath.matrix([[mpmath.mpf(v.p) / mpmath.mpf(v.q) for v in row] for row in Mj.tolist()]) for Mj in M]
    Qm = mpmath.matrix(Q.tolist())
    points = []
    for y0 in ys:
        xs = mpmath.polyroots([sm.lambdify(y, c, "mpmath")(y0) for c in Fx.all_coeffs()],
                              maxsteps=800, extraprec=800)
        x0 = min(xs, key=lambda v: abs(g_num(v, y0)))
        sol = mpmath.findroot(lambda a, b: [f_num(a, b), g_num(a, b)], (x0, y0), tol=mpmath.mpf(10) ** (-2 * DPS))
        points.append(Qm * mpmath.matrix([sol[0], sol[1], 1]))
    return points, Mm


def burmester_mp(R, seed=0):
    """Return (real solutions as [(u, w)] float unit vectors with u.w >= 0, number of
    Burmester points found among the nine common points of the cubics)."""
    Rq = [sm.Matrix(3, 3, [sm.Rational(float(v)) for v in Rj.ravel()]) for Rj in R]
    K = [Rq[j] * Rq[0].T - sm.eye(3) for j in range(1, 5)]
    found = []
    with mpmath.workdps(DPS + 10):
        points, Km = _common_points(K, seed, lambda w: (sm.Matrix.hstack(K[0] * w, K[1] * w, K[2] * w),
                                                        sm.Matrix.hstack(K[0] * w, K[1] * w, K[3] * w)))
        for wv in points:
            cols = [Kj * wv for Kj in Km]
            u = mpmath.matrix([cols[0][1] * cols[1][2] - cols[0][2] * cols[1][1],
                               cols[0][2] * cols[1][0] - cols[0][0] * cols[1][2],
                               cols[0][0] * cols[1][1] - cols[0][1] * cols[1][0]])
            size = mpmath.norm(u) * mpmath.norm(wv)
            if size == 0:
                continue
            off = max(abs(sum(u[i] * c[i] for i in range(3))) / (size * mpmath.norm(c) + mpmath.mpf(10) ** -300)
                      for c in cols[2:])
            if off < mpmath.mpf(10) ** (-30):
                found.append((u, wv))
        real = []
        for u, wv in found:
            if max(abs(mpmath.im(v / max(u, key=abs))) for v in u) < 1e-30 and \
                    max(abs(mpmath.im(v / max(wv, key=abs))) for v in wv) < 1e-30:
                ur = mpmath.matrix([mpmath.re(v / max(u, key=abs)) for v in u])
                wr = mpmath.matrix([mpmath.re(v / max(wv, key=abs)) for v in wv])
                ur, wr = ur / mpmath.norm(ur), wr / mpmath.norm(wr)
                if sum(ur[i] * wr[i] for i in range(3)) < 0:
                    ur = -ur
                real.append((np.array([float(c) for c in ur]), np.array([float(c) for c in wr])))
    return real, len(found)


def slider_points_mp(R, seed=0):
    """Slider points of four orientations by the same exact-resultant route: the common points
    of det[w, D_2 w, D_3 w] and det[w, D_2 w, D_4 w] less those where w and D_2 w are parallel.
    Returns (real slider axes w as float unit vectors at orientation 1, number found)."""
    Rq = [sm.Matrix(3, 3, [sm.Rational(float(v)) for v in Rj.ravel()]) for Rj in R]
    D = [Rq[j] * Rq[0].T for j in range(1, 4)]
    found = []
    with mpmath.workdps(DPS + 10):
        points, Dm = _common_points(D, seed, lambda w: (sm.Matrix.hstack(w, D[0] * w, D[1] * w),
                                                        sm.Matrix.hstack(w, D[0] * w, D[2] * w)))
        for wv in points:
            d2 = Dm[0] * wv
            cross = [wv[1] * d2[2] - wv[2] * d2[1], wv[2] * d2[0] - wv[0] * d2[2], wv[0] * d2[1] - wv[1] * d2[0]]
            if max(abs(c) for c in cross) > mpmath.mpf(10) ** (-30) * mpmath.norm(wv) ** 2:
                found.append(wv)
        real = []
        for wv in found:
            top = max(wv, key=abs)
            if max(abs(mpmath.im(v / top)) for v in wv) < 1e-30:
                wr = mpmath.matrix([mpmath.re(v / top) for v in wv])
                wr = wr / mpmath.norm(wr)
                real.append(np.array([float(c) for c in wr]))
    return real, len(found)
