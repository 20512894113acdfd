"""Cut what every page of the book downloads from the theme (issue 17: page weight).

After the HTML build (``build-finished``), in the output folder only:

1. Icons. pydata-sphinx-theme loads ``_static/scripts/fontawesome.js`` (1.49 MB: every
   Font Awesome icon) on every page to turn ``<i class="fa-solid fa-bars">`` into inline
   SVG. This step finds the icon names that the built pages and the theme's scripts use,
   takes their outlines from that file, and writes in its place a small script
   (:func:`icon_script`) that does the same replacement for those icons only.
2. Icon font. The theme's CSS draws a few icons (admonition titles, breadcrumbs, the
   "on this page" arrow) from ``fa-solid-900.woff2`` (156 kB). The font is cut down to the
   code points that the CSS files use (fontTools), and the CSS rules that map every icon
   name to the font (``.fa-<name>:before{content:...}``, 1,900 rules that nothing uses
   once the icons are SVG) are removed.
3. Search index. The theme loads ``searchindex.js`` (0.39 MB) and Sphinx's search scripts
   on every page for its search-as-you-type box, which this book does not turn on (its
   search box opens ``search.html``). They are removed from every page but ``search.html``.

Each step checks what it assumes (the icons it needs exist, the script tags it removes
are there) and stops the build with an error otherwise, so a theme upgrade cannot silently
break the pages.
"""

import json
import re
from pathlib import Path

ICON_JS = Path("_static", "scripts", "fontawesome.js")
SOLID_FONT = Path("_static", "vendor", "fontawesome", "webfonts", "fa-solid-900.woff2")
# Font Awesome class names that are not icons: styles, sizes and helpers.
STYLE_PREFIX = {"fa-solid": "fas", "fas": "fas", "fa-regular": "far", "far": "far",
                "fa-brands": "fab", "fab": "fab", "fa": "fas"}
NOT_ICONS = re.compile(r"fa-(solid|regular|brands|light|thin|duotone|sharp|lg|fw|[0-9]?x[sl]?|[0-9]+x|sm|xs|2xs|"
                       r"2xl|xl|spin.*|pulse|beat.*|fade|bounce|flip.*|shake|rotate.*|pull-.*|border|inverse|"
                       r"stack.*|li|ul|width-auto)$")
SEARCH_SCRIPTS = re.compile(
    r'[ \t]*<script src="[^"]*(?:_static/searchtools\.js|_static/language_data\.js|searchindex\.js)"></script>\n?')
FA_NAME_RULES = re.compile(r'(?:\.fa-[a-z0-9-]+:(?:before|after),?)+\{content:"[^"]*"\}')
PUA = re.compile(r"[\uf000-\uf8ff]|\\(f[0-9a-fA-F]{3})(?![0-9a-fA-F])")


class PageWeightError(RuntimeError):
    """The theme's files are not what this extension expects."""


# ---------------------------------------------------------------- icons

def icons_in_html(text):
    """{(prefix, name)} for every icon element (``<i class="fa-solid fa-bars">``, or a span) of a page."""
    found = set()
    for tag, classes in re.findall(r'<([a-z]+)\s+[^>]*class="([^"]*)"', text):
        classes = classes.split()
        if tag != "svg" and STYLE_PREFIX.keys() & set(classes):
            found |= _icons_of(classes)
    return found


def icons_in_script(text):
    """Icons a script sets through ``classList``/``className`` strings: "fa-solid fa-xmark"."""
    found = set()
    for classes in re.findall(r'["\'`]((?:fa-solid|fa-regular|fa-brands|fas|far|fab) fa-[a-z0-9 -]+)["\'`]', text):
        found |= _icons_of(classes.split())
    return found


def _icons_of(classes):
    prefix = next((STYLE_PREFIX[c] for c in classes if c in STYLE_PREFIX), None)
    names = [c[3:] for c in classes if c.startswith("fa-") and c not in STYLE_PREFIX and not NOT_ICONS.match(c)]
    return {(prefix or "fas", name) for name in names}


def icon_packs(source):
    """{prefix: text of its icon table} from Font Awesome's all-in-one script."""
    packs = {}
    for m in re.finditer(r'd\("(fa[bsr])",p\),d\("fa-(?:brands|regular|solid)",p\)', source):
        start = source.rfind("var p={", 0, m.start())
        if start < 0:
            raise PageWeightError(f"no icon table before the {m.group(1)} pack")
        packs[m.group(1)] = source[start:m.start()]
    if set(packs) != {"fab", "far", "fas"}:
        raise PageWeightError(f"expected the fab, far and fas icon packs in {ICON_JS}, found {sorted(packs)}")
    return packs


def icon_outline(pack, name):
    """(width, height, path) of icon ``name`` (or an alias) in a pack's table."""
    entry = r'\[(\d+),(\d+),\[([^\]]*)\],"[0-9a-f]+",("(?:[^"\\]|\\.)*"|\[[^\]]*\])\]'
    m = re.search(r'(?:"' + re.escape(name) + r'"|[,{]' + re.escape(name) + r'):' + entry, pack)
    if m is None:  # an old name: look for it among the aliases
        for m in re.finditer(r'(?:"[a-z0-9-]+"|[a-z0-9]+):' + entry, pack):
            if f'"{name}"' in m.group(3).split(","):
                break
        else:
            return None
    path = json.loads(m.group(4))
    if isinstance(path, list):  # duotone: two layers; draw both
        path = " ".join(p for p in path if p)
    return int(m.group(1)), int(m.group(2)), path


# The part of Font Awesome's own stylesheet that sizes and places its inline SVG.
ICON_CSS = (
    "svg:not(:host).svg-inline--fa,svg:not(:root).svg-inline--fa{overflow:visible;box-sizing:content-box}"
    ".svg-inline--fa{display:var(--fa-display,inline-block);height:1em;overflow:visible;vertical-align:-.125em}"
    ".svg-inline--fa.fa-2xs{vertical-align:.1em}.svg-inline--fa.fa-xs{vertical-align:0}"
    ".svg-inline--fa.fa-sm{vertical-align:-.0714285705em}.svg-inline--fa.fa-lg{vertical-align:-.2em}"
    ".svg-inline--fa.fa-xl{vertical-align:-.25em}.svg-inline--fa.fa-2xl{vertical-align:-.3125em}"
    ".svg-inline--fa.fa-fw{width:var(--fa-fw-width,1.25em)}"
)

ICON_RUNTIME = r"""
  const css = document.createElement("style");
  css.textContent = CSS;
  document.head.appendChild(css);
  const NS = "http://www.w3.org/2000/svg";
  function draw(i) {
    const classes = [...i.classList];
    const prefix = classes.map((c) => PREFIX[c]).find(Boolean) || "fas";
    const name = classes.find((c) => c.startsWith("fa-") && ICONS[prefix][c.slice(3)]);
    if (!name) return;
    const [w, h, d] = ICONS[prefix][name.slice(3)];
    const svg = document.createElementNS(NS, "svg");
    for (const a of i.attributes) if (a.name !== "class") svg.setAttribute(a.name, a.value);
    svg.setAttribute("class", ["svg-inline--fa", ...classes].join(" "));
    svg.setAttribute("data-prefix", prefix);
    svg.setAttribute("data-icon", name.slice(3));
    svg.setAttribute("viewBox", `0 0 ${w} ${h}`);
    svg.setAttribute("role", "img");
    if (!i.hasAttribute("aria-label") && !i.hasAttribute("title")) svg.setAttribute("aria-hidden", "true");
    const path = document.createElementNS(NS, "path");
    path.setAttribute("fill", "currentColor");
    path.setAttribute("d", d);
    svg.appendChild(path);
    i.replaceWith(svg);
  }
  // Font Awesome's own rule: any element (an <i>, a <span>) with a style class.
  const SELECTOR = Object.keys(PREFIX).map((c) => `.${c}:not(svg)`).join(",");
  const scan = (root) => {
    if (root.matches && root.matches(SELECTOR)) draw(root);
    if (root.querySelectorAll) root.querySelectorAll(SELECTOR).forEach(draw);
  };
  const start = () => {
    scan(document.body);
    new MutationObserver((records) => records.forEach((r) => r.addedNodes.forEach(scan)))
      .observe(document.body, {childList: true, subtree: true});
  };
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
"""


def icon_script(outlines):
    """The replacement of ``fontawesome.js``: ``outlines`` is {prefix: {name: (w, h, path)}}."""
    count = sum(len(v) for v in outlines.values())
    return (
        "/* Generated by book/_ext/page_weight.py: the " f"{count}"
        " Font Awesome Free icons that this book's pages use (icons: CC BY 4.0, code: MIT;\n"
        "   see fontawesome.js.LICENSE.txt), drawn as inline SVG like Font Awesome's own script. */\n"
        "(() => {\n"
        f"  const ICONS = {json.dumps(outlines, separators=(',', ':'), sort_keys=True)};\n"
        f"  const PREFIX = {json.dumps(STYLE_PREFIX, separators=(',', ':'))};\n"
        f"  const CSS = {json.dumps(ICON_CSS)};\n"
        f"{ICON_RUNTIME}"
        "})();\n"
    )


def subset_icons(outdir, pages):
    """Replace ``fontawesome.js`` with a script for the icons in use; returns their names."""
    source_path = Path(outdir, ICON_JS)
    source = source_path.read_text(encoding="utf-8")
    if "Generated by book/_ext/page_weight.py" in source:  # an incremental build: already done
        return None
    wanted = set()
    for page in pages:
        wanted |= icons_in_html(page.read_text(encoding="utf-8"))
    for script in Path(outdir, "_static").rglob("*.js"):
        if script != source_path:
            wanted |= icons_in_script(script.read_text(encoding="utf-8", errors="replace"))
    packs = icon_packs(source)
    outlines, missing = {}, []
    for prefix, name in sorted(wanted):
        outline = icon_outline(packs[prefix], name)
        if outline is None:
            missing.append(f"{prefix} {name}")
        else:
            outlines.setdefault(prefix, {})[name] = outline
    if missing:
        raise PageWeightError(f"icons used by the pages but not in Font Awesome: {missing}")
    source_path.write_text(icon_script(outlines), encoding="utf-8")
    source_path.with_name("fontawesome.js.map").unlink(missing_ok=True)
    return sorted(f"{p} {n}" for p, v in outlines.items() for n in v)


# ---------------------------------------------------------------- icon font

def css_code_points(outdir):
    """Private-use code points (icon glyphs) that the CSS files draw, after the name rules go."""
    points = set()
    for css in Path(outdir, "_static").rglob("*.css"):
        text = FA_NAME_RULES.sub("", css.read_text(encoding="utf-8"))
        for m in PUA.finditer(text):
            points.add(int(m.group(1), 16) if m.group(1) else ord(m.group(0)))
    return points


def strip_icon_name_rules(outdir):
    """Drop ``.fa-<name>:before{content:...}`` rules (the icons are SVG now)."""
    for css in Path(outdir, "_static").rglob("*.css"):
        text = css.read_text(encoding="utf-8")
        stripped = FA_NAME_RULES.sub("", text)
        if stripped != text:
            css.write_text(stripped, encoding="utf-8")


def subset_font(outdir, points):
    """Cut ``fa-solid-900.woff2`` down to ``points``; returns (bytes before, bytes after)."""
    from fontTools import subset
    from fontTools.ttLib import TTFont

    path = Path(outdir, SOLID_FONT)
    before = path.stat().st_size
    font = TTFont(path)
    if font.flavor != "woff2":
        raise PageWeightError(f"{path} is not a WOFF2 font")
    have = set(font.getBestCmap())
    keep = sorted(points & have)
    if not keep:
        raise PageWeightError(f"none of the CSS icon code points {sorted(map(hex, points))} is in {path}")
    options = subset.Options()
    options.flavor = "woff2"
    options.layout_features = ["*"]
    options.name_IDs = ["*"]  # keep the copyright and licence names
    sub = subset.Subsetter(options)
    sub.populate(unicodes=keep)
    sub.subset(font)
    font.flavor = "woff2"
    font.save(path)
    return before, path.stat().st_size


# ---------------------------------------------------------------- search scripts

def drop_search_scripts(page, outdir):
    """Remove the search index and scripts from a page that is not ``search.html``."""
    if page.relative_to(outdir).as_posix() == "search.html":
        return False
    text = page.read_text(encoding="utf-8")
    new, count = SEARCH_SCRIPTS.subn("", text)
    if count not in (0, 3):
        raise PageWeightError(f"{page}: found {count} of the 3 search script tags")
    if count:
        page.write_text(new, encoding="utf-8")
    return bool(count)


# ---------------------------------------------------------------- Sphinx

def html_pages(outdir):
    skip = {"_static", "_sources", "_images", "_sphinx_design_static", "_downloads"}
    return [p for p in Path(outdir).rglob("*.html") if not skip.intersection(p.relative_to(outdir).parts)]


def lighten(app, exception):
    if exception is not None or app.builder.format != "html":
        return
    from sphinx.util import logging

    log = logging.getLogger(__name__)
    outdir = Path(app.outdir)
    pages = html_pages(outdir)
    dropped = sum(drop_search_scripts(page, outdir) for page in pages)
    icons = subset_icons(outdir, pages)
    points = css_code_points(outdir)
    strip_icon_name_rules(outdir)
    font = Path(outdir, SOLID_FONT)
    if font.stat().st_size > 20000:  # not yet cut (an incremental build may have done it)
        before, after = subset_font(outdir, points)
        log.info(f"page_weight: fa-solid-900.woff2 {before} -> {after} bytes ({len(points)} code points)")
    log.info(f"page_weight: search scripts removed from {dropped} pages; icons kept: {icons}")


def setup(app):
    # After png_palette and the other build-finished steps (priority 500).
    app.connect("build-finished", lighten, priority=800)
    return {"parallel_read_safe": True, "parallel_write_safe": True, "version": "1"}
