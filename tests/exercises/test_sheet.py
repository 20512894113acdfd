"""Problem sheets, answer keys and answer checking (`mech.exercises._sheet`, the
``sheet`` and ``check`` commands).

The reference values of exercise 2-3 come from the law of cosines in mpmath, at the limit
positions (AC = BC + AB and BC - AB), not from `FourBar`; the reference of 2-20 from the
rolling mill's geometry, cos(phi) = (D + a - h)/D with tan(phi) = mu.
"""

import math
import re

import mpmath
import pytest

from mech.exercises import get
from mech.exercises.__main__ import main
from mech.exercises._sheet import (
    DEFAULT_EXERCISES, answer_quantities, check_answers, make_sheet, markdown_to_html, student_seeds,
)

mpmath.mp.dps = 50


def _k_2_3(p):
    """Time ratio and extreme-position angle (degrees) of 2-3 by the law of cosines."""
    a, b, c, d = (mpmath.mpf(p[k]) for k in ("AB", "BC", "CD", "AD"))
    ang = lambda opp, s1, s2: mpmath.acos((s1**2 + s2**2 - opp**2) / (2 * s1 * s2))
    theta = mpmath.degrees(ang(c, d, b - a) - ang(c, d, b + a))
    return float((180 + theta) / (180 - theta)), float(theta)


def _h_max_2_20(p):
    phi = mpmath.atan(mpmath.mpf(p["mu"]))
    return float(p["D"] * (1 - mpmath.cos(phi)) + p["a"])


def test_student_seeds_reproducible_distinct_and_validated():
    seeds = student_seeds(2026, 30)
    assert seeds == student_seeds(2026, 30)
    assert len(set(seeds)) == 30
    assert seeds[:5] == student_seeds(2026, 5)              # adding students keeps the first ones
    assert set(seeds).isdisjoint(student_seeds(2027, 30))
    with pytest.raises(ValueError, match="Expected `students`"):
        student_seeds(1, 0)
    with pytest.raises(ValueError, match="Expected `seed`"):
        student_seeds(-1, 3)


def test_sheet_reproducible_for_a_seed():
    assert make_sheet(["2-3", "2-20"], students=4, seed=11) == make_sheet(["2-3", "2-20"], students=4, seed=11)


def test_sheet_differs_across_seeds_and_students():
    sheet_a, key_a = make_sheet(["2-3"], students=4, seed=11)
    sheet_b, key_b = make_sheet(["2-3"], students=4, seed=12)
    assert sheet_a != sheet_b and key_a != key_b
    statements = re.findall(r"A hinged four-bar has .*? mm and AD = \d+ mm", sheet_a)
    assert len(statements) == 4 and len(set(statements)) == 4


def test_key_matches_variant_and_independent_values():
    """Each student's sheet states ``variant NUMBER --seed SEED``'s numbers, and the key
    gives K and h_max of those numbers as the independent formulas do."""
    seeds = student_seeds(5, 3)
    sheet, key = make_sheet(["2-3", "2-20"], students=3, seed=5)
    keyed = key.split("## Student ")[1:]
    for k, (s, part) in enumerate(zip(seeds, keyed), start=1):
        assert part.startswith(f"{k:02d} (seed {s})")
        for number in ("2-3", "2-20"):
            ex = get(number)
            p = ex.variant(s)
            assert ex.statement_text(p) in sheet
        p = get("2-3").variant(s)
        K, theta = _k_2_3(p)
        row = re.search(r"\| `K` \| time ratio K \| ([0-9.]+)", part)
        assert float(row.group(1)) == pytest.approx(K, rel=1e-5)
        row = re.search(r"\| `theta` \| extreme-position angle θ \| ([0-9.]+) deg", part)
        assert float(row.group(1)) == pytest.approx(theta, rel=1e-5)
        row = re.search(r"\| `h_max` \| largest thickness h_max \| ([0-9.]+) mm", part)
        assert float(row.group(1)) == pytest.approx(_h_max_2_20(get("2-20").variant(s)), rel=1e-5)


def test_key_matches_variant_command(capsys):
    seed = student_seeds(8, 2)[1]
    assert main(["variant", "2-3", "--seed", str(seed)]) == 0
    shown = capsys.readouterr().out
    _, key = make_sheet(["2-3"], students=2, seed=8)
    student_2 = key.split("## Student 02")[1]
    for q in answer_quantities(get("2-3").solve(get("2-3").variant(seed))):
        if q.unit == "deg":
            assert f"{q.value:.4f}°" in shown                  # the variant's rendering
        assert f"| `{q.key}` | {q.name} | {q.value:.6g}" in student_2


def test_check_accepts_right_and_rejects_wrong_naming_the_quantity(capsys):
    seed = 7
    K, theta = _k_2_3(get("2-3").variant(seed))
    assert main(["check", "2-3", "--seed", str(seed), "--answer", f"K={K:.4f}", f"theta={theta:.3f}"]) == 0
    out = capsys.readouterr().out
    assert "right  K (time ratio K)" in out and "right  theta" in out and "2 of 2 right" in out
    code = main(["check", "2-3", "--seed", str(seed), "--answer", f"K={K:.4f}", f"theta={theta * 1.1:.3f}"])
    out = capsys.readouterr().out
    assert code == 1
    assert "WRONG  theta (extreme-position angle θ)" in out and "too high" in out
    assert "1 of 2 right; check theta" in out
    # the full result name works too, and the tolerance is the one stated
    verdicts = check_answers(get("2-3"), seed, {"time ratio K": K * 1.02}, rtol=0.01, atol=0.0)
    assert not verdicts[0].right and verdicts[0].quantity.key == "K"
    assert check_answers(get("2-3"), seed, {"K": K * 1.02}, rtol=0.03, atol=0.0)[0].right


def test_check_bad_input_named(capsys):
    with pytest.raises(SystemExit) as err:
        main(["check", "2-3", "--seed", "7", "--answer", "Z=1"])
    assert err.value.code == 2
    assert "got 'Z'" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        main(["check", "2-3", "--seed", "7", "--answer", "K=abc"])
    assert "got 'K=abc'" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        main(["check", "2-3", "--seed", "7", "--answer", "K=1.2", "--rtol", "-1"])
    assert "Expected `rtol`, `atol` >= 0" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        main(["check", "2-99", "--seed", "7", "--answer", "K=1.2"])
    assert "got '2-99'" in capsys.readouterr().err
    with pytest.raises(ValueError, match="at least one answer"):
        check_answers(get("2-3"), 7, {})


def test_sheet_command_one_file_per_student(tmp_path, capsys):
    """``sheet`` writes a sheet and a key per student (Markdown and HTML), each sheet with
    its own figures; the HTML pages stand alone (figures inline, nothing loaded)."""
    assert main(["sheet", "--students", "5", "--seed", "2026", "--out", str(tmp_path)]) == 0
    assert "for 5 students, class seed 2026" in capsys.readouterr().out
    seeds = student_seeds(2026, 5)
    for k in range(1, 6):
        sheet = (tmp_path / f"student_{k:02d}.md").read_text(encoding="utf-8")
        key = (tmp_path / f"student_{k:02d}_key.md").read_text(encoding="utf-8")
        assert f"(seed {seeds[k - 1]})" in sheet
        assert sheet.count("## Exercise ") == len(DEFAULT_EXERCISES)
        assert sheet.count("![Figure of exercise") == len(DEFAULT_EXERCISES)
        assert "Solution of exercise" not in sheet and "Solution of exercise 2-3" in key
        for number in DEFAULT_EXERCISES:
            assert (tmp_path / "figures" / f"student_{k:02d}_{number}.png").read_bytes()[:4] == b"\x89PNG"
        html = (tmp_path / f"student_{k:02d}.html").read_text(encoding="utf-8")
        assert html.startswith("<!DOCTYPE html>") and html.count("data:image/png;base64,") == len(DEFAULT_EXERCISES)
        assert not re.search(r"(src|href)=\"https?:", html)          # nothing loaded from outside
        assert "<table>" in (tmp_path / f"student_{k:02d}_key.html").read_text(encoding="utf-8")
    assert (tmp_path / "class_list.csv").read_text(encoding="utf-8").splitlines()[1] == f"1,student_01,{seeds[0]}"


@pytest.mark.parametrize("number", ["2-4", "2-5", "2-7"])
def test_sheet_simulated_exercises_thirty_students(number):
    """The exercises that simulate a linkage (and root-solve 2-7's crank) make a 30-student
    sheet too: 45 s for 2-7 before the multisection refinement and the shared solve, about
    5 s after on a loaded machine (timed in benchmarks/bench_sheet.py, not here). The key is the solution of
    each student's variant (the solve that accepted the variant is the one keyed), and 2-7's
    tool stroke is 2 AD to rounding."""
    sheet, key = make_sheet([number], students=30, seed=2026)
    assert sheet.count("## Student ") == 30 and key.count("### Exercise ") == 30
    ex = get(number)
    for s in student_seeds(2026, 30)[:2]:
        assert ex.solve(ex.variant(s)).as_markdown() in key
    if number == "2-7":
        for s in student_seeds(2026, 30)[:5]:
            p = ex.variant(s)
            assert ex.solve(p)["stroke H of P"].value == pytest.approx(2 * p["AD"], rel=1e-12)


def test_sheet_bad_input(tmp_path, capsys):
    with pytest.raises(SystemExit):
        main(["sheet", "--students", "0", "--seed", "1", "--out", str(tmp_path)])
    assert "Expected `students`" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        main(["sheet", "2-99", "--seed", "1", "--out", str(tmp_path)])
    assert "got '2-99'" in capsys.readouterr().err
    with pytest.raises(ValueError, match="at least one exercise"):
        make_sheet([], students=2, seed=1)


def test_markdown_to_html_tables_and_math():
    html = markdown_to_html("# T\n\n| a | b |\n|---|---|\n| 1 | $x^2$ |\n", title="T & U")
    assert "<title>T &amp; U</title>" in html and "<td>1</td>" in html and "x^2" in html
