"""`Linkage` and the five class II groups against independent mpmath solutions.

Each reference below is written by hand for one test linkage, at 50 digits, with other
formulas than the generated code (arccosine angles, the textbook's quadratic (2-16),
arcsine offsets, Cramer's rule through ``mpmath.lu_solve``), and its rates come from
``mpmath.diff`` along the input. Nothing is shared with ``derivations/planar/assur_groups.md``.
"""

import math

import mpmath
import numpy as np
import pytest

from mech import AssemblyError
from mech.planar import FourBar, Guide, Linkage, SliderCrank

mpmath.mp.dps = 50
RNG = np.random.default_rng(20261122)


def mpc(z):
    return mpmath.mpc(z.real, z.imag)


def expi(x):
    return mpmath.expj(x)


# ---------------------------------------------------------------- mpmath group solvers
def rrr_ref(P1, P2, r1, r2, M):
    g = P2 - P1
    d = abs(g)
    alpha = mpmath.acos((d**2 + r1**2 - r2**2) / (2 * r1 * d))
    return P1 + r1 * expi(mpmath.arg(g) + M * alpha)


def rrp_ref(P1, Q, e, r1, M):
    """Roots of (2-16) s^2 + E s + F = 0; the root with M * (P3 - P1).e > 0."""
    g = Q - P1
    E = 2 * (g.real * e.real + g.imag * e.imag)
    F = abs(g) ** 2 - r1**2
    for s in ((-E + mpmath.sqrt(E**2 - 4 * F)) / 2, (-E - mpmath.sqrt(E**2 - 4 * F)) / 2):
        u = g + s * e
        if M * (u.real * e.real + u.imag * e.imag) > 0:
            return s
    raise AssertionError("no root on this branch")


def rpr_ref(P1, P2, off, M):
    """Guide angle and block position: P2 - P1 = (s + i off) w."""
    g = P2 - P1
    d = abs(g)
    s = M * mpmath.sqrt(d**2 - off**2)
    theta = mpmath.arg(g) - mpmath.asin(off / d) if M > 0 else mpmath.arg(g) - (mpmath.pi - mpmath.asin(off / d))
    return theta, s


def lin2(a, b, rhs):
    """Solve x a + y b = rhs for real x, y."""
    A = mpmath.matrix([[a.real, b.real], [a.imag, b.imag]])
    x = mpmath.lu_solve(A, mpmath.matrix([rhs.real, rhs.imag]))
    return x[0], x[1]


# ---------------------------------------------------------------- comparison helper
def compare(sol, reference, inputs, scale, rtol=1e-12):
    """reference(x) -> dict name -> mp value; compare values and their 1st/2nd derivatives."""
    worst = 0.0
    for i, x in enumerate(inputs):
        x = mpmath.mpf(float(x))
        ref0 = reference(x)
        for key, val in ref0.items():
            kind, name = key
            d1 = mpmath.diff(lambda t: reference(t)[key], x, 1)
            d2 = mpmath.diff(lambda t: reference(t)[key], x, 2)
            got = _got(sol, kind, name, i)
            for order, (g, r) in enumerate(zip(got, (val, d1, d2))):
                if g is None:
                    continue
                err = abs(complex(g) - complex(r)) / scale[order]
                worst = max(worst, err)
                assert err < rtol, (key, order, float(x), complex(g), complex(r))
    return worst


def _got(sol, kind, name, i):
    if kind == "point":
        return sol.points[name][i], sol.velocities[name][i], sol.accelerations[name][i]
    if kind == "angle":
        return None, sol.omegas[name][i], sol.alphas[name][i]
    if kind == "slide":
        sl = sol.slides[name]
        return sl.s[i], sl.v[i], sl.a[i]
    raise KeyError(kind)


def wrapped_angle_ok(sol, link, ref_angle, i):
    diff = (sol.angles[link][i] - float(ref_angle) + math.pi) % (2 * math.pi) - math.pi
    return abs(diff) < 1e-12


# ---------------------------------------------------------------- RRR
@pytest.mark.parametrize("branch", [1, -1])
def test_linkage_rrr_agrees_with_mpmath(branch):
    a, b, c, d = 25.0, 60.0, 45.0, 55.0
    lk = (Linkage({"A": 0, "D": d}).crank("crank", pivot="A", tip="B", length=a)
          .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(b, c), branch=branch)
          .point("E", link="coupler", at=30 + 20j))
    theta = RNG.uniform(-math.pi, math.pi, 12)
    sol = lk.solve(theta, order=2)   # omega = 1, alpha = 0: time derivative = theta derivative

    def ref(x):
        B = a * expi(x)
        C = rrr_ref(B, mpmath.mpf(d), b, c, branch)
        phi = mpmath.arg(C - B)
        return {("point", "C"): C, ("point", "E"): B + mpmath.mpc(30, 20) * expi(phi),
                ("angle", "coupler"): phi, ("angle", "rocker"): mpmath.arg(C - d)}

    compare(sol, ref, theta, scale=(100, 100, 100))


def test_linkage_rrr_matches_fourbar_and_branch_rule():
    lk = (Linkage({"A": 0, "D": 35}).crank("crank", pivot="A", tip="B", length=10)
          .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(40, 30), branch=-1))
    theta = np.linspace(0, 2 * np.pi, 50)
    sol = lk.solve(theta, order=2, omega=-3.0, alpha=0.5)
    fb = FourBar(10, 40, 30, 35, branch=-1).solve(theta, order=2, omega=-3.0, alpha=0.5)
    np.testing.assert_allclose(sol.points["C"], fb.C, atol=1e-12 * 40)
    np.testing.assert_allclose(sol.accelerations["C"], fb.aC, atol=1e-12 * 400)
    B, C = sol.points["B"], sol.points["C"]
    assert np.all(np.imag(np.conj(35 - B) * (C - B)) < 0)     # right of B -> D


# ---------------------------------------------------------------- RRP on a turning guide, RPR
@pytest.mark.parametrize("m_rpr,m_rrp", [(1, 1), (1, -1), (-1, 1)])
def test_linkage_rpr_then_rrp_on_turning_guide(m_rpr, m_rrp):
    """Crank, a guide-bar (RPR), then a rod to a slider on that turning guide (RRP)."""
    a, off, r1 = 30.0, 4.0, 35.0
    C0 = 50 + 5j
    lk = (Linkage({"A": 0, "C": C0}).crank("crank", pivot="A", tip="B", length=a)
          .rpr(("guide", "block"), pins=("C", "B"), offset=off, branch=m_rpr)
          .point("G", link="guide", at=20 + 3j)
          .rrp(("rod", "slider"), pin="B", guide=Guide("guide", 10 - 2j, 0.4), joint="S",
               length=r1, branch=m_rrp))
    theta = RNG.uniform(-math.pi, math.pi, 60)
    theta = theta[lk.solve(theta).valid][:8]     # this test linkage does not assemble everywhere
    assert theta.size == 8
    sol = lk.solve(theta, order=2)

    def ref(x):
        B = a * expi(x)
        th, s = rpr_ref(mpmath.mpc(C0), B, off, m_rpr)
        w = expi(th)
        G = C0 + mpmath.mpc(20, 3) * w
        Q = C0 + mpmath.mpc(10, -2) * w
        e = w * expi(mpmath.mpf(0.4))
        s2 = rrp_ref(B, Q, e, r1, m_rrp)
        S = Q + s2 * e
        return {("point", "G"): G, ("point", "S"): S, ("angle", "guide"): th,
                ("angle", "rod"): mpmath.arg(S - B),
                ("slide", ("block", "guide")): s, ("slide", ("slider", "guide")): s2}

    compare(sol, ref, theta, scale=(100, 100, 200))
    # Coriolis terms: 2 omega_guide x v_rel
    for key in (("block", "guide"), ("slider", "guide")):
        sl = sol.slides[key]
        np.testing.assert_allclose(sl.coriolis, 2j * sol.omegas["guide"] * sl.v * sl.direction, atol=1e-12)


# ---------------------------------------------------------------- PRP, RPP
def test_linkage_prp_and_rpp_agree_with_mpmath():
    a, C0 = 30.0, 60 + 0j
    lk = (Linkage({"A": 0, "C": C0}).crank("crank", pivot="A", tip="B", length=a)
          .rpr(("guide", "block"), pins=("C", "B"), offset=0.0)
          .prp(("b1", "b2"), guides=(Guide("guide", 5 + 4j, 0.0), Guide("ground", 100j, 0.3)), joint="P")
          .rpp(("pinned", "yoke"), pin="B", guide=Guide("guide", -6 + 1j, 0.2), angle=1.2, point="J",
               offset=0.5))
    # its own draws, so that deselecting another test (make test-fast) does not change them
    theta = np.random.default_rng(2).uniform(-math.pi, math.pi, 8)
    sol = lk.solve(theta, order=2)
    assert sol.valid.all()

    def ref(x):
        B = a * expi(x)
        th, s = rpr_ref(mpmath.mpc(C0), B, 0, 1)
        w = expi(th)
        Q1, e1 = C0 + mpmath.mpc(5, 4) * w, w
        Q2, e2 = mpmath.mpc(0, 100), expi(mpmath.mpf(0.3))
        s1, s2n = lin2(e1, -e2, Q2 - Q1)
        Qr, er = C0 + mpmath.mpc(-6, 1) * w, w * expi(mpmath.mpf(0.2))
        wi = er * expi(mpmath.mpf(1.2))
        # B - Qr = s2 er + (t + 0.5 i) wi
        s2, t = lin2(er, wi, B - Qr - mpmath.mpc(0, 0.5) * wi)
        return {("point", "P"): Q1 + s1 * e1, ("point", "J"): Qr + s2 * er,
                ("slide", ("b1", "guide")): s1, ("slide", ("b2", "ground")): s2n,
                ("slide", ("yoke", "guide")): s2, ("slide", ("pinned", "yoke")): t}

    compare(sol, ref, theta, scale=(300, 300, 600))
    assert np.allclose(sol.omegas["pinned"], sol.omegas["guide"])
    assert np.allclose(sol.slides[("b2", "ground")].coriolis, 0)


# ---------------------------------------------------------------- two drivers: actuator + crank
def test_linkage_actuator_length_is_a_driver():
    lk = (Linkage({"O": 0, "H": 40 + 0j}).crank("boom", pivot="H", tip="T", length=50)
          .rrr(("cyl", "rod"), pins=("O", "T"), joint="X", lengths=("stroke", 20.0)))
    rng = np.random.default_rng(5)
    th = rng.uniform(1.5, 2.2, 6)
    L = rng.uniform(55, 65, 6)
    sol = lk.solve({"boom": th, "stroke": L}, order=2, omega={"boom": 0.0, "stroke": 1.0})
    assert lk.drivers == ("boom", "stroke")
    for i in range(6):
        def X(lv):
            T = 40 + 50 * expi(mpmath.mpf(float(th[i])))
            return rrr_ref(mpmath.mpf(0), T, lv, 20, 1)
        lv = mpmath.mpf(float(L[i]))
        assert abs(complex(sol.points["X"][i]) - complex(X(lv))) < 1e-12 * 100
        assert abs(complex(sol.velocities["X"][i]) - complex(mpmath.diff(X, lv))) < 1e-12 * 100
        assert abs(complex(sol.accelerations["X"][i]) - complex(mpmath.diff(X, lv, 2))) < 1e-12 * 100


def test_linkage_slider_driver_matches_inverted_slider_crank():
    """Drive the slider of a slider-crank; the crank angle must match SliderCrank."""
    lk = (Linkage({"A": 0}).slider("piston", guide=Guide("ground", 10j, 0.0), point="C")
          .rrr(("rod", "crank"), pins=("C", "A"), joint="B", lengths=(100.0, 30.0), branch=1))
    x = np.linspace(75, 125, 7)
    sol = lk.solve(x, order=0)
    theta = np.angle(sol.points["B"])
    sc = SliderCrank(30, 100, 10).solve(theta)
    np.testing.assert_allclose(sc.x, x, atol=1e-12)


# ---------------------------------------------------------------- failures and errors
def test_linkage_strict_error_names_group_and_input():
    lk = (Linkage({"A": 0, "D": 35}).crank("crank", pivot="A", tip="B", length=10)
          .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(20, 10)))
    sol = lk.solve(np.array([0.0, 2.0]))
    assert sol.valid.tolist() == [True, False]
    assert np.isnan(sol.points["C"][1])
    assert sol.failures["RRR coupler-rocker"].tolist() == [False, True]
    with pytest.raises(AssemblyError, match=r"RRR coupler-rocker.*crank = 2\.0; it assembles for crank in \[-0.918336, 0.918336\]"):
        lk.solve(np.array([0.0, 2.0]), strict=True)


def test_linkage_assembly_range_matches_closed_form():
    # B must stay within 30 of D: |10 e^{i t} - 35| <= 30  <=>  cos t >= (100 + 1225 - 900) / 700
    lk = (Linkage({"A": 0, "D": 35}).crank("crank", pivot="A", tip="B", length=10)
          .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(20, 10)))
    (iv,) = lk.assembly_range()
    limit = math.acos(425 / 700)
    assert abs(iv.start + limit) < 1e-12 and abs(iv.end - limit) < 1e-12


def test_linkage_rejects_bad_input():
    lk = Linkage({"A": 0, "D": 35})
    with pytest.raises(ValueError, match=r"Expected `length of crank` > 0, got -1.0"):
        lk.crank("crank", pivot="A", tip="B", length=-1)
    with pytest.raises(ValueError, match=r"known point for `pivot`, got 'Z'"):
        lk.crank("crank", pivot="Z", tip="B", length=1)
    lk2 = lk.crank("crank", pivot="A", tip="B", length=10)
    with pytest.raises(ValueError, match=r"new link name for `link`, got 'crank'"):
        lk2.crank("crank", pivot="A", tip="B2", length=1)
    with pytest.raises(ValueError, match=r"branch.*got 0"):
        lk2.rrr(("b", "c"), pins=("B", "D"), joint="C", lengths=(40, 30), branch=0)
    with pytest.raises(ValueError, match=r"finite `inputs`, got nan"):
        lk2.solve([0.0, float("nan")])
    with pytest.raises(ValueError, match=r"not parallel"):
        lk2.rpp(("p", "y"), pin="B", guide=Guide("ground"), angle=0.0, point="J")


def test_linkage_is_immutable_and_order_is_respected():
    lk = Linkage({"A": 0, "D": 35}).crank("crank", pivot="A", tip="B", length=10)
    lk2 = lk.rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(40, 30))
    assert "C" not in lk.point_names and "C" in lk2.point_names
    sol = lk2.solve(0.3)
    assert sol.velocities == {} and sol.omegas == {}
    with pytest.raises(AttributeError):
        sol.valid = None


# ---------------------------------------------------------------- instant centres
def test_linkage_instant_centres_agree_with_analytic_rates():
    """Fifteen centres of a six-bar with a slider; omegas and a velocity from them."""
    from mech.planar.kinematics._instant_centres import centre_velocities

    lk = (Linkage({"A": 0, "D": 55}).crank("crank", pivot="A", tip="B", length=25)
          .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(60, 45))
          .point("E", link="rocker", at=20 + 15j)
          .rrp(("rod", "slider"), pin="E", guide=Guide("ground", 40j, 0.2), joint="S", length=70))
    theta = RNG.uniform(-math.pi, math.pi, 40)
    theta = theta[lk.solve(theta).valid]
    sol = lk.solve(theta, order=1, omega=2.0)
    ic = sol.instant_centres()
    assert len(ic) == 15
    assert ic["slider", "ground"].at_infinity.all()
    lv = centre_velocities(ic, "ground", "crank", 2.0)
    for link, w in sol.omegas.items():
        np.testing.assert_allclose(lv.omega[link], w, rtol=0, atol=1e-12 * 2.0)
    np.testing.assert_allclose(lv.point_velocity("rod", sol.points["S"]), sol.velocities["S"],
                               rtol=0, atol=1e-12 * 2.0 * 100)
    with pytest.raises(ValueError, match="invalid pose at index"):
        (Linkage({"A": 0, "D": 35}).crank("crank", pivot="A", tip="B", length=10)
         .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(20, 10))
         .solve(np.array([0.0, 2.0])).instant_centres())


# ---------------------------------------------------------------- errata of §2.2 (book/errata.md)
def test_erratum_10_link_angles_keep_their_quadrant():
    """Errata row 10 (§2.2 II, after (2-10)): angles as arctg(dy/dx) lose the quadrant. A
    rocker pointing into the second and third quadrants must give the angle of mpmath's atan2,
    which differs from arctan(dy/dx) by pi there."""
    a, b, c, d = 20.0, 60.0, 45.0, 70.0
    lk = (Linkage({"A": 0, "D": d}).crank("crank", pivot="A", tip="B", length=a)
          .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(b, c)))
    theta = np.linspace(-math.pi, math.pi, 37)
    sol = lk.solve(theta)
    C = np.asarray(sol.points["C"])
    for t, got, z in zip(theta, sol.angles["rocker"], C):
        ref = rrr_ref(a * expi(t), mpmath.mpf(d), b, c, 1)
        want = mpmath.atan2((ref - d).imag, (ref - d).real)
        assert abs(got - float(want)) < 1e-12
        assert abs(z - complex(ref)) < 1e-11
    dz = C - d
    assert np.all(dz.real < 0)                                     # C left of D: quadrants II, III
    assert np.allclose(np.abs(sol.angles["rocker"] - np.arctan(dz.imag / dz.real)), math.pi)


@pytest.mark.parametrize("make", ["fourbar", "slider_crank", "guide_bar"])
def test_erratum_12_groups_are_class_ii(make):
    """Errata row 12 (captions of Figs 2-54, 2-55) and row 41 (example 2-12): the groups of a
    four-bar, a slider-crank and a guide-bar are class II (II 级): two links and three lower
    pairs, 3n - 2 P_L = 0, statically determinate. Each group label names its pairs (R, P)
    and its links; the whole linkage must then have one degree of freedom (Gruebler)."""
    from mech.planar.forces._statics import as_linkage

    if make == "fourbar":
        lk = as_linkage(FourBar(1.0, 3.0, 2.5, 3.0))
    elif make == "slider_crank":
        lk = as_linkage(SliderCrank(1.0, 3.0))
    else:
        lk = (Linkage({"A": 0, "D": 2.0j}).crank("crank", pivot="A", tip="B", length=1.0)
              .rpr(("bar", "block"), pins=("D", "B")))
    driver, *groups = lk.groups
    assert driver.split()[0] == "crank"
    for label in groups:
        kind, links = label.split()
        n, pairs = len(links.split("-")), len(kind)
        assert set(kind) <= {"R", "P"} and (n, pairs) == (2, 3)
        assert 3 * n - 2 * pairs == 0
    moving = 1 + 2 * len(groups)                                   # crank and the groups' links
    lower_pairs = 1 + 3 * len(groups)
    assert 3 * moving - 2 * lower_pairs == 1


def test_erratum_a8_five_bar_turn_counts():
    """Errata row 76 (§2.1, part IV): for the two-crank five-bar the text gives
    i14 = omega1/omega4 = -m/n and says that crank 1 turns n times and crank 4 m times per
    cycle of C. With the ratio as printed the counts are the other way round: crank 1 turns
    m times and crank 4 n times. Here m = 1, n = 2: C's path closes after crank 4 has made
    two turns (crank 1 one), not earlier, and the printed counts would need omega1/omega4
    = -2."""
    m, n = 1, 2
    lk = (Linkage({"A": 0, "E": 3.0})
          .crank("crank1", pivot="A", tip="B", length=1.0, driver="t1")
          .crank("crank4", pivot="E", tip="D", length=1.0, driver="t4")
          .rrr(("link2", "link3"), pins=("B", "D"), joint="C", lengths=(3.0, 3.0)))
    t = np.linspace(0.0, 2.0 * math.pi * n, 4001)                  # crank 4 angle, omega4 = 1
    sol = lk.solve({"t1": -m / n * t, "t4": t}, order=1, omega={"t1": -m / n, "t4": 1.0}, strict=True)
    C = np.asarray(sol.points["C"])
    w = sol.omegas
    assert np.allclose(np.asarray(w["crank1"]) / np.asarray(w["crank4"]), -m / n)
    turns1, turns4 = abs(-m / n * t[-1]) / (2 * math.pi), t[-1] / (2 * math.pi)
    assert (turns1, turns4) == pytest.approx((m, n))
    assert abs(C[-1] - C[0]) < 1e-12                               # one cycle of C
    assert abs(C[len(t) // n] - C[0]) > 0.1                        # not after one turn of crank 4


def _dwell_six_bar_reference(theta):
    """Fig. 2-31a (§2.2, part I) by hand in NumPy: four-bar A = 0, D = 1.15, AB = 0.43,
    BC = CD = 1; M on the coupler with CM = 1 and angle BCM = 95 deg; F from AF = 2.51,
    DF = 1.47 (below AD); E from EM = R = 3.34 and EF = 0.41. Returns E - F."""
    def meet(p, r, q, s, side):
        g = q - p
        L = np.abs(g)
        along = (r * r - s * s + L * L) / (2 * L)
        return p + g / L * (along + 1j * side * np.sqrt(r * r - along * along))

    B = 0.43 * np.exp(1j * theta)
    C = meet(B, 1.0, 1.15 + 0j, 1.0, 1)                           # C left of B->D (branch +1)
    M = C + (B - C) * np.exp(-1j * math.radians(95.0))
    F = meet(0j, 2.51, 1.15 + 0j, 1.47, -1)
    E = meet(M, 3.34, F * np.ones_like(M), 0.41, 1)
    return E - F


def test_erratum_a31_dwell_six_bar_printed_data_has_no_dwell():
    """Errata row 79 (Fig. 2-31a, §2.2, part I): the double-dwell six-bar built from the printed
    relative lengths assembles through a full crank turn and swings its rocker EF by 52.37
    deg, but stays near its two limit positions no longer than a harmonic rocker of the same
    swing: within 0.25 deg of them for 16.0 and 11.5 deg of crank turn (a harmonic swing:
    15.8 deg). `Linkage` is checked against the NumPy construction above."""
    theta = np.linspace(0.0, 2.0 * math.pi, 36001)
    ref = _dwell_six_bar_reference(theta)
    assert not np.isnan(ref).any()
    found = False
    for branch in (1, -1):
        lk = (Linkage({"A": 0, "D": 1.15, "F": _dwell_F()})
              .crank("crank", pivot="A", tip="B", length=0.43)
              .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(1.0, 1.0))
              .point("M", link="coupler", at=1.0 - np.exp(-1j * math.radians(95.0)))
              .rrr(("rod", "swing"), pins=("M", "F"), joint="E", lengths=(3.34, 0.41), branch=branch))
        sol = lk.solve(theta)
        got = np.asarray(sol.points["E"]) - _dwell_F()
        if np.all(sol.valid) and np.max(np.abs(got - ref)) < 1e-9:
            found = True
    assert found
    angle = np.degrees(np.unwrap(np.angle(ref)))
    swing = angle.max() - angle.min()
    assert swing == pytest.approx(52.37, abs=0.01)
    near_top = 360.0 * np.mean(angle.max() - angle < 0.25)
    near_bottom = 360.0 * np.mean(angle - angle.min() < 0.25)
    harmonic = 2.0 * math.degrees(math.acos(1.0 - 0.25 / (swing / 2.0)))
    assert near_top == pytest.approx(16.0, abs=0.1) and near_bottom == pytest.approx(11.5, abs=0.1)
    assert max(near_top, near_bottom) < 1.05 * harmonic


def _dwell_F():
    g = 1.15
    along = (2.51**2 - 1.47**2 + g * g) / (2 * g)
    return complex(along, -math.sqrt(2.51**2 - along**2))


def test_fig_2_24c_dwell_press_punch_rests_while_m_follows_the_arc():
    """Fig. 2-24c (dimensions chosen on the linkages page): the punch N of the dwell press,
    from `Linkage`, against an independent construction (circle intersections for C, the
    coupler point M, and N on the vertical through O at MN from M); N moves about 0.11 mm
    over the 90 deg of crank turn where M follows the arc, out of a 31.9 mm stroke."""
    from mech.planar import Guide

    O, R, D = -19.43 + 1.97j, 30.34, 70.98j
    press = (Linkage({"A": 0, "D": D, "O": O}).crank("crank", pivot="A", tip="B", length=20)
             .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(76.09, 85.77), branch=1)
             .point("M", link="coupler", at=20.47 + 19.68j)
             .rrp(("rod", "punch"), pin="M", guide=Guide("ground", through="O", angle=np.pi / 2),
                  joint="N", length=R, branch=1))
    theta = np.linspace(0.0, 2 * np.pi, 1441)
    N = press.solve(theta).points["N"]
    B = 20 * np.exp(1j * theta)
    m = np.abs(D - B)
    u = (D - B) / m
    along = (76.09**2 - 85.77**2 + m**2) / (2 * m)
    C = B + u * (along + 1j * np.sqrt(76.09**2 - along**2))     # left of B -> D
    M = B + (20.47 + 19.68j) * (C - B) / np.abs(C - B)
    x = M.real - O.real
    y_rel = M.imag - O.imag + np.sqrt(R**2 - x**2)
    assert np.allclose(N.real, O.real, atol=1e-12)
    assert np.allclose(N.imag - O.imag, y_rel, atol=1e-9)
    deg = np.degrees(theta)
    dwell = (deg >= 210) & (deg <= 300)
    assert np.ptp(y_rel[dwell]) == pytest.approx(0.110, abs=0.002)
    assert np.ptp(y_rel) == pytest.approx(31.898, abs=0.002)
    assert np.abs(np.abs(M[dwell] - O) - R).max() < 0.051


def test_fig_2_12a_rppp_chain_revolute_never_turns():
    """Fig. 2-12a: in the R-P-P-P chain (frame CD; DA slides at 60 deg through D, BC at
    120 deg through C, AB in a guide of BC at 100 deg to it) no link turns, so the
    revolute A keeps its angle, and B moves along its line by the sine rule of the
    triangle of the three sliding directions: sin(20 deg) / sin(80 deg) times A's move."""
    rppp = (Linkage({"D": 0j, "C": 100 + 0j})
            .slider("DA", guide=Guide("ground", through="D", angle=np.radians(60.0)), point="A")
            .rpp(("AB", "BC"), pin="A", guide=Guide("ground", through="C", angle=np.radians(120.0)),
                 angle=np.radians(100.0), point="B"))
    s = np.linspace(20.0, 60.0, 41)
    sol = rppp.solve(s)
    A, B = sol.points["A"], sol.points["B"]
    assert np.allclose(A, s * np.exp(1j * np.radians(60.0)), atol=1e-12)
    angle_a = np.angle((B - A) / (0 - A))
    assert np.ptp(angle_a) < 1e-12
    assert abs(np.degrees(angle_a[0])) == pytest.approx(160.0, abs=1e-10)
    moved = np.abs(B - B[0])
    assert np.allclose(moved, (s - s[0]) * np.sin(np.radians(20.0)) / np.sin(np.radians(80.0)), atol=1e-10)
