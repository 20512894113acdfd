"""The eighth-order coupler curve of the spherical four-bar (monograph §2.1) and the planar
sextic: generated evaluator against coupler points built independently in mpmath at 50
digits, exact degrees, great-circle intersections, the mirrored triangle, the planar limit.
"""

import mpmath
import numpy as np
import pytest

from mech.planar import FourBar, coupler_sextic
from mech.spherical import (CouplerOctic, SphericalFourBar, coupler_octic, coupler_quartic, ground_frame,
                            nine_parameters, to_xyz)

DPS = 50


# ----------------------------------------------------------------------------- independent routes
def _mp_rot(axis, t):
    c, s = mpmath.cos(t), mpmath.sin(t)
    if axis == "z":
        return mpmath.matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    return mpmath.matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def _mp_frame(lon, lat, heading):
    """ground_frame by rotations: R = Rz(lon) Ry(pi/2 - lat) Rz(heading), then checked below."""
    return _mp_rot("z", lon) * _mp_rot("y", mpmath.pi / 2 - lat) * _mp_rot("z", heading)


def _mp_coupler_points(params, thetas, sigma):
    """Coupler points at 50 digits: frames by rotations, C by Newton on B.C = cos b.

    A different route from the derivation's (no linear system, no Cramer): B and the
    output pin C are rotations of the pole, psi is found by mpmath.findroot from the
    double-precision package solution, and P is the rotation of the pole by
    Rz(theta) Ry(a) Rz(phi + gamma) Ry(r) with phi read from C in the frame at B.
    """
    lon, lat, heading, a, b, c, d, r, gamma = (mpmath.mpf(float(v)) for v in params)
    frame = _mp_frame(lon, lat, heading)
    ez = mpmath.matrix([0, 0, 1])
    fb = SphericalFourBar(*(float(v) for v in params[3:7]), branch=sigma, coupler=(float(r), float(gamma)))
    out = []
    for t in thetas:
        start = fb.solve(float(t))
        if not bool(start.valid):
            continue
        t = mpmath.mpf(float(t))
        B = _mp_rot("z", t) * _mp_rot("y", a) * ez

        def closure(psi):
            C = _mp_rot("y", d) * _mp_rot("z", psi) * _mp_rot("y", c) * ez
            return (B.T * C)[0] - mpmath.cos(b)

        psi = mpmath.findroot(closure, mpmath.mpf(float(start.psi)))
        C = _mp_rot("y", d) * _mp_rot("z", psi) * _mp_rot("y", c) * ez
        frame_B = _mp_rot("z", t) * _mp_rot("y", a)
        local = frame_B.T * C
        phi = mpmath.atan2(local[1], local[0])
        P = frame_B * _mp_rot("z", phi + gamma) * _mp_rot("y", r) * ez
        out.append(frame * P)
    return out


def _random_params(rng):
    return np.array([rng.uniform(-3, 3), rng.uniform(-1.5, 1.5), rng.uniform(-3, 3),
                     *rng.uniform(0.2, 2.9, 4), rng.uniform(0.1, 2.5), rng.uniform(-3, 3)])


# ----------------------------------------------------------------------------- tests
def test_mp_frame_is_ground_frame():
    with mpmath.workdps(DPS):
        R = _mp_frame(mpmath.mpf(0.3), mpmath.mpf(0.2), mpmath.mpf(1.0))
        got = np.array([[float(R[i, j]) for j in range(3)] for i in range(3)])
    assert np.allclose(got, ground_frame(0.3, 0.2, 1.0), atol=1e-15)


@pytest.mark.parametrize("seed", range(6))
def test_coupler_octic_mpmath_points_random_placement(seed):
    """Monograph §2.1: points built at 50 digits lie on the generated octic and quartic to
    1e-10 of |grad| (random placement, both branches, the cone and the antipode)."""
    rng = np.random.default_rng(1400 + seed)
    params = _random_params(rng)
    worst, count = 0.0, 0
    with mpmath.workdps(DPS):
        for sigma in (1, -1):
            pts = _mp_coupler_points(params, np.linspace(0, 2 * np.pi, 17)[:-1], sigma)
            if not pts:
                continue
            P = np.array([[float(p[i]) for i in range(3)] for p in pts])
            for f in (coupler_octic, coupler_quartic):
                value, grad = f(params, P)
                worst = max(worst, float(np.max(np.abs(value) / np.linalg.norm(grad, axis=-1))))
            value, grad = coupler_octic(params, -2.5 * P)          # the cone and the antipode
            worst = max(worst, float(np.max(np.abs(value) / np.linalg.norm(grad, axis=-1))))
            count += len(P)
    assert count > 0
    assert worst < 1e-10, worst


def test_coupler_octic_broadcasts_many_linkages():
    rng = np.random.default_rng(7)
    params = np.array([_random_params(rng) for _ in range(5)])
    P = to_xyz(rng.uniform(-3, 3, (4, 5)), rng.uniform(-1.5, 1.5, (4, 5)))
    value, grad = coupler_octic(params, P)
    assert value.shape == (4, 5) and grad.shape == (4, 5, 3)
    one = np.array([coupler_octic(params[j], P[i, j])[0] for i in range(4) for j in range(5)]).reshape(4, 5)
    assert np.allclose(value, one, rtol=1e-13, atol=0)


def test_coupler_octic_homogeneous_degree_exactly_8():
    """F(t x) = t**8 F(x), and F restricted to a line is a polynomial of degree exactly 8."""
    rng = np.random.default_rng(8)
    params = _random_params(rng)
    x = rng.normal(size=3)
    for t in (0.3, 2.0, -1.7):
        assert np.isclose(coupler_octic(params, t * x)[0], t**8 * coupler_octic(params, x)[0], rtol=1e-12)
    v = rng.normal(size=3)
    s = np.linspace(-1, 1, 40)
    values = coupler_octic(params, x + s[:, None] * v)[0]
    coef = np.polynomial.polynomial.polyfit(s, values, 10)
    scale = np.max(np.abs(coef))
    assert abs(coef[8]) > 1e-6 * scale
    assert abs(coef[9]) < 1e-9 * scale and abs(coef[10]) < 1e-9 * scale


def test_coupler_sextic_degree_exactly_6_and_planar_points():
    rng = np.random.default_rng(9)
    m = FourBar(1.0, 3.5, 3.0, 3.2, coupler=(1.5, 0.8))
    P = m.solve(np.linspace(0, 2 * np.pi, 30)).P
    value, grad = coupler_sextic(m, P)
    assert np.all(np.abs(value) < 1e-10 * np.abs(grad))
    z0, v = complex(*rng.normal(size=2)), complex(*rng.normal(size=2))
    s = np.linspace(-1, 1, 40)
    values = coupler_sextic([0.2, -0.1, 0.4, 1.0, 3.5, 3.0, 3.2, 1.5, 0.8], z0 + s * v)[0]
    coef = np.polynomial.polynomial.polyfit(s, values, 8)
    scale = np.max(np.abs(coef))
    assert abs(coef[6]) > 1e-6 * scale and abs(coef[7]) < 1e-9 * scale and abs(coef[8]) < 1e-9 * scale


def test_coupler_sextic_placed_mirrors_planar_points():
    """The placed sextic vanishes on the moved coupler points, and not on the mirrored ones."""
    m = FourBar(1.0, 3.5, 3.0, 3.2, coupler=(1.5, 0.8))
    x0, heading = 0.7 - 0.4j, 0.9
    P = x0 + np.exp(1j * heading) * m.solve(np.linspace(0, 2 * np.pi, 25)).P
    linkage = [x0.real, x0.imag, heading, 1.0, 3.5, 3.0, 3.2, 1.5, 0.8]
    value, grad = coupler_sextic(linkage, P)
    assert np.all(np.abs(value) < 1e-10 * np.abs(grad))
    mirrored = FourBar(1.0, 3.5, 3.0, 3.2, coupler=(1.5, -0.8)).solve(np.linspace(0, 2 * np.pi, 25)).P
    value, grad = coupler_sextic(m, mirrored)
    assert np.max(np.abs(value) / np.abs(grad)) > 1e-2


@pytest.mark.parametrize("seed", range(5))
def test_great_circle_meets_curve_at_most_8_times(seed):
    """Sign changes of Q along a great circle: at most 8, and as many as the parametric
    curve of monograph §2.3 (both branches) crosses the plane of that circle."""
    rng = np.random.default_rng(1410 + seed)
    params = _random_params(rng)
    frame = ground_frame(*params[:3])
    normal = rng.normal(size=3)
    normal /= np.linalg.norm(normal)
    u = np.cross(normal, rng.normal(size=3))
    u /= np.linalg.norm(u)
    v = np.cross(normal, u)
    t = np.linspace(0, 2 * np.pi, 200001)
    circle = np.cos(t)[:, None] * u + np.sin(t)[:, None] * v
    q = coupler_quartic(params, circle)[0]
    roots = int(np.count_nonzero(np.sign(q[1:]) != np.sign(q[:-1])))
    crossings = 0
    for branch in (1, -1):
        fb = SphericalFourBar(*params[3:7], branch=branch, coupler=tuple(params[7:]), frame=frame)
        _, P = fb.coupler_curve(40001)
        side = np.sign(P @ normal)
        ok = np.isfinite(side[1:]) & np.isfinite(side[:-1])
        crossings += int(np.count_nonzero(side[1:][ok] != side[:-1][ok]))
    assert roots <= 8
    # a branch with limit positions traces its circuit back and forth on the two branches:
    # each real intersection is counted once by the pair of branches
    assert roots == crossings, (roots, crossings)


def test_mirrored_coupler_triangle_is_another_curve():
    """The point on the other side of BC, (r, -gamma), is off the curve of (r, gamma)."""
    m = SphericalFourBar(0.5, 1.1, 0.9, 1.2, coupler=(0.6, 0.8))
    mirror = SphericalFourBar(0.5, 1.1, 0.9, 1.2, coupler=(0.6, -0.8))
    P = mirror.solve(np.linspace(0, 2 * np.pi, 40)).P
    value, grad = m.coupler_curve_polynomial()(P)
    assert np.max(np.abs(value) / np.linalg.norm(grad, axis=-1)) > 1e-2
    value, grad = mirror.coupler_curve_polynomial()(P)
    assert np.max(np.abs(value) / np.linalg.norm(grad, axis=-1)) < 1e-12


def test_nine_parameters_roundtrip():
    rng = np.random.default_rng(11)
    for _ in range(5):
        params = _random_params(rng)
        m = SphericalFourBar(*params[3:7], coupler=tuple(params[7:]), frame=ground_frame(*params[:3]))
        got = nine_parameters(m)
        assert np.allclose(ground_frame(*got[:3]), ground_frame(*params[:3]), atol=1e-13)
        assert np.allclose(got[3:], params[3:])
    curve = CouplerOctic(m)
    theta = np.linspace(0, 2 * np.pi, 9)
    P = m.solve(theta).P[m.solve(theta).valid]
    lon = np.arctan2(P[:, 1], P[:, 0])
    lat = np.arcsin(P[:, 2])
    assert np.all(np.abs(curve.lonlat(lon, lat)) < 1e-12)


# ----------------------------------------------------------------------------- planar limit
def _mp_quartic(X, a, b, c, d, r, g):
    """Q by solving the 3x3 system (2) numerically in mpmath: Q = det(M)**2 (|B|**2 - 1)."""
    A = mpmath.matrix([0, 0, 1])
    D = mpmath.matrix([mpmath.sin(d), 0, mpmath.cos(d)])
    DX = mpmath.matrix([D[1] * X[2] - D[2] * X[1], D[2] * X[0] - D[0] * X[2], D[0] * X[1] - D[1] * X[0]])
    w = (mpmath.sin(r) * mpmath.cos(b) - mpmath.sin(b) * mpmath.cos(g) * mpmath.cos(r)) * D \
        + mpmath.sin(b) * mpmath.sin(g) * DX
    M = mpmath.matrix([[A[i] for i in range(3)], [X[i] for i in range(3)], [w[i] for i in range(3)]])
    h = mpmath.matrix([mpmath.cos(a), mpmath.cos(r),
                       mpmath.sin(r) * mpmath.cos(c) - mpmath.sin(b) * mpmath.cos(g) * (D.T * X)[0]])
    B = mpmath.lu_solve(M, h)
    return mpmath.det(M) ** 2 * ((B.T * B)[0] - 1)


LINKAGE = (1.0, 3.5, 3.0, 3.2)
R0, G0, X0, Y0 = 1.7, 0.49, 1.3, 2.1


def _limit_target():
    S, _ = coupler_sextic([0, 0, 0, *LINKAGE, R0 * np.cos(G0), R0 * np.sin(G0)], X0 + 1j * Y0)
    b, d = LINKAGE[1], LINKAGE[3]
    ell = 4 * ((b * X0 - d * (b - R0 * np.cos(G0))) ** 2 + (b * Y0 + d * R0 * np.sin(G0)) ** 2)
    return ell * float(S) / (16 * R0**2)


@pytest.mark.parametrize("scale", [1e-2, 1e-3, 1e-4, 1e-5, 1e-6])
def test_octic_tends_to_sextic(scale):
    """F(eps X, eps Y, 1) / eps**12 -> ell S / (16 r**2) at the rate eps**2 (eq. (6); 50 eps**2 here): the
    octic at 60 digits by numeric elimination, the sextic from the generated planar code."""
    target = _limit_target()
    with mpmath.workdps(60):
        e = mpmath.mpf(scale)
        X = mpmath.matrix([e * X0, e * Y0, 1])
        rho = mpmath.norm(X)
        args = [e * v for v in LINKAGE] + [e * R0, mpmath.mpf(G0)]
        F = rho**8 * _mp_quartic(X / rho, *args) * _mp_quartic(-X / rho, *args)
        gap = abs(float(F / e**12) / target - 1)
    assert 10 * scale**2 < gap < 100 * scale**2, gap        # the O(eps**2) rate, measured 50 eps**2


@pytest.mark.parametrize("scale, tol", [(1e-2, 1e-2), (1e-3, 1e-4), (1e-4, 1e-6), (1e-5, 1e-3), (1e-6, 3e-2)])
def test_generated_octic_tends_to_sextic_in_double(scale, tol):
    """The direct double-precision octic (eq. (4)): the limit gap is eps**2 until rounding takes
    over (F ~ eps**12 from O(1) terms: about 1e-16 / eps**2.3 relative, 4e-3 at 1e-6)."""
    args = [scale * v for v in LINKAGE] + [scale * R0, G0]
    F, _ = coupler_octic([0.0, np.pi / 2, 0.0, *args], [scale * X0, scale * Y0, 1.0], form="direct")
    gap = abs(float(F) / scale**12 / _limit_target() - 1)
    assert gap < tol, gap


def test_coupler_octic_rejects_bad_input():
    with pytest.raises(ValueError, match="Expected `linkage` of shape"):
        coupler_octic([1.0, 2.0], [0, 0, 1])
    with pytest.raises(ValueError, match="arcs a, b, c, d of `linkage`"):
        coupler_octic([0, 0, 0, 0.5, 4.0, 0.9, 1.2, 0.6, 0.8], [0, 0, 1])
    with pytest.raises(ValueError, match="Expected `points` of shape"):
        coupler_octic([0, 0, 0, 0.5, 1.0, 0.9, 1.2, 0.6, 0.8], [0, 1])
    with pytest.raises(ValueError, match="`points` small enough"):
        coupler_octic([0, 0, 0, 0.5, 1.0, 0.9, 1.2, 0.6, 0.8], [0, 1e300, 1])
    with pytest.raises(ValueError, match="Expected non-zero `points`"):
        coupler_octic([0, 0, 0, 0.5, 1.0, 0.9, 1.2, 0.6, 0.8], [0.0, 0.0, 0.0])


def test_coupler_quartic_takes_directions_and_octic_factors_on_sphere():
    """On the unit sphere F(x) = Q(x) Q(-x) (eq. (4)); off it Q is evaluated at x / |x|."""
    rng = np.random.default_rng(12)
    params = _random_params(rng)
    P = to_xyz(rng.uniform(-3, 3, 20), rng.uniform(-1.5, 1.5, 20))
    F = coupler_octic(params, P)[0]
    assert np.allclose(F, coupler_quartic(params, P)[0] * coupler_quartic(params, -P)[0], rtol=1e-10, atol=0)
    # 2 and 2**-1000 are powers of two: x / |x| is then the same float vector
    for s in (2.0, 2.0**-1000, 2.0**1000):
        assert np.array_equal(coupler_quartic(params, s * P)[0], coupler_quartic(params, P)[0])


# ----------------------------------------------------------------------------- the gradient
def _mp_octic_placed(params, x):
    """F at 50 digits by another route: the placement by rotations (_mp_frame), the quartic by
    solving the 3x3 system (2) numerically (_mp_quartic), then F = |x|**8 Q(x^) Q(-x^)."""
    lon, lat, heading, a, b, c, d, r, gamma = (mpmath.mpf(float(v)) for v in params)
    frame = _mp_frame(lon, lat, heading)
    std = frame.T * mpmath.matrix(x)
    rho = mpmath.norm(std)
    unit = std / rho
    return rho**8 * _mp_quartic(unit, a, b, c, d, r, gamma) * _mp_quartic(-unit, a, b, c, d, r, gamma)


def _mp_quartic_placed(params, x):
    lon, lat, heading, a, b, c, d, r, gamma = (mpmath.mpf(float(v)) for v in params)
    return _mp_quartic(_mp_frame(lon, lat, heading).T * mpmath.matrix(x), a, b, c, d, r, gamma)


def _mp_central_gradient(function, params, x, h=mpmath.mpf(10) ** -15):
    """Central differences of `function` at the point x (mpmath), step h: error O(h**2)."""
    x = [mpmath.mpf(float(v)) for v in x]
    grad = []
    for k in range(3):
        up, down = list(x), list(x)
        up[k] += h
        down[k] -= h
        grad.append((function(params, up) - function(params, down)) / (2 * h))
    return np.array([float(g) for g in grad])


@pytest.mark.parametrize("form", ["direct", "scaled"])
@pytest.mark.parametrize("seed", range(4))
def test_coupler_octic_gradient_central_differences(seed, form):
    """The generated gradient of F (eq. (4), or eqs. (7)-(9) on A's half of the sphere) and
    of Q (at the direction of the point) against central differences of F at 50 digits
    computed by another route (numeric elimination, rotations), for random linkages in
    arbitrary placement, at points off the curve (any length) and on it: relative 1e-9."""
    rng = np.random.default_rng(1420 + seed)
    params = _random_params(rng)
    points = list(rng.normal(size=(4, 3)) * rng.uniform(0.5, 2.0, (4, 1)))
    with mpmath.workdps(DPS):
        on_curve = _mp_coupler_points(params, rng.uniform(0, 2 * np.pi, 6), 1)
        on_curve += _mp_coupler_points(params, rng.uniform(0, 2 * np.pi, 6), -1)
        points += [np.array([float(p[i]) for i in range(3)]) for p in on_curve[:4]]
        worst_F = worst_Q = 0.0
        for x in points:
            _, grad = coupler_octic(params, x, form=form)
            reference = _mp_central_gradient(_mp_octic_placed, params, x)
            worst_F = max(worst_F, float(np.linalg.norm(grad - reference) / np.linalg.norm(reference)))
            # Q and its gradient are taken at the direction x / |x| (Q means the curve on the sphere)
            _, grad = coupler_quartic(params, x)
            reference = _mp_central_gradient(_mp_quartic_placed, params, x / np.linalg.norm(x))
            worst_Q = max(worst_Q, float(np.linalg.norm(grad - reference) / np.linalg.norm(reference)))
    assert len(points) >= 6
    assert worst_F < 1e-9 and worst_Q < 1e-9, (worst_F, worst_Q)


def test_coupler_octic_gradient_euler_relation():
    """F is homogeneous of degree 8: x . grad F = 8 F (Euler), an identity the generated
    gradient must keep."""
    rng = np.random.default_rng(1430)
    params = _random_params(rng)
    x = rng.normal(size=(50, 3)) * rng.uniform(0.3, 3.0, (50, 1))
    value, grad = coupler_octic(params, x)
    scale = np.linalg.norm(grad, axis=-1) * np.linalg.norm(x, axis=-1)
    assert np.max(np.abs(np.sum(x * grad, axis=-1) - 8 * value) / scale) < 1e-12


# ----------------------------------------------------------------------------- small linkages
def _mp_octic_at(arcs, gamma, x, frame=None):
    """F at the exact double vector x, 60 digits, by numeric elimination (_mp_quartic); the
    frame (a double matrix, taken as exact) maps the standard frame to the ground frame."""
    with mpmath.workdps(60):
        X = mpmath.matrix([v if isinstance(v, mpmath.mpf) else mpmath.mpf(float(v)) for v in x])
        if frame is not None:
            X = mpmath.matrix([[mpmath.mpf(float(frame[i, j])) for i in range(3)] for j in range(3)]) * X
        rho = mpmath.norm(X)
        args = [mpmath.mpf(float(v)) for v in arcs] + [mpmath.mpf(float(gamma))]
        return rho**8 * _mp_quartic(X / rho, *args) * _mp_quartic(-X / rho, *args)


def _mp_gradient_at(arcs, gamma, x, h, frame=None):
    with mpmath.workdps(60):
        x = [mpmath.mpf(float(v)) for v in x]
        grad = []
        for k in range(3):
            up, down = list(x), list(x)
            up[k] += h
            down[k] -= h
            grad.append((_mp_octic_at(arcs, gamma, up, frame) - _mp_octic_at(arcs, gamma, down, frame)) / (2 * h))
        return np.array([float(g) for g in grad])


def _small_linkage(rng, scale):
    """A random assemblable four-bar with every arc of order `scale`, and its coupler point."""
    while True:
        hats = rng.uniform(0.3, 1.0, 5)
        try:
            m = SphericalFourBar(*(scale * hats[:4]), coupler=(scale * hats[4], rng.uniform(-3, 3)))
        except ValueError:
            continue
        if m.assembly_range().intervals.size or m.assembly_range().full_turn:
            return m


@pytest.mark.parametrize("scale", [1e-2, 1e-4, 1e-6, 1e-8])
def test_coupler_octic_small_against_60_digits(scale):
    """Eqs. (7)-(9): at points near a linkage of size eps (its own frame), on its curve and
    off it, the double-precision F agrees with a 60-digit evaluation by numeric elimination
    to 1e-12 of |grad F| eps (a distance relative to the size), off the curve to 1e-12
    relative, and so does its gradient (central differences at 60 digits)."""
    rng = np.random.default_rng(int(-np.log10(scale)) + 1440)
    m = _small_linkage(rng, scale)
    arcs, gamma = (m.a, m.b, m.c, m.d, m.coupler[0]), m.coupler[1]
    off = [np.array([scale * X, scale * Y, 1.0]) for X, Y in rng.uniform(-2, 2, (4, 2))]
    theta = rng.uniform(0, 2 * np.pi, 40)
    pose = m.solve(theta)
    on = list(pose.P[pose.valid][:4])
    assert len(on) >= 2
    worst_distance = worst_value = worst_grad = 0.0
    for x in off + on:
        value, grad = coupler_octic(m, x)
        ref = _mp_octic_at(arcs, gamma, x)
        ref_grad = _mp_gradient_at(arcs, gamma, x, mpmath.mpf(scale) * mpmath.mpf(10) ** -20)
        g = np.linalg.norm(ref_grad)
        worst_distance = max(worst_distance, abs(float(value - ref)) / (g * scale))
        worst_grad = max(worst_grad, float(np.linalg.norm(grad - ref_grad) / g))
        if any(x is o for o in off):
            worst_value = max(worst_value, abs(float(value / ref) - 1))
    assert worst_distance < 1e-12 and worst_value < 1e-12 and worst_grad < 1e-12, \
        (worst_distance, worst_value, worst_grad)
    # the direct form (eq. (4)) at the same points, for contrast: it loses about 1 / eps**2
    if scale <= 1e-4:
        direct = max(abs(float(coupler_octic(m, x, form="direct")[0] / _mp_octic_at(arcs, gamma, x)) - 1) for x in off)
        assert direct > 1e3 * max(worst_value, 1e-16)


@pytest.mark.parametrize("scale", [1e-2, 1e-5, 1e-8])
def test_coupler_octic_small_random_placement(scale):
    """A small linkage placed anywhere: the point's own rounding (its coordinates are of order
    one) limits any evaluation to about 1e-16 / eps of the size; the scaled form reaches
    that floor (measured against 60 digits at the exact double inputs)."""
    rng = np.random.default_rng(int(-np.log10(scale)) + 1450)
    m0 = _small_linkage(rng, scale)
    R = ground_frame(rng.uniform(-3, 3), rng.uniform(-1.5, 1.5), rng.uniform(-3, 3))
    m = SphericalFourBar(m0.a, m0.b, m0.c, m0.d, coupler=m0.coupler, frame=R)
    arcs, gamma = (m.a, m.b, m.c, m.d, m.coupler[0]), m.coupler[1]
    points = [R @ np.array([scale * X, scale * Y, 1.0]) for X, Y in rng.uniform(-2, 2, (4, 2))]
    worst = 0.0
    for x in points:
        value, _ = coupler_octic(m, x)
        ref_grad = _mp_gradient_at(arcs, gamma, x, mpmath.mpf(scale) * mpmath.mpf(10) ** -20, frame=R)
        worst = max(worst, abs(float(value - _mp_octic_at(arcs, gamma, x, frame=R))) / (np.linalg.norm(ref_grad) * scale))
    assert worst < 1e-12 + 1e-15 / scale, worst


@pytest.mark.parametrize("scale", [1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8])
def test_coupler_octic_small_tends_to_planar_sextic(scale):
    """Eq. (6) in double precision through the scaled form: F(eps X, eps Y, 1) / eps**12
    -> ell S / (16 r**2) with S from mech.planar.coupler_sextic, at the rate 50 eps**2 (the
    60-digit rate of test_octic_tends_to_sextic) and to 1e-12 below eps = 1e-6."""
    m = SphericalFourBar(*(scale * np.array(LINKAGE)), coupler=(scale * R0, G0))
    F, _ = coupler_octic(m, [scale * X0, scale * Y0, 1.0])
    gap = abs(float(F) / scale**12 / _limit_target() - 1)
    assert gap < 100 * scale**2 + 1e-12, gap
    if scale >= 1e-5:
        assert gap > 10 * scale**2, gap


def test_coupler_octic_forms_agree_and_choose():
    """The forms agree for a mid-sized linkage; "auto" takes the scaled form only for small
    linkages and only on A's half of the sphere; bad options are named."""
    rng = np.random.default_rng(1460)
    params = np.array([0.4, 0.3, -1.0, 0.05, 0.09, 0.08, 0.1, 0.06, 0.7])
    x = rng.normal(size=(200, 3))
    direct = coupler_octic(params, x, form="direct")
    scaled = coupler_octic(params, x, form="scaled")
    auto = coupler_octic(params, x)
    size = np.linalg.norm(direct[1], axis=-1) * np.linalg.norm(x, axis=-1)
    assert np.max(np.abs(direct[0] - scaled[0]) / size) < 1e-12
    assert np.max(np.linalg.norm(direct[1] - scaled[1], axis=-1) / np.linalg.norm(direct[1], axis=-1)) < 1e-11
    assert np.array_equal(auto[0], scaled[0])
    far = coupler_octic(params, x, small=0.01)                  # the linkage is larger than `small`
    assert np.array_equal(far[0], direct[0])
    curve = SphericalFourBar(0.05, 0.09, 0.08, 0.1, coupler=(0.06, 0.7)).coupler_curve_polynomial()
    assert curve(x, form="direct")[0].shape == (200,)
    with pytest.raises(ValueError, match="Expected `form`"):
        coupler_octic(params, x, form="bogus")
    with pytest.raises(ValueError, match="Expected `small` >= 0"):
        coupler_octic(params, x, small=-1.0)
