"""Offer every derivation page as a notebook (``.ipynb``) and say how to run it.

Jupyter Book 1 (sphinx-book-theme) adds an ``.ipynb`` entry to the page's download menu
only when a launch service (Binder, JupyterHub, Colab, Thebe) is configured, and each of
those points the reader at a server outside the book. This extension does the offline part
alone, for the pages under ``derivations/``:

- on ``html-page-context`` it copies the notebook that MyST-NB executed for the page
  (``_build/jupyter_execute/<page>.ipynb``, outputs included) to ``_sources/<page>.ipynb``
  and sets ``ipynb_source``, so the theme's download menu offers it;
- on ``doctree-read`` it puts a short "Run this derivation yourself" box under the title.
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


def run_note(docname):
    """The admonition that tells a reader how to run the page's notebook."""
    stem = Path(docname).name
    box = nodes.admonition(classes=["tip", "mech-run-notebook"])
    box += nodes.title(text="Run this derivation yourself")
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


def offer_notebook(app, pagename, templatename, context, doctree):
    if not pagename.startswith(PREFIX):
        return
    source = Path(app.outdir).parent / "jupyter_execute" / f"{pagename}.ipynb"
    if not source.is_file():
        from sphinx.util import logging

        logging.getLogger(__name__).warning(f"no executed notebook for {pagename} at {source}")
        return
    target = Path(app.outdir) / "_sources" / f"{pagename}.ipynb"
    target.parent.mkdir(parents=True, exist_ok=True)
    shutil.copy2(source, target)
    context["ipynb_source"] = f"{pagename}.ipynb"


def setup(app):
    app.connect("doctree-read", add_run_note)
    # Before sphinx-book-theme builds its header buttons (priority 501).
    app.connect("html-page-context", offer_notebook, priority=400)
    return {"parallel_read_safe": True, "parallel_write_safe": True, "version": "1"}
