"""Tests for ``mech.planar.forces._force_gain`` (force gain, dead points, toggle presses).

Three routes must agree: the solution's loop velocities, the instant centres (positions
only) and a 50-digit mpmath finite difference of positions solved independently by
triangles; dead points must make the driven-side force gain vanish.
"""

import math

import mpmath
import numpy as np
import pytest

from mech.planar import FourBar, Linkage, SliderCrank, limit_positions
from mech.planar.forces._force_gain import (
    fourbar_dead_points,
    fourbar_mechanical_advantage,
    hand_press,
    jaw_crusher,
    mechanical_advantage,
    slider_crank_dead_points,
    slider_crank_mechanical_advantage,
)
from mech.planar.kinematics._linkage import Guide


def _psi_mp(a, b, c, d, t, branch):
    """Rocker angle by the triangles ABD and BCD at 50 digits (branch: C left of B->D)."""
    B = a * mpmath.expj(t)
    k = abs(d - B)
    base = mpmath.arg(B - d)                                   # direction D -> B
    return base - branch * mpmath.acos((c**2 + k**2 - b**2) / (2 * c * k))


def _fourbar(a, b, c, d, branch=1):
    return (Linkage({"A": 0, "D": d}).crank("crank", pivot="A", tip="B", length=a)
            .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(b, c), branch=branch))


@pytest.mark.parametrize("branch", [1, -1])
def test_mechanical_advantage_fourbar_three_routes(branch):
    a, b, c, d = 30.0, 70.0, 60.0, 80.0
    theta = np.linspace(-3.0, 3.0, 13) + 0.1
    sol = _fourbar(a, b, c, d, branch).solve(theta, order=1)
    by_v = mechanical_advantage(sol, "crank", "rocker")
    by_ic = mechanical_advantage(sol, "crank", "rocker", method="centres")
    closed = fourbar_mechanical_advantage(a, b, c, d, theta, branch=branch)
    with mpmath.workdps(50):
        ref = [float(1 / mpmath.diff(lambda s: _psi_mp(a, b, c, d, s, branch), mpmath.mpf(float(t))))
               for t in theta]
    np.testing.assert_allclose(by_v, ref, rtol=1e-11)
    np.testing.assert_allclose(by_ic, ref, rtol=1e-11)
    np.testing.assert_allclose(closed, ref, rtol=1e-11)
    np.testing.assert_allclose(fourbar_mechanical_advantage(a, b, c, d, theta, branch=branch, driver="rocker"),
                               1 / np.asarray(ref), rtol=1e-11)


@pytest.mark.parametrize("e", [0.0, 15.0, -25.0])
def test_mechanical_advantage_slider_crank_three_routes(e):
    a, b = 30.0, 100.0
    theta = np.linspace(-2.9, 2.9, 11) + 0.1
    lk = (Linkage({"A": 0}).crank("crank", pivot="A", tip="B", length=a)
          .rrp(("rod", "slider"), pin="B", guide=Guide("ground", e * 1j, 0.0), joint="C", length=b))
    sol = lk.solve(theta, order=1)
    by_v = mechanical_advantage(sol, "crank", ("C", 1.0))
    by_ic = mechanical_advantage(sol, "crank", ("C", 1.0), method="centres")
    closed = slider_crank_mechanical_advantage(a, b, e, theta)
    with mpmath.workdps(50):
        x = lambda s: a * mpmath.cos(s) + mpmath.sqrt(b**2 - (e - a * mpmath.sin(s))**2)
        ref = [float(1 / mpmath.diff(x, mpmath.mpf(float(t)))) for t in theta]
    for got in (by_v, by_ic, closed):
        np.testing.assert_allclose(got, ref, rtol=1e-11)
    engine = mechanical_advantage(sol, ("C", 1.0), "crank")
    np.testing.assert_allclose(engine, 1 / np.asarray(ref), rtol=1e-11)
    np.testing.assert_allclose(slider_crank_mechanical_advantage(a, b, e, theta, driver="slider"),
                               1 / np.asarray(ref), rtol=1e-11)


def test_fourbar_dead_points_ma_zero_and_limit_positions():
    a, b, c, d = 10.0, 40.0, 30.0, 35.0
    dp = fourbar_dead_points(a, b, c, d)
    ma = fourbar_mechanical_advantage(a, b, c, d, np.array(dp.theta), driver="rocker")
    assert np.max(np.abs(ma)) < 1e-10
    lp = limit_positions(a, b, c, d)
    assert sorted(dp.inputs) == pytest.approx(sorted([lp.psi_extended, lp.psi_folded]), abs=1e-12)
    pose = FourBar(a, b, c, d).solve(np.array(dp.theta))
    np.testing.assert_allclose(pose.psi, dp.inputs, atol=1e-12)


@pytest.mark.parametrize("lengths", [(40.0, 20.0, 30.0, 35.0), (30.0, 20.0, 45.0, 50.0)])
@pytest.mark.parametrize("branch", [1, -1])
def test_fourbar_dead_points_collinear_geometry(lengths, branch):
    a, b, c, d = lengths
    dp = fourbar_dead_points(a, b, c, d, branch=branch)
    assert len(dp.inputs) >= 1
    for psi, th, kind in zip(dp.inputs, dp.theta, dp.collinear):
        C = d + c * complex(math.cos(psi), math.sin(psi))
        B = a * complex(math.cos(th), math.sin(th))
        assert abs(abs(C - B) - b) < 1e-10                         # assembles
        assert abs(((C - B) * B.conjugate()).imag) < 1e-9 * a * b  # crank and coupler collinear
        assert (((C - B) * B.conjugate()).real > 0) == (kind == "extended")
        assert ((d - B).conjugate() * (C - B)).imag * branch >= -1e-9


def test_slider_crank_dead_points_engine_ma_zero():
    for e in (0.0, 20.0, -10.0):
        dp = slider_crank_dead_points(30, 100, e)
        ma = slider_crank_mechanical_advantage(30, 100, e, np.array(dp.theta), driver="slider")
        assert np.max(np.abs(ma)) < 1e-10
        x = SliderCrank(30, 100, e).solve(np.array(dp.theta)).x
        np.testing.assert_allclose(x, dp.inputs, atol=1e-10)
        with mpmath.workdps(50):
            assert abs(dp.inputs[0] - float(mpmath.sqrt(130**2 - mpmath.mpf(e)**2))) < 1e-10


def test_slider_crank_dead_points_offset_too_large():
    with pytest.raises(ValueError, match=r"Expected `a` \+ \|`e`\| <= `b`"):
        slider_crank_dead_points(30, 100, 75)


def test_fourbar_dead_points_none_for_a_double_crank():
    assert fourbar_dead_points(30.0, 50.0, 45.0, 20.0).inputs == ()


def test_parallelogram_change_point_is_indeterminate():
    rates = [[float(FourBar(1.0, 2.0, 1.0, 2.0, branch=br).solve(t, order=1).omega_output)
              for br in (1, -1)] for t in (1e-2, 1e-3)]
    assert rates[1][0] == pytest.approx(1.0, abs=1e-12)
    assert rates[1][1] == pytest.approx(-3.0, abs=1e-4)


def test_hand_press_toggle_gain():
    lk = hand_press()
    gap = np.array([0.3, 0.1, 0.03, 0.01, 0.003])
    sol = lk.solve(np.pi / 2 - gap, order=1)
    ma_v = mechanical_advantage(sol, "lever", ("E", -1j))
    ma_c = mechanical_advantage(sol, "lever", ("E", -1j), method="centres")
    assert np.all(np.abs(ma_v - ma_c) <= 1e-12 / gap**2 * np.abs(ma_v))   # conditioning ~ 1/gap^2
    assert np.all(np.diff(ma_v) > 0) and ma_v[-1] > 50 * ma_v[0]
    # near the toggle the ram's travel to the bottom is quadratic in the lever angle, so MA ~ 1/gap
    assert np.std(ma_v[2:] * gap[2:]) / np.mean(ma_v[2:] * gap[2:]) < 0.02
    # handle force ratio: force at H, perpendicular to the lever, per ram force
    hand = mechanical_advantage(sol, ("H", -1j * sol.direction("lever")), ("E", -1j))
    np.testing.assert_allclose(np.abs(hand), np.abs(ma_v) * 250.0, rtol=1e-9)


def test_jaw_crusher_gain_peaks_where_plates_straighten():
    theta = np.linspace(0, 2 * np.pi, 3601)
    sol = jaw_crusher().solve(theta, order=1)
    ma = np.abs(mechanical_advantage(sol, "crank", "jaw"))
    np.testing.assert_allclose(ma, np.abs(mechanical_advantage(sol, "crank", "jaw", method="centres")),
                               rtol=1e-8)
    plates = np.abs(np.angle((sol.points["D"] - sol.points["C"]) / (sol.points["E"] - sol.points["C"])))
    # at the largest plate angle the gain is far above its median
    assert ma[np.argmax(plates)] > 20 * np.median(ma)


def test_mechanical_advantage_bad_inputs():
    sol0 = _fourbar(30, 70, 60, 80).solve(0.5)
    with pytest.raises(ValueError, match="order >= 1"):
        mechanical_advantage(sol0, "crank", "rocker")
    sol = _fourbar(30, 70, 60, 80).solve(0.5, order=1)
    with pytest.raises(ValueError, match="moving link or"):
        mechanical_advantage(sol, "cranky", "rocker")
    with pytest.raises(ValueError, match="point of the linkage"):
        mechanical_advantage(sol, "crank", ("Q", 1.0))
    with pytest.raises(ValueError, match="non-zero direction"):
        mechanical_advantage(sol, "crank", ("C", 0.0))
    with pytest.raises(ValueError, match="method"):
        mechanical_advantage(sol, "crank", "rocker", method="guess")
    with pytest.raises(ValueError, match="driver"):
        fourbar_mechanical_advantage(30, 70, 60, 80, 0.5, driver="coupler")
    with pytest.raises(ValueError, match="Expected `c` > 0, got -60.0"):
        fourbar_dead_points(30, 70, -60, 80)
    with pytest.raises(ValueError, match="Expected `lever` > 0, got -1.0"):
        hand_press(lever=-1)


def test_fig_2_83_slotter_lever_gain_by_ram_position_derivative():
    """Fig. 2-83: the slotter (`shaper_watt` with E between the bar's pivot and the crank).
    Its ram force per crank moment equals 1 / (dx_F / dtheta), with x_F from an independent
    construction differentiated by mpmath at 50 digits; the gain is about DB / DE times the
    shaper layout's."""
    import mpmath

    from mech.planar import mechanical_advantage, shaper_watt

    mpmath.mp.dps = 50

    def ram_x(t, r, crank=60, frame=200, rod=100):
        B = mpmath.mpc(crank * mpmath.cos(t), crank * mpmath.sin(t))
        u = (B + frame * 1j) / abs(B + frame * 1j)
        E = -frame * 1j + r * u
        h = r - frame                                   # the ram's line through E's top
        return E.real + mpmath.sqrt(rod**2 - (h - E.imag) ** 2)

    theta = np.linspace(0.1, 6.2, 13)
    gains = {}
    for r in (80.0, 320.0):
        sol = shaper_watt(crank=60.0, frame=200.0, bar=r, rod=100.0).solve(theta, order=1)
        ma = mechanical_advantage(sol, "crank", ("F", 1.0))
        for t, m in zip(theta, ma):
            x_rate = mpmath.diff(lambda s: ram_x(s, r), t)
            assert float(m) == pytest.approx(float(1 / x_rate), rel=1e-9)
        gains[r] = np.abs(ma)
    ratio = gains[80.0] / gains[320.0]
    assert ratio.min() > 3.8 and ratio.max() < 4.2
