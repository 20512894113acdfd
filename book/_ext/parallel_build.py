"""Let Sphinx read (and execute) the pages on several cores (``book/_build_book.py``).

Sphinx reads in parallel only when every loaded extension declares itself safe for it.
Two extensions that Jupyter Book loads declare nothing, so their missing flags made every
build serial. Both are safe, as their code shows:

- ``sphinx_multitoc_numbering`` only replaces the table-of-contents collector's
  ``assign_section_numbers``, which Sphinx runs in the main process after the readers'
  results are merged;
- ``sphinx_jupyterbook_latex`` adds transforms that change the doctree of the page being
  read (and nothing else) and event handlers that act for the LaTeX builder only.

The flags are set just before Sphinx decides how to read. ``tests/test_book_config.py``
fails if Sphinx would still read serially.
"""

SAFE_UNDECLARED = ("sphinx_multitoc_numbering", "sphinx_jupyterbook_latex")


def _declare(app, env, docnames):
    for name in SAFE_UNDECLARED:
        extension = app.extensions.get(name)
        if extension is not None:
            extension.parallel_read_safe = True
            extension.parallel_write_safe = True


def setup(app):
    app.connect("env-before-read-docs", _declare)
    return {"parallel_read_safe": True, "parallel_write_safe": True, "version": "1"}
