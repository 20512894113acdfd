"""Read textbook references ("eqs. 2-11 to 2-18", "Fig. 2-86", "(2-19)", "§1.3.1") out of text.

The index is built from what the notebooks, modules, pages and tests already say; this module
is the one place that decides how such a phrase is read. Standard library only.

A reference is a pair ``(kind, number)``:

- ``eq``, ``fig``, ``example``, ``table``, ``exercise`` with numbers like ``"2-19"`` (the
  planar chapter);
- ``chapter`` (``"5"``) and ``section`` (``"1.3.1"``) of the spherical monograph, read only
  from text about the sphere (``spherical=True``), because the planar pages use "§2.2" for
  the chapter's own sections.
"""

import re

__all__ = ["KINDS", "parse", "parse_test_name", "kind_of_word", "expand_sections"]

#: Kinds in display order, with their display names.
KINDS = {
    "eq": "equation",
    "example": "example",
    "table": "table",
    "fig": "figure",
    "exercise": "exercise",
    "chapter": "monograph chapter",
    "section": "monograph section",
}

_WORDS = (
    ("exercise", r"exercises?|exerc\.|习题|题"),
    ("example", r"examples?|exs?\.?|例"),
    ("table", r"tables?|tab\.|表"),
    ("fig", r"figs?\.?|figures?|图"),
    ("eq", r"eqs?\.?|equations?|formulas?|式"),
)
_WORD_RE = {kind: re.compile(rf"^(?:{pat})$", re.I) for kind, pat in _WORDS}

_NUM = r"2-(\d{1,3})(?:[a-h](?:\s*(?:,|/|and)\s*[a-h]\b)*)?"
_PNUM = r"\(2-(\d{1,3})\)"
_SEP = r"\s*(?:,|;|/|&|\band\b|\bor\b|\bto\b|–|—|-|~|…)\s*"
_LIST = rf"(?:{_PNUM}(?:{_SEP}{_PNUM})*|{_NUM}(?:{_SEP}{_NUM})*)"
# A keyword, then a list of numbers. "题图 2-1" is an exercise's figure, not a chapter figure.
_KEYWORD_LIST = re.compile(
    rf"(?<![A-Za-z])(?P<word>{'|'.join(p for _, p in _WORDS)})\s*(?P<list>{_LIST})(?!\d|\.\d)",
    re.I,
)
_BARE_EQ = re.compile(rf"\(2-(\d{{1,3}})\)(?:(?P<sep>{_SEP})\(2-(\d{{1,3}})\))*")
_BARE_EQ_ITEM = re.compile(r"\(2-(\d{1,3})\)|(?P<to>\bto\b|–|—|~|-|…)")
_LIST_ITEM = re.compile(r"2-(\d{1,3})|(?P<to>\bto\b|–|—|~|…|(?<=[\d)])\s*-\s*(?=\(?2-))")

_CHAPTER = re.compile(r"(?<![A-Za-z])(?:chapters?|chs?\.)\s*([1-7])(?:\s*(?:,|and|to|–)\s*([1-7]))*(?![\d.])",
                      re.I)
_CHAPTER_ITEM = re.compile(r"([1-7])|(?P<to>\bto\b|–)")
_SEC2 = r"[1-7]\.\d{1,2}(?:\.\d{1,2})?"
_SEC3 = r"[1-7]\.[1-9]\.[1-9]"
_SECTION = re.compile(
    rf"(?:(?:§§?\s*|\bsections?\s+|\bproblems?\s+)(?P<first>{_SEC2})"
    rf"(?:\s*(?P<to>to|–|and|,)\s*(?P<last>{_SEC2}))?"
    rf"|(?<![\d.\w])(?P<bfirst>{_SEC3})(?:\s*(?P<bto>to|–|and|,)\s*(?P<blast>{_SEC3}))?)"
    r"(?!\d|\.\d)"
)


def kind_of_word(word):
    """The kind a keyword names ("Figs." -> "fig"), or None."""
    word = word.strip()
    if word.startswith("题图"):
        return None
    for kind, pattern in _WORD_RE.items():
        if pattern.match(word):
            return kind
    return None


def _numbers(text, item_re):
    """Numbers of a list like "2-11 to 2-18, 2-20": ranges expanded, order kept."""
    out, pending_range = [], False
    for m in item_re.finditer(text):
        if m.group("to"):
            pending_range = bool(out)
            continue
        n = int(m.group(1))
        if pending_range and out and out[-1] < n <= out[-1] + 40:
            out.extend(range(out[-1] + 1, n + 1))
        else:
            out.append(n)
        pending_range = False
    return out


def _key(n):
    return f"2-{n}"


def expand_sections(first, last, known=()):
    """Sections from ``first`` to ``last``: known ones in between, or a counted range."""
    def split(s):
        return tuple(int(p) for p in s.split("."))

    a, b = split(first), split(last)
    inside = sorted({s for s in known if a <= split(s) <= b} | {first, last}, key=split)
    if len(a) == len(b) and a[:-1] == b[:-1] and b[-1] - a[-1] < 20:
        prefix = ".".join(str(p) for p in a[:-1])
        counted = {f"{prefix}.{k}" for k in range(a[-1], b[-1] + 1)}
        inside = sorted(set(inside) | counted, key=split)
    return inside


def parse(text, *, spherical=False, known_sections=()):
    """Every textbook reference in ``text``, in order, without repeats.

    Parameters
    ----------
    text : str
        Any prose: a title, a caption, a docstring, a code-generation header.
    spherical : bool, keyword-only
        Also read the monograph's chapters ("chapter 5", "ch. 6") and sections ("§1.7",
        "§§1.3 to 1.6", "problems 1.3.1 to 1.4.2").
    known_sections : iterable of str
        Sections to fill a range of sections with ("1.3.1 to 1.4.2").

    Returns
    -------
    list of (kind, number)

    Examples
    --------
    >>> parse("Four-bar position (eqs. 2-11 to 2-13, Fig. 2-54b) and (2-19), (2-20)")
    [('eq', '2-11'), ('eq', '2-12'), ('eq', '2-13'), ('fig', '2-54'), ('eq', '2-19'), ('eq', '2-20')]
    >>> parse("Examples 2-17 and 2-18 (Table 2-3); exercise 2-24; 题图 2-5")
    [('example', '2-17'), ('example', '2-18'), ('table', '2-3'), ('exercise', '2-24')]
    >>> parse("the monograph's chapter 5, §§1.3 to 1.5", spherical=True)
    [('chapter', '5'), ('section', '1.3'), ('section', '1.4'), ('section', '1.5')]
    """
    if not isinstance(text, str):
        raise TypeError(f"Expected `text` to be a string, got {text!r} of type {type(text).__name__}")
    text = text.replace("\\text{-}", "-").replace("\u2011", "-")
    found = []
    spans = []
    for m in _KEYWORD_LIST.finditer(text):
        word = m.group("word")
        start = m.start()
        kind = kind_of_word(word)
        if text[max(0, start - 1):start] == "题" or kind is None:
            spans.append(m.span())
            continue
        for n in _numbers(m.group("list"), _LIST_ITEM):
            found.append((m.start(), (kind, _key(n))))
        spans.append(m.span())

    def free(a, b):
        return not any(s < b and a < e for s, e in spans)

    for m in _BARE_EQ.finditer(text):
        if free(*m.span()):
            for n in _numbers(m.group(0), _BARE_EQ_ITEM):
                found.append((m.start(), ("eq", _key(n))))
    if spherical:
        for m in _CHAPTER.finditer(text):
            for n in _numbers(m.group(0), _CHAPTER_ITEM):
                found.append((m.start(), ("chapter", str(n))))
        for m in _SECTION.finditer(text):
            if not free(*m.span()):
                continue
            first = m.group("first") or m.group("bfirst")
            last = m.group("last") or m.group("blast")
            if last and (m.group("to") or m.group("bto")) in ("to", "–"):
                sections = expand_sections(first, last, known_sections)
            else:
                sections = [first] + ([last] if last else [])
            for s in sections:
                found.append((m.start(), ("section", s)))
    found.sort(key=lambda item: item[0])
    out = []
    for _, ref in found:
        if ref not in out:
            out.append(ref)
    return out


_NAME_WORDS = {"example": "example", "examples": "example", "exercise": "exercise",
               "exercises": "exercise", "fig": "fig", "figure": "fig", "table": "table",
               "eq": "eq", "equation": "eq", "equations": "eq"}
_NAME_RE = re.compile(r"(?:^|_)(?P<word>[a-z]+)_(?P<nums>2_\d{1,3}(?:_2_\d{1,3})*)(?=_|$)")
_BARE_NAME_RE = re.compile(r"^test_(?P<nums>2_\d{1,3}(?:_2_\d{1,3})*)(?=_|$)")


def parse_test_name(name, *, bare_kind=None):
    """References in a test's name: ``test_example_2_3_limit_positions`` -> example 2-3.

    ``bare_kind`` is the kind of a number that opens the name with no keyword
    (``test_2_30_...`` in the exercise tests).

    >>> parse_test_name("test_synthesis_exercises_2_27_2_28")
    [('exercise', '2-27'), ('exercise', '2-28')]
    >>> parse_test_name("test_example_exercise_2_19_free_bodies")
    [('exercise', '2-19')]
    """
    out = []
    for m in _NAME_RE.finditer(name):
        kind = _NAME_WORDS.get(m.group("word"))
        if kind:
            out += [(kind, "2-" + n) for n in re.findall(r"2_(\d{1,3})", m.group("nums"))]
    m = _BARE_NAME_RE.match(name)
    if m and bare_kind:
        out += [(bare_kind, "2-" + n) for n in re.findall(r"2_(\d{1,3})", m.group("nums"))]
    seen = []
    for ref in out:
        if ref not in seen:
            seen.append(ref)
    return seen
