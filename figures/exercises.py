"""Figures of the exercise page (``book/kinematics/exercises.md``): plain plotting functions.

Each function takes data computed by ``mech`` and a Matplotlib ``Axes`` (a new figure when
``ax`` is None) and returns the axes; nothing is computed or drawn at import.
"""

import numpy as np

__all__ = ["kind_map", "transmission_curves"]

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
