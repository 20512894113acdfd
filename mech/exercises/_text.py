"""Plain text from the exercises' Markdown: for a terminal (``show``, ``variant``) and for
the PDF sheets. Bold and code marks are dropped, headings underlined, and the LaTeX between
dollars is spelt in Unicode (``\\gamma_{min}`` -> ``γ_min``, ``\\frac{a}{b}`` -> ``(a)/(b)``).
Only the standard library is used.
"""

from __future__ import annotations

import re

__all__ = ["latex_to_text", "markdown_to_text"]

_LATEX_SYMBOLS = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "varepsilon": "ε", "epsilon": "ε", "eta": "η",
    "theta": "θ", "vartheta": "θ", "lambda": "λ", "mu": "μ", "pi": "π", "rho": "ρ", "sigma": "σ", "tau": "τ",
    "varphi": "φ", "phi": "φ", "psi": "ψ", "omega": "ω", "Delta": "Δ", "Omega": "Ω", "Sigma": "Σ",
    "cdot": "·", "times": "×", "le": "≤", "leq": "≤", "ge": "≥", "geq": "≥", "ne": "≠", "neq": "≠",
    "approx": "≈", "pm": "±", "circ": "°", "infty": "∞", "to": "→", "rightarrow": "→", "sqrt": "√",
    "deg": "°", "quad": " ", "qquad": "  ", ",": " ", ";": " ", "!": "", "left": "", "right": "",
    "sin": "sin", "cos": "cos", "tan": "tan", "arctan": "arctan", "arccos": "arccos", "arcsin": "arcsin",
    "atan": "atan", "min": "min", "max": "max", "ln": "ln", "exp": "exp", "cup": "∪", "in": "∈",
    "lvert": "|", "rvert": "|", "mid": "|", "ldots": "...", "dots": "...", "operatorname": "",
}


def latex_to_text(tex):
    """Spell a LaTeX formula in Unicode plain text (the few commands the solutions use).

    >>> latex_to_text(r"\\gamma_{min} = \\frac{a}{b} \\cdot 2^{3}")
    'γ_min = (a)/(b) · 2^3'
    """
    s = tex
    for _ in range(3):                                   # nested fractions
        s = re.sub(r"\\[dt]?frac\s*\{([^{}]*)\}\s*\{([^{}]*)\}", r"(\1)/(\2)", s)
    s = re.sub(r"\\(?:mathrm|text|mathit|mathbf|operatorname|textrm)\s*\{([^{}]*)\}", r"\1", s)
    s = re.sub(r"\\sqrt\s*\{([^{}]*)\}", r"√(\1)", s)
    s = re.sub(r"\\([A-Za-z]+|[,;!])(?=(.?))", lambda m: _LATEX_SYMBOLS.get(m.group(1), m.group(1))
               + (" " if (m.group(2).isalnum() or m.group(2) == "\\") and m.group(1).isalpha() else ""), s)
    s = re.sub(r"([_^])\{([^{}]*)\}", r"\1\2", s)
    s = s.replace("{", "").replace("}", "").replace("~", " ")
    return re.sub(r"[ \t]+", " ", s).strip()


def markdown_to_text(md):
    """The exercises' Markdown as plain text for a terminal or a PDF."""
    out = []
    for line in md.splitlines():
        line = re.sub(r"\$\$?([^$]+)\$\$?", lambda m: latex_to_text(m.group(1)), line)
        bold = re.fullmatch(r"\*\*([^*]+)\*\*", line.strip())
        line = line.replace("**", "").replace("`", "")
        if bold:                                         # a bold line is a part's heading
            out += [line.strip(), "-" * min(len(line.strip()), 78)]
            continue
        m = re.match(r"(#+)\s+(.*)", line)
        if m:
            text = m.group(2)
            out += [text, ("=" if len(m.group(1)) <= 2 else "-") * min(len(text), 78)]
            continue
        if re.fullmatch(r"\|?\s*-{3,}.*", line):
            continue                                      # a table's rule line
        if line.startswith("|"):
            line = "  ".join(c.strip() for c in line.strip().strip("|").split("|"))
        out.append(line)
    return "\n".join(out).rstrip() + "\n"
