"""Static force analysis (mech.planar.forces._statics): virtual work, mpmath equilibrium, friction."""

import math

import mpmath
import numpy as np
import pytest

from mech import AssemblyError
from mech.planar import FourBar, Guide, Linkage, SliderCrank
from mech.planar.special._library import shaper_watt, stephenson_six_bar, watt_six_bar
from mech.planar.forces._friction import friction_angle, friction_circle
from mech.planar.forces._statics import _pairs, as_linkage, static_forces

RNG = np.random.default_rng(20261122)


def _guide_bar():
    return (Linkage({"A": 0, "D": 2.0j}).crank("crank", pivot="A", tip="B", length=1.0)
            .rpr(("bar", "block"), pins=("D", "B")).point("T", link="bar", at=3.0))


def _yoke():
    return (Linkage({"A": 0}).crank("crank", pivot="A", tip="B", length=1.0)
            .rpp(("block", "yoke"), pin="B", guide=Guide("ground", 0.3j, 0.0), angle=math.pi / 2.5,
                 point="J", offset=0.2)
            .point("T", link="yoke", at=2.0 + 0.5j))


def _prp():
    return (Linkage({"A": 0}).crank("crank", pivot="A", tip="B", length=1.0).point("K", link="crank", at=0.3 + 0.2j)
            .prp(("b1", "b2"), guides=(Guide("crank", "K", 0.4), Guide("ground", 0.5j, 0.2)), joint="J")
            .point("T", link="b2", at=0.5 + 0.5j))


def _double_slider(l):
    return (Linkage({}).slider("slider2", guide=Guide("ground", 1j * l, -math.pi / 2), point="A")
            .rrp(("coupler", "slider3"), pin="A", guide=Guide("ground", 0j, 0.0), joint="B", length=l))


CASES = {
    "fourbar": (as_linkage(FourBar(1, 3, 2.5, 3)), {"C": -10 + 3j, "B": 2j}, {"coupler": 1.5, "rocker": -0.7}),
    "slider_crank": (as_linkage(SliderCrank(1, 3, 0.5)), {"C": -10 + 3j, "B": 2j}, {"rod": 1.5}),
    "guide_bar": (_guide_bar(), {"T": 1 - 2j}, {"bar": 0.5}),
    "watt_six_bar": (watt_six_bar(), {"G": 3 - 2j, "E": 1j, "C": 1}, {"output": 2.0, "link5": 0.3}),
    "stephenson_six_bar": (stephenson_six_bar(), {"G": 3 - 2j, "E": 1j, "C": 1}, {"output": 2.0, "link5": 0.3}),
    "shaper": (shaper_watt(), {"F": -300 + 20j}, {"rod": 10.0}),
    "rpp_yoke": (_yoke(), {"T": 1 - 2j, "B": 0.5}, {"yoke": 0.5, "block": -0.3}),
    "prp": (_prp(), {"T": 1 - 2j, "J": 0.5}, {"b1": 0.5, "b2": -0.3}),
}


def _power(sol, sf, forces, couples, factor=1.0):
    """Residual of M_b omega + sum F.v + sum M omega, relative to the loads' power scale."""
    p = factor * sf.balancing * 1.0
    scale = 0.0
    for pt, f in forces.items():
        p = p + np.real(np.conj(f) * sol.velocities[pt])
        scale = scale + abs(f) * np.abs(sol.velocities[pt])
    for link, m in couples.items():
        p = p + m * sol.omegas[link]
        scale = scale + abs(m) * np.abs(sol.omegas[link])
    return np.abs(p) / scale


@pytest.mark.parametrize("name", list(CASES))
def test_static_forces_virtual_work(name):
    lk, forces, couples = CASES[name]
    theta = RNG.uniform(-math.pi, math.pi, 400)
    theta = theta[lk.solve(theta).valid][:200]
    sol = lk.solve(theta, order=1)
    sf = static_forces(sol, forces, couples)
    assert theta.size > 50
    assert np.max(_power(sol, sf, forces, couples)) < 1e-10
    assert np.all(sf.efficiency[sf.frictionless[lk.drivers[0]] > 0] == 1.0)


def test_static_forces_virtual_work_check_can_fail():
    # the same check with a balancing moment off by 1e-6 must fail: the test has teeth
    lk, forces, couples = CASES["watt_six_bar"]
    sol = lk.solve(np.array([0.3, 1.1, 2.5]), order=1)
    sf = static_forces(sol, forces, couples)
    assert np.max(_power(sol, sf, forces, couples, factor=1 + 1e-6)) > 1e-10


def test_static_forces_fourbar_mpmath_equilibrium():
    # 9 equations (3 per link) in 7 unknowns solved independently at 50 digits
    mpmath.mp.dps = 50
    a, b, c, d = 1.0, 3.0, 2.5, 3.0
    theta, Q, E_local = 0.9, -7.0 + 4.0j, 1.6 + 0.4j
    lk = as_linkage(FourBar(a, b, c, d)).point("E", link="rocker", at=E_local)
    sol = lk.solve(theta, order=1)
    sf = static_forces(sol, {"E": Q})
    B = mpmath.mpc(a * mpmath.cos(theta), a * mpmath.sin(theta))
    Cz = mpmath.findroot(lambda x, y: ((x - B.real) ** 2 + (y - B.imag) ** 2 - b**2, (x - d) ** 2 + y**2 - c**2),
                         (complex(sol.points["C"]).real, complex(sol.points["C"]).imag))
    C = mpmath.mpc(Cz[0], Cz[1])
    D = mpmath.mpf(d)
    E = D + (C - D) / c * mpmath.mpc(E_local.real, E_local.imag)
    cr = lambda p, f: p.real * f.imag - p.imag * f.real
    # unknowns: R_A (on crank, 2), R_B (on coupler from crank, 2), R_C (on rocker from coupler, 2),
    # R_D (on rocker, 2), M_b
    rows, rhs = [], []
    z = [0] * 9

    def eq(coeffs, value):
        row = list(z)
        for k, v in coeffs.items():
            row[k] = v
        rows.append(row)
        rhs.append(value)

    # crank: R_A - R_B = 0 ; moment about A: cross(B, -R_B) + M_b = 0
    eq({0: 1, 2: -1}, 0), eq({1: 1, 3: -1}, 0), eq({2: B.imag, 3: -B.real, 8: 1}, 0)
    # coupler: R_B - R_C = 0 ; moment about B: cross(C - B, -R_C) = 0
    eq({2: 1, 4: -1}, 0), eq({3: 1, 5: -1}, 0), eq({4: (C - B).imag, 5: -(C - B).real}, 0)
    # rocker: R_C + R_D + Q = 0 ; moment about D: cross(C - D, R_C) + cross(E - D, Q) = 0
    Qm = mpmath.mpc(Q.real, Q.imag)
    eq({4: 1, 6: 1}, -Qm.real), eq({5: 1, 7: 1}, -Qm.imag)
    eq({4: -(C - D).imag, 5: (C - D).real}, -cr(E - D, Qm))
    A = mpmath.matrix(rows)
    x = mpmath.lu_solve(A, mpmath.matrix(rhs))
    want = {("ground", "crank"): x[0] + 1j * x[1], ("crank", "coupler"): x[2] + 1j * x[3],
            ("coupler", "rocker"): x[4] + 1j * x[5], ("ground", "rocker"): x[6] + 1j * x[7]}
    scale = abs(complex(Q))
    for key, value in want.items():
        assert abs(complex(sf.reactions[key]) - complex(value)) < 1e-12 * scale
    assert abs(float(sf.balancing) - float(x[8])) < 1e-12 * scale * a


def test_static_forces_reactions_are_antisymmetric():
    lk, forces, couples = CASES["shaper"]
    sf = static_forces(lk.solve(np.array([0.2, 2.0])), forces, couples)
    for (i, j), r in sf.reactions.items():
        np.testing.assert_array_equal(sf.reactions[(j, i)], -r)


def test_example_2_14_self_locking_boundary():
    l, r, mu0, mu = 100.0, 10.0, 0.15, 0.2
    rho = friction_circle(mu0, r)
    x_lock = l * math.sin(math.atan(mu) + math.asin(2 * r * mu0 / l))
    lk = _double_slider(l)

    def locked(x):
        s = l - np.sqrt(l * l - np.asarray(x) ** 2)
        return static_forces(lk.solve(s, order=1), {"B": -1.0}, rho=rho, mu=mu).self_locking

    lo, hi = 5.0, 60.0
    assert locked(lo)[()] and not locked(hi)[()]
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if locked(mid)[()] else (lo, mid)
    assert abs(0.5 * (lo + hi) - x_lock) < 1e-8 * l
    # the required force diverges like 1/(x - x_lock) there
    dx = np.array([1e-3, 1e-5, 1e-7])
    x = x_lock + dx
    sf = static_forces(lk.solve(l - np.sqrt(l * l - x * x), order=1), {"B": -1.0}, rho=rho, mu=mu)
    k = sf.balancing * dx
    assert np.all(sf.balancing > 1e2) and np.ptp(k) < 1e-4 * k[0]


def test_static_forces_friction_circle_tangency_slider_crank():
    rho, mu = 0.04, 0.12
    lk = as_linkage(SliderCrank(1.0, 3.2, 0.3))
    theta = np.linspace(-3.0, 3.0, 41)
    sol = lk.solve(theta, order=1)
    sf = static_forces(sol, {("C", "slider"): -10.0}, rho=rho, mu=mu)
    for p in _pairs(sol):
        R = sf.reactions[p.links]
        point = sf.lines[p.links]
        if p.kind == "R":
            # the moment of the reaction about its pin is rho |R| against the relative rotation
            m = np.imag(np.conj(point - p.at) * R)
            np.testing.assert_allclose(m, -np.sign(p.rate) * rho * np.abs(R), atol=1e-12)
        else:
            # tilted by the friction angle from the normal, against the sliding velocity
            along = np.real(np.conj(p.e) * R)
            normal = np.real(np.conj(1j * p.e) * R)
            np.testing.assert_allclose(along, -np.sign(p.rate) * mu * np.abs(normal), atol=1e-12)
            tilt = np.arctan2(np.abs(along), np.abs(normal))
            np.testing.assert_allclose(tilt, friction_angle(mu), atol=1e-12)


def test_static_forces_friction_power_is_the_dissipation():
    rho, mu = 0.05, 0.1
    lk = as_linkage(SliderCrank(1, 3, 0.5))
    theta = RNG.uniform(-math.pi, math.pi, 100)
    sol = lk.solve(theta, order=1)
    sf = static_forces(sol, {("C", "slider"): -10.0}, rho=rho, mu=mu)
    power_in = sf.balancing + np.real(-10.0 * sol.velocities["C"])
    lost = 0.0
    for p in _pairs(sol):
        R = sf.reactions[p.links]
        if p.kind == "R":
            lost = lost + rho * np.abs(R) * np.abs(p.rate)
        else:
            lost = lost + mu * np.abs(np.real(np.conj(1j * p.e) * R)) * np.abs(p.rate)
    ok = ~sf.self_locking
    assert ok.sum() > 80
    np.testing.assert_allclose(power_in[ok], lost[ok], rtol=1e-11)
    driving = ok & (sf.frictionless["crank"] > 0)          # the crank drives (omega = 1)
    eta = sf.efficiency[driving]
    assert driving.sum() > 30 and np.all((eta > 0) & (eta < 1))
    assert np.all(np.isnan(sf.efficiency[~driving]))


def test_static_forces_fourbar_friction_converges():
    lk = as_linkage(FourBar(1, 3, 2.5, 3))
    sol = lk.solve(np.linspace(0, 6.2, 32), order=1)
    sf = static_forces(sol, {"C": -10 + 3j}, rho=0.03)
    ok = ~sf.self_locking
    assert ok.sum() > 20
    for key in (("crank", "coupler"), ("coupler", "rocker")):
        R = sf.reactions[key]
        m = np.imag(np.conj(sf.lines[key] - sol.points["B" if key[0] == "crank" else "C"]) * R)
        turning = np.abs(np.sign(sol.omegas[key[1]] - sol.omegas[key[0]]))
        np.testing.assert_allclose(np.abs(m[ok]), 0.03 * turning[ok] * np.abs(R[ok]), rtol=1e-12, atol=1e-14)


def test_static_forces_bad_inputs():
    lk = as_linkage(SliderCrank(1, 3))
    sol = lk.solve(np.array([0.3, 1.0]), order=1)
    with pytest.raises(ValueError, match=r"Expected `rho` >= 0, got -0.1"):
        static_forces(sol, {"C": -1}, rho=-0.1)
    with pytest.raises(ValueError, match=r"Expected `mu` >= 0, got -0.2"):
        static_forces(sol, {"C": -1}, mu=-0.2)
    with pytest.raises(ValueError, match="cross tangent does not exist"):
        static_forces(sol, {("C", "slider"): -1}, rho=1.6)
    with pytest.raises(ValueError, match="Expected a known point"):
        static_forces(sol, {"Z": -1})
    with pytest.raises(ValueError, match="order >= 1"):
        static_forces(lk.solve(0.3), {"C": -1}, rho=0.01)
    with pytest.raises(ValueError, match="Expected `mu` keys"):
        static_forces(sol, {"C": -1}, mu={("rod", "ground"): 0.1})
    bad = as_linkage(FourBar(1, 1.2, 1.5, 3)).solve(np.array([0.5, 3.0]), order=1)
    with pytest.raises(AssemblyError, match=r"index \(1,\)"):
        static_forces(bad, {"C": -1})
    with pytest.raises(ValueError, match="Expected `mu0` >= 0"):
        friction_circle(-0.1, 10)


def test_as_linkage_matches_fourbar_and_slider_crank():
    fb = FourBar(1, 3, 2.5, 3, branch=-1)
    th = np.linspace(0, 6, 7)
    np.testing.assert_allclose(as_linkage(fb).solve(th).points["C"], fb.solve(th).C, atol=1e-12)
    sc = SliderCrank(1, 3, 0.4)
    np.testing.assert_allclose(as_linkage(sc).solve(th).points["C"].real, sc.solve(th).x, atol=1e-12)


def test_exercise_2_22_virtual_work_and_friction():
    from mech.exercises.chapter2_reactions import EXERCISE_2_22, LAYOUT_2_22, linkage_2_22

    s = EXERCISE_2_22.solve()
    sol = linkage_2_22().solve(LAYOUT_2_22["theta"], order=1)
    # ideal: P AE omega1 = Q BF |omega2| (virtual work, from the velocities alone)
    q0 = 30.0 * LAYOUT_2_22["AE"] * 1.0 / (LAYOUT_2_22["BF"] * abs(float(sol.omegas["lever2"])))
    assert abs(s["Q without friction"].value - q0) < 1e-10 * q0
    assert 0.85 * q0 < s["Q with friction"].value < q0
    assert s["friction-circle radius"].value == 2.5
    assert EXERCISE_2_22.solve(mu0=0.0)["Q with friction"].value == pytest.approx(q0, rel=1e-12)


def test_static_forces_negative_mu_without_sliding_pairs():
    sol = as_linkage(FourBar(1, 3, 2.5, 3)).solve(0.5, order=1)
    with pytest.raises(ValueError, match="Expected `mu` >= 0, got -0.2"):
        static_forces(sol, {"C": -10}, mu=-0.2)


def _mp_circle_intersection(p, r, q, s, left_of):
    """Intersection of the circles |z - p| = r and |z - q| = s (mpmath, closed form), the
    root on the left of the directed line p -> ``left_of`` (cross product > 0)."""
    dz = q - p
    L = abs(dz)
    along = (r**2 - s**2 + L**2) / (2 * L)
    h = mpmath.sqrt(r**2 - along**2)
    base = p + dz / L * along
    roots = [base + 1j * dz / L * h, base - 1j * dz / L * h]
    u = left_of - p
    return [z for z in roots if u.real * (z - p).imag - u.imag * (z - p).real > 0][0]


def test_example_2_12_chosen_data_by_hand_free_bodies():
    """Ex. 2-12 as stated on book page ``book-forces-static-forces`` (FourBar(30, 70, 60, 80),
    crank at 60 deg, Q = 100 N at E, 40 mm from D on the rocker, against its motion).

    The reference is a hand free-body solution at 50 digits: the coupler is a two-force
    member, so R23 = F (C - B)/|C - B| with one unknown F, fixed by the rocker's moments about
    D; R43 closes the rocker's force triangle and M_d balances the crank about A. The rocker's
    sense of turning comes from a finite difference of the position, not from the package.
    The printed numbers of the page are pinned too.
    """
    mpmath.mp.dps = 50
    a, b, c, d, de, q = 30, 70, 60, 80, 40, 100
    D = mpmath.mpc(d, 0)

    def C_of(theta):
        B = a * mpmath.expjpi(theta / mpmath.pi)
        return B, _mp_circle_intersection(B, b, D, c, left_of=D)  # branch +1: C left of B->D

    theta = mpmath.radians(60)
    B, C = C_of(theta)
    h = mpmath.mpf("1e-20")
    psi = lambda th: mpmath.arg(C_of(th)[1] - D)
    omega3 = (psi(theta + h) - psi(theta - h)) / (2 * h)          # crank at +1 rad/s
    u = (C - D) / c
    E = D + de * u
    Q = -mpmath.sign(omega3) * 1j * u * q                          # against the rocker's motion
    cr = lambda p, f: p.real * f.imag - p.imag * f.real
    e_bc = (C - B) / b
    F = -cr(E - D, Q) / cr(C - D, e_bc)                            # moments of the rocker about D
    R23 = F * e_bc                                                 # on the rocker from the coupler
    R43 = -(R23 + Q)
    R21 = -R23                                                     # on the crank from the coupler
    M_d = -cr(B, R21)                                              # moments of the crank about A

    lk = as_linkage(FourBar(a, b, c, d)).point("E", link="rocker", at=float(de))
    sol = lk.solve(math.radians(60.0), order=1)
    u_pkg = sol.direction("rocker")
    Q_pkg = complex(-np.sign(sol.omegas["rocker"]) * 1j * u_pkg * 100.0)
    sf = static_forces(sol, {"E": Q_pkg})
    assert abs(Q_pkg - complex(Q)) < 1e-12
    assert abs(complex(sf.reactions[("coupler", "rocker")]) - complex(R23)) < 1e-10
    assert abs(complex(sf.reactions[("ground", "rocker")]) - complex(R43)) < 1e-10
    assert abs(complex(sf.reactions[("crank", "coupler")]) - complex(-R21)) < 1e-10
    assert abs(complex(sf.reactions[("ground", "crank")]) - complex(-R21)) < 1e-10
    assert abs(float(sf.balancing) - float(M_d)) < 1e-9
    # the numbers the page prints (four significant decimals)
    assert float(M_d) == pytest.approx(1141.1755, abs=5e-5)
    assert float(abs(R23)) == pytest.approx(73.7865, abs=5e-4)
    assert float(abs(R43)) == pytest.approx(45.9468, abs=5e-4)


def test_example_2_13_chosen_data_by_hand_free_bodies():
    """Ex. 2-13 as stated on book page ``book-forces-static-forces`` (SliderCrank(50, 150),
    crank at 45 deg turning clockwise at 1 rad/s, Q = 1000 N to the left on the slider, pin
    radius 10 mm with mu0 = 0.15, slider mu = 0.15): M_d with and without friction and eta.

    The reference writes the free bodies by hand at 50 digits: on the rod (a two-force link)
    the friction moments at B and C oppose its rotation relative to the crank and to the
    slider; on the slider the frame's reaction has the normal N and the friction mu |N|
    against the sliding; on the crank the friction moments at B and A oppose its rotation
    relative to the rod and to the frame. The senses come from the exact velocities of the
    centric slider-crank, computed here, not from the package. Three equations (rod moments,
    slider forces) fix the rod force; the crank's moments give M_d.
    """
    mpmath.mp.dps = 50
    r, l, q, rho, mu = 50, 150, 1000, mpmath.mpf("1.5"), mpmath.mpf("0.15")
    th, w1 = mpmath.radians(45), -1
    B = r * mpmath.expjpi(th / mpmath.pi)
    phi = mpmath.asin(-r * mpmath.sin(th) / l)                     # rod angle, C right of B
    C = B + l * mpmath.expjpi(phi / mpmath.pi)
    w2 = -r * mpmath.cos(th) * w1 / (l * mpmath.cos(phi))          # d/dt of r sin th + l sin phi = 0
    v = -r * mpmath.sin(th) * w1 - l * mpmath.sin(phi) * w2        # slider velocity
    s21, s23, s1, sv = (int(mpmath.sign(x)) for x in (w2 - w1, w2, w1, v))
    cr = lambda p, f: p.real * f.imag - p.imag * f.real

    def solve(rho, mu):
        def eqs(fx, fy, n):
            F = mpmath.mpc(fx, fy)                                  # on the rod at B, from the crank
            size = abs(F)
            rod = cr(C - B, -F) - rho * size * s21 - rho * size * s23
            slider = F - q + mpmath.mpc(-sv * mu * abs(n), n)      # rod pushes the slider with F
            return rod, slider.real, slider.imag
        fx, fy, n = mpmath.findroot(eqs, (1000, -300, 300))
        F = mpmath.mpc(fx, fy)
        # crank: force -F at B, reaction F at A, friction moments at B and A
        return -cr(B, -F) - rho * abs(F) * s21 + rho * abs(F) * s1, F

    M_d, F = solve(rho, mu)
    M_d0, _ = solve(0, 0)
    sc = as_linkage(SliderCrank(50, 150))
    sol = sc.solve(math.radians(45.0), order=1, omega=-1.0)
    load = {("C", "slider"): -1000.0}
    rough = static_forces(sol, load, rho=friction_circle(0.15, 10.0), mu=0.15)
    assert abs(float(rough.balancing) - float(M_d)) < 1e-8 * abs(float(M_d))
    assert abs(float(rough.frictionless["crank"]) - float(M_d0)) < 1e-8 * abs(float(M_d0))
    assert abs(complex(rough.reactions[("crank", "rod")]) - complex(F)) < 1e-8 * float(abs(F))
    assert float(rough.efficiency) == pytest.approx(float(M_d0 / M_d), rel=1e-10)
    # the numbers the page prints
    assert float(M_d) == pytest.approx(-49754.3, abs=0.05)
    assert float(M_d0) == pytest.approx(-43930.3, abs=0.05)
    assert float(M_d0 / M_d) == pytest.approx(0.8829, abs=5e-5)


def test_fig_2_85_pin_off_the_guide_moves_the_normal_force():
    """Fig. 2-85: a slider whose pin C is e above the face that carries the resistance W.
    The block's own equilibrium (forces and moments about C, worked here from the rod's
    push, W and the guide's force) puts the guide's normal force at W e / N from the pin,
    which is where `static_forces` says it acts; for e = 0 it passes through the pin."""
    from mech.planar import Guide, Linkage, static_forces

    theta = np.radians(np.arange(10.0, 360.0, 20.0))
    for e in (0.0, 15.0):
        lk = (Linkage({"A": 0, "O": 0j}).crank("crank", pivot="A", tip="B", length=30)
              .rrp(("rod", "slider"), pin="B", guide=Guide("ground", through="O", angle=0.0), joint="C",
                   length=100, branch=1)
              .point("G", link="slider", at=-1j * e))
        sol = lk.solve(theta, order=1)
        W = -100.0 * np.sign(sol.velocities["C"].real) + 0j
        sf = static_forces(sol, {("G", "slider"): W})
        rod = sf.reactions["rod", "slider"]
        N = sf.reactions["ground", "slider"]
        C = sol.points["C"]
        assert np.abs(rod + W + N).max() < 1e-9
        assert np.abs(N.real).max() < 1e-9                      # no friction: normal to the guide
        # moments about C: W at C - e j, N at the reported point; the rod's push passes through C
        shift = -(np.imag(np.conj(-1j * e) * W)) / N.imag
        line = sf.lines["ground", "slider"]
        assert np.allclose((line - C).real, shift, rtol=1e-9, atol=1e-9)
        assert np.allclose(line.imag, 0.0, atol=1e-12)
        if e == 0:
            assert np.abs(line - C).max() < 1e-9
        else:
            # end forces of a 40-long base by the lever rule: the sum is 2 W e / 40 once the
            # line lies outside the base
            n = N.imag
            ends = np.abs(n / 2 - n * shift / 40), np.abs(n / 2 + n * shift / 40)
            outside = np.abs(shift) > 20
            assert outside.all()
            assert np.allclose(ends[0] + ends[1], 2 * 100 * e / 40, rtol=1e-12)
