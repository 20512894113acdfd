"""Spherical path synthesis by optimisation (monograph §2.5), checked by independent analysis.

The coupler points of every synthesised linkage are rebuilt here from its parameters by
Rodrigues rotations in mpmath (`sixbar_reference.chain`, and a four-bar built from the
cosine law below), not by `SphericalFourBar.solve` or `SphericalLinkage.solve`.
"""

import mpmath
import numpy as np
import pytest

from mech.spherical import (SphericalFourBar, from_xyz, ground_frame, path_fourbar, path_stephenson1, path_verify,
                            stephenson1, to_xyz)
from mech.spherical.path._sixpath import _chain
from mech.spherical.path._synthesis import _stephenson
from tests.spherical.sixbar_reference import chain, dyad_guesses

mpmath.mp.dps = 50

#: Example 1: a four-bar (nine parameters) whose coupler points, with noise, make the task.
X1 = np.array([0.4, 1.0, 0.6, 0.45, 1.05, 0.85, 1.15, 0.55, 0.7])
TH1 = np.linspace(0.3, 0.3 + np.radians(240.0), 8)
NOISE = 1e-3
#: Example 2: nine points 40 degrees apart on a small circle (arc radius 0.25 about
#: lon 0.5, lat 0.9), met at input angles 30 degrees apart; the start is the best of a
#: multi-start search (book page).
X2 = np.array([0.52653, 0.99258, -4.38134, 0.51352, 0.17085, 0.63038, 0.05345, 0.3594, -2.56499])
TH2 = np.radians(np.arange(9) * 30.0)
TOL2 = 5e-3


#: Example 3: a Stephenson-1 six-bar (fifteen parameters) whose coupler points, with noise
#: of 1e-3 per coordinate, make the task: twelve points at input angles 0 to 1.6 rad.
X6 = np.array([0.2, 1.1, 0.3, 0.3, 0.9, 0.7, 1.0, 0.2, 0.8, 0.3, -1.0, 0.8, 0.7, 0.4, 0.5])
TH6 = np.linspace(0.0, 1.6, 12)
TOL6 = 2e-3


def example3_points():
    Q = _stephenson(X6, (1, 1)).solve(TH6).points["P"] + NOISE * np.random.default_rng(1).standard_normal((12, 3))
    return Q / np.linalg.norm(Q, axis=1)[:, None]


def random_starts(points, count, seed):
    """Starts that know nothing of the linkage that made the task: the input pivot within
    0.5 rad (in longitude and latitude) of the points' mean direction, every arc uniform in
    a middle range, every angle uniform in (-pi, pi)."""
    lon, lat = from_xyz(np.mean(points, axis=0) / np.linalg.norm(np.mean(points, axis=0)))
    rng = np.random.default_rng(seed)
    u = lambda lo, hi: rng.uniform(lo, hi, count)  # noqa: E731
    angle = lambda: u(-np.pi, np.pi)  # noqa: E731
    return np.column_stack([lon + u(-0.5, 0.5), np.clip(lat + u(-0.5, 0.5), -1.5, 1.5), angle(),
                            u(0.2, 1.3), u(0.2, 1.3), u(0.2, 1.3), u(0.2, 1.3),
                            u(0.1, 1.0), angle(), u(0.1, 1.0), angle(),
                            u(0.3, 1.3), u(0.3, 1.3), u(0.1, 1.0), angle()])


def small_circle(centre, rho, angles):
    z = np.asarray(centre, dtype=float)
    x = np.cross([0.0, 0.0, 1.0], z)
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    return np.cos(rho) * z + np.sin(rho) * (np.cos(angles)[:, None] * x + np.sin(angles)[:, None] * y)


def example1_points():
    m = SphericalFourBar(*X1[3:7], coupler=tuple(X1[7:]), frame=ground_frame(*X1[:3]))
    rng = np.random.default_rng(1)
    Q = m.solve(TH1).P + NOISE * rng.standard_normal((TH1.size, 3))
    return Q / np.linalg.norm(Q, axis=1)[:, None]


def example2_points():
    return small_circle(to_xyz(0.5, 0.9), 0.25, np.radians(np.arange(9) * 40.0))


def mp_fourbar_points(linkage, theta):
    """Coupler points from the arcs and the frame alone: B by rotation about A, C from the
    two cosine conditions B.C = cos b, D.C = cos c with the branch sign, P by rotation about B."""
    R = [[mpmath.mpf(float(v)) for v in row] for row in linkage.frame]
    col = lambda j: mpmath.matrix([R[0][j], R[1][j], R[2][j]])
    X, Y, A = col(0), col(1), col(2)
    a, b, c, d = (mpmath.mpf(float(v)) for v in (linkage.a, linkage.b, linkage.c, linkage.d))
    r, g = (mpmath.mpf(float(v)) for v in linkage.coupler)
    dot = lambda p, q: sum(p[i] * q[i] for i in range(3))
    cross = lambda p, q: mpmath.matrix([p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]])
    D = A * mpmath.cos(d) + X * mpmath.sin(d)
    out = []
    for t in theta:
        t = mpmath.mpf(float(t))
        B = A * mpmath.cos(a) + (X * mpmath.cos(t) + Y * mpmath.sin(t)) * mpmath.sin(a)
        k = dot(B, D)
        # C = u B + v D + w (B x D): u + v k = cos b, u k + v = cos c, |C| = 1
        u = (mpmath.cos(b) - k * mpmath.cos(c)) / (1 - k * k)
        v = (mpmath.cos(c) - k * mpmath.cos(b)) / (1 - k * k)
        n = cross(B, D)
        w = linkage.branch * mpmath.sqrt((1 - u * u - v * v - 2 * u * v * k) / dot(n, n))
        C = B * u + D * v + n * w
        tb = C - B * dot(B, C)
        tb = tb / mpmath.sqrt(dot(tb, tb))
        P = B * mpmath.cos(r) + (tb * mpmath.cos(g) + cross(B, tb) * mpmath.sin(g)) * mpmath.sin(r)
        out.append([float(P[i]) for i in range(3)])
    return np.array(out)


def arcs(P, Q):
    return np.arctan2(np.linalg.norm(np.cross(P, Q), axis=1), np.sum(P * Q, axis=1))


def check_by_mpmath(design, tol):
    P = mp_fourbar_points(design.linkage, design.theta)
    assert np.max(np.abs(P - design.generated)) < 1e-12
    assert np.max(arcs(P, design.points)) <= tol


@pytest.mark.parametrize("formulation", ["distance", "constant-arc"])
def test_exact_points_are_recovered(formulation):
    m = SphericalFourBar(*X1[3:7], coupler=tuple(X1[7:]), frame=ground_frame(*X1[:3]))
    Q = m.solve(TH1).P
    d = path_fourbar(Q, TH1, X1 + 0.05, formulation=formulation)
    assert d.passes and d.in_order and d.max_error < 1e-9
    check_by_mpmath(d, 1e-9)


def test_example1_noisy_points_both_formulations():
    Q = example1_points()
    start = X1 + np.array([0.1, -0.1, 0.1, 0.05, -0.05, 0.05, -0.05, 0.1, -0.1])
    dist = path_fourbar(Q, TH1, start, tol=2e-3)
    const = path_fourbar(Q, TH1, start, formulation="constant-arc", tol=2e-3)
    for d in (dist, const):
        assert d.in_order and d.max_error <= 2e-3
        check_by_mpmath(d, 2e-3)
    # the distance formulation minimises the distances themselves: never worse in rms
    assert dist.rms_error <= const.rms_error + 1e-12
    # the noise is 1e-3 per coordinate: the designs stay near the linkage that made the task
    assert np.max(np.abs(dist.parameters - X1)) < 0.05
    # the chordal objective gives the same design to first order in the (small) errors
    chord = path_fourbar(Q, TH1, start, metric="chord")
    assert abs(chord.rms_error - dist.rms_error) < 1e-5


def test_example2_small_circle():
    Q = example2_points()
    d = path_fourbar(Q, TH2, X2, tol=TOL2)
    assert d.passes and d.in_order
    assert d.max_error == pytest.approx(4.179e-3, abs=2e-6)
    check_by_mpmath(d, TOL2)
    # the points are met in order: the coupler point's position angle about the circle's
    # centre increases from point to point along the sweep
    z = to_xyz(0.5, 0.9)
    sweep = d.linkage.solve(np.linspace(TH2[0], TH2[-1], 801)).P
    x = np.cross([0.0, 0.0, 1.0], z)
    x /= np.linalg.norm(x)
    ang = np.unwrap(np.arctan2(sweep @ np.cross(z, x), sweep @ x))
    assert np.all(np.diff(ang) > 0)


def test_stephenson1_recovers_a_known_sixbar():
    x = np.array([0.2, 1.1, 0.3, 0.3, 0.9, 0.7, 1.0, 0.2, 0.8, 0.3, -1.0, 0.8, 0.7, 0.4, 0.5])
    th = np.linspace(0.0, 1.6, 7)
    Q = _stephenson(x, (1, 1)).solve(th).points["P"]
    d = path_stephenson1(Q, th, x + 0.02)
    assert d.passes and d.max_error < 1e-6
    pose = d.linkage.solve(th)
    for i, t in enumerate(th):
        guesses = dyad_guesses(d.linkage, {k: v[i] for k, v in pose.points.items()})
        P = chain(d.linkage, t, guesses)["P"]
        assert np.allclose([float(P[k]) for k in range(3)], Q[i], atol=1e-6)


def test_verify_flags_the_other_branch_and_unassembled_sweeps():
    m = SphericalFourBar(*X1[3:7], coupler=tuple(X1[7:]), frame=ground_frame(*X1[:3]))
    other = SphericalFourBar(*X1[3:7], branch=-1, coupler=tuple(X1[7:]), frame=ground_frame(*X1[:3]))
    Q = m.solve(TH1).P
    assert path_verify(m, Q, TH1)["passes"]
    v = path_verify(other, Q, TH1)
    assert not v["passes"] and v["max_error"] > 0.1
    # a triple rocker cannot sweep a full half turn of its input
    rocker = SphericalFourBar(0.9, 0.5, 0.6, 0.7, coupler=(0.2, 0.3))
    th = np.linspace(0.0, 3.0, 4)
    assert not path_verify(rocker, np.tile([0.0, 0.0, 1.0], (4, 1)), th)["in_order"]


@pytest.mark.parametrize("kwargs, name", [
    ({"points": np.ones((3, 3))}, "points"),
    ({"theta": np.array([0.0, 2.0, 1.0])}, "theta"),
    ({"start": np.ones(8)}, "start"),
    ({"formulation": "sum"}, "formulation"),
    ({"metric": "euclid"}, "metric"),
    ({"tol": -1.0}, "tol"),
])
def test_bad_inputs_are_named(kwargs, name):
    args = {"points": SphericalFourBar(0.5, 1.1, 0.9, 1.2).solve([0.0, 1.0, 2.0]).P,
            "theta": np.array([0.0, 1.0, 2.0]), "start": X1}
    args.update(kwargs)
    with pytest.raises(ValueError, match=f"`{name}`"):
        path_fourbar(args.pop("points"), args.pop("theta"), args.pop("start"), **args)


def test_formulations_compared_on_speed_and_result():
    """Exact points: the constant-arc formulation (dot-product residuals, exact Jacobian) is
    the faster one; the small-circle task, which no four-bar meets exactly: from the same
    start only the distance formulation ends near the points."""
    m = SphericalFourBar(*X1[3:7], coupler=tuple(X1[7:]), frame=ground_frame(*X1[:3]))
    Q = m.solve(TH1).P
    best = {f: min(path_fourbar(Q, TH1, X1 + 0.05, formulation=f).seconds for _ in range(3))
            for f in ("distance", "constant-arc")}
    assert best["constant-arc"] < best["distance"]
    Q2 = example2_points()
    dist = path_fourbar(Q2, TH2, X2, tol=TOL2)
    const = path_fourbar(Q2, TH2, X2, formulation="constant-arc", tol=TOL2)
    assert dist.passes and not const.passes
    assert const.max_error > 10 * dist.max_error


def sixbar_of(design):
    """The designed six-bar rebuilt from its fifteen parameters by the public constructor."""
    x = design.parameters
    lk = design.linkage
    branches = tuple(step[-1] for step in lk._steps if step[0] == "rrr")
    return stephenson1(*x[3:7], E=tuple(x[7:9]), F=tuple(x[9:11]), arcs=tuple(x[11:13]), coupler=tuple(x[13:15]),
                       branches=branches, frame=ground_frame(*x[:3]))


def transmission_sines(points, linkage):
    """sin of the transmission angle of both dyads from the joint positions alone:
    branch * det[P1, P2, J] / (sin b1 sin b2), with the arcs measured from the points;
    positive while each joint stays on its dyad's branch."""
    out = []
    for step in linkage._steps:
        if step[0] == "rrr":
            _, _, (p1, p2), j, _, sign = step
            P1, P2, J = points[p1], points[p2], points[j]
            det = sign * np.einsum("ij,ij->i", np.cross(P1, P2), J)
            out.append(det / (np.linalg.norm(np.cross(P1, J), axis=1) * np.linalg.norm(np.cross(P2, J), axis=1)))
    return np.array(out)


def test_batch_chain_matches_the_linkage_solver():
    """`_chain` (the search's batch evaluation) against `SphericalLinkage.solve` for random
    parameters on both branch pairs, where both assemble."""
    rng = np.random.default_rng(3)
    X = X6 + rng.uniform(-0.2, 0.2, (6, 15))
    th = np.linspace(0.0, 2 * np.pi, 50)
    for branches in ((1, 1), (1, -1), (-1, 1)):
        P, s = _chain(X, th, branches)
        for k, x in enumerate(X):
            pose = _stephenson(x, branches).solve(th)
            ok = pose.assembled
            assert np.array_equal(np.isfinite(P[k]).all(axis=1), ok)   # the same inputs assemble
            assert np.max(np.abs(P[k][ok] - pose.points["P"][ok])) < 1e-12
            assert np.allclose(s[k][ok].T, transmission_sines({n: v[ok] for n, v in pose.points.items()},
                                                               _stephenson(x, branches)), atol=1e-9)


def test_example3_noisy_sixbar_without_constraint_is_not_in_order():
    """The failure the constraint removes: fitted to the noisy points alone, the six-bar
    meets all twelve points, but its second dyad (E-G-F) does not assemble for some inputs
    between the last two prescribed angles, so it cannot move from one to the next."""
    Q = example3_points()
    d = path_stephenson1(Q, TH6, X6 + 0.02, tol=TOL6, min_transmission=None)
    assert not d.in_order and not d.passes
    assert np.isfinite(d.generated).all() and d.max_error < TOL6
    sweep = np.linspace(TH6[0], TH6[-1], 16001)
    pose = sixbar_of(d).solve(sweep)
    gap = sweep[~pose.assembled]
    assert gap.size and TH6[-2] < gap.min() and gap.max() < TH6[-1]
    # the four-bar ABCD (solved on its own) assembles throughout: only E-G-F is lost
    x = d.parameters
    assert SphericalFourBar(*x[3:7], frame=ground_frame(*x[:3])).solve(sweep).valid.all()


def test_example3_noisy_sixbar_from_random_starts():
    """Worked example 3 (book page): ten random starts; the design reaches the twelve noisy
    points within TOL6, on one branch, in order, checked here without `path_verify`."""
    Q = example3_points()
    d = path_stephenson1(Q, TH6, random_starts(Q, 10, 7), tol=TOL6)
    assert d.passes and d.in_order
    lk = sixbar_of(d)
    # (1) every coupler point by an mpmath rotation chain (dyads by findroot, not the closed form)
    pose = lk.solve(TH6)
    P = np.empty((TH6.size, 3))
    for i, t in enumerate(TH6):
        guesses = dyad_guesses(lk, {k: v[i] for k, v in pose.points.items()})
        P[i] = [float(c) for c in chain(lk, mpmath.mpf(float(t)), guesses)["P"]]
    assert np.max(np.abs(P - d.generated)) < 1e-12
    errors = arcs(P, Q)
    assert np.max(np.abs(errors - d.errors)) < 1e-12
    assert errors.max() <= TOL6 and errors.max() == pytest.approx(d.max_error, abs=1e-12)
    # (2) one branch: along a fine sweep both dyads assemble and keep the sign of their
    # transmission sine, bounded away from zero
    sweep = np.linspace(TH6[0], TH6[-1], 16001)
    sp = lk.solve(sweep)
    assert sp.assembled.all()
    s = transmission_sines(sp.points, lk)
    assert s.min() > np.sin(np.radians(30.0)) - 1e-3   # the default min_transmission, to the penalty's give
    # (3) in order: the sweep moves without jumps and passes the points in the given order
    path = sp.points["P"]
    steps = np.linalg.norm(np.diff(path, axis=0), axis=1)
    assert steps.max() < 3.0 * steps.mean()
    nearest = np.argmin(np.linalg.norm(path[None, :, :] - Q[:, None, :], axis=2), axis=1)
    assert np.all(np.diff(nearest) > 0)
    # (4) the path is found, not the parameters: over the whole range the designed curve
    # stays within a few noise levels of the curve that made the task (at equal inputs)
    truth = _stephenson(X6, (1, 1)).solve(sweep).points["P"]
    assert np.max(arcs(path, truth)) < 4e-3
