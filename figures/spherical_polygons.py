"""Figures of book/spherical/polygon-laws.md: a spherical polygon with its joint axes, a cut
into two open chains, and the planar limit of a small polygon.

Plain functions taking data (unit axes, complex planar points) and optional axes; nothing
is computed or drawn at import. The sphere is drawn with ``figures.sphere``.
"""

import numpy as np

from figures import sphere

__all__ = ["polygon_on_sphere", "cut_chains", "planar_limit"]

FORWARD, BACKWARD, CONNECT = "tab:blue", "tab:orange", "tab:green"


def _axis_lines(ax, axes, colour="0.35"):
    for u in axes:
        ax.plot([-0.25 * u[0], u[0]], [-0.25 * u[1], u[1]], [-0.25 * u[2], u[2]],
                color=colour, lw=0.8, ls="--")


def polygon_on_sphere(axes, ax=None, *, elev=30.0, azim=35.0, title=None):
    """The closed polygon through the unit joint axes `axes` (n, 3): axes through the
    centre, links as great-circle arcs, vertices labelled u_1 .. u_n."""
    axes = np.asarray(axes, dtype=float)
    ax = sphere.globe(ax)
    _axis_lines(ax, axes)
    ax.scatter([0.0], [0.0], [0.0], color="black", s=10)
    n = len(axes)
    for k in range(n):
        sphere.arc(ax, axes[k], axes[(k + 1) % n], color=FORWARD)
        sphere.point(ax, axes[k], f"$u_{k + 1}$")
    if title:
        ax.set_title(title, fontsize=10)
    return sphere.finish(ax, elev=elev, azim=azim)


def cut_chains(axes, j, k, ax=None, *, elev=30.0, azim=35.0):
    """The cut (j, k) (1-based) of the polygon through `axes`: forward chain j -> .. -> k,
    backward chain j -> j-1 -> .. -> k, and the connecting arc u_j u_k (dashed)."""
    axes = np.asarray(axes, dtype=float)
    n = len(axes)
    ax = sphere.globe(ax)
    i = j - 1
    while i != k - 1:
        sphere.arc(ax, axes[i], axes[(i + 1) % n], color=FORWARD)
        i = (i + 1) % n
    i = j - 1
    while i != k - 1:
        sphere.arc(ax, axes[i], axes[(i - 1) % n], color=BACKWARD)
        i = (i - 1) % n
    sphere.arc(ax, axes[j - 1], axes[k - 1], color=CONNECT, ls="--", lw=1.5)
    for m in range(n):
        colour = CONNECT if m in (j - 1, k - 1) else "black"
        sphere.point(ax, axes[m], f"$u_{m + 1}$", colour=colour)
    ax.plot([], [], color=FORWARD, label=f"forward chain {j} → {k}")
    ax.plot([], [], color=BACKWARD, label=f"backward chain {j} → {k}")
    ax.plot([], [], color=CONNECT, ls="--", label=f"connecting arc $u_{j}u_{k}$")
    ax.legend(loc="lower center", fontsize=8, frameon=False, ncol=1)
    return sphere.finish(ax, elev=elev, azim=azim)


def planar_limit(planar, scaled, ax=None):
    """The planar polygon `planar` (complex vertices, closed) and the tangent-plane
    projections of small spherical chains, `scaled`: a dict eps -> complex vertices / eps."""
    import matplotlib.pyplot as plt

    if ax is None:
        _, ax = plt.subplots(figsize=(5.5, 4.5))
    ax.plot(planar.real, planar.imag, color="black", lw=2.5, label="planar polygon", zorder=1)
    for (eps, pts), style in zip(scaled.items(), ("-", "--", ":")):
        ax.plot(pts.real, pts.imag, ls=style, marker="o", ms=3, label=rf"sphere, $\varepsilon$ = {eps:g}",
                zorder=2)
    ax.set_aspect("equal")
    ax.set_xlabel(r"$x/\varepsilon$")
    ax.set_ylabel(r"$y/\varepsilon$")
    ax.legend(fontsize=8, loc="best")
    ax.grid(alpha=0.3)
    return ax
