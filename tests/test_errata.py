"""The errata page (book/errata.md) against the list of errata and the test suite.

Every row of sections 1, 2, 3 and 5 of the chapter (and of the spherical monograph) must
name at least one test that exists; every erratum found in these sections must have a
row. The wording-only corrections, which no computation can tell apart, are checked where
the book states them.
"""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
ERRATA = ROOT / "book" / "errata.md"

#: Errata found when the text was read (A*: sections 1 and 2, B*: section 3, C*: sections 4
#: and 5) -> the row of the errata page that corrects each.
#: Section 4 (synthesis: B17-B31, C1-C15) is listed in rows 46-74 and is not mapped here.
CATALOG_TO_ROW = {
    "A1": 75, "A2": 1, "A3": 2, "A4": 3, "A5": 4, "A6": 18, "A7": 5, "A8": 76, "A9": 15,
    "A10": 77, "A11": 78, "A12": 8, "A13": 9, "A14": 19, "A15": 20, "A16": 22, "A17": 21,
    "A18": 21, "A19": 24, "A20": 24, "A21": 6, "A22": 11, "A23": 10, "A24": 12, "A25": 12,
    "A26": 13, "A27": 14, "A28": 14, "A29": 17, "A30": 16, "A31": 79,
    "B1": 80, "B2": 81, "B3": 32, "B4": 33, "B5": 34, "B6": 35, "B7": 36, "B8": 37, "B9": 38,
    "B10": 39, "B11": 40, "B12": 82, "B13": 83, "B14": 41, "B15": 42, "B16": 43,
    "C16": 26, "C17": 27, "C18": 28, "C19": 25, "C20": 31, "C21": 84,
}
SYNTHESIS_ROWS = range(46, 75)


def _rows():
    """Errata rows as {number: text of the whole table row}."""
    rows = {}
    for line in ERRATA.read_text(encoding="utf-8").splitlines():
        m = re.match(r"^\| (\d+) \|", line)
        if m:
            number = int(m.group(1))
            assert number not in rows, f"row {number} appears twice"
            rows[number] = line
    return rows


def _test_names():
    names = set()
    for path in (ROOT / "tests").rglob("test_*.py"):
        names.update(re.findall(r"^def (test_\w+)", path.read_text(encoding="utf-8"), re.M))
    return names


def _text(relative):
    return " ".join((ROOT / relative).read_text(encoding="utf-8").split())


def test_errata_rows_name_existing_tests():
    rows, names = _rows(), _test_names()
    assert len(rows) >= 84
    for number, line in rows.items():
        named = re.findall(r"`(test_\w+)`", line)
        assert named, f"Expected errata row {number} to name a test, got none: {line[:80]}"
        missing = [n for n in named if n not in names]
        assert not missing, f"Expected the tests named by errata row {number} to exist, got {missing}"


def test_catalog_errata_of_sections_1_2_3_5_have_rows():
    rows = _rows()
    for erratum, number in CATALOG_TO_ROW.items():
        assert number in rows, f"Expected erratum {erratum} on errata row {number}"
        assert number not in SYNTHESIS_ROWS
    assert len([k for k in CATALOG_TO_ROW if k.startswith("A")]) == 31
    assert len([k for k in CATALOG_TO_ROW if k.startswith("B")]) == 16


def test_editorial_corrections_are_stated():
    """Rows 22, 34, 75 and 77: corrections of wording, equation and figure numbers."""
    # row 22: example 2-9 compares its equations with example 2-8, not 2-7
    assert "the four-bar with relative-motion equations is example 2-8" in _text("book/analysis/relative-motion.md")
    # row 34: the power form of §2.3 I rewrites (2-21)
    assert "but it rewrites (2-21)" in _text("derivations/planar/efficiency.md")
    # row 75: the OCR misreadings of Fig 2-3's caption are replaced by the right terms
    glossary = _text("book/glossary.md")
    assert "| 楔块机构 | wedge mechanism" in glossary and "| 无过约束机构 |" in glossary
    # row 77: the tangent mechanism is Fig 2-11d
    assert "Tangent mechanism (正切机构, F17, Fig. 2-11d)" in _text("derivations/planar/special_mechanisms.md")
