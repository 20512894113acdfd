"""The book's LaTeX -> MathML step (book/_ext/mathml.py) on the constructs the pages use.

Each expected structure is written out by hand from what MathML Core needs to draw the
formula (not taken from the converter's output); a formula that cannot be converted must
raise, so the build stops instead of showing raw TeX.
"""

import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

pytest.importorskip("latex2mathml")
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "book" / "_ext"))
import mathml  # noqa: E402

NS = "{http://www.w3.org/1998/Math/MathML}"


def tree(tex, display=False):
    text, tag = mathml.tex_to_mathml(tex, display=display)
    root = ET.fromstring(text)
    return root, tag, text


def tokens(root, kind):
    return [el.text for el in root.iter(NS + kind)]


def test_inline_and_display():
    root, tag, text = tree(r"\theta + 1")
    assert root.tag == NS + "math" and "display" not in root.attrib and tag is None
    assert tokens(root, "mi") == ["θ"] and tokens(root, "mn") == ["1"]
    root, _, _ = tree(r"\theta + 1", display=True)
    assert root.attrib["display"] == "block"


def test_tag_becomes_the_equation_number():
    root, tag, text = tree(r"\cos\psi = K_1 \tag{2-53}", display=True)
    assert tag == "2-53"
    assert "2-53" not in text and "tag" not in text


def test_tag_in_inline_math_is_an_error():
    with pytest.raises(mathml.MathMLError, match="tag"):
        mathml.tex_to_mathml(r"x \tag{1}")


def test_aligned_becomes_a_table_of_right_and_left_cells():
    root, _, _ = tree(r"\begin{aligned} a &= b + c,\\ d &= e \end{aligned}", display=True)
    table = root.find(f".//{NS}mtable")
    rows = table.findall(f"{NS}mtr")
    assert len(rows) == 2
    cells = rows[0].findall(f"{NS}mtd")
    assert [c.attrib["columnalign"] for c in cells] == ["right", "left"]
    assert tokens(cells[0], "mi") == ["a"]
    assert tokens(cells[1], "mo")[0] == "="  # the relation starts the left-aligned cell
    assert "&" not in ET.tostring(root, encoding="unicode")


def test_rows_without_environment_and_equation_star_wrapper():
    root, tag, _ = tree("\\begin{equation*}\nx = 1 \\\\\ny = 2 \\tag{5}\n\\end{equation*}", display=True)
    assert tag == "5"
    assert len(root.findall(f".//{NS}mtr")) == 2


def test_matrix_keeps_its_cells():
    root, _, _ = tree(r"\begin{bmatrix} 1 & 0 \\ 0 & 1 \end{bmatrix}", display=True)
    assert len(root.findall(f".//{NS}mtd")) == 4
    assert tokens(root, "mo")[0] == "[" and tokens(root, "mo")[-1] == "]"


def test_matrix_whose_first_cell_starts_with_a_bracket():
    root, _, _ = tree(r"\begin{bmatrix}[\mathbf z]_\times & 0\\0&0\end{bmatrix}", display=True)
    assert len(root.findall(f".//{NS}mtd")) == 4


def test_operatorname_and_mathrm_are_upright():
    root, _, _ = tree(r"\operatorname{atan2}(y, x) + e^{\mathrm{i}\theta} + \operatorname{Im} z")
    mis = [(el.text, el.attrib.get("mathvariant")) for el in root.iter(NS + "mi")]
    assert ("atan2", None) in mis  # a multi-letter <mi> is upright
    assert ("i", "normal") in mis  # a single letter needs mathvariant="normal"
    assert ("Im", None) in mis


def test_bold_letters_become_unicode_bold():
    # MathML Core draws no mathvariant="bold": the letters must be the bold code points.
    root, _, text = tree(r"\mathbf z + \boldsymbol\omega + \mathbf{R}")
    assert "mathvariant" not in text
    assert "\U0001D433" in text  # MATHEMATICAL BOLD SMALL Z
    assert "\U0001D74E" in text  # MATHEMATICAL BOLD ITALIC SMALL OMEGA
    assert "\U0001D411" in text  # MATHEMATICAL BOLD CAPITAL R


@pytest.mark.parametrize("variant, letter, code", [
    ("bold", "A", 0x1D400), ("bold", "a", 0x1D41A), ("bold", "Ω", 0x1D6C0), ("bold", "α", 0x1D6C2),
    ("italic", "h", 0x210E), ("bold-italic", "θ", 0x1D73D), ("bold", "7", 0x1D7D5),
    ("sans-serif", "F", 0x1D5A5), ("double-struck", "R", 0x211D), ("double-struck", "S", 0x1D54A),
    ("script", "L", 0x2112), ("fraktur", "g", 0x1D524),
])
def test_styled_letters(variant, letter, code):
    assert mathml.styled(letter, variant) == chr(code)


def test_plus_minus_is_an_operator():
    root, _, _ = tree(r"a \pm b")
    assert "±" in tokens(root, "mo")


def test_big_delimiters_and_control_space():
    root, _, text = tree("\\bigl\\lVert x \\bigr\\rVert + a\\\nb + \\arg z")
    assert "\\" not in text
    assert tokens(root, "mo").count("‖") == 2
    assert "arg" in tokens(root, "mi")


@pytest.mark.parametrize("bad", [r"\unknowncommand x", r"a & b", r"\frac{a}{b"])
def test_what_cannot_be_converted_raises(bad):
    with pytest.raises(mathml.MathMLError):
        mathml.tex_to_mathml(bad)


def test_split_top_ignores_nested_groups():
    assert mathml.split_top(r"a & \begin{matrix} 1 & 2 \end{matrix} & {c & d}", "&") == [
        "a ", r" \begin{matrix} 1 & 2 \end{matrix} ", " {c & d}"]


def test_fences_around_short_content_are_not_stretched():
    # Chromium would stretch them and set them apart from a single letter: sin ( x ).
    root, _, _ = tree(r"\sin{\left(\alpha_{1} \right)}")
    assert {mo.attrib.get("stretchy") for mo in root.iter(NS + "mo")} == {"false"}
    root, _, _ = tree(r"\left(\frac{a}{b}\right)")  # a fraction: the fences stretch
    assert [mo.attrib.get("stretchy") for mo in root.iter(NS + "mo")] == ["true", "true"]


def test_big_delimiters_are_the_normal_glyph_enlarged():
    root, _, _ = tree(r"\bigl(x\bigr)")
    mos = list(root.iter(NS + "mo"))
    assert [mo.attrib.get("style") for mo in mos] == ["font-size:1.2em"] * 2
    assert all("minsize" not in mo.attrib and mo.attrib["stretchy"] == "false" for mo in mos)


def test_thin_space_around_a_function_name_as_in_tex():
    # TeX: a thin space between a function name and an ordinary symbol on either side,
    # none next to an opening, an operator or a relation.
    assert mathml._function_spaces(r"\cos\alpha_1\cos\alpha_2") == r"\cos\,\alpha_1\,\cos\,\alpha_2"
    assert mathml._function_spaces(r"X^-\cos\theta = (\sin x)") == r"X^-\,\cos\,\theta = (\sin\, x)"
    assert mathml._function_spaces(r"\sin^2(\theta) + \tan\left(x\right)") == r"\sin^2(\theta) + \tan\left(x\right)"
    assert mathml._function_spaces(r"\max_{k} x_k") == r"\max_{k}\, x_k"


def test_bars_and_signs_are_spaced_as_in_tex():
    root, _, _ = tree(r"Y = -(X + |P|)")
    mos = [(mo.text, mo.attrib) for mo in root.iter(NS + "mo")]
    assert mos[1][0] == "−" and mos[1][1].get("form") == "prefix"  # a sign after "="
    assert [a.get("form") for t, a in mos if t == "+"] == [None]  # X + |P|: binary
    assert all(a.get("lspace") == "0" == a.get("rspace") for t, a in mos if t == "|")
    root, _, _ = tree(r"a + b \ge c + d.")
    stop = [mo for mo in root.iter(NS + "mo") if mo.text == "."]
    assert stop and stop[0].attrib.get("lspace") == "0"


def test_sums_and_limits_put_their_limits_under_the_operator():
    root, _, _ = tree(r"\sum_{k=1}^{n} a_k + \lim_{x\to 0} f + \max_k x_k", display=True)
    over = root.find(f".//{NS}munderover")
    assert over is not None and over[0].text == "∑" and over[0].attrib["movablelimits"] == "true"
    assert [el[0].text for el in root.iter(NS + "munder")] == ["lim", "max"]
    assert root.find(f".//{NS}msubsup") is None


def test_operatorname_with_a_subscript_stays_well_formed():
    root, _, _ = tree(r"\operatorname{atan}_2\left(y, x\right)")
    sub = root.find(f".//{NS}msub")
    assert [child.text for child in sub] == ["atan", "2"]


def test_a_script_on_a_matrix_belongs_to_the_whole_matrix():
    root, _, _ = tree(r"\begin{bmatrix}X\\Y\end{bmatrix}_{j\to k} = 0", display=True)
    sub = root.find(f".//{NS}msub")
    assert len(sub) == 2 and sub[0].find(f".//{NS}mtable") is not None
