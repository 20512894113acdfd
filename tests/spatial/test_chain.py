"""Open chains, eqs. (2-73) to (2-75): positions against a 50-digit mpmath product of the
elementary motions, rates against ``mpmath.diff`` of that product along a joint motion, and
example 2-25 against the textbook's printed closed forms."""

import math

import mpmath
import numpy as np
import pytest

from mech.spatial._chain import (Joint, OpenChain, example_2_25_manipulator, example_2_25_pose,
                                 example_2_25_reach)

SHAPES = [(), (7,), (3, 4)]


def _mp_hd(phi, lam, s, h):
    c, sn, cl, sl = mpmath.cos(phi), mpmath.sin(phi), mpmath.cos(lam), mpmath.sin(lam)
    Tz = mpmath.matrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, s], [0, 0, 0, 1]])
    Rz = mpmath.matrix([[c, -sn, 0, 0], [sn, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
    Tx = mpmath.matrix([[1, 0, 0, h], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
    Rx = mpmath.matrix([[1, 0, 0, 0], [0, cl, -sl, 0], [0, sl, cl, 0], [0, 0, 0, 1]])
    return Tz * Rz * Tx * Rx


def _mp_end(joints, q, point):
    """M_0n [point; 1] and the end frame's axes, from the joint rules written out again."""
    T, k = mpmath.eye(4), 0
    for j in joints:
        phi, s = mpmath.mpf(j.phi), mpmath.mpf(j.s)
        if j.kind == "R":
            phi += q[k]
        elif j.kind == "P":
            s += q[k]
        elif j.kind == "H":
            phi += q[k]
            s += mpmath.mpf(j.pitch) * q[k] / (2 * mpmath.pi)
        else:
            phi += q[k]
            s += q[k + 1]
        k += 2 if j.kind == "C" else 1
        T = T * _mp_hd(phi, mpmath.mpf(j.lam), s, mpmath.mpf(j.h))
    P = T * mpmath.matrix([point[0], point[1], point[2], 1])
    return [P[i] for i in range(3)] + [T[i, c] for c in range(3) for i in range(3)]


def _random_chain(rng, n):
    joints = []
    for kind in rng.choice(list("RPCH"), n):
        joints.append(Joint(str(kind), phi=rng.uniform(-3, 3), lam=rng.uniform(-3, 3), s=rng.uniform(-1, 1),
                            h=rng.uniform(-1, 1), pitch=rng.uniform(-2, 2) if kind == "H" else 0.0))
    return OpenChain(joints)


@pytest.mark.parametrize("seed", range(4))
def test_solve_rates_match_mpmath_diff(seed):
    """vP, aP, omega, alpha against the first and second derivatives of the 50-digit product
    along q(t) = q0 + qdot t + qddot t^2 / 2, taken by mpmath.diff. omega and alpha are
    checked through the end axes: de/dt = omega x e, d2e/dt2 = alpha x e + omega x (omega x e)."""
    rng = np.random.default_rng(seed)
    chain = _random_chain(rng, 3 + seed)
    q0, qd, qdd = (rng.uniform(-2, 2, chain.dof) for _ in range(3))
    point = rng.uniform(-1, 1, 3)
    got = chain.solve(q0, order=2, qdot=qd, qddot=qdd, point=point)
    with mpmath.workdps(50):
        def end(t, i):
            q = [mpmath.mpf(a) + mpmath.mpf(b) * t + mpmath.mpf(c) * t * t / 2 for a, b, c in zip(q0, qd, qdd)]
            return _mp_end(chain.joints, q, point)[i]
        d1 = np.array([float(mpmath.diff(lambda t: end(t, i), 0)) for i in range(12)])
        d2 = np.array([float(mpmath.diff(lambda t: end(t, i), 0, 2)) for i in range(12)])
        pos = np.array([float(end(mpmath.mpf(0), i)) for i in range(12)])
    np.testing.assert_allclose(got.P, pos[:3], rtol=0, atol=1e-13)
    np.testing.assert_allclose(got.vP, d1[:3], rtol=0, atol=1e-12)
    np.testing.assert_allclose(got.aP, d2[:3], rtol=0, atol=1e-11)
    for c, e in enumerate((got.e1, got.e2, got.e3)):
        np.testing.assert_allclose(e, pos[3 + 3 * c:6 + 3 * c], rtol=0, atol=1e-14)
        np.testing.assert_allclose(np.cross(got.omega, e), d1[3 + 3 * c:6 + 3 * c], rtol=0, atol=1e-12)
        want = np.cross(got.alpha, e) + np.cross(got.omega, np.cross(got.omega, e))
        np.testing.assert_allclose(want, d2[3 + 3 * c:6 + 3 * c], rtol=0, atol=1e-11)


@pytest.mark.parametrize("length", [2, 10, 50])
def test_solve_long_chain_orthonormal(length):
    chain = _random_chain(np.random.default_rng(length), length)
    pose = chain.solve(np.random.default_rng(0).uniform(-3, 3, (5, chain.dof)))
    R = pose.M[..., :3, :3]
    assert np.abs(R @ np.swapaxes(R, -1, -2) - np.eye(3)).max() < 1e-13
    np.testing.assert_allclose(np.cross(pose.e1, pose.e2), pose.e3, atol=1e-13)


@pytest.mark.parametrize("shape", SHAPES)
def test_solve_broadcast(shape):
    arm = example_2_25_manipulator(0.5)
    rng = np.random.default_rng(5)
    q = rng.uniform(-1, 1, shape + (4,))
    pose = arm.solve(q, order=2, qdot=[0.1, 0.2, 0.3, 0.4])
    assert pose.P.shape == shape + (3,) and pose.aP.shape == shape + (3,) and pose.M.shape == shape + (4, 4)
    flat = q.reshape(-1, 4)
    for k in range(flat.shape[0]):
        one = arm.solve(flat[k], order=2, qdot=[0.1, 0.2, 0.3, 0.4])
        np.testing.assert_allclose(pose.aP.reshape(-1, 3)[k], one.aP, atol=1e-15)


def _printed_2_75(phi01, phi12, s2, phi34, s0, p):
    """Example 2-25 as printed: (2-75) and the direction cosines (l, m, n), (u, v, w)."""
    L = p + s2
    c1, s1, c2, s2_, c4, s4 = (math.cos(phi01), math.sin(phi01), math.cos(phi12), math.sin(phi12),
                               math.cos(phi34), math.sin(phi34))
    return (np.array([L * c1 * s2_, L * s1 * s2_, -L * c2 + s0]),
            np.array([c1 * c2 * c4 + s1 * s4, s1 * c2 * c4 - c1 * s4, s2_ * c4]),
            np.array([c1 * s2_, s1 * s2_, -c2]))


def test_example_2_25_pose_matches_printed_2_75():
    """Example 2-25: the chain product M01 M12 M23 M34 (2-73), (2-74) reproduces the
    printed (2-75) and direction cosines, and so does the generated closed form."""
    s0, p = 0.5, 0.1
    arm = example_2_25_manipulator(s0)
    rng = np.random.default_rng(25)
    for phi01, phi12, s2, phi34 in zip(rng.uniform(-3, 3, 10), rng.uniform(-3, 3, 10), rng.uniform(0, 1, 10),
                                       rng.uniform(-3, 3, 10)):
        P, e1, e3 = _printed_2_75(phi01, phi12, s2, phi34, s0, p)
        pose = arm.pose([phi01, phi12, s2, phi34], point=(0.0, 0.0, p))
        np.testing.assert_allclose(pose.P, P, atol=1e-15)
        np.testing.assert_allclose(pose.e1, e1, atol=1e-15)
        np.testing.assert_allclose(pose.e3, e3, atol=1e-15)
        closed = example_2_25_pose(phi01, phi12, s2, phi34, s0, p)
        for got, want in zip(closed, (P, e1, e3)):
            np.testing.assert_allclose(got, want, atol=1e-15)


def test_example_2_25_name_is_rrpr():
    """The text calls the manipulator PRPR; its joints are R, R, P, R."""
    arm = example_2_25_manipulator(1.0)
    assert "".join(j.kind for j in arm.joints) == "RRPR"
    assert repr(arm) == "OpenChain(RRPR)"


def test_example_2_25_reach_against_mpmath():
    """AP = sqrt(S0^2 + (p+S2)^2 - 2 S0 (p+S2) cos phi12): against the printed form at 50
    digits, including near-cancellation (S0 = p + S2, tiny phi12), and against |P|."""
    with mpmath.workdps(50):
        for phi12, s2, s0, p in [(0.3, 0.4, 0.5, 0.1), (1e-7, 0.4, 0.5, 0.1), (2.9, 1.0, 0.2, 0.3),
                                 (1e-9, 0.4 + 1e-9, 0.5, 0.1)]:
            L = mpmath.mpf(p) + mpmath.mpf(s2)
            want = mpmath.sqrt(mpmath.mpf(s0) ** 2 + L**2 - 2 * mpmath.mpf(s0) * L * mpmath.cos(mpmath.mpf(phi12)))
            got = example_2_25_reach(phi12, s2, s0, p)
            # relative to AP, plus the rounding of the input sum p + S2 (the conditioning)
            assert abs(got - float(want)) <= 4e-16 * float(want) + 1.2e-16 * (s0 + p + s2)
        # the printed form, evaluated as written, loses about 1% at phi12 = 1e-7 (the check can fail)
        naive = math.sqrt(0.5**2 + 0.5**2 - 2 * 0.5 * 0.5 * math.cos(1e-7))
        assert abs(naive - 5e-8) > 1e-4 * 5e-8
    arm = example_2_25_manipulator(0.5)
    pose = arm.pose([[0.2, 0.9, 0.3, 1.0], [2.0, -1.0, 0.7, 0.0]], point=(0, 0, 0.1))
    np.testing.assert_allclose(example_2_25_reach([0.9, -1.0], [0.3, 0.7], 0.5, 0.1),
                               np.linalg.norm(pose.P, axis=-1), rtol=1e-15)
    # P lies on the sphere of radius p + S2 about the shoulder B = (0, 0, S0)
    np.testing.assert_allclose(np.linalg.norm(pose.P - [0, 0, 0.5], axis=-1), [0.4, 0.8], rtol=1e-15)


def test_example_2_25_velocity_by_differentiating_2_75():
    """Differentiating (2-75) by hand gives the gripper velocity; compare with solve."""
    s0, p = 0.5, 0.1
    q, qd = np.array([0.4, 1.1, 0.35, -0.7]), np.array([0.3, -0.5, 0.2, 1.3])
    phi01, phi12, s2, _ = q
    L, dL = p + s2, qd[2]
    c1, s1, c2, s2_ = math.cos(phi01), math.sin(phi01), math.cos(phi12), math.sin(phi12)
    want = np.array([dL * c1 * s2_ - L * s1 * s2_ * qd[0] + L * c1 * c2 * qd[1],
                     dL * s1 * s2_ + L * c1 * s2_ * qd[0] + L * s1 * c2 * qd[1],
                     -dL * c2 + L * s2_ * qd[1]])
    got = example_2_25_manipulator(s0).solve(q, order=1, qdot=qd, point=(0, 0, p)).vP
    np.testing.assert_allclose(got, want, atol=1e-15)


def test_solve_errors():
    arm = example_2_25_manipulator(0.5)
    with pytest.raises(ValueError, match="Expected `qdot` for order >= 1"):
        arm.solve([0, 0, 0, 0], order=1)
    with pytest.raises(ValueError, match="Expected `q` with last axis 4"):
        arm.solve([0, 0, 0])
    with pytest.raises(ValueError, match="Expected finite `q`"):
        arm.solve([0, np.nan, 0, 0])
    with pytest.raises(ValueError, match="Expected `order`"):
        arm.solve([0, 0, 0, 0], order=3)
    with pytest.raises(ValueError, match="Expected `kind`"):
        Joint("S")
    with pytest.raises(ValueError, match="Expected `pitch` = 0"):
        Joint("R", pitch=1.0)
    with pytest.raises(ValueError, match="Expected `s0` > 0"):
        example_2_25_manipulator(-1.0)
    with pytest.raises(AttributeError, match="needs solve"):
        arm.solve([0, 0, 0, 0]).vP
