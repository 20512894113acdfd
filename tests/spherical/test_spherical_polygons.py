"""Side-angle laws of spherical polygons (deriv-spherical-polygon-laws).

Closed polygons are built here by a route that does not use the package: random unit axes,
twists from atan2(|u x v|, u . v), and turning angles from tangent vectors (the direction
of link k-1 continued beyond u_k, and the direction of link k), not from link normals.
Chain ends are checked against 50-digit mpmath products of the rotation matrices."""

import mpmath
import numpy as np
import pytest

from mech.spherical._polygons import (
    SphericalPolygon, chain_components, close_polygon, cosine_law, law_count, open_chain_axes,
    polygon_relations, sine_cosine_law, sine_law)

SHAPES = [(), (7,), (3, 4)]


def _unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _tangent(at, towards):
    """Unit tangent at `at` of the great circle towards `towards`."""
    return _unit(towards - np.sum(at * towards, axis=-1, keepdims=True) * at)


def _reference_polygon(rng, n, size):
    """Axes, twists and turning angles of random closed polygons, shapes (size, n, ...)."""
    u = _unit(rng.normal(size=(size, n, 3)))
    nxt, prev = np.roll(u, -1, axis=-2), np.roll(u, 1, axis=-2)
    arcs = np.arctan2(np.linalg.norm(np.cross(u, nxt), axis=-1), np.sum(u * nxt, axis=-1))
    t_in = -_tangent(u, prev)                  # link k-1 continued beyond u_k
    t_out = _tangent(u, nxt)                   # link k leaving u_k
    angles = np.arctan2(np.sum(u * np.cross(t_in, t_out), axis=-1), np.sum(t_in * t_out, axis=-1))
    return u, arcs, angles


def _mp_chain_end(arcs, angles):
    """u_{m+1} in the start frame: R_x(a1) R_z(t2) R_x(a2) ... e_z at 50 digits."""
    with mpmath.workdps(50):
        def rx(a):
            c, s = mpmath.cos(a), mpmath.sin(a)
            return mpmath.matrix([[1, 0, 0], [0, c, -s], [0, s, c]])

        def rz(t):
            c, s = mpmath.cos(t), mpmath.sin(t)
            return mpmath.matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])

        M = rx(mpmath.mpf(float(arcs[0])))
        for a, t in zip(arcs[1:], angles):
            M = M * rz(mpmath.mpf(float(t))) * rx(mpmath.mpf(float(a)))
        return np.array([float(M[i, 2]) for i in range(3)])


@pytest.mark.parametrize("n", [3, 4, 5, 6, 7])
def test_polygon_relations_random_closed_polygons(n):
    """Acceptance of issue 5: every law holds to 1e-12 on 1000 random closed polygons."""
    _, arcs, angles = _reference_polygon(np.random.default_rng(n), n, 1000)
    rel = polygon_relations(arcs, angles)
    assert len(rel) == law_count(n)["total"]
    for name in ("sine", "sine-cosine", "cosine"):
        assert rel.family(name).shape == (1000, law_count(n)[name])
    worst = rel.worst()
    assert worst.shape == (1000,)
    assert worst.max() < 1e-12


@pytest.mark.parametrize("n", [3, 5, 7])
def test_polygon_relations_perturbed_angle_jumps(n):
    """Turning one joint angle by 1e-4 breaks the laws that contain it, and only those."""
    _, arcs, angles = _reference_polygon(np.random.default_rng(10 + n), n, 200)
    p = 2                                                   # the perturbed axis (1-based)
    bent = angles.copy()
    bent[:, p - 1] += 1e-4
    rel = polygon_relations(arcs, bent)
    assert np.all(rel.worst() > 1e-6)
    # a cosine law of a cut at the perturbed axis does not contain its angle
    for k in range(1, n + 1):
        if k != p:
            key = f"cosine({min(p, k)},{max(p, k)})"
            assert np.max(np.abs(rel[key])) < 1e-12
    # the fundamental sine law at the perturbed axis does contain it
    assert np.min(np.abs(rel[f"sine({p},{p - 1})"])) > 0.0
    assert np.median(np.abs(rel[f"sine({p},{p - 1})"])) > 1e-6


def test_polygon_relations_perturbed_arc_jumps():
    _, arcs, angles = _reference_polygon(np.random.default_rng(3), 4, 200)
    arcs[:, 0] += 1e-4
    rel = polygon_relations(arcs, angles)
    assert np.median(rel.worst()) > 1e-6
    assert np.median(np.abs(rel["cosine(1,2)"])) > 1e-6      # the fundamental cosine law of link 1


@pytest.mark.parametrize("law, family", [(sine_law, "sine"), (sine_cosine_law, "sine-cosine"),
                                         (cosine_law, "cosine")])
def test_named_laws_match_relations(law, family):
    _, arcs, angles = _reference_polygon(np.random.default_rng(4), 6, 50)
    bent = angles + np.random.default_rng(5).normal(scale=0.1, size=angles.shape)
    rel = polygon_relations(arcs, bent)
    for j, k in ((1, 6), (2, 5), (4, 3)):
        if family == "cosine":      # listed once, for j < k; the reversed cut changes its sign
            expected = np.sign(k - j) * rel[f"cosine({min(j, k)},{max(j, k)})"]
        else:
            expected = rel[f"{family}({j},{k})"]
        np.testing.assert_allclose(law(arcs, bent, j, k), expected, rtol=0, atol=1e-15)
        assert np.all(np.abs(law(arcs, angles, j, k)) < 1e-12)


def test_cosine_law_symmetric_in_the_cut():
    _, arcs, angles = _reference_polygon(np.random.default_rng(6), 5, 20)
    bent = angles + 0.3
    np.testing.assert_allclose(cosine_law(arcs, bent, 2, 4), -cosine_law(arcs, bent, 4, 2), atol=1e-14)


def test_cosine_law_fundamental_is_dot_product():
    """Z of the long chain j -> j-1 is u_j . u_{j-1} = cos(alpha_{j-1}) on a closed polygon."""
    u, arcs, angles = _reference_polygon(np.random.default_rng(7), 4, 30)
    X, Y, Z = chain_components(arcs[:, :3], angles[:, 1:3])
    np.testing.assert_allclose(Z, np.sum(u[:, 0] * u[:, 3], axis=-1), atol=1e-14)
    np.testing.assert_allclose(X, np.sin(arcs[:, 3]) * np.sin(angles[:, 0]), atol=1e-14)
    np.testing.assert_allclose(Y, np.sin(arcs[:, 3]) * np.cos(angles[:, 0]), atol=1e-14)


@pytest.mark.parametrize("m", [1, 2, 3, 4, 5, 6])
def test_chain_components_mpmath(m):
    rng = np.random.default_rng(20 + m)
    arcs = rng.uniform(0.05, 3.1, (8, m))
    angles = rng.uniform(-np.pi, np.pi, (8, m - 1))
    X, Y, Z = chain_components(arcs, angles if m > 1 else np.zeros((8, 0)))
    for i in range(8):
        np.testing.assert_allclose([X[i], Y[i], Z[i]], _mp_chain_end(arcs[i], angles[i]), atol=2e-15)


@pytest.mark.parametrize("shape", SHAPES)
def test_chain_components_broadcast(shape):
    X, Y, Z = chain_components(np.full(shape + (3,), 0.4), np.full(shape + (2,), 1.0))
    assert X.shape == Y.shape == Z.shape == shape
    np.testing.assert_allclose(X**2 + Y**2 + Z**2, 1.0, atol=1e-15)


def test_open_chain_axes_default_start():
    u = open_chain_axes([0.3, 0.5], [0.7])
    np.testing.assert_allclose(u[0], [0.0, 0.0, 1.0], atol=1e-16)
    np.testing.assert_allclose(u[1], [np.sin(0.3), 0.0, np.cos(0.3)], atol=1e-16)


def test_open_chain_axes_closes_reference_polygon():
    """Twists and turning angles of a closed polygon, fed to the open chain, return to u_1,
    and the chain's axes have the given twists and turning angles."""
    u, arcs, angles = _reference_polygon(np.random.default_rng(8), 6, 100)
    chain = open_chain_axes(arcs, angles[:, 1:])
    np.testing.assert_allclose(chain[:, -1], chain[:, 0], atol=1e-13)
    _, arcs_back, angles_back = _reference_polygon_from_axes(chain[:, :-1])
    np.testing.assert_allclose(arcs_back, arcs, atol=1e-13)
    np.testing.assert_allclose(np.angle(np.exp(1j * (angles_back - angles))), 0.0, atol=1e-12)


def _reference_polygon_from_axes(u):
    nxt, prev = np.roll(u, -1, axis=-2), np.roll(u, 1, axis=-2)
    arcs = np.arctan2(np.linalg.norm(np.cross(u, nxt), axis=-1), np.sum(u * nxt, axis=-1))
    t_in, t_out = -_tangent(u, prev), _tangent(u, nxt)
    angles = np.arctan2(np.sum(u * np.cross(t_in, t_out), axis=-1), np.sum(t_in * t_out, axis=-1))
    return u, arcs, angles


def test_open_chain_axes_frame_places_the_chain():
    rng = np.random.default_rng(9)
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    R = q * np.sign(np.diag(r))
    R = R * np.linalg.det(R)                                   # proper
    arcs, angles = rng.uniform(0.2, 2.5, 4), rng.uniform(-3, 3, 3)
    np.testing.assert_allclose(open_chain_axes(arcs, angles, frame=R),
                               open_chain_axes(arcs, angles) @ R.T, atol=1e-15)


def test_open_chain_axes_planar_limit():
    """Small arcs: the axes, seen in the tangent plane at the north pole and scaled by
    1/eps, tend to the planar polygon's vertices with error O(eps^2)."""
    sides = np.array([1.0, 0.8, 1.3, 0.9])
    turns = np.array([1.1, 0.9, 1.4])
    heading = np.concatenate([[0.0], np.cumsum(turns)])
    planar = np.concatenate([[0.0], np.cumsum(sides * np.exp(1j * heading))])
    errors = []
    for eps in (1e-1, 1e-2, 1e-3):
        u = open_chain_axes(eps * sides, turns)
        projected = (u[:, 0] + 1j * u[:, 1]) / eps
        errors.append(np.max(np.abs(projected - planar)))
    assert errors[2] < 1e-5
    assert errors[0] / errors[1] > 50 and errors[1] / errors[2] > 50


def test_polygon_relations_planar_limit_four_bar():
    """The fundamental laws (7) of a 4-loop of small arcs, divided by eps (sine, sine-cosine)
    or eps^2 (cosine), tend to zero when the planar closure holds: the planar laws (8)."""
    sides = np.array([1.0, 0.8, 1.3])
    turns = np.array([1.1, 0.9])
    end = np.sum(sides * np.exp(1j * np.concatenate([[0.0], np.cumsum(turns)])))
    closing = abs(end)
    theta4 = np.angle(-end) - np.sum(turns)                     # turn at u_4 onto the closing side
    theta1 = -np.angle(-end)                                    # turn at u_1 back onto link 1
    for eps, bound in ((1e-2, 1e-3), (1e-3, 1e-5)):
        arcs = eps * np.array([*sides, closing])
        angles = np.array([theta1, *turns, theta4])
        rel = polygon_relations(arcs, angles)
        assert abs(rel["sine(1,4)"]) / eps < bound
        assert abs(rel["sine-cosine(1,4)"]) / eps < bound
        assert abs(rel["cosine(1,4)"]) / eps**2 < bound


def test_fourbar_angles_are_turning_angles():
    """On a spherical four-bar A B C D (CONVENTIONS), the loop's turning angles are
    theta_1 = theta + pi and theta_4 = -psi, as the derivation uses for the cosine law."""
    u, arcs, angles = _reference_polygon(np.random.default_rng(11), 4, 50)
    A, B, C, D = (u[:, i] for i in range(4))
    t_AD, t_AB = _tangent(A, D), _tangent(A, B)
    theta = np.arctan2(np.sum(A * np.cross(t_AD, t_AB), axis=-1), np.sum(t_AD * t_AB, axis=-1))
    t_beyond, t_DC = -_tangent(D, A), _tangent(D, C)
    psi = np.arctan2(np.sum(D * np.cross(t_beyond, t_DC), axis=-1), np.sum(t_beyond * t_DC, axis=-1))
    np.testing.assert_allclose(np.angle(np.exp(1j * (angles[:, 0] - theta - np.pi))), 0.0, atol=1e-12)
    np.testing.assert_allclose(np.angle(np.exp(1j * (angles[:, 3] + psi))), 0.0, atol=1e-12)
    # and the cosine law of the cut (2, 3) is the coupler condition B . C = cos b
    a, b, c, d = (arcs[:, i] for i in range(4))
    assert np.max(np.abs(cosine_law(arcs, angles, 2, 3))) < 1e-13
    fourbar = (np.sin(c) * (np.sin(a) * np.cos(d) * np.cos(theta) - np.cos(a) * np.sin(d)) * np.cos(psi)
               + np.sin(a) * np.sin(c) * np.sin(theta) * np.sin(psi)
               - (np.cos(b) - np.cos(c) * (np.sin(a) * np.sin(d) * np.cos(theta) + np.cos(a) * np.cos(d))))
    assert np.max(np.abs(fourbar)) < 1e-13


def test_close_polygon_matches_reference():
    u, arcs, angles = _reference_polygon(np.random.default_rng(12), 5, 100)
    p = close_polygon(3.0 * u)
    assert isinstance(p, SphericalPolygon) and p.n == 5
    np.testing.assert_allclose(p.axes, u, atol=1e-15)
    np.testing.assert_allclose(p.arcs, arcs, atol=1e-14)
    np.testing.assert_allclose(np.angle(np.exp(1j * (p.angles - angles))), 0.0, atol=1e-13)
    assert p.relations().worst().max() < 1e-13
    with pytest.raises(AttributeError):
        p.arcs = arcs
    with pytest.raises(ValueError):
        p.arcs[0, 0] = 1.0


@pytest.mark.parametrize("shape", SHAPES)
def test_polygon_relations_broadcast(shape):
    _, arcs, angles = _reference_polygon(np.random.default_rng(13), 4, 1)
    arcs = np.broadcast_to(arcs[0], shape + (4,))
    rel = polygon_relations(arcs, angles[0])
    assert all(v.shape == shape for v in rel.values())
    assert rel.worst().shape == shape


@pytest.mark.parametrize("n, total", [(3, 15), (4, 30), (5, 50), (6, 75), (7, 105)])
def test_law_count_table(n, total):
    assert law_count(n)["total"] == total


def test_polygon_relations_bad_input():
    with pytest.raises(ValueError, match="Expected `arcs` in"):
        polygon_relations([0.5, 3.5, 1.0], [0.1, 0.2, 0.3])
    with pytest.raises(ValueError, match="Expected `arcs` with 3 to 7"):
        polygon_relations(np.full(8, 0.5), np.zeros(8))
    with pytest.raises(ValueError, match="Expected `angles` with 4"):
        polygon_relations(np.full(4, 0.5), np.zeros(3))
    with pytest.raises(ValueError, match="Expected finite `angles`"):
        polygon_relations(np.full(3, 0.5), [0.0, np.nan, 0.0])
    with pytest.raises(ValueError, match=r"Expected `k` to be an integer in \[1, 4\], got 5"):
        sine_law(np.full(4, 0.5), np.zeros(4), 1, 5)
    with pytest.raises(ValueError, match="Expected `k` different"):
        cosine_law(np.full(4, 0.5), np.zeros(4), 2, 2)
    with pytest.raises(ValueError, match="Expected `arcs` with 1 to 6"):
        chain_components(np.full(7, 0.5), np.zeros(6))
    with pytest.raises(ValueError, match="Expected `angles` with 2"):
        open_chain_axes([0.5, 0.5, 0.5], [0.1])
    with pytest.raises(ValueError, match="Expected consecutive `axes`"):
        close_polygon([[0, 0, 1], [0, 0, 2], [1, 0, 0]])
    with pytest.raises(ValueError, match="Expected `n`"):
        law_count(2)


def test_fourbar_pose_satisfies_the_cut_at_the_coupler():
    """A pose of `SphericalFourBar` is a closed 4-loop A B C D whose turning angles are
    theta + pi at A and -psi at D; the cosine law of the cut (2, 3) holds."""
    from mech.spherical._fourbar import SphericalFourBar, ground_frame

    R = ground_frame(0.7, 0.4, 1.1)
    linkage = SphericalFourBar(0.35, 0.9, 0.7, 1.0, frame=R)
    theta = np.linspace(0.0, 2 * np.pi, 9)
    pose = linkage.solve(theta)
    axes = np.stack([np.broadcast_to(linkage.A, pose.B.shape), pose.B, pose.C,
                     np.broadcast_to(linkage.D, pose.B.shape)], axis=-2)
    p = close_polygon(axes)
    np.testing.assert_allclose(p.arcs, np.broadcast_to([0.35, 0.9, 0.7, 1.0], p.arcs.shape), atol=1e-13)
    np.testing.assert_allclose(np.angle(np.exp(1j * (p.angles[:, 0] - theta - np.pi))), 0.0, atol=1e-12)
    np.testing.assert_allclose(np.angle(np.exp(1j * (p.angles[:, 3] + pose.psi))), 0.0, atol=1e-12)
    assert p.relations().worst().max() < 1e-12
    # the same placement as an open chain: the ground link A -> D
    ground = open_chain_axes([1.0], [], frame=R)
    np.testing.assert_allclose(ground, [linkage.A, linkage.D], atol=1e-15)
