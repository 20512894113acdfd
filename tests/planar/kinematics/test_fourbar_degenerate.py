"""FourBar through its change points and through the kite pose where B meets D.

The oracle is independent of the package: at 120 digits it intersects the circles about B
and D, follows one root by continuity from a pose 0.25 rad away from the change point
(where the branch is named by the side of C), walking in geometric steps down to 1e-30
rad from the change point and out on the other side, and takes the rates from the loop
equation as ratios of cross products. Those ratios read 0/0 at the change point itself.
At a distance t from it the height of C over BD (about t) comes from its square, so it
keeps 120 digits less twice those of t, and so do the velocity ratios; the acceleration
ratios, whose numerators cancel down to about t, lose three times the digits of t: at
t = 1e-30 that leaves about 30 correct digits. So the
oracle evaluates any angle closer than 1e-30 rad to the change point 1e-30 rad away, an
error of order 1e-30.
"""

import mpmath
import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from mech.planar import FourBar

DPS = 120
EPS = np.finfo(float).eps
TINY = mpmath.mpf("1e-30")

# (a, b, c, d), the change-point angles, and what kind of change point they are
LINKAGES = {
    "rhombus": ((1.0, 1.0, 1.0, 1.0), (0.0, np.pi)),
    "kite-long-coupler": ((1.0, 2.0, 2.0, 1.0), (0.0,)),
    "kite-short-coupler": ((2.0, 1.0, 1.0, 2.0), (0.0,)),
    "deltoid-short-crank": ((1.0, 1.0, 2.0, 2.0), (0.0, np.pi)),
    "deltoid-long-crank": ((2.0, 2.0, 1.0, 1.0), (0.0, np.pi)),
    "parallelogram": ((2.0, 3.0, 2.0, 3.0), (0.0, np.pi)),
    "parallelogram-long-crank": ((3.0, 2.0, 3.0, 2.0), (0.0, np.pi)),
    "change-point-gap2": ((1.0, 2.0, 4.0, 3.0), (0.0,)),
    "change-point-gap3": ((1.0, 4.0, 2.0, 3.0), (0.0,)),
    "change-point-gap4": ((2.0, 3.0, 4.0, 5.0), (np.pi,)),
}
CASES = [(name, branch, centre) for name, (_, centres) in LINKAGES.items()
         for branch in (1, -1) for centre in centres]
OFFSETS = [0.0] + [s * x for x in (1e-300, 1e-200, 1e-100, 1e-30, 1e-16, 1e-12, 1e-8,
                                   1e-5, 1e-3, 0.05, 0.5, 1.0) for s in (1, -1)]
COUPLER = (0.3, 0.7)
OMEGA, ALPHA = 1.3, -0.4


def _cross(x, y):
    return (x.conjugate() * y).imag


class Oracle:
    """One branch of a four-bar near a change point, followed root by root in mpmath."""

    def __init__(self, lengths, branch, centre):
        self.a, self.b, self.c, self.d = (mpmath.mpf(v) for v in lengths)
        with mpmath.workdps(DPS):
            self.centre = mpmath.pi if centre else mpmath.mpf(0)
            # Start 0.25 rad inside (0, pi), where the side of C is the branch sign, and
            # approach the change point from there.
            self.side = 1 if centre == 0 else -1
            start = self.centre + self.side * mpmath.mpf("0.25")
            B = self.a * mpmath.expj(start)
            roots = self.roots(start)
            pick = roots[0] if _cross(self.d - B, roots[0] - B) * branch > 0 else roots[1]
            self.start = (start, pick)
            # the geometric steps from 0.25 rad down to TINY, the same for every angle
            toward = [mpmath.mpf("0.25") / mpmath.mpf(2) ** n for n in range(1, 200)]
            self.toward = [x for x in toward if x > TINY] + [TINY]

    def roots(self, t):
        B = self.a * mpmath.expj(t)
        w = self.d - B
        k = abs(w)
        along = (self.b**2 - self.c**2 + k**2) / (2 * k)
        height = mpmath.sqrt(self.b**2 - along**2)
        return [B + w / k * (along + 1j * h) for h in (height, -height)]

    def follow(self, angles):
        """Follow the root from the start through `angles` (linear prediction, nearest root).

        The walks to the angles of one test share their geometric steps: a walk's state
        after a sequence of steps is kept in a tree keyed by the steps, so a shared prefix
        is walked once (the same arithmetic, so the same roots, as walking it again)."""
        if not hasattr(self, "_walked"):
            self._walked = {}                   # (node, angle) -> (node, last two poses)
        node, path = 0, [self.start]
        for t in angles:
            hit = self._walked.get((node, t))
            if hit is None:
                (t0, C0), (t1, C1) = path[max(len(path) - 2, 0)], path[-1]
                guess = C1 if t1 == t0 else C1 + (C1 - C0) * (t - t1) / (t1 - t0)
                path = [path[-1], (t, min(self.roots(t), key=lambda C: abs(C - guess)))]
                hit = self._walked[(node, t)] = (len(self._walked) + 1, path)
            node, path = hit
        return path[-1][1]

    def solve(self, theta):
        """B, C, P, psi and the rates at the float angle `theta` (its exact value)."""
        with mpmath.workdps(DPS):
            # distance from the change point, positive on the side the walk starts from
            rel = (mpmath.mpf(float(theta)) - self.centre) * self.side
            if abs(rel) < TINY:             # the change point itself: its limit
                rel = TINY
            quarter, toward = mpmath.mpf("0.25"), self.toward
            if rel > 0:
                steps = [x for x in toward if x > rel]
            else:
                steps = toward + [-x for x in reversed(toward) if x < -rel]
            # then on to the target in steps of at most 0.01 rad
            last = steps[-1] if steps else quarter
            count = int(mpmath.ceil(abs(rel - last) / mpmath.mpf("0.01"))) or 1
            steps += [last + (rel - last) * j / count for j in range(1, count + 1)]
            C = self.follow([self.centre + self.side * x for x in steps])
            t = self.centre + self.side * rel
            B = self.a * mpmath.expj(t)
            u, r = C - B, C - self.d
            i, om, al = mpmath.mpc(0, 1), mpmath.mpf(OMEGA), mpmath.mpf(ALPHA)
            den = _cross(u, r)
            w3 = om * _cross(u, B) / den
            w2 = om * _cross(r, B) / den
            Q = al * B + i * om**2 * B - i * w3**2 * r + i * w2**2 * u
            a3, a2 = _cross(u, Q) / den, _cross(r, Q) / den
            P = B + mpmath.mpc(*COUPLER) * u / self.b
            return {"B": B, "C": C, "P": P, "psi": mpmath.arg(r), "omega_output": w3,
                    "omega_coupler": w2, "alpha_output": a3, "alpha_coupler": a2,
                    "vC": i * w3 * r, "vP": i * om * B + i * w2 * (P - B),
                    "aC": (i * a3 - w3**2) * r,
                    "aP": (i * al - om**2) * B + (i * a2 - w2**2) * (P - B)}


def _angle_gap(x, y):
    return abs(float(mpmath.arg(mpmath.expj(mpmath.mpf(float(x)) - y))))


WORST = {}


@pytest.mark.parametrize("name, branch, centre", CASES)
def test_solve_change_point_against_mpmath(name, branch, centre):
    """Positions and rates at, near and up to 1 rad from each change point against mpmath
    (the rates of a change-point linkage come from the factored formulas everywhere):
    errors relative to the linkage size L (positions), L omega (velocities),
    L (omega^2 + |alpha|) (accelerations), and likewise for the angular rates, or to the
    value itself where that is larger, below 4e-15."""
    lengths, _ = LINKAGES[name]
    linkage = FourBar(*lengths, branch=branch, coupler=COUPLER)
    oracle = Oracle(lengths, branch, centre)
    theta = np.array([centre + x for x in OFFSETS])
    pose = linkage.solve(theta, order=2, omega=OMEGA, alpha=ALPHA, strict=True)
    rate, accel = abs(OMEGA), OMEGA**2 + abs(ALPHA)
    scale = {"C": 1.0, "P": 1.0, "vC": rate, "vP": rate, "aC": accel, "aP": accel}
    size = sum(lengths)
    worst, where = 0.0, None
    for i, t in enumerate(theta):
        ref = oracle.solve(t)
        errs = {field: abs(complex(getattr(pose, field)[i]) - complex(ref[field]))
                / max(size * unit, abs(complex(ref[field]))) for field, unit in scale.items()}
        errs.update({field: abs(float(getattr(pose, field)[i]) - float(ref[field]))
                     / max(unit, abs(float(ref[field])))
                     for field, unit in (("omega_output", rate), ("omega_coupler", rate),
                                         ("alpha_output", accel), ("alpha_coupler", accel))})
        errs["psi"] = _angle_gap(pose.psi[i], ref["psi"])
        field = max(errs, key=errs.get)
        if errs[field] > worst:
            worst, where = errs[field], (field, float(t))
    WORST[(name, branch, centre)] = worst
    assert worst < 4e-15, (worst, where)


DENSE = 400_000


@pytest.mark.parametrize("name, branch, centre", CASES)
def test_solve_change_point_dense_sweep(name, branch, centre):
    """4e5 angles within 1e-3 rad of each change point plus tiny offsets, all valid.

    No jump between branches: over every step the change of psi agrees with the
    trapezoidal integral of omega_output, and the change of omega_output with that of
    alpha_output, to rounding (the trapezoid's own error, step^3 times the next derivative,
    is below 1e-24 here). alpha_output agrees with the central difference of
    omega_output to the rounding of that difference, eps / step, about 1e-7."""
    lengths, _ = LINKAGES[name]
    linkage = FourBar(*lengths, branch=branch)
    tiny = [s * x for x in (1e-300, 1e-200, 1e-100, 1e-16) for s in (1, -1)] + [0.0]
    grid = centre + np.linspace(-1e-3, 1e-3, DENSE)
    theta = np.unique(np.concatenate([grid, centre + np.array(tiny)]))
    pose = linkage.solve(theta, order=2)
    assert pose.valid.all()
    for field in ("C", "P", "omega_output", "alpha_output", "omega_coupler", "alpha_coupler"):
        assert np.all(np.isfinite(getattr(pose, field)))
    step = np.diff(theta)
    dpsi = np.angle(np.exp(1j * np.diff(pose.psi)))
    trapezoid = step * (pose.omega_output[1:] + pose.omega_output[:-1]) / 2
    assert np.max(np.abs(dpsi - trapezoid)) < 1e-14
    trapezoid = step * (pose.alpha_output[1:] + pose.alpha_output[:-1]) / 2
    assert np.max(np.abs(np.diff(pose.omega_output) - trapezoid)) < 1e-14
    # the uniform grid inside the sweep (solve is pointwise, so no second solve is needed)
    on_grid = np.searchsorted(theta, grid)
    omega, alpha = pose.omega_output[on_grid], pose.alpha_output[on_grid]
    h = grid[1] - grid[0]
    central = (omega[2:] - omega[:-2]) / (2 * h)
    assert np.max(np.abs(central - alpha[1:-1])) < 1e-6


@pytest.mark.parametrize("lengths", [(1, 1, 1, 1), (1, 2, 2, 1), (2, 1, 1, 2), (5, 3, 3, 5)])
def test_solve_kite_pin_on_pivot_is_valid(lengths):
    """B = D at theta = 0: the pose is assembled, so it is valid, and strict does not raise."""
    for branch in (1, -1):
        pose = FourBar(*lengths, branch=branch).solve([0.0, 1e-300, -1e-300], order=2, strict=True)
        assert pose.valid.all()
        a, b = lengths[0], lengths[1]
        # the coupler is along +x (branch +1) or -x (branch -1) from B = D
        np.testing.assert_allclose(pose.C, a + branch * b, rtol=0, atol=1e-15 * a)
        assert np.all(np.isfinite(pose.alpha_output))


def test_solve_rhombus_branches():
    """The rhombus: branch +1 is the parallelogram (psi = theta), branch -1 folds C onto A."""
    theta = np.linspace(-7, 7, 1401)
    para = FourBar(1, 1, 1, 1).solve(theta, order=2)
    np.testing.assert_allclose(np.exp(1j * para.psi), np.exp(1j * theta), atol=1e-15)
    np.testing.assert_allclose(para.omega_output, 1.0, atol=1e-15)
    folded = FourBar(1, 1, 1, 1, branch=-1).solve(theta, order=2)
    np.testing.assert_allclose(folded.C, 0.0, atol=1e-15)
    np.testing.assert_allclose(folded.omega_coupler, 1.0, atol=1e-15)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.integers(1, 64), min_size=3, max_size=3),
       st.permutations(range(4)), st.sampled_from([1, -1]))
def test_solve_random_change_point_linkage_continuous(shorts, order, branch):
    """Random change-point linkages (s + l = p + q exactly, lengths in 1/64 steps, links
    in any order): valid at every change point, and across each one psi and omega_output
    agree with the trapezoidal integrals of omega_output and alpha_output (no jump), and
    alpha_output with the central difference of omega_output."""
    s, p, q = sorted(x / 64 for x in shorts)
    sides = (s, p, q, p + q - s)
    a, b, c, d = (sides[i] for i in order)
    assume(max(a, b, c, d) < a + b + c + d - max(a, b, c, d))
    linkage = FourBar(a, b, c, d, branch=branch)
    centres = ([0.0] if abs(d - a) == abs(c - b) else []) + ([np.pi] if b + c == a + d else [])
    assert centres
    for centre in centres:
        grid = centre + np.linspace(-1e-3, 1e-3, 20001)
        theta = np.unique(np.concatenate([grid, centre + np.array([0.0, 1e-300, -1e-300, 1e-16])]))
        pose = linkage.solve(theta, order=2)
        assert pose.valid.all()
        step = np.diff(theta)
        dpsi = np.angle(np.exp(1j * np.diff(pose.psi)))
        w, al = pose.omega_output, pose.alpha_output
        assert np.all(np.isfinite(w)) and np.all(np.isfinite(al))
        # Rounding: a few eps times the size of the values, or, for the ill-conditioned
        # linkages that random lengths give (B passing near D, a flat kite), the
        # rounding noise read off the data: over a step of 1e-7 the second difference
        # of a smooth function is about 1e-14 times its second derivative, so its median
        # is the noise. A jump between branches is of order 1 and is not in the median.
        uniform = linkage.solve(grid, order=2)
        wiggle = max(np.median(np.abs(np.diff(uniform.psi, 2))),
                     np.median(np.abs(np.diff(uniform.omega_output, 2))))
        noise = 20 * wiggle + 16 * EPS * (1 + np.max(np.abs(w)) + np.max(np.abs(al)))
        assert np.max(np.abs(dpsi - step * (w[1:] + w[:-1]) / 2)) < noise
        assert np.max(np.abs(np.diff(w) - step * (al[1:] + al[:-1]) / 2)) < noise
        h = grid[1] - grid[0]
        central = (uniform.omega_output[2:] - uniform.omega_output[:-2]) / (2 * h)
        # rounding of the difference (noise / h) plus its truncation (h^2 |w'''| / 6)
        bound = noise / h + 1e-6 * (1 + np.max(np.abs(al)))
        assert np.max(np.abs(central - uniform.alpha_output[1:-1])) < bound
