"""SphericalFourBar against an independent 50-digit construction, and its planar limit.

The reference (``spherical_reference.py``) intersects two small circles with vectors and
differentiates the construction with ``mpmath.diff``; it never uses the input-output
equation. The planar limit compares with ``mech.planar.FourBar``.
"""

import sys
from pathlib import Path

import numpy as np
import pytest

from mech import AssemblyError
from mech.planar import FourBar
from mech.spherical._fourbar import SphericalFourBar, ground_frame
from mech.spherical._types import classify

sys.path.insert(0, str(Path(__file__).resolve().parent))
import spherical_reference as ref  # noqa: E402


def _to_xyz(lon, lat):
    return np.array([np.cos(lat) * np.cos(lon), np.cos(lat) * np.sin(lon), np.sin(lat)])


def _local_frame(lon, lat):
    """Local x (toward decreasing latitude) and y (east) at to_xyz(lon, lat)."""
    x = np.array([np.sin(lat) * np.cos(lon), np.sin(lat) * np.sin(lon), -np.cos(lat)])
    y = np.array([-np.sin(lon), np.cos(lon), 0.0])
    return x, y


def _inclination(p, q):
    """Inclination at p of the great circle p -> q (p given by lon, lat)."""
    lon, lat = np.arctan2(p[1], p[0]), np.arcsin(np.clip(p[2], -1, 1))
    x, y = _local_frame(lon, lat)
    t = q - np.dot(p, q) * p
    return np.arctan2(np.dot(t, y), np.dot(t, x))


# (arcs, branch, coupler, frame): small, medium, arcs beyond pi/2, both branches, placed
LINKAGES = [
    ((0.3, 0.9, 0.7, 1.0), 1, (0.4, 0.5), None),
    ((0.3, 0.9, 0.7, 1.0), -1, (0.4, 0.5), None),
    ((0.5, 2.0, 1.7, 1.1), -1, (1.9, -2.0), ground_frame(0.3, 0.2, 1.0)),
    ((2.2, 1.9, 2.5, 1.4), 1, (2.0, 2.5), ground_frame(-1.0, -0.5, -2.0)),
    ((1.2, 2.6, 1.8, 2.9), 1, (0.7, 3.0), ground_frame(2.5, 1.2, 0.4)),
    ((0.8, 0.5, 0.6, 0.7), -1, (0.3, -1.0), None),
]
FIELDS3 = ("B", "C", "P", "vB", "vC", "vP", "aB", "aC", "aP", "w_coupler", "dw_coupler")


def _reference_angles(linkage, count=2, margin=0.05):
    """Input angles inside the assembly range, at least `margin` from its ends."""
    rng = linkage.assembly_range()
    if rng.full_turn:
        return np.array([0.4, 2.3])[:count]
    start, end = rng.intervals[0]
    return start + margin + (end - start - 2 * margin) * np.array([0.3, 0.8])[:count]


@pytest.mark.parametrize("case", range(len(LINKAGES)))
def test_solve_matches_reference(case):
    arcs, branch, coupler, frame = LINKAGES[case]
    linkage = SphericalFourBar(*arcs, branch=branch, coupler=coupler, frame=frame)
    meeting = classify(*arcs).meeting_angles
    omega, alpha = 1.3, -0.4
    for theta in _reference_angles(linkage):
        # past a change point (0 or pi) the motion continues on the other det[B, D, C] sign
        side = branch * (-1 if 0.0 in meeting and np.sin(theta / 2) < 0 else 1)
        side *= -1 if np.pi in meeting and np.cos(theta / 2) < 0 else 1
        reference = ref.Linkage(*arcs, branch=side, coupler=coupler,
                                frame=None if frame is None else frame.tolist())
        pose = linkage.solve(theta, order=2, omega=omega, alpha=alpha)
        exact = ref.pose(reference, theta)
        exact.update(ref.rates(reference, theta, omega, alpha))
        assert pose.valid
        for name in FIELDS3:
            want = np.array([float(x) for x in exact[name]])
            assert np.max(np.abs(getattr(pose, name) - want)) < 1e-12, name
        for name in ("psi", "omega_output", "alpha_output"):
            assert abs(getattr(pose, name) - float(exact[name])) < 1e-12, name
        D = linkage.D
        assert np.max(np.abs(pose.w_output - pose.omega_output * D)) < 1e-15
        assert np.max(np.abs(pose.dw_output - pose.alpha_output * D)) < 1e-15
        assert np.max(np.abs(pose.w_input - omega * linkage.A)) < 1e-15


def test_solve_branch_sign_is_det_BDC():
    theta = np.linspace(-3.0, 3.0, 31)
    for arcs, _, coupler, frame in LINKAGES[:5]:
        for branch in (1, -1):
            pose = SphericalFourBar(*arcs, branch=branch, coupler=coupler, frame=frame).solve(theta)
            ok = pose.valid
            D = np.broadcast_to(SphericalFourBar(*arcs, frame=frame).D, pose.B[ok].shape)
            det = np.linalg.det(np.stack((pose.B[ok], D, pose.C[ok]), axis=-1))
            assert ok.sum() > 5 and np.all(np.sign(det) == branch)


def test_solve_theta_psi_are_inclination_differences():
    """theta = incl(A->B) - incl(A->D) at A; psi = incl(D->C) - incl(A->D continued) at D."""
    frame = ground_frame(0.7, -0.3, 2.0)
    linkage = SphericalFourBar(0.5, 2.0, 1.7, 1.1, coupler=(0.3, 0.2), frame=frame)
    A, D = linkage.A, linkage.D
    assert np.allclose(A, _to_xyz(0.7, -0.3), atol=1e-15)
    assert abs(_inclination(A, D) - 2.0) < 1e-14
    for theta in (-2.0, 0.5, 2.9):
        pose = linkage.solve(theta)
        wrap = lambda x: np.angle(np.exp(1j * x))  # noqa: E731
        assert abs(wrap(_inclination(A, pose.B) - _inclination(A, D) - theta)) < 1e-13
        continued = _inclination(D, A) + np.pi
        assert abs(wrap(_inclination(D, pose.C) - continued - pose.psi)) < 1e-13


def _planar_errors(dims, r, gamma, branch, eps_values, theta):
    """Largest relative error, over all fields, of the eps-scaled linkage against FourBar."""
    p, q = r * np.cos(gamma), r * np.sin(gamma)
    planar = FourBar(*dims, branch=branch, coupler=(p, q)).solve(theta, order=2, omega=1.3, alpha=-0.4)
    errors = []
    for eps in eps_values:
        sph = SphericalFourBar(*(eps * np.asarray(dims)), branch=branch, coupler=(eps * r, gamma)).solve(
            theta, order=2, omega=1.3, alpha=-0.4)
        worst = 0.0
        for name in ("B", "C", "P", "vB", "vC", "vP", "aB", "aC", "aP"):
            z = getattr(planar, name)
            got = getattr(sph, name)[..., 0] / eps + 1j * getattr(sph, name)[..., 1] / eps
            worst = max(worst, np.max(np.abs(got - z)) / np.max(np.abs(z)))
        pairs = ((sph.omega_output, planar.omega_output), (sph.alpha_output, planar.alpha_output),
                 (sph.w_coupler[..., 2], planar.omega_coupler), (sph.dw_coupler[..., 2], planar.alpha_coupler))
        for got, want in pairs:
            worst = max(worst, np.max(np.abs(got - want)) / np.max(np.abs(want)))
        worst = max(worst, np.max(np.abs(np.angle(np.exp(1j * (sph.psi - planar.psi))))) / np.pi)
        errors.append(worst)
    return np.array(errors)


@pytest.mark.parametrize("branch", [1, -1])
def test_solve_planar_limit_rate(branch):
    """Arcs (and r) scaled by eps from 1e-1 to 1e-6: errors fall as eps**2 all the way."""
    eps_values = 10.0 ** -np.arange(1, 7)
    theta = np.linspace(-np.pi, np.pi, 73)
    errors = _planar_errors((1.0, 4.0, 3.0, 3.5), 2.2, 0.45, branch, eps_values, theta)
    slope = np.polyfit(np.log10(eps_values), np.log10(errors), 1)[0]
    assert abs(slope - 2.0) < 0.2, (slope, errors)
    assert np.all(errors[1:] < errors[:-1] / 50)
    assert errors[-1] < 1e-11, errors


def test_solve_planar_limit_example_2_1():
    """Example 2-1 (10, 40, 30, 35) shrunk to the sphere: same psi within eps**2."""
    theta = np.linspace(0.0, 2 * np.pi, 25)
    dims = np.array([10.0, 40.0, 30.0, 35.0]) / 40.0          # the longest arc is eps
    errors = _planar_errors(dims, 0.5, 0.6, 1, [1e-4, 1e-6], theta)
    assert errors[0] < 1e-8 and errors[1] < 1e-12


def _jump_ratio(points):
    """Largest ratio of a step to the larger of its two neighbours: near 1 on a smooth
    curve (also where it speeds up toward a limit position), large at an isolated jump."""
    steps = np.linalg.norm(np.diff(points, axis=0), axis=-1)
    return np.max(steps[1:-1] / np.maximum(steps[:-2], steps[2:]))


@pytest.mark.parametrize("case", [0, 3, 4])
def test_solve_branch_continuity(case):
    arcs, _, coupler, frame = LINKAGES[case]
    for branch in (1, -1):
        linkage = SphericalFourBar(*arcs, branch=branch, coupler=coupler, frame=frame)
        rng = linkage.assembly_range()
        start, end = (-np.pi, np.pi) if rng.full_turn else rng.intervals[0] + np.array([1e-3, -1e-3])
        theta = np.linspace(start, end, 4001)
        pose = linkage.solve(theta)
        assert np.all(pose.valid)
        assert _jump_ratio(pose.C) < 1.5
        assert _jump_ratio(pose.P) < 1.5
    # control: switching branch half-way produces a jump the measure sees
    other = SphericalFourBar(*arcs, branch=1, coupler=coupler, frame=frame).solve(theta).C
    mixed = np.where((np.arange(theta.size) < theta.size // 2)[:, None], pose.C, other)
    assert _jump_ratio(mixed) > 10.0


def test_assembly_range_matches_scan():
    for arcs, branch, coupler, frame in LINKAGES + [((0.8, 0.3, 0.9, 0.5), 1, (0.0, 0.0), None),
                                                   ((0.5, 0.4, 0.3, 1.1), 1, (0.0, 0.0), None)]:
        linkage = SphericalFourBar(*arcs, branch=branch, coupler=coupler, frame=frame)
        rng = linkage.assembly_range()
        theta = np.linspace(-np.pi, np.pi, 2001)[:-1] + 1e-4
        valid = linkage.solve(theta).valid
        inside = rng.contains(theta)
        assert np.array_equal(valid, inside)
        for start, end in rng.intervals:
            for end_point, side in ((start, -1), (end, 1)):
                assert linkage.solve(end_point - side * 1e-7).valid
                assert not linkage.solve(end_point + side * 1e-7).valid


def test_assembly_range_never():
    rng = SphericalFourBar(0.2, 0.3, 0.2, 1.5).assembly_range()
    assert not rng.full_turn and rng.intervals.shape == (0, 2)


def test_solve_strict_error_message():
    linkage = SphericalFourBar(0.8, 0.5, 0.6, 0.7)
    with pytest.raises(AssemblyError, match=r"at theta = 3.0; it assembles for theta in \[-"):
        linkage.solve([0.0, 3.0, 3.1], strict=True)
    assert not linkage.solve(3.0).valid and np.isnan(linkage.solve(3.0).P).all()
    assert linkage.solve([0.0, 0.5], strict=True).valid.all()


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_solve_shapes(shape):
    theta = np.full(shape, 0.7)
    pose = SphericalFourBar(0.3, 0.9, 0.7, 1.0, coupler=(0.4, 0.5)).solve(theta, order=2)
    assert np.shape(pose.psi) == shape and pose.valid.shape == shape
    assert pose.P.shape == shape + (3,) and pose.dw_coupler.shape == shape + (3,)


def test_solve_order_limits_fields():
    pose = SphericalFourBar(0.3, 0.9, 0.7, 1.0).solve(0.5, order=1)
    assert pose.vP.shape == (3,)
    with pytest.raises(AttributeError, match="order=2"):
        pose.aP
    with pytest.raises(AttributeError, match="order=1"):
        SphericalFourBar(0.3, 0.9, 0.7, 1.0).solve(0.5).w_coupler


@pytest.mark.parametrize("name, value", [("a", 0.0), ("b", np.pi), ("c", -0.1), ("d", 4.0)])
def test_init_rejects_arcs_outside_open_interval(name, value):
    arcs = dict(a=0.3, b=0.9, c=0.7, d=1.0)
    arcs[name] = value
    with pytest.raises(ValueError, match=f"Expected `{name}` in \\(0, pi\\)"):
        SphericalFourBar(**arcs)


def test_init_rejects_improper_frame():
    with pytest.raises(ValueError, match="Expected `frame` to be a proper rotation"):
        SphericalFourBar(0.3, 0.9, 0.7, 1.0, frame=np.diag([1.0, 1.0, -1.0]))
    with pytest.raises(ValueError, match="Expected `frame`"):
        SphericalFourBar(0.3, 0.9, 0.7, 1.0, frame=np.eye(2))
    with pytest.raises(ValueError, match="Expected `branch`"):
        SphericalFourBar(0.3, 0.9, 0.7, 1.0, branch=0)


def test_ground_frame_is_rotation_with_pole_and_heading():
    for lon, lat, heading in ((0.0, np.pi / 2, 0.0), (0.3, 0.2, 1.0), (-2.0, -1.1, -2.5)):
        R = ground_frame(lon, lat, heading)
        assert np.allclose(R.T @ R, np.eye(3), atol=1e-15) and np.linalg.det(R) > 0
        A = _to_xyz(lon, lat)
        assert np.allclose(R[:, 2], A, atol=1e-15)
        D = SphericalFourBar(0.3, 0.9, 0.7, 1.0, frame=R).D
        assert abs(np.angle(np.exp(1j * (_inclination(A, D) - heading)))) < 1e-13
    assert np.allclose(ground_frame(0.0, np.pi / 2, 0.0), np.eye(3))


def test_coupler_curve_on_sphere_and_range():
    linkage = SphericalFourBar(0.8, 0.5, 0.6, 0.7, coupler=(0.3, 1.0))
    theta, P = linkage.coupler_curve(200)
    ok = np.isfinite(theta)
    assert np.all(np.isfinite(P[ok])) and np.allclose(np.linalg.norm(P[ok], axis=-1), 1.0)
    assert np.all(linkage.assembly_range().contains(theta[ok]))
