"""Tests of the relative-motion polygons and images (F38-F43, examples 2-8, 2-9, 2-10).

Expected values come from routes that do not use the linkage solver: circle intersections
differentiated by mpmath at 50 digits, an exact SymPy solution of example 2-9's loop
equations, and the textbook's (corrected) numbers.
"""

import mpmath as mp
import numpy as np
import pytest

from mech.planar import Guide, Linkage
from mech.planar.kinematics._polygons import (
    acceleration_image,
    acceleration_polygon,
    coincident_motion,
    example_2_9,
    example_2_10,
    relative_motion,
    velocity_image,
    velocity_polygon,
)

SQ3 = np.sqrt(3.0)
# Example 2-8 has no dimensions in the text: a four-bar chosen for it (mm, rad/s).
A8, B8, C8, D8, E8, OMEGA8, THETA8 = 25.0, 60.0, 45.0, 55.0, 30 + 20j, -4.0, np.pi / 3


def _fourbar_2_8(theta=THETA8, branch=1):
    lk = (Linkage({"A": 0, "D": D8})
          .crank("1", pivot="A", tip="B", length=A8)
          .rrr(("2", "3"), pins=("B", "D"), joint="C", lengths=(B8, C8), branch=branch)
          .point("E", link="2", at=E8))
    return lk.solve(theta, order=2, omega=OMEGA8)


def _motions_2_8(sol):
    return [relative_motion(sol, "C", base="B", link="2", pivot="D", pivot_link="3"),
            relative_motion(sol, "E", base="B", link="2", pivot="C")]


def _mp_fourbar_2_8(theta):
    """B, C, E, phi, psi of the four-bar by circle intersection (branch +1)."""

    def pose(t):
        B = A8 * mp.expj(t)
        D = mp.mpf(D8)
        g = D - B
        L = abs(g)
        x = (L**2 + B8**2 - C8**2) / (2 * L)
        h = mp.sqrt(B8**2 - x**2)
        C = B + (x + 1j * h) * g / L        # to the left of B -> D
        phi = mp.arg(C - B)
        E = B + mp.mpc(E8.real, E8.imag) * mp.expj(phi)
        return B, C, E, phi, mp.arg(C - D)

    return pose, mp.mpf(theta)


def _mp_rates_2_8(theta):
    """Velocities, accelerations and link rates at 50 digits by mpmath differentiation."""
    out = {}
    with mp.workdps(50):
        pose, t = _mp_fourbar_2_8(theta)
        for k, name in enumerate(("B", "C", "E", "phi", "psi")):
            d1 = mp.diff(lambda s: pose(s)[k], t, 1)
            d2 = mp.diff(lambda s: pose(s)[k], t, 2)
            out[name] = tuple(complex(z) for z in (pose(t)[k], OMEGA8 * d1, OMEGA8**2 * d2))
    return out


def _rel_close(residual, scale, tol=1e-12):
    return np.max(np.abs(residual)) <= tol * scale


# ---------------------------------------------------------------- example 2-8
def test_example_2_8_rates_match_catalog_and_mpmath():
    """Example 2-8 (F38, F39): omega_2, omega_3, alpha_2, alpha_3 of the chosen four-bar."""
    sol = _fourbar_2_8()
    ref = _mp_rates_2_8(THETA8)
    vp, ap = velocity_polygon(_motions_2_8(sol)), acceleration_polygon(_motions_2_8(sol))
    # omega from the polygon as the textbook reads it: |bc| / BC, |pc| / CD
    BC = abs(complex(sol.points["C"] - sol.points["B"]))
    omega2 = abs(complex(vp.segment("b", "c"))) / BC
    omega3 = abs(complex(vp.vertices["c"])) / C8
    alpha3 = abs(complex(ap.segment("n_c", "c"))) / C8
    alpha2 = abs(complex(ap.segment("n_cb", "c"))) / BC
    assert omega2 == pytest.approx(abs(ref["phi"][1].real), rel=1e-12)
    assert omega3 == pytest.approx(abs(ref["psi"][1].real), rel=1e-12)
    assert alpha2 == pytest.approx(abs(ref["phi"][2].real), rel=1e-10)
    assert alpha3 == pytest.approx(abs(ref["psi"][2].real), rel=1e-10)
    # independently recomputed values (6 digits), with signs
    assert float(sol.omegas["2"]) == pytest.approx(0.455932, abs=1e-6)
    assert float(sol.omegas["3"]) == pytest.approx(-1.79334, abs=1e-5)
    assert float(sol.alphas["2"]) == pytest.approx(5.39114, abs=1e-5)
    assert float(sol.alphas["3"]) == pytest.approx(6.58387, abs=1e-5)


def test_example_2_8_point_e_matches_mpmath():
    """Example 2-8: v_E and a_E (the tip e of both polygons) against mpmath."""
    sol = _fourbar_2_8()
    ref = _mp_rates_2_8(THETA8)
    vp, ap = velocity_polygon(_motions_2_8(sol)), acceleration_polygon(_motions_2_8(sol))
    assert complex(vp.vertices["e"]) == pytest.approx(complex(ref["E"][1]), rel=1e-12)
    assert complex(ap.vertices["e"]) == pytest.approx(complex(ref["E"][2]), rel=1e-10)


def test_example_2_8_equations_as_printed():
    """Example 2-8 (F38, F39 corrected): the terms of each equation, in the textbook's order."""
    sol = _fourbar_2_8()
    mc = _motions_2_8(sol)[0]
    assert mc.velocity.text == "v_C = v_B + v_CB"
    assert mc.acceleration.text == "a_C^n + a_C^t = a_B + a_CB^n + a_CB^t"
    B, C, D = (complex(sol.points[k]) for k in "BCD")
    an, at, aB, acbn, acbt = (complex(t.vector) for t in mc.acceleration.terms)
    w1, w2, w3 = (float(sol.omegas[k]) for k in "123")
    # a_C^n = omega_3^2 CD along C -> D (printed omega_2^2 CD: erratum)
    assert an == pytest.approx(w3**2 * (D - C), rel=1e-13)
    # a_B along B -> A (printed A -> B: erratum)
    assert aB == pytest.approx(w1**2 * (0 - B), rel=1e-13)
    assert acbn == pytest.approx(w2**2 * (B - C), rel=1e-13)
    assert abs((at / (D - C)).real) < 1e-12 * abs(at)        # a_C^t perpendicular to CD
    assert abs((acbt / (B - C)).real) < 1e-12 * abs(acbt)    # a_CB^t perpendicular to CB


# ---------------------------------------------------------------- images
def test_velocity_image_rotated_90_scaled_by_omega():
    """F38: the velocity image of BCE is BCE turned 90 deg in the sense of omega_2, scale |omega_2|."""
    sol = _fourbar_2_8()
    ref = _mp_rates_2_8(THETA8)
    img = velocity_image(sol, "2", "B", ["B", "C", "E"])
    w2 = ref["phi"][1].real
    assert float(img.scale) == pytest.approx(abs(w2), rel=1e-12)
    assert float(img.rotation) == pytest.approx(np.sign(w2) * np.pi / 2, abs=1e-12)
    fig, tips = img.figure, img.tips
    for k in range(3):        # each side of the image is the side of the link times 1j*omega_2
        i, j = k, (k + 1) % 3
        assert complex(tips[j] - tips[i]) == pytest.approx(1j * w2 * complex(fig[j] - fig[i]), rel=1e-11)
    # the image tips are the true velocities of the points (mpmath)
    assert complex(tips[1]) == pytest.approx(complex(ref["C"][1]), rel=1e-12)
    assert complex(tips[2]) == pytest.approx(complex(ref["E"][1]), rel=1e-12)


def _signed_area(z):
    z = np.asarray(z, dtype=complex)
    return 0.5 * np.sum((np.conj(z) * np.roll(z, -1)).imag)


def test_acceleration_image_angle_and_scale():
    """F40: a_CB makes arctan(|alpha_2| / omega_2^2) with C -> B; scale sqrt(alpha^2 + omega^4)."""
    sol = _fourbar_2_8()
    ref = _mp_rates_2_8(THETA8)
    w2, a2 = ref["phi"][1].real, ref["phi"][2].real
    img = acceleration_image(sol, "2", "B", ["B", "C", "E"])
    assert float(img.scale) == pytest.approx(np.hypot(a2, w2**2), rel=1e-10)
    assert float(img.scale) == pytest.approx(5.39514, abs=1e-5)           # recomputed independently
    # rotation 180 deg - phi in the sense of alpha_2
    phi = np.arctan(abs(a2) / w2**2)
    assert float(img.rotation) == pytest.approx(np.sign(a2) * (np.pi - phi), abs=1e-10)
    fig, tips = img.figure, img.tips
    for i, j in ((1, 0), (2, 0), (2, 1)):        # b'c' vs C -> B, b'e' vs E -> B, c'e' vs E -> C
        ang = np.angle(complex(tips[i] - tips[j]) / complex(fig[j] - fig[i]))
        assert abs(ang) == pytest.approx(phi, abs=1e-10)
    assert np.degrees(phi) == pytest.approx(87.7919, abs=1e-4)             # recomputed independently
    # same vertex order: the image triangle has the orientation of the link triangle
    assert np.sign(_signed_area(tips)) == np.sign(_signed_area(fig))
    assert complex(tips[2]) == pytest.approx(complex(ref["E"][2]), rel=1e-10)


def test_velocity_image_point_on_extended_link():
    """F38: F on DC extended: f on cp extended with CD : DF = cp : pf."""
    sol = _fourbar_2_8()
    C, D = complex(sol.points["C"]), complex(sol.points["D"])
    F = D + 0.5 * (D - C)
    img = velocity_image(sol, "3", "D", {"C": C, "D": D, "F": F})
    c, p, f = (complex(t) for t in img.tips)
    assert p == 0
    assert f == pytest.approx(-0.5 * c, rel=1e-13)


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_velocity_polygon_broadcast_closure(shape):
    """Every relative-motion equation closes to rounding over arrays of crank angles."""
    theta = np.linspace(-3.0, 3.0, int(np.prod(shape))).reshape(shape)
    sol = _fourbar_2_8(theta)
    ms = _motions_2_8(sol)
    vp, ap = velocity_polygon(ms), acceleration_polygon(ms)
    assert np.shape(vp.vertices["e"]) == shape
    for eq in vp.equations + ap.equations:
        scale = max(np.max(np.abs(t.vector)) for t in eq.terms)
        assert _rel_close(eq.residual, scale)


# ---------------------------------------------------------------- example 2-9
def _sympy_2_9():
    """Exact alpha_3 / omega_1^2 and the sliding rates of example 2-9, by SymPy."""
    sm = pytest.importorskip("sympy")
    t, w, l = sm.symbols("t omega l", positive=True)
    psi, s = sm.Function("psi")(t), sm.Function("s")(t)
    th = sm.pi / 4 - w * t                      # crank turning clockwise at omega
    # slot fixed in link 3 (pivot C = sqrt(2) l): foot F = C + (l/sqrt2) (cos(psi+pi/2), ...)
    # rotated, slot direction e = (cos psi, sin psi); psi = pi/2 at t = 0 (slot vertical)
    C = sm.Matrix([sm.sqrt(2) * l, 0])
    e = sm.Matrix([sm.cos(psi), sm.sin(psi)])
    nrm = sm.Matrix([-sm.sin(psi), sm.cos(psi)])
    B = sm.Matrix([l * sm.cos(th), l * sm.sin(th)])
    loop = C + (l / sm.sqrt(2)) * nrm + s * e - B
    d1, d2 = loop.diff(t), loop.diff(t, 2)
    at0 = {psi: sm.pi / 2, s: l / sm.sqrt(2)}
    dpsi, ds, ddpsi, dds = sm.symbols("dpsi ds ddpsi dds")
    rep = lambda ex, extra: ex.subs({psi.diff(t, 2): ddpsi, s.diff(t, 2): dds, psi.diff(t): dpsi,
                                     s.diff(t): ds}).subs(extra).subs(at0).subs(t, 0)
    assert sm.simplify(rep(loop, {})) == sm.zeros(2, 1)
    v = sm.solve(list(rep(d1, {})), [dpsi, ds], dict=True)[0]
    a = sm.solve(list(rep(d2, v)), [ddpsi, dds], dict=True)[0]
    return sm.simplify(v[dpsi] / w), sm.simplify(a[ddpsi] / w**2), sm.simplify(v[ds] / (l * w))


def test_example_2_9_alpha3_exact():
    """Example 2-9 (F41, F42): omega_3 = -omega_1 and alpha_3 = -2 omega_1^2 exactly (clockwise)."""
    sm = pytest.importorskip("sympy")
    w_ratio, a_ratio, v_ratio = _sympy_2_9()
    assert w_ratio == -1
    assert a_ratio == -2
    assert sm.simplify(v_ratio + sm.sqrt(2)) == 0
    for l, w in ((1.0, 1.0), (0.3, 7.0), (120.0, 2.5)):
        sol = example_2_9(l, w)
        m = coincident_motion(sol, "B", carrier="2", link="3", pivot="C")
        at = complex(m.acceleration.lhs[1].vector)        # a_B3^t, length alpha_3 BC
        BC = abs(complex(sol.points["B"] - sol.points["C"]))
        alpha3 = (at / (1j * (complex(sol.points["B"]) - complex(sol.points["C"])))).real
        assert alpha3 == pytest.approx(float(a_ratio) * w**2, rel=1e-13)
        assert abs(at) / BC == pytest.approx(2 * w**2, rel=1e-13)
        assert float(sol.omegas["3"]) == pytest.approx(-w, rel=1e-13)


def test_example_2_9_coriolis_term():
    """Example 2-9 (F42): |a^k| = 2 omega v_rel = 2 sqrt(2) omega^2 l, v_rel turned 90 deg with omega."""
    l, w = 2.0, 3.0
    sol = example_2_9(l, w)
    m = coincident_motion(sol, "B", carrier="2", link="3", pivot="C")
    assert m.velocity.text == "v_B3 = v_B2 + v_B3B2"
    assert m.acceleration.text == "a_B3^n + a_B3^t = a_B2 + a_B3B2^k + a_B3B2^r"
    vrel = complex(m.velocity.rhs[1].vector)
    ak = complex(m.acceleration.rhs[1].vector)
    ar = complex(m.acceleration.rhs[2].vector)
    assert abs(vrel) == pytest.approx(np.sqrt(2) * w * l, rel=1e-13)
    assert abs(ak) == pytest.approx(2 * np.sqrt(2) * w**2 * l, rel=1e-13)
    assert ak == pytest.approx(2 * (-w) * 1j * vrel, rel=1e-13)       # omega_3 = -w (cw)
    assert abs(ar) == pytest.approx(np.sqrt(2) * w**2 * l, rel=1e-13)
    assert abs((ar / vrel).imag) < 1e-13                               # a^r along the slot
    # v_B2 points down and to the right (the text's arrow)
    vB2 = complex(m.velocity.rhs[0].vector)
    assert vB2.real > 0 and vB2.imag < 0
    # the velocity polygon: pb3 = pb2
    vp = velocity_polygon([m])
    assert abs(complex(vp.vertices["b3"])) == pytest.approx(abs(complex(vp.vertices["b2"])), rel=1e-13)
    ap = acceleration_polygon([m])
    assert ap.closure <= 1e-13 * abs(ak)


def _sine_mechanism(theta, omega=2.0, alpha=0.5):
    lk = (Linkage({"A": 0})
          .crank("1", pivot="A", tip="B", length=1.0)
          .rpp(("2", "3"), pin="B", guide=Guide("ground", 0j, 0.0), angle=np.pi / 2, point="Q"))
    return lk.solve(theta, order=2, omega=omega, alpha=alpha)


def test_coincident_motion_sine_mechanism_no_coriolis():
    """Fig. 2-50d: the guide translates, so the Coriolis term vanishes at every angle."""
    theta = np.linspace(-3.0, 3.0, 13)
    sol = _sine_mechanism(theta)
    m = coincident_motion(sol, "B", carrier="2", link="3", pivot="Q")
    ak = m.acceleration.rhs[1]
    assert ak.name == "a_B3B2^k"
    assert np.all(ak.vector == 0)
    vrel = m.velocity.rhs[1].vector
    assert np.max(np.abs(vrel)) > 0.5                     # yet the block slides
    x_dd = (2.0**2 * -np.cos(theta) - 0.5 * np.sin(theta))     # d2/dt2 of cos(theta)
    assert np.allclose(m.acceleration.lhs[0].vector.real, x_dd, rtol=0, atol=1e-13)
    assert acceleration_polygon([m]).closure < 1e-13


# ---------------------------------------------------------------- example 2-10
def _motions_2_10(sol):
    return [relative_motion(sol, "C", base="B", link="2", pivot="D", pivot_link="3"),
            relative_motion(sol, "E", base="C", link="3", pivot="D"),
            coincident_motion(sol, "E", carrier="4", link="5", pivot="F")]


def _mp_2_10():
    """Example 2-10 by circle intersection and 50-digit differentiation (the chosen layout)."""
    with mp.workdps(50):
        return _mp_2_10_at_50()


def _mp_2_10_at_50():
    D = mp.mpc(500, -200)
    F = mp.mpc(500 + 200 * mp.sqrt(3), -200)

    def pose(t):
        B = 100 * mp.expj(t)
        g = D - B
        L = abs(g)
        x = (L**2 + 400**2 - 200**2) / (2 * L)
        C = B + (x + 1j * mp.sqrt(400**2 - x**2)) * g / L
        E = D - (C - D)
        return C, E, mp.arg(C - B), mp.arg(E - F)

    out = {}
    for k, name in enumerate(("C", "E", "phi2", "phi5")):
        f = lambda s: pose(s)[k]
        out[name] = tuple(complex(z) for z in (pose(0)[k], -10 * mp.diff(f, 0, 1), 100 * mp.diff(f, 0, 2)))
    return out


def test_example_2_10_textbook_numbers():
    """Example 2-10 (F43): omega_2 = 2.5 ccw, v_C = 0, a_C = a_E = 12500, a_E5 = 6250, alpha_5 = 15.625 ccw."""
    sol = example_2_10()
    vp, ap = velocity_polygon(_motions_2_10(sol)), acceleration_polygon(_motions_2_10(sol))
    BC, EF = 400.0, 400.0
    assert abs(complex(vp.vertices["b"])) == pytest.approx(1000.0, rel=1e-14)
    assert abs(complex(vp.vertices["c"])) < 1e-9
    omega2 = complex(vp.segment("b", "c")) / (1j * complex(sol.points["C"] - sol.points["B"]))
    assert omega2.real == pytest.approx(2.5, rel=1e-14) and omega2.imag == 0
    assert abs(complex(vp.vertices["e5"])) < 1e-9                     # omega_5 = 0
    a_C, a_E, a_E5 = (complex(ap.vertices[k]) for k in ("c", "e", "e5"))
    assert a_C == pytest.approx(-12500.0, abs=1e-8)                    # horizontal, to the left
    assert a_E == pytest.approx(12500.0, abs=1e-8)                     # horizontal, to the right
    assert abs(a_E5) == pytest.approx(6250.0, rel=1e-13)
    assert a_E5 == pytest.approx(3125.0 - 3125.0 * SQ3 * 1j, rel=1e-13)   # recomputed independently (3125, -5412.66)
    assert abs(complex(ap.terms["a_E5^t"].vector)) / EF == pytest.approx(15.625, rel=1e-13)
    assert float(sol.alphas["5"]) == pytest.approx(15.625, rel=1e-13)    # ccw
    assert float(sol.alphas["3"]) == pytest.approx(62.5, rel=1e-13)      # recomputed independently
    assert abs(complex(ap.terms["a_B"].vector)) == pytest.approx(10000.0, rel=1e-14)
    assert abs(complex(ap.terms["a_CB^n"].vector)) == pytest.approx(2500.0, rel=1e-13)
    assert complex(ap.terms["a_E5E4^k"].vector) == 0
    # angle e5' e4' p' = 30 degrees and p'e5' = p'e4' / 2
    e4, e5 = complex(ap.vertices["e4"]), complex(ap.vertices["e5"])
    assert np.degrees(abs(np.angle((e5 - e4) / (0 - e4)))) == pytest.approx(30.0, abs=1e-10)
    assert abs(e5) == pytest.approx(abs(e4) / 2, rel=1e-13)
    assert abs(complex(sol.points["C"] - sol.points["B"])) == pytest.approx(BC, rel=1e-15)


def test_example_2_10_against_mpmath():
    """Example 2-10: the polygon tips against circle intersection differentiated at 50 digits."""
    sol = example_2_10()
    ref = _mp_2_10()
    vp, ap = velocity_polygon(_motions_2_10(sol)), acceleration_polygon(_motions_2_10(sol))
    assert complex(ap.vertices["c"]) == pytest.approx(complex(ref["C"][2]), rel=1e-12)
    assert complex(ap.vertices["e"]) == pytest.approx(complex(ref["E"][2]), rel=1e-12)
    assert float(sol.omegas["2"]) == pytest.approx(ref["phi2"][1].real, rel=1e-13)
    assert float(sol.alphas["5"]) == pytest.approx(ref["phi5"][2].real, rel=1e-12)
    assert abs(ref["phi5"][1].real) < 1e-30


def test_example_2_10_drawing_lengths():
    """Example 2-10 at mu_v = 0.05 (m/s)/mm and mu_a = 0.5 (m/s^2)/mm, in mm."""
    sol = example_2_10()
    vp, ap = velocity_polygon(_motions_2_10(sol)), acceleration_polygon(_motions_2_10(sol))
    lv, la = vp.lengths(50.0), ap.lengths(500.0)
    assert lv["v_B"] == pytest.approx(20.0) and lv["v_CB"] == pytest.approx(20.0)
    assert la["a_B"] == pytest.approx(20.0) and la["a_CB^n"] == pytest.approx(5.0)
    assert la["a_C^t"] == pytest.approx(25.0) and la["a_E5^t"] == pytest.approx(12.5)


def test_example_2_10_closure():
    """Every equation of example 2-10 closes to 1e-12 of its largest term."""
    sol = example_2_10()
    for m in _motions_2_10(sol):
        for eq in (m.velocity, m.acceleration):
            scale = max(float(np.max(np.abs(t.vector))) for t in eq.terms)
            assert _rel_close(eq.residual, max(scale, 1.0))


# ---------------------------------------------------------------- errors
def test_relative_motion_unknown_point():
    with pytest.raises(ValueError, match="Expected `point` to be a point of the solution"):
        relative_motion(example_2_10(), "Z", base="B", link="2")


def test_relative_motion_unknown_link():
    with pytest.raises(ValueError, match="Expected `link` to be a link of the solution"):
        relative_motion(example_2_10(), "C", base="B", link="9")


def test_relative_motion_needs_order_2():
    sol = _fourbar_2_8().linkage.solve(0.3, order=1)
    with pytest.raises(ValueError, match="to be a point of the solution"):
        relative_motion(sol, "C", base="B", link="2")


def test_coincident_motion_not_a_sliding_pair():
    with pytest.raises(ValueError, match=r"Expected \(`carrier`, `link`\) to be a sliding pair"):
        coincident_motion(example_2_10(), "C", carrier="2", link="3", pivot="D")


def test_polygon_lengths_bad_scale():
    vp = velocity_polygon(_motions_2_10(example_2_10()))
    with pytest.raises(ValueError, match="Expected `mu` > 0"):
        vp.lengths(-1.0)


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_coincident_motion_closure_over_a_turn(shape):
    """The guide-bar of example 2-9 closes its Coriolis equation at every crank angle it reaches."""
    # the slot is l/sqrt(2) from C, so it reaches B for |B - C|^2 >= 1/2: cos(theta) <= 0.884
    theta = np.linspace(0.6, 2 * np.pi - 0.6, int(np.prod(shape))).reshape(shape)
    lk = (Linkage({"A": 0, "C": np.sqrt(2)})
          .crank("1", pivot="A", tip="B", length=1.0)
          .rpr(("3", "2"), pins=("C", "B"), offset=1 / np.sqrt(2), branch=1))
    sol = lk.solve(theta, order=2, omega=-1.5, alpha=0.7)
    assert np.all(sol.valid)
    m = coincident_motion(sol, "B", carrier="2", link="3", pivot="C")
    assert np.shape(m.acceleration.residual) == shape
    for eq in (m.velocity, m.acceleration):
        scale = max(np.max(np.abs(t.vector)) for t in eq.terms)
        assert _rel_close(eq.residual, scale)
    assert np.max(np.abs(m.acceleration.rhs[1].vector)) > 0.1       # a Coriolis term is present
