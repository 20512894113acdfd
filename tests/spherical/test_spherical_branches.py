"""SphericalFourBar through its change points: no jump, continuous rates, the branch rule.

Change-point linkages of every kind (deltoids a = d, b = c and a = b, c = d, isograms a = c,
b = d, rhombi, all arcs pi/2, arcs beyond pi/2 with B passing through the antipode of D, and
general s + l = p + q linkages) are swept densely through a full turn and through clusters
of angles 1e-12 .. 1e-3 from each change point, and compared with the independent 50-digit
construction of ``spherical_reference.py`` (two small circles intersected, the root chosen
by the sign of det[B, D, C]). The rule under test: `branch` names the branch on
0 < theta < pi; crossing a change point at 0 or pi the motion continues onto the other sign
of det[B, D, C] (it stays smooth). At the change point itself the expected pose is the
reference's limit from theta > 0.
"""

import sys
from pathlib import Path

import mpmath
import numpy as np
import pytest

from mech import spherical
from mech.planar import FourBar
from mech.spherical import SphericalFourBar

sys.path.insert(0, str(Path(__file__).resolve().parent))
import spherical_reference as ref  # noqa: E402

EPS = np.finfo(float).eps
DPS = 80          # digits: at 1e-25 from B = D the reference's 1 - (B.D)^2 is 1e-50
Q = np.pi / 2

# name -> (arcs, meeting angles): every kind of change point named in issue 11. Arcs are
# exact expressions: the reference uses them at 50 digits (pi - 0.8 rounded to a double is
# only a near-change-point linkage, whose motion near the change point differs).
KINDS = {
    "deltoid-a=d": (("0.3", "0.8", "0.8", "0.3"), (0.0,)),
    "deltoid-wide": (("0.5", "1.1", "1.1", "0.5"), (0.0,)),
    "deltoid-large-crank": (("2.5", "1.0", "1.0", "2.5"), (0.0,)),
    "deltoid-a=b": (("0.5", "0.5", "0.9", "0.9"), (0.0, np.pi)),
    "isogram": (("0.4", "0.9", "0.4", "0.9"), (0.0, np.pi)),
    "rhombus": (("0.6", "0.6", "0.6", "0.6"), (0.0, np.pi)),
    "rhombus-large": (("2.0", "2.0", "2.0", "2.0"), (0.0, np.pi)),
    "quarter": (("pi/2", "pi/2", "pi/2", "pi/2"), (0.0, np.pi)),
    "deltoid-quarter-coupler": (("0.5", "pi/2", "pi/2", "0.5"), (0.0,)),
    "antipodal-deltoid": (("0.3", "0.8", "pi-0.8", "pi-0.3"), (np.pi,)),
    "antipodal-isogram": (("0.4", "0.9", "pi-0.4", "pi-0.9"), (0.0, np.pi)),
    "antipodal-crank": (("0.6", "2.1", "pi-2.1", "pi-0.6"), (np.pi,)),
    "s+l=p+q-at-0": (("0.4", "1.3", "0.9", "0.8"), (0.0,)),
    "s+l=p+q-b>c": (("0.7", "1.1", "0.9", "0.9"), (0.0,)),
}


def _exact(text):
    """An arc written as a decimal, "pi/2" or "pi-x", at 50 digits."""
    with mpmath.workdps(DPS):
        if text == "pi/2":
            return mpmath.pi / 2
        if text.startswith("pi-"):
            return mpmath.pi - mpmath.mpf(text[3:])
        return mpmath.mpf(text)


def _arcs(name):
    return tuple(float(_exact(t)) for t in KINDS[name][0])


def _ref_linkage(name, side):
    """The reference linkage with the exact arcs."""
    lk = ref.Linkage(*_arcs(name), branch=side, coupler=COUPLER)
    with mpmath.workdps(DPS):
        lk.a, lk.b, lk.c, lk.d = (_exact(t) for t in KINDS[name][0])
        lk.D = lk.R * mpmath.matrix([mpmath.sin(lk.d), 0, mpmath.cos(lk.d)])
    return lk


COUPLER = (0.4, 0.7)
OFFSETS = np.logspace(-12, -3, 19)


def _linkage(name, branch):
    return SphericalFourBar(*_arcs(name), branch=branch, coupler=COUPLER)


def _side_branch(branch, meeting, theta):
    """The det[B, D, C] sign the rule predicts at theta (period 4 pi)."""
    sign = branch
    if 0.0 in meeting and np.sin(theta / 2) < 0:
        sign = -sign
    if np.pi in meeting and np.cos(theta / 2) < 0:
        sign = -sign
    return sign


def _reference(name, branch, theta):
    """Reference pose at theta on the branch the rule predicts; at a meeting angle the limit
    from above (evaluated 1e-30 past it at 50 digits)."""
    meeting = KINDS[name][1]
    lk = _ref_linkage(name, _side_branch(branch, meeting, theta + 1e-300))
    with mpmath.workdps(DPS):
        at = mpmath.mpf(float(theta))
        if theta in meeting or theta == 0.0:
            at += mpmath.mpf("1e-25")
        return ref._points(lk, at)


def _angles(meeting):
    out = [0.3, 1.9, -2.2, 2.9]
    for m in meeting:
        for sign in (1.0, -1.0):
            out.extend(m + sign * OFFSETS)
        out.append(m)
    return np.array(out)


@pytest.mark.parametrize("branch", [1, -1])
@pytest.mark.parametrize("name", sorted(KINDS))
def test_solve_change_point_against_reference(name, branch):
    """Positions near and at every change point agree with 50 digits to a few rounding errors."""
    linkage = _linkage(name, branch)
    assert linkage.change_point
    assert spherical.classify(*_arcs(name)).meeting_angles == KINDS[name][1]
    theta = _angles(KINDS[name][1])
    pose = linkage.solve(theta)
    worst = 0.0
    for i, th in enumerate(theta):
        want = _reference(name, branch, th)
        if want is None:
            assert not pose.valid[i], (name, th)
            continue
        assert pose.valid[i], (name, th)
        err = abs(np.angle(np.exp(1j * (pose.psi[i] - float(want["psi"])))))
        for field in ("B", "C", "P"):
            err = max(err, np.max(np.abs(getattr(pose, field)[i] - np.array([float(x) for x in want[field]]))))
        worst = max(worst, err)
    assert worst <= 64 * EPS, (name, worst)


def test_issue_example_no_jump():
    """The tester's example: psi and the output rate on both sides of theta = 0."""
    pose = SphericalFourBar(0.3, 0.8, 0.8, 0.3).solve([-1e-9, 0.0, 1e-9], order=2)
    assert pose.valid.all()
    assert np.max(np.abs(np.diff(pose.psi))) <= 1e-9
    assert np.max(np.abs(np.diff(pose.omega_output))) <= 1e-9
    quarter = SphericalFourBar(Q, Q, Q, Q).solve([-1e-9, 0.0, 1e-9, np.pi], order=1)
    assert quarter.valid.all() and np.ptp(np.exp(1j * quarter.psi)) <= 1e-15


def test_deltoid_helper_and_isogram_helper():
    for linkage in (spherical.deltoid(0.3, 0.8), spherical.deltoid(0.5, 1.1, branch=-1),
                    spherical.isogram(0.4, 0.9), spherical.isogram(0.4, 0.9, branch=-1)):
        assert linkage.change_point
        theta = np.concatenate([-OFFSETS[::-1], [0.0], OFFSETS])
        pose = linkage.solve(theta, order=2)
        assert pose.valid.all()
        assert np.max(np.abs(np.angle(np.exp(1j * np.diff(pose.psi))))) <= 2e-3
        assert np.max(np.abs(np.diff(pose.omega_output))) <= 2e-3 * np.max(np.abs(pose.alpha_output)) + 1e-12


def _sweep(meeting, n=100_000):
    """A full turn of n angles plus the clusters around each meeting angle, sorted; the
    turn runs from -pi to 3 pi so that theta = pi and -pi are both inside."""
    parts = [np.linspace(-np.pi, 3 * np.pi, n)]
    for m in meeting:
        for centre in (m, m + 2 * np.pi):
            parts.append(centre + np.concatenate([-OFFSETS, OFFSETS, [0.0]]))
    return np.unique(np.concatenate(parts))


@pytest.mark.parametrize("branch", [1, -1])
@pytest.mark.parametrize("name", sorted(KINDS))
def test_solve_branch_continuity_dense(name, branch):
    """No jump: |d psi| <= |dpsi/dtheta| h + |d2psi/dtheta2| h^2 / 2 (the larger end values),
    and the same for the rate; 1e5 angles plus the clusters, on both turns of the 4 pi period."""
    theta = _sweep(KINDS[name][1])
    pose = _linkage(name, branch).solve(theta, order=2)
    ok = pose.valid[1:] & pose.valid[:-1]
    h = np.diff(theta)
    w, al = np.abs(pose.omega_output), np.abs(pose.alpha_output)
    wmax, amax = np.maximum(w[1:], w[:-1]), np.maximum(al[1:], al[:-1])
    floor = 16 * EPS * np.pi                    # rounding of psi itself
    dpsi = np.abs(np.angle(np.exp(1j * np.diff(pose.psi))))
    slack = 1.01 * (wmax * h + amax * h * h / 2) + floor
    assert np.all((dpsi <= slack)[ok]), (name, np.max((dpsi / slack)[ok]))
    # the rate: its change is bounded by the acceleration, plus a third-derivative term
    third = np.max(np.abs(np.diff(pose.alpha_output))[ok] / h[ok])
    dw = np.abs(np.diff(pose.omega_output))
    slack_w = 1.01 * (amax * h + third * h * h / 2) + 16 * EPS * (1 + wmax)
    assert np.all((dw <= slack_w)[ok]), (name, np.max((dw / slack_w)[ok]))
    # a change-point linkage with a full-turn crank assembles everywhere, also at B = D
    if SphericalFourBar(*_arcs(name)).assembly_range().full_turn:
        assert pose.valid.all()


@pytest.mark.parametrize("name", ["deltoid-a=d", "isogram", "rhombus", "quarter", "antipodal-deltoid",
                                  "s+l=p+q-b>c", "deltoid-a=b"])
def test_solve_change_point_rates_against_reference(name, monkeypatch):
    """Rates (order 2) at 1e-9 and 1e-4 from each change point and at it (the limit)."""
    monkeypatch.setattr(ref, "DPS", DPS)
    meeting = KINDS[name][1]
    omega, alpha = 1.3, -0.7
    linkage = _linkage(name, 1)
    worst = 0.0
    for m in meeting:
        for th in (m - 1e-4, m - 1e-9, m, m + 1e-9):
            pose = linkage.solve(th, order=2, omega=omega, alpha=alpha)
            side = _side_branch(1, meeting, th + 1e-300)
            lk = _ref_linkage(name, side)
            at = mpmath.mpf(th) + mpmath.mpf("1e-20") if th == m else th
            want = ref.rates(lk, at, omega, alpha)
            scale = 1.0 + max(abs(float(want["omega_output"])), abs(float(want["alpha_output"])))
            errs = [abs(pose.omega_output - float(want["omega_output"])),
                    abs(pose.alpha_output - float(want["alpha_output"]))]
            for field in ("vB", "vC", "vP", "aB", "aC", "aP", "w_coupler", "dw_coupler"):
                errs.append(np.max(np.abs(getattr(pose, field) - np.array([float(x) for x in want[field]]))))
            worst = max(worst, max(errs) / scale)
    assert worst <= 1e-12, (name, worst)


# planar change-point shapes (lengths a, b, c, d), scaled to arcs of size eps
PLANAR_SHAPES = {"parallelogram": (2.0, 3.0, 2.0, 3.0), "kite": (1.0, 2.0, 2.0, 1.0),
                 "rhombus": (1.0, 1.0, 1.0, 1.0), "deltoid": (1.0, 1.0, 2.0, 2.0),
                 "s+l=p+q": (0.4, 1.3, 0.9, 0.8)}


@pytest.mark.parametrize("branch", [1, -1])
@pytest.mark.parametrize("shape", sorted(PLANAR_SHAPES))
def test_solve_change_point_planar_limit(shape, branch):
    """Arcs eps * (a, b, c, d) follow the planar FourBar of the same shape through its change
    points (the same branch rule, two turns): psi and the rate differ by O(eps^2). Angles
    within 0.01 of theta = 0 or pi are left out: the planar solver loses digits there for
    kites and rhombi (issue 11, item 5); the spherical clusters are checked above."""
    lengths = np.array(PLANAR_SHAPES[shape])
    theta = np.linspace(-np.pi, 3 * np.pi, 401)
    theta = theta[np.abs(np.sin(theta)) >= 0.01]
    planar = FourBar(*lengths, branch=branch).solve(theta, order=1)
    assert planar.valid.all()
    for eps in (1e-2, 1e-4, 1e-6):
        pose = SphericalFourBar(*(eps * lengths), branch=branch).solve(theta, order=1)
        assert pose.valid.all()
        dpsi = np.abs(np.angle(np.exp(1j * (pose.psi - planar.psi))))
        assert np.max(dpsi) <= 4 * eps**2 + 1e-13, (shape, eps, np.max(dpsi))
        dw = np.abs(pose.omega_output - planar.omega_output)
        assert np.max(dw) <= 4 * eps**2 * (1 + np.max(np.abs(planar.omega_output))) + 1e-12


@pytest.mark.parametrize("shape", ["kite", "rhombus", "parallelogram"])
def test_solve_change_point_planar_limit_closed_form(shape):
    """Near theta = 0 the planar kite and rhombus have closed forms (C on the bisector of the
    input angle, A C = b + ... by symmetry): the spherical linkage at eps = 1e-6 follows them
    to O(eps^2) at 1e-12 .. 1e-3 from the change point and at it."""
    lengths = np.array(PLANAR_SHAPES[shape])
    a, b, c, d = lengths
    theta = np.concatenate([-OFFSETS, [0.0], OFFSETS])
    if shape == "parallelogram":
        want = theta.copy()                          # psi = theta, rate 1
        rate = np.ones_like(theta)
    else:
        # a = d: C = (cos(theta/2) + sqrt(b^2 - sin^2(theta/2))) exp(i theta/2) (branch +1)
        h = np.sqrt(b * b - (a * np.sin(theta / 2)) ** 2)
        C = (a * np.cos(theta / 2) + h) * np.exp(0.5j * theta)
        want = np.angle(C - d)
        dC = 0.5j * C + (-a * np.sin(theta / 2) / 2 - a * a * np.sin(theta) / (4 * h)) * np.exp(0.5j * theta)
        rate = np.imag(dC / (C - d))
    eps = 1e-6
    pose = SphericalFourBar(*(eps * lengths)).solve(theta, order=1)
    assert pose.valid.all()
    assert np.max(np.abs(pose.psi - want)) <= 4 * eps**2
    assert np.max(np.abs(pose.omega_output - rate)) <= 4 * eps**2


def test_solve_change_point_frame_and_strict():
    """A placed change-point linkage: every vector is the frame times the default one
    (the default frame is checked against the reference above); strict=True raises only
    outside the assembly range, not at B = D."""
    from mech import AssemblyError
    from mech.spherical import ground_frame

    R = ground_frame(0.3, -0.4, 1.1)
    home = SphericalFourBar(0.3, 0.8, 0.8, 0.3, coupler=COUPLER)
    placed = SphericalFourBar(0.3, 0.8, 0.8, 0.3, coupler=COUPLER, frame=R)
    theta = np.array([-1e-7, 0.0, 1e-7, 2.0])
    a, b = home.solve(theta, order=2), placed.solve(theta, order=2)
    for field in ("B", "C", "P", "vP", "aP", "w_coupler", "dw_coupler", "w_output", "dw_input"):
        assert np.max(np.abs(getattr(b, field) - getattr(a, field) @ R.T)) <= 4 * EPS
    assert placed.solve(theta, strict=True).valid.all()
    kite = SphericalFourBar(0.8, 0.3, 0.3, 0.8)            # rocks: |theta| <= 0.849
    assert kite.change_point and kite.solve([-0.5, 0.0, 0.5], strict=True).valid.all()
    with pytest.raises(AssemblyError, match="theta = 1.0"):
        kite.solve([0.0, 1.0], strict=True)


@pytest.mark.parametrize("arcs", [(0.3, 0.9, 0.7, 1.0), (0.3, 0.8, 0.8, 0.3)])
def test_solve_rates_any_input_speed(arcs):
    """Rates scale as omega and (omega^2, alpha) for input rates from 1e-300 to 1e300;
    where the true value exceeds the float range it is masked like a dead point's rate
    (NaN, `valid` False, `assembled` True: never inf or NaN under a True mask), with no
    warning."""
    linkage = SphericalFourBar(*arcs, coupler=COUPLER)
    theta = np.array([0.0, 1.0, -2.5])
    unit = linkage.solve(theta, order=2, omega=1.0, alpha=0.0)
    spin = linkage.solve(theta, order=2, omega=0.0, alpha=1.0)
    for omega, alpha in [(1e-300, 0.0), (1e-150, 1e-300), (1e150, 0.0), (-3e100, 1e200), (1e153, -1e306)]:
        pose = linkage.solve(theta, order=2, omega=omega, alpha=alpha)
        np.testing.assert_allclose(pose.omega_output, omega * unit.omega_output, rtol=4 * EPS, atol=0)
        want = omega * omega * unit.aP + alpha * spin.aP
        np.testing.assert_allclose(pose.aP, want, rtol=1e-14, atol=1e-14 * np.max(np.abs(want)))
    huge = linkage.solve(theta, order=2, omega=1e200, alpha=0.0)
    assert huge.assembled.all() and not huge.valid.any()
    assert np.isnan(huge.alpha_output).all() and np.isfinite(huge.omega_output).all()
    assert np.isfinite(huge.B).all() and np.isfinite(huge.C).all()


def test_solve_pin_all_but_on_the_pivot_is_quiet():
    """a = d, b != c: at theta = 1e-160 the generated 1 / |B x D|^2 overflowed with a
    RuntimeWarning; the pose cannot be assembled there."""
    import warnings

    linkage = SphericalFourBar(0.41915436819625707, 0.07445237811859015, 0.5721404825477754,
                               0.41915436819625707, coupler=(0.3, 0.4))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pose = linkage.solve([1e-160, -1e-160, 0.0], order=2)
    assert not pose.valid.any() and np.isnan(pose.psi).all()
