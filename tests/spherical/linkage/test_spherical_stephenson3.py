"""The Stephenson-3 spherical six-bar (monograph chapter 4): its analysis (a triad, continued
from the assembly) against an mpmath solution of the six link arcs in other unknowns, and its
guidance design by the constant-length condition, checked by analysis and at 50 digits."""

import mpmath as mp
import numpy as np
import pytest

from mech import AssemblyError
from mech.spherical import SphericalStephenson3, guidance_stephenson3, stephenson3

mp.mp.dps = 50
THETA = np.array([0.0, 0.25, 0.5, 0.75, 1.0])


def _lk():
    return stephenson3(0.35, 0.9, 0.8, 1.1, E=(0.5, 0.7), arcs=(0.9, 0.6), H=(0.55, -0.6), coupler=(0.3, 0.4),
                       mu=0.8)


def _vec(v):
    return mp.matrix([mp.mpf(float(x)) for x in v])


def _dot(p, q):
    return sum(p[i] * q[i] for i in range(3))


def _rot(axis, angle):
    """Rodrigues' rotation at 50 digits."""
    k = _vec(axis)
    k = k / mp.norm(k)
    K = mp.matrix([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    t = mp.mpf(angle) if isinstance(angle, mp.mpf) else mp.mpf(float(angle))
    return mp.eye(3) + mp.sin(t) * K + (1 - mp.cos(t)) * (K * K)


def _sph(lon, lat):
    return mp.matrix([mp.cos(lat) * mp.cos(lon), mp.cos(lat) * mp.sin(lon), mp.sin(lat)])


def _lonlat(v):
    return mp.atan2(v[1], v[0]), mp.asin(v[2])


def test_constructor_arcs_and_links():
    lk = _lk()
    assert lk.theta0 == pytest.approx(0.0, abs=1e-14)
    for name, value in (("AB", 0.35), ("BC", 0.9), ("DH", 0.8), ("AD", 1.1), ("EG", 0.9), ("CG", 0.6),
                        ("AE", 0.5), ("CH", 0.55)):
        assert lk.arcs[name] == pytest.approx(value, abs=1e-12)
    m = lk.members
    # the Stephenson chain with a binary link of its two-link path fixed: ground binary,
    # the ternary links ABE and CGH not adjacent (no joint in common)
    assert len(m["ground"]) == 2 and len(m["ABE"]) == 3 and len(m["CGH"]) >= 3
    assert not set(m["ABE"]) & set(m["CGH"])


def test_closure_along_the_motion_and_continuity():
    lk = _lk()
    th = np.linspace(-2.5, 1.6, 400)
    pose = lk.solve(th)
    assert pose.valid.all()
    assert lk.closure(pose) < 1e-12
    # one branch: the guided link moves continuously (no jump between neighbouring inputs)
    step = np.linalg.norm(np.diff(pose.points["P"], axis=0), axis=-1)
    assert step.max() < 5 * np.median(step)


def test_analysis_matches_an_mpmath_solution_of_the_six_arcs():
    """Independent route: the guided link's joints C, G, H as three points in longitude and
    latitude (six unknowns) meeting the six arc conditions BC, EG, DH, CG, CH, GH, solved by
    mpmath.findroot at 50 digits; the crank's joints by Rodrigues rotations about A."""
    lk = _lk()
    P0 = {k: _vec(v) for k, v in lk.assembly.items()}
    arcs = {k: mp.cos(mp.mpf(v)) for k, v in lk.arcs.items()}
    for t in (-1.9, -0.4, 0.6, 1.5):
        pose = lk.solve(t)
        K = _rot(lk.assembly["A"], t - lk.theta0)
        B, E = K * P0["B"], K * P0["E"]
        start = [c for k in "CGH" for c in _lonlat(_vec(pose.points[k]))]

        def eqs(*x):
            C, G, H = _sph(x[0], x[1]), _sph(x[2], x[3]), _sph(x[4], x[5])
            return [_dot(B, C) - arcs["BC"], _dot(E, G) - arcs["EG"], _dot(P0["D"], H) - arcs["DH"],
                    _dot(C, G) - arcs["CG"], _dot(C, H) - arcs["CH"], _dot(G, H) - arcs["GH"]]

        x = mp.findroot(eqs, start, tol=mp.mpf(10) ** -40)
        for i, k in enumerate("CGH"):
            ref = np.array([float(c) for c in _sph(x[2 * i], x[2 * i + 1])])
            assert np.abs(pose.points[k] - ref).max() < 1e-12
        assert np.abs(pose.points["B"] - np.array([float(c) for c in B])).max() < 1e-14


def test_the_branch_ends_at_a_dead_point_of_the_triad():
    lk = _lk()
    th = np.linspace(1.6, 2.0, 401)
    pose = lk.solve(th)
    assert pose.valid[0] and not pose.valid[-1]
    last = th[pose.valid][-1]
    # there the triad's equations (14) are singular: their smallest singular value falls
    sv = [np.linalg.svd(lk._jacobian(lk.rotations(t), t - lk.theta0), compute_uv=False)[-1] for t in (0.0, last)]
    assert sv[1] < 0.25 * sv[0]
    # never the other assembly: everything beyond the dead point is NaN
    assert np.isnan(pose.points["C"][~pose.valid]).all()
    with pytest.raises(AssemblyError, match="theta"):
        lk.solve(th, strict=True)


def test_a_revolving_crank_repeats_after_one_turn():
    """A branch without dead points closes after one crank turn: far inputs are reduced by the
    period and land where the march over one turn does, links intact."""
    lk = stephenson3(0.2, 1.26, 0.62, 1.26, E=(0.16, 2.54), arcs=(1.06, 0.73), H=(0.53, -2.83), coupler=(0.3, 0.4),
                     mu=1.5)
    turn = lk.solve(np.linspace(0.0, 2 * np.pi, 200))
    assert turn.valid.all() and lk.closure(turn) < 1e-12
    assert np.abs(turn.points["P"][-1] - turn.points["P"][0]).max() < 1e-9
    far = lk.solve([0.3, 0.3 + 2 * np.pi, 0.3 - 6 * np.pi, 0.3 + 40 * np.pi])
    assert far.valid.all() and lk.closure(far) < 1e-12
    assert np.abs(far.points["H"] - far.points["H"][0]).max() < 1e-9


def test_designs_reach_five_orientations_by_analysis_and_recover_the_task():
    """Monograph chapter 4, the Stephenson-3 by the constant-length condition, five orientations:
    square system, exact designs; the six-bar that made the task is among them."""
    lk = _lk()
    R = lk.orientations(THETA)
    designs = guidance_stephenson3(R, THETA, lk.assembly["A"])
    passing = [d for d in designs if d.passes]
    assert passing
    for d in passing:
        assert d.in_order and d.pose_error < 1e-9 and d.arc_residual < 1e-12
        assert np.abs(d.guided_orientations(THETA) - R).max() < 1e-9
        # one branch, in order: the analysis moves through every input in between
        assert np.isfinite(d.guided_orientations(np.linspace(THETA[0], THETA[-1], 41))).all()
    truth = lk.assembly

    def same_axis(p, q):
        return np.linalg.norm(np.cross(p, q)) < 1e-8

    found = [d for d in passing
             if same_axis(d.linkage.assembly["D"], truth["D"])
             and {tuple(np.round(d.linkage.assembly[k], 8)) for k in "BE"}
             == {tuple(np.round(truth[k], 8)) for k in "BE"}]
    assert found


def test_design_keeps_the_arcs_at_50_digits():
    """Independent route: the body carried by the prescribed rotations and the crank turned by
    the prescribed inputs (mpmath Rodrigues rotations, not the design code) keep every arc."""
    lk = _lk()
    R = lk.orientations(THETA)
    d = [x for x in guidance_stephenson3(R, THETA, lk.assembly["A"]) if x.passes][0]
    P = {k: _vec(v) for k, v in d.linkage.assembly.items()}
    R1 = mp.matrix(R[0].tolist())
    worst = mp.mpf(0)
    for j in range(len(THETA)):
        M = mp.matrix(R[j].tolist()) * R1.T
        K = _rot(d.linkage.assembly["A"], THETA[j] - THETA[0])
        for p, q, body in (("B", "C", True), ("E", "G", True), ("D", "H", False)):
            a = K * P[p] if body else P[p]
            worst = max(worst, abs(_dot(a, M * P[q]) - _dot(P[p], P[q])))
    assert worst < 1e-12, worst


def test_beyond_five_least_squares_states_its_error():
    """Eight orientations, one turned by 0.01 rad: the least-squares dyads give a six-bar whose
    errors, measured by analysis, are those reported, in order, on one branch."""
    lk = _lk()
    theta = np.linspace(0.0, 1.4, 8)
    R = lk.orientations(theta)
    exact = guidance_stephenson3(R, theta, lk.assembly["A"])
    # consistent data: the overdetermined constant-length system is solved exactly
    assert exact[0].passes and exact[0].pose_error < 1e-9
    c, s = np.cos(0.01), np.sin(0.01)
    R[3] = R[3] @ np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    designs = guidance_stephenson3(R, theta, lk.assembly["A"], rtol=0.01)
    best = designs[0]
    assert best.passes and best.in_order and best.arc_residual > 1e-4
    got = best.linkage.orientations(theta + best.input_offset) @ best.linkage.orientations(best.linkage.theta0).T
    got = got @ best.first_orientation
    gap = 2 * np.arcsin(np.minimum(1, np.linalg.norm(got - R, axis=(1, 2)) / np.sqrt(8)))
    assert np.allclose(gap, best.errors, atol=1e-12)
    assert 0.002 < best.pose_error < 0.01


def test_bad_inputs():
    lk = _lk()
    R = lk.orientations(THETA)
    with pytest.raises(ValueError, match="at least 5"):
        guidance_stephenson3(R[:4], THETA[:4], [0, 0, 1])
    with pytest.raises(ValueError, match="`subset`"):
        guidance_stephenson3(R, THETA, [0, 0, 1], subset=[0, 1, 2, 3, 3])
    with pytest.raises(ValueError, match="`points`"):
        SphericalStephenson3({"A": [0, 0, 1]})
    with pytest.raises(AssemblyError, match="assemble"):
        stephenson3(0.35, 0.2, 0.1, 1.1, E=(0.5, 0.7), arcs=(0.2, 0.1), H=(0.1, -0.6), coupler=(0.3, 0.4), mu=0.8)
