"""Change-point four-bars: rates that stay finite where the two branches meet, and the kite.

At a change point of a four-bar (s + l = p + q) the four joints fall on one line, the area
term S of the triangle BCD vanishes, and the velocity formula of the generated code, a
ratio of two cross products that both vanish there, reads 0/0. Along the smooth branch
the rates have finite limits. They are found here by writing S as the product of the
factor that vanishes, sin(theta/2) or cos(theta/2), and a reduced root R that does not:

    S = sin(theta/2)**m23 * cos(theta/2)**m4 * R,

so that sin(theta)/S, the only singular ratio in the rates, becomes a quotient of smooth
functions. The accelerations are the theta-derivatives of the velocity ratios, found by
the chain rule through the same factors.

The kite a = d, b = c (the rhombus included) also has its crank pin B on the pivot D at
theta = 0: the diagonal BD has zero length and its direction is that of the smooth unit
vector (sin(theta/2), -cos(theta/2)). Writing BD as its signed length 2 a sin(theta/2)
times that unit vector gives C, P and the rates there as the limits along the branch.

All lengths here are normalised (the longest link between 1/2 and 1, see `_fourbar`).
"""

import numpy as np

__all__ = []        # internal to the subpackage: nothing here is re-exported


def _ratio_slopes(a, b, c, d, s, ch, T, dT, sigma):
    """Velocity ratios omega_coupler/omega, omega_output/omega and their theta-derivatives.

    With E = |BD|^2, N = b^2 - c^2 + E and T = sin(theta)/S, differentiating the loop gives
    g3 = (a d sigma T N + a (a - d) + 2 a d s^2) / E and the same for g2 with N replaced
    by b^2 - c^2 - E; their derivatives follow with dE/dtheta = 2 a d sin(theta).
    """
    sin_t = 2.0 * s * ch
    E = (a - d) ** 2 + 4.0 * a * d * s * s
    dE = 2.0 * a * d * sin_t
    base = a * (a - d) + 2.0 * a * d * s * s
    out = []
    for sign in (-1.0, 1.0):            # coupler (g2), then output (g3)
        M = b * b - c * c + sign * E
        g = (a * d * sigma * T * M + base) / E
        dg = (a * d * sigma * (sign * dE * T + M * dT) + a * d * sin_t - g * dE) / E
        out.append((g, dg))
    return out


def change_point_rates(a, b, c, d, theta, branch, gaps, m23, m4):
    """Velocity ratios and their derivatives of a change-point linkage that is not a kite.

    Returns ``((g2, dg2), (g3, dg3))`` with g = omega_link / omega and dg = dg/dtheta, so
    that omega_link = g omega and alpha_link = g alpha + dg omega^2.
    """
    g2, g3, g4 = gaps
    s, ch = np.sin(0.5 * theta), np.cos(0.5 * theta)
    ad4 = 4.0 * a * d
    k = np.sqrt((a - d) ** 2 + ad4 * s * s)
    m = abs(a - d)
    near = ad4 * s * s / (k + m)            # k - m without cancellation
    far = ad4 * ch * ch / (d + a + k)       # (d + a) - k likewise
    f1 = b + c + k
    # each factor of S^2 and d(log factor)/dk; a zero gap leaves the reduced factor
    F2, L2 = (ad4 / (k + m), -1.0 / (k + m)) if g2 == 0.0 else (near + g2, 1.0 / (near + g2))
    F3, L3 = (ad4 / (k + m), -1.0 / (k + m)) if g3 == 0.0 else (near + g3, 1.0 / (near + g3))
    F4, L4 = (ad4 / (d + a + k), -1.0 / (d + a + k)) if g4 == 0.0 else (far + g4, -1.0 / (far + g4))
    R = np.sqrt(f1 * F2 * F3 * F4)
    dk = a * d * 2.0 * s * ch / k
    dlogR = 0.5 * dk * (1.0 / f1 + L2 + L3 + L4)
    # sin(theta) = 2 s ch, less the factors that S shares with it
    num, dnum = {
        (0, 0): (2.0 * s * ch, np.cos(theta)),
        (1, 0): (2.0 * ch, -s),
        (0, 1): (2.0 * s, ch),
        (1, 1): (2.0 + 0.0 * s, 0.0 * s),
    }[(m23, m4)]
    T = num / R
    dT = dnum / R - T * dlogR
    return _ratio_slopes(a, b, c, d, s, ch, T, dT, branch)


def kite_pose(a, b, gap4, m4, p, q, theta, branch):
    """Joints, area term and velocity ratios of the kite a = d, b = c, through B = D.

    Returns ``B, C, P, S, ((g2, dg2), (g3, dg3))`` (B, C, P complex; S NaN where the
    linkage cannot be assembled).
    """
    s, ch = np.sin(0.5 * theta), np.cos(0.5 * theta)
    ks = 2.0 * a * s                        # signed length of BD
    k = np.abs(ks)
    f1 = 2.0 * b + k
    f4 = gap4 + 4.0 * a * a * ch * ch / (2.0 * a + k)
    F4 = 4.0 * a * a / (2.0 * a + k) if m4 else f4
    RW = np.sqrt(f1 * F4)
    W = ch * RW if m4 else RW               # S / ks, signed by cos(theta/2) on the rhombus
    B = a * ((1.0 - 2.0 * s * s) + 2j * s * ch)
    u = s - 1j * ch                         # unit vector along B->D, smooth through B = D
    C = B + u * (ks + 1j * branch * W) / 2.0
    P = B + (p + 1j * q) * (C - B) / b
    # T = sin(theta)/S = cos(theta/2)^(1 - m4) / (a RW); d log RW/dtheta from RW^2 = f1 f4
    T = (1.0 if m4 else ch) / (a * RW)
    dlogRW = 0.0 if m4 else -a * a * 2.0 * s * ch / (f1 * f4)
    dT = (0.0 if m4 else -0.5 * s) / (a * RW) - T * dlogRW
    half = 0.5 + 0.0 * s
    rates = ((half - branch * a * a * T, -branch * a * a * dT),
             (half + branch * a * a * T, branch * a * a * dT))
    return B, C, P, ks * W, rates
