"""Ready-made linkages: full turns without jumps, shapes, strokes, and mpmath references.

Positions and rates are compared with ``linkage_reference.py``, a second solver written in
mpmath at 50 digits by the law of cosines, with rates from ``mpmath.diff``; strokes and
time ratios with the closed forms of the offset slider-crank (F31, eq. 2-9).
"""

import math

import mpmath
import numpy as np
import pytest

from mech import AssemblyError
from mech.planar import SliderCrank
from mech.planar.special import _library as lib
from tests.planar import linkage_reference as ref

N = 3600
THETA = 2.0 * np.pi * np.arange(N + 1) / N
FULL_TURN = [lib.watt_six_bar, lib.stephenson_six_bar, lib.shaper_watt, lib.shaper_stephenson,
             lib.quick_return_guide_bar, lib.quick_return_slider_crank, lib.quick_return_crank_rocker,
             lib.jansen_linkage]


@pytest.mark.parametrize("build", FULL_TURN, ids=lambda f: f.__name__)
def test_library_full_turn(build):
    """Every ready-made linkage assembles at every one of 3600 crank angles."""
    sol = build().solve(THETA, strict=True)
    assert sol.valid.all()


@pytest.mark.parametrize("build", FULL_TURN, ids=lambda f: f.__name__)
def test_step_ratio_no_jump(build):
    """Largest step / median step stays at the smooth-motion value: no jump of mode.

    For a smooth motion sampled at 3600 uniform steps the step is |v| d(theta) to within
    O(d(theta)), so the ratio equals max|v| / median|v| (< 5 for all these linkages) to
    within a few per cent. A jump between assembly modes gives one step of the order of a
    link length, hundreds of median steps (see `test_step_ratio_detects_jump`).
    """
    sol = build().solve(THETA, order=1)
    ratios = lib.step_ratio(sol)
    for name, r in ratios.items():
        speed = np.abs(sol.velocities[name])
        assert r < 5.0, name
        assert r <= 1.02 * speed.max() / np.median(speed), name


def test_step_ratio_detects_jump():
    """A motion that switches the Jansen knee to its other mode halfway has a huge ratio."""
    base = lib.jansen_linkage()
    sol = base.solve(THETA)
    n = lib.JANSEN_HOLY_NUMBERS
    C, D = sol.points["C"], sol.points["D"]
    g = D - C
    alpha = np.arccos((n["f"] ** 2 + np.abs(g) ** 2 - n["g"] ** 2) / (2 * n["f"] * np.abs(g)))
    other = C + n["f"] * np.exp(1j * (np.angle(g) + alpha))   # the mode not chosen (+1)
    E = np.where(np.arange(N + 1) < N // 2, sol.points["E"], other)

    class Fake:
        points = {"E": E}

    assert lib.step_ratio(Fake())["E"] > 100


def test_jansen_linkage_foot_stance_flat():
    """The foot's path has a flat bottom: over the stance its height varies by < 4 units.

    The stance is where the foot moves in +x (the ground stroke, about 220 degrees of crank
    turn); it covers more than 60 units of stride, and the foot lifts by more than 19
    units in the rest of the turn.
    """
    sol = lib.jansen_linkage().solve(THETA, order=1)
    F, vF = sol.points["F"], sol.velocities["F"]
    stance = vF.real > 0
    assert 200 < np.degrees(stance.mean() * 2 * np.pi) < 240
    assert np.ptp(F.imag[stance]) < 4.0
    assert np.ptp(F.real[stance]) > 60.0
    assert F.imag[~stance].max() - F.imag.min() > 19.0


def test_stephenson_six_bar_dwell():
    """The output of the Stephenson six-bar stays within 1 degree over 120 degrees of crank."""
    sol = lib.stephenson_six_bar().solve(THETA)
    psi = np.degrees(np.unwrap(sol.angles["output"]))
    deg = np.degrees(THETA)
    dwell = (deg >= 230) & (deg <= 350)
    assert np.ptp(psi[dwell]) < 1.0
    assert np.ptp(psi) > 20.0


@pytest.mark.parametrize("name, build", [("watt", lib.watt_six_bar), ("stephenson", lib.stephenson_six_bar),
                                         ("jansen", lib.jansen_linkage)])
def test_solve_against_mpmath(name, build):
    """Positions, velocities, accelerations against the 50-digit reference, to 1e-12.

    Errors are relative to the largest magnitude of each quantity over the samples.
    """
    rng = np.random.default_rng(7)
    theta = np.concatenate([rng.uniform(0, 2 * np.pi, 12), [0.0, np.pi / 2, np.pi]])
    omega, alpha = 2.0, 0.5
    sol = build().solve(theta, order=2, omega=omega, alpha=alpha)
    refs = [ref.rates(ref.REFERENCES[name], float(t), omega, alpha) for t in theta]
    for k, got in enumerate((sol.points, sol.velocities, sol.accelerations)):
        for point in refs[0][0]:
            want = np.array([complex(r[k][point]) for r in refs])
            err = np.max(np.abs(got[point] - want)) / np.max(np.abs(want))
            assert err < 1e-12, (point, k, err)


def test_ram_stroke_slider_crank_closed_form():
    """Stroke and K of the offset slider-crank against F31 and (2-9) at 50 digits."""
    a, b, e = 129, 280, 120
    with mpmath.workdps(50):
        H = mpmath.sqrt((b + a) ** 2 - e**2) - mpmath.sqrt((b - a) ** 2 - e**2)
        th0 = mpmath.asin(mpmath.mpf(e) / (b - a)) - mpmath.asin(mpmath.mpf(e) / (b + a))
        K = (mpmath.pi + th0) / (mpmath.pi - th0)
    s = lib.ram_stroke(lib.quick_return_slider_crank(crank=a, rod=b, offset=e))
    assert s.length == pytest.approx(float(H), rel=1e-12)
    assert s.time_ratio == pytest.approx(float(K), rel=1e-9)
    assert s.time_ratio == pytest.approx(SliderCrank(a, b, e).time_ratio(), rel=1e-9)


def test_ram_stroke_guide_bar_extreme_angle():
    """With a ram line through the bar's pivot level, the extreme angle is 2 asin(a/d) (F23).

    A very long rod makes the ram follow E's x, whose ends are exactly the bar's limit
    positions, where the crank is perpendicular to the bar.
    """
    a, d = 124.0, 400.0
    s = lib.ram_stroke(lib.shaper_watt(crank=a, frame=d, rod=1e7))
    theta0 = 2 * math.asin(a / d)
    assert s.time_ratio == pytest.approx((math.pi + theta0) / (math.pi - theta0), rel=1e-6)


def test_quick_return_candidates_comparable():
    """The three Fig. 2-36 candidates have a stroke of 300 +- 1 % and K of 1.5 +- 1 %."""
    for build in (lib.quick_return_guide_bar, lib.quick_return_slider_crank, lib.quick_return_crank_rocker):
        s = lib.ram_stroke(build())
        assert s.length == pytest.approx(300, rel=0.01)
        assert s.time_ratio == pytest.approx(1.5, rel=0.01)


def test_solve_strict_names_group_and_input():
    """An impossible input raises AssemblyError naming the group and the input value."""
    lk = lib.jansen_linkage(j=10.0)
    with pytest.raises(AssemblyError, match=r"RRR j-b.*crank = 0\.0"):
        lk.solve([0.0, 1.0], strict=True)


def test_jansen_linkage_bad_lengths():
    with pytest.raises(ValueError, match="Expected `m` > 0"):
        lib.jansen_linkage(m=-1.0)
    with pytest.raises(ValueError, match="Expected lengths among"):
        lib.jansen_linkage(z=1.0)
    with pytest.raises(ValueError, match="form a triangle"):
        lib.jansen_linkage(h=200.0)


def test_shaper_bad_crank():
    with pytest.raises(ValueError, match="Expected `crank` < `frame`"):
        lib.shaper_watt(crank=500.0)
    with pytest.raises(ValueError, match="Expected `bar` >"):
        lib.shaper_stephenson(bar=100.0)


def test_sketch_links():
    sk = lib.sketch(lib.jansen_linkage())
    assert sk["ground"] == ("O", "Z")
    assert sk["links"]["b"] == ("Z", "B", "C")
    assert sk["links"]["g"] == ("D", "E", "F")
    assert lib.sketch(lib.shaper_stephenson())["blocks"] == (("D", "block"), ("F", "ram"))
