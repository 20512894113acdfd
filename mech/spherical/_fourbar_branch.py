"""The spherical four-bar through its change points: a smooth closed form and its rates.

Used by `SphericalFourBar` for change-point linkages only (its two branches meet at theta = 0
or pi). The output angle is written psi = delta - branch * beta, with delta the direction
of D->B at D and beta the angle at D of the triangle BCD from the spherical half-angle
formula tan^2(beta/2) = F2 F4 / (F1 F3). Each factor F is the sine of half the distance of
the arc g = BD from one end of its window, written as a smooth part plus a constant gap, so
that at a change point (a gap of zero) the factor is a perfect square whose root is taken
with its sign (sin(theta/2) at theta = 0, cos(theta/2) at theta = pi). Where B passes
through D (a = d, b = c) or through the antipode of D (a + d = b + c = pi), the common
factors of delta and beta are cancelled, so the pose there is the limit along the branch.
Rates are exact derivatives of the same closed form, carried by truncated Taylor series in
theta (`_Jet`), so they are continuous through the change points too. Derivation:
:ref:`deriv-spherical-fourbar`, eqs. (11) to (13).
"""

import numpy as np

from mech._jet import Jet as _Jet, jet_atan2 as _atan2

__all__ = ["change_gaps", "solve_change_point"]


def change_gaps(a, b, c, d, rtol):
    """The four gaps of the arc BD to the ends of the triangle window, with zero flags.

    gap2 = |a - d| - (c - b) and gap3 = |a - d| - (b - c) (theta = 0, g at its least);
    gap4 = (b + c) - g_pi and gap1 = (2 pi - b - c) - g_pi (theta = pi, g at its most,
    g_pi = min(a + d, 2 pi - a - d)). A gap within ``rtol * (a + b + c + d)`` of zero is
    set to zero: the branches meet at theta = 0 if gap2 or gap3 is zero and at theta = pi
    if gap4 or gap1 is zero.
    """
    g0 = abs(a - d)
    gpi = min(a + d, 2 * np.pi - a - d)
    gaps = {2: g0 - (c - b), 3: g0 - (b - c), 4: (b + c) - gpi, 1: (2 * np.pi - b - c) - gpi}
    tol = rtol * (a + b + c + d)
    return {k: (0.0 if abs(v) <= tol else float(v)) for k, v in gaps.items()}


def solve_change_point(dims, coupler, gaps, theta, branch, order):
    """Positions (and theta-derivatives up to `order`) of a change-point linkage.

    Returns jets ``psi`` and ``B, C, P`` (tuples of three jets) in the default frame; psi
    is not wrapped. NaN where it cannot be assembled.
    """
    a, b, c, d = dims
    r, gamma = coupler
    sa, ca, sd, cd = np.sin(a), np.cos(a), np.sin(d), np.cos(d)
    K = sa * sd
    g0, gpi = abs(a - d), min(a + d, 2 * np.pi - a - d)
    z = {k: v == 0.0 for k, v in gaps.items()}
    # sine and cosine of each half gap; gap1 = 2 pi - (b + c + g_pi) is taken through its
    # supplement, since 2 pi - x rounded to a double loses the digits of a small x
    half_gap = {k: (np.sin(v / 2), np.cos(v / 2)) for k, v in gaps.items()}
    x1 = (b + c + gpi) / 2
    half_gap[1] = (0.0, 1.0) if z[1] else (np.sin(x1), -np.cos(x1))
    through_d = z[2] and z[3]            # a = d, b = c: B passes through D at theta = 0
    through_anti = z[4] and z[1]         # a + d = b + c = pi: B passes through -D at pi
    zero = np.zeros_like(theta)
    th = _Jet(theta, zero + 1.0 if order >= 1 else None, zero if order >= 2 else None, order)
    half = th * 0.5
    s, ch = half.sin(), half.cos()
    neg_s, neg_ch = s.v < 0.0, ch.v < 0.0

    if through_d and through_anti:
        # every arc pi/2: C stays at a pole of the great circle through B and D
        delta = _Jet.const(np.pi / 2, th)
        beta = _Jet.const(np.pi / 2, th)
    else:
        # g = BD by the haversine form: both squares are sums of non-negative terms
        if through_d:
            root0 = s * np.sqrt(K)                     # signed: the arc BD reverses at 0
        else:
            root0 = (s * s * K + np.sin((a - d) / 2) ** 2).sqrt()
        if through_anti:
            root_pi = ch * np.sqrt(K)
        else:
            root_pi = (ch * ch * K + np.cos((a + d) / 2) ** 2).sqrt()
        g_hat = 2.0 * _atan2(root0, root_pi)
        if through_d:
            g = g_hat.where(neg_s, -g_hat)
        elif through_anti:
            g = g_hat.where(neg_ch, 2 * np.pi - g_hat)
        else:
            g = g_hat
        roots = {}
        if not through_d:
            # sin((g - g0)/2) = K s^2 / sin((g + g0)/2), exact where g is near g0
            den0 = ((g + g0) * 0.5).sin()
            for k in (2, 3):
                if z[k]:
                    roots[k] = s * (K / den0).sqrt()
                else:
                    lo = (s * s * K) / den0
                    sin_h, cos_h = half_gap[k]
                    roots[k] = (lo * cos_h + ((g - g0) * 0.5).cos() * sin_h).sqrt()
        if not through_anti:
            den_pi = ((g + gpi) * 0.5).sin()
            for k in (4, 1):
                if z[k]:
                    roots[k] = ch * (K / den_pi).sqrt()
                else:
                    hi = (ch * ch * K) / den_pi
                    sin_h, cos_h = half_gap[k]
                    roots[k] = (hi * cos_h + ((gpi - g) * 0.5).cos() * sin_h).sqrt()
        if through_d:
            # the common factor sqrt(F2 F3) = sin(g/2) is cancelled; past theta = 0 the
            # signed arc -g swaps F1 and F4
            beta = 2.0 * _atan2(roots[4].where(neg_s, roots[1]), roots[1].where(neg_s, roots[4]))
            x_dir, y_dir = -cd * s, ch
        elif through_anti:
            beta = 2.0 * _atan2(roots[2].where(neg_ch, roots[3]), roots[3].where(neg_ch, roots[2]))
            x_dir, y_dir = cd * ch, s
        else:
            beta = 2.0 * _atan2(roots[2] * roots[4], roots[1] * roots[3])
            # D->B in the frame at D, each form exact near its own end of the turn
            near0 = np.sin(a - d) - 2 * sa * cd * (s * s)
            near_pi = 2 * sa * cd * (ch * ch) - np.sin(a + d)
            x_dir = near0.where(np.cos(theta) < 0.0, near_pi)
            y_dir = 2 * sa * (s * ch)
        delta = _atan2(y_dir, x_dir)
    psi = delta - branch * beta

    sb, sc, cc = np.sin(b), np.sin(c), np.cos(c)
    cth, sth = th.cos(), th.sin()
    B = (cth * sa, sth * sa, _Jet.const(ca, th))
    cp, sp = psi.cos(), psi.sin()
    C = (cp * (cd * sc) + cc * sd, sp * sc, cc * cd - cp * (sc * sd))
    e1 = (cth * ca, sth * ca, _Jet.const(-sa, th))
    e2 = (-sth, cth)
    u1 = e1[0] * C[0] + e1[1] * C[1] + e1[2] * C[2]
    u2 = e2[0] * C[0] + e2[1] * C[1]
    cg, sg = np.cos(gamma), np.sin(gamma)
    k1 = (u1 * cg - u2 * sg) * (np.sin(r) / sb)
    k2 = (u2 * cg + u1 * sg) * (np.sin(r) / sb)
    cr = np.cos(r)
    P = (B[0] * cr + k1 * e1[0] + k2 * e2[0], B[1] * cr + k1 * e1[1] + k2 * e2[1], B[2] * cr + k1 * e1[2])
    return psi, B, C, P
