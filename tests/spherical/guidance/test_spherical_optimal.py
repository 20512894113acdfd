"""Motion analysis and optimal synthesis of spherical guidance four-bars (§3.7), and minimax
function generation (§1.8).

Independent routes: orientations of a task are built from a known linkage solved by
`SphericalFourBar` and placed with Rodrigues rotations written here; orientation errors
are re-measured by the trace formula in mpmath; the equioscillation is checked on the
output angle of `SphericalFourBar.solve` (not the generator's own simulation), with the
extrema found by sign segments written here.
"""


import mpmath
import numpy as np
import pytest

from mech.spherical import (SphericalFourBar, guidance_fourbars, guidance_motion, least_squares, minimax,
                            optimal_guidance, planar_orientations, rotation_matrix)

ARCS = (0.35, 0.75, 0.6, 0.8)
THETA = np.linspace(0.3, 2.6, 9)


def _frame(p, q):
    t = q - np.dot(p, q) * p
    t /= np.linalg.norm(t)
    return np.column_stack([p, t, np.cross(p, t)])


def _task(noise=0.0, seed=0):
    """Nine coupler orientations of a crank-rocker (body axes: zB the north pole, zC at arc b)."""
    linkage = SphericalFourBar(*ARCS, branch=1)
    pose = linkage.solve(THETA)
    zB, zC = np.array([0.0, 0.0, 1.0]), np.array([np.sin(ARCS[1]), 0.0, np.cos(ARCS[1])])
    R = np.stack([_frame(b, c) @ _frame(zB, zC).T for b, c in zip(pose.B, pose.C)])
    rng = np.random.default_rng(seed)
    return np.stack([rotation_matrix(rng.normal(size=3), noise) @ r for r in R]) if noise else R


def _angle_mp(Ra, Rb):
    """Rotation angle of Ra Rb^T by the trace, in mpmath."""
    mpmath.mp.dps = 50
    Ma, Mb = mpmath.matrix(Ra.tolist()), mpmath.matrix(Rb.tolist())
    K = Ma * Mb.T
    half = (K[0, 0] + K[1, 1] + K[2, 2] - 1) / 2
    return float(mpmath.acos(max(-1, min(1, half))))


def _check_by_analysis(fit, R):
    """The reached orientations, by independent measure, match `errors`; one branch, in order."""
    d = fit.design
    motion = guidance_motion(d, d.theta_input)
    assert np.all(motion.valid)
    for j in range(R.shape[0]):
        assert abs(_angle_mp(motion.orientation[j], R[j]) - fit.errors[j]) < 1e-6
    assert d.in_order and d.direction != 0
    steps = np.remainder(d.direction * np.diff(d.theta_input), 2 * np.pi)
    assert np.sum(steps) < 2 * np.pi


def test_motion_reproduces_burmester_design_and_rigid_body():
    """Motion analysis of a guidance four-bar (§3.7): a rigid coupler that meets the design's orientations."""
    P = [13.84 + 188.47j, -31.07 + 140.64j, -51.64 + 96.33j, 44.74 + 113.95j, 66.27 + 215.07j]
    R = planar_orientations(np.radians([0.0, 8.88, 22.1, 63.68, -3.0]), P, 1e-3)
    best = guidance_fourbars(R).passing[0]
    theta = np.linspace(best.theta_input.min(), best.theta_input.max(), 7)
    m = guidance_motion(best, theta)
    zB, zC = best.input_dyad.circle_point, best.output_dyad.circle_point
    assert np.allclose(np.einsum("nij,j->ni", m.orientation, zB), m.B, atol=1e-12)
    assert np.allclose(np.einsum("nij,j->ni", m.orientation, zC), m.C, atol=1e-12)
    assert np.allclose(np.einsum("nij,nkj->nik", m.orientation, m.orientation), np.eye(3), atol=1e-12)
    A, D = best.linkage.A, best.linkage.D
    assert np.allclose(np.arccos(m.B @ A), best.linkage.a, atol=1e-7)
    assert np.allclose(np.arccos(np.sum(m.C * D, axis=-1)), best.linkage.c, atol=1e-7)
    exact = guidance_motion(best, best.theta_input)
    assert max(_angle_mp(exact.orientation[j], R[j]) for j in range(5)) < 1e-7


@pytest.mark.parametrize("objective", ["orientation", "constant_length"])
def test_exact_task_recovers_the_linkage(objective):
    """Optimal synthesis through nine orientations of a known linkage (§3.7) recovers it."""
    R = _task()
    fit = optimal_guidance(R, objective=objective, rtol=1e-9)
    assert fit.design.passes and fit.design.pose_error < 1e-9
    arcs = sorted((fit.design.linkage.a, fit.design.linkage.c))
    assert np.allclose(arcs, sorted((ARCS[0], ARCS[2])), atol=1e-8)
    assert abs(fit.design.linkage.d - ARCS[3]) < 1e-8
    _check_by_analysis(fit, R)


def test_noisy_task_both_objectives_compared():
    """Orientation error against constant length (§3.7), each fit checked by analysis (which
    objective is cheaper is measured in benchmarks/bench_spherical_optimal.py, not here)."""
    R = _task(noise=0.01)
    fits = {}
    for objective in ("orientation", "constant_length"):
        fits[objective] = optimal_guidance(R, objective=objective, rtol=0.02)
        assert fits[objective].design.passes
        _check_by_analysis(fits[objective], R)
    # the orientation objective is the better fit of what it measures
    assert fits["orientation"].rms_error <= fits["constant_length"].rms_error * 1.001
    assert fits["constant_length"].rms_error < 2.0 * fits["orientation"].rms_error


def test_prescribed_input_angles_are_kept():
    R = _task()
    fit = optimal_guidance(R, theta_input=THETA - THETA[0], rtol=1e-8)
    assert fit.design.passes
    assert np.allclose(np.diff(fit.design.theta_input), np.diff(THETA), atol=1e-12)
    _check_by_analysis(fit, R)


def test_bad_inputs():
    R = _task()
    with pytest.raises(ValueError, match="`objective`"):
        optimal_guidance(R, objective="angles")
    with pytest.raises(ValueError, match="`theta_input`"):
        optimal_guidance(R, objective="constant_length", theta_input=THETA)
    with pytest.raises(ValueError, match="`R`"):
        optimal_guidance(R[:4])
    with pytest.raises(TypeError, match="`design`"):
        guidance_motion("linkage", [0.1])


def _segments(e):
    """Largest |e| in each run of one sign, with its sign."""
    cuts = np.flatnonzero(np.diff(np.sign(e)) != 0) + 1
    return [(float(np.sign(s[0])), float(np.max(np.abs(s)))) for s in np.split(e, cuts)]


def test_minimax_equioscillates_and_beats_least_squares():
    """Best approximation (§1.8): five equal alternating extrema, below the least-squares maximum."""
    span_in, span_out = np.radians(90.0), np.radians(60.0)
    theta0, psi0 = np.radians(-120.0), np.radians(-70.0)
    u = np.linspace(1.0, 10.0, 401)
    x, y = span_in * (u - 1.0) / 9.0, span_out * np.log10(u)
    fit = least_squares(x, y, theta0, psi0)
    best = minimax(x, y, theta0, psi0, start=fit)
    psi = SphericalFourBar(*best.arcs, branch=best.branch).solve(theta0 + x).psi
    e = np.angle(np.exp(1j * (psi - psi0 - y)))
    seg = _segments(e)
    assert len(seg) == 5                                    # n + 1 = 5 alternation points for 4 arcs
    peaks = np.array([m for _, m in seg])
    assert np.all(np.abs(peaks / peaks.max() - 1.0) < 1e-6)
    assert abs(peaks.max() - np.max(np.abs(e))) < 1e-15
    assert np.max(np.abs(e)) < 0.75 * fit.max_error


def test_minimax_bad_inputs():
    x = np.linspace(0.0, 1.0, 41)
    with pytest.raises(ValueError, match="`max_iter`"):
        minimax(x, 0.5 * np.sin(x), 0.7, 1.4, max_iter=0)
    with pytest.raises(TypeError, match="`start`"):
        minimax(x, 0.5 * np.sin(x), 0.7, 1.4, start="fit")


@pytest.mark.parametrize("objective", ["orientation", "constant_length"])
def test_planar_limit_of_optimal_synthesis(objective):
    """§3.7 as the arcs shrink: nine poses of a planar four-bar carried onto spheres of radius
    1/scale; the optimal spherical four-bar's arcs divided by the scale tend to the planar
    lengths, with an error that falls like scale**2."""
    from mech.planar import FourBar

    lengths = np.array([1.0, 3.0, 2.5, 3.0])
    pl = FourBar(*lengths).solve(np.linspace(0.4, 2.8, 9))
    theta, d = np.angle(pl.C - pl.B), pl.B          # body frame: origin at B, x along BC
    errors = []
    for scale in (1e-2, 1e-3, 1e-4):
        fit = optimal_guidance(planar_orientations(theta, d, scale), objective=objective)
        link = fit.design.linkage
        got = np.array([link.a, link.b, link.c, link.d]) / scale
        errors.append(float(np.max(np.abs(got - lengths)) / lengths.max()))
        assert fit.design.in_order
    rates = -np.diff(np.log10(errors))
    assert errors[-1] < 1e-6 and np.all(rates > 1.8), (errors, rates)
