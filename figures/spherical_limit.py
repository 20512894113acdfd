"""Figures of the page on the planar limit of the spherical four-bar
(``book/spherical/planar-limit.md``). Plain functions on data computed by ``mech``;
nothing is computed or drawn at import.
"""

import numpy as np

from figures import sphere

__all__ = ["shrinking_linkages", "convergence"]


def shrinking_linkages(cases, planar_curve, *, elev=30.0, azim=-60.0):
    """Left: the same linkage at several sizes on the sphere. Right: their coupler curves
    seen in the tangent plane at the north pole, divided by the scale, with the planar one.

    Parameters
    ----------
    cases : sequence of (eps, A, D, B, C, curve)
        Scale factor, pivots, pins at one pose, and the coupler curve (unit vectors).
    planar_curve : ndarray, complex
        The planar four-bar's coupler curve.
    """
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(10.5, 4.8))
    ax3 = fig.add_subplot(1, 2, 1, projection="3d")
    ax2 = fig.add_subplot(1, 2, 2)
    sphere.globe(ax3)
    colours = plt.cm.viridis(np.linspace(0.0, 0.8, len(cases)))
    for (eps, A, D, B, C, curve), colour in zip(cases, colours):
        for p, q in ((A, B), (B, C), (C, D), (A, D)):
            sphere.arc(ax3, p, q, color=colour, lw=1.8)
        ax3.plot(curve[:, 0], curve[:, 1], curve[:, 2], color=colour, lw=0.9)
        ax2.plot(curve[:, 0] / eps, curve[:, 1] / eps, color=colour, lw=1.2,
                 label=f"sphere, scale {eps:g}")
    sphere.point(ax3, A, "A")
    sphere.finish(ax3, elev=elev, azim=azim)
    ax2.plot(planar_curve.real, planar_curve.imag, "k--", lw=1.2, label="planar FourBar")
    ax2.set_aspect("equal")
    ax2.set_xlabel("x / scale")
    ax2.set_ylabel("y / scale")
    ax2.legend(fontsize=8, loc="best")
    fig.tight_layout()
    return fig


def convergence(eps, errors, *, slope=2.0):
    """Log-log plot of the largest difference from the planar linkage against the scale,
    one line per quantity, with a reference line of the given slope."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    eps = np.asarray(eps, dtype=float)
    for (name, values), marker in zip(errors.items(), "osd^v"):
        ax.loglog(eps, values, marker=marker, label=name)
    first = max(v[0] for v in errors.values())
    ax.loglog(eps, first * (eps / eps[0]) ** slope, "k:", label=f"slope {slope:g}")
    ax.set_xlabel(r"scale $\varepsilon$ of all arcs")
    ax.set_ylabel("largest difference from the planar four-bar")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    return fig
