"""The progress bar of a long run: tqdm when asked for, a stand-in that does nothing otherwise.

tqdm is imported only when a bar is asked for, so a search or an atlas build runs without it.
In a terminal the bar goes to standard error, as a command line's bars do (standard output
stays for results), is redrawn in place and removed at the end. In a Jupyter kernel (a book
page) it goes to standard output, since any standard error of a page fails the strict book
build, and every redraw stays in the cell's output: there it is redrawn at most once a second
and its final state is kept.
"""

import sys

__all__ = []


class _NoBar:
    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    def update(self, n=1):
        pass


def _in_kernel():
    """Whether this code runs in a Jupyter kernel: ipykernel loaded and an IPython shell active
    (a test run may have imported ipykernel without being a kernel)."""
    ipython = sys.modules.get("IPython")
    return "ipykernel" in sys.modules and ipython is not None and ipython.get_ipython() is not None


def progress_bar(enabled, total, initial=0, desc=None, unit="it"):
    """A context manager with ``update(n)``: a tqdm bar of `total` steps if `enabled`.

    Examples
    --------
    >>> with progress_bar(False, 10) as bar:
    ...     bar.update(3)
    """
    if not enabled:
        return _NoBar()
    from tqdm import tqdm

    in_kernel = _in_kernel()
    return tqdm(total=total, initial=initial, desc=desc, unit=unit, leave=in_kernel,
                file=sys.stdout if in_kernel else sys.stderr,
                mininterval=1.0 if in_kernel else 0.1)
