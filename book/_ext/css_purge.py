"""Drop the CSS rules that no page of the book can use (issue 17: page weight, uncompressed).

Every page loads the theme's and the extensions' stylesheets whole: pydata-sphinx-theme's
alone is 0.31 MB, and most of it styles components this book never shows. After the HTML
build (``build-finished``, after ``page_weight``), in the output folder only, this step
parses each stylesheet under ``_static`` with ``tinycss2`` and writes back only the rules
that can match something.

The words a selector may need are the union of

- the ``class`` and ``id`` attribute values of every built HTML page (templates included), and
- every word (``[A-Za-z0-9_-]+``) of every script the pages load: the ``.js`` files under
  ``_static`` and the inline ``<script>`` blocks, because scripts add classes as the reader
  clicks (Bootstrap's ``show``/``collapsing``, the theme switcher, the search dialog,
  copybutton, togglebutton, sphinx-design's tabs, ``figures/mech_anim.js``).

A style rule stays when at least one selector of its list needs no class or id outside
that union (:func:`selector_needs`). Only the classes and ids a selector requires count:
those inside ``:not()``, ``:is()``, ``:where()``, ``:has()`` and other functions, and
attribute selectors, never make a rule go. A rule is kept or dropped whole; its selector
list is never shortened, because one selector that a browser does not understand voids
the whole list, and shortening it could bring a void rule to life.

At-rules: ``@media``, ``@supports``, ``@layer`` and ``@container`` blocks are purged
inside and dropped when nothing is left; ``@keyframes`` stay when a kept rule or a script
names them; ``@font-face``, ``@import``, ``@charset``, ``@namespace``, ``@property`` and
the rest stay as they are. Comments go, except licence comments (``/*! ... */``); a
``sourceMappingURL`` comment goes with the others (the maps would no longer match).
"""

import re
from pathlib import Path

import tinycss2

MARK = "/* purged by book/_ext/css_purge.py */\n"
WORD = re.compile(r"[A-Za-z0-9_-]+")
# A class name that a script builds from pieces: `bs-${name}-auto`, "sd-tab-" + id. The
# piece before the join is kept as a prefix: every class that starts with it may be made.
PREFIX = re.compile(r"""([A-Za-z0-9_-]*[A-Za-z][A-Za-z0-9_]*-)(?:\$\{|["']\s*\+)""")
ATTR = re.compile(r"""\b(?:class|id)\s*=\s*(?:"([^"]*)"|'([^']*)'|([^\s"'=<>`]+))""", re.I)
INLINE_SCRIPT = re.compile(r"<script\b[^>]*>(.*?)</script>", re.S | re.I)
GROUP_AT_RULES = {"media", "supports", "layer", "container", "document", "-moz-document", "scope"}
# Not shipped to every page, or not a script of the pages: the search index is words of the text.
SKIP_SCRIPTS = {"searchindex.js"}


class CSSPurgeError(RuntimeError):
    """A stylesheet could not be parsed."""


# ---------------------------------------------------------------- the words in use

def words_of_html(text):
    """Class and id values of a page, and every word of its inline scripts."""
    words = set()
    for m in ATTR.finditer(text):
        words.update(next(g for g in m.groups() if g is not None).split())
    for m in INLINE_SCRIPT.finditer(text):
        words.update(words_of_script(m.group(1)))
    return words


def words_of_script(text):
    """Every word of a script (any string in it may become a class or an id), and the
    prefixes it joins to other pieces, as ``"bs-*"``."""
    return set(WORD.findall(text)) | {p + "*" for p in PREFIX.findall(text)}


def words_in_use(outdir, pages):
    words = set()
    for page in pages:
        words |= words_of_html(page.read_text(encoding="utf-8", errors="replace"))
    for script in Path(outdir).rglob("*.js"):
        if script.name not in SKIP_SCRIPTS and "_sources" not in script.parts:
            words |= words_of_script(script.read_text(encoding="utf-8", errors="replace"))
    return words


# ---------------------------------------------------------------- selectors

def split_selectors(prelude):
    """A selector list (tokens) split at its top-level commas."""
    selectors, current = [], []
    for token in prelude:
        if token.type == "literal" and token.value == ",":
            selectors.append(current)
            current = []
        else:
            current.append(token)
    selectors.append(current)
    return selectors


def selector_needs(tokens):
    """The classes and ids (as ``.name`` / ``#name``) that one selector requires to match.

    Only top-level compound parts count: the contents of functions (``:not(.a)``,
    ``:is(.b)``) and of attribute selectors (``[class~=c]``) are blocks, not looked into.
    """
    needs = set()
    tokens = [t for t in tokens if t.type != "comment"]
    for i, token in enumerate(tokens):
        if token.type == "hash" and token.is_identifier:
            needs.add("#" + token.value)
        elif token.type == "literal" and token.value == "." and i + 1 < len(tokens):
            following = tokens[i + 1]
            if following.type == "ident":
                needs.add("." + following.value)
    return needs


def known(name, words):
    """True when ``name`` is in ``words`` or starts with a prefix (``"bs-*"``) in it."""
    if name in words:
        return True
    return any(name[:i + 1] + "*" in words for i, c in enumerate(name) if c == "-")


def rule_can_match(prelude, words):
    """True when one selector of a style rule's list needs only words in use."""
    return any(all(known(n[1:], words) for n in selector_needs(sel)) for sel in split_selectors(prelude))


# ---------------------------------------------------------------- stylesheets

def _names_in(tokens, into):
    for token in tokens:
        if token.type == "ident":
            into.add(token.value)
        elif getattr(token, "content", None) is not None and token.type in ("function", "() block", "[] block",
                                                                             "{} block"):
            _names_in(token.content, into)
        elif token.type == "function":
            _names_in(token.arguments, into)


def _purge_rules(rules, words, out, kept_names, keyframes):
    """Append the kept rules' CSS text to ``out``; collect identifiers of kept declarations."""
    for rule in rules:
        if rule.type in ("whitespace",):
            continue
        if rule.type == "comment":
            if rule.value.startswith("!"):
                out.append("/*" + rule.value + "*/")
            continue
        if rule.type == "error":
            raise CSSPurgeError(f"{rule.kind}: {rule.message} (line {rule.source_line})")
        if rule.type == "qualified-rule":
            if rule_can_match(rule.prelude, words):
                out.append(tinycss2.serialize(rule.prelude).strip() + "{" + tinycss2.serialize(rule.content) + "}")
                _names_in(rule.content, kept_names)
            continue
        # an at-rule
        keyword = rule.lower_at_keyword
        if keyword in GROUP_AT_RULES and rule.content is not None:
            inner = []
            _purge_rules(tinycss2.parse_rule_list(rule.content, skip_whitespace=True), words, inner, kept_names,
                         keyframes)
            if inner:
                out.append("@" + rule.at_keyword + tinycss2.serialize(rule.prelude).rstrip()
                           + "{" + "".join(inner) + "}")
        elif keyword.endswith("keyframes"):
            name = next((t.value for t in rule.prelude if t.type in ("ident", "string")), None)
            keyframes.append((name, len(out)))
            out.append(rule.serialize())
        else:
            if keyword == "font-face" or rule.content is not None:
                _names_in(rule.content or [], kept_names)
            out.append(rule.serialize())


def purge_css(text, words):
    """The text of stylesheet ``text`` with only the rules that can match ``words``."""
    rules = tinycss2.parse_stylesheet(text, skip_comments=False, skip_whitespace=True)
    out, kept_names, keyframes = [], set(), []
    _purge_rules(rules, words, out, kept_names, keyframes)
    for name, index in keyframes:
        if name is not None and name not in kept_names and name not in words:
            out[index] = ""
    return "".join(part for part in out if part) + "\n"


def stylesheets(outdir):
    return sorted(p for p in Path(outdir, "_static").rglob("*.css"))


def purge(outdir, pages):
    """Purge every stylesheet under ``outdir/_static``; returns {name: (bytes before, after)}."""
    words = words_in_use(outdir, pages)
    sizes = {}
    for css in stylesheets(outdir):
        text = css.read_text(encoding="utf-8")
        if text.endswith(MARK):  # an incremental build: purged already
            continue
        try:
            new = purge_css(text, words) + MARK
        except CSSPurgeError as err:
            raise CSSPurgeError(f"{css}: {err}") from None
        css.write_text(new, encoding="utf-8")
        css.with_name(css.name + ".map").unlink(missing_ok=True)
        sizes[css.relative_to(outdir).as_posix()] = (len(text.encode()), len(new.encode()))
    return sizes


# ---------------------------------------------------------------- Sphinx

def on_build_finished(app, exception):
    if exception is not None or app.builder.format != "html":
        return
    from sphinx.util import logging

    from page_weight import html_pages

    outdir = Path(app.outdir)
    sizes = purge(outdir, html_pages(outdir))
    before = sum(b for b, _ in sizes.values())
    after = sum(a for _, a in sizes.values())
    logging.getLogger(__name__).info(
        f"css_purge: {len(sizes)} stylesheets, {before} -> {after} bytes: "
        + ", ".join(f"{name} {b} -> {a}" for name, (b, a) in sizes.items()))


def setup(app):
    # After page_weight (800): the icon-name rules are gone and fontawesome.js is the subset.
    app.connect("build-finished", on_build_finished, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True, "version": "1"}
