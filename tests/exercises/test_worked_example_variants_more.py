"""Worked examples 2-4, 2-5, 2-7, 2-11, 2-12, 2-14, 2-17, 2-18 and 2-25 with variants,
each checked by another route.

Oracles: for E2-4 and E2-5 the linkage closed in mpmath at 50 digits (the four-bar's C as
the intersection of two circles, to the left of B->D; the slider's place by Pythagoras),
its angles differentiated numerically (mpmath.diff) for the rates, and the instant centres
as intersections of lines through the joints; for E2-7 the follower tip's height on the
disc differentiated by mpmath.diff; for E2-17 and E2-18 the design put back into
the law of cosines at its two limit positions (the swing, K and the transmission angle
must be the givens); for E2-11 the equilibrium of the two wedges solved as linear systems
in mpmath (each reaction tilted by the friction angle) besides the closed forms (2-25) to
(2-29); for E2-12 the driving moment by virtual work (E's velocity from the loop
differentiated numerically) and R12 from the rocker's moments about D; for E2-14, whose answer the solver finds by bisection on its force analysis, the
textbook's closed self-locking condition; for E2-25 the gripper point by spherical coordinates about the shoulder and AP by
the law of cosines, not by the H-D matrices. At the defaults: the angular velocities the book's instant-centre page
recomputed independently (E2-4, E2-5, at the crank angles it chose) and the textbook's
corrected numbers of examples 2-17 and 2-18 (b = 73.67 mm, d = 95.98 mm, α = 28.50°), and
the pose the book's open-chain page chose for example 2-25.
"""

import math

import mpmath
import pytest

from mech.exercises import EXAMPLES, get
from mech.exercises._answers import ANSWER_KEYS, answers
from mech.exercises._sheet import solved_variant
from tests.exercises.test_worked_example_variants import _fourbar_mp

mpmath.mp.dps = 50
SEEDS = [0, 1, 2, 3, 5, 8, 13, 21]


def _givens(number, seed):
    """The example's own numbers (seed None) or the variant ``seed``."""
    return get(number).defaults if seed is None else get(number).variant(seed)


def _keys(number, params):
    return {a[0]: a[2] for a in answers(get(number).solve(params))}


def _six(x):
    """``x`` to the six significant digits the page prints."""
    return float(f"{x:.6g}")


def _meet(p1, p2, q1, q2):
    """The point where line p1p2 meets line q1q2 (complex mpmath numbers)."""
    d1, d2 = p2 - p1, q2 - q1
    cross = lambda u, v: u.real * v.imag - u.imag * v.real
    return p1 + d1 * cross(q1 - p1, d2) / cross(d1, d2)


# ----------------------------------------------------------------------------- E2-4
def _fourbar_rates(p):
    a, b, c, d = (mpmath.mpf(p[k]) for k in "abcd")
    w1 = mpmath.mpf(p["omega1"])

    def joints(t):
        B, D = a * mpmath.expj(t), mpmath.mpc(d, 0)
        s = abs(D - B)
        along = (b * b - c * c + s * s) / (2 * s)                  # from B towards D
        across = mpmath.sqrt(b * b - along * along)
        u = (D - B) / s
        return B, B + u * (along + 1j * across)                    # C to the left of B->D

    angle = lambda z: mpmath.atan2(z.imag, z.real)
    t0 = mpmath.radians(mpmath.mpf(p["theta1"]))
    B, C = joints(t0)
    D = mpmath.mpc(d, 0)
    return {"omega2": w1 * mpmath.diff(lambda t: angle(joints(t)[1] - joints(t)[0]), t0),
            "omega3": w1 * mpmath.diff(lambda t: angle(joints(t)[1] - D), t0),
            "P13": _meet(B, C, mpmath.mpc(0), D), "P24": _meet(mpmath.mpc(0), B, C, D)}


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_e2_4_against_the_closed_loop(seed):
    p = _givens("E2-4", seed)
    got, ref = _keys("E2-4", p), _fourbar_rates(p)
    assert got["omega2"] == pytest.approx(float(ref["omega2"]), rel=1e-9, abs=1e-12)
    assert got["omega3"] == pytest.approx(float(ref["omega3"]), rel=1e-9, abs=1e-12)
    assert got["P13_x"] == pytest.approx(float(ref["P13"].real), rel=1e-9, abs=1e-9)
    assert float(abs(ref["P13"].imag)) < 1e-30
    assert (got["P24_x"], got["P24_y"]) == pytest.approx((float(ref["P24"].real), float(ref["P24"].imag)),
                                                         rel=1e-9, abs=1e-9)


@pytest.mark.parametrize("theta, omega2, omega3", [(0.7, 0.682725, -0.120816), (2.0, -0.213381, -1.06914),
                                                   (4.0, -0.764037, -0.0701034)])
def test_e2_4_the_book_page_numbers(theta, omega2, omega3):
    got = _keys("E2-4", get("E2-4").params({"theta1": math.degrees(theta)}))
    assert (_six(got["omega2"]), _six(got["omega3"])) == (omega2, omega3)


# ----------------------------------------------------------------------------- E2-5
def _slider_rates(p):
    a, b, w1 = (mpmath.mpf(p[k]) for k in ("a", "b", "omega1"))
    x = lambda t: a * mpmath.cos(t) + mpmath.sqrt(b * b - (a * mpmath.sin(t)) ** 2)
    rod = lambda t: mpmath.atan2(-a * mpmath.sin(t), mpmath.sqrt(b * b - (a * mpmath.sin(t)) ** 2))
    t0 = mpmath.radians(mpmath.mpf(p["theta1"]))
    B, C = a * mpmath.expj(t0), mpmath.mpc(x(t0), 0)
    return {"v_C": w1 * mpmath.diff(x, t0), "omega2": w1 * mpmath.diff(rod, t0),
            "P13": _meet(B, C, mpmath.mpc(0), mpmath.mpc(0, 1))}


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_e2_5_against_pythagoras(seed):
    p = _givens("E2-5", seed)
    got, ref = _keys("E2-5", p), _slider_rates(p)
    assert got["v_C"] == pytest.approx(float(ref["v_C"]), rel=1e-9, abs=1e-9)
    assert got["omega2"] == pytest.approx(float(ref["omega2"]), rel=1e-9, abs=1e-12)
    assert got["P13_y"] == pytest.approx(float(ref["P13"].imag), rel=1e-9, abs=1e-9)
    # F35: the slider moves as fast as the crank's point at P13
    assert abs(got["v_C"]) == pytest.approx(abs(p["omega1"] * got["P13_y"]), rel=1e-9)


@pytest.mark.parametrize("theta, omega2, speed", [(0.8, -0.542529, 54.7170), (2.5, 0.616586, 24.8380)])
def test_e2_5_the_book_page_numbers(theta, omega2, speed):
    got = _keys("E2-5", get("E2-5").params({"theta1": math.degrees(theta)}))
    assert (_six(got["omega2"]), _six(abs(got["v_C"]))) == (omega2, speed)


# ----------------------------------------------------------------------------- E2-12
def _four_bar_statics_mp(p):
    """M_d by virtual work (the velocity of E from the closed loop differentiated by
    mpmath.diff) and R12 from the rocker's moments about D with R23 along BC."""
    a, b, c, d, de, Q = (mpmath.mpf(p[k]) for k in ("AB", "BC", "CD", "AD", "DE", "Q"))
    D = mpmath.mpc(d, 0)

    def joints(t):
        B = a * mpmath.expj(t)
        s = abs(D - B)
        along = (b * b - c * c + s * s) / (2 * s)
        C = B + (D - B) / s * (along + 1j * mpmath.sqrt(b * b - along * along))   # C left of B->D
        return B, C, D + de * (C - D) / c

    t0 = mpmath.radians(mpmath.mpf(p["theta1"]))
    B, C, E = joints(t0)
    vE = mpmath.mpc(mpmath.diff(lambda t: joints(t)[2].real, t0), mpmath.diff(lambda t: joints(t)[2].imag, t0))
    u = (C - D) / c
    w3 = (mpmath.conj(u) * vE / de).imag                          # the rocker's rate, ω1 = 1
    load = -mpmath.sign(w3) * 1j * u * Q
    cross = lambda z, w: z.real * w.imag - z.imag * w.real
    ub = (C - B) / b
    f23 = -cross(E - D, load) / cross(C - D, ub)
    return {"M_d": -(mpmath.conj(load) * vE).real, "R12": abs(f23)}


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_e2_12_against_virtual_work(seed):
    p = _givens("E2-12", seed)
    got, ref = _keys("E2-12", p), _four_bar_statics_mp(p)
    assert got["M_d"] == pytest.approx(float(ref["M_d"]), rel=1e-8, abs=1e-8)
    assert got["R12"] == pytest.approx(float(ref["R12"]), rel=1e-8)


# ----------------------------------------------------------------------------- E2-14
@pytest.mark.parametrize("seed", [None] + SEEDS[:4])
def test_e2_14_against_the_textbook_condition(seed):
    """The solver's bisection on its own self-locking verdict lands on the textbook's
    closed condition x = l sin[arctan μ + arcsin(2 r μ0 / l)] (in mpmath)."""
    p = _givens("E2-14", seed)
    l, r, mu0, mu = (mpmath.mpf(p[k]) for k in ("l", "r", "mu0", "mu"))
    x = l * mpmath.sin(mpmath.atan(mu) + mpmath.asin(2 * r * mu0 / l))
    # near the boundary the push grows like 1/(x - x_lock) and rounding decides the verdict
    # within about 1e-9 of x: the search lands within 1e-7
    assert _keys("E2-14", p)["x_lock"] == pytest.approx(float(x), rel=1e-7)


# ----------------------------------------------------------------------------- E2-17, E2-18
def _design_meets_its_task(p, lengths, gamma_min):
    ref = _fourbar_mp(dict(zip("abcd", lengths)))
    assert float(mpmath.degrees(ref["phi"])) == pytest.approx(p["phi"], rel=1e-9)
    assert float(ref["K"]) == pytest.approx(p["K"], rel=1e-9)
    assert gamma_min == pytest.approx(float(mpmath.degrees(ref["gamma_min"])), rel=1e-6)


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_e2_17_design_meets_its_task(seed):
    p = _givens("E2-17", seed)
    got = _keys("E2-17", p)
    _design_meets_its_task(p, (p["a"], got["l_BC"], p["c"], got["l_AD"]), got["gamma_min"])


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_e2_18_design_meets_its_task(seed):
    p = _givens("E2-18", seed)
    got = _keys("E2-18", p)
    _design_meets_its_task(p, (got["l_AB"], p["b"], p["c"], got["l_AD"]), got["gamma_min"])


def test_e2_17_e2_18_textbook_numbers():
    """The textbook's corrected answers (its printed d = 95.95 mm is 0.03 mm short)."""
    s17 = get("E2-17").solve()
    got = _keys("E2-17", get("E2-17").defaults)
    assert (got["l_BC"], got["l_AD"]) == pytest.approx((73.67, 95.98), abs=0.005)
    assert math.degrees(s17["angle α = ∠AOC1"].value) == pytest.approx(28.50, abs=0.005)
    got = _keys("E2-18", get("E2-18").defaults)
    assert (got["l_AB"], got["l_AD"]) == pytest.approx((31.40, 95.98), abs=0.005)


# ----------------------------------------------------------------------------- E2-7
@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_e2_7_against_the_tip_height(seed):
    """The tip's height y(θ) = e sin θ + √(R² − e² cos² θ) differentiated by mpmath.diff;
    P12 where the normal T->K meets the horizontal through A."""
    p = _givens("E2-7", seed)
    R, e, w1 = (mpmath.mpf(p[k]) for k in ("R", "e", "omega1"))
    y = lambda t: e * mpmath.sin(t) + mpmath.sqrt(R * R - (e * mpmath.cos(t)) ** 2)
    t0 = mpmath.radians(mpmath.mpf(p["theta1"]))
    K = e * mpmath.expj(t0)
    p12 = _meet(mpmath.mpc(0, y(t0)), K, mpmath.mpc(0), mpmath.mpc(1))
    got = _keys("E2-7", p)
    assert got["v2"] == pytest.approx(float(w1 * mpmath.diff(y, t0)), rel=1e-9, abs=1e-9)
    assert got["P12_x"] == pytest.approx(float(p12.real), rel=1e-9, abs=1e-9)


def test_e2_7_the_book_page_numbers():
    """At the page's data the velocity is ω1 times the distance of P12 from A (F37)."""
    got = _keys("E2-7", get("E2-7").defaults)
    assert got["v2"] == pytest.approx(2.5 * abs(got["P12_x"]), rel=1e-12)


# ----------------------------------------------------------------------------- E2-11
def _wedge_mp(p):
    """The two wedges' equilibrium solved as linear systems in mpmath: each total reaction
    tilted by φ from its face's normal against the sliding (pressing: wedge 2 moves +x,
    wedge 3 moves +y; the release reverses every friction force). Built from the geometry
    here, not from the code's force routine."""
    Q, lam, phi = mpmath.mpf(p["Q"]), mpmath.radians(mpmath.mpf(p["lam"])), mpmath.atan(mpmath.mpf(p["mu"]))
    out = {}
    for name, s in (("P", 1), ("P_release", -1)):
        u = lambda ang: mpmath.matrix([mpmath.cos(ang), mpmath.sin(ang)])
        # the incline falls towards +x (the thick end is pushed), so wedge 2 slides along it
        r_base = u(mpmath.pi / 2 + s * phi)             # on wedge 2 from the base, against its +x motion
        r_face = u(-mpmath.pi / 2 - lam - s * phi)      # on wedge 2 from wedge 3, against sliding down the face
        r_guide = u(mpmath.pi + s * phi)                # on wedge 3 from the guide it leans on, against +y
        # wedge 3: Q (down) + F23 (-r_face) + F_guide r_guide = 0 -> F23, F_guide
        A = mpmath.matrix([[-r_face[0], r_guide[0]], [-r_face[1], r_guide[1]]])
        f23, _ = mpmath.lu_solve(A, mpmath.matrix([0, Q]))
        # wedge 2: P (+x) + F_base r_base + f23 r_face = 0
        B = mpmath.matrix([[1, r_base[0]], [0, r_base[1]]])
        push, _ = mpmath.lu_solve(B, -f23 * r_face)
        out[name] = push
    p0 = Q * mpmath.tan(lam)                            # no friction
    out["eta"], out["eta_release"] = p0 / out["P"], out["P_release"] / p0
    return out


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_e2_11_against_the_force_polygons(seed):
    p = _givens("E2-11", seed)
    got, ref = _keys("E2-11", p), _wedge_mp(p)
    for key in ("P", "P_release", "eta", "eta_release"):
        assert got[key] == pytest.approx(float(ref[key]), rel=1e-9, abs=1e-9), key
    # the textbook's closed forms (2-25), (2-26)
    lam, phi = mpmath.radians(mpmath.mpf(p["lam"])), mpmath.atan(mpmath.mpf(p["mu"]))
    assert got["P"] == pytest.approx(float(p["Q"] * mpmath.tan(lam + 2 * phi)), rel=1e-12)
    assert (got["eta_release"] <= 0) == (lam <= 2 * phi)            # (2-29): it holds by itself


# ----------------------------------------------------------------------------- E2-25
def _gripper_mp(p):
    """The gripper point by spherical coordinates about the shoulder B (φ12 from the
    downward vertical, φ01 about z0), and AP by the law of cosines in the triangle ABP."""
    s0, r = mpmath.mpf(p["S0"]), mpmath.mpf(p["S2"]) + mpmath.mpf(p["p"])
    t, az = mpmath.radians(mpmath.mpf(p["phi12"])), mpmath.radians(mpmath.mpf(p["phi01"]))
    P = (r * mpmath.sin(t) * mpmath.cos(az), r * mpmath.sin(t) * mpmath.sin(az), s0 - r * mpmath.cos(t))
    return P, mpmath.sqrt(s0**2 + r**2 - 2 * s0 * r * mpmath.cos(t))


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_e2_25_against_spherical_coordinates(seed):
    p = _givens("E2-25", seed)
    got = _keys("E2-25", p)
    P, ap = _gripper_mp(p)
    assert (got["P_x"], got["P_y"], got["P_z"]) == pytest.approx(tuple(float(v) for v in P), rel=1e-12, abs=1e-9)
    assert got["l_AP"] == pytest.approx(float(ap), rel=1e-12)
    assert got["l_AP"] == pytest.approx(math.hypot(got["P_x"], got["P_y"], got["P_z"]), rel=1e-12)


def test_e2_25_the_book_page_numbers():
    """The book's chosen pose: P = (0.2475, 0.142894, 0.235) m and AP = 0.37 m."""
    got = _keys("E2-25", get("E2-25").defaults)
    assert (_six(got["P_x"]), _six(got["P_y"]), _six(got["P_z"]), _six(got["l_AP"])) == (247.5, 142.894, 235.0,
                                                                                        370.0)


# ----------------------------------------------------------------------------- registry
def test_new_examples_registered_with_figures_and_keys():
    from mech.exercises._figures import figure_png

    for number in ("E2-4", "E2-5", "E2-7", "E2-11", "E2-12", "E2-14", "E2-17", "E2-18", "E2-25"):
        assert number in EXAMPLES
        params, solution = solved_variant(get(number), 4)
        assert {a[0] for a in answers(solution)} == {k for k, _, _ in ANSWER_KEYS[number]}
        assert all(math.isfinite(a[2]) for a in answers(solution))
    assert figure_png("E2-17", get("E2-17").defaults)[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("number, bad, message", [
    ("E2-4", {"a": 30.0}, "crank-rocker"), ("E2-4", {"omega1": 0.0}, "omega1"),
    ("E2-5", {"b": 20.0}, "`b` > `a`"), ("E2-17", {"a": 60.0}, "crank"), ("E2-18", {"K": 0.5}, "`K`"),
    ("E2-17", {"phi": 200.0}, "`phi`"), ("E2-11", {"lam": 80.0}, "`lam`"), ("E2-11", {"mu": 1.5}, "`mu`"),
    ("E2-25", {"S2": -1.0}, "S2"),
])
def test_new_examples_refuse_bad_givens_by_name(number, bad, message):
    with pytest.raises(ValueError, match=message):
        get(number).solve(**bad)
