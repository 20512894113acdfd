"""Path generation by precision points (textbook section 4.4, Ex. 2-21 and 2-22).

Oracles: mpmath at 50 digits on the raw constant-length equations (2-53)/(2-54) and (2-56),
and the coupler point recomputed here from circle intersections, not by `FourBar`.
"""

import mpmath
import numpy as np
import pytest

from mech.planar.synthesis import PathFourBar, path_design, path_residuals, path_timed, path_untimed

P21 = [13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 32.95 + 99.62j,
       44.74 + 113.95j, 58.62 + 127.98j, 66.27 + 215.07j]
P22 = [12.42 + 0j, 7.98 + 1.89j, 0.76 + 1.47j, 1.30 - 0.85j, 8.83 + 0.3j]
ALPHA22 = np.radians([4.2, 64.87, 145.82, 219.24, 303.45])
STAGE1 = (0j, -82.5 + 70.7j, 89.7 + 158.2j, 190.4 + 1j)


def _oracle_point(A, B1, C1, D, P1, crank_angle, flip=False):
    """Coupler point at a ground-frame crank angle by two circle intersections (mpmath, 50 digits).

    C is taken on the side of B->D where it was drawn (the other side with `flip`).
    """
    mpmath.mp.dps = 50
    A, B1, C1, D, P1 = (mpmath.mpc(complex(v)) for v in (A, B1, C1, D, P1))
    a, b, c = abs(B1 - A), abs(C1 - B1), abs(C1 - D)
    side = mpmath.sign(mpmath.im(mpmath.conj(D - B1) * (C1 - B1))) * (-1 if flip else 1)
    B = A + a * mpmath.expj(mpmath.mpf(float(crank_angle)))
    e = D - B
    s = abs(e)
    along = (s**2 + b**2 - c**2) / (2 * s)
    C = B + e / s * (along + 1j * side * mpmath.sqrt(b**2 - along**2))
    return complex(B + (C - B) * (P1 - B1) / (C1 - B1))


def _raw_untimed_root(points, A, B1, C1, D, rot):
    """Polish (B1, C1, D, rotations) at 50 digits on the raw equations |B_i - A| = |B_1 - A|, |C_i - D| = |C_1 - D|."""
    mpmath.mp.dps = 50
    P = [mpmath.mpc(complex(p)) for p in points]
    A = mpmath.mpc(complex(A))

    def eqs(*x):
        B1m, C1m, Dm = mpmath.mpc(x[0], x[1]), mpmath.mpc(x[2], x[3]), mpmath.mpc(x[4], x[5])
        out = []
        for i in range(1, len(P)):
            turn = mpmath.expj(x[5 + i])
            out.append(abs(P[i] + turn * (B1m - P[0]) - A) ** 2 - abs(B1m - A) ** 2)
            out.append(abs(P[i] + turn * (C1m - P[0]) - Dm) ** 2 - abs(C1m - Dm) ** 2)
        return out

    x0 = [B1.real, B1.imag, C1.real, C1.imag, D.real, D.imag] + list(rot[1:])
    root = mpmath.findroot(eqs, [mpmath.mpf(float(v)) for v in x0], tol=mpmath.mpf("1e-40"))
    return [complex(root[0], root[1]), complex(root[2], root[3]), complex(root[4], root[5])]


@pytest.fixture(scope="module")
def ex21():
    return path_untimed(P21, A=0j, initial=[STAGE1], starts=0)


def test_example_2_21_stage_one():
    """Ex. 2-21, first stage: A = 0 and D = (190.4, 1) fixed, points P1, P2, P3, P5, P7."""
    found = path_untimed([P21[i] for i in (0, 1, 2, 4, 6)], A=0j, D=190.4 + 1j, initial=[STAGE1], starts=0)
    k = found.candidates[0]
    assert abs(k.B1 - (-82.512 + 70.711j)) < 1e-3
    assert abs(k.C1 - (89.684 + 158.20j)) < 1e-2
    assert k.residual < 1e-12


def test_example_2_21_untimed_reproduces_book(ex21):
    """Ex. 2-21, second stage: seven points, A = 0; the printed linkage is the exact root to its digits."""
    k = ex21.candidates[0]
    assert abs(k.B1 - (-95.524 + 80.407j)) < 1e-3
    assert abs(k.C1 - (76.791 + 170.535j)) < 1e-3
    assert abs(k.D - (174.194 + 18.575j)) < 1e-3
    lengths = [k.linkage.a, k.linkage.b, k.linkage.c, k.linkage.d]
    np.testing.assert_allclose(lengths, [124.86, 194.46, 180.50, 175.18], atol=6e-3)
    assert k.passes and k.in_order and k.point_error < 1e-9
    assert k.kind == "crank-rocker"
    assert 0.0 < k.gamma_min <= np.min(k.gamma_at_points)
    # independently recomputed coupler rotations, degrees
    np.testing.assert_allclose(np.degrees(k.coupler_rotation[1:]),
                               [8.35102, 20.0436, 80.8362, 76.1784, 70.6636, -3.76876], atol=1e-3)


def test_example_2_21_mpmath_oracle(ex21):
    """The root agrees with a 50-digit root of the raw equations, and the coupler point meets every point."""
    k = ex21.candidates[0]
    B1, C1, D = _raw_untimed_root(P21, 0j, k.B1, k.C1, k.D, k.coupler_rotation)
    scale = abs(k.C1 - k.B1)
    assert max(abs(B1 - k.B1), abs(C1 - k.C1), abs(D - k.D)) < 1e-10 * scale
    placed = k.to_ground(0.0)
    assert placed == 0j
    for theta_std, p in zip(k.theta_input, P21):
        q = _oracle_point(k.A, k.B1, k.C1, k.D, P21[0], theta_std + k.angle)
        assert abs(q - p) < 1e-9 * scale


def test_example_2_21_order_sweep(ex21):
    """A dense sweep of the input from the first point to the last stays assembled and meets the points in order."""
    k = ex21.candidates[0]
    unwrapped = k.theta_input[0] + k.direction * np.remainder(k.direction * (k.theta_input - k.theta_input[0]),
                                                              2 * np.pi)
    assert np.all(np.diff(unwrapped) * k.direction > 0)
    sweep = np.linspace(unwrapped[0], unwrapped[-1], 20001)
    P = k.coupler_point(sweep)
    assert np.all(np.isfinite(P))
    # the path between neighbouring samples is short: no jump to the other branch
    assert np.max(np.abs(np.diff(P))) < 1e-2 * k.linkage.b
    hit = [int(np.argmin(np.abs(P - p))) for p in P21]
    assert hit == sorted(hit)


def test_example_2_21_radius_erratum():
    """The text says P1, P2, P3, P7 lie on an arc of radius 174 and P4, P5, P6 on radius 100: they do not."""
    mpmath.mp.dps = 50

    def circle(p, q, r):
        p, q, r = (mpmath.mpc(complex(v)) for v in (p, q, r))
        M = mpmath.matrix([[2 * (q - p).real, 2 * (q - p).imag], [2 * (r - p).real, 2 * (r - p).imag]])
        rhs = mpmath.matrix([abs(q) ** 2 - abs(p) ** 2, abs(r) ** 2 - abs(p) ** 2])
        c = mpmath.lu_solve(M, rhs)
        centre = mpmath.mpc(c[0], c[1])
        return centre, abs(p - centre)

    centre, radius = circle(*P21[:3])
    assert abs(radius - mpmath.mpf("180.052")) < 1e-3
    assert abs(abs(mpmath.mpc(P21[6]) - centre) - mpmath.mpf("180.043")) < 1e-3
    _, radius = circle(*P21[3:6])
    assert abs(radius - mpmath.mpf("209.174")) < 1e-3


def test_example_2_21_printed_design_analysed():
    """The printed (rounded) linkage of Ex. 2-21 misses the points by rounding only (under 0.01 mm)."""
    book = path_design(0j, -95.524 + 80.407j, 76.791 + 170.535j, 174.194 + 18.575j, P21)
    assert book.in_order
    assert 1e-9 < book.point_error * max(book.linkage.a, book.linkage.b, book.linkage.c, book.linkage.d) < 1e-2


def test_example_2_22_timed_exact_solutions():
    """Ex. 2-22: every exact design (two), checked against the raw equations (2-55), (2-56) at 50 digits."""
    found = path_timed(P22, ALPHA22)
    assert len(found.candidates) == 2
    mpmath.mp.dps = 50
    for k in found.candidates:
        A, B1, C1, D = (mpmath.mpc(v) for v in (k.A, k.B1, k.C1, k.D))
        P = [mpmath.mpc(p) for p in P22]
        B = [A + mpmath.expj(mpmath.mpf(float(al - ALPHA22[0]))) * (B1 - A) for al in ALPHA22]
        PB = [abs(b - p) for b, p in zip(B, P)]
        assert max(PB) - min(PB) < 1e-12 * PB[0]
        turn = [(b - p) / abs(b - p) / ((B1 - P[0]) / abs(B1 - P[0])) for b, p in zip(B, P)]
        CD = [abs(p + u * (C1 - P[0]) - D) for p, u in zip(P, turn)]
        assert max(CD) - min(CD) < 1e-10 * CD[0]
        assert k.residual < 1e-12
    printed = [k for k in found.candidates if abs(k.A - (-5.46 + 1.17j)) < 0.01]
    assert len(printed) == 1
    assert abs(printed[0].B1 - (0.74 + 1.54j)) < 0.01
    assert abs(printed[0].C1 - (31.6267 + 2.6480j)) < 1e-3
    assert abs(printed[0].D - (25.4596 + 5.3593j)) < 1e-3


def test_example_2_22_exact_designs_switch_branch():
    """Neither exact design of Ex. 2-22 traces the points on one branch: analysis rejects both."""
    found = path_timed(P22, ALPHA22)
    assert found.passing == ()
    for k in found.candidates:
        assert not k.passes
        assert k.point_error > 1e-3
        # every point is reached on one branch or the other, and both are needed: the design
        # switches branch between the points
        errors = np.array([[abs(_oracle_point(k.A, k.B1, k.C1, k.D, P22[0], theta + k.angle, flip) - p)
                            for theta, p in zip(k.theta_input, P22)] for flip in (False, True)])
        assert np.all(np.min(errors, axis=0) < 1e-9 * abs(k.C1 - k.B1))
        assert np.max(errors[0]) > 1e-3 and np.max(errors[1]) > 1e-3


def test_example_2_22_printed_result_not_a_root():
    """The printed C1 = (16.9, 15.29), D = (9.34, -20.54) leaves (2-54) residuals of mm^2 and misses the points."""
    A, B1 = -5.46 + 1.17j, 0.74 + 1.54j
    exact = [k for k in path_timed(P22, ALPHA22).candidates if abs(k.A - A) < 0.01][0]
    C1, D = 16.9 + 15.29j, 9.34 - 20.54j
    P = np.asarray(P22)
    rot = exact.coupler_rotation
    C = P + np.exp(1j * rot) * (C1 - P[0])
    resid = np.abs(C - D) ** 2 - abs(C1 - D) ** 2
    assert np.max(np.abs(resid)) > 1.0
    crank = ALPHA22 - ALPHA22[0] + np.angle(B1 - A)
    miss = np.abs(path_residuals((A, B1, C1, D, P22[0]), P22, crank))
    assert miss[0] < 1e-9 and 0.01 < np.max(miss) < 0.1
    for theta, p, m in zip(crank, P22, miss):
        assert abs(abs(_oracle_point(A, B1, C1, D, P22[0], theta) - p) - m) < 1e-9


def _known_linkage(rng):
    """A crank-rocker placed at random in the plane, with its coupler point."""
    a, b, c, d = 1.0, 3.2, 2.6, 3.0
    origin, angle = complex(*rng.uniform(-5, 5, 2)), rng.uniform(-np.pi, np.pi)
    place = lambda w: origin + np.exp(1j * angle) * w
    B1 = a * np.exp(0.3j)
    e = d - B1
    along = (abs(e) ** 2 + b**2 - c**2) / (2 * abs(e))
    C1 = B1 + e / abs(e) * (along + 1j * np.sqrt(b**2 - along**2))
    P1 = B1 + (C1 - B1) * (0.4 + 0.7j)
    return tuple(place(v) for v in (0j, B1, C1, d + 0j, P1)), angle


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_path_timed_recovers_known_linkage(seed):
    """Five points of a known linkage's coupler curve, with its crank angles, give that linkage back."""
    rng = np.random.default_rng(seed)
    (A, B1, C1, D, P1), angle = _known_linkage(rng)
    crank = np.angle(B1 - A) + np.array([0.0, 0.9, 2.0, 3.4, 4.8])
    points = [_oracle_point(A, B1, C1, D, P1, t) for t in crank]
    found = path_timed(points, crank)
    match = [k for k in found.candidates if max(abs(k.A - A), abs(k.B1 - B1), abs(k.C1 - C1), abs(k.D - D)) < 1e-7]
    assert len(match) == 1 and match[0].passes
    assert match[0].direction == 1
    turned = np.exp(1j * (match[0].theta_input + match[0].angle - crank))
    np.testing.assert_allclose(turned, 1.0, atol=1e-9)


def test_path_untimed_recovers_known_linkage_nine_points():
    """Nine points of a known coupler curve, no pivot fixed, from a start 5 % off."""
    rng = np.random.default_rng(7)
    (A, B1, C1, D, P1), _ = _known_linkage(rng)
    crank = np.angle(B1 - A) + np.linspace(0.0, 5.5, 9)
    points = [_oracle_point(A, B1, C1, D, P1, t) for t in crank]
    start = tuple(v * (1 + 0.05 * rng.standard_normal()) for v in (A, B1, C1, D))
    found = path_untimed(points, initial=[start], starts=0)
    k = found.candidates[0]
    assert max(abs(k.A - A), abs(k.B1 - B1), abs(k.C1 - C1), abs(k.D - D)) < 1e-8
    assert k.passes


@pytest.mark.parametrize("scale", [1e-300, 1e-150, 1e150, 1e300])
def test_path_scale_invariance(scale):
    """Ex. 2-22 and the stage one of Ex. 2-21 at extreme units: same angles, lengths scaled."""
    ref = path_timed(P22, ALPHA22)
    got = path_timed(np.asarray(P22) * scale, ALPHA22)
    assert len(got.candidates) == len(ref.candidates)
    for r, g in zip(ref.candidates, got.candidates):
        assert abs(g.A / scale - r.A) < 1e-9 * abs(r.B1 - r.A)
        np.testing.assert_allclose(g.theta_input, r.theta_input, atol=1e-9)
        assert abs(g.point_error - r.point_error) < 1e-9
    pts = [P21[i] * scale for i in (0, 1, 2, 4, 6)]
    s1 = path_untimed(pts, A=0j, D=(190.4 + 1j) * scale, initial=[tuple(v * scale for v in STAGE1)], starts=0)
    assert abs(s1.candidates[0].B1 / scale - (-82.5116 + 70.7110j)) < 1e-3


def test_path_residuals_zero_on_design(ex21):
    """`path_residuals` vanishes at the designed input angles and grows off them."""
    k = ex21.candidates[0]
    crank = k.theta_input + k.angle
    assert np.max(np.abs(path_residuals(k, P21, crank))) < 1e-9 * k.linkage.b
    same = path_residuals((k.A, k.B1, k.C1, k.D, P21[0]), P21, crank)
    np.testing.assert_allclose(same, path_residuals(k, P21, crank), atol=1e-9)
    assert np.min(np.abs(path_residuals(k, P21, crank + 0.01)[1:])) > 1e-3
    assert isinstance(k, PathFourBar)


def test_path_untimed_random_starts_find_book_solution():
    """Without the book's starting values, random starts still find the Ex. 2-21 linkage."""
    found = path_untimed(P21, A=0j, starts=100, seed=0)
    assert any(abs(k.B1 - (-95.5236 + 80.4072j)) < 1e-3 and k.passes for k in found.candidates)
    assert all(k.residual <= 1e-10 for k in found.candidates)


@pytest.mark.parametrize("call, match", [
    (lambda: path_untimed(P21), "Expected 9 points"),
    (lambda: path_untimed(P21[:4]), "Expected `points`"),
    (lambda: path_untimed(["1"] * 9), "Expected `points`"),
    (lambda: path_untimed(P21[:6] + [np.nan], A=0j), "Expected finite `points`"),
    (lambda: path_untimed(P21, A="0"), "Expected `A`"),
    (lambda: path_untimed(P21, A=0j, starts=-1), "Expected `starts`"),
    (lambda: path_untimed(P21, A=0j, tol=0.0), "Expected `tol`"),
    (lambda: path_untimed(P21, A=0j, initial=[(0j, 1j)]), "Expected each `initial`"),
    (lambda: path_timed(P22, ALPHA22[:4]), "Expected `crank_angles`"),
    (lambda: path_timed(P22, [1j] * 5), "Expected `crank_angles`"),
    (lambda: path_timed(P21, ALPHA22), "Expected `points`"),
    (lambda: path_timed([1j] * 5, ALPHA22), "Expected `points` not all equal"),
    (lambda: path_design(0j, 0j, 1 + 1j, 2 + 0j, P22), "Expected `B1`"),
    (lambda: path_residuals((0j, 1j), P22, ALPHA22), "Expected `design`"),
    (lambda: path_residuals((0j, 1j, 2 + 1j, 2 + 0j, 1 + 1j), P22, ALPHA22[:3]), "Expected `points` and `crank_angles`"),
])
def test_path_inputs_rejected(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_generated_path_dyad_residual_mpmath():
    """The generated (2-53) residual and gradient agree with a 50-digit geometric computation."""
    from mech._generated.path_generation import path_dyad_coefficients, path_dyad_residual

    rng = np.random.default_rng(11)
    mpmath.mp.dps = 50
    for _ in range(20):
        v = rng.uniform(-3, 3, 9)

        def direct(xA, yA, xB, yB, t):
            A, B1 = mpmath.mpc(xA, yA), mpmath.mpc(xB, yB)
            P1, Pi = mpmath.mpc(v[4], v[5]), mpmath.mpc(v[6], v[7])
            return abs(Pi + mpmath.expj(t) * (B1 - P1) - A) ** 2 - abs(B1 - A) ** 2

        got = path_dyad_residual(*v)
        x = [mpmath.mpf(float(s)) for s in (v[0], v[1], v[2], v[3], v[8])]
        want = [direct(*x)] + [mpmath.diff(direct, x, tuple(int(j == i) for j in range(5))) for i in range(5)]
        scale = 1 + max(abs(w) for w in want)
        assert max(abs(g - float(w)) for g, w in zip(got, want)) < 1e-13 * scale
        a1, a2, a3 = path_dyad_coefficients(*v[:8])
        assert abs(a1 * np.sin(v[8]) + a2 * np.cos(v[8]) - a3 - float(want[0])) < 1e-13 * scale
