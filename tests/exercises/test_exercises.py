"""Tests of the generated exercise solutions (2-2, 2-3, 2-6) and the command line.

Every expected value comes from another route than the solver's: the textbook theory
worked by hand, mpmath at 50 digits through the law of cosines, or brute-force sweeps of
the linkage in plain NumPy (rotatability by sampling joint angles, limit positions and
transmission angles by sampling the crank angle).
"""

import math
import subprocess
import sys

import mpmath
import numpy as np
import pytest

import mech.exercises as ex
from mech.exercises import Interval, chapter2
from mech.exercises.__main__ import main

mpmath.mp.dps = 50
SEEDS = [0, 1, 2, 7, 11]


# ----------------------------------------------------------------------------- helpers
def _joint_turns(x, y, u, v, n=721):
    """True if the joint between links x and y turns fully in the loop x, y, u, v.

    Sample the joint's angle over a full turn; the diagonal opposite it must close the
    triangle with the other two links u and v everywhere.
    """
    t = np.linspace(0.0, 2.0 * np.pi, n)
    diag = np.sqrt(x * x + y * y - 2.0 * x * y * np.cos(t))
    return bool(np.all((diag >= abs(u - v) - 1e-12) & (diag <= u + v + 1e-12)))


def _simulated_kind(ab, bc, cd, ad):
    """Type of the four-bar with frame AD from sampled rotatability of joints A and D."""
    a_turns = _joint_turns(ab, ad, bc, cd)
    d_turns = _joint_turns(cd, ad, ab, bc)
    if a_turns and d_turns:
        return "double-crank"
    if a_turns:
        return "crank-rocker"
    if d_turns:
        return "rocker-crank"
    return "double-rocker"


def _in(intervals, x):
    return any(x in iv for iv in intervals)


def _fourbar_sweep(a, b, c, d, n=200_001):
    """Dense crank sweep of the branch with C left of B->D: theta, psi, gamma."""
    theta = np.linspace(-np.pi, np.pi, n)
    B = a * np.exp(1j * theta)
    k = np.abs(d - B)
    # angle at B between B->D and B->C, by the law of cosines (triangle B, C, D)
    beta = np.arccos(np.clip((b * b + k * k - c * c) / (2.0 * b * k), -1.0, 1.0))
    C = B + b * np.exp(1j * (np.angle(d - B) + beta))
    psi = np.unwrap(np.angle(C - d))
    bc, dc = C - B, C - d
    delta = np.abs(np.angle(bc / dc))
    gamma = np.minimum(delta, np.pi - delta)
    return theta, psi, gamma


def _mp_limit_positions(a, b, c, d):
    """Extreme angle, swing and gamma_min by the law of cosines at 50 digits."""
    a, b, c, d = (mpmath.mpf(v) for v in (a, b, c, d))
    at_a = lambda s: mpmath.acos((s * s + d * d - c * c) / (2 * s * d))
    at_d = lambda s: mpmath.acos((c * c + d * d - s * s) / (2 * c * d))
    theta = abs(at_a(b + a) - at_a(b - a))
    swing = abs(at_d(b + a) - at_d(b - a))
    gammas = []
    for k in (d - a, d + a):
        delta = mpmath.acos((b * b + c * c - k * k) / (2 * b * c))
        gammas.append(min(delta, mpmath.pi - delta))
    return float(theta), float(swing), float(min(gammas))


def _wrap(angle):
    return (angle + np.pi) % (2.0 * np.pi) - np.pi


# ----------------------------------------------------------------------------- registry
def test_exercises_numbers():
    assert list(ex.EXERCISES) == ["2-1", "2-2", "2-3", "2-4", "2-5", "2-6", "2-7", "2-8", "2-9", "2-10", "2-11", "2-12", "2-13", "2-14", "2-15", "2-16", "2-17", "2-18", "2-19", "2-20", "2-21", "2-22", "2-23", "2-24", "2-25", "2-26", "2-27", "2-28", "2-29", "2-30", "2-31", "2-32"]
    assert [e.number for e in chapter2.EXERCISES] == ["2-1", "2-2", "2-3", "2-4", "2-5", "2-6", "2-7", "2-8", "2-9", "2-10", "2-11", "2-12", "2-13", "2-14", "2-15", "2-16", "2-17", "2-18", "2-19", "2-20", "2-21", "2-22", "2-23", "2-24", "2-25", "2-26", "2-27", "2-28", "2-29", "2-30", "2-31", "2-32"]


def test_get_unknown_number():
    with pytest.raises(ValueError, match="Expected `number` among 2-1, 2-2, 2-3, 2-4, 2-5, 2-6, 2-7, 2-8, 2-9, 2-10, 2-11, 2-12, 2-13, 2-14, 2-15, 2-16, 2-17, 2-18, 2-19, 2-20, 2-21, 2-22, 2-23, 2-24, 2-25, 2-26, 2-27, 2-28, 2-29, 2-30, 2-31, 2-32 \\(or a worked example among E2-1, .*\\), got '2-99'"):
        ex.get("2-99")


def test_params_unknown_name():
    with pytest.raises(ValueError, match="Expected parameters of exercise 2-3"):
        ex.get("2-3").solve(XY=3.0)


def test_solution_unknown_result():
    with pytest.raises(KeyError, match="Expected a result name"):
        ex.get("2-3").solve()["no such result"]


@pytest.mark.parametrize("number", ["2-2", "2-3", "2-6"])
def test_statement_text_defaults(number):
    exercise = ex.get(number)
    text = exercise.statement_text()
    for p in exercise.parameters:
        assert f"{p.name} = {p.default:g}" in text


@pytest.mark.parametrize("number", ["2-2", "2-3", "2-6"])
def test_variant_reproducible_and_valid(number):
    exercise = ex.get(number)
    first, again = exercise.variant(3), exercise.variant(3)
    assert first == again
    draws = {tuple(exercise.variant(s).values()) for s in SEEDS}
    assert len(draws) > 1
    exercise.solve(first)  # a variant is a valid instance


@pytest.mark.parametrize("number", ["2-2", "2-3", "2-6"])
def test_as_markdown_lists_every_result(number):
    solution = ex.get(number).solve()
    text = solution.as_markdown()
    assert text.startswith(f"**Solution of exercise {number}**")
    assert solution.as_markdown(heading_level=2).startswith(f"## Solution of exercise {number}")
    for r in solution.results():
        assert f"**{r.name}**" in text


def test_interval_contains_and_str():
    iv = Interval(15.0, 45.0, closed_low=False, closed_high=True)
    assert str(iv) == "(15, 45]"
    assert 45.0 in iv and 15.0 not in iv and 30.0 in iv and 46.0 not in iv


def test_merge_intervals_touching():
    merged = chapter2.merge_intervals(
        (Interval(1.0, 2.0, False, False), Interval(0.0, 1.0, False, True))
    )
    assert merged == (Interval(0.0, 2.0, False, False),)
    apart = chapter2.merge_intervals((Interval(0.0, 1.0), Interval(1.0, 2.0)))
    assert len(apart) == 2


# ----------------------------------------------------------------------------- 2-2
def test_exercise_2_2_textbook_ranges():
    """Exercise 2-2, worked by hand: AB <= 15; 45 <= AB <= 55; the rest of (0, 115)."""
    s = ex.get("2-2").solve()
    assert s["AB for a crank-rocker"].value == (Interval(0.0, 15.0, False, True),)
    assert s["AB for a double-crank"].value == (Interval(45.0, 55.0, True, True),)
    assert s["AB for a double-rocker"].value == (
        Interval(15.0, 45.0, False, False),
        Interval(55.0, 115.0, False, False),
    )
    assert s["of which Grashof double-rocker"].value == ()
    text = s.as_markdown()
    assert "(0, 15] mm" in text and "[45, 55] mm" in text and "(15, 45) ∪ (55, 115) mm" in text


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_exercise_2_2_simulation(seed):
    """Sampled AB lengths: the simulated type agrees with the solution's ranges."""
    exercise = ex.get("2-2")
    p = exercise.defaults if seed is None else exercise.variant(seed)
    s = exercise.solve(p)
    bc, cd, ad = p["BC"], p["CD"], p["AD"]
    total = bc + cd + ad
    ranges = {
        "crank-rocker": s["AB for a crank-rocker"].value,
        "double-crank": s["AB for a double-crank"].value,
        "double-rocker": s["AB for a double-rocker"].value,
    }
    ends = np.array([v for ivs in ranges.values() for iv in ivs for v in (iv.low, iv.high)])
    checked = 0
    for ab in np.linspace(0.0, total, 2003)[1:-1]:
        if np.min(np.abs(ends - ab)) < 1e-6 * total:
            continue
        kind = _simulated_kind(ab, bc, cd, ad)
        assert kind != "rocker-crank"
        owners = [k for k, ivs in ranges.items() if _in(ivs, ab)]
        assert owners == [kind], (ab, owners, kind)
        checked += 1
    assert checked > 1900


@pytest.mark.parametrize("seed", [None] + SEEDS)
def test_exercise_2_2_boundaries_change_point(seed):
    """Each finite end point is a change-point linkage: s + l = p + q by hand."""
    exercise = ex.get("2-2")
    p = exercise.defaults if seed is None else exercise.variant(seed)
    s = exercise.solve(p)
    total = p["BC"] + p["CD"] + p["AD"]
    for name in ("AB for a crank-rocker", "AB for a double-crank"):
        for iv in s[name].value:
            for end in (iv.low, iv.high):
                if 0.0 < end < total:
                    ls = sorted([end, p["BC"], p["CD"], p["AD"]])
                    assert ls[0] + ls[3] == pytest.approx(ls[1] + ls[2], abs=1e-9)


def test_exercise_2_2_rejects_open_chain():
    with pytest.raises(ValueError, match="Expected `BC` <"):
        ex.get("2-2").solve(BC=100.0)
    with pytest.raises(ValueError, match="Expected `AD` > 0"):
        ex.get("2-2").solve(AD=-1.0)


# ----------------------------------------------------------------------------- 2-3
def _check_2_3_part1(p, s):
    a, b, c, d = p["AB"], p["BC"], p["CD"], p["AD"]
    theta, swing, gamma_min = _mp_limit_positions(a, b, c, d)
    assert s["extreme-position angle θ"].value == pytest.approx(theta, abs=1e-10)
    assert s["time ratio K"].value == pytest.approx((math.pi + theta) / (math.pi - theta), rel=1e-10)
    assert s["swing φ of CD"].value == pytest.approx(swing, abs=1e-10)
    assert s["minimum transmission angle γ_min"].value == pytest.approx(gamma_min, abs=1e-10)
    # brute force: dense crank sweep
    th, psi, gamma = _fourbar_sweep(a, b, c, d)
    assert np.ptp(psi) == pytest.approx(swing, abs=1e-8)
    sweep_theta = abs(_wrap(th[np.argmax(psi)] - th[np.argmin(psi)] - np.pi))
    assert sweep_theta == pytest.approx(theta, abs=1e-4)
    assert gamma.min() == pytest.approx(gamma_min, abs=1e-8)
    at = s["crank angle at γ_min"].value
    assert abs(_wrap(at - th[np.argmin(gamma)])) < 1e-3


def test_exercise_2_3_textbook_values():
    """Exercise 2-3 (1): theta 18.56 deg, K 1.230, swing 70.56 deg, gamma_min 22.73 deg."""
    p = ex.get("2-3").defaults
    s = ex.get("2-3").solve()
    assert s["type"].value == "crank-rocker"
    _check_2_3_part1(p, s)
    assert math.degrees(s["extreme-position angle θ"].value) == pytest.approx(18.5617, abs=1e-4)
    assert s["time ratio K"].value == pytest.approx(1.22995, abs=1e-5)
    assert math.degrees(s["swing φ of CD"].value) == pytest.approx(70.5582, abs=1e-4)
    assert math.degrees(s["minimum transmission angle γ_min"].value) == pytest.approx(22.7342, abs=1e-4)


@pytest.mark.parametrize("seed", SEEDS)
def test_exercise_2_3_variants(seed):
    exercise = ex.get("2-3")
    p = exercise.variant(seed)
    s = exercise.solve(p)
    _check_2_3_part1(p, s)
    _check_2_3_part2(p, s)


def _check_2_3_part2(p, s):
    a, b, c, d = p["AB"], p["BC"], p["CD"], p["AD"]
    # joints by simulation of the chain A-B-C-D: (links at the joint, the other two)
    turns = {
        "A": _joint_turns(a, d, b, c),
        "B": _joint_turns(a, b, c, d),
        "C": _joint_turns(b, c, a, d),
        "D": _joint_turns(c, d, a, b),
    }
    assert s["joints that turn fully"].value == frozenset(j for j, t in turns.items() if t)
    for j in "CD":
        expected = "整转副" if turns[j] else "摇转副"
        assert expected in s[f"joint {j}"].value
    # AB fixed: AD turns about A, BC about B
    if turns["A"] and turns["B"]:
        assert s["type"].value == "crank-rocker"
        assert s["type with AB as the frame"].value.startswith("a double-crank")


def test_exercise_2_3_frame_ab():
    """Exercise 2-3 (2): AB fixed gives a double-crank; C and D are oscillating joints."""
    p = ex.get("2-3").defaults
    s = ex.get("2-3").solve()
    assert s["type with AB as the frame"].value.startswith("a double-crank")
    assert s["joints that turn fully"].value == frozenset("AB")
    assert "摇转副" in s["joint C"].value and "摇转副" in s["joint D"].value
    _check_2_3_part2(p, s)


def test_exercise_2_3_rejects_non_crank_rocker():
    with pytest.raises(ValueError, match="Expected a crank-rocker with AD as the frame"):
        ex.get("2-3").solve(AB=45.0)
    with pytest.raises(ValueError, match="Expected `CD` > 0"):
        ex.get("2-3").solve(CD=0.0)


# ----------------------------------------------------------------------------- 2-6
def _slider_sweep(r, length, e, n=2**16 + 1):
    theta = np.linspace(-np.pi, np.pi, n)
    B = r * np.exp(1j * theta)
    x = r * np.cos(theta) + np.sqrt(length**2 - (e - r * np.sin(theta)) ** 2)
    rod = (x + 1j * e) - B
    alpha = np.abs(np.angle(rod))  # angle between rod and the guide direction +x
    alpha = np.minimum(alpha, np.pi - alpha)
    return theta, x, np.pi / 2 - alpha


def _mp_stroke(r, length, e):
    r, length, e = (mpmath.mpf(v) for v in (r, length, e))
    return float(mpmath.sqrt((length + r) ** 2 - e * e) - mpmath.sqrt((length - r) ** 2 - e * e))


def _check_2_6(p, s):
    r, length, e = p["r"], p["l"], p["e"]
    theta, x, gamma = _slider_sweep(r, length, e)
    assert s["γ_min"].value == pytest.approx(gamma.min(), abs=1e-8)
    assert s["range of γ: smallest"].value == pytest.approx(gamma.min(), abs=1e-8)
    assert s["range of γ: largest"].value == pytest.approx(gamma.max(), abs=1e-3)
    assert abs(_wrap(s["crank angle at γ_min"].value - theta[np.argmin(gamma)])) < 1e-3
    assert s["stroke, offset"].value == pytest.approx(np.ptp(x), rel=1e-7)
    assert s["stroke, offset"].value == pytest.approx(_mp_stroke(r, length, e), rel=1e-12)
    assert s["stroke, offset"].value > 2.0 * r
    assert s["time ratio K, offset"].value > 1.0
    theta0, x0, gamma0 = _slider_sweep(r, length, 0.0)
    assert s["stroke, centric"].value == pytest.approx(2.0 * r, rel=1e-12)
    assert s["stroke, centric"].value == pytest.approx(np.ptp(x0), rel=1e-7)
    assert s["largest γ (at θ = 0° and 180°)"].value == pytest.approx(np.pi / 2, abs=1e-12)
    assert s["smallest γ (at θ = ±90°)"].value == pytest.approx(
        float(mpmath.acos(mpmath.mpf(r) / length)), abs=1e-10
    )
    assert s["smallest γ (at θ = ±90°)"].value == pytest.approx(gamma0.min(), abs=1e-8)


def test_exercise_2_6_illustrative():
    """Exercise 2-6 with r, l, e = 30, 100, 20: gamma_min = acos(0.5) = 60 deg at -90 deg."""
    p = ex.get("2-6").defaults
    s = ex.get("2-6").solve()
    assert s["γ_min"].value == pytest.approx(math.pi / 3, abs=1e-12)
    assert s["crank angle at γ_min"].value == pytest.approx(-math.pi / 2, abs=1e-9) or (
        s["crank angle at γ_min"].value == pytest.approx(1.5 * math.pi, abs=1e-9)
    )
    assert s["stroke, offset"].value == pytest.approx(61.3703, abs=1e-4)
    _check_2_6(p, s)


@pytest.mark.parametrize("seed", SEEDS)
def test_exercise_2_6_variants(seed):
    exercise = ex.get("2-6")
    p = exercise.variant(seed)
    _check_2_6(p, exercise.solve(p))


def test_exercise_2_6_rejects_crank_that_cannot_turn():
    with pytest.raises(ValueError, match="Expected `r` \\+ `e` < `l`"):
        ex.get("2-6").solve(r=50.0, l=60.0, e=20.0)
    with pytest.raises(ValueError, match="Expected `e` >= 0"):
        ex.get("2-6").solve(e=-5.0)


# ----------------------------------------------------------------------------- command
def test_main_list(capsys):
    assert main(["list"]) == 0
    out = capsys.readouterr().out
    tags = [line.split()[0] for line in out.splitlines() if line.startswith("  [")]
    assert tags == ["[N]", "[A]", "[G]"] and out.startswith("Tags:")
    assert [line.split()[0] for line in out.splitlines() if line.startswith("2-")] == ["2-1", "2-2", "2-3", "2-4", "2-5", "2-6", "2-7", "2-8", "2-9", "2-10", "2-11", "2-12", "2-13", "2-14", "2-15", "2-16", "2-17", "2-18", "2-19", "2-20", "2-21", "2-22", "2-23", "2-24", "2-25", "2-26", "2-27", "2-28", "2-29", "2-30", "2-31", "2-32"]


def test_main_show(capsys):
    assert main(["show", "2-2"]) == 0
    out = capsys.readouterr().out
    assert "BC = 50 mm" in out and "(0, 15] mm" in out and "[45, 55] mm" in out


def test_main_show_plain_text(capsys):
    """`show` and `variant` print plain text for a terminal: no Markdown marks, no LaTeX;
    ``--markdown`` gives the Markdown."""
    for argv in (["show", "2-6"], ["variant", "2-6", "--seed", "3"]):
        assert main(argv) == 0
        out = capsys.readouterr().out
        assert "**" not in out and "$" not in out and "\\" not in out and "`" not in out
        assert "cos γ" in out and "Solution of exercise 2-6\n----" in out
    assert main(["show", "2-6", "--markdown"]) == 0
    assert "**Solution of exercise 2-6**" in capsys.readouterr().out


def test_main_show_set(capsys):
    assert main(["show", "2-3", "--set", "AB=30"]) == 0
    out = capsys.readouterr().out
    assert "AB = 30 mm" in out


def test_main_variant_seed(capsys):
    assert main(["variant", "2-3", "--seed", "7"]) == 0
    first = capsys.readouterr().out
    assert main(["variant", "2-3", "--seed", "7"]) == 0
    assert capsys.readouterr().out == first
    p = ex.get("2-3").variant(7)
    assert f"AB = {p['AB']:g} mm" in first and "(variant, seed 7)" in first


def test_main_variant_without_seed_prints_seed(capsys):
    assert main(["variant", "2-6"]) == 0
    out = capsys.readouterr().out
    seed = int(out.split("(variant, seed ")[1].split(")")[0])
    assert main(["variant", "2-6", "--seed", str(seed)]) == 0
    assert capsys.readouterr().out == out


def test_main_unknown_number(capsys):
    with pytest.raises(SystemExit) as info:
        main(["variant", "2-99"])
    assert info.value.code == 2
    assert "Expected `number` among 2-1, 2-2, 2-3, 2-4, 2-5, 2-6, 2-7, 2-8, 2-9, 2-10, 2-11, 2-12, 2-13, 2-14, 2-15, 2-16, 2-17, 2-18, 2-19, 2-20, 2-21, 2-22, 2-23, 2-24, 2-25, 2-26, 2-27, 2-28, 2-29, 2-30, 2-31, 2-32 (or a worked example among E2-1, E2-2, E2-3, E2-4, E2-5, E2-7, E2-8, E2-9, E2-11, E2-12, E2-14, E2-17, E2-18, E2-19, E2-20, E2-25), got '2-99'" in capsys.readouterr().err


def test_main_invalid_values(capsys):
    with pytest.raises(SystemExit) as info:
        main(["show", "2-3", "--set", "AB=45"])
    assert info.value.code == 2
    assert "Expected a crank-rocker" in capsys.readouterr().err


def test_command_line_module_runs():
    out = subprocess.run(
        [sys.executable, "-m", "mech.exercises", "show", "2-6"],
        capture_output=True, text=True, check=True,
    ).stdout
    assert "Solution of exercise 2-6" in out


def test_import_is_light():
    code = (
        "import sys, mech.exercises; "
        "bad = [m for m in ('sympy', 'scipy', 'matplotlib') if m in sys.modules]; "
        "assert not bad, bad"
    )
    subprocess.run([sys.executable, "-c", code], check=True)
