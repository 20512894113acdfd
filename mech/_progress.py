"""The progress bar of a long run: tqdm when asked for, a stand-in that does nothing otherwise.

tqdm is imported only when a bar is asked for, so a search or an atlas build runs without it.
The bar is written to standard output, never standard error (with ``-W`` any standard error
of a page fails the book build). In a terminal the bar is redrawn in place and removed at the
end; in a Jupyter kernel (a book page) every redraw stays in the cell's output, so there it is
redrawn at most once a second and its final state is kept.
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

    in_kernel = "ipykernel" in sys.modules
    return tqdm(total=total, initial=initial, desc=desc, unit=unit, file=sys.stdout, leave=in_kernel,
                mininterval=1.0 if in_kernel else 0.1)
