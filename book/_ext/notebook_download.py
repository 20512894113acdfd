"""Offer every page as a notebook (``.ipynb``); on derivation pages, say how to run it.

Jupyter Book 1 (sphinx-book-theme) adds an ``.ipynb`` entry to the page's download menu
only when a launch service (Binder, JupyterHub, Colab, Thebe) is configured, and each of
those points the reader at a server outside the book. This extension does the offline part
alone, for every page (issue 26):

- on ``html-page-context`` it copies the notebook that MyST-NB executed for the page
  (``_build/jupyter_execute/<page>.ipynb``, outputs included) to ``_sources/<page>.ipynb``
  and sets ``ipynb_source``, so the theme's download menu offers it; a page without code
  (plain MyST Markdown) is converted with jupytext into a notebook of text cells;
- on ``doctree-read`` it puts a short "Run this derivation yourself" box under the title of
  the pages under ``derivations/``, folded (a ``<details>`` element that opens on a click),
  so that it does not fill a phone's first screen.
"""

import shutil
from pathlib import Path

from docutils import nodes

PREFIX = "derivations/"


def _text(*parts):
    """A paragraph from strings; strings in backticks become inline code."""
    para = nodes.paragraph()
    for part in parts:
        if part.startswith("`") and part.endswith("`"):
            para += nodes.literal(text=part.strip("`"))
        else:
            para += nodes.Text(part)
    return para


class run_box(nodes.General, nodes.Element):
    """A folded box: ``<details>`` with the title as its ``<summary>``."""


def visit_run_box(self, node):
    self.body.append('<details class="admonition tip mech-run-notebook">'
                     f'<summary class="admonition-title">{self.encode(node["title"])}</summary>\n')


def depart_run_box(self, node):
    self.body.append("</details>\n")


def run_note(docname):
    """The folded box that tells a reader how to run the page's notebook."""
    stem = Path(docname).name
    box = run_box(title="Run this derivation yourself")
    box += _text(
        "Download this page as a notebook (the download button at the top of the page, then ",
        "`.ipynb`", "). In a clone of the repository, ", "`make setup`",
        " creates ", "`.venv`", " with the pinned SymPy and installs ", "`mech`",
        " with the repository's ", "`derivations`", " helpers on its path; then run the notebook from any folder with ",
        f"`.venv/bin/jupyter execute {stem}.ipynb`",
        ", or open it in Jupyter with that environment's kernel.",
    )
    box += _text(
        "The code-generation cell rewrites its module of ", "`mech/_generated/`",
        " only when the derivation changed; with ", "`MECH_CODEGEN=check`",
        " in the environment it only checks that the module is current.",
    )
    return box


def add_run_note(app, doctree):
    docname = app.env.docname
    if not docname.startswith(PREFIX):
        return
    for section in doctree.findall(nodes.section):
        if section.children and isinstance(section[0], nodes.title):
            section.insert(1, run_note(docname))
        return


def _text_notebook(source, target):
    """Write ``source`` (MyST Markdown without code) as a notebook of text cells."""
    import jupytext
    import nbformat

    notebook = jupytext.read(source, fmt="md:myst")
    notebook.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    notebook.metadata.pop("jupytext", None)
    nbformat.write(notebook, target)


def offer_notebook(app, pagename, templatename, context, doctree):
    if doctree is None or pagename in ("genindex", "search", "py-modindex"):
        return
    target = Path(app.outdir) / "_sources" / f"{pagename}.ipynb"
    target.parent.mkdir(parents=True, exist_ok=True)
    source = Path(app.outdir).parent / "jupyter_execute" / f"{pagename}.ipynb"
    if source.is_file():
        shutil.copy2(source, target)
    else:
        page = Path(app.env.doc2path(pagename))
        if pagename.startswith(PREFIX) or page.suffix != ".md" or not page.is_file():
            from sphinx.util import logging

            logging.getLogger(__name__).warning(f"no executed notebook for {pagename} at {source}")
            return
        _text_notebook(page, target)
    context["ipynb_source"] = f"{pagename}.ipynb"


def setup(app):
    app.add_node(run_box, html=(visit_run_box, depart_run_box))
    app.connect("doctree-read", add_run_note)
    # Before sphinx-book-theme builds its header buttons (priority 501).
    app.connect("html-page-context", offer_notebook, priority=400)
    return {"parallel_read_safe": True, "parallel_write_safe": True, "version": "1"}
