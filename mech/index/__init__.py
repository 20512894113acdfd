"""Find it by number: every equation, example, table, figure and exercise of the planar
chapter, and the chapters and sections of the spherical monograph, mapped to the derivation
that proves it, the public functions that compute it, the book pages that show it and the
tests that pin it.

The index is harvested from what the repository already declares (see
:mod:`mech.index._harvest`): titles, headings, captions and labels of the pages, the
equations each derivation passes to its code generator, public docstrings, the exercise
registry and test names. The numbers the textbooks have (every equation, example, table,
figure and exercise of the planar chapter, every chapter and section of the monograph's
contents, each with a short title) are the package's data files ``mech/index/data/*.toml``
(:mod:`mech.index._catalog`). Only the gaps are kept by hand, in
:data:`mech.index._not_covered.NOT_COVERED`, each with its reason.

It reads the repository's ``derivations/``, ``book/``, ``mech/`` and ``tests/`` folders,
so it needs a clone, not an installed wheel. Standard library only; nothing is imported
but parsed.

>>> from mech.index import lookup, repository_root
>>> root = repository_root()
>>> [entry.key for entry in lookup("2-19", root=root)][:2]
[('eq', '2-19'), ('example', '2-19')]

From the command line: ``python -m mech.index 2-19`` (every kind numbered 2-19), or
``eq 2-19``, ``fig 2-86``, ``ex 2-15`` (an example), ``exercise 2-27``, ``table 2-3``,
``chapter 5``, ``§1.3.1``; ``python -m mech.index --missing`` lists what is not covered.
"""

import os
import re
from dataclasses import dataclass
from pathlib import Path

from mech.index._catalog import DATA_DIR, catalog_items, catalog_numbers
from mech.index._harvest import Place, harvest, make_id
from mech.index._not_covered import NOT_COVERED
from mech.index._refs import KINDS, kind_of_word, parse

__all__ = [
    "Entry",
    "Index",
    "KINDS",
    "NOT_COVERED",
    "Place",
    "RepositoryNotFound",
    "build_index",
    "catalog_items",
    "catalog_numbers",
    "lookup",
    "make_id",
    "parse",
    "parse_query",
    "repository_root",
]

_ROLES = ("derivation", "function", "book", "test")


class RepositoryNotFound(FileNotFoundError):
    """The repository's folders are not there (``mech`` was installed from a wheel)."""


def repository_root(start=None):
    """The clone that holds this ``mech``: the folder with ``derivations/`` beside ``mech/``.

    Raises
    ------
    RepositoryNotFound
        If ``start`` (default: the folder above the ``mech`` package) has no
        ``derivations/`` and ``book/`` folders, as in an installed wheel.
    """
    root = Path(start) if start is not None else Path(__file__).resolve().parents[2]
    if not ((root / "derivations").is_dir() and (root / "book").is_dir()):
        raise RepositoryNotFound(
            f"Expected a clone of the mech repository with derivations/ and book/ at {root}, "
            "got none: the index is built from those folders, which an installed wheel does "
            "not ship. Run it from a clone, or pass its path (python -m mech.index --root PATH)."
        )
    return root


def _sort_key(key):
    kind, number = key
    order = list(KINDS).index(kind)
    return order, tuple(int(p) for p in re.split(r"[-.]", number))


def _label(key):
    kind, number = key
    if kind == "eq":
        return f"({number})"
    if kind == "section":
        return f"§{number}"
    return number


@dataclass(frozen=True)
class Entry:
    """One number and every place that covers it.

    Attributes
    ----------
    key : tuple
        ``(kind, number)``, e.g. ``("eq", "2-19")``.
    places : tuple
        The `Place` records that cover it.
    catalogued : bool or None
        Whether the textbook data (``mech/index/data``) lists the number.
    not_covered : str or None
        The reason from ``NOT_COVERED``, or None.
    item : CatalogItem or None
        The number's catalogue record (its short title, section, part or page), or None
        when the data does not list it.
    """

    key: tuple
    places: tuple
    catalogued: bool | None
    not_covered: str | None
    item: dict | None = None

    @property
    def title(self):
        """'equation (2-19)', 'figure 2-86', 'monograph §1.3.1'."""
        return f"{KINDS[self.key[0]]} {_label(self.key)}"

    @property
    def name(self):
        """The number's short title from the data ("friction-circle radius of a journal"),
        or None."""
        return self.item.get("title") if self.item else None

    def role(self, role):
        """The places of one role ("derivation", "function", "book", "test")."""
        return tuple(p for p in self.places if p.role == role)

    @property
    def covered(self):
        """A derivation declares it (equations); or a derivation, page or function does."""
        roles = {p.role for p in self.places}
        if self.key[0] == "eq":
            return "derivation" in roles
        return bool(roles & {"derivation", "book", "function"})

    @property
    def stale(self):
        """Listed as not covered, but covered; the entry in NOT_COVERED can go."""
        return self.not_covered is not None and self.covered


class Index:
    """Every harvested and catalogued number of one repository.

    Build it with :func:`build_index`. ``index[("fig", "2-86")]`` is an :class:`Entry`;
    iterating gives the entries in textbook order.
    """

    def __init__(self, root, places, catalog, items=None):
        self.root = Path(root)
        self.catalog = None if catalog is None else tuple(catalog)
        # (kind, number) -> its catalogue record: title, section and page
        self.items = dict(items or {})
        grouped = {}
        for key, place in places:
            grouped.setdefault(key, [])
            if place not in grouped[key]:
                grouped[key].append(place)
        keys = set(grouped) | set(self.catalog or ()) | set(NOT_COVERED)
        catalogued = set(self.catalog or ())
        self._entries = {
            key: Entry(key, tuple(grouped.get(key, ())),
                       None if self.catalog is None else key in catalogued,
                       NOT_COVERED.get(key), self.items.get(key))
            for key in sorted(keys, key=_sort_key)
        }

    def __getitem__(self, key):
        return self._entries[key]

    def __contains__(self, key):
        return key in self._entries

    def __iter__(self):
        return iter(self._entries.values())

    def __len__(self):
        return len(self._entries)

    def kind(self, kind):
        """Entries of one kind, in order."""
        return [e for e in self if e.key[0] == kind]

    def missing(self):
        """Catalogued entries neither covered nor listed in NOT_COVERED."""
        return [e for e in self if e.catalogued and not e.covered and e.not_covered is None]

    def stale(self):
        """Entries of NOT_COVERED that are covered now."""
        return [e for e in self if e.stale]

    def summary(self):
        """{kind: (catalogued, covered, not yet covered)} over the catalogued numbers."""
        out = {}
        for kind in KINDS:
            entries = [e for e in self.kind(kind) if e.catalogued]
            covered = sum(e.covered for e in entries)
            out[kind] = (len(entries), covered, len(entries) - covered)
        return out

    def lookup(self, query):
        """Entries matching a query (see :func:`parse_query`); [] when none does."""
        return [self._entries[k] for k in parse_query(query, self._entries) if k in self._entries]


def build_index(root=None, *, catalog="auto"):
    """Harvest the repository at ``root`` (default: this clone) into an :class:`Index`.

    ``catalog`` is the folder of the textbook data (``planar.toml`` and ``spherical.toml``):
    ``"auto"`` for the package's own ``mech/index/data``, another folder (a test plants a
    change in a copy), or None to index the harvest alone.
    """
    root = repository_root(root)
    if catalog == "auto":
        catalog = DATA_DIR
    items = catalog_items(catalog) if catalog is not None else {}
    numbers = catalog_numbers(catalog) if catalog is not None else None
    known = [n for k, n in numbers or () if k == "section"]
    return Index(root, harvest(root, known_sections=known), numbers, items)


_QUERY_WORDS = {"ch": "chapter", "chapter": "chapter", "chapters": "chapter",
                "section": "section", "sec": "section", "sections": "section",
                "ex": "example", "eq": "eq", "fig": "fig"}


def parse_query(query, keys=()):
    """The (kind, number) keys a query asks for.

    "2-19" asks for every kind numbered 2-19 (those among ``keys``, or all kinds when
    ``keys`` is empty); "eq 2-19", "(2-19)", "fig 2-86b", "ex 2-15" (an example),
    "exercise 2-27", "table 2-3", "chapter 5", "§1.3.1" and "1.3.1" ask for one.

    >>> parse_query("fig 2-86b")
    [('fig', '2-86')]
    >>> parse_query("ex 2-15"), parse_query("(2-19)"), parse_query("§1.3.1")
    ([('example', '2-15')], [('eq', '2-19')], [('section', '1.3.1')])

    Raises
    ------
    ValueError
        If the query names no number.
    TypeError
        If the query is not a string.
    """
    _check_query(query)
    text = query.strip()
    m = re.fullmatch(r"\(\s*(2-\d{1,3})\s*\)", text)
    if m:
        return [("eq", m.group(1))]
    m = re.fullmatch(r"(?:(?P<word>[^\d\s§(]+)\.?\s*)?(?P<num>2-\d{1,3})[a-h]?", text)
    if m:
        number = m.group("num")
        word = m.group("word")
        if word:
            kind = _QUERY_WORDS.get(word.lower().rstrip(".")) or kind_of_word(word)
            if kind is None or kind in ("chapter", "section"):
                raise ValueError(f"Expected `query` to name a kind among eq, ex (example), table, fig, "
                                 f"exercise, got {word!r} in {query!r}")
            return [(kind, number)]
        kinds = [k for k in KINDS if (k, number) in keys] if keys else \
            [k for k in KINDS if k not in ("chapter", "section")]
        return [(k, number) for k in kinds]
    m = re.fullmatch(r"(?:(?P<word>[A-Za-z]+)\.?\s*|§+\s*)?(?P<num>[1-9](?:\.\d{1,2}){0,2})", text)
    if m:
        number, word = m.group("num"), (m.group("word") or "").lower()
        kind = _QUERY_WORDS.get(word) if word else ("chapter" if "." not in number else "section")
        if kind == "chapter" and "." in number:
            kind = "section"
        if kind not in ("chapter", "section"):
            raise ValueError(f"Expected `query` of the form chapter N or §N.N for the monograph, got {query!r}")
        return [(kind, number)]
    raise ValueError(f"Expected `query` to name a number like 2-19, eq 2-19, fig 2-86, ex 2-15, exercise 2-27, "
                     f"table 2-3, chapter 5 or §1.3.1, got {query!r}")


def _check_query(query):
    """Raise TypeError naming `query` unless it is a string (checked before any work)."""
    if not isinstance(query, str):
        raise TypeError(f"Expected `query` to be a string such as '2-19' or 'eq 2-19', got {query!r} "
                        f"of type {type(query).__name__}")


def lookup(query, *, root=None, index=None):
    """The entries that answer ``query`` (a list, maybe empty).

    Raises
    ------
    TypeError
        If ``query`` is not a string or ``index`` is not an :class:`Index`.
    ValueError
        If ``query`` names no number (see :func:`parse_query`).
    """
    _check_query(query)
    parse_query(query)                       # a bad query is refused before the harvest
    if index is not None and not isinstance(index, Index):
        raise TypeError(f"Expected `index` to be an Index (from build_index) or None, got {index!r}")
    if root is not None and (isinstance(root, bytes) or not isinstance(root, (str, os.PathLike))):
        raise TypeError(f"Expected `root` to be a folder name or None, got {root!r}")
    index = index if index is not None else build_index(root)
    return index.lookup(query)
