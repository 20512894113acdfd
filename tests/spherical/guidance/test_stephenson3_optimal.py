"""Optimal guidance by the Stephenson-3 beyond five orientations (monograph chapter 4): the
optimum beats every exact design of five orientations on all eight, and its errors are
measured here from the guided link's joints (C, G, H) solved by `SphericalStephenson3`,
composed into frames written in the test."""

import numpy as np
import pytest

from mech.spherical import guidance_stephenson3, optimal_guidance_stephenson3, stephenson3
from mech.spherical.guidance._stephenson3_optimal import _march

SOURCE = dict(E=(0.5, 0.7), arcs=(0.9, 0.6), H=(0.55, -0.6), coupler=(0.3, 0.4), mu=0.8)


def gap(P, Q):
    M = np.swapaxes(P, -1, -2) @ Q
    axis = np.stack([M[..., 2, 1] - M[..., 1, 2], M[..., 0, 2] - M[..., 2, 0], M[..., 1, 0] - M[..., 0, 1]], -1)
    return np.arctan2(np.linalg.norm(axis, axis=-1), np.trace(M, axis1=-2, axis2=-1) - 1.0)


def test_batched_march_agrees_with_the_linkage_continuation():
    lk = stephenson3(0.35, 0.9, 0.8, 1.1, **SOURCE)
    turns = np.linspace(0.0, 1.0, 21)
    Q, det = _march({k: v[None] for k, v in lk.assembly.items()}, turns)
    assert np.max(np.abs(Q[0] - lk.rotations(lk.theta0 + turns))) < 1e-13
    assert np.all(det > 0.05)


@pytest.mark.slow
def test_optimum_beats_every_exact_design_on_eight_orientations():
    lk = stephenson3(0.35, 0.9, 0.8, 1.1, **SOURCE)
    theta = np.linspace(0.0, 1.0, 8)
    R = lk.orientations(theta)
    c, s = np.cos(0.01), np.sin(0.01)
    R[3] = R[3] @ np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    five = [0, 2, 4, 5, 7]
    exact = [d for d in guidance_stephenson3(R[five], theta[five], lk.assembly["A"]) if d.passes]
    assert exact
    worst = [np.nan_to_num(gap(d.guided_orientations(theta), R), nan=np.pi).max() for d in exact]
    start = exact[int(np.argmin(worst))]
    best = optimal_guidance_stephenson3(R, theta, start)
    assert best.in_order and best.converged
    # the guided link's frame from its joints C and G (the class's own orientation frame is
    # not used), carried from the assembly by the solved rotations
    pose = best.linkage.solve(theta + best.input_offset)
    C, G = pose.points["C"], pose.points["G"]
    t = G - np.sum(C * G, -1, keepdims=True) * C
    t /= np.linalg.norm(t, axis=-1, keepdims=True)
    frames = np.stack([C, t, np.cross(C, t)], axis=-1)
    first = frames[0]
    got = frames @ first.T @ best.first_orientation
    errors = gap(got, R)
    assert np.allclose(errors, best.errors, atol=1e-10)
    assert errors.max() < 0.6 * min(worst)
    assert best.linkage.solve(np.linspace(theta[0], theta[-1], 801) + best.input_offset).valid.all()


def test_a_start_of_another_kind_is_refused_by_name():
    with pytest.raises(TypeError, match="`start`"):
        optimal_guidance_stephenson3(_turns_about_z(6), np.arange(6.0) / 10, object())


def _turns_about_z(n):
    """n distinct orientations: turns of 0.1 rad steps about the z axis."""
    a = 0.1 * np.arange(n)
    c, s = np.cos(a), np.sin(a)
    R = np.zeros((n, 3, 3))
    R[:, 0, 0], R[:, 0, 1], R[:, 1, 0], R[:, 1, 1], R[:, 2, 2] = c, -s, s, c, 1.0
    return R
