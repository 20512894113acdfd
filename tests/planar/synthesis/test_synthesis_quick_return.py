"""Quick-return design (2-46)-(2-52), examples 2-17 to 2-20 and tables 2-3 to 2-5.

Oracles: every design is simulated over a full crank turn by the analysis classes
(`simulate_quick_return` finds the output's stops on `FourBar`/`SliderCrank`/`GuideBar`),
and the lengths and transmission angles are recomputed at 50 digits with mpmath from the
coordinates of A, D, C1, C2 and the pin positions (no closed form of (2-46) or (2-48)).
"""

import math

import mpmath
import numpy as np
import pytest
from scipy.optimize import brentq

import mech
from mech.planar import FourBar, SliderCrank, time_ratio
from mech.planar.synthesis import (
    crank_rocker_family,
    quick_return_crank_rocker,
    quick_return_guide_bar,
    quick_return_slider_crank,
    simulate_quick_return,
    slider_crank_family,
)
from mech.planar.synthesis._quick_return_search import (
    PRINTED_TABLE_2_3,
    PRINTED_TABLE_2_4,
    PRINTED_TABLE_2_5,
    TABLE_2_3_SWINGS_DEG,
    TABLE_K,
    crank_rocker_best_table,
    crank_rocker_table,
    slider_crank_table,
    table_errata,
)

mpmath.mp.dps = 50
RTOL = 1e-9
deg = math.radians


# ----------------------------------------------------------------------------- mpmath oracle
def _mp_points(K, c, swing, alpha, side):
    """A, D, C1, C2 at 50 digits from the construction: circle seeing C1C2 under theta."""
    K, c, swing, alpha = (mpmath.mpf(x) for x in (K, c, swing, alpha))
    theta = mpmath.pi * (K - 1) / (K + 1)
    half_chord = c * mpmath.sin(swing / 2)
    R = half_chord / mpmath.sin(theta)
    C1 = mpmath.mpc(-half_chord, R * mpmath.cos(theta))
    C2 = mpmath.mpc(half_chord, R * mpmath.cos(theta))
    A = R * mpmath.expj(mpmath.pi / 2 + theta + alpha)
    # D on the perpendicular bisector at the foot of the rocker's isosceles triangle
    D = mpmath.mpc(0, R * mpmath.cos(theta) - side * c * mpmath.cos(swing / 2))
    return A, D, C1, C2


def _mp_lengths(K, c, swing, alpha, side):
    A, D, C1, C2 = _mp_points(K, c, swing, alpha, side)
    long_, short = abs(C2 - A), abs(C1 - A)
    return (long_ - short) / 2, (long_ + short) / 2, mpmath.mpf(c), abs(D - A)


def _mp_pins_angle(a, b, c, d, crank):
    """Transmission angle from the pins of the four-bar at crank angle 0 or pi (circle meet)."""
    B = mpmath.mpc(a * mpmath.cos(crank), 0)
    D = mpmath.mpc(d, 0)
    # C on the circles |C - B| = b, |C - D| = c, from the radical line
    L = abs(D - B)
    x = (b**2 - c**2 + L**2) / (2 * L)
    h = mpmath.sqrt(b**2 - x**2)
    u = (D - B) / L
    C = B + u * mpmath.mpc(x, h)
    v1, v2 = B - C, D - C
    delta = mpmath.acos((v1.real * v2.real + v1.imag * v2.imag) / (abs(v1) * abs(v2)))
    return min(delta, mpmath.pi - delta)


def _mp_gamma_min(K, c, swing, alpha, side):
    a, b, c, d = _mp_lengths(K, c, swing, alpha, side)
    return min(_mp_pins_angle(a, b, c, d, 0), _mp_pins_angle(a, b, c, d, mpmath.pi))


def _mp_golden_max(f, lo, hi, steps=140):
    lo, hi = mpmath.mpf(lo), mpmath.mpf(hi)
    g = (mpmath.sqrt(5) - 1) / 2
    x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
    f1, f2 = f(x1), f(x2)
    for _ in range(steps):
        if f1 < f2:
            lo, x1, f1 = x1, x2, f2
            x2 = lo + g * (hi - lo)
            f2 = f(x2)
        else:
            hi, x2, f2 = x2, x1, f1
            x1 = hi - g * (hi - lo)
            f1 = f(x1)
    return (lo + hi) / 2, max(f1, f2)


# ----------------------------------------------------------------------------- crank-rocker
def test_random_designs_reproduce_the_task_when_simulated():
    """300 random tasks and alphas, both sides: simulated K, swing, gamma_min and stops agree."""
    rng = np.random.default_rng(12)
    worst, built, rejected = 0.0, 0, 0
    for _ in range(300):
        K = rng.uniform(1.02, 2.5)
        theta = math.pi * (K - 1) / (K + 1)
        swing = rng.uniform(deg(3), deg(150))
        alpha = rng.uniform(0.01, 0.99) * (math.pi - theta)
        side = int(rng.choice([1, -1]))
        try:
            q = quick_return_crank_rocker(K, 10.0 ** rng.uniform(-3, 3), swing, alpha=alpha, side=side)
        except ValueError as err:
            assert "crank-rocker" in str(err)
            # a rejected alpha really has no crank-rocker doing the task, on either branch
            a, b, c, d = (float(x) for x in _mp_lengths(K, 1.0, swing, alpha, side))
            if mech.planar.grashof(a, b, c, d).kind == "crank-rocker":
                for branch in (1, -1):
                    m = simulate_quick_return(FourBar(a, b, c, d, branch=branch))
                    assert abs(m.time_ratio - K) > 1e-6 or abs(m.output_range - swing) > 1e-6
                rejected += 1
            continue
        built += 1
        m = q.check()
        errs = (abs(m.time_ratio - K) / K, abs(m.output_range - swing) / swing,
                abs(m.min_transmission_angle - q.min_transmission_angle),
                abs(m.extreme_angle - theta))
        worst = max(worst, *errs)
        stops = sorted(m.theta_limits)
        assert stops == pytest.approx(sorted((q.theta_extended, q.theta_folded)), abs=1e-9)
    assert built > 100 and rejected > 10
    assert worst < RTOL


@pytest.mark.parametrize("side", [1, -1])
def test_lengths_agree_with_mpmath_coordinates(side):
    for K, swing, alpha in [(1.3, deg(40), 0.5), (1.1, deg(10), 1.2), (2.0, deg(100), 0.3), (1.45, deg(80), 1.6)]:
        try:
            q = quick_return_crank_rocker(K, 7.0, swing, alpha=alpha, side=side)
        except ValueError:
            continue
        ref = _mp_lengths(K, 7.0, swing, alpha, side)
        assert q.lengths == pytest.approx([float(x) for x in ref], rel=1e-13)
        assert q.min_transmission_angle == pytest.approx(float(_mp_gamma_min(K, 7.0, swing, alpha, side)), abs=1e-12)


def test_crank_and_coupler_fix_alpha():
    base = quick_return_crank_rocker(1.3, 100.0, deg(40), alpha=0.6)
    a, b, c, d = base.lengths
    for kw in ({"crank": a}, {"coupler": b}):
        q = quick_return_crank_rocker(1.3, 100.0, deg(40), **kw)
        assert q.alpha == pytest.approx(0.6, abs=1e-12)
        assert q.lengths == pytest.approx(base.lengths, rel=1e-12)


def test_in_text_example_with_given_crank():
    """§2.4 III, after (2-47): K = 1.3, c = 100, phi = 40°, a = 31.4 -> alpha 28.49°, b 73.65, d 95.95 (printed)."""
    q = quick_return_crank_rocker(1.3, 100.0, deg(40), crank=31.4)
    m = q.check()
    assert math.degrees(q.alpha) == pytest.approx(28.5013, abs=1e-4)
    assert q.lengths[1] == pytest.approx(73.6655, abs=1e-4)
    assert q.lengths[3] == pytest.approx(95.9807, abs=1e-4)       # erratum: printed 95.95
    assert m.time_ratio == pytest.approx(1.3, rel=RTOL)
    assert m.output_range == pytest.approx(deg(40), rel=RTOL)


def test_in_text_example_frame_perpendicular_to_bisector():
    """§2.4 III (2-47): alpha = 76.74° puts the rocker's limits at 70° and 110° from DA."""
    theta = math.pi * 0.3 / 2.3
    alpha = math.acos(math.sin(deg(20) - theta) / math.sin(deg(20))) - theta          # (2-47)
    q = quick_return_crank_rocker(1.3, 100.0, deg(40), alpha=alpha)
    assert math.degrees(alpha) == pytest.approx(76.7393, abs=1e-4)
    assert [round(x, 2) for x in q.lengths] == [22.40, 128.98, 100.0, 84.49]
    lo, hi = q.check().output_limits
    # interior angles CDA of the simulated stops: pi - psi
    assert sorted(abs(math.pi - abs(x)) for x in (lo, hi)) == pytest.approx([deg(70), deg(110)], abs=1e-9)


def test_in_text_example_with_permitted_angle():
    """§2.4 III, after (2-48): K = 1.25, c = 500, phi = 40°, [gamma] = 40°; printed 69.2° is 68.19°."""
    fam = crank_rocker_family(1.25, 500.0, deg(40), min_transmission=deg(40))
    (lo, hi), = fam.intervals
    assert (math.degrees(lo), math.degrees(hi)) == pytest.approx((14.4487, 45.2267), abs=1e-4)
    other = []
    for al, lengths in ((lo, (165.861, 291.615, 500.0, 500.0)), (hi, (146.269, 530.779, 500.0, 500.0))):
        q = fam.design(al)
        assert q.lengths == pytest.approx(lengths, abs=1e-3)
        assert q.check().min_transmission_angle == pytest.approx(deg(40), abs=1e-9)
        a, b, c, d = (mpmath.mpf(x) for x in q.lengths)
        other.append(max(float(_mp_pins_angle(a, b, c, d, 0)), float(_mp_pins_angle(a, b, c, d, mpmath.pi))))
    assert [math.degrees(x) for x in other] == pytest.approx([68.1928, 77.5905], abs=1e-4)


def test_in_text_example_read_from_figure_2_102():
    """§2.4 III, after (2-48): at alpha = 15° gamma_min is 37.31° (printed 37.97°); at 46° it is 37.83°."""
    got = [quick_return_crank_rocker(1.3, 100.0, deg(40), alpha=deg(al)).check().min_transmission_angle
           for al in (15.0, 46.0)]
    ref = [float(_mp_gamma_min(1.3, 100, deg(40), mpmath.radians(al), 1)) for al in (15, 46)]
    assert got == pytest.approx(ref, abs=1e-9)
    assert [math.degrees(g) for g in got] == pytest.approx([37.3116, 37.8270], abs=1e-4)


def test_family_best_is_the_mpmath_maximum():
    for K, swing, side in [(1.3, deg(30), 1), (1.05, deg(80), 1), (1.45, deg(10), 1), (1.3, deg(30), -1)]:
        fam = crank_rocker_family(K, 1.0, swing, side=side)
        theta = math.pi * (K - 1) / (K + 1)
        _, gmax = _mp_golden_max(lambda al: _mp_gamma_min(K, 1, swing, al, side), 1e-6, math.pi - theta - 1e-6)
        assert fam.best.min_transmission_angle == pytest.approx(float(gmax), abs=1e-10)
        assert fam.best.check().min_transmission_angle == pytest.approx(float(gmax), abs=1e-9)


def test_table_2_3_regenerated_with_its_two_misprints():
    table = crank_rocker_table()
    wrong = {s: table_errata(PRINTED_TABLE_2_3[s], table[s]) for s in TABLE_2_3_SWINGS_DEG}
    flat = [(s, r, i, p) for s, rows in wrong.items() for r, i, p, _ in rows]
    # 50°, K = 1.30: d/c printed 1.091 (1.019); 80°, K = 1.40: a/c printed 0.547 (0.597);
    # 10°, K = 1.40 and 1.45: a/c lost in the text
    assert [(s, r, i) for s, r, i, _ in flat] == [(10, "a/c", 7), (10, "a/c", 8), (50, "d/c", 5), (80, "a/c", 7)]
    assert round(table[50]["d/c"][5], 3) == 1.019 and round(table[80]["a/c"][7], 3) == 0.597
    assert [round(x, 3) for x in table[10]["a/c"][7:]] == [0.079, 0.078]


def test_table_2_4_regenerated_with_its_misprint():
    table = crank_rocker_best_table()
    assert [(r, i, p) for r, i, p, _ in table_errata(PRINTED_TABLE_2_4, table)] == [("theta", 0, 4.37)]
    assert table["theta"][0] == pytest.approx(4.3902, abs=1e-4)
    # the best swing is phi = theta (§2.4 III, after (2-50)): one degree either side is worse
    for K, th in zip(TABLE_K, np.radians(table["theta"])):
        best = crank_rocker_family(K, 1.0, th).best.min_transmission_angle
        assert best == pytest.approx(deg(table["gamma"][list(TABLE_K).index(K)]), abs=1e-12)
        for off in (-deg(1), deg(1)):
            assert crank_rocker_family(K, 1.0, th + off).best.min_transmission_angle < best


def test_largest_time_ratio_for_40_degrees():
    """§2.4 III (near Table 2-4): with [gamma] = 40° no crank-rocker has K > 1.324346; §2.4 III, after (2-52): no slider-crank K > 1.2862."""
    def rocker(K):
        return crank_rocker_family(K, 1.0, math.pi * (K - 1) / (K + 1), xtol=1e-14).best.min_transmission_angle - deg(40)

    def slider(K):
        return slider_crank_family(K, 1.0, xtol=1e-14).best.min_transmission_angle - deg(40)

    assert brentq(rocker, 1.2, 1.4, xtol=1e-12) == pytest.approx(1.324346, abs=1e-6)
    assert brentq(slider, 1.2, 1.4, xtol=1e-12) == pytest.approx(1.2862, abs=1e-4)


# ----------------------------------------------------------------------------- slider-crank
@pytest.mark.parametrize("alpha_deg, lengths, gamma_deg", [
    (15.0, (48.4215, 86.5848, 17.6219), 40.2920),     # erratum: b printed 96.582
    (45.0, (42.8201, 154.709, 75.5912), 40.0592),     # erratum: a printed 48.82
    (25.0, (46.9066, 110.189, 34.0018), 42.7547),
])
def test_slider_crank_examples(alpha_deg, lengths, gamma_deg):
    """§2.4 III, after (2-52): K = 1.25, H = 100, three alphas read from Fig. 2-104."""
    q = quick_return_slider_crank(1.25, 100.0, alpha=deg(alpha_deg))
    assert q.lengths == pytest.approx(lengths, abs=1e-3)
    m = q.check()
    assert m.output_range == pytest.approx(100.0, rel=RTOL)
    assert m.time_ratio == pytest.approx(1.25, rel=RTOL)
    assert math.degrees(m.min_transmission_angle) == pytest.approx(gamma_deg, abs=1e-4)
    assert m.min_transmission_angle == pytest.approx(q.min_transmission_angle, abs=1e-9)


def test_slider_crank_offset_fixes_alpha_and_random_designs_simulate():
    rng = np.random.default_rng(5)
    worst = 0.0
    for _ in range(200):
        K = rng.uniform(1.02, 2.95)
        theta = math.pi * (K - 1) / (K + 1)
        H = 10.0 ** rng.uniform(-2, 2)
        q = quick_return_slider_crank(K, H, alpha=rng.uniform(0.01, 0.99) * (math.pi - 2 * theta))
        m = q.check()
        worst = max(worst, abs(m.time_ratio - K) / K, abs(m.output_range - H) / H,
                    abs(m.min_transmission_angle - q.min_transmission_angle))
        again = quick_return_slider_crank(K, H, offset=q.lengths[2])
        assert again.lengths == pytest.approx(q.lengths, rel=1e-9)
    assert worst < RTOL


def test_table_2_5_regenerated_without_misprints():
    table = slider_crank_table()
    assert table_errata(PRINTED_TABLE_2_5, table) == []
    for K, a, b, e in zip(TABLE_K, table["a/H"], table["b/H"], table["e/H"]):
        m = simulate_quick_return(SliderCrank(a, b, e))
        assert m.time_ratio == pytest.approx(K, rel=RTOL)
        assert m.output_range == pytest.approx(1.0, rel=RTOL)


# ----------------------------------------------------------------------------- guide-bar
@pytest.mark.parametrize("K", [1.1, 1.5, 2.0, 3.0])
def test_guide_bar_example_2_20(K):
    q = quick_return_guide_bar(K, 250.0)
    m = q.check()
    theta = math.pi * (K - 1) / (K + 1)
    assert m.time_ratio == pytest.approx(K, rel=RTOL)
    assert m.output_range == pytest.approx(theta, rel=RTOL)
    assert q.crank == pytest.approx(float(mpmath.mpf(250) * mpmath.sin(mpmath.mpf(theta) / 2)), rel=1e-14)
    assert q.min_guide_length == pytest.approx(250.0 + q.crank)


# ----------------------------------------------------------------------------- scale, checks, inputs
@pytest.mark.parametrize("scale", [1e-300, 1e-150, 1e-10, 1.0, 1e10, 1e150, 1e300])
def test_designs_do_not_depend_on_the_unit(scale):
    ref = quick_return_crank_rocker(1.3, 1.0, deg(40), alpha=0.5)
    q = quick_return_crank_rocker(1.3, scale, deg(40), alpha=0.5)
    assert [x / scale for x in q.lengths] == pytest.approx(ref.lengths, rel=1e-15)
    m, mref = q.check(), ref.check()
    assert (m.time_ratio, m.output_range, m.min_transmission_angle) == pytest.approx(
        (mref.time_ratio, mref.output_range, mref.min_transmission_angle), rel=1e-12)
    s = quick_return_slider_crank(1.3, scale, alpha=0.5)
    assert s.check().output_range / scale == pytest.approx(1.0, rel=RTOL)
    assert quick_return_guide_bar(1.3, scale).check().time_ratio == pytest.approx(1.3, rel=RTOL)


def test_simulation_detects_a_wrong_design():
    q = quick_return_crank_rocker(1.3, 100.0, deg(40), alpha=0.5)
    a, b, c, d = q.lengths
    m = simulate_quick_return(FourBar(a, b, c, 1.01 * d, branch=q.fourbar.branch))
    assert abs(m.time_ratio - 1.3) > 1e-3
    assert simulate_quick_return(FourBar(10, 40, 30, 35)).time_ratio == pytest.approx(
        time_ratio(FourBar(10, 40, 30, 35).limit_positions().extreme_angle), rel=RTOL)


@pytest.mark.parametrize("call, name", [
    (lambda: quick_return_crank_rocker(0.9, 1.0, 0.5, alpha=0.5), "time_ratio"),
    (lambda: quick_return_crank_rocker(1.0, 1.0, 0.5, alpha=0.5), "coupler"),
    (lambda: quick_return_crank_rocker(1.0, 1.0, 0.5, crank=0.2), "coupler"),
    (lambda: quick_return_crank_rocker(1.0, 1.0, 0.5, coupler=0.1), "coupler"),
    (lambda: quick_return_crank_rocker(1.0, 1.0, 0.5, coupler=-1.0), "coupler"),
    (lambda: quick_return_crank_rocker(1.0, 1.0, 0.5, coupler=2.0, side=0), "side"),
    (lambda: quick_return_crank_rocker("1.3", 1.0, 0.5, alpha=0.5), "time_ratio"),
    (lambda: quick_return_crank_rocker(1.3, -1.0, 0.5, alpha=0.5), "rocker"),
    (lambda: quick_return_crank_rocker(1.3, 1.0, 4.0, alpha=0.5), "swing"),
    (lambda: quick_return_crank_rocker(1.3, 1.0, 0.5, alpha=3.0), "alpha"),
    (lambda: quick_return_crank_rocker(1.3, 1.0, 0.5, alpha=0.5, crank=0.1), "alpha"),
    (lambda: quick_return_crank_rocker(1.3, 1.0, 0.5), "crank"),
    (lambda: quick_return_crank_rocker(1.3, 1.0, 0.5, crank=0.9), "crank"),
    (lambda: quick_return_crank_rocker(1.3, 1.0, 0.5, coupler=0.1), "coupler"),
    (lambda: quick_return_crank_rocker(1.3, 1.0, 0.5, alpha=0.5, side=0), "side"),
    (lambda: quick_return_slider_crank(1.3, 1.0, offset=100.0), "offset"),
    (lambda: quick_return_slider_crank(1.3, float("nan"), alpha=0.5), "stroke"),
    (lambda: quick_return_guide_bar(1.3, 1j), "frame"),
    # K so large that the extreme angle or the crank rounds to its limit: named `time_ratio`
    # (the messages named `swing` and `a`, which the caller never gave)
    (lambda: quick_return_guide_bar(1e300, 10.0), "time_ratio"),
    (lambda: quick_return_guide_bar(1e15, 10.0), "time_ratio"),
    (lambda: quick_return_crank_rocker(1e300, 1.0, 0.5, alpha=0.5), "time_ratio"),
    (lambda: crank_rocker_family(1.3, 1.0, 0.5, min_transmission=2.0), "min_transmission"),
    (lambda: slider_crank_family(1.3, 1.0, samples=True), "samples"),
    (lambda: simulate_quick_return("FourBar"), "linkage"),
    (lambda: simulate_quick_return(FourBar(1, 2, 2, 2.5), samples=3), "samples"),
])
def test_bad_inputs_name_the_argument(call, name):
    with pytest.raises(ValueError, match=f"`{name}`"):
        call()


def test_type_errors_are_input_type_errors():
    with pytest.raises(mech.InputTypeError):
        quick_return_slider_crank(1.3, "100", alpha=0.5)
    with pytest.raises(mech.InputTypeError):
        simulate_quick_return(None)


def test_family_designs_all_keep_the_permitted_angle():
    fam = crank_rocker_family(1.2, 80.0, deg(35), min_transmission=deg(42))
    assert len(fam.intervals) == 1
    designs = fam.designs(7)
    assert len(designs) == 7
    for q in designs:
        m = q.check()
        assert m.min_transmission_angle >= deg(42)
        assert m.time_ratio == pytest.approx(1.2, rel=RTOL)
    lo, hi = fam.intervals[0]
    outside = [fam.design(lo - 1e-3), fam.design(hi + 1e-3)]
    assert all(q.check().min_transmission_angle < deg(42) for q in outside)
    assert crank_rocker_family(1.2, 80.0, deg(35), min_transmission=deg(80)).intervals == ()


def test_eq_2_49_printed_derivative_is_wrong():
    """Erratum 65: (2-49), the derivative of cos(gamma_min) of (2-48) along the design family
    (d' = 0 at phi = theta), has -2 a a' b c in its numerator (printed -2 a a' d c) and the
    denominator -2 b^2 c^2 sin(gamma_min) (printed -4 b^2 c^2 sin(gamma_min)). Checked against
    mpmath's numerical derivative at 30 digits for random lengths and rates."""
    rng = np.random.default_rng(49)
    with mpmath.workdps(30):
        checked = 0
        while checked < 10:
            a, b, c, d, ap, bp = (mpmath.mpf(float(v)) for v in (*rng.uniform(0.5, 2.0, 4), *rng.normal(size=2)))
            cos_gamma = lambda t: ((b + t * bp) ** 2 + c**2 - (d - a - t * ap) ** 2) / (2 * (b + t * bp) * c)
            if not abs(cos_gamma(0)) < 0.95:
                continue
            checked += 1
            gamma = mpmath.acos(cos_gamma(0))
            dgamma = mpmath.diff(lambda t: mpmath.acos(cos_gamma(t)), 0)
            common = b**2 * bp * c + 2 * ap * b * c * d - bp * c**3 + bp * c * d**2 - 2 * a * bp * c * d + a**2 * bp * c
            corrected = (common - 2 * a * ap * b * c) / (-2 * b**2 * c**2 * mpmath.sin(gamma))
            printed = (common - 2 * a * ap * d * c) / (-4 * b**2 * c**2 * mpmath.sin(gamma))
            assert abs(dgamma - corrected) < mpmath.mpf(10) ** -20 * (1 + abs(dgamma))
            assert abs(dgamma - printed) > 1e-6 * (1 + abs(float(dgamma)))


@pytest.mark.parametrize("side", [1, -1])
def test_crank_rocker_k1_simulates_to_no_quick_return(side):
    """Fig. 2-100: K = 1 puts A on the line C1C2; `FourBar.limit_positions` gives K = 1 and the swing."""
    rng = np.random.default_rng(100 + side)
    for _ in range(40):
        c, swing = rng.uniform(10.0, 500.0), rng.uniform(0.1, 2.8)
        a = c * math.sin(swing / 2)
        b = a * rng.uniform(1.05, 8.0)
        try:
            q = quick_return_crank_rocker(1.0, c, swing, coupler=b, side=side)
        except ValueError:
            continue            # the crank does not revolve for this coupler
        lp = q.fourbar.limit_positions()
        assert abs(lp.time_ratio - 1.0) <= 1e-12
        assert abs(lp.extreme_angle) <= 1e-12
        assert lp.swing == pytest.approx(swing, rel=1e-12)
        assert q.lengths[0] == pytest.approx(a, rel=1e-14)
        assert q.lengths[3] == pytest.approx(math.hypot(b, c * math.cos(swing / 2)), rel=1e-14)
        assert np.exp(1j * q.theta_extended) == pytest.approx(np.exp(1j * lp.theta_extended), abs=1e-12)
        assert np.exp(1j * q.theta_folded) == pytest.approx(np.exp(1j * lp.theta_folded), abs=1e-12)
        # A, C1 and C2 collinear in the placed frame, with the chord's midpoint at 0
        A, rot = q.placement
        pose = q.fourbar.solve(np.array([q.theta_extended, q.theta_folded]))
        C2, C1 = A + np.exp(1j * rot) * pose.C
        assert abs(C1 + C2) <= 1e-12 * c and abs(C1.imag) <= 1e-12 * c and abs(A.imag) <= 1e-12 * c
        m = q.check()
        assert m.time_ratio == pytest.approx(1.0, abs=1e-12)
        assert m.output_range == pytest.approx(swing, rel=1e-12)


def test_crank_rocker_k1_is_the_limit_of_k_above_1():
    """The K = 1 design is the limit of (2-46) with the coupler held fixed, as the derivation proves."""
    c, swing, b = 100.0, deg(40), 90.0
    k1 = quick_return_crank_rocker(1.0, c, swing, coupler=b)
    for gap in (1e-3, 1e-6, 1e-9, 1e-12):
        near = quick_return_crank_rocker(1.0 + gap, c, swing, coupler=b)
        # the lengths differ by O(K - 1) and no more: (2-46) is evaluated from the chord's midpoint
        assert np.allclose(near.lengths, k1.lengths, rtol=2 * gap, atol=0)
        assert near.fourbar.branch == k1.fourbar.branch
        assert abs(near.theta_extended - k1.theta_extended) <= gap
        assert near.fourbar.limit_positions().time_ratio == pytest.approx(1.0 + gap, abs=1e-14)


def _alpha_max(theta, swing, side):
    """The end of the working alpha interval stated in `quick_return_crank_rocker`'s Notes."""
    if side == 1:
        return min(np.pi - theta, np.pi - swing, np.pi - 2 * theta + swing)
    return np.pi - 2 * theta - swing


def test_crank_rocker_alpha_interval_stated_in_the_docstring():
    """Two thirds of random alphas in the documented (0, pi - theta) raised; the docstring now
    gives the working interval (0, alpha_max). Checked by building designs inside and outside
    it, and each accepted design by simulation."""
    rng = np.random.default_rng(11)
    tried = 0
    while tried < 60:
        K, swing, side = np.exp(rng.uniform(np.log(1.01), np.log(8.0))), rng.uniform(0.05, 3.0), int(rng.choice([1, -1]))
        theta = np.pi * (K - 1) / (K + 1)
        top = _alpha_max(theta, swing, side)
        if top <= 0.02:
            with pytest.raises(ValueError, match="crank-rocker"):
                quick_return_crank_rocker(K, 1.0, swing, alpha=0.5 * (np.pi - theta), side=side)
            continue
        tried += 1
        for f in (1e-3, 0.5, 0.95):
            q = quick_return_crank_rocker(K, 1.0, swing, alpha=f * top, side=side)
            check = q.check(samples=512)
            assert abs(check.time_ratio - K) < 1e-9 and abs(check.output_range - swing) < 1e-9
        if top * (1 + 1e-4) < np.pi - theta:
            with pytest.raises(ValueError, match="crank-rocker"):
                quick_return_crank_rocker(K, 1.0, swing, alpha=top * (1 + 1e-4), side=side)
    fam = crank_rocker_family(2.0, 1.0, np.radians(30.0))
    # the end stops short of alpha_max = pi/2 by the band rejected as a change-point linkage
    assert len(fam.intervals) == 1 and 0.0 < np.pi / 2 - fam.intervals[0][1] < 1e-4


def test_crank_rocker_near_a_change_point_is_rejected_by_name():
    """Near alpha_max the design tends to a change-point linkage. Within `grashof`'s tolerance
    it was accepted, FourBar then continued through the change point, and `check()` failed
    inside SciPy ("f(a) and f(b) must have different signs"); now `alpha` is rejected."""
    K, swing = 3.1466343002270505, 0.13466639317576154
    top = _alpha_max(np.pi * (K - 1) / (K + 1), swing, 1)
    for f in (0.999, 0.9999):
        with pytest.raises(ValueError, match=r"`alpha`.*not a change-point linkage"):
            quick_return_crank_rocker(K, 1.0, swing, alpha=f * top)
    q = quick_return_crank_rocker(K, 1.0, swing, alpha=0.99 * top)
    assert not mech.planar.grashof(*q.lengths).change_point
    check = q.check()
    assert abs(check.time_ratio - K) < 1e-8 and abs(check.output_range - swing) < 1e-8


@pytest.mark.parametrize("lengths", [(1.0, 3.0, 2.0, 2.0), (0.06643943019070922, 0.06802770547188149, 1.0,
                                                               0.9984117247188289)])
def test_simulate_change_point_linkage_is_named(lengths):
    """A change-point crank-rocker (s + l = p + q) made `simulate_quick_return` fail inside SciPy
    ("f(a) and f(b) must have different signs"); the error now names `linkage`."""
    with pytest.raises(ValueError, match=r"Expected `linkage` whose output repeats every crank turn.*change-point"):
        simulate_quick_return(FourBar(*lengths))
