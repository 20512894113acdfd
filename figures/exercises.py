"""Figures of the exercise page (``book/kinematics/exercises.md``): plain plotting functions.

Each function takes data computed by ``mech`` and a Matplotlib ``Axes`` (a new figure when
``ax`` is None) and returns the axes; nothing is computed or drawn at import.
"""

import numpy as np

__all__ = ["kind_map", "limit_positions", "transmission_curves"]

_COLOURS = ("tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple")


def _axes(ax, size):
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=size)
    return ax


def kind_map(ranges, total, ax=None, *, xlabel="length of AB (mm)"):
    """Draw a number line of a varying length coloured by linkage type.

    Parameters
    ----------
    ranges : mapping of str to sequence of Interval
        Label to the intervals where it applies (objects with ``low``, ``high``,
        ``closed_low``, ``closed_high``), one row per label.
    total : float
        Right end of the axis (the sum of the fixed lengths).
    """
    ax = _axes(ax, (7.0, 2.4))
    labels = list(ranges)
    for row, (label, colour) in enumerate(zip(labels, _COLOURS)):
        y = len(labels) - 1 - row
        for iv in ranges[label]:
            ax.broken_barh([(iv.low, iv.high - iv.low)], (y - 0.3, 0.6), color=colour, alpha=0.6)
            for x, closed in ((iv.low, iv.closed_low), (iv.high, iv.closed_high)):
                if 0.0 < x < total:
                    ax.plot(x, y, "o", ms=6, mec=colour, mfc=colour if closed else "white", zorder=3)
                    ax.annotate(f"{x:g}", (x, y + 0.32), ha="center", va="bottom", fontsize=8)
    ax.set_yticks(range(len(labels)), labels[::-1])
    ax.set_xlim(0.0, total)
    ax.set_ylim(-0.6, len(labels) - 0.2)
    ax.set_xlabel(xlabel)
    ax.grid(axis="x", alpha=0.3)
    return ax


def limit_positions(d, B, C, ax=None, *, names=("extended", "folded")):
    """Draw a four-bar (A = 0, D = d) in its two limit positions.

    Parameters
    ----------
    d : float
        Frame length AD.
    B, C : array_like of complex, shape (2,)
        The moving joints in the two positions.
    """
    ax = _axes(ax, (6.0, 4.5))
    B, C = np.asarray(B), np.asarray(C)
    a, c = abs(B[0]), abs(C[0] - d)
    t = np.linspace(0.0, 2.0 * np.pi, 200)
    ax.plot(a * np.cos(t), a * np.sin(t), ":", color="0.6", lw=1)
    psi = np.unwrap(np.angle(C - d))
    arc = np.linspace(psi[0], psi[1], 60)
    ax.plot(d + c * np.cos(arc), c * np.sin(arc), ":", color="0.6", lw=1)
    ax.plot([0.0, d], [0.0, 0.0], color="k", lw=2.5)
    for i, (style, name) in enumerate(zip(("-", "--"), names)):
        pts = np.array([0.0, B[i], C[i], d])
        ax.plot(pts.real, pts.imag, style, marker="o", color=_COLOURS[i], label=name)
        ax.annotate(f"B{'′' * (i + 1)}", (B[i].real, B[i].imag), textcoords="offset points",
                    xytext=(4, 4), color=_COLOURS[i])
        ax.annotate(f"C{'′' * (i + 1)}", (C[i].real, C[i].imag), textcoords="offset points",
                    xytext=(4, 4), color=_COLOURS[i])
    # the extreme-position angle: between A->B' and A->C'' (the folded crank, extended)
    u = np.angle(np.array([B[0], -B[1]]))
    ax.plot([0.0, C[1].real], [0.0, C[1].imag], ":", color=_COLOURS[1], lw=1)
    arc = np.linspace(u[0], u[0] + np.angle(np.exp(1j * (u[1] - u[0]))), 30)
    rho = 0.8 * a
    ax.plot(rho * np.cos(arc), rho * np.sin(arc), color="k", lw=1)
    mid = arc[len(arc) // 2]
    ax.annotate("θ", (1.15 * rho * np.cos(mid), 1.15 * rho * np.sin(mid)), ha="center", va="center")
    ax.annotate("A", (0.0, 0.0), textcoords="offset points", xytext=(-12, -12))
    ax.annotate("D", (d, 0.0), textcoords="offset points", xytext=(4, -12))
    ax.set_aspect("equal")
    ax.legend(loc="best", fontsize=8)
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    return ax


def transmission_curves(theta, curves, marks=(), ax=None):
    """Plot transmission angles against the crank angle, both in degrees.

    Parameters
    ----------
    theta : array_like
        Crank angles, radians.
    curves : mapping of str to array_like
        Label to the transmission angle at ``theta``, radians.
    marks : sequence of (theta, gamma, text)
        Points to mark, radians.
    """
    ax = _axes(ax, (7.0, 3.8))
    deg = np.degrees(np.asarray(theta))
    for (label, gamma), colour in zip(curves.items(), _COLOURS):
        ax.plot(deg, np.degrees(np.asarray(gamma)), color=colour, label=label)
    for th, g, text in marks:
        ax.plot(np.degrees(th), np.degrees(g), "ko", ms=4)
        ax.annotate(text, (np.degrees(th), np.degrees(g)), textcoords="offset points",
                    xytext=(5, -12), fontsize=8)
    ax.set_xlabel("crank angle θ (degrees)")
    ax.set_ylabel("transmission angle γ (degrees)")
    ax.set_xlim(deg.min(), deg.max())
    ax.set_xticks(np.arange(-180, 181, 90))
    low = min(np.nanmin(np.degrees(np.asarray(g))) for g in curves.values())
    ax.set_ylim(low - 10.0, 92.0)
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right", fontsize=8)
    return ax
