"""Break a long display formula into aligned rows before it becomes MathML (issue 26).

Browsers do not break MathML lines, so a long SymPy result or a long hand-written equation
is one line that scrolls sideways in its column. :func:`break_long` estimates the width of
a display formula from its LaTeX (in em of the math font) and, when it is wider than the
column, rewrites it as an ``aligned`` environment:

- a relation chain ``a = b + c + ... = d`` is cut at its top-level relations (one row each),
  and a row still too wide at its top-level ``+`` and ``-`` (the continuation rows are
  indented under the right-hand side);
- a matrix whose cells are too wide together has each long cell broken the same way inside
  the cell, so the matrix keeps its shape and narrows by column.

Only what sits at the top level of the formula (outside braces, ``\\left ... \\right``
pairs and environments) is cut, so no parenthesis, fraction or root is ever split. A
formula that is already aligned (``&`` or ``\\\\`` at its top level) is left alone.
The estimate is deliberately rough (letters 0.55 em, a binary operator with its spaces
1.3 em, a fraction the wider of its parts, scripts at 70 %); the browser test measures what
really fits.
"""

import re

# The column at 1280 px is 676 px; the math font is 1.25 x 16 px = 20 px per em, so about
# 34 em. Rows are packed to LIMIT, a little under it, because the estimate is rough.
LIMIT = 29.0
MIN_CELL = 9.0  # em: a matrix cell is never broken narrower than this

_RELATIONS = ("=", "<", ">", "\\le", "\\ge", "\\leq", "\\geq", "\\ne", "\\neq", "\\approx", "\\equiv",
              "\\to", "\\Rightarrow", "\\iff")
_WIDE_CMDS = {"quad": 1.0, "qquad": 2.0, ",": 0.17, ":": 0.22, ";": 0.28, "!": -0.17, " ": 0.33,
              "cdot": 0.8, "times": 0.9, "pm": 1.3, "mp": 1.3, "left": 0.0, "right": 0.0,
              "displaystyle": 0.0, "textstyle": 0.0, "limits": 0.0, "nolimits": 0.0,
              "sum": 1.4, "prod": 1.4, "int": 0.8, "infty": 1.0, "cdots": 1.5, "ldots": 1.5, "dots": 1.5}
_FUNC_CMDS = {"sin", "cos", "tan", "cot", "sec", "csc", "arcsin", "arccos", "arctan", "atan", "sinh", "cosh",
              "tanh", "log", "ln", "exp", "det", "min", "max", "lim", "sqrt", "operatorname", "mathrm", "text",
              "mathbf", "boldsymbol", "mathit", "mathcal", "frac", "dfrac", "tfrac", "overline", "hat", "bar",
              "vec", "dot", "ddot", "tilde", "operatorname*", "begin", "end", "big", "Big", "bigg", "Bigg",
              "bigl", "bigr", "Bigl", "Bigr", "biggl", "biggr", "Biggl", "Biggr"}


def _group(tex, i):
    """(content, index after) of the argument at ``i``: a ``{...}`` group, a command or a character."""
    while i < len(tex) and tex[i].isspace():
        i += 1
    if i >= len(tex):
        return "", i
    if tex[i] == "{":
        depth, j = 0, i
        while j < len(tex):
            c = tex[j]
            if c == "\\":
                j += 2
                continue
            depth += {"{": 1, "}": -1}.get(c, 0)
            if depth == 0:
                return tex[i + 1:j], j + 1
            j += 1
        return tex[i + 1:], len(tex)
    if tex[i] == "\\":
        m = re.match(r"\\([A-Za-z]+|[\s\S])", tex[i:])
        if m is None:
            return "", len(tex)
        return m.group(0), i + m.end()
    return tex[i], i + 1


def width(tex):
    """Estimated width of ``tex`` in em (of the math font)."""
    total, i = 0.0, 0
    while i < len(tex):
        c = tex[i]
        if c.isspace() or c in "{}&":
            i += 1
            continue
        if c in "^_":
            arg, i = _group(tex, i + 1)
            total += 0.7 * width(arg)
            continue
        if c == "\\":
            m = re.match(r"\\([A-Za-z]+\*?|[\s\S])", tex[i:])
            if m is None:  # a lone backslash at the end
                break
            name = m.group(1)
            i += m.end()
            if name in ("frac", "dfrac", "tfrac", "binom"):
                a, i = _group(tex, i)
                b, i = _group(tex, i)
                total += max(width(a), width(b)) + 0.4
            elif name == "sqrt":
                if tex[i:i + 1] == "[":
                    i = tex.index("]", i) + 1
                a, i = _group(tex, i)
                total += width(a) + 1.0
            elif name in ("text", "mathrm", "operatorname", "operatorname*", "textrm", "mbox"):
                a, i = _group(tex, i)
                total += 0.5 * len(re.sub(r"\\[A-Za-z]+|[{}]", "", a)) + (0.3 if name.startswith("op") else 0)
            elif name in ("mathbf", "boldsymbol", "mathit", "mathcal", "hat", "bar", "vec", "dot", "ddot",
                          "tilde", "overline", "widehat", "mathbb"):
                a, i = _group(tex, i)
                total += width(a)
            elif name in ("begin", "end"):
                env, i = _group(tex, i)
                if name == "begin" and env in ("matrix", "bmatrix", "pmatrix", "aligned", "array", "cases"):
                    from_, to = i, _env_close(tex, env, i)
                    total += _matrix_width(tex[from_:to]) + 0.8
                    i = to + len(f"\\end{{{env}}}")
            elif name in _WIDE_CMDS:
                total += _WIDE_CMDS[name]
            elif name in _FUNC_CMDS:
                total += 0.5 * len(name) + 0.2
            elif name in ("left", "right"):
                continue
            elif name in [r[1:] for r in _RELATIONS if r.startswith("\\")]:
                total += 1.6
            elif len(name) == 1:  # \{ \| \, ...
                total += 0.4
            else:  # a Greek letter or a symbol
                total += 0.6
            continue
        if c in "+-":
            total += 1.3
        elif c in "=<>":
            total += 1.6
        elif c in "()[]|":
            total += 0.4
        elif c in ",;":
            total += 0.45
        elif c.isdigit() or c == ".":
            total += 0.5
        else:
            total += 0.55
        i += 1
    return total


def _matrix_width(body):
    """Width of a matrix (or aligned) body: the sum of its widest cell in each column."""
    rows = [r for r in split_rows(body) if r.strip()]
    cells = [[piece for _, piece in _split_top(r, r"&")] for r in rows]
    if not cells:
        return 0.0
    ncols = max(len(r) for r in cells)
    return sum(max(width(r[k]) if k < len(r) else 0.0 for r in cells) + 1.0 for k in range(ncols))


def split_rows(body):
    """The rows of an environment body, split at its top-level ``\\\\``."""
    return [piece for _, piece in _split_top(body, r"\\\\")]


def _env_close(tex, env, start):
    """Index of the ``\\end{env}`` that closes the environment whose body starts at ``start``."""
    depth = 1
    for m in re.finditer(r"\\(begin|end)\{" + re.escape(env) + r"\}", tex[start:]):
        depth += 1 if m.group(1) == "begin" else -1
        if depth == 0:
            return start + m.start()
    return len(tex)


def _split_top(tex, seps):
    """Split ``tex`` at top-level occurrences of ``seps`` (regex). Returns [(sep, piece), ...]
    where the first sep is ''. Top level: outside braces, \\left..\\right and environments."""
    parts, depth, last, last_sep, i = [], 0, 0, "", 0
    pattern = re.compile(seps)
    while i < len(tex):
        c = tex[i]
        if c == "\\":
            m = re.match(r"\\(left|right|begin|end)(?![A-Za-z])", tex[i:])
            if m:
                depth += 1 if m.group(1) in ("left", "begin") else -1
                i += m.end()
                if m.group(1) in ("begin", "end"):
                    _, i = _group(tex, i)
                elif i < len(tex):  # the delimiter after \left or \right
                    i += 2 if tex[i] == "\\" else 1
                continue
        if c in "{":
            depth += 1
        elif c == "}":
            depth -= 1
        if depth == 0:
            m = pattern.match(tex, i)
            if m and m.group(0):
                parts.append((last_sep, tex[last:i]))
                last_sep, last = m.group(0), m.end()
                i = m.end()
                continue
        if c == "\\":
            m = re.match(r"\\([A-Za-z]+|[\s\S])", tex[i:])
            i += m.end() if m else 1
            continue
        i += 1
    parts.append((last_sep, tex[last:]))
    return parts


_REL_RE = r"(?:=|<|>|\\(?:leq?|geq?|neq?|approx|equiv|to|Rightarrow|iff)(?![A-Za-z]))"


def _terms(tex):
    """Top-level terms of a sum: [(sign, term)], binary + and - only (a sign after nothing
    or after another operator belongs to its term)."""
    raw = _split_top(tex, r"[+-]")
    terms = []
    for sep, piece in raw:
        if terms and not piece.strip() and sep:
            # "a + -b": the minus is unary, glue it to the next piece
            terms[-1] = (terms[-1][0], terms[-1][1] + sep)
            continue
        if terms and (not terms[-1][1].strip() or re.search(r"(\\cdot|\\times|[*/(,^_])\s*$", terms[-1][1])):
            terms[-1] = (terms[-1][0], terms[-1][1] + sep + piece)
            continue
        terms.append((sep, piece))
    if terms and not terms[0][1].strip() and len(terms) > 1:  # a leading sign
        sign = terms[1][0]
        terms = [(sign, terms[1][1])] + terms[2:]
    return terms


def _pack(terms, limit):
    """Rows of terms, each at most ``limit`` em wide (a term wider than that is a row alone)."""
    rows, row, w = [], "", 0.0
    for sign, term in terms:
        piece = (f" {sign} " if sign else "") + term.strip()
        pw = width(piece)
        if row and w + pw > limit:
            rows.append(row)
            row, w = piece, pw
        else:
            row, w = row + piece, w + pw
    if row:
        rows.append(row)
    return rows


def _unwrap_groups(tex):
    """``{\\left( ... \\right)}`` -> ``\\left( ... \\right)``: SymPy's braces around a
    function's arguments only group them."""
    out, i = [], 0
    while True:
        j = tex.find("{\\left(", i)
        if j < 0:
            out.append(tex[i:])
            return "".join(out)
        depth, k, close = 0, j + 1, None
        for m in re.finditer(r"\\(left|right)(?![A-Za-z])", tex[j + 1:]):
            depth += 1 if m.group(1) == "left" else -1
            if depth == 0:
                close = j + 1 + m.end()
                break
        end = None
        if close is not None:
            k = close + 1 if tex[close:close + 1] in ")]." else close
            if tex[k:k + 1] == "}":
                end = k
        if end is None:
            out.append(tex[i:j + 1])
            i = j + 1
            continue
        out.append(tex[i:j] + tex[j + 1:end])
        i = end + 1


def _widest_group(tex):
    """(start, end) of the top-level ``\\left( ... \\right)`` group whose inside is widest, or None."""
    best, depth, start, brace = None, 0, None, 0
    i = 0
    while i < len(tex):
        c = tex[i]
        if c == "\\":
            m = re.match(r"\\(left|right)(?![A-Za-z])", tex[i:])
            if m:
                if m.group(1) == "left":
                    if depth == 0 and brace == 0 and tex[i + m.end():i + m.end() + 1] == "(":
                        start = i
                    depth += 1
                else:
                    depth -= 1
                    if depth == 0 and start is not None and tex[i + m.end():i + m.end() + 1] == ")":
                        w = width(tex[start + 6:i])
                        if best is None or w > best[2]:
                            best = (start, i + m.end() + 1, w)
                        start = None
                i += m.end() + 1
                continue
            i += 2
            continue
        brace += {"{": 1, "}": -1}.get(c, 0)
        i += 1
    return best


def _break_paren(tex, limit, depth=0):
    """Rows of ``prefix \\left( inside \\right) suffix`` with the inside broken (at its
    commas, else at its + and -), or None when no group holds most of the width."""
    tex = _unwrap_groups(tex)
    group = _widest_group(tex)
    if group is None or group[2] < 0.5 * width(tex):
        return None
    start, end, _ = group
    prefix, inside, suffix = tex[:start], tex[start + 6:end - 7], tex[end:]
    items = [piece.strip() for _, piece in _split_top(inside, r",(?:\s*\\ )?")]
    if len(items) > 1:
        pieces = [(item if width(item) <= limit - 3 else break_long(item, limit - 3))
                  + ("," if k < len(items) - 1 else "") for k, item in enumerate(items)]
    else:
        pieces = _pack(_terms(inside), limit - 3)
        if len(pieces) <= 1:  # a product of parenthesised factors: one factor group per row
            factors = [("", f) for _, f in _split_top(inside, _FACTOR)]
            pieces = _pack(factors, limit - 3)
            pieces = [pieces[0]] + ["\\times " + p for p in pieces[1:]]
    if len(pieces) <= 1:
        return None
    if depth < 3:  # a piece still too wide: break inside its own parentheses
        deeper = []
        for piece in pieces:
            rows_of = _break_paren(piece, limit - 2, depth + 1) if width(piece) > limit + 3 else None
            deeper.extend(rows_of or [piece])
        pieces = deeper
    rows = [prefix + "\\Bigl(" + pieces[0]] + ["\\quad " + p for p in pieces[1:]]
    rows[-1] += "\\Bigr)" + suffix
    return rows


def _break_expression(tex, limit):
    """Rows (LaTeX, for the right column of ``aligned``) of an expression too wide."""
    terms = _terms(tex)
    rows = _pack(terms, limit) if len(terms) > 1 else [tex]
    out = []
    for row in rows:
        broken = _break_paren(row, limit) if width(row) > limit + 3 else None
        if broken is None and width(row) > limit + 3:
            broken = _break_product(row, limit)
        if broken is None and width(row) > limit + 3:
            broken = _break_fraction(row, limit)
        out.extend(broken or [row])
    return out


def _break_fraction(tex, limit):
    """``sign \\frac{N}{D}`` with a wide numerator as ``sign \\frac{1}{D}\\Bigl(N\\Bigr)``,
    the numerator in rows; None for anything else."""
    m = re.match(r"\s*([+-]?)\s*\\frac\s*\{", tex)
    if not m:
        return None
    num, i = _group(tex, m.end() - 1)
    den, j = _group(tex, i)
    if tex[j:].strip() or width(num) <= limit:
        return None
    pieces = _break_expression(num, limit - 4)
    if len(pieces) <= 1:
        return None
    rows = [f"{m.group(1)}\\frac{{1}}{{{den}}}\\Bigl(" + pieces[0]] + ["\\quad " + p for p in pieces[1:]]
    rows[-1] += "\\Bigr)"
    return rows


_FACTOR = r"(?<=\\right\))\s+(?=\\left\()"


def _break_product(tex, limit):
    """Rows of a product of parenthesised factors, each factor group broken further if
    needed, or None when it has a single factor."""
    tex = _unwrap_groups(tex)
    factors = [f for _, f in _split_top(tex, _FACTOR)]
    if len(factors) <= 1:
        return None
    rows = _pack([("", f) for f in factors], limit - 2)
    out = []
    for k, row in enumerate(rows):
        parts = (_break_paren(row, limit - 2, 1) if width(row) > limit + 3 else None) or [row]
        if k:
            parts[0] = "\\times " + parts[0]
        out.extend(parts)
    return out


def _break_matrix(tex, limit):
    """A matrix environment whose long cells are broken into rows inside the cells."""
    m = re.search(r"\\begin\{([pbvBV]?matrix)\}", tex)
    if not m:
        return tex
    env = m.group(1)
    start = m.end()
    end = _env_close(tex, env, start)
    body = tex[start:end]
    if "\\begin{matrix}" in body or "\\begin{aligned}" in body:
        return tex
    rows = [r for r in split_rows(body) if r.strip()]
    cells = [[piece for _, piece in _split_top(r, r"&")] for r in rows]
    ncols = max(len(r) for r in cells)
    col_w = [max(width(r[k]) if k < len(r) else 0 for r in cells) for k in range(ncols)]
    if sum(col_w) + 1.2 * ncols <= limit:
        return tex
    cell_limit = max(MIN_CELL, limit / ncols - 1.2)
    new_rows = []
    for row in cells:
        new_cells = []
        for cell in row:
            if width(cell) > cell_limit:
                parts = _break_expression(cell.strip(), cell_limit)
                if len(parts) > 1:
                    cell = ("\\begin{aligned}{}&" + " \\\\ {}&\\quad ".join(parts) + "\\end{aligned}")
            new_cells.append(cell)
        new_rows.append(" & ".join(new_cells))
    return tex[:start] + " \\\\ ".join(new_rows) + tex[end:]


def _tuple_items(body):
    """The items of ``body`` when it is one tuple ``\\left( a, \\  b\\right)``, else None."""
    body = body.strip()
    if not (body.startswith("\\left(") and body.endswith("\\right)")):
        return None
    depth, i = 0, 0
    for m in re.finditer(r"\\(left|right)(?![A-Za-z])", body):
        depth += 1 if m.group(1) == "left" else -1
        if depth == 0 and m.end() + 1 < len(body):
            return None  # the first \left( closes before the end: not one tuple
    inside = body[len("\\left("):-len("\\right)")]
    items = [piece.strip() for _, piece in _split_top(inside, r",(?:\s*\\ )?")]
    return [item for item in items if item]


def break_long(tex, limit=LIMIT):
    """``tex`` itself when it fits in ``limit`` em, else the same formula in aligned rows."""
    body = tex.strip()
    if width(body) <= limit:
        return tex
    if len(_split_top(body, r"&|\\\\")) > 1 or "\\tag" in body:
        return tex
    if re.search(r"\\begin\{(aligned|align\*?|split|gather\*?|cases|array)\}", body):
        return tex
    display = ""
    if body.startswith("\\displaystyle"):
        display, body = "\\displaystyle ", body[len("\\displaystyle"):].strip()
    # a tuple (SymPy prints several results of a cell as one): a few items per row
    inner = _tuple_items(body)
    if inner is not None and len(inner) > 1:
        items = [break_long(item, limit - 2.0) if width(item) > limit - 2.0 else item for item in inner]
        rows, row = [], []
        for item in items:
            if row and width(",\\quad ".join(row + [item])) + 2.0 > limit:
                rows.append(row)
                row = [item]
            else:
                row.append(item)
        rows.append(row)
        if len(rows) > 1:
            lines = [",\\quad ".join(r) for r in rows]
            lines = [("\\Bigl(\\, " if k == 0 else "\\quad ") + line + ("," if k < len(lines) - 1 else "\\,\\Bigr)")
                     for k, line in enumerate(lines)]
            return display + "\\begin{aligned}" + " \\\\ ".join("{}& " + line for line in lines) + "\\end{aligned}"
    # a list of equations side by side ("a = b,\\qquad c = d"): one group of them per row
    pieces = _split_top(body, r",\s*\\q?quad(?![A-Za-z])|\\qquad(?![A-Za-z])")
    if len(pieces) > 1:
        items = [(piece.strip() + ("," if k < len(pieces) - 1 and sep_next.startswith(",") else ""))
                 for k, ((_, piece), (sep_next, _)) in enumerate(zip(pieces, pieces[1:] + [("", "")]))]
        items = [break_long(item, limit) if width(item) > limit else item for item in items]
        rows, row = [], ""
        for item in items:
            if row and width(row) + width(item) + 2.0 > limit:
                rows.append(row)
                row = item
            else:
                row = f"{row}\\quad {item}" if row else item
        rows.append(row)
        if len(rows) > 1:
            return display + "\\begin{aligned}" + " \\\\ ".join("{}& " + r for r in rows) + "\\end{aligned}"
    sides = _split_top(body, _REL_RE)
    if re.search(r"\\begin\{[pbvBV]?matrix\}", body):
        # break the matrices' cells; each side keeps its place
        out = "".join((f" {sep} " if sep else "") + _break_matrix(side, limit) for sep, side in sides)
        if width(out) <= width(body):
            return display + out
        return tex
    lhs = sides[0][1].strip() if len(sides) > 1 else ""
    rows = []  # (left column, relation, right column)
    chain = sides[1:] if len(sides) > 1 else [("", body)]
    if lhs and width(lhs) > 10.0:
        # a wide left-hand side (a long sum "= 0"): one column, the left side in rows first
        chain = [("", lhs)] + chain
        lhs = ""
    indent = (min(width(lhs), 8.0) if lhs else 0.0) + 2.0
    for sep, side in chain:
        side_rows = _break_expression(side.strip(), limit - indent)
        for k, row in enumerate(side_rows):
            rows.append((sep, row) if k == 0 else ("", "\\quad " + row))
    if len(rows) <= 1:
        return tex
    lines = []
    for k, (sep, row) in enumerate(rows):
        left = lhs if (k == 0 and lhs) else "{}"
        lines.append(f"{left} &{(' ' + sep + ' ') if sep else ' '}{row}")
    return display + "\\begin{aligned}" + " \\\\ ".join(lines) + "\\end{aligned}"
