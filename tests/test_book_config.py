"""The book's configuration keeps the strictness that makes a broken page fail the build.

See STYLE.md, section 9 (book configuration): without ``raise_on_error`` a failing cell only warns; without
``stderr_output: warn`` (and ``-W``) a NumPy RuntimeWarning, i.e. a NaN, slips through.
The table of contents must name existing files, include every derivation notebook, and
every page must carry a ``(label)=`` line before its title so that ``{ref}`` works.
"""

import re
from pathlib import Path

import pytest

yaml = pytest.importorskip("yaml")

ROOT = Path(__file__).resolve().parents[1]
BOOK = ROOT / "book"
DERIVATIONS = ROOT / "derivations"
LABEL = re.compile(r"^\(([A-Za-z0-9_-]+)\)=\s*$")
FENCE = re.compile(r"^(`{3,}|~{3,}|:{3,})")


def _config():
    return yaml.safe_load((BOOK / "_config.yml").read_text(encoding="utf-8"))


def _toc_files():
    """Every ``file:`` entry of ``book/_toc.yml``, the root first."""
    toc = yaml.safe_load((BOOK / "_toc.yml").read_text(encoding="utf-8"))
    files = [toc["root"]]

    def walk(node):
        if isinstance(node, dict):
            if "file" in node:
                files.append(node["file"])
            for value in node.values():
                walk(value)
        elif isinstance(node, list):
            for item in node:
                walk(item)

    walk({k: v for k, v in toc.items() if k != "root"})
    return files


def _page_path(entry):
    """The file a TOC entry names (with or without its extension), or None."""
    for suffix in ("", ".md", ".ipynb"):
        path = BOOK / f"{entry}{suffix}"
        if path.is_file():
            return path
    return None


def _all_keys(node):
    if isinstance(node, dict):
        for key, value in node.items():
            yield key
            yield from _all_keys(value)
    elif isinstance(node, list):
        for item in node:
            yield from _all_keys(item)


def _label_and_title(text):
    """Return (labels before the first ``# `` title, the title line) of a MyST page."""
    lines = text.splitlines()
    if lines and lines[0].strip() == "---":  # front matter
        end = next(i for i in range(1, len(lines)) if lines[i].strip() == "---")
        lines = lines[end + 1 :]
    labels, fence = [], None
    for line in lines:
        match = FENCE.match(line)
        if fence is None and match:
            fence = match.group(1)
            continue
        if fence is not None:
            if line.strip() == fence:
                fence = None
            continue
        label = LABEL.match(line)
        if label:
            labels.append(label.group(1))
        elif line.startswith("# "):
            return labels, line
    return labels, None


# --- execution strictness -------------------------------------------------------------


def test_config_execute_raise_on_error():
    assert _config()["execute"]["raise_on_error"] is True


def test_config_execute_allow_errors_false():
    assert _config()["execute"]["allow_errors"] is False


def test_config_execute_stderr_output_warn():
    assert _config()["execute"]["stderr_output"] == "warn"


def test_config_execute_notebooks_cache():
    assert _config()["execute"]["execute_notebooks"] == "cache"


# --- offline: nothing fetched at build or read time -----------------------------------


def test_config_no_mathjax_path_or_intersphinx():
    keys = set(_all_keys(_config()))
    assert "mathjax_path" not in keys
    assert "intersphinx_mapping" not in keys
    sphinx = _config().get("sphinx", {})
    extensions = list(sphinx.get("extra_extensions") or []) + list(sphinx.get("local_extensions") or {})
    assert "sphinx.ext.intersphinx" not in extensions


def test_config_math_is_mathml_written_at_build_time():
    """No MathJax (1.2 MB on every page, issue 17): book/_ext/mathml.py writes MathML."""
    sphinx = _config()["sphinx"]
    assert "sphinx-mathjax-offline" not in (sphinx.get("extra_extensions") or [])
    assert sphinx["local_extensions"]["mathml"] == "_ext/"
    assert sphinx["config"]["html_math_renderer"] == "mathml"


def test_config_page_weight_extension():
    assert _config()["sphinx"]["local_extensions"]["page_weight"] == "_ext/"


def test_config_css_purge_extension():
    """book/_ext/css_purge.py drops unused CSS rules after page_weight (issue 17)."""
    extensions = _config()["sphinx"]["local_extensions"]
    assert extensions["css_purge"] == "_ext/"
    assert list(extensions).index("css_purge") > list(extensions).index("page_weight")


def test_config_launch_buttons_off():
    launch = _config().get("launch_buttons") or {}
    for key in ("binderhub_url", "jupyterhub_url", "colab_url", "deepnote_url"):
        assert not launch.get(key), f"launch button {key} is on: {launch.get(key)!r}"
    assert not launch.get("thebe")


# --- table of contents and page labels ------------------------------------------------


def test_toc_files_exist():
    missing = [entry for entry in _toc_files() if _page_path(entry) is None]
    assert missing == [], f"TOC entries without a file: {missing}"


def test_toc_has_no_duplicates():
    files = _toc_files()
    assert len(files) == len(set(files))


def test_toc_lists_every_derivation():
    notebooks = sorted(
        p for p in DERIVATIONS.rglob("*.md") if p.name != "README.md" and "_build" not in p.parts
    )
    assert notebooks, "no derivation notebooks found"
    listed = {entry.removesuffix(".md") for entry in _toc_files()}
    absent = [
        str(p.relative_to(ROOT)) for p in notebooks
        if f"derivations/{p.relative_to(DERIVATIONS).with_suffix('').as_posix()}" not in listed
    ]
    assert absent == [], f"derivation notebooks missing from book/_toc.yml: {absent}"


def test_toc_pages_have_label_before_title():
    problems = []
    for entry in _toc_files():
        path = _page_path(entry)
        if path is None or path.suffix != ".md":
            continue
        labels, title = _label_and_title(path.read_text(encoding="utf-8"))
        if title is None:
            problems.append(f"{entry}: no '# ' title")
        elif not labels:
            problems.append(f"{entry}: no '(label)=' line before {title!r}")
    assert problems == [], "\n".join(problems)


def test_toc_page_labels_unique():
    seen = {}
    for entry in _toc_files():
        path = _page_path(entry)
        if path is None or path.suffix != ".md":
            continue
        for label in _label_and_title(path.read_text(encoding="utf-8"))[0]:
            seen.setdefault(label, []).append(entry)
    repeated = {label: pages for label, pages in seen.items() if len(pages) > 1}
    assert repeated == {}


def test_label_and_title_ignores_code_comments():
    """The page parser itself: a ``# comment`` in a code cell is not a title."""
    text = "---\nkernelspec: {}\n---\n\n```{code-cell} ipython3\n# not a title\n```\n(x-y)=\n# Title\n"
    assert _label_and_title(text) == (["x-y"], "# Title")
    assert _label_and_title("# Title\n(late)=\n") == ([], "# Title")


REQUIRED_LABELS = {
    "deriv-grashof", "deriv-fourbar-position", "deriv-fourbar-limit-positions",
    "deriv-transmission-angle", "deriv-slider-crank",
    "book-intro", "book-how-to-read", "book-structure", "book-kinematics", "book-examples",
    "book-motion-diagrams", "book-exercises", "book-benchmarks", "book-glossary",
    "book-errata", "book-status",
}


def test_toc_pages_define_required_labels():
    """The labels other pages cross-reference ({ref}`deriv-grashof` ...) all exist."""
    found = set()
    for entry in _toc_files():
        path = _page_path(entry)
        if path is not None and path.suffix == ".md":
            found.update(_label_and_title(path.read_text(encoding="utf-8"))[0])
    assert sorted(REQUIRED_LABELS - found) == []


# --- navigation titles (issue 17, item 5) ----------------------------------------------


def _titles():
    """``{toc entry: title text}`` for every MyST page of the table of contents."""
    titles = {}
    for entry in _toc_files():
        path = _page_path(entry)
        if path is not None and path.suffix == ".md":
            title = _label_and_title(path.read_text(encoding="utf-8"))[1]
            if title is not None:
                titles[entry] = title[2:].strip()
    return titles


def _topic(title):
    """A title without its kind prefix and its parenthesised numbers, lower case."""
    title = re.sub(r"^(Derivation|Worked examples):\s*", "", title)
    return re.sub(r"\s*\([^()]*\)\s*$", "", title).strip().lower()


def test_page_titles_unique():
    seen = {}
    for entry, title in _titles().items():
        seen.setdefault(title, []).append(entry)
    repeated = {title: pages for title, pages in seen.items() if len(pages) > 1}
    assert repeated == {}, f"pages sharing a title in the side bar: {repeated}"


TITLE_LIMIT = 50  # characters of a page title (issue 26); its equation numbers go in the page


def test_page_titles_short():
    """A title a reader takes in at a glance, in the side bar and the browser's tab: at most
    TITLE_LIMIT characters; the textbook's numbers are in the line under it (and declared
    for mech.index in the page's front matter)."""
    long = {entry: len(title) for entry, title in _titles().items() if len(title) > TITLE_LIMIT}
    assert long == {}


def test_derivation_pages_say_derivation():
    """A reader tells a derivation from its worked use in the side bar alone."""
    wrong = [
        f"{entry}: {title!r}" for entry, title in _titles().items()
        if entry.startswith("derivations/") != title.startswith("Derivation: ")
    ]
    assert wrong == [], "\n".join(wrong)


def test_derivation_and_worked_use_titles_differ_beyond_prefix():
    """Removing 'Derivation:' and the numbers may leave a shared topic, but never two
    pages of the same kind on one topic (that is a duplicate page)."""
    seen = {}
    for entry, title in _titles().items():
        kind = "derivation" if entry.startswith("derivations/") else "page"
        seen.setdefault((kind, _topic(title)), []).append(entry)
    repeated = {key: pages for key, pages in seen.items() if len(pages) > 1}
    assert repeated == {}


def test_title_checks_can_fail():
    assert _topic("Derivation: the RSSR spatial four-bar (eqs. 2-67 to 2-71)") == "the rssr spatial four-bar"
    assert _topic("Worked examples: the RSSR (§2.4)") == "the rssr"


def test_png_palette_shrinks_a_figure_faithfully(tmp_path):
    """book/_ext/png_palette.py: a Matplotlib figure gets smaller and stays within 0.5/255 on average."""
    import importlib.util

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from PIL import Image

    spec = importlib.util.spec_from_file_location("png_palette", ROOT / "book" / "_ext" / "png_palette.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)

    fig, ax = plt.subplots(figsize=(5, 4))
    t = np.linspace(0, 2 * np.pi, 400)
    for k in range(1, 5):
        ax.plot(np.cos(k * t), np.sin((k + 1) * t), lw=1.5)
    ax.fill_between(t / 7 - 0.5, -0.2, 0.2, alpha=0.3)
    ax.set_title("coupler curves")
    path = tmp_path / "figure.png"
    fig.savefig(path, dpi=100)
    plt.close(fig)
    before = np.asarray(Image.open(path).convert("RGB"), dtype=float)
    size = path.stat().st_size
    assert module.palette_png(path)
    after = np.asarray(Image.open(path).convert("RGB"), dtype=float)
    assert path.stat().st_size < 0.7 * size
    assert np.abs(after - before).mean() < 0.5
    assert not module.palette_png(path)  # already a palette image

    transparent = tmp_path / "transparent.png"
    Image.new("RGBA", (8, 8), (255, 0, 0, 10)).save(transparent)
    raw = transparent.read_bytes()
    assert not module.palette_png(transparent) and transparent.read_bytes() == raw


def test_module_kernels_are_not_page_scripts():
    """Jupyter Book puts every .js under book/_static on every page; the ES-module kernels
    and their layer must not be (they throw on `export` as classic scripts)."""
    import importlib.util
    from types import SimpleNamespace

    spec = importlib.util.spec_from_file_location("module_scripts", ROOT / "book" / "_ext" / "module_scripts.py")
    ext = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(ext)
    config = SimpleNamespace(html_js_files=["kernels/fourbar_position.js", ("mech/planar.js", {}), "mech_anim.js",
                                            "other.js"])
    ext._drop_module_scripts(None, config)
    assert config.html_js_files == ["mech_anim.js", "other.js"]
    built = ROOT / "book" / "_build" / "html" / "structure" / "index.html"
    if built.is_file():
        html = built.read_text(encoding="utf-8")
        assert "_static/kernels/" not in html and "_static/mech/" not in html


def test_book_is_read_on_every_core(tmp_path):
    """`make book` (book/_build_book.py) passes Sphinx the number of jobs, and every extension
    the book loads allows a parallel read: one extension without the flag makes the whole
    build read, and execute its notebooks, one page after another. The build is stopped at
    the moment Sphinx chooses."""
    import subprocess
    import sys

    probe = f"""
import functools, sys
sys.path.insert(0, {str(BOOK)!r})
import _build_book
from sphinx import builders

def stop(label):
    def method(self, docnames, *args, **kwargs):
        print(label, self.app.parallel, flush=True)
        raise SystemExit(0)
    return method

builders.Builder._read_serial = stop("serial")
builders.Builder._read_parallel = stop("parallel")
_build_book.main([{str(BOOK)!r}, "--path-output", {str(tmp_path)!r}])
"""
    env = dict(__import__("os").environ, MECH_BOOK_JOBS="2", PYTHONPATH=str(ROOT))
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, env=env, timeout=600)
    assert "parallel 2" in out.stdout, out.stdout[-2000:] + out.stderr[-2000:]
