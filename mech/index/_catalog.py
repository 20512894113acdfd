"""The numbers the catalogs list: every equation, example, table, figure and exercise of the
planar chapter, and the chapters and sections of the spherical monograph.

The catalogs live in ``shared/catalog/`` beside the repository (``<repo>/../shared``); they are
not part of the package. Standard library only.
"""

import re
from pathlib import Path

from mech.index._refs import expand_sections

__all__ = ["catalog_dir", "catalog_numbers"]

_PLANAR = ("planar-part-A-structure-kinematics.md", "planar-part-B-forces-synthesis.md",
           "planar-part-C-synthesis-spatial.md")


def catalog_dir(root):
    """``<root>/../shared/catalog`` if it exists, else None."""
    path = Path(root).resolve().parent / "shared" / "catalog"
    return path if path.is_dir() else None


def _sort_key(ref):
    kind, number = ref
    return kind, tuple(int(p) for p in re.split(r"[-.]", number))


def catalog_numbers(directory):
    """Every catalogued number, as a sorted list of ``(kind, number)``.

    Equations are the ``(2-N)`` tags of the planar catalogs; examples their ``Example 2-N``
    headings; tables every ``Table 2-N``; figures the rows of their figure tables; exercises the
    headings of ``exercises.md``; the monograph's chapters and the sections that
    ``spherical-guide.md`` names.
    """
    directory = Path(directory)
    found = set()
    for name in _PLANAR:
        text = (directory / name).read_text(encoding="utf-8").replace("\\text{-}", "-")
        found |= {("eq", f"2-{n}") for n in re.findall(r"\(2-(\d+)\)", text)}
        found |= {("example", f"2-{n}") for n in
                  re.findall(r"^###\s+(?:Example|Ex\.)\s+2-(\d+)", text, re.M)}
        found |= {("table", f"2-{n}") for n in re.findall(r"\bTable 2-(\d+)", text)}
        in_figures = False
        for line in text.splitlines():
            if line.startswith("#"):
                in_figures = "Figures" in line
            elif in_figures:
                m = re.match(r"\|\s*2-(\d+)\b", line)
                if m:
                    found.add(("fig", f"2-{m.group(1)}"))
    exercises = (directory / "exercises.md").read_text(encoding="utf-8")
    found |= {("exercise", f"2-{n}") for n in re.findall(r"^###\s+2-(\d+)\b", exercises, re.M)}
    guide = (directory / "spherical-guide.md").read_text(encoding="utf-8")
    found |= {("chapter", n) for n in re.findall(r"^## Chapter (\d+)", guide, re.M)}
    for first, last in re.findall(r"\((\d\.\d+\.\d+)\)(?:\s*to\s*\((\d\.\d+\.\d+)\))?", guide):
        found |= {("section", s) for s in (expand_sections(first, last) if last else [first])}
    return sorted(found, key=_sort_key)
