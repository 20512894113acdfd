"""Coupler curves of a four-bar (``book/kinematics/motion-diagrams.md``): plotting functions.

The function takes coupler-point paths computed by ``mech`` (``FourBar(...).solve(theta).P``)
and a Matplotlib ``Axes`` (a new figure when None) and returns the axes; nothing is computed
or drawn at import.
"""

import numpy as np

__all__ = ["coupler_curves"]


def coupler_curves(curves, d, B, C, points, ax=None):
    """Draw coupler curves and the linkage in one pose (like Fig. 2-29b).

    Parameters
    ----------
    curves : mapping of str to array_like of complex
        Label to the path of a coupler point over a crank turn.
    d : float
        Ground length: pivots A = 0 and D = d.
    B, C : complex
        Crank pin and rocker pin in the pose drawn.
    points : mapping of str to complex
        The coupler points in that pose (same labels as `curves`).
    """
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=(7.0, 5.0))
    for label, path in curves.items():
        path = np.asarray(path)
        line, = ax.plot(path.real, path.imag, lw=1.2, label=label)
        P = points[label]
        ax.fill([B.real, C.real, P.real], [B.imag, C.imag, P.imag], color=line.get_color(), alpha=0.12)
        ax.plot(P.real, P.imag, "o", ms=4, color=line.get_color())
    ax.plot([0.0, B.real, C.real, d], [0.0, B.imag, C.imag, 0.0], "-o", color="black", lw=2, ms=5)
    ax.plot([0.0, d], [0.0, 0.0], "k^", ms=9)
    for name, z, dy in (("A", 0j, -1.0), ("D", d + 0j, -1.0), ("B", B, 1.0), ("C", C, 1.0)):
        ax.annotate(name, (z.real, z.imag), xytext=(4, 8 * dy - 3), textcoords="offset points")
    ax.set_aspect("equal")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    return ax
