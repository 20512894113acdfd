"""High-precision reference for the coupler curve of a planar four-bar (mpmath, 50 digits).

This route shares nothing with the derivation notebooks or ``mech/_generated``:

- positions by intersecting two circles, circle(B, b) and circle(D, c), in complex
  arithmetic, taking the root on the side of the directed line B->D named by ``branch``;
- velocities and accelerations of C from the 2x2 linear systems obtained by differentiating
  the two constraints |C - B|^2 = b^2 and |C - D|^2 = c^2 once and twice in time;
- the coupler point P = B + (p + i q)(C - B)/b and its derivatives, which are linear in B, C.

Conventions are those of ``CONVENTIONS.md``: A = 0, D = d, B = a exp(i theta), input link
turning at ``omega`` with angular acceleration ``alpha``.
"""

from __future__ import annotations

import mpmath
import numpy as np

__all__ = ["DPS", "coupler_reference", "self_check"]

#: Working precision of the reference, in decimal digits.
DPS = 50


def _solve2(m11, m12, m21, m22, r1, r2):
    """Solve the real 2x2 system [[m11, m12], [m21, m22]] x = [r1, r2] by Cramer's rule."""
    det = m11 * m22 - m12 * m21
    return (r1 * m22 - m12 * r2) / det, (m11 * r2 - m21 * r1) / det


def _dot(u, v):
    """Real dot product of two planar vectors held as complex numbers: Re(conj(u) v)."""
    return u.real * v.real + u.imag * v.imag


def _one(theta, a, b, c, d, branch, coupler, omega, alpha):
    a, b, c, d = (mpmath.mpf(x) for x in (a, b, c, d))
    w, al = mpmath.mpf(omega), mpmath.mpf(alpha)
    theta = mpmath.mpf(theta)
    z = mpmath.mpc(coupler[0], coupler[1])
    D = mpmath.mpc(d, 0)
    # Positions: B on the crank circle, C on both circles.
    B = a * mpmath.expj(theta)
    e = D - B
    L = abs(e)
    along = (b * b - c * c + L * L) / (2 * L)
    h2 = b * b - along * along
    if h2 < 0:
        nan = mpmath.mpc(mpmath.nan, mpmath.nan)
        return nan, nan, nan
    C = B + (along + 1j * branch * mpmath.sqrt(h2)) * e / L
    # Velocities: d/dt |C-B|^2 = 0 and d/dt |C-D|^2 = 0 give two linear equations in vC.
    vB = 1j * w * B
    u1, u2 = C - B, C - D
    vx, vy = _solve2(u1.real, u1.imag, u2.real, u2.imag, _dot(u1, vB), mpmath.mpf(0))
    vC = mpmath.mpc(vx, vy)
    # Accelerations: differentiate once more.
    aB = (1j * al - w * w) * B
    rel = vC - vB
    r1 = _dot(u1, aB) - _dot(rel, rel)
    r2 = -_dot(vC, vC)
    ax, ay = _solve2(u1.real, u1.imag, u2.real, u2.imag, r1, r2)
    aC = mpmath.mpc(ax, ay)
    k = z / b
    return B + k * (C - B), vB + k * (vC - vB), aB + k * (aC - aB)


def coupler_reference(theta, a, b, c, d, *, branch=1, coupler=(0.0, 0.0), omega=1.0, alpha=0.0):
    """Coupler point P and its velocity and acceleration at 50 digits, rounded to complex128.

    Parameters
    ----------
    theta : array_like of float
        Input angles (radians); each float is taken exactly.
    a, b, c, d : float
        Crank AB, coupler BC, rocker CD, ground AD.
    branch : {1, -1}
        +1 when C is left of the directed line B->D.
    coupler : (float, float)
        (p, q): P = B + (p + i q) (C - B) / b.
    omega, alpha : float
        Angular velocity and acceleration of the crank.

    Returns
    -------
    P, vP, aP : ndarray of complex
        NaN where the linkage cannot be assembled.
    """
    theta = np.asarray(theta, dtype=float)
    out = np.empty((3,) + theta.shape, dtype=complex)
    with mpmath.workdps(DPS):
        for i, t in np.ndenumerate(theta):
            vals = _one(float(t), a, b, c, d, branch, coupler, omega, alpha)
            for k in range(3):
                out[(k,) + i] = complex(vals[k])
    return out[0], out[1], out[2]


def self_check(a, b, c, d, *, branch=1, coupler=(0.0, 0.0), angles=(0.3, 1.7, 4.0)):
    """Check the reference against itself by another route: ``mpmath.diff`` of P(theta).

    With omega = 1 and alpha = 0, vP = dP/dtheta and aP = d2P/dtheta2. Also checks that
    C satisfies both constraints and the branch sign. Raises ``AssertionError`` on failure.
    """
    with mpmath.workdps(DPS):
        tol = mpmath.mpf(10) ** (-30)
        for t in angles:
            P, vP, aP = _one(t, a, b, c, d, branch, coupler, 1, 0)

            def pos(x):
                return _one(x, a, b, c, d, branch, coupler, 1, 0)[0]

            t = mpmath.mpf(t)
            d1 = mpmath.diff(lambda x: pos(x).real, t) + 1j * mpmath.diff(lambda x: pos(x).imag, t)
            d2 = mpmath.diff(lambda x: pos(x).real, t, 2) + 1j * mpmath.diff(lambda x: pos(x).imag, t, 2)
            assert abs(d1 - vP) < tol, (t, d1, vP)
            assert abs(d2 - aP) < tol, (t, d2, aP)
            B = a * mpmath.expj(t)
            # Recover C from P, then test the constraints and the branch.
            C = B + (P - B) * b / mpmath.mpc(*coupler) if coupler != (0.0, 0.0) else None
            if C is not None:
                D = mpmath.mpf(d)
                assert abs(abs(C - B) - b) < tol and abs(abs(C - D) - c) < tol
                cross = ((D - B).conjugate() * (C - B)).imag
                assert cross * branch > 0
    return True


if __name__ == "__main__":
    import time

    geometry = dict(a=1.0, b=4.0, c=3.0, d=3.5)
    print("self check:", self_check(**geometry, coupler=(2.0, 1.0)))
    start = time.perf_counter()
    P, vP, aP = coupler_reference(np.linspace(0, 2 * np.pi, 200), **geometry, coupler=(2.0, 1.0))
    print(f"200 angles in {time.perf_counter() - start:.2f} s; P[0] = {P[0]}, vP[0] = {vP[0]}")
