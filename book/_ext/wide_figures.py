"""Wide multi-panel figures stay legible on a phone (issue 26).

A figure of three spheres side by side (13 x 4 inches) is shrunk to the width of a phone's
column, about 360 px, so each sphere is about 100 px wide. This extension marks every image
of a page whose width is more than ``RATIO`` times its height with the class ``mech-wide``
(on ``doctree-resolved``, reading the PNG's size), and ``mech-math.css`` gives such an image
a minimum width on a narrow screen inside a box that scrolls sideways, so the panels keep a
readable size and the page itself never pans.
"""

from pathlib import Path

from docutils import nodes

RATIO = 2.2


def _size(path):
    from PIL import Image

    try:
        with Image.open(path) as image:
            return image.size
    except (OSError, ValueError):
        return None


def mark_wide(app, doctree, docname):
    for image in doctree.findall(nodes.image):
        uri = (image.get("candidates") or {}).get("*") or image.get("uri", "")
        if not uri.lower().endswith(".png") or "://" in uri:
            continue
        path = Path(app.srcdir, uri.lstrip("/"))
        if not path.is_file():
            path = Path(app.srcdir, app.env.doc2path(docname, False)).parent / uri
        size = _size(path) if path.is_file() else None
        if size and size[1] and size[0] / size[1] > RATIO:
            image["classes"].append("mech-wide")


def setup(app):
    app.connect("doctree-resolved", mark_wide)
    return {"parallel_read_safe": True, "parallel_write_safe": True, "version": "1"}
