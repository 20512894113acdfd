"""Tests of exercises 2-17, 2-18 and 2-26 (reactions in the pairs on assumed layouts).

The expected values come from another route than `static_forces` (which solves one Assur
group at a time from the load back to the driver): the positions are written by hand as
circle and line intersections and evaluated with mpmath at 50 digits, and the free-body
equations of every member at once are solved as one system in mpmath (a linear solve
without friction, `mpmath.findroot` with the friction circles and the friction angle).
The balancing effort is checked once more by virtual work, with the velocities from
mpmath's numerical differentiation of the hand positions.
"""

import math
import subprocess
import sys

import mpmath as mp
import pytest

from mech.exercises import chapter2_reactions as cr

mp.mp.dps = 50
SEEDS = [0, 1, 7]


def _circles(p, rp, q, rq, side):
    d = q - p
    L = abs(d)
    a = (rp * rp - rq * rq + L * L) / (2 * L)
    return p + d / L * mp.mpc(a, side * mp.sqrt(rp * rp - a * a))


def _cross(a, b):
    return a.real * b.imag - a.imag * b.real


def _c(v):
    return mp.mpc(v[0], v[1])


# ----------------------------------------------------------------------------- 2-17
def _pose_2_17(p, t):
    ab = mp.mpf(p["AB"])
    B = ab * mp.expjpi(t / mp.pi)
    D = 2 * ab
    C = _circles(B, 2 * ab, mp.mpc(D), 2 * ab, 1)
    S = D + (C - D) * mp.mpf(3) / 4
    return B, C, mp.mpc(D), S


def _hand_2_17(p):
    ab = mp.mpf(p["AB"])
    t0 = mp.radians(p["theta"])
    _, _, _, S0 = _pose_2_17(p, t0)
    yg = S0.imag - ab / 4                                 # SK at 30° to the guide: 0.5 AB sin 30°

    def K(t):
        _, _, _, S = _pose_2_17(p, t)
        return mp.mpc(S.real + mp.sqrt((ab / 2) ** 2 - (yg - S.imag) ** 2), yg)
    B, C, D, S = _pose_2_17(p, t0)
    k = K(t0)
    vK = mp.diff(lambda t: K(t).real, t0)
    P5 = -mp.mpf(p["P5"]) * mp.sign(vK)
    # unknowns: R_A, R_B, R_C, R_D, R_S, R_K (force on the later link), N, Mb
    idx = {n: i for i, n in enumerate(["Ax", "Ay", "Bx", "By", "Cx", "Cy", "Dx", "Dy", "Sx", "Sy", "Kx", "Ky", "N", "Mb"])}
    rows, rhs = [], []

    def eq(terms, value=0):
        row = [mp.mpf(0)] * len(idx)
        for name, coef in terms:
            row[idx[name]] += coef
        rows.append(row)
        rhs.append(value)

    def force(plus, minus):          # sum of forces on a link: + plus pairs, - minus pairs
        for comp in "xy":
            eq([(n + comp, 1) for n in plus] + [(n + comp, -1) for n in minus])

    def moment(about, items, extra=(), value=0):   # items: (pair, point, sign)
        terms = list(extra)
        for n, at, sgn in items:
            r = at - about
            terms += [(n + "x", -sgn * r.imag), (n + "y", sgn * r.real)]
        eq(terms, value)
    force(["A"], ["B"]); moment(mp.mpc(0), [("B", B, -1)], [("Mb", 1)])
    force(["B"], ["C"]); moment(B, [("C", C, -1)])
    force(["C", "D"], ["S"]); moment(D, [("C", C, 1), ("S", S, -1)])
    force(["S"], ["K"]); moment(S, [("K", k, -1)])
    eq([("Kx", 1)], -P5)
    eq([("Ky", 1), ("N", 1)], 0)
    x = mp.lu_solve(mp.matrix(rows), mp.matrix(rhs))
    sol = {n: x[i] for n, i in idx.items()}
    work = -P5 * vK                                     # Mb * omega + P5 . v_K = 0, omega = 1
    return sol, work


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_exercise_2_17_against_global_free_body(seed):
    ex = cr.EXERCISE_2_17
    p = ex.defaults if seed is None else ex.variant(seed)
    s = ex.solve(p)
    hand, work = _hand_2_17(p)
    Mb = float(hand["Mb"])
    assert s["balancing moment on member 1"].value * 1000 == pytest.approx(Mb, rel=1e-10)
    assert Mb == pytest.approx(float(work), rel=1e-10)
    assert s["balancing force P1"].value == pytest.approx(Mb / (p["AB"] / 2), rel=1e-10)
    for label, pin in (("R_01", "A"), ("R_12", "B"), ("R_23", "C"), ("R_03", "D"), ("R_34", "S"), ("R_45", "K")):
        R = complex(hand[pin + "x"], hand[pin + "y"])
        where = {"K": "K", "S": "S"}.get(pin, pin)
        assert s[f"{label} at {where}"].value == pytest.approx(abs(R), rel=1e-10)
        assert s[f"direction of {label}"].value == pytest.approx(math.atan2(R.imag, R.real), abs=1e-10)
    assert s["R_05 at the guide"].value == pytest.approx(abs(float(hand["N"])), rel=1e-10)


# ----------------------------------------------------------------------------- 2-18
def _hand_2_18(p):
    ab = mp.mpf(p["AB"])
    E = mp.mpc(2.5 * ab, ab)
    t0 = mp.radians(p["theta"])

    def pose(t):
        B = ab * mp.expjpi(t / mp.pi)
        C = _circles(B, 2 * ab, E, ab, 1)
        D = 2 * E - C
        F = mp.mpc(D.real + mp.sqrt(ab ** 2 - (D.imag + ab / 2) ** 2), -ab / 2)
        return B, C, D, F
    B, C, D, F = pose(t0)
    vF = mp.diff(lambda t: pose(t)[3].real, t0)
    P5 = -mp.mpf(p["P5"]) * mp.sign(vF)
    names = ["Ax", "Ay", "Bx", "By", "Cx", "Cy", "Ex", "Ey", "Dx", "Dy", "Fx", "Fy", "N", "Mb"]
    M = mp.zeros(14, 14)
    rhs = mp.zeros(14, 1)
    col = {n: i for i, n in enumerate(names)}
    row = [0]

    def put(terms, value=0):
        for n, c in terms:
            M[row[0], col[n]] += c
        rhs[row[0]] = value
        row[0] += 1

    def link(plus, minus, about, arms, extra=()):
        for comp in "xy":
            put([(n + comp, 1) for n in plus] + [(n + comp, -1) for n in minus])
        terms = list(extra)
        for n, at, sgn in arms:
            r = at - about
            terms += [(n + "x", -sgn * r.imag), (n + "y", sgn * r.real)]
        put(terms)
    link(["A"], ["B"], mp.mpc(0), [("B", B, -1)], [("Mb", 1)])
    link(["B"], ["C"], B, [("C", C, -1)])
    link(["C", "E"], ["D"], E, [("C", C, 1), ("D", D, -1)])
    link(["D"], ["F"], D, [("F", F, -1)])
    put([("Fx", 1)], -P5)
    put([("Fy", 1), ("N", 1)])
    x = mp.lu_solve(M, rhs)
    return {n: x[i] for n, i in col.items()}, -P5 * vF


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_exercise_2_18_against_global_free_body(seed):
    ex = cr.EXERCISE_2_18
    p = ex.defaults if seed is None else ex.variant(seed)
    s = ex.solve(p)
    hand, work = _hand_2_18(p)
    assert s["balancing moment M1"].value * 1000 == pytest.approx(float(hand["Mb"]), rel=1e-10)
    assert float(hand["Mb"]) == pytest.approx(float(work), rel=1e-10)
    for label, pin, where in (("R_01", "A", "A"), ("R_12", "B", "B"), ("R_23", "C", "C"), ("R_03", "E", "E"),
                              ("R_34", "D", "D"), ("R_45", "F", "F")):
        R = complex(hand[pin + "x"], hand[pin + "y"])
        assert s[f"{label} at {where}"].value == pytest.approx(abs(R), rel=1e-10)
        assert s[f"direction of {label}"].value == pytest.approx(math.atan2(R.imag, R.real), abs=1e-10)


# ----------------------------------------------------------------------------- 2-26
def _hand_2_26(p, deg):
    r, l, rho = mp.mpf(p["r"]), mp.mpf(p["l"]), mp.mpf(p["mu0"]) * mp.mpf(p["d"]) / 2
    mu, Mr = mp.mpf(p["mu"]), mp.mpf(p["Mr"]) * 1000

    def pose(t):
        B = r * mp.expjpi(t / mp.pi)
        C = mp.mpc(B.real + mp.sqrt(l * l - B.imag ** 2), 0)
        return B, C
    t0 = mp.radians(deg)
    B, C = pose(t0)
    w1 = mp.mpf(1)
    w2 = mp.diff(lambda t: mp.arg(pose(t)[1] - pose(t)[0]), t0)
    v3 = mp.diff(lambda t: pose(t)[1].real, t0)
    s = mp.sign

    def equations(Ax, Ay, Bx, By, Cx, Cy, N, F, friction=1):
        RA, RB, RC = mp.mpc(Ax, Ay), mp.mpc(Bx, By), mp.mpc(Cx, Cy)   # on crank from frame, on rod
        k = friction                                                  # from crank, on slider from rod
        return [
            Ax - Bx, Ay - By,
            _cross(B, -RB) - k * s(w1) * rho * abs(RA) - k * s(w1 - w2) * rho * abs(RB) - Mr,
            Bx - Cx, By - Cy,
            _cross(C - B, -RC) - k * s(w2 - w1) * rho * abs(RB) - k * s(w2) * rho * abs(RC),
            Cx - k * s(v3) * mu * abs(N) + F, Cy + N,
        ]
    lin = mp.findroot(lambda *x: equations(*x, friction=0), [1] * 8)
    sol = mp.findroot(equations, list(lin))
    return dict(zip(["Ax", "Ay", "Bx", "By", "Cx", "Cy", "N", "F"], sol)), rho


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_exercise_2_26_against_global_free_body(seed):
    ex = cr.EXERCISE_2_26
    p = ex.defaults if seed is None else ex.variant(seed)
    s = ex.solve(p)
    for deg in cr.THETAS_2_26:
        hand, rho = _hand_2_26(p, deg)
        tag = f"θ = {deg:g}°"
        assert s[f"{tag}: driving force F"].value == pytest.approx(float(hand["F"]), rel=1e-9)
        for label, key in (("R_41", "A"), ("R_21", "B"), ("R_23", "C")):
            R = complex(hand[key + "x"], hand[key + "y"]) * (-1 if label == "R_21" else 1)
            assert s[f"{tag}: {label} size"].value == pytest.approx(abs(R), rel=1e-9)
            assert s[f"{tag}: {label} direction"].value == pytest.approx(math.atan2(R.imag, R.real), abs=1e-9)
            assert abs(s[f"{tag}: {label} moment arm about {key}"].value) == pytest.approx(float(rho), rel=1e-9)
        N = float(hand["N"])
        assert abs(s[f"{tag}: R_43 tilt from the guide normal"].value) == pytest.approx(math.atan(p["mu"]), rel=1e-9)
        assert N != 0


@pytest.mark.parametrize("number", ["2-17", "2-18", "2-25", "2-26"])
def test_cli_show_and_variant(number):
    for args in (["show", number], ["variant", number, "--seed", "7"]):
        out = subprocess.run([sys.executable, "-m", "mech.exercises", *args], capture_output=True, text=True,
                             check=True).stdout
        assert f"Solution of exercise {number}" in out and "Assumed layout" in out


# ----------------------------------------------------------------------------- 2-25
def _hand_2_25(p):
    """The cam and the follower as two free bodies with the contact force written directly.

    R12 = N n + f t at K, n the normal from O to K, |f| = mu N against the follower's sliding on
    the disc; journal friction couples rho |R| at A and D against the turning; no equivalent
    linkage is used.
    """
    P = {k: mp.mpf(v) for k, v in p.items()}
    A, D = mp.mpc(0), mp.mpc(P["AD"])
    rho = P["mu"] * P["rs"]

    def pose(t):
        O = P["e"] * mp.expjpi(t / mp.pi)
        K = _circles(O, P["R"], D, P["L"], 1)
        return O, K
    t0 = mp.radians(P["theta"])
    O, K = pose(t0)
    H = D + (K - D) * P["DH"] / P["L"]
    w2 = mp.diff(lambda t: mp.arg(pose(t)[1] - D), t0)
    vK2 = mp.diff(lambda t: pose(t)[1].real, t0) + 1j * mp.diff(lambda t: pose(t)[1].imag, t0)
    vK1 = 1j * K                                   # the cam's point at K, omega1 = 1
    n = (K - O) / abs(K - O)
    tng = 1j * n
    slide = (vK2 - vK1).real * tng.real + (vK2 - vK1).imag * tng.imag
    G = mp.mpc(0, -P["G"])

    def eqs(N, Dx, Dy, Ax, Ay, M1):
        R12 = N * n - mp.sign(slide) * P["mu"] * N * tng
        R32, R31 = mp.mpc(Dx, Dy), mp.mpc(Ax, Ay)
        f = R12 + R32 + G
        m = _cross(K - D, R12) + _cross(H - D, G) - mp.sign(w2) * rho * abs(R32)
        g = R31 - R12
        mc = _cross(K - A, -R12) - rho * abs(R31) + M1
        return [f.real, f.imag, m, g.real, g.imag, mc]
    guess = [100, 0, 100, 0, 100, 1000]
    x = mp.findroot(eqs, guess)
    N, Dx, Dy, Ax, Ay, M1 = x
    R12 = N * n - mp.sign(slide) * P["mu"] * N * tng
    return {"R12": R12, "R32": mp.mpc(Dx, Dy), "R31": mp.mpc(Ax, Ay), "M1": M1}


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_exercise_2_25_against_direct_contact_free_bodies(seed):
    ex = cr.EXERCISE_2_25
    p = ex.defaults if seed is None else ex.variant(seed)
    s = ex.solve(p)
    hand = _hand_2_25(p)
    assert s["driving moment M1"].value * 1000 == pytest.approx(float(hand["M1"]), rel=1e-9)
    for label in ("R12", "R32", "R31"):
        R = complex(hand[label])
        assert s[f"{label} size"].value == pytest.approx(abs(R), rel=1e-9)
        assert s[f"{label} direction"].value == pytest.approx(math.atan2(R.imag, R.real), abs=1e-9)
    assert abs(s["R12 angle from the common normal"].value) == pytest.approx(math.atan(p["mu"]), rel=1e-12)
    assert s["R12 moment arm about K"].value == pytest.approx(0.0, abs=1e-9)
