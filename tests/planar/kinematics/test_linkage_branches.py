"""`Linkage` keeps each group's mode through change points, as `FourBar` does.

The change-point linkages (parallelogram, anti-parallelogram, both deltoids, rhombus as a
crank and an RRR group; a slider-crank with a + |e| = b; a guide bar whose pins meet; a
six-bar whose second loop is a parallelogram) are checked three ways: point for point
against `FourBar` on dense sweeps, against an independent mpmath solution (circle or
line intersections at 50 digits, the root chosen by continuity along the sweep, rates by
``mpmath.diff`` on the chosen root), and against exact identities where the geometry gives
one (a parallelogram's output turns with its crank).
"""

import math

import mpmath
import numpy as np
import pytest

from mech.planar import FourBar, Guide, Linkage

mpmath.mp.dps = 50

# change-point four-bars (a, b, c, d): the dimension sets of the conventions' examples
CHANGE_POINT = {
    "parallelogram": (2.0, 3.0, 2.0, 3.0),
    "deltoid-a=b": (2.0, 2.0, 3.0, 3.0),
    "deltoid-a=d": (1.0, 3.0, 3.0, 1.0),
    "rhombus": (1.0, 1.0, 1.0, 1.0),
    "one-change-point": (1.0, 3.0, 2.0, 2.0),
}


def fourbar_linkage(a, b, c, d, branch=1):
    return (Linkage({"A": 0, "D": d})
            .crank("crank", pivot="A", tip="B", length=a)
            .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(b, c), branch=branch))


def clustered(centres, span=(-12, -3), n=60):
    """Angles at 10**span[0] .. 10**span[1] on both sides of each centre, and the centres."""
    mags = np.logspace(*span, n)
    return np.concatenate([np.concatenate((c - mags, [c], c + mags)) for c in centres])


def sweep(centres, n=100_001, lo=-2 * math.pi, hi=4 * math.pi):
    return np.sort(np.concatenate((np.linspace(lo, hi, n), clustered(centres))))


# ---------------------------------------------------------------- independent reference
def walk(ts, candidates, start, side):
    """Follow one root along the sorted angles ``ts`` from index ``start`` both ways.

    ``candidates(t)`` gives the two roots (mpmath); ``side`` picks one at the start. At each
    next angle the root nearest the linear extrapolation of the last two is kept, which
    crosses a change point onto the smooth continuation. Returns the angles (mpf) and, for
    each, the index of the root kept.
    """
    def run(order):
        idx = [side]
        prev = [candidates(order[0])[side]]
        for i in range(1, len(order)):
            cs = candidates(order[i])
            if i == 1:
                pred = prev[-1]
            else:
                pred = prev[-1] + (prev[-1] - prev[-2]) * (order[i] - order[i - 1]) / (order[i - 1] - order[i - 2])
            k = min((0, 1), key=lambda j: abs(cs[j] - pred))
            idx.append(k)
            prev.append(cs[k])
        return idx, prev

    mts = [mpmath.mpf(float(t)) for t in ts]
    fi, fv = run(mts[start:])
    bi, bv = run(mts[: start + 1][::-1])
    return mts, bi[::-1][:-1] + fi, bv[::-1][:-1] + fv


def rrr_candidates(a, b, c, d):
    def cands(t):
        B = a * mpmath.expj(t)
        g = mpmath.mpf(d) - B
        k = abs(g)
        x = (k**2 + b**2 - c**2) / (2 * k)
        y = mpmath.sqrt(max(b**2 - x**2, 0))
        return [B + g / k * (x + 1j * y), B + g / k * (x - 1j * y)]
    return cands


def rates(candidates, t, k, direction=0):
    f = lambda u: candidates(u)[k]
    return f(t), mpmath.diff(f, t, 1, direction=direction), mpmath.diff(f, t, 2, direction=direction)


def reference(candidates, mts, side, i):
    """Position, first and second derivative of the followed root at the i-th angle.

    Where the two roots meet (a change point itself) the derivatives are one-sided, taken
    on the root that the motion follows next.
    """
    c0, c1 = candidates(mts[i])
    if abs(c0 - c1) > mpmath.mpf("1e-40"):
        return rates(candidates, mts[i], side[i])
    return rates(candidates, mts[i], side[i + 1], direction=1)


# ---------------------------------------------------------------- against FourBar
@pytest.mark.parametrize("name", ["parallelogram", "deltoid-a=b", "one-change-point"])
@pytest.mark.parametrize("branch", [1, -1])
def test_solve_change_point_matches_fourbar(name, branch):
    """1e5 angles over three turns plus clusters 1e-12..1e-3 rad around 0, pi, 2 pi."""
    dims = CHANGE_POINT[name]
    th = sweep([0.0, math.pi, 2 * math.pi, -math.pi])
    ref = FourBar(*dims, branch=branch).solve(th, order=2)
    got = fourbar_linkage(*dims, branch=branch).solve(th, order=2)
    assert np.array_equal(got.valid, ref.valid)
    ok = ref.valid
    assert np.max(np.abs(got.points["C"][ok] - ref.C[ok])) < 1e-12 * sum(dims)
    # FourBar's rates are 0/0 exactly at the meeting points and lose digits within 1e-6
    far = ok & (np.abs(np.sin(th)) > 1e-6)
    assert np.max(np.abs(got.omegas["rocker"][far] - ref.omega_output[far])) < 1e-9
    assert np.max(np.abs(got.alphas["rocker"][far] - ref.alpha_output[far])) < 1e-7


@pytest.mark.parametrize("dims", [CHANGE_POINT["parallelogram"], CHANGE_POINT["rhombus"], (3.0, 2.0, 3.0, 2.0)])
def test_solve_parallelogram_stays_parallelogram(dims):
    """The parallelogram's rocker turns with its crank: C = D + c e^{i theta}, exactly."""
    a, b, c, d = dims
    th = sweep([0.0, math.pi, -math.pi, 2 * math.pi, 3 * math.pi])
    om, al = 1.7, -0.4
    sol = fourbar_linkage(*dims).solve(th, order=2, omega=om, alpha=al)
    assert sol.valid.all()
    exact = d + c * np.exp(1j * th)
    assert np.max(np.abs(sol.points["C"] - exact)) < 1e-13 * (a + b + c + d)
    assert np.max(np.abs(sol.omegas["rocker"] - om)) < 1e-10
    assert np.max(np.abs(sol.alphas["rocker"] - al)) < 1e-8
    assert np.max(np.abs(sol.omegas["coupler"])) < 1e-10
    assert np.max(np.abs(sol.velocities["C"] - 1j * om * c * np.exp(1j * th))) < 1e-10


# ---------------------------------------------------------------- against mpmath
@pytest.mark.parametrize("name", list(CHANGE_POINT))
def test_solve_change_point_mpmath_continuity(name):
    """Positions and rates against circle intersections followed by continuity (mpmath)."""
    a, b, c, d = CHANGE_POINT[name]
    cands = rrr_candidates(a, b, c, d)
    lk = fourbar_linkage(a, b, c, d)
    ts = np.sort(np.concatenate((np.linspace(-1.0, 4.0, 41), clustered([0.0, math.pi], (-12, -2), 12))))
    ts = ts[np.abs(ts) > 0]            # the kites' pins coincide at 0: checked separately
    start = int(np.searchsorted(ts, 0.5))
    mts, side, _ = walk(ts, cands, start, 0)     # branch +1 just after 0: C left of B->D
    sol = lk.solve(ts, order=2)
    worst = [0.0, 0.0, 0.0]
    for i, t in enumerate(mts):
        p, v, acc = reference(cands, mts, side, i)
        if not sol.valid[i]:
            assert b**2 < ((abs(d - a * mpmath.expj(t)) ** 2 + b**2 - c**2) / (2 * abs(d - a * mpmath.expj(t)))) ** 2
            continue
        worst[0] = max(worst[0], abs(complex(p) - sol.points["C"][i]))
        worst[1] = max(worst[1], abs(complex(v) - sol.velocities["C"][i]))
        worst[2] = max(worst[2], abs(complex(acc) - sol.accelerations["C"][i]))
    assert worst[0] < 1e-13 * (a + b + c + d), worst
    assert worst[1] < 1e-10 * (a + b + c + d), worst
    assert worst[2] < 1e-8 * (a + b + c + d), worst


@pytest.mark.parametrize("name", ["deltoid-a=d", "rhombus", "parallelogram"])
def test_solve_change_point_exact_input(name):
    """At the meeting point itself: assembled, finite, equal to the one-sided mpmath limit."""
    a, b, c, d = CHANGE_POINT[name]
    cands = rrr_candidates(a, b, c, d)
    sol = fourbar_linkage(a, b, c, d).solve([0.0, 1e-300, -1e-300], order=2)
    assert sol.valid.all()
    with mpmath.workdps(120):                     # the roots differ by ~1e-20 there
        p, v, acc = rates(cands, mpmath.mpf("1e-20"), 0, direction=1)   # C left of B->D after 0
    for i in range(3):
        assert abs(sol.points["C"][i] - complex(p)) < 1e-12
        assert abs(sol.velocities["C"][i] - complex(v)) < 1e-9
        assert abs(sol.accelerations["C"][i] - complex(acc)) < 1e-7


# ---------------------------------------------------------------- jumps
@pytest.mark.parametrize("name", list(CHANGE_POINT))
@pytest.mark.parametrize("branch", [1, -1])
def test_solve_no_jump(name, branch):
    """Neighbouring inputs give neighbouring outputs: no step larger than the rates allow."""
    dims = CHANGE_POINT[name]
    th = sweep([0.0, math.pi, 2 * math.pi, -math.pi], n=200_001)
    sol = fourbar_linkage(*dims, branch=branch).solve(th, order=2)
    ok = sol.valid[1:] & sol.valid[:-1]
    dt = np.diff(th)[ok]
    for z, dz, ddz in (("C", sol.velocities["C"], sol.accelerations["C"]),):
        step = np.abs(np.diff(sol.points[z]))[ok]
        bound = np.max(np.abs(dz)) * dt + 1e-12
        assert np.all(step <= 1.01 * bound)
        vstep = np.abs(np.diff(dz))[ok]
        assert np.all(vstep <= 1.01 * np.max(np.abs(ddz)) * dt + 1e-8)
    for link in ("coupler", "rocker"):
        dw = np.abs(np.diff(sol.omegas[link]))[ok]
        assert np.all(dw <= 1.01 * np.max(np.abs(sol.alphas[link])) * dt + 1e-8)


def test_solve_rule_is_local():
    """The result at an input does not depend on the other inputs or their order."""
    dims = CHANGE_POINT["one-change-point"]
    th = np.linspace(-9, 9, 2001)
    perm = np.random.default_rng(11).permutation(th.size)
    lk = fourbar_linkage(*dims)
    whole = lk.solve(th, order=2)
    shuffled = lk.solve(th[perm], order=2)
    single = [lk.solve(t, order=2) for t in th[::97]]
    assert np.array_equal(whole.points["C"][perm], shuffled.points["C"])
    assert np.array_equal(whole.alphas["rocker"][perm], shuffled.alphas["rocker"])
    for t, s in zip(th[::97], single):
        assert s.points["C"] == pytest.approx(whole.points["C"][np.flatnonzero(th == t)[0]], abs=1e-14)


def test_solve_branch_named_after_zero():
    """`branch` names the mode just after theta = 0 (C left of B->D for +1), and the period
    of a one-change-point linkage is two crank turns, as for `FourBar`."""
    dims = CHANGE_POINT["one-change-point"]
    for branch in (1, -1):
        sol = fourbar_linkage(*dims, branch=branch).solve([1e-6, 1.0, 2 * math.pi + 1.0, 4 * math.pi + 1.0])
        B, C, D = sol.points["B"], sol.points["C"], dims[3]
        side = np.sign(np.imag(np.conj(D - B) * (C - B)))
        assert side.tolist() == [branch, branch, -branch, branch]


# ---------------------------------------------------------------- RRP and RPR
def test_rrp_change_point_slider_crank():
    """A slider-crank with a + |e| = b: crank 1, offset 1, rod 2 meet the guide at theta = -pi/2."""
    a, e, b = 1.0, 1.0, 2.0
    lk = (Linkage({"A": 0}).crank("crank", pivot="A", tip="B", length=a)
          .rrp(("rod", "block"), pin="B", guide=Guide("ground", 1j * e, 0.0), joint="C", length=b))

    def cands(t):
        B = a * mpmath.expj(t)
        half = mpmath.sqrt(max(b**2 - (e - B.imag) ** 2, 0))
        return [mpmath.mpc(B.real + half, e), mpmath.mpc(B.real - half, e)]

    ts = np.sort(np.concatenate((np.linspace(-2.5, 5.5, 33), clustered([-math.pi / 2, 1.5 * math.pi], (-12, -2), 12))))
    start = int(np.searchsorted(ts, 0.3))
    mts, side, _ = walk(ts, cands, start, 0)     # branch +1: slider right of the pin
    sol = lk.solve(ts, order=2)
    assert sol.valid.all()
    worst = np.zeros(3)
    for i in range(len(mts)):
        p, v, acc = reference(cands, mts, side, i)
        worst = np.maximum(worst, [abs(complex(p) - sol.points["C"][i]), abs(complex(v) - sol.velocities["C"][i]),
                                   abs(complex(acc) - sol.accelerations["C"][i])])
        assert sol.slides[("block", "ground")].s[i] == pytest.approx(float(p.real), abs=1e-12)
    assert worst[0] < 1e-13 and worst[1] < 1e-10 and worst[2] < 1e-8, worst
    # the slider passes from the right of the pin to its left and back every two turns
    side_of_pin = np.sign(sol.points["C"].real - sol.points["B"].real)
    assert set(side_of_pin[np.abs(ts + math.pi / 2) > 1e-3].tolist()) == {-1.0, 1.0}


def test_rpr_pins_meet():
    """A guide bar through D driven by a crank as long as the frame: B passes through D.

    The bar's direction is i e^{i theta / 2} and the block is at s = 2 sin(theta / 2) along it,
    exactly, through theta = 0 where the two pins coincide.
    """
    lk = (Linkage({"A": 0, "D": 1.0}).crank("crank", pivot="A", tip="B", length=1.0)
          .rpr(("bar", "block"), pins=("D", "B"), offset=0.0))
    th = np.sort(np.concatenate((np.linspace(-7, 7, 20001), clustered([0.0, 2 * math.pi, -2 * math.pi]))))
    om, al = 0.8, 0.3
    sol = lk.solve(th, order=2, omega=om, alpha=al)
    assert sol.valid.all()
    w = 1j * np.exp(0.5j * th)
    assert np.max(np.abs(sol.direction("bar") - w)) < 1e-13
    assert np.max(np.abs(sol.omegas["bar"] - om / 2)) < 1e-10
    assert np.max(np.abs(sol.alphas["bar"] - al / 2)) < 1e-8
    sl = sol.slides[("block", "bar")]
    assert np.max(np.abs(sl.s - 2 * np.sin(th / 2))) < 1e-13
    assert np.max(np.abs(sl.v - om * np.cos(th / 2))) < 1e-10
    assert np.max(np.abs(sl.a - (al * np.cos(th / 2) - 0.5 * om**2 * np.sin(th / 2)))) < 1e-8


# ---------------------------------------------------------------- two loops
def _six_bar(branch2):
    """A drag link (double crank) A-B-C-D whose output DE drives a second loop D-E-G-F.

    With FG = DE and EG = DF the second loop is a parallelogram (or an anti-parallelogram),
    and it passes a change point whenever DE lines up with DF, twice per turn.
    """
    return (Linkage({"A": 0, "D": 1.0, "F": 3.5})
            .crank("crank", pivot="A", tip="B", length=3.0)
            .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(4.0, 3.5))
            .point("E", link="rocker", at=2.0)
            .rrr(("link5", "output"), pins=("E", "F"), joint="G", lengths=(2.5, 2.0), branch=branch2))


def _six_bar_change_points():
    """Crank angles where DE lines up with DF (the rocker angle is 0 or pi), by bisection on FourBar."""
    fb = FourBar(3.0, 4.0, 3.5, 1.0)
    f = lambda t: math.sin(float(fb.solve(t).psi))
    grid = np.linspace(0, 2 * math.pi, 721)
    vals = np.array([f(t) for t in grid])
    out = []
    for i in np.flatnonzero(np.sign(vals[:-1]) != np.sign(vals[1:])):
        lo, hi = grid[i], grid[i + 1]
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if mid in (lo, hi):
                break
            lo, hi = (mid, hi) if np.sign(f(mid)) == np.sign(vals[i]) else (lo, mid)
        out.append(lo)
    return out


def test_six_bar_second_loop_stays_parallelogram():
    cps = _six_bar_change_points()
    assert len(cps) == 2
    th = sweep(cps + [c + 2 * math.pi for c in cps], n=100_001)
    sols = {m: _six_bar(m).solve(th, order=2, omega=1.3, alpha=0.2) for m in (1, -1)}
    para = [m for m, s in sols.items()
            if abs(s.points["G"][0] - (s.points["E"][0] + 3.5 - 1.0)) < 1e-9]
    assert len(para) == 1
    sol = sols[para[0]]
    assert sol.valid.all()
    assert np.max(np.abs(sol.points["G"] - (sol.points["E"] + 2.5))) < 1e-12
    assert np.max(np.abs(sol.velocities["G"] - sol.velocities["E"])) < 1e-9
    assert np.max(np.abs(sol.accelerations["G"] - sol.accelerations["E"])) < 1e-7
    assert np.max(np.abs(sol.omegas["output"] - sol.omegas["rocker"])) < 1e-9
    # the other mode is the anti-parallelogram throughout: EG and DF cross, no jump
    anti = sols[-para[0]]
    assert anti.valid.all()
    g = anti.points["G"]
    assert np.all(np.abs(np.diff(g)) <= 1.01 * np.max(np.abs(anti.velocities["G"])) / 1.3 * np.diff(th) + 1e-12)
    assert np.max(np.abs(np.abs(g - anti.points["E"]) - 2.5)) < 1e-12
    assert np.max(np.abs(np.abs(g - 3.5) - 2.0)) < 1e-12
