"""The RSSR four-bar against routes that share no code with it: mpmath root solves at 50
digits on the vector constraint (C built by Rodrigues' rotation, no H-D matrix), mpmath
derivatives, the textbook's half-angle formula evaluated literally, and sampling."""

import warnings

import mpmath
import numpy as np
import pytest

from mech import AssemblyError
from mech.spatial._rssr import RSSR



@pytest.fixture(autouse=True)
def fifty_digits():
    with mpmath.workdps(50):
        yield


def _random_linkages(seed, count):
    rng = np.random.default_rng(seed)
    for _ in range(count):
        yield (rng.uniform(0.5, 2), rng.uniform(1.5, 5), rng.uniform(0.5, 2), rng.uniform(-1.5, 1.5),
               rng.uniform(-1.5, 1.5), rng.uniform(-3, 3), rng.uniform(-np.pi, np.pi))


def _points_mp(dims, p1, p3):
    """B and C at 50 digits: C turns D + l3 x0 about the rocker axis (Rodrigues)."""
    l1, l2, l3, s0, s3, h0, lam = (mpmath.mpf(float(x)) for x in dims)
    k = mpmath.matrix([0, mpmath.sin(lam), mpmath.cos(lam)])
    D = mpmath.matrix([h0, 0, 0]) + s3 * k
    v = mpmath.matrix([l3, 0, 0])
    kxv = mpmath.matrix([k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]])
    C = D + v * mpmath.cos(p3) + kxv * mpmath.sin(p3)
    B = mpmath.matrix([l1 * mpmath.cos(p1), l1 * mpmath.sin(p1), s0])
    return B, C, D, k


def _phi03_mp(dims, p1, guess):
    l2 = mpmath.mpf(float(dims[1]))
    f = lambda x: mpmath.norm(_points_mp(dims, p1, x)[1] - _points_mp(dims, p1, x)[0]) ** 2 - l2**2
    return mpmath.findroot(f, mpmath.mpf(float(guess)) + mpmath.mpf("1e-4"))


def _wrap(x):
    return np.angle(np.exp(1j * np.asarray(x, dtype=float)))


def test_solve_coupler_length_both_modes():
    worst, poses = 0.0, 0
    phi = np.linspace(-np.pi, np.pi, 721)
    for dims in _random_linkages(1, 60):
        for branch in (1, -1):
            pose = RSSR(*dims, branch=branch).solve(phi)
            length = np.linalg.norm(pose.C[pose.valid] - pose.B[pose.valid], axis=-1)
            worst = max(worst, float(np.max(np.abs(length / dims[1] - 1.0), initial=0.0)))
            poses += int(pose.valid.sum())
    assert poses > 10000
    assert worst < 1e-12


def test_solve_agrees_with_mpmath_findroot():
    worst, checked = 0.0, 0
    rng = np.random.default_rng(2)
    for dims in _random_linkages(3, 40):
        p1 = rng.uniform(-np.pi, np.pi)
        for branch in (1, -1):
            pose = RSSR(*dims, branch=branch).solve(p1)
            if not pose.valid:
                continue
            reference = _phi03_mp(dims, p1, pose.phi03)
            B, C, D, k = _points_mp(dims, p1, reference)
            u, v = C - D, B - C
            triple = (k[0] * (u[1] * v[2] - u[2] * v[1]) + k[1] * (u[2] * v[0] - u[0] * v[2])
                      + k[2] * (u[0] * v[1] - u[1] * v[0]))
            assert (triple > 0) == (branch == 1)
            worst = max(worst, abs(float(_wrap(float(reference) - pose.phi03))))
            checked += 1
    assert checked >= 30
    assert worst < 1e-12


def test_solve_branch_matches_textbook_half_angle_formula():
    """branch=+1 is the + sign of phi03 = 2 atan((A + sqrt(A^2+B^2-C^2)) / (B - C)), with the
    textbook's A, B and the corrected C typed in literally from (2-71)."""
    phi = np.linspace(-3.0, 3.0, 61)
    for dims in _random_linkages(4, 20):
        l1, l2, l3, s0, s3, h0, lam = dims
        A = s0 * np.sin(lam) / l1 - np.cos(lam) * np.sin(phi)
        B = h0 / l1 - np.cos(phi)
        C = ((l1**2 + l3**2 - l2**2 + s0**2 + s3**2 + h0**2) / (2 * l1 * l3)
             - (s3 * np.sin(lam) * np.sin(phi) + h0 * np.cos(phi)) / l3 - s0 * s3 * np.cos(lam) / (l1 * l3))
        disc = A**2 + B**2 - C**2
        ok = (disc > 1e-6) & (np.abs(B - C) > 1e-6)
        for branch in (1, -1):
            text = 2 * np.arctan((A[ok] + branch * np.sqrt(disc[ok])) / (B[ok] - C[ok]))
            ours = RSSR(*dims, branch=branch).solve(phi[ok]).phi03
            assert np.max(np.abs(_wrap(ours - text)), initial=0.0) < 1e-9


def test_solve_printed_c_fails_length_condition():
    """With the textbook's printed C (last term +S0 S3 cos(lam)/(l1 l3)) the root gives a
    coupler of length sqrt(l2^2 - 4 S0 S3 cos(lam)), not l2."""
    l1, l2, l3, s0, s3, h0, lam = 1.0, 4.0, 2.0, 0.5, 0.8, 3.0, np.radians(60)
    phi = np.linspace(-np.pi, np.pi, 37)
    A = s0 * np.sin(lam) / l1 - np.cos(lam) * np.sin(phi)
    B = h0 / l1 - np.cos(phi)
    C_printed = ((l1**2 + l3**2 - l2**2 + s0**2 + s3**2 + h0**2) / (2 * l1 * l3)
                 - (s3 * np.sin(lam) * np.sin(phi) + h0 * np.cos(phi)) / l3 + s0 * s3 * np.cos(lam) / (l1 * l3))
    phi03 = 2 * np.arctan((A + np.sqrt(A**2 + B**2 - C_printed**2)) / (B - C_printed))
    Bp = np.stack([l1 * np.cos(phi), l1 * np.sin(phi), np.full_like(phi, s0)], axis=-1)
    Cp = np.stack([l3 * np.cos(phi03) + h0, l3 * np.cos(lam) * np.sin(phi03) + s3 * np.sin(lam),
                   -l3 * np.sin(lam) * np.sin(phi03) + s3 * np.cos(lam)], axis=-1)
    length = np.linalg.norm(Cp - Bp, axis=-1)
    np.testing.assert_allclose(length, np.sqrt(l2**2 - 4 * s0 * s3 * np.cos(lam)), rtol=1e-12)
    assert np.min(np.abs(length - l2)) > 0.09
    good = RSSR(l1, l2, l3, s0, s3, h0, lam).solve(phi)
    np.testing.assert_allclose(np.linalg.norm(good.C - good.B, axis=-1), l2, rtol=1e-13)


def test_solve_rates_against_mpmath_diff():
    dims = (1.0, 4.0, 2.0, 0.5, 0.8, 3.0, np.radians(60))
    omega, alpha = 1.7, -0.6
    rng = np.random.default_rng(5)
    for branch in (1, -1):
        rssr = RSSR(*dims, branch=branch)
        for t0 in rng.uniform(-2, 2, 4):
            p1 = lambda t: mpmath.mpf(0.3) + omega * t + alpha * t**2 / 2
            guess = rssr.solve(float(p1(t0))).phi03

            def phi03(t):
                return _phi03_mp(dims, p1(t), guess)

            pose = rssr.solve(float(p1(t0)), order=2, omega=omega + alpha * t0, alpha=alpha)
            w3 = mpmath.diff(phi03, t0, 1)
            a3 = mpmath.diff(phi03, t0, 2)
            assert abs(pose.omega_output - float(w3)) < 1e-11 * max(1, abs(float(w3)))
            assert abs(pose.alpha_output - float(a3)) < 1e-10 * max(1, abs(float(a3)))
            vC = [mpmath.diff(lambda t: _points_mp(dims, p1(t), phi03(t))[1][i], t0) for i in range(3)]
            aB = [mpmath.diff(lambda t: _points_mp(dims, p1(t), 0)[0][i], t0, 2) for i in range(3)]
            np.testing.assert_allclose(pose.vC, np.array(vC, dtype=float), atol=1e-11)
            np.testing.assert_allclose(pose.aB, np.array(aB, dtype=float), atol=1e-11)


def test_assembly_range_endpoints_are_zeros_of_discriminant():
    phi = np.linspace(-np.pi, np.pi, 20001)
    limited = 0
    for dims in _random_linkages(6, 80):
        rssr = RSSR(*dims)
        rng_ = rssr.assembly_range()
        disc = rssr.discriminant(phi)
        inside = rng_.contains(phi)
        # sampling agrees except within a grid step of an end
        mismatch = inside != (disc >= 0)
        if rng_.intervals.size:
            limited += 1
            ends = rng_.intervals.ravel()
            near = np.min(np.abs(_wrap(phi[:, None] - ends[None, :])), axis=1) < 2 * (phi[1] - phi[0])
            mismatch &= ~near
            l1, l2, l3, s0, s3, h0, lam = dims
            for end in ends:          # A^2 + B^2 = C^2 at the ends, at 50 digits
                e = mpmath.mpf(float(end))
                A = mpmath.mpf(h0) / l1 - mpmath.cos(e)
                B = mpmath.mpf(s0) * mpmath.sin(lam) / l1 - mpmath.cos(lam) * mpmath.sin(e)
                C = ((s3 * mpmath.sin(lam) * mpmath.sin(e) + h0 * mpmath.cos(e)) / l3
                     + mpmath.mpf(s0) * s3 * mpmath.cos(lam) / (l1 * l3)
                     - (mpmath.mpf(l1)**2 + l3**2 - l2**2 + s0**2 + s3**2 + h0**2) / (2 * l1 * l3))
                slope = abs(mpmath.diff(lambda x: (mpmath.mpf(h0) / l1 - mpmath.cos(x))**2, e)) + 1
                assert abs(float(A**2 + B**2 - C**2)) < 1e-12 * float(slope) * 10
        else:
            assert rng_.full_turn == bool(np.all(disc >= 0))
        assert not np.any(mismatch)
    assert limited >= 20


def test_solve_continuous_along_branch():
    rssr = RSSR(1.0, 4.0, 2.0, 0.5, 0.8, 3.0, np.radians(60))
    assert rssr.assembly_range().full_turn
    phi = np.linspace(-np.pi, np.pi, 4001)
    for branch in (1, -1):
        step = np.diff(np.unwrap(RSSR(1.0, 4.0, 2.0, 0.5, 0.8, 3.0, np.radians(60), branch=branch).solve(phi).phi03))
        assert np.max(np.abs(step)) < 0.01


def test_solve_planar_limit_is_fourbar():
    from mech.planar import FourBar

    phi = np.linspace(-np.pi, np.pi, 37)
    for branch in (1, -1):
        ours = RSSR(10.0, 40.0, 30.0, 0.0, 0.0, 35.0, 0.0, branch=branch).solve(phi)
        ref = FourBar(10.0, 40.0, 30.0, 35.0, branch=branch).solve(phi)
        assert np.max(np.abs(_wrap(ours.phi03 - ref.psi))) < 1e-13
        np.testing.assert_allclose(ours.C[..., 0] + 1j * ours.C[..., 1], ref.C, atol=1e-12)


def test_solve_coupler_point_is_rigid():
    rssr = RSSR(1.0, 4.0, 2.0, 0.5, 0.8, 3.0, np.radians(60), coupler=(1.5, 0.7, -0.4))
    pose = rssr.solve(np.linspace(-np.pi, np.pi, 91))
    dB = np.linalg.norm(pose.P - pose.B, axis=-1)
    dC = np.linalg.norm(pose.P - pose.C, axis=-1)
    np.testing.assert_allclose(dB, np.sqrt(1.5**2 + 0.7**2 + 0.4**2), rtol=1e-13)
    np.testing.assert_allclose(dC, np.sqrt(2.5**2 + 0.7**2 + 0.4**2), rtol=1e-13)
    # the e2 direction lies in the plane of BC and the rocker axis
    z3 = np.array([0.0, np.sin(rssr.lam), np.cos(rssr.lam)])
    normal = np.cross(pose.C - pose.B, z3)
    offset = pose.P - pose.B
    along_normal = np.einsum("...i,...i->...", offset, normal) / np.linalg.norm(normal, axis=-1)
    np.testing.assert_allclose(along_normal, -0.4, atol=1e-13)


def test_solve_invalid_is_nan_and_strict_raises():
    rssr = RSSR(2.0, 1.0, 1.0, 0.0, 0.0, 2.0, 0.5)
    pose = rssr.solve([0.0, np.pi], order=2)
    # at phi01 = 0 the crank pin is on the rocker axis (l2 = l3): a change point of this
    # spatial kite, where the branch continues with finite rates (test_rssr_change.py)
    assert pose.assembled.tolist() == [True, False] and pose.valid.tolist() == [True, False]
    assert rssr.solve([0.0, np.pi]).valid.tolist() == [True, False]
    assert np.isnan(pose.phi03[1]) and np.all(np.isnan(pose.C[1])) and np.isnan(pose.alpha_output[1])
    with pytest.raises(AssemblyError, match=r"phi01 = 3\.14159"):
        rssr.solve([0.0, np.pi], strict=True)


@pytest.mark.parametrize("kwargs, message", [
    ({"l1": -1.0}, r"Expected `l1` > 0, got -1\.0"),
    ({"l2": 0.0}, r"Expected `l2` > 0, got 0\.0"),
    ({"h0": np.nan}, r"Expected finite `h0`, got nan"),
    ({"lam": "x"}, r"Expected `lam` to be a real number"),
    ({"branch": 0}, r"Expected `branch` to be \+1 or -1, got 0"),
    ({"coupler": (1.0, 2.0)}, r"Expected `coupler` to be 3 numbers"),
])
def test_rssr_bad_input(kwargs, message):
    args = dict(l1=1.0, l2=4.0, l3=2.0, s0=0.5, s3=0.8, h0=3.0, lam=1.0)
    options = {k: kwargs.pop(k) for k in ("branch", "coupler") if k in kwargs}
    args.update(kwargs)
    with pytest.raises(ValueError, match=message):
        RSSR(*args.values(), **options)


def test_solve_bad_input():
    rssr = RSSR(1.0, 4.0, 2.0, 0.5, 0.8, 3.0, 1.0)
    with pytest.raises(ValueError, match=r"Expected finite `phi01`, got inf"):
        rssr.solve([0.0, np.inf])
    with pytest.raises(ValueError, match=r"Expected `order` to be an integer in \[0, 2\], got 3"):
        rssr.solve(0.0, order=3)
    with pytest.raises(AttributeError, match=r"needs solve\(\.\.\., order=1\)"):
        rssr.solve(0.0).omega_output


# ----------------------------------------------------------------------------- scale invariance
SCALES = [1e-300, 1e-200, 1e-160, 1e-150, 1e-110, 1e-50, 1.0, 1e50, 1e110, 1e160, 1e200, 1e300]
# Inputs at scale s differ from exact multiples of the unit ones by one rounding each; away
# from the limit positions (the sweeps keep |A^2 + B^2 - C^2| >= 0.05) the outputs then
# agree to a few hundred ulps at most.
RTOL = 256 * np.finfo(float).eps
_LINEAR = ("B", "C", "P", "vB", "vC", "aB", "aC")


def _scaled(dims, s):
    """The RSSR dimensions with every length and offset times s (lam is an angle)."""
    return tuple(x * s for x in dims[:6]) + (dims[6],)


@pytest.mark.parametrize("scale", SCALES)
@pytest.mark.parametrize("dims", [(1.0, 4.0, 2.0, 0.5, 0.8, 3.0, 1.0),      # crank turns fully
                                  (2.0, 2.5, 1.5, 0.3, -0.4, 1.5, 0.8)])    # crank rocks
@pytest.mark.parametrize("branch", [1, -1])
def test_solve_scale_invariance(dims, branch, scale):
    unit = RSSR(*dims, branch=branch, coupler=(0.7, -0.3, 0.2))
    phi = np.linspace(-np.pi, np.pi, 721)
    phi = phi[np.abs(unit.discriminant(phi)) >= 0.05]
    want = unit.solve(phi, order=2, omega=1.5, alpha=-0.5)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        rssr = RSSR(*_scaled(dims, scale), branch=branch, coupler=(0.7 * scale, -0.3 * scale, 0.2 * scale))
        got = rssr.solve(phi, order=2, omega=1.5, alpha=-0.5)
        assert np.max(np.abs(rssr.discriminant(phi) - unit.discriminant(phi))) <= RTOL
    assert np.array_equal(got.assembled, want.assembled) and np.array_equal(got.valid, want.valid)
    assert np.array_equal(got.valid, want.assembled)
    ok = want.valid
    assert not np.isnan(got.phi03[ok]).any() and np.isnan(got.phi03[~ok]).all()
    assert np.max(np.abs(_wrap(got.phi03[ok] - want.phi03[ok])), initial=0.0) <= RTOL
    for name in ("omega_output", "alpha_output"):
        ref = getattr(want, name)[ok]
        assert np.max(np.abs(getattr(got, name)[ok] - ref), initial=0.0) <= RTOL * max(1.0, np.max(np.abs(ref)))
    for name in _LINEAR:
        ref = getattr(want, name)[ok]
        error = np.abs(getattr(got, name)[ok] / scale - ref)
        assert np.max(error, initial=0.0) <= RTOL * max(1.0, np.max(np.abs(ref))), name


@pytest.mark.parametrize("scale", [1e-300, 1e-160, 1e160, 1e300])
def test_solve_agrees_with_mpmath_at_scale(scale):
    """mpmath on the vector constraint with the scaled dimensions as given (no rescaling:
    mpmath has no overflow), the residual divided by l2^2 so that its tolerance is unit-free."""
    dims = _scaled((1.0, 4.0, 2.0, 0.5, 0.8, 3.0, 1.0), scale)
    l2 = mpmath.mpf(dims[1])
    for branch in (1, -1):
        for p1 in (-2.5, -0.4, 0.9, 2.2):
            pose = RSSR(*dims, branch=branch).solve(p1)

            def f(x):
                B, C, _, _ = _points_mp(dims, p1, x)
                return (mpmath.norm(C - B) ** 2 - l2**2) / l2**2

            reference = mpmath.findroot(f, mpmath.mpf(float(pose.phi03)) + mpmath.mpf("1e-4"))
            assert abs(float(_wrap(float(reference) - pose.phi03))) <= RTOL
            B, C, _, _ = _points_mp(dims, p1, reference)
            for got, want in ((pose.B, B), (pose.C, C)):
                assert max(abs(got[i] - want[i]) for i in range(3)) <= RTOL * l2


def test_solve_limit_position_rates_masked():
    """RSSR(1, 2, 1, 0, 0, 4, 0) reaches D only at phi01 = 0 (|BD| = 3 = l2 + l3): the pose
    there is exact and valid, the rocker's rates singular (NaN, `valid` False, `assembled` True)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pose = RSSR(1.0, 2.0, 1.0, 0.0, 0.0, 4.0, 0.0).solve([0.0, 0.1], order=2, strict=False)
    assert pose.assembled.tolist() == [True, False] and pose.valid.tolist() == [False, False]
    np.testing.assert_allclose(pose.C[0], [3.0, 0.0, 0.0], atol=1e-15)
    for name in ("omega_output", "vC", "alpha_output", "aC"):
        assert np.isnan(getattr(pose, name)[0]).all(), name
    assert np.isfinite(pose.vB[0]).all() and np.isfinite(pose.aB[0]).all()


def test_rssr_crank_and_rocker_too_small_for_the_coefficients():
    """(2-71) is divided by l1 l3: below 2**-500 of the largest dimension squared its
    coefficients would overflow, so the constructor names the short link instead."""
    with pytest.raises(ValueError, match=r"Expected `l1` \* `l3` >= 2\*\*-500.*got `l1` = 1e-160"):
        RSSR(1e-160, 2.0, 1.0, 0.3, 0.2, 2.0, 0.5)
    with pytest.raises(ValueError, match=r"`l3` = 1e-100"):
        RSSR(1e-100, 2.0, 1e-100, 0.3, 0.2, 2.0, 0.5)
    # just inside the bound everything is quiet, and never NaN under a True mask
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for dims in [(2.0**-498, 2.0, 1.0, 0.3, 0.2, 2.0, 0.5), (1.0, 2.0, 2.0**-498, 0.3, 0.2, 2.0, 0.5)]:
            rssr = RSSR(*dims)
            pose = rssr.solve(np.linspace(-np.pi, np.pi, 61), order=2, omega=1.5, alpha=0.5)
            rssr.assembly_range()
            assert not np.isnan(pose.C[pose.valid]).any()
            assert not np.isnan(pose.aC[pose.valid]).any()
    # a crank of 2**-498: C barely moves, and the crank turns fully
    pose = RSSR(2.0**-498, 2.0, 1.0, 0.3, 0.2, 2.0, 0.5).solve(np.linspace(-np.pi, np.pi, 61), order=2)
    assert pose.assembled.all() and pose.valid.all()


def test_assembly_range_nowhere_assembled():
    """Links that meet at most at isolated angles: an empty range, not an IndexError."""
    rng = RSSR(2.0**-249, 2.0, 2.0**-249, 0.3, 0.2, 2.0, 0.5).assembly_range()
    assert rng.intervals.shape == (0, 2) and not rng.full_turn
