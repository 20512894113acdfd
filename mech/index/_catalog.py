"""The textbook numbers the index knows, read from the package's own data files.

``mech/index/data/planar.toml`` lists the planar chapter's sections, equations, worked
examples, tables, figures and exercises; ``mech/index/data/spherical.toml`` the spherical
monograph's chapters and the sections of its table of contents. Each item has a number and a
short title; the planar items also name the section (and part) of the chapter that prints
them, the monograph's sections the page. The files ship inside the wheel (package data), so
the index needs nothing outside the repository. Standard library only.
"""

import re
import tomllib
from pathlib import Path

__all__ = ["DATA_DIR", "CatalogItem", "catalog_items", "catalog_numbers"]

#: The folder of the data files that ship with the package.
DATA_DIR = Path(__file__).resolve().parent / "data"

#: Table name in the data files -> kind of reference (see :data:`mech.index._refs.KINDS`).
_PLANAR_TABLES = {"equation": "eq", "example": "example", "table": "table",
                  "figure": "fig", "exercise": "exercise"}
_SPHERICAL_TABLES = {"chapter": "chapter", "section": "section"}
_NUMBER = {"planar": re.compile(r"2-[1-9]\d{0,2}"),
           "spherical": re.compile(r"[1-9](?:\.[1-9]\d?){0,2}")}


class CatalogItem(dict):
    """One catalogued number: ``key``, ``title`` and, when known, ``section``, ``part``,
    ``page`` (a dict with attribute access)."""

    __getattr__ = dict.get


def _sort_key(ref):
    kind, number = ref
    return kind, tuple(int(p) for p in re.split(r"[-.]", number))


def _read(path, tables, pattern):
    data = tomllib.loads(Path(path).read_text(encoding="utf-8"))
    items = {}
    for table, kind in tables.items():
        for row in data.get(table, ()):
            number = row.get("number")
            if not isinstance(number, str) or not pattern.fullmatch(number):
                raise ValueError(f"Expected a number like {pattern.pattern} in [[{table}]] of "
                                 f"{path}, got {number!r}")
            key = (kind, number)
            if key in items:
                raise ValueError(f"Expected each number once in {path}, got [[{table}]] "
                                 f"{number} twice")
            if not str(row.get("title", "")).strip():
                raise ValueError(f"Expected a title for [[{table}]] {number} in {path}, got none")
            items[key] = CatalogItem(row, key=key)
    return items


def _items(directory):
    directory = Path(directory)
    items = _read(directory / "planar.toml", _PLANAR_TABLES, _NUMBER["planar"])
    items.update(_read(directory / "spherical.toml", _SPHERICAL_TABLES, _NUMBER["spherical"]))
    return items


def catalog_items(directory=None):
    """Every catalogued number with its data, as ``{(kind, number): CatalogItem}``.

    ``directory`` holds ``planar.toml`` and ``spherical.toml`` (default: the package's
    ``DATA_DIR``).

    >>> items = catalog_items()
    >>> items[("eq", "2-19")].section, items[("section", "1.3.1")].page
    ('2.3', 5)
    """
    return _items(directory if directory is not None else DATA_DIR)


def catalog_numbers(directory=None):
    """Every catalogued number, as a sorted list of ``(kind, number)``.

    >>> from collections import Counter
    >>> counts = Counter(kind for kind, _ in catalog_numbers())
    >>> counts["eq"], counts["example"], counts["exercise"], counts["chapter"]
    (75, 25, 32, 7)
    """
    return sorted(catalog_items(directory), key=_sort_key)
