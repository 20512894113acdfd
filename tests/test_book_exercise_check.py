"""The in-page answer check reads answers as ``python -m mech.exercises check`` does (issue 25).

``book/_static/mech/exercise_check.js`` ports `mech.exercises._grade.parse_answer` and
`judge`; under Node it must give the same value (to the last bit) or the same refusal for
every text of a list that covers bare numbers, every unit spelling of the table, spaces and
case, the minus sign U+2212, units of the wrong kind and text that is not a number, and the
same verdict at and around the tolerance's edge. The per-page answer table of
``book/_ext/exercise_check.py`` holds, for a seed, the values that ``check`` compares with.
"""

import json
import math
import subprocess
import sys
from pathlib import Path

import pytest

from derivations import _node

ROOT = Path(__file__).resolve().parents[1]
JS = ROOT / "book" / "_static" / "mech" / "exercise_check.js"

pytestmark = pytest.mark.skipif(_node.node() is None, reason="node is not installed (make setup installs nodejs)")


def _texts():
    from mech.exercises._grade import UNITS

    numbers = ["1", "-2.5", "+3.", ".25", "1e3", "2.5E-2", "\u22124.5", "  7  ", "0", "1e400"]
    out = [(n, u) for n in numbers for u in ("deg", "mm", "N", "", "m/s", "N·m", "rad/s²", "mm/s")]
    for spelt in UNITS:
        for form in (spelt, spelt.upper(), spelt.lower(), f"  {spelt}  ", spelt.replace(" ", "  ")):
            for unit in ("deg", "mm", "N", "N·m", "m/s", "m/s²", "rad/s", "rad/s²", ""):
                out.append((f"12.5{form}", unit))
                out.append((f"-0.75 {form}", unit))
    out += [(t, "mm") for t in ("abc", "1.2.3", "1,5", "1 2", "5 furlongs", "--3", "3 -", "", "e5", "1e", "12 mm mm")]
    return out


def _js(calls):
    script = (f'import {{ parseAnswer, judge }} from "{JS.as_uri()}";\n'
              f"const rules = {json.dumps(_rules())};\n"
              f"const calls = {json.dumps(calls, ensure_ascii=False)};\n"
              "process.stdout.write(JSON.stringify(calls.map(([what, a, b, c]) => what === 'parse' ? "
              "parseAnswer(rules, a, b) : judge(rules, { unit: b }, c, a).status)));")
    done = subprocess.run([_node.node(), "--input-type=module", "-"], input=script, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def _rules():
    sys.path.insert(0, str(ROOT / "book" / "_ext"))
    import exercise_check

    return exercise_check.page_data({})


def test_answers_read_as_check_reads_them():
    from mech.exercises._grade import parse_answer

    texts = _texts()
    got = _js([["parse", t, u] for t, u in texts])
    agree = 0
    for (text, unit), g in zip(texts, got):
        try:
            want = parse_answer(text, unit)
        except ValueError as err:
            assert "why" in g, (text, unit, g)
            assert g["why"] == str(err), (text, unit)
        else:
            assert "value" in g, (text, unit, g)
            if math.isinf(want):
                assert g["value"] is None      # JSON has no infinity: JS wrote null
            else:
                assert g["value"] == want, (text, unit)
        agree += 1
    assert agree > 1500


def test_verdicts_at_the_tolerance_edge():
    from mech.exercises._grade import judge
    from mech.exercises._sheet import Quantity

    cases = []
    for value in (0.0, 1.0, -37.25, 123.456, 1e-4, 5e5):
        tol = 0.01 * abs(value) + 0.01
        for given in (value, value + tol, value - tol, value + 1.0001 * tol, value - 0.9999 * tol,
                      value + 2 * tol):
            for unit in ("deg", "mm", ""):
                cases.append((repr(given), unit, value))
        cases.append(("", "mm", value))
        cases.append(("3 N", "mm", value))
    got = _js([["judge", t, u, v] for t, u, v in cases])
    for (text, unit, value), g in zip(cases, got):
        want = judge(Quantity("q", "q", value, unit), text, 0.01, 0.01).status
        assert g == want, (text, unit, value)


def test_page_table_holds_the_answers_check_compares_with():
    sys.path.insert(0, str(ROOT / "book" / "_ext"))
    import exercise_check
    from mech.exercises import get
    from mech.exercises._sheet import check_answers

    table = exercise_check.exercise_table("2-3")
    assert len(table["seeds"]) == 100
    for seed in (0, 41, 99):
        givens, values = table["seeds"][seed]
        for q, v in zip(table["quantities"], values):
            # the value itself is right, and 3 % beyond it (plus 0.01) is wrong, for check
            right, wrong = check_answers(get("2-3"), seed, [(q["key"], repr(v)), (q["key"], repr(v * 1.03 + 0.02))])
            assert right.status == "right" and wrong.status == "wrong"


def test_every_exercise_has_its_check_on_one_page():
    """The ``exercise-check`` directives of the book's pages list each of the 32 exercises once."""
    import re

    from mech.exercises import EXERCISES

    listed = []
    for page in sorted((ROOT / "book").rglob("*.md")):
        if "_build" in page.parts:
            continue
        for line in re.findall(r"^```\{exercise-check\}(.*)$", page.read_text(encoding="utf-8"), re.M):
            listed += line.split()
    assert sorted(listed) == sorted(EXERCISES)
