"""Typeset the book's math at build time as MathML, so no page ships MathJax.

MathJax (its ``tex-chtml.js``, 1.16 MB, and its fonts) was the second-largest file of every
page (issue 17 asks for a median page under 500 kB). Chromium, Firefox and Safari draw
MathML Core natively, so this extension turns each formula's LaTeX into MathML when the
page is written, with `latex2mathml` (pure Python) and a few repairs around it:

- ``aligned``/``split``/``align``/``gather`` and rows separated by ``\\\\`` become an
  ``mtable`` built here (latex2mathml leaves the ``&`` of ``aligned`` in the output);
- ``\\tag{...}`` becomes the equation number at the right, as Sphinx writes its own numbers
  (``span.eqno``);
- ``\\operatorname{...}`` and ``\\mathrm{...}`` become upright identifiers;
- ``mathvariant`` bold and bold-italic (``\\mathbf``, ``\\boldsymbol``), which MathML Core
  does not draw, become the Unicode mathematical bold letters;
- ``\\pm`` and ``\\mp`` become operators;
- a display formula wider than the column is first broken into aligned rows
  (``math_breaks.py``).

A formula that cannot be converted (an unknown command, a stray ``&``, malformed output)
raises :class:`MathMLError`, which stops the build: nothing falls back to raw TeX.
The page's math font is a CSS stack of OpenType math fonts (``mech-math.css``); the browser
test checks that every formula became a ``<math>`` element with a size and that no TeX is
left in the text.
"""

import re
import xml.etree.ElementTree as ET
from pathlib import Path

from docutils import nodes

from math_breaks import break_long
from math_breaks import width as math_width

MATHML_NS = "http://www.w3.org/1998/Math/MathML"
PLACEHOLDER = "MECHPH{}Z"
ALIGN_ENVS = ("aligned", "split", "align", "align*", "alignat", "alignat*", "gather", "gather*",
              "gathered", "multline", "multline*", "flalign", "flalign*", "eqnarray", "eqnarray*")
WRAPPER_ENVS = ("equation", "equation*", "displaymath", "math")
CSS = "mech-math.css"
LONG_INLINE_EM = 14.0  # an inline formula wider than this (about 280 px) is marked mech-long


class MathMLError(ValueError):
    """A formula that cannot be written as MathML."""


# ---------------------------------------------------------------- scanning LaTeX

def _matching_brace(tex, start):
    """Index of the ``}`` that closes the ``{`` at ``start``."""
    depth = 0
    i = start
    while i < len(tex):
        c = tex[i]
        if c == "\\":
            i += 2
            continue
        if c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
            if depth == 0:
                return i
        i += 1
    raise MathMLError(f"unbalanced braces in {tex!r}")


def _env_end(tex, name, start):
    """(begin of ``\\end{name}``, index after it) for the environment whose body starts at ``start``."""
    depth = 1
    pattern = re.compile(r"\\(begin|end)\{" + re.escape(name) + r"\}")
    for m in pattern.finditer(tex, start):
        depth += 1 if m.group(1) == "begin" else -1
        if depth == 0:
            return m.start(), m.end()
    raise MathMLError(f"\\begin{{{name}}} without \\end{{{name}}} in {tex!r}")


_BEGIN_END = re.compile(r"\\(begin|end)\{[^}]*\}")


def split_top(tex, sep):
    """Split at ``sep`` (``\\\\`` or ``&``) where it is outside braces and environments."""
    parts, depth, env, last, i = [], 0, 0, 0, 0
    while i < len(tex):
        m = _BEGIN_END.match(tex, i)
        if m:  # the whole \begin{name} or \end{name}, braces included
            env += 1 if m.group(1) == "begin" else -1
            i = m.end()
            continue
        if depth == 0 and env == 0 and tex.startswith(sep, i) and not (sep == "&" and tex[i - 1:i] == "\\"):
            parts.append(tex[last:i])
            i += len(sep)
            if sep == "\\\\":  # an optional row gap: \\[4pt]
                m = re.match(r"\s*\[[^\]]*\]", tex[i:])
                if m:
                    i += m.end()
            last = i
            continue
        c = tex[i]
        if c == "\\":
            i += 2
            continue
        if c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
        i += 1
    parts.append(tex[last:])
    return parts


def _check_braces(tex):
    """Raise unless every ``{`` has its ``}`` (escaped ``\\{`` and ``\\}`` aside)."""
    depth, i = 0, 0
    while i < len(tex):
        if tex[i] == "\\":
            i += 2
            continue
        depth += {"{": 1, "}": -1}.get(tex[i], 0)
        if depth < 0:
            break
        i += 1
    if depth != 0:
        raise MathMLError(f"unbalanced braces in {tex!r}")


def extract_tag(tex):
    """(tex without its ``\\tag{...}``, the tag text or None); two tags are an error."""
    tags = []
    while True:
        m = re.search(r"\\tag\*?\s*\{", tex)
        if not m:
            break
        close = _matching_brace(tex, m.end() - 1)
        tags.append(tex[m.end():close].strip())
        tex = tex[:m.start()] + tex[close + 1:]
    if len(tags) > 1:
        raise MathMLError(f"more than one \\tag in one formula: {tags}")
    return tex, (tags[0] if tags else None)


# ---------------------------------------------------------------- MathML repair

_GREEK_UPPER = "ΑΒΓΔΕΖΗΘΙΚΛΜΝΞΟΠΡϴΣΤΥΦΧΨΩ∇"
_GREEK_LOWER = "αβγδεζηθικλμνξοπρςστυφχψω∂ϵϑϰϕϱϖ"
# first code point of A, a, Α (Greek capital), α and 0 in each Unicode mathematical style
# (None: the style has no such letters), and the letters that live elsewhere in Unicode
_STYLES = {
    "bold": (0x1D400, 0x1D41A, 0x1D6A8, 0x1D6C2, 0x1D7CE),
    "italic": (0x1D434, 0x1D44E, 0x1D6E2, 0x1D6FC, None),
    "bold-italic": (0x1D468, 0x1D482, 0x1D71C, 0x1D736, 0x1D7CE),
    "sans-serif": (0x1D5A0, 0x1D5BA, None, None, 0x1D7E2),
    "bold-sans-serif": (0x1D5D4, 0x1D5EE, 0x1D756, 0x1D770, 0x1D7EC),
    "double-struck": (0x1D538, 0x1D552, None, None, 0x1D7D8),
    "script": (0x1D49C, 0x1D4B6, None, None, None),
    "fraktur": (0x1D504, 0x1D51E, None, None, None),
    "monospace": (0x1D670, 0x1D68A, None, None, 0x1D7F6),
}
_HOLES = {
    "italic": {"h": "\u210E"},
    "double-struck": dict(zip("CHNPQRZ", "\u2102\u210D\u2115\u2119\u211A\u211D\u2124")),
    "script": dict(zip("BEFHILMRego", "\u212C\u2130\u2131\u210B\u2110\u2112\u2133\u211B\u212F\u210A\u2134")),
    "fraktur": dict(zip("CHIRZ", "\u212D\u210C\u2111\u211C\u2128")),
}


def styled(text, variant):
    """``text`` in the Unicode mathematical alphabet of ``variant`` (bold, italic, sans-serif, ...)."""
    upper, lower, gupper, glower, digit = _STYLES[variant]
    holes = _HOLES.get(variant, {})
    out = []
    for c in text:
        if c in holes:
            out.append(holes[c])
        elif "A" <= c <= "Z":
            out.append(chr(upper + ord(c) - ord("A")))
        elif "a" <= c <= "z":
            out.append(chr(lower + ord(c) - ord("a")))
        elif c in _GREEK_UPPER and gupper is not None:
            out.append(chr(gupper + _GREEK_UPPER.index(c)))
        elif c in _GREEK_LOWER and glower is not None:
            out.append(chr(glower + _GREEK_LOWER.index(c)))
        elif c.isdigit() and digit is not None:
            out.append(chr(digit + ord(c) - ord("0")))
        else:
            out.append(c)
    return "".join(out)


def _inner(mathml):
    """The children of latex2mathml's ``<math>`` element, as text."""
    start = mathml.index(">") + 1
    end = mathml.rindex("</math>")
    return mathml[start:end]


def _convert(tex):
    from latex2mathml.converter import convert

    try:
        return _inner(convert(tex))
    except Exception as exc:  # latex2mathml raises its own exception types
        raise MathMLError(f"latex2mathml cannot convert {tex!r}: {type(exc).__name__}: {exc}") from exc


_TOKENS = {"mi", "mn", "mo", "mtext", "ms"}
_TALL = {"mfrac", "mtable", "msqrt", "mroot", "munderover"}


def _local(el):
    return el.tag.split("}")[-1]


def _fences(tree):
    """Fences that Chromium should not stretch.

    Chromium stretches a ``stretchy`` parenthesis even around a single letter, and Latin
    Modern's stretched glyphs then stand apart from what they enclose: ``sin ( x )``.
    TeX's ``\\left( x \\right)`` keeps the normal glyph when the content is no taller
    than a letter, so a fence pair around content without fractions, tables, roots or big
    operators becomes ``stretchy="false"``; a ``\\bigl(`` (latex2mathml: ``minsize``)
    becomes the normal glyph enlarged by its factor, as TeX's bigger sizes look.
    """
    for mrow in tree.iter():
        kids = list(mrow)
        if (_local(mrow) == "mrow" and len(kids) >= 2 and _local(kids[0]) == "mo" and _local(kids[-1]) == "mo"
                and kids[0].attrib.get("stretchy") == "true"
                and not any(_local(el) in _TALL for el in mrow.iter())):
            for mo in (kids[0], kids[-1]):
                mo.attrib["stretchy"] = "false"
    for mo in tree.iter():
        size = mo.attrib.get("minsize", "")
        if _local(mo) == "mo" and size.endswith("em") and mo.attrib.get("maxsize") == size:
            del mo.attrib["minsize"], mo.attrib["maxsize"]
            mo.attrib["stretchy"] = "false"
            mo.attrib["style"] = f"font-size:{size}"


_CLOSING = {")", "]", "}", "|", "‖", "⟩", "⌋", "⌉"}


def _spacing(tree):
    """TeX's spacing where MathML Core's operator dictionary differs.

    ``|``, ``‖`` and ``.`` are ordinary symbols in TeX (no space around ``|P|``, none
    before a full stop); as an ``<mo>`` Chromium gives them thick spaces. A ``+``/``−`` right after another operator,
    a relation or an opening (``= −(x)``, ``(−x``) is a sign in TeX, with no space; Chromium
    sets it as a binary operator unless its form is prefix.
    """
    for parent in tree.iter():
        previous = None
        for el in parent:
            if _local(el) == "mo":
                text = el.text or ""
                if text in ("|", "‖", "."):  # "." is not in the operator dictionary: thick spaces
                    el.attrib.setdefault("lspace", "0")
                    el.attrib.setdefault("rspace", "0")
                elif text in ("−", "+", "±", "∓") and previous is not None and _local(previous) == "mo" \
                        and (previous.text or "") not in _CLOSING:
                    el.attrib.setdefault("form", "prefix")
            previous = el


_BIG_OPS = {"∑", "∏", "∐", "⋂", "⋃", "⨀", "⨁", "⨂", "⨄", "⨆", "lim", "max", "min", "sup", "inf", "liminf", "limsup"}
_LIMITS = {"msub": "munder", "msup": "mover", "msubsup": "munderover"}
_ARITY = {"mfrac": 2, "msub": 2, "msup": 2, "msubsup": 3, "munder": 2, "mover": 2, "munderover": 3, "mroot": 2}


def _big_operators(tree):
    """``\\sum_k``, ``\\lim_{x\\to 0}``, ``\\max_k``: limits under and over the operator in a
    display formula and a large ∑, as in TeX (``movablelimits`` puts them back beside the
    operator in inline math); latex2mathml writes them as sub/superscripts."""
    for el in tree.iter():
        kids = list(el)
        if _local(el) in _LIMITS and kids and _local(kids[0]) == "mo" and (kids[0].text or "") in _BIG_OPS:
            el.tag = el.tag.replace(_local(el), _LIMITS[_local(el)])
            kids[0].attrib["movablelimits"] = "true"
            if len(kids[0].text) == 1:
                kids[0].attrib["largeop"] = "true"


def _check_arity(tree):
    for el in tree.iter():
        n = _ARITY.get(_local(el))
        if n is not None and len(el) != n:
            raise MathMLError(f"<{_local(el)}> with {len(el)} children instead of {n}")


def _repair(tree):
    """Unicode bold letters for mathvariant, operators for ±/∓, fences, limits, spacing;
    raises on leftover TeX or malformed MathML."""
    _check_arity(tree)
    _fences(tree)
    _big_operators(tree)
    for el in tree.iter():
        tag = el.tag.split("}")[-1]
        variant = el.attrib.get("mathvariant")
        if tag in _TOKENS and variant in _STYLES:
            el.text = styled(el.text or "", variant)
            del el.attrib["mathvariant"]
        elif tag == "mi" and variant == "normal" and len(el.text or "") > 1:
            del el.attrib["mathvariant"]  # a name of several letters is upright anyway
        if tag == "mi" and (el.text or "") in ("±", "∓"):
            el.tag = el.tag.replace("mi", "mo")
        if tag in _TOKENS:
            text = el.text or ""
            if "\\" in text:
                raise MathMLError(f"unknown LaTeX command {text!r}")
            if tag != "mtext" and "&" in text:
                raise MathMLError("a stray alignment '&' outside an aligned environment")


# ---------------------------------------------------------------- LaTeX -> MathML

def _table(rows_tex, kind):
    """An ``mtable`` for aligned rows: columns alternate right/left (centred for gather)."""
    rows = []
    for row in split_top(rows_tex, "\\\\"):
        if not row.strip():
            continue
        cells = split_top(row, "&")
        tds = []
        for k, cell in enumerate(cells):
            if kind.startswith(("gather", "multline")):
                align, pad = "center", ""
            elif k % 2 == 0:
                align, pad = "right", "padding-right:0;" + ("padding-left:2em;" if k else "")
            else:
                align, pad = "left", "padding-left:0;"
                cell = "{}" + cell  # a relation that starts the cell keeps its spacing
            # an empty cell (a continuation row "\\ &= ...") is an empty group
            body = _to_mathml(cell if cell.strip() else "{}")
            tds.append(f'<mtd columnalign="{align}" style="text-align:{align};{pad}">'
                       f'<mrow>{body}</mrow></mtd>')
        rows.append("<mtr>" + "".join(tds) + "</mtr>")
    if not rows:
        raise MathMLError(f"an empty {kind} environment")
    return '<mtable displaystyle="true" class="mech-aligned">' + "".join(rows) + "</mtable>"


# \bigl\lVert and friends: latex2mathml keeps a command after \big as text; give it the character.
_BIG_DELIMS = {"lVert": "\u2016", "rVert": "\u2016", "Vert": "\u2016", "|": "\u2016", "lvert": "|",
               "rvert": "|", "vert": "|", "{": "{", "}": "}", "lbrace": "{", "rbrace": "}",
               "langle": "\u27E8", "rangle": "\u27E9", "lfloor": "\u230A", "rfloor": "\u230B",
               "lceil": "\u2308", "rceil": "\u2309"}
_BIG = re.compile(r"(\\[bB]igg?[lrm]?)\s*\\(" + "|".join(re.escape(k) for k in _BIG_DELIMS) + r")(?![A-Za-z])")
# operator names latex2mathml does not know
_NAMES = ("arg", "sgn")


def preprocess(tex):
    """Rewrite the few constructs latex2mathml misreads into ones it reads right."""
    tex = _BIG.sub(lambda m: m.group(1) + _BIG_DELIMS[m.group(2)], tex)
    tex = re.sub(r"\\(" + "|".join(_NAMES) + r")(?![A-Za-z])", r"\\operatorname{\1}", tex)
    # a control space (backslash, then a space or a line break), but not the row break \\
    tex = re.sub(r"(?<!\\)((?:\\\\)*)\\\s", r"\1\\ ", tex)
    # a matrix whose first cell starts with [ : latex2mathml takes it for an optional argument
    tex = re.sub(r"(\\begin\{[pbvBV]?matrix\})\s*\[", r"\1{}[", tex)
    return _function_spaces(_group_scripted_matrices(tex))


def _group_scripted_matrices(tex):
    """``\\begin{bmatrix}...\\end{bmatrix}_{j}``: braces around the matrix, so that the
    script belongs to the whole matrix (latex2mathml gives it to its closing bracket)."""
    out, i = [], 0
    pattern = re.compile(r"\\begin\{([pbvBV]?matrix)\}")
    while True:
        m = pattern.search(tex, i)
        if not m:
            out.append(tex[i:])
            return "".join(out)
        _, after = _env_end(tex, m.group(1), m.end())
        out.append(tex[i:m.start()])
        if re.match(r"\s*[_^]", tex[after:]):
            out.append("{" + tex[m.start():after] + "}")
        else:
            out.append(tex[m.start():after])
        i = after


_FUNCTIONS = re.compile(r"\\(?:arcsin|arccos|arctan|sinh|cosh|tanh|coth|sin|cos|tan|cot|sec|csc|log|ln|lg|"
                        r"exp|det|dim|ker|deg|gcd|min|max|sup|inf|lim|Pr)(?![A-Za-z])")
_SCRIPT = re.compile(r"\s*[\^_]\s*(\{|\\[A-Za-z]+|.)")
# what may follow a function name with no space between (TeX: an opening, a relation, a
# binary operator, punctuation, a closing, or a space already there)
_NO_SPACE_BEFORE = re.compile(r"\s*(?:$|[()\[\]|,;.=+\-*/<>!&}']|\\(?:[,;:! {}\\]|(?:left|right|[bB]igg?[lr]?|q?quad|"
                              r"lvert|rvert|lVert|rVert|langle|rangle|cdot|times|pm|mp|le|ge|ne|to)(?![A-Za-z]))"
                              r"|\{\s*\\left)")


_ORD_COMMANDS = re.compile(r"\\(alpha|beta|gamma|delta|epsilon|varepsilon|zeta|eta|theta|vartheta|iota|kappa|lambda|"
                           r"mu|nu|xi|pi|varpi|rho|varrho|sigma|varsigma|tau|upsilon|phi|varphi|chi|psi|omega|Gamma|"
                           r"Delta|Theta|Lambda|Xi|Pi|Sigma|Upsilon|Phi|Psi|Omega|ell|infty|partial|prime|hbar|"
                           r"sin|cos|tan|cot|sec|csc|arcsin|arccos|arctan|sinh|cosh|tanh|coth|log|ln|lg|exp|det|dim|"
                           r"ker|deg|gcd|min|max|sup|inf|lim|Pr|right[)\]|.]|rvert|rVert|[bB]igg?r[)\]|])$")


def _space_before(prefix):
    """True when TeX puts a thin space between ``prefix`` and a function name after it:
    after an ordinary symbol or a closing (``X^-\\cos``, ``(a)\\sin``), not after an
    operator, a relation, an opening, punctuation or a space."""
    stripped = prefix.rstrip()
    if not stripped:
        return False
    if re.search(r"[\^_]\s*[^\s{}\\]$", stripped):  # a one-character script: X^-, a_1
        return True
    command = re.search(r"\\[A-Za-z]+\S?$", stripped)
    if command:
        return bool(_ORD_COMMANDS.search(stripped))
    return stripped[-1].isalnum() or stripped[-1] in ")]}'!"


def _function_spaces(tex):
    """A thin space after \\sin, \\cos, ... before an argument without parentheses.

    TeX puts a thin space between a function name and an ordinary symbol (``\\sin x``) but
    none before an opening (``\\sin(x)``); latex2mathml writes the name as a bare ``<mi>``,
    which MathML Core sets with no space at all.
    """
    out, i = [], 0
    for m in _FUNCTIONS.finditer(tex):
        if m.start() < i:
            continue
        before = tex[i:m.start()]
        if _space_before(tex[:m.start()]):
            before += "\\,"
        out.append(before)
        i = m.start()
        end = m.end()
        while True:  # skip the name's sub- and superscripts: \sin^2, \max_{k}
            s = _SCRIPT.match(tex, end)
            if not s:
                break
            end = _matching_brace(tex, s.start(1)) + 1 if s.group(1) == "{" else s.end()
        out.append(tex[i:end])
        if not _NO_SPACE_BEFORE.match(tex, end):
            out.append("\\,")
        i = end
    out.append(tex[i:])
    return "".join(out)


_WORD_OPS = re.compile(r"\\(operatorname\*?|mathrm|rm\b)\s*")


def _to_mathml(tex):
    """MathML (children of ``<math>``) for one formula without tags or wrappers."""
    pieces = {}

    def hold(markup):
        key = PLACEHOLDER.format(len(pieces))
        pieces[key] = markup
        return "\\text{" + key + "}"

    # 1. aligned-like environments, innermost handled by recursion through _table
    out, i = [], 0
    pattern = re.compile(r"\\begin\{(" + "|".join(re.escape(e) for e in ALIGN_ENVS) + r")\}")
    while True:
        m = pattern.search(tex, i)
        if not m:
            out.append(tex[i:])
            break
        name = m.group(1)
        body_start = m.end()
        if name.startswith("alignat"):  # \begin{alignat}{2}
            n = re.match(r"\s*\{\d+\}", tex[body_start:])
            body_start += n.end() if n else 0
        end, after = _env_end(tex, name, body_start)
        out.append(tex[i:m.start()])
        out.append(hold(_table(tex[body_start:end], name)))
        i = after
    tex = "".join(out)

    # 2. upright names: \operatorname{atan2}, \mathrm{i}, {\rm lo}
    out, i = [], 0
    while True:
        m = _WORD_OPS.search(tex, i)
        if not m:
            out.append(tex[i:])
            break
        out.append(tex[i:m.start()])
        if m.group(1) == "rm":
            # {\rm lo}: the rest of the group; only a plain word is supported
            w = re.match(r"([A-Za-z0-9]+)\s*", tex[m.end():])
            if not w:
                raise MathMLError(f"\\rm must be followed by a plain word in {tex!r}")
            name, i = w.group(1), m.end() + w.end()
        else:
            if tex[m.end():m.end() + 1] != "{":
                word = re.match(r"\\?[A-Za-z0-9]", tex[m.end():])  # \mathrm x
                if not word:
                    raise MathMLError(f"\\{m.group(1)} needs an argument in {tex!r}")
                name, i = word.group(0), m.end() + word.end()
            else:
                close = _matching_brace(tex, m.end())
                name, i = tex[m.end() + 1:close].strip(), close + 1
        if re.fullmatch(r"[A-Za-z0-9 ]+", name):
            name = name.replace(" ", "")
            variant = ' mathvariant="normal"' if len(name) == 1 else ""
            markup = f"<mi{variant}>{name}</mi>"
            if m.group(1).startswith("operatorname") and not re.match(r"\s*(\(|\\left|\\[bB]igg?l?\(|\\[bB]igg?l|\[|\\\{|[_^])", tex[i:]):
                markup += '<mspace width="0.167em"/>'  # a thin space before an argument without parentheses
            out.append(hold(markup))
        else:  # \mathrm{\Delta x} and the like: upright through latex2mathml
            inner = _repair_fragment(_convert(name), upright=True)
            out.append(hold(f"<mrow>{inner}</mrow>"))
    tex = "".join(out)

    markup = _convert(tex)
    for key, value in pieces.items():
        markup = markup.replace(f"<mtext>{key}</mtext>", value)
        if key in markup:
            raise MathMLError(f"could not place a converted part back into {tex!r}")
    return markup


def _repair_fragment(markup, upright=False):
    """Mark single-letter identifiers of ``markup`` upright (for \\mathrm of an expression)."""
    if upright:
        markup = re.sub(r"<mi>([^<]{1})</mi>", r'<mi mathvariant="normal">\1</mi>', markup)
    return markup


def tex_to_mathml(tex, display=False):
    """``(mathml, tag)``: a ``<math>`` element for the LaTeX ``tex`` and its ``\\tag`` or None.

    Raises :class:`MathMLError` for anything that does not convert cleanly.
    """
    tex = tex.strip()
    if tex.startswith("$") and tex.endswith("$"):
        tex = tex.strip("$").strip()
    _check_braces(tex)
    tex, tag = extract_tag(preprocess(tex))
    if tag is not None and not display:
        raise MathMLError(f"\\tag in inline math: {tex!r}")
    m = re.fullmatch(r"\\begin\{(" + "|".join(re.escape(e) for e in WRAPPER_ENVS) + r")\}(.*)\\end\{\1\}",
                     tex.strip(), re.S)
    if m:
        tex = m.group(2).strip()
    if not tex:
        raise MathMLError("an empty formula")
    if display:  # a formula wider than the column: aligned rows (math_breaks.py, issue 26)
        tex = break_long(tex)
    parts = [p for p in re.split(r"\n\s*\n", tex) if p.strip()] if display else [tex]
    if display and (len(parts) > 1 or len(split_top(tex, "\\\\")) > 1 or len(split_top(tex, "&")) > 1):
        # rows without an environment (Sphinx wraps them in split): an aligned table
        body = _table("\\\\".join(parts), "split")
    else:
        body = _to_mathml(tex)
    attrs = f'xmlns="{MATHML_NS}"' + (' display="block"' if display else "")
    mathml = f"<math {attrs}>{body}</math>"
    try:
        tree = ET.fromstring(mathml)
    except ET.ParseError as exc:
        raise MathMLError(f"malformed MathML for {tex!r}: {exc}") from exc
    _repair(tree)
    _spacing(tree)
    ET.register_namespace("", MATHML_NS)
    text = ET.tostring(tree, encoding="unicode", short_empty_elements=True)
    # ElementTree writes the namespace once on the root; HTML needs no prefix anywhere.
    text = text.replace("<ns0:", "<").replace("</ns0:", "</")
    return text, tag


# ---------------------------------------------------------------- Sphinx

def _fail(self, node, exc):
    source = node.source or self.builder.current_docname
    raise MathMLError(f"{source}:{node.line or '?'}: {exc}") from exc


def html_visit_math(self, node):
    try:
        mathml, _ = tex_to_mathml(node.astext(), display=False)
    except MathMLError as exc:
        _fail(self, node, exc)
    # a long inline formula may scroll in its own box on a phone instead of widening the page
    long = " mech-long" if math_width(node.astext()) > LONG_INLINE_EM else ""
    self.body.append(self.starttag(node, "span", "", CLASS="math notranslate nohighlight" + long))
    self.body.append(mathml + "</span>")
    raise nodes.SkipNode


def html_visit_displaymath(self, node):
    from sphinx.locale import _
    from sphinx.util.math import get_node_equation_number

    try:
        mathml, tag = tex_to_mathml(node.astext(), display=True)
    except MathMLError as exc:
        _fail(self, node, exc)
    self.body.append(self.starttag(node, "div", CLASS="math notranslate nohighlight"))
    if node.get("number"):
        number = get_node_equation_number(self, node)
        self.body.append(f'<span class="eqno">({number})')
        self.add_permalink_ref(node, _("Link to this equation"))
        self.body.append("</span>")
    elif tag is not None:
        self.body.append(f'<span class="eqno">({self.encode(tag)})</span>')
    self.body.append(mathml + "</div>\n")
    raise nodes.SkipNode


def write_css(app, exception):
    if exception is None and app.builder.format == "html":
        source = Path(__file__).with_name(CSS)
        target = Path(app.outdir, "_static", CSS)
        target.write_text(source.read_text(encoding="utf-8"), encoding="utf-8")


def setup(app):
    app.add_html_math_renderer("mathml", (html_visit_math, None), (html_visit_displaymath, None))
    app.add_css_file(CSS)
    app.connect("build-finished", write_css)
    return {"parallel_read_safe": True, "parallel_write_safe": True, "version": "1"}
