"""Second, independent solver of the ready-made linkages in mpmath (50 digits).

Nothing here uses ``mech``: every linkage is rebuilt from its dimensions by the law of
cosines (the angle at a known pin by ``mpmath.acos``, the base direction by
``mpmath.atan2``), not by the generated Assur-group formulas, and every rate comes from
``mpmath.diff`` of the positions along the crank angle:

    v = omega P'(theta),   a = omega^2 P''(theta) + alpha P'(theta).

The default dimensions are written out again here, so that a change of a library default
shows up as a failing comparison rather than passing silently.
"""

from __future__ import annotations

import mpmath

__all__ = ["DPS", "watt_positions", "stephenson_positions", "jansen_positions", "rates", "REFERENCES"]

DPS = 50

WATT = dict(crank=20, coupler=50, rocker=45, frame=50, lever=44, lever_angle_deg=-150,
            pivot=(68, -9), link5=24, output=18)
STEPHENSON = dict(crank=20, coupler=50, rocker=45, frame=50, point=(55, 15), pivot=(54, -27),
                  link5="82.3", output=8)
JANSEN = dict(a=38, b="41.5", c="39.3", d="40.1", e="55.8", f="39.4", g="36.7", h="65.7",
              i=49, j=50, k="61.9", l="7.8", m=15)


def _f(x):
    return mpmath.mpf(x)


def _pt(xy):
    return mpmath.mpc(_f(xy[0]), _f(xy[1]))


def _pin(P1, P2, r1, r2, side):
    """The point at r1 from P1 and r2 from P2, left of P1->P2 if side > 0 (law of cosines)."""
    g = P2 - P1
    dist = abs(g)
    base = mpmath.atan2(g.imag, g.real)
    gamma = mpmath.acos((r1 * r1 + dist * dist - r2 * r2) / (2 * r1 * dist))
    return P1 + r1 * mpmath.expj(base + side * gamma)


def _along(P, Q, r, angle):
    """The point at r from P, at ``angle`` from the direction P->Q."""
    g = Q - P
    return P + r * mpmath.expj(mpmath.atan2(g.imag, g.real) + angle)


def watt_positions(theta, dims=WATT):
    """Moving points of `watt_six_bar` (defaults) at crank angle theta."""
    p = {k: (_f(v) if not isinstance(v, tuple) else _pt(v)) for k, v in dims.items()}
    A, D, F = mpmath.mpc(0), mpmath.mpc(p["frame"]), p["pivot"]
    B = A + p["crank"] * mpmath.expj(theta)
    C = _pin(B, D, p["coupler"], p["rocker"], +1)
    E = _along(D, C, p["lever"], mpmath.radians(p["lever_angle_deg"]))
    G = _pin(E, F, p["link5"], p["output"], -1)
    return {"B": B, "C": C, "E": E, "G": G}


def stephenson_positions(theta, dims=STEPHENSON):
    """Moving points of `stephenson_six_bar` (defaults) at crank angle theta."""
    p = {k: (_f(v) if not isinstance(v, tuple) else _pt(v)) for k, v in dims.items()}
    A, D, H = mpmath.mpc(0), mpmath.mpc(p["frame"]), p["pivot"]
    B = A + p["crank"] * mpmath.expj(theta)
    C = _pin(B, D, p["coupler"], p["rocker"], +1)
    E = B + p["point"] * (C - B) / p["coupler"]
    G = _pin(E, H, p["link5"], p["output"], +1)
    return {"B": B, "C": C, "E": E, "G": G}


def jansen_positions(theta, dims=JANSEN):
    """Moving points of `jansen_linkage` (holy numbers) at crank angle theta."""
    n = {k: _f(v) for k, v in dims.items()}
    O, Z = mpmath.mpc(0), mpmath.mpc(-n["a"], -n["l"])
    A = O + n["m"] * mpmath.expj(theta)
    B = _pin(A, Z, n["j"], n["b"], -1)
    C = _pin(Z, B, n["d"], n["e"], +1)
    D = _pin(A, Z, n["k"], n["c"], +1)
    E = _pin(C, D, n["f"], n["g"], -1)
    F = _pin(D, E, n["i"], n["h"], +1)
    return {"A": A, "B": B, "C": C, "D": D, "E": E, "F": F}


REFERENCES = {"watt": watt_positions, "stephenson": stephenson_positions, "jansen": jansen_positions}


def rates(positions, theta, omega=1, alpha=0):
    """Positions, velocities and accelerations of every point, each a dict name -> mpc.

    ``positions(theta)`` gives the points; the derivatives along theta come from
    ``mpmath.diff`` (real and imaginary parts separately) at ``DPS`` digits.
    """
    with mpmath.workdps(DPS):
        theta, omega, alpha = _f(theta), _f(omega), _f(alpha)
        cache = {}

        def at(t):
            key = mpmath.nstr(t, DPS + 10)
            if key not in cache:
                cache[key] = positions(t)
            return cache[key]

        P = positions(theta)
        V, Acc = {}, {}
        for name in P:
            d1 = [mpmath.diff(lambda t, f=f: f(at(t)[name]), theta, 1) for f in (mpmath.re, mpmath.im)]
            d2 = [mpmath.diff(lambda t, f=f: f(at(t)[name]), theta, 2) for f in (mpmath.re, mpmath.im)]
            p1, p2 = mpmath.mpc(*d1), mpmath.mpc(*d2)
            V[name] = omega * p1
            Acc[name] = omega**2 * p2 + alpha * p1
        return P, V, Acc
