"""The spherical calculus (monograph chapter 1) against 50-digit mpmath computations by
other routes: explicit products of elementary rotations for frames and turns, arccos and
arcsin on exactly normalised vectors (well conditioned at 50 digits), Cramer's rule for the
circle through three points; plus pairs of points deliberately at arcs below 1e-6 and above
pi - 1e-6, and the planar limits near the north pole."""

import mpmath
import numpy as np
import pytest

from mech.spherical._circles import (angle_between, bisector, circle_through, collinearity,
                                     distance_to_great_circle, great_circle_at,
                                     great_circle_through, intersect)
from mech.spherical._coordinates import distance, distance_lonlat, from_xyz, local_frame, to_xyz
from mech.spherical._rigid_body import (angle_at, inclination, point_at, rotate_about,
                                        rotation_matrix, tangent, triangle_point, turn, velocity)

mpmath.mp.dps = 50
TOL = 1e-13
SMALL_ARCS = [1e-7, 3.3e-8, 5e-9, 9e-7]
rng = np.random.default_rng(20261122)


# ---------------------------------------------------------------- 50-digit helpers
def mpv(v):
    """Exact mpf copy of a double vector."""
    return [mpmath.mpf(float(x)) for x in v]


def mdot(u, v):
    return sum(x * y for x, y in zip(u, v))


def mcross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


def munit(u):
    n = mpmath.sqrt(mdot(u, u))
    return [x / n for x in u]


def mlonlat(p):
    p = munit(p)
    rho = mpmath.sqrt(p[0] ** 2 + p[1] ** 2)
    lon = mpmath.atan2(p[1], p[0]) if rho > 0 else mpmath.mpf(0)
    return lon, mpmath.asin(p[2])


def rz(t):
    return mpmath.matrix([[mpmath.cos(t), -mpmath.sin(t), 0], [mpmath.sin(t), mpmath.cos(t), 0], [0, 0, 1]])


def ry(t):
    return mpmath.matrix([[mpmath.cos(t), 0, mpmath.sin(t)], [0, 1, 0], [-mpmath.sin(t), 0, mpmath.cos(t)]])


def placement(p):
    """The rotation Rz(lon) Ry(pi/2 - lat) taking the north pole to p and its x, y axes to
    the local frame of p: built from elementary rotations, not from the frame formula."""
    lon, lat = mlonlat(p)
    return rz(lon) * ry(mpmath.pi / 2 - lat)


def mvec(matrix, v):
    out = matrix * mpmath.matrix(v)
    return [out[i] for i in range(3)]


def m_inclination(a, b):
    """Inclination by the placement route: carry b to the north-pole frame and take its angle."""
    local = mvec(placement(a).T, munit(b))
    return mpmath.atan2(local[1], local[0])


def m_arc(p, q):
    """acos of the exactly normalised dot product: well conditioned at 50 digits."""
    return mpmath.acos(mdot(munit(p), munit(q)))


def wrap(x):
    return (x + np.pi) % (2 * np.pi) - np.pi


def random_points(n):
    v = rng.normal(size=(n, 3))
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def near_pair(arc, antipodal=False):
    """A double point p and q rounded from the point at exactly `arc` (or pi - arc) from p."""
    p = random_points(1)[0]
    t = np.cross(p, random_points(1)[0])
    pm, tm = munit(mpv(p)), munit(mpv(t))
    s = mpmath.pi - mpmath.mpf(arc) if antipodal else mpmath.mpf(arc)
    q = np.array([float(mpmath.cos(s) * x + mpmath.sin(s) * y) for x, y in zip(pm, tm)])
    return p, q


def near_pairs():
    pairs = [near_pair(s) for s in SMALL_ARCS] + [near_pair(s, True) for s in SMALL_ARCS]
    return [(p, q) for p, q in pairs] + [tuple(random_points(2)) for _ in range(20)]


# ---------------------------------------------------------------- coordinates
def test_to_xyz_mpmath():
    lon, lat = rng.uniform(-3.1, 3.1, 30), rng.uniform(-1.57, 1.57, 30)
    got = to_xyz(lon, lat)
    for i in range(30):
        ref = mvec(rz(lon[i]) * ry(-lat[i]), [1, 0, 0])
        assert np.allclose(got[i], [float(x) for x in ref], rtol=0, atol=TOL)


def test_from_xyz_roundtrip():
    lon, lat = rng.uniform(-3.1, 3.1, 50), rng.uniform(-1.5, 1.5, 50)
    lon2, lat2 = from_xyz(to_xyz(lon, lat))
    assert np.allclose(lon2, lon, atol=TOL) and np.allclose(lat2, lat, atol=TOL)


def test_from_xyz_poles_lon_zero():
    lon, lat = from_xyz([[0.0, 0.0, 1.0], [-0.0, -0.0, -3.0], [-0.0, 0.0, 2.0]])
    assert np.array_equal(lon, [0.0, 0.0, 0.0])
    assert np.array_equal(lat, [np.pi / 2, -np.pi / 2, np.pi / 2])


def test_from_xyz_near_pole_mpmath():
    for arc in SMALL_ARCS:
        v = np.array([arc * 0.6, -arc * 0.8, 1.0])
        lon, lat = from_xyz(v)
        ref_lon, ref_lat = mlonlat(mpv(v))
        assert abs(lon - float(ref_lon)) < TOL
        # atan2 keeps lat correct to its last bit; arcsin(z) would lose half the digits
        assert abs(lat - float(ref_lat)) < 4.5e-16


def test_local_frame_mpmath():
    pts = np.vstack([random_points(20), [[0, 0, 1.0], [0, 0, -1.0], [1e-9, 0, 1.0]]])
    ex, ey = local_frame(pts)
    for i, p in enumerate(pts):
        m = placement(mpv(p))
        assert np.allclose(ex[i], [float(m[j, 0]) for j in range(3)], atol=TOL)
        assert np.allclose(ey[i], [float(m[j, 1]) for j in range(3)], atol=TOL)
    assert np.allclose(np.cross(ex, ey), pts / np.linalg.norm(pts, axis=-1, keepdims=True), atol=TOL)


# ---------------------------------------------------------------- distance
def test_distance_random_and_extreme_arcs_mpmath():
    for p, q in near_pairs():
        ref = m_arc(mpv(p), mpv(q))
        assert abs(distance(p, q) - float(ref)) <= TOL * float(ref), (p, q)


def test_distance_near_pi_mpmath():
    for arc in SMALL_ARCS:
        p, q = near_pair(arc, antipodal=True)
        ref = m_arc(mpv(p), mpv(q))
        # pi - d is what is left of the information: compare it too (absolute, at 1e-16)
        assert abs(distance(p, q) - float(ref)) < 4e-16


def test_distance_arccos_fails_where_atan2_does_not():
    p, q = near_pair(1e-7)
    ref = float(m_arc(mpv(p), mpv(q)))
    naive = np.arccos(np.clip(p @ q, -1.0, 1.0))
    assert abs(naive - ref) / ref > 1e-6
    assert abs(distance(p, q) - ref) / ref < TOL


def test_distance_scale_free():
    assert distance([0, 0, 5.0], [0, 3.0, 3.0]) == pytest.approx(np.pi / 4, abs=TOL)


def test_distance_lonlat_agrees_with_distance():
    for p, q in near_pairs():
        lon1, lat1 = from_xyz(p)
        lon2, lat2 = from_xyz(q)
        ref = float(m_arc(mpv(to_xyz(lon1, lat1)), mpv(to_xyz(lon2, lat2))))
        got = distance_lonlat(lon1, lat1, lon2, lat2)
        assert abs(got - ref) <= 1e-12 * ref + 1e-15


def test_distance_lonlat_law_of_cosines_mpmath():
    lon1, lat1, lon2, lat2 = (rng.uniform(-1.5, 1.5, 20) for _ in range(4))
    got = distance_lonlat(lon1, lat1, lon2, lat2)
    for i in range(20):
        a, b, c, d = (mpmath.mpf(float(x[i])) for x in (lon1, lat1, lon2, lat2))
        ref = mpmath.acos(mpmath.sin(b) * mpmath.sin(d) + mpmath.cos(b) * mpmath.cos(d) * mpmath.cos(a - c))
        assert abs(got[i] - float(ref)) < TOL


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_distance_broadcast(shape):
    p = random_points(int(np.prod(shape))).reshape(shape + (3,))
    assert distance(p, [0.0, 0.0, 1.0]).shape == shape
    assert inclination([0.0, 0.0, 1.0], p).shape == shape
    assert circle_through(p, [1.0, 0, 0], [0, 1.0, 0]).radius.shape == shape


# ---------------------------------------------------------------- inclination, turning, triangle
def test_inclination_mpmath():
    for p, q in near_pairs():
        ref = m_inclination(mpv(p), mpv(q))
        assert abs(wrap(inclination(p, q) - float(ref))) < TOL, (p, q)


def test_inclination_planar_limit_at_pole():
    # at the north pole the inclination is the planar angle of the line AB
    for angle in (0.3, 2.0, -2.5):
        b = np.array([1e-5 * np.cos(angle), 1e-5 * np.sin(angle), 1.0])
        assert inclination([0, 0, 1.0], b) == pytest.approx(angle, abs=TOL)


def test_inclination_planar_limit_plus_longitude():
    eps = 1e-5
    za, zb = 0.3 + 0.4j, -0.5 + 0.9j
    a = np.array([eps * za.real, eps * za.imag, 1.0])
    b = np.array([eps * zb.real, eps * zb.imag, 1.0])
    lon_a, _ = from_xyz(a)
    assert wrap(inclination(a, b) + lon_a - np.angle(zb - za)) == pytest.approx(0.0, abs=1e-9)


def test_tangent_mpmath():
    for p, q in near_pairs():
        pm, qm = munit(mpv(p)), munit(mpv(q))
        t = munit([y - mdot(pm, qm) * x for x, y in zip(pm, qm)])
        assert np.allclose(tangent(p, q), [float(x) for x in t], atol=1e-12)


def test_point_at_mpmath():
    a = random_points(15)
    arcs = np.concatenate([rng.uniform(0.1, 3.0, 11), [1e-7, 5e-9, np.pi - 1e-7, 2.0]])
    incs = rng.uniform(-3.1, 3.1, 15)
    got = point_at(a, arcs, incs)
    for i in range(15):
        s, t = mpmath.mpf(float(arcs[i])), mpmath.mpf(float(incs[i]))
        local = [mpmath.sin(s) * mpmath.cos(t), mpmath.sin(s) * mpmath.sin(t), mpmath.cos(s)]
        ref = mvec(placement(mpv(a[i])), local)
        assert np.allclose(got[i], [float(x) for x in ref], atol=TOL)


def test_point_at_roundtrip_small_arcs():
    a = random_points(4)
    for arc in SMALL_ARCS:
        b = point_at(a, arc, 1.1)
        assert np.allclose(distance(a, b), arc, rtol=1e-9)
        assert np.allclose(inclination(a, b), 1.1, atol=1e-8)


def test_rotate_about_mpmath():
    axes, pts = random_points(10), random_points(10)
    angles = np.concatenate([rng.uniform(-3.1, 3.1, 8), [1e-9, -2e-8]])
    got = rotate_about(pts, axes, angles)
    for i in range(10):
        m = placement(mpv(axes[i]))
        ref = mvec(m * rz(mpmath.mpf(float(angles[i]))) * m.T, munit(mpv(pts[i])))
        assert np.allclose(got[i], [float(x) for x in ref], atol=TOL)


def test_rotation_matrix_proper():
    r = rotation_matrix(random_points(6), rng.uniform(-3, 3, 6))
    assert np.allclose(r @ np.swapaxes(r, -1, -2), np.eye(3), atol=TOL)
    assert np.allclose(np.linalg.det(r), 1.0, atol=TOL)


def test_turn_keeps_arc_and_adds_inclination():
    a, b = random_points(10), random_points(10)
    g = rng.uniform(-3, 3, 10)
    b2 = turn(a, b, g)
    assert np.allclose(distance(a, b2), distance(a, b), atol=TOL)
    assert np.allclose(wrap(inclination(a, b2) - inclination(a, b) - g), 0.0, atol=1e-12)


def test_angle_at_mpmath():
    a, b, c = random_points(20), random_points(20), random_points(20)
    got = angle_at(a, b, c)
    for i in range(20):
        ref = m_inclination(mpv(a[i]), mpv(c[i])) - m_inclination(mpv(a[i]), mpv(b[i]))
        assert abs(wrap(got[i] - float(ref))) < TOL


def test_angle_at_tiny_triangle_mpmath():
    for arc in SMALL_ARCS:
        a = random_points(1)[0]
        b, c = point_at(a, arc, 0.4), point_at(a, 2 * arc, 1.9)
        ref = m_inclination(mpv(a), mpv(c)) - m_inclination(mpv(a), mpv(b))
        assert abs(wrap(angle_at(a, b, c) - float(ref))) < 1e-11


def test_angle_at_planar_limit():
    eps = 1e-5
    za, zb, zc = 0.2 + 0.1j, 1.0 - 0.3j, -0.4 + 0.8j
    pts = [np.array([eps * z.real, eps * z.imag, 1.0]) for z in (za, zb, zc)]
    assert angle_at(*pts) == pytest.approx(np.angle((zc - za) / (zb - za)), abs=1e-9)


def test_triangle_point_mpmath():
    a, b = random_points(10), random_points(10)
    g, s = rng.uniform(-3, 3, 10), rng.uniform(0.05, 3.0, 10)
    c = triangle_point(a, b, g, s)
    for i in range(10):
        ref_inc = m_inclination(mpv(a[i]), mpv(b[i])) + mpmath.mpf(float(g[i]))
        local = [mpmath.sin(s[i]) * mpmath.cos(ref_inc), mpmath.sin(s[i]) * mpmath.sin(ref_inc), mpmath.cos(s[i])]
        ref = mvec(placement(mpv(a[i])), local)
        assert np.allclose(c[i], [float(x) for x in ref], atol=TOL)
    assert np.allclose(wrap(angle_at(a, b, c) - g), 0.0, atol=1e-12)


def test_velocity_planar_limit():
    eps, omega, z = 1e-6, 2.5, 0.7 - 0.2j
    p = np.array([eps * z.real, eps * z.imag, 1.0])
    v = velocity([0.0, 0.0, omega], p) / eps
    assert v[0] + 1j * v[1] == pytest.approx(1j * omega * z, abs=1e-9)


# ---------------------------------------------------------------- circles
def test_great_circle_through_mpmath():
    for p, q in near_pairs():
        ref = munit(mcross(munit(mpv(p)), munit(mpv(q))))
        circle = great_circle_through(p, q)
        assert np.allclose(circle.pole, [float(x) for x in ref], atol=1e-12)
        assert circle.radius == np.pi / 2


def test_great_circle_at_passes_and_heads():
    a = random_points(8)
    inc = rng.uniform(-3, 3, 8)
    pole = great_circle_at(a, inc).pole
    assert np.allclose(np.sum(pole * a, axis=-1), 0.0, atol=TOL)
    b = point_at(a, 0.5, inc)
    assert np.allclose(distance_to_great_circle(b, pole), 0.0, atol=TOL)
    assert np.allclose(inclination(a, b), inc, atol=1e-12)


def test_distance_to_great_circle_mpmath():
    p, n = random_points(20), random_points(20)
    got = distance_to_great_circle(p, n)
    for i in range(20):
        ref = mpmath.asin(mdot(munit(mpv(p[i])), munit(mpv(n[i]))))
        assert abs(got[i] - float(ref)) < TOL


def test_collinearity_mpmath():
    a, b, c = random_points(10), random_points(10), random_points(10)
    r = collinearity(a, b, c)
    for i in range(10):
        am, bm, cm = (munit(mpv(x[i])) for x in (a, b, c))
        det = mpmath.det(mpmath.matrix([am, bm, cm]))
        ref = mpmath.asin(det / mpmath.sqrt(mdot(mcross(am, bm), mcross(am, bm))))
        assert abs(r.det[i] - float(det)) < TOL and abs(r.distance[i] - float(ref)) < TOL


def test_collinearity_points_on_a_great_circle():
    a, b = random_points(1)[0], random_points(1)[0]
    pole = great_circle_through(a, b).pole
    c = rotate_about(a, pole, 2.1)
    r = collinearity(a, b, c)
    assert abs(r.det) < 1e-15 and abs(r.distance) < 1e-15


def test_intersect_mpmath_and_inclination_relation():
    n1, n2 = random_points(10), random_points(10)
    x = intersect(n1, n2)
    for i in range(10):
        ref = munit(mcross(mpv(n1[i]), mpv(n2[i])))
        assert np.allclose(x.point[i], [float(v) for v in ref], atol=TOL)
        assert abs(x.angle[i] - float(m_arc(mpv(n1[i]), mpv(n2[i])))) < TOL
    # the angle of two great circles is the difference of their inclinations (eq. 11)
    t1 = x.point + np.cross(n1, x.point) * 1e-3
    t2 = x.point + np.cross(n2, x.point) * 1e-3
    diff = inclination(x.point, t2) - inclination(x.point, t1)
    assert np.allclose(wrap(diff - x.angle), 0.0, atol=1e-12)
    diff_back = inclination(x.antipode, -t2) - inclination(x.antipode, -t1)
    assert np.allclose(wrap(diff_back + x.angle), 0.0, atol=1e-12)
    assert np.allclose(angle_between(n1, n2), x.angle)


def test_bisector_equidistant():
    a, b = random_points(10), random_points(10)
    pole = bisector(a, b).pole
    on = intersect(pole, random_points(10)).point
    assert np.allclose(distance(on, a), distance(on, b), atol=1e-12)
    assert np.all(distance_to_great_circle(a, pole) > 0)


def m_circle(a, b, c):
    """Cramer's rule: solve [a; b; c] n = (1, 1, 1); the pole is n/|n| oriented like
    det[a, b, c], and cos r = 1 / |n| (with that sign)."""
    m = mpmath.matrix([munit(mpv(a)), munit(mpv(b)), munit(mpv(c))])
    det = mpmath.det(m)
    n = []
    for k in range(3):
        mk = m.copy()
        for i in range(3):
            mk[i, k] = 1
        n.append(mpmath.det(mk) / det)
    size = mpmath.sqrt(mdot(n, n))
    sign = 1 if det > 0 else -1
    return [sign * x / size for x in n], mpmath.acos(sign / size)


def test_circle_through_mpmath():
    for _ in range(10):
        a, b, c = random_points(3)
        pole, r = m_circle(a, b, c)
        k = circle_through(a, b, c)
        assert np.allclose(k.pole, [float(x) for x in pole], atol=1e-12)
        assert abs(k.radius - float(r)) < 1e-12


def test_circle_through_small_circle_relative():
    for arc in SMALL_ARCS:
        centre = random_points(1)[0]
        pts = [rotate_about(point_at(centre, arc, 0.0), centre, g) for g in (0.3, 2.0, 4.4)]
        pole, r = m_circle(*pts)
        k = circle_through(*pts)
        assert abs(k.radius - float(r)) < 1e-9 * arc


def test_circle_through_great_circle_case():
    a, b = random_points(1)[0], random_points(1)[0]
    pole = great_circle_through(a, b).pole
    c = rotate_about(a, pole, -2.3)
    assert circle_through(a, b, c).radius == pytest.approx(np.pi / 2, abs=1e-15)


def test_circle_through_planar_limit():
    eps = 1e-5
    za, zb, zc = 0.0 + 0.0j, 1.0 + 0.2j, 0.3 + 0.9j
    pts = [np.array([eps * z.real, eps * z.imag, 1.0]) for z in (za, zb, zc)]
    r_planar = abs(zb - za) * abs(zc - zb) * abs(za - zc) / (2 * abs(((zb - za).conjugate() * (zc - za)).imag))
    assert circle_through(*pts).radius / eps == pytest.approx(r_planar, rel=1e-9)


# ---------------------------------------------------------------- errors
def test_distance_rejects_zero_vector():
    with pytest.raises(ValueError, match="Expected non-zero vectors in `q`"):
        distance([0, 0, 1], [[0, 0, 1], [0, 0, 0]])


def test_distance_rejects_bad_shape():
    with pytest.raises(ValueError, match=r"Expected `p` of shape \(..., 3\)"):
        distance([0, 1], [0, 0, 1])


def test_inclination_rejects_coincident_and_antipodal():
    with pytest.raises(ValueError, match="Expected `a` and `b` neither equal nor antipodal"):
        inclination([0, 0, 1], [0, 0, 1])
    with pytest.raises(ValueError, match="Expected `a` and `b` neither equal nor antipodal"):
        great_circle_through([0, 0, 1], [0, 0, -2])


def test_intersect_rejects_same_circle():
    with pytest.raises(ValueError, match="Expected `pole1` and `pole2`"):
        intersect([0, 0, 1], [0, 0, 1])


def test_circle_through_rejects_coincident():
    with pytest.raises(ValueError, match="Expected three different points"):
        circle_through([1, 0, 0], [1, 0, 0], [0, 1, 0])


def test_to_xyz_rejects_nan():
    with pytest.raises(ValueError, match="Expected finite `lat`"):
        to_xyz(0.0, np.nan)


# ---------------------------------------------------------------- the book's worked examples
def _book_example_points():
    a = to_xyz(np.radians(30), np.radians(50))
    b = point_at(a, np.radians(40), np.radians(60))
    return a, b


def test_example_1_3_1_to_1_3_3_book_values():
    """Problems 1.3.1-1.3.3 as worked on book-spherical-calculus (A at lon 30, lat 50 deg;
    arc AB 40 deg; inclination 60 deg; turn 45 deg), against the placement route at 50 digits."""
    a, b = _book_example_points()
    m = placement(mpv(a))
    s, i = mpmath.radians(40), mpmath.radians(60)
    ref_b = mvec(m, [mpmath.sin(s) * mpmath.cos(i), mpmath.sin(s) * mpmath.sin(i), mpmath.cos(s)])
    assert np.allclose(b, [float(x) for x in ref_b], atol=TOL)
    assert np.degrees(inclination(a, b)) == pytest.approx(60.0, abs=1e-11)
    i2 = mpmath.radians(105)
    ref_b2 = mvec(m, [mpmath.sin(s) * mpmath.cos(i2), mpmath.sin(s) * mpmath.sin(i2), mpmath.cos(s)])
    assert np.allclose(turn(a, b, np.radians(45)), [float(x) for x in ref_b2], atol=TOL)


def test_example_1_4_1_and_1_4_2_book_values():
    """Problems 1.4.1 and 1.4.2 on book-spherical-calculus: gamma 70 deg, arc AC 25 deg."""
    a, b = _book_example_points()
    c = triangle_point(a, b, np.radians(70), np.radians(25))
    s, i = mpmath.radians(25), mpmath.radians(130)
    ref_c = mvec(placement(mpv(a)), [mpmath.sin(s) * mpmath.cos(i), mpmath.sin(s) * mpmath.sin(i), mpmath.cos(s)])
    assert np.allclose(c, [float(x) for x in ref_c], atol=1e-12)
    assert np.degrees(angle_at(a, b, c)) == pytest.approx(70.0, abs=1e-11)
