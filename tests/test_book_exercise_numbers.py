"""Exercise boxes carry the textbook's numbers (issue 26): ``book/_ext/textbook_numbers.py``.

A small Sphinx project with sphinx-exercise and the extension is built, and every exercise
of the book is checked to be written so that the extension titles it.
"""

import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BOOK = ROOT / "book"
sys.path.insert(0, str(BOOK / "_ext"))

import textbook_numbers  # noqa: E402


def test_title_from_label():
    assert textbook_numbers.textbook_title("ex-2-19") == "Exercise 2-19"
    assert textbook_numbers.textbook_title("ex-3-4") == "Exercise 3-4"
    assert textbook_numbers.textbook_title("sol-2-19") is None
    assert textbook_numbers.textbook_title(None) is None


def _exercises():
    """(page, label, options) of every exercise directive of the book."""
    found = []
    for page in sorted(BOOK.rglob("*.md")):
        if "_build" in page.parts:
            continue
        lines = page.read_text(encoding="utf-8").splitlines()
        for i, line in enumerate(lines):
            if re.match(r"^(`{3,}|:{3,})\{exercise\}", line):
                options = []
                for opt in lines[i + 1:]:
                    if not opt.startswith(":"):
                        break
                    options.append(opt)
                label = next((o.split(":", 2)[2].strip() for o in options if o.startswith(":label:")), None)
                found.append((page.relative_to(BOOK).as_posix(), label, options))
    return found


def test_every_exercise_is_titled_with_the_textbook_number():
    exercises = _exercises()
    assert len(exercises) >= 29
    bad = [(page, label) for page, label, options in exercises
           if textbook_numbers.textbook_title(label) is None or ":nonumber:" not in options]
    assert bad == []
    labels = [label for _, label, _ in exercises]
    assert len(labels) == len(set(labels))


def test_sphinx_build_titles_boxes(tmp_path):
    pytest.importorskip("sphinx_exercise")
    from sphinx.application import Sphinx

    src = tmp_path / "src"
    src.mkdir()
    (src / "conf.py").write_text(
        "import sys\n"
        f"sys.path.insert(0, {str(BOOK / '_ext')!r})\n"
        "extensions = ['sphinx_exercise', 'textbook_numbers']\n"
        "numfig = True\n", encoding="utf-8")
    (src / "index.rst").write_text(
        "Page\n====\n\n"
        ".. exercise::\n   :label: ex-2-19\n   :nonumber:\n\n   A wedge.\n\n"
        ".. exercise::\n   :label: other\n   :nonumber:\n\n   Something else.\n", encoding="utf-8")
    out = tmp_path / "out"
    app = Sphinx(str(src), str(src), str(out), str(tmp_path / "doctrees"), "html",
                 status=None, warning=None, freshenv=True)
    app.build()
    html = (out / "index.html").read_text(encoding="utf-8")
    titles = re.findall(r'<p class="admonition-title">(.*?)</p>', html, re.S)
    text = [re.sub(r"<[^>]+>", "", t).strip() for t in titles]
    assert "Exercise 2-19" in text, text
    assert "Exercise" in text, text  # a label of another form keeps the extension's title
    assert not any(re.fullmatch(r"Exercise \d+", t) for t in text), text
