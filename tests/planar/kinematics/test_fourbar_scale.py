"""Four-bar results do not depend on the unit of length, from 1e-300 to 1e300.

Every length (and the coupler point) is multiplied by a scale s. Angles, angular rates
and the valid mask must not change; points, velocities and accelerations must scale by
s. With s a power of two the package's internal scaling is exact, so the results must be
identical to the last bit. With s a power of ten the scaled lengths are themselves
rounded (half an ulp each), which moves the results by their condition number times
that. A pose a relative distance delta from a limit position has rates that grow like
delta^-1/2 and delta^-3/2 and a condition number of about 1/delta, so poses with delta
below 1e-3 are compared for the mask and NaN only, and the others within 1e-12, relative
to the linkage size (points) or to the value itself where that is larger.
"""

import math
import warnings

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from mech.planar import FourBar
from mech.planar.coupler._atlas import coupler_dashes
from mech.planar.coupler._centrodes import coupler_centrodes
from mech.planar.coupler._cognates import cognates
from mech.planar.forces._force_gain import fourbar_dead_points, fourbar_mechanical_advantage
from mech.planar.structure._limit_positions import limit_positions
from mech.planar.forces._pressure_angle import fourbar_pressure_angle, transmission_extremes
from mech.planar.forces._transmission import min_transmission_angle, transmission_angle

SCALES = [1e-300, 1e-200, 1e-160, 1e-150, 1e-110, 1e-50, 1.0, 1e50, 1e110, 1e160, 1e200, 1e300]
POWERS = [2.0**k for k in (-990, -520, -1, 3, 520, 990)]
LINKAGES = {
    "crank-rocker": ((10.0, 40.0, 30.0, 35.0), (20.0, 10.0)),
    "triple-rocker": ((3.0, 2.0, 2.5, 4.0), (1.0, -0.5)),
    "parallelogram": ((2.0, 3.0, 2.0, 3.0), (1.0, 1.0)),
    "kite": ((1.0, 2.0, 2.0, 1.0), (0.5, 0.3)),
    "rhombus": ((1.0, 1.0, 1.0, 1.0), (0.2, 0.7)),
}
THETA = np.concatenate([np.linspace(-2 * np.pi, 2 * np.pi, 2001), [0.0, 1e-300, -1e-16, np.pi]])
OMEGA, ALPHA = 1.7, -0.3
POINTS = ("B", "C", "P", "vB", "vC", "vP", "aB", "aC", "aP")
ANGLES = ("phi", "psi", "omega_coupler", "omega_output", "alpha_coupler", "alpha_output")
TOL = 1e-12


def _solve(name, branch, s):
    (a, b, c, d), (p, q) = LINKAGES[name]
    linkage = FourBar(a * s, b * s, c * s, d * s, branch=branch, coupler=(p * s, q * s))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return linkage.solve(THETA, order=2, omega=OMEGA, alpha=ALPHA)


def _limit_slack(name, branch):
    """Relative distance of each pose from a limit position (the triangle BCD flat)."""
    (a, b, c, d), _ = LINKAGES[name]
    k = np.abs(d - a * np.exp(1j * THETA))
    with np.errstate(invalid="ignore"):
        return np.minimum.reduce([k - abs(c - b), (b + c) - k]) / (a + b + c + d)


def _same_bits(scaled, base, s):
    """`scaled` equals `base` times the power of two `s`, bit for bit.

    Multiplying by `s` rounds like the package's own scaling, also where the scaled value
    falls among the subnormal numbers; only where `base` itself is subnormal (rounded by
    the package's scaling to the unit of `base`) may the bits differ, and those entries
    are left out.
    """
    tiny = np.finfo(float).tiny
    parts = [(scaled.real, base.real), (scaled.imag, base.imag)] if np.iscomplexobj(base) else [(scaled, base)]
    for x, y in parts:
        normal = (y == 0) | (np.abs(y) >= tiny)
        if not np.array_equal(x[normal], y[normal] * s):
            return False
    return True


def _check_pose(pose, base, s, size, exact):
    assert np.array_equal(pose.valid, base.valid)
    ok = base.valid
    for name in POINTS + ANGLES:
        value = np.asarray(getattr(pose, name))
        # never NaN with valid True; NaN wherever the linkage cannot be assembled (the
        # crank pin B and its motion exist at every input angle)
        assert not np.any(np.isnan(value[ok])), name
        if name not in ("B", "vB", "aB"):
            assert np.all(np.isnan(value[~ok])), name
    if exact is None:
        return None
    if exact:
        # multiplying by a power of two rounds like the package's own scaling, also
        # where the scaled value falls among the subnormal numbers
        for name in POINTS:
            assert _same_bits(getattr(pose, name)[ok], getattr(base, name)[ok], s), name
        for name in ANGLES:
            assert np.array_equal(getattr(pose, name)[ok], getattr(base, name)[ok]), name
        return 0.0
    worst = 0.0
    for name in POINTS:
        unit = size * {"": 1.0, "v": OMEGA, "a": OMEGA**2 + abs(ALPHA)}[name[:-1]]
        ref = getattr(base, name)[ok]
        err = np.abs(getattr(pose, name)[ok] / s - ref) / np.maximum(unit, np.abs(ref))
        worst = max(worst, np.max(err, initial=0.0))
    for name in ANGLES:
        ref = getattr(base, name)[ok]
        diff = getattr(pose, name)[ok] - ref
        if name in ("phi", "psi"):
            diff = np.angle(np.exp(1j * diff))
        unit = {"p": 1.0, "o": OMEGA, "a": OMEGA**2 + abs(ALPHA)}[name[0]]
        worst = max(worst, np.max(np.abs(diff) / np.maximum(unit, np.abs(ref)), initial=0.0))
    return worst


@pytest.mark.parametrize("name", list(LINKAGES))
@pytest.mark.parametrize("branch", [1, -1])
def test_solve_scale_powers_of_two_exact(name, branch):
    """s = 2**k, k from -990 to 990: identical bits after dividing by s."""
    base = _solve(name, branch, 1.0)
    size = sum(LINKAGES[name][0])
    for s in POWERS:
        _check_pose(_solve(name, branch, s), base, s, size, exact=True)


@pytest.mark.parametrize("name", list(LINKAGES))
@pytest.mark.parametrize("branch", [1, -1])
def test_solve_scale_powers_of_ten(name, branch):
    """s = 1e-300 ... 1e300: the same angles and mask, points scaled by s, within 1e-12
    (poses within 1e-3 of a limit position, where rounding of the lengths is amplified
    beyond that, are compared for the mask and NaN only)."""
    base = _solve(name, branch, 1.0)
    size = sum(LINKAGES[name][0])
    far = ~(_limit_slack(name, branch) < 1e-3)
    for s in SCALES:
        pose = _solve(name, branch, s)
        assert np.array_equal(pose.valid, base.valid)
        sub_pose = _Subset(pose, far)
        sub_base = _Subset(base, far)
        _check_pose(pose, base, s, size, exact=None)
        assert _check_pose(sub_pose, sub_base, s, size, exact=False) < TOL, s


class _Subset:
    """The fields of a pose at a boolean selection of its input angles."""

    def __init__(self, pose, keep):
        self._pose, self._keep = pose, keep

    def __getattr__(self, name):
        return np.asarray(getattr(self._pose, name))[self._keep]


def _free_functions(s):
    a, b, c, d = (x * s for x in (10.0, 40.0, 30.0, 35.0))
    theta = np.linspace(-3, 3, 13)
    out = {
        "transmission_angle": transmission_angle(a, b, c, d, theta),
        "min_transmission_angle": np.array(min_transmission_angle(a, b, c, d)),
        "fourbar_pressure_angle": fourbar_pressure_angle(a, b, c, d, theta),
        "dead_points": np.array(fourbar_dead_points(a, b, c, d).inputs),
        "mechanical_advantage": np.ravel(fourbar_mechanical_advantage(a, b, c, d, theta)),
    }
    x = transmission_extremes(a, b, c, d)
    out["transmission_extremes"] = np.array([x.delta_min, x.delta_max, x.gamma_min, x.theta_at])
    lp = limit_positions(a, b, c, d)
    out["limit_positions"] = np.array([lp.theta_extended, lp.theta_folded, lp.psi_extended,
                                       lp.psi_folded, lp.swing, lp.extreme_angle, lp.time_ratio])
    linkage = FourBar(a, b, c, d, coupler=(20 * s, 10 * s))
    trio = cognates(linkage)
    out["cognates"] = np.concatenate([trio.path(theta).ravel(), [trio.K]]) / s
    out["cognate_lengths"] = np.array([x.lengths for x in trio]).ravel() / s
    out["cognate_branches"] = trio.branches(theta).ravel()
    cen = coupler_centrodes(linkage, theta)
    out["centrodes"] = np.concatenate([cen.fixed, cen.moving]) / s
    out["dashes"] = coupler_dashes(a, b, c, d, [20 * s + 10j * s, 5 * s - 3j * s], n=12).points.ravel() / s
    return out


@pytest.mark.parametrize("s", SCALES)
def test_fourbar_functions_scale(s):
    """Limit positions, transmission and pressure angles, dead points, mechanical
    advantage, cognates, centrodes and coupler dashes at every scale, with no warning."""
    base = _free_functions(1.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        got = _free_functions(s)
    for name, ref in base.items():
        value = got[name]
        assert value.shape == ref.shape, name
        assert np.array_equal(np.isnan(value), np.isnan(ref)), name
        ok = ~np.isnan(ref)
        err = np.max(np.abs(value[ok] - ref[ok]) / np.maximum(1.0, np.abs(ref[ok])), initial=0.0)
        assert err < TOL, (name, err)


def test_fourbar_extreme_length_ratio():
    """Lengths at the ends of the float range together (1e300 and 1e-300 in one linkage):
    a crank 1e-300 long on links 1e300 long leaves the rocker still, without warnings."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pose = FourBar(1e-300, 1e300, 1e300, 1e300).solve(np.linspace(0, 6, 7), order=2)
    assert pose.valid.all()
    assert np.all(np.abs(pose.omega_output) < 1e-299)
    assert math.isclose(float(np.abs(pose.C[0] - 1e300)), 1e300, rel_tol=1e-15)


@settings(max_examples=60, deadline=None)
@given(lengths=st.lists(st.floats(0.05, 1.0), min_size=4, max_size=4),
       coupler=st.tuples(st.floats(-2, 2), st.floats(-2, 2)),
       k=st.integers(-1000, 1000), branch=st.sampled_from([1, -1]))
def test_solve_scale_power_of_two_random(lengths, coupler, k, branch):
    """Random linkages at a random power-of-two scale: the same bits, scaled."""
    assume(max(lengths) < sum(lengths) - max(lengths))
    s = 2.0**k
    # the claim holds while nothing is subnormal: neither the scaled inputs nor the products
    # of an input with the unit-size factors of the solution (a coupler offset of 2.2e-308
    # makes a subnormal coordinate at scale 1 whose last bit the scaled run keeps)
    assume(all(x == 0 or min(abs(x), abs(x * s)) >= 1e-290 for x in (*lengths, *coupler)))
    theta = np.linspace(-4, 4, 41)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        base = FourBar(*lengths, branch=branch, coupler=coupler).solve(theta, order=2)
        pose = FourBar(*(x * s for x in lengths), branch=branch,
                       coupler=tuple(x * s for x in coupler)).solve(theta, order=2)
    ok = base.valid
    assert np.array_equal(pose.valid, ok)
    for name in POINTS:
        assert _same_bits(getattr(pose, name)[ok], getattr(base, name)[ok], s), name
    for name in ANGLES:
        assert np.array_equal(getattr(pose, name)[ok], getattr(base, name)[ok]), name


def test_rates_beyond_the_float_range_are_masked():
    """Near the dead point of (1, b, b, b), b = 1 - 1.4e-6, the unit acceleration of C is
    about 9e11; times lengths of 1e300 it leaves the float range, and the complex product
    held NaN under ``valid`` True. It is masked like a dead point's now: the pose is
    assembled, its rates are not numbers."""
    b = 0.999998627552429
    theta = np.array([1.1920929e-07, 0.5])
    unit = FourBar(1, b, b, b).solve(theta, order=2, omega=1.3, alpha=0.7)
    assert unit.valid.all() and abs(unit.aC[0]) > 1e11            # finite at scale 1
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        huge = FourBar(1e300, b * 1e300, b * 1e300, b * 1e300).solve(theta, order=2, omega=1.3, alpha=0.7)
    assert huge.assembled.tolist() == [True, True] and huge.valid.tolist() == [False, True]
    assert np.isnan(huge.aC[0]) and np.isfinite(huge.C[0])
    for name in ("B", "C", "P", "omega_output", "vC", "vP", "alpha_output", "aC", "aP"):
        assert np.all(np.isfinite(getattr(huge, name)[huge.valid])), name
    np.testing.assert_allclose(huge.psi, unit.psi, rtol=1e-9)    # near a dead point: ill-conditioned


@pytest.mark.parametrize("lengths", [(1, 0.78314, 1, 1), (3000, 492.155, 32.487, 3000), (1, 1, 0.01, 1)])
def test_pin_all_but_on_the_pivot_is_quiet(lengths):
    """a = d: at theta ~ 1e-157 B is 1e-157 from D, 1 / |BD|^2 overflowed with a
    RuntimeWarning (the pose cannot be assembled there: b != c)."""
    theta = [2.4e-157, -6.3e-155, 1e-160, 0.0]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pose = FourBar(*lengths).solve(theta, order=2)
    assert not pose.valid.any() and np.isnan(pose.psi).all()
