"""Rotations and H-D matrices, eqs. (2-59) to (2-68), against independent references: an
mpmath product of the four elementary motions at 50 digits, the standard
Denavit-Hartenberg matrix written out by hand, and the textbook's printed entries."""

import math

import mpmath
import numpy as np
import pytest

from mech.spatial._transforms import hd, hd_inv, homogeneous, rot_x, rot_z

SHAPES = [(), (7,), (3, 4)]


def _mp_hd(phi, lam, s, h):
    """M_ij = T_z(s) R_z(phi) T_x(h) R_x(lam), built from the four motions in mpmath."""
    c, sn = mpmath.cos(phi), mpmath.sin(phi)
    cl, sl = mpmath.cos(lam), mpmath.sin(lam)
    Tz = mpmath.matrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, s], [0, 0, 0, 1]])
    Rz = mpmath.matrix([[c, -sn, 0, 0], [sn, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
    Tx = mpmath.matrix([[1, 0, 0, h], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
    Rx = mpmath.matrix([[1, 0, 0, 0], [0, cl, -sl, 0], [0, sl, cl, 0], [0, 0, 0, 1]])
    return Tz * Rz * Tx * Rx


def _random_params(rng, n):
    return (rng.uniform(-np.pi, np.pi, n), rng.uniform(-np.pi, np.pi, n),
            rng.uniform(-5, 5, n), rng.uniform(-5, 5, n))


@pytest.mark.parametrize("length", [2, 3, 5, 8, 13, 21, 34, 50])
def test_hd_chain_product_orthogonal_and_matches_mpmath(length):
    """Products of 2 to 50 random H-D matrices: R R^T = I to 1e-13, and every entry agrees
    with a 50-digit mpmath product of the elementary motions to 1e-12 (relative)."""
    rng = np.random.default_rng(length)
    params = _random_params(rng, length)
    stack = hd(*params)                                     # one call for the whole chain
    product = np.eye(4)
    for M in stack:
        product = product @ M
    R = product[:3, :3]
    assert np.abs(R @ R.T - np.eye(3)).max() < 1e-13
    assert abs(np.linalg.det(R) - 1.0) < 1e-13
    with mpmath.workdps(50):
        ref = mpmath.eye(4)
        for phi, lam, s, h in zip(*(p.tolist() for p in params)):
            ref = ref * _mp_hd(mpmath.mpf(phi), mpmath.mpf(lam), mpmath.mpf(s), mpmath.mpf(h))
        ref = np.array(ref.tolist(), dtype=float)
    assert np.abs(product - ref).max() <= 1e-12 * np.abs(ref).max()


@pytest.mark.parametrize("shape", SHAPES)
def test_hd_inv_roundtrip(shape):
    rng = np.random.default_rng(7)
    size = int(np.prod(shape))
    params = [p.reshape(shape) for p in _random_params(rng, size)]
    M, Minv = hd(*params), hd_inv(*params)
    assert M.shape == shape + (4, 4) and Minv.shape == shape + (4, 4)
    eye = np.broadcast_to(np.eye(4), M.shape)
    np.testing.assert_allclose(Minv @ M, eye, rtol=0, atol=1e-14)
    np.testing.assert_allclose(M @ Minv, eye, rtol=0, atol=1e-14)
    np.testing.assert_allclose(Minv, np.linalg.inv(M), rtol=0, atol=1e-13)


def test_hd_inv_last_column_is_origin_i_in_frame_j():
    """(2-68): r_j^(oi) = (-h, -S sin(lam), -S cos(lam))."""
    phi, lam, s, h = 0.3, 1.2, 2.5, -0.7
    np.testing.assert_allclose(hd_inv(phi, lam, s, h)[:3, 3],
                               [-h, -s * math.sin(lam), -s * math.cos(lam)], rtol=0, atol=1e-15)


def test_hd_origin_offset_2_66():
    """(2-66): the origin of j in frame i is (h cos phi, h sin phi, S)."""
    phi, lam, s, h = 2.0, -0.4, 1.5, 3.0
    np.testing.assert_allclose(hd(phi, lam, s, h) @ [0, 0, 0, 1],
                               [h * math.cos(phi), h * math.sin(phi), s, 1.0], rtol=0, atol=1e-15)


def _standard_dh(theta, d, a, alpha):
    """The standard (distal) Denavit-Hartenberg link matrix, written out by hand."""
    ct, st, ca, sa = math.cos(theta), math.sin(theta), math.cos(alpha), math.sin(alpha)
    return np.array([[ct, -st * ca, st * sa, a * ct],
                     [st, ct * ca, -ct * sa, a * st],
                     [0.0, sa, ca, d],
                     [0.0, 0.0, 0.0, 1.0]])


def _modified_dh(theta, d, a, alpha):
    """Craig's modified DH matrix R_x(alpha) T_x(a) R_z(theta) T_z(d), written out."""
    ct, st, ca, sa = math.cos(theta), math.sin(theta), math.cos(alpha), math.sin(alpha)
    return np.array([[ct, -st, 0.0, a],
                     [st * ca, ct * ca, -sa, -sa * d],
                     [st * sa, ct * sa, ca, ca * d],
                     [0.0, 0.0, 0.0, 1.0]])


def test_hd_matches_standard_dh():
    """(theta, d, a, alpha) = (phi_ij, S_i, h_j, lambda_ij); the modified convention and the
    mapping with the two offsets swapped do not match (the check can fail)."""
    rng = np.random.default_rng(3)
    for theta, alpha, d, a in zip(*_random_params(rng, 20)):
        np.testing.assert_allclose(hd(theta, alpha, d, a), _standard_dh(theta, d, a, alpha), rtol=0, atol=1e-14)
        assert np.abs(hd(theta, alpha, d, a) - _modified_dh(theta, d, a, alpha)).max() > 1e-3
        assert np.abs(hd(theta, alpha, a, d) - _standard_dh(theta, d, a, alpha)).max() > 1e-3


def test_rot_z_rot_x_textbook_entries():
    """(2-60), (2-62), (2-63), (2-64) as printed."""
    phi, lam = 0.7, -1.9
    c, s, cl, sl = math.cos(phi), math.sin(phi), math.cos(lam), math.sin(lam)
    np.testing.assert_allclose(rot_z(phi), [[c, -s, 0], [s, c, 0], [0, 0, 1]], rtol=0, atol=1e-16)
    np.testing.assert_allclose(rot_x(lam), [[1, 0, 0], [0, cl, -sl], [0, sl, cl]], rtol=0, atol=1e-16)
    R_ij = np.array([[c, -cl * s, sl * s], [s, cl * c, -sl * c], [0, sl, cl]])      # (2-63)
    np.testing.assert_allclose(rot_z(phi) @ rot_x(lam), R_ij, rtol=0, atol=1e-15)
    np.testing.assert_allclose(hd(phi, lam, 0.0, 0.0)[:3, :3], R_ij, rtol=0, atol=1e-16)
    np.testing.assert_allclose(hd_inv(phi, lam, 0.0, 0.0)[:3, :3], R_ij.T, rtol=0, atol=1e-16)   # (2-64)
    # the fixed-axis order is a different matrix (§2.5 I)
    assert np.abs(rot_x(lam) @ rot_z(phi) - R_ij).max() > 0.1


def test_rot_z_inverse_is_transpose_and_negative_angle():
    angles = np.linspace(-7, 7, 29)
    R = rot_z(angles)
    np.testing.assert_allclose(R @ np.swapaxes(R, -1, -2), np.broadcast_to(np.eye(3), R.shape), atol=1e-15)
    np.testing.assert_allclose(np.linalg.det(R), 1.0, atol=1e-15)
    np.testing.assert_allclose(rot_z(-angles), np.swapaxes(R, -1, -2), atol=0)
    np.testing.assert_allclose(rot_x(-angles), np.swapaxes(rot_x(angles), -1, -2), atol=0)


@pytest.mark.parametrize("shape", SHAPES)
def test_hd_broadcast(shape):
    phi = np.full(shape, 0.4)
    M = hd(phi, 0.2, 1.0, np.array(2.0))
    assert M.shape == shape + (4, 4)
    np.testing.assert_allclose(M, np.broadcast_to(hd(0.4, 0.2, 1.0, 2.0), M.shape), atol=0)
    assert rot_z(phi).shape == shape + (3, 3)


def test_hd_large_stack_matches_loop():
    rng = np.random.default_rng(11)
    params = _random_params(rng, 100_000)
    stack = hd(*params)
    for k in rng.integers(0, 100_000, 20):
        np.testing.assert_allclose(stack[k], _standard_dh(params[0][k], params[2][k], params[3][k], params[1][k]),
                                   rtol=0, atol=1e-14)


@pytest.mark.parametrize("bad", [np.nan, np.inf])
def test_hd_rejects_nonfinite(bad):
    with pytest.raises(ValueError, match="Expected finite `s`"):
        hd(0.0, 0.0, [1.0, bad], 0.0)
    with pytest.raises(ValueError, match="Expected finite `phi`"):
        rot_z(bad)
    with pytest.raises(ValueError, match="Expected finite `lam`"):
        hd_inv(0.0, bad, 0.0, 0.0)


def test_homogeneous_roundtrip_with_hd():
    M = hd(0.5, 1.0, 2.0, 3.0)
    np.testing.assert_array_equal(homogeneous(M[:3, :3], M[:3, 3]), M)
    with pytest.raises(ValueError, match="Expected `R` of shape"):
        homogeneous(np.eye(4), [0, 0, 0])
