"""Worked examples with variants (E2-1, E2-2, E2-3, E2-8, E2-9, E2-19, E2-20): the same
registry as the exercises, so sheets, Moodle, QTI and PDFs take them.

Oracles, each by another route than the solver: the law of cosines in mpmath at 50 digits
for the four-bar's limit positions and transmission angle (E2-1); the textbook's closed
forms (F30, F31, eq. 2-9) in mpmath for E2-2, E2-3 and E2-20; for E2-8 the loop closed by
intersecting two circles in mpmath and differentiated numerically (mpmath.diff); for E2-9
the text's result (ω3 = ω1, both clockwise, α3 = 2 ω1² clockwise); for E2-19 the design put
back into F31 (its stroke and K must be the givens). The textbook's printed numbers are
checked for the defaults.
"""

import math

import mpmath
import pytest

from mech.exercises import EXAMPLES, get
from mech.exercises._answers import answers
from tests.exercises.test_exercise_inputs import HOSTILE, _check

mpmath.mp.dps = 50
SEEDS = [0, 1, 2, 5, 11]


def _keys(number, params):
    return {a[0]: a[2] for a in answers(get(number).solve(params))}


def _k(theta):
    return (mpmath.pi + theta) / (mpmath.pi - theta)


# ----------------------------------------------------------------------------- E2-1
def _fourbar_mp(p):
    a, b, c, d = (mpmath.mpf(p[k]) for k in "abcd")
    at_d = lambda s: mpmath.acos((c * c + d * d - s * s) / (2 * c * d))     # angle ADC with AC = s
    at_a = lambda s, r: mpmath.acos((s * s + d * d - c * c) / (2 * s * d))  # angle CAD
    swing = abs(at_d(b - a) - at_d(b + a))
    theta = at_a(b - a, 0) - at_a(b + a, 0)
    delta = lambda s: mpmath.acos((b * b + c * c - s * s) / (2 * b * c))    # angle BCD with BD = s
    gammas = [min(x, mpmath.pi - x) for x in (delta(d - a), delta(d + a))]
    return {"phi": swing, "theta": abs(theta), "K": _k(abs(theta)), "gamma_min": min(gammas)}


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_e2_1_against_the_law_of_cosines(seed):
    p = get("E2-1").defaults if seed is None else get("E2-1").variant(seed)
    got, want = _keys("E2-1", p), _fourbar_mp(p)
    for k in ("phi", "theta", "gamma_min"):
        assert got[k] == pytest.approx(float(mpmath.degrees(want[k])), abs=1e-9), (k, p)
    assert got["K"] == pytest.approx(float(want["K"]), rel=1e-11)


def test_e2_1_textbook_numbers():
    got = _keys("E2-1", {})
    assert round(got["phi"], 4) == 45.9719 and round(got["theta"], 4) == 18.1324
    assert round(got["K"], 5) == 1.22404 and round(got["gamma_min"], 4) == 38.6248


# ----------------------------------------------------------------------------- E2-2, E2-3, E2-20
@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_e2_2_closed_forms(seed):
    p = get("E2-2").defaults if seed is None else get("E2-2").variant(seed)
    d, phi = mpmath.mpf(p["d"]), mpmath.radians(p["phi"])
    a = d * mpmath.sin(phi / 2)
    got = _keys("E2-2", p)
    assert got["l_AB"] == pytest.approx(float(a), rel=1e-12)
    assert got["K"] == pytest.approx(float(_k(phi)), rel=1e-12)
    assert got["L_min"] == pytest.approx(float(d + a), rel=1e-12)


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_e2_3_formulas_f31(seed):
    p = get("E2-3").defaults if seed is None else get("E2-3").variant(seed)
    a, b, e = (mpmath.mpf(p[k]) for k in "abe")
    theta = mpmath.acos(e / (b + a)) - mpmath.acos(e / (b - a))
    H = mpmath.sqrt((b + a) ** 2 - e * e) - mpmath.sqrt((b - a) ** 2 - e * e)
    got = _keys("E2-3", p)
    assert got["theta"] == pytest.approx(abs(float(mpmath.degrees(theta))), abs=1e-10)
    assert got["H"] == pytest.approx(float(H), rel=1e-11)
    assert got["K"] == pytest.approx(float(_k(abs(theta))), rel=1e-11)
    if seed is None:
        assert round(got["theta"], 5) == 7.75167 and round(got["H"], 4) == 61.3703


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_e2_20_closed_forms(seed):
    p = get("E2-20").defaults if seed is None else get("E2-20").variant(seed)
    K, d = mpmath.mpf(p["K"]), mpmath.mpf(p["d"])
    theta = mpmath.pi * (K - 1) / (K + 1)
    got = _keys("E2-20", p)
    assert got["theta"] == pytest.approx(float(mpmath.degrees(theta)), abs=1e-10)
    assert got["l_AB"] == pytest.approx(float(d * mpmath.sin(theta / 2)), rel=1e-12)
    assert got["L_min"] == pytest.approx(float(d + d * mpmath.sin(theta / 2)), rel=1e-12)


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_e2_19_design_meets_its_givens(seed):
    """The crank and rod put back into F31 give the stroke and time ratio asked for, and
    cos γ_min = (a + e)/b."""
    p = get("E2-19").defaults if seed is None else get("E2-19").variant(seed)
    got = _keys("E2-19", p)
    a, b, e = mpmath.mpf(got["l_AB"]), mpmath.mpf(got["l_BC"]), mpmath.mpf(p["e"])
    theta = abs(mpmath.acos(e / (b + a)) - mpmath.acos(e / (b - a)))
    H = mpmath.sqrt((b + a) ** 2 - e * e) - mpmath.sqrt((b - a) ** 2 - e * e)
    assert float(H) == pytest.approx(p["H"], rel=1e-9)
    assert float(_k(theta)) == pytest.approx(p["K"], rel=1e-9)
    assert got["gamma_min"] == pytest.approx(float(mpmath.degrees(mpmath.acos((a + e) / b))), abs=1e-7)


# ----------------------------------------------------------------------------- E2-8, E2-9
def _fourbar_rates_mp(p):
    """ω2, ω3, α2, α3 and |v_E|, |a_E| of E2-8: C by intersecting circles about B and D
    (C above AD), differentiated in mpmath with respect to time."""
    AB, BC, CD, AD = (mpmath.mpf(p[k]) for k in ("AB", "BC", "CD", "AD"))
    w1 = mpmath.mpf(p["omega1"])
    t0 = mpmath.radians(p["theta1"])
    local = mpmath.mpc(p["BE_along"], p["BE_left"])

    def pose(t):
        B = AB * mpmath.expj(t0 + w1 * t)
        D = mpmath.mpf(AD)
        u = D - B
        L = abs(u)
        x = (BC**2 - CD**2 + L**2) / (2 * L)
        h = mpmath.sqrt(BC**2 - x * x)
        C = B + (x + 1j * h) * u / L                      # to the left of B->D: above AD here
        return B, C

    ang = lambda f: lambda t: mpmath.arg(f(t))
    coupler = ang(lambda t: pose(t)[1] - pose(t)[0])
    rocker = ang(lambda t: pose(t)[1] - mpmath.mpf(AD))
    E = lambda t: pose(t)[0] + local * (pose(t)[1] - pose(t)[0]) / BC
    Ex, Ey = (lambda t: mpmath.re(E(t))), (lambda t: mpmath.im(E(t)))
    d1 = lambda f: mpmath.diff(f, 0)
    d2 = lambda f: mpmath.diff(f, 0, 2)
    return {"omega2": d1(coupler), "omega3": d1(rocker), "alpha2": d2(coupler), "alpha3": d2(rocker),
            "v_E": mpmath.hypot(d1(Ex), d1(Ey)), "a_E": mpmath.hypot(d2(Ex), d2(Ey))}


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_e2_8_against_differentiated_closure(seed):
    p = get("E2-8").defaults if seed is None else get("E2-8").variant(seed)
    got, want = _keys("E2-8", p), _fourbar_rates_mp(p)
    for k, v in want.items():
        assert got[k] == pytest.approx(float(v), rel=1e-8, abs=1e-9), (k, p)


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_e2_9_text_result(seed):
    p = get("E2-9").defaults if seed is None else get("E2-9").variant(seed)
    got = _keys("E2-9", p)
    w1, l = p["omega1"], p["l"]
    assert got["omega3"] == pytest.approx(-w1, rel=1e-12)
    assert got["alpha3"] == pytest.approx(-2 * w1**2, rel=1e-10)
    assert got["a_k"] == pytest.approx(float(2 * mpmath.sqrt(2) * w1**2 * l), rel=1e-12)


# ----------------------------------------------------------------------------- registry and inputs
def test_examples_in_the_registry():
    assert list(EXAMPLES) == ["E2-1", "E2-2", "E2-3", "E2-4", "E2-5", "E2-7", "E2-8", "E2-9", "E2-11", "E2-12",
                              "E2-14", "E2-17", "E2-18", "E2-19", "E2-20", "E2-25"]
    assert get("e2-8") is get("E2-8") is EXAMPLES["E2-8"]
    with pytest.raises(ValueError, match="worked example among E2-1"):
        get("E2-6")


@pytest.mark.parametrize("number", list(EXAMPLES))
def test_hostile_givens_refused_by_name(number):
    """Every given of every example, at each hostile value, solves cleanly or is refused by
    a ValueError naming a given; strings and complex numbers are refused by name too."""
    failures = [f for p in get(number).parameters for v in HOSTILE if (f := _check(number, {p.name: v}))]
    assert not failures, failures
    name = get(number).parameters[0].name
    for bad in ("ten", 1 + 2j, float("nan"), True):
        with pytest.raises(ValueError, match=f"`{name}`"):
            get(number).solve(**{name: bad})


def test_examples_exported_to_moodle_and_qti(tmp_path):
    from mech.exercises._export import build_class, write_moodle, write_qti
    from tests.exercises.test_teaching import check_moodle, check_qti

    numbers = ["E2-1", "E2-8", "E2-19"]
    students = build_class(numbers, students=2, seed=5)
    write_moodle(students, tmp_path / "quiz.xml")
    write_qti(students, tmp_path / "quiz.zip")
    check_moodle(tmp_path / "quiz.xml", 2, numbers)
    check_qti(tmp_path / "quiz.zip", 2, numbers)
    assert math.isfinite(students[0].items[1].quantities[0].value)


def test_sheet_command_takes_the_examples(tmp_path, capsys):
    from mech.exercises.__main__ import main

    assert main(["sheet", "examples", "2-3", "--students", "1", "--seed", "4", "--out", str(tmp_path),
                 "--format", "md"]) == 0
    text = (tmp_path / "student_01.md").read_text(encoding="utf-8")
    assert [n for n in list(EXAMPLES) + ["2-3"] if f"## Exercise {n}:" in text] == list(EXAMPLES) + ["2-3"]
    main(["list"])
    assert "E2-8  [A]  Worked example 2-8" in capsys.readouterr().out


def test_examples_in_the_pdfs(tmp_path):
    """The sheets hold each student's givens of the examples, the keys answers that `check`
    accepts (read back with pdftotext)."""
    import shutil

    if shutil.which("pdftotext") is None or shutil.which("pdftoppm") is None:
        pytest.skip("poppler-utils (pdftotext, pdftoppm) not installed: make test-deps")
    from mech.exercises._export import build_class, write_pdf
    from tests.exercises.test_teaching import check_pdfs

    students = build_class(["E2-2", "E2-8", "E2-20"], students=2, seed=9)
    write_pdf(students, tmp_path)
    check_pdfs(tmp_path, students)
