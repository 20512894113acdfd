"""Fail if the built HTML loads any file from outside the build, or loads MathJax at all.

Usage: python book/_check_offline.py book/_build/html
Links (<a href>) may point anywhere; what a browser fetches by itself (scripts, styles,
images, fonts, iframes) must be local. The math is MathML written at build time
(book/_ext/mathml.py): no page may load MathJax, and every ``.math`` element holds ``<math>``.
"""

import re
import sys
from pathlib import Path

FETCHED = re.compile(
    r"<(?:script|img|iframe|source|audio|video)\b[^>]*\bsrc=[\"']([^\"']+)[\"']"
    r"|<link\b[^>]*\bhref=[\"']([^\"']+)[\"'][^>]*>",
    re.I,
)
REMOTE = re.compile(r"^(?:https?:)?//", re.I)


def main(root):
    root = Path(root)
    pages = sorted(root.rglob("*.html"))
    if not pages:
        sys.exit(f"no HTML under {root}")
    problems = []
    formulas = 0
    for page in pages:
        text = page.read_text(encoding="utf-8", errors="replace")
        if re.search(r"<script\b[^>]*mathjax", text, re.I):
            problems.append(f"{page.relative_to(root)}: loads MathJax (the math must be MathML)")
        spans = len(re.findall(r'class="math notranslate', text))
        maths = len(re.findall(r"<math\b", text))
        if maths < spans:
            problems.append(f"{page.relative_to(root)}: {spans - maths} formulas without MathML")
        formulas += maths
        for m in FETCHED.finditer(text):
            url = m.group(1) or m.group(2)
            tag = m.group(0)
            if m.group(2) and not re.search(r"rel=[\"'](?:stylesheet|preload|icon|shortcut icon|modulepreload)", tag, re.I):
                continue
            if REMOTE.match(url):
                problems.append(f"{page.relative_to(root)}: loads {url}")
    for css in root.rglob("*.css"):
        for url in re.findall(r"@import\s+(?:url\()?[\"']?((?:https?:)?//[^\"')]+)", css.read_text(errors="replace")):
            problems.append(f"{css.relative_to(root)}: imports {url}")
    if problems:
        print("\n".join(problems))
        sys.exit(f"{len(problems)} problem(s): the book must not fetch anything from outside the build")
    print(f"offline check: {len(pages)} pages, no remote fetches, {formulas} formulas as MathML, no MathJax")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "book/_build/html")
