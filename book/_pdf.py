"""The whole book as one PDF, printed offline from the built HTML (issue 26).

Usage: python book/_pdf.py book/_build/html [output.pdf]

Every page of the table of contents (``book/_toc.yml``, the landing page first) is loaded
from a local server in the operating system's Chromium (through Playwright, which never
downloads a browser), printed with the browser's print layout (``page.pdf``: the MathML
math, the SVG and PNG figures and the first frame of each animation, as the page shows
them) and the pages are joined in the order of the contents with pypdf, with one bookmark
per page. The default output is ``mech-book.pdf`` beside the landing page, which links to
it. Nothing is fetched from outside the machine.
"""

import asyncio
import functools
import http.server
import io
import shutil
import sys
import threading
from contextlib import contextmanager
from pathlib import Path

import yaml

BOOK = Path(__file__).resolve().parent
PDF_NAME = "mech-book.pdf"
# Printed pages: no side bars, header, buttons or footer navigation; folded boxes open.
PRINT_CSS = """
.bd-header, .bd-sidebar-primary, .bd-sidebar-secondary, .bd-header-article, .prev-next-area,
.bd-footer, .bd-footer-content, .header-article-items, .mech-play, .mech-slider, #pst-skip-link,
.bd-footer-article, .toc-drawer, button { display: none !important; }
#jb-print-toc { display: none !important; }
.bd-main, .bd-content, .bd-article-container, .bd-page-width, .bd-article {
  max-width: 100% !important; width: 100% !important; margin: 0 !important; padding: 0 !important; }
.bd-container, .bd-container__inner { display: block !important; }
div.math, div.highlight pre, div.cell_output, div.cell_output pre { overflow: visible !important; white-space: pre-wrap; }
figure, div.math, table, img, svg { break-inside: avoid; }
h1, h2, h3 { break-after: avoid; }
"""


def toc_pages(toc_path=BOOK / "_toc.yml"):
    """The book's pages in the order of its contents (document names, the root first)."""
    toc = yaml.safe_load(Path(toc_path).read_text(encoding="utf-8"))
    pages = [toc["root"]]

    def walk(node):
        if isinstance(node, dict):
            if "file" in node:
                pages.append(node["file"])
            for key in ("parts", "chapters", "sections"):
                walk(node.get(key, []))
        elif isinstance(node, list):
            for item in node:
                walk(item)

    walk({k: v for k, v in toc.items() if k in ("parts", "chapters", "sections")})
    return list(dict.fromkeys(pages))


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


@contextmanager
def _serve(root):
    handler = functools.partial(_Quiet, directory=str(root))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/"
    finally:
        server.shutdown()
        server.server_close()


def _chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        if shutil.which(name):
            return shutil.which(name)
    raise SystemExit("no Chromium found (make browser-deps installs Debian's chromium)")


async def _print_all(root, pages, tabs=2):
    from playwright.async_api import async_playwright

    printed = {}
    with _serve(root) as base:
        async with async_playwright() as pw:
            browser = await pw.chromium.launch(
                executable_path=_chromium(), headless=True,
                proxy={"server": "http://127.0.0.1:9", "bypass": "127.0.0.1"})
            gate = asyncio.Semaphore(tabs)

            async def one(name):
                async with gate:
                    context = await browser.new_context(viewport={"width": 1000, "height": 1400})
                    await context.add_init_script("localStorage.setItem('mode', 'light')")
                    page = await context.new_page()
                    await page.goto(base + name + ".html", wait_until="load", timeout=120000)
                    await page.add_style_tag(content=PRINT_CSS)
                    await page.evaluate("""() => {
                      for (const d of document.querySelectorAll('details')) d.open = true;
                      for (const img of document.images) img.loading = 'eager';
                    }""")
                    await page.evaluate("document.fonts.ready")
                    await page.wait_for_timeout(300)
                    title = await page.evaluate("(document.querySelector('h1') || {}).textContent || document.title")
                    pdf = await page.pdf(format="A4", print_background=True, display_header_footer=False,
                                         margin={"top": "16mm", "bottom": "16mm", "left": "14mm", "right": "14mm"})
                    printed[name] = (title.replace("#", "").strip(), pdf)
                    await context.close()

            await asyncio.gather(*(one(name) for name in pages))
            await browser.close()
    return printed


def build_pdf(root, output=None):
    """Print every page of the contents of the build at ``root`` into one PDF; its path."""
    from pypdf import PdfReader, PdfWriter

    root = Path(root)
    output = Path(output) if output else root / PDF_NAME
    pages = [name for name in toc_pages() if (root / f"{name}.html").is_file()]
    if not pages:
        raise SystemExit(f"no built pages under {root}")
    printed = asyncio.run(_print_all(root, pages))
    writer = PdfWriter()
    for name in pages:
        title, pdf = printed[name]
        first = len(writer.pages)
        writer.append(PdfReader(io.BytesIO(pdf)))
        writer.add_outline_item(title=title, page_number=first)
    writer.add_metadata({"/Title": "mech: a symbolic-numeric companion to linkage kinematics"})
    with open(output, "wb") as f:
        writer.write(f)
    print(f"{output}: {len(pages)} pages of the book, {len(writer.pages)} PDF pages")
    return output


if __name__ == "__main__":
    build_pdf(sys.argv[1] if len(sys.argv) > 1 else BOOK / "_build" / "html",
              sys.argv[2] if len(sys.argv) > 2 else None)
