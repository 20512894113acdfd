"""Store the book's figures as palette PNGs, about a third of their size.

Matplotlib writes full-colour PNGs, and the figures are most of what a reader downloads
for a page once the shared theme and MathJax files are cached (issue 17 asks for a median
page under 500 kB). A line drawing has few colours, so an adaptive palette of 256 keeps it
visually unchanged: an image is replaced only when its mean error per channel stays below
`MEAN_LIMIT` (0.5 of 255) and it has no transparency; anything else is left as it was.
"""

import io
from pathlib import Path

MEAN_LIMIT = 0.5


def palette_png(path):
    """Rewrite one PNG with a 256-colour palette if that is smaller and faithful; True if rewritten."""
    import numpy as np
    from PIL import Image

    raw = path.read_bytes()
    with Image.open(io.BytesIO(raw)) as image:
        rgba = np.asarray(image.convert("RGBA"))
        if image.mode == "P" or (rgba[..., 3] < 255).any():
            return False
        quantized = Image.fromarray(rgba[..., :3]).quantize(
            256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    error = np.abs(np.asarray(quantized.convert("RGB"), dtype=np.int16) - rgba[..., :3]).mean()
    out = io.BytesIO()
    quantized.save(out, "PNG", optimize=True)
    if error > MEAN_LIMIT or len(out.getvalue()) >= len(raw):
        return False
    path.write_bytes(out.getvalue())
    return True


def shrink_images(app, exception):
    if exception is not None or app.builder.format != "html":
        return
    for path in sorted(Path(app.outdir, "_images").glob("*.png")):
        palette_png(path)


def setup(app):
    app.connect("build-finished", shrink_images)
    return {"parallel_read_safe": True, "parallel_write_safe": True, "version": "1"}
