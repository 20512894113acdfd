"""Figures for the conventions page (``book/how-to-read.md``).

Plain plotting functions: they take already computed points and a Matplotlib ``Axes`` and
draw; nothing is computed or imported from Matplotlib at import time.
"""

import numpy as np

__all__ = ["draw_branches"]

_BRANCH_STYLE = {1: dict(color="C0", ls="-"), -1: dict(color="C3", ls="--")}


def _arc(ax, centre, radius, start, stop, label, color, label_radius=1.35):
    """Draw an arc from angle ``start`` to ``stop`` (arrow at ``stop``) with a label."""
    t = np.linspace(start, stop, 60)
    pts = centre + radius * np.exp(1j * t)
    ax.plot(pts.real, pts.imag, color=color, lw=1)
    tip, before = pts[-1], pts[-2]
    ax.annotate("", xy=(tip.real, tip.imag), xytext=(before.real, before.imag),
                arrowprops=dict(arrowstyle="->", color=color, lw=1))
    mid = centre + label_radius * radius * np.exp(1j * 0.5 * (start + stop))
    ax.text(mid.real, mid.imag, label, color=color, ha="center", va="center", fontsize=12)


def _joint(ax, z, name, offset, ground=False):
    ax.plot([z.real], [z.imag], "o", ms=7 if ground else 6, mfc="white", mec="k", zorder=5)
    ax.annotate(name, (z.real, z.imag), xytext=offset, textcoords="offset points",
                fontsize=12, ha="center", va="center")


def draw_branches(ax, d, B, C, phi, psi, theta):
    """Draw a four-bar at one crank angle in both assembly modes, with its angles.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    d : float
        Frame length; the pivots are A = 0 and D = d.
    B : complex
        Crank pin.
    C : dict
        ``{+1: C_plus, -1: C_minus}``, the rocker pin in each assembly mode.
    phi, psi : float
        Coupler and rocker angles of the ``branch=+1`` pose, radians.
    theta : float
        Crank angle, radians.
    """
    A, D = 0j, complex(d)
    size = abs(B) + abs(d)
    # The frame, hatched.
    ax.plot([A.real - 0.1 * size, D.real + 0.1 * size], [0, 0], color="0.6", lw=1, zorder=0)
    for x in np.linspace(A.real - 0.1 * size, D.real + 0.1 * size, 24):
        ax.plot([x, x - 0.02 * size], [0, -0.03 * size], color="0.6", lw=0.8, zorder=0)
    # The directed line B -> D that decides the branch.
    ax.annotate("", xy=(D.real, D.imag), xytext=(B.real, B.imag),
                arrowprops=dict(arrowstyle="->", color="0.4", lw=1, ls=":"))
    ax.plot([A.real, B.real], [A.imag, B.imag], color="k", lw=2.5)
    for branch, c in C.items():
        style = _BRANCH_STYLE[branch]
        ax.plot([B.real, c.real, D.real], [B.imag, c.imag, D.imag], lw=2, **style,
                label=f"branch = {branch:+d}")
        _joint(ax, c, f"C ({branch:+d})", (0, 12) if c.imag >= 0 else (0, -12))
    # The angles of the branch +1 pose, each from the +x direction.
    r = 0.2 * size
    _arc(ax, A, 0.6 * r, 0.0, theta, r"$\theta$", "k")
    ax.plot([D.real, D.real + 0.9 * r], [0, 0], color="C0", lw=0.8)
    _arc(ax, D, 0.5 * r, 0.0, psi, r"$\psi$", "C0")
    ax.plot([B.real, B.real + 0.9 * r], [B.imag, B.imag], color="C0", lw=0.8, ls=":")
    _arc(ax, B, 0.5 * r, 0.0, phi, r"$\varphi$", "C0")
    _joint(ax, A, "A", (-10, -12), ground=True)
    _joint(ax, D, "D", (10, -12), ground=True)
    _joint(ax, B, "B", (-10, 8))
    ax.set_aspect("equal")
    ax.axis("off")
    ax.legend(loc="upper left", frameon=False)
    return ax
