"""Rigid-body guidance on the sphere (monograph chapter 3): displacements, poles, cranks and
sliders, the Burmester cubics and points, and the four-bars checked by analysis.

Independent routes: the five-orientation solution of `guidance_reference` (an exact
rational resultant of two circle-point cubics in SymPy, roots and Newton polishing in mpmath
at 50 digits, all six solutions); numpy's eigenvectors for poles; mpmath for the residuals;
and the planar guidance functions of `mech.planar.synthesis` for the limit of small arcs.
"""


import mpmath
import numpy as np
import pytest

import mech.planar.synthesis as pl
from mech.spherical import (SphericalFourBar, burmester, circle_point_curve, crank_residual, dyad_for_centre_point,
                            dyad_for_circle_point, guidance_fourbars, guidance_slider_crank, planar_orientations,
                            pole_triangle, relative_rotation, rotation_matrix, rotation_pole, slider_dyad_for_point,
                            slider_point_curve, slider_residual)

from tests.spherical.guidance_reference import burmester_mp

# example 2-15 of the planar chapter (five poses), used for the planar limit
P15 = np.array([13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j, 66.27 + 215.07j])
T15 = np.radians([0.0, 8.88, 22.1, 63.68, -3.0])


def _random_set(rng, n, spread=1.2):
    return np.stack([rotation_matrix(rng.normal(size=3), rng.uniform(0.1, spread)) for _ in range(n)])


def _gnomonic(v, scale):
    v = np.asarray(v)
    return (v[..., 0] + 1j * v[..., 1]) / (v[..., 2] * scale)


# ------------------------------------------------------------------ displacements and poles
def test_relative_rotation_product_and_excess():
    rng = np.random.default_rng(0)
    R = _random_set(rng, 4)
    D, K = relative_rotation(R[0], R[1:])
    assert np.allclose(D @ R[0], R[1:], atol=1e-15)
    assert np.allclose(K, np.einsum("nij,kj->nik", R[1:], R[0]) - np.eye(3), atol=1e-15)


@pytest.mark.parametrize("angle", [1e-12, 1e-6, 0.3, 2.0, np.pi - 1e-3, np.pi - 1e-9])
def test_rotation_pole_axis_and_angle(angle):
    axis = np.array([0.3, -0.5, 0.81])
    axis /= np.linalg.norm(axis)
    R1 = rotation_matrix([1, 2, 3], 0.7)
    R2 = rotation_matrix(axis, angle) @ R1
    k, phi = rotation_pole(R1, R2)
    # independent: numpy's eigenvector of eigenvalue 1 of R2 R1^T
    vals, vecs = np.linalg.eig(R2 @ R1.T)
    e = np.real(vecs[:, np.argmin(np.abs(vals - 1))])
    e *= np.sign(e @ axis)
    assert abs(phi - angle) <= 1e-15 * 8 + 1e-15 * angle
    assert np.max(np.abs(k - axis)) <= 4e-16 / min(np.sin(angle), 1.0) + 1e-12 * (angle > 3.14) + 1e-14
    if 1e-3 < angle:
        assert np.max(np.abs(k - e)) < 1e-9


def test_pole_triangle_fixed_points():
    rng = np.random.default_rng(1)
    R = _random_set(rng, 3)
    P = pole_triangle(R)
    for (i, j), p in zip([(0, 1), (0, 2), (1, 2)], P):
        D = R[j] @ R[i].T
        assert np.max(np.abs(D @ p - p)) < 1e-14


def test_rotation_pole_equal_orientations():
    with pytest.raises(ValueError, match="`R_1` and `R_j`"):
        rotation_pole(np.eye(3), np.eye(3))


def test_crank_and_slider_residual_mpmath():
    rng = np.random.default_rng(2)
    R1, Rj = _random_set(rng, 2)
    u, z = rng.normal(size=3), rng.normal(size=3)
    u, z = u / np.linalg.norm(u), z / np.linalg.norm(z)
    with mpmath.workdps(50):
        M1 = mpmath.matrix(R1.tolist())
        Mj = mpmath.matrix(Rj.tolist())
        mu, mz = mpmath.matrix(u.tolist()), mpmath.matrix(z.tolist())
        ref = float((mu.T * Mj * mz)[0] - (mu.T * M1 * mz)[0])
        ref_s = float((mu.T * Mj * mz)[0])
    assert abs(float(crank_residual(R1, Rj, z, u)) - ref) < 1e-15
    assert abs(float(slider_residual(Rj, z, u)) - ref_s) < 1e-15


# ------------------------------------------------------------------ two and three positions
def test_dyad_two_positions_bisector():
    rng = np.random.default_rng(3)
    R = _random_set(rng, 2)
    z = np.array([0.2, 0.3, 0.93])
    for along in (-1.0, 0.0, 0.7):
        k = dyad_for_circle_point(R, z, along=along)
        arcs = [np.arccos(np.clip(Rj @ k.circle_point @ k.centre_point, -1, 1)) for Rj in R]
        assert abs(arcs[0] - arcs[1]) < 1e-12 and abs(arcs[0] - k.arc) < 1e-12
    k = dyad_for_centre_point(R, [0.1, 0.0, 1.0], along=0.4)
    assert abs(float(crank_residual(R[0], R[1], k.circle_point, k.centre_point))) < 1e-15


@pytest.mark.parametrize("shape", [(3,), (7, 3), (2, 4, 3)])
def test_dyad_three_positions_broadcast(shape):
    rng = np.random.default_rng(4)
    R = _random_set(rng, 3)
    z = rng.normal(size=shape)
    k = dyad_for_circle_point(R, z)
    assert k.centre_point.shape == shape and np.shape(k.arc) == shape[:-1]
    for Rj in R[1:]:
        assert np.max(np.abs(crank_residual(R[0], Rj, k.circle_point, k.centre_point))) < 1e-14
    back = dyad_for_centre_point(R, k.centre_point)
    assert np.allclose(back.circle_point, k.circle_point, atol=1e-10)


def test_three_positions_crank_slider():
    """§3.3: slider points of three orientations (7) and the crank-slider they make."""
    rng = np.random.default_rng(5)
    R = _random_set(rng, 3, spread=0.8)
    curve = slider_point_curve(R, samples=90)
    w = curve.moving_pivot[curve.valid]
    dets = [np.linalg.det(np.stack([wi, (R[1] @ R[0].T) @ wi, (R[2] @ R[0].T) @ wi])) for wi in w]
    assert np.max(np.abs(dets)) < 1e-13
    assert np.allclose(curve.arc[curve.valid], np.pi / 2, atol=1e-12)
    crank = dyad_for_circle_point(R, R[0].T @ np.array([0.1, 0.2, 0.97]))
    passing = 0
    for i, k in np.argwhere(curve.valid)[::5]:
        slider = curve.dyad(i, k)
        again = slider_dyad_for_point(R, slider.circle_point, rtol=1e-12)
        assert np.allclose(abs(again.centre_point @ slider.centre_point), 1.0, atol=1e-12)
        design = guidance_slider_crank(R, crank, slider)
        if design is None:
            continue
        if design.in_order:
            assert design.pose_error < 1e-9
            passing += design.passes
    assert passing > 0


# ------------------------------------------------------------------ four positions: the cubics
def test_circle_point_curve_four_equal_arcs():
    rng = np.random.default_rng(6)
    R = _random_set(rng, 4)
    curve = circle_point_curve(R, samples=120)
    assert curve.valid.sum() > 60
    z, u = curve.circle_point[curve.valid], curve.centre_point[curve.valid]
    cosines = np.einsum("nij,mj,mi->mn", R, z, u)
    assert np.max(np.ptp(cosines, axis=1)) < 1e-12


def _planar_cubic_error(scale):
    """Largest relative planar error of the spherical cubics of example 2-15 (poses 1-4)."""
    R = planar_orientations(T15[:4], P15[:4], scale)
    curve = circle_point_curve(R, samples=180)
    ok = curve.valid & (curve.moving_pivot[..., 2] > 0.5)
    zb = _gnomonic(curve.circle_point[ok], scale)
    A = _gnomonic(curve.centre_point[ok], scale)
    keep = (np.abs(zb) < 300) & (np.abs(A) < 300)
    zb, A = zb[keep], A[keep]
    # the planar crank of poses 1-3 through the projected circle point: its centre, and pose 4
    planar = pl.dyad_for_circle_point(T15[:3], P15[:3], zb)
    Z4 = np.exp(1j * T15[3]) * zb + P15[3]
    off_curve = np.abs(np.abs(Z4 - planar.centre_point) - planar.length) / planar.length
    centre = np.abs(A - planar.centre_point) / planar.length
    return float(max(np.max(off_curve), np.max(centre))), int(keep.sum())


def test_circle_point_curve_planar_limit():
    """The four-position cubics tend to the planar ones (as `mech.planar` computes them)."""
    errors = {s: _planar_cubic_error(s) for s in (1e-2, 1e-3, 1e-4, 1e-5, 1e-6)}
    assert all(n > 60 for _, n in errors.values() if _ < 1)
    e = {s: v for s, (v, _) in errors.items()}
    # measured: 1.3e-2, 1.3e-4, 1.3e-6, 2.0e-8 at 1e-3 .. 1e-6 (about 1.3e4 scale^2 for
    # points within 300 of the origin, i.e. (scale * size)^2)
    assert e[1e-4] < 3e-4 and e[1e-5] < 3e-6 and e[1e-6] < 1e-7
    assert e[1e-3] / e[1e-4] > 50 and e[1e-4] / e[1e-5] > 50      # rate 2: an error ~ scale^2


# ------------------------------------------------------------------ five positions
@pytest.mark.parametrize("seed", [3, 11, 25, 27, 45, 55, 60, 61])
def test_burmester_matches_mpmath(seed):
    """Every real solution, matching the exact-resultant 50-digit solution of all six to 1e-9."""
    rng = np.random.default_rng(seed)
    R = _random_set(rng, 5)
    _compare_with_mpmath(R, seed)


def _compare_with_mpmath(R, seed):
    found = burmester(R)
    real, n = burmester_mp(R, seed=seed)
    assert n == 6
    assert len(found.dyads) == len(real) and len(found.dyads) + found.n_complex == 6
    for k in found.dyads:
        gap = min(max(np.max(np.abs(s * k.moving_pivot - rw)), np.max(np.abs(s * k.centre_point - ru)))
                  for ru, rw in real for s in (1, -1))
        assert gap < 1e-9
    assert found.residual < 1e-13
    return found


def test_burmester_six_real_solutions():
    """A set with six real Burmester pairs (more than the planar four)."""
    found = _compare_with_mpmath(_six_real(), 3)
    assert len(found.dyads) == 6


def _six_real():
    rng = np.random.default_rng(0)
    for _ in range(400):
        R = _random_set(rng, 5, spread=2.5)
        if len(burmester(R).dyads) == 6:
            return R
    pytest.fail("no set with six real solutions found")


def test_burmester_planar_limit():
    """Four spherical Burmester points tend to the planar ones of example 2-15; rate about 2."""
    planar = pl.burmester(T15, P15).dyads
    errors = {}
    for scale in (1e-2, 1e-3, 1e-4, 1e-5, 1e-6):
        found = burmester(planar_orientations(T15, P15, scale))
        worst = 0.0
        for k in planar:
            gaps = [max(abs(_gnomonic(s.centre_point, scale) - k.centre_point),
                        abs(_gnomonic(s.moving_pivot, scale) - k.moving_pivot)) / k.length for s in found.dyads]
            worst = max(worst, min(gaps) if gaps else np.inf)
        errors[scale] = worst
    # measured: 6.9e-1, 5.2e-3, 5.2e-5, 5.0e-7 at 1e-3 .. 1e-6 (the far dyad of length 1503
    # is the worst); rate 2 down to 1e-5, then rounding (eps / scale^2 in the sextic) shows
    assert errors[1e-4] < 1e-2 and errors[1e-5] < 1e-4 and errors[1e-6] < 2e-6
    assert errors[1e-4] / errors[1e-5] > 50


@pytest.mark.parametrize("seed", [3, 11, 29, 41])
def test_guidance_fourbars_reach_every_orientation(seed):
    """Every candidate on one branch reaches its orientations to 1e-9 by analysis."""
    rng = np.random.default_rng(seed)
    R = _random_set(rng, 5)
    result = guidance_fourbars(R)
    for c in result.candidates:
        B = np.einsum("nij,j->ni", R, c.input_dyad.circle_point)
        C = np.einsum("nij,j->ni", R, c.output_dyad.circle_point)
        side = np.sign(np.sum(B * np.cross(c.output_dyad.centre_point, C), axis=-1))
        if np.all(side == side[0]):
            assert c.pose_error < 1e-9
            # independent re-check: solve the linkage and compare the body axes directly
            pose = c.linkage.solve(c.theta_input)
            assert np.max(np.abs(pose.B - B)) < 1e-9 and np.max(np.abs(pose.C - C)) < 1e-9
            orient = c.coupler_orientations(c.theta_input)
            assert np.max(np.abs(orient - R)) < 1e-9
        else:
            assert not c.passes                              # a branch defect
        assert 0.0 <= c.gamma_min <= np.pi / 2
    for c in result.passing:
        # in order: the input turns one way and meets the orientations in the given order
        steps = np.remainder(c.direction * np.diff(c.theta_input), 2 * np.pi)
        assert np.sum(steps) < 2 * np.pi
        sweep = c.theta_input[0] + c.direction * np.linspace(0, np.sum(steps), 400)
        assert np.all(c.linkage.solve(sweep).valid)


def test_guidance_fourbars_planar_example_on_sphere():
    """Example 2-15 on a sphere of radius 1000 (scale 1e-3): a crank-rocker close to the planar one."""
    R = planar_orientations(T15, P15, 1e-3)
    result = guidance_fourbars(R)
    planar = pl.guidance_fourbars(T15, P15).passing[0]
    best = min(result.passing, key=lambda c: abs(c.linkage.a - planar.linkage.a * 1e-3))
    assert best.kind == planar.kind == "crank-rocker"
    arcs = np.array([best.linkage.a, best.linkage.b, best.linkage.c, best.linkage.d]) / 1e-3
    lengths = np.array([planar.linkage.a, planar.linkage.b, planar.linkage.c, planar.linkage.d])
    assert np.max(np.abs(arcs - lengths) / lengths) < 0.02


def test_bad_orientations():
    with pytest.raises(ValueError, match="`R`"):
        burmester(np.stack([np.eye(3)] * 4))
    with pytest.raises(ValueError, match="proper rotations"):
        circle_point_curve(np.stack([np.eye(3), np.eye(3), np.eye(3), -np.eye(3)]))
    with pytest.raises(ValueError, match="`slider_point`"):
        rng = np.random.default_rng(8)
        slider_dyad_for_point(_random_set(rng, 3), [0.3, 0.4, 0.8])
    with pytest.raises(ValueError, match="`dyads`"):
        guidance_fourbars(_random_set(np.random.default_rng(8), 3), dyads=[])
    with pytest.raises(ValueError, match="orientations 1 and 2 .*`R`|`R`.* 1 and 2"):
        guidance_fourbars(np.stack([np.eye(3)] * 3), dyads=[])


@pytest.mark.parametrize("seed", [1, 2, 3, 5])
def test_slider_dyads_four_positions_match_resultant(seed):
    """§3.5: the slider points of four orientations, every real one, against the exact route."""
    from tests.spherical.guidance_reference import slider_points_mp
    from mech.spherical import slider_dyads

    rng = np.random.default_rng(seed)
    R = _random_set(rng, 4, spread=1.5)
    found = slider_dyads(R)
    real, n = slider_points_mp(R, seed)
    assert n == 6 and len(found) == len(real)
    for k in found:
        assert min(np.max(np.abs(s * k.moving_pivot - r)) for r in real for s in (1, -1)) < 1e-9
        assert abs(float(k.arc) - np.pi / 2) < 1e-12
        dets = [slider_residual(Rj, k.circle_point, k.centre_point) for Rj in R]
        assert np.max(np.abs(dets)) < 1e-14


def test_crank_slider_four_positions_by_analysis():
    """§3.5: a crank from the circle-point curve and a slider of four orientations make a
    crank-slider that reaches every orientation (checked by SphericalFourBar)."""
    from mech.spherical import slider_dyads

    rng = np.random.default_rng(2)
    R = _random_set(rng, 4, spread=1.5)
    sliders = slider_dyads(R)
    assert sliders
    curve = circle_point_curve(R, samples=60)
    reached = 0
    for i, k in np.argwhere(curve.valid):
        design = guidance_slider_crank(R, curve.dyad(i, k), sliders[0])
        if design is not None and design.in_order:
            assert design.pose_error < 1e-9
            reached += 1
    assert reached > 0


@pytest.mark.parametrize("scale, bound", [(1e-3, 1e-14), (1e-4, 1e-12), (1e-5, 1e-10), (1e-6, 1e-8)])
def test_burmester_accuracy_as_the_arcs_shrink_is_as_documented(scale, bound):
    """`burmester`'s Notes give the orientation error of Example 2-15's crank-rocker at each
    scale; the error grows about as 1/scale**2, by analysis with `SphericalFourBar`."""
    from mech.spherical import guidance_fourbars, planar_orientations

    P = [13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j, 66.27 + 215.07j]
    R = planar_orientations(np.radians([0.0, 8.88, 22.1, 63.68, -3.0]), P, scale)
    best = guidance_fourbars(R, rtol=1.0).candidates[0]
    assert best.kind == "crank-rocker" and best.in_order
    assert bound / 1e3 < best.pose_error < bound


def test_stacks_that_do_not_broadcast_are_named():
    """Four orientations against two body points failed with NumPy's 'operands could not be
    broadcast together', naming no argument; the message now names each stack."""
    R = np.stack([rotation_matrix([0, 0, 1], t) for t in (0.1, 0.2, 0.3, 0.4)])
    with pytest.raises(ValueError, match=r"`R_j` \(4,\), `circle_point` \(2,\)"):
        crank_residual(np.eye(3), R, np.ones((2, 3)), [0, 0, 1])
    with pytest.raises(ValueError, match=r"`R_j` \(4,\), `slider_point` \(2,\)"):
        slider_residual(R, np.ones((2, 3)), [0, 0, 1])
    with pytest.raises(ValueError, match=r"`R_1` \(2,\), `R_j` \(4,\)"):
        relative_rotation(R[:2], R)
    with pytest.raises(ValueError, match=r"`R_1` \(2,\), `R_j` \(4,\)"):
        rotation_pole(R[:2], R)
    # stacks that broadcast still work
    assert crank_residual(np.eye(3), R, np.ones((1, 3)), [0, 0, 1]).shape == (4,)
    assert relative_rotation(R[:1], R)[0].shape == (4, 3, 3)
