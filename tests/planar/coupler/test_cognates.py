"""Roberts-Chebyshev cognates (Fig. 2-32): ``mech.planar.coupler._cognates``.

Expected values come from an independent route: each cognate is rebuilt from the
package's dimensions and placement, driven by ITS OWN crank over a full turn on both of
its branches, and solved by circle intersection with mpmath at 50 digits; every point it
traces must lie on the original's coupler curve, also solved with mpmath.
"""

import cmath

import mpmath
import numpy as np
import pytest

from mech.planar import FourBar, grashof
from mech.planar.coupler._cognates import Cognate, Cognates, cognates

RNG_SEED = 20240603


def _random_fourbar(rng, want_grashof):
    """A random four-bar of the requested Grashof type with a random coupler point."""
    while True:
        a, b, c, d = rng.uniform(0.3, 3.0, 4)
        if max(a, b, c, d) > 0.97 * (a + b + c + d) / 2:         # far from unassemblable
            continue
        if grashof(a, b, c, d).grashof != want_grashof:
            continue
        s, l = min(a, b, c, d), max(a, b, c, d)
        if abs(s + l - (a + b + c + d - s - l)) < 0.05 * l:      # keep away from change points
            continue
        p, q = rng.uniform(-1.5, 1.5, 2) * b
        branch = int(rng.choice([1, -1]))
        return FourBar(a, b, c, d, branch=branch, coupler=(p, q))


def _cases():
    rng = np.random.default_rng(RNG_SEED)
    out = [FourBar(1, 2, 2.5, 3, coupler=(1.2, 0.7)),            # crank-rocker
           FourBar(3, 2, 2.5, 1, coupler=(0.4, -0.9), branch=-1),  # double-crank
           FourBar(2, 1, 2.5, 3, coupler=(1.5, 1.0))]              # double-rocker
    out += [_random_fourbar(rng, True) for _ in range(6)]
    out += [_random_fourbar(rng, False) for _ in range(6)]
    return out


CASES = _cases()


def _size(fb):
    return fb.a + fb.b + fb.c + fb.d + abs(complex(*fb.coupler))


def _circle_point50(a, b, c, d, theta, branch):
    """Crank pin, rocker pin of a four-bar in its frame at 50 digits, or None."""
    B = a * mpmath.expj(theta)
    k = abs(d - B)
    x = (b**2 + k**2 - c**2) / (2 * k)
    if x**2 > b**2:
        return None
    return B, B + (d - B) / k * (x + 1j * branch * mpmath.sqrt(b**2 - x**2))


def _original_points50(fb, theta):
    """Coupler points of both branches of the original at crank angle theta (50 digits)."""
    w = mpmath.mpc(*fb.coupler)
    out = []
    for branch in (1, -1):
        pose = _circle_point50(*(mpmath.mpf(x) for x in (fb.a, fb.b, fb.c, fb.d)), theta, branch)
        if pose is not None:
            B, C = pose
            out.append((branch, B + w * (C - B) / abs(C - B)))
    return out


@pytest.mark.parametrize("fb", CASES[:3] + CASES[3:15:3], ids=repr)
def test_cognates_own_crank_sweep_traces_original_curve_mpmath(fb):
    """Each cognate, driven by its own crank on both branches, stays on the original curve."""
    trio = cognates(fb)
    size = _size(fb)
    lam = mpmath.mpc(trio.ratio.real, trio.ratio.imag)
    hits = 0
    with mpmath.workdps(50):
        for cog, theta_of in (
            # the original crank angle from a cognate pose (derivation page, angle table)
            (trio.aegk, lambda Bo, Co, d: mpmath.arg(Co - Bo)),           # its coupler angle
            (trio.dfhk, lambda Bo, Co, d: mpmath.arg(Co - d) - mpmath.pi),  # its rocker angle - pi
        ):
            a, b, c, d = (mpmath.mpf(x) for x in cog.lengths)
            w = mpmath.mpc(*cog.coupler)
            rot = mpmath.mpc(cog.rotation.real, cog.rotation.imag)
            origin = mpmath.mpc(cog.origin.real, cog.origin.imag)
            for own_branch in (1, -1):
                for t in np.linspace(0, 2 * np.pi, 37)[:-1]:
                    pose = _circle_point50(a, b, c, d, mpmath.mpf(t), own_branch)
                    if pose is None:
                        continue
                    Bo, Co = pose
                    M = origin + rot * (Bo + w * (Co - Bo) / b)
                    refs = _original_points50(fb, theta_of(Bo, Co, d))
                    gap = min(abs(M - Mr) for _, Mr in refs)
                    assert gap < 1e-13 * size, (cog.name, t, own_branch)   # dims rounded to doubles
                    hits += 1
    assert hits >= 36                         # every cognate sweep found assembled poses
    assert abs(trio.K - complex(lam * fb.d)) < 1e-14 * size


@pytest.mark.parametrize("fb", CASES, ids=repr)
def test_path_coincides_with_mpmath_original(fb):
    """path(theta): all three coupler points equal the original's (mpmath) to 1e-12 * size."""
    trio = cognates(fb)
    theta = np.linspace(0, 2 * np.pi, 181)
    M = trio.path(theta)
    assert M.shape == (3, 181)
    size = _size(fb)
    valid = np.isfinite(M[0])
    assert valid.sum() > 10
    assert np.array_equal(valid, np.isfinite(M[1])) and np.array_equal(valid, np.isfinite(M[2]))
    with mpmath.workdps(50):
        for i in np.flatnonzero(valid)[::3]:
            ref = dict(_original_points50(fb, mpmath.mpf(theta[i])))[fb.branch]
            assert np.abs(M[:, i] - complex(ref)).max() < 1e-12 * size


def test_path_coincide_over_full_turn_many_random():
    """Spread of the three curves over a full turn, 40 random linkages of both kinds."""
    rng = np.random.default_rng(RNG_SEED + 1)
    theta = np.linspace(0, 2 * np.pi, 721)
    worst = 0.0
    for k in range(40):
        fb = _random_fourbar(rng, k % 2 == 0)
        M = cognates(fb).path(theta)
        ok = np.isfinite(M[0])
        worst = max(worst, np.abs(M[1:, ok] - M[0, ok]).max() / _size(fb))
    assert worst < 1e-13


@pytest.mark.parametrize("fb", CASES, ids=repr)
def test_joints_K_fixed_and_triangles_similar(fb):
    trio = cognates(fb)
    j = trio.joints(np.linspace(0, 2 * np.pi, 361))
    A, B, C, D, E, F, G, H = (getattr(j, n)[j.valid] for n in "ABCDEFGH")
    M = j.M[0][j.valid]
    size = _size(fb)
    # K from the textbook's last step, the parallelogram GMHK, at every pose
    assert np.abs(G + H - M - trio.K).max() < 1e-12 * size
    # triangle ADK ~ BCM (same orientation): equal complex ratios
    assert abs(trio.K / fb.d - trio.ratio) < 1e-15 * size
    assert np.abs((M - B) / (C - B) - trio.ratio).max() < 1e-12 * size
    # triangles GEM ~ MBC ~ HMF
    assert np.abs((G - E) / (M - E) - trio.ratio).max() < 1e-11 * size
    assert np.abs((H - M) / (F - M) - trio.ratio).max() < 1e-11 * size
    # parallelograms ABME, DCMF
    assert np.abs(E - A - (M - B)).max() < 1e-12 * size
    assert np.abs(F - D - (M - C)).max() < 1e-12 * size


@pytest.mark.parametrize("fb", CASES[:6], ids=repr)
def test_joints_link_lengths_constant(fb):
    trio = cognates(fb)
    j = trio.joints(np.linspace(0, 2 * np.pi, 361))
    ok = j.valid
    size = _size(fb)
    for cog, (P0, P1, P2, P3) in ((trio.aegk, (j.A, j.E, j.G, j.K)), (trio.dfhk, (j.D, j.F, j.H, j.K))):
        a, b, c, d = cog.lengths
        for got, want in ((P1 - P0, a), (P2 - P1, b), (P2 - P3, c), (P3 - P0, d)):
            assert np.abs(np.abs(got[ok]) - want).max() < 1e-12 * size
        assert np.allclose(cog.pivots, (P0[ok][0], P3[ok][0]), rtol=0, atol=1e-12 * size)


def test_cognates_lengths_are_scaled_permutations():
    fb = FourBar(1, 2, 2.5, 3, coupler=(1.2, 0.7))
    trio = cognates(fb)
    lam = complex(1.2, 0.7) / 2
    assert np.allclose(trio.aegk.lengths, abs(lam) * np.array([2, 1, 2.5, 3]), rtol=1e-15)
    assert np.allclose(trio.dfhk.lengths, abs(lam - 1) * np.array([2, 2.5, 1, 3]), rtol=1e-15)
    assert grashof(*trio.aegk.lengths).kind == "double-rocker"
    assert grashof(*trio.dfhk.lengths).kind == "rocker-crank"
    assert [c.name for c in trio] == ["ABCD", "AEGK", "DFHK"]
    assert [c.driver for c in trio] == ["crank", "coupler", "rocker"]


@pytest.mark.parametrize("fb", CASES[:6], ids=repr)
def test_cognate_solve_own_crank_angle_is_original_phi(fb):
    """A cognate's own crank angle is the original coupler angle phi (both cognates)."""
    trio = cognates(fb)
    theta = np.linspace(0, 2 * np.pi, 241)
    pose = fb.solve(theta)
    ok = pose.valid
    M = trio.path(theta)
    branches = trio.branches(theta)
    size = _size(fb)
    for i, cog in ((1, trio.aegk), (2, trio.dfhk)):
        phi = np.where(ok, pose.phi, 0.0)
        up, down = cog.solve(phi, branch=1), cog.solve(phi, branch=-1)
        P = np.where(branches[i] > 0, up.P, down.P)
        # accuracy of a solve near the cognate's own limit positions is sqrt(eps / delta)
        assert np.abs(P - M[0])[ok].max() < 1e-9 * size
        assert np.median(np.abs(P - M[0])[ok]) < 1e-14 * size


def test_cognates_driver_links_turn_with_original():
    """AE and DF turn with BC; EG and KH turn with AB; KG with DC (constant angle offsets)."""
    fb = FourBar(1, 2, 2.5, 3, coupler=(1.2, 0.7))
    trio = cognates(fb)
    j = trio.joints(np.linspace(0, 2 * np.pi, 73))
    lam = trio.ratio
    def offset(z1, z2):
        return np.angle(z1 / z2)
    for moving, reference, want in (
        (j.E - j.A, j.C - j.B, cmath.phase(lam)),
        (j.F - j.D, j.C - j.B, cmath.phase(lam - 1)),
        (j.G - j.E, j.B - j.A, cmath.phase(lam)),
        (j.H - j.K, j.B - j.A, cmath.phase(1 - lam)),
        (j.G - j.K, j.C - j.D, cmath.phase(lam)),
        (j.H - j.F, j.C - j.D, cmath.phase(1 - lam)),
    ):
        assert np.abs(np.angle(np.exp(1j * (offset(moving, reference) - want)))).max() < 1e-13


def test_branches_double_crank_constant():
    fb = FourBar(3, 2, 2.5, 1, coupler=(0.4, -0.9), branch=-1)
    trio = cognates(fb)
    br = trio.branches(np.linspace(0, 2 * np.pi, 721))
    for row, cog in zip(br, trio):
        assert set(row.tolist()) == {cog.fourbar.branch}
    assert all(grashof(*c.lengths).kind == "double-crank" for c in trio)


def test_branches_crank_rocker_cognates_switch():
    """Crank-rocker original: its cognates' cranks swing, so their own branch flips."""
    fb = FourBar(1, 2, 2.5, 3, coupler=(1.2, 0.7))
    br = cognates(fb).branches(np.linspace(0, 2 * np.pi, 721))
    assert set(br[0].tolist()) == {1}
    assert set(br[1].tolist()) == {1, -1} and set(br[2].tolist()) == {1, -1}


def test_branches_double_rocker_constant_on_each_circuit():
    """Double-rocker original (coupler shortest): crank-rocker cognates, one branch per circuit."""
    fb = FourBar(2, 1, 2.5, 3, coupler=(1.5, 1.0))
    trio = cognates(fb)
    theta = np.linspace(0, 2 * np.pi, 1441)
    br = trio.branches(theta)
    valid = br[0] != 0
    edges = np.flatnonzero(np.diff(valid.astype(int)))
    pieces = np.split(np.arange(theta.size), edges + 1)
    runs = [p for p in pieces if valid[p[0]]]
    assert len(runs) >= 2
    for run in runs:
        assert len(set(br[1, run].tolist())) == 1 and len(set(br[2, run].tolist())) == 1


def test_cognates_errors():
    with pytest.raises(TypeError, match="Expected `fourbar` to be a FourBar"):
        cognates((1, 2, 3, 4))
    with pytest.raises(ValueError, match=r"Expected `\|MB\|` > 0"):
        cognates(FourBar(1, 2, 2.5, 3, coupler=(0, 0)))
    with pytest.raises(ValueError, match=r"Expected `\|MC\|` > 0"):
        cognates(FourBar(1, 2, 2.5, 3, coupler=(2, 0)))
    trio = cognates(FourBar(1, 2, 2.5, 3, coupler=(1, 1)))
    with pytest.raises(ValueError, match="Expected finite `theta`"):
        trio.path([0.0, np.nan])
    with pytest.raises(ValueError, match="Expected `branch` to be"):
        trio.aegk.solve(0.0, branch=0)
    with pytest.raises(AttributeError, match="immutable"):
        trio.K = 0
    with pytest.raises(AttributeError, match="immutable"):
        trio.aegk.origin = 1


def test_cognate_solve_strict_raises():
    from mech import AssemblyError

    trio = cognates(FourBar(1, 2, 2.5, 3, coupler=(1.2, 0.7)))       # AEGK is a double-rocker
    with pytest.raises(AssemblyError, match="AEGK"):
        trio.aegk.solve(np.linspace(0, 2 * np.pi, 73), strict=True)


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_path_broadcast_shapes(shape):
    trio = cognates(FourBar(1, 2, 2.5, 3, coupler=(1, 1)))
    theta = np.random.default_rng(0).uniform(0, 6, shape)
    assert trio.path(theta).shape == (3,) + shape
    assert trio.branches(theta).shape == (3,) + shape
    assert trio.aegk.solve(theta).P.shape == shape


def test_cognates_types():
    trio = cognates(FourBar(1, 2, 2.5, 3, coupler=(1, 1)))
    assert isinstance(trio, Cognates) and all(isinstance(c, Cognate) for c in trio)
    assert trio.abcd.fourbar.coupler == (1.0, 1.0)
    assert trio.K == pytest.approx(1.5 + 1.5j, abs=1e-15)


@pytest.mark.parametrize("fb", CASES[::2], ids=repr)
def test_cognates_dimensions_match_construction_mpmath(fb):
    """Lengths, placement and coupler offsets against Fig. 2-32 built point by point at 50 digits."""
    trio = cognates(fb)
    with mpmath.workdps(50):
        a, b, c, d = (mpmath.mpf(x) for x in (fb.a, fb.b, fb.c, fb.d))
        w = mpmath.mpc(*fb.coupler)
        for t in np.linspace(0, 2 * np.pi, 25)[:-1]:
            pose = _circle_point50(a, b, c, d, mpmath.mpf(t), fb.branch)
            if pose is not None:
                break
        B, C = pose
        A, D = mpmath.mpc(0), mpmath.mpc(d)
        M = B + w * (C - B) / b
        lam = (M - B) / (C - B)
        E, F = A + M - B, D + M - C
        G, H = E + lam * (M - E), M + lam * (F - M)
        K = G + H - M
        for cog, (P0, P1, P2, P3) in ((trio.aegk, (A, E, G, K)), (trio.dfhk, (D, F, H, K))):
            want = [abs(P1 - P0), abs(P2 - P1), abs(P2 - P3), abs(P3 - P0)]
            assert np.allclose(cog.lengths, [float(x) for x in want], rtol=1e-14, atol=0)
            rot = (P3 - P0) / abs(P3 - P0)
            assert abs(cog.rotation - complex(rot)) < 1e-14
            assert abs(cog.origin - complex(P0)) < 1e-14 * float(d)
            offset = (M - P1) / ((P2 - P1) / abs(P2 - P1))       # (p' + i q') in its own frame
            assert abs(complex(*cog.coupler) - complex(offset)) < 1e-14 * _size(fb)
        assert abs(trio.K - complex(K)) < 1e-14 * _size(fb)


@pytest.mark.parametrize("fb", CASES, ids=repr)
def test_branches_cognates_always_opposite(fb):
    """S2 = -(|mu| / |lam|)**2 S1 (derivation page): the cognates' own branches differ."""
    br = cognates(fb).branches(np.linspace(0, 2 * np.pi, 361))
    ok = br[0] != 0
    assert np.array_equal(br[1][ok], -br[2][ok])
    assert np.all(br[0][ok] == fb.branch)


@pytest.mark.parametrize("dims", [(1, 2, 1, 2), (2, 1, 2, 1), (1, 3, 2, 2), (1, 2, 3, 2)])
@pytest.mark.parametrize("branch", [1, -1])
def test_path_change_point_linkages(dims, branch):
    """Change-point originals (s + l = p + q): the three curves still coincide everywhere."""
    fb = FourBar(*dims, coupler=(0.7, 0.4), branch=branch)
    M = cognates(fb).path(np.linspace(0, 2 * np.pi, 721))
    assert np.all(np.isfinite(M))
    assert np.abs(M[1:] - M[0]).max() < 1e-13 * _size(fb)
