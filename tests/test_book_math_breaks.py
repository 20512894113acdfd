"""Long display formulas broken into aligned rows (issue 26): ``book/_ext/math_breaks.py``.

The rows must hold exactly the formula's symbols (nothing lost, nothing split inside a
parenthesis or a fraction), be narrower than the column by the module's own estimate, and
convert to MathML.
"""

import re
import sys
from pathlib import Path

import pytest

pytest.importorskip("latex2mathml")
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "book" / "_ext"))
import math_breaks  # noqa: E402
import mathml  # noqa: E402

LONG_SUM = (r"\displaystyle C_t = \frac{S_{0}^{2} + S_{3}^{2} + h_{0}^{2} + l_{1}^{2} - l_{2}^{2} + l_{3}^{2}}"
            r"{2 l_{1} l_{3}} - \frac{S_{3} \sin{\left(\lambda \right)} \sin{\left(\varphi_{01} \right)}}{l_{1}}"
            r" - \frac{h_{0} \cos{\left(\varphi_{01} \right)}}{l_{3}} - \frac{S_{0} S_{3} \cos{\left(\lambda \right)}}"
            r"{l_{1} l_{3}} + \left(a + b + c + d + e + f\right)^{2} + \sin{\left(x \right)} \cos{\left(y \right)}")
MATRIX = (r"\left[\begin{matrix}\cos{\left(\varphi \right)} & - \sin{\left(\varphi \right)} \cos{\left(\lambda \right)}"
          r" & h \cos{\left(\varphi \right)} + a b c d e f g + q r s t u v w + \sin{\left(\lambda \right)} x y z\\"
          r"\sin{\left(\varphi \right)} & \cos{\left(\lambda \right)} \cos{\left(\varphi \right)}"
          r" & h \sin{\left(\varphi \right)} - k l m n o p + x y z w v - \cos{\left(\lambda \right)} a b c\\"
          r"0 & 0 & 1\end{matrix}\right]")


def _symbols(tex):
    """The formula without the layout that breaking adds (rows, alignment, indents, spaces)."""
    tex = re.sub(r"\\(begin|end)\{aligned\}|\\displaystyle|\\quad|\{\}|&|\\\\", "", tex)
    return re.sub(r"\s+", "", tex)


def test_short_formula_is_untouched():
    assert math_breaks.break_long(r"a + b = c") == r"a + b = c"


@pytest.mark.parametrize("tex", [LONG_SUM, MATRIX])
def test_long_formula_breaks_without_losing_anything(tex):
    out = math_breaks.break_long(tex)
    assert out != tex
    assert _symbols(out) == _symbols(tex)
    math, _ = mathml.tex_to_mathml(out, display=True)
    assert "<mtable" in math


def test_rows_fit_and_parentheses_stay_whole():
    out = math_breaks.break_long(LONG_SUM)
    body = re.search(r"\\begin\{aligned\}(.*)\\end\{aligned\}", out).group(1)
    rows = [r for _, r in math_breaks._split_top(body, r"\\\\")]
    assert len(rows) >= 2
    for row in rows:
        assert math_breaks.width(row) <= math_breaks.LIMIT + 2
        assert row.count(r"\left") == row.count(r"\right")  # no pair cut between rows
        assert row.count("{") == row.count("}")
    assert r"\left(a + b + c + d + e + f\right)^{2}" in out


def test_matrix_keeps_its_shape():
    out = math_breaks.break_long(MATRIX)
    body = re.search(r"\\begin\{matrix\}(.*)\\end\{matrix\}", out, re.S).group(1)
    rows = [r for r in math_breaks.split_rows(body) if r.strip()]
    assert len(rows) == 3
    assert all(len(math_breaks._split_top(r, "&")) == 3 for r in rows)
    assert out.count(r"\begin{aligned}") == 2  # the two long cells
    assert math_breaks.width(out) < math_breaks.width(MATRIX)


def test_aligned_formula_is_left_alone():
    tex = r"a &= " + " + ".join(f"x_{{{k}}}" for k in range(60)) + r" \\ b &= c"
    assert math_breaks.break_long(tex) == tex


def test_tuple_of_results_goes_one_group_per_row():
    """SymPy prints a cell's several results as one tuple; a long one is split at its commas."""
    sm = pytest.importorskip("sympy")
    x, y, lam = sm.symbols("x y lambda")
    items = [sm.sin(lam) * x * y + sm.cos(lam) * x ** 2 + sm.sin(x) * sm.cos(y) * k for k in range(1, 6)]
    tex = r"\displaystyle " + sm.latex(tuple(items))
    out = math_breaks.break_long(tex)
    strip = lambda t: _symbols(re.sub(r"\\\\|\\quad|\\left\(|\\right\)|\\Bigl\(\\,|\\,\\Bigr\)|,|\\ ", "", t))
    assert out != tex and strip(out) == strip(tex)
    body = re.search(r"\\begin\{aligned\}(.*)\\end\{aligned\}", out, re.S).group(1)
    rows = [r for _, r in math_breaks._split_top(body, r"\\\\")]
    assert len(rows) >= 2 and all(math_breaks.width(r) <= math_breaks.LIMIT + 2 for r in rows)
    mathml.tex_to_mathml(out, display=True)


def test_long_function_arguments_go_one_per_row():
    """A long atan2(y, x) is written with its arguments in rows (nothing lost)."""
    sm = pytest.importorskip("sympy")
    a, b, c, d, th = sm.symbols("a b c d theta", positive=True)
    expr = 2 * sm.atan2(4 * a * d * sm.sin(th / 2) ** 2 + (-a - b + c + d) * (-a + b - c + d),
                        4 * a * d * sm.cos(th / 2) ** 2 + (-a + b + c - d) * (a + b + c + d))
    tex = r"\displaystyle " + sm.latex(expr)
    out = math_breaks.break_long(tex)
    body = re.search(r"\\begin\{aligned\}(.*)\\end\{aligned\}", out, re.S).group(1)
    rows = [r for _, r in math_breaks._split_top(body, r"\\\\")]
    assert len(rows) == 2 and all(math_breaks.width(r) <= math_breaks.LIMIT + 3 for r in rows)
    strip = lambda t: re.sub(r"\\\\|\\quad|\\left|\\right|\\Bigl|\\Bigr|[(){},]|\\ ", "", _symbols(t))
    assert strip(out) == strip(tex)
    mathml.tex_to_mathml(out, display=True)


def test_wide_fraction_becomes_a_factor_and_rows():
    """N/D with a long numerator is written (1/D)(N) with N in rows: the same value."""
    sm = pytest.importorskip("sympy")
    u = sm.symbols("u0:12")
    num = sum(u[k] * u[(k + 1) % 12] * sm.sin(u[(k + 2) % 12]) for k in range(12))
    tex = sm.latex(num / (u[0] - u[1]))
    out = math_breaks.break_long(tex)
    assert r"\frac{1}{u_{0} - u_{1}}\Bigl(" in out and out.count(r"\\") >= 1
    mathml.tex_to_mathml(out, display=True)
    # the same expression: parse both back with SymPy's LaTeX-free route (strip layout, compare terms)
    terms = lambda t: sorted(re.findall(r"u_\{\d+\} u_\{\d+\} \\sin\{\\left\(u_\{\d+\} \\right\)\}", t))
    assert terms(out) == terms(tex) and len(terms(tex)) == 12
