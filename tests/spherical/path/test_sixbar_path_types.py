"""Path synthesis of the four spherical six-bars (monograph §2.5 with §2.4), checked by an
independent analysis: every coupler point is rebuilt by Rodrigues rotations in mpmath at 50
digits with each dyad solved by `findroot` (`tests/spherical/sixbar_reference.py`), never by
the closed form the search uses."""

import mpmath
import numpy as np
import pytest

from mech.spherical import path_stephenson1, path_stephenson2, path_watt1, path_watt2
from mech.spherical.path._sixpath import KNOWN, _chain
from mech.spherical.path._synthesis import _sixbar
from tests.spherical.sixbar_reference import chain, dyad_guesses

SYNTHESIS = {"stephenson1": path_stephenson1, "stephenson2": path_stephenson2, "watt1": path_watt1,
             "watt2": path_watt2}
TH = np.linspace(0.0, 3.2, 12)
NOISE, TOL = 1e-3, 2.5e-3


def reference_points(linkage, theta):
    """Coupler points of `linkage` at `theta` by the mpmath rotation chain."""
    pose = linkage.solve(theta)
    out = np.empty((len(theta), 3))
    with mpmath.workdps(50):
        for i, t in enumerate(theta):
            guesses = dyad_guesses(linkage, {k: v[i] for k, v in pose.points.items()})
            P = chain(linkage, mpmath.mpf(float(t)), guesses)["P"]
            out[i] = [float(P[k]) for k in range(3)]
    return out


def arcs(P, Q):
    return np.arctan2(np.linalg.norm(np.cross(P, Q), axis=1), np.sum(P * Q, axis=1))


def transmission_signs(linkage, theta):
    """Sign of det[P1, P2, J] of each dyad (times its branch) along `theta`, from the joint
    positions: +1 while the joint stays on its branch."""
    pose = linkage.solve(theta)
    signs = []
    for step in linkage._steps:
        if step[0] == "rrr":
            _, _, (p1, p2), j, _, sign = step
            P1, P2, J = (pose.points[n] for n in (p1, p2, j))
            signs.append(np.sign(sign * np.einsum("ij,ij->i", np.cross(P1, P2), J)))
    return np.array(signs)


@pytest.mark.parametrize("kind", sorted(SYNTHESIS))
def test_batch_chain_matches_the_linkage_solver(kind):
    rng = np.random.default_rng(11)
    X = np.array(KNOWN[kind]) + rng.uniform(-0.15, 0.15, (5, 15))
    th = np.linspace(0.0, 2 * np.pi, 40)
    for branches in ((1, 1), (1, -1), (-1, 1)):
        P, _ = _chain(X, th, branches, kind)
        for k, x in enumerate(X):
            pose = _sixbar(kind, x, branches).solve(th)
            ok = pose.assembled
            assert np.array_equal(np.isfinite(P[k]).all(axis=1), ok)
            assert np.max(np.abs(P[k][ok] - pose.points["P"][ok]), initial=0.0) < 1e-12


@pytest.mark.parametrize("kind", sorted(SYNTHESIS))
def test_exact_points_recover_the_sixbar(kind):
    """Twelve points of a known six-bar of each type (sixteen for the Watt-2); the design
    passes through them to 1e-10 rad by the independent chain."""
    x = np.array(KNOWN[kind])
    # the Watt-2 has one independent parameter less and a nearly flat direction more: twelve
    # points over 3.2 rad leave it creeping from this start, sixteen over 5.8 rad pin it
    th = np.linspace(0.0, 5.8, 16) if kind == "watt2" else TH
    Q = reference_points(_sixbar(kind, x, (1, 1)), th)
    d = SYNTHESIS[kind](Q, th, x + 0.02)
    assert d.kind == kind and d.passes and d.in_order
    assert np.max(arcs(reference_points(d.linkage, th), Q)) < 1e-10


@pytest.mark.parametrize("kind", sorted(SYNTHESIS))
def test_noisy_points_are_met_to_the_noise_on_one_branch_in_order(kind):
    """Twelve points with noise of 1e-3 per coordinate: the design meets every point to
    within the noise (by the independent chain), keeps both dyads on their branches along a
    sweep of 4001 inputs (so it meets the points in the order of its increasing input), and
    its coupler point moves without a jump."""
    x = np.array(KNOWN[kind])
    rng = np.random.default_rng(5)
    Q = _sixbar(kind, x, (1, 1)).solve(TH).points["P"] + NOISE * rng.standard_normal((TH.size, 3))
    Q /= np.linalg.norm(Q, axis=1)[:, None]
    noise = arcs(_sixbar(kind, x, (1, 1)).solve(TH).points["P"], Q)
    d = SYNTHESIS[kind](Q, TH, x + 0.02, tol=TOL)
    assert d.passes and d.in_order
    errors = arcs(reference_points(d.linkage, TH), Q)
    # a least-squares fit is no worse than the linkage that made the points
    assert np.sqrt(np.mean(errors**2)) <= np.sqrt(np.mean(noise**2)) + 1e-9
    assert errors.max() < TOL
    sweep = np.linspace(TH[0], TH[-1], 4001)
    assert d.linkage.solve(sweep).assembled.all()
    signs = transmission_signs(d.linkage, sweep)
    assert np.all(signs == 1)
    # in order: the points are met at increasing inputs, and between them the coupler point
    # moves continuously on the one assembly (no jump to the other branch)
    P = d.linkage.solve(sweep).points["P"]
    steps = arcs(P[1:], P[:-1])
    assert steps.max() < 20 * np.median(steps)


def test_watt2_input_fourbar_turns_about_D_freely():
    """Counting precision points: the Jacobian of the twelve coupler points with respect to
    the fifteen parameters has rank 15 for the Stephenson-1, Stephenson-2 and Watt-1 and
    rank 14 for the Watt-2, whose input four-bar can be turned about D without moving a
    coupler point (the null vector involves the frame, E's angle and F)."""
    th = np.linspace(0.0, 6.0, 12)
    for kind in SYNTHESIS:
        x, h = np.array(KNOWN[kind]), 1e-5
        P, _ = _chain(np.concatenate((x + h * np.eye(15), x - h * np.eye(15))), th, (1, 1), kind)
        J = ((P[:15] - P[15:]) / (2 * h)).reshape(15, -1).T
        _, sv, vt = np.linalg.svd(J)
        ratio = sv / sv[0]
        if kind == "watt2":
            assert ratio[-1] < 1e-9 and ratio[-2] > 1e-7
            null = vt[-1] / np.abs(vt[-1]).max()
            assert np.all(np.abs(null[3:8]) < 1e-3) and np.all(np.abs(null[11:]) < 1e-3)
        else:
            assert ratio[-1] > 1e-7
