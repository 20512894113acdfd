"""Exercise boxes carry the textbook's numbers, not a running count of the book.

sphinx-exercise numbers its boxes across the whole book ("Exercise 22"), which contradicts
the textbook's numbering that the pages follow ("Exercise 2-19"). Every exercise of the
book is written as

    ```{exercise}
    :label: ex-2-19
    :nonumber:
    ```

and this post-transform, run after sphinx-exercise has resolved the titles (priority 20),
turns the label into the box's title: ``ex-2-19`` becomes "Exercise 2-19". A box without a
label of that form keeps the extension's title.

The build-status table of MyST-NB marks each page with an emoji (U+2705, U+274C) that a
machine without an emoji font draws as a box; :class:`StatusWords` writes "passed" and
"failed" instead.

The book's own figures carry no number: only the textbook's figures are numbered ("Fig.
2-37"), so a number a reader sees is always the textbook's. ``_config.yml`` sets ``numfig:
false``, but sphinx-jupyterbook-latex turns it on again when the configuration is read
(for its LaTeX output, on every builder); :func:`no_figure_numbers` turns it off after it.
"""

import re

from docutils import nodes
from sphinx.transforms.post_transforms import SphinxPostTransform

LABEL = re.compile(r"^ex-(\d+)-(\d+)$")


def textbook_title(label):
    """``"ex-2-19"`` -> ``"Exercise 2-19"``; None for a label of another form."""
    match = LABEL.match(label or "")
    return f"Exercise {match.group(1)}-{match.group(2)}" if match else None


class ExerciseTextbookNumbers(SphinxPostTransform):
    default_priority = 22  # after sphinx-exercise's ResolveTitlesInExercises (20)

    def run(self):
        from sphinx_exercise.nodes import exercise_node

        for node in self.document.findall(exercise_node):
            title = textbook_title(node.get("label"))
            if title is None or not node.children or not isinstance(node[0], nodes.title):
                continue
            node[0].children = []
            node[0] += nodes.Text(title)
            node["title"] = title


STATUS_WORDS = {"\u2705": "passed", "\u274c": "failed"}


class StatusWords(SphinxPostTransform):
    default_priority = 9  # after MyST-NB writes its execution table (8)

    def run(self):
        for text in list(self.document.findall(nodes.Text)):
            word = STATUS_WORDS.get(str(text).strip())
            if word is not None:
                text.parent.replace(text, nodes.Text(word))


def no_figure_numbers(app, config):
    config.numfig = False


def setup(app):
    # after sphinx-jupyterbook-latex's own config-inited handler (priority 500)
    app.connect("config-inited", no_figure_numbers, priority=900)
    app.add_post_transform(ExerciseTextbookNumbers)
    app.add_post_transform(StatusWords)
    return {"parallel_read_safe": True, "parallel_write_safe": True, "version": "1"}
