"""Independent 50-digit solution of the five-orientation Burmester problem, in mpmath.

Nothing here uses ``mech``: the four crank equations u^T (R_j R_1^T - I) w = 0 are written
in a random chart, u = Q (a1, a2, 1) and w = Q (b1, b2, 1), and solved by Newton's method
(``mpmath.findroot``) from random complex starts, in fresh random charts if needed, until
six distinct solutions are found (six is the Bezout number of four bilinear equations on
P^2 x P^2, so none is missing).
"""

import mpmath
import numpy as np

DPS = 50


def _mat(A):
    return mpmath.matrix([[mpmath.mpf(float(x)) for x in row] for row in A])


def _projective(v):
    """A homogeneous complex vector scaled so its largest entry is 1."""
    k = max(range(3), key=lambda i: abs(v[i]))
    return [v[i] / v[k] for i in range(3)]


def burmester_mp(R, seed=0, starts_per_chart=120, charts=6):
    """Return (real solutions as [(u, w)] float unit vectors with u.w >= 0, number found)."""
    rng = np.random.default_rng(seed)
    found = []
    with mpmath.workdps(DPS):
        Rm = [_mat(Rj) for Rj in R]
        K = [Rm[j] * Rm[0].T - mpmath.eye(3) for j in range(1, 5)]
        for _ in range(charts):
            Q = _mat(np.linalg.qr(rng.normal(size=(3, 3)))[0])
            KQ = [Q.T * Kj * Q for Kj in K]

            def f(a1, a2, b1, b2, KQ=KQ):
                u, w = mpmath.matrix([a1, a2, 1]), mpmath.matrix([b1, b2, 1])
                return [(u.T * Kj * w)[0] for Kj in KQ]

            def jac(a1, a2, b1, b2, KQ=KQ):
                u, w = mpmath.matrix([a1, a2, 1]), mpmath.matrix([b1, b2, 1])
                rows = []
                for Kj in KQ:
                    Kw, Ku = Kj * w, Kj.T * u
                    rows.append([Kw[0], Kw[1], Ku[0], Ku[1]])
                return mpmath.matrix(rows)

            for _ in range(starts_per_chart):
                x0 = [mpmath.mpc(*rng.uniform(-3, 3, size=2)) for _ in range(4)]
                try:
                    x = mpmath.findroot(f, x0, J=jac, tol=mpmath.mpf(10) ** (-2 * DPS + 10), maxsteps=100)
                except (ValueError, ZeroDivisionError):
                    continue
                x = [x[i] for i in range(4)]
                if max(abs(v) for v in f(*x)) > mpmath.mpf(10) ** (-DPS + 10):
                    continue
                u = Q * mpmath.matrix([x[0], x[1], 1])
                w = Q * mpmath.matrix([x[2], x[3], 1])
                key = _projective(u) + _projective(w)
                if all(max(abs(a - b) for a, b in zip(key, other)) > mpmath.mpf(10) ** (-20) for other, _ in found):
                    found.append((key, (u, w)))
                if len(found) == 6:
                    break
            if len(found) == 6:
                break
        real = []
        for key, (u, w) in found:
            if max(abs(mpmath.im(v)) for v in key) < mpmath.mpf(10) ** (-30):
                u = mpmath.matrix([mpmath.re(v) for v in key[:3]])
                w = mpmath.matrix([mpmath.re(v) for v in key[3:]])
                u, w = u / mpmath.norm(u), w / mpmath.norm(w)
                if (u.T * w)[0] < 0:
                    u = -u
                real.append((np.array([float(c) for c in u]), np.array([float(c) for c in w])))
        return real, len(found)
