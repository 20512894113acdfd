"""Scale invariance of the slider and guide-bar family and the other length-taking solvers.

A linkage given in another unit of length is the same linkage: every length times a
factor s must give the same angles and valid masks, and lengths and linear rates times s.
Each solver is run at twelve factors from 1e-300 to 1e300 and compared with its own
solution at s = 1 (which the other test modules check against mpmath), and at a few
factors against mpmath at 50 digits directly, through closed forms and numerical
derivatives that share no code with the package.

Tolerance: the scaled inputs differ from the exact multiples of the unit ones by one
rounding each (relative 2**-53), so the outputs may differ by that times the condition
number of the pose. The sweeps stay away from dead points (except where a dead point is
hit on purpose, and then only masks are compared there), so a few hundred ulps bound it:
`RTOL` below.
"""

import warnings

import mpmath
import numpy as np
import pytest

from mech.planar import FourBar, GuideBar, Linkage, SliderCrank
from mech.planar.forces._force_gain import slider_crank_dead_points, slider_crank_mechanical_advantage
from mech.planar.forces._pressure_angle import slider_crank_min_transmission_angle, slider_crank_pressure_angle
from mech.planar.special._double_slider import EllipticTrammel, OldhamCoupling, ScotchYoke, TangentMechanism
from mech.planar.special._library import _triangle
from mech.planar.special._special import RotatingGuideBar, SwingingBlock
from mech.planar.kinematics._triad import TriadSixBar
from mech.spatial._chain import example_2_25_reach
from mech.spatial._rccc import RCCC
from mech._pose import mask_singular_rates
from mech._scaling import length_scale

SCALES = [1e-300, 1e-200, 1e-160, 1e-150, 1e-110, 1e-50, 1.0, 1e50, 1e110, 1e160, 1e200, 1e300]
RTOL = 256 * np.finfo(float).eps
THETA = np.linspace(-np.pi, np.pi, 721)
# the rocking slider-crank (2, 1, 0.5) has dead points where |0.5 - 2 sin(theta)| = 1; its
# sweep keeps 10 % of b away from them, where the conditioning is still modest
THETA_ROCKING = THETA[np.abs(np.abs(0.5 - 2.0 * np.sin(THETA)) - 1.0) > 0.1]

# name -> (build(s) -> solver, input angles, fields that scale with length)
_SC_LINEAR = {"x", "B", "C", "v", "vB", "acc", "aB"}
_GB_LINEAR = {"rho", "B", "v_slide", "vB", "a_slide", "aB"}
CASES = {
    "slider_crank_example_2_3": (lambda s: SliderCrank(30 * s, 100 * s, 20 * s), THETA, _SC_LINEAR),
    "slider_crank_branch_-1": (lambda s: SliderCrank(1 * s, 3 * s, -0.5 * s, branch=-1), THETA, _SC_LINEAR),
    "slider_crank_rocking": (lambda s: SliderCrank(2 * s, 1 * s, 0.5 * s), THETA_ROCKING, _SC_LINEAR),
    "guide_bar_example_2_2": (lambda s: GuideBar(150 * s, 300 * s), THETA, _GB_LINEAR),
    "rotating_guide_bar": (lambda s: RotatingGuideBar(2 * s, 1 * s), THETA, _GB_LINEAR),
    "rotating_guide_bar_equal": (lambda s: RotatingGuideBar(1 * s, 1 * s), THETA, _GB_LINEAR),
    "swinging_block": (lambda s: SwingingBlock(1 * s, 3 * s), THETA, _GB_LINEAR),
    "turning_block": (lambda s: SwingingBlock(3 * s, 1 * s), THETA, _GB_LINEAR),
    "elliptic_trammel": (lambda s: EllipticTrammel(2 * s, point=(0.5 * s, 0.3 * s)), THETA,
                         {"B", "C", "M", "P", "I", "vB", "vC", "vP", "aB", "aC", "aP"}),
    "scotch_yoke": (lambda s: ScotchYoke(2 * s), THETA, {"x", "B", "v", "acc"}),
    "oldham_coupling": (lambda s: OldhamCoupling(2 * s), THETA, {"S", "s1", "s3", "vS", "aS"}),
}


def _quiet(function, *args, **kwargs):
    """Call `function` with every warning turned into an error."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return function(*args, **kwargs)


def _compare(got, want, s, linear, masks=("valid", "assembled")):
    """Worst error of the fields of pose `got` (scale s) against `want` (scale 1).

    Angles and angular rates are compared as they are, lengths and linear rates after
    dividing by s; each error is relative to the largest magnitude of the field over the
    sweep (absolute for angles, whose natural size is one).
    """
    worst = 0.0
    for name, ref in want._fields.items():
        value = got._fields[name]
        if name in masks:
            assert np.array_equal(value, ref), name
            continue
        mask = np.broadcast_to(want.valid if name in want._ORDER_OF
                               else want.assembled, np.shape(ref)[: np.ndim(want.valid)])
        value, ref = np.asarray(value), np.asarray(ref)
        # never NaN where the mask of the field is True, at any scale
        assert not np.isnan(value).reshape(mask.shape + (-1,)).any(-1)[mask].any(), name
        value = value / s if name in linear else value
        size = max(1.0, float(np.max(np.abs(ref[mask]), initial=0.0)))
        error = np.abs(value[mask] - ref[mask])
        if name in ("phi", "psi", "phi03", "phi41", "orbit", "theta"):
            error = np.abs(np.angle(np.exp(1j * (value[mask] - ref[mask]))))
        worst = max(worst, float(np.max(error, initial=0.0)) / size)
    return worst


@pytest.mark.parametrize("scale", SCALES)
@pytest.mark.parametrize("name", sorted(CASES))
def test_solve_scale_invariance(name, scale):
    build, theta, linear = CASES[name]
    want = build(1.0).solve(theta, order=2, omega=1.5, alpha=-0.5)
    got = _quiet(build(scale).solve, theta, order=2, omega=1.5, alpha=-0.5)
    assert _compare(got, want, scale, linear) <= RTOL


@pytest.mark.parametrize("scale", SCALES)
def test_tangent_mechanism_scale_invariance(scale):
    """Away from cos(theta) = 0, where the slide of a huge L leaves the float range."""
    theta = np.linspace(-1.4, 1.4, 301)
    want = TangentMechanism(2.0).solve(theta, order=2, omega=1.5, alpha=-0.5)
    got = _quiet(TangentMechanism(2.0 * scale).solve, theta, order=2, omega=1.5, alpha=-0.5)
    assert _compare(got, want, scale, {"h", "S", "v", "acc"}) <= RTOL


def test_tangent_mechanism_overflow_is_quiet():
    pose = _quiet(TangentMechanism(1e300).solve, [np.pi / 2, np.pi / 2 - 1e-9, 0.0], order=1)
    assert pose.assembled.tolist() == [True, True, True] and np.isinf(pose.h[:2]).all()
    # a rate beyond the float range is masked like a dead point's: NaN under a False mask
    assert pose.valid.tolist() == [False, False, True] and np.isnan(pose.v[:2]).all()


def test_rate_overflow_near_a_dead_point_is_quiet():
    """Near a dead point a unit rate of 1e8 times a length of 1e300 leaves the float range.

    The product was taken outside ``np.errstate``: a RuntimeWarning escaped on valid input.
    Beyond the float range the rate is masked like a dead point's (NaN, ``valid`` False).
    """
    theta = np.linspace(-np.pi, np.pi, 721)      # hits -5 pi / 6 of the slider-crank
    pose = _quiet(SliderCrank(3e300, 2e300, 0.5e300).solve, theta, order=2)
    for value in (pose.v, pose.acc):
        assert np.all(np.isfinite(value[pose.valid])) and np.all(np.isnan(value[~pose.valid]))


@pytest.mark.parametrize("scale", SCALES)
def test_rccc_scale_invariance(scale):
    def build(s):
        return RCCC((0.6, 0.2 * s), (1.2, 0.5 * s), (1.0, 0.1 * s), (1.3, 0.4 * s), s1=0.3 * s)

    want = build(1.0).solve(THETA, order=1, omega=1.5)
    got = _quiet(build(scale).solve, THETA, order=1, omega=1.5)
    assert _compare(got, want, scale, {"s4", "s2", "s3", "v_output"}) <= RTOL


@pytest.mark.parametrize("scale", SCALES)
def test_triad_scale_invariance(scale):
    dims = dict(a=10, b=60, cd=36, ce=36, g=40, f=40)
    theta = np.linspace(np.pi / 2, np.pi / 2 + 2 * np.pi, 73)

    def solve(s):
        triad = TriadSixBar(**{k: v * s for k, v in dims.items()}, angle=-np.pi / 2,
                            G=(118 + 41j) * s, F=(91 - 48j) * s)
        return _quiet(triad.solve, theta, ((60 + 10j) * s, np.pi / 3), omega=1.5)

    want, got = solve(1.0), solve(scale)
    assert np.array_equal(got.valid, want.valid) and want.valid.all()
    assert np.max(np.abs(np.angle(np.exp(1j * (got.phi - want.phi))))) <= RTOL
    assert np.max(np.abs(got.omega - want.omega)) <= RTOL * np.max(np.abs(want.omega))
    for name in ("B", "C", "D", "E", "vB", "vC", "vD", "vE"):
        ref = getattr(want, name)
        assert np.max(np.abs(getattr(got, name) / scale - ref)) <= RTOL * np.max(np.abs(ref)), name


@pytest.mark.parametrize("scale", SCALES)
def test_slider_crank_helpers_scale_invariance(scale):
    unit, scaled = SliderCrank(30, 100, 20), SliderCrank(30 * scale, 100 * scale, 20 * scale)
    want, got = unit.limit_positions(), _quiet(scaled.limit_positions)
    for field in ("theta_extended", "theta_folded", "extreme_angle", "time_ratio"):
        assert getattr(got, field) == pytest.approx(getattr(want, field), rel=RTOL, abs=RTOL)
    for field in ("x_extended", "x_folded", "stroke"):
        assert getattr(got, field) / scale == pytest.approx(getattr(want, field), rel=RTOL)
    assert _quiet(scaled.stroke) / scale == pytest.approx(unit.stroke(), rel=RTOL)
    assert _quiet(scaled.extreme_angle) == pytest.approx(unit.extreme_angle(), rel=RTOL)
    assert _quiet(scaled.min_transmission_angle)[0] == pytest.approx(unit.min_transmission_angle()[0], rel=RTOL)
    np.testing.assert_allclose(_quiet(scaled.transmission_angle, THETA), unit.transmission_angle(THETA),
                               rtol=0, atol=RTOL)
    want = SliderCrank(1.0, 4.0).approximate(THETA, 1.5)
    got = _quiet(SliderCrank(scale, 4.0 * scale).approximate, THETA, 1.5)
    for name in ("x", "v", "acc"):
        ref = getattr(want, name)
        assert np.max(np.abs(getattr(got, name) / scale - ref)) <= RTOL * np.max(np.abs(ref)), name
    assert np.max(np.abs(got.cos_phi - want.cos_phi)) <= RTOL


@pytest.mark.parametrize("scale", SCALES)
def test_guide_bar_helpers_scale_invariance(scale):
    unit, scaled = GuideBar(150, 300), GuideBar(150 * scale, 300 * scale)
    assert _quiet(scaled.swing) == pytest.approx(unit.swing(), rel=RTOL)
    assert _quiet(scaled.time_ratio) == pytest.approx(unit.time_ratio(), rel=RTOL)
    assert _quiet(scaled.min_guide_length) / scale == pytest.approx(unit.min_guide_length(), rel=RTOL)
    assert _quiet(GuideBar.from_swing, 300 * scale, np.pi / 3).a / scale == pytest.approx(150, rel=RTOL)
    assert _quiet(SwingingBlock(scale, 2 * scale).swing) == pytest.approx(np.pi / 3, rel=RTOL)


@pytest.mark.parametrize("scale", SCALES)
def test_length_helpers_scale_invariance(scale):
    reach = _quiet(example_2_25_reach, THETA, 0.2 * scale, 0.3 * scale, 0.2 * scale)
    np.testing.assert_allclose(reach / scale, example_2_25_reach(THETA, 0.2, 0.3, 0.2), rtol=RTOL)
    # Jansen's link b-d-e: sides 41.5, 40.1, 55.8
    corner = _quiet(_triangle, 41.5 * scale, 40.1 * scale, 55.8 * scale, 1, "b-d-e")
    want = _triangle(41.5, 40.1, 55.8, 1, "b-d-e")
    assert abs(corner / scale - want) <= RTOL * abs(want)


@pytest.mark.parametrize("scale", SCALES)
def test_slider_crank_functions_scale_invariance(scale):
    """The free functions on slider-crank dimensions: angles unchanged, the mechanical
    advantage (force over torque, 1 / length) divided by the scale, dead points times it."""
    dims, scaled = (30.0, 100.0, 20.0), (30.0 * scale, 100.0 * scale, 20.0 * scale)
    np.testing.assert_allclose(_quiet(slider_crank_pressure_angle, *scaled, THETA),
                               slider_crank_pressure_angle(*dims, THETA), rtol=0, atol=RTOL)
    assert _quiet(slider_crank_min_transmission_angle, *scaled)[0] == pytest.approx(
        slider_crank_min_transmission_angle(*dims)[0], rel=RTOL)
    # the advantage has poles at the limit positions: compare where it is below 1 / mm
    # (30 times its smallest magnitude), where its condition number is modest
    want = slider_crank_mechanical_advantage(*dims, THETA)
    keep = np.abs(want) < 1.0
    assert keep.sum() > 600
    np.testing.assert_allclose(_quiet(slider_crank_mechanical_advantage, *scaled, THETA)[keep] * scale,
                               want[keep], rtol=RTOL)
    np.testing.assert_allclose(np.array(_quiet(slider_crank_dead_points, *scaled).inputs) / scale,
                               slider_crank_dead_points(*dims).inputs, rtol=RTOL)


def test_length_scale_is_a_power_of_two_near_the_longest():
    for lengths in [(3.0, -10.0, 0.5), (1e-300,), (1.7e308, 1.0), (5e-324,), (0.0, 0.0)]:
        unit = length_scale(*lengths)
        assert np.frexp(unit)[0] == 0.5
        biggest = max(abs(x) for x in lengths)
        assert biggest == 0.0 and unit == 1.0 or unit <= biggest < 2 * unit


# ----------------------------------------------------------------------------- mpmath
def _mp_slider_crank(a, b, e, m, theta, omega, alpha):
    """x, phi, v, acc of a slider-crank at 50 digits: the closed form x(theta) evaluated
    unfactored (mpmath has no overflow), and its derivatives by numerical differentiation."""
    a, b, e = (mpmath.mpf(float(v)) for v in (a, b, e))
    x = lambda t: a * mpmath.cos(t) + m * mpmath.sqrt(b**2 - (e - a * mpmath.sin(t)) ** 2)
    t = mpmath.mpf(float(theta))
    x0, x1, x2 = (mpmath.diff(x, t, k) for k in range(3))
    phi = mpmath.atan2(e - a * mpmath.sin(t), x0 - a * mpmath.cos(t))
    return x0, phi, x1 * omega, x2 * omega**2 + x1 * alpha


@pytest.mark.parametrize("scale", [1e-300, 1e-160, 1.0, 1e160, 1e300])
def test_slider_crank_against_mpmath_at_scale(scale):
    theta = np.linspace(-3.0, 3.0, 13)
    for a, b, e, m in [(30, 100, 20, 1), (1, 3, -0.5, -1)]:
        pose = _quiet(SliderCrank(a * scale, b * scale, e * scale, branch=m).solve, theta,
                      order=2, omega=1.5, alpha=-0.5)
        with mpmath.workdps(50):
            for k, t in enumerate(theta):
                x, phi, v, acc = _mp_slider_crank(a * scale, b * scale, e * scale, m, t, 1.5, -0.5)
                size = mpmath.mpf(b * scale)
                assert abs(pose.x[k] - x) <= RTOL * size
                assert abs(pose.phi[k] - phi) <= RTOL
                assert abs(pose.v[k] - v) <= RTOL * size
                assert abs(pose.acc[k] - acc) <= RTOL * size


@pytest.mark.parametrize("scale", [1e-300, 1e-160, 1.0, 1e160, 1e300])
def test_guide_bar_against_mpmath_at_scale(scale):
    theta = np.linspace(-3.0, 3.0, 13)
    for cls, a, d in [(GuideBar, 150, 300), (RotatingGuideBar, 2, 1)]:
        pose = _quiet(cls(a * scale, d * scale).solve, theta, order=1, omega=1.5)
        with mpmath.workdps(50):
            A, D = mpmath.mpf(a * scale), mpmath.mpf(d * scale)
            arm = lambda t: A * mpmath.expjpi(t / mpmath.pi) - D        # B - D
            for k, t in enumerate(theta):
                t = mpmath.mpf(float(t))
                rho = abs(arm(t))
                angle = mpmath.arg(arm(t))
                rate = mpmath.diff(lambda u: mpmath.im(mpmath.log(arm(u) / arm(t))), t) * 1.5
                assert abs(pose.rho[k] - rho) <= RTOL * D
                assert abs(mpmath.sin(pose.psi[k] - angle)) <= RTOL
                assert mpmath.cos(pose.psi[k] - angle) > 0
                assert abs(pose.omega_guide[k] - rate) <= RTOL


# ----------------------------------------------------------------------------- dead points
def test_mask_singular_rates_rule():
    fields = {"valid": np.array([True, True, False, True]),
              "w": np.array([1.0, np.inf, np.nan, 2.0]),
              "v": np.array([[1.0, 2.0, 3.0], [1.0, 2.0, 3.0], [np.nan] * 3, [1.0, np.nan, 3.0]])}
    mask_singular_rates(fields, ("w", "v"))
    assert fields["valid"].tolist() == [True, False, False, False]
    assert fields["assembled"].tolist() == [True, True, False, True]
    assert np.isnan(fields["w"][1:3]).all() and np.isnan(fields["v"][1:]).all()
    assert fields["w"][0] == 1.0 and fields["v"][0].tolist() == [1.0, 2.0, 3.0]


@pytest.mark.parametrize("scale", SCALES)
def test_slider_crank_dead_points_at_every_scale(scale):
    """Exact dead points (sin(+-pi/2) = +-1 exactly): positions valid, rates masked."""
    for (a, b, e), theta in [((1, 2, -1), np.pi / 2), ((1, 1.5, 0.5), -np.pi / 2)]:
        pose = _quiet(SliderCrank(a * scale, b * scale, e * scale).solve, [theta, 0.0], order=2)
        assert pose.assembled.tolist() == [True, True]
        assert pose.valid.tolist() == [False, True]
        assert pose.x[0] / scale == pytest.approx(0.0, abs=1e-16)
        assert pose.phi[0] == pytest.approx(-np.sign(theta) * np.pi / 2, abs=1e-15)
        for name in ("v", "omega_coupler", "acc", "alpha_coupler"):
            value = getattr(pose, name)
            assert np.isnan(value[0]) and np.isfinite(value[1]), name
        assert np.isfinite(pose.vB).all() and np.isfinite(pose.aB).all()


def _fourbar_margin(a, b, c, d, theta):
    """Distance (relative to a + b + c + d) by which |BD| lies inside [|b - c|, b + c], at 50 digits."""
    mpmath.mp.dps = 50
    k = mpmath.sqrt(mpmath.mpf(d - a) ** 2 + 4 * a * d * mpmath.sin(mpmath.mpf(theta) / 2) ** 2)
    return float(min(b + c - k, k - abs(b - c)) / (a + b + c + d))


@pytest.mark.parametrize("lengths", [(1, 2, 3, 1), (1, 1, 2, 1), (2, 1, 3, 2), (6, 3, 3, 6), (3, 4, 2, 6)])
@pytest.mark.parametrize("samples", [721, 361, 24])
def test_dead_point_samples_valid_in_every_unit(lengths, samples):
    """Grids of nice angles land on dead points (|BD| = b + c or |b - c|) of nice lengths:
    whether such a sample assembled was a rounding, decided differently at 1e-300 or 3.7
    than at 1 (289 of 11440 integer four-bars and grids). Within 2**-46 of the size the
    input is the dead point: assembled, with NaN rates (`valid` False with rates) in
    every unit, for `FourBar` and `Linkage` alike. The mask is checked against the margin
    at 50 digits: True where it is >= -1e-15, False where it is < -1e-13."""
    theta = np.linspace(-np.pi, np.pi, samples) if samples != 24 else np.radians(np.arange(0, 360, 15.0))
    margin = np.array([_fourbar_margin(*lengths, t) for t in theta])
    for order in (0, 1):
        masks = []
        for s in [1.0, 1e-300, 3.7, 1e300]:
            L = [x * s for x in lengths]
            fb = _quiet(FourBar(*L).solve, theta, order=order)
            lk = (Linkage({"A": 0, "D": L[3]}).crank("crank", pivot="A", tip="B", length=L[0])
                  .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(L[1], L[2])))
            masks += [fb.valid, _quiet(lk.solve, theta, order=order).valid]
            if order == 0:
                assert np.all(fb.valid[margin >= -1e-15]) and not np.any(fb.valid[margin < -1e-13])
        for m in masks[1:]:
            np.testing.assert_array_equal(m, masks[0])


@pytest.mark.parametrize("lengths", [(3, 2, 0.5), (1, 2, 3), (2, 3, -1)])
def test_slider_crank_dead_point_samples_valid_in_every_unit(lengths):
    """The slider-crank's dead points |a sin(theta) - e| = b on a nice grid, and b = |e| - a
    (the rod just reaches the guide), which the constructor refused at 1e-300 only."""
    theta = np.linspace(-np.pi, np.pi, 721)
    for order in (0, 1):
        ref = SliderCrank(*lengths).solve(theta, order=order)
        for s in [1e-300, 3.7, 1e300]:
            pose = _quiet(SliderCrank(*(x * s for x in lengths)).solve, theta, order=order)
            np.testing.assert_array_equal(pose.valid, ref.valid)
            np.testing.assert_array_equal(pose.assembled, ref.assembled)


@pytest.mark.parametrize("lengths", [(1, 2, -2), (1, 2, 2), (3, 2, 0.5)])
def test_linkage_slider_dead_point_samples_valid_in_every_unit(lengths):
    """The RRP group of a `Linkage` (the slider-crank by `as_linkage`) on a grid that lands on
    its dead points: the masks were scale-dependent (39 of 624 nice cases)."""
    from mech.planar import as_linkage

    theta = np.linspace(-np.pi, np.pi, 721)
    for order in (0, 1):
        ref = as_linkage(SliderCrank(*lengths)).solve(theta, order=order).valid
        np.testing.assert_array_equal(ref, SliderCrank(*lengths).solve(theta, order=order).valid)
        for s in [1e-300, 3.7, 1e300]:
            got = _quiet(as_linkage(SliderCrank(*(x * s for x in lengths))).solve, theta, order=order).valid
            np.testing.assert_array_equal(got, ref)


@pytest.mark.parametrize("dims", [(1, 2, 1, 0.0, 0.0, 1.0, 0.0), (1, 2, 1, 0.0, 1.0, 1.0, np.pi / 2),
                                  (2, 4, 1, 0.5, 1.0, 3.0, 1.0)])
def test_rssr_limit_position_samples_valid_in_every_unit(dims):
    """RSSR limit positions on a nice grid (79 of 2958 nice cases had scale-dependent masks)."""
    from mech.spatial import RSSR

    theta = np.linspace(-np.pi, np.pi, 721)
    *lengths, lam = dims
    for order in (0, 1):
        ref = RSSR(*lengths, lam).solve(theta, order=order)
        for s in [1e-300, 3.7, 1e300]:
            got = _quiet(RSSR(*(x * s for x in lengths), lam).solve, theta, order=order)
            np.testing.assert_array_equal(got.valid, ref.valid)
            np.testing.assert_array_equal(got.assembled, ref.assembled)


@pytest.mark.parametrize("dims", [(1, 1, 1), (3, 4, 5), (3, 5, 7), (2, 1, 3), (4, 3, 5)])
def test_linkage_rpr_dead_point_samples_valid_in_every_unit(dims):
    """The RPR group of a `Linkage` (crank AB, guide pinned at D through the block at B, at
    an offset e) on a grid of nice angles that lands on its dead points |B - D| = |e|: the
    masks were scale-dependent (125 of 11340 nice cases over 1e-300..1e300). Reference: the
    exact angle in 60-digit arithmetic; a dead point assembles with NaN rates."""
    import mpmath
    from mech.planar import Linkage

    a, d, e = dims
    degrees = np.arange(-360, 361) * 0.5
    theta = np.radians(degrees)
    with mpmath.workdps(60):
        gap = [mpmath.sqrt(a * a + d * d - 2 * a * d * mpmath.cos(mpmath.radians(mpmath.mpf(x)))) - e
               for x in degrees]
    dead = np.array([abs(x) < 1e-40 for x in gap])
    assembled = np.array([x > 0 for x in gap]) | dead
    assert dead.any()

    def linkage(s):
        return (Linkage({"A": 0, "D": d * s}).crank("crank", pivot="A", tip="B", length=a * s)
                .rpr(("guide", "block"), pins=("D", "B"), offset=e * s))

    for s in [1e-300, 1e-150, 1.0, 3.7, 1e150, 1e300]:
        np.testing.assert_array_equal(_quiet(linkage(s).solve, theta).valid, assembled)
        pose = _quiet(linkage(s).solve, theta, order=2)
        np.testing.assert_array_equal(pose.valid, assembled & ~dead)
