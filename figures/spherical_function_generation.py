"""Figures of ``book/spherical/function-generation.md``: a function generator drawn on the
sphere at its precision positions, and structural-error curves. Nothing runs at import."""

import numpy as np

from figures import sphere

__all__ = ["linkage_positions", "error_curves"]


def linkage_positions(points, ax=None, *, title=None, elev=30.0, azim=-60.0):
    """Draw a spherical four-bar at several positions on the globe.

    `points` is (A, B, C, D), each of shape (m, 3): the joints at m input positions. The
    ground arc AD is black, the input AB blue, the coupler BC grey, the output DC red; the
    first position is drawn bold, the others thin.
    """
    ax = sphere.globe(ax)
    A, B, C, D = (np.atleast_2d(p) for p in points)
    sphere.arc(ax, A[0], D[0], color="black", lw=2.5)
    for i in range(B.shape[0]):
        lw = 2.2 if i == 0 else 1.0
        sphere.arc(ax, A[i], B[i], color="tab:blue", lw=lw)
        sphere.arc(ax, B[i], C[i], color="0.45", lw=lw)
        sphere.arc(ax, D[i], C[i], color="tab:red", lw=lw)
        sphere.point(ax, B[i], "B" if i == 0 else None, colour="tab:blue")
        sphere.point(ax, C[i], "C" if i == 0 else None, colour="tab:red")
    sphere.point(ax, A[0], "A")
    sphere.point(ax, D[0], "D")
    if title:
        ax.set_title(title, fontsize=10)
    return sphere.finish(ax, elev=elev, azim=azim)


def error_curves(u, errors, pairs=None, ax=None, *, xlabel="u"):
    """Structural error in degrees against the function's argument `u`.

    `errors` maps a label to an array (radians) over `u`; `pairs` maps the same labels to
    the arguments of their precision points, marked on the zero line.
    """
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(7.0, 3.6))
    for label, err in errors.items():
        line, = ax.plot(u, np.degrees(err), label=label, lw=1.4)
        if pairs and label in pairs:
            ax.plot(pairs[label], np.zeros(len(pairs[label])), "o", ms=4, color=line.get_color())
    ax.axhline(0.0, color="0.5", lw=0.6)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("structural error (deg)")
    ax.legend(fontsize=8, ncol=2)
    ax.grid(alpha=0.3)
    return ax
