"""Tests of the instant centres (Kennedy's theorem) against independent velocity routes.

The centres are found by line intersections only. They are checked by their defining
property (links i and j have the same velocity at P_ij), with the link velocities taken
from the analytic loop derivatives of `FourBar` / `SliderCrank` (a different route) or
from the exact derivative of the cam follower's position; and against the independently recomputed
recomputed numbers of examples 2-4 and 2-5.
"""

import numpy as np
import pytest

from mech.planar import FourBar, SliderCrank
from mech.planar.kinematics._instant_centres import (
    centre_count,
    higher_pair,
    instant_centres,
    omega_ratio,
    prismatic,
    revolute,
    centre_velocities,
)


def _fourbar_fields(linkage, theta, omega):
    """Direct centres and the analytic velocity field of each link (1 crank ... 4 frame)."""
    pose = linkage.solve(theta, order=1, omega=omega)
    B, C, D = pose.B, pose.C, linkage.d + 0j
    direct = {(1, 4): 0j * B, (1, 2): B, (2, 3): C, (3, 4): D + 0 * B}
    fields = {
        1: lambda z: 1j * omega * z,
        2: lambda z: pose.vB + 1j * pose.omega_coupler * (z - B),
        3: lambda z: 1j * pose.omega_output * (z - D),
        4: lambda z: 0 * z,
    }
    return direct, fields, pose


def _random_fourbars(n, seed):
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        a, b, c, d = rng.uniform(0.2, 2.0, 4)
        if max(a, b, c, d) >= (a + b + c + d) / 2:
            continue
        theta = rng.uniform(-np.pi, np.pi)
        branch = int(rng.choice([-1, 1]))
        pose = FourBar(a, b, c, d, branch=branch).solve(theta)
        if not pose.valid:
            continue
        # keep poses away from the dead centres, where the rates themselves blow up
        s = abs(np.sin(np.angle(pose.C - pose.B) - np.angle(pose.C - d)))
        if s < 0.1:
            continue
        out.append((a, b, c, d, branch, theta))
    return out


def _check_defining_property(centres, fields, scale, rtol):
    for pair in centres:
        i, j = pair
        ctr = centres[pair]
        if np.all(ctr.at_infinity):
            # relative translation: equal velocities everywhere up to the direction
            z0 = 0j
            dv = fields[i](z0) - fields[j](z0)
            assert abs(np.real(dv * np.conj(ctr.direction))) <= rtol * scale
            continue
        P = ctr.point
        vi, vj = fields[i](P), fields[j](P)
        tol = rtol * scale * (1 + np.abs(P) / scale) ** 2
        assert np.all(np.abs(vi - vj) <= tol), (pair, P, vi, vj)


@pytest.mark.parametrize("n", range(2, 12))
def test_centre_count_formula(n):
    assert centre_count(n) == sum(1 for i in range(n) for j in range(i + 1, n))


def test_centre_count_rejects_non_integer():
    with pytest.raises(ValueError, match="integer >= 2"):
        centre_count(1)
    with pytest.raises(ValueError, match="integer >= 2"):
        centre_count(3.0)


def test_instant_centres_fourbar_random_poses_defining_property():
    for a, b, c, d, branch, theta in _random_fourbars(200, seed=31):
        direct, fields, _ = _fourbar_fields(FourBar(a, b, c, d, branch=branch), theta, -1.7)
        centres = instant_centres(4, direct)
        assert len(centres) == centre_count(4)
        _check_defining_property(centres, fields, a + b + c + d, 1e-12)


def test_omega_ratio_fourbar_matches_analytic():
    """F34 with signs: omega_2/omega_1 and omega_3/omega_1 agree to ~1e-12 relative."""
    worst = 0.0
    for a, b, c, d, branch, theta in _random_fourbars(300, seed=32):
        pose = FourBar(a, b, c, d, branch=branch).solve(theta, order=1, omega=1.0)
        centres = instant_centres(4, {(1, 4): 0j, (1, 2): pose.B, (2, 3): pose.C, (3, 4): d})
        for link, want in ((2, pose.omega_coupler), (3, pose.omega_output)):
            got = omega_ratio(centres, link, 1, 4)
            err = abs(got - want) / max(abs(want), 1e-3)
            worst = max(worst, err)
    assert worst < 1e-11, worst


def test_omega_ratio_direction_rule():
    """Same sense iff P13 lies outside the segment P14 P34 (the rule of §2.2, part II)."""
    for a, b, c, d, branch, theta in _random_fourbars(100, seed=33):
        pose = FourBar(a, b, c, d, branch=branch).solve(theta, order=1)
        centres = instant_centres(4, {(1, 4): 0j, (1, 2): pose.B, (2, 3): pose.C, (3, 4): d})
        p13 = centres[1, 3].point
        if centres[1, 3].at_infinity:
            continue
        outside = not (0.0 < p13.real < d)
        assert (pose.omega_output > 0) == outside


@pytest.mark.parametrize("theta, omega2, omega3", [
    (0.7, 0.682725, -0.120816), (2.0, -0.213381, -1.06914), (4.0, -0.764037, -0.0701034)])
def test_example_2_4_catalog_numbers(theta, omega2, omega3):
    """Catalog: four-bar (10, 40, 30, 35), omega_1 = -3 rad/s (clockwise, as in the text)."""
    pose = FourBar(10, 40, 30, 35).solve(theta)
    centres = instant_centres(4, {(1, 4): 0j, (1, 2): pose.B, (2, 3): pose.C, (3, 4): 35})
    motion = centre_velocities(centres, frame=4, driver=1, omega=-3.0)
    assert motion.omega[2] == pytest.approx(omega2, rel=5e-6)
    assert motion.omega[3] == pytest.approx(omega3, rel=5e-6)
    # P24 is where the lines AB and DC meet; P13 where AD and BC meet
    P24, P13 = centres[2, 4].point, centres[1, 3].point
    assert abs(np.imag(np.conj(pose.B) * P24)) < 1e-9 * abs(P24) * 10
    assert abs(np.imag(np.conj(pose.C - 35) * (P24 - 35))) < 1e-9 * abs(P24 - 35) * 30
    assert abs(P13.imag) < 1e-12 * abs(P13)


@pytest.mark.parametrize("theta, omega2, speed", [(0.8, -0.542529, 54.7170), (2.5, 0.616586, 24.8380)])
def test_example_2_5_catalog_numbers(theta, omega2, speed):
    """Catalog: centric slider-crank a = 30, b = 80, omega_1 = 2 rad/s; slider moves left."""
    pose = SliderCrank(30, 80).solve(theta)
    centres = instant_centres(4, {(1, 4): 0j, (1, 2): pose.B, (2, 3): pose.C, (3, 4): prismatic(1.0)})
    assert bool(centres[3, 4].at_infinity)
    motion = centre_velocities(centres, frame=4, driver=1, omega=2.0)
    v3 = motion.point_velocity(3, pose.C)
    assert motion.omega[2] == pytest.approx(omega2, rel=5e-6)
    assert abs(v3) == pytest.approx(speed, rel=5e-6)
    assert v3.real < 0 and abs(v3.imag) < 1e-12 * speed
    assert motion.omega[3] == 0.0
    # v3 = omega_1 * P14P13 (F35): P13 is on the vertical through A
    assert abs(centres[1, 3].point.real) < 1e-12 * 80
    assert abs(v3) == pytest.approx(2.0 * abs(centres[1, 3].point), rel=1e-13)


def test_velocities_offset_slider_crank_random_matches_analytic():
    rng = np.random.default_rng(34)
    count = 0
    while count < 200:
        a, e = rng.uniform(0.2, 1.0), rng.uniform(-1.0, 1.0)
        b = (a + abs(e)) * rng.uniform(1.1, 3.0)
        theta, omega = rng.uniform(-np.pi, np.pi), rng.uniform(-3, 3)
        pose = SliderCrank(a, b, e).solve(theta, order=1, omega=omega)
        guide = np.exp(1j * rng.uniform(-np.pi, np.pi)) * rng.choice([-1, 1])  # any sense, any length
        guide = np.sign(guide.real or 1.0) * 1.0 + 0j        # the guide is the x direction
        centres = instant_centres(4, {(1, 4): 0j, (1, 2): pose.B, (2, 3): pose.C,
                                      (3, 4): prismatic(guide * rng.uniform(0.5, 2))})
        motion = centre_velocities(centres, frame=4, driver=1, omega=omega)
        assert motion.omega[2] == pytest.approx(pose.omega_coupler, rel=1e-11, abs=1e-12 * abs(omega))
        assert motion.point_velocity(3, 0j) == pytest.approx(pose.v, rel=1e-11, abs=1e-12 * abs(omega))
        assert omega_ratio(centres, 3, 1, 4) == 0.0
        count += 1


def _six_bar(theta, omega):
    """A Watt II six-bar from two four-bars in series, with analytic rates.

    Links: 1 crank AB, 2 coupler BC, 3 rocker CDE (turns about D = 6 + 0j), 4 coupler EF,
    5 rocker FG (about G), 6 frame. The second four-bar D-E-F-G is solved by `FourBar` in
    its own frame (D at the origin, G on its +x axis) and carried back.
    """
    first = FourBar(2.0, 7.0, 5.0, 6.0)
    p1 = first.solve(theta, order=1, omega=omega)
    D, G = 6.0 + 0j, 13.0 + 3.0j
    E = D + 3.0 * np.exp(1j * (p1.psi + 2.0))            # on link 3, 2 rad from D->C
    beta = np.angle(G - D)
    second = FourBar(3.0, 7.0, 5.0, abs(G - D))
    p2 = second.solve(np.angle((E - D) * np.exp(-1j * beta)), order=1, omega=p1.omega_output)
    rot = np.exp(1j * beta)
    F = D + rot * p2.C
    assert abs(D + rot * p2.B - E) < 1e-12
    direct = {(1, 6): 0j, (1, 2): p1.B, (2, 3): p1.C, (3, 6): D, (3, 4): E, (4, 5): F, (5, 6): G}
    fields = {
        1: lambda z: 1j * omega * z,
        2: lambda z: p1.vB + 1j * p1.omega_coupler * (z - p1.B),
        3: lambda z: 1j * p1.omega_output * (z - D),
        4: lambda z: 1j * p1.omega_output * (E - D) + 1j * p2.omega_coupler * (z - E),
        5: lambda z: 1j * p2.omega_output * (z - G),
        6: lambda z: 0 * z,
    }
    omegas = {1: omega, 2: p1.omega_coupler, 3: p1.omega_output, 4: p2.omega_coupler,
              5: p2.omega_output, 6: 0.0}
    return direct, fields, omegas


@pytest.mark.parametrize("theta", [0.3, 1.4, 2.9, 4.4, 5.5])
def test_instant_centres_six_bar_fifteen_centres(theta):
    direct, fields, omegas = _six_bar(theta, 1.3)
    centres = instant_centres(6, direct)
    assert len(centres) == 15 == centre_count(6)
    assert sum(step.round > 0 for step in centres.construction) == 8
    _check_defining_property(centres, fields, 40.0, 1e-12)
    motion = centre_velocities(centres, frame=6, driver=1, omega=1.3)
    for link in range(1, 6):
        assert motion.omega[link] == pytest.approx(omegas[link], rel=1e-11, abs=1e-13)


def test_instant_centres_labels_any_hashable():
    pose = FourBar(10, 40, 30, 35).solve(1.0)
    centres = instant_centres(["crank", "coupler", "rocker", "frame"], {
        ("frame", "crank"): 0j, ("crank", "coupler"): pose.B, ("coupler", "rocker"): pose.C,
        ("rocker", "frame"): revolute(35)})
    assert centres["frame", "coupler"].pair == ("coupler", "frame")
    assert centres["coupler", "frame"].source == "kennedy"


def test_instant_centres_broadcast_over_poses():
    theta = np.linspace(0.1, 6.0, 37)
    pose = FourBar(10, 40, 30, 35).solve(theta, order=1, omega=2.0)
    centres = instant_centres(4, {(1, 4): 0j, (1, 2): pose.B, (2, 3): pose.C, (3, 4): 35.0})
    assert centres[2, 4].point.shape == (37,)
    got = centre_velocities(centres, 4, 1, 2.0).omega[3]
    np.testing.assert_allclose(got, pose.omega_output, rtol=1e-11, atol=1e-13)


def test_instant_centres_double_slider_centre_at_infinity():
    """Ellipsograph: both sliders translate, so P23 is at infinity along the coupler."""
    L, t = 5.0, 0.6
    P24, P34 = L * np.cos(t) + 0j, 1j * L * np.sin(t)        # slider 2 on x, slider 3 on y
    centres = instant_centres(4, {(1, 2): prismatic(1), (1, 3): prismatic(1j),
                                  (2, 4): P24, (3, 4): P34})
    assert bool(centres[2, 3].at_infinity)
    coupler = (P24 - P34) / abs(P24 - P34)
    assert abs(np.imag(centres[2, 3].direction * np.conj(coupler))) < 1e-14
    # the coupler's centre is the corner of the rectangle on O, P24, P34
    assert centres[1, 4].point == pytest.approx(P24 + P34, abs=1e-13)
    assert omega_ratio(centres, 2, 3, 1) == 1.0 or np.isnan(omega_ratio(centres, 2, 3, 1))


def test_instant_centres_cam_follower_matches_position_derivative():
    """Eccentric disc cam, offset knife-edge follower on x = s (example 2-7 set-up)."""
    e, R, s, omega = 12.0, 30.0, 5.0, 2.5
    for theta in np.linspace(0.0, 2 * np.pi, 13):
        K = e * np.exp(1j * theta)                          # disc centre
        y = K.imag + np.sqrt(R**2 - (s - K.real) ** 2)      # follower tip on the circle
        T = s + 1j * y
        centres = instant_centres(3, {(1, 3): 0j, (2, 3): prismatic(1j),
                                      (1, 2): higher_pair(T, T - K)})
        assert centres[1, 2].source == "kennedy+line"
        v2 = centre_velocities(centres, frame=3, driver=1, omega=omega).point_velocity(2, T)
        # exact derivative of y(theta) = e sin(theta) + sqrt(R^2 - (s - e cos theta)^2)
        dy = e * np.cos(theta) - (s - e * np.cos(theta)) * e * np.sin(theta) / np.sqrt(R**2 - (s - K.real) ** 2)
        assert v2.real == pytest.approx(0.0, abs=1e-12)
        assert v2.imag == pytest.approx(omega * dy, rel=1e-12, abs=1e-12)


def test_instant_centres_five_bar_raises_naming_pairs():
    direct = {(1, 2): 0j, (2, 3): 1 + 1j, (3, 4): 3 + 1j, (4, 5): 4 + 0j, (1, 5): 2 + 0j}
    with pytest.raises(ValueError, match=r"P_13, P_14, P_24, P_25, P_35 are left"):
        instant_centres(5, direct)


def test_instant_centres_input_errors():
    with pytest.raises(ValueError, match="two different links"):
        instant_centres(4, {(1, 5): 0j})
    with pytest.raises(ValueError, match="each pair once"):
        instant_centres(3, {(1, 2): 0j, (2, 1): 1j, (2, 3): 1.0})
    with pytest.raises(ValueError, match="non-zero `direction`"):
        prismatic(0)
    with pytest.raises(ValueError, match="Expected finite"):
        instant_centres(3, {(1, 2): np.nan, (2, 3): 1.0, (1, 3): 2.0})
    with pytest.raises(ValueError, match="at least two distinct"):
        instant_centres(["a", "a"], {})
    centres = instant_centres(3, {(1, 2): 0j, (2, 3): 1.0, (1, 3): prismatic(1)})
    with pytest.raises(ValueError, match="finite centre"):
        centre_velocities(centres, frame=1, driver=3, omega=1.0)
    with pytest.raises(ValueError, match="the frame does not turn"):
        omega_ratio(centres, 2, 1, 1)
    with pytest.raises(KeyError):
        centres[1, 1]


def test_instant_centres_coincident_lines_undefined():
    """A folded four-bar (all joints on one line): the Kennedy lines coincide. With
    undefined='nan' the centres are NaN and flagged; by default that is an error."""
    direct = {(1, 4): 0j, (1, 2): 1 + 0j, (2, 3): 3 + 0j, (3, 4): 5 + 0j}
    centres = instant_centres(4, direct, undefined="nan")
    assert not centres[1, 3].defined and not centres[2, 4].defined
    assert np.isnan(centres[1, 3].point)
    assert np.isfinite(centres[1, 2].point)


def test_instant_centres_degenerate_pose_raises():
    """Never a silent NaN: the error names the centre, the pose and the lines."""
    direct = {(1, 4): 0j, (1, 2): 1 + 0j, (2, 3): 3 + 0j, (3, 4): 5 + 0j}
    with pytest.raises(ValueError, match=r"place P_13, but at this pose the line through "
                                         r"P_12 and P_23 and the line through P_14 and P_34"):
        instant_centres(4, direct)
    # the kite a = d, b = c at theta = 0: the crank pin B on the pivot D, all in line
    pose = FourBar(1, 2, 2, 1).solve(np.array([0.5, 0.0]))
    with pytest.raises(ValueError, match=r"P_13, but at pose \(1,\)"):
        instant_centres(4, {(1, 4): 0j, (1, 2): pose.B, (2, 3): pose.C, (3, 4): 1.0})
    with pytest.raises(ValueError, match="Expected `undefined` to be 'raise' or 'nan', got 'x'"):
        instant_centres(4, direct, undefined="x")


def test_fig_2_42_lower_pair_centres_from_relative_velocities():
    """Fig. 2-42: the normals of the relative velocities meet at the pin (revolute) and are
    parallel, perpendicular to the guide (prismatic). Velocities from the analytic loop
    derivatives of `FourBar` and `SliderCrank`, not from the centres."""
    linkage = FourBar(10, 40, 30, 35)
    direct, fields, pose = _fourbar_fields(linkage, 2.8, -3.0)
    C = complex(pose.C)
    z1, z2 = (C + 35) / 2 + 5j, 30 - 12j                     # two points of the rocker's plane
    v1, v2 = (complex(fields[3](z) - fields[2](z)) for z in (z1, z2))
    # the normals z1 + s i v1 and z2 + t i v2 meet where
    s, t = np.linalg.solve([[(-1j * v1).real, (1j * v2).real], [(-1j * v1).imag, (1j * v2).imag]],
                           [(z1 - z2).real, (z1 - z2).imag])
    meet = z1 + s * 1j * v1
    centres = instant_centres(4, direct)
    assert meet == pytest.approx(complex(centres[2, 3].point), abs=1e-9)
    assert abs(complex(fields[3](C) - fields[2](C))) < 1e-12

    slider = SliderCrank(30, 80)
    sp = slider.solve(0.8, order=1, omega=2.0)
    # the block translates: every point moves with the pin's velocity sp.v along the guide
    centres = instant_centres(4, {(1, 4): 0j, (1, 2): sp.B, (2, 3): sp.C, (3, 4): prismatic(1.0)})
    assert centres[3, 4].at_infinity
    assert abs(complex(centres[3, 4].direction).real) < 1e-15      # perpendicular to x
    v_block = centre_velocities(centres, frame=4, driver=1, omega=2.0).point_velocity(3, sp.C + 7 - 3j)
    assert complex(v_block) == pytest.approx(complex(sp.v), rel=1e-12)


def test_fig_2_43_cam_rocker_centre_on_common_normal_and_frame_line():
    """Fig. 2-43: a disc cam (about A) and a knife-edge rocker (about D). The centre P12 from
    the common normal and Kennedy's line AD equals the point of AD where both links have
    the same velocity, omega1 (P - A) = omega2 (P - D), with omega2 taken by a central
    difference of the rocker angle from an independent circle intersection."""
    e, R, L, d, omega1 = 12.0, 30.0, 50.0, 60.0, 2.5

    def tip(theta):
        K = e * np.exp(1j * theta)
        # circle |T - K| = R meets circle |T - d| = L; the tip above the line K D
        u = (d - K) / abs(d - K)
        m = abs(d - K)
        x = (R**2 - L**2 + m**2) / (2 * m)
        return K, K + u * (x + 1j * np.sqrt(R**2 - x**2))

    for theta in np.radians([10.0, 40.0, 100.0, 200.0, 300.0]):
        K, T = tip(theta)
        h = 1e-6
        psi = [np.angle(tip(theta + s * h)[1] - d) for s in (1, -1)]
        omega2 = omega1 * (psi[0] - psi[1]) / (2 * h)
        expected = omega2 * d / (omega2 - omega1)
        centres = instant_centres(3, {(1, 3): 0j, (2, 3): d, (1, 2): higher_pair(T, T - K)})
        P12 = complex(centres[1, 2].point)
        assert P12 == pytest.approx(expected, rel=1e-7, abs=1e-7)
        # and it lies on the common normal K T
        assert abs(((P12 - K) * np.conj(T - K)).imag) < 1e-9 * abs(T - K) * max(1, abs(P12 - K))


def test_fig_2_48_example_2_7_centre_where_normal_meets_ax():
    """Fig. 2-48: P12 is where the normal through the contact and the disc's centre meets the
    line through A perpendicular to the follower's path (here the x axis)."""
    e, R, theta = 12.0, 30.0, np.radians(40.0)
    K = e * np.exp(1j * theta)
    T = 1j * (K.imag + np.sqrt(R**2 - K.real**2))
    centres = instant_centres(3, {(1, 3): 0j, (2, 3): prismatic(1j), (1, 2): higher_pair(T, T - K)})
    # the line T + s (K - T) crosses y = 0 at s = T.imag / (T - K).imag
    crossing = T + T.imag / (T - K).imag * (K - T)
    assert complex(centres[1, 2].point) == pytest.approx(crossing, abs=1e-12)
    assert crossing.real == pytest.approx(11.675510, abs=1e-6)
