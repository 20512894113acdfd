"""The RSSR through its change points: no branch jump, rates continuous, the branch rule.

The reference is independent of the package: the loop |C - B| = l2 written from the pins'
geometry and solved in mpmath, continued along the crank angle by a predictor step (the
root nearest to the linear extrapolation of the last two), started on the branch named by
the geometric sign z3 . ((C - D) x (B - C)) at the smallest non-negative crank angle where
the branches differ; rates by implicit differentiation in mpmath. Change-point RSSRs are
made by setting l2 to the largest least distance of the crank pin from the rocker circle.
"""

import mpmath
import numpy as np
import pytest

from mech.spatial import RSSR

mpmath.mp.dps = 60


class _Reference:
    """The RSSR loop in mpmath: pins from the H-D geometry of (2-69), (2-70)."""

    def __init__(self, l1, l2, l3, s0, s3, h0, lam):
        mp = mpmath.mpf
        self.l1, self.l2, self.l3, self.s0 = mp(l1), mp(l2), mp(l3), mp(s0)
        sl, cl = mpmath.sin(mp(lam)), mpmath.cos(mp(lam))
        self.D0 = [mp(h0), mp(s3) * sl, mp(s3) * cl]      # rocker pin circle centre
        self.x3, self.y3, self.z3 = [1, 0, 0], [0, cl, -sl], [0, sl, cl]

    def pins(self, phi, x):
        B = [self.l1 * mpmath.cos(phi), self.l1 * mpmath.sin(phi), self.s0]
        C = [d + self.l3 * (mpmath.cos(x) * u + mpmath.sin(x) * v) for d, u, v in zip(self.D0, self.x3, self.y3)]
        return B, C

    def roots(self, phi):
        B, _ = self.pins(phi, 0)
        P = [d - b for d, b in zip(self.D0, B)]
        al = 2 * self.l3 * sum(p * u for p, u in zip(P, self.x3))
        be = 2 * self.l3 * sum(p * v for p, v in zip(P, self.y3))
        ga = self.l2 ** 2 - self.l3 ** 2 - sum(p * p for p in P)
        if al == 0 and be == 0:                          # B on the rocker axis: any angle
            return []
        base, arg = mpmath.atan2(be, al), ga / mpmath.sqrt(al * al + be * be)
        half = mpmath.acos(max(min(arg, 1), -1))
        return [base + half, base - half]

    def side(self, phi, x):
        B, C = self.pins(phi, x)
        u = [c - d for c, d in zip(C, self.D0)]
        w = [b - c for b, c in zip(B, C)]
        cross = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
        return sum(a * b for a, b in zip(self.z3, cross))

    def rates(self, phi, x):
        """d phi03 / d phi01 and d2 phi03 / d phi01^2 by implicit differentiation."""
        l1, l3 = self.l1, self.l3
        B, C = self.pins(phi, x)
        R = [c - b for c, b in zip(C, B)]
        dB = [-l1 * mpmath.sin(phi), l1 * mpmath.cos(phi), 0]
        ddB = [-l1 * mpmath.cos(phi), -l1 * mpmath.sin(phi), 0]
        dE = [l3 * (-mpmath.sin(x) * u + mpmath.cos(x) * v) for u, v in zip(self.x3, self.y3)]
        ddE = [-l3 * (mpmath.cos(x) * u + mpmath.sin(x) * v) for u, v in zip(self.x3, self.y3)]
        dot = lambda a, b: sum(p * q for p, q in zip(a, b))
        fx, fp = dot(R, dE), -dot(R, dB)
        fxx, fpp, fpx = dot(dE, dE) + dot(R, ddE), dot(dB, dB) - dot(R, ddB), -dot(dB, dE)
        d1 = -fp / fx
        d2 = -(fpp + 2 * fpx * d1 + fxx * d1 * d1) / fx
        return d1, d2


def _float_roots(dims, phi):
    """Both rocker angles at crank angles `phi`, in floats, from the same geometry."""
    l1, l2, l3, s0, s3, h0, lam = dims
    P = np.stack([h0 - l1 * np.cos(phi), s3 * np.sin(lam) - l1 * np.sin(phi), s3 * np.cos(lam) - s0 + 0 * phi])
    al = 2 * l3 * P[0]
    be = 2 * l3 * (P[1] * np.cos(lam) - P[2] * np.sin(lam))
    ga = l2 ** 2 - l3 ** 2 - (P * P).sum(axis=0)
    with np.errstate(invalid="ignore", divide="ignore"):
        half = np.arccos(np.clip(ga / np.hypot(al, be), -1, 1))
    base = np.arctan2(be, al)
    return base + half, base - half


def _continue(dims, angles, start, x0, slope0):
    """Unwrapped reference rocker angles along sorted float `angles` (predictor steps)."""
    r1, r2 = _float_roots(dims, angles)
    out = np.empty(angles.size)
    i0 = np.searchsorted(angles, start)
    for idx in (range(i0, angles.size), range(i0 - 1, -1, -1)):
        prev_p, prev_x, slope = start, x0, slope0
        for i in idx:
            pred = prev_x + slope * (angles[i] - prev_p)
            c = np.array([r1[i], r2[i]])
            c = c + 2 * np.pi * np.round((pred - c) / (2 * np.pi))
            x = c[np.argmin(np.abs(c - pred))] if np.isfinite(c).all() else pred
            if abs(angles[i] - prev_p) > 1e-7:       # slopes from well-separated points
                slope = (x - prev_x) / (angles[i] - prev_p)
                prev_p, prev_x = angles[i], x
            out[i] = x
    return out


def _near(ref, cp, side, x_far, far):
    """mpmath reference at cp + side * 10**-k (k = 4..12) continued from x_far at `far`."""
    prev_p, prev_x = mpmath.mpf(far), mpmath.mpf(x_far)
    slope = ref.rates(prev_p, ref_root(ref, prev_p, prev_x))[0]
    prev_x = ref_root(ref, prev_p, prev_x)
    out = {}
    for k in range(4, 13):
        a = mpmath.mpf(cp) + side * mpmath.mpf(10) ** -k
        pred = prev_x + slope * (a - prev_p)
        x = ref_root(ref, a, pred)
        slope = (x - prev_x) / (a - prev_p)
        prev_p, prev_x = a, x
        out[k] = (a, x)
    return out


def ref_root(ref, a, pred):
    cands = ref.roots(a)
    cands = [r + 2 * mpmath.pi * mpmath.nint((pred - r) / (2 * mpmath.pi)) for r in cands]
    return min(cands, key=lambda r: abs(r - pred))


def _change_point_dims(seed):
    """A random RSSR with l2 at the largest least distance from B to the rocker circle."""
    rng = np.random.default_rng(seed)
    l1, l3 = rng.uniform(0.5, 1.5, 2)
    s0, s3 = rng.uniform(-0.5, 0.5, 2)
    h0, lam = rng.uniform(2.5, 3.5), rng.uniform(-1.0, 1.0)
    ref = _Reference(l1, 1.0, l3, s0, s3, h0, lam)

    def least(phi):
        B, _ = ref.pins(phi, 0)
        P = [b - d for b, d in zip(B, ref.D0)]
        w = sum(p * z for p, z in zip(P, ref.z3))
        rho = mpmath.sqrt(sum(p * p for p in P) - w * w)
        return mpmath.sqrt((rho - ref.l3) ** 2 + w * w)

    grid = [2 * mpmath.pi * k / 720 for k in range(720)]
    best = max(grid, key=least)
    lo, hi = best - 2 * mpmath.pi / 720, best + 2 * mpmath.pi / 720
    for _ in range(120):                                # golden section for the maximum
        m1, m2 = lo + (hi - lo) * 0.382, lo + (hi - lo) * 0.618
        lo, hi = (m1, hi) if least(m1) < least(m2) else (lo, m2)
    l2 = least((lo + hi) / 2)
    # the crank must turn fully: the farthest distance stays above l2 everywhere
    most = lambda phi: mpmath.sqrt(least(phi) ** 2 + 4 * ref.l3 * mpmath.sqrt(
        sum((b - d) ** 2 for b, d in zip(ref.pins(phi, 0)[0], ref.D0))
        - sum((b - d) * z for b, d, z in zip(ref.pins(phi, 0)[0], ref.D0, ref.z3)) ** 2))
    if min(most(p) for p in grid[::8]) < l2 + 0.05:
        return _change_point_dims(seed + 100)
    # the package gets l2 rounded (a change point within its rtol); the reference the exact one
    return (float(l1), float(l2), float(l3), float(s0), float(s3), float(h0), float(lam)), l2


def _check(dims, branch, n, tol_phi, tol_rate, l2_exact=None):
    rssr = RSSR(*dims, branch=branch)
    cps = rssr.change_angles()
    assert cps.size >= 1
    ref = _Reference(*dims)
    if l2_exact is not None:
        ref.l2 = l2_exact
    first = cps.min()
    start = first + 1e-6 if first < 1e-6 else 0.0      # smallest angle >= 0 where they differ
    x0 = [x for x in ref.roots(start) if np.sign(float(ref.side(start, x))) == branch][0]
    angles = np.linspace(-2 * np.pi, 2 * np.pi, n)
    want = _continue(dims, angles, start, float(x0), float(ref.rates(mpmath.mpf(start), x0)[0]))
    pose = rssr.solve(angles, order=2)
    assert pose.valid.all()
    assert np.abs(np.angle(np.exp(1j * (pose.phi03 - want)))).max() < tol_phi
    # no jump: consecutive poses of the dense sweep differ by at most the rate times the step
    step = np.abs(np.angle(np.exp(1j * np.diff(pose.phi03))))
    assert step.max() < 1.01 * np.abs(pose.omega_output).max() * np.diff(angles).max()
    assert np.abs(np.diff(pose.omega_output)).max() < 1.01 * np.abs(pose.alpha_output).max() * np.diff(angles).max()
    # pairs at +-1e-9 and +-1e-12 around each change point, against mpmath continued there
    for cp in np.concatenate([cps, cps - 2 * np.pi]):
        for side in (1, -1):
            far = cp + side * 1e-3
            x_far = _continue(dims, np.sort(np.append(angles, far)), start, float(x0),
                              float(ref.rates(mpmath.mpf(start), x0)[0]))[np.searchsorted(np.sort(np.append(angles, far)), far)]
            for k, (a, x) in _near(ref, cp, side, x_far, far).items():
                if k not in (9, 12):
                    continue
                got = rssr.solve(float(a), order=2)
                d1, d2 = ref.rates(a, x)
                assert abs(np.angle(np.exp(1j * (float(got.phi03) - float(x))))) < tol_phi
                assert abs(float(got.omega_output) - float(d1)) < tol_rate
                assert abs(float(got.alpha_output) - float(d2)) < tol_rate
        at = rssr.solve(cp, order=2)                   # on the change point: the limit
        assert at.valid and np.isfinite(at.alpha_output)


@pytest.mark.slow
@pytest.mark.parametrize("branch", [1, -1])
def test_solve_change_point_kite_dense_sweep(branch):
    """RSSR(1, 2, 2, 0, 0, 1, 0), the planar kite: B passes through the rocker axis at 0."""
    _check((1.0, 2.0, 2.0, 0.0, 0.0, 1.0, 0.0), branch, 100_000, 1e-12, 1e-9)


@pytest.mark.slow
@pytest.mark.parametrize("seed", [1, 2, 3, 4])
@pytest.mark.parametrize("branch", [1, -1])
def test_solve_change_point_random_spatial(seed, branch):
    """Random spatial RSSRs at a change point: continuous through it, rates finite there."""
    dims, l2 = _change_point_dims(seed)
    _check(dims, branch, 20_000, 1e-9, 1e-6, l2)


def test_solve_change_point_no_jump_kite():
    """The audit's repro: omega went 0.25 -> 0.75 across theta = 0, phi03 jumped by pi."""
    pose = RSSR(1, 2, 2, 0, 0, 1, 0).solve([-1e-9, 0.0, 1e-9], order=2)
    assert np.ptp(pose.phi03) < 2e-9
    np.testing.assert_allclose(pose.omega_output, 0.75, atol=1e-9)
    assert pose.valid.all()


@pytest.mark.parametrize("dims", [(1, 2, 2, 1), (2, 3, 2, 3), (1, 1, 1, 1), (1, 3, 2, 2), (3, 2, 3, 2)])
@pytest.mark.parametrize("branch", [1, -1])
def test_solve_change_point_planar_limit_is_fourbar(dims, branch):
    """With lam = 0 and no offsets the RSSR is the planar four-bar (a, b, c, d) =
    (l1, l2, l3, h0): the same branch, through the change points, as `FourBar`."""
    from mech.planar import FourBar
    a, b, c, d = dims
    theta = np.concatenate([np.linspace(-7, 7, 2001), [0, 1e-12, -1e-12, np.pi, np.pi + 1e-12, np.pi - 1e-12]])
    want = FourBar(a, b, c, d, branch=branch).solve(theta, order=2)
    got = RSSR(a, b, c, 0, 0, d, 0, branch=branch).solve(theta, order=2)
    assert np.abs(np.angle(np.exp(1j * (got.phi03 - want.psi)))).max() < 1e-12
    np.testing.assert_allclose(got.omega_output, want.omega_output, atol=1e-12)
    np.testing.assert_allclose(got.alpha_output, want.alpha_output, atol=1e-12)


def test_change_angles_and_rtol():
    assert RSSR(1, 2, 2, 0, 0, 1, 0).change_angles().tolist() == [0.0]
    np.testing.assert_allclose(RSSR(1, 1, 1, 0, 0, 1, 0).change_angles(), [0.0, np.pi])
    assert not RSSR(1.0, 4.0, 2.0, 0.5, 0.8, 3.0, 1.0).change_point
    assert RSSR(1, 2, 2, 0, 0, 1 + 1e-14, 0).change_point
    assert not RSSR(1, 2, 2, 0, 0, 1 + 1e-14, 0, rtol=0.0).change_point
