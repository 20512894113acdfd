"""Independent 50-digit solver of the spherical four-bar, in mpmath.

Nothing here uses ``mech`` or the input-output equation. The linkage is placed by its
pivots and frame; C is the intersection of the small circle (小圆) of arc radius c about D
with the small circle of arc radius b about B, written as C = x D + y B + z (D x B) with
C.D = cos c, C.B = cos b, |C| = 1; the branch is the sign of det[B, D, C]. P is built at arc
r from B along the direction at angle gamma from the great circle B->C. Rates are
``mpmath.diff`` of the construction along a motion theta(t) = theta0 + omega t + alpha t^2/2;
the coupler's angular velocity is the axial vector of dQ/dt Q^T for the coupler frame Q.
"""

from __future__ import annotations

import mpmath

__all__ = ["DPS", "Linkage", "pose", "rates"]

DPS = 50


def _v(x):
    return mpmath.matrix([mpmath.mpf(float(c)) if not isinstance(c, mpmath.mpf) else c for c in x])


def _cross(p, q):
    return mpmath.matrix([p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]])


def _dot(p, q):
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]


def _unit(p):
    return p / mpmath.sqrt(_dot(p, p))


def _tangent(p, q):
    """Unit tangent at p of the great circle p -> q."""
    return _unit(q - _dot(p, q) * p)


class Linkage:
    """Dimensions and placement (frame given as a 3x3 nested list of floats, or None)."""

    def __init__(self, a, b, c, d, branch=1, coupler=(0.0, 0.0), frame=None):
        self.a, self.b, self.c, self.d = (mpmath.mpf(float(x)) for x in (a, b, c, d))
        self.branch = branch
        self.r, self.gamma = (mpmath.mpf(float(x)) for x in coupler)
        rows = frame if frame is not None else [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
        self.R = mpmath.matrix([[mpmath.mpf(float(x)) for x in row] for row in rows])
        self.A = self.R * _v((0, 0, 1))
        self.D = self.R * mpmath.matrix([mpmath.sin(self.d), 0, mpmath.cos(self.d)])


def _points(lk, theta):
    A, D = lk.A, lk.D
    e1 = _tangent(A, D)
    e2 = _cross(A, e1)
    B = mpmath.cos(lk.a) * A + mpmath.sin(lk.a) * (mpmath.cos(theta) * e1 + mpmath.sin(theta) * e2)
    k = _dot(B, D)
    cb, cc = mpmath.cos(lk.b), mpmath.cos(lk.c)
    x = (cc - k * cb) / (1 - k * k)
    y = (cb - k * cc) / (1 - k * k)
    n = _cross(D, B)
    z2 = (1 - (x * x + y * y + 2 * x * y * k)) / _dot(n, n)
    if z2 < 0:
        return None
    # det[B, D, C] = z det[B, D, D x B] = -z |D x B|^2: branch +1 takes z < 0
    z = -lk.branch * mpmath.sqrt(z2)
    C = x * D + y * B + z * n
    u = _tangent(B, C)
    v = _cross(B, u)
    P = mpmath.cos(lk.r) * B + mpmath.sin(lk.r) * (mpmath.cos(lk.gamma) * u + mpmath.sin(lk.gamma) * v)
    # psi: at D, from the continuation of A -> D to D -> C
    t1 = -_tangent(D, A)
    t2 = _cross(D, t1)
    psi = mpmath.atan2(_dot(C, t2), _dot(C, t1))
    return {"B": B, "C": C, "P": P, "psi": psi, "Q": (B, u, v)}


def pose(lk, theta):
    """Positions at one input angle: dict of B, C, P (mpmath matrices) and psi; None if it
    cannot be assembled."""
    with mpmath.workdps(DPS):
        return _points(lk, mpmath.mpf(float(theta)))


def rates(lk, theta, omega, alpha):
    """Velocities and accelerations at one input angle by mpmath.diff along the motion.

    Returns a dict with omega_output, alpha_output and, for X in B, C, P: vX, aX (lists of
    three mpf), w_coupler and dw_coupler (lists of three mpf).
    """
    with mpmath.workdps(DPS):
        th0, w, al = (mpmath.mpf(float(x)) for x in (theta, omega, alpha))
        psi0 = _points(lk, th0)["psi"]

        # mpmath.diff asks for the same few steps (at its own working precision) once per
        # component differentiated: each pose is built once and shared
        poses = {}

        def at(t):
            key = (t, mpmath.mp.prec)
            if key not in poses:
                poses[key] = _points(lk, th0 + w * t + al * t * t / 2)
            return poses[key]

        def psi(t):                       # unwrapped about psi0
            return psi0 + mpmath.atan2(mpmath.sin(at(t)["psi"] - psi0), mpmath.cos(at(t)["psi"] - psi0))

        out = {"omega_output": mpmath.diff(psi, 0), "alpha_output": mpmath.diff(psi, 0, 2)}
        for name in ("B", "C", "P"):
            out["v" + name] = [mpmath.diff(lambda t, i=i: at(t)[name][i], 0) for i in range(3)]
            out["a" + name] = [mpmath.diff(lambda t, i=i: at(t)[name][i], 0, 2) for i in range(3)]

        def Q(t):
            cols = at(t)["Q"]
            return mpmath.matrix([[cols[j][i] for j in range(3)] for i in range(3)])

        Q0 = Q(0)
        dQ = mpmath.matrix(3, 3)
        ddQ = mpmath.matrix(3, 3)
        for i in range(3):
            for j in range(3):
                dQ[i, j] = mpmath.diff(lambda t, i=i, j=j: Q(t)[i, j], 0)
                ddQ[i, j] = mpmath.diff(lambda t, i=i, j=j: Q(t)[i, j], 0, 2)
        W = dQ * Q0.T                      # skew: W x = w cross x
        dW = ddQ * Q0.T + dQ * dQ.T        # its derivative (dQ dQ^T is symmetric: drops out)
        out["w_coupler"] = [(W[2, 1] - W[1, 2]) / 2, (W[0, 2] - W[2, 0]) / 2, (W[1, 0] - W[0, 1]) / 2]
        out["dw_coupler"] = [(dW[2, 1] - dW[1, 2]) / 2, (dW[0, 2] - dW[2, 0]) / 2, (dW[1, 0] - dW[0, 1]) / 2]
        return out
