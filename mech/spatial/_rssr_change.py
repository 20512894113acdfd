"""The RSSR through its change points: the root of (2-71) taken with its sign.

A, B, C of A cos(phi03) + B sin(phi03) = C are trigonometric polynomials of degree 1 in
the crank angle phi01, so the discriminant D = A^2 + B^2 - C^2 is one of degree 2. Where D
has a double zero without changing sign (a change point) the two branches meet, and the
plain root sqrt(D) has a corner: following one sign of it jumps from one smooth solution
to the other. Writing D = 4 sin^2((t - t_k)/2) q(t) for each double zero t_k (deflation of
its Fourier coefficients, exact for a trigonometric polynomial), the smooth root is
prod_k 2 sin((t - t_k)/2) sqrt(q(t)), which changes sign at each t_k. Where A, B and C all
vanish together (the crank pin B on the rocker axis, with every rocker angle a solution:
the spatial kite), each of them is 2 sin((phi01 - phi_b)/2) times a trigonometric
polynomial in t = (phi01 + phi_b)/2, and the equation is solved with that common factor
cancelled, so the pose there is the limit along the branch. Rates are the exact
derivatives of the same closed form (`mech._jet`), as for the spherical four-bar
(`mech.spherical._fourbar_branch`), so they are finite and continuous at the change points.

`branch` names the sign of the root at the smallest non-negative crank angle where the two
branches differ, the rule of the planar and spherical four-bars.
"""

import numpy as np

from mech._generated import rssr as _gen
from mech._jet import Jet, jet_atan2
from mech._scaling import DEAD_POINT_RTOL

__all__ = ["ChangePoints", "change_points"]

_SAMPLES = 720


def _triples(dims):
    """(x0, x1, x2) of x = x0 + x1 cos(phi01) + x2 sin(phi01) for x in A, B, C."""
    phi = np.array([0.0, np.pi / 2, np.pi, -np.pi / 2])
    values = np.array(_gen.rssr_abc(*dims, phi))        # rows A, B, C; columns 0, pi/2, pi, -pi/2
    out = []
    for v0, v1, v2, v3 in values:
        x0 = 0.5 * (v0 + v2)
        out.append((x0, 0.5 * (v0 - v2), 0.5 * (v1 - v3)))
    return out


def _fourier(triples):
    """Coefficients c_0, c_1, c_2 (complex) of D(t) = sum c_k exp(i k t), c_-k = conj(c_k)."""
    c = np.zeros(3, dtype=complex)
    for sign, (x0, x1, x2) in zip((1.0, 1.0, -1.0), triples):
        alpha = 0.5 * (x1 - 1j * x2)                    # x = x0 + alpha z + conj(alpha) / z
        c += sign * np.array([x0 * x0 + 2.0 * abs(alpha) ** 2, 2.0 * x0 * alpha, alpha * alpha])
    return c


def _evaluate(c, t, k=0):
    """The k-th derivative of D(t) = c_0 + 2 Re(c_1 e^{it} + c_2 e^{2it})."""
    z = np.exp(1j * t)
    return (c[0].real if k == 0 else 0.0) + 2.0 * np.real((1j) ** k * c[1] * z + (2j) ** k * c[2] * z * z)


def _double_zeros(c, rtol):
    """Double zeros t in [0, 2 pi) of D(t) >= 0 (local minima within rtol of zero)."""
    norm = abs(c[0]) + 2.0 * (abs(c[1]) + abs(c[2]))
    if norm == 0.0:
        return []
    t = np.arange(_SAMPLES) * (2 * np.pi / _SAMPLES)
    D = _evaluate(c, t)
    found = []
    for i in np.flatnonzero((D <= np.roll(D, 1)) & (D <= np.roll(D, -1))):
        x = t[i]
        for _ in range(60):                              # Newton on D'(t) = 0
            d1, d2 = _evaluate(c, x, 1), _evaluate(c, x, 2)
            if d2 <= 0.0:
                break
            step = d1 / d2
            x -= step
            if abs(step) <= 1e-17:
                break
        x = float(np.mod(x, 2 * np.pi))
        if abs(x - 2 * np.pi) <= 1e-13 or abs(x) <= 1e-13:
            x = 0.0
        if _evaluate(c, x, 2) > 0.0 and abs(_evaluate(c, x)) <= rtol * norm:
            if all(abs(np.angle(np.exp(1j * (x - y)))) > 1e-9 for y in found):
                found.append(x)
    return sorted(found)


def _deflate(c, t0):
    """Coefficients of q with D(t) = 4 sin^2((t - t0)/2) q(t)."""
    w = np.exp(1j * t0)
    q1 = -c[2] * w
    q0 = ((2.0 * q1 - c[1]) * w).real
    return np.array([q0, q1, 0.0], dtype=complex)


class ChangePoints:
    """The smooth-root solver of a change-point RSSR (see the module docstring)."""

    def __init__(self, triples, shift, half, sign0, zeros, q, rtol):
        self.triples, self.shift, self.half = triples, shift, half
        self.sign0, self.zeros, self.q, self.rtol = sign0, zeros, q, rtol

    def crank_angles(self):
        """The crank angles in [0, 2 pi) where the branches meet."""
        if not self.half:
            return sorted(float(np.mod(t, 2 * np.pi)) for t in self.zeros)
        angles = [float(np.mod(self.shift, 2 * np.pi))]
        angles += [float(np.mod(2 * t - self.shift, 2 * np.pi)) for t in self.zeros]
        unique = []
        for x in sorted(angles):
            x = 0.0 if abs(x - 2 * np.pi) <= 1e-12 else x
            if all(abs(x - y) > 1e-12 for y in unique):
                unique.append(x)
        return unique

    def solve(self, phi01, branch, order):
        """Jets of phi03 (not wrapped) in phi01, the mask where it assembles and the mask
        of its limit positions (dead points, where the rates are infinite)."""
        zero = np.zeros_like(phi01)
        ph = Jet(phi01, zero + 1.0 if order >= 1 else None, zero if order >= 2 else None, order)
        t = (ph + self.shift) * 0.5 if self.half else ph
        ct, st = t.cos(), t.sin()
        A, B, C = (ct * x1 + st * x2 + x0 for x0, x1, x2 in self.triples)
        q = ct * (2.0 * self.q[1].real) - st * (2.0 * self.q[1].imag) + self.q[0].real
        if self.q[2] != 0.0:
            t2 = t * 2.0
            q = q + t2.cos() * (2.0 * self.q[2].real) - t2.sin() * (2.0 * self.q[2].imag)
        norm = abs(self.q[0]) + 2.0 * (abs(self.q[1]) + abs(self.q[2]))
        ok = q.v >= -DEAD_POINT_RTOL * norm
        q = q.where(q.v < 0.0, 0.0)
        root = q.sqrt() * (branch * self.sign0)
        for tk in self.zeros:
            root = root * ((t - tk) * 0.5).sin() * 2.0
        phi03 = jet_atan2(A * root + B * C, A * C - B * root)
        return phi03, ok, q.v <= DEAD_POINT_RTOL * norm


def change_points(dims, rtol):
    """`ChangePoints` for an RSSR of unit dimensions `dims`, or None without change points."""
    triples = _triples(dims)
    c = _fourier(triples)
    zeros = _double_zeros(c, rtol)
    if not zeros:
        return None
    size = max(abs(x) for tr in triples for x in tr)
    through = [z for z in zeros
               if all(abs(x0 + x1 * np.cos(z) + x2 * np.sin(z)) <= rtol * size for x0, x1, x2 in triples)]
    shift, half, sign0 = 0.0, False, 1.0
    if through:
        # the crank pin crosses the rocker axis: cancel 2 sin((phi01 - phi_b)/2) from A, B, C
        # and solve in t = (phi01 + phi_b)/2; the original root is that factor times the new
        # one, whose sign at phi01 = 0+ is +1 only if phi_b = 0
        phib = through[0]
        shift, half, sign0 = phib, True, (1.0 if phib == 0.0 else -1.0)
        triples = [(0.0, x2, -x1) for _, x1, x2 in triples]
        c = _fourier(triples)
        zeros = _double_zeros(c, rtol)
        start = 0.5 * phib                               # t at phi01 = 0
    else:
        start = 0.0
    # each factor 2 sin((t - t_k)/2) is negative just above the start unless t_k is the start
    ks = []
    q = c
    for tk in zeros:
        tk = start + float(np.mod(tk - start, 2 * np.pi))
        if abs(tk - start - 2 * np.pi) <= 1e-13:
            tk = start
        ks.append(tk)
        q = _deflate(q, tk)
        if tk != start:
            sign0 = -sign0
    return ChangePoints(triples, shift, half, sign0, ks, q, rtol)
