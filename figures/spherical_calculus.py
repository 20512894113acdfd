"""Figures of the spherical calculus page (book/spherical/calculus.md).

Each function takes data computed by `mech.spherical` and draws it with the shared helpers
of `figures.sphere`; nothing is computed or drawn at import.
"""

import numpy as np

from figures import sphere

__all__ = ["coordinate_lines", "turned_triangle", "circle_through_three", "two_great_circles",
           "accuracy"]


def _arrow(ax, p, d, colour, label, length=0.35):
    ax.quiver(*p, *(length * np.asarray(d)), color=colour, lw=1.6, arrow_length_ratio=0.25)
    ax.text(*(np.asarray(p) + 1.15 * length * np.asarray(d)), label, color=colour, fontsize=10)


def coordinate_lines(meridians, parallels, p, ex, ey, ax=None):
    """Meridians and parallels (arrays of points, shape (k, n, 3)), a point `p` with its
    local frame `ex`, `ey`, and the north pole."""
    ax = sphere.globe(ax, meridians=0, parallels=0)
    for line in meridians:
        ax.plot(*line.T, color="tab:blue", lw=0.8)
    for line in parallels:
        ax.plot(*line.T, color="tab:orange", lw=0.8)
    sphere.point(ax, [0.0, 0.0, 1.0], "N")
    sphere.point(ax, p, "P", colour="black")
    _arrow(ax, p, ex, "tab:red", "$e_x$")
    _arrow(ax, p, ey, "tab:green", "$e_y$")
    ax.plot([], [], color="tab:blue", label="meridians (lon fixed)")
    ax.plot([], [], color="tab:orange", label="parallels (lat fixed)")
    ax.legend(loc="lower left", fontsize=8)
    return sphere.finish(ax, elev=20.0, azim=20.0)


def turned_triangle(a, b, c, b2, c2, ax=None):
    """The rigid triangle ABC (black) and its position AB'C' after turning about A (red)."""
    ax = sphere.globe(ax)
    for (p, q), colour in (((a, b), "black"), ((b, c), "black"), ((c, a), "black"),
                           ((a, b2), "tab:red"), ((b2, c2), "tab:red"), ((c2, a), "tab:red")):
        sphere.arc(ax, p, q, color=colour)
    for p, label, colour in ((a, "A", "black"), (b, "B", "black"), (c, "C", "black"),
                             (b2, "B'", "tab:red"), (c2, "C'", "tab:red")):
        sphere.point(ax, p, label, colour=colour)
    _arrow(ax, a, a, "tab:purple", "axis", length=0.3)
    return sphere.finish(ax, elev=30.0, azim=30.0)


def circle_through_three(points, pole, radius, ax=None):
    """Three points, the circle through them (pole and arc radius) and the pole."""
    ax = sphere.globe(ax)
    sphere.circle(ax, pole, radius, color="tab:blue", lw=1.5)
    for p, label in zip(points, "ABC"):
        sphere.point(ax, p, label)
        sphere.arc(ax, pole, p, color="0.5", lw=0.8, ls="--")
    sphere.point(ax, pole, "N", colour="tab:blue")
    return sphere.finish(ax, elev=25.0, azim=40.0)


def two_great_circles(pole1, pole2, point, antipode, ax=None):
    """Two directed great circles (their poles), and their two common points."""
    ax = sphere.globe(ax)
    for pole, colour, label in ((pole1, "tab:blue", "$N_1$"), (pole2, "tab:orange", "$N_2$")):
        sphere.circle(ax, pole, np.pi / 2, color=colour, lw=1.5)
        sphere.point(ax, pole, label, colour=colour)
    sphere.point(ax, point, "X", colour="black")
    sphere.point(ax, antipode, "-X", colour="0.4")
    return sphere.finish(ax, elev=20.0, azim=60.0)


def accuracy(arcs, err_acos, err_atan2, ax=None):
    """Relative error against the arc for arccos of the dot product and the atan2 form."""
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=(6.0, 3.6))
    floor = 1e-18
    ax.loglog(arcs, np.maximum(err_acos, floor), "o-", label="arccos(p . q)")
    ax.loglog(arcs, np.maximum(err_atan2, floor), "s-", label="distance (atan2 form)")
    ax.set_xlabel("arc (its distance from 0 or from pi), rad")
    ax.set_ylabel("relative error")
    ax.axhline(np.finfo(float).eps, color="0.5", lw=0.8, ls=":")
    ax.legend(fontsize=8)
    ax.grid(True, which="major", lw=0.3)
    return ax
