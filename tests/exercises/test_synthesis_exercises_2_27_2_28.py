"""Exercises 2-27 (furnace door, two-position guidance) and 2-28 (rocker to slider, inversion).

The expected values come from other routes, at 30 digits with mpmath: for 2-27 the fixed
pivots solve |A - B1| = |A - B2| with A on the frame line (one linear equation in y); for
2-28 the hinge E solves the two linear equations |R_j u - f_j|^2 = |R_1 u - f_1|^2 (u = E - D
in the rocker, f_j = F_j - D), and the slider positions are rebuilt from the crank by
circle intersections. The analysis classes are then handed only the reported numbers.
"""

import math

import mpmath
import numpy as np
import pytest

from mech.exercises.__main__ import main
from mech.exercises.chapter2_synthesis import EXERCISE_2_27, EXERCISE_2_28, design_2_27, design_2_28
from mech.planar import FourBar, Guide, Linkage


# ----------------------------------------------------------------------------- 2-27
def _pivot_on_line(P1, P2, x0):
    """The point (x0, y) equidistant from P1 and P2, at 30 digits."""
    with mpmath.workdps(30):
        x0 = mpmath.mpf(x0)
        (x1, y1), (x2, y2) = (map(mpmath.mpf, P) for P in (P1, P2))
        y = ((x0 - x2) ** 2 - (x0 - x1) ** 2 + y2**2 - y1**2) / (2 * (y2 - y1))
        return x0, y


def _mp_lengths_2_27(p):
    pts = {k: (p[f"x{k}"], p[f"y{k}"]) for k in ("B1", "C1", "B2", "C2")}
    with mpmath.workdps(30):
        A = _pivot_on_line(pts["B1"], pts["B2"], p["x0"])
        D = _pivot_on_line(pts["C1"], pts["C2"], p["x0"])
        dist = lambda P, Q: mpmath.sqrt((mpmath.mpf(P[0]) - Q[0]) ** 2 + (mpmath.mpf(P[1]) - Q[1]) ** 2)
        return A, D, [float(v) for v in (dist(pts["B1"], A), dist(pts["B1"], pts["C1"]), dist(pts["C1"], D),
                                         dist(A, D))]


def test_exercise_2_27_pivots_and_lengths_by_bisectors():
    s = EXERCISE_2_27.solve()
    A, D, want = _mp_lengths_2_27(EXERCISE_2_27.defaults)
    got = [float(s[k].value) for k in ("l_AB", "l_BC", "l_CD", "l_AD")]
    assert np.allclose(got, want, rtol=1e-12)
    assert np.allclose([s["A (x)"].value, s["A (y)"].value, s["D (x)"].value, s["D (y)"].value],
                       [float(A[0]), float(A[1]), float(D[0]), float(D[1])], rtol=1e-12)
    assert np.allclose(got, [388.104, 260.0, 266.788, 161.515], atol=1e-3)


@pytest.mark.parametrize("seed", [None, 0, 1, 2, 7])
def test_exercise_2_27_fourbar_from_reported_numbers_moves_the_door(seed):
    """A FourBar built from the reported lengths and pivots alone carries B and C to both poses."""
    p = EXERCISE_2_27.defaults if seed is None else EXERCISE_2_27.variant(seed)
    s = EXERCISE_2_27.solve(p)
    a, b, c, d = (float(s[k].value) for k in ("l_AB", "l_BC", "l_CD", "l_AD"))
    A = complex(s["A (x)"].value, s["A (y)"].value)
    D = complex(s["D (x)"].value, s["D (y)"].value)
    frame = np.angle(D - A)
    B = np.array([complex(p["xB1"], p["yB1"]), complex(p["xB2"], p["yB2"])])
    C = np.array([complex(p["xC1"], p["yC1"]), complex(p["xC2"], p["yC2"])])
    theta = np.angle((B - A) * np.exp(-1j * frame))
    linkage = FourBar(a, b, c, d, branch=int(s["assembly branch"].value))
    pose = linkage.solve(theta, strict=True)
    placed = A + np.exp(1j * frame) * pose.C
    assert np.max(np.abs(placed - C)) <= 1e-9 * max(a, b, c, d)
    # in order on one branch: the input sweeps the reported angle without a dead point
    sweep = theta[0] + np.linspace(0.0, float(s["input AB turns by"].value), 801)
    assert np.all(linkage.solve(sweep).valid)
    assert abs(np.angle(np.exp(1j * (theta[0] + s["input AB turns by"].value - theta[1])))) < 1e-12
    assert s["reaches both door positions on one branch"].value
    assert float(s["largest pose error"].value) < 1e-9


def test_exercise_2_27_bad_givens():
    with pytest.raises(ValueError, match=r"Expected `xB1`, .* with \|B2C2\| = \|B1C1\| > 0 .*xC2=150\.0"):
        EXERCISE_2_27.solve(xC2=150.0)
    with pytest.raises(ValueError, match="Expected `yB2` != `yB1`"):
        EXERCISE_2_27.solve(yB2=380.0, yC2=380.0)
    with pytest.raises(ValueError, match="Expected finite `x0`"):
        design_2_27({**EXERCISE_2_27.defaults, "x0": float("nan")})


# ----------------------------------------------------------------------------- 2-28
def _mp_hinge_2_28(p):
    """E - D in the rocker frame (x along D->C) and EF, by two linear equations at 30 digits."""
    with mpmath.workdps(30):
        d = mpmath.mpf(p["AD"])
        psi = [mpmath.radians(p[k]) for k in ("psi1", "psi2", "psi3")]
        f = [mpmath.mpc(p[k] + 0, p["e"]) + mpmath.mpf(0) for k in ("xF1", "xF2", "xF3")]
        # the slider pin seen from the rocker: g_j = exp(-i psi_j) f_j; |g_j - u| equal for all j
        g = [mpmath.expj(-ps) * fj for ps, fj in zip(psi, f)]
        rows = [[2 * (g[j].real - g[0].real), 2 * (g[j].imag - g[0].imag)] for j in (1, 2)]
        rhs = [abs(g[j]) ** 2 - abs(g[0]) ** 2 for j in (1, 2)]
        u = mpmath.lu_solve(mpmath.matrix(rows), mpmath.matrix(rhs))
        u = mpmath.mpc(u[0], u[1])
        return complex(u), float(abs(g[0] - u)), d


def _mp_slider_positions(p, u, length, crank_angles):
    """Slider positions rebuilt from the crank angles by circle intersections (30 digits)."""
    with mpmath.workdps(30):
        a, b, c, d = (mpmath.mpf(p[k]) for k in ("AB", "BC", "CD", "AD"))
        u, L, e = mpmath.mpc(u), mpmath.mpf(length), mpmath.mpf(p["e"])
        out, rocker = [], []
        for t in crank_angles:
            B = a * mpmath.expj(mpmath.mpf(t))
            # C on the circle of radius c about D and b about B, on the side of the reported psi
            dist = abs(d - B)
            along = (b**2 - c**2 + dist**2) / (2 * dist)
            h = mpmath.sqrt(b**2 - along**2)
            unit = (d - B) / dist
            Cs = [B + unit * (along + 1j * s * h) for s in (1, -1)]
            psi = [mpmath.arg(C - d) for C in Cs]
            rocker.append(psi)
            out.append([(d + mpmath.expj(ps) * u) for ps in psi])
        return out, rocker, L, e


def test_exercise_2_28_hinge_by_linear_inversion():
    s = EXERCISE_2_28.solve()
    u, L, _ = _mp_hinge_2_28(EXERCISE_2_28.defaults)
    assert np.isclose(float(s["l_DE"].value), abs(u), rtol=1e-12)
    assert np.isclose(float(s["angle of DE from DC"].value), np.angle(u), rtol=1e-12)
    assert np.isclose(float(s["l_EF"].value), L, rtol=1e-12)
    assert np.allclose([s["l_DE"].value, s["l_EF"].value], [61.7404, 152.593], atol=1e-3)


@pytest.mark.parametrize("seed", [None, 0, 1, 3, 7])
def test_exercise_2_28_six_bar_meets_the_slider_positions(seed):
    """Crank angles from the design; rocker and slider rebuilt by circle intersections in mpmath."""
    p = EXERCISE_2_28.defaults if seed is None else EXERCISE_2_28.variant(seed)
    g = design_2_28(p)
    u, L, _ = _mp_hinge_2_28(p)
    assert abs(g.hinge - u) <= 1e-10 * abs(u) and abs(g.length - L) <= 1e-10 * L
    hinges, rockers, L, e = _mp_slider_positions(p, u, L, g.crank_angles)
    psi_given = [math.radians(p[k]) for k in ("psi1", "psi2", "psi3")]
    for j, (E_two, psi_two) in enumerate(zip(hinges, rockers)):
        # the C of the design's branch is the one at the given rocker angle
        k = int(np.argmin([abs(math.remainder(float(ps) - psi_given[j], 2 * math.pi)) for ps in psi_two]))
        assert abs(math.remainder(float(psi_two[k]) - psi_given[j], 2 * math.pi)) < 1e-9
        E = E_two[k]
        x = E.real + g.slider_branch * mpmath.sqrt(L**2 - (e - E.imag) ** 2)
        assert abs(float(x) - (p["AD"] + p[f"xF{j + 1}"])) < 1e-9 * max(p["AD"], L)
    assert g.error < 1e-9 and g.stroke_assembles
    # the crank meets the positions in order, turning counter-clockwise by less than a turn
    assert np.all(np.diff(g.crank_angles) > 0) and g.crank_angles[-1] - g.crank_angles[0] < 2 * math.pi


def test_exercise_2_28_linkage_from_reported_numbers():
    """A Linkage built from the rendered results alone reproduces the three slider positions."""
    p = EXERCISE_2_28.defaults
    s = EXERCISE_2_28.solve()
    g = design_2_28(p)
    E = float(s["l_DE"].value) * np.exp(1j * float(s["angle of DE from DC"].value))
    six = (Linkage({"A": 0.0, "D": p["AD"]})
           .crank("crank", pivot="A", tip="B", length=p["AB"])
           .rrr(("coupler", "rocker"), pins=("B", "D"), joint="C", lengths=(p["BC"], p["CD"]),
                branch=int(s["four-bar branch"].value))
           .point("E", link="rocker", at=E)
           .rrp(("link", "slider"), pin="E", guide=Guide("ground", through=0j, angle=0.0), joint="F",
                length=float(s["l_EF"].value), branch=int(s["slider-group branch"].value)))
    sol = six.solve(g.crank_angles, strict=True)
    want = p["AD"] + np.array([p["xF1"], p["xF2"], p["xF3"]])
    assert np.max(np.abs(sol.points["F"] - want)) < 1e-9 * p["BC"]
    assert np.allclose(np.degrees(np.angle(sol.points["C"] - p["AD"])), [p["psi1"], p["psi2"], p["psi3"]],
                       rtol=0, atol=1e-9)


def test_exercise_2_28_bad_givens():
    with pytest.raises(ValueError, match="Expected `psi[123]` that the crank-rocker .* reaches"):
        EXERCISE_2_28.solve(psi1=10.0)
    with pytest.raises(ValueError, match="meets in this order"):
        EXERCISE_2_28.solve(psi2=140.0)
    with pytest.raises(ValueError, match="Expected `AB` > 0"):
        EXERCISE_2_28.solve(AB=-1.0)


# ----------------------------------------------------------------------------- command line
@pytest.mark.parametrize("number", ["2-27", "2-28"])
def test_exercises_2_27_2_28_variant_from_the_command_line(number, capsys):
    assert main(["variant", number, "--seed", "7"]) == 0
    out = capsys.readouterr().out
    assert f"Exercise {number} (variant, seed 7)" in out and "Assumed layout" in out
    assert main(["show", number]) == 0
