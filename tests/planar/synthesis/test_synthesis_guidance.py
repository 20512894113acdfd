"""Rigid-body guidance: displacement matrices, RR dyads for 2, 3 and 5 poses, and the
four-bars they make, each checked against an independent route (complex arithmetic,
mpmath at 50 digits on the raw constant-length equations, multi-start least squares, or
the analysis class `FourBar` moving the designed linkage)."""

import mpmath
import numpy as np
import pytest
from scipy.optimize import least_squares

from mech import InputTypeError
from mech.planar import FourBar, grashof
from mech.planar.synthesis import (
    circle_point_curve,
    Dyad,
    burmester,
    displacement_matrix,
    dyad_for_centre_point,
    dyad_for_circle_point,
    guidance_fourbars,
    pole,
)

# Example 2-15 (§2.4 I): reference points P_i and angles theta_i (degrees)
EX_P = np.array([13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j, 66.27 + 215.07j])
EX_DEG = np.array([0.0, 8.88, 22.1, 63.68, -3.0])


# an independent recomputation of example 2-15 (4000 random starts, 6 significant digits):
# per dyad (centre point A, moving pivot B_1, crank length), for theta_41 = 63.68 and 63.38 deg
_EX15_CATALOG = [
    (63.68, [((0.643066, 1.32317), (-81.8776, 72.1637), 108.757), ((189.490, 1.33828), (88.6722, 158.475), 186.698),
             ((310.819, 859.871), (345.607, 392.762), 468.402), ((8.19817, 1966.30), (262.224, 484.929), 1503.00)]),
    (63.38, [((0.537736, 1.03926), (-81.8976, 71.7237), 108.590), ((189.785, 1.08356), (89.0339, 158.184), 186.632),
             ((318.377, 835.118), (349.390, 387.818), 448.374), ((-22.5208, 2088.63), (258.247, 488.930), 1624.15)]),
]


def _coupler_task(seed):
    """Five poses of the coupler of a random crank-rocker, placed anywhere, and its two dyads."""
    rng = np.random.default_rng(seed)
    while True:
        a, b, c, d = rng.uniform(0.2, 1.0), *rng.uniform(1.0, 3.0, 3)
        if 2 * max(a, b, c, d) < a + b + c + d and grashof(a, b, c, d).kind == "crank-rocker":
            break
    p, q = rng.uniform(-1.5, 1.5, 2)
    branch = int(rng.choice([-1, 1]))
    linkage = FourBar(a, b, c, d, branch=branch, coupler=(p, q))
    start = rng.uniform(-np.pi, np.pi)
    theta_in = start + np.sort(rng.uniform(0.3, 2 * np.pi - 0.3, 4))
    theta_in = np.concatenate([[start], theta_in])
    pose = linkage.solve(theta_in)
    origin, turn, offset = complex(*rng.normal(size=2)) * 3, rng.uniform(-np.pi, np.pi), rng.uniform(-np.pi, np.pi)
    place = np.exp(1j * turn)
    theta = np.angle(pose.C - pose.B) + turn + offset          # body frame at P, turned by `offset`
    dvec = origin + place * pose.P
    body = lambda w: np.exp(-1j * theta[0]) * (origin + place * w - dvec[0])
    crank = (origin, body(pose.B[0]))
    rocker = (origin + place * d, body(pose.C[0]))
    return theta, dvec, crank, rocker, (a, b, c, d)


def _raw_equations_mp(theta, d):
    """(2-40) in full form, |B_j - A|^2 - |B_1 - A|^2, with B_j by (2-37) written out in mpmath."""
    th = [mpmath.mpf(float(t)) for t in theta]
    dd = [mpmath.mpc(complex(v).real, complex(v).imag) for v in d]

    def f(bx, by, ax, ay):
        B1, A = mpmath.mpc(bx, by), mpmath.mpc(ax, ay)
        out = []
        for j in range(1, 5):
            Bj = mpmath.expj(th[j] - th[0]) * (B1 - dd[0]) + dd[j]
            out.append(abs(Bj - A) ** 2 - abs(B1 - A) ** 2)
        return out
    return f


def _multistart_roots(theta, d, starts, seed):
    """Distinct real roots (B_1, A) of (2-40) from random starts, by scipy least squares."""
    rng = np.random.default_rng(seed)
    size = np.max(np.abs(d - d.mean()))
    w = np.exp(1j * (theta - theta[0]))

    def res(v):
        B1, A = (v[0] + 1j * v[1]) * size, (v[2] + 1j * v[3]) * size
        Bj = w[1:] * (B1 - d[0]) + d[1:]
        return (np.abs(Bj - A) ** 2 - np.abs(B1 - A) ** 2) / size**2

    roots = []
    for _ in range(starts):
        radius = np.exp(rng.uniform(np.log(0.1), np.log(60.0)))
        c = d.mean() / size
        x0 = np.array([c.real, c.imag, c.real, c.imag]) + radius * rng.normal(size=4) / 2
        sol = least_squares(res, x0, xtol=1e-15, ftol=1e-15, gtol=1e-15)
        B1, A = (sol.x[0] + 1j * sol.x[1]) * size, (sol.x[2] + 1j * sol.x[3]) * size
        if np.max(np.abs(sol.fun)) < 1e-10 and abs(B1 - A) > 1e-6 * size:
            if all(abs(A - r[1]) > 1e-6 * max(size, abs(A)) for r in roots):
                roots.append((B1, A))
    return roots


# --- displacement matrix and pole ------------------------------------------------------------

def test_displacement_matrix_maps_body_points():
    """[P]_i1 (2-37) moves a body point as the pose convention says (complex route)."""
    rng = np.random.default_rng(1)
    t1, ti = rng.uniform(-4, 4, (2, 50))
    d1, di = rng.normal(size=(2, 50)) + 1j * rng.normal(size=(2, 50))
    z = rng.normal(size=50) + 1j * rng.normal(size=50)
    M = displacement_matrix(t1, d1, ti, di)
    b1 = np.exp(1j * t1) * z + d1
    bi = M @ np.stack([b1.real, b1.imag, np.ones(50)], axis=-1)[..., None]
    expect = np.exp(1j * ti) * z + di
    assert np.max(np.abs(bi[:, 0, 0] + 1j * bi[:, 1, 0] - expect)) < 1e-13 * np.max(np.abs(expect))
    assert np.allclose(M[:, 2], [0, 0, 1])


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_displacement_matrix_shape(shape):
    t = np.full(shape, 0.3)
    assert displacement_matrix(0.0, 0, t, 1j).shape == shape + (3, 3)
    assert np.shape(pole(0.0, 0, t, 1j)) == shape


def test_example_2_15_displacement_matrices():
    """Example 2-15: [P]_21, [P]_31 as printed; [P]_41 has t_y = +17.129 (printed -17.129)
    with the text's 63.38 deg; [P]_51 has (1, 2) entry +0.0523 (printed -0.052)."""
    th = np.radians(EX_DEG)
    M = displacement_matrix(th[0], EX_P[0], th[1:], EX_P[1:])
    assert np.allclose(M[0, :2], [[0.988, -0.154, -15.650], [0.154, 0.988, -47.707]], atol=1e-3)
    assert np.allclose(M[1, :2], [[0.927, -0.376, 6.444], [0.376, 0.927, -83.500]], atol=1e-3)
    text_41 = displacement_matrix(0.0, EX_P[0], np.radians(63.38), EX_P[3])
    assert abs(text_41[1, 2] - 17.129) < 1e-3 and abs(text_41[0, 2] - 207.030) < 1e-3
    assert abs(M[3, 0, 1] - np.sin(np.radians(3.0))) < 1e-15
    # constant terms (t_x^2 + t_y^2)/2 of the expanded equations: printed 25.105, 41.874, 25.369
    k0 = 0.5 * (M[:, 0, 2] ** 2 + M[:, 1, 2] ** 2)
    assert np.allclose(k0[[0, 1, 3]], [1260.47, 3506.87, 1287.15], atol=0.01)


def test_example_2_15_text_solution_is_not_a_solution():
    """The text's A = (-4.53e-4, -1.58e-6), B_1 = (-82.512, 70.711): the crank length would
    have to vary from 108.34 to 110.35 over the five poses (errata row 50)."""
    th = np.radians(EX_DEG)
    B = np.exp(1j * th) * (-82.512 + 70.711j - EX_P[0]) + EX_P
    r = np.abs(B - (-4.53e-4 - 1.58e-6j))
    assert np.allclose(r, [108.666, 108.498, 108.337, 110.353, 108.690], atol=1e-3)


def test_pole_is_fixed():
    rng = np.random.default_rng(2)
    t1, ti = rng.uniform(-3, 3, (2, 40))
    d1, di = rng.normal(size=(2, 40)) + 1j * rng.normal(size=(2, 40))
    Q = pole(t1, d1, ti, di)
    moved = np.exp(1j * (ti - t1)) * (Q - d1) + di
    assert np.max(np.abs(moved - Q) / (1 + np.abs(Q))) < 1e-13


def test_pole_small_turn_keeps_relative_accuracy():
    """For a turn of 1e-9 the pole is about 1e9 away; mpmath at 50 digits agrees to 1e-12."""
    q = pole(0.0, 0.0, 1e-9, 1.0)
    with mpmath.workdps(50):
        w = mpmath.expj(mpmath.mpf(1e-9))
        ref = 1 / (1 - w)                                   # Q (1 - w) = d_i - w d_1
    assert abs(q - complex(ref)) < 1e-12 * abs(complex(ref))


def test_pole_beyond_float_range_is_infinite():
    q = pole(0.0, 1e300, 1e-300, -1e300)          # about -2e600j: -inf on the bisector, never NaN
    assert q.real == 0.0 and q.imag == -np.inf


@pytest.mark.parametrize("scale", [1e-300, 1e300])
def test_dyad_three_poses_scale_invariance(scale):
    theta, d = np.array([0.0, 0.3, 0.7]), np.array([0, 1 + 0.2j, 1.8 + 0.9j])
    ref = dyad_for_circle_point(theta, d, 0.5 + 0.5j)
    got = dyad_for_circle_point(theta, d * scale, (0.5 + 0.5j) * scale)
    assert abs(got.centre_point / scale - ref.centre_point) < 1e-14 * abs(ref.centre_point)
    back = dyad_for_centre_point(theta, d * scale, got.centre_point)
    assert abs(back.circle_point / scale - (0.5 + 0.5j)) < 1e-13


def test_pole_pure_translation_raises():
    with pytest.raises(ValueError, match="pure translation"):
        pole(0.5, 0, 0.5, 1 + 1j)


# --- two and three poses ---------------------------------------------------------------------

def test_dyad_for_circle_point_three_poses():
    """The centre point is equidistant from the three positions (bisectors solved directly)."""
    rng = np.random.default_rng(3)
    theta, d = np.array([0.1, 0.5, 1.2]), np.array([0, 1 + 0.3j, 1.5 + 1.4j])
    z = rng.normal(size=(3, 4)) + 1j * rng.normal(size=(3, 4))
    crank = dyad_for_circle_point(theta, d, z)
    assert crank.centre_point.shape == (3, 4)
    Z = np.exp(1j * theta) * z[..., None] + d
    for k in np.ndindex(3, 4):
        u, v = Z[k][1] - Z[k][0], Z[k][2] - Z[k][0]
        rhs = 0.5 * np.array([abs(u) ** 2, abs(v) ** 2])
        A = Z[k][0] + complex(*np.linalg.solve([[u.real, u.imag], [v.real, v.imag]], rhs))
        assert abs(A - crank.centre_point[k]) < 1e-12 * (1 + abs(A))
        assert abs(crank.length[k] - abs(Z[k][0] - A)) < 1e-12 * (1 + abs(A))


def test_dyad_for_centre_point_inverts():
    theta, d = np.array([0.0, 0.4, 0.9]), np.array([0, 0.8 + 0.1j, 1.2 + 0.9j])
    A = np.array([-1 + 2j, 0.3 - 0.5j, 4 + 4j])
    crank = dyad_for_centre_point(theta, d, A)
    back = dyad_for_circle_point(theta, d, crank.circle_point)
    assert np.max(np.abs(back.centre_point - A)) < 1e-12 * np.max(np.abs(A))
    Z = np.exp(1j * theta) * crank.circle_point[:, None] + d
    assert np.max(np.abs(np.abs(Z - A[:, None]) - crank.length[:, None])) < 1e-12


@pytest.mark.parametrize("along", [-3.0, 0.0, 0.7])
def test_dyad_two_poses_on_bisector(along):
    theta, d = np.array([0.2, 1.0]), np.array([0, 1 + 1j])
    for chooser, point in ((dyad_for_circle_point, 0.3 + 0.2j), (dyad_for_centre_point, -2 + 1j)):
        crank = chooser(theta, d, point, along=along)
        Z = np.exp(1j * theta) * crank.circle_point + d
        assert abs(abs(Z[1] - crank.centre_point) - abs(Z[0] - crank.centre_point)) < 1e-13 * crank.length


def test_dyad_collinear_positions_raise():
    """Three translations along a line: every point moves on a line, no finite crank."""
    with pytest.raises(ValueError, match="Expected `circle_point`"):
        dyad_for_circle_point([0.0, 0.0, 0.0], [0, 1, 2], 0.5j)


def test_dyad_at_the_pole_raises():
    theta, d = np.array([0.0, np.pi / 2]), np.array([0, 1 + 1j])
    with pytest.raises(ValueError, match="non-zero length"):
        dyad_for_circle_point(theta, d, 1j)            # the pole, seen from the body at pose 1


def test_three_pose_fourbar_reproduces_poses():
    """Two chosen circle points give a four-bar that FourBar moves through the three poses."""
    theta, d = np.array([0.0, 0.35, 0.8]), np.array([0, 0.9 + 0.25j, 1.6 + 0.9j])
    dyads = [dyad_for_circle_point(theta, d, z) for z in (-0.4 - 0.6j, 0.9 - 0.7j)]
    result = guidance_fourbars(theta, d, dyads)
    assert result.passing
    for cand in result.passing:
        pose = cand.linkage.solve(cand.theta_input)
        placed = cand.origin + np.exp(1j * cand.angle) * pose.P
        assert np.max(np.abs(placed - d)) < 1e-9 * max(cand.linkage.a, cand.linkage.d)


# --- five poses ------------------------------------------------------------------------------

# seeds 13, 18 and 21 give two real and two complex dyads; the others four real ones
@pytest.mark.parametrize("seed", [*range(8), 13, 18, 21])
def test_burmester_finds_generating_dyads(seed):
    """Poses of a crank-rocker's coupler: its crank and rocker are Burmester dyads, and the
    linkage they make passes every check."""
    theta, d, crank, rocker, lengths = _coupler_task(seed)
    found = burmester(theta, d)
    assert len(found.dyads) in (2, 4) and found.n_complex == 4 - len(found.dyads)
    size = np.max(np.abs(d - d.mean()))
    for A, z in (crank, rocker):
        err = min(abs(k.centre_point - A) + abs(k.circle_point - z) for k in found.dyads)
        assert err < 1e-9 * max(size, abs(A))
    result = guidance_fourbars(theta, d)
    match = [c for c in result.passing
             if abs(c.input_dyad.centre_point - crank[0]) < 1e-9 * size
             and abs(c.output_dyad.centre_point - rocker[0]) < 1e-9 * size]
    assert len(match) == 1 and match[0].kind == "crank-rocker"
    assert np.allclose([match[0].linkage.a, match[0].linkage.b, match[0].linkage.c, match[0].linkage.d],
                       lengths, rtol=1e-9)


@pytest.mark.parametrize("seed", [*range(6), 13, 18])
def test_burmester_against_multistart_and_mpmath(seed):
    """Independent route: 300 random starts of least squares on the raw equations (2-40),
    each distinct root refined to 50 digits by mpmath.findroot. They are exactly our dyads,
    to 1e-9 relative."""
    theta, d, *_ = _coupler_task(seed)
    found = burmester(theta, d)
    others = _multistart_roots(theta, d, 300, seed)
    assert len(others) == len(found.dyads)
    f = _raw_equations_mp(theta, d)
    matched = set()
    with mpmath.workdps(50):
        for B1, A in others:
            start = (B1.real, B1.imag, A.real, A.imag)
            root = [mpmath.re(r) for r in mpmath.findroot(f, start, tol=mpmath.mpf(10) ** -40)]
            B_ref, A_ref = complex(mpmath.mpc(root[0], root[1])), complex(mpmath.mpc(root[2], root[3]))
            scale = max(1.0, abs(A_ref), abs(B_ref))
            errs = [abs(k.centre_point - A_ref) + abs(k.moving_pivot - B_ref) for k in found.dyads]
            k = int(np.argmin(errs))
            assert errs[k] < 1e-9 * scale
            matched.add(k)
    assert matched == set(range(len(found.dyads)))
    assert found.residual < 1e-12


@pytest.mark.parametrize("deg4, table", _EX15_CATALOG)
def test_example_2_15_burmester(deg4, table):
    """Example 2-15: four real Burmester dyads, for the data's 63.68 deg and the text's 63.38 deg.
    Reference values: an independent recomputation (4000 random starts), 6 significant digits."""
    deg = EX_DEG.copy()
    deg[3] = deg4
    found = burmester(np.radians(deg), EX_P)
    assert len(found.dyads) == 4 and found.n_complex == 0
    for k, ((ax, ay), (bx, by), r) in zip(found.dyads, table):
        assert abs(k.centre_point - complex(ax, ay)) < 5e-6 * max(abs(complex(ax, ay)), 100)
        assert abs(k.moving_pivot - complex(bx, by)) < 5e-6 * abs(complex(bx, by))
        assert abs(k.length - r) < 5e-6 * r


@pytest.mark.parametrize("deg4, table", _EX15_CATALOG)
def test_example_2_15_burmester_against_mpmath(deg4, table):
    """Example 2-15 by another route: each dyad of the independently recomputed table (6 digits, found there
    by 4000 random starts) refined by mpmath.findroot on the raw equations (2-40) at 50
    digits; `burmester` matches every one to 1e-9 relative. Four real roots is the most the
    quartic allows, so none is missing."""
    deg = EX_DEG.copy()
    deg[3] = deg4
    theta = np.radians(deg)
    found = burmester(theta, EX_P)
    assert len(found.dyads) == 4 and found.n_complex == 0
    f = _raw_equations_mp(theta, EX_P)
    matched = set()
    with mpmath.workdps(50):
        for (ax, ay), (bx, by), _ in table:
            B0, A0 = complex(bx, by), complex(ax, ay)
            root = [mpmath.re(r) for r in mpmath.findroot(f, (B0.real, B0.imag, A0.real, A0.imag),
                                                           tol=mpmath.mpf(10) ** -40)]
            B_ref, A_ref = complex(mpmath.mpc(root[0], root[1])), complex(mpmath.mpc(root[2], root[3]))
            scale = max(abs(A_ref), abs(B_ref))
            errs = [abs(j.centre_point - A_ref) + abs(j.moving_pivot - B_ref) for j in found.dyads]
            assert min(errs) < 1e-9 * scale
            matched.add(int(np.argmin(errs)))
    assert matched == {0, 1, 2, 3}


def test_example_2_15_fourbar():
    """Example 2-15: the one four-bar that passes is the text's crank-rocker (its first two
    roots). Catalog: crank angles 139.355, 174.921, 206.640, 346.853, 469.356 deg; angle
    between coupler and rocker 95.84, 103.79, 100.34, 26.45, 81.71 deg."""
    result = guidance_fourbars(np.radians(EX_DEG), EX_P)
    assert len(result.candidates) == 12 and len(result.passing) == 1
    best = result.passing[0]
    L = best.linkage
    assert best.kind == "crank-rocker" and best.direction == 1
    assert np.allclose([L.a, L.b, L.c, L.d], [108.757, 191.146, 186.698, 188.847], atol=1e-3)
    crank_ground = np.degrees(np.unwrap(best.theta_input + best.angle)) % 360
    assert np.allclose(crank_ground, [139.355, 174.921, 206.640, 346.853, 109.356], atol=2e-3)
    delta = np.array([95.84, 103.79, 100.34, 26.45, 81.71])
    assert np.allclose(np.degrees(best.gamma_at_poses), np.minimum(delta, 180 - delta), atol=0.01)
    assert best.gamma_min <= best.gamma_at_poses.min()
    # one call of FourBar.solve reproduces the task
    pose = L.solve(best.theta_input)
    placed = best.origin + np.exp(1j * best.angle) * pose.P
    assert np.max(np.abs(placed - EX_P)) < 1e-9 * L.d
    turned = np.angle(pose.C - pose.B) + best.angle - np.angle(best.output_dyad.circle_point
                                                              - best.input_dyad.circle_point)
    assert np.max(np.abs(np.angle(np.exp(1j * (turned - np.radians(EX_DEG)))))) < 1e-9


@pytest.mark.parametrize("seed", range(4))
def test_guidance_fourbars_reproduce_poses(seed):
    """Every passing candidate moves through the poses (FourBar.solve, placed) to 1e-9."""
    theta, d, *_ = _coupler_task(seed + 100)
    result = guidance_fourbars(theta, d)
    assert result.passing
    for cand in result.passing:
        t, dd = cand.coupler_poses(cand.theta_input)
        size = max(cand.linkage.a, cand.linkage.b, cand.linkage.c, cand.linkage.d)
        assert np.max(np.abs(dd - d)) < 1e-9 * size
        assert np.max(np.abs(np.angle(np.exp(1j * (t - theta))))) < 1e-9
        steps = np.remainder(cand.direction * np.diff(cand.theta_input), 2 * np.pi)
        assert steps.sum() < 2 * np.pi
        # the motion between the first and last pose stays assembled (dense sweep)
        sweep = cand.theta_input[0] + cand.direction * np.linspace(0, steps.sum(), 2001)
        assert np.all(cand.linkage.solve(sweep).valid)
        gam = cand.linkage.transmission_angle(sweep)
        assert cand.gamma_min <= gam.min() + 1e-12 and gam.min() - cand.gamma_min < 1e-5


@pytest.mark.parametrize("scale", [1e-300, 1e-150, 1e-20, 1e20, 1e150, 1e300])
def test_burmester_scale_invariance(scale):
    th = np.radians(EX_DEG)
    ref = burmester(th, EX_P)
    got = burmester(th, EX_P * scale)
    for k, r in zip(got.dyads, ref.dyads):
        assert abs(k.centre_point / scale - r.centre_point) < 1e-11 * abs(r.centre_point)
        assert abs(k.length / scale - r.length) < 1e-11 * r.length
    best, best_ref = guidance_fourbars(th, EX_P * scale).passing, guidance_fourbars(th, EX_P).passing
    assert len(best) == len(best_ref) == 1
    assert np.allclose(best[0].theta_input, best_ref[0].theta_input, rtol=0, atol=1e-11)
    assert abs(best[0].gamma_min - best_ref[0].gamma_min) < 1e-11


def test_burmester_dependent_poses_raise():
    """Five turns about one point: every body point is a circle point (no finite set)."""
    with pytest.raises(ValueError, match="independent"):
        burmester([0.0, 0.3, 0.7, 1.1, 2.0], np.zeros(5))


# --- bad input -------------------------------------------------------------------------------

@pytest.mark.parametrize("call, match", [
    (lambda: burmester([0.0, 0.1, 0.2, 0.3], [0, 1, 2, 3]), "Expected 5 poses"),
    (lambda: burmester(np.zeros(5), np.zeros(4)), "same shape"),
    (lambda: burmester([0.0, 0.1, 0.2, 0.3, np.nan], np.arange(5)), "Expected finite `theta`"),
    (lambda: burmester(np.zeros(5), [0, 1, 2, 3, complex(np.inf, 0)]), "Expected finite `d`"),
    (lambda: dyad_for_circle_point([0.0, 1.0], [0, 1], 0j, along=np.nan), "Expected finite `along`"),
    (lambda: guidance_fourbars([0.0, 1.0, 2.0], [0, 1, 1j]), "Expected `dyads`"),
    (lambda: guidance_fourbars([0.0, 1.0, 2.0], [0, 1, 1j], ["crank"]), "Expected `dyads`"),
    (lambda: guidance_fourbars([0.0, 1.0, 2.0], [0, 1, 1j], [Dyad(0j, 1j, np.nan, 1.0)]), "finite numeric"),
    (lambda: pole(0.0, 0, 1.0, np.nan), "Expected finite `d_i`"),
])
def test_bad_values_raise(call, match):
    with pytest.raises(ValueError, match=match):
        call()


@pytest.mark.parametrize("call, match", [
    (lambda: burmester([0.0, 0.1, 0.2, 0.3, 1j], np.arange(5)), "`theta`"),
    (lambda: burmester(np.zeros(5), ["0", 1, 2, 3, 4]), "`d`"),
    (lambda: dyad_for_circle_point([0.0, 1.0], [0, 1], True), "`circle_point`"),
    (lambda: dyad_for_centre_point([0.0, 1.0], [0, 1], None), "`centre_point`"),
    (lambda: displacement_matrix(0.0, "1", 0.5, 1j), "`d_1`"),
    (lambda: pole(False, 0, 1.0, 1j), "`theta_1`"),
    (lambda: burmester(np.zeros(5), np.arange(5), imag_tol="small"), "`imag_tol`"),
])
def test_wrong_types_raise(call, match):
    with pytest.raises(InputTypeError, match=match):
        call()


# --- four poses: the circle-point curve ------------------------------------------------------

def _concyclic_mp(Z):
    """Imaginary part of the cross-ratio of four points at 50 digits, over its size (0 if concyclic)."""
    with mpmath.workdps(50):
        z = [mpmath.mpc(complex(v).real, complex(v).imag) for v in Z]
        cr = (z[0] - z[2]) * (z[1] - z[3]) / ((z[0] - z[3]) * (z[1] - z[2]))
        return float(abs(mpmath.im(cr)) / abs(cr))


def test_circle_point_curve_points_are_concyclic():
    """Every valid circle point's four positions lie on a circle (cross-ratio real, mpmath),
    about the reported centre point."""
    theta, d = np.radians(EX_DEG[:4]), EX_P[:4]
    curve = circle_point_curve(theta, d, samples=120)
    assert curve.valid.sum() > 100
    for z, A in zip(curve.circle_point[curve.valid], curve.centre_point[curve.valid]):
        Z = np.exp(1j * theta) * z + d
        assert _concyclic_mp(Z) < 1e-9
        r = np.abs(Z - A)
        assert np.max(np.abs(r - r[0])) < 1e-9 * r[0]
    assert np.all(np.isnan(curve.circle_point[~curve.valid]))


def test_circle_point_curve_contains_burmester_points():
    """The Burmester dyads of poses 1-5 lie on the curve of poses 1-4."""
    theta, d = np.radians(EX_DEG), EX_P
    pole_z = circle_point_curve(theta[:4], d[:4], samples=1).pole
    for dyad in burmester(theta, d).dyads:
        phi = np.angle(dyad.circle_point - pole_z) % np.pi
        curve = circle_point_curve(theta[:4], d[:4], phi=[phi])
        err = np.nanmin(np.abs(curve.circle_point[0] - dyad.circle_point))
        assert err < 1e-9 * max(1.0, abs(dyad.circle_point))
        k = int(np.nanargmin(np.abs(curve.circle_point[0] - dyad.circle_point)))
        assert abs(curve.dyad(0, k).centre_point - dyad.centre_point) < 1e-9 * max(1.0, abs(dyad.centre_point))


@pytest.mark.parametrize("scale", [1e-300, 1e300])
def test_circle_point_curve_scale_invariance(scale):
    theta, d = np.radians(EX_DEG[:4]), EX_P[:4]
    ref = circle_point_curve(theta, d, samples=60)
    got = circle_point_curve(theta, d * scale, samples=60)
    assert np.array_equal(ref.valid, got.valid)
    v = ref.valid
    assert np.max(np.abs(got.centre_point[v] / scale - ref.centre_point[v]) / np.abs(ref.centre_point[v])) < 1e-10


def test_four_pose_fourbar_from_the_curve():
    """Two points of the curve make four-bars that FourBar moves through the four poses."""
    theta, d = np.radians(EX_DEG[:4]), EX_P[:4]
    curve = circle_point_curve(theta, d, samples=24)
    picks = [(i, k) for i in range(24) for k in range(2) if curve.valid[i, k]]
    passing = []
    for m in range(1, len(picks)):
        result = guidance_fourbars(theta, d, [curve.dyad(*picks[0]), curve.dyad(*picks[m])])
        passing.extend(result.passing)
        for cand in result.candidates:       # a candidate that reproduces the poses on one branch passes
            assert cand.passes == (cand.in_order and cand.pose_error <= 1e-9)
    assert len(passing) >= 5
    for cand in passing:
        t, dd = cand.coupler_poses(cand.theta_input)
        size = max(cand.linkage.a, cand.linkage.b, cand.linkage.c, cand.linkage.d)
        assert np.max(np.abs(dd - d)) < 1e-9 * size
        assert np.max(np.abs(np.angle(np.exp(1j * (t - theta))))) < 1e-9


def test_circle_point_curve_bad_input():
    theta, d = np.radians(EX_DEG[:4]), EX_P[:4]
    with pytest.raises(ValueError, match="Expected `samples`"):
        circle_point_curve(theta, d, samples=0)
    with pytest.raises(ValueError, match="turn relative"):
        circle_point_curve(np.zeros(4), d)
    with pytest.raises(ValueError, match="Expected a valid point"):
        curve = circle_point_curve(theta, d, samples=200)
        i, k = np.argwhere(~curve.valid)[0]
        curve.dyad(int(i), int(k))


def test_eq_2_33_2_34_printed_second_lines_are_wrong():
    """Erratum 46: the second lines of (2-33) and (2-34) swap sine and cosine. As printed,
    R_y = R'_y sin(theta) + R'_x cos(theta) neither keeps the length of R' nor agrees with
    `displacement_matrix`; the corrected R_y = R'_x sin(theta) + R'_y cos(theta) does both."""
    rng = np.random.default_rng(33)
    for _ in range(20):
        th1, thi = rng.uniform(-np.pi, np.pi, 2)
        P1, Pi, B1 = (complex(*rng.normal(size=2)) * 5 for _ in range(3))
        M = displacement_matrix(th1, P1, thi, Pi)
        moved = M @ np.array([B1.real, B1.imag, 1.0])
        t = thi - th1
        R = B1 - P1                                        # R' of (2-32): from P_1 to B_1
        Rx = R.real * np.cos(t) - R.imag * np.sin(t)       # first line, printed correctly
        Ry_printed = R.imag * np.sin(t) + R.real * np.cos(t)
        Ry_fixed = R.real * np.sin(t) + R.imag * np.cos(t)
        assert np.allclose(moved[:2], [Pi.real + Rx, Pi.imag + Ry_fixed], rtol=0, atol=1e-12)
        assert abs(np.hypot(Rx, Ry_fixed) - abs(R)) < 1e-12
        if abs(np.sin(t) - np.cos(t)) > 0.1 and abs(R.real - R.imag) > 0.1:
            assert abs(Ry_printed - Ry_fixed) > 1e-3
